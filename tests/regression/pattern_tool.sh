#!/usr/bin/env bash
# hylc-pattern end to end: summary lines, .pyp output, VTK export, -help, unused-option warning,
# and identical results on 1 and 2 MPI ranks.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-pattern
die() { echo "FAIL: $*"; exit 1; }

$tool -pattern_type basket -pattern_radius 5e-4 -pattern_output b.pyp -pattern_vtk b.vtk -pattern_vtk_tiles 3,2 >out1.txt 2>&1 || { cat out1.txt; die "basket generation failed"; }
for want in 'vertices: 128' 'loops: 8' 'periods: 0.008 0.008' 'radius: 0.0005' 'loop 0: 16 vertices, winding \(1, 0\)' 'loop 7: 16 vertices, winding \(0, 1\)' 'yarn length:' 'area density:' 'min distance: 2\.[0-9]+ r' 'wrote b.pyp' 'wrote b.vtk \(3 x 2 tiles\)'; do
  grep -Eq "$want" out1.txt || { cat out1.txt; die "summary lacks /$want/"; }
done

# the written file loads and summarizes identically
$tool -pattern_file b.pyp >out2.txt 2>&1 || { cat out2.txt; die "reload failed"; }
diff <(grep -v -e '^ *file:' -e '^ *type:' -e '^wrote' out1.txt) <(grep -v -e '^ *file:' -e '^ *type:' out2.txt) || die "summary changed after the .pyp round trip"

# VTK: 3x2 copies of 8 loops, each loop 16 vertices + the closing point
head -n 4 b.vtk | grep -q 'DATASET POLYDATA' || die "VTK header"
grep -q '^POINTS 816 double' b.vtk || die "VTK point count: $(grep ^POINTS b.vtk)"
grep -q '^LINES 48 864' b.vtk || die "VTK line count: $(grep ^LINES b.vtk)"
grep -q '^CELL_DATA 48' b.vtk || die "VTK cell data"

# the same on two ranks
$MPIEXEC -n 2 $tool -pattern_file b.pyp >out3.txt 2>&1 || { cat out3.txt; die "2-rank run failed"; }
diff <(grep -v 'MPI process' out2.txt) <(grep -v 'MPI processes' out3.txt) || die "1 and 2 ranks differ"

# -help documents every option of the tool
$tool -help >help.txt 2>&1
for opt in -pattern_file -pattern_type -pattern_radius -pattern_spacing -pattern_gap -pattern_wale -pattern_course -pattern_depth -pattern_seglen -pattern_size -pattern_density -pattern_exclude_arc -pattern_output -pattern_vtk -pattern_vtk_tiles; do
  grep -q -- "$opt" help.txt || die "-help does not document $opt"
done

# a misspelt option is reported, not silently ignored
$tool -pattern_type plain -pattern_radus 2e-3 -pattern_output typo.pyp >typo.txt 2>&1 && { cat typo.txt; die "a misspelt option was accepted"; }
grep -q '^hylc: error: Unknown option(s): -pattern_radus ' typo.txt || { cat typo.txt; die "the misspelt option is not named"; }
[ ! -e typo.pyp ] || die "a pattern was written despite the misspelt option"

# bad option values give clear errors
$tool -pattern_type satin -pattern_size 4,5 >bad.txt 2>&1 && die "satin with size 4,5 accepted"
grep -q 'repeats every 5 threads' bad.txt || { cat bad.txt; die "unclear size error"; }
$tool -pattern_type plain -pattern_spacing 0.003 >bad.txt 2>&1 && die "too small spacing accepted"
grep -q 'too small for crimped crossings' bad.txt || { cat bad.txt; die "unclear spacing error"; }
$tool -pattern_type weave >bad.txt 2>&1 && die "unknown type accepted"
grep -qi 'weave' bad.txt || { cat bad.txt; die "unclear type error"; }
exit 0
