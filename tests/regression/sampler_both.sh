#!/usr/bin/env bash
# hylc-sample -sampler_start both (issue 27): 1, 2 and 3 ranks give bitwise the same /samples (the other
# start's psi and status and the multistable flag included); on every sample solved from both starts the
# kept psi is the lower of the two converged ones and the flag says whether they differ by more than
# -sampler_both_rtol; the cold psi of every sample (the kept one where start = 0, the other one where 1)
# equals a plain -sampler_start cold run's bitwise; a run killed with SIGKILL and resumed on another number
# of ranks gives the same data; both and -sampler_both_rtol are part of the run identity.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
[ -x $py ] && $py -c 'import h5py, numpy' >/dev/null 2>&1 || { echo "python3-h5py not installed: cannot read the files"; exit 77; }
cat >same.py <<'PY'
import sys, h5py
names = ("psi", "strain", "status", "iterations", "start", "negcurv", "escapes", "psi_other", "status_other", "multistable")
with h5py.File(sys.argv[1], "r") as f, h5py.File(sys.argv[2], "r") as g:
    for d in names:
        a, b = f["samples/" + d][:], g["samples/" + d][:]
        assert a.shape == b.shape and a.tobytes() == b.tobytes(), "/samples/%s differs" % d
PY
cat >check.py <<'PY'
import sys, h5py, numpy as np
rtol = float(sys.argv[3])
with h5py.File(sys.argv[1], "r") as f, h5py.File(sys.argv[2], "r") as g:
    s, c = f["samples"], g["samples"]
    psi, po, st, so, start, ms = (s[d][:] for d in ("psi", "psi_other", "status", "status_other", "start", "multistable"))
    term = s["term"][:]
    cold = np.where(start == 0, psi, po)
    cstat = np.where(start == 0, st, so)
    assert cold.tobytes() == c["psi"][:].tobytes(), "the cold psi differs from the plain cold run's"
    assert (cstat == c["status"][:]).all(), "the cold status differs from the plain cold run's"
    both = so >= 0
    conv = both & (st == 0) & (so == 0)
    assert (psi[conv] <= po[conv]).all(), "a kept psi above the other start's"
    assert ((start[conv] == 0) | (psi[conv] < po[conv])).all(), "the continued start kept on a tie"
    want = np.abs(psi - po) > rtol * np.maximum(np.abs(psi), np.abs(po))
    assert (ms[conv] == want[conv]).all(), "the multistable flag disagrees with the two psi"
    assert (ms[~conv] == -1).all(), "a flag on a sample not converged from both starts"
    assert (np.isnan(po[~both])).all() and (start[~both] == 0).all(), "a sample solved once has another psi or a continued start"
    # a start of each half-line (the zero sample and the first sample of each) is solved only cold
    assert (~both).sum() >= 1 and conv.sum() > 0, "nothing compared"
    print("compared %d samples, %d multistable, continued kept %d" % (conv.sum(), (ms == 1).sum(), (start == 1).sum()))
PY
common=(-pattern_type plain -yarn_kc 50 -sampler_terms zero,sx,sa,sx-sa -sampler_n1 7 -sampler_n2 4 -sampler_progress 0.5 -sampler_start both)
# 1 + 7 + 7 + 16 = 31 samples in 13 half-lines: 13 solved only cold, 18 from both starts
$tool "${common[@]}" -sampler_output one.h5 -sampler_view >one.txt 2>&1 || { cat one.txt; die "1-rank run failed"; }
grep -q 'start: both' one.txt || { cat one.txt; die "-sampler_view does not print the start"; }
grep -q 'wrote one.h5: 31 samples' one.txt || { cat one.txt; die "1-rank summary"; }
grep -q -- '-sampler_start both: 18 samples converged from both starts' one.txt || { cat one.txt; die "the summary does not count the 18 samples solved from both starts"; }
for np in 2 3; do
  $MPIEXEC -n $np $tool "${common[@]}" -sampler_output n$np.h5 >n$np.txt 2>&1 || { cat n$np.txt; die "$np-rank run failed"; }
  $py same.py one.h5 n$np.h5 || die "1 and $np ranks give different data with -sampler_start both"
done
$MPIEXEC -n 2 $tool "${common[@]}" -sampler_start cold -sampler_output cold.h5 >cold.txt 2>&1 || { cat cold.txt; die "cold run failed"; }
$py check.py one.h5 cold.h5 1e-3 || die "the samples of -sampler_start both are inconsistent"
# a tighter tolerance flags at least as many samples; the tolerance and the start are part of the identity
$tool "${common[@]}" -sampler_both_rtol 1e-12 -sampler_output tight.h5 >tight.txt 2>&1 || { cat tight.txt; die "-sampler_both_rtol 1e-12 run failed"; }
$py check.py tight.h5 cold.h5 1e-12 || die "the flags of -sampler_both_rtol 1e-12 are inconsistent"
$tool "${common[@]}" -sampler_both_rtol 1e-12 -sampler_output one.h5 -sampler_resume >bad.txt 2>&1 && die "resume with another -sampler_both_rtol accepted"
grep -q "sampler_both_rtol" bad.txt || { cat bad.txt; die "the refusal does not name -sampler_both_rtol"; }
$tool "${common[@]}" -sampler_both_rtol 0 -sampler_output zero.h5 >zero.txt 2>&1 && die "-sampler_both_rtol 0 accepted"
grep -q "sampler_both_rtol 0.*: must be finite and positive" zero.txt || { cat zero.txt; die "-sampler_both_rtol 0: unexpected message"; }

# SIGKILL, then resume on another number of ranks
long=(-pattern_type plain -yarn_kc 50 -sampler_terms sx,sa,sx-sa -sampler_n1 30 -sampler_n2 5 -sampler_progress 0.5 -sampler_start both)
# 30 + 30 + 25 = 85 samples
$tool "${long[@]}" -sampler_output ref.h5 >ref.txt 2>&1 || { cat ref.txt; die "reference run failed"; }
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
    [ -n "$done_before" ] && [ "$done_before" -gt 0 ] && [ "$done_before" -lt 85 ] && break
    echo "attempt $attempt on $np ranks: the kill did not interrupt the run (${done_before:-?} of 85 done); again"
    done_before=
  done
  [ -n "$done_before" ] || die "killed on $np ranks: in 4 attempts no kill interrupted the run"
  $py same.py ref.h5 $k || die "killed on $np ranks, resumed on $other: different data"
  echo "killed on $np ranks after $done_before of 85 samples, resumed on $other: identical"
done
exit 0
