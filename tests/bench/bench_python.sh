#!/usr/bin/env bash
# Python batch evaluation through the hylc module (libhylcmat via ctypes), hessian=False, one core:
# Psi + grad per second on 10^6 random strains of the paper's stock1 table (a built-in table without
# $HYLC_REFDATA). Target (issue 16): >= 1e6 per second.
set -u
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
$py -c "import numpy" 2>/dev/null || { echo "skipped: /usr/bin/python3 with numpy not found"; exit 0; }
PYTHONPATH=$PWD/python taskset -c 0 $py - "${HYLC_REFDATA:-../shared/refdata}/materials/stock1.json" <<'PY'
import sys, time, os, tempfile
import numpy as np
import hylc
path = sys.argv[1]
if not os.path.exists(path):
    path = os.path.join(tempfile.mkdtemp(), "small.json")
    open(path, "w").write('{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 3, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}')
m = hylc.Material(path)
N = 1000000
S = np.random.default_rng(1).uniform(-1, 1, (N, 6)) * [0.2, 0.3, 0.2, 50, 30, 50]
best = {}
for hess in (False, True):
    rates = []
    for rep in range(3):
        t = time.perf_counter()
        m.evaluate(S, hessian=hess)
        rates.append(N / (time.perf_counter() - t))
    best[hess] = max(rates)
print("python hylc.Material.evaluate on %s, %d strains, one core:" % (os.path.basename(path), N))
print("  hessian=False: %.3g Psi+grad per second (target >= 1e6: %s)" % (best[False], "met" if best[False] >= 1e6 else "NOT met"))
print("  hessian=True:  %.3g Psi+grad+Hessian per second" % best[True])
PY
# the shell element's whole-mesh call from Python (hylc.Mesh.evaluate): the 100,352-triangle mesh of
# bench_shell, numpy in and out, the Hessian as scipy.sparse (triplets without scipy); rates from the
# process CPU time (as bench_shell: other work may share the core), the best of 3
[ -f "${HYLC_REFDATA:-../shared/refdata}/materials/stock1.json" ] || { echo "python hylc.Mesh: skipped (no stock1.json)"; exit 0; }
PYTHONPATH=$PWD/python taskset -c 0 $py - "${HYLC_REFDATA:-../shared/refdata}/materials/stock1.json" <<'PY'
import sys, time
import numpy as np
import hylc
m = hylc.Material(sys.argv[1])
n = 224
idx = lambda i, j: i * (n + 1) + j
I, J = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
p, q, r = idx(I, J).ravel(), idx(I + 1, J).ravel(), idx(I + 1, J + 1).ravel()
tri = np.concatenate([np.stack([p, q, r], 1), np.stack([p, r, p + 1], 1)])
U, V = np.meshgrid(np.arange(n + 1) / n, np.arange(n + 1) / n, indexing="ij")
uv = np.stack([U.ravel(), V.ravel()], 1)
t = time.perf_counter()
mesh = hylc.Mesh(tri, uv=uv)
setup = time.perf_counter() - t
x = np.c_[uv[:, 0] * (1.05 + 0.02 * np.sin(7 * uv[:, 1])), uv[:, 1], 0.01 * np.sin(2 * np.pi * uv[:, 0] / 0.2) * np.cos(2 * np.pi * uv[:, 1] / 0.3)]
try:
    import scipy.sparse
    kind = "scipy.sparse"
except ImportError:
    kind = "triplets"
print("python hylc.Mesh.evaluate, %d triangles, %d vertices, one core (mesh set-up %.2f s), Hessian as %s, CPU time:" % (mesh.nt, mesh.nv, setup, kind))
for name, kw in (("energy", dict(gradient=False, hessian=False)), ("energy + gradient", dict(hessian=False)), ("+ Hessian", {}), ("+ PSD projection", dict(project=True))):
    best = 0
    for rep in range(3):
        t = time.process_time()
        mesh.evaluate(m, x, **kw)
        best = max(best, mesh.nt / (time.process_time() - t))
    print("  %-18s %10.3g triangles/s" % (name, best))
PY
