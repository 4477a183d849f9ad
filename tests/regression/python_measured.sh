#!/usr/bin/env bash
# The Python module's measured cloth (python/hylc: MeasuredMaterial, table_tension; docs/measured-cloth.md):
# loading (from a file and from data), the shapes of stiffness / membrane / face / edge, the frozen force
# equal to minus the energy gradient for a stiffness constant in G, the strip states and bending moments
# equal to hylc-eval -eval_sheet's, the export of a table (MeasuredMaterial.fit) and its write / read round
# trip, errors (a malformed file: HylcError naming the file, line and key; a bad direction or shape:
# ValueError). With the reference data: the denim's sheet through Python equals hylc-eval's.
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy not found"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
export PYTHONPATH=$HYLC_ROOT/python
cat >mc.json <<'JSON'
{
  "density": 0.25,
  "stretching": [[20, 2, 30, 5], [40, 5, 60, 8], [42, 6, 61, 9], [45, 12, 62, 4], [47, 6, 63, 9], [50, 5, 70, 10]],
  "bending": [[1e-5, 2e-5, 3e-5, 4e-5, 5e-5], [2e-5, 2e-5, 2e-5, 2e-5, 2e-5], [3e-5, 1e-5, 4e-5, 2e-5, 1e-5]]
}
JSON
printf '{"density": 0.25,\n "stretching": [[20, 2, 30, 5]],\n "bending": []}\n' >bad.json
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
           {"k": 4, "t": [-1.0, 0.0, 1.0], "p": [0.02, 0, 0.02], "m": [-0.04, 0, 0.04]}]
  }
}
JSON
files=(mc.json)
d=$HYLC_REFDATA/materials/wang2011
[ -f "$d/11oz-black-denim.json" ] && files+=("$d/11oz-black-denim.json") || echo "note: no $d: the denim is not compared"
for f in "${files[@]}"; do
  "$HYLC_BIN/hylc-eval" -measured "$f" -eval_sheet -eval_sheet_energy -eval_sheet_json "$(basename "$f" .json)-sheet.json" >/dev/null 2>&1 || die "hylc-eval -measured $f"
done
"$HYLC_BIN/hylc-eval" -material tab.json -eval_sheet -eval_sheet_json tab-sheet.json >/dev/null 2>&1 || die "hylc-eval -material tab.json -eval_sheet"
$py - "${files[@]}" <<'PY' || die "python checks"
import json, math, os, sys
import numpy as np
import hylc

for path in sys.argv[1:]:
    mc = hylc.MeasuredMaterial(path)
    sheet = json.load(open(os.path.basename(path)[:-5] + "-sheet.json"))
    assert mc.density == sheet["density"]
    for d in ("x", "y", "bias"):
        for mode, key in ((False, "tension"), (True, "tension_energy")):
            for row in sheet[key][d]:
                st = mc.tension(d, row["s"], energy=mode)
                assert abs(st["T"] - row["T"]) <= 1e-12 * abs(row["T"]), (path, d, mode, st["T"], row["T"])
                assert abs(st["poisson"] - row["poisson"]) <= 1e-9 * max(1, abs(row["poisson"])), (st, row)
    for d in ("x", "y"):
        for row in sheet["bending"][d]:
            assert mc.bending_moment(d, row["kappa"]) == row["M"]
            assert mc.bending_moment(d, row["kappa"], energy=True) == sheet["bending_energy"][d][[r["kappa"] for r in sheet["bending"][d]].index(row["kappa"])]["M"]
    # shapes
    G = np.random.default_rng(3).uniform(-0.1, 0.2, (4, 5, 3))
    k, dk = mc.stiffness(G, derivative=True)
    assert k.shape == (4, 5, 4) and dk.shape == (4, 5, 4, 3) and mc.sample(G).shape == (4, 5, 4)
    psi, fr, en = mc.membrane(G)
    assert psi.shape == (4, 5) and fr.shape == (4, 5, 3) and en.shape == (4, 5, 3)
    assert mc.stiffness([0.01, 0.0, 0.0]).shape == (4,)
    E, force, grad = mc.face([[0, 0], [0.01, 0], [0, 0.01]], [[0, 0, 0], [0.0105, 0, 0], [0, 0.0099, 0.0003]])
    assert force.shape == (3, 3) and grad.shape == (3, 3) and E > 0
    E, f, info = mc.edge([[0, 0], [0.01, 0], [0.005, 0.01], [0.005, -0.01]], [[0, 0, 0], [0.01, 0, 0], [0.005, 0.01, 0.001], [0.005, -0.01, 0.001]])
    assert f.shape == (4, 3) and info["theta"] > 0 and abs(info["kappa"] - info["theta"] * 0.01 / 1e-4) < 1e-12

# a stiffness constant in G: the frozen force is minus the energy gradient
flat = hylc.MeasuredMaterial(density=0.2, stretching=np.tile([30.0, 4, 50, 6], (6, 1)), bending=np.zeros((3, 5)))
E, force, grad = flat.face([[0, 0], [0.01, 0], [0, 0.01]], [[0, 0, 0], [0.0107, 0.0002, 0], [0.0001, 0.0097, 0.0004]])
assert np.allclose(force, -grad, rtol=0, atol=1e-14 * np.abs(grad).max())
# data round trip through write
mc = hylc.MeasuredMaterial("mc.json")
mc.write("again.json")
again = hylc.MeasuredMaterial("again.json")
assert np.array_equal(again.stretching, mc.stretching) and np.array_equal(again.bending, mc.bending) and again.density == mc.density
# errors
try:
    hylc.MeasuredMaterial("bad.json")
    raise SystemExit("a malformed file was accepted")
except hylc.HylcError as e:
    assert "bad.json:2: stretching: expected 6 rows of 4 numbers, got 1 rows" in str(e), str(e)
for bad in (lambda: mc.tension("z", 0.05), lambda: mc.bending_moment("bias", 10), lambda: mc.stiffness([0.1, 0.2]), lambda: hylc.MeasuredMaterial(density=0.1, stretching=np.zeros(23), bending=np.zeros(15))):
    try:
        bad()
        raise SystemExit("bad input accepted")
    except ValueError:
        pass
try:
    mc.tension("x", 1.5)
    raise SystemExit("a stretch >= 1 was accepted")
except hylc.HylcError as e:
    assert "outside [0, 1)" in str(e)
# a table: its strip states equal hylc-eval's sheet; its export reads back and keeps T along x within 10 %
tab = hylc.Material("tab.json")
sheet = json.load(open("tab-sheet.json"))
for d, ang in (("x", 0.0), ("y", math.pi / 2), ("bias", math.pi / 4)):
    g = None
    for s in np.arange(0.005, 0.1001, 0.005):
        t = hylc.table_tension(tab, ang, s, guess=g)
        g = [1 + t["lateral"], t["shear"]]
        for row in sheet["tension"][d]:
            if abs(row["s"] - s) < 1e-12:
                assert abs(t["T"] - row["T"]) <= 1e-9 * abs(row["T"]), (d, s, t["T"], row["T"])
exp, rep = hylc.MeasuredMaterial.fit(tab)
assert set(rep) == {"rms_tension", "worst_tension", "rms_moment", "prestress", "rest_moment"} and rep["rms_tension"] < 0.2, rep
for row in sheet["tension"]["x"]:
    r = exp.tension("x", row["s"])["T"] / row["T"]
    assert abs(r - 1) < 0.1, ("x", row["s"], r)
print("export of the small table:", {k: round(v, 4) for k, v in rep.items()})
PY
echo "python measured cloth checked"
