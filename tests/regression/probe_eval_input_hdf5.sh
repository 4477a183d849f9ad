#!/usr/bin/env bash
# Issue 28, item 6: hylc-eval's HDF5 input. A string-typed /strain printed 16 lines of HDF5 diagnostics
# before the error, a group /strain 7 lines, a chunked /strain declared 1e9 x 6 in a few-KB file a 12-line
# out-of-memory traceback. Now each is one line naming the file and the dataset, HDF5 prints nothing, the
# declared size is checked against what the file stores before anything is allocated, and a NaN or a
# strain outside the domain is named by dataset, row and column. No output is written.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|HDF5-DIAG|evaluated'
die() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
[ -x $py ] && $py -c 'import h5py' 2>/dev/null || { echo "python3 h5py not installed: skipped"; exit 77; }
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >m.json
$py - <<'PY' || die "building the files"
import h5py, numpy as np
with h5py.File("str.h5", "w") as f: f.create_dataset("strain", data=np.array([b"0.1"] * 6).reshape(1, 6))
with h5py.File("grp.h5", "w") as f: f.create_group("strain")
with h5py.File("huge.h5", "w") as f: f.create_dataset("strain", shape=(10**9, 6), dtype="f8", chunks=(100, 6))
with h5py.File("cols.h5", "w") as f: f.create_dataset("strain", data=np.zeros((3, 5)))
with h5py.File("none.h5", "w") as f: f.create_dataset("x", data=np.zeros((3, 6)))
with h5py.File("sgrp.h5", "w") as f: f.create_dataset("samples", data=np.zeros(3))
z = np.zeros((4, 6)); z[2, 1] = np.nan
with h5py.File("nan.h5", "w") as f: f.create_dataset("samples/strain", data=z)
z = np.zeros((4, 6)); z[3, 2] = -1.5
with h5py.File("dom.h5", "w") as f: f.create_dataset("strain", data=z)
z = np.zeros((4, 6)); z[:, 0] = [0, 0.1, 0.2, 0.3]
with h5py.File("ok.h5", "w") as f: f.create_dataset("strain", data=z, compression="gzip")
PY
E=("$HYLC_BIN/hylc-eval" -material m.json -eval_output out.txt)
expect_fail '^hylc: error: str.h5 \(-eval_input\): dataset /strain holds strings, expected numbers$' "${E[@]}" -eval_input str.h5
expect_fail '^hylc: error: grp.h5 \(-eval_input\): /strain is a group, not a dataset$' "${E[@]}" -eval_input grp.h5
expect_fail '^hylc: error: huge.h5 \(-eval_input\): dataset /strain declares 6000000000 values \(48000000000 bytes\) but the file stores 0 bytes of it$' "${E[@]}" -eval_input huge.h5
expect_fail '^hylc: error: cols.h5 \(-eval_input\): dataset /strain has shape \(3 x 5\), expected \(N x 6\)$' "${E[@]}" -eval_input cols.h5
expect_fail '^hylc: error: none.h5 \(-eval_input\): no dataset /strain or /samples/strain$' "${E[@]}" -eval_input none.h5
expect_fail '^hylc: error: sgrp.h5 \(-eval_input\): no dataset /strain or /samples/strain$' "${E[@]}" -eval_input sgrp.h5
expect_fail '^hylc: error: nan.h5: dataset /samples/strain row 2, column 2 \(sa\): nan is not finite$' "${E[@]}" -eval_input nan.h5
expect_fail '^hylc: error: dom.h5: dataset /strain row 3, column 3 \(sy\) = -1.5: the stretch factor 1 \+ sy must be positive$' "${E[@]}" -eval_input dom.h5
[ -e out.txt ] && die "out.txt written by a refused run"
# a compressed (chunked, deflate) dataset is read
"${E[@]}" -eval_input ok.h5 >ok.txt 2>&1 && grep -q '^evaluated 4 strains from ok.h5' ok.txt || { cat ok.txt; die "ok.h5 (gzip) not read"; }
[ "$(grep -v '^#' out.txt | tr '\n' ' ')" = "0.5 0.51900000000000002 0.57200000000000006 0.65300000000000002 " ] || { cat out.txt; die "ok.h5: psi"; }
finish
