#!/usr/bin/env bash
# Probe 4.9: a directory given as the pattern file was reported as "too large (9223372036854775807
# bytes)"; .pyp and VTK output was written in place, so a failed write left a partial file. Now the
# directory is named as such, outputs are checked before the work and written via a temporary renamed
# into place: a failing write (here: a file size limit) leaves an existing output untouched and no
# temporary behind.
set -u
. "$(dirname "$0")/probe_common.inc"
cd "$HYLC_TMP"
P=$HYLC_BIN/hylc-pattern
mkdir -p adir.pyp
refused input-directory "^hylc: error: Cannot read adir.pyp \(-pattern_file\): it is a directory$" $P -pattern_file adir.pyp
refused output-directory "^hylc: error: Cannot write adir.pyp \(-pattern_output\): it is a directory$" $P -pattern_type plain -pattern_output adir.pyp
refused output-missing-dir "^hylc: error: Cannot write nodir/x.pyp \(-pattern_output\): directory nodir does not exist$" $P -pattern_type plain -pattern_output nodir/x.pyp
refused vtk-directory "^hylc: error: Cannot write adir.pyp \(-pattern_vtk\): it is a directory$" $P -pattern_type plain -pattern_vtk adir.pyp
$P -pattern_type plain -pattern_output in.pyp >/dev/null 2>&1 || { echo "FAIL: cannot write in.pyp"; exit 1; }
refused output-is-input "^hylc: error: Output in.pyp \(-pattern_output\) is the input in.pyp \(-pattern_file\)" $P -pattern_file in.pyp -pattern_output in.pyp

# a write that fails midway (a file size limit of 16 KiB, SIGXFSZ ignored so that write() fails with EFBIG; PMIx's
# shared-memory store, which would hit the limit in MPI_Init, replaced by its hash store)
echo "previous content" >out.pyp
echo "previous content" >out.vtk
( export PMIX_MCA_gds=hash; trap "" XFSZ; ulimit -f 16; exec $P -pattern_type satin -pattern_output out.pyp ) >w.txt 2>&1
st=$?
[ $st -ne 0 ] && [ $st -lt 128 ] || { cat w.txt; echo "FAIL: failed .pyp write: exit $st"; exit 1; }
grep -q "^hylc: error: Cannot write out.pyp: File too large" w.txt || { cat w.txt; echo "FAIL: .pyp write error not reported"; exit 1; }
[ "$(cat out.pyp)" = "previous content" ] || { echo "FAIL: out.pyp was changed by a failed write"; exit 1; }
( export PMIX_MCA_gds=hash; trap "" XFSZ; ulimit -f 16; exec $P -pattern_type satin -pattern_vtk out.vtk -pattern_vtk_tiles 4,4 ) >w.txt 2>&1
st=$?
[ $st -ne 0 ] && [ $st -lt 128 ] || { cat w.txt; echo "FAIL: failed VTK write: exit $st"; exit 1; }
grep -q "^hylc: error: Cannot write out.vtk: File too large" w.txt || { cat w.txt; echo "FAIL: VTK write error not reported"; exit 1; }
[ "$(cat out.vtk)" = "previous content" ] || { echo "FAIL: out.vtk was changed by a failed write"; exit 1; }
ls | grep -q '\.tmp\.' && { ls; echo "FAIL: a temporary was left behind"; exit 1; }
# and a successful write replaces the file
$P -pattern_type plain -pattern_output out.pyp >/dev/null 2>&1 && grep -q '^\*pattern' out.pyp || { echo "FAIL: write failed"; exit 1; }
finish
