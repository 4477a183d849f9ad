#!/usr/bin/env bash
# An error inside a sample's solve stops the sampling job (issue 12, deliver 2): with HYLC_INJECT_ERROR=3
# each rank's third solve raises an error; the 2-rank job exits != 0 naming it, its journal keeps the
# samples finished before the error (valid records, bitwise equal to an uninterrupted run's), and
# -sampler_resume without the fault completes the run with /samples/psi and /samples/strain bitwise equal
# to an uninterrupted run's. Each run writes to its own fresh output path.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
args="-pattern_type plain -sampler_reference none -sampler_terms zero,sx -sampler_n1 8"

$MPIEXEC -n 2 $tool $args -sampler_output ref.h5 >ref.txt 2>&1 || { cat ref.txt; die "uninterrupted run failed"; }
grep -q 'wrote ref.h5: 9 samples, 0 not converged' ref.txt || { cat ref.txt; die "uninterrupted run: unexpected summary"; }

HYLC_INJECT_ERROR=3 $MPIEXEC -n 2 $tool $args -sampler_output a.h5 >inj.txt 2>&1 && { cat inj.txt; die "job with an injected error exited 0"; }
grep -qF 'injected error (HYLC_INJECT_ERROR=3)' inj.txt || { cat inj.txt; die "injected error not named"; }
grep -q 'wrote a.h5' inj.txt && die "job with an injected error wrote its output"
[ -s a.h5.journal ] || die "journal missing after the error"

py=/usr/bin/python3
havepy=0
[ -x $py ] && $py -c 'import h5py, numpy' >/dev/null 2>&1 && havepy=1
if [ $havepy = 1 ]; then
  # the journal (docs/output-format.md) holds valid records of the samples done before the error, equal
  # to the uninterrupted run's
  $py - a.h5.journal ref.h5 >journal.txt 2>&1 <<'PY' || { cat journal.txt; die "journal check failed"; }
import struct, sys, numpy as np, h5py
b = open(sys.argv[1], "rb").read()
assert b[:8] == b"HYLCJNL1", "journal magic"
L = struct.unpack_from("<I", b, 20)[0]
rs = struct.unpack_from("<I", b, 16)[0]
body = b[40 + L:]
rec = np.dtype([("index", "<i8"), ("term", "<i4"), ("status", "<i4"), ("iterations", "<i4"),
                ("retries", "<i4"), ("z", "<f8", 6), ("psi", "<f8"), ("parts", "<f8", 4),
                ("residual", "<f8"), ("cresidual", "<f8"), ("time", "<f8"), ("fnv", "<u8")])
assert rs == rec.itemsize, "record size %d" % rs
r = np.frombuffer(body[: len(body) // rs * rs], dtype=rec)
assert len(r) >= 1, "no sample in the journal"
with h5py.File(sys.argv[2], "r") as f:
    psi, z = f["samples/psi"][:], f["samples/strain"][:]
for x in r:
    k = int(x["index"])
    assert x["status"] == 0, "sample %d status %d" % (k, x["status"])
    assert x["psi"].tobytes() == psi[k].tobytes() and x["z"].tobytes() == z[k].tobytes(), "sample %d differs" % k
print("journal records", len(r))
PY
fi

$MPIEXEC -n 2 $tool $args -sampler_output a.h5 -sampler_resume >res.txt 2>&1 || { cat res.txt; die "resume failed"; }
grep -q 'wrote a.h5: 9 samples, 0 not converged' res.txt || { cat res.txt; die "resume: unexpected summary"; }
grep -Eq '; [1-9][0-9]* already done' res.txt || { cat res.txt; die "resume did not use the journal"; }

if [ $havepy = 1 ]; then
  $py - ref.h5 a.h5 >cmp.txt 2>&1 <<'PY' || { cat cmp.txt; die "resumed run differs from the uninterrupted run"; }
import sys, h5py
with h5py.File(sys.argv[1], "r") as f, h5py.File(sys.argv[2], "r") as g:
    for d in ("samples/psi", "samples/strain", "samples/status"):
        a, b = f[d][:], g[d][:]
        assert a.shape == b.shape and a.tobytes() == b.tobytes(), d
print("bitwise equal")
PY
else
  command -v h5dump >/dev/null 2>&1 || { echo "neither h5py nor h5dump: cannot compare the files"; exit 77; }
  for d in /samples/psi /samples/strain; do
    h5dump -d $d -m %.17g ref.h5 | sed 1d >r.txt && h5dump -d $d -m %.17g a.h5 | sed 1d >a.txt || die "h5dump $d"
    cmp -s r.txt a.txt || die "$d differs from the uninterrupted run"
  done
fi
exit 0
