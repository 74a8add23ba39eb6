#!/bin/bash
# Usage: bench/run_contact_limit.sh [LEVEL...] (after scripts/build; level 3 takes about 5 s, level 5 about 75 s per
# reference on 2 cores). How far a stiffer smooth floor moves the bounce's converged path through the first impact:
# scenes/bounce_smooth.json (0-1.2 s) by rk45 at tolerance 1e-8 with the floor's time constant τ at 2 ms (the scene's),
# 1, 0.5 and 0.25 ms (at level 3; 1 and 0.5 ms at the others), its smoothing at 2 mm instead of 1 cm and its slip speed
# at 0.01 instead of 0.1 m/s (level 3). Each line: the worst volume difference and the worst centre-of-mass distance
# from the scene's own floor (bench/csv_errors.py). τ → 0 is a hard floor, the limit a contact solved as a constraint
# would take: where it is more than the accuracy goal's 1 cm away, such a contact is another model than the reference's.
cd "$(dirname "$0")/.."
B=build/softbody
out=${OUT:-out/contact_limit}
mkdir -p "$out"
reference() { # level name extra-args...
  local level=$1 name=$2; shift 2
  [ -f "$out/L${level}_$name.csv" ] || $B simulate scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" \
    --set duration=1.2 --set solver.integrator=rk45 --set solver.tolerance=1e-8 --set solver.threads=1 \
    --csv "$out/L${level}_$name.csv" "$@" > /dev/null 2>&1
}
for level in "${@:-3}"; do
  reference $level tau2ms
  variants="tau1ms tau0.5ms"
  [ $level = 3 ] && variants="$variants tau0.25ms smoothing2mm slip0.01"
  for v in $variants; do
    case $v in
      tau*) reference $level $v --set floor.time_constant=$(python3 -c "print(float('${v#tau}'.rstrip('ms'))/1000)") ;;
      smoothing2mm) reference $level $v --set floor.smoothing=0.002 ;;
      slip0.01) reference $level $v --set floor.slip_speed=0.01 ;;
    esac
    echo "level $level, $v against tau2ms:$(python3 bench/csv_errors.py $out/L${level}_tau2ms.csv $out/L${level}_$v.csv 1.2 | cut -d: -f2)"
  done
done
