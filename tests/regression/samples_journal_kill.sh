#!/usr/bin/env bash
# The sample journal survives SIGKILL at any moment: a writer appending records one by one (fflush +
# fsync each) is killed with SIGKILL at random times; resuming finds an exact prefix of the records
# (a torn tail, if any, is dropped), continues it, and a second resume sees the continuation.
set -u
cd "$HYLC_TMP"
exe=$HYLC_BIN/../tests/test_samples
die() { echo "FAIL: $*"; exit 1; }
[ -x "$exe" ] || die "missing $exe (run make)"

for round in 1 2 3 4; do
  rm -f kill.journal writer.txt # a stale "started" of the last round would race the new redirection
  "$exe" -test_journal_writer kill.journal >writer.txt 2>&1 &
  pid=$!
  for _ in $(seq 400); do grep -q started writer.txt && break; sleep 0.05; done
  grep -q started writer.txt || { kill -9 $pid; cat writer.txt; die "writer did not start"; }
  h=$(stat -c %s kill.journal) # the header: wait for a first record (a loaded machine may be slow)
  for _ in $(seq 200); do [ "$(stat -c %s kill.journal)" -gt $((h + 172)) ] && break; sleep 0.02; done
  sleep "0.$((RANDOM % 5 + 1))$((RANDOM % 10))"
  kill -9 $pid 2>/dev/null || die "writer ended before it was killed"
  wait $pid 2>/dev/null
  "$exe" -test_journal_check kill.journal >check.txt 2>&1 || { cat check.txt; die "round $round: resume after SIGKILL failed"; }
  grep -Eq '^records [1-9][0-9]* dropped [0-9]+$' check.txt || { cat check.txt; die "round $round: unexpected output"; }
done
exit 0
