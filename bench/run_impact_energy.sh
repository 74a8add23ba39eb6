#!/bin/bash
# Usage: bench/run_impact_energy.sh [LEVEL] (after scripts/build; about 3 s at icosphere:3, 1 min at :4).
# Where the smooth-floor bounce's energy goes through its first impact (scenes/bounce_smooth.json with the floor's
# dashpot and friction off: restitution 1, friction 0, so that only the springs' dampers and the integrator take
# energy): rk45 at tolerance 1e-8 against vbd ("converge") with its impact steps at omega h <= 0.125 to 4
# (solver.impact_phase). bench/impact_energy.py prints the centre of mass's energy at 0.6 s (falling, before the
# touch-down) and 1.0 s (rising, after it), the total energy's loss and the height at 1.2 s.
# Longer impact steps (vbd with impact_phase 16, or 1e6: the frame's 33 ms step through the impact) need a build whose
# src/scene/scene_keys.cpp allows impact_phase above 4; pass it as WIDE=path/to/softbody to add those rows.
cd "$(dirname "$0")/.."
B=build/softbody
level=${1:-3}
out=${OUT:-out/impact_energy}
mkdir -p "$out"
scene=(scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" --set duration=1.2 --set solver.threads=1
       --set floor.restitution=1 --set floor.friction=0)
runs=($out/L${level}_rk45.csv)
$B simulate "${scene[@]}" --set solver.integrator=\"rk45\" --set solver.tolerance=1e-8 --csv ${runs[0]} > /dev/null
vbd() { # binary phase
  local csv=$out/L${level}_vbd_phase$2.csv
  $1 simulate "${scene[@]}" --set solver.integrator=\"vbd\" --set solver.iterations=\"converge\" \
    --set solver.impact_phase=$2 --csv $csv > /dev/null 2>&1
  runs+=($csv)
}
for phase in 0.125 0.5 1 2 4; do vbd $B $phase; done
if [ -n "$WIDE" ]; then for phase in 16 1e6; do vbd "$WIDE" $phase; done; fi
python3 bench/impact_energy.py 0.6 1.0 "${runs[@]}"
