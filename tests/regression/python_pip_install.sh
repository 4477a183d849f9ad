#!/usr/bin/env bash
# Issue 33, item 7: `pip install ./python` offline with Debian's pip, into a fresh virtual environment
# with the system's site packages (numpy, h5py from Debian), exactly as docs/library.md gives it:
#   python3 -m venv --system-site-packages V; V/bin/pip install --no-build-isolation --no-index ./python
# The package then works outside the checkout with no PYTHONPATH or HYLCMAT_LIB: `import hylc` loads
# the libhylcmat.so inside the installed package, hylc.__version__ is hylc's version, and evaluate gives
# bit for bit the values of the checkout's module (build/libhylcmat.so) on (..., 6) strains. The build
# leaves the source tree as it was (setup.py builds in a temporary directory).
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy, venv, ensurepip" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy, venv and ensurepip (python3-venv) not found"; exit 77; }
$py -c "import setuptools, wheel" 2>/dev/null || { echo "SKIP: Debian's python3-setuptools and python3-wheel are not installed"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
want=$(sed -n 's/^#define HYLC_VERSION_STRING "\(.*\)"/\1/p' "$HYLC_ROOT/include/hylc/sys.h")
before=$(git -C "$HYLC_ROOT" status --porcelain --ignored python 2>/dev/null)
unset PYTHONPATH HYLCMAT_LIB
# no index, no user configuration: nothing may come from the network
export PIP_CONFIG_FILE=/dev/null PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
$py -m venv --system-site-packages venv || die "python3 -m venv failed"
venv/bin/pip install --no-build-isolation --no-index "$HYLC_ROOT/python" >pip.log 2>&1 || { tail -n 30 pip.log; die "pip install ./python failed"; }
after=$(git -C "$HYLC_ROOT" status --porcelain --ignored python 2>/dev/null)
[ "$before" = "$after" ] || { echo "$after"; die "pip install left files in python/"; }
cat >small.json <<'JSON'
{"density": 0.3, "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
 "coeffs": {"const": 0.5,
  "1D": [{"k": 3, "t": [-1.0, 0.0, 1.0], "p": [1, 0, 1], "m": [-1, 0, 1]}],
  "2D": [{"k0": 0, "k1": 3, "tu": [-1, 0, 1], "tv": [-1, 1], "p": [0, 1, 0, 0, 0, 1], "mu": [0, 0, 0, 0, 0, 0], "mv": [0, 0, 0, 0, 0, 0], "muv": [0, 0, 0, 0, 0, 0]}]}}
JSON
mkdir -p elsewhere && cd elsewhere
"$HYLC_TMP/venv/bin/python" - "$want" "$HYLC_TMP/venv" <<'PY' >../installed.txt || die "the installed package"
import os, sys
import numpy as np
import hylc
want, venv = sys.argv[1], os.path.realpath(sys.argv[2])
assert hylc.__version__ == want, (hylc.__version__, want)
assert os.path.realpath(hylc.__file__).startswith(venv), hylc.__file__
assert os.path.realpath(hylc.library_path).startswith(venv), "libhylcmat loaded from %s, not the package" % hylc.library_path
S = np.random.default_rng(7).uniform(-0.2, 0.2, (3, 4, 6)) * [1, 1, 1, 100, 100, 100]
psi, grad, hess = hylc.Material("../small.json").evaluate(S)
assert psi.shape == (3, 4) and grad.shape == (3, 4, 6) and hess.shape == (3, 4, 6, 6)
np.save("../installed.npy", np.concatenate([psi[..., None], grad, hess.reshape(3, 4, 36)], axis=-1))
print(hylc.__version__, hylc.library_path)
PY
cd "$HYLC_TMP"
PYTHONPATH=$HYLC_ROOT/python $py - <<'PY' || die "the checkout's module differs from the installed one"
import numpy as np, hylc
S = np.random.default_rng(7).uniform(-0.2, 0.2, (3, 4, 6)) * [1, 1, 1, 100, 100, 100]
psi, grad, hess = hylc.Material("small.json").evaluate(S)
ours = np.concatenate([psi[..., None], grad, hess.reshape(3, 4, 36)], axis=-1)
inst = np.load("installed.npy")
assert np.array_equal(ours, inst), np.abs(ours - inst).max()
assert np.abs(ours).max() > 0
PY
echo "pip-installed hylc $(cat installed.txt), equal to the checkout's module"

# the same from an installed prefix: make install, then pip install PREFIX/share/hylc/python (setup.py
# copies PREFIX/lib/libhylcmat.so into the package)
build=${BUILD:-build}
asanflag=(); [ "${HYLC_ASAN:-0}" = 1 ] && asanflag=(ASAN=1)
[ "${COVERAGE:-0}" = 1 ] && asanflag=(COVERAGE=1)
make -C "$HYLC_ROOT" --no-print-directory BUILD="$build" "${asanflag[@]}" install PREFIX="$HYLC_TMP/prefix" >install.log 2>&1 || { tail install.log; die "make install"; }
$py -m venv --system-site-packages venv2 || die "python3 -m venv failed"
venv2/bin/pip install -v --no-build-isolation --no-index "$HYLC_TMP/prefix/share/hylc/python" >pip2.log 2>&1 || { tail -n 30 pip2.log; die "pip install PREFIX/share/hylc/python failed"; }
grep -q "hylc: libhylcmat.so copied from .*/prefix/lib/libhylcmat.so" pip2.log || { grep 'hylc:' pip2.log; die "the prefix's package did not take PREFIX/lib/libhylcmat.so"; }
cd elsewhere
"$HYLC_TMP/venv2/bin/python" -c 'import sys, hylc, numpy as np; assert hylc.library_path.startswith(sys.prefix), hylc.library_path; assert hylc.__version__ == sys.argv[1]; assert hylc.Material("../small.json").psi(np.zeros((2, 2, 6))).shape == (2, 2)' "$want" || die "the package installed from the prefix"
echo "and from the installed prefix"
