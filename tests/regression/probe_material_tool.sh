#!/usr/bin/env bash
# tools/hylc-material under faults and stale inputs:
# - SIGTERM, SIGINT or SIGHUP to the tool (timeout's SIGTERM) left mpiexec and every rank running; now
#   each stops the running stage, mpiexec and every rank, and the tool exits 128 + the signal; a rerun
#   resumes. -np beyond the cores is warned about (a mistyped -np 1000 ran 500 ranks on 2 cores).
# - "current, no sampling" kept a stale table when the pattern file was named quoted ("p.pyp", valid YAML)
#   or with a blank, or when options came from PETSC_OPTIONS: the freshness key is now made of what
#   hylc-sample reads (the pattern as hylc-pattern loads it with the same options, PETSC_OPTIONS).
# - an options file that is the fit's output was found only after the whole sampling; now refused before
#   any work. A study refused by hylc-pattern or hylc-sample left the -o folder behind; now it does not.
#   A failed fit left fit.txt.tmp; now its output is fit.txt.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
command -v h5dump >/dev/null || { echo "h5dump (hdf5-tools) not installed"; exit 77; }
tool=$HYLC_ROOT/tools/hylc-material
export HYLC_BIN MPIEXEC
B=$HYLC_BIN
# a small plan (57 samples) whose fit is refused (too few samples): the sampling stage is what is tested
printf 'pattern_type: plain\npattern_radius: 1.0e-3\nyarn_kc: 50\nsampler_family: woven\nsampler_n1: 4\nsampler_n2: 2\n' >tiny.yaml
# a longer one (276 samples) to signal during its sampling
printf 'pattern_type: plain\npattern_radius: 1.0e-3\nyarn_kc: 50\nsampler_family: woven\nsampler_n1: 10\nsampler_n2: 5\n' >long.yaml
tree() { local c; for c in $(ps -o pid= --ppid "$1" 2>/dev/null); do echo "$c"; tree "$c"; done; }

# 1. signals: the tool and every process it started end; exit status 128 + the signal
n=0
for sig in TERM INT HUP; do
  n=$((n + 1))
  # job control on: a background job of a script otherwise starts with SIGINT ignored (and a shell cannot
  # trap a signal ignored on entry), unlike the tool run from a terminal
  set -m
  "$tool" -o s$sig -no_plots long.yaml >s$sig.txt 2>&1 &
  pid=$!
  set +m
  for _ in $(seq 600); do [ "$(stat -c %s s$sig/samples.h5.journal 2>/dev/null || echo 0)" -gt 2000 ] && break; sleep 0.05; done
  kids=$(tree $pid)
  [ -n "$kids" ] || { cat s$sig.txt; die "SIG$sig: the tool had no children when signalled"; }
  kill -$sig $pid
  wait $pid
  st=$?
  sleep 0.5
  left=""
  for p in $kids; do kill -0 "$p" 2>/dev/null && left="$left $p"; done
  if [ -n "$left" ]; then
    ps -o pid,args -p "$(echo $left | tr ' ' ,)"
    kill -KILL $left 2>/dev/null
    die "SIG$sig: processes of the tool still run after it exited:$left"
  fi
  case $sig in TERM) want=143 ;; INT) want=130 ;; HUP) want=129 ;; esac
  [ $st = $want ] || { cat s$sig.txt; die "SIG$sig: exit status $st, expected $want"; }
  grep -q "^hylc-material: stopped by SIG$sig (the running stage and its processes ended); run it again to resume" s$sig.txt || { cat s$sig.txt; die "SIG$sig: the message"; }
  [ -f s$sig/samples.h5.journal ] || die "SIG$sig: no journal kept"
done
# the stopped run resumes
"$tool" -o sTERM -no_plots long.yaml >r.txt 2>&1
grep -q 'samples: resuming sTERM/samples.h5' r.txt && grep -Eq 'on 2 ranks; [1-9][0-9]* already done' r.txt || { cat r.txt; die "the stopped run did not resume"; }
grep -q 'wrote sTERM/samples.h5: 276 samples, 0 not converged' r.txt || { cat r.txt; die "the resumed run's summary"; }
# more ranks than cores: warned (then the study is refused: nothing runs)
cores=$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)
"$tool" -np $((cores + 3)) -o w -no_plots tiny.yaml -yarn_kc x >w.txt 2>&1 && { cat w.txt; die "-yarn_kc x accepted"; }
grep -q "^hylc-material: warning: -np $((cores + 3)) exceeds the $cores cores of this machine" w.txt || { cat w.txt; die "no warning for -np beyond the cores"; }

# 2. the freshness key: the pattern as hylc-sample reads it
$B/hylc-pattern -pattern_type plain -pattern_radius 1e-3 -pattern_output "p q.pyp" >/dev/null || die "hylc-pattern"
cp "p q.pyp" p.pyp
for name in quoted blank env; do
  case $name in
    quoted) printf 'pattern_file: "p.pyp"\nyarn_kc: 50\nsampler_family: woven\nsampler_n1: 4\nsampler_n2: 2\n' >k.yaml; pf=p.pyp ;;
    blank) printf "pattern_file: 'p q.pyp'\nyarn_kc: 50\nsampler_family: woven\nsampler_n1: 4\nsampler_n2: 2\n" >k.yaml; pf="p q.pyp" ;;
    env) printf 'pattern_file: p.pyp\nsampler_family: woven\nsampler_n1: 4\nsampler_n2: 2\n' >k.yaml; pf=p.pyp ;;
  esac
  rm -rf k
  PETSC_OPTIONS="${PETSC_OPTIONS:-} -yarn_kc 50" "$tool" -o k -no_plots k.yaml >k1.txt 2>&1
  grep -q 'wrote k/samples.h5: 57 samples' k1.txt || { cat k1.txt; die "$name: the first run"; }
  PETSC_OPTIONS="${PETSC_OPTIONS:-} -yarn_kc 50" "$tool" -o k -no_plots k.yaml >k2.txt 2>&1
  grep -q 'is current (identity [0-9a-f]\{64\}): no sampling' k2.txt || { cat k2.txt; die "$name: the rerun was not current"; }
  if [ $name = env ]; then # other options in PETSC_OPTIONS
    PETSC_OPTIONS="${PETSC_OPTIONS:-} -yarn_kc 60" "$tool" -o k -no_plots k.yaml >k3.txt 2>&1
  else # the same file name, another pattern in it
    $B/hylc-pattern -pattern_type plain -pattern_radius 1.1e-3 -pattern_output "$pf" >/dev/null || die "hylc-pattern"
    PETSC_OPTIONS="${PETSC_OPTIONS:-} -yarn_kc 50" "$tool" -o k -no_plots k.yaml >k3.txt 2>&1
    cp "p q.pyp" p.pyp
    $B/hylc-pattern -pattern_type plain -pattern_radius 1e-3 -pattern_output "p q.pyp" >/dev/null
  fi
  grep -q 'is current' k3.txt && { cat k3.txt; die "$name: a changed input was taken as current"; }
  grep -q 'computed with other settings, or the run failed (above); -overwrite starts over' k3.txt || { cat k3.txt; die "$name: the changed input did not reach hylc-sample's identity check"; }
done

# 3. before any work: an options file that is an output; a refused study leaves no folder
mkdir -p c
cp tiny.yaml c/model.json
"$tool" -o c -no_plots c/model.json >c.txt 2>&1 && { cat c.txt; die "the study file as the fit's output accepted"; }
grep -q '^hylc-material: error: the options file c/model.json is this study.s output c/model.json' c.txt || { cat c.txt; die "c: the message"; }
[ ! -e c/samples.h5.journal ] && [ ! -e c/.hylc-material ] || die "c: work was done before the refusal"
"$tool" -o new/dir -no_plots tiny.yaml -pattern_radiuss 1 >n.txt 2>&1 && { cat n.txt; die "a misspelt option accepted"; }
grep -q 'pattern_radiuss' n.txt || { cat n.txt; die "n: the misspelt option is not named"; }
[ ! -e new ] || die "a study refused by hylc-pattern left the folder new/"
"$tool" -o new/dir -no_plots tiny.yaml -sampler_n1 -3 >n.txt 2>&1 && { cat n.txt; die "-sampler_n1 -3 accepted"; }
grep -q 'sampler_n1' n.txt || { cat n.txt; die "n: -sampler_n1 is not named"; }
[ ! -e new ] || { ls -R new; die "a study refused by hylc-sample left the folder new/"; }
# a failed fit: its output is fit.txt, no fit.txt.tmp
"$tool" -o f -no_plots tiny.yaml >f.txt 2>&1 && { cat f.txt; die "the fit of 57 samples was accepted"; }
grep -q '^hylc-material: error: the fit failed (its output: f/fit.txt)' f.txt || { cat f.txt; die "f: the message"; }
[ ! -e f/fit.txt.tmp ] && grep -q 'usable samples' f/fit.txt || die "f: fit.txt.tmp left, or fit.txt without the fit's error"
exit 0
