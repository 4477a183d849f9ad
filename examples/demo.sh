#!/usr/bin/env bash
# make demo: the whole pipeline on a built-in default, outputs in out/demo/:
#   1. a generated stockinette tile (pattern tool: summary, .pyp, 3x3 tiled VTK polylines for ParaView);
#   2. one microscale sample of a generated plain weave (hylc-solve);
#   3. the sampling job of config/demo.yaml on 2 MPI ranks (reference state, 4351 samples, HDF5);
#   4. the fit of those samples (hylc-fit: HDF5 and ARCSim-HYLC JSON tables);
#   5. the fitted energy and its derivatives at one strain (hylc-eval), and PNG plots of the fit when
#      python3-matplotlib is installed (examples/plot_fit.py);
#   6. a calibration (hylc-calibrate): the yarn parameters recovered from about 70 of those samples, starting
#      from wrong values (E x 2, Es / 2, kc / 2.5), with plots (examples/plot_calibrate.py).
set -eu
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1
out=out/demo
mkdir -p "$out"
echo "== hylc demo: generated stockinette tile (2 wales x 2 courses, r = 1 mm)"
mpiexec -n 1 build/bin/hylc-pattern -pattern_type stockinette -pattern_size 2,2 \
  -pattern_output "$out/stockinette.pyp" -pattern_vtk "$out/stockinette.vtk" -pattern_vtk_tiles 3,3
echo
echo "== the same tile read back from $out/stockinette.pyp"
build/bin/hylc-pattern -pattern_file "$out/stockinette.pyp" | grep -E 'vertices|loops|periods|radius'
echo
echo "== one microscale sample: the plain weave stretched by 10 % along x"
build/bin/hylc-solve -pattern_type plain -yarn_kc 50 -strain 0.1,0,0,0,0,0 -solve_vtk "$out/plain_sx0.1.vtk"
echo
echo "== the sampling job on 2 MPI ranks: config/demo.yaml (reference state, then 4351 samples)"
rm -f "$out/samples.h5" "$out/samples.h5.journal"
mpiexec --oversubscribe -n 2 build/bin/hylc-sample -options_file config/demo.yaml
if command -v h5dump >/dev/null; then
  echo "psi (J/m^2) of the first samples (the zero sample, then the sx term):"
  h5dump -d /samples/psi -c 8 "$out/samples.h5" | awk '/DATA {/{f=1} f{print} f&&/}/{exit}'
fi
echo
echo "== the fit: spline tables of the homogenized material (docs/fit.md)"
build/bin/hylc-fit -fit_input "$out/samples.h5" -fit_output "$out/model.h5" -fit_json "$out/model.json"
echo
echo "== the fitted energy density at sx = 0.1, sa = 0.2, II00 = 20 1/m (hylc-eval)"
build/bin/hylc-eval -material "$out/model.json" -strain 0.1,0.2,0,20,0,0 -derivatives
plots=""
if /usr/bin/python3 -c 'import h5py, matplotlib' 2>/dev/null; then
  echo
  echo "== plots of every term (examples/plot_fit.py)"
  /usr/bin/python3 examples/plot_fit.py "$out/samples.h5" "$out/model.h5" "$out/plots"
  plots=", $out/plots/*.png (fit plots)"
fi
echo
echo "== calibration: E, Es, kc recovered from about 70 of the samples (-calibrate_max_samples 60), starting from E x 2, Es / 2, kc / 2.5 (hylc-calibrate)"
mpiexec --oversubscribe -n 2 build/bin/hylc-calibrate -pattern_file "$out/reference.pyp" -calibrate_target "$out/samples.h5" \
  -calibrate_max_samples 60 -yarn_E 2e6 -yarn_Es 5e5 -yarn_kc 20 -calibrate_params E,Es,kc \
  -calibrate_output "$out/calibrated.yaml" -calibrate_dump "$out/calibrate.csv"
grep '^yarn_' "$out/calibrated.yaml"
if [ -n "$plots" ]; then
  /usr/bin/python3 examples/plot_calibrate.py "$out/calibrate.csv" "$out/calibrate_plots" | tail -1
  plots="$plots, $out/calibrate_plots/*.png (calibration plots)"
fi
echo
echo "demo outputs: $out/stockinette.pyp (pattern), $out/stockinette.vtk and $out/plain_sx0.1.vtk (ParaView),"
echo "              $out/reference.pyp (reference state), $out/samples.h5 (HDF5 samples, docs/output-format.md),"
echo "              $out/model.h5 and $out/model.json (fitted material, docs/material.md),"
echo "              $out/calibrated.yaml and $out/calibrate.csv (calibration, docs/calibrate.md)$plots"
