#!/usr/bin/env bash
# make demo: the main job on a built-in default.  For now: generate a stockinette tile with the pattern
# tool, print its summary, write it as .pyp and as 3x3 tiled VTK polylines (open in ParaView, apply a
# Tube filter with the yarn radius).  Outputs go to out/demo/.
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
echo "demo outputs: $out/stockinette.pyp (pattern), $out/stockinette.vtk and $out/plain_sx0.1.vtk (ParaView),"
echo "              $out/reference.pyp (reference state), $out/samples.h5 (HDF5 samples, docs/output-format.md)"
