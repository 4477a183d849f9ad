#!/usr/bin/env bash
# Drape benchmark of hylc-cloth (issue 32, Deliver 5; docs/performance.md), run by `make bench`: the
# static Cusick drape of the paper's satin1 (a 30 cm specimen on an 18 cm disc, face up) at >= 20,000
# triangles on HYLC_BENCH_DRAPE_NP (default 2) ranks. Prints the time to rest (wall time of the whole
# run, mesh to equilibrium), the Newton iterations per load step (from -cloth_monitor), and the cost per
# Newton iteration split into assembly (log event CLOTH_Assemble: energy, gradient and Hessian of the C8
# element, including the line search's evaluations) and solve (the factorization events and KSPSolve),
# from PETSc's -log_view (the max over ranks). Target: <= 2 min.
# HYLC_BENCH_DRAPE_H (default 0.0028 m: 21,000 triangles) sets the mesh, HYLC_BENCH_DRAPE_TIMEOUT
# (default 900 s) stops a run that is far too slow (reported as such). The table is read from the
# shared reference data (HYLC_REFDATA), never copied; skipped when it is absent.
set -u
cd "$(dirname "$0")/../.."
root=$PWD
ref=${HYLC_REFDATA:-$root/../shared/refdata}
table=$ref/materials/satin1.json
[ -f "$table" ] || { echo "bench_drape: $table not found; skipped"; exit 0; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_pml=ob1
cloth=$root/build/bin/hylc-cloth
np=${HYLC_BENCH_DRAPE_NP:-2}
h=${HYLC_BENCH_DRAPE_H:-0.0028}
limit=${HYLC_BENCH_DRAPE_TIMEOUT:-900}
tmp=${HYLC_BENCH_DRAPE_KEEP:-}
if [ -z "$tmp" ]; then tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT; else mkdir -p "$tmp"; fi
log=$tmp/drape.log lv=$tmp/drape.logview
args=(-cloth_material "$table" -cloth_test drape -cloth_face up -cloth_h "$h" -cloth_monitor
  -cloth_vtk 0 -cloth_plot 0 -cloth_output "$tmp/drape" -log_view ascii:"$lv")
if [ "$np" = 1 ]; then cmd=("$cloth" "${args[@]}"); else cmd=(mpiexec --oversubscribe -n "$np" "$cloth" "${args[@]}"); fi
echo "command: ${cmd[*]}" | sed "s|$tmp/|TMP/|g"
echo "load before: $(cat /proc/loadavg)"
t0=$(date +%s.%N)
timeout "$limit" "${cmd[@]}" >"$log" 2>&1
rc=$?
t1=$(date +%s.%N)
wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", b - a }')
echo "load after:  $(cat /proc/loadavg)"
head -n 1 "$log"
if [ $rc -eq 124 ]; then
  echo "drape: NOT AT REST after $wall s (stopped by the $limit s limit); load steps so far:"
  grep -c 'load step' "$log" | sed 's/^/  load steps tried: /'
  grep 'load step' "$log" | tail -n 3
  exit 1
elif [ $rc -ne 0 ]; then
  echo "drape: FAILED (exit $rc) after $wall s"; tail -n 5 "$log"; exit 1
fi
grep -E 'drape coefficient' "$log"
awk '/load step/ && / converged in / && !/not converged/ { n++; it += $(NF-1); if ($(NF-1) > mx) mx = $(NF-1) }
     /load step/ && /not converged/ { r++; rit += $(NF-1) }
     END { printf "load steps: %d converged (%.1f Newton iterations per step on average, at most %d), %d rejected and halved (%d iterations in them)\n", n, (n ? it / n : 0), mx, r, rit }' "$log"
its=$(sed -n 's/.*Newton iterations \([0-9]*\).*/\1/p' "$log" | tail -n 1)
awk -v its="$its" -v wall="$wall" -v np="$np" '
  $1 == "CLOTH_Assemble" { a = $4; na = $2 } $1 == "CLOTH_Solve" { s = $4 } $1 == "CLOTH_LineSearch" { l = $4 }
  $1 == "MatCholFctrNum" || $1 == "MatCholFctrSym" || $1 == "MatLUFactorNum" || $1 == "MatLUFactorSym" { f += $4 }
  $1 == "KSPSolve" { k = $4 }
  END {
    printf "time to rest: %s s wall on %d rank(s) (Newton solves %.1f s); target <= 120 s: %s\n", wall, np, s, (wall <= 120 ? "met" : "missed")
    printf "Newton iterations: %d\n", its
    printf "per Newton iteration: assembly %.3f s (%d assemblies in all, %.1f s, line search included), solve %.3f s (factorization %.1f s + triangular solves %.1f s), line search %.1f s in all\n", a / its, na, a, (f + k) / its, f, k, l
  }' "$lv"
