#!/usr/bin/env bash
# fidelity_all.sh: the fabric-fidelity report of docs/fabric-fidelity.md (`make fidelity`).
#
#   tools/fidelity_all.sh [CONFIG.yaml ...]
#
# For each options file (default: the seven paper patterns and the generated plain, twill, satin, stockinette
# and rib) the default pipeline (tools/hylc-material with no plan, reference or fit option) into
# $FIDELITY_DIR/<name> (default out/fidelity; <name> the file's name without .yaml), then
# tools/fabric_fidelity.py on it, then one document of all of them: $FIDELITY_DOC (default
# docs/fabric-fidelity.md) with its plots in $FIDELITY_PLOTS (default docs/img/fidelity). Work already done
# is skipped (hylc-material's stamps; a fidelity.json newer than its table and tile), so a killed run resumes.
# Hours of CPU for all twelve (the ribs dominate): docs/fabric-fidelity.md lists each pattern's cost.
# Environment: NP (MPI ranks, default 2), PYTHON (default /usr/bin/python3), and hylc-material's.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
dir=${FIDELITY_DIR:-$root/out/fidelity}
doc=${FIDELITY_DOC:-$root/docs/fabric-fidelity.md}
plots=${FIDELITY_PLOTS:-$root/docs/img/fidelity}
python=${PYTHON:-/usr/bin/python3}
np=${NP:-2}
if [ $# -gt 0 ]; then
  configs=("$@")
else
  configs=()
  for c in basket satin satin_small stockinette stockinette_small cartridge_belt_rib slip_stitch_honeycomb generated-plain generated-twill generated-satin generated-stockinette generated-rib; do
    configs+=("$root/config/$c.yaml")
  done
fi
"$python" -c "import h5py, numpy" 2>/dev/null || { echo "fidelity_all.sh: error: $python has no h5py/numpy (Debian: python3-h5py)" >&2; exit 1; }
results=()
for cfg in "${configs[@]}"; do
  [ -f "$cfg" ] || { echo "fidelity_all.sh: error: cannot read $cfg" >&2; exit 1; }
  name=$(basename "$cfg" .yaml)
  out=$dir/$name
  echo "[fidelity] $name: the default pipeline into $out"
  "$here/hylc-material" -np "$np" -no_plots -o "$out" "$cfg"
  table=$out/model.h5
  [ -f "$table" ] || table=$out/model.json
  if [ -f "$out/fidelity.json" ] && [ "$out/fidelity.json" -nt "$table" ] && [ "$out/fidelity.json" -nt "$out/reference.pyp" ]; then
    echo "[fidelity] $name: the report is current ($out/fidelity.json)"
  else
    echo "[fidelity] $name: the report (tile and table along the fabric tests' paths)"
    "$python" "$here/fabric_fidelity.py" --name "$name" --np "$np" "$cfg" "$out" > "$out/fidelity.log" 2>&1 || { tail -20 "$out/fidelity.log" >&2; exit 1; }
    tail -1 "$out/fidelity.log"
  fi
  results+=("$out/fidelity.json")
done
"$python" "$here/fabric_fidelity.py" --collect "$doc" --plots-dir "$plots" "${results[@]}"
