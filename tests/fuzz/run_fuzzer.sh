#!/usr/bin/env bash
# Runs one libFuzzer harness for SECONDS from its seed corpus; new inputs go to WORK/corpus, findings to
# WORK/findings (crash-*, timeout-*, oom-*), and the last lines of libFuzzer's report are printed.
#   run_fuzzer.sh FUZZER SEED_DIR WORK_DIR SECONDS
set -euo pipefail
fuzzer=$1; seeds=$2; work=$3; seconds=$4
mkdir -p "$work/corpus" "$work/findings"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# -timeout: an input that takes more than 10 s is a hang (assimp's PLY reader looped on some headers).
# -seed: fixed (SOFTBODY_FUZZ_SEED, default 1) so that a smoke run in CI tries the same inputs every time;
# scripts/fuzz sets a new one for long runs.
"$fuzzer" -seed="${SOFTBODY_FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 \
  -artifact_prefix="$work/findings/" "$work/corpus" "$seeds" >"$work/log.txt" 2>&1 || {
  status=$?
  tail -n 40 "$work/log.txt"
  exit $status
}
grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ *DONE)' "$work/log.txt" || tail -n 5 "$work/log.txt"
