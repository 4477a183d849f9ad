#!/usr/bin/env bash
# make demo: the whole pipeline on a built-in default, outputs in out/demo/:
#   1. a generated stockinette tile (pattern tool: summary, .pyp, 3x3 tiled VTK polylines for ParaView);
#   2. one microscale sample of a generated plain weave (hylc-solve);
#   3. the pipeline of config/demo.yaml on 2 MPI ranks (tools/hylc-material): the reference state, 4351
#      samples (HDF5), the fit (HDF5 and ARCSim-HYLC JSON tables, the family from the samples), PNG plots
#      of the fit when python3-matplotlib is installed (examples/plot_fit.py) and out/demo/report.md;
#      run again, it skips what is current;
#   4. the fitted energy and its derivatives at one strain (hylc-eval);
#   5. a calibration (hylc-calibrate): the yarn parameters recovered from about 70 of those samples, starting
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
echo "== the pipeline on 2 MPI ranks: config/demo.yaml -> reference state, 4351 samples, fit, plots, report (tools/hylc-material)"
# samples of a demo from before the pipeline (no stamps): start over
[ -f "$out/.hylc-material/sample" ] || rm -f "$out/samples.h5" "$out/samples.h5.journal"
MPIEXEC="mpiexec --oversubscribe" tools/hylc-material -np 2 -o "$out" config/demo.yaml
if command -v h5dump >/dev/null; then
  echo "psi (J/m^2) of the first samples (the zero sample, then the sx term):"
  h5dump -d /samples/psi -c 8 "$out/samples.h5" | awk '/DATA {/{f=1} f{print} f&&/}/{exit}'
fi
echo
plots=""
[ -f "$out/plots/index.txt" ] && plots=", $out/plots/*.png (fit plots)"
echo "== the fitted energy density at sx = 0.1, sa = 0.2, II00 = 20 1/m (hylc-eval)"
build/bin/hylc-eval -material "$out/model.json" -strain 0.1,0.2,0,20,0,0 -derivatives
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
echo "              $out/model.h5 and $out/model.json (fitted material, docs/material.md), $out/report.md,"
echo "              $out/calibrated.yaml and $out/calibrate.csv (calibration, docs/calibrate.md)$plots"
