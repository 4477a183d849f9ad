#!/usr/bin/env bash
# Issue 12, probe 4.9 (material and fit inputs): a directory given as an input is named as such, never
# "too large (9223372036854775807 bytes)": hylc-eval -material and -material_file, hylc-fit -fit_input
# (a directory without data.txt, with data.txt or info.txt that is itself a directory) and a special
# file (/dev/null). One line, exit != 0, naming the path and the option.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|too large'
mkdir -p adir empty raw1/data.txt raw2
printf '0.1 0 0 0 0 0 0.01\n' >raw2/data.txt
mkdir -p raw2/info.txt
eval=$HYLC_BIN/hylc-eval fit=$HYLC_BIN/hylc-fit
expect_fail 'Cannot read adir \(-material\): it is a directory' $eval -material adir -strain 0,0,0,0,0,0
expect_fail 'Cannot read adir \(-material_file\): it is a directory' $eval -material_file adir -strain 0,0,0,0,0,0
expect_fail 'Cannot read /dev/null \(-material\): not a regular file' $eval -material /dev/null -strain 0,0,0,0,0,0
expect_fail '-fit_input empty is a directory without data.txt' $fit -fit_input empty -fit_json o.json
expect_fail 'Cannot read raw1/data.txt \(-fit_input\): it is a directory' $fit -fit_input raw1 -fit_json o.json
expect_fail 'Cannot read raw2/info.txt \(-fit_input\): it is a directory' $fit -fit_input raw2 -fit_json o.json
expect_fail 'Cannot read /dev/null \(-fit_input\): not a regular file' $fit -fit_input /dev/null -fit_json o.json
echo "probe 4.9: 7 non-file inputs refused with one line"
exit 0
