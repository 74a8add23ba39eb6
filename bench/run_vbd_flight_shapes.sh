#!/bin/bash
# Usage: bench/run_vbd_flight_shapes.sh (after scripts/build; about 1 min on 2 cores). vbd in flight, no floor: how its
# error against rk45 (tolerance 1e-8) depends on the sweeps and the steps where the body is not a sphere that starts
# near its shape (the bodies: bench/flight_shapes_common.sh). Each line: the worst volume error and the worst
# centre-of-mass distance over the second (bench/csv_errors.py), user CPU s of one thread.
cd "$(dirname "$0")/.."
B=build/softbody
out=${OUT:-out/vbd_flight_shapes}
shapes=$out
mkdir -p "$out"
source bench/flight_shapes_common.sh
shape() { # name extra-args...
  local name=$1; shift
  flight_reference "$name" "$@"
  for setting in "1 1" "1 2" "1 4" "1 8" "8 4" "8 64"; do
    local substeps=${setting% *} sweeps=${setting#* }
    local t=$( { /usr/bin/time -f "%U" $B simulate $S --set duration=1 --set solver.threads=1 \
      --set solver.integrator=\"vbd\" --set solver.dt=\"auto\" --set solver.substeps=$substeps \
      --set solver.iterations=$sweeps "$@" --csv "$out/${name}_${substeps}_$sweeps.csv" > /dev/null; } 2>&1 | tail -1)
    echo "$name, $substeps step(s) per frame, $sweeps sweeps: cpu_s=$t" \
      "$(python3 bench/csv_errors.py "$out/${name}_ref.csv" "$out/${name}_${substeps}_$sweeps.csv" | cut -d: -f2)"
  done
}
each_flight_shape shape
