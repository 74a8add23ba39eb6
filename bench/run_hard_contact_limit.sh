#!/bin/bash
# Usage: bench/run_hard_contact_limit.sh [LEVEL] (after scripts/build; about 1 min at icosphere:3, 10 at :4).
# The smooth-floor bounce (scenes/bounce_smooth.json, 0-1.2 s: the fall and the first impact) against the hard
# contact's limit: rk45 references at tolerance 1e-8 with the floor's time constant tau at 2 (the scene's), 1, 0.5 and
# 0.25 ms, each one's distance from the 0.25 ms path (they converge linearly in tau), the limit extrapolated as
# 2 x path(0.25 ms) - path(0.5 ms) (bench/extrapolate_csv.py), and vbd against it: its defaults and "converge" at
# impact_phase 0.5 to 4 and at tau 2, 0.5 and 0.1 ms. Errors: bench/csv_errors.py (worst volume error and worst
# centre-of-mass distance through the first impact); vbd's own steps from the run's summary.
cd "$(dirname "$0")/.."
B=build/softbody
level=${1:-3}
out=${OUT:-out/hard_contact_limit}
mkdir -p "$out"
scene=(scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" --set duration=1.2 --set solver.threads=1)
for tau in 0.002 0.001 0.0005 0.00025; do
  [ -f $out/ref${level}_tau$tau.csv ] || $B simulate "${scene[@]}" --set floor.time_constant=$tau \
    --set solver.integrator=rk45 --set solver.tolerance=1e-8 --csv $out/ref${level}_tau$tau.csv > /dev/null
done
for tau in 0.002 0.001 0.0005; do
  echo "rk45 tau $tau against tau 0.00025:$(python3 bench/csv_errors.py $out/ref${level}_tau0.00025.csv \
    $out/ref${level}_tau$tau.csv 1.2 | cut -d: -f2)"
done
hard=$out/ref${level}_hard.csv
python3 bench/extrapolate_csv.py $out/ref${level}_tau0.0005.csv $out/ref${level}_tau0.00025.csv $hard
for tau in 0.002 0.0005 0.0001; do for phase in 0.5 1 2 4; do for it in 4 '"converge"'; do
  name=vbd${level}_tau${tau}_phase${phase}_${it//\"/}
  steps=$($B simulate "${scene[@]}" --set floor.time_constant=$tau --set solver.integrator=\"vbd\" \
    --set solver.iterations=$it --set solver.impact_phase=$phase --csv $out/$name.csv 2>/dev/null |
    sed -nE 's/.*\(vbd; ([0-9]+) of its own.*/\1/p')
  echo "vbd tau $tau impact_phase $phase iterations $it: $steps steps;" \
       "against the hard limit$(python3 bench/csv_errors.py $hard $out/$name.csv 1.2 | cut -d: -f2)"
done; done; done
