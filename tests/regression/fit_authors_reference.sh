#!/usr/bin/env bash
# hylc-fit -fit_compat authors against the tables that the HYLC authors' own fitting code (pyHYLC) made
# of the same synthetic data.txt ($HYLC_REFDATA/pyhylc, README.md there): the default case (clean/) and
# the stockinette settings (clean_stockinette/, -fit_family stockinette). Table by table, knot by knot,
# each difference relative to the largest |value| of the reference array must be below: knots 1e-12,
# 1D values and slopes 1e-9, 2D values 1e-8, mu and mv 1e-6, muv 1e-5; const, density and the strain
# scale to 1e-12, and the same terms in the same order. Prints the largest relative difference per array.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-fit
die() { echo "FAIL: $*"; exit 1; }
ref=${HYLC_REFDATA:-}/pyhylc
if [ -z "${HYLC_REFDATA:-}" ] || [ ! -d "$ref" ]; then
  echo "skipped: the authors' reference fits \$HYLC_REFDATA/pyhylc (../shared/refdata/pyhylc) not found"
  exit 77
fi
py=/usr/bin/python3
[ -x $py ] || py=$(command -v python3 || true)
[ -n "$py" ] || { echo "skipped: no python3 to compare the JSON tables"; exit 77; }
[ -x "$tool" ] || die "missing $tool (run make)"

cat >compare.py <<'PY'
import json, sys
ours, theirs = (json.load(open(f)) for f in sys.argv[1:3])
tol1 = {"t": 1e-12, "p": 1e-9, "m": 1e-9}
tol2 = {"tu": 1e-12, "tv": 1e-12, "p": 1e-8, "mu": 1e-6, "mv": 1e-6, "muv": 1e-5}
bad = []
def rel(a, b):
    a, b = list(map(float, a)), list(map(float, b))
    if len(a) != len(b):
        return float("inf")
    big = max(abs(x) for x in b) if b else 0.0
    d = max((abs(x - y) for x, y in zip(a, b)), default=0.0)
    return d / big if big > 0 else d
def check(label, a, b, tol):
    r = rel(a, b)
    print(f"  {label:16s} {r:9.2e}  (tol {tol:g})")
    if not r <= tol:
        bad.append(f"{label}: {r:.3e} > {tol:g}" + ("" if r != float("inf") else f" (sizes {len(a)} vs {len(b)})"))
check("const", [ours["coeffs"]["const"]], [theirs["coeffs"]["const"]], 1e-12)
check("density", [ours["density"]], [theirs["density"]], 1e-12)
check("strain scale", ours["strain scale"], theirs["strain scale"], 1e-12)
for dim, tol, key in (("1D", tol1, lambda s: (s["k"],)), ("2D", tol2, lambda s: (s["k0"], s["k1"]))):
    a, b = ours["coeffs"][dim], theirs["coeffs"][dim]
    ka, kb = [key(s) for s in a], [key(s) for s in b]
    if ka != kb:
        bad.append(f"{dim} terms {ka} vs reference {kb}")
        continue
    for s, r in zip(a, b):
        name = dim + " " + ",".join(map(str, key(s)))
        for f, t in tol.items():
            check(f"{name} {f}", s[f], r[f], t)
if bad:
    print("differences above tolerance:\n  " + "\n  ".join(bad))
    sys.exit(1)
PY

fail=0
for case in clean clean_stockinette; do
  opts=()
  [ $case = clean_stockinette ] && opts=(-fit_family stockinette)
  [ -f "$ref/$case/data.txt" ] && [ -f "$ref/$case/$case.json" ] || die "$ref/$case lacks data.txt or $case.json"
  $tool -fit_input "$ref/$case" -fit_compat authors "${opts[@]}" -fit_json $case.json >$case.txt 2>&1 || { cat $case.txt; die "fit of $case failed"; }
  echo "$case (-fit_compat authors ${opts[*]}): largest |ours - authors'| / max |authors'| per array"
  $py compare.py $case.json "$ref/$case/$case.json" || { echo "FAIL: $case differs from the authors' table"; fail=1; }
done
exit $fail
