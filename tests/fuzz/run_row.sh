#!/usr/bin/env bash
# One row of docs/fuzz_runs.csv (date,harness,seconds,seed,executions,findings,assimp,note) for a run of
# tests/fuzz/run_fuzzer.sh, from libFuzzer's log: executions from its final "Done N runs in S second(s)" line,
# the seed from "INFO: Seed: N" (the one used, also when -seed=0 let libFuzzer draw it), and which assimp the
# fuzzer loads under the LD_LIBRARY_PATH in effect (asan-built: build-assimp-asan/lib, from
# scripts/build-assimp-asan; else system). scripts/fuzz appends it; SOFTBODY_FUZZ_NOTE adds a note.
#   run_row.sh FUZZER LOG SECONDS STATUS NEW_FINDINGS
set -euo pipefail
fuzzer=$1; log=$2; seconds=$3; status=$4; new_findings=$5
csv() {  # one CSV field: quoted when it holds a comma, a quote or a line break
  local s=${1//$'\n'/ }
  if [[ $s == *[,\"]* ]]; then s="\"${s//\"/\"\"}\""; fi
  printf '%s' "$s"
}
name=$(basename "$fuzzer")
seed=$(grep -ao '^INFO: Seed: [0-9]*' "$log" | head -n 1 | grep -o '[0-9]*$' || true)
done_line=$(grep -aE '^Done [0-9]+ runs in [0-9]+ second' "$log" | tail -n 1 || true)
notes=()
if [ -n "$done_line" ]; then
  executions=$(echo "$done_line" | awk '{print $2}')
  ran=$(echo "$done_line" | awk '{print $5}')
  if [ "$ran" -lt "$seconds" ]; then notes+=("ran $ran s"); fi
else
  # No "Done" line: libFuzzer stopped on a finding (or never started); its final stats may still count the runs.
  executions=$(grep -ao 'stat::number_of_executed_units: *[0-9]*' "$log" | tail -n 1 | grep -o '[0-9]*$' || echo "?")
  notes+=("stopped without a Done line, exit status $status")
fi
library=$(ldd "$fuzzer" 2>/dev/null | awk '$1 ~ /^libassimp/ {print $3}' || true)
if [[ $library == */build-assimp-asan/* ]] ||
  { [ -z "$library" ] && [[ ${LD_LIBRARY_PATH:-} == *build-assimp-asan* ]]; }; then
  assimp=asan-built
else
  assimp=system
fi
if [ -n "${SOFTBODY_FUZZ_NOTE:-}" ]; then notes+=("$SOFTBODY_FUZZ_NOTE"); fi
note=""
for n in "${notes[@]}"; do note=${note:+$note; }$n; done
printf '%s,%s,%s,%s,%s,%s,%s,%s\n' "$(date -u +%F)" "$name" "$seconds" "$seed" "$executions" "$new_findings" "$assimp" \
  "$(csv "$note")"
