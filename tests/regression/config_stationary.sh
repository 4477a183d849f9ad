#!/usr/bin/env bash
# config/stockinette.yaml as shipped (issue 30): the paper's stored stockinette tile is stationary at z = 0
# under the configured yarn, |dPsi/dsx(0)| and |dPsi/dsy(0)| below 1 % of the paper table's dPsi/ds at 5 %
# (hylc-calibrate's stat_sx, stat_sy with no iteration; measured +0.0072, -0.0014 at the recalibration,
# docs/method.md, "Small strains", item 3). The other six configs are not stationary, for the reasons that
# section measures; their comments say so. The check is able to fail: with the values shipped before the
# recalibration (E 502.4, Es 5.0e5, G 200.96, kc 37.86) stat_sx is +0.0124, which is tested too. The tile is
# taken as stored (-calibrate_reference none): the default, auto, relaxes it to rest under any yarn.
set -u
cd "$(dirname "$0")/../.."
die() { echo "FAIL: $*"; exit 1; }
pyp=$HYLC_REFDATA/patterns/hylc2020/stockinette.pyp
tab=$HYLC_REFDATA/materials/stock1.json
[ -r "$pyp" ] && [ -r "$tab" ] || { echo "no paper pattern or table under $HYLC_REFDATA"; exit 77; }
out=$HYLC_TMP/stat
# the two stat lines' ratios "after" (both equal "before" with -calibrate_max_it 0)
ratios() { awk '$1 == "stat_sx" || $1 == "stat_sy" { print $1, $6 }' "$1"; }
run() { # label, extra options
  local label=$1
  shift
  $HYLC_BIN/hylc-calibrate -options_file config/stockinette.yaml -pattern_file "$pyp" -calibrate_target "$tab" -calibrate_n 2 -calibrate_stationary 1 -calibrate_max_it 0 -calibrate_reference none "$@" >"$out-$label.txt" 2>&1 ||
    { cat "$out-$label.txt"; die "hylc-calibrate ($label) failed"; }
  [ "$(ratios "$out-$label.txt" | wc -l)" = 2 ] || { cat "$out-$label.txt"; die "($label) no stat_sx, stat_sy lines"; }
  ratios "$out-$label.txt" | sed "s/^/  $label: /"
}
run shipped
ratios "$out-shipped.txt" | awk '{ r = $2 < 0 ? -$2 : $2; if (!(r < 0.01)) { print "  " $1 " = " $2 ": not below 1 %"; bad = 1 } } END { exit bad }' ||
  die "config/stockinette.yaml: the stored tile is not stationary at z = 0"
run old -yarn_E 502.4 -yarn_Es 5.0e5 -yarn_G 200.96 -yarn_kc 37.86
ratios "$out-old.txt" | awk '$1 == "stat_sx" { exit !($2 > 0.01) }' || die "the values before the recalibration pass the 1 % check: the check cannot fail"
echo "ok"
