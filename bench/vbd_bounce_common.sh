# Sourced by bench/run_vbd_bounce.sh and bench/run_vbd_coarse.sh: the smooth-floor bounce (scenes/bounce_smooth.json)
# at icosphere levels, its rk45 references at tolerance 1e-8 (made once in $out), and run(), which times one
# setting and prints its errors against the reference (bench/csv_errors.py: worst volume error and worst
# centre-of-mass distance through the first impact, 0-1.2 s, and over the whole run); times: user CPU s of one
# thread (solver.threads=1) per simulated s.
cd "$(dirname "$0")/.."
B=build/softbody
out=${OUT:-out/vbd_bounce}
mkdir -p "$out"
run() { # name level duration extra-args...   (REF=file: another reference than $out/ref<level>.csv)
  local name=$1 level=$2 dur=$3; shift 3
  local ref=${REF:-$out/ref$level.csv}
  local t=$( { /usr/bin/time -f "%U" $B simulate scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$level\" \
    --set duration=$dur --set solver.threads=1 --csv $out/$name.csv "$@" >/dev/null; } 2>&1 | tail -1)
  echo "$name L$level cpu_s=$t per_sim_s=$(python3 -c "print(round($t/$dur,4))")" \
       "first_impact:$(python3 bench/csv_errors.py $ref $out/$name.csv 1.2 | cut -d: -f2)" \
       "whole:$(python3 bench/csv_errors.py $ref $out/$name.csv | cut -d: -f2)"
}
make_reference() { # level duration
  [ -f $out/ref$1.csv ] || $B simulate scenes/bounce_smooth.json --set bodies.0.mesh=\"icosphere:$1\" \
    --set duration=$2 --set solver.integrator=rk45 --set solver.tolerance=1e-8 --set solver.threads=1 \
    --csv $out/ref$1.csv > /dev/null
}
