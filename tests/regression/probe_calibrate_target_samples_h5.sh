#!/usr/bin/env bash
# Issue 28, item 3: a samples.h5 target of hylc-calibrate with /samples/psi, status or term deleted, a
# string-typed status, /samples a dataset, a psi declared with 1e10 rows, or a psi one row short printed a
# 14-line PETSc traceback (or "samples/strain has an unexpected shape") and leaked its read buffers. Now
# each is one line naming the file and the dataset (HDF5 prints nothing), the same as hylc-fit's for the
# same file; a converged sample with a NaN energy is refused by dataset and row. The inputs are unchanged
# and no work is started. probe_readers_valgrind.sh checks the error exits for leaks.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|HDF5-DIAG|\[calibrate\]'
die() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
[ -x $py ] && $py -c 'import h5py' 2>/dev/null || { echo "python3 h5py not installed: skipped"; exit 77; }
cal=$HYLC_BIN/hylc-calibrate fit=$HYLC_BIN/hylc-fit
mkdir -p in
"$HYLC_BIN/hylc-sample" -pattern_type plain -sampler_terms zero,sx -sampler_n1 4 -yarn_kc 50 -sampler_output in/s.h5 >sample.txt 2>&1 || { cat sample.txt; die "hylc-sample failed"; }
$py - <<'PY' || die "building the malformed files"
import h5py, shutil, numpy as np
def edit(name, f):
    shutil.copy("in/s.h5", "in/" + name)
    with h5py.File("in/" + name, "r+") as h:
        f(h)
edit("nopsi.h5", lambda h: h["samples"].__delitem__("psi"))
edit("nostatus.h5", lambda h: h["samples"].__delitem__("status"))
edit("noterm.h5", lambda h: h["samples"].__delitem__("term"))
def strstatus(h):
    g = h["samples"]; del g["status"]; g.create_dataset("status", data=np.array([b"ok"] * 5))
edit("strstatus.h5", strstatus)
def dataset(h):
    del h["samples"]; h.create_dataset("samples", data=[1.0])
edit("dataset.h5", dataset)
def big(h):
    g = h["samples"]; del g["psi"]; g.create_dataset("psi", shape=(10**10,), dtype="f8", chunks=(1000,))
edit("bigpsi.h5", big)
def bigall(h):
    g = h["samples"]
    for k in list(g.keys()):
        d = g[k]; shape = (10**10,) + d.shape[1:]; dt = d.dtype; del g[k]
        g.create_dataset(k, shape=shape, dtype=dt, chunks=(1000,) + d.shape[1:])
edit("bigall.h5", bigall)
def short(h):
    g = h["samples"]; d = g["psi"][:-1]; del g["psi"]; g.create_dataset("psi", data=d)
edit("short.h5", short)
def nanpsi(h):
    d = h["samples/psi"][:]; d[2] = np.nan; h["samples/psi"][...] = d
edit("nanpsi.h5", nanpsi)
PY
sum0=$(cat in/* | sha256sum)
args=(-pattern_type plain -calibrate_reference none -calibrate_max_it 2)
for f in nopsi:psi nostatus:status noterm:term; do
  expect_fail "^hylc: error: in/${f%%:*}.h5 \(-calibrate_target\): no dataset /samples/${f#*:}$" "$cal" "${args[@]}" -calibrate_target in/${f%%:*}.h5
  expect_fail "^hylc: error: in/${f%%:*}.h5 \(-fit_input\): no dataset /samples/${f#*:}$" "$fit" -fit_input in/${f%%:*}.h5 -fit_json o.json
done
expect_fail '^hylc: error: in/strstatus.h5 \(-calibrate_target\): dataset /samples/status holds strings, expected integers$' "$cal" "${args[@]}" -calibrate_target in/strstatus.h5
expect_fail '^hylc: error: in/dataset.h5 \(-calibrate_target\): /samples is a dataset, not a group$' "$cal" "${args[@]}" -calibrate_target in/dataset.h5
expect_fail '^hylc: error: in/bigpsi.h5 \(-calibrate_target\): dataset /samples/psi has shape \(10000000000\), expected \(5\)' "$cal" "${args[@]}" -calibrate_target in/bigpsi.h5
expect_fail '^hylc: error: in/bigall.h5 \(-calibrate_target\): dataset /samples/strain declares 60000000000 values \(480000000000 bytes\) but the file stores 0 bytes of it$' "$cal" "${args[@]}" -calibrate_target in/bigall.h5
expect_fail '^hylc: error: in/bigall.h5 \(-fit_input\): dataset /samples/strain declares 60000000000 values' "$fit" -fit_input in/bigall.h5 -fit_json o.json
expect_fail '^hylc: error: in/short.h5 \(-calibrate_target\): dataset /samples/psi has shape \(4\), expected \(5\): one row per row of /samples/strain$' "$cal" "${args[@]}" -calibrate_target in/short.h5
expect_fail '^hylc: error: in/nanpsi.h5: dataset /samples/psi row 2: nan is not finite \(a converged sample\)$' "$cal" "${args[@]}" -calibrate_target in/nanpsi.h5
expect_fail '^hylc: error: in/nanpsi.h5: dataset /samples/psi row 2: nan is not finite' "$fit" -fit_input in/nanpsi.h5 -fit_json o.json
[ -e o.json ] && die "hylc-fit wrote o.json"
# the untouched file is a target
"$cal" "${args[@]}" -calibrate_target in/s.h5 >ok.txt 2>&1 || { cat ok.txt; die "in/s.h5 refused"; }
grep -q 'target in/s.h5 (samples), 5 samples' ok.txt || { cat ok.txt; die "in/s.h5: expected 5 samples"; }
[ "$(cat in/* | sha256sum)" = "$sum0" ] || die "an input was changed"
finish
