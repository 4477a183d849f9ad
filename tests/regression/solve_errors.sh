#!/usr/bin/env bash
# Errors inside a Newton solve are errors, not samples (issue 12, deliver 2): hylc-solve exits != 0 naming
# the error for an error injected into the SNES function evaluation (HYLC_INJECT_ERROR=N: the N-th solve
# of the process) and for an unknown factorization package; a solve that is not the N-th is unaffected;
# a malformed HYLC_INJECT_ERROR is refused.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-solve
die() { echo "FAIL: $*"; exit 1; }
args="-pattern_type plain -strain 0.1,0,0,0,0,0"

HYLC_INJECT_ERROR=1 $tool $args >inj.txt 2>&1 && { cat inj.txt; die "injected error: exit 0"; }
grep -qF 'injected error (HYLC_INJECT_ERROR=1)' inj.txt || { cat inj.txt; die "injected error not named"; }
grep -q '^status:' inj.txt && { cat inj.txt; die "injected error printed a status"; }
# it travels the path of a real error: raised inside the SNES function evaluation
grep -q 'FormFunction' inj.txt || grep -q 'SNESComputeFunction' inj.txt || grep -q 'hylc: error' inj.txt || { cat inj.txt; die "injected error: unexpected report"; }

# hylc-solve solves once: the second solve never comes
HYLC_INJECT_ERROR=2 $tool $args >ok.txt 2>&1 || { cat ok.txt; die "HYLC_INJECT_ERROR=2 failed the only solve"; }
grep -q '^status: converged$' ok.txt || { cat ok.txt; die "HYLC_INJECT_ERROR=2: not converged"; }
HYLC_INJECT_ERROR=0 $tool $args >ok0.txt 2>&1 || { cat ok0.txt; die "HYLC_INJECT_ERROR=0 failed"; }
HYLC_INJECT_ERROR=x1 $tool $args >bad.txt 2>&1 && die "HYLC_INJECT_ERROR=x1 accepted"
grep -q 'HYLC_INJECT_ERROR=x1' bad.txt || { cat bad.txt; die "malformed HYLC_INJECT_ERROR not named"; }

# a bad option of the inner factorization is an error, not a failed sample
$tool $args -micro_factor_pc_factor_mat_solver_type nosuchsolver >nos.txt 2>&1 && { cat nos.txt; die "unknown solver type: exit 0"; }
grep -q 'nosuchsolver' nos.txt || { cat nos.txt; die "unknown solver type not named"; }
grep -q '^status:' nos.txt && { cat nos.txt; die "unknown solver type printed a status"; }
[ "$(wc -l <nos.txt)" -le 3 ] || { cat nos.txt; die "unknown solver type: more than three lines of output"; }
grep -q "option -micro_factor_pc_factor_mat_solver_type nosuchsolver" nos.txt || { cat nos.txt; die "the option is not named"; }
exit 0
