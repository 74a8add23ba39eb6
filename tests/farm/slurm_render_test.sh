#!/usr/bin/env bash
# The farm test (ctest label `farm`): installs Slurm, munge and GNU parallel where missing, starts a
# single-node cluster on this machine (tests/farm/local_cluster.sh), renders a small scene with
# scripts/slurm-render in 4 chunks, and checks that every frame is byte-identical to a local render and that
# the video has every frame; then the GNU parallel recipe of docs/guide/caches-resume-farms.md, and a two-value wedge. The cluster is
# stopped at the end whatever happens. Exit 77 (ctest: skipped) when the daemons cannot start (no root).
#   slurm_render_test.sh SOFTBODY SOURCE_DIR SCRATCH_DIR
set -euo pipefail
softbody=$1; source_dir=$2; scratch=$3
rm -rf "$scratch"; mkdir -p "$scratch"

if [ "$(id -u)" -eq 0 ]; then
  missing=()
  for package in slurm-wlm munge parallel; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "installing ${missing[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null 2>&1 ||
      { apt-get update -qq >/dev/null 2>&1 && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; } ||
      { echo "SKIP: could not install ${missing[*]}"; exit 77; }
  fi
fi

cluster="$scratch/cluster"
trap '"$source_dir/tests/farm/local_cluster.sh" stop "$cluster"' EXIT
status=0
conf=$("$source_dir/tests/farm/local_cluster.sh" start "$cluster") || status=$?
if [ $status -eq 77 ]; then exit 77; fi
[ $status -eq 0 ] || { echo "FAIL: the cluster did not start"; exit 1; }
export "$conf"

scene="$source_dir/scenes/bounce.json"
small=(--set duration=0.5 --set render.width=160 --set render.height=120)  # frames 0..15
started=$(date +%s.%N)
"$softbody" render "$scene" "${small[@]}" -o "$scratch/local" --video "$scratch/local/bounce.mp4" >/dev/null
local_s=$(awk -v a="$(date +%s.%N)" -v b="$started" 'BEGIN {printf "%.1f", a - b}')

started=$(date +%s.%N)
SOFTBODY="$softbody" "$source_dir/scripts/slurm-render" "$scene" -o "$scratch/farm" --chunk 4 --wait "${small[@]}"
farm_s=$(awk -v a="$(date +%s.%N)" -v b="$started" 'BEGIN {printf "%.1f", a - b}')

failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

frames=$(ls "$scratch/local" | grep -c '^frame_.*\.png$')
check "the local render wrote 16 frames (found $frames)" "[ $frames -eq 16 ]"
check "4 render chunks ran" "[ \$(ls '$scratch/farm/slurm' | grep -c '^render_[0-9]*\.log\$') -eq 4 ]"
identical=0
for f in "$scratch"/local/frame_*.png; do cmp -s "$f" "$scratch/farm/$(basename "$f")" && identical=$((identical + 1)); done
check "every farm frame is byte-identical to the local one ($identical of $frames)" "[ $identical -eq $frames ]"
video_frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$scratch/farm/bounce.mp4")
check "the farm video has every frame ($video_frames of $frames)" "[ '$video_frames' -eq $frames ]"
check "the farm's CSV equals a local simulate's" "'$softbody' simulate '$scene' ${small[*]} --csv '$scratch/local.csv' >/dev/null && cmp -s '$scratch/local.csv' '$scratch/farm/simulation.csv'"

# The GNU parallel recipe of docs/guide/caches-resume-farms.md (one machine, many cores): cache once, then frame ranges in parallel.
(
  cd "$scratch"
  "$softbody" simulate "$scene" "${small[@]}" --cache out/cache --csv out/simulation.csv >/dev/null
  seq 0 4 15 | parallel -j 2 "$softbody" render "$scene" "${small[@]}" -o out --from-cache out/cache --frames '{}-{=$_+=3=}' >/dev/null
)
identical=0
for f in "$scratch"/local/frame_*.png; do cmp -s "$f" "$scratch/out/$(basename "$f")" && identical=$((identical + 1)); done
check "every GNU parallel frame is byte-identical to the local one ($identical of $frames)" "[ $identical -eq $frames ]"

# A wedge of two stiffnesses: two variants rendered, and the sheet puts them one above the other.
SOFTBODY="$softbody" "$source_dir/scripts/slurm-render" "$scene" -o "$scratch/wedge" --wait "${small[@]}" \
  --vary bodies.0.stiffness=500,2000
size=$(ffprobe -v error -select_streams v:0 -show_entries stream=width,height -of csv=p=0 "$scratch/wedge/wedge.png" 2>/dev/null || true)
check "the wedge sheet holds 2 rows of 6 frames (6 x 320 by 2 x 240: $size)" "[ '$size' = '1920,480' ]"

echo "local render $local_s s, 4-chunk Slurm render (simulate + 4 chunks + assembly) $farm_s s"
[ $failures -eq 0 ] || exit 1
echo "farm test: all checks passed"
