#!/usr/bin/env bash
# tools/small_strain.py (issue 30's report, docs/small-strain.md) on the basket: its 1D terms sampled on the
# thinned plan (-sampler_n1 30, 1D terms only: the 1D fits are those of the whole plan; the stored tile as given,
# -sampler_reference none, as the report solves it), fitted by hylc-fit,
# then the report with --ours and --samples. Checks: every probe table row is there; the probe criterion
# counts the probes above 1 % of their term's range and finds our table within 10 % of the tile on all of
# them (4 of 4 on 2026-11-27: II00 and II11 at +-40 1/m); the RMS table of the 1D terms (ours and the
# paper layout's fit of the same samples) has its five rows; the stationarity line reports the stored basket
# far from stationary (|dPsi/dsx(0)| 97 % of dPsi/dsx at 5 % with config/basket.yaml; checked > 50 %, so a
# change of the model that made it a minimum would show here); a missing samples file is one line.
set -u
cd "$(dirname "$0")/../.."
die() { echo "FAIL: $*"; exit 1; }
pyp=$HYLC_REFDATA/patterns/hylc2020/basket.pyp
[ -r "$pyp" ] && [ -r "$HYLC_REFDATA/materials/basket1.json" ] || { echo "no paper pattern or table under $HYLC_REFDATA"; exit 77; }
/usr/bin/python3 -c 'import h5py' 2>/dev/null || { echo "python3-h5py not installed"; exit 77; }
t=$HYLC_TMP
mkdir -p "$t/ours" "$t/samples"
$MPIEXEC -n 2 "$HYLC_BIN/hylc-sample" -options_file config/basket.yaml -pattern_file "$pyp" -sampler_n1 30 -sampler_terms zero,sx,sa,sy,II00,II11 -sampler_reference none \
  -sampler_output "$t/samples/basket.h5" >"$t/sample.txt" 2>&1 || { cat "$t/sample.txt"; die "hylc-sample failed"; }
"$HYLC_BIN/hylc-fit" -fit_input "$t/samples/basket.h5" -fit_json "$t/ours/basket.json" >"$t/fit.txt" 2>&1 || { cat "$t/fit.txt"; die "hylc-fit failed"; }
BUILD=$(basename "$(dirname "$HYLC_BIN")") /usr/bin/python3 tools/small_strain.py --ours "$t/ours" --samples "$t/samples" basket >"$t/report.md" 2>"$t/report.err" ||
  { cat "$t/report.md" "$t/report.err"; die "small_strain.py failed"; }
[ "$(grep -c '^| \(sx\|sa\|sy\|II00\|II11\) = ' "$t/report.md")" = 28 ] || { cat "$t/report.md"; die "not 28 probe rows"; }
grep -q '^| sx = 0.05 | [-0-9.e]* | [-0-9.e]* ([-0-9.]*) | [-0-9.e]* ([-0-9.]*) |$' "$t/report.md" || { cat "$t/report.md"; die "the probe rows lack a tile, our or the paper's value"; }
crit=$(grep '^Probe criterion' "$t/report.md") || { cat "$t/report.md"; die "no probe criterion line"; }
echo "$crit"
echo "$crit" | grep -Eq ': ([1-9][0-9]*) of \1 probes above 1 % of it have our table within 10 % of the tile\.$' || die "the probe criterion is not met on every counted probe"
# the 1D terms' RMS against the samples, ours beside the paper layout's fit of the same samples
[ "$(grep -c '^| \(sx\|sa\|sy\|II00\|II11\) | [0-9.]* | [0-9.]* | [-+0-9.e]* % |$' "$t/report.md")" = 5 ] || { cat "$t/report.md"; die "not 5 rows of RMS, ours against the paper layout"; }
stat=$(grep '^Stationarity of the tile' "$t/report.md") || { cat "$t/report.md"; die "no stationarity line"; }
echo "$stat"
echo "$stat" | awk '{ if (match($0, /dPsi\/dsx\(sx = 5 %\) = [0-9.]+ %/)) { split(substr($0, RSTART, RLENGTH), w, " "); exit !(w[6] > 50) } exit 1 }' ||
  die "the stored basket's |dPsi/dsx(0)| is not above 50 % of its slope at 5 %"
# a missing samples file: one line naming it
rm "$t/samples/basket.h5"
BUILD=$(basename "$(dirname "$HYLC_BIN")") /usr/bin/python3 tools/small_strain.py --ours "$t/ours" --samples "$t/samples" basket >"$t/r2.md" 2>"$t/r2.err" && die "a missing samples file was accepted"
[ "$(wc -l <"$t/r2.err")" = 1 ] && grep -q "basket.h5" "$t/r2.err" || { cat "$t/r2.err"; die "the error for a missing samples file is not one line naming it"; }
echo ok
