#!/usr/bin/env bash
# An option given without a value (-fit_knots "", -yarn_E "", "yarn_E:" in a YAML file, -yarn_E last on the
# command line) was ignored silently: PETSc stores no value, its number readers then keep the default and
# its string and choice readers read "". Now the project's option readers (src/sys/options.c), which every
# stage reads its options with, refuse it in one line, "Option -yarn_E: no value", before any work; a
# flag (-sampler_overwrite, -reference_minimum) still needs none. Also the reference state's counts:
# -reference_max_rounds / -reference_max_evals <= 0 and -reference_xtol < 0 were accepted (the relaxation
# skipped, a sentinel printed as "E = 4.494e+307 J", samples written).
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|^psi:|\[calibrate\]|\[sampler\]|\[reference\]|\[fit\]'
die() { echo "FAIL: $*"; exit 1; }
B=$HYLC_BIN
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0.1,0,0,0,0,0,2\n' >t.csv
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >m.json
solve="$B/hylc-solve -pattern_type plain"
sample="$B/hylc-sample -pattern_type plain -sampler_output s.h5"
calib="$B/hylc-calibrate -pattern_type plain -calibrate_target t.csv"
# every kind of reader, in every program
for e in '-yarn_E|real' '-micro_rtol|real' '-micro_ls_max|int' '-macro_phi|choice' '-macro_grid|int' '-periodic_slide|choice' \
  '-hylc_metis_seed|int' '-pattern_radius|real' '-strain|list' '-solve_output|path' '-solve_uniaxial|string'; do
  o=${e%|*}
  expect_fail "^hylc: error: Option $o: no value$" $solve $o ''
done
expect_fail '^hylc: error: Option -pattern_type: no value$' $B/hylc-pattern -pattern_type ''
expect_fail '^hylc: error: Option -pattern_file: no value$' $B/hylc-pattern -pattern_file ''
expect_fail '^hylc: error: Option -pattern_vtk_tiles: no value$' $B/hylc-pattern -pattern_type plain -pattern_vtk_tiles ''
for o in -fit_knots -fit_knots1d -fit_terms -fit_json -fit_reg -fit_knots2d_stretch -fit_family; do
  expect_fail "^hylc: error: Option $o: no value$" $B/hylc-fit -fit_input t.csv $o ''
done
for o in -sampler_output -sampler_n1 -sampler_family -sampler_range_sx -reference_max_rounds -reference_output -reference_bounds -yarn_kc; do
  expect_fail "^hylc: error: Option $o: no value$" $sample $o ''
done
for o in -calibrate_params -calibrate_max_samples -calibrate_stationary -calibrate_output; do
  expect_fail "^hylc: error: Option $o: no value$" $calib $o ''
done
for o in -material -strain -eval_input -eval_output; do
  expect_fail "^hylc: error: Option $o: no value$" $B/hylc-eval -material m.json $o ''
done
# the option last on the command line, in an options file, in YAML, in PETSC_OPTIONS
expect_fail '^hylc: error: Option -yarn_E: no value$' $solve -yarn_E
printf -- '-yarn_E\n' >o.txt
expect_fail '^hylc: error: (o.txt:1: )?Option -yarn_E: no value$' $solve -options_file o.txt
printf 'pattern_type: plain\nyarn_E:\n' >e.yaml
expect_fail "^hylc: error: e.yaml:2:8: 'yarn_E' has no value" $B/hylc-solve -options_file e.yaml
expect_fail '^hylc: error: Option -fit_knots: no value$' env PETSC_OPTIONS="-fit_knots" $B/hylc-fit -fit_input t.csv
[ -e s.h5 ] || [ -e s.h5.journal ] && die "hylc-sample left s.h5"
# flags need no value
$B/hylc-pattern -pattern_type plain -pattern_output p.pyp >p.txt 2>&1 || { cat p.txt; die "hylc-pattern"; }
$B/hylc-eval -material m.json -strain 0.1,0,0,0,0,0 -derivatives >d.txt 2>&1 || { cat d.txt; die "the flag -derivatives without a value"; }

# the reference state's counts and tolerance
expect_fail '^hylc: error: -reference_max_rounds 0: at least 1 round of the stress-free relaxation' $sample -reference_max_rounds 0
expect_fail '^hylc: error: -reference_max_rounds -3: at least 1 round' $calib -reference_max_rounds -3
expect_fail '^hylc: error: -reference_max_evals 0: at least 3 solves \(the first simplex' $sample -reference_max_evals 0
expect_fail '^hylc: error: -reference_max_evals 2: at least 3 solves' $sample -reference_max_evals 2
expect_fail '^hylc: error: -reference_xtol -0.001: a simplex size, >= 0' $sample -reference_xtol -1e-3
[ -e s.h5 ] || [ -e s.h5.journal ] && die "hylc-sample left s.h5"
finish
