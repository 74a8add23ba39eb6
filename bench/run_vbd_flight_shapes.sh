#!/bin/bash
# Usage: bench/run_vbd_flight_shapes.sh (after scripts/build; about 1 min on 2 cores). vbd in flight, no floor: how its
# error against rk45 (tolerance 1e-8) depends on the sweeps and the steps where the body is not a sphere that starts
# near its shape. bench/peers/breathing.json's ball and four others, each for 1 s with gravity, thrown at (2, 3, 0) m/s
# with its dampers (c 1 N·s/m): a level-4 sphere (its dampers off, no gravity: the peers' breathing), a torus:48,24,
# a cube:12 with bending links (k_b 50 N/m), a soft level-3 sphere (k 100 N/m, nRT 200 J) and a capsule:16 turned
# (30°, 0, 20°). The cube and the capsule swell by about 25 % within their first 0.1 s. Each line: the worst volume
# error and the worst centre-of-mass distance over the second (bench/csv_errors.py), user CPU s of one thread.
cd "$(dirname "$0")/.."
B=build/softbody
S=bench/peers/breathing.json
out=${OUT:-out/vbd_flight_shapes}
mkdir -p "$out"
thrown=(--set 'gravity=[0,-9.81,0]' --set 'bodies.0.velocity=[2,3,0]' --set bodies.0.damping=1)
shape() { # name extra-args...
  local name=$1; shift
  [ -f "$out/${name}_ref.csv" ] || $B simulate $S --set duration=1 --set solver.threads=1 --set solver.integrator=rk45 \
    --set solver.tolerance=1e-8 --set solver.dt=\"auto\" "$@" --csv "$out/${name}_ref.csv" > /dev/null 2>&1
  for setting in "1 1" "1 2" "1 4" "1 8" "8 4" "8 64"; do
    local substeps=${setting% *} sweeps=${setting#* }
    local t=$( { /usr/bin/time -f "%U" $B simulate $S --set duration=1 --set solver.threads=1 \
      --set solver.integrator=\"vbd\" --set solver.dt=\"auto\" --set solver.substeps=$substeps \
      --set solver.iterations=$sweeps "$@" --csv "$out/${name}_${substeps}_$sweeps.csv" > /dev/null; } 2>&1 | tail -1)
    echo "$name, $substeps step(s) per frame, $sweeps sweeps: cpu_s=$t" \
      "$(python3 bench/csv_errors.py "$out/${name}_ref.csv" "$out/${name}_${substeps}_$sweeps.csv" | cut -d: -f2)"
  done
}
shape sphere4_breathing --set bodies.0.mesh=\"icosphere:4\"
shape torus "${thrown[@]}" --set bodies.0.mesh=\"torus:48,24\"
shape cube "${thrown[@]}" --set bodies.0.mesh=\"cube:12\" --set bodies.0.bending=50
shape soft_sphere "${thrown[@]}" --set bodies.0.stiffness=100 --set bodies.0.pressure=200
shape capsule "${thrown[@]}" --set bodies.0.mesh=\"capsule:16\" --set 'bodies.0.rotation=[30,0,20]'
