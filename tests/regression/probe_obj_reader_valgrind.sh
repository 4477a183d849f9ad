#!/usr/bin/env bash
# The .obj reader of hylc-cloth's scene under valgrind (--leak-check=full --errors-for-leak-kinds=definite,
# Open MPI's start-up suppressed by tests/valgrind.supp): a mesh of more than 1,024 v, vt and f lines (its
# arrays grown one by one from one PetscMalloc3 and freed by PetscFree3 before: a double free) read whole
# and its scene refused at the clamp; a 5,000-character line; the refusals of a vertex in no face, a mesh
# in two pieces and a face item that is not one: no invalid access, no definite leak.
set -u
here=$(cd "$(dirname "$0")" && pwd)
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
command -v valgrind >/dev/null || { echo "valgrind not installed"; exit 77; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
vg=(valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite --num-callers=50 --suppressions="$here/../valgrind.supp")
cloth=("$HYLC_BIN/hylc-cloth" -cloth_material "$M/satin1.json" -cloth_test scene -cloth_vtk 0 -cloth_output never)
run() { # message-regex .obj options...: refused, valgrind clean
  local re=$1 st; shift
  "${vg[@]}" "${cloth[@]}" -cloth_mesh_file "$@" >out.txt 2>&1
  st=$?
  [ $st -eq 99 ] && { cat out.txt; die "valgrind: a memory error or a definite leak: $*"; }
  [ $st -ge 128 ] && { cat out.txt; die "killed by a signal ($st): $*"; }
  [ $st -ne 0 ] || { cat out.txt; die "accepted: $*"; }
  grep -Eq -- "$re" out.txt || { cat out.txt; die "output lacks /$re/: $*"; }
  return 0
}
# a 33 x 33 grid with texture coordinates: 1,089 v and vt lines, 2,048 faces
awk -v n=33 'BEGIN { for (j = 0; j < n; j++) for (i = 0; i < n; i++) printf "v %.6f %.6f 0\nvt %.6f %.6f\n", i / (n - 1), j / (n - 1), i / (n - 1), j / (n - 1)
  for (j = 0; j < n - 1; j++) for (i = 0; i < n - 1; i++) { a = j * n + i + 1; printf "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a, a + 1, a + 1, a + n + 1, a + n + 1, a, a, a + n + 1, a + n + 1, a + n, a + n } }' >grid.obj
run 'cloth_scene_clamp 2\.? m is outside the mesh' grid.obj -cloth_scene_clamp 2
{ awk '/^v /' grid.obj; printf '#'; head -c 5000 /dev/zero | tr '\0' x; printf '\n'; awk '/^f /' grid.obj | sed 's/\/[0-9]*//g'; printf 'v 5 5 0\n'; } >unused.obj
run 'unused.obj:3139: vertex 1090 belongs to no triangle' unused.obj -cloth_scene_clamp 0.5
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nv 2 0 0\nv 3 0 0\nv 3 1 0\nf 4 5 6\n' >two.obj
run 'two.obj: the mesh is in 2 pieces' two.obj -cloth_scene_clamp 0.5
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3/\n' >item.obj
run 'item.obj:4: cannot read face item 3' item.obj -cloth_scene_clamp 0.5
echo "4 refusals clean under valgrind"
