#!/usr/bin/env bash
# hylc-cloth -cloth_test bias (docs/fabric.md) on the paper's satin1 table, a coarse 0.15 x 0.05 m strip
# at 45 degrees: the CSV (header, one row per step), the force and the central zone's shear angle growing
# with the extension, the shear angle below 45 degrees, the same CSV on 2 ranks (1e-8 relative), and a
# length not above the width refused in one line.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
common="-cloth_material $M/satin1.json -cloth_test bias -cloth_h 0.005 -cloth_vtk 0 -cloth_plot 0 -cloth_strain_max 0.1 -cloth_strain_steps 5"

$cloth $common -cloth_output b1 >b1.txt 2>&1 || { cat b1.txt; die "hylc-cloth bias failed"; }
[ "$(head -n 1 b1_bias.csv)" = "step,strain,extension_m,force_N,F_per_width_N_per_m,shear_deg,shear_kinematic_deg,sx,sy,newton_its" ] || { head -n 2 b1_bias.csv; die "CSV header"; }
[ "$(tail -n +2 b1_bias.csv | wc -l)" = 5 ] || { cat b1_bias.csv; die "expected 5 rows"; }
awk -F, 'NR > 1 { if (!($4 > Fp && $6 > gp && $6 < 45)) { print "row " NR - 1 ": F " $4 " (before " Fp "), shear " $6 " (before " gp ")"; bad = 1 } Fp = $4; gp = $6 } END { exit bad }' b1_bias.csv || { cat b1_bias.csv; die "force and shear angle should grow"; }
grep -q "central shear angle" b1.txt || { cat b1.txt; die "summary line"; }

$MPIEXEC -n 2 $cloth $common -cloth_output b2 >b2.txt 2>&1 || { cat b2.txt; die "2 ranks: hylc-cloth failed"; }
paste -d, b1_bias.csv b2_bias.csv | awk -F, 'NR > 1 { for (k = 2; k <= 9; k++) { a = $k; b = $(k + 10); d = a - b; if (d < 0) d = -d; m = a < 0 ? -a : a; if (d > 1e-8 * m + 1e-12) { print "column " k " row " NR - 1 ": " a " vs " b; bad = 1 } } } END { exit bad }' || die "2 ranks differ from 1 rank"

expect_fail 'bias: -cloth_length 0.05 m must exceed -cloth_width 0.05 m' $cloth -cloth_material $M/satin1.json -cloth_test bias -cloth_length 0.05 -cloth_width 0.05 -cloth_output never
finish
