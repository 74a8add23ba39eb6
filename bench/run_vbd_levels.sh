#!/bin/bash
# Usage: bench/run_vbd_levels.sh (after scripts/build; makes its rk45 references if missing: level 4 about 1 min,
# level 6 about 20 min on one core; the runs themselves about 6 min).
# Where vbd stands between and above bench/run_vbd_bounce.sh's levels: the smooth-floor bounce
# (scenes/bounce_smooth.json) at icosphere:4 over 1.2 s and icosphere:6 over 0.75 s (the fall and the first impact),
# vbd at 2-16 sweeps with and without 128 coarse cells, and xpbd at its automatic substeps. Errors against rk45 at
# tolerance 1e-8 (bench/csv_errors.py: worst volume error and worst centre-of-mass distance); times: user CPU s of one
# thread per simulated s.
source "$(dirname "$0")/vbd_bounce_common.sh"
make_reference 4 1.2
for it in 2 4 8 16; do for cells in 0 128; do
  run vbd_L4_${it}_$cells 4 1.2 --set solver.integrator=vbd --set solver.iterations=$it --set solver.coarse_space=$cells
done; done
run xpbd_L4_auto 4 1.2 --set solver.integrator=xpbd --set solver.substeps=\"auto\"
make_reference 6 0.75
for it in 4 8; do for cells in 0 128; do
  run vbd_L6_${it}_$cells 6 0.75 --set solver.integrator=vbd --set solver.iterations=$it --set solver.coarse_space=$cells
done; done
run xpbd_L6_auto 6 0.75 --set solver.integrator=xpbd --set solver.substeps=\"auto\"
