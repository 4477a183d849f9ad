#!/usr/bin/env bash
# Probe 4.4: a yarn radius larger than the period used to hang hylc-pattern (the periodic-image search
# ran over ~1e9 images), and periods of 1e-300 overflowed an integer and printed a wrong minimum
# distance. Now: refused quickly, in one line naming the file and the values.
set -u
. "$(dirname "$0")/probe_common.inc"
cd "$HYLC_TMP"
src=$HYLC_REFDATA/patterns/stocktiniest.pyp
[ -r "$src" ] || src=$HYLC_REFDATA/patterns/hylc2020/stocktiniest.pyp
[ -r "$src" ] || { echo "reference pattern stocktiniest.pyp not found"; exit 77; }
tool=$HYLC_BIN/hylc-pattern

sed '2s/.*/0.00072000001 0.00044 1 13/' "$src" >big.pyp
refused radius-over-period 'hylc: error: big.pyp:2: yarn radius 1 is not smaller than the periods \(px = 0.00072, py = 0.00044\)' "$tool" -pattern_file big.pyp
sed '2s/.*/1e-300 1e-300 9.9999997e-05 13/' "$src" >tiny.pyp
refused tiny-periods 'hylc: error: tiny.pyp:2: yarn radius 9.9999997e-05 is not smaller than the periods \(px = 1e-300, py = 1e-300\)' "$tool" -pattern_file tiny.pyp
# a period tiny in y only: the image search would need ~1e298 rings; refused with the numbers
sed '2s/.*/0.00072000001 1e-300 9.9999997e-05 13/' "$src" >tinyy.pyp
refused tiny-period-y 'hylc: error: tinyy.pyp: periods px = 0.00072, py = 1e-300 are too small .*periodic images to search' "$tool" -pattern_file tinyy.pyp
# ...also from hylc-solve, which loads the same file
refused solve-radius-over-period 'big.pyp:2: yarn radius 1 is not smaller' "$HYLC_BIN/hylc-solve" -pattern_file big.pyp -strain 0,0,0,0,0,0

# the unmodified pattern still gives its finite minimum distance
"$tool" -pattern_file "$src" >ok.txt 2>&1 || { cat ok.txt; echo "FAIL: the reference pattern is refused"; exit 1; }
grep -Eq 'min distance: [0-9.]+ r' ok.txt || { cat ok.txt; echo "FAIL: no finite min distance"; exit 1; }
finish
