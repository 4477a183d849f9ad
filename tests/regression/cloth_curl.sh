#!/usr/bin/env bash
# hylc-cloth -cloth_test curl (docs/fabric.md): a free 3 x 2 cm strip, no gravity, relaxes from flat.
# stock1 (the paper's stockinette prefers II00 < 0, II11 > 0): the central zone curls with the table's
# signs, short of the table's free curl (a strip cannot take both curvatures without in-plane strain), the
# same relative to n with either face up; satin1 (no preferred curvature) stays flat.
set -u
cd "$HYLC_TMP"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/stock1.json" ] && [ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
for f in up down; do
  $cloth -cloth_material $M/stock1.json -cloth_test curl -cloth_face $f -cloth_plot 0 -cloth_vtk 0 -cloth_output s$f >s$f.txt 2>&1 || { cat s$f.txt; die "stock1 face $f failed"; }
  awk -F, 'NR == 2 { exit !($1 < -20 && $2 > 20 && $1 > $3 && $2 < $4 && $3 < 0 && $4 > 0) }' s${f}_curl.csv || { cat s${f}_curl.csv; die "stock1 face $f: expected II00 < 0 < II11, short of the table's curl"; }
done
paste -d, sup_curl.csv sdown_curl.csv | awk -F, 'NR == 2 { for (k = 1; k <= 2; k++) { d = $k - $(k + 4); if (d < 0) d = -d; m = $k < 0 ? -$k : $k; if (d > 0.05 * m) exit 1 } }' || die "stock1: face up and down differ by more than 5 % relative to n"
$cloth -cloth_material $M/satin1.json -cloth_test curl -cloth_plot 0 -cloth_vtk 0 -cloth_output t >t.txt 2>&1 || { cat t.txt; die "satin1 failed"; }
awk -F, 'NR == 2 { exit !($1 * $1 + $2 * $2 < 1e-12) }' t_curl.csv || { cat t_curl.csv; die "satin1 should stay flat"; }
