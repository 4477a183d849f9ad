#!/usr/bin/env bash
# The HDF5 samples file as a user sees it: h5dump -H shows the documented schema, and h5py (Debian
# python3-h5py with /usr/bin/python3) reads every dataset with the documented shapes, types, units and
# not-done conventions. The file is written by tests/unit/test_samples -test_write_h5 (57 samples, every
# fifth from sample 2 not done; the plain pattern; kc = 50). Skips (77) without h5py.
set -u
cd "$HYLC_TMP"
exe=$HYLC_BIN/../tests/test_samples
die() { echo "FAIL: $*"; exit 1; }
[ -x "$exe" ] || die "missing $exe (run make)"
"$exe" -test_write_h5 s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }
[ -e s.h5.tmp ] && die "temporary file left behind"

if command -v h5dump >/dev/null 2>&1; then
  h5dump -H s.h5 >schema.txt 2>&1 || { cat schema.txt; die "h5dump -H failed"; }
  for want in 'GROUP "samples"' 'GROUP "reference"' 'GROUP "material"' 'DATASET "options"' \
              'DATASET "strain"' 'DATASET "psi"' 'DATASET "term"' 'DATASET "status"' 'DATASET "iterations"' \
              'DATASET "retries"' 'DATASET "energy_parts"' 'DATASET "residual"' 'DATASET "constraint_residual"' \
              'DATASET "time"' 'DATASET "X"' 'DATASET "rest_kappa"' 'DATASET "ref_d1"' 'ATTRIBUTE "hylc_version"' \
              'ATTRIBUTE "status_names"' 'ATTRIBUTE "term_names"' 'ATTRIBUTE "ks"' 'SIMPLE { ( 57, 6 ) / ( 57, 6 ) }'; do
    grep -qF "$want" schema.txt || die "h5dump -H lacks $want"
  done
fi

py=/usr/bin/python3
if ! [ -x $py ] || ! $py -c 'import h5py, numpy' >/dev/null 2>&1; then
  echo "h5dump checks passed; /usr/bin/python3 has no h5py (apt-get install python3-h5py): skipping the h5py checks"
  exit 77
fi
$py - s.h5 <<'PY' || die "h5py checks failed"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
s = f["samples"]
N = int(f.attrs["nsamples"])
assert N == 57, N
status = s["status"][:]
done = status >= 0
assert status.dtype == np.int32 and s["term"].dtype == np.int32
assert s["strain"].shape == (N, 6) and s["strain"].dtype == np.float64
assert s["energy_parts"].shape == (N, 4)
for name in ("psi", "term", "status", "iterations", "retries", "residual", "constraint_residual", "time"):
    assert s[name].shape == (N,), name
    assert "units" in s[name].attrs and "description" in s[name].attrs, name
assert s["psi"].attrs["units"] == "J/m^2" and s["energy_parts"].attrs["units"] == "J" and s["time"].attrs["units"] == "s"
assert int(f.attrs["ndone"]) == done.sum() == 57 - 11
assert int(f.attrs["nconverged"]) == (status == 0).sum()
assert (~done == (np.arange(N) % 5 == 2)).all()
assert np.isnan(s["psi"][~done]).all() and np.isnan(s["strain"][~done]).all() and (s["term"][~done] == -1).all()
assert np.isfinite(s["psi"][done]).all() and np.isfinite(s["strain"][done]).all()
k = np.arange(N)[done]
assert np.array_equal(s["psi"][done], 1e-3 * k + 1.0 / 3.0)          # MakeRecord in test_samples.c
assert np.array_equal(s["term"][done], k % 15)
names = list(s.attrs["status_names"])
assert names == ["converged", "iteration_cap", "time_cap", "stalled", "nonfinite", "failed"], names
assert list(s.attrs["term_names"])[:3] == ["zero", "sx", "sa"] and len(s.attrs["term_names"]) == 22
r = f["reference"]
nv = int(r.attrs["nv"])
for name, shape in (("X", (nv, 3)), ("theta", (nv,)), ("next", (nv,)), ("prev", (nv,)), ("shift", (nv, 2)),
                    ("rest_length", (nv,)), ("rest_kappa", (nv, 2)), ("rest_twist", (nv,)), ("ref_d1", (nv, 3)), ("ref_twist", (nv,))):
    assert r[name].shape == shape, (name, r[name].shape)
nxt = r["next"][:]
assert sorted(nxt) == list(range(nv))                                   # a permutation
assert np.allclose(np.linalg.norm(r["ref_d1"][:], axis=1), 1)
m = f["material"].attrs
rad = m["radius"]
assert m["kc"] == 50 and abs(m["B"] - m["E"] * np.pi * rad**4 / 4) <= 1e-12 * m["B"]
assert m["curvature"] == "averaged" and m["contact_type"] == "quadrature"
assert f.attrs["hylc_version"] and f.attrs["creation_date"].endswith("Z") and f.attrs["hostname"]
opts = f["options"].asstr()[()]
assert "-yarn_kc 50" in opts, opts
PY
exit 0
