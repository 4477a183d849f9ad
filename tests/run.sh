#!/usr/bin/env bash
# hylc test runner: C unit tests (build/tests/*) and program-level regression tests
# (tests/regression/*.sh).  Prints one line per test and closes with "N passed, N failed[, N skipped]".
# Exit status: 0 if nothing failed.
#   tests/run.sh [FILTER]     run the tests whose name contains FILTER
#   tests/run.sh --unit [FILTER]   only the C unit tests
# BUILD=dir takes the programs from dir (default build). HYLC_ASAN=1 (make test ASAN=1, make test-asan:
# BUILD=build-asan) sets the sanitizer options and suppressions of docs/testing.md and skips the
# valgrind tests (a sanitized program does not run under valgrind). Under ASan every unit test runs twice:
# with PETSc's default allocator, which puts the arrays of one PetscMalloc2..7 in one block (as users run:
# an array of such a block freed or grown alone is an invalid free), and with -malloc_coalesce 0, one block
# per array (an overrun from one array into the next is a heap overflow); the regression scripts run with
# the default (HYLC_ASAN_COALESCE=0: with -malloc_coalesce 0 instead).
# A unit test declares its MPI size with a comment line "hylc-test: nprocs=N" (default 1).
# A regression script gets $HYLC_BIN, $HYLC_REFDATA, $MPIEXEC and a private $HYLC_TMP; it exits 0 to
# pass, 77 to skip (its last output line says why), anything else to fail.
set -u
cd "$(dirname "$0")/.."
top=$PWD
unit_only=0
[ "${1:-}" = --unit ] && { unit_only=1; shift; }
filter=${1:-}
build=${BUILD:-build}
asan=${HYLC_ASAN:-0}
if [ "$asan" = 1 ]; then
  # the stacks of leaks are unwound slowly (Open MPI and libc have no frame pointers) so that the
  # suppressions of tests/lsan.supp match them; PETSc's signal handler would hide ASan's report of a
  # fault
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:fast_unwind_on_malloc=0:malloc_context_size=20:suppressions=$top/tests/asan.supp}
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$top/tests/lsan.supp:print_suppressions=0}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
  export PETSC_OPTIONS="${PETSC_OPTIONS:-} -no_signal_handler"
  [ "${HYLC_ASAN_COALESCE:-1}" = 0 ] && PETSC_OPTIONS="$PETSC_OPTIONS -malloc_coalesce 0"
  export HYLC_ASAN=1
fi

# Open MPI as root, more ranks than cores, quick start-up; harmless when not root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
export HYLC_ROOT=$top HYLC_BIN=$top/$build/bin
export HYLC_REFDATA=${HYLC_REFDATA:-$top/../shared/refdata}
export MPIEXEC="mpiexec --oversubscribe"
timeout_s=${HYLC_TEST_TIMEOUT:-900}

tmproot=$(mktemp -d "${TMPDIR:-/tmp}/hylc-test.XXXXXX")
trap 'rm -rf "$tmproot"' EXIT
pass=0 fail=0 skip=0 failed=()

report() { # name status seconds logfile
  local name=$1 st=$2 secs=$3 log=$4
  case $st in
    0) pass=$((pass + 1)); printf 'PASS  %-40s %6.1f s\n' "$name" "$secs" ;;
    77) skip=$((skip + 1)); printf 'SKIP  %-40s %s\n' "$name" "$(tail -n 1 "$log")" ;;
    *) fail=$((fail + 1)); failed+=("$name")
       printf 'FAIL  %-40s %6.1f s (exit %d)\n' "$name" "$secs" "$st"
       tail -n 30 "$log" | sed 's/^/      | /' ;;
  esac
}

run_one() { # name logfile command...
  local name=$1 log=$2; shift 2
  local t0 t1 st
  t0=$(date +%s.%N)
  timeout "$timeout_s" "$@" >"$log" 2>&1 </dev/null
  st=$?
  t1=$(date +%s.%N)
  [ $st -eq 124 ] && echo "timed out after ${timeout_s} s" >>"$log"
  # a unit test that leaks fails: PETSc's -malloc_dump lists every block not freed at PetscFinalize as
  # "[rank] N bytes function() at file:line" (it does not change the exit status itself)
  if [ $st -eq 0 ] && [ "${leakcheck:-0}" = 1 ] && grep -Eq '^\[ *[0-9]+\] *[0-9]+ bytes .*\(\) at ' "$log"; then
    echo "leak: PETSc -malloc_dump reports memory not freed at PetscFinalize (lines above)" >>"$log"
    st=1
  fi
  report "$name" $st "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')" "$log"
}

# unit tests run with PETSc's tracing allocator and its dump of unfreed memory (not under ASan, whose
# LeakSanitizer checks leaks and whose overrun checks the allocator's padding would hide)
unit_petsc_options=${PETSC_OPTIONS:-}
[ "$asan" = 1 ] || unit_petsc_options="$unit_petsc_options -malloc_debug -malloc_dump"
for src in tests/unit/*.c; do
  [ -e "$src" ] || continue
  name=$(basename "$src" .c)
  [ -n "$filter" ] && [[ $name != *"$filter"* ]] && continue
  exe=$build/tests/$name
  log=$tmproot/$name.log
  if [ ! -x "$exe" ]; then
    echo "missing executable $exe (run make)" >"$log"; report "unit/$name" 1 0 "$log"; continue
  fi
  np=$(sed -n 's/.*hylc-test: *nprocs=\([0-9]*\).*/\1/p' "$src" | head -n 1)
  np=${np:-1}
  mkdir -p "$tmproot/$name" && pushd "$tmproot/$name" >/dev/null
  leakcheck=1
  # under ASan: PETSc's default allocator, then one block per array (see the top)
  for alloc in default $([ "$asan" = 1 ] && echo separate); do
    opts=$unit_petsc_options label=""
    [ $alloc = separate ] && opts="$opts -malloc_coalesce 0" label=" [-malloc_coalesce 0]"
    [ $alloc = default ] && [ "$asan" = 1 ] && opts=${opts// -malloc_coalesce 0/}
    if [ "$np" -gt 1 ]; then
      PETSC_OPTIONS=$opts run_one "unit/$name (np=$np)$label" "$log" $MPIEXEC -x PETSC_OPTIONS -n "$np" "$top/$exe"
    else
      PETSC_OPTIONS=$opts run_one "unit/$name$label" "$log" "$top/$exe"
    fi
  done
  leakcheck=0
  popd >/dev/null
done

for script in tests/regression/*.sh; do
  [ -e "$script" ] || continue
  [ $unit_only = 1 ] && break
  name=$(basename "$script" .sh)
  [ -n "$filter" ] && [[ $name != *"$filter"* ]] && continue
  log=$tmproot/$name.log
  if [ "$asan" = 1 ] && [[ $name == *valgrind* ]]; then
    echo "skipped under ASan: a sanitized program does not run under valgrind (run it with make test)" >"$log"
    report "regression/$name" 77 0 "$log"
    continue
  fi
  export HYLC_TMP=$tmproot/reg-$name
  mkdir -p "$HYLC_TMP"
  run_one "regression/$name" "$log" bash "$script"
done

[ ${#failed[@]} -gt 0 ] && printf 'failed: %s\n' "${failed[*]}"
if [ $skip -gt 0 ]; then
  echo "$pass passed, $fail failed, $skip skipped"
else
  echo "$pass passed, $fail failed"
fi
[ $fail -eq 0 ]
