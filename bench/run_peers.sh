#!/usr/bin/env bash
# The peers' work-precision curves: CPU s of one thread per simulated s against the worst volume error and the
# worst centre-of-mass distance from softbody's rk45 reference (tolerance 1e-9), for Jolt Physics over its dt and
# iterations and softbody's xpbd and vbd over their substeps and sweeps (vbd also without its coarse level), its
# explicit methods at their "auto" steps and rk45 over its tolerance, on two scenes:
#   breathing (bench/peers/breathing.json): no gravity, no floor, no dampers; the whole 1 s;
#   bounce    (bench/peers/bounce.json):    the first impact on the floor, 0-1.2 s (the contact models differ).
# Usage: JOLT_PREFIX=/path/to/installed/jolt bench/run_peers.sh [LEVELS]      (default "3 5"; after scripts/build)
#        JOLT_ITERATIONS="1 5 20" bench/run_peers.sh 6   (fewer Jolt settings: its error depends on dt/iterations only)
#        PROGRAMS="bullet" BULLET_ITERATIONS="1 4" bench/run_peers.sh 5   (only Bullet's runs, added to the table)
#        SCENES=breathing bench/run_peers.sh 6   (one scene: the bounce's rk45 runs take hours at level 6)
# Bullet (build/bench_peers_bullet: btSoftBody, its own links, kPR = nRT) runs over its dt and position iterations;
# on the breathing its error is the distance from our model, not a convergence error (bench/peers/peers.gp also
# plots its volume history).
# Writes out/peers/LEVEL/*.csv (every run's frames), out/peers/peers_LEVEL.csv (one row per run) and plots them with
# bench/peers/peers.gp. Without JOLT_PREFIX only softbody's curves are measured.
# Times: Jolt's are the thread CPU time of its PhysicsSystem::Update calls (the harness's own timing, single-threaded
# job system); softbody's are the wall time of its steps with solver.threads 1 (`--profile`'s step phase: the
# integrator, the contacts and the guard, without reading the scene, building the body or writing the CSV, as Jolt's
# time leaves out its setup, Optimize included; vbd's colouring and coarse level are built with the run's setup,
# outside it). One run each.
set -euo pipefail
cd "$(dirname "$0")/.."
levels="${1:-3 5}"
programs="${PROGRAMS:-softbody jolt bullet}"
want() { case " $programs " in *" $1 "*) return 0;; esac; return 1; }
SB=build/softbody
[ -x $SB ] || cmake --build build --target softbody
jolt=""
if [ -n "${JOLT_PREFIX:-}" ] && want jolt; then jolt=$(bench/peers/build_jolt.sh); fi
! want jolt || [ -n "$jolt" ] || echo "bench/run_peers.sh: JOLT_PREFIX not set: Jolt's curves are skipped" >&2
declare -A scene_file=([breathing]=bench/peers/breathing.json [bounce]=bench/peers/bounce.json)
declare -A seconds=([breathing]=1 [bounce]=1.2)
declare -A jolt_scene=([breathing]="--gravity 0 --no-floor --height 0 --velocity 0" [bounce]="")
mkdir -p out/peers

for level in $levels; do
  out=out/peers/$level
  mkdir -p $out
  table=out/peers/peers_$level.csv
  # Rows of the programs not run now are kept (PROGRAMS="bullet" adds Bullet's to an earlier run's table).
  header="scene,level,program,family,dt_s,substeps,iterations,cpu_per_sim_s,volume_error_pct,com_error_cm,volume_max"
  kept=$( [ -f $table ] && tail -n +2 $table | awk -F, -v run=" $programs " \
    '{ p = ($3 ~ /^(xpbd|vbd|symplectic|verlet|rk4|rk45)$/) ? "softbody" : $3; if (index(run, " " p " ") == 0) print }' || true)
  { echo "$header"; [ -z "$kept" ] || echo "$kept"; } > $table
  for scene in ${SCENES:-breathing bounce}; do
    file=${scene_file[$scene]}
    dur=${seconds[$scene]}
    ref=$out/${scene}_ref.csv
    mesh=(--set "bodies.0.mesh=\"icosphere:$level\"")
    [ -f $ref ] || $SB simulate $file "${mesh[@]}" --csv $ref > /dev/null
    row() { # program family dt substeps iterations cpu_per_sim_s csv
      local errors vmax
      # A run that stopped early (a divergence, the guard) or whose volume is not finite counts as failed: inf.
      vmax=$(python3 -c "import csv,sys,math; v=[float(r['volume']) for r in csv.DictReader(open(sys.argv[1]))]
print(round(max(v)/v[0],5) if len(v) >= round(float(sys.argv[2])*30)+1 and all(map(math.isfinite, v)) else 'inf')" $7 $dur)
      errors=inf,inf
      [ "$vmax" = inf ] || errors=$(python3 bench/csv_errors.py $ref $7 $dur | sed -E 's/.*vol ([^ ]+) %  com ([^ ]+) cm/\1,\2/')
      echo "$scene,$level,$1,$2,$3,$4,$5,$6,$errors,$vmax" | tee -a $table
    }
    softbody() { # program family dt substeps iterations name --set...
      local p=$1 fam=$2 dt=$3 sub=$4 it=$5 name=$6; shift 6
      local csv=$out/${scene}_$name.csv t
      t=$( { $SB simulate $file "${mesh[@]}" --csv $csv --profile "$@" 2>&1 > /dev/null || true; } |
        awk '$1 == "step" { print $2 }')
      [ -n "$t" ] || t=inf
      row "$p" "$fam" "$dt" "$sub" "$it" "$(python3 -c "print(round(float('$t')/$dur,5))")" $csv
    }
    if want bullet; then
      [ -x build/bench_peers_bullet ] || cmake --build build --target bench_peers_bullet
      for it in ${BULLET_ITERATIONS:-1 4 16}; do for rate in 60 120 240 480 960 1920; do
        csv=$out/${scene}_bullet_${rate}_$it.csv
        cpu=$(build/bench_peers_bullet $file $level $rate $it $csv | sed -nE 's/^cpu_per_sim_s=//p' || true)
        row bullet bullet_it$it "1/$rate" - $it "$cpu" $csv
      done; done
    fi
    want softbody || { [ -n "$jolt" ] && want jolt; } || continue
    if want softbody; then
    softbody xpbd xpbd_auto auto auto - xpbd_auto --set solver.integrator=xpbd --set 'solver.substeps="auto"'
    for s in 2 4 8 16 32 64; do
      softbody xpbd xpbd_fixed "1/$((30 * s))" $s - xpbd_$s --set solver.integrator=xpbd --set solver.substeps=$s
    done
    for it in 4 8; do for s in 1 2 4; do
      softbody vbd vbd_it$it "1/$((30 * s))" $s $it vbd_${s}_$it --set solver.integrator=vbd --set solver.substeps=$s \
        --set solver.iterations=$it
    done; done
    # vbd with the affine correction alone (no coarse level: a flight's breathing is affine) and 1 or 2 sweeps.
    for it in 1 2; do
      softbody vbd vbd_affine 1/30 1 $it vbd_affine_1_$it --set solver.integrator=vbd --set solver.substeps=1 \
        --set solver.iterations=$it --set solver.coarse_space=0
    done
    # The explicit methods at their "auto" step (0.7 x the stable estimate), and rk45 over its tolerance.
    for integrator in symplectic verlet rk4; do
      softbody $integrator ${integrator}_auto auto - - ${integrator}_auto --set solver.integrator=$integrator \
        --set 'solver.dt="auto"'
    done
    for tolerance in 1e-3 1e-4 1e-5 1e-6; do
      softbody rk45 rk45_tolerance "tolerance $tolerance" - - rk45_$tolerance --set solver.integrator=rk45 \
        --set solver.tolerance=$tolerance
    done
    fi
    [ -n "$jolt" ] && want jolt || continue
    for it in ${JOLT_ITERATIONS:-1 2 5 10 20 40}; do for rate in 60 120 240 480 960 1920; do
      csv=$out/${scene}_jolt_${rate}_$it.csv
      cpu=$($jolt --level $level --dt 1/$rate --iterations $it --seconds $dur --linear-damping 0 ${jolt_scene[$scene]} \
        --frames-csv $csv | sed -nE 's/^RESULT .* cpu_per_sim_s=([^ ]+) .*/\1/p' || true)
      row jolt jolt_it$it "1/$rate" - $it "$cpu" $csv
    done; done
  done
done
for level in $levels; do (cd out/peers && gnuplot -e "level=$level" ../../bench/peers/peers.gp); done
