#!/usr/bin/env bash
# The bounce against the peers, in one run: scenes/bounce_smooth.json (k 1000 N/m, c 1 N·s/m, nRT 200 J, 1 kg, the
# smooth floor; thrown sideways at 2 m/s from 3 m) at icosphere levels 3 and 5 over 1.2 s and 6 over 0.75 s (the fall
# and the first impact), softbody's defaults for vbd and xpbd beside Jolt Physics (bench/peers/jolt, the same ball and
# gas, its own floor contact) at 1/60 and 1/240 s with 5 iterations (its default) and at 1/240 s with 20, and Bullet
# (build/bench_peers_bullet, its own links) at 1/240 s with 4 position iterations.
# CPU s of one thread per simulated s (softbody: the process's user time; Jolt: its Update calls' thread time;
# Bullet: its stepping's), the worst volume error and centre-of-mass distance through the first impact against
# softbody's rk45 reference at tolerance 1e-8 (bench/vbd_bounce_common.sh makes it once; level 6's takes about 15
# minutes), and the largest volume over the start's. The contact models differ, so the peers' errors through the
# impact include their models' differences; their volume in flight (the largest volume) is the same model's.
# Usage: JOLT_PREFIX=/path/to/installed/jolt bench/run_bounce_table.sh [LEVELS]     (default "3 5 6"; after
# scripts/build). Without JOLT_PREFIX, Jolt's rows are skipped.
# Writes out/vbd_bounce/bounce_table.csv and prints it as a Markdown table.
set -euo pipefail
source "$(dirname "$0")/vbd_bounce_common.sh"  # cd to the repository, B, out, make_reference
levels="${1:-3 5 6}"
scene=scenes/bounce_smooth.json
jolt=""
[ -z "${JOLT_PREFIX:-}" ] || jolt=$(bench/peers/build_jolt.sh)
[ -x build/bench_peers_bullet ] || cmake --build build --target bench_peers_bullet
table=$out/bounce_table.csv
echo "level,run,cpu_per_sim_s,volume_error_pct,com_error_cm,volume_max" > $table
for level in $levels; do
  dur=1.2
  [ "$level" = 6 ] && dur=0.75
  make_reference $level $dur
  row() { # label cpu_per_sim_s csv
    local errors vmax
    vmax=$(python3 -c "import csv,sys; v=[float(r['volume']) for r in csv.DictReader(open(sys.argv[1]))]
print(round(max(v)/v[0],4))" $3)
    errors=$(python3 bench/csv_errors.py $out/ref$level.csv $3 1.2 | sed -E 's/.*vol ([^ ]+) %  com ([^ ]+) cm/\1,\2/')
    echo "$level,$1,$2,$errors,$vmax" >> $table
  }
  softbody() { # file-name label --set...
    local name=$1 label=$2 t; shift 2
    t=$( { /usr/bin/time -f "%U" $B simulate $scene --set bodies.0.mesh=\"icosphere:$level\" --set duration=$dur \
      --set solver.threads=1 --csv $out/table_${level}_$name.csv "$@" > /dev/null; } 2>&1 | tail -1)
    row "$label" "$(python3 -c "print(round($t/$dur,4))")" $out/table_${level}_$name.csv
  }
  softbody vbd "softbody vbd (defaults)" --set solver.integrator=vbd --set 'solver.substeps="auto"'
  softbody xpbd "softbody xpbd (substeps auto)" --set solver.integrator=xpbd --set 'solver.substeps="auto"'
  if [ -n "$jolt" ]; then
    for setting in "60 5" "240 5" "240 20"; do
      read -r rate it <<< "$setting"
      csv=$out/table_${level}_jolt_${rate}_$it.csv
      cpu=$($jolt --level $level --dt 1/$rate --iterations $it --seconds $dur --pressure 200 --linear-damping 0 \
        --frames-csv $csv | sed -nE 's/^RESULT .* cpu_per_sim_s=([^ ]+) .*/\1/p')
      row "Jolt 1/$rate s with $it iterations" "$cpu" $csv
    done
  fi
  csv=$out/table_${level}_bullet_240_4.csv
  cpu=$(build/bench_peers_bullet $scene $level 240 4 $csv | sed -nE 's/^cpu_per_sim_s=//p')
  row "Bullet 1/240 s with 4 iterations" "$cpu" $csv
done
python3 - "$table" <<'EOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| level | run | CPU s per simulated s | volume error | centre of mass | largest volume |")
print("|---|---|---|---|---|---|")
for r in rows:
    print(f"| {r['level']} | {r['run']} | {r['cpu_per_sim_s']} | {r['volume_error_pct']} % | {r['com_error_cm']} cm | "
          f"{r['volume_max']} |")
EOF
