#!/usr/bin/env bash
# Probe item 4.6 (issue 12), hylc-solve: -solve_output and -solve_vtk into a missing directory or onto a
# directory, onto the input pattern, onto each other, or a .pyp of a bent tile are refused before the solve
# (no status line, no time spent, one line naming the option and the path), and no file is created.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-solve
die() { echo "FAIL: $*"; exit 1; }

$HYLC_BIN/hylc-pattern -pattern_type plain -pattern_output in.pyp >gen.txt 2>&1 || { cat gen.txt; die "cannot write the input pattern"; }
cp in.pyp in.orig
mkdir adir
refuse() { # expected-message-part options...
  local want=$1
  shift
  $tool -pattern_file in.pyp -strain 0.1,0,0,0,0,0 "$@" >out.txt 2>&1 && { cat out.txt; die "accepted: $*"; }
  grep -qF -- "$want" out.txt || { cat out.txt; die "$*: message lacks '$want'"; }
  grep -q '^status:' out.txt && { cat out.txt; die "$*: refused only after the solve"; }
  [ "$(grep -c 'error' out.txt)" = 1 ] || { cat out.txt; die "$*: not one error line"; }
  cmp -s in.pyp in.orig || die "$*: the input pattern changed"
}
refuse 'nodir/x.pyp (-solve_output): directory nodir does not exist' -solve_output nodir/x.pyp
refuse 'adir (-solve_output): it is a directory' -solve_output adir
refuse 'adir/ (-solve_output): it names a directory' -solve_output adir/
refuse 'nodir/x.vtk (-solve_vtk): directory nodir does not exist' -solve_vtk nodir/x.vtk
refuse 'adir (-solve_vtk): it is a directory' -solve_vtk adir
refuse '(-solve_output) is the input in.pyp (-pattern_file)' -solve_output in.pyp
refuse '(-solve_output) is the input in.pyp (-pattern_file)' -solve_output ./in.pyp
refuse '(-solve_vtk) is the input in.pyp (-pattern_file)' -solve_vtk in.pyp
refuse '-solve_output and -solve_vtk name the same file same.out' -solve_output same.out -solve_vtk same.out
# a bent tile has no .pyp form: refused before the solve too
$tool -pattern_file in.pyp -strain 0,0,0,50,0,0 -solve_output bent.pyp >out.txt 2>&1 && die "bent .pyp accepted"
grep -q 'only without shear and bending' out.txt || { cat out.txt; die "bent .pyp: unclear message"; }
grep -q '^status:' out.txt && die "bent .pyp: refused only after the solve"
[ -e nodir ] || [ -e bent.pyp ] || [ -e same.out ] && die "a refused output was created"
ls adir | grep -q . && die "something was written into adir"
# the good case still writes both
$tool -pattern_file in.pyp -strain 0.1,0,0,0,0,0 -solve_output eq.pyp -solve_vtk eq.vtk >out.txt 2>&1 || { cat out.txt; die "valid outputs refused"; }
[ -s eq.pyp ] && [ -s eq.vtk ] || die "outputs missing"
exit 0
