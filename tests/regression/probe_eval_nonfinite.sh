#!/usr/bin/env bash
# Issue 12, probe 4.1: hylc-eval on tables at the edge of what the loader accepts never crashes.
# stock1.json with its first 1D term set to t = [0, 5e-324] (a spacing whose inverse overflows) is
# refused with one line naming the file, line and knot; with t = [-1e308, 0, 1e308] (accepted: finite
# spacings) the evaluation at sx = 7.5e307 (and at the largest double, both signs) gives finite psi,
# gradient and Hessian. A 2D term with a too small spacing and a strain scale with an infinite inverse
# are refused the same way.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-eval
R=${HYLC_REFDATA:-}
die() { echo "FAIL: $*"; exit 1; }
[ -n "$R" ] && [ -f "$R/materials/stock1.json" ] || { echo "no \$HYLC_REFDATA/materials/stock1.json: skipped"; exit 77; }
py=/usr/bin/python3
[ -x $py ] || py=python3

$py - "$R/materials/stock1.json" <<'PY' || die "building the tables"
import json, sys
d = json.load(open(sys.argv[1]))
def edit(name, f):
    e = json.loads(json.dumps(d))
    f(e)
    json.dump(e, open(name, "w"), indent=2)
edit("tiny.json", lambda e: e["coeffs"]["1D"][0].update(t=[0, 5e-324], p=[0, 1], m=[0, 0]))
edit("wide.json", lambda e: e["coeffs"]["1D"][0].update(t=[-1e308, 0, 1e308], p=[0, 0.5, 1], m=[1, 0, 2]))
def tiny2(e):
    s = e["coeffs"]["2D"][0]
    s["tu"] = [0, 1e-320] + s["tu"][2:]
edit("tiny2d.json", tiny2)
edit("scale.json", lambda e: e.update({"strain scale": [1e-320, 1, 1, 1, 1]}))
PY

# refused: one line (at most three), exit != 0 and not a crash, naming the file, line and key
expect_refused() { # name message-regex
  local f=$1 want=$2 st
  $tool -material "$f" -strain 0,0,0,0,0,0 >err.txt 2>&1
  st=$?
  [ $st -eq 0 ] && { cat err.txt; die "$f accepted"; }
  [ $st -gt 128 ] && { cat err.txt; die "$f: crashed (exit $st)"; }
  [ "$(wc -l <err.txt)" -le 3 ] || { cat err.txt; die "$f: more than three lines"; }
  grep -Eq -- "$want" err.txt || { cat err.txt; die "$f: message lacks /$want/"; }
  grep -q 'PETSC ERROR' err.txt && { cat err.txt; die "$f: traceback"; }
  return 0
}
expect_refused tiny.json 'tiny.json:[0-9]+: coeffs.1D\[0\].t\[1\]: the knot spacing 5e-324 - 0.0 is too small'
expect_refused tiny2d.json 'tiny2d.json:[0-9]+: coeffs.2D\[0\].tu\[1\]: the knot spacing .* is too small'
expect_refused scale.json 'scale.json:[0-9]+: strain scale\[0\]: must be positive with a finite inverse'

# accepted: finite values at huge strains
num='-?[0-9.]+(e[-+][0-9]+)?'
for st in 7.5e307,0,0,0,0,0 -7.5e307,0,0,0,0,0 1.7976931348623157e308,0,0,0,0,0 -1.7976931348623157e308,0,0,0,0,0 \
          7.5e307,7.5e307,7.5e307,7.5e307,7.5e307,7.5e307 0,0,0,0,0,0 1e-320,0,0,0,0,0; do
  $tool -material wide.json -strain $st -derivatives >out.txt 2>&1
  s=$?
  [ $s -eq 0 ] || { cat out.txt; die "wide.json at $st: exit $s"; }
  grep -Eq "^psi: $num$" out.txt && grep -Eq "^grad:( $num){6}$" out.txt && [ "$(sed -n '4,9p' out.txt | grep -Ec "^$num( $num){5}$")" = 6 ] ||
    { cat out.txt; die "wide.json at $st: non-finite or malformed output"; }
done
# the linear extrapolation is exact: f_0(7.5e307) = 1 + 2 (7.5e307 - 1e308) < 0 (in table units, scale of sx)
$tool -material wide.json -strain 7.5e307,0,0,0,0,0 >out.txt 2>&1 || die "wide.json"
grep -Eq '^psi: -' out.txt || { cat out.txt; die "wide.json at 7.5e307: expected a negative psi (slope 2 from 1e308)"; }
echo "probe 4.1: 3 tables refused, 7 huge strains finite"
exit 0
