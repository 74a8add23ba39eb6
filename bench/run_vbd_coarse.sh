#!/bin/bash
# Usage: bench/run_vbd_coarse.sh (after scripts/build; its references are bench/run_vbd_bounce.sh's, made here if
# missing: about 15 min on 2 cores, most of it rk45's level-5 reference; the runs themselves about 5 min).
# vbd with and without its coarse level (solver.coarse_space cells) on the smooth-floor bounce
# (scenes/bounce_smooth.json), substeps "auto", 2, 3, 4 and 8 sweeps: icosphere:3 over 3 s, icosphere:5 over 1.2 s.
# Errors against rk45 at tolerance 1e-8 (bench/csv_errors.py: worst volume error and worst centre-of-mass distance
# through the first impact, 0-1.2 s, and over the whole run); times: user CPU s of one thread per simulated s.
source "$(dirname "$0")/vbd_bounce_common.sh"
for level in 3 5; do
  dur=3; [ $level = 5 ] && dur=1.2
  make_reference $level $dur
  for cells in 0 32 64 128; do for it in 2 3 4 8; do
    run vbd_coarse${cells}_$it $level $dur --set solver.integrator=vbd --set solver.substeps=\"auto\" \
      --set solver.iterations=$it --set solver.coarse_space=$cells
  done; done
done
