#!/usr/bin/env bash
# hylc-eval -eval_sheet (docs/measured-cloth.md): the sheet of a measured-cloth material (-measured) and of
# a table (-material): the printed lines (T > 0 growing with s, the bias shearing, M > 0), -eval_sheet_json
# (the same numbers), -eval_sheet_energy (the energy's T beside the balance's); bad input refused in one
# line naming the file, line and key or the option and value. On the ten fabrics of Wang et al. 2011 (when
# $HYLC_REFDATA/materials/wang2011 is present): every sheet is complete.
set -u
cd "$HYLC_TMP"
ev=$HYLC_BIN/hylc-eval
die() { echo "FAIL: $*"; exit 1; }
num='-?[0-9.]+(e[-+][0-9]+)?'
cat >mc.json <<'JSON'
{
  "density": 0.25,
  "stretching": [
    [20, 2, 30, 5],
    [40, 5, 60, 8],
    [42, 6, 61, 9],
    [45, 12, 62, 4],
    [47, 6, 63, 9],
    [50, 5, 70, 10]
  ],
  "bending": [
    [1e-5, 2e-5, 3e-5, 4e-5, 5e-5],
    [2e-5, 2e-5, 2e-5, 2e-5, 2e-5],
    [3e-5, 1e-5, 4e-5, 2e-5, 1e-5]
  ]
}
JSON
$ev -measured mc.json -eval_sheet -eval_sheet_energy -eval_sheet_json mc-sheet.json >out.txt 2>&1 || { cat out.txt; die "hylc-eval -measured -eval_sheet failed"; }
grep -q '^sheet of the measured cloth mc.json: strips at the balance of the frozen-stiffness forces' out.txt || { cat out.txt; die "header"; }
grep -q '^density: 0.25 kg/m^2$' out.txt || { cat out.txt; die "density line"; }
for d in x y bias; do
  [ "$(grep -Ec "^tension $d: s (0.02|0.05|0.1) T $num N/m lateral $num poisson $num shear $num$" out.txt)" = 3 ] || { cat out.txt; die "tension $d lines"; }
  [ "$(grep -Ec "^tension $d energy: s (0.02|0.05|0.1) T $num N/m lateral .* \(T [-+][0-9.]+ % against the balance\)$" out.txt)" = 3 ] || { cat out.txt; die "tension $d energy lines"; }
  awk -v d="$d" '$1 == "tension" && $2 == d":" { T[++n] = $6 } END { exit !(n == 3 && T[1] > 0 && T[2] > T[1] && T[3] > T[2]) }' out.txt || { cat out.txt; die "$d: T should grow with s"; }
done
awk '$1 == "tension" && $2 == "bias:" && $4 == 0.05 { exit !($14 != 0) } ' out.txt || { cat out.txt; die "the bias strip should shear"; }
for d in x y; do
  [ "$(grep -Ec "^bending $d: kappa (10|20|40) 1/m M $num N m/m$" out.txt)" = 3 ] || { cat out.txt; die "bending $d lines"; }
done
# M = k kappa / 4 with k the sample of the edges across the bend: x curves -> edges along v (row 2), at kappa 10: 1e-5
grep -q '^bending x: kappa 10 1/m M 2.500000e-05 N m/m$' out.txt || { cat out.txt; die "bending x at 10 1/m: expected k kappa/4 = 1e-5 * 10 / 4"; }
grep -q '^bending y: kappa 20 1/m M 1.500000e-04 N m/m$' out.txt || { cat out.txt; die "bending y at 20 1/m: expected the edges along u (row 0) at 20 1/m, 3e-5 * 20 / 4"; }
grep -q '^wrote mc-sheet.json$' out.txt || die "JSON not announced"
/usr/bin/python3 - <<'PY' || die "the sheet JSON"
import json, re
d = json.load(open("mc-sheet.json"))
assert d["kind"] == "measured" and d["density"] == 0.25
lines = open("out.txt").read().splitlines()
for dr in ("x", "y", "bias"):
    for row in d["tension"][dr]:
        l = [x for x in lines if x.startswith("tension %s: s %g " % (dr, row["s"]))][0].split()
        assert abs(float(l[5]) - row["T"]) <= 1e-6 * row["T"], (l, row)
    assert len(d["tension_energy"][dr]) == 3
assert [r["kappa"] for r in d["bending"]["x"]] == [10, 20, 40]
PY
# a table's sheet
cat >tab.json <<'JSON'
{
  "density": 0.3,
  "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
  "coeffs": {
    "const": 0.0,
    "1D": [{"k": 0, "t": [-0.5, 0.0, 0.5, 1.0], "p": [0.75, 0, 0.75, 3.0], "m": [-3, 0, 3, 6]},
           {"k": 1, "t": [-0.5, 0.0, 0.5], "p": [0.25, 0, 0.25], "m": [-1, 0, 1]},
           {"k": 2, "t": [-0.5, 0.0, 0.5], "p": [0.5, 0, 0.5], "m": [-2, 0, 2]},
           {"k": 3, "t": [-1.0, 0.0, 1.0], "p": [0.01, 0, 0.01], "m": [-0.02, 0, 0.02]},
           {"k": 4, "t": [-1.0, 0.0, 1.0], "p": [0.02, 0, 0.02], "m": [-0.04, 0, 0.04]}],
    "2D": [{"k0": 0, "k1": 2, "tu": [-0.5, 1.0], "tv": [-0.5, 1.0], "p": [0.25, -0.5, -0.5, 1.0], "mu": [-0.5, -0.5, 1.0, 1.0], "mv": [-0.5, 1.0, -0.5, 1.0], "muv": [1, 1, 1, 1]}]
  }
}
JSON
$ev -material tab.json -eval_sheet -eval_sheet_strains 0.03,0.08 -eval_sheet_curvatures 5 >tab.txt 2>&1 || { cat tab.txt; die "hylc-eval -material -eval_sheet failed"; }
grep -q '^sheet of the table tab.json: strips with Psi minimized over the lateral strains' tab.txt || { cat tab.txt; die "table header"; }
[ "$(grep -Ec "^tension (x|y|bias): s (0.03|0.08) T $num N/m lateral $num poisson $num shear $num$" tab.txt)" = 6 ] || { cat tab.txt; die "table tension lines"; }
# the table's T along x is hylc-eval -eval_uniaxial's
$ev -material tab.json -eval_uniaxial x -eval_uniaxial_strains 0.03 >uni.txt 2>&1 || { cat uni.txt; die "-eval_uniaxial"; }
Tu=$(sed -n 's/^uniaxial x: s 0.03 T \([^ ]*\) N\/m.*/\1/p' uni.txt)
Ts=$(sed -n 's/^tension x: s 0.03 T \([^ ]*\) N\/m.*/\1/p' tab.txt)
awk -v a="$Tu" -v b="$Ts" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * a) }' || die "the sheet's T along x ($Ts) is not -eval_uniaxial's ($Tu)"
# bending: dPsi/dII00 at II00 = 5 1/m: the 1D term 100 * 0.01 * (5/100)^2 ... its derivative: p'(0.05) / 100
grep -Eq "^bending x: kappa 5 1/m M $num N m/m$" tab.txt || { cat tab.txt; die "table bending line"; }

# errors: one line naming the file, line and key, or the option and value
check_err() { # expected message, then the command
  local want=$1; shift
  "$@" >e.txt 2>&1 && { cat e.txt; die "accepted: $*"; }
  grep -q "^hylc: error: $want" e.txt || { cat e.txt; die "expected '$want' for: $*"; }
  [ "$(grep -c '^hylc: error:' e.txt)" = 1 ] || { cat e.txt; die "more than one error line: $*"; }
}
sed 's/\[42, 6, 61, 9\]/[42, 6, "61", 9]/' mc.json >bad1.json
check_err 'bad1.json:6: stretching\[2\]\[2\]: expected a number, got a string' $ev -measured bad1.json -eval_sheet
sed 's/"density": 0.25/"density": -0.25/' mc.json >bad2.json
check_err 'bad2.json:2: density: the area density must be finite and >= 0 (kg/m^2), got -0.25' $ev -measured bad2.json -eval_sheet
sed 's/"bending"/"bend"/' mc.json >bad3.json
check_err 'bad3.json:11: unknown key "bend"' $ev -measured bad3.json -eval_sheet
check_err 'Cannot open nosuch.json (-measured): No such file or directory' $ev -measured nosuch.json -eval_sheet
check_err '-measured and -material exclude each other' $ev -measured mc.json -material tab.json -eval_sheet
check_err 'Nothing to do with -measured: give -eval_sheet' $ev -measured mc.json
check_err '-eval_sheet_strains: stretch 1.5 is outside (0, 1)' $ev -measured mc.json -eval_sheet -eval_sheet_strains 0.1,1.5
check_err '-eval_sheet_energy is for a measured-cloth material' $ev -material tab.json -eval_sheet -eval_sheet_energy
check_err '-eval_sheet_strains, -eval_sheet_curvatures, -eval_sheet_energy and -eval_sheet_json need -eval_sheet' $ev -measured mc.json -eval_sheet_json x.json
check_err '-measured takes -eval_sheet only' $ev -measured mc.json -eval_sheet -strain 0,0,0,0,0,0

# the ten fabrics
dir=$HYLC_REFDATA/materials/wang2011
if [ -d "$dir" ]; then
  n=0
  for f in "$dir"/*.json; do
    $ev -measured "$f" -eval_sheet -eval_sheet_energy >f.txt 2>&1 || { cat f.txt; die "sheet of $f"; }
    [ "$(grep -Ec "^tension (x|y|bias): s .* T $num N/m" f.txt)" = 9 ] || { cat f.txt; die "$f: a strip state was not reached"; }
    [ "$(grep -Ec "^tension (x|y|bias) energy: s .* T $num N/m" f.txt)" = 9 ] || { cat f.txt; die "$f: an energy state was not reached"; }
    n=$((n + 1))
  done
  [ $n = 10 ] || die "expected the ten fabrics, found $n"
  echo "the sheets of the ten fabrics are complete"
else
  echo "note: no $dir: the ten fabrics are not checked"
fi
echo "hylc-eval -eval_sheet checked"
