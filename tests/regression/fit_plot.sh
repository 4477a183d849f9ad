#!/usr/bin/env bash
# examples/plot_fit.py on a small fit (tests/regression/fit_tool.sh's samples): PNGs of a 1D and two 2D
# terms and index.txt from the JSON model; the HDF5 model reads as the same model. Skips (77) without /usr/bin/python3 + h5py + matplotlib.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
if ! [ -x $py ] || ! $py -c 'import h5py, numpy, matplotlib' >/dev/null 2>&1; then
  echo "/usr/bin/python3 lacks h5py or matplotlib (apt-get install python3-h5py python3-matplotlib): skipping"
  exit 77
fi
script=$HYLC_ROOT/examples/plot_fit.py
"$HYLC_BIN/../tests/test_fit_input" -test_write_samples s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }
"$HYLC_BIN/hylc-fit" -fit_input s.h5 -fit_output model.h5 -fit_json model.json >fit.txt 2>&1 || { cat fit.txt; die "hylc-fit failed"; }
# three terms at low resolution (all 14 at the default take ~3 s)
$py "$script" --terms sx,sx-sy,sa-II00 --dpi 50 s.h5 model.json plots >plot.txt 2>&1 || { cat plot.txt; die "plot_fit.py failed"; }
for t in sx sx-sy sa-II00; do
  f=plots/$t.png
  [ -s "$f" ] || die "$f missing"
  head -c 8 "$f" | od -An -c | grep -q 'P   N   G' || die "$f is not a PNG"
done
[ "$(ls plots/*.png | wc -l)" = 3 ] || die "plots other than the three asked for"
[ "$(wc -l <plots/index.txt)" = 3 ] || die "index.txt should list 3 terms"
$py "$script" --terms sx,bogus s.h5 model.json plots >bad.txt 2>&1 && die "unknown term accepted"
grep -q "bogus" bad.txt || die "unknown term message"
# the script reads the HDF5 model as the same model (plotting it again would only cost time)
PYTHONPATH=$HYLC_ROOT/examples $py - <<'PY' || die "the JSON and the HDF5 model differ in plot_fit.py"
import numpy as np, plot_fit
z, psi, term = plot_fit.load_samples("s.h5")
a, b = plot_fit.load_model("model.json"), plot_fit.load_model("model.h5")
assert a["const"] == b["const"] and a["scale"] == b["scale"], (a["const"], b["const"], a["scale"], b["scale"])
assert sorted(a["1D"]) == sorted(b["1D"]) and sorted(a["2D"]) == sorted(b["2D"])
fa, fb = plot_fit.model_psi(a, z), plot_fit.model_psi(b, z)
assert np.array_equal(fa, fb), np.abs(fa - fb).max()
assert np.sqrt(np.mean((fa - psi) ** 2)) < 1e-3
PY
$py "$script" -h >usage.txt 2>&1 || die "-h"
grep -q "OUTDIR" usage.txt || die "usage text"
exit 0
