#!/usr/bin/env bash
# The Python module's hylc.Mesh and hylc.Material under misuse: a Mesh passed where the Material goes
# (mesh.evaluate(mesh, x)) segfaulted, now a TypeError; a Mesh or Material used after an explicit free
# (__del__()) returned uninitialised memory (stencils, hessian_structure()), now a HylcError on every
# method and property (its repr says "freed"); Material.evaluate returned values at strains outside the
# domain (1 + sx > 0, 1 + sy > 0, |sa| < 1) and at NaN strains although its docstring says it raises, now a
# HylcError naming the strain; Mesh truncated float indices (0.9 -> vertex 0) and wrapped int64 ones
# (2**32 + 1 -> vertex 1), now a TypeError and a HylcError.
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy not found"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
export PYTHONPATH=$HYLC_ROOT/python
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >m.json
# each case in a child process: a segfault is a failure of that case, not of the script
$py - <<'PY' || die "python probes"
import subprocess, sys, textwrap
SETUP = """
import numpy as np, hylc
m = hylc.Material("m.json")
uv = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]]) * 0.1
tri = np.array([[0, 1, 2], [0, 2, 3]])
mesh = hylc.Mesh(tri, uv=uv)
x = np.c_[uv, np.zeros(4)]
"""
cases = [
    ("a Mesh where the Material goes", "mesh.evaluate(mesh, x)", "TypeError", "material must be a hylc.Material, got Mesh"),
    ("a path where the Material goes", "mesh.evaluate('m.json', x)", "TypeError", "got str"),
    ("stencils after free", "mesh.__del__(); mesh.stencils", "HylcError", "hylc.Mesh: used after it was freed"),
    ("hessian_structure after free", "mesh.__del__(); mesh.hessian_structure()", "HylcError", "used after it was freed"),
    ("hessian_triplets after free", "mesh.__del__(); mesh.hessian_triplets()", "HylcError", "used after it was freed"),
    ("area after free", "mesh.__del__(); mesh.area", "HylcError", "used after it was freed"),
    ("strains after free", "mesh.__del__(); mesh.strains(x)", "HylcError", "used after it was freed"),
    ("evaluate after free", "mesh.__del__(); mesh.evaluate(m, x)", "HylcError", "hylc.Mesh: used after it was freed"),
    ("a freed Material", "m.__del__(); mesh.evaluate(m, x)", "HylcError", "hylc.Material: used after it was freed"),
    ("Material.evaluate after free", "m.__del__(); m.evaluate(np.zeros(6))", "HylcError", "hylc.Material: used after it was freed"),
    ("density after free", "m.__del__(); m.density", "HylcError", "used after it was freed"),
    ("terms after free", "m.__del__(); m.terms()", "HylcError", "used after it was freed"),
    ("sx = -1", "m.evaluate([-1, 0, 0, 0, 0, 0])", "HylcError", r"strain \(-1, 0, 0, 0, 0, 0\): outside the domain 1 \+ sx > 0, 1 \+ sy > 0, \|sa\| < 1"),
    ("sy = -1.5 in a batch", "m.evaluate(np.array([[0.1, 0, 0, 0, 0, 0], [0, 0, -1.5, 0, 0, 0]]))", "HylcError", r"strain \(1,\) \(0, 0, -1.5, 0, 0, 0\): outside the domain"),
    ("sa = 1", "m.psi([0, 1, 0, 0, 0, 0])", "HylcError", "outside the domain"),
    ("sa = -2 in a grid", "m.psi(np.zeros((2, 3, 6)) + [0, -2, 0, 0, 0, 0])", "HylcError", r"strain \(0, 0\) .*outside the domain"),
    ("a NaN strain", "m.evaluate([0, 0, 0, float('nan'), 0, 0])", "HylcError", r"strain \(0, 0, 0, nan, 0, 0\): not finite"),
    ("float indices", "hylc.Mesh(tri + 0.9, uv=uv)", "TypeError", "triangles must be integer vertex indices, got float64"),
    ("float indices, rest", "hylc.Mesh(np.array([[0, 1, 2.0]]), rest=x)", "TypeError", "got float64"),
    ("int64 index 2**32 + 1", "hylc.Mesh(np.array([[0, 2**32 + 1, 2]], dtype=np.int64), rest=x)", "HylcError", "mesh: vertex index 4294967297 is out of range"),
    ("int64 index 2**32 + 1, uv per corner", "hylc.Mesh(np.array([[0, 2**32 + 1, 2]]), uv=np.zeros((1, 3, 2)))", "HylcError", "vertex index 4294967297 is out of range"),
    ("a negative index", "hylc.Mesh(np.array([[0, -1, 2]]), rest=x)", "HylcError", "vertex index -1 is out of range"),
    ("boolean indices", "hylc.Mesh(np.array([[True, False, True]]), rest=x)", "TypeError", "got bool"),
]
import re
bad = 0
for name, code, exc, msg in cases:
    prog = SETUP + textwrap.dedent("""
        try:
            %s
        except hylc.HylcError as e:
            print("HylcError:", e)
        except TypeError as e:
            print("TypeError:", e)
        else:
            print("no error")
        """) % code
    r = subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, timeout=60)
    out = (r.stdout + r.stderr).strip()
    if r.returncode != 0 or not out.startswith(exc + ":") or not re.search(msg, out):
        print("FAIL %s: %s -> exit %d: %s (expected %s matching /%s/)" % (name, code, r.returncode, out[-300:], exc, msg))
        bad += 1
# what still works: the repr of a freed object, a valid evaluation, integer indices of any integer type
prog = SETUP + """
assert "freed" not in repr(mesh)
print(repr(m.evaluate([0.1, 0.2, -0.1, 5, 0, 3])[0]))
for dt in (np.int16, np.int64, np.uint32):
    assert hylc.Mesh(tri.astype(dt), uv=uv).nt == 2
mesh.__del__(); m.__del__()
print(repr(mesh), repr(m))
"""
r = subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, timeout=60)
if r.returncode != 0 or r.stdout.split("\n")[1:2] != ["<hylc.Mesh: freed> <hylc.Material 'm.json': freed>"]:
    print("FAIL the valid uses:", r.returncode, r.stdout, r.stderr[-500:])
    bad += 1
print("%d cases, %d wrong" % (len(cases) + 1, bad))
sys.exit(1 if bad else 0)
PY
