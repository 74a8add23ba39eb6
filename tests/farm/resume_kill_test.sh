#!/usr/bin/env bash
# --resume after SIGKILL at random moments (ctest label `farm`): simulate, render (PNGs, figure, video) and
# export are each killed KILLS times at random moments of a run with --resume, then run to the end with
# --resume; every output must be byte-identical to an uninterrupted run's, and no temporary or state file
# may be left. Prints every kill's moment, so a failure can be replayed.
#   resume_kill_test.sh SOFTBODY SOURCE_DIR SCRATCH_DIR [KILLS]
set -uo pipefail
softbody=$1; source_dir=$2; scratch=$3; kills=${4:-20}
rm -rf "$scratch"; mkdir -p "$scratch"
scene="$source_dir/scenes/bounce.json"
small=(--set duration=1.5 --set render.width=160 --set render.height=120)
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

# kill_and_resume NAME OUTPUT_ARGS...: the reference run, then runs with --resume killed at random moments
# (a run that ends before its kill starts the next one afresh), then one to the end.
kill_and_resume() {
  local name=$1 command=$2; shift 2
  local reference=("$@")
  local start end duration
  start=$(date +%s%N)
  "$softbody" "$command" "$scene" "${small[@]}" "${reference[@]//@/$scratch/$name/reference}" >/dev/null 2>&1
  end=$(date +%s%N)
  duration=$(( (end - start) / 1000000 ))  # ms
  local killed=0 finished=0 moments=""
  while [ $killed -lt "$kills" ]; do
    local moment=$(( 20 + RANDOM % (duration + 200) ))  # ms after the start, start-up included
    timeout -s KILL "$(printf '%d.%03d' $((moment / 1000)) $((moment % 1000)))" \
      "$softbody" "$command" "$scene" "${small[@]}" "${reference[@]//@/$scratch/$name/resumed}" --resume >/dev/null 2>&1
    case $? in
      137) killed=$((killed + 1)); moments="$moments ${moment}ms" ;;
      0) finished=$((finished + 1)) ;;
      *) echo "FAIL: $name: a run with --resume failed"; failures=$((failures + 1)); return ;;
    esac
  done
  "$softbody" "$command" "$scene" "${small[@]}" "${reference[@]//@/$scratch/$name/resumed}" --resume >/dev/null 2>&1 ||
    { echo "FAIL: $name: the last run with --resume failed"; failures=$((failures + 1)); return; }
  echo "$name: a run takes $duration ms; $killed runs killed at$moments; $finished ended before their kill"
  local files=0 same=0
  for f in "$scratch/$name/reference"/* "$scratch/$name/reference"/*/*; do
    [ -f "$f" ] || continue
    files=$((files + 1))
    cmp -s "$f" "${f/reference/resumed}" && same=$((same + 1))
  done
  check "$name: every output identical to the uninterrupted run's ($same of $files files)" "[ $files -gt 0 ] && [ $same -eq $files ]"
  local extra; extra=$(cd "$scratch/$name/resumed" && find . -type f | sort | diff - <(cd "$scratch/$name/reference" && find . -type f | sort) | grep -c '^<')
  check "$name: nothing left beside the outputs (temporaries, states): $extra extra files" "[ $extra -eq 0 ]"
}

kill_and_resume simulate simulate --csv @/simulation.csv
kill_and_resume render render -o @ --video @/bounce.mp4
kill_and_resume export export -o @ --format ply

[ $failures -eq 0 ] || exit 1
echo "resume test: all checks passed"
