#!/usr/bin/env bash
# Runs every benchmark program in build/bench (built by make); each prints its own measured figures.
# Benchmarks that need MPI or the paper's patterns get the same environment as the tests.
set -u
cd "$(dirname "$0")/../.."
build=${BUILD:-build}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1
export HYLC_REFDATA=${HYLC_REFDATA:-$PWD/../shared/refdata} HYLC_ROOT=$PWD
st=0
for exe in "$build"/bench/*; do
  [ -x "$exe" ] || continue
  echo "== $(basename "$exe")"
  "$exe" || st=1
done
for script in tests/bench/bench_*.sh; do
  [ -f "$script" ] || continue
  echo "== $(basename "$script" .sh)"
  bash "$script" || st=1
done
exit $st
