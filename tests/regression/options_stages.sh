#!/usr/bin/env bash
# Every program reads the whole study's options file (issue 33): the options of the other programs'
# stages are ignored without a word (src/sys/programs.c), a misspelt option is an error in every
# program. The options a program lists in -help (its hylc options; PETSc's solver options of the micro
# stage by a few representatives, the table knows them by prefix) are given, all at once, to each of the
# other programs, which must not refuse one of them; the satin study's file is read by hylc-fit and
# hylc-eval.
set -u
cd "$(dirname "$0")/../.."
B=$HYLC_BIN
T=$HYLC_TMP
die() { echo "FAIL: $*"; exit 1; }
progs="pattern solve sample fit eval calibrate cloth"
hylc_re='^ +-(pattern_|yarn_|micro_|periodic_|macro_|hylc_metis_|reference_|sampler_|solve_|strain|fit_|material|eval_|derivatives|calibrate_|cloth_)[A-Za-z0-9_]*'

# each program's options, from its -help
for p in $progs; do
  "$B/hylc-$p" -help >"$T/$p.help" 2>&1 || { tail -n 5 "$T/$p.help"; die "hylc-$p -help failed"; }
  grep -oE "$hylc_re" "$T/$p.help" | tr -d ' ' | sort -u >"$T/$p.opts"
  [ "$(wc -l <"$T/$p.opts")" -ge 5 ] || die "hylc-$p -help lists fewer than 5 hylc options"
done
# the micro stage's PETSc solvers: a few representatives of each prefix
for p in $progs; do
  grep -qE '^-micro_snes_' "$T/$p.opts" || continue
  sed -i -E '/^-micro_(snes|ksp|pc|factor_pc|factor_mat)_/d' "$T/$p.opts"
  printf '%s\n' -micro_snes_monitor -micro_ksp_type -micro_pc_type -micro_factor_pc_factor_mat_solver_type -micro_factor_mat_factor_view >>"$T/$p.opts"
  sort -u -o "$T/$p.opts" "$T/$p.opts"
done
# and the cloth's (hylc-cloth: SNES, KSP, PC, TAO)
for p in $progs; do
  grep -qE '^-cloth_snes_' "$T/$p.opts" || continue
  sed -i -E '/^-cloth_(snes|ksp|pc|tao)_/d' "$T/$p.opts"
  printf '%s\n' -cloth_snes_monitor -cloth_ksp_type -cloth_pc_type -cloth_tao_monitor >>"$T/$p.opts"
  sort -u -o "$T/$p.opts" "$T/$p.opts"
done
cat "$T"/*.opts | sort -u >"$T/all.opts"
[ "$(wc -l <"$T/all.opts")" -ge 150 ] || die "only $(wc -l <"$T/all.opts") hylc options in all programs' -help"

# run NAME EXPECTED-EXIT EXPECTED-STDERR-REGEX COMMAND...: the options of the other programs, not read by
# this one, given with a dummy value in an options file (the value is never read)
run() {
  local p=$1 want=$2 re=$3 st
  shift 3
  comm -23 "$T/all.opts" "$T/$p.opts" | sed 's/$/ 1/' >"$T/others-$p.txt"
  [ -s "$T/others-$p.txt" ] || die "no other options for hylc-$p"
  (cd "$T" && "$B/hylc-$p" -options_file "others-$p.txt" "$@" >"$p.out" 2>"$p.err")
  st=$?
  if grep -Eq 'Unknown option|was not used' "$T/$p.err"; then
    cat "$T/$p.err"
    die "hylc-$p refuses options of another program's stage (add them to src/sys/programs.c)"
  fi
  [ $st -eq "$want" ] || { tail -n 5 "$T/$p.out" "$T/$p.err"; die "hylc-$p exits $st, expected $want"; }
  if [ -n "$re" ]; then
    grep -Eq -- "$re" "$T/$p.err" || { cat "$T/$p.err"; die "hylc-$p: stderr does not match /$re/"; }
  else
    [ ! -s "$T/$p.err" ] || { cat "$T/$p.err"; die "hylc-$p: unexpected output on stderr"; }
  fi
}
run pattern 0 '' -pattern_type plain
run solve 0 '' -pattern_type plain -strain 0.01,0,0,0,0,0
run sample 0 '' -pattern_type plain -sampler_terms zero -sampler_output s.h5 -sampler_reference none
run fit 65 'Cannot open nosuch.h5 \(-fit_input\)' -fit_input nosuch.h5
run eval 65 'Cannot open nosuch.json \(-material\)' -material nosuch.json -strain 0,0,0,0,0,0
run calibrate 65 'nosuch.csv' -pattern_type plain -calibrate_target nosuch.csv
run cloth 65 'nosuch.json' -cloth_material nosuch.json -cloth_test tensile -cloth_plot 0

# a misspelt option is an error in every program, named, before any work; in an options file too
misspelt() { # program option args...
  local p=$1 o=$2 st
  shift 2
  (cd "$T" && "$B/hylc-$p" "$o" 1 "$@" >"$p.out" 2>"$p.err")
  st=$?
  [ $st -ne 0 ] || { cat "$T/$p.out" "$T/$p.err"; die "hylc-$p accepts the misspelt $o"; }
  grep -q -- "^hylc: error: Unknown option(s): $o " "$T/$p.err" || { cat "$T/$p.err"; die "hylc-$p does not name the misspelt $o"; }
  ! grep -q 'wrote' "$T/$p.out" || die "hylc-$p did its work before refusing $o"
}
misspelt pattern -pattern_typ -pattern_type plain -pattern_output p.pyp
misspelt solve -strian -pattern_type plain -strain 0.01,0,0,0,0,0
misspelt solve -micro_rtoll -pattern_type plain -strain 0.01,0,0,0,0,0
misspelt sample -sampler_outptu -pattern_type plain -sampler_terms zero -sampler_output s2.h5
misspelt fit -fit_jsn -fit_input nosuch.h5
: >"$T/empty.json" # exists: the files are checked before the options, the material read after
misspelt eval -eval_jsn -material empty.json -strain 0,0,0,0,0,0
misspelt calibrate -calibrate_paramz -pattern_type plain -calibrate_target nosuch.csv
misspelt cloth -cloth_tset -cloth_material empty.json -cloth_test tensile
# a solver's -..._converged_reason is read when its solve ends, after the check: accepted
(cd "$T" && "$B/hylc-solve" -pattern_type plain -strain 0.01,0,0,0,0,0 -micro_snes_converged_reason >cr.out 2>&1) || { cat "$T/cr.out"; die "hylc-solve refuses -micro_snes_converged_reason"; }
# one of another stage's names misspelt, in the study's file: still an error
sed 's/^sampler_family:/sampler_familly:/' config/satin.yaml >"$T/typo.yaml"
(cd "$T" && "$B/hylc-fit" -options_file typo.yaml -fit_input nosuch.h5 >fit.out 2>fit.err) && die "hylc-fit accepts sampler_familly"
line=$(grep -n '^sampler_familly:' "$T/typo.yaml" | cut -d: -f1)
grep -q "^hylc: error: typo.yaml:$line: Unknown option(s): -sampler_familly " "$T/fit.err" || { cat "$T/fit.err"; die "hylc-fit does not name sampler_familly with its file and line"; }

# the satin study's file in the fit and the evaluation (as in issue 33)
(cd "$T" && "$B/hylc-fit" -options_file "$OLDPWD/config/satin.yaml" -fit_input nosuch.h5 >fit.out 2>fit.err)
grep -q '^hylc: error: Cannot open nosuch.h5' "$T/fit.err" || { cat "$T/fit.err"; die "hylc-fit -options_file config/satin.yaml"; }
(cd "$T" && "$B/hylc-eval" -options_file "$OLDPWD/config/satin.yaml" -material nosuch.json -strain 0,0,0,0,0,0 >eval.out 2>eval.err)
grep -q '^hylc: error: Cannot open nosuch.json' "$T/eval.err" || { cat "$T/eval.err"; die "hylc-eval -options_file config/satin.yaml"; }
exit 0
