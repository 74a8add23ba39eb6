#!/bin/sh
# A mesh simulated as it is against on a remeshed proxy ("resolution": N, issue 17): the stable step each
# allows (`softbody info`), the wall time per simulated second (`softbody export`'s summary line: the same
# run also writes the OBJ frames), and a rendered last frame of each for a side-by-side look. The last
# frame's detailed mesh of the proxy run is compared vertex by vertex with the raw run's (the same welded
# vertices in the same order): the largest and RMS distance, relative to the body's size.
# usage: bench/proxy_speed.sh MESH SCALE HEIGHT DURATION [N=2000] [OUT=out/proxy_speed]
#   SCALE: the body's "scale" (mesh units to metres); HEIGHT: its "position" y [m]; DURATION: simulated
#   seconds (the raw mesh of a large model needs hundreds of thousands of steps per second); MESH closed.
set -eu
mesh=$(realpath "$1"); scale=$2; height=$3; duration=$4; resolution=${5:-2000}; out=${6:-out/proxy_speed}
exe=${SOFTBODY:-build/softbody}
name=$(basename "$mesh" .obj)
mkdir -p "$out"
# The same physical intent on both meshes (membrane stiffness E·t, damping ratio) so that they behave alike;
# verlet at 0.7 x each mesh's own estimated stable dt.
scene() {  # $1: scene file, $2: extra body keys
  cat > "$1" <<JSON
{ "name": "$name", "duration": $duration, "fps": 30,
  "solver": { "integrator": "verlet", "dt": "auto" },
  "floor": { "height": 0.0, "contact": "friction", "restitution": 0.3, "friction": 0.5 },
  "bodies": [ { "mesh": "$mesh", "scale": $scale, "position": [0, $height, 0], $2
                "mass": 5.0, "stiffness": { "youngs": 2e6, "thickness": 0.002 }, "damping": { "ratio": 0.1 },
                "pressure": 20.0, "color": [0.8, 0.12, 0.07] } ],
  "render": { "width": 640, "height": 480, "figure_frames": 0 },
  "camera": { "position": [0.6, 1.4, 4.0], "target": [0, 0.6, 0] } }
JSON
}
scene "$out/${name}_raw.json" ""
scene "$out/${name}_proxy.json" "\"resolution\": $resolution,"
for kind in raw proxy; do
  echo "== $name $kind"
  "$exe" info "$out/${name}_$kind.json" 2>&1 | grep -E "^body|simulated on|^  verlet|note: .*resolution" || true
  "$exe" export "$out/${name}_$kind.json" --format obj -o "$out/${name}_${kind}_obj" 2>&1 | tail -n 1
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
rms = math.sqrt(sum(x * x for x in d) / len(d))
print(f"{sys.argv[1].split('/')[-1]}: {len(raw)} vertices, body diagonal {size:.3f} m, largest distance raw-proxy "
      f"{max(d):.4f} m ({100 * max(d) / size:.2f} %), rms {rms:.4f} m ({100 * rms / size:.2f} %)")
PY
