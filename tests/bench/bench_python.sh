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
