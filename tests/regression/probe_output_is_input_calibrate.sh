#!/usr/bin/env bash
# Issue 28, item 4: inputs overwritten, outputs lost. hylc-calibrate compared its outputs only with the
# target: -reference_output onto the CSV target turned it into a .pyp, -calibrate_output onto the pattern
# file overwrote it, -calibrate_output and -calibrate_dump on one file lost the YAML. hylc-eval
# -eval_json onto -eval_input overwrote the strains, -eval_output and -eval_json on one file lost the
# results. No tool protected its options files: hylc-calibrate -calibrate_output, hylc-sample
# -reference_output and hylc-eval -eval_json each replaced the file they were started with, exit 0.
# Now every program lists its files (include/hylc/files.h) and refuses, in one line and before any work,
# an output that is an input (by device and inode: another spelling, a hard link; the options files of the
# command line, of PETSC_OPTIONS and those they name; PETSc's .petscrc) or another output (also when
# neither exists yet, by directory and name, and through a dangling link). Checksums of every input before
# and after; no output file created.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|\[calibrate\]|\[sampler\]|^psi:|^wrote|evaluated'
die() { echo "FAIL: $*"; exit 1; }
B=$HYLC_BIN
mkdir -p in sub
printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,1\n0.1,0,0,0,0,0,2\n' >in/t.csv
"$B/hylc-pattern" -pattern_type plain -pattern_output in/p.pyp >/dev/null 2>&1 || die "hylc-pattern failed"
printf 'pattern_type: plain\ncalibrate_target: in/t.csv\ncalibrate_reference: none\n' >in/c.yaml
printf -- '-calibrate_target in/t.csv\n-options_file in/nested.txt\n' >in/outer.txt
printf -- '-calibrate_max_it 1\n' >in/nested.txt
printf 'pattern_type: plain\nsampler_terms: zero\n' >in/s.yaml
printf -- '-material %s\n' "$PWD/in/m.json" >in/e.txt
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 3, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >in/m.json
printf '0 0 0 0 0 0\n0.1 0 0 0 0 0\n' >in/strains.txt
printf 'fit_terms: sx\n' >in/f.yaml
cp in/p.pyp in/p.pyp.journal
ln -f in/t.csv in/hard.csv
ln -sf ../newfile.yaml sub/dangling.yaml
sum0=$(cat in/* | sha256sum)
C=("$B/hylc-calibrate" -pattern_type plain -calibrate_target in/t.csv)
expect_fail '^hylc: error: Output in/t.csv \(-reference_output\) is the input in/t.csv \(-calibrate_target\): refusing to overwrite an input$' "${C[@]}" -reference_output in/t.csv
expect_fail '^hylc: error: Output in/p.pyp \(-calibrate_output\) is the input in/p.pyp \(-pattern_file\)' "$B/hylc-calibrate" -pattern_type file -pattern_file in/p.pyp -calibrate_reference none -calibrate_target in/t.csv -calibrate_output in/p.pyp
expect_fail '^hylc: error: -calibrate_output and -calibrate_dump name the same file x.yaml: one output would replace the other$' "${C[@]}" -calibrate_output x.yaml -calibrate_dump x.yaml
expect_fail '^hylc: error: -calibrate_output and -calibrate_dump name the same file \(newfile.yaml, sub/dangling.yaml\)' "${C[@]}" -calibrate_output newfile.yaml -calibrate_dump sub/dangling.yaml
expect_fail '^hylc: error: -calibrate_output and -reference_output name the same file \(y.yaml, sub/../y.yaml\)' "${C[@]}" -calibrate_output y.yaml -reference_output sub/../y.yaml
expect_fail '^hylc: error: Output in/hard.csv \(-calibrate_dump\) is the input in/t.csv \(-calibrate_target\)' "${C[@]}" -calibrate_dump in/hard.csv
expect_fail '^hylc: error: Output ./in/../in/t.csv \(-calibrate_output\) is the input in/t.csv \(-calibrate_target\)' "${C[@]}" -calibrate_output ./in/../in/t.csv
expect_fail '^hylc: error: Output in/c.yaml \(-calibrate_output\) is the input in/c.yaml \(-options_file\)' "$B/hylc-calibrate" -options_file in/c.yaml -calibrate_output in/c.yaml
expect_fail '^hylc: error: Output in/nested.txt \(-calibrate_dump\) is the input in/nested.txt \(-options_file in in/outer.txt\)' "$B/hylc-calibrate" -pattern_type plain -options_file in/outer.txt -calibrate_dump in/nested.txt
expect_fail '^hylc: error: Output in/outer.txt \(-calibrate_output\) is the input in/outer.txt \(-options_file in PETSC_OPTIONS\)' env PETSC_OPTIONS="-options_file in/outer.txt" "$B/hylc-calibrate" -pattern_type plain -calibrate_output in/outer.txt
cp in/nested.txt .petscrc
expect_fail "^hylc: error: Output .petscrc \(-calibrate_output\) is the input .petscrc \(PETSc's .petscrc\)" "${C[@]}" -calibrate_output .petscrc
cmp -s .petscrc in/nested.txt || die ".petscrc was changed"
rm -f .petscrc
S=("$B/hylc-sample" -options_file in/s.yaml)
expect_fail '^hylc: error: Output in/s.yaml \(-reference_output\) is the input in/s.yaml \(-options_file\)' "${S[@]}" -sampler_output out.h5 -reference_output in/s.yaml
expect_fail '^hylc: error: Output in/s.yaml \(-sampler_output\) is the input in/s.yaml \(-options_file\)' "${S[@]}" -sampler_output in/s.yaml
expect_fail '^hylc: error: Output in/p.pyp.journal \(the journal of -sampler_output\) is the input' "${S[@]}" -pattern_type file -pattern_file in/p.pyp.journal -sampler_output in/p.pyp
[ -e out.h5 ] || [ -e out.h5.journal ] && die "hylc-sample left out.h5 or its journal"
E=("$B/hylc-eval" -material in/m.json)
expect_fail '^hylc: error: Output in/strains.txt \(-eval_json\) is the input in/strains.txt \(-eval_input\)' "${E[@]}" -eval_input in/strains.txt -eval_output o.txt -eval_json in/strains.txt
expect_fail '^hylc: error: -eval_output and -eval_json name the same file same.txt' "${E[@]}" -eval_input in/strains.txt -eval_output same.txt -eval_json same.txt
expect_fail '^hylc: error: Output in/e.txt \(-eval_json\) is the input in/e.txt \(-options_file\)' "$B/hylc-eval" -options_file in/e.txt -eval_json in/e.txt
expect_fail '^hylc: error: Output in/m.json \(-eval_output\) is the input in/m.json \(-material\)' "${E[@]}" -eval_input in/strains.txt -eval_output in/m.json
expect_fail '^hylc: error: Output in/f.yaml \(-fit_json\) is the input in/f.yaml \(-options_file\)' "$B/hylc-fit" -options_file in/f.yaml -fit_input in/strains.txt -fit_json in/f.yaml
expect_fail '^hylc: error: Output in/s.yaml \(-pattern_output\) is the input in/s.yaml \(-options_file\)' "$B/hylc-pattern" -options_file in/s.yaml -pattern_output in/s.yaml
expect_fail '^hylc: error: Output in/s.yaml \(-solve_vtk\) is the input in/s.yaml \(-options_file\)' "$B/hylc-solve" -options_file in/s.yaml -solve_vtk in/s.yaml
[ -z "$(ls | grep -E '^(x|y|o|same|newfile)\.|\.tmp')" ] || die "outputs or temporaries left: $(ls)"
[ "$(cat in/* | sha256sum)" = "$sum0" ] || die "an input was changed"
finish
