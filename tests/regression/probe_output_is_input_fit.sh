#!/usr/bin/env bash
# Issue 12, probe 4.5 (fit and eval): an output that is an input is refused before any work and the
# input is left as it was: hylc-fit -fit_output / -fit_json equal to -fit_input (same name, another
# spelling, a hard link, a symbolic link), to data.txt or info.txt of a raw directory, or to info.txt
# beside a raw data.txt; -fit_output and -fit_json naming one file; hylc-eval -eval_json / -eval_hdf5
# equal to -material or -material_file, and the two outputs naming one file.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
fit=$HYLC_BIN/hylc-fit eval=$HYLC_BIN/hylc-eval
"$HYLC_BIN/../tests/test_fit_input" -test_write_samples s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }
ln -f s.h5 hard.h5
ln -sf s.h5 sym.h5
mkdir -p raw sub
printf '0.1 0 0 0 0 0 0.01\n' >raw/data.txt
printf 'density 0.2\n' >raw/info.txt
cat >m.json <<'JSON'
{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [0, 1], "p": [0, 1], "m": [0, 2]}], "2D": []}}
JSON
sums() { md5sum s.h5 raw/data.txt raw/info.txt m.json; }
sums >before.txt
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|^samples:|^psi:'
check_fail() { # message-regex command...: refused, and no input changed
  expect_fail "$@"
  sums | cmp -s - before.txt || die "an input changed: ${*:2}"
}
check_fail 'Output s.h5 \(-fit_output\) is the input s.h5 \(-fit_input\)' $fit -fit_input s.h5 -fit_output s.h5
check_fail 'Output ./s.h5 \(-fit_json\) is the input s.h5 \(-fit_input\)' $fit -fit_input s.h5 -fit_json ./s.h5
check_fail 'Output hard.h5 \(-fit_output\) is the input s.h5' $fit -fit_input s.h5 -fit_output hard.h5
check_fail 'Output sym.h5 \(-fit_json\) is the input s.h5' $fit -fit_input s.h5 -fit_json sym.h5
check_fail 'Output sub/../s.h5 \(-fit_output\) is the input s.h5' $fit -fit_input s.h5 -fit_output sub/../s.h5
check_fail 'Output raw/data.txt \(-fit_json\) is the input raw/data.txt \(-fit_input\)' $fit -fit_input raw -fit_json raw/data.txt
check_fail 'Output raw/info.txt \(-fit_output\) is the input raw/info.txt \(-fit_input\)' $fit -fit_input raw -fit_output raw/info.txt
check_fail 'Output raw/info.txt \(-fit_json\) is the input raw/info.txt \(-fit_input\)' $fit -fit_input raw/data.txt -fit_json raw/info.txt
check_fail '-fit_output and -fit_json name the same file x.out' $fit -fit_input s.h5 -fit_output x.out -fit_json x.out
check_fail 'Output m.json \(-eval_json\) is the input m.json \(-material\)' $eval -material m.json -eval_json m.json -strain 0,0,0,0,0,0
check_fail 'Output ./m.json \(-eval_hdf5\) is the input m.json \(-material_file\)' $eval -material_file m.json -eval_hdf5 ./m.json -strain 0,0,0,0,0,0
check_fail '-eval_json and -eval_hdf5 name the same file y.out' $eval -material m.json -eval_json y.out -eval_hdf5 y.out
[ -e x.out ] || [ -e y.out ] && die "an output was written by a refused run"
ls ./*.tmp* raw/*.tmp* >/dev/null 2>&1 && die "a temporary file was left behind"
echo "probe 4.5 (fit, eval): 12 outputs naming an input refused, inputs unchanged"
exit 0
