#!/usr/bin/env bash
# Malformed material files: each must be refused by hylc-eval with a one-line message naming the file
# (and, for JSON, the line and the key path) and a non-zero exit, never a crash. With HYLC_VALGRIND=1
# (material_malformed_valgrind.sh) every case runs under valgrind memcheck, which must report no error
# and no definite leak (the error exits free what they allocated).
set -u
here=$(cd "$(dirname "$0")" && pwd)
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-eval
vg=()
if [ "${HYLC_VALGRIND:-0}" = 1 ]; then
  command -v valgrind >/dev/null || { echo "valgrind not installed"; exit 77; }
  # definite leaks are errors too; Open MPI's own allocations in MPI_Init/MPI_Finalize are suppressed
  vg=(valgrind -q --error-exitcode=99 --track-origins=no --leak-check=full --errors-for-leak-kinds=definite
      --num-callers=50 --suppressions="$here/../valgrind.supp")
fi
die() { echo "FAIL: $*"; exit 1; }

cat > good.json <<'JSON'
{
  "density": 0.3,
  "strain scale": [
    0.8,
    0.75,
    0.8,
    200.0,
    230.0
  ],
  "strain shift": [1, 0, 1, 0, 0],
  "coeffs": {
    "const": 0.05,
    "1D": [
      {
        "k": 0,
        "t": [-0.5, 0.0, 0.5],
        "p": [0.1, 0.0, 0.2],
        "m": [-0.3, 0.0, 0.5]
      }
    ],
    "2D": [
      {
        "k0": 0,
        "k1": 3,
        "tu": [0.0, 0.5],
        "tv": [-1.0, 0.0, 1.0],
        "p": [0, 0, 0, 0, 0, 0.1],
        "mu": [0, 0, 0, 0, 0, 0],
        "mv": [0, 0, 0, 0, 0, 0],
        "muv": [0, 0, 0, 0, 0, 0]
      }
    ]
  }
}
JSON
"${vg[@]}" $tool -material good.json -strain 0.1,0,0,10,0,0 >out.txt 2>&1 || { cat out.txt; die "good.json refused"; }

n=0
case_() { # name message-regex (file content on stdin)
  local name=$1 want=$2 st
  cat > "$name"
  n=$((n + 1))
  "${vg[@]}" $tool -material "$name" -strain 0,0,0,0,0,0 >err.txt 2>&1
  st=$?
  [ $st -eq 99 ] && { cat err.txt; die "$name: valgrind reported a memory error or a definite leak"; }
  [ $st -eq 0 ] && { cat err.txt; die "$name: accepted"; }
  [ $st -gt 128 ] && { cat err.txt; die "$name: crashed (exit $st)"; }
  grep -Eq -- "$want" err.txt || { cat err.txt; die "$name: unclear message (expected /$want/)"; }
  grep -q 'PETSC ERROR' err.txt && { cat err.txt; die "$name: traceback instead of a one-line message"; }
  return 0
}
sub() { sed "$1" good.json; } # good.json edited

case_ empty.json 'empty.json: empty file' </dev/null
head -c 300 good.json | case_ truncated.json 'truncated.json:2[0-9]: (end of file|unexpected end)'
sub 's/"const": 0.05,/"const": 0.05/' | case_ comma.json "comma.json:14: expected ',' or '}' in the object opened at line 12"
sub 's/"p": \[0.1, 0.0, 0.2\]/"p": [0.1, 0.0]/' | case_ count.json 'count.json:18: coeffs.1D\[0\].p: expected 3 numbers \(one per knot\), got 2'
sub 's/"muv": \[0, 0, 0, 0, 0, 0\]/"muv": [0, 0, 0, 0, 0]/' | case_ count2.json 'count2.json:33: coeffs.2D\[0\].muv: expected 6 numbers \(len\(tu\) \* len\(tv\) = 2 \* 3\), got 5'
sub 's/"t": \[-0.5, 0.0, 0.5\]/"t": [-0.5, 0.5, 0.0]/' | case_ knots.json 'knots.json:17: coeffs.1D\[0\].t\[2\]: knots must be strictly increasing'
sub 's/"const"/"constant"/' | case_ key.json 'key.json:12: coeffs: unknown key "constant"'
sub 's/"k1": 3/"k1": 0/' | case_ pair.json 'pair.json:24: coeffs.2D\[0\].k1: expected an integer in 1..4'
sub 's/"k0": 0,/"k0": 2, "k1": 2,/' | case_ dup.json 'dup.json:25: duplicate key "k1" \(also at line 24\)'
sub 's/0.75,/Infinity,/' | case_ inf.json 'inf.json:5: expected a value'
sub 's/"density": 0.3/"density": "0.3"/' | case_ type.json 'type.json:2: density: expected a number, got a string'
sub 's/"ext"//; s/"k": 0,/"k": 0, "ext": 7,/' | case_ ext.json 'ext.json:15: coeffs.1D\[0\].ext: expected an integer in 0..2'
printf '{"density": 0.3,\0 "x": 1}' | case_ nul.json 'nul.json: contains a NUL byte at offset 17'
printf '\211HDF\r\n\032\n\0\0\0\0\0\0\0\0' | case_ trunc.h5 'trunc.h5: cannot open as HDF5'
head -c 2000 /dev/urandom | tr -d '\000' | sed '1s/^/x/' | case_ random.json 'random.json:[0-9]+: expected a value'
case_ deep.json 'nesting deeper than 64' < <(printf '{"density": '; for i in $(seq 100); do printf '['; done; for i in $(seq 100); do printf ']'; done; printf '}')
echo "$n malformed files refused"
exit 0
