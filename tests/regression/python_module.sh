#!/usr/bin/env bash
# The Python module (python/hylc, ctypes over libhylcmat.so) with Debian's /usr/bin/python3: shapes of
# evaluate(), hessian=False, HDF5 materials (converted by hylc-eval) equal to their JSON, a malformed
# table raising HylcError with file:line, and agreement with hylc-eval to 1e-15 relative on the
# paper's tables ($HYLC_REFDATA/materials/*.json; a small built-in table without them).
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy, h5py" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy and h5py not found"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
export PYTHONPATH=$HYLC_ROOT/python
cat >small.json <<'JSON'
{
  "density": 0.3,
  "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
  "coeffs": {
    "const": 0.5,
    "1D": [{"k": 3, "t": [-1.0, 0.0, 1.0], "p": [1, 0, 1], "m": [-1, 0, 1]}],
    "2D": [{"k0": 0, "k1": 3, "tu": [0, 1], "tv": [0, 1], "p": [0, 0, 0, 1], "mu": [0, 0, 0, 0], "mv": [0, 0, 0, 0], "muv": [0, 0, 0, 0]}]
  }
}
JSON
printf '{\n  "density": 0.3,\n  "strain scale": [1, 1, 1, 1, 1],\n  "coeffs": {"const": 0, "1D": [{"k": 0, "t": [0, 0], "p": [0, 0], "m": [0, 0]}]}\n}' >bad.json
tables=(small.json)
if [ -d "$HYLC_REFDATA/materials" ]; then
  for f in "$HYLC_REFDATA"/materials/*.json; do
    "$HYLC_BIN/hylc-eval" -material "$f" -strain 0,0,0,0,0,0 >/dev/null 2>&1 && tables+=("$f")
  done
else
  echo "note: no $HYLC_REFDATA/materials: the paper's tables are not compared"
fi
strains=(0,0,0,0,0,0 0.1,0,0,0,0,0 0.05,0.1,-0.05,20,5,-30 0,0,0,40,0,40 -0.1,-0.2,0.15,-60,25,10 0.3,0.4,0.3,300,-200,300)
: >expected.txt
for t in "${tables[@]}"; do
  "$HYLC_BIN/hylc-eval" -material "$t" -eval_hdf5 "$(basename "$t" .json).h5" >/dev/null || die "hylc-eval -eval_hdf5 $t"
  for s in "${strains[@]}"; do
    "$HYLC_BIN/hylc-eval" -material "$t" -strain "$s" -derivatives >e.txt 2>&1 || { cat e.txt; die "hylc-eval $t $s"; }
    echo "$t $s $(sed 's/^[a-z]*://' e.txt | tr '\n' ' ')" >>expected.txt
  done
done
$py - <<'PY' || die "python checks"
import numpy as np, os, hylc
rows = [l.split() for l in open("expected.txt")]
tables = {}
for r in rows:
    tables.setdefault(r[0], []).append(([float(x) for x in r[1].split(",")], [float(x) for x in r[2:]]))
worst = 0.0
for path, cases in tables.items():
    m = hylc.Material(path)
    S = np.array([c[0] for c in cases])
    psi, grad, hess = m.evaluate(S)
    assert psi.shape == (len(S),) and grad.shape == (len(S), 6) and hess.shape == (len(S), 6, 6)
    p2, g2 = m.evaluate(S, hessian=False)
    assert np.array_equal(p2, psi) and np.array_equal(g2, grad)
    ours = np.concatenate([psi[:, None], grad, hess.reshape(len(S), 36)], axis=1)
    ref = np.array([c[1] for c in cases])
    scale = np.maximum(np.abs(ref), 1e-300)
    rel = np.abs(ours - ref) / scale
    rel[(ours == ref)] = 0
    worst = max(worst, rel.max())
    if rel.max() > 1e-15:
        i, j = np.unravel_index(rel.argmax(), rel.shape)
        raise SystemExit("%s: strain %s component %d: python %.17g, hylc-eval %.17g" % (path, S[i], j, ours[i, j], ref[i, j]))
    h5 = os.path.basename(path)[:-5] + ".h5"
    mh = hylc.Material(h5)
    ph, gh, hh = mh.evaluate(S)
    assert np.array_equal(ph, psi) and np.array_equal(gh, grad) and np.array_equal(hh, hess), h5 + " differs from its JSON"
    assert mh.density == m.density and np.array_equal(mh.strain_scale, m.strain_scale)
one = hylc.Material("small.json").evaluate([0, 0, 0, 50, 0, 50], hessian=False)
assert one[0] == 0.875 and one[1].shape == (6,), one
try:
    hylc.Material("bad.json")
    raise SystemExit("bad.json: no error")
except hylc.HylcError as e:
    assert "bad.json:4: coeffs.1D[0].t[1]: knots must be strictly increasing" in str(e), str(e)
d = hylc.read_material_h5("small.h5")
assert d["constant"] == 0.5 and "II00" in d["1D"] and d["attrs"]["format"] == "hylc-material", d
print("python agrees with hylc-eval on %d tables x %d strains (worst relative difference %.3g)" % (len(tables), len(rows) // len(tables), worst))
PY
