#!/usr/bin/env bash
# hylc-sample -sampler_start continue: 1, 2 and 3 ranks give bitwise the same /samples (start included);
# samples are continued (start 1) except the first of each half-line (0); a run killed with SIGKILL and
# resumed (on another number of ranks) gives the same data; -sampler_start is part of the run identity.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || { echo "h5dump (hdf5-tools) not installed"; exit 77; }
dset() { h5dump -y -w 0 -d /samples/$1 "$2" | sed -n '/^   DATA {/{n;p;q}' | tr -d ' ' | tr ',' '\n' ; }
data() { h5dump -d /samples/psi -d /samples/strain -d /samples/status -d /samples/iterations -d /samples/start -d /samples/negcurv -d /samples/escapes "$1" | grep -v -e HDF5 -e '^}' ; }
starts() { dset start "$1"; }
common=(-pattern_type plain -yarn_kc 50 -sampler_terms zero,sx,sa,sx-sa -sampler_n1 7 -sampler_n2 4 -sampler_progress 0.5 -sampler_start continue)
# 1 + 7 + 7 + 16 = 31 samples; units: 1 + 2 + 2 + 8 half-lines = 13 cold starts
$tool "${common[@]}" -sampler_output one.h5 -sampler_view >one.txt 2>&1 || { cat one.txt; die "1-rank run failed"; }
grep -q 'start: continue' one.txt || { cat one.txt; die "-sampler_view does not print the start"; }
grep -q 'wrote one.h5: 31 samples' one.txt || { cat one.txt; die "1-rank summary"; }
for np in 2 3; do
  $MPIEXEC -n $np $tool "${common[@]}" -sampler_output n$np.h5 >n$np.txt 2>&1 || { cat n$np.txt; die "$np-rank run failed"; }
  [ "$(data one.h5)" = "$(data n$np.h5)" ] || die "1 and $np ranks give different data with -sampler_start continue"
done
s=$(starts one.h5 | sort | uniq -c | tr -s ' ' | tr '\n' ';')
n0=$(starts one.h5 | grep -c '^0$'); n1=$(starts one.h5 | grep -c '^1$'); n2=$(starts one.h5 | grep -c '^2$')
[ "$n0" = 13 ] || die "expected 13 cold starts (one per unit), got $n0 ($s)"
[ $((n1 + n2)) = 18 ] || die "expected 18 continued samples, got $n1 + $n2 retried ($s)"
echo "starts: $n0 cold, $n1 continued, $n2 retried cold"
# the second-order test (on by default) is recorded: every converged sample has a known count (>= 0), and
# the summary counts the saddles
paste <(dset status one.h5) <(dset negcurv one.h5) <(dset escapes one.h5) | awk '$1 == 0 && ($2 < 0 || $3 < 0) { bad++ } END { exit bad > 0 }' ||
  die "a converged sample without a second-order test or an escape count in /samples/negcurv, /samples/escapes"
grep -q 'converged samples: .* left a saddle point' one.txt || { cat one.txt; die "the summary does not count saddles"; }
# cold runs write start 0 everywhere; the start is part of the identity (a different digest)
$tool "${common[@]}" -sampler_start cold -sampler_output cold.h5 >cold.txt 2>&1 || { cat cold.txt; die "cold run failed"; }
[ "$(starts cold.h5 | sort -u)" = 0 ] || die "a cold run has a start other than 0"
[ "$(h5dump -a /provenance/digest one.h5 | grep '(0)')" != "$(h5dump -a /provenance/digest cold.h5 | grep '(0)')" ] || die "-sampler_start does not change the digest"
$tool "${common[@]}" -sampler_start cold -sampler_output one.h5 -sampler_resume >bad.txt 2>&1 && die "resume of a continue run with -sampler_start cold accepted"
grep -q "sampler_start" bad.txt || { cat bad.txt; die "the refusal does not name -sampler_start"; }

# SIGKILL, then resume on another number of ranks: a unit cut by the kill is recomputed from its start
long=(-pattern_type plain -yarn_kc 50 -sampler_terms sx,sa,sx-sa -sampler_n1 40 -sampler_n2 6 -sampler_progress 0.5 -sampler_start continue)
# 40 + 40 + 36 = 116 samples
$tool "${long[@]}" -sampler_output ref.h5 >ref.txt 2>&1 || { cat ref.txt; die "reference run failed"; }
# (a kill that lands after the run finished, possible on a loaded machine, does not test resume: try again,
# up to 4 times, before calling it a failure)
for np in 1 2; do
  k=$HYLC_TMP/kill$np.h5 # absolute: the pkill pattern below matches only this run's ranks
  other=$((3 - np))
  done_before=
  for attempt in 1 2 3 4; do
    rm -f $k $k.journal
    $MPIEXEC -n $np $tool "${long[@]}" -sampler_output $k >kill1.txt 2>&1 &
    pid=$!
    s0=
    for i in $(seq 1 2000); do
      if [ -f $k.journal ]; then
        s=$(stat -c %s $k.journal)
        [ -z "$s0" ] && [ "$s" -gt 0 ] && s0=$s
        [ -n "$s0" ] && [ "$s" -ge $((s0 + 172)) ] && break
      fi
      sleep 0.005
    done
    kill -9 $pid 2>/dev/null; pkill -9 -f "hylc-sample.*$k" 2>/dev/null; wait $pid 2>/dev/null
    [ -f $k.journal ] || continue # killed before the journal existed: nothing to resume
    $MPIEXEC -n $other $tool "${long[@]}" -sampler_output $k -sampler_resume >kill2.txt 2>&1 || { cat kill1.txt kill2.txt; die "resume on $other ranks failed"; }
    done_before=$(sed -n 's/.*; \([0-9]*\) already done.*/\1/p' kill2.txt)
    [ -n "$done_before" ] && [ "$done_before" -gt 0 ] && [ "$done_before" -lt 116 ] && break
    echo "attempt $attempt on $np ranks: the kill did not interrupt the run (${done_before:-?} of 116 done); again"
    done_before=
  done
  [ -n "$done_before" ] || die "killed on $np ranks: in 4 attempts no kill interrupted the run"
  [ "$(data ref.h5)" = "$(data $k)" ] || die "killed on $np ranks, resumed on $other: different data"
  echo "killed on $np ranks after $done_before of 116 samples, resumed on $other: identical"
done
exit 0
