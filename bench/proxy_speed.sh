#!/bin/sh
# A mesh simulated as it is against on a remeshed proxy ("resolution": N, issue 17): wall time per simulated
# second of `softbody simulate` for both, and one rendered frame of each for a side-by-side look.
# The last frame's detailed mesh of the proxy run is compared vertex by vertex with the raw run's (the same
# welded vertices in the same order): the largest and RMS distance, relative to the body's size.
# usage: bench/proxy_speed.sh MESH.obj SCALE HEIGHT [N=2000] [OUT=out/proxy_speed]
#   SCALE: the body's "scale" (mesh units to metres); HEIGHT: its "position" y [m]; the mesh must be closed.
set -eu
mesh=$(realpath "$1"); scale=$2; height=$3; resolution=${4:-2000}; out=${5:-out/proxy_speed}
exe=${SOFTBODY:-build/softbody}
name=$(basename "$mesh" .obj)
mkdir -p "$out"
# The same physical intent on both meshes (membrane stiffness E·t, damping ratio) so that they behave alike;
# verlet at 0.7 x each mesh's own estimated stable dt.
scene() {  # $1: scene file, $2: extra body keys
  cat > "$1" <<JSON
{ "name": "$name", "duration": 1.0, "fps": 30,
  "solver": { "integrator": "verlet", "dt": "auto" },
  "floor": { "height": 0.0, "contact": "friction", "restitution": 0.3, "friction": 0.5 },
  "bodies": [ { "mesh": "$mesh", "scale": $scale, "position": [0, $height, 0], $2
                "mass": 5.0, "stiffness": { "youngs": 2e6, "thickness": 0.002 }, "damping": { "ratio": 0.1 },
                "pressure": 20.0, "color": [0.8, 0.12, 0.07] } ],
  "render": { "width": 640, "height": 480, "figure_frames": 0 },
  "camera": { "position": [0, 1.2, 4.5], "target": [0, 0.7, 0] } }
JSON
}
scene "$out/${name}_raw.json" ""
scene "$out/${name}_proxy.json" "\"resolution\": $resolution,"
for kind in raw proxy; do
  echo "== $name $kind"
  "$exe" info "$out/${name}_$kind.json" 2>&1 | grep -E "^body|simulated on|^  verlet|this scene|note: .*resolution" || true
  "$exe" simulate "$out/${name}_$kind.json" --csv "$out/${name}_$kind.csv" 2>&1 | tail -n 1
done
for kind in raw proxy; do
  "$exe" export "$out/${name}_$kind.json" --format obj -o "$out/${name}_${kind}_obj" > /dev/null 2>&1
  "$exe" render "$out/${name}_$kind.json" -o "$out/${name}_${kind}_png" 2>&1 | tail -n 1
done
last=$(ls "$out/${name}_raw_obj" | sort | tail -n 1)
python3 - "$out/${name}_raw_obj/$last" "$out/${name}_proxy_obj/$last" <<'PY'
import math, sys
def vertices(path):
    return [tuple(map(float, l.split()[1:4])) for l in open(path) if l.startswith("v ")]
raw, proxy = vertices(sys.argv[1]), vertices(sys.argv[2])
assert len(raw) == len(proxy), (len(raw), len(proxy))
size = math.dist([min(v[k] for v in raw) for k in range(3)], [max(v[k] for v in raw) for k in range(3)])
d = [math.dist(a, b) for a, b in zip(raw, proxy)]
print(f"last frame: {len(raw)} vertices, body diagonal {size:.3f} m, largest distance {max(d):.4f} m "
      f"({100 * max(d) / size:.2f} %), rms {math.sqrt(sum(x * x for x in d) / len(d)):.4f} m "
      f"({100 * math.sqrt(sum(x * x for x in d) / len(d)) / size:.2f} %)")
PY
