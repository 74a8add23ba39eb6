#!/bin/bash
# Usage: bench/run_vbd_bounce.sh (after scripts/build; about 15 min on 2 cores, most of it rk45's level-5 reference).
# vbd against xpbd auto on the smooth-floor bounce (scenes/bounce_smooth.json): icosphere:3 over 3 s, icosphere:5
# over 1.2 s (the fall, the first impact and the rebound). Errors against rk45 at tolerance 1e-8 (bench/csv_errors.py:
# worst volume error and worst centre-of-mass distance, through the first impact, 0-1.2 s, and over the whole run);
# times: user CPU s of one thread (solver.threads=1) per simulated s, one run each.
source "$(dirname "$0")/vbd_bounce_common.sh"
for level in 3 5; do
  dur=3; [ $level = 5 ] && dur=1.2
  make_reference $level $dur
  run xpbd_auto $level $dur --set solver.integrator=xpbd --set solver.substeps=\"auto\"
  run vbd_auto $level $dur --set solver.integrator=vbd --set solver.substeps=\"auto\"
  for s in 1 2 4; do for it in 4 8; do
    run vbd_${s}_${it} $level $dur --set solver.integrator=vbd --set solver.dt=0.001 --set solver.substeps=$s \
      --set solver.iterations=$it
  done; done
done
