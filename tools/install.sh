#!/usr/bin/env bash
# make install / make uninstall (Makefile passes the directories in the environment).
#   install:   headers, libraries (static + shared), programs, pkg-config files hylc.pc and hylcmat.pc,
#              docs; every file and every directory it creates is listed in the manifest
#              $DESTDIR$MANIFEST (lines "f path" and "d path", paths without DESTDIR).
#   uninstall: removes the files of the manifest, then the directories install created (when empty),
#              then the manifest.
set -euo pipefail
cmd=${1:?install or uninstall}
: "${PREFIX:?}" "${MANIFEST:?}"
DESTDIR=${DESTDIR:-}
man=$DESTDIR$MANIFEST

case $cmd in
install)
  tmpman=$(mktemp)
  trap 'rm -f "$tmpman"' EXIT
  # merge with a previous manifest (a re-install over an old one keeps its directories listed)
  [ -f "$man" ] && cat "$man" >>"$tmpman"
  case $PREFIX in /*) ;; *) echo "hylc: PREFIX must be an absolute path, got '$PREFIX'" >&2; exit 2 ;; esac
  mkd() { # creates a directory and its missing parents, listing each one created
    local d=$1 missing=() p
    p=$d
    while [ "$p" != / ] && [ "$p" != . ] && [ ! -d "$DESTDIR$p" ]; do missing=("$p" "${missing[@]}"); p=$(dirname "$p"); done
    [ -z "$DESTDIR" ] || mkdir -p "$DESTDIR" # DESTDIR itself is the packager's
    for p in "${missing[@]}"; do mkdir "$DESTDIR$p" && echo "d $p" >>"$tmpman"; done
  }
  put() { # mode src dstdir [name]
    local mode=$1 src=$2 dir=$3 name=${4:-$(basename "$2")}
    mkd "$dir"
    install -m "$mode" "$src" "$DESTDIR$dir/$name"
    echo "f $dir/$name" >>"$tmpman"
  }
  link() { # target dir name
    mkd "$2"
    ln -sfn "$1" "$DESTDIR$2/$3"
    echo "f $2/$3" >>"$tmpman"
  }
  for h in include/hylcmat.h; do put 644 "$h" "$INCDIR"; done
  for h in include/hylc/*.h; do put 644 "$h" "$INCDIR/hylc"; done
  put 644 "$BUILD/libhylc.a" "$LIBDIR"
  put 755 "$BUILD/libhylc.so.$HYLC_SOVERSION" "$LIBDIR"
  link "libhylc.so.$HYLC_SOVERSION" "$LIBDIR" libhylc.so
  put 644 "$BUILD/libhylcmat.a" "$LIBDIR"
  put 755 "$BUILD/libhylcmat.so.$HYLCMAT_SOVERSION" "$LIBDIR"
  link "libhylcmat.so.$HYLCMAT_SOVERSION" "$LIBDIR" libhylcmat.so
  for b in "$BUILD"/bin/*; do put 755 "$b" "$BINDIR"; done
  # a .pc variable is split at blanks by pkg-config when used in Cflags or Libs: escape blanks, quotes and
  # backslashes (and write '$' as '$$'), so that a prefix with a space gives -I/opt/my\ dir/include, which
  # make and 'eval' pass on as one argument
  pcesc() {
    local s=$1
    s=${s//\\/\\\\}
    s=${s//\$/\$\$}
    s=${s// /\\ }
    s=${s//$'\t'/\\$'\t'}
    s=${s//\"/\\\"}
    s=${s//\'/\\\'}
    printf '%s' "$s"
  }
  pc=$(mktemp -d)
  cat >"$pc/hylc.pc" <<PC
prefix=$(pcesc "$PREFIX")
libdir=$(pcesc "$LIBDIR")
includedir=$(pcesc "$INCDIR")

Name: hylc
Description: homogenized yarn-level cloth: sampling, fitting and evaluation of cloth material models (PETSc, MPI, HDF5)
Version: $VERSION
Requires: $PC_REQUIRES
Libs: -L\${libdir} -lhylc
Libs.private: $PC_LIBS_PRIVATE
Cflags: -I\${includedir}
PC
  cat >"$pc/hylcmat.pc" <<PC
prefix=$(pcesc "$PREFIX")
libdir=$(pcesc "$LIBDIR")
includedir=$(pcesc "$INCDIR")

Name: hylcmat
Description: the hylc cloth material model (JSON tables; Psi, gradient, Hessian), C99 with libc and libm only
Version: $VERSION
Libs: -L\${libdir} -lhylcmat
Libs.private: $HM_LIBS
Cflags: -I\${includedir}
PC
  put 644 "$pc/hylc.pc" "$PCDIR"
  put 644 "$pc/hylcmat.pc" "$PCDIR"
  rm -rf "$pc"
  put 644 README.md "$DOCDIR"
  for d in docs/*.md; do put 644 "$d" "$DOCDIR"; done
  if [ -d python/hylc ]; then
    for f in python/hylc/*.py; do put 644 "$f" "$DATADIR/hylc/python/hylc"; done
    # pip install PREFIX/share/hylc/python: setup.py copies PREFIX/lib/libhylcmat.so into the package
    for f in python/pyproject.toml python/setup.py python/README.md; do put 644 "$f" "$DATADIR/hylc/python"; done
  fi
  # hylc-cloth's plots (src/cloth/output.c looks for PREFIX/share/hylc/plot_cloth.py beside PREFIX/bin)
  put 755 examples/plot_cloth.py "$DATADIR/hylc"
  # the pipeline from an options file to a table (tools/hylc-material) and its helper scripts
  put 755 tools/hylc-material "$BINDIR"
  put 644 tools/material_report.py "$DATADIR/hylc"
  put 644 examples/plot_fit.py "$DATADIR/hylc"
  mkd "$(dirname "$MANIFEST")"
  sort -u "$tmpman" >"$man"
  echo "installed $(grep -c '^f ' "$man") files under $DESTDIR$PREFIX (manifest: $man)"
  ;;
uninstall)
  if [ ! -f "$man" ]; then
    echo "hylc: nothing to uninstall: no manifest $man (was hylc installed with this PREFIX and DESTDIR?)" >&2
    exit 0
  fi
  n=0
  while read -r kind path; do
    [ "$kind" = f ] || continue
    if [ -e "$DESTDIR$path" ] || [ -L "$DESTDIR$path" ]; then rm -f "$DESTDIR$path" && n=$((n + 1)); fi
  done <"$man"
  # the directories install created, deepest first, one per line (a path may hold blanks)
  dirs=$(sed -n 's/^d //p' "$man" | sort -r)
  rm -f "$man"
  while IFS= read -r d; do
    [ -n "$d" ] && { rmdir "$DESTDIR$d" 2>/dev/null || true; }
  done <<<"$dirs"
  echo "removed $n files from $DESTDIR$PREFIX"
  ;;
*) echo "usage: $0 install|uninstall" >&2; exit 2 ;;
esac
