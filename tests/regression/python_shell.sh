#!/usr/bin/env bash
# The shell element from Python (hylc.Mesh, ctypes over libhylcmat.so) with Debian's /usr/bin/python3:
# shapes, the Hessian as scipy.sparse and as triplets (the same values), the gradient and Hessian of a
# small mesh against central differences, rigid-motion invariance, errors as HylcError with the
# triangle named; then examples/hanging_cloth.py (a hanging cloth minimized with scipy) must reduce the
# gradient norm by 1e-8 on the paper's stock1 table ($HYLC_REFDATA/materials).
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy, scipy.sparse, scipy.optimize" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy and scipy not found (apt-get install python3-scipy)"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
table=$HYLC_REFDATA/materials/stock1.json
[ -f "$table" ] || { echo "SKIP: $table not found (the paper's tables, \$HYLC_REFDATA)"; exit 77; }
export PYTHONPATH=$HYLC_ROOT/python
$py - "$table" <<'PY' || die "python checks"
import sys, numpy as np, scipy.sparse, hylc
m = hylc.Material(sys.argv[1])
n = 4
u = np.linspace(0, 0.04, n + 1)
U, V = np.meshgrid(u, u, indexing="ij")
uv = np.stack([U.ravel(), V.ravel()], 1)
tri = np.array([t for i in range(n) for j in range(n) for t in (((i*(n+1)+j), (i+1)*(n+1)+j, (i+1)*(n+1)+j+1), (i*(n+1)+j, (i+1)*(n+1)+j+1, i*(n+1)+j+1))])
mesh = hylc.Mesh(tri, uv=uv)
X = np.c_[uv, np.zeros(len(uv))]
assert (mesh.nv, mesh.nt) == (25, 32) and abs(mesh.area - 0.0016) < 1e-15, (mesh.nv, mesh.nt, mesh.area)
assert abs(mesh.area - hylc.Mesh(tri, rest=X, angle=0.3).area) < 1e-15
st = mesh.stencils
assert st.shape == (32, 6) and (st[:, :3] == tri).all() and (st[:, 3:] == -1).sum() == 16, st
rng = np.random.default_rng(7)
x = X * [1.05, 0.97, 1] + 0.001 * rng.uniform(-1, 1, X.shape)
E, g, H = mesh.evaluate(m, x)
assert isinstance(H, scipy.sparse.csr_matrix) and H.shape == (75, 75) and g.shape == (25, 3) and H.nnz == mesh.nnz
E2, g2, (r, c, v) = mesh.evaluate(m, x, sparse=False)
assert E2 == E and np.array_equal(g2, g) and np.array_equal(scipy.sparse.coo_matrix((v, (r, c)), shape=H.shape).toarray(), H.toarray())
assert mesh.evaluate(m, x, hessian=False)[0] == E and mesh.evaluate(m, x, gradient=False, hessian=False) == E
assert abs(H - H.T).max() == 0
h, gfd, Hfd = 1e-7, np.zeros(75), np.zeros((75, 75))
for i in range(75):
    xp, xm = x.copy().ravel(), x.copy().ravel()
    xp[i] += h; xm[i] -= h
    Ep, gp = mesh.evaluate(m, xp.reshape(-1, 3), hessian=False)
    Em, gm = mesh.evaluate(m, xm.reshape(-1, 3), hessian=False)
    gfd[i], Hfd[:, i] = (Ep - Em) / (2 * h), (gp - gm).ravel() / (2 * h)
eg, eH = np.abs(gfd - g.ravel()).max() / np.abs(g).max(), np.abs(Hfd - H.toarray()).max() / abs(H).max()
assert eg < 1e-6 and eH < 1e-5, (eg, eH)
Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
Q *= np.sign(np.linalg.det(Q))
Er, gr = mesh.evaluate(m, x @ Q.T + [1, -2, 3], hessian=False)
assert abs(Er - E) <= 1e-12 * abs(E) and np.abs(gr - g @ Q.T).max() <= 1e-10 * np.abs(g).max(), (Er - E, np.abs(gr - g @ Q.T).max())
_, _, Hp = mesh.evaluate(m, x, project=True)
assert np.linalg.eigvalsh(Hp.toarray()).min() > 0
z = mesh.strains(x)
assert z.shape == (32, 6) and np.abs(mesh.strains(X)).max() < 1e-15
for bad, what in (([[0, 1, 2], [0, 2, 3], [0, 2, 4]], "non-manifold"), ([[0, 1, 2], [0, 3, 2]], "orientations")):
    try:
        hylc.Mesh(np.array(bad), rest=np.eye(5, 3))
        raise SystemExit("no error for " + what)
    except hylc.HylcError as e:
        assert e.code == 10 and what in str(e), str(e)
try:
    hylc.Mesh([[0, 1, 2]], uv=[[0, 0], [0, 1], [1, 0]])
    raise SystemExit("no error for a clockwise triangle")
except hylc.HylcError as e:
    assert e.code == 11 and "inverted" in str(e), str(e)
xn = x.copy(); xn[7, 1] = np.nan
try:
    mesh.evaluate(m, xn)
    raise SystemExit("no error for NaN")
except hylc.HylcError as e:
    assert e.code == 12 and "triangle" in str(e), str(e)
print("hylc.Mesh: gradient %.1e, Hessian %.1e against differences; rigid motion %.1e" % (eg, eH, abs(Er - E) / abs(E)))
PY
out=$($py "$HYLC_ROOT/examples/hanging_cloth.py" "$table" 2>&1) || { echo "$out"; die "examples/hanging_cloth.py did not converge"; }
echo "$out"
echo "$out" | grep -q "reduced by" || die "unexpected output of hanging_cloth.py"
