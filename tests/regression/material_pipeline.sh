#!/usr/bin/env bash
# tools/hylc-material on a tiny plan (a generated plain weave, 10 samples per 1D term, 5 x 5 grids) on 2
# ranks (issue 33): the reference state, samples, fit (its family from the samples' provenance), HDF5 and
# JSON tables, plots and report.md; rerun, it samples and fits nothing; with other options the run
# identity refuses the resume; killed during the sampling and rerun, it resumes and ends with the same
# table, byte for byte, as the run that was not interrupted.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || { echo "h5dump (hdf5-tools) not installed"; exit 77; }
tool=$HYLC_ROOT/tools/hylc-material
export HYLC_BIN MPIEXEC
printf 'pattern_type: plain\npattern_radius: 1.0e-3\nyarn_kc: 50\nsampler_family: woven\nsampler_n1: 10\nsampler_n2: 5\n' >tiny.yaml

# 1. the whole pipeline
$tool -o a tiny.yaml >a.txt 2>&1 || { cat a.txt; die "the pipeline failed"; }
for f in reference.pyp samples.h5 model.h5 model.json report.md fit.txt; do [ -s a/$f ] || die "a/$f missing"; done
head -n 1 a/reference.pyp | grep -q 'hylc state: reference$' || die "a/reference.pyp is not a reference state"
grep -q 'wrote a/samples.h5: 276 samples, 0 not converged' a.txt || { cat a.txt; die "the sampling summary"; }
grep -q 'family: woven (the samples' a.txt || { cat a.txt; die "the fit's family"; }
if /usr/bin/python3 -c 'import h5py, matplotlib' 2>/dev/null; then
  for t in sx sa sy II00 II11 sx-sa sx-sy sa-II11 sy-II11; do [ -s a/plots/$t.png ] || die "a/plots/$t.png missing"; done
  for s in '# Material table: a' '## Fit' '| sx | 17 knots | 10 |' '| sx-sy | ' '![sx-sa](plots/sx-sa.png)' '## Cost' \
    '- samples: 276 of the plan, 276 computed, 276 converged' '## Provenance' '- run identity `digest`: ' '-sampler_family woven'; do
    grep -qF -- "$s" a/report.md || { cat a/report.md; die "report.md lacks '$s'"; }
  done
  grep -q '^- family: woven (the samples' a/report.md || die "report.md lacks the family"
fi
# the JSON is the one hylc-fit writes from these samples
$HYLC_BIN/hylc-fit -fit_input a/samples.h5 -fit_json check.json >check.txt 2>&1 || { cat check.txt; die "hylc-fit failed"; }
cmp -s check.json a/model.json || die "a/model.json differs from hylc-fit's table of a/samples.h5"

# 2. rerun: nothing sampled, nothing fitted
before=$(stat -c '%Y %s' a/samples.h5 a/model.json a/model.h5)
$tool -o a tiny.yaml >a2.txt 2>&1 || { cat a2.txt; die "the rerun failed"; }
grep -q 'is current (identity [0-9a-f]\{64\}): no sampling' a2.txt || { cat a2.txt; die "the rerun sampled"; }
grep -q 'are current: no fit' a2.txt || { cat a2.txt; die "the rerun fitted"; }
! grep -q '^\[sampler\]' a2.txt || die "the rerun ran hylc-sample"
[ "$(stat -c '%Y %s' a/samples.h5 a/model.json a/model.h5)" = "$before" ] || die "the rerun rewrote the tables"

# 3. other options: the run identity refuses to resume the old samples; nothing is replaced
$tool -o a tiny.yaml -yarn_kc 60 >a3.txt 2>&1 && { cat a3.txt; die "a resume with other settings was accepted"; }
grep -q 'yarn_kc' a3.txt || { cat a3.txt; die "the refusal does not name -yarn_kc"; }
grep -q 'computed with other settings, or the run failed (above); -overwrite starts over' a3.txt || { cat a3.txt; die "no hint"; }
cmp -s check.json a/model.json || die "a refused run changed a/model.json"

# 4. killed during the sampling (SIGKILL of the whole job), then rerun: the same table
setsid $tool -o b -no_plots tiny.yaml >b1.txt 2>&1 &
pid=$!
for _ in $(seq 600); do [ "$(stat -c %s b/samples.h5.journal 2>/dev/null || echo 0)" -gt 3000 ] && break; sleep 0.05; done
# the job's processes, by id (mpiexec's ranks need not be in its process group), then SIGKILL to all
tree() { local c; for c in $(ps -o pid= --ppid "$1" 2>/dev/null); do echo "$c"; tree "$c"; done; }
pids="$pid $(tree $pid)"
kill -KILL -- -$pid 2>/dev/null
kill -KILL $pids 2>/dev/null
wait $pid 2>/dev/null
for _ in $(seq 100); do ps -o pid= -p "$(echo $pids | tr ' ' ,)" >/dev/null 2>&1 || break; sleep 0.1; done
[ -f b/samples.h5.journal ] || { cat b1.txt; die "the job was killed before its journal existed"; }
[ ! -f b/model.json ] || die "the job ended before it was killed (the plan is too small for this machine)"
$tool -o b -no_plots tiny.yaml >b2.txt 2>&1 || { cat b2.txt; die "the rerun after the kill failed"; }
grep -q 'samples: resuming b/samples.h5' b2.txt || { cat b2.txt; die "the rerun did not resume"; }
grep -Eq 'on 2 ranks; [1-9][0-9]* already done' b2.txt || { cat b2.txt; die "nothing was kept from the killed run"; }
cmp -s a/model.json b/model.json || die "the killed and rerun job gives another table than the uninterrupted one"
cmp -s a/reference.pyp b/reference.pyp || die "the killed and rerun job gives another reference state"
exit 0
