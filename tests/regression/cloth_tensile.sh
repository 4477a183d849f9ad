#!/usr/bin/env bash
# hylc-cloth -cloth_test tensile (docs/fabric.md) on the paper's stock1 and satin1 tables, coarse strips:
# the CSV (header, one row per strain step, T growing with the strain where the table is convex), the
# central zone's force per width within 1 % of the table's own homogeneous uniaxial state
# (hylcmat_uniaxial at the zone's strain), and the same CSV on 1, 2 and 3 ranks (1e-8 relative).
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/stock1.json" ] && [ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
common="-cloth_test tensile -cloth_h 0.005 -cloth_vtk 0 -cloth_plot 0"

# stock1 along x (to 10 %) and y (to 2 %: beyond, the table softens and the strip localizes);
# satin1 along y (to 10 %)
run() { # name material direction strain_max steps
  $cloth -cloth_material "$M/$2.json" $common -cloth_direction $3 -cloth_strain_max $4 -cloth_strain_steps $5 -cloth_output $1 >$1.txt 2>&1 || { cat $1.txt; die "$1: hylc-cloth failed"; }
  [ "$(head -n 1 ${1}_tensile.csv)" = "direction,face,step,strain,T_N_per_m,central_strain,lateral_strain,poisson,T_table,lateral_table,T_rel_diff,newton_its" ] || { head -n 2 ${1}_tensile.csv; die "$1: CSV header"; }
  [ "$(tail -n +2 ${1}_tensile.csv | wc -l)" = "$5" ] || { cat ${1}_tensile.csv; die "$1: expected $5 rows"; }
  # T > 0 and growing; the central zone within 1 % of the table (rows from 1 % strain on)
  awk -F, -v n=$1 'NR > 1 { if ($5 <= Tp) { print n ": T does not grow at row " NR - 1; bad = 1 } Tp = $5
                   if ($4 >= 0.01 - 1e-12 && $11 > 0.01) { print n ": central zone " 100 * $11 " % from the table at strain " $4; bad = 1 } }
                   END { exit bad }' ${1}_tensile.csv || { cat ${1}_tensile.csv; die "$1: tensile curve"; }
  grep -q "central zone vs the table: T within" $1.txt || { cat $1.txt; die "$1: summary line"; }
}
run sx stock1 x 0.1 5
run sy stock1 y 0.02 2
run ty satin1 y 0.1 5
# the Poisson ratio at 5 % is printed and positive for stock1 along x (a knit contracts strongly)
grep -Eq 'Poisson\(5%\) [0-9.]+;' sx.txt || { cat sx.txt; die "Poisson ratio"; }

# rank independence: stock1 along x on 2 and 3 ranks against 1 rank (T and strains 1e-8 relative;
# rounding-level lateral strains 1e-12 absolute)
for n in 2 3; do
  $MPIEXEC -n $n $cloth -cloth_material "$M/stock1.json" $common -cloth_direction x -cloth_strain_max 0.1 -cloth_strain_steps 5 -cloth_output np$n >np$n.txt 2>&1 || { cat np$n.txt; die "$n ranks: hylc-cloth failed"; }
  paste -d, sx_tensile.csv np${n}_tensile.csv | awk -F, -v n=$n 'NR > 1 { for (k = 4; k <= 11; k++) { a = $k; b = $(k + 12); d = a - b; if (d < 0) d = -d; m = a < 0 ? -a : a; if (d > 1e-8 * m + 1e-12) { print n " ranks: column " k " row " NR - 1 ": " a " vs " b; bad = 1 } } } END { exit bad }' || die "$n ranks differ from 1 rank"
done

# bad input: one line naming what is wrong
expect_fail 'cloth_width' $cloth -cloth_material "$M/stock1.json" $common -cloth_width -0.05
finish
