#!/usr/bin/env bash
# hylc-cloth -cloth_test cantilever (ASTM D1388 option A, docs/fabric.md) on the paper's satin1 table, a
# 1 cm wide strip along x, face up, with 8, 16 and 32 row spacings over the overhang (h, h/2, h/4): the
# CSV, the elastica of the table's bending term beside it; the shell's bending length computed with 16
# spacings (and with 32) within 1 % of the elastica's, and the mesh convergence reported and better than
# first order (the differences c(h/2) - c(h) and c(h/4) - c(h/2) shrink by more than 3; the clamp held at
# the platform edge's rows, bending.c); the same CSV on 2 and 3 ranks (1e-8 relative).
set -u
cd "$HYLC_TMP"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
common="-cloth_material $M/satin1.json -cloth_test cantilever -cloth_direction x -cloth_face up -cloth_cantilever_width 0.01 -cloth_vtk 0 -cloth_plot 0"

for n in 8 16 32; do
  $cloth $common -cloth_cantilever_n $n -cloth_output n$n >n$n.txt 2>&1 || { cat n$n.txt; die "n = $n: hylc-cloth failed"; }
  [ "$(head -n 1 n${n}_cantilever.csv)" = "direction,face,overhang_m,c_mm,G_uNm,c_elastica_mm,rel_diff,curvature_along_per_m,curvature_across_per_m,newton_its" ] || { cat n${n}_cantilever.csv; die "n = $n: CSV header"; }
  grep -q "secant not converged" n$n.txt && { cat n$n.txt; die "n = $n: the overhang search did not converge"; }
done
paste -d, n8_cantilever.csv n16_cantilever.csv n32_cantilever.csv | awk -F, 'NR == 2 { c8 = $4; c16 = $14; c32 = $24; ce = $6; r8 = (c8 - ce) / ce; r16 = (c16 - ce) / ce; r32 = (c32 - ce) / ce; d1 = c16 - c8; d2 = c32 - c16
  q = d2 != 0 ? d1 / d2 : 1e300
  printf "elastica c %.6g mm; 8 spacings %.6g mm (%+.3g %%), 16 %.6g mm (%+.3g %%), 32 %.6g mm (%+.3g %%); differences %.3g, %.3g mm (ratio %.3g)\n", ce, c8, 100 * r8, c16, 100 * r16, c32, 100 * r32, d1, d2, q
  if (!(ce > 0)) { print "no elastica"; exit 1 }
  if (r16 * r16 > 1e-4) { print "16 spacings: not within 1 % of the elastica"; exit 1 }
  if (r32 * r32 > 1e-4) { print "32 spacings: not within 1 % of the elastica"; exit 1 }
  if (!(q > 3 || q < -3)) { print "the mesh convergence is first order (ratio of the differences <= 3)"; exit 1 } }' || die "the shell's bending length vs the elastica's"

for n in 2 3; do
  $MPIEXEC -n $n $cloth $common -cloth_cantilever_n 8 -cloth_output np$n >np$n.txt 2>&1 || { cat np$n.txt; die "$n ranks: hylc-cloth failed"; }
  paste -d, n8_cantilever.csv np${n}_cantilever.csv | awk -F, -v n=$n 'NR > 1 { for (k = 3; k <= 9; k++) { a = $k; b = $(k + 10); d = a - b; if (d < 0) d = -d; m = a < 0 ? -a : a; if (d > 1e-8 * m + 1e-12) { print n " ranks: column " k ": " a " vs " b; bad = 1 } } } END { exit bad }' || die "$n ranks differ from 1 rank"
done
