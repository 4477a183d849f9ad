#!/usr/bin/env bash
# Issue 28, item 8: make install into a prefix with a space. hylc.pc and hylcmat.pc wrote the prefix
# unescaped, so that `pkg-config --cflags hylcmat` split it into two arguments and the build against the
# installed library failed; make uninstall left every directory it had created (its loop split the paths
# at the space). Now the .pc files escape the blank (pkg-config's rule), a program builds against the
# installed libhylcmat from a Makefile ($(shell pkg-config ...)) and from the shell (eval), runs, and
# make uninstall removes every file and directory it created.
set -u
cd "$HYLC_TMP"
top=$HYLC_ROOT
die() { echo "FAIL: $*"; exit 1; }
command -v pkg-config >/dev/null || { echo "SKIP: no pkg-config"; exit 77; }
build=${BUILD:-build}
flags=(); [ "${HYLC_ASAN:-0}" = 1 ] && flags=(ASAN=1)
[ "${COVERAGE:-0}" = 1 ] && flags=(COVERAGE=1)
mk() { make -C "$top" --no-print-directory BUILD="$build" "${flags[@]}" "$@"; }
prefix="$HYLC_TMP/my prefix/hylc"
mk install PREFIX="$prefix" >install.log 2>&1 || { cat install.log; die "make install failed"; }
grep -qxF 'prefix='"$HYLC_TMP"'/my\ prefix/hylc' "$prefix/lib/pkgconfig/hylcmat.pc" || { head -3 "$prefix/lib/pkgconfig/hylcmat.pc"; die "hylcmat.pc: the prefix is not escaped"; }
grep -qxF 'includedir='"$HYLC_TMP"'/my\ prefix/hylc/include' "$prefix/lib/pkgconfig/hylc.pc" || die "hylc.pc: includedir is not escaped"
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
[ "$(pkg-config --cflags hylcmat | sed 's/ *$//')" = "-I$HYLC_TMP/my\\ prefix/hylc/include" ] || die "pkg-config --cflags hylcmat: '$(pkg-config --cflags hylcmat)'"
# a Makefile of a simulator (make hands the escaped blank to the shell)
printf 'em: %s\n\tcc -std=c99 -O2 $< $(shell pkg-config --cflags --libs hylcmat) -o $@\n' "$top/examples/eval_material.c" >Makefile.em
make -f Makefile.em em >mk.log 2>&1 || { cat mk.log; die "eval_material does not build from a Makefile with pkg-config hylcmat"; }
eval "cc -std=c99 -O2 \"$top/examples/eval_material.c\" $(pkg-config --cflags --libs hylcmat) -o em2" 2>cc.log || { cat cc.log; die "eval_material does not build with eval and pkg-config"; }
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 3, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-1, 0, 1]}], "2D": []}}\n' >small.json
for exe in em em2; do
  out=$(LD_LIBRARY_PATH=$prefix/lib ./$exe small.json 0,0,0,50,0,0 | head -1)
  [ "$out" = "psi: 0.875" ] || die "$exe: '$out', expected psi: 0.875"
done
mk uninstall PREFIX="$prefix" >uninstall.log 2>&1 || { cat uninstall.log; die "make uninstall failed"; }
[ ! -e "$HYLC_TMP/my prefix" ] || { find "$HYLC_TMP/my prefix"; die "make uninstall left directories it created"; }
echo "install into a prefix with a space, build with pkg-config (make and eval), uninstall: ok"
