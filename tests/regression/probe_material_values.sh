#!/usr/bin/env bash
# Material tables under bad values. An HDF5 table's errors did not name the file (a NaN value was
# "1D term sx (k = 0): p[0] = nan is not finite"; a string where a number goes was a PETSc traceback of
# H5Dread); now every one names the file, in C (hylc-eval) and in Python (hylc.Material through h5py).
# A loadable table with a value of 1e308 made the projected element Hessian HYLCMAT_ERR_NAN ("a defect:
# please report it"): the projection squared entries beyond 1e154; now such a Hessian is projected
# divided by a power of 2 (an sa term of 1e100 at a scale of 1e-30: 2e160), and one whose projection is
# itself beyond the double range (values of 1e308) is HYLCMAT_ERR_RANGE. A density of 1e300 ended
# hylc-cloth in a failed solve ("Absolute tolerance -nan" in the issue); densities beyond 1e6 kg/m^2 are
# refused at load, naming the file (and the JSON line).
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
die() { echo "FAIL: $*"; exit 1; }
B=$HYLC_BIN
py=/usr/bin/python3
table() { # density p0 [strain scale of sa]
  printf '{"density": %s, "strain scale": [1, %s, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 1, "t": [-1, 0, 1], "p": [%s, 0, %s], "m": [-%s, 0, %s]}], "2D": []}}\n' "$1" "${3:-1}" "$2" "$2" "$2" "$2"
}
table 0.3 1 >m.json
table 0.3 1e308 >big.json
table 1e300 1 >dens.json
table 0.3 1e100 1e-30 >steep.json
expect_fail '^hylc: error: dens.json:1: density: the area density must be in \[0, 1e\+06\] kg/m\^2, got 1e\+300$' $B/hylc-eval -material dens.json -strain 0,0,0,0,0,0
expect_fail '^hylc: error: dens.json:1: density' $B/hylc-cloth -cloth_material dens.json -cloth_test tensile -cloth_output never
$B/hylc-eval -material m.json -eval_hdf5 m.h5 >e.txt 2>&1 || { cat e.txt; die "hylc-eval -eval_hdf5"; }
$B/hylc-eval -material steep.json -strain 0,0,0,0,0,0 >e.txt 2>&1 || { cat e.txt; die "steep.json (values 1e100) must load"; }

have_h5py=0
$py -c 'import h5py, numpy' 2>/dev/null && have_h5py=1
if [ $have_h5py = 1 ]; then
  $py - <<'PY' || die "making the HDF5 variants"
import h5py, shutil, numpy as np
def variant(name, fn):
    shutil.copy("m.h5", name)
    with h5py.File(name, "r+") as f:
        fn(f)
def setd(f, name, v):
    del f[name]
    f.create_dataset(name, data=v)
variant("nan.h5", lambda f: f["1D/sa/p"].__setitem__(0, np.nan))
variant("dens.h5", lambda f: setd(f, "density", 1e300))
variant("strdens.h5", lambda f: setd(f, "density", b"heavy"))
variant("strp.h5", lambda f: setd(f["1D/sa"], "p", np.array([b"a", b"b", b"c"])))
variant("strk.h5", lambda f: f["1D/sa"].attrs.__setitem__("k", "one"))
variant("cmp.h5", lambda f: setd(f, "constant", np.array([(1, 2.0)], dtype=[("a", "i4"), ("b", "f8")])[0]))
PY
  for c in "nan.h5|nan.h5: 1D term sa \(k = 1\): p\[0\] = nan is not finite" \
    "dens.h5|dens.h5: Material density must be finite and in \[0, 1e\+06\] kg/m\^2, got 1e\+300" "strdens.h5|strdens.h5: dataset /density holds strings, expected numbers" \
    "strp.h5|strp.h5: dataset /1D/sa/p holds strings, expected numbers" "strk.h5|strk.h5: attribute /1D/sa/@k holds strings, expected an integer" \
    "cmp.h5|cmp.h5: dataset /constant holds compound records, expected numbers"; do
    expect_fail "^hylc: error: ${c#*|}" $B/hylc-eval -material "${c%%|*}" -strain 0,0,0,0,0,0
  done
  # Python (libhylcmat without HDF5: the h5py reader, libhylcmat's setters): the same files named
  [ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
  PYTHONPATH=$HYLC_ROOT/python $py - <<'PY' || die "python"
import hylc
for f, want in (("nan.h5", "nan.h5: 1D term sa (k = 1): p[0] = nan is not finite"), ("dens.h5", "dens.h5: Material density must be finite and in [0, 1e+06] kg/m^2, got 1e+300"),
                ("dens.json", "dens.json:1: density: the area density must be in [0, 1e+06] kg/m^2, got 1e+300")):
    try:
        hylc.Material(f)
    except hylc.HylcError as e:
        assert str(e).startswith(want), (f, str(e))
    else:
        raise SystemExit("%s: loaded" % f)
PY
fi

# an element Hessian of 2e160 (values 1e100 at an sa scale of 1e-30), projected: it was HYLCMAT_ERR_NAN
if $py -c 'import numpy' 2>/dev/null; then
  PYTHONPATH=$HYLC_ROOT/python $py - <<'PY' || die "the projection of a Hessian beyond 1e154"
import numpy as np, hylc
m = hylc.Material("steep.json")
uv = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]]) * 0.1
mesh = hylc.Mesh(np.array([[0, 1, 2], [0, 2, 3]]), uv=uv)
x = np.c_[uv, np.zeros(4)]
E, g, (r, c, h0) = mesh.evaluate(m, x, sparse=False)
E, g, (r, c, h1) = mesh.evaluate(m, x, project=True, sparse=False)
assert 1e155 < np.abs(h0).max() < 1e170 and np.all(np.isfinite(h1)), np.abs(h0).max()
assert np.abs(h1 - h0).max() <= 1e-12 * np.abs(h0).max(), np.abs(h1 - h0).max()
# values of 1e308 (sa = 0.5): the projection is beyond the double range, a HylcError of that name
m = hylc.Material("big.json")
xs = x.copy(); xs[:, 0] += 0.5 * 0.7 * x[:, 1]
E, g, (r, c, h0) = mesh.evaluate(m, xs, sparse=False)
try:
    mesh.evaluate(m, xs, project=True)
except hylc.HylcError as e:
    assert e.code == 14 and "a result beyond the double range" in str(e), (e.code, str(e))
else:
    raise SystemExit("big.json at sa = 0.35: no error")
PY
fi
finish
