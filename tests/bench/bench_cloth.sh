#!/usr/bin/env bash
# Benchmark of hylc-cloth (docs/fabric.md), run by `make bench`: the wall time, Newton iterations and the
# time of the Newton solves (log event CLOTH_Solve) with its assembly (CLOTH_Assemble), factorization and
# line search (CLOTH_LineSearch) of
# - strip tensile (stock1 and satin1, x and y, h = 5 mm, 10 steps to 10 %) on 1 and 2 ranks,
# - bias extension (satin1, 45 degrees, h = 5 mm, 10 steps to 10 %),
# - Cusick drape, static (satin1, h = 1 cm: 847 vertices) on 1 and 2 ranks,
# - cantilever bending length (satin1, x and y, face up, 1 cm wide, 16 spacings over the overhang),
# with the measured results each prints (T(5%), the central zone against the table, c against the
# elastica). Skipped when the paper's tables are absent. HYLC_BENCH_CLOTH_NP (default 2) ranks for the
# parallel run.
set -u
cd "$(dirname "$0")/../.."
root=$PWD
ref=${HYLC_REFDATA:-$root/../shared/refdata}
[ -d "$ref/materials" ] || { echo "bench_cloth: $ref/materials not found; skipped"; exit 0; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cloth=$root/build/bin/hylc-cloth
np=${HYLC_BENCH_CLOTH_NP:-2}
st=0

# name ranks options...
run() {
  local name=$1 n=$2; shift 2
  local load t0 t1 log=$tmp/$name.log
  load=$(cut -d' ' -f1 /proc/loadavg)
  t0=$(date +%s.%N)
  if [ "$n" = 1 ]; then
    "$cloth" "$@" -cloth_vtk 0 -cloth_plot 0 -cloth_output "$tmp/$name" -log_view ascii:"$tmp/$name.logview" >"$log" 2>&1
  else
    mpiexec --oversubscribe -n "$n" "$cloth" "$@" -cloth_vtk 0 -cloth_plot 0 -cloth_output "$tmp/$name" -log_view ascii:"$tmp/$name.logview" >"$log" 2>&1
  fi
  local rc=$?
  t1=$(date +%s.%N)
  if [ $rc -ne 0 ]; then
    echo "$name: FAILED (exit $rc)"; tail -n 3 "$log"; st=1; return
  fi
  # event times (max over ranks, s): the second column after the count in PETSc's -log_view table
  local ev
  ev=$(awk '$1 == "CLOTH_Assemble" { a = $4 } $1 == "CLOTH_Solve" { s = $4 } $1 == "CLOTH_LineSearch" { l = $4 } $1 == "MatCholFctrNum" || $1 == "MatCholFctrSym" || $1 == "MatLUFactorNum" || $1 == "MatLUFactorSym" { f += $4 }
            END { printf "Newton solves %.2f s: assembly %.2f s (energy, gradient, Hessian), factorization %.2f s, line search %.2f s", s, a, f, l }' "$tmp/$name.logview")
  printf '%-24s %d rank(s): %6.1f s wall (load %s); %s\n' "$name" "$n" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')" "$load" "$ev"
  grep -E '^  T\(5%\)|^  F\(5%\)|^  drape coefficient|^cantilever|^Newton iterations' "$log" | sed 's/^/    /'
}

echo "== hylc-cloth: strip tensile, bias extension, cantilever (the paper's tables)"
for m in stock1 satin1; do
  run "tensile_$m" 1 -cloth_material "$ref/materials/$m.json" -cloth_test tensile -cloth_h 0.005
done
run "tensile_stock1_np$np" "$np" -cloth_material "$ref/materials/stock1.json" -cloth_test tensile -cloth_h 0.005
run "bias_satin1" 1 -cloth_material "$ref/materials/satin1.json" -cloth_test bias -cloth_h 0.005
run "drape_satin1_h10mm" 1 -cloth_material "$ref/materials/satin1.json" -cloth_test drape -cloth_h 0.01
run "drape_satin1_h10mm_np$np" "$np" -cloth_material "$ref/materials/satin1.json" -cloth_test drape -cloth_h 0.01
run "cantilever_satin1" 1 -cloth_material "$ref/materials/satin1.json" -cloth_test cantilever -cloth_face up -cloth_cantilever_width 0.01 -cloth_cantilever_n 16
exit $st
