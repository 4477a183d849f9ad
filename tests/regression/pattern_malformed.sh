#!/usr/bin/env bash
# Malformed .pyp files: each must be refused with a clear message (naming the file, line and problem)
# and a non-zero exit, never a crash. With HYLC_VALGRIND=1 (see pattern_malformed_valgrind.sh) a
# subset of the cases, one per error path of the reader (valgrind makes each run take seconds), runs
# under valgrind memcheck, which must report no memory error and no definite leak (Open MPI's own
# allocations in MPI_Init/MPI_Finalize are suppressed by tests/valgrind.supp).
set -u
supp=$(cd "$(dirname "$0")/.." && pwd)/valgrind.supp
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-pattern
vg=()
vgcases=""
if [ "${HYLC_VALGRIND:-0}" = 1 ]; then
  command -v valgrind >/dev/null || { echo "valgrind not installed"; exit 77; }
  vg=(valgrind -q --error-exitcode=99 --track-origins=no --num-callers=40 --leak-check=full
      --errors-for-leak-kinds=definite --suppressions="$supp")
  export OMPI_MCA_btl=self
  vgcases=" missing-block repeated-block row-count non-numeric index-range two-outgoing zero-length director-parallel radius-period binary directory missing-file "
fi

# a valid base pattern: one straight yarn of 4 vertices along x
cat > good.pyp <<'PYP'
*pattern # px py radius num_vertedges
0.004 0.002 0.0005 4

*Q # dofs: x y z t
-0.0015 0 0 0
-0.0005 0 0 0
0.0005 0 0 0
0.0015 0 0 0

*E # edges: v0 v1 dx dy
3 0 1 0
0 1 0 0
1 2 0 0
2 3 0 0

*RL # rest lengths
0.001
0.001
0.001
0.001

*RK # rest kappas
0 0
0 0
0 0
0 0

*RT # rest twists
0
0
0
0

*RefD1 # reference directors
0 0 1
0 0 1
0 0 1
0 0 1

*RefT # reference twists
0
0
0
0
PYP

# setval BLOCK ROW COL VALUE < in > out: replace one value (rows and columns count from 1)
setval() {
  awk -v B="$1" -v R="$2" -v C="$3" -v V="$4" '
    /^\*/ { blk = substr($1, 2); row = 0; print; next }
    NF && blk == B { row++; if (row == R) { $C = V } }
    { print }'
}
# delrow BLOCK ROW: delete one data row
delrow() {
  awk -v B="$1" -v R="$2" '
    /^\*/ { blk = substr($1, 2); row = 0; print; next }
    NF && blk == B { row++; if (row == R) next }
    { print }'
}
# delblock BLOCK: delete a block with its rows
delblock() { awk -v B="$1" '/^\*/ { blk = substr($1, 2) } blk == B { next } { print }'; }

pass=0 fail=0
# expect NAME REGEX FILE: the tool must exit non-zero (not by a signal, not a valgrind error) with a
# message matching REGEX that names the file
expect() {
  local name=$1 re=$2 file=$3
  [ -n "$vgcases" ] && [[ $vgcases != *" $name "* ]] && return
  "${vg[@]}" "$tool" -pattern_file "$file" >out.txt 2>err.txt
  local st=$?
  if [ $st -eq 0 ]; then echo "FAIL $name: accepted"; fail=$((fail + 1)); return; fi
  if [ $st -ge 128 ] || [ $st -eq 99 ]; then echo "FAIL $name: crashed or memory error (exit $st)"; cat err.txt; fail=$((fail + 1)); return; fi
  if ! grep -Eq -- "$re" err.txt || ! grep -q -- "$file" err.txt; then
    echo "FAIL $name: message does not match /$re/ or does not name $file:"; cat err.txt; fail=$((fail + 1)); return
  fi
  pass=$((pass + 1))
}

"${vg[@]}" "$tool" -pattern_file good.pyp >out.txt 2>&1 || { echo "the base pattern is refused:"; cat out.txt; exit 1; }
grep -q 'vertices: 4' out.txt || { echo "base pattern summary wrong"; cat out.txt; exit 1; }

delblock RT <good.pyp >missing_block.pyp;             expect missing-block "missing block '\*RT'" missing_block.pyp
{ cat good.pyp; printf '\n*RT # again\n0\n0\n0\n0\n'; } >repeated.pyp
                                                      expect repeated-block "repeated.pyp:[0-9]+: block '\*RT' repeated \(first at line 28\)" repeated.pyp
delrow RL 2 <good.pyp >rows.pyp;                      expect row-count "rows.pyp:[0-9]+: block \*RL has 3 rows, expected 4" rows.pyp
{ cat good.pyp; echo "0.001"; } >extra_row.pyp;       expect extra-row "extra_row.pyp:[0-9]+: block \*RefT has 5 rows, expected 4" extra_row.pyp
setval Q 2 3 abc <good.pyp >nonnum.pyp;               expect non-numeric "nonnum.pyp:6: block \*Q: 'abc' is not a number" nonnum.pyp
setval Q 3 1 nan <good.pyp >nan.pyp;                  expect nan "nan.pyp:7: block \*Q: value 'nan' is not finite" nan.pyp
setval RL 1 1 inf <good.pyp >inf.pyp;                 expect inf "inf.pyp:17: block \*RL: value 'inf' is not finite" inf.pyp
setval RL 1 1 1e999 <good.pyp >overflow.pyp;          expect overflow "overflow.pyp:17: block \*RL: value '1e999' is not finite" overflow.pyp
setval E 2 2 7 <good.pyp >range.pyp;                  expect index-range "range.pyp:12: edge vertex index \(0, 7\) out of range" range.pyp
setval E 3 1 0 <good.pyp >twoout.pyp;                 expect two-outgoing "twoout.pyp:13: vertex 0 has a second outgoing edge \(the first is at line 12\)" twoout.pyp
setval E 3 2 0 <good.pyp >twoin.pyp;                  expect two-incoming "twoin.pyp:13: vertex 0 has a second incoming edge" twoin.pyp
setval E 2 3 0.5 <good.pyp >frac.pyp;                 expect fractional-offset "frac.pyp:12: periodic offsets dx dy must be integers" frac.pyp
setval Q 2 1 -0.0015 <good.pyp >zero.pyp;             expect zero-length "zero.pyp:12: edge 0 -> 1 has zero length" zero.pyp
setval pattern 1 3 0 <good.pyp >radius.pyp;           expect radius "radius.pyp:2: yarn radius must be positive" radius.pyp
setval pattern 1 1 -0.004 <good.pyp >period.pyp;      expect period "period.pyp:2: periods must be positive" period.pyp
setval pattern 1 3 0.004 <good.pyp >rp.pyp;          expect radius-period "rp.pyp:2: yarn radius 0.004 is not smaller than the periods \(px = 0.004, py = 0.002\)" rp.pyp
setval pattern 1 4 4.5 <good.pyp >count.pyp;          expect vertex-count "count.pyp:2: num_vertedges must be a positive integer" count.pyp
setval RL 3 1 0 <good.pyp >rl.pyp;                    expect rest-length "rl.pyp:19: rest length of the edge leaving vertex 2 must be positive" rl.pyp
setval RefD1 2 1 1 <good.pyp | setval RefD1 2 3 0 >par.pyp
                                                      expect director-parallel "par.pyp:36: reference director of the edge leaving vertex 1 is not perpendicular" par.pyp
setval RefD1 4 3 0 <good.pyp >zerod.pyp;              expect director-zero "zerod.pyp:38: reference director of the edge leaving vertex 3 is zero" zerod.pyp
setval RK 1 3 0 <good.pyp >cols.pyp;                  expect columns "cols.pyp:23: block \*RK \(rest kappas\) expects 2 values per row, found more" cols.pyp
setval RK 1 2 "" <good.pyp >fewcols.pyp;             expect few-columns "fewcols.pyp:23: block \*RK \(rest kappas\) expects 2 values per row, found 1" fewcols.pyp
sed 's/^\*RT /*Twist /' good.pyp >unknown.pyp;       expect unknown-block "unknown.pyp:28: unknown block '\*Twist'" unknown.pyp
{ echo "1 2 3"; cat good.pyp; } >early.pyp;           expect data-first "early.pyp:1: data before the first block header" early.pyp
head -c 300 good.pyp >truncated.pyp;                  expect truncated "truncated.pyp: missing block|truncated.pyp:[0-9]+: (block|unknown block)" truncated.pyp
printf 'a\0b' >binary.pyp;                            expect binary "binary.pyp: contains a NUL byte" binary.pyp
: >empty.pyp;                                         expect empty "empty.pyp: missing block '\*pattern'" empty.pyp
mkdir -p dir.pyp;                                     expect directory "Cannot read dir.pyp \(-pattern_file\): it is a directory" dir.pyp
expect missing-file "Cannot open does_not_exist.pyp \(-pattern_file\): No such file" does_not_exist.pyp

echo "$pass cases refused correctly, $fail wrong"
[ $fail -eq 0 ] && [ $pass -ge 10 ]
