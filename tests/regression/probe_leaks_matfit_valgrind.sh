#!/usr/bin/env bash
# Issue 12, probe 4.12 (material and fit): no definite leak on the error exits of hylc-fit and hylc-eval
# (valgrind --leak-check=full --errors-for-leak-kinds=definite; Open MPI's own allocations in
# MPI_Init/MPI_Finalize suppressed by tests/valgrind.supp). The malformed material files are covered by
# material_malformed_valgrind.sh; here: a raw data.txt with a bad number and with a bad row count, a
# fit refused after reading its input, an output that is the input, and a material refused by the
# loader's spacing rule.
set -u
here=$(cd "$(dirname "$0")" && pwd)
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
command -v valgrind >/dev/null || { echo "valgrind not installed"; exit 77; }
vg=(valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite --num-callers=50 --suppressions="$here/../valgrind.supp")
fit=$HYLC_BIN/hylc-fit eval=$HYLC_BIN/hylc-eval
"$HYLC_BIN/../tests/test_fit_input" -test_write_samples s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }
mkdir -p raw bad
printf '0.1 0 0 0 0 0 0.01\n' >raw/data.txt
printf '0.1 0 0 0 0 0 0.01\n0.2 0 0 x 0 0 0.01\n' >bad/data.txt
cat >tiny.json <<'JSON'
{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [0, 1e-320], "p": [0, 1], "m": [0, 2]}], "2D": []}}
JSON
n=0
case_() { # message-regex command...
  local want=$1 st; shift
  "${vg[@]}" "$@" >err.txt 2>&1
  st=$?
  n=$((n + 1))
  [ $st -eq 99 ] && { cat err.txt; die "valgrind: memory error or definite leak: $*"; }
  [ $st -eq 0 ] && { cat err.txt; die "accepted: $*"; }
  grep -Eq -- "$want" err.txt || { cat err.txt; die "message lacks /$want/: $*"; }
  return 0
}
case_ "bad/data.txt:2: column 4 \(II00\): 'x' is not a number" $fit -fit_input bad -fit_json o.json
case_ 'raw/data.txt: 1 rows do not make' $fit -fit_input raw -fit_json o.json
case_ 'term sx has only 150 usable samples' $fit -fit_input s.h5 -fit_min_samples_1d 151
case_ 'Output s.h5 \(-fit_output\) is the input' $fit -fit_input s.h5 -fit_output s.h5
case_ 'tiny.json:1: coeffs.1D\[0\].t\[1\]: the knot spacing' $eval -material tiny.json -strain 0,0,0,0,0,0
echo "probe 4.12 (material, fit): $n error exits without a definite leak"
exit 0
