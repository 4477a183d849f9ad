#!/usr/bin/env bash
# make install into a temporary prefix, then build two programs from examples/ against it with
# pkg-config alone: eval_material.c (libhylcmat: evaluates a table as a simulator would; ldd shows no
# PETSc, MPI or HDF5; its numbers equal hylc-eval's), shell_element.c (libhylcmat: the shell element on
# a small bent mesh; no PETSc, MPI or HDF5 either) and solve_sample.c (libhylc: solves a sample).
# make uninstall then leaves nothing behind. The same with DESTDIR (a staged install for packaging).
set -u
cd "$HYLC_TMP"
top=$HYLC_ROOT
die() { echo "FAIL: $*"; exit 1; }
command -v pkg-config >/dev/null || { echo "SKIP: no pkg-config"; exit 77; }
prefix=$HYLC_TMP/prefix
build=${BUILD:-build}
asanflag=(); [ "${HYLC_ASAN:-0}" = 1 ] && asanflag=(ASAN=1)
[ "${COVERAGE:-0}" = 1 ] && asanflag=(COVERAGE=1) # make coverage: the build-cov objects are instrumented
mk() { make -C "$top" --no-print-directory BUILD="$build" "${asanflag[@]}" "$@"; }

mk install PREFIX="$prefix" >install.log 2>&1 || { cat install.log; die "make install failed"; }
# the pipeline and hylc-cloth's plots installed with what they call (tools/hylc-material finds them there)
for f in bin/hylc-material share/hylc/material_report.py share/hylc/plot_fit.py share/hylc/plot_cloth.py; do
  [ -f "$prefix/$f" ] || die "make install: no $prefix/$f"
done
"$prefix/bin/hylc-material" -help >hm.txt 2>&1 || { cat hm.txt; die "installed hylc-material -help failed"; }
for f in include/hylcmat.h include/hylc/material.h lib/libhylcmat.so lib/libhylcmat.a lib/libhylc.so lib/libhylc.a \
  lib/pkgconfig/hylc.pc lib/pkgconfig/hylcmat.pc bin/hylc-eval bin/hylc-sample share/doc/hylc/material.md; do
  [ -e "$prefix/$f" ] || die "make install did not install $f"
done
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
[ "$(pkg-config --variable=prefix hylcmat)" = "$prefix" ] || die "hylcmat.pc prefix: $(pkg-config --variable=prefix hylcmat)"

# a simulator: libhylcmat only, the system C compiler
cc -std=c99 -O2 "$top/examples/eval_material.c" $(pkg-config --cflags --libs hylcmat) -o eval_material 2>cc1.log || { cat cc1.log; die "eval_material does not build with pkg-config hylcmat"; }
LD_LIBRARY_PATH=$prefix/lib ldd ./eval_material >ldd.txt
cat ldd.txt
grep -q "libhylcmat.so.1 => $prefix/lib/" ldd.txt || die "eval_material does not use the installed libhylcmat"
if grep -Eiq 'petsc|mpi|hdf5|metis' ldd.txt; then die "eval_material depends on PETSc/MPI/HDF5/METIS"; fi
cc -std=c99 -O2 "$top/examples/shell_element.c" $(pkg-config --cflags --libs hylcmat) -lm -o shell_element 2>cc3.log || { cat cc3.log; die "shell_element does not build with pkg-config hylcmat"; }
LD_LIBRARY_PATH=$prefix/lib ldd ./shell_element >ldd3.txt
grep -q "libhylcmat.so.1 => $prefix/lib/" ldd3.txt || die "shell_element does not use the installed libhylcmat"
if grep -Eiq 'petsc|mpi|hdf5|metis' ldd3.txt; then die "shell_element depends on PETSc/MPI/HDF5/METIS"; fi

mat=$HYLC_TMP/small.json
cat >"$mat" <<'JSON'
{
  "density": 0.3,
  "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
  "coeffs": {
    "const": 0.5,
    "1D": [{"k": 3, "t": [-1.0, 0.0, 1.0], "p": [1, 0, 1], "m": [-1, 0, 1]}],
    "2D": [{"k0": 0, "k1": 3, "tu": [0, 1], "tv": [0, 1], "p": [0, 0, 0, 1], "mu": [0, 0, 0, 0], "mv": [0, 0, 0, 0], "muv": [0, 0, 0, 0]}]
  }
}
JSON
mats=("$mat")
[ -f "$HYLC_REFDATA/materials/stock1.json" ] && mats+=("$HYLC_REFDATA/materials/stock1.json")
LD_LIBRARY_PATH=$prefix/lib ./shell_element "$mat" >se.txt 2>&1 || { cat se.txt; die "shell_element failed"; }
grep -q "II00, II01, II11): .* 49.48 0.00 0.00" se.txt || { cat se.txt; die "shell_element: unexpected II of the cylinder"; }
for m in "${mats[@]}"; do
  for s in 0,0,0,50,0,50 0.1,0.2,-0.1,30,-20,10; do
    LD_LIBRARY_PATH=$prefix/lib ./eval_material "$m" "$s" >a.txt 2>&1 || { cat a.txt; die "eval_material $m $s failed"; }
    "$prefix/bin/hylc-eval" -material "$m" -strain "$s" -derivatives >b.txt 2>&1 || { cat b.txt; die "hylc-eval failed"; }
    cmp -s a.txt b.txt || { diff a.txt b.txt; die "eval_material and hylc-eval differ on $m at $s"; }
  done
done
[ "$(LD_LIBRARY_PATH=$prefix/lib ./eval_material "$mat" 0,0,0,50,0,50 | head -1)" = "psi: 0.875" ] || die "psi of small.json: expected 0.875"
echo "eval_material: same output as hylc-eval (${#mats[@]} tables)"

# libhylc: PETSc/MPI through hylc.pc's Requires
# under make test ASAN=1 the installed libhylc is sanitized: its programs link the sanitizer runtime too
san=()
[ "${HYLC_ASAN:-0}" = 1 ] && san=(-fsanitize=address,undefined)
[ "${COVERAGE:-0}" = 1 ] && san=(--coverage)
cc -O2 "${san[@]}" "$top/examples/solve_sample.c" $(pkg-config --cflags --libs hylc) -o solve_sample 2>cc2.log || { cat cc2.log; die "solve_sample does not build with pkg-config hylc"; }
LD_LIBRARY_PATH=$prefix/lib ldd ./solve_sample | grep -q "libhylc.so.1 => $prefix/lib/" || die "solve_sample does not use the installed libhylc"
LD_LIBRARY_PATH=$prefix/lib ./solve_sample -pattern_type stockinette -strain 0.05,0,0,0,0,0 >solve.txt 2>&1 || { cat solve.txt; die "solve_sample failed"; }
cat solve.txt
psi=$(sed -n 's/^psi: \([^ ]*\) J.*/\1/p' solve.txt)
ref=$("$prefix/bin/hylc-solve" -pattern_type stockinette -strain 0.05,0,0,0,0,0 | sed -n 's/^psi: *\([^ ]*\).*/\1/p')
awk -v a="$psi" -v b="$ref" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0 && d <= 1e-8 * b) }' || die "solve_sample psi $psi, hylc-solve psi $ref"

mk uninstall PREFIX="$prefix" >uninstall.log 2>&1 || { cat uninstall.log; die "make uninstall failed"; }
cat uninstall.log
if [ -e "$prefix" ]; then find "$prefix" | head; die "make uninstall left files or directories in $prefix"; fi

# DESTDIR: staged under $stage, configured for /opt/hylc-test
stage=$HYLC_TMP/stage
mk install PREFIX=/opt/hylc-test DESTDIR="$stage" >install2.log 2>&1 || { cat install2.log; die "make install DESTDIR failed"; }
[ -f "$stage/opt/hylc-test/lib/libhylcmat.so.1" ] || die "DESTDIR install: no $stage/opt/hylc-test/lib/libhylcmat.so.1"
grep -q '^prefix=/opt/hylc-test$' "$stage/opt/hylc-test/lib/pkgconfig/hylcmat.pc" || die "DESTDIR install: the .pc prefix is not /opt/hylc-test"
[ ! -e /opt/hylc-test ] || die "DESTDIR install wrote to /opt/hylc-test"
mk uninstall PREFIX=/opt/hylc-test DESTDIR="$stage" >uninstall2.log 2>&1 || { cat uninstall2.log; die "make uninstall DESTDIR failed"; }
left=$(find "$stage" -mindepth 1 | head)
[ -z "$left" ] || { echo "$left"; die "make uninstall DESTDIR left files"; }
echo "install, build with pkg-config, uninstall: ok"
