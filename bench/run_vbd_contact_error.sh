#!/bin/bash
# Usage: bench/run_vbd_contact_error.sh (after scripts/build; about 8 min on 2 cores once the references exist, which
# are bench/run_vbd_bounce.sh's and are made here if missing: about 15 min more, most of it rk45's level-5 one).
# Where vbd's error on the smooth-floor bounce (scenes/bounce_smooth.json, 0-1.2 s: the fall and the first impact)
# comes from: the sweeps (4, vbd's default, against 16, converged within 0.1 cm) and the impacts' steps
# (solver.impact_phase 0.5, the default, against 0.25 and 0.125), with the floor's friction (the scene's, 0.5) and
# without (floor.friction 0, against an rk45 reference made without it). Errors against rk45 at tolerance 1e-8
# (bench/csv_errors.py: worst volume error and worst centre-of-mass distance); times: user CPU s of one thread per
# simulated s.
source "$(dirname "$0")/vbd_bounce_common.sh"
dur=1.2
for level in 3 4 5; do
  make_reference $level $dur
  for phase in 0.5 0.25 0.125; do for it in 4 16; do
    run contact_L${level}_phase${phase}_it$it $level $dur --set solver.integrator=\"vbd\" \
      --set solver.iterations=$it --set solver.impact_phase=$phase
  done; done
done
# Without friction: the same runs against a reference without it (levels 3 and 4; rk45's level 5 takes 15 min).
for level in 3 4; do
  [ -f $out/ref${level}_frictionless.csv ] || $B simulate scenes/bounce_smooth.json \
    --set bodies.0.mesh=\"icosphere:$level\" --set duration=$dur --set floor.friction=0 \
    --set solver.integrator=rk45 --set solver.tolerance=1e-8 --set solver.threads=1 \
    --csv $out/ref${level}_frictionless.csv > /dev/null
  for phase in 0.5 0.125; do for it in 4 16; do
    REF=$out/ref${level}_frictionless.csv run frictionless_L${level}_phase${phase}_it$it $level $dur \
      --set floor.friction=0 --set solver.integrator=\"vbd\" --set solver.iterations=$it --set solver.impact_phase=$phase
  done; done
done
