#!/bin/bash
# Usage: bench/run_vbd_threads.sh (after scripts/build; about 6 min on 2 cores with REPS=5).
# vbd on two threads against one: the smooth-floor bounce (scenes/bounce_smooth.json) with vbd's defaults at
# icosphere:5 over 1.2 s and icosphere:6 over 0.75 s (the fall and the first impact). Wall s per simulated s, the
# median of REPS runs with one and two threads interleaved, their ratio, and whether the two CSVs are the same bytes;
# for the whole process (the mesh, the body and vbd's colouring built on one thread included) and for its steps alone
# (`--profile`'s step phase, as bench/run_peers.sh times softbody).
# Run it on an otherwise idle machine: two threads need both cores. Where other guests slow the machine down in bursts
# (one thread's runs spreading by half or more), the fastest runs' ratio is the steadier figure.
source "$(dirname "$0")/vbd_bounce_common.sh"
REPS=${REPS:-5}
median() { python3 -c "import statistics, sys; print(statistics.median(float(v) for v in sys.argv[1:]))" "$@"; }
least() { python3 -c "import sys; print(min(float(v) for v in sys.argv[1:]))" "$@"; }
for level in 5 6; do
  dur=1.2; [ $level = 6 ] && dur=0.75
  declare -A walls=([1]="" [2]="") steps=([1]="" [2]="")
  for rep in $(seq "$REPS"); do
    for threads in 1 2; do
      log=$out/threads_L${level}_$threads.log
      { /usr/bin/time -f "%e" $B simulate scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" \
        --set duration=$dur --set solver.integrator=\"vbd\" --set solver.threads=$threads --profile \
        --csv $out/threads_L${level}_$threads.csv >/dev/null; } 2>$log
      walls[$threads]="${walls[$threads]} $(tail -1 $log)"
      steps[$threads]="${steps[$threads]} $(awk '$1 == "step" {print $2}' $log)"
    done
  done
  one=$(median ${walls[1]}); two=$(median ${walls[2]})
  one_steps=$(median ${steps[1]}); two_steps=$(median ${steps[2]})
  same=different; cmp -s $out/threads_L${level}_1.csv $out/threads_L${level}_2.csv && same=same
  echo "L$level ${dur}s: process: one thread ${one} s (runs:${walls[1]}), two threads ${two} s (runs:${walls[2]})," \
       "per simulated s $(python3 -c "print(round($one/$dur,3), round($two/$dur,3))"), speed-up" \
       "$(python3 -c "print(round($one/$two,2))"); steps: one thread ${one_steps} s (runs:${steps[1]}), two threads" \
       "${two_steps} s (runs:${steps[2]}), speed-up $(python3 -c "print(round($one_steps/$two_steps,2))");" \
       "steps' fastest runs $(least ${steps[1]}) s and $(least ${steps[2]}) s, speed-up" \
       "$(python3 -c "print(round($(least ${steps[1]})/$(least ${steps[2]}),2))"); CSV bytes $same"
done
