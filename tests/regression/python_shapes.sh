#!/usr/bin/env bash
# Issue 33, item 7: the Python module (python/hylc on PYTHONPATH, the checkout's libhylcmat.so):
# hylc.__version__ equals hylc's own version (HYLC_VERSION_STRING of include/hylc/sys.h);
# Material.evaluate accepts strains of any shape (..., 6) and returns psi (...), grad (..., 6), hess
# (..., 6, 6) with the values of the same strains evaluated as one (N, 6) batch; a last axis other than
# 6 is a ValueError; repr names the file, density and terms, Mesh's its size; every public function,
# class, method and property has a docstring.
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy not found"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
export PYTHONPATH=$HYLC_ROOT/python
want=$(sed -n 's/^#define HYLC_VERSION_STRING "\(.*\)"/\1/p' "$HYLC_ROOT/include/hylc/sys.h")
[ -n "$want" ] || die "no HYLC_VERSION_STRING in include/hylc/sys.h"
cat >small.json <<'JSON'
{
  "density": 0.3,
  "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
  "coeffs": {
    "const": 0.5,
    "1D": [{"k": 3, "t": [-1.0, 0.0, 1.0], "p": [1, 0, 1], "m": [-1, 0, 1]},
           {"k": 0, "t": [-1.0, 0.0, 1.0], "p": [2, 0, 3], "m": [-4, 0, 5]}],
    "2D": [{"k0": 0, "k1": 3, "tu": [-1, 1], "tv": [-1, 1], "p": [0, 0, 0, 1], "mu": [0, 0, 0, 0], "mv": [0, 0, 0, 0], "muv": [0, 0, 0, 0]}]
  }
}
JSON
$py - "$want" <<'PY' || die "python checks"
import inspect, sys
import numpy as np
import hylc
want = sys.argv[1]
assert hylc.__version__ == want, "hylc.__version__ %r, include/hylc/sys.h %r" % (hylc.__version__, want)
m = hylc.Material("small.json")
rng = np.random.default_rng(33)
checked = 0
for lead in [(), (0,), (1,), (7,), (2, 3), (4, 1, 5), (1, 1, 1, 1)]:
    S = rng.uniform(-0.3, 0.3, lead + (6,))
    S[..., 3:] *= 100
    psi, grad, hess = m.evaluate(S)
    assert np.shape(psi) == lead and grad.shape == lead + (6,) and hess.shape == lead + (6, 6), (lead, np.shape(psi), grad.shape, hess.shape)
    p2, g2 = m.evaluate(S, hessian=False)
    p3 = m.psi(S)
    assert np.shape(p2) == lead and g2.shape == lead + (6,) and np.shape(p3) == lead
    flat = S.reshape(-1, 6)
    fp, fg, fh = m.evaluate(flat) if flat.shape[0] else (np.empty(0), np.empty((0, 6)), np.empty((0, 6, 6)))
    assert np.array_equal(np.reshape(psi, -1), fp) and np.array_equal(grad.reshape(-1, 6), fg) and np.array_equal(hess.reshape(-1, 6, 6), fh), lead
    assert np.array_equal(np.reshape(p2, -1), fp) and np.array_equal(np.reshape(p3, -1), fp)
    # each entry equals the evaluation of that strain alone
    for idx in np.ndindex(*lead):
        one = m.evaluate(S[idx])
        assert np.ndim(one[0]) == 0 and one[1].shape == (6,) and one[2].shape == (6, 6)
        assert one[0] == psi[idx] and np.array_equal(one[1], grad[idx]) and np.array_equal(one[2], hess[idx]), idx
    if flat.shape[0]:
        assert np.any(grad != 0) and np.any(hess != 0), lead
    checked += 1
# a list of lists, a non-contiguous view
S = rng.uniform(-0.2, 0.2, (5, 12))[:, ::2]
assert np.array_equal(m.psi(S), m.psi(np.ascontiguousarray(S))) and np.array_equal(m.psi(S.tolist()), m.psi(S))
for bad in [(5,), (3, 5), (2, 6, 2), ()]:
    try:
        m.evaluate(np.zeros(bad))
    except ValueError as e:
        assert "(..., 6)" in str(e), e
    else:
        raise SystemExit("shape %s: no ValueError" % (bad,))
r = repr(m)
for part in ("hylc.Material", "small.json", "density 0.3 kg/m^2", "C0 0.5 J/m^2", "2 1D + 1 2D terms", "100."):
    assert part in r, (part, r)
assert m.terms() == ["sx", "II00", "sx-II00"], m.terms()
mesh = hylc.Mesh([[0, 1, 2], [2, 1, 3]], uv=[[0, 0], [1, 0], [0, 1], [1, 1]])
r = repr(mesh)
assert r == "<hylc.Mesh: 4 vertices, 2 triangles, rest area 1 m^2, %d Hessian nonzeros>" % mesh.nnz, r
# docstrings on every public function, class, method and property
missing = []
for name in hylc.__all__:
    obj = getattr(hylc, name)
    if not (inspect.isclass(obj) or callable(obj)):
        continue
    if not (obj.__doc__ or "").strip():
        missing.append(name)
    if inspect.isclass(obj):
        for k, v in vars(obj).items():
            if k.startswith("_") or not (callable(v) or isinstance(v, property)):
                continue
            if not (v.__doc__ or "").strip():
                missing.append(name + "." + k)
assert not missing, "no docstring: " + ", ".join(missing)
print("hylc %s: %d shapes (..., 6) checked" % (hylc.__version__, checked))
PY
echo ok
