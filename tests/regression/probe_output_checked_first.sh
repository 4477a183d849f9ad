#!/usr/bin/env bash
# Probe item 4.6 (issue 12, sampler part): output paths were validated only after the work
# (-sampler_output a directory: found after all samples, leaving a .tmp; -sampler_export_raw and
# -reference_output into a missing directory or a directory). Now every output path is checked before
# the first solve (the reference state of a generated pattern included): one line naming the option and
# the path, exit != 0, nothing computed, nothing left behind; on 2 ranks every rank stops with it.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
mkdir -p adir rawdir
touch afile
args=(-pattern_type plain -yarn_kc 50 -sampler_terms zero,sx -sampler_n1 2 -sampler_progress 100)
refused() { # nprocs regex args...
  local np=$1 re=$2; shift 2
  [ -d out.h5.journal ] || rm -f out.h5.journal
  if [ $np = 1 ]; then run=("$tool"); else run=($MPIEXEC -n $np "$tool"); fi
  "${run[@]}" "${args[@]}" "$@" >out.txt 2>&1 && { cat out.txt; die "accepted: $*"; }
  grep -Eq -- "^hylc: error: $re" out.txt || { cat out.txt; die "unclear message for: $*"; }
  [ "$(grep -c '^hylc: error' out.txt)" = 1 ] || { cat out.txt; die "$np ranks: the error is not printed once: $*"; }
  # (on 2 ranks Open MPI's launcher adds its own report of the exit code, not counted)
  [ $np != 1 ] || [ "$(grep -c . out.txt)" -le 3 ] || { cat out.txt; die "more than three lines for: $*"; }
  grep -qi 'sampler\]\|reference state\|relax' out.txt && { cat out.txt; die "work started before the check: $*"; }
  [ -z "$(ls -A adir)$(ls -A rawdir)" ] || die "left behind in adir or rawdir: $(ls -A adir rawdir)"
  [ -z "$(ls | grep -E 'tmp|journal' | grep -v '^out.h5.journal$')" ] || die "left behind: $(ls | grep -E 'tmp|journal')"
  [ ! -f out.h5.journal ] || die "a journal was created for: $*"
}
for np in 1 2; do
  refused $np "Cannot write adir \(-sampler_output\): it is a directory" -sampler_output adir
  refused $np "Cannot write adir/ \(-sampler_output\): it names a directory" -sampler_output adir/
  refused $np "Cannot write missing/out.h5 \(-sampler_output\): directory missing does not exist" -sampler_output missing/out.h5
  refused $np "Cannot write afile/out.h5 \(-sampler_output\): afile is not a directory" -sampler_output afile/out.h5
  refused $np "Cannot write into -sampler_export_raw missing: no such directory" -sampler_output out.h5 -sampler_export_raw missing
  refused $np "Cannot write into -sampler_export_raw afile: not a directory" -sampler_output out.h5 -sampler_export_raw afile
  mkdir -p raw2/data.txt
  refused $np "Cannot write raw2/data.txt \(-sampler_export_raw\): it is a directory" -sampler_output out.h5 -sampler_export_raw raw2
  refused $np "Cannot write missing/ref.pyp \(-reference_output\): directory missing does not exist" -sampler_output out.h5 -reference_output missing/ref.pyp
  refused $np "Cannot write adir \(-reference_output\): it is a directory" -sampler_output out.h5 -reference_output adir
  mkdir -p out.h5.journal
  refused $np "Cannot write out.h5.journal \(the journal of -sampler_output\): it is a directory" -sampler_output out.h5
  rmdir out.h5.journal
done
# and with every path good, the run writes them all
"$tool" "${args[@]}" -sampler_output out.h5 -sampler_export_raw rawdir -reference_output ref.pyp >run.txt 2>&1 || { cat run.txt; die "good run failed"; }
[ -s out.h5 ] && [ -s rawdir/data.txt ] && [ -s rawdir/info.txt ] && [ -s ref.pyp ] || die "outputs missing"
[ -z "$(ls -A . rawdir | grep -E '\.tmp')" ] || die "temporaries left"
exit 0
