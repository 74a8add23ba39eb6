#!/bin/bash
# Usage: bench/run_pruning.sh (after scripts/build; about 5 min on 2 cores when the level-5 rk45 reference is
# already in out/vbd_bounce, else add about 15 min).
# Does each large-step integrator sit on a work-precision front? vbd and xpbd in one run, one thread each, on
# - the smooth-floor bounce (scenes/bounce_smooth.json) at icosphere:3 over 3 s and icosphere:5 over 1.2 s;
# - the same bounce with a very stiff body (k 1e6 N/m) at icosphere:3 over 1.2 s, where xpbd's substeps grow with √k;
# - the breathing ball in flight (bench/peers/breathing.json) at icosphere:3 over 1 s, dampers off;
# errors against rk45 at tolerance 1e-8 (bench/csv_errors.py: worst volume error and centre-of-mass distance,
# through the first impact and over the whole run); times: user CPU s per simulated s.
# (newton and implicit, which this script also ran until they were removed, are in docs/notes/2026-12-05-pruning.md
# and docs/notes/2026-12-05-vbd-coarse-linear.md.)
source "$(dirname "$0")/vbd_bounce_common.sh"
for level in 3 5; do
  dur=3; [ $level = 5 ] && dur=1.2
  make_reference $level $dur
  run vbd_auto_4 $level $dur --set solver.integrator=vbd --set solver.substeps=\"auto\" --set solver.iterations=4
  run vbd_auto_8 $level $dur --set solver.integrator=vbd --set solver.substeps=\"auto\" --set solver.iterations=8
  run xpbd_auto $level $dur --set solver.integrator=xpbd --set solver.substeps=\"auto\"
done
# The stiff body: its own reference (rk45 at 1e-8, about 6 s), then the same runs; run() reads ref$level.csv, so the
# stiff runs print their errors here.
stiff=(--set bodies.0.mesh=\"icosphere:3\" --set duration=1.2 --set solver.threads=1 --set bodies.0.stiffness=1e6)
[ -f $out/ref3_stiff.csv ] || $B simulate scenes/bounce_smooth.json "${stiff[@]}" --set solver.integrator=rk45 \
  --set solver.tolerance=1e-8 --csv $out/ref3_stiff.csv >/dev/null
stiff_run() { # name extra-args...
  local name=$1; shift
  local t=$( { /usr/bin/time -f "%U" $B simulate scenes/bounce_smooth.json "${stiff[@]}" \
    --csv $out/stiff_$name.csv "$@" >/dev/null; } 2>&1 | tail -1)
  echo "stiff_$name L3 cpu_s=$t per_sim_s=$(python3 -c "print(round($t/1.2,4))")" \
       "first_impact:$(python3 bench/csv_errors.py $out/ref3_stiff.csv $out/stiff_$name.csv 1.2 | cut -d: -f2)"
}
stiff_run vbd_auto_4 --set solver.integrator=vbd --set solver.substeps=\"auto\"
stiff_run xpbd_auto --set solver.integrator=xpbd --set solver.substeps=\"auto\"
# The breathing ball: no contact, so every integrator on its own; the reference is rk45 at 1e-8.
S=bench/peers/breathing.json
[ -f $out/breathing_ref.csv ] || $B simulate $S --set solver.tolerance=1e-8 --csv $out/breathing_ref.csv >/dev/null
breathe() { # name extra-args...
  local name=$1; shift
  local t=$( { /usr/bin/time -f "%U" $B simulate $S --csv $out/breathing_$name.csv "$@" >/dev/null; } 2>&1 | tail -1)
  echo "breathing_$name L3 cpu_s=$t per_sim_s=$t" \
       "whole:$(python3 bench/csv_errors.py $out/breathing_ref.csv $out/breathing_$name.csv | cut -d: -f2)"
}
for rate in 60 240 960; do
  dt=$(python3 -c "print(1/$rate)")
  breathe vbd_${rate}_4 --set solver.integrator=vbd --set solver.dt=$dt --set solver.iterations=4
done
