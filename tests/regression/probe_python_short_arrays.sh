#!/usr/bin/env bash
# Issue 28, item 7: the Python loader (python/hylc, h5py path) passed n = len(t) to libhylcmat without
# checking the lengths of p, m, mu, ...: an HDF5 table with /1D/II00/p and m cut to 2 elements was read
# out of bounds (hylcmat_set_term1d). Now every array of a table is shortened in turn (each 1D and 2D
# array, strain_scale, strain_shift) and each file is refused with a HylcError naming the dataset, and a
# table with /1D/II00/p and m cut to 2 elements too; the untouched file still loads and evaluates as
# hylc-eval does. Missing datasets and attributes are HylcErrors too, never a KeyError.
set -u
cd "$HYLC_TMP"
py=/usr/bin/python3
die() { echo "FAIL: $*"; exit 1; }
[ -x $py ] && $py -c "import numpy, h5py" 2>/dev/null || { echo "SKIP: /usr/bin/python3 with numpy and h5py not found"; exit 77; }
[ -f "$HYLC_ROOT/${BUILD:-build}/libhylcmat.so" ] || die "no ${BUILD:-build}/libhylcmat.so (make)"
export PYTHONPATH=$HYLC_ROOT/python
cat >small.json <<'JSON'
{"density": 0.3, "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
 "coeffs": {"const": 0.5,
  "1D": [{"k": 3, "t": [-1.0, 0.0, 1.0], "p": [1, 0, 1], "m": [-1, 0, 1]}],
  "2D": [{"k0": 0, "k1": 3, "tu": [0, 0.5, 1], "tv": [0, 1], "p": [0, 0, 0, 0, 0, 1], "mu": [0, 0, 0, 0, 0, 0], "mv": [0, 0, 0, 0, 0, 0], "muv": [0, 0, 0, 0, 0, 0]}]}}
JSON
tables=(small.json)
[ -f "$HYLC_REFDATA/materials/stock1.json" ] && tables+=("$HYLC_REFDATA/materials/stock1.json")
for t in "${tables[@]}"; do
  "$HYLC_BIN/hylc-eval" -material "$t" -eval_hdf5 "$(basename "$t" .json).h5" >/dev/null || die "hylc-eval -eval_hdf5 $t"
  "$HYLC_BIN/hylc-eval" -material "$t" -strain 0.1,0.05,-0.05,20,0,-10 | sed -n 's/^psi: //p' >"$(basename "$t" .json).psi"
done
$py - "${tables[@]}" <<'PY' || die "python checks"
import os, shutil, sys
import h5py, numpy as np
import hylc
stats = {"files": 0, "refused": 0}
def arrays(path):
    out = []
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.append(n) if isinstance(o, h5py.Dataset) and o.size >= 2 else None)
    return out
def rewrite(src, dst, edits):
    shutil.copy(src, dst)
    with h5py.File(dst, "r+") as f:
        for name, fn in edits.items():
            data = f[name][()]
            del f[name]
            f.create_dataset(name, data=fn(data))
def refused(path, want):
    stats["files"] += 1
    try:
        m = hylc.Material(path)
    except hylc.HylcError as e:
        if want not in str(e):
            raise SystemExit("%s: HylcError '%s' does not name %s" % (path, e, want))
        stats["refused"] += 1
        return
    raise SystemExit("%s: loaded (expected a HylcError naming %s)" % (path, want))
for t in sys.argv[1:]:
    base = os.path.splitext(os.path.basename(t))[0]
    h5 = base + ".h5"
    names = arrays(h5)
    assert any(n.startswith("1D/") for n in names) and any(n.startswith("2D/") for n in names), names
    for n in names:  # every array of the table, one element short
        out = "%s-short-%s.h5" % (base, n.replace("/", "_"))
        rewrite(h5, out, {n: lambda a: a.ravel()[:-1]})
        refused(out, "/" + n)
    # the issue's case: /1D/II00/p and m cut to 2 elements (stock1's II00 term; small's only 1D term)
    term = "1D/II00" if "1D/II00/t" in names else [n for n in names if n.startswith("1D/")][0].rsplit("/", 1)[0]
    rewrite(h5, base + "-cut2.h5", {term + "/p": lambda a: a[:2], term + "/m": lambda a: a[:2]})
    refused(base + "-cut2.h5", "/" + term + "/p")
    # a missing dataset, a missing attribute, a string dataset
    shutil.copy(h5, base + "-nom.h5")
    with h5py.File(base + "-nom.h5", "r+") as f:
        del f[term + "/m"]
    refused(base + "-nom.h5", "no dataset /" + term + "/m")
    shutil.copy(h5, base + "-noext.h5")
    with h5py.File(base + "-noext.h5", "r+") as f:
        del f[term].attrs["ext"]
    refused(base + "-noext.h5", "/" + term + "@ext")
    rewrite(h5, base + "-str.h5", {"strain_scale": lambda a: np.array([b"x"] * 5)})
    refused(base + "-str.h5", "/strain_scale holds")
    # the untouched file loads and gives hylc-eval's psi
    psi = hylc.Material(h5).psi(np.array([0.1, 0.05, -0.05, 20, 0, -10]))
    ref = float(open(base + ".psi").read())
    assert abs(psi - ref) <= 1e-14 * max(1, abs(ref)), (h5, psi, ref)
print("python loader: %d malformed tables, %d refused with a HylcError naming the dataset" % (stats["files"], stats["refused"]))
PY
exit 0
