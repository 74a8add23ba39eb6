#!/usr/bin/env bash
# Render ms per frame on each GL backend of the build (EGL, OSMesa): scenes/bounce.json at 640×480 and
# 1280×720 with shadows and 4× MSAA, REPS runs per case alternating backends (the machine is shared), the
# medians of the summary line's stages. Writes OUT/perf_render_backends.csv and prints a Markdown table.
#   bench/render_backends.sh [REPS] [OUT_DIR]   (defaults 3, docs/)
set -euo pipefail
cd "$(dirname "$0")/.."
reps="${1:-3}"; out="${2:-docs}"
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
csv="$out/perf_render_backends.csv"
echo "backend,width,height,run,frames,fps_end_to_end,simulate_ms,render_ms,read_back_ms,encode_ms" > "$csv"
for size in 640x480 1280x720; do
  w=${size%x*}; h=${size#*x}
  for run in $(seq 1 "$reps"); do
    for backend in egl osmesa; do
      line=$(SOFTBODY_GL=$backend build/softbody render scenes/bounce.json -o "$tmp/frames" --set duration=1.0 \
        --set render.width=$w --set render.height=$h --set render.figure_frames=0 2>/dev/null | grep 'fps end to end')
      row=$(python3 bench/parse_render_summary.py "$w" "$h" true 4 "$line" | cut -d, -f1,2,5-)
      echo "$backend,${row%%,*},$(echo "$row" | cut -d, -f2),$run,$(echo "$row" | cut -d, -f3-)" >> "$csv"
    done
  done
done
python3 - "$csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| size | backend | render ms/frame | read-back ms/frame | end-to-end fps | runs |")
print("|---|---|---|---|---|---|")
for size in sorted({(int(r["width"]), int(r["height"])) for r in rows}):
    for backend in ("egl", "osmesa"):
        sel = [r for r in rows if (int(r["width"]), int(r["height"])) == size and r["backend"] == backend]
        if not sel:
            continue
        med = lambda k: statistics.median(float(r[k]) for r in sel)
        print("| %dx%d | %s | %.1f | %.1f | %.1f | %d |" % (*size, backend, med("render_ms"), med("read_back_ms"),
                                                          med("fps_end_to_end"), len(sel)))
PY
