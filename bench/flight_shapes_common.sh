# Sourced by bench/run_vbd_flight_shapes.sh and bench/run_vbd_converge.sh: five bodies in flight for 1 s and their
# references (rk45 at tolerance 1e-8, made once in $shapes). bench/peers/breathing.json's ball and four others, each
# thrown at (2, 3, 0) m/s with gravity and its dampers (c 1 N·s/m): a level-4 sphere (its dampers off, no gravity: the
# peers' breathing), a torus:48,24, a cube:12 with bending links (k_b 50 N/m), a soft level-3 sphere (k 100 N/m, nRT
# 200 J) and a capsule:16 turned (30°, 0, 20°). The cube and the capsule swell by about 25 % within their first 0.1 s.
# Needs B (the program) and shapes (the references' folder).
S=bench/peers/breathing.json
thrown=(--set 'gravity=[0,-9.81,0]' --set 'bodies.0.velocity=[2,3,0]' --set bodies.0.damping=1)
flight_reference() { # name extra-args...: makes $shapes/<name>_ref.csv where it is missing
  local name=$1; shift
  [ -f "$shapes/${name}_ref.csv" ] || $B simulate $S --set duration=1 --set solver.threads=1 \
    --set solver.integrator=rk45 --set solver.tolerance=1e-8 --set solver.dt=\"auto\" "$@" \
    --csv "$shapes/${name}_ref.csv" > /dev/null 2>&1
}
each_flight_shape() { # function: calls it with each body's name and its --set arguments
  "$1" sphere4_breathing --set bodies.0.mesh=\"icosphere:4\"
  "$1" torus "${thrown[@]}" --set bodies.0.mesh=\"torus:48,24\"
  "$1" cube "${thrown[@]}" --set bodies.0.mesh=\"cube:12\" --set bodies.0.bending=50
  "$1" soft_sphere "${thrown[@]}" --set bodies.0.stiffness=100 --set bodies.0.pressure=200
  "$1" capsule "${thrown[@]}" --set bodies.0.mesh=\"capsule:16\" --set 'bodies.0.rotation=[30,0,20]'
}
