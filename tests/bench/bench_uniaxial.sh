#!/usr/bin/env bash
# The fabric-level check of the method (issue 32, docs/fabric-uniaxial.md): the homogeneous uniaxial tension
# state computed from the yarn tile directly (hylc-solve -solve_uniaxial: Psi minimized over the lateral
# strains at every stretch, each Psi a microscale equilibrium) against the same state from our full-plan
# table of the pattern (hylc-eval -eval_uniaxial) and, for reference, from the paper's table, along x and y,
# on stockinette, satin and basket. Prints T (N/m) at s = 5, 10, 20 %, the relative difference of each table
# to the tile and the target (<= 3 %) met or missed per pattern, direction and stretch; writes the curves as
# CSV and a PNG per pattern (T(s) and the lateral stretch).
#
# Our full-plan tables: hylc's defaults (mpiexec -n 2 hylc-sample -options_file config/<p>.yaml, then hylc-fit,
# -fit_family stockinette for the stockinette), minutes per pattern: made once into $HYLC_FABRIC_TABLES
# (default build/fabric-tables, <p>.json with <p>.provenance: the commit and date that made it) and reused;
# delete a file there to remake it. HYLC_BENCH_UNIAXIAL="satin" picks patterns; HYLC_BENCH_UNIAXIAL_OUT the
# directory of the CSV, logs and PNG (default build/bench-uniaxial). Skipped without the reference data.
set -u
cd "$(dirname "$0")/../.."
root=$PWD
build=${BUILD:-build}
bin=$root/$build/bin
ref=${HYLC_REFDATA:-$root/../shared/refdata}
tables=${HYLC_FABRIC_TABLES:-$root/$build/fabric-tables}
out=${HYLC_BENCH_UNIAXIAL_OUT:-$root/$build/bench-uniaxial}
patterns=${HYLC_BENCH_UNIAXIAL:-stockinette satin basket}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1 OMPI_MCA_rmaps_base_oversubscribe=1
mpiexec=${MPIEXEC:-mpiexec --oversubscribe}
[ -d "$ref/patterns/hylc2020" ] && [ -d "$ref/materials" ] || { echo "bench_uniaxial: the reference data ($ref) are absent: skipped"; exit 0; }
/usr/bin/python3 -c 'import numpy' 2>/dev/null || { echo "bench_uniaxial: python3-numpy not installed: skipped"; exit 0; }
mkdir -p "$tables" "$out" || exit 1
# the stretches of the curves, in order (each state continued from the one before): steps of 1.25 %
strains=$(awk 'BEGIN { for (i = 1; i <= 16; i++) printf "%s%g", (i > 1 ? "," : ""), 0.0125 * i }')
# the same path in steps of 2.5 %: how much the tile's state depends on its path (multistability)
coarse=$(awk 'BEGIN { for (i = 1; i <= 8; i++) printf "%s%g", (i > 1 ? "," : ""), 0.025 * i }')
declare -A paper=([stockinette]=stock1 [satin]=satin1 [basket]=basket1 [rib]=rib1 [slip_stitch_honeycomb]=honey1)
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg) (2 cores shared: timings are noisy)"
st=0
for p in $patterns; do
  cfg=config/$p.yaml
  [ -f "$cfg" ] || { echo "bench_uniaxial: no $cfg"; st=1; continue; }
  pyp=$ref/patterns/hylc2020/$p.pyp
  json=$tables/$p.json
  if [ ! -f "$json" ]; then
    fam=""
    [ "$p" = stockinette ] && fam="-fit_family stockinette"
    echo "$p: making our full-plan table $json (hylc-sample on 2 ranks, then hylc-fit; minutes)"
    rm -f "$tables/$p.h5" "$tables/$p.h5.journal"
    t0=$(date +%s.%N)
    if ! $mpiexec -n 2 "$bin/hylc-sample" -options_file "$cfg" -pattern_file "$pyp" -sampler_output "$tables/$p.h5" >"$tables/$p.sample.log" 2>&1; then
      tail -n 5 "$tables/$p.sample.log"; echo "bench_uniaxial: hylc-sample failed on $p"; st=1; continue
    fi
    t1=$(date +%s.%N)
    # shellcheck disable=SC2086
    if ! "$bin/hylc-fit" -fit_input "$tables/$p.h5" -fit_json "$json" $fam >"$tables/$p.fit.log" 2>&1; then
      tail -n 5 "$tables/$p.fit.log"; echo "bench_uniaxial: hylc-fit failed on $p"; st=1; continue
    fi
    echo "made by $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown) on $(date -u +%Y-%m-%dT%H:%MZ): hylc-sample $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.0f", b - a }') s on 2 ranks, load $(cut -d' ' -f1 /proc/loadavg)" >"$tables/$p.provenance"
  fi
  echo "$p: our table $json ($(cat "$tables/$p.provenance" 2>/dev/null || echo "provenance unknown"))"
  for d in x y; do
    t0=$(date +%s.%N)
    if ! "$bin/hylc-solve" -options_file "$cfg" -pattern_file "$pyp" -solve_uniaxial $d -solve_uniaxial_strains "$strains" \
        -solve_uniaxial_csv "$out/$p-$d-tile.csv" >"$out/$p-$d-tile.log" 2>&1; then
      tail -n 5 "$out/$p-$d-tile.log"; echo "bench_uniaxial: hylc-solve -solve_uniaxial $d failed on $p"; st=1; continue
    fi
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f\n", b - a }' >"$out/$p-$d-tile.time"
    "$bin/hylc-solve" -options_file "$cfg" -pattern_file "$pyp" -solve_uniaxial $d -solve_uniaxial_strains "$coarse" \
      -solve_uniaxial_csv "$out/$p-$d-tile2.csv" >"$out/$p-$d-tile2.log" 2>&1 || { tail -n 5 "$out/$p-$d-tile2.log"; echo "bench_uniaxial: the 2.5 % path failed on $p $d"; st=1; }
    "$bin/hylc-eval" -material "$json" -eval_uniaxial $d -eval_uniaxial_strains "$strains" -eval_uniaxial_csv "$out/$p-$d-ours.csv" >"$out/$p-$d-ours.log" 2>&1 ||
      { cat "$out/$p-$d-ours.log"; echo "bench_uniaxial: our table failed on $p $d"; st=1; }
    if [ -n "${paper[$p]:-}" ]; then
      "$bin/hylc-eval" -material "$ref/materials/${paper[$p]}.json" -eval_uniaxial $d -eval_uniaxial_strains "$strains" -eval_uniaxial_csv "$out/$p-$d-paper.csv" >"$out/$p-$d-paper.log" 2>&1 ||
        { cat "$out/$p-$d-paper.log"; echo "bench_uniaxial: the paper's table failed on $p $d"; st=1; }
    fi
  done
done
# shellcheck disable=SC2086
/usr/bin/python3 tests/bench/uniaxial_compare.py "$out" $patterns || st=1
exit $st
