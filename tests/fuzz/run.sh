#!/usr/bin/env bash
# Runs each libFuzzer harness FUZZ_SECONDS seconds (make fuzz; docs/testing.md) on its corpus in
# $FUZZ_BUILD/corpus/<harness>, one process each, one after the other. A crash, a sanitizer report, a
# leak, a timeout (> 10 s for one input) or an out-of-memory (> 2 GB) stops the harness and leaves the
# input in $FUZZ_BUILD/findings/<harness>/; the exit status is then non-zero. The log of each run is in
# $FUZZ_BUILD/logs/<harness>.log (its last "#N ... cov: ft: exec/s:" line gives the figures).
#   tests/fuzz/run.sh HARNESS...        (FUZZ_SECONDS=60 by default; extra libFuzzer flags: FUZZ_FLAGS)
set -u
cd "$(dirname "$0")/../.."
top=$PWD
fb=${FUZZ_BUILD:-build-fuzz}
secs=${FUZZ_SECONDS:-60}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$top/tests/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
bash tests/fuzz/seeds.sh "$@" || exit 1
mkdir -p "$fb/logs"
fail=0
for h in "$@"; do
  mkdir -p "$fb/findings/$h"
  log=$fb/logs/$h.log
  echo "fuzz: $h for $secs s (log: $log)"
  "$fb/$h" "$fb/corpus/$h" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$fb/findings/$h/" -print_final_stats=1 ${FUZZ_FLAGS:-} >"$log" 2>&1
  st=$?
  grep -E '^#[0-9]+' "$log" | tail -n 1 | sed "s/^/fuzz: $h: /"
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' "$log" | sed "s/^/fuzz: $h: /"
  if [ $st -ne 0 ]; then
    fail=1
    echo "fuzz: $h: FINDING (exit $st); the input is in $fb/findings/$h/:"
    grep -E 'ERROR|SUMMARY|runtime error|Test unit written' "$log" | head -n 8 | sed 's/^/      | /'
  fi
done
exit $fail
