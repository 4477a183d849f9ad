#!/usr/bin/env bash
# Issue 12, probe 4.6 (fit and eval): every output path of hylc-fit and hylc-eval is checked before any
# work: an output that is a directory, ends in '/', or lies in a missing directory is refused at once,
# with one line naming the option, before the fit runs (no per-term summary) or psi is printed, and no
# file or temporary is left behind.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
fit=$HYLC_BIN/hylc-fit eval=$HYLC_BIN/hylc-eval
"$HYLC_BIN/../tests/test_fit_input" -test_write_samples s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }
cat >m.json <<'JSON'
{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [0, 1], "p": [0, 1], "m": [0, 2]}], "2D": []}}
JSON
mkdir -p adir
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|^samples:|RMS residual|^psi:|^wrote'
expect_fail 'Cannot write adir \(-fit_output\): it is a directory' $fit -fit_input s.h5 -fit_output adir
expect_fail 'Cannot write adir/ \(-fit_json\): it names a directory' $fit -fit_input s.h5 -fit_json adir/
expect_fail 'Cannot write no/such/m.json \(-fit_json\): directory no/such does not exist' $fit -fit_input s.h5 -fit_output ok.h5 -fit_json no/such/m.json
expect_fail 'Cannot write adir \(-eval_hdf5\): it is a directory' $eval -material m.json -strain 0,0,0,0,0,0 -eval_hdf5 adir
expect_fail 'Cannot write no/such/x.json \(-eval_json\): directory no/such does not exist' $eval -material m.json -strain 0,0,0,0,0,0 -eval_json no/such/x.json
[ -e ok.h5 ] && die "ok.h5 written although -fit_json was refused"
[ -z "$(ls adir)" ] || die "something was written into adir"
ls ./*.tmp* >/dev/null 2>&1 && die "a temporary file was left behind"
echo "probe 4.6 (fit, eval): 5 bad outputs refused before any work"
exit 0
