#!/usr/bin/env bash
# The uniaxial modes of hylc-solve (-solve_uniaxial, from the yarn tile) and hylc-eval (-eval_uniaxial, from a
# table), docs/fabric-uniaxial.md: the CSV (header, one row per stretch, T > 0 growing with s, the lateral
# stretch contracting), the printed lines, the same T along x and y for the symmetric generated plain weave;
# bad input refused in one line naming the option and the value (an unknown direction, a stretch < 0 or
# >= 1 or outside the table's range, -strain with the uniaxial mode, the CSV option without the mode).
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc"
solve=$HYLC_BIN/hylc-solve
eval_=$HYLC_BIN/hylc-eval
die() { echo "FAIL: $*"; exit 1; }
num='-?[0-9.]+(e[-+][0-9]+)?'

# the yarn tile: a generated plain weave along x and y
for d in x y; do
  $solve -pattern_type plain -solve_uniaxial $d -solve_uniaxial_strains 0.1,0.2 -solve_uniaxial_csv $d.csv >$d.txt 2>&1 || { cat $d.txt; die "hylc-solve -solve_uniaxial $d failed"; }
  [ "$(grep -c "^uniaxial $d: s .* converged;" $d.txt)" = 2 ] || { cat $d.txt; die "$d: expected two converged lines"; }
  grep -q "^poisson ratio -s[xy]/s$d at s = 0.1: " $d.txt || { cat $d.txt; die "$d: Poisson ratio line"; }
  grep -q "^wrote $d.csv$" $d.txt || { cat $d.txt; die "$d: CSV not announced"; }
  [ "$(head -n 1 $d.csv)" = "strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2" ] || { cat $d.csv; die "$d: CSV header"; }
  [ "$(wc -l <$d.csv)" = 3 ] || { cat $d.csv; die "$d: expected 2 rows"; }
  grep -Evq "^$num,$num,$num,$num$" <(tail -n +2 $d.csv) && { cat $d.csv; die "$d: a row is not 4 numbers"; }
  awk -F, 'NR == 2 { s1 = $1; T1 = $2; c1 = $4 } NR == 3 { exit !(s1 == 0.1 && $1 == 0.2 && T1 > 1 && $2 > T1 && c1 < 0 && $4 < c1) }' $d.csv || { cat $d.csv; die "$d: T should grow and the lateral stretch contract"; }
done
paste -d, x.csv y.csv | awk -F, 'NR > 1 { d = $2 - $6; if (d < 0) d = -d; if (d > 1e-5 * $2) exit 1 }' || { paste x.csv y.csv; die "the plain weave's T differs along x and y"; }

# a table: the uniaxial state of a small JSON material with an sx-sy coupling
cat > small.json <<'JSON'
{
  "density": 0.3,
  "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
  "coeffs": {
    "const": 0.0,
    "1D": [{"k": 0, "t": [-0.5, 0.0, 0.5, 1.0], "p": [0.75, 0, 0.75, 3.0], "m": [-3, 0, 3, 6]},
           {"k": 1, "t": [-0.5, 0.0, 0.5], "p": [0.25, 0, 0.25], "m": [-1, 0, 1]},
           {"k": 2, "t": [-0.5, 0.0, 0.5], "p": [0.5, 0, 0.5], "m": [-2, 0, 2]}],
    "2D": [{"k0": 0, "k1": 2, "tu": [-0.5, 1.0], "tv": [-0.5, 1.0], "p": [0.25, -0.5, -0.5, 1.0], "mu": [-0.5, -0.5, 1.0, 1.0], "mv": [-0.5, 1.0, -0.5, 1.0], "muv": [1, 1, 1, 1]}]
  }
}
JSON
# Psi = 3 sx^2 + sa^2 + 2 sy^2 + sx sy: along x the minimum over sy is at sy = -sx / 4, T = 6 s - s / 4 = 5.75 s
$eval_ -material small.json -eval_uniaxial x -eval_uniaxial_strains 0.1,0.2 -eval_uniaxial_csv t.csv >t.txt 2>&1 || { cat t.txt; die "hylc-eval -eval_uniaxial failed"; }
[ "$(head -n 1 t.csv)" = "strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2" ] || { cat t.csv; die "table CSV header"; }
awk -F, 'NR > 1 { t = 5.75 * $1; c = -$1 / 4; if (($2 - t) ^ 2 > 1e-20 || ($4 - c) ^ 2 > 1e-20 || $3 ^ 2 > 1e-20) exit 1 }' t.csv || { cat t.csv; die "table: expected T = 5.75 s, sy = -s/4, sa = 0"; }
grep -q '^poisson ratio -sy/sx at s = 0.1: 0.25$' t.txt || { cat t.txt; die "table: Poisson ratio 0.25"; }

# bad input: one line, naming the option and the value
expect_fail '-solve_uniaxial z: unknown direction' $solve -pattern_type plain -solve_uniaxial z
expect_fail '-solve_uniaxial_strains: stretch -0.1 is outside \[0, 1\)' $solve -pattern_type plain -solve_uniaxial x -solve_uniaxial_strains 0.1,-0.1
expect_fail '-solve_uniaxial_strains: stretch 1\.? is outside \[0, 1\)' $solve -pattern_type plain -solve_uniaxial y -solve_uniaxial_strains 1
expect_fail '-strain cannot be combined with -solve_uniaxial' $solve -pattern_type plain -solve_uniaxial x -strain 0.1,0,0,0,0,0
expect_fail '-solve_uniaxial_strains and -solve_uniaxial_csv need -solve_uniaxial' $solve -pattern_type plain -solve_uniaxial_csv a.csv
expect_fail '-eval_uniaxial diagonal: unknown direction' $eval_ -material small.json -eval_uniaxial diagonal
expect_fail '-eval_uniaxial_strains: stretch 1.5 is outside \[0, 1\)' $eval_ -material small.json -eval_uniaxial x -eval_uniaxial_strains 1.5
expect_fail 'stretch 0.6 along y \(sy = s\) is outside the table.s range \[-0.5, 0.5\] of sy' $eval_ -material small.json -eval_uniaxial y -eval_uniaxial_strains 0.1,0.6 -eval_uniaxial_csv never.csv
[ -e never.csv ] && die "a CSV was written for a refused stretch"
finish
