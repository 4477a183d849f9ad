#!/usr/bin/env bash
# Measured cloth (docs/measured-cloth.md) against an independent reference: a small pure-Python
# implementation of the formulas (math and json only, written from the documented conventions, not from
# src/hylcmat/measured.c) checks the reader and the evaluator of libhylcmat (through python/hylc) on two of
# the ten fabrics of Wang et al. 2011 (11oz-black-denim, gray-interlock): the stiffness sample khat and the
# looked-up k, the energy and the frozen-stiffness force of a face at 5 strain states (stretch along u and
# v, shear of both signs, compression, a stretch beyond 1/6, a rotated 3D state), and the bending of a hinge
# at 2 curvatures and 2 edge directions (theta, kappa, the stiffness, the energy, the force), each to 1e-12
# relative (forces to 1e-7 against the reference's central differences at fixed k). Skips (77) without
# the reference data or numpy.
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
dir=$HYLC_REFDATA/materials/wang2011
[ -f "$dir/11oz-black-denim.json" ] && [ -f "$dir/gray-interlock.json" ] || { echo "SKIP: the measured fabrics of Wang et al. 2011 are not in $dir"; exit 77; }
[ -x $py ] && $py -c "import numpy" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy not found"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
export PYTHONPATH=$HYLC_ROOT/python
MC_DIR=$dir $py - <<'PY' || die "the reference checks"
import json, math, os

# ---------------- the reference: the formulas of docs/measured-cloth.md, plain Python ----------------
def sample(st, G):
    """khat(G): C = 2G + I, its larger eigenvalue and eigenvector, the strain and direction coordinates"""
    a, b, d = 2 * G[0] + 1, 2 * G[2], 2 * G[1] + 1
    l1 = ((a + d) + math.sqrt(4 * b * b + (a - d) ** 2)) / 2
    if b != 0:
        V = (l1 - d, b)
    else:
        V = (1.0, 0.0) if a >= d else (0.0, 1.0)
    w = math.sqrt(l1)
    sig = min(max(6 * (w - 1), 0.0), 1 - 1e-6)
    alpha = min(max(8 * abs(math.atan2(V[1], V[0])) / math.pi, 0.0), 4 - 1e-6)
    j = int(math.floor(alpha))
    wa = alpha - j
    # the data table: level 0 is r0 in every direction, level 1 is r(j+1)
    dat = [[st[0]] * 5, [st[1], st[2], st[3], st[4], st[5]]]
    out = []
    for c in range(4):
        v = ((1 - sig) * ((1 - wa) * dat[0][j][c] + wa * dat[0][j + 1][c]) + sig * ((1 - wa) * dat[1][j][c] + wa * dat[1][j + 1][c]))
        out.append(2 * max(v, 0.0))
    return out

def stiffness(st, G):
    """the trilinear lookup on the 30^3 grid G00 = -0.25 + i/30, G11 = -0.25 + j/30, G01 = k/30"""
    coords = [(G[0] + 0.25) * 30, (G[1] + 0.25) * 30, abs(G[2]) * 30]
    idx, wts = [], []
    for x in coords:
        x = min(max(x, 0.0), 29 - 1e-5)
        i = min(max(int(math.floor(x)), 0), 28)
        idx.append(i)
        wts.append(x - i)
    k = [0.0] * 4
    for di in (0, 1):
        for dj in (0, 1):
            for dk in (0, 1):
                w = (wts[0] if di else 1 - wts[0]) * (wts[1] if dj else 1 - wts[1]) * (wts[2] if dk else 1 - wts[2])
                g = (-0.25 + (idx[0] + di) / 30, -0.25 + (idx[1] + dj) / 30, (idx[2] + dk) / 30)
                kh = sample(st, g)
                for c in range(4):
                    k[c] += w * kh[c]
    return k

def sub(a, b): return [a[i] - b[i] for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]

def face(st, uv, x, k=None):
    """E = A psi(G) with psi = (k0 G00^2 + 2 k1 G00 G11 + k2 G11^2 + k3 G01^2) / 2; k = k(G) unless given"""
    e1 = (uv[1][0] - uv[0][0], uv[1][1] - uv[0][1]); e2 = (uv[2][0] - uv[0][0], uv[2][1] - uv[0][1])
    det = e1[0] * e2[1] - e1[1] * e2[0]
    A = det / 2
    inv = ((e2[1] / det, -e2[0] / det), (-e1[1] / det, e1[0] / det))   # Dm^-1, rows
    d1, d2 = sub(x[1], x[0]), sub(x[2], x[0])
    Fu = [d1[c] * inv[0][0] + d2[c] * inv[1][0] for c in range(3)]
    Fv = [d1[c] * inv[0][1] + d2[c] * inv[1][1] for c in range(3)]
    G = ((dot(Fu, Fu) - 1) / 2, (dot(Fv, Fv) - 1) / 2, dot(Fu, Fv) / 2)
    if k is None:
        k = stiffness(st, G)
    psi = (k[0] * G[0] ** 2 + 2 * k[1] * G[0] * G[1] + k[2] * G[1] ** 2 + k[3] * G[2] ** 2) / 2
    return A * psi, G, k

def bend_sample(be, kappa, du):
    value = min(0.1 * kappa, 4.0)
    vi = min(max(int(value), 0), 3)       # int() truncates toward 0
    wv = value - vi
    beta = abs(4 * math.atan2(du[1], du[0]) / math.pi)
    if beta > 4: beta = 8 - beta
    if beta > 2: beta = 4 - beta
    bi = min(max(int(math.floor(beta)), 0), 1)
    wb = beta - bi
    k = ((1 - wb) * ((1 - wv) * be[bi][vi] + wv * be[bi][vi + 1]) + wb * ((1 - wv) * be[bi + 1][vi] + wv * be[bi + 1][vi + 1]))
    return max(k, 0.0)

def hinge(be, uv, x, k=None):
    """faces (a, b, p0), (b, a, p1); theta = atan2(e.(n0 x n1), n0.n1) with e = (a - b)/|a - b|"""
    a, b, p0, p1 = x
    N0 = cross(sub(b, a), sub(p0, a)); N1 = cross(sub(a, b), sub(p1, b))
    n0 = [c / math.sqrt(dot(N0, N0)) for c in N0]; n1 = [c / math.sqrt(dot(N1, N1)) for c in N1]
    e = sub(a, b); e = [c / math.sqrt(dot(e, e)) for c in e]
    theta = math.atan2(dot(e, cross(n0, n1)), dot(n0, n1))
    du = (uv[1][0] - uv[0][0], uv[1][1] - uv[0][1])
    l = math.hypot(*du)
    A0 = abs(du[0] * (uv[2][1] - uv[0][1]) - du[1] * (uv[2][0] - uv[0][0])) / 2
    A1 = abs(du[0] * (uv[3][1] - uv[0][1]) - du[1] * (uv[3][0] - uv[0][0])) / 2
    kappa = theta * l / (A0 + A1)
    if k is None:
        k = bend_sample(be, kappa, du)
    E = k * l * l / (2 * (A0 + A1)) * theta ** 2 / 4
    return E, theta, kappa, k

def fd_force(fun, x, h=1e-7):
    """-dE/dx by central differences (x a list of points)"""
    f = []
    for i in range(len(x)):
        for c in range(3):
            xp = [list(p) for p in x]; xm = [list(p) for p in x]
            xp[i][c] += h; xm[i][c] -= h
            f.append(-(fun(xp) - fun(xm)) / (2 * h))
    return f

# ---------------- the checks against libhylcmat ----------------
import numpy as np
import hylc

worst = {"khat": 0, "k": 0, "E": 0, "force": 0, "bend": 0, "bforce": 0}
def rel(a, b, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = scale if scale is not None else max(np.abs(b).max(), 1e-300)
    return float(np.abs(a - b).max() / s)

def rot(axis, ang):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(ang) * K + (1 - math.cos(ang)) * K @ K

uv = [(0.0, 0.0), (0.012, 0.001), (0.002, 0.010)]
R3 = rot((0.3, -0.5, 0.8), 0.7)
states = {   # the deformation gradient (3 x 2) of each state
    "stretch u 5 %": np.array([[1.05, 0], [0, 0.99], [0, 0]]),
    "shear +": np.array([[1.08, 0.03], [0.02, 1.04], [0, 0]]),
    "compression, shear -": np.array([[0.90, -0.02], [0.01, 0.95], [0, 0]]),
    "stretch v 25 %": np.array([[0.98, 0], [0, 1.25], [0, 0]]),
    "rotated 3D": R3 @ np.array([[1.12 * math.cos(0.5), -0.97 * math.sin(0.5)], [1.12 * math.sin(0.5), 0.97 * math.cos(0.5)], [0, 0]]) @ np.array([[math.cos(0.5), math.sin(0.5)], [-math.sin(0.5), math.cos(0.5)]]),
}
for name in ("11oz-black-denim", "gray-interlock"):
    path = os.path.join(os.environ["MC_DIR"], name + ".json")
    data = json.load(open(path))
    st, be = data["stretching"], data["bending"]
    mc = hylc.MeasuredMaterial(path)
    assert mc.density == data["density"], (mc.density, data["density"])
    assert np.array_equal(mc.stretching, np.array(st)) and np.array_equal(mc.bending, np.array(be)), "the data read differ from the file"
    for sname, F in states.items():
        x = [tuple(F @ np.array(p)) for p in uv]
        E_ref, G, k_ref = face(st, uv, x)
        kh_ref = sample(st, G)
        E, force, grad = mc.face(np.array(uv), np.array(x))
        worst["khat"] = max(worst["khat"], rel(mc.sample(G), kh_ref))
        worst["k"] = max(worst["k"], rel(mc.stiffness(G), k_ref))
        worst["E"] = max(worst["E"], rel(E, E_ref))
        f_ref = fd_force(lambda xx: face(st, uv, xx, k_ref)[0], x)
        worst["force"] = max(worst["force"], rel(force.ravel(), f_ref))
        print("%s %-22s G (%.5f, %.5f, %.5f) khat %s k %s E %.10e J" % (name, sname, G[0], G[1], G[2], ["%.6g" % v for v in kh_ref], ["%.6g" % v for v in k_ref], E_ref))
    # hinges: edges along u and at 30 degrees, curvatures about 7 and 33 1/m (wings lifted toward n)
    for ang in (0.0, math.pi / 6):
        t = np.array([math.cos(ang), math.sin(ang)]); nrm = np.array([-t[1], t[0]])
        h = 0.01
        U = [np.zeros(2), h * t, 0.5 * h * t + h * nrm, 0.4 * h * t - 0.9 * h * nrm]
        for lift in (0.00035, 0.0017):
            X = [np.array([p[0], p[1], 0.0]) for p in U]
            X[2][2] += lift; X[3][2] += 0.8 * lift
            X = [tuple(R3 @ p + np.array([0.1, -0.2, 0.3])) for p in X]
            uvl = [tuple(p) for p in U]
            E_ref, theta, kappa, k_ref = hinge(be, uvl, X)
            E, force, info = mc.edge(np.array(uvl), np.array(X))
            worst["bend"] = max(worst["bend"], rel([E, info["theta"], info["kappa"], info["k"]], [E_ref, theta, kappa, k_ref], None) if False else max(rel(E, E_ref), rel(info["theta"], theta), rel(info["kappa"], kappa), rel(info["k"], k_ref)))
            f_ref = fd_force(lambda xx: hinge(be, uvl, xx, k_ref)[0], X)
            worst["bforce"] = max(worst["bforce"], rel(force.ravel(), f_ref))
            assert theta > 0, "wings lifted toward n must give theta > 0"
            print("%s hinge at %2.0f deg: theta %.6f kappa %.4f 1/m k %.6e N m E %.6e J" % (name, math.degrees(ang), theta, kappa, k_ref, E_ref))
print("worst relative differences:", {k: "%.2e" % v for k, v in worst.items()})
for key, tol in (("khat", 1e-12), ("k", 1e-12), ("E", 1e-12), ("force", 1e-7), ("bend", 1e-12), ("bforce", 1e-7)):
    assert worst[key] <= tol, "%s differs from the reference by %.3e (tolerance %g)" % (key, worst[key], tol)
PY
echo "measured cloth agrees with the reference"
