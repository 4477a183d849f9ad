#!/usr/bin/env bash
# Issue 12, probe 4.7: hylc-fit checks every /samples dataset by name, shape and type before reading it.
# /samples/psi one row short, /samples/psi missing, /samples/strain with 5 columns and an integer
# dataset stored as doubles are each refused with one line naming the file and the dataset (no HDF5
# traceback); -fit_raw_n2 2147483598 (and -fit_raw_n1 2147483647) no longer wrap around the row check
# of a raw data.txt. The samples file is the small synthetic one of test_fit_input; the edits use h5py.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-fit
die() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
[ -x $py ] || py=python3
$py -c 'import h5py' 2>/dev/null || { echo "python3 h5py not installed: skipped"; exit 77; }
"$HYLC_BIN/../tests/test_fit_input" -test_write_samples s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }
sum0=$(md5sum <s.h5)

$py - <<'PY' || die "building the malformed files"
import h5py, shutil
def edit(name, f):
    shutil.copy("s.h5", name)
    with h5py.File(name, "r+") as h:
        f(h["samples"])
def short(g):
    d = g["psi"][:-1]; del g["psi"]; g.create_dataset("psi", data=d)
def missing(g):
    del g["psi"]
def cols(g):
    d = g["strain"][:, :5]; del g["strain"]; g.create_dataset("strain", data=d)
def ftype(g):
    d = g["term"][:].astype("f8"); del g["term"]; g.create_dataset("term", data=d)
def nogroup(g):
    pass
edit("short.h5", short)
edit("nopsi.h5", missing)
edit("cols.h5", cols)
edit("ftype.h5", ftype)
with h5py.File("nosamples.h5", "w") as h:
    h.create_dataset("x", data=[1.0])
# a raw layout: 5 1D blocks of 2 rows and 9 2D blocks of 1 x 1
rows = []
for t, c in enumerate([0, 1, 2, 3, 5]):
    for i in range(2):
        z = [0.0] * 6; z[c] = 0.1 * (i + 1); rows.append(z + [0.01 * (i + 1)])
pairs = [(0, 1), (0, 2), (0, 3), (0, 5), (1, 2), (1, 3), (1, 5), (2, 3), (2, 5)]
for a, b in pairs:
    z = [0.0] * 6; z[a] = 0.1; z[b] = 0.1; rows.append(z + [0.02])
import os
os.makedirs("raw", exist_ok=True)
open("raw/data.txt", "w").write("\n".join(" ".join(repr(v) for v in r) for r in rows) + "\n")
open("raw/info.txt", "w").write("density 0.2\n")
PY

. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|HDF5-DIAG'
fit_fail() { # message-regex hylc-fit-args...: refused, and no output written
  expect_fail "$1" "$tool" "${@:2}"
  [ -e out.json ] && die "out.json written by a failed run: ${*:2}"
  return 0
}
fit_fail 'short.h5 \(-fit_input\): dataset /samples/psi has shape \(4350\), expected \(4351\)' -fit_input short.h5 -fit_json out.json
fit_fail 'nopsi.h5 \(-fit_input\): no dataset /samples/psi$' -fit_input nopsi.h5 -fit_json out.json
fit_fail 'cols.h5 \(-fit_input\): dataset /samples/strain has shape \(4351 x 5\), expected \(N x 6\)' -fit_input cols.h5 -fit_json out.json
fit_fail 'ftype.h5 \(-fit_input\): dataset /samples/term holds floating-point numbers, expected integers' -fit_input ftype.h5 -fit_json out.json
fit_fail 'nosamples.h5 \(-fit_input\): no group /samples' -fit_input nosamples.h5 -fit_json out.json
fit_fail 'raw/data.txt: -fit_raw_n1 0 and -fit_raw_n2 2147483598 must be in 0..19' -fit_input raw -fit_raw_n2 2147483598 -fit_json out.json
fit_fail 'raw/data.txt: -fit_raw_n1 2147483647 and -fit_raw_n2 0 must be in 0..19' -fit_input raw -fit_raw_n1 2147483647 -fit_json out.json
fit_fail 'raw/data.txt: 19 rows do not make 5 1D blocks of n1 = 1 rows and 9 2D blocks of n2 x n2 = 1 x 1' -fit_input raw -fit_raw_n1 1 -fit_raw_n2 1 -fit_json out.json
# the raw data's block sizes are still found (the row check passes, the fit then runs)
"$tool" -fit_input raw -fit_raw_n1 2 -fit_raw_n2 1 -fit_terms sx -fit_min_samples_1d 2 -fit_knots1d 2 >raw.txt 2>&1
grep -q 'rows do not make' raw.txt && { cat raw.txt; die "raw: 5 x 2 + 9 x 1 rows refused"; }
[ "$(md5sum <s.h5)" = "$sum0" ] || die "s.h5 changed"
echo "probe 4.7: 8 malformed inputs refused with one line"
exit 0
