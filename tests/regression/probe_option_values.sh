#!/usr/bin/env bash
# Issue 28, item 9: values and sizes. -yarn_E inf was accepted (only > 0 was checked): hylc-solve printed
# "psi: inf" and exited 0, hylc-sample and hylc-calibrate failed later without naming the option. An
# options file of more than 512 keys gave a 1,058-line PETSc error. Paths longer than 4,096 characters were
# cut silently, so -calibrate_output under a long directory failed only after the whole calibration.
# -calibrate_bounds_E 1e5,1e7,1e8 silently dropped the third value. Now every real option is finite, a
# list option has at most its values, more than 512 options is one line naming the 513th and where it was
# set, and a path over the limits is refused before any work, naming the option.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|^psi:|\[calibrate\]|\[sampler\]|\[reference\]'
die() { echo "FAIL: $*"; exit 1; }
B=$HYLC_BIN
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0.1,0,0,0,0,0,2\n' >t.csv
for v in inf nan -inf 1e999; do
  expect_fail "^hylc: error: Option -yarn_E $v: not a finite number$" "$B/hylc-solve" -pattern_type plain -yarn_E $v
done
expect_fail '^hylc: error: Option -yarn_E inf: not a finite number$' "$B/hylc-sample" -pattern_type plain -sampler_output s.h5 -yarn_E inf
expect_fail '^hylc: error: Option -yarn_E inf: not a finite number$' "$B/hylc-calibrate" -pattern_type plain -calibrate_target t.csv -yarn_E inf
expect_fail '^hylc: error: Option -yarn_kc 1e400: not a finite number$' "$B/hylc-solve" -pattern_type plain -yarn_kc 1e400
expect_fail '^hylc: error: Option -micro_rtol nan: not a finite number$' "$B/hylc-solve" -pattern_type plain -micro_rtol nan
expect_fail '^hylc: error: Option -calibrate_lambda inf: not a finite number$' "$B/hylc-calibrate" -pattern_type plain -calibrate_target t.csv -calibrate_lambda inf
expect_fail '^hylc: error: Option -fit_reg inf: not a finite number$' "$B/hylc-fit" -fit_input t.csv -fit_reg inf
expect_fail '^hylc: error: Option -pattern_radius inf: not a finite number$' "$B/hylc-pattern" -pattern_type plain -pattern_radius inf
expect_fail '^hylc: error: Option -sampler_range_sx -0.1,inf: value 2 is not a finite number$' "$B/hylc-sample" -pattern_type plain -sampler_output s.h5 -sampler_range_sx -0.1,inf
expect_fail '^hylc: error: Option -reference_bounds -0.5,inf: value 2 is not a finite number$' "$B/hylc-sample" -pattern_type plain -sampler_output s.h5 -reference_bounds -0.5,inf
expect_fail '^hylc: error: Option -calibrate_bounds_E 1e5,1e7,1e8: more than 2 values$' "$B/hylc-calibrate" -pattern_type plain -calibrate_target t.csv -calibrate_bounds_E 1e5,1e7,1e8
expect_fail '^hylc: error: Option -strain 0,0,0,0,0,0,0.1: more than 6 values$' "$B/hylc-solve" -pattern_type plain -strain 0,0,0,0,0,0,0.1
expect_fail '^hylc: error: Option -pattern_vtk_tiles 1,2,3: more than 2 values$' "$B/hylc-pattern" -pattern_type plain -pattern_vtk_tiles 1,2,3
expect_fail '^hylc: error: Option -fit_knots2d_stretch 2,7,1: more than 2 values$' "$B/hylc-fit" -fit_input t.csv -fit_knots2d_stretch 2,7,1
[ -e s.h5 ] || [ -e s.h5.journal ] && die "hylc-sample left s.h5"
# more than 512 options: one line naming the 513th and where it is (PETSC_OPTIONS emptied: the test
# runner's, under ASan, would count too)
for i in $(seq 1 512); do echo "-zz_opt$i 1"; done >o512.txt
expect_fail '^hylc: error: Too many options: -pattern_type \(the command line\) is the 513th distinct one; PETSc holds at most 512' env PETSC_OPTIONS= "$B/hylc-pattern" -options_file o512.txt -pattern_type plain
for i in $(seq 1 600); do echo "k$i: 1"; done >o600.yaml
expect_fail '^hylc: error: Too many options: -k513 \(o600.yaml:513\) is the 513th distinct one' env PETSC_OPTIONS= "$B/hylc-pattern" -options_file o600.yaml
expect_fail '^hylc: error: Too many options: -pattern_type \(PETSC_OPTIONS\) is the 513th distinct one' env PETSC_OPTIONS="-pattern_type plain" "$B/hylc-pattern" -options_file o512.txt
# 510 keys and two more are within PETSc's limit (the unknown options are then refused as such, the
# list cut with "and N more": it overflowed a stack buffer before, found by this case under ASan, since
# PETSc 3.18's PetscStrlcat writes past a nearly full buffer)
head -n 510 o512.txt >o510.txt
expect_fail '^hylc: error: Unknown option\(s\): -zz_opt.* and [0-9]+ more \(misspelt' env PETSC_OPTIONS= "$B/hylc-calibrate" -options_file o510.txt -pattern_type plain -calibrate_target t.csv
# paths over the limits: refused before any work, naming the option
long=$(printf 'd%.0s' $(seq 1 200))
dir=$long; for i in $(seq 2 21); do dir=$dir/$long; done
mkdir -p "$dir" || die "cannot create a 4,220-character directory"
expect_fail '^hylc: error: -calibrate_output: the path has 4227 characters, over the limit of 4084 for an output' "$B/hylc-calibrate" -pattern_type plain -calibrate_target t.csv -calibrate_output "$dir/o.yaml"
expect_fail '^hylc: error: -sampler_output: the path has 4225 characters, over the limit of 4084 for an output' "$B/hylc-sample" -pattern_type plain -sampler_output "$dir/s.h5"
expect_fail '^hylc: error: -calibrate_target: the path has 4226 characters, over the limit of 4095$' "$B/hylc-calibrate" -pattern_type plain -calibrate_target "$dir/t.csv"
expect_fail '^hylc: error: -fit_json: the path component .* has 250 characters, over the limit of 244' "$B/hylc-fit" -fit_input t.csv -fit_json "$(printf 'j%.0s' $(seq 1 250))"
# a value longer than a path buffer (4,096) is not cut: refused naming the option
expect_fail '^hylc: error: -eval_json: the path has 5006 characters, over the limit of 4084' "$B/hylc-eval" -material t.csv -eval_json "$(printf 'x/%.0s' $(seq 1 2500))o.json"
finish
