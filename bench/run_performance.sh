#!/usr/bin/env bash
# The performance benchmark: step cost per integrator and size, the skipped passes, Bullet side by side,
# the render pipeline per stage, and peak memory. Writes CSVs and the results section of docs/performance.md.
#   bench/run_performance.sh [--quick] [OUT_DIR]   (default docs/; --quick: shorter runs, for a smoke test)
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
if [ "${1:-}" = "--quick" ]; then quick=1; shift; fi
out="${1:-docs}"
mkdir -p "$out"
[ -x build/bench_step ] && [ -x build/softbody ] || scripts/build
start=$(date +%s)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. Simulation: every integrator at levels 1-6, skipped passes at level 5, ours and Bullet at levels 3 and 5
#    alternating. Repetitions give medians (the machine is shared).
if [ $quick = 1 ]; then reps=1; min_time=0.05; else reps=3; min_time=0.3; fi
build/bench_step --benchmark_repetitions=$reps --benchmark_min_time=$min_time \
  --benchmark_report_aggregates_only=$([ $reps -gt 1 ] && echo true || echo false) \
  --benchmark_out="$tmp/step.json" --benchmark_out_format=json

# 2. Render pipeline: bounce.json at two sizes, shadows and MSAA off and on. The summary line gives ms per
#    frame of each stage and the end-to-end fps, all from the same run.
duration=3.0
if [ $quick = 1 ]; then duration=0.5; fi
echo "width,height,shadows,msaa,frames,fps_end_to_end,simulate_ms,render_ms,read_back_ms,encode_ms" > "$tmp/render.csv"
for size in 640x480 1280x720; do
  for shadows in false true; do
    for msaa in 1 4; do
      w=${size%x*}; h=${size#*x}
      line=$(build/softbody render scenes/bounce.json -o "$tmp/frames" --set duration=$duration \
        --set render.width=$w --set render.height=$h --set render.shadows=$shadows --set render.msaa=$msaa \
        --set render.figure_frames=0 | grep 'fps end to end')
      echo "$line"
      python3 bench/parse_render_summary.py "$w" "$h" "$shadows" "$msaa" "$line" >> "$tmp/render.csv"
    done
  done
done

# 3. Peak memory: a level-6 body (40962 vertices) rendered at 1920x1080 with shadows and MSAA (2 frames
#    after the first; dt small enough for level 6).
/usr/bin/time -f '%M' -o "$tmp/rss.txt" build/softbody render scenes/bounce.json -o "$tmp/frames6" \
  --set bodies.0.mesh=icosphere:6 --set render.width=1920 --set render.height=1080 --set duration=0.0667 \
  --set solver.dt=6e-6 --set render.figure_frames=0 > /dev/null
echo "case,peak_rss_MiB" > "$tmp/memory.csv"
echo "icosphere:6 at 1920x1080 with shadows and msaa 4,$(awk '{printf "%.1f", $1 / 1024}' "$tmp/rss.txt")" >> "$tmp/memory.csv"

python3 bench/performance_report.py "$tmp/step.json" "$tmp/render.csv" "$tmp/memory.csv" "$out" \
  "$(( $(date +%s) - start ))"
echo "bench/run_performance.sh: $(( $(date +%s) - start )) s in all; results in $out/performance.md"
