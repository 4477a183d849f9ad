#!/usr/bin/env bash
# An error inside a sample's solve stops the sampling job (issue 12, deliver 2): with HYLC_INJECT_ERROR=3
# each rank's third solve raises an error; the job exits != 0 naming it, its journal keeps the samples
# finished before the error (valid records, bitwise equal to an uninterrupted run's), and -sampler_resume
# without the fault completes the run with /samples/psi and /samples/strain bitwise equal to an
# uninterrupted run's. On 2 ranks (how many samples rank 0 journals before the other rank's error stops
# it depends on timing) and on 1 rank (exactly 2). Each run writes to its own fresh output path.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
args="-pattern_type plain -sampler_reference none -sampler_terms zero,sx -sampler_n1 8 -sampler_start cold" # cold: a sample per unit of work, so 1 rank journals exactly 2
py=/usr/bin/python3
havepy=0
[ -x $py ] && $py -c 'import h5py, numpy' >/dev/null 2>&1 && havepy=1
if [ $havepy = 0 ] && ! command -v h5dump >/dev/null 2>&1; then
  echo "neither h5py nor h5dump: cannot read the files"
  exit 77
fi

cat >journal.py <<'PY'
# the journal (docs/output-format.md) holds valid records of finished samples, equal to the reference run's
import struct, sys, numpy as np, h5py
b = open(sys.argv[1], "rb").read()
assert b[:8] == b"HYLCJNL1", "journal magic"
assert struct.unpack_from("<I", b, 12)[0] == 6, "journal format version"
rs, L = struct.unpack_from("<II", b, 16)
rec = np.dtype([("index", "<i8"), ("term", "<i4"), ("status", "<i4"), ("iterations", "<i4"),
                ("retries", "<i4"), ("z", "<f8", 6), ("psi", "<f8"), ("parts", "<f8", 4),
                ("residual", "<f8"), ("cresidual", "<f8"), ("time", "<f8"), ("start", "<i4"), ("negcurv", "<i4"),
                ("escapes", "<i4"), ("psi_other", "<f8"), ("status_other", "<i4"), ("multistable", "<i4"),
                ("stress", "<f8", 6), ("fnv", "<u8")])
assert rs == rec.itemsize, "record size %d" % rs
body = b[72 + L:]  # format 6: 64-byte fixed header, identity, 8-byte hash
r = np.frombuffer(body[: len(body) // rs * rs], dtype=rec)
want = int(sys.argv[3])
assert want < 0 or len(r) == want, "%d records in the journal, expected %d" % (len(r), want)
with h5py.File(sys.argv[2], "r") as f:
    psi, z = f["samples/psi"][:], f["samples/strain"][:]
for x in r:
    k = int(x["index"])
    assert x["status"] == 0, "sample %d status %d" % (k, x["status"])
    assert x["psi"].tobytes() == psi[k].tobytes() and x["z"].tobytes() == z[k].tobytes(), "sample %d differs" % k
print("journal records", len(r))
PY
cat >compare.py <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f, h5py.File(sys.argv[2], "r") as g:
    for d in ("samples/psi", "samples/strain", "samples/status"):
        a, b = f[d][:], g[d][:]
        assert a.shape == b.shape and a.tobytes() == b.tobytes(), d
print("bitwise equal")
PY

$MPIEXEC -n 2 $tool $args -sampler_output ref.h5 >ref.txt 2>&1 || { cat ref.txt; die "uninterrupted run failed"; }
grep -q 'wrote ref.h5: 9 samples, 0 not converged' ref.txt || { cat ref.txt; die "uninterrupted run: unexpected summary"; }

check_run() { # nprocs output expected-journal-records (-1: any)
  local np=$1 out=$2 want=$3 n
  HYLC_INJECT_ERROR=3 $MPIEXEC -n "$np" $tool $args -sampler_output "$out" >inj.txt 2>&1 && { cat inj.txt; die "$np ranks: job with an injected error exited 0"; }
  grep -qF 'injected error (HYLC_INJECT_ERROR=3)' inj.txt || { cat inj.txt; die "$np ranks: injected error not named"; }
  grep -qF "wrote $out" inj.txt && die "$np ranks: job with an injected error wrote its output"
  [ -s "$out.journal" ] || die "$np ranks: journal missing after the error"
  if [ $havepy = 1 ]; then
    $py journal.py "$out.journal" ref.h5 "$want" >journal.txt 2>&1 || { cat journal.txt; die "$np ranks: journal check failed"; }
    n=$(sed -n 's/^journal records //p' journal.txt)
  fi

  $MPIEXEC -n 2 $tool $args -sampler_output "$out" -sampler_resume >res.txt 2>&1 || { cat res.txt; die "$np ranks: resume failed"; }
  grep -qF "wrote $out: 9 samples, 0 not converged" res.txt || { cat res.txt; die "$np ranks: resume: unexpected summary"; }
  if [ $havepy = 1 ]; then
    grep -q "; $n already done" res.txt || { cat res.txt; die "$np ranks: resume did not find the $n journal records"; }
    $py compare.py ref.h5 "$out" >cmp.txt 2>&1 || { cat cmp.txt; die "$np ranks: resumed run differs from the uninterrupted run"; }
  else
    for d in /samples/psi /samples/strain; do
      h5dump -d $d -m %.17g ref.h5 | sed 1d >r.txt && h5dump -d $d -m %.17g "$out" | sed 1d >a.txt || die "h5dump $d"
      cmp -s r.txt a.txt || die "$np ranks: $d differs from the uninterrupted run"
    done
  fi
}

check_run 2 a.h5 -1
check_run 1 b.h5 2
exit 0
