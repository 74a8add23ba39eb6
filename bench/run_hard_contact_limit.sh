#!/bin/bash
# Usage: bench/run_hard_contact_limit.sh [LEVEL] (after scripts/build; about 40 s at icosphere:3).
# The smooth-floor bounce (scenes/bounce_smooth.json, 0-1.2 s: the fall and the first impact) against the hard
# contact's limit. bench/run_contact_limit.sh makes the rk45 references at tolerance 1e-8 with the floor's time
# constant tau at 2 (the scene's), 1 and 0.5 ms (and 0.25 ms, made here at levels other than 3); their paths converge
# linearly in tau, so the limit is 2 x path(0.25 ms) - path(0.5 ms) (bench/extrapolate_csv.py). Then vbd against it:
# its defaults and "converge" at impact_phase 0.5 to 4, at tau 2, 0.5 and 0.1 ms. Errors: bench/csv_errors.py (worst
# volume error and worst centre-of-mass distance through the first impact); vbd's own steps from the run's summary.
cd "$(dirname "$0")/.."
B=build/softbody
level=${1:-3}
out=${OUT:-out/contact_limit}
OUT=$out bench/run_contact_limit.sh $level
scene=(scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" --set duration=1.2 --set solver.threads=1)
[ -f $out/L${level}_tau0.25ms.csv ] || $B simulate "${scene[@]}" --set floor.time_constant=0.00025 \
  --set solver.integrator=rk45 --set solver.tolerance=1e-8 --csv $out/L${level}_tau0.25ms.csv > /dev/null 2>&1
hard=$out/L${level}_hard.csv
python3 bench/extrapolate_csv.py $out/L${level}_tau0.5ms.csv $out/L${level}_tau0.25ms.csv $hard
echo "level $level, tau2ms against the hard limit:$(python3 bench/csv_errors.py $hard $out/L${level}_tau2ms.csv 1.2 |
  cut -d: -f2)"
for tau in 0.002 0.0005 0.0001; do for phase in 0.5 1 2 4; do for it in 4 '"converge"'; do
  name=vbd${level}_tau${tau}_phase${phase}_${it//\"/}
  steps=$($B simulate "${scene[@]}" --set floor.time_constant=$tau --set solver.integrator=\"vbd\" \
    --set solver.iterations=$it --set solver.impact_phase=$phase --csv $out/$name.csv 2>/dev/null |
    sed -nE 's/.*\(vbd; ([0-9]+) of its own.*/\1/p')
  echo "vbd tau $tau impact_phase $phase iterations $it: $steps steps;" \
       "against the hard limit$(python3 bench/csv_errors.py $hard $out/$name.csv 1.2 | cut -d: -f2)"
done; done; done
