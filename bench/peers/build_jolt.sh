#!/usr/bin/env bash
# Builds the Jolt Physics peer (bench/peers/jolt) against an installed Jolt given by JOLT_PREFIX (see
# bench/peers/jolt/README.md for building Jolt); prints the harness's path. Jolt is not part of the project's
# build: without JOLT_PREFIX this says so and exits 0 without building anything.
set -euo pipefail
cd "$(dirname "$0")/../.."
if [ -z "${JOLT_PREFIX:-}" ]; then
  echo "bench/peers/build_jolt.sh: JOLT_PREFIX is not set (an installed JoltPhysics, bench/peers/jolt/README.md): skipped" >&2
  exit 0
fi
[ -d "$JOLT_PREFIX" ] || { echo "bench/peers/build_jolt.sh: JOLT_PREFIX=$JOLT_PREFIX is not a folder" >&2; exit 2; }
cmake -S bench/peers/jolt -B build/peers-jolt -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$JOLT_PREFIX" >/dev/null
cmake --build build/peers-jolt >/dev/null
echo build/peers-jolt/jolt_bounce
