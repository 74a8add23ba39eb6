#!/bin/sh
# Real meshes from their original files (issue 17): each model repaired ("repair": true), simulated on a proxy
# ("resolution": N) in bench/shape_keeping.json's drop (0.3 m onto the friction floor, 2 s), without and with
# bending links; bench_shape_keeping's deviation from the rest shape and wall time for each, and the last frame
# (t = 2 s) rendered for each, side by side per model, stacked into one contact sheet (rows: models in the order
# given; left: no bending, right: "bending": {"ratio": RATIO}).
# usage: bench/real_meshes.sh OUT MODEL... with MODEL as NAME:FILE:SCALE:X,Y,Z:RESOLUTION
#   (FILE a mesh file anywhere: nothing is copied; SCALE mesh units to metres; X,Y,Z the "position" [m])
# environment: RATIO (default 3), REPAIR (the "repair" value, default true; e.g. {"parts":"largest"}), SOFTBODY (build/softbody), SHAPE_KEEPING (build/bench_shape_keeping)
set -eu
out=$1; shift
ratio=${RATIO:-3}
repair=${REPAIR:-true}
exe=${SOFTBODY:-build/softbody}
bench=${SHAPE_KEEPING:-build/bench_shape_keeping}
scene=bench/shape_keeping.json
mkdir -p "$out"
rows=""
for model in "$@"; do
  name=$(echo "$model" | cut -d: -f1); file=$(realpath "$(echo "$model" | cut -d: -f2)")
  scale=$(echo "$model" | cut -d: -f3); position=$(echo "$model" | cut -d: -f4)
  resolution=$(echo "$model" | cut -d: -f5)
  for kind in plain bending; do
    bending=0
    [ "$kind" = bending ] && bending="{\"ratio\":$ratio}"
    set -- --set "bodies.0.mesh=$file" --set "bodies.0.scale=$scale" --set "bodies.0.position=[$position]" \
      --set "bodies.0.repair=$repair" --set "bodies.0.resolution=$resolution" --set "bodies.0.bending=$bending" \
      --set render.width=640 --set render.height=480 --set render.figure_frames=0
    echo "== $name $kind"
    "$bench" "$scene" "$@" > "$out/${name}_$kind.txt" 2>&1 || { cat "$out/${name}_$kind.txt"; exit 1; }
    grep -E "^scene|^body|note: .*(proxy|repair|filled|split|removed|crossing)" "$out/${name}_$kind.txt" || true
    "$exe" render "$scene" "$@" --frames 60 -o "$out/${name}_${kind}_png" 2>&1 | tail -n 1
  done
  ffmpeg -loglevel error -y -i "$out/${name}_plain_png/frame_0060.png" -i "$out/${name}_bending_png/frame_0060.png" \
    -filter_complex hstack "$out/${name}_pair.png"
  rows="$rows $out/${name}_pair.png"
done
# shellcheck disable=SC2086  # one word per row (no spaces in OUT)
set -- $rows
if [ $# -gt 1 ]; then
  inputs=""; for row in "$@"; do inputs="$inputs -i $row"; done
  # shellcheck disable=SC2086  # one -i per row
  ffmpeg -loglevel error -y $inputs -filter_complex "vstack=inputs=$#" "$out/contact_sheet.png"
else
  cp "$1" "$out/contact_sheet.png"
fi
echo "wrote $out/contact_sheet.png"
