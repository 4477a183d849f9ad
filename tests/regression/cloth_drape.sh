#!/usr/bin/env bash
# hylc-cloth -cloth_test drape (Cusick, static, docs/fabric.md) on the paper's satin1 table, a coarse
# disc (h = 2 cm): the drape coefficient in (0, 1) with at least 3 nodes, the outline CSV (360 sectors,
# radii between the support's and the specimen's), no vertex inside the support pedestal (VTK), the same
# CSV on 2 ranks (1e-8 relative) with the default solver (hylc's Cholesky on every rank) and with MUMPS
# and one of its options (-cloth_mat_mumps_icntl_14, read at the first factorization), the option
# refused on 1 rank where nothing reads it, and a support disc not
# smaller than the specimen refused in one line.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
common="-cloth_material $M/satin1.json -cloth_test drape -cloth_h 0.02 -cloth_plot 0"

$cloth $common -cloth_output d1 >d1.txt 2>&1 || { cat d1.txt; die "hylc-cloth drape failed"; }
line=$(grep '^  drape coefficient' d1.txt) || { cat d1.txt; die "summary line"; }
echo "$line" | awk '{ dc = $3; n = $0; sub(/.*\), /, "", n); split(n, a, " "); exit !(dc > 0 && dc < 1 && a[1] >= 3) }' || die "expected 0 < DC < 1 and >= 3 nodes: $line"
[ "$(grep -c '^-\?[0-9.]*,[0-9.e-]*$' d1_drape.csv)" = 360 ] || { head d1_drape.csv; die "expected 360 sectors"; }
awk -F, 'NR > 2 { if (!($2 > 0.09 - 1e-9 && $2 < 0.15 * 1.05)) { print "sector " $1 ": r " $2; bad = 1 } } END { exit bad }' d1_drape.csv || die "outline radius out of [disc, specimen]"
# no vertex inside the pedestal (r < 0.09 m, z below its top at -0.0005 m)
awk '/^POINTS/ { n = $2; getline; while (n > 0) { for (k = 1; k <= NF; k += 3) { r = sqrt($k * $k + $(k + 1) * $(k + 1)); if (r < 0.09 - 1e-6 && $(k + 2) < -0.0005) bad = 1; n-- } if (n > 0) getline } exit bad }' d1_drape.vtk || die "a vertex inside the support"

# on 2 ranks: the default (every rank factors the whole matrix with hylc's Cholesky, PCREDUNDANT), and MUMPS
# chosen with one of MUMPS' options, read at the first factorization: accepted (issue 32)
cmp_csv() { paste -d, <(tail -n +3 d1_drape.csv) <(tail -n +3 "$1") | awk -F, '{ d = $2 - $4; if (d < 0) d = -d; if (d > 1e-8 * $2) { print "sector " $1 ": " $2 " vs " $4; bad = 1 } } END { exit bad }'; }
$MPIEXEC -n 2 $cloth $common -cloth_output d2 >d2.txt 2>&1 || { cat d2.txt; die "2 ranks: hylc-cloth failed"; }
cmp_csv d2_drape.csv || die "2 ranks differ from 1 rank"
$MPIEXEC -n 2 $cloth $common -cloth_pc_type cholesky -cloth_pc_factor_mat_solver_type mumps -cloth_mat_mumps_icntl_14 60 -cloth_output d4 >d4.txt 2>&1 || { cat d4.txt; die "2 ranks, MUMPS: hylc-cloth failed (or refused -cloth_mat_mumps_icntl_14)"; }
cmp_csv d4_drape.csv || die "2 ranks with MUMPS differ from 1 rank"

# on 1 rank (hylc's Cholesky) nothing reads it: refused at the end, not silently ignored
$cloth $common -cloth_mat_mumps_icntl_14 60 -cloth_output d3 >d3.txt 2>&1 && { cat d3.txt; die "1 rank: -cloth_mat_mumps_icntl_14 accepted without MUMPS"; }
grep -q "option -cloth_mat_mumps_icntl_14 60 was not used" d3.txt || { cat d3.txt; die "1 rank: the unused MUMPS option not named"; }

expect_fail '-cloth_drape_diameter 0.1 and -cloth_drape_disc 0.18: need 0 < disc < specimen' $cloth -cloth_material $M/satin1.json -cloth_test drape -cloth_drape_diameter 0.1 -cloth_output never
finish
