#!/usr/bin/env bash
# Issue 13's benchmark of what the user waits for: the bounce at icosphere levels 3, 5 and 6, every integrator
# at its automatic step (newton and implicit at 1/60 and 1/240 s) and Bullet's btSoftBody at 1/60 and 1/240 s,
# CPU (and wall) time per simulated second on one thread against the error from a converged rk45 run; writes
# docs/large_steps_bounce.{csv,png} (or into the folder given as $1). About 45 min of one core here.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-docs}"
[ -x build/bench_large_steps ] || cmake --build build --target bench_large_steps
csv="$out/large_steps_bounce.csv"
start=$(date +%s)
# Level 3 (642 vertices): the whole 3 s (fall, impact, rebound, roll); the reference rk45 at tolerance 1e-8,
# checked against 1e-9 and 1e-7.
build/bench_large_steps --levels 3 --duration 3 --reference-tolerances 1e-8,1e-9,1e-7 > "$csv"
# Level 5 (10242 vertices) costs about 8x level 3 per simulated second for the explicit methods and newton about
# 50x: the first 1 s (the first touch is at 0.64 s), newton at 1/60 s only.
build/bench_large_steps --levels 5 --duration 1 --reference-tolerances 1e-8,1e-7 --newton-rates 60 \
  --no-header >> "$csv"
# Level 6 (40962 vertices): the first 0.75 s (fall and the start of the impact), one reference, the cheaper
# methods only (rk4, verlet, rk45 and newton would take 5 to 15 min each here).
build/bench_large_steps --levels 6 --duration 0.75 --reference-tolerances 1e-8 --rates 60 \
  --integrators euler,symplectic,implicit,xpbd --friction-too '' --no-header >> "$csv"
gnuplot -e "cd '$out'" docs/large_steps_bounce.gp
echo "bench/run_large_steps.sh: $(( $(date +%s) - start )) s in all"
