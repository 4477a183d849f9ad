#!/usr/bin/env bash
# Probe item 4.3 (issue 12): two jobs started at the same instant on the same output. Formerly both ran
# (once in 25 tries) or the loser failed with "Cannot rename ...journal.tmp" (a shared fixed-name
# temporary, locked only after the rename). Now the journal is locked before anything is read or
# created: in every round exactly one job runs; the other is refused in one line (in use by another
# job, or -- if the winner already finished -- an existing output/journal), having solved nothing; no
# temporary is left; the output is complete.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
args=(-pattern_type plain -yarn_kc 50 -sampler_reference none -sampler_terms zero,sx -sampler_n1 3 -sampler_progress 100 -sampler_output race.h5)
inuse=0
for round in $(seq 1 12); do
  rm -f race.h5 race.h5.journal go
  for who in a b; do
    (while [ ! -e go ]; do sleep 0.001; done; exec "$tool" "${args[@]}") >$who.txt 2>&1 &
    eval pid_$who=$!
  done
  touch go
  wait "$pid_a"; ra=$?
  wait "$pid_b"; rb=$?
  if [ $ra -eq 0 ] && [ $rb -ne 0 ]; then loser=b.txt
  elif [ $rb -eq 0 ] && [ $ra -ne 0 ]; then loser=a.txt
  else cat a.txt b.txt; die "round $round: exit codes $ra and $rb (exactly one job must run)"; fi
  [ "$(grep -c . $loser)" = 1 ] || { cat $loser; die "round $round: the loser printed more than one line"; }
  grep -Eq '^hylc: error: (Journal race.h5.journal is in use by another job( \(pid [0-9]+\))?|Journal race.h5.journal holds [0-9]+ samples? of an earlier run|Output race.h5 exists)' $loser || { cat $loser; die "round $round: unclear refusal"; }
  grep -q 'in use by another job' $loser && inuse=$((inuse + 1))
  leftover=$(ls | grep '^race' | grep -v '^race.h5$' | grep -v '^race.h5.journal$')
  [ -z "$leftover" ] || die "round $round: left behind: $leftover"
  h5dump -d /samples/status race.h5 2>/dev/null | grep -q '(0): 0, 0, 0, 0' || die "round $round: incomplete output"
done
echo "12 rounds: one job ran each time; the other was refused as in use $inuse times (else the winner had finished)"
exit 0
