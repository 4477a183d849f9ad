#!/usr/bin/env bash
# Benchmark of the sampling job (hylc-sample), run by `make bench`:
# - samples per second and the parallel efficiency from 1 to 2 ranks on a one-dimensional stockinette plan;
# - the projected wall time of the full 23,251-sample plan on this 2-core machine, from a thinned plan
#   over the same ranges (n1 = 5, n2 = 3: 107 samples), for the stockinette (HYLC_BENCH_ALL=1: all seven
#   paper patterns).
set -u
cd "$(dirname "$0")/../.."
root=$PWD
ref=${HYLC_REFDATA:-$root/../shared/refdata}
[ -d "$ref/patterns/hylc2020" ] || { echo "bench_sampler: $ref/patterns/hylc2020 not found; skipped"; exit 0; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
tool=$root/build/bin/hylc-sample
family() { case $1 in basket|satin|satin_small) echo woven;; stockinette|stockinette_small) echo stockinette;; slip_stitch_honeycomb) echo honeycomb;; cartridge_belt_rib) echo rib;; esac; }
run() { # nranks name output args... -> prints wall seconds
  local np=$1 name=$2 out=$3; shift 3
  local t0 t1
  t0=$(date +%s.%N)
  (cd "$tmp" && mpiexec --oversubscribe -n "$np" "$tool" -options_file "$root/config/$name.yaml" -pattern_file "$ref/patterns/hylc2020/$name.pyp" \
     -sampler_family "$(family "$name")" -sampler_output "$out" -sampler_progress 1e9 "$@" >"$out.log" 2>&1) || { echo "run failed:"; cat "$tmp/$out.log"; exit 1; }
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.2f", b-a}'
}

echo "== parallel efficiency, stockinette, one-dimensional plan (5 terms x 20 samples)"
t1=$(run 1 stockinette e1.h5 -sampler_terms sx,sa,sy,II00,II11 -sampler_n1 20)
t2=$(run 2 stockinette e2.h5 -sampler_terms sx,sa,sy,II00,II11 -sampler_n1 20)
awk -v a="$t1" -v b="$t2" 'BEGIN{printf "  1 rank: %.2f s (%.1f samples/s); 2 ranks: %.2f s (%.1f samples/s); parallel efficiency %.0f%%\n", a, 100/a, b, 100/b, 100*a/(2*b)}'

echo "== projected wall time of the full plan (23,251 samples) on 2 ranks, from a thinned plan (107 samples)"
names=stockinette
[ "${HYLC_BENCH_ALL:-0}" = 1 ] && names="basket satin stockinette cartridge_belt_rib slip_stitch_honeycomb satin_small stockinette_small"
for name in $names; do
  t=$(run 2 "$name" "p_$name.h5" -sampler_n1 5 -sampler_n2 3)
  fails=$(sed -n 's/.*samples, \([0-9]*\) not converged.*/\1/p' "$tmp/p_$name.h5.log")
  awk -v n="$name" -v t="$t" -v f="$fails" 'BEGIN{printf "  %-22s %.1f s for 107 samples on 2 ranks (%s not converged) -> %.2f h for 23,251\n", n, t, f, t/107*23251/3600}'
done
