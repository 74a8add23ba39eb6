#!/bin/bash
# Usage: bench/run_stiff_floor_sweeps.sh [LEVEL] (after scripts/build; about 30 s at icosphere:3, 5 min at 4).
# vbd's sweeps on a floor stiffer than the scene's: scenes/bounce_smooth.json (0-1.2 s, the fall and the first impact)
# with the floor's time constant tau at 2 (the scene's), 1, 0.5 and 0.25 ms, each against rk45 at tolerance 1e-8 with
# the same tau (bench/run_contact_limit.sh's references, made here where missing): vbd with its default 4 sweeps,
# "converge" and "auto", its impact steps at its default impact_phase (0.5; 0.25 with "auto"). Errors:
# bench/csv_errors.py (worst volume error and centre-of-mass distance through the first impact); user CPU s of one
# thread.
cd "$(dirname "$0")/.."
B=build/softbody
level=${1:-3}
out=${OUT:-out/contact_limit}
mkdir -p "$out"
scene=(scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" --set duration=1.2 --set solver.threads=1)
for tau in 2 1 0.5 0.25; do
  tau_s=$(python3 -c "print($tau / 1000)")
  ref=$out/L${level}_tau${tau}ms.csv
  [ -f "$ref" ] || $B simulate "${scene[@]}" --set floor.time_constant=$tau_s --set solver.integrator=rk45 \
    --set solver.tolerance=1e-8 --csv "$ref" > /dev/null 2>&1
  for it in 4 '"converge"' '"auto"'; do
    name=$out/vbd${level}_tau${tau}ms_${it//\"/}.csv
    /usr/bin/time -f "%U" -o "$out/cpu_s" $B simulate "${scene[@]}" --set floor.time_constant=$tau_s \
      --set solver.integrator=\"vbd\" --set solver.iterations=$it --csv "$name" > /dev/null 2>&1
    cpu=$(tail -1 "$out/cpu_s")
    echo "level $level, tau $tau ms, iterations $it: $cpu CPU s;$(python3 bench/csv_errors.py "$ref" "$name" 1.2 |
      cut -d: -f2)"
  done
done
