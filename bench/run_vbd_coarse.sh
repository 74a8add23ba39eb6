#!/bin/bash
# Usage: bench/run_vbd_coarse.sh (after scripts/build; its references are bench/run_vbd_bounce.sh's, made here if
# missing: about 15 min on 2 cores, most of it rk45's level-5 reference; the runs themselves about 5 min).
# vbd with and without its coarse level (solver.coarse_space cells) on the smooth-floor bounce
# (scenes/bounce_smooth.json), substeps "auto", 2, 3, 4 and 8 sweeps: icosphere:3 over 3 s, icosphere:5 over 1.2 s.
# Errors against rk45 at tolerance 1e-8 (bench/csv_errors.py: worst volume error and worst centre-of-mass distance
# through the first impact, 0-1.2 s, and over the whole run); times: user CPU s of one thread per simulated s.
cd "$(dirname "$0")/.."
B=build/softbody
out=${OUT:-out/vbd_bounce}
mkdir -p "$out"
run() { # name level duration extra-args...
  local name=$1 level=$2 dur=$3; shift 3
  local t=$( { /usr/bin/time -f "%U" $B simulate scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" \
    --set duration=$dur --set solver.threads=1 --csv $out/$name.csv "$@" >/dev/null; } 2>&1 | tail -1)
  echo "$name L$level cpu_s=$t per_sim_s=$(python3 -c "print(round($t/$dur,4))")" \
       "first_impact:$(python3 bench/csv_errors.py $out/ref$level.csv $out/$name.csv 1.2 | cut -d: -f2)" \
       "whole:$(python3 bench/csv_errors.py $out/ref$level.csv $out/$name.csv | cut -d: -f2)"
}
for level in 3 5; do
  dur=3; [ $level = 5 ] && dur=1.2
  [ -f $out/ref$level.csv ] || $B simulate scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" \
    --set duration=$dur --set solver.integrator=rk45 --set solver.tolerance=1e-8 --set solver.threads=1 \
    --csv $out/ref$level.csv > /dev/null
  for cells in 0 32 64 128; do for it in 2 3 4 8; do
    run vbd_coarse${cells}_$it $level $dur --set solver.integrator=vbd --set solver.substeps=\"auto\" \
      --set solver.iterations=$it --set solver.coarse_space=$cells
  done; done
done
