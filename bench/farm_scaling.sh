#!/usr/bin/env bash
# What a farm render costs: the simulation task (simulate --cache) against the render tasks (render
# --from-cache), per frame, for the bounce at 1920x1080 and an icosphere:6 body, and what that makes of N
# nodes: the render tasks split N ways, the simulation does not (Amdahl). With SLURM_CONF set to a running
# cluster (tests/farm/local_cluster.sh start DIR), also times a 4-chunk scripts/slurm-render of the bounce.
#   bench/farm_scaling.sh [OUT_DIR]     (default out/farm_scaling; about 5 minutes here)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/farm_scaling}
softbody=${SOFTBODY:-build/softbody}
rm -rf "$out"; mkdir -p "$out"

now() { date +%s.%N; }
seconds_since() { awk -v a="$(now)" -v b="$1" 'BEGIN {printf "%.3f", a - b}'; }

# measure NAME SCENE [--set ...]: prints "NAME frames sim_s render_s"
measure() {
  local name=$1 scene=$2; shift 2
  local dir="$out/$name"
  local start; start=$(now)
  "$softbody" simulate "$scene" "$@" --cache "$dir/cache" --csv "$dir/simulation.csv" > "$dir.simulate.log" 2>&1
  local sim_s; sim_s=$(seconds_since "$start")
  start=$(now)
  "$softbody" render "$scene" "$@" -o "$dir" --from-cache "$dir/cache" > "$dir.render.log" 2>&1
  local render_s; render_s=$(seconds_since "$start")
  local frames; frames=$(ls "$dir" | grep -c '^frame_.*\.png$')
  local state_kb; state_kb=$(( $(stat -c %s "$dir/cache/state_000000.bin") / 1000 ))
  echo "$name $frames $sim_s $render_s $state_kb"
}

hd=(--set render.width=1920 --set render.height=1080)
{
  measure bounce_1080p scenes/bounce.json "${hd[@]}"
  measure icosphere6_1080p scenes/bounce.json "${hd[@]}" --set bodies.0.mesh=icosphere:6 \
    --set solver.integrator=symplectic --set solver.dt=auto --set duration=0.5
} > "$out/measurements.txt"

echo "| scene | frames | simulation task s | render s per frame | state kB per frame | best speedup (N → ∞) | N for 80 % of it |"
echo "|---|---|---|---|---|---|---|"
while read -r name frames sim_s render_s state_kb; do
  awk -v n="$name" -v f="$frames" -v s="$sim_s" -v r="$render_s" -v kb="$state_kb" 'BEGIN {
    total = s + r; best = total / s;
    for (N = 1; N <= 4096; N *= 2) { if (total / (s + r / N) >= 0.8 * best) break }
    printf "| %s | %d | %.1f | %.3f | %d | %.1f× | %d |\n", n, f, s, r / f, kb, best, N }'
done < "$out/measurements.txt"

if [ -n "${SLURM_CONF:-}" ]; then
  start=$(now)
  "$softbody" render scenes/bounce.json "${hd[@]}" -o "$out/local" > "$out/local.log" 2>&1
  local_s=$(seconds_since "$start")
  start=$(now)
  SOFTBODY="$softbody" scripts/slurm-render scenes/bounce.json -o "$out/slurm" --chunk 23 --wait "${hd[@]}" > "$out/slurm.log" 2>&1
  slurm_s=$(seconds_since "$start")
  printf "\nbounce 1920x1080, 91 frames: local render (with video off) %.1f s; 4-chunk Slurm render on this node, simulation + chunks + video assembly, %.1f s\n" "$local_s" "$slurm_s"
fi
