#!/usr/bin/env bash
# The demo configuration (config/demo.yaml, smaller plan) on 2 ranks, and `h5dump -H` of its output
# shows the schema of docs/output-format.md: every documented group, dataset and root attribute.
set -u
cd "$HYLC_TMP"
command -v h5dump >/dev/null || { echo "h5dump (hdf5-tools) not installed"; exit 77; }
die() { echo "FAIL: $*"; exit 1; }
$MPIEXEC -n 2 $HYLC_BIN/hylc-sample -options_file "$HYLC_ROOT/config/demo.yaml" -sampler_n1 4 -sampler_n2 2 \
  -sampler_output demo.h5 -reference_output ref.pyp >run.txt 2>&1 || { cat run.txt; die "demo run failed"; }
grep -q 'wrote demo.h5: 57 samples, 0 not converged' run.txt || { cat run.txt; die "demo summary"; }
h5dump -H demo.h5 >schema.txt || die "h5dump -H failed"
for item in 'GROUP "samples"' 'DATASET "strain"' 'DATASET "psi"' 'DATASET "term"' 'DATASET "status"' \
  'DATASET "iterations"' 'DATASET "retries"' 'DATASET "energy_parts"' 'DATASET "residual"' \
  'DATASET "constraint_residual"' 'DATASET "time"' 'GROUP "reference"' 'GROUP "material"' 'DATASET "options"' \
  'ATTRIBUTE "hylc_version"' 'ATTRIBUTE "creation_date"' 'ATTRIBUTE "nsamples"' 'ATTRIBUTE "nconverged"' \
  'ATTRIBUTE "status_names"' 'ATTRIBUTE "term_names"'; do
  grep -q "$item" schema.txt || die "h5dump -H lacks $item"
  name=$(echo "$item" | sed 's/.*"\(.*\)"/\1/')
  grep -q -e "\`$name\`" -e "/$name" "$HYLC_ROOT/docs/output-format.md" || die "docs/output-format.md does not document $name"
done
grep -A3 'DATASET "strain"' schema.txt | grep -q 'DATASPACE  SIMPLE { ( 57, 6 )' || { grep -A3 'DATASET "strain"' schema.txt; die "strain shape"; }
$HYLC_BIN/hylc-pattern -pattern_file ref.pyp >/dev/null 2>&1 || die "the reference state .pyp does not load"
exit 0
