#!/usr/bin/env bash
# Issue 28, items 1 and 2: hylc-calibrate's file targets are checked where they are read.
# 1. A CSV whose strains are all far from zero (1e300: no row had a finite distance from zero, the base
#    row stayed -1 and R->z - 6 was read) ran a "successful" calibration on a denormal base strain; a raw
#    data.txt of nan strains did the same. Now: one line naming the file and line.
# 2. A data.txt row "nan 0 0 0 0 0 5" or a CSV row "-2,0,0,0,0,0,1" failed only after the reference state
#    with "Invalid strain (nan., ...)" naming no file. Now refused on reading, naming file, line and column.
# Every case: exit != 0, at most three lines, no work started ([calibrate] lines), the inputs unchanged
# (checksums). On two ranks the error is one line and the job ends normally (no MPI_Abort).
# probe_readers_valgrind.sh runs the out-of-bounds case under valgrind.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|\[calibrate\]'
tool=$HYLC_BIN/hylc-calibrate
die() { echo "FAIL: $*"; exit 1; }
H='sx,sa,sy,II00,II01,II11,psi'
printf '%s\n1e300,0,0,0,0,0,1\n2e300,0,0,0,0,0,2\n' $H >huge.csv
printf 'nan 0 0 0 0 0 1\nnan 0 0 0 0 0 2\n' >allnan.txt
mkdir -p rawdir && printf '0 0 0 0 0 0 1\nnan 0 0 0 0 0 5\n' >rawdir/data.txt
printf '%s\n0,0,0,0,0,0,1\n-2,0,0,0,0,0,1\n' $H >neg.csv
printf '%s\n0,0,0,0,0,0,1\n0.1,0,0,0,0,0,inf\n' $H >infpsi.csv
printf '%s\n0,0,0,0,0,0,1\n0,1.5,0,0,0,0,2\n' $H >sa.csv
printf '%s\n0,0,0,0,0,0,1\n0.1,0,0,1e6,0,0,2\n' $H >bent.csv
printf '0 0 0 0 0 0 1\n0.1 0 0 0 0 0\n' >short.txt
sum0=$(cat ./*.csv allnan.txt short.txt rawdir/data.txt | sha256sum)
base=(-pattern_type plain -calibrate_max_it 3)
expect_fail '^hylc: error: huge.csv:2: sx = 1e\+300: the stretch factor 1 \+ sx must be at most 1e3$' "$tool" "${base[@]}" -calibrate_target huge.csv
expect_fail "^hylc: error: allnan.txt:1: column 1 \(sx\): 'nan' is not a finite number$" "$tool" "${base[@]}" -calibrate_target allnan.txt
expect_fail "^hylc: error: rawdir/data.txt:2: column 1 \(sx\): 'nan' is not a finite number$" "$tool" "${base[@]}" -calibrate_target rawdir
expect_fail '^hylc: error: neg.csv:3: column 1 \(sx\) = -2: the stretch factor 1 \+ sx must be positive$' "$tool" "${base[@]}" -calibrate_target neg.csv
expect_fail "^hylc: error: infpsi.csv:3: column 7 \(psi\): 'inf' is not a finite number$" "$tool" "${base[@]}" -calibrate_target infpsi.csv
expect_fail '^hylc: error: sa.csv:3: column 2 \(sa\) = 1.5: \|sa\| must be below 1' "$tool" "${base[@]}" -calibrate_target sa.csv
expect_fail '^hylc: error: bent.csv:3: II00 = 1000000: the midsurface would turn by' "$tool" "${base[@]}" -calibrate_target bent.csv
expect_fail '^hylc: error: short.txt:2: 6 fields, expected 7 \(sx sa sy II00 II01 II11 psi\)$' "$tool" "${base[@]}" -calibrate_target short.txt
# the same file given as another target type
expect_fail "^hylc: error: neg.csv:1: column 1 \(sx\): 'sx' is not a number$" "$tool" "${base[@]}" -calibrate_target neg.csv -calibrate_target_type raw
# two ranks: rank 0 reads, every rank raises its error (one line, no abort)
$MPIEXEC -n 2 "$tool" "${base[@]}" -calibrate_target huge.csv >mpi.txt 2>&1 && { cat mpi.txt; die "2 ranks: accepted"; }
[ "$(grep -c '^hylc: error' mpi.txt)" = 1 ] && grep -q '^hylc: error: huge.csv:2: sx = 1e+300' mpi.txt || { cat mpi.txt; die "2 ranks: not one error line naming huge.csv:2"; }
grep -q 'MPI_ABORT' mpi.txt && { cat mpi.txt; die "2 ranks: the job was aborted"; }
[ "$(cat ./*.csv allnan.txt short.txt rawdir/data.txt | sha256sum)" = "$sum0" ] || die "an input was changed"
finish
