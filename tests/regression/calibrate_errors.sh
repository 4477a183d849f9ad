#!/usr/bin/env bash
# hylc-calibrate refuses bad input with a one-line error before any solve: an unknown parameter name,
# inverted or non-positive bounds, a missing target, a directory target without data.txt, an unknown
# term, a CSV without the needed columns, an unwritable output, the retired -calibrate_max_reject, a bad
# -calibrate_stationary (weight, step, no scale in a file target); -help
# lists the options (the optimizer's, TAO's, under -calibrate_tao_*);
# the tile options reach the solves.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
tool=$HYLC_BIN/hylc-calibrate
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0.1,0,0,0,0,0,2\n' >ok.csv
printf 'sx,sa,sy,II00,II11,psi\n0,0,0,0,0,1\n' >nocol.csv
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0.1,0,x,0,0,0,2\n' >badnum.csv
mkdir -p emptydir
base=(-pattern_type plain -calibrate_reference none)
expect() { # pattern args...
  local pat=$1; shift
  $MPIEXEC -n 2 $tool "${base[@]}" "$@" >out.txt 2>&1 && { cat out.txt; die "accepted: $*"; }
  [ "$(grep -c '^hylc: error' out.txt)" = 1 ] || { cat out.txt; die "not one error line: $*"; }
  grep -q "^hylc: error[^:]*: .*$pat" out.txt || { cat out.txt; die "message should match '$pat': $*"; }
  grep -q '^\[calibrate\]' out.txt && { cat out.txt; die "work was done before the error: $*"; }
  return 0
}
expect "-calibrate_params: unknown parameter 'Ex'" -calibrate_target ok.csv -calibrate_params E,Ex
expect "-calibrate_tie: unknown parameter 'H'" -calibrate_target ok.csv -calibrate_tie H
expect "-calibrate_bounds_E 2e+06,100000: inverted bounds" -calibrate_target ok.csv -calibrate_bounds_E 2e6,1e5
expect "-calibrate_bounds_kc .*must be positive" -calibrate_target ok.csv -calibrate_bounds_kc 0,10
expect "initial E = 1e+06 .* outside -calibrate_bounds_E" -calibrate_target ok.csv -calibrate_bounds_E 1,10
expect "Cannot open missing.json" -calibrate_target missing.json
expect "emptydir/data.txt" -calibrate_target emptydir
expect "No target" -calibrate_params E
expect "-calibrate_terms: unknown term 'sz'" -calibrate_target ok.csv -calibrate_terms sx,sz
expect "nocol.csv:1: the header has no column 'II01'" -calibrate_target nocol.csv
expect "badnum.csv:3: column 3 (sy): 'x' is not a number" -calibrate_target badnum.csv
expect "-calibrate_output" -calibrate_target ok.csv -calibrate_output nodir/p.yaml
expect "Unknown option.*-calibrate_paramz" -calibrate_target ok.csv -calibrate_paramz E
# the hand-written Levenberg-Marquardt's option with no TAO counterpart names the TAO option to use
expect "-calibrate_max_reject no longer applies.*-calibrate_tao_max_funcs" -calibrate_target ok.csv -calibrate_max_reject 8
# the stationarity (issue 30): a bad weight or step; a file target without a row to scale dPsi/dsy by
expect "-calibrate_stationary must be a finite number >= 0" -calibrate_target ok.csv -calibrate_stationary -1
expect "-calibrate_stationary_h must be in" -calibrate_target ok.csv -calibrate_stationary 1 -calibrate_stationary_h 0
expect "-calibrate_stationary: no scale of dPsi/dsy" -calibrate_target ok.csv -calibrate_stationary 1
# the tile options (-periodic_*, -macro_*) reach every evaluation's solves (each rebuilds the tile): the
# closed-form midsurface refuses a doubly curved row in the solve (they were once silently dropped)
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0,0,0,50,0,50,2\n' >curved.csv
$MPIEXEC -n 2 $tool "${base[@]}" -calibrate_target curved.csv -calibrate_max_it 0 >out.txt 2>&1 || { cat out.txt; die "a doubly curved row failed with the default -macro_phi"; }
$MPIEXEC -n 2 $tool "${base[@]}" -calibrate_target curved.csv -calibrate_max_it 0 -macro_phi closed >out.txt 2>&1 && { cat out.txt; die "-macro_phi closed was not applied to the solves"; }
grep -q "^hylc: error.*-macro_phi closed needs a flat or singly curved II" out.txt || { cat out.txt; die "-macro_phi closed: wrong message"; }
# -help documents every option of the tool
$tool -help >help.txt 2>&1 || { cat help.txt; die "-help failed"; }
for o in target target_type output dump params tie bounds_E bounds_Es bounds_G bounds_kc terms n n2 stride max_samples \
  weight_zero weights stationary stationary_jacobian stationary_h max_it lambda xtol ftol fatol flat_tol reference tao_type tao_max_funcs tao_brgn_regularization_type; do
  grep -q -- "-calibrate_$o " help.txt || grep -q -- "-calibrate_$o <" help.txt || die "-help does not list -calibrate_$o"
done
grep -q -- '-sampler_family' help.txt && grep -q -- '-yarn_E' help.txt && grep -q -- '-micro_rtol' help.txt || die "-help lacks the pattern/yarn/solver options"
# the solver's sub-objects' options, listed by -help without setting up a pattern (a missing file is not opened)
$tool -pattern_type file -pattern_file missing.pyp -help >help2.txt 2>&1 || { tail -3 help2.txt; die "-help opened the pattern (set up the solver)"; }
for opt in -periodic_slide -macro_phi -micro_snes_max_it -micro_factor_pc_factor_mat_solver_type -calibrate_target; do
  grep -q -- "^ *$opt[ :]" help2.txt || die "-help without a pattern does not list $opt"
done
exit 0
