#!/usr/bin/env bash
# The factorization of the Newton matrix is an ordinary PCCHOLESKY whose solver type is chosen with
# -micro_factor_pc_factor_mat_solver_type: hylc (HylcChol, the default), petsc, mumps and cholmod solve two
# of the paper's patterns (stockinette_small, whose bent and sheared sample needs a regularization retry,
# and satin_small) to the same psi within 1e-9 (relative). CHOLMOD only factors positive definite matrices,
# so it is compared with the others under -micro_factor_indefinite false (alpha x 10 at any negative
# eigenvalue, counted by MatGetInertia), where all four must agree too. Also: -micro_view names the solver
# type, the default is bitwise the explicit "-micro_factor_pc_factor_mat_solver_type hylc", and
# -log_view shows MICRO_Solve under the class HylcMicro and CHOL_Numeric under HylcChol.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-solve
die() { echo "FAIL: $*"; exit 1; }
strain=0,0.2,0,300,0,-200

solve() { # pattern, output file, options...
  local p=$1 out=$2
  shift 2
  # the solver settings are pinned (the stockinette_small config of 2026-11-24 before its recalibration, with
  # the paper's schedule, the default until 2026-11-26), so that tuning config/*.yaml or the defaults does not
  # remove the indefinite case this test needs
  "$tool" -options_file "$root/config/$p.yaml" -pattern_file "$HYLC_REFDATA/patterns/hylc2020/$p.pyp" -micro_alpha_start 5e4 -micro_alpha_schedule paper -periodic_slide global -strain $strain "$@" >"$out" 2>&1 || { cat "$out"; die "$p $*: failed"; }
  grep -q '^status: converged$' "$out" || { cat "$out"; die "$p $*: not converged"; }
}
psi() { sed -n 's/^psi: //p' "$1"; }
same() { # label, a, b
  awk -v a="$2" -v b="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= 1e-9 * a) }' || die "$1: psi $2 and $3 differ by more than 1e-9"
}

[ -f "$HYLC_REFDATA/patterns/hylc2020/stockinette_small.pyp" ] || { echo "the paper's patterns are not in $HYLC_REFDATA"; exit 77; }
cholmod=yes
"$tool" -pattern_type plain -strain 0.05,0,0,0,0,0 -micro_factor_pc_factor_mat_solver_type cholmod >probe.txt 2>&1 || cholmod=no
[ $cholmod = no ] && echo "note: this PETSc has no CHOLMOD; its column is skipped: $(head -1 probe.txt)"

for p in stockinette_small satin_small; do
  solve $p $p-default.txt -log_view
  solve $p $p-hylc.txt -micro_factor_pc_factor_mat_solver_type hylc -micro_view
  grep -q 'solver type hylc' $p-hylc.txt || { cat $p-hylc.txt; die "-micro_view does not name the solver type hylc"; }
  [ "$(psi $p-default.txt)" = "$(psi $p-hylc.txt)" ] || die "$p: the default differs from the explicit hylc solver type"
  ref=$(psi $p-hylc.txt)
  for t in petsc mumps; do
    solve $p $p-$t.txt -micro_factor_pc_factor_mat_solver_type $t
    same "$p, hylc vs $t" "$ref" "$(psi $p-$t.txt)"
  done
  solve $p $p-hylc-pd.txt -micro_factor_indefinite false
  refpd=$(psi $p-hylc-pd.txt)
  types="petsc mumps"
  [ $cholmod = yes ] && types="$types cholmod"
  for t in $types; do
    solve $p $p-$t-pd.txt -micro_factor_indefinite false -micro_factor_pc_factor_mat_solver_type $t
    same "$p, positive definite only, hylc vs $t" "$refpd" "$(psi $p-$t-pd.txt)"
  done
done
# the indefinite case is exercised: stockinette_small needs a retry with an indefinite factorization refused
grep -q 'regularization retries: [1-9]' stockinette_small-hylc-pd.txt || { cat stockinette_small-hylc-pd.txt; die "no regularization retry: the test does not exercise indefiniteness"; }

# log events under their own classes (HylcMicro in the object table; the events in the event table)
grep -q 'HylcMicro' satin_small-default.txt && grep -q 'MICRO_Solve' satin_small-default.txt && grep -q 'CHOL_Numeric' satin_small-default.txt || { cat satin_small-default.txt; die "-log_view lacks MICRO_Solve / CHOL_Numeric or the class HylcMicro"; }
exit 0
