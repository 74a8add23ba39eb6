#!/bin/bash
# Usage: bench/run_path_sensitivity.sh SCENE [--set PATH=VALUE ...]        (after scripts/build)
# How much a scene's path depends on a change of its start far below any integrator's error: the scene under rk45
# at tolerance 1e-8, then again with body 0 turned by TURN degrees (default 0.01: 0.17 mm at 1 m from its centre)
# about x, y and z (its "rotation" key, so a rotation the scene gives body 0 is replaced). Prints each turned run's
# worst volume and centre-of-mass differences from the unturned one (bench/csv_errors.py, over the whole run).
# Where these are large, an integrator's error against the reference is not meaningful below them: e.g. the fast
# throw of docs/notes/2026-12-06-vbd-contact-error.md at icosphere:4 and :5.
# Writes out/sensitivity/<scene>_{ref,x,y,z}.csv; the extra arguments go to every run.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 1 ] || { sed -n 2,9p "$0"; exit 2; }
scene=$1
shift
B=build/softbody
turn=${TURN:-0.01}
out=out/sensitivity
mkdir -p $out
name=$(basename "$scene" .json)
simulate() { # csv extra-args...
  local csv=$1
  shift
  $B simulate "$scene" "$@" --set solver.integrator='"rk45"' --set solver.tolerance=1e-8 --csv "$csv" >/dev/null
}
simulate $out/${name}_ref.csv "$@"
declare -A turned=([x]="[$turn,0,0]" [y]="[0,$turn,0]" [z]="[0,0,$turn]")
for axis in x y z; do
  simulate $out/${name}_$axis.csv "$@" --set "bodies.0.rotation=${turned[$axis]}"
  echo "turned by $turn deg about $axis:$(python3 bench/csv_errors.py $out/${name}_ref.csv $out/${name}_$axis.csv |
    cut -d: -f2)"
done
