#!/bin/bash
# Usage: bench/run_vbd_converge.sh (after scripts/build; about 8 min on 2 cores, 2 of them the level-5 reference
# where out/vbd_bounce has none). vbd's default 4 sweeps per step against "iterations": "converge" (each step sweeps until
# a sweep moves no vertex by more than 3e-4 of its body's mean edge, 2 to 32 sweeps) and "auto" (those sweeps with the
# move scaled by the step, and its steps halved where the volume's local error needs it): the five bodies in flight of
# bench/flight_shapes_common.sh (1 s, against rk45 at 1e-8) and the smooth-floor bounce (scenes/bounce_smooth.json,
# 0-1.2 s, the fall, the first impact and the rebound) at icosphere:3, :4 and :5, with each control's own impact steps
# (solver.impact_phase unset: 0.5, and 0.25 for "auto"), "auto" at 0.5, and all at 0.125. Each line: user CPU s of one
# thread, vbd's own steps and its sweeps per step (from the run's summary), the worst volume error and the worst centre-of-mass
# distance (bench/csv_errors.py).
# The bounce's references are bench/vbd_bounce_common.sh's (make_reference, in its $out: out/vbd_bounce or $OUT),
# shared with bench/run_vbd_bounce.sh.
source "$(dirname "$0")/vbd_bounce_common.sh"
bounce=$out
out=${CONVERGE_OUT:-out/vbd_converge}
shapes=${SHAPES_OUT:-out/vbd_flight_shapes}
mkdir -p "$out" "$shapes"
# run NAME REFERENCE SCENE args...: one vbd run, timed, and its errors (in place of vbd_bounce_common.sh's run, which
# takes the bounce only).
run() {
  local name=$1 ref=$2 scene=$3; shift 3
  local log=$out/$name.log
  local t=$( { /usr/bin/time -f "%U" $B simulate "$scene" --set solver.threads=1 --set solver.integrator=\"vbd\" \
    "$@" --csv "$out/$name.csv" > "$log"; } 2>&1 | tail -1)
  local steps=$(sed -nE 's/.* steps of [0-9.e-]+ s (\(vbd.*\)), [0-9]+ vertices.*/\1/p' "$log" | head -1)
  echo "$name: cpu_s=$t $steps $(python3 bench/csv_errors.py "$ref" "$out/$name.csv" | cut -d: -f2)"
}
source bench/flight_shapes_common.sh
shape() { # name extra-args...
  local name=$1; shift
  flight_reference "$name" "$@"
  for sweeps in 4 '"converge"' '"auto"'; do
    run "${name}_${sweeps//\"/}" "$shapes/${name}_ref.csv" $S --set duration=1 --set solver.dt=\"auto\" \
      --set solver.substeps=1 --set solver.iterations=$sweeps "$@"
  done
}
each_flight_shape shape
# bounce_run NAME args...: the bounce at icosphere:$level against $ref.
bounce_run() {
  local name=$1; shift
  run "$name" "$ref" scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" --set duration=1.2 \
    --set solver.substeps=\"auto\" "$@"
}
for level in 3 4 5; do
  out=$bounce make_reference $level 1.2  # a longer one made by run_vbd_bounce.sh serves as well
  ref=$bounce/ref$level.csv
  # Each sweep control at its own impact steps (the default phase 0.5; "auto"'s 0.25), "auto" at 0.5 too, then all
  # at 0.125.
  for sweeps in 4 '"converge"' '"auto"'; do
    bounce_run "bounce${level}_${sweeps//\"/}_default" --set solver.iterations=$sweeps
  done
  bounce_run "bounce${level}_auto_0.5" --set solver.iterations=\"auto\" --set solver.impact_phase=0.5
  for sweeps in 4 '"converge"' '"auto"'; do
    bounce_run "bounce${level}_${sweeps//\"/}_0.125" --set solver.iterations=$sweeps --set solver.impact_phase=0.125
  done
done
