#!/usr/bin/env bash
# hylc-sample end to end: a quick run on 1 and 2 ranks gives bitwise the same HDF5 data; a run killed
# with SIGKILL and resumed loses and recomputes nothing and gives the same data; non-converged samples
# are recorded with their status; bad options are refused clearly.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || { echo "h5dump (hdf5-tools) not installed"; exit 77; }
common=(-pattern_type plain -yarn_kc 50 -sampler_terms zero,sx,sa,sx-sa -sampler_n1 5 -sampler_n2 3 -sampler_progress 0.5)
# 1 + 5 + 5 + 9 = 20 samples
data() { h5dump -d /samples/psi -d /samples/strain -d /samples/status -d /samples/iterations "$1" | grep -v -e HDF5 -e '^}' ; }

mkdir -p raw
$tool "${common[@]}" -sampler_output one.h5 -sampler_export_raw raw >one.txt 2>&1 || { cat one.txt; die "1-rank run failed"; }
[ "$(wc -l <raw/data.txt)" = 19 ] || die "data.txt should have 19 rows (the zero sample is not a row): $(wc -l <raw/data.txt)"
[ "$(awk 'NF != 7' raw/data.txt | wc -l)" = 0 ] || die "data.txt rows need 7 columns"
grep -q '^area [0-9.e+-]*$' raw/info.txt && grep -q '^density [0-9.e+-]*$' raw/info.txt || { cat raw/info.txt; die "info.txt"; }
grep -q 'wrote one.h5: 20 samples' one.txt || { cat one.txt; die "1-rank summary"; }
grep -q '^\[sampler\] .*samples/s, ETA' one.txt || { cat one.txt; die "no progress line"; }
$MPIEXEC -n 2 $tool "${common[@]}" -sampler_output two.h5 >two.txt 2>&1 || { cat two.txt; die "2-rank run failed"; }
[ "$(data one.h5)" = "$(data two.h5)" ] || die "1 and 2 ranks give different data"
$MPIEXEC -n 3 $tool "${common[@]}" -sampler_output three.h5 >three.txt 2>&1 || { cat three.txt; die "3-rank run failed"; }
[ "$(data one.h5)" = "$(data three.h5)" ] || die "1 and 3 ranks give different data"
h5dump -d /samples/status one.h5 | grep -q '(0): 0' || die "status dataset"

# killed with SIGKILL, then resumed (1 and 2 ranks): the same data, finished samples not recomputed; a
# resume with a setting that changes results is refused before any solve, naming it, journal untouched
long=(-pattern_type plain -yarn_kc 50 -sampler_terms sx,sa -sampler_n1 40 -sampler_progress 0.5 -sampler_batch 1)
$tool "${long[@]}" -sampler_output ref.h5 >ref.txt 2>&1 || { cat ref.txt; die "reference run failed"; }
for np in 1 2; do
  k=kill$np.h5
  rm -f $k $k.journal
  $MPIEXEC -n $np $tool "${long[@]}" -sampler_output $k >kill1.txt 2>&1 &
  pid=$!
  s0=
  for i in $(seq 1 1000); do
    if [ -f $k.journal ]; then
      s=$(stat -c %s $k.journal)
      [ -z "$s0" ] && [ "$s" -gt 0 ] && s0=$s
      [ -n "$s0" ] && [ "$s" -ge $((s0 + 3 * 172)) ] && break
    fi
    sleep 0.005
  done
  kill -9 $pid 2>/dev/null; pkill -9 -f "hylc-sample.*$k" 2>/dev/null; wait $pid 2>/dev/null
  jsize=$(stat -c %s $k.journal)
  # a setting that changes results: refused before any solve, naming the option and both values
  $MPIEXEC -n $np $tool "${long[@]}" -sampler_output $k -sampler_resume -micro_rtol 1e-3 >bad.txt 2>&1 && die "$np ranks: resume with -micro_rtol added accepted"
  grep -q "option -micro_rtol added ('1e-3')" bad.txt || { cat bad.txt; die "$np ranks: the refusal does not name -micro_rtol"; }
  grep -q '\[sampler\]' bad.txt && { cat bad.txt; die "$np ranks: work started before the refusal"; }
  $tool "${long[@]}" -sampler_n1 6 -sampler_output $k -sampler_resume >bad.txt 2>&1 && die "resume of a different plan accepted"
  grep -q "option -sampler_n1 changed from '40' to '6'" bad.txt || { cat bad.txt; die "unclear message for a changed option"; }
  $tool "${long[@]}" -sampler_output $k >bad.txt 2>&1 && die "a rerun without -sampler_resume replaced a partial journal"
  grep -q "sampler_resume.*sampler_overwrite" bad.txt || { cat bad.txt; die "the refusal of a rerun does not say how to continue or start over"; }
  [ "$(stat -c %s $k.journal)" = "$jsize" ] || die "a refused run changed the journal"
  # progress options, the batch size and output-only options do not change results: accepted
  $MPIEXEC -n $np $tool "${long[@]}" -sampler_output $k -sampler_resume -sampler_progress 3 -sampler_batch 3 >kill2.txt 2>&1 || { cat kill2.txt; die "$np ranks: resume failed"; }
  done_before=$(sed -n 's/.*; \([0-9]*\) already done.*/\1/p' kill2.txt)
  [ -n "$done_before" ] || { cat kill2.txt; die "resume did not report the finished samples"; }
  [ "$done_before" -gt 0 ] && [ "$done_before" -lt 80 ] || { cat kill2.txt; die "$np ranks: the kill did not interrupt the run ($done_before of 80 done)"; }
  [ "$(data ref.h5)" = "$(data $k)" ] || die "$np ranks: resumed run gives different data"
  echo "$np ranks: resumed after $done_before of 80 finished samples"
done
# the batch size does not change results (it is left out of the run identity)
$MPIEXEC -n 2 $tool "${long[@]}" -sampler_batch 7 -sampler_output batch7.h5 >b7.txt 2>&1 || { cat b7.txt; die "batch 7 run failed"; }
[ "$(data ref.h5)" = "$(data batch7.h5)" ] || die "-sampler_batch 7 gives different data"
[ "$(h5dump -a /provenance/digest ref.h5 | grep '(0)')" = "$(h5dump -a /provenance/digest batch7.h5 | grep '(0)')" ] || die "-sampler_batch changed the digest"

# samples that do not converge are recorded with their status, never dropped
# (with an option of the ordering, read at set-up: accepted, not refused as unknown)
$tool "${common[@]}" -sampler_reference none -sampler_terms sx -micro_snes_max_it 1 -hylc_metis_nseps 2 -sampler_output cap.h5 >cap.txt 2>&1 || { cat cap.txt; die "capped run failed"; }
grep -q 'wrote cap.h5: 5 samples' cap.txt || { cat cap.txt; die "capped samples dropped"; }
h5dump -d /samples/status cap.h5 | grep -q '1, 1\|(0): 1' || { h5dump -d /samples/status cap.h5; die "iteration_cap status not recorded"; }

# bad input is refused before any work (no journal is created), with a clear message
refuse() { # message-regex args...
  local re=$1; shift
  rm -f refused.h5.journal
  $tool -pattern_type plain -sampler_output refused.h5 "$@" >bad.txt 2>&1 && die "accepted: $*"
  grep -Eq -- "$re" bad.txt || { cat bad.txt; die "unclear message for: $*"; }
  [ ! -e refused.h5.journal ] || die "work was started for: $*"
}
refuse "unknown term 'shear'" -sampler_terms sx,shear
refuse "sampler_n1 and -sampler_n2 must be in 1..1024" -sampler_n1 0
refuse "sampler_n1 and -sampler_n2 must be in 1..1024" -sampler_n2 -3
refuse "needs two values min,max with min <= max" -sampler_range_sa 0.5,-0.5
refuse "Cannot open missing.pyp \(-pattern_file\)" -pattern_type file -pattern_file missing.pyp
refuse "Cannot write /nonexistent-dir/out.h5 \(-sampler_output\): directory /nonexistent-dir does not exist" -sampler_output /nonexistent-dir/out.h5
refuse "Unknown option\\(s\\): -sampler_outptu" -sampler_outptu x.h5
refuse "sampler_batch must be at least 1" -sampler_batch 0
refuse "option -hylc_metis_nseps: 0 is not >= 1" -hylc_metis_nseps 0
# -help documents every option of the job and does no work
rm -f samples.h5 samples.h5.journal
$tool -pattern_type plain -help >help.txt 2>&1 || { tail help.txt; die "-help failed"; }
for opt in -sampler_output -sampler_resume -sampler_overwrite -sampler_start -sampler_terms -sampler_n1 -sampler_n2 -sampler_family -sampler_range_sx -sampler_batch -sampler_progress -sampler_export_raw -sampler_reference -reference_output -reference_etol -micro_rtol -micro_snes_max_it -micro_saddle_test -hylc_metis_nseps -periodic_slide -yarn_kc -pattern_file; do
  grep -q -- "$opt" help.txt || die "-help does not document $opt"
done
[ ! -e samples.h5.journal ] || die "-help started the job"
# -help only reads options: the solver's own (tile, midsurface, SNES, factorization) without a pattern
# (a missing -pattern_file is not opened), each hylc option listed once and naming its setter
$tool -pattern_type file -pattern_file missing.pyp -help >help2.txt 2>&1 || { tail -3 help2.txt; die "-help opened the pattern (set up the solver)"; }
for opt in -periodic_slide -periodic_margin -macro_phi -micro_snes_max_it -micro_ksp_type -micro_factor_pc_factor_mat_solver_type -micro_factor_pc_factor_mat_ordering_type -micro_alpha_start; do
  grep -q -- "^ *$opt[ :]" help2.txt || die "-help without a pattern does not document $opt"
done
dups=$(grep -oE '^ +-(sampler|reference|pattern|yarn|micro|periodic|macro)_[a-zA-Z0-9_]+' help2.txt | grep -vE -- '-micro_(snes|ksp|pc|factor_pc)_' | sort | uniq -d)
[ -z "$dups" ] || die "-help lists these options more than once: $dups"
nosetter=$(grep -E '^ +-(sampler|reference|pattern|yarn|micro|periodic|macro)_' help2.txt | grep -vE -- '^ +-micro_(snes|ksp|pc|factor_pc)_' | grep -vE '\(Hylc[A-Za-z]+\) *$' || true)
[ -z "$nosetter" ] || die "-help lines without a Hylc setter: $nosetter"
exit 0
