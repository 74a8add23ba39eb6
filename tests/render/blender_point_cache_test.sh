#!/usr/bin/env bash
# Blender reads what softbody exports (ctest label `blender`): the bounce's point caches (PC2, MDD) through
# the Mesh Cache modifier, and its OBJ and PLY sequences (tests/render/blender_check.py says what is checked).
# Installs Debian's blender where it is missing and this runs as root; exit 77 (ctest: skipped) with a line
# saying why where Blender cannot be installed or cannot run headless.
#   blender_point_cache_test.sh SOFTBODY SOURCE_DIR SCRATCH_DIR
set -euo pipefail
softbody=$1; source_dir=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch"

source "$source_dir/tests/blender/ensure_blender.sh"

scene="$source_dir/scenes/bounce.json"
short=(--set duration=1.2)  # frames 0..36: the fall, the landing (about frame 19) and the squash
run() { "$softbody" "$@" >>"$scratch/softbody.log" 2>&1 || { cat "$scratch/softbody.log"; echo "FAIL: softbody $*"; exit 1; }; }
run export "$scene" "${short[@]}" --format pc2 -o "$scratch/cache"
run export "$scene" "${short[@]}" --format mdd -o "$scratch/cache"
run export "$scene" "${short[@]}" --format ply -o "$scratch/ply"
run export "$scene" "${short[@]}" --format obj -o "$scratch/obj"
run simulate "$scene" "${short[@]}" --csv "$scratch/bounce.csv"

# Frame 0, the landing's squash, the last frame.
blender -b --factory-startup --python-exit-code 1 --python "$source_dir/tests/render/blender_check.py" -- \
  "$scratch/cache" "$scratch/ply" "$scratch/obj" "$scratch/bounce.csv" 0 22 36 >"$scratch/blender.log" 2>&1 ||
  { cat "$scratch/blender.log"; echo "FAIL: the Blender check failed"; exit 1; }
grep -E "^blender|FAIL" "$scratch/blender.log"
