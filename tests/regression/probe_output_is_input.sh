#!/usr/bin/env bash
# Probe item 4.5 (issue 12, sampler part): -sampler_output (or -reference_output, or the journal) naming
# the pattern file turned the pattern into an HDF5 file; a rerun without -sampler_resume silently
# replaced an existing samples file and a partial journal. Now each is refused in one line before any
# work, the input is untouched, and the message says how to continue (-sampler_resume) or start over
# (-sampler_overwrite), which then works.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
$HYLC_BIN/hylc-pattern -pattern_type plain -pattern_output in.pyp >/dev/null 2>&1 || die "hylc-pattern failed"
ln -sf in.pyp link.pyp
sum0=$(sha256sum <in.pyp)
args=(-pattern_type file -pattern_file in.pyp -yarn_kc 50 -sampler_terms zero,sx -sampler_n1 2 -sampler_progress 100)
refused() { # regex args...
  local re=$1; shift
  "$tool" "$@" >out.txt 2>&1 && { cat out.txt; die "accepted: $*"; }
  [ "$(grep -c . out.txt)" -le 3 ] || { cat out.txt; die "more than three lines for: $*"; }
  grep -Eq -- "$re" out.txt || { cat out.txt; die "unclear message for: $*"; }
  grep -q '\[sampler\]' out.txt && { cat out.txt; die "work started for: $*"; }
  [ "$(sha256sum <in.pyp)" = "$sum0" ] || die "the input was changed by: $*"
}
refused "Output in.pyp \(-sampler_output\) is the input in.pyp \(-pattern_file\)" "${args[@]}" -sampler_output in.pyp
refused "Output link.pyp \(-sampler_output\) is the input in.pyp \(-pattern_file\)" "${args[@]}" -sampler_output link.pyp
refused "Output in.pyp \(-sampler_output\) is the input" "${args[@]}" -sampler_output in.pyp -sampler_overwrite
cp in.pyp pj.journal
refused "Output pj.journal \(the journal of -sampler_output\) is the input pj.journal \(-pattern_file\)" "${args[@]}" -pattern_file pj.journal -sampler_output pj
cmp -s in.pyp pj.journal || die "the pattern named by the journal path was changed"
refused "Output in.pyp \(-reference_output\) is the input in.pyp \(-pattern_file\)" "${args[@]}" -sampler_output s.h5 -reference_output in.pyp
[ ! -e s.h5.journal ] || die "a refused run left a journal"
# a finished run, rerun without -sampler_resume: refused, saying how to continue or start over
"$tool" "${args[@]}" -sampler_output s.h5 >run.txt 2>&1 || { cat run.txt; die "first run failed"; }
s0=$(sha256sum <s.h5)
refused "Output s.h5 exists: start over with -sampler_overwrite, or continue its run with -sampler_resume" "${args[@]}" -sampler_output s.h5
[ "$(sha256sum <s.h5)" = "$s0" ] || die "the refused rerun changed s.h5"
# a partial journal without its samples file: refused too
mv s.h5 keep.h5
refused "Journal s.h5.journal holds 3 samples of an earlier run: continue it with -sampler_resume, or start over with -sampler_overwrite" "${args[@]}" -sampler_output s.h5
refused "exclude each other" "${args[@]}" -sampler_output s.h5 -sampler_resume -sampler_overwrite
mv keep.h5 s.h5
# resume without a journal but with an output: nothing to continue
mv s.h5.journal keep.journal
refused "output s.h5 exists but its journal s.h5.journal does not" "${args[@]}" -sampler_output s.h5 -sampler_resume
mv keep.journal s.h5.journal
# the ways out work
"$tool" "${args[@]}" -sampler_output s.h5 -sampler_resume >run.txt 2>&1 || { cat run.txt; die "-sampler_resume failed"; }
grep -q '; 3 already done' run.txt || { cat run.txt; die "-sampler_resume recomputed"; }
"$tool" "${args[@]}" -sampler_output s.h5 -sampler_overwrite >run.txt 2>&1 || { cat run.txt; die "-sampler_overwrite failed"; }
grep -q '; 0 already done' run.txt || { cat run.txt; die "-sampler_overwrite did not start over"; }
[ -z "$(ls | grep -E '\.tmp')" ] || die "temporary files left: $(ls | grep tmp)"
exit 0
