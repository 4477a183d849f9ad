#!/usr/bin/env bash
# Issue 12, probe 4.10: numeric edges of hylc-eval.
# - stock1.json at -strain 0,0,0,1e155,1,0 gives a finite psi (sqrt(B^2 + C^2) no longer overflows);
# - a subnormal strain (1e-320) is accepted (finite is finite) and gives psi at 0; 1e999 is refused;
# - every paper table ($HYLC_REFDATA/materials/*.json) gives finite psi, gradient and Hessian at
#   three extreme finite strains (+-1e308 mixed, huge curvatures, +-1e-320 mixed).
# The full sweep (each component alone and mixed, +-1e-320 ... the largest double, 1000 random mixes,
# extreme built-in tables, every paper table) is the unit test test_material_extreme.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-eval
R=${HYLC_REFDATA:-}
die() { echo "FAIL: $*"; exit 1; }
[ -n "$R" ] && [ -d "$R/materials" ] || { echo "no \$HYLC_REFDATA/materials: skipped"; exit 77; }
num='-?[0-9.]+(e[-+][0-9]+)?'
finite() { # output file: psi, grad, 6 Hessian rows of finite numbers
  grep -Eq "^psi: $num$" "$1" && grep -Eq "^grad:( $num){6}$" "$1" && [ "$(sed -n '4,9p' "$1" | grep -Ec "^$num( $num){5}$")" = 6 ]
}

$tool -material "$R/materials/stock1.json" -strain 0,0,0,1e155,1,0 -derivatives >out.txt 2>&1 || { cat out.txt; die "1e155"; }
finite out.txt || { cat out.txt; die "stock1 at 0,0,0,1e155,1,0: not finite"; }
$tool -material "$R/materials/stock1.json" -strain 0,0,0,0,0,0 >zero.txt 2>&1 || die "zero strain"
$tool -material "$R/materials/stock1.json" -strain 1e-320,0,-1e-320,1e-320,0,0 >sub.txt 2>&1 || { cat sub.txt; die "1e-320 refused"; }
cmp -s zero.txt sub.txt || { cat zero.txt sub.txt; die "psi at 1e-320 differs from psi at 0"; }
$tool -material "$R/materials/stock1.json" -strain 1e999,0,0,0,0,0 >err.txt 2>&1 && die "1e999 accepted"
grep -q "'1e999' is not a finite number" err.txt || { cat err.txt; die "1e999: message"; }

n=0
for f in "$R"/materials/*.json; do
  for st in 1e308,-1e308,1e308,-1e308,1e308,-1e308 0.1,0,0,1e300,1e300,-1e300 1e-320,-1e-320,1e-320,-1e-320,1e-320,-1e-320; do
    $tool -material "$f" -strain $st -derivatives >out.txt 2>&1
    s=$?
    [ $s -eq 0 ] || { cat out.txt; die "$(basename "$f") at $st: exit $s"; }
    finite out.txt || { cat out.txt; die "$(basename "$f") at $st: not finite"; }
    n=$((n + 1))
  done
done
echo "probe 4.10: $n evaluations of the paper's tables at extreme strains, all finite"
exit 0
