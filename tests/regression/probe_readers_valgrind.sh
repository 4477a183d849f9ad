#!/usr/bin/env bash
# Issue 28 under valgrind (--leak-check=full --errors-for-leak-kinds=definite, Open MPI's start-up
# suppressed by tests/valgrind.supp): the reproducers of items 1, 3, 5 and 6 read no memory out of bounds
# and leak nothing on their error exits, and the long-line inputs are read cleanly:
# - hylc-calibrate on a CSV of 1e300 strains (the base row stayed -1 and R->z - 6 was read) and on a
#   data.txt of nan strains;
# - hylc-calibrate on samples files with /samples/psi one row short and a string status (the read buffers
#   of h5samples.c leaked);
# - hylc-eval on a string /strain and a chunked /strain declared 1e9 x 6, and on a text input whose
#   comment is 100 000 characters long;
# - hylc-calibrate on a CSV with an 8,191-character comment, refused at an empty field after it.
set -u
here=$(cd "$(dirname "$0")" && pwd)
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
command -v valgrind >/dev/null || { echo "valgrind not installed"; exit 77; }
py=/usr/bin/python3
[ -x $py ] && $py -c 'import h5py' 2>/dev/null || { echo "python3 h5py not installed: skipped"; exit 77; }
vg=(valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite --num-callers=50 --suppressions="$here/../valgrind.supp")
B=$HYLC_BIN
n=0
run() { # expected-exit(0|fail) message-regex command...
  local want=$1 re=$2 st; shift 2
  "${vg[@]}" "$@" >out.txt 2>&1
  st=$?
  n=$((n + 1))
  [ $st -eq 99 ] && { cat out.txt; die "valgrind: a memory error or a definite leak: $*"; }
  [ $st -ge 128 ] && { cat out.txt; die "killed by a signal ($st): $*"; }
  if [ "$want" = 0 ]; then [ $st -eq 0 ] || { cat out.txt; die "failed (exit $st): $*"; }; else [ $st -ne 0 ] || { cat out.txt; die "accepted: $*"; }; fi
  grep -Eq -- "$re" out.txt || { cat out.txt; die "output lacks /$re/: $*"; }
  return 0
}
printf 'sx,sa,sy,II00,II01,II11,psi\n1e300,0,0,0,0,0,1\n2e300,0,0,0,0,0,2\n' >huge.csv
printf 'nan 0 0 0 0 0 1\nnan 0 0 0 0 0 2\n' >nan.txt
"$B/hylc-sample" -pattern_type plain -sampler_terms zero,sx -sampler_n1 4 -yarn_kc 50 -sampler_output s.h5 >sample.txt 2>&1 || { cat sample.txt; die "hylc-sample failed"; }
$py - <<'PY' || die "building the HDF5 files"
import h5py, shutil, numpy as np
def edit(name, f):
    shutil.copy("s.h5", name)
    with h5py.File(name, "r+") as h:
        f(h["samples"])
def short(g):
    d = g["psi"][:-1]; del g["psi"]; g.create_dataset("psi", data=d)
edit("short.h5", short)
def strstatus(g):
    del g["status"]; g.create_dataset("status", data=np.array([b"ok"] * 5))
edit("strstatus.h5", strstatus)
with h5py.File("str.h5", "w") as f: f.create_dataset("strain", data=np.array([b"0.1"] * 6).reshape(1, 6))
with h5py.File("big.h5", "w") as f: f.create_dataset("strain", shape=(10**9, 6), dtype="f8", chunks=(100, 6))
PY
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >m.json
{ printf '#'; head -c 100000 /dev/zero | tr '\0' x; printf '0.1 0 0 0 0 0\n0.2 0 0 0 0 0\n'; } >long.txt
{ printf 'sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,0.0121\n#'; head -c 8190 /dev/zero | tr '\0' x; printf '0.3,0,0,0,0,0,500\n0.02,0,0,0,0,0,0.0122\n0.1,,0,0,0,0,1\n'; } >long.csv
C=("$B/hylc-calibrate" -pattern_type plain -calibrate_reference none -yarn_kc 50)
run fail 'huge.csv:2: sx = 1e\+300' "${C[@]}" -calibrate_target huge.csv
run fail "nan.txt:1: column 1 \(sx\): 'nan' is not a finite number" "${C[@]}" -calibrate_target nan.txt
run fail 'short.h5 \(-calibrate_target\): dataset /samples/psi has shape \(4\), expected \(5\)' "${C[@]}" -calibrate_target short.h5
run fail 'strstatus.h5 \(-calibrate_target\): dataset /samples/status holds strings' "${C[@]}" -calibrate_target strstatus.h5
run fail 'str.h5 \(-eval_input\): dataset /strain holds strings' "$B/hylc-eval" -material m.json -eval_input str.h5 -eval_output o.txt
run fail 'big.h5 \(-eval_input\): dataset /strain declares 6000000000 values' "$B/hylc-eval" -material m.json -eval_input big.h5 -eval_output o.txt
run 0 'evaluated 1 strains from long.txt' "$B/hylc-eval" -material m.json -eval_input long.txt -eval_output o.txt
run fail 'long.csv:5: field 2: empty field' "${C[@]}" -calibrate_target long.csv
echo "issue 28 readers under valgrind: $n runs clean"
exit 0
