#!/usr/bin/env bash
# The .obj reader of hylc-cloth's scene (-cloth_mesh_file, src/cloth/mesh.c). It allocated its arrays with
# one PetscMalloc3, grew them one by one and freed them with PetscFree3: any mesh of more than 1,024 v, vt
# or f lines aborted ("double free or corruption"). A 24 x 24 grid (1,058 faces) hung from its corners
# now solves, and a mesh of 100,352 faces with texture coordinates is read whole (its width in the
# refusal of a clamp outside it). Then the reader's input rules, each refused in one line naming the file
# and line: lines of any length are one line (a 5,000-character comment whose tail read "v 9 9 9" added a
# vertex); "f 1 2 3 # comment" is a triangle (it was "more than 3 vertices"); a vertex in no face is
# named at its line (it was blamed on the clamp when it widened the mesh); a coordinate beyond 1e6 m is
# refused at its line (x 1e300 was "triangle 0 is clockwise"); a mesh in two pieces is refused before any
# solve (the piece no clamp held ran 30 s of dynamics first).
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
cloth="$HYLC_BIN/hylc-cloth -cloth_material $M/satin1.json -cloth_test scene -cloth_vtk 0"
grid() { # n [vt]: an n x n grid of the unit square, 2 (n-1)^2 counter-clockwise faces
  awk -v n="$1" -v vt="${2:-}" 'BEGIN {
    for (j = 0; j < n; j++) for (i = 0; i < n; i++) { printf "v %.6f %.6f 0\n", i / (n - 1), j / (n - 1); if (vt) printf "vt %.6f %.6f\n", i / (n - 1), j / (n - 1) }
    for (j = 0; j < n - 1; j++) for (i = 0; i < n - 1; i++) {
      a = j * n + i + 1; b = a + 1; c = a + n + 1; d = a + n
      if (vt) printf "f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n", a, a, b, b, c, c, a, a, c, c, d, d
      else printf "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d } }'
}

# 1. more than 1,024 faces: the 24 x 24 grid (0.2 m) hung from its four corners solves
grid 24 | awk '/^v / { $2 *= 0.2; $3 *= 0.2 } 1' >g23.obj
$cloth -cloth_mesh_file g23.obj -cloth_scene_corners 0,1,2,3 -cloth_output g >g.txt 2>&1 || { cat g.txt; die "the 24 x 24 grid (1,058 faces) failed"; }
grep -q '^scene: g23.obj, 576 vertices, 1058 triangles' g.txt || { cat g.txt; die "the grid's summary"; }
[ "$(tail -n +2 g_scene.csv | wc -l)" = 576 ] || die "g_scene.csv: expected 576 rows"
grep -q 'lowest z -0\.0[0-9]' g.txt || { cat g.txt; die "the hung grid should sag by some cm"; }
# over 100,000 faces and texture coordinates: read whole (1 m wide), then the clamp of 2 m refused
grid 225 vt >big.obj
[ "$(grep -c '^f ' big.obj)" = 100352 ] || die "big.obj: expected 100352 faces"
expect_fail '^hylc: error: -cloth_scene_clamp 2\.? m is outside the mesh: its end x = 0\.? is 1\.? m wide$' $cloth -cloth_mesh_file big.obj -cloth_scene_clamp 2 -cloth_output never

# 2. the line rules
sq='v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\n'
comment() { printf '#'; head -c $(($1 - 1)) /dev/zero | tr '\0' x; printf '%s\n' "$2"; }
for n in 4095 4096 5000; do
  { printf "$sq"; comment $n 'v 9 9 9'; printf 'f 1 2 3\nf 1 3 4\n'; } >long$n.obj
  $cloth -cloth_mesh_file long$n.obj -cloth_scene_corners 0,3 -cloth_output l$n >l.txt 2>&1 || { cat l.txt; die "long$n.obj: the comment's tail was read as a line"; }
  grep -q '^scene: long'$n'.obj, 4 vertices, 2 triangles' l.txt || { cat l.txt; die "long$n.obj: expected 4 vertices"; }
done
# a coordinate of 5,000 digits is one number (0.1000...)
{ printf 'v 0 0 0\nv 0.1'; head -c 5000 /dev/zero | tr '\0' 0; printf ' 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nf 1 2 3\nf 1 3 4\n'; } >digits.obj
$cloth -cloth_mesh_file digits.obj -cloth_scene_corners 0,3 -cloth_output d >d.txt 2>&1 || { cat d.txt; die "digits.obj failed"; }
awk -F, '$1 == 1 && $2 != 0.1 { bad = 1 } END { exit bad }' d_scene.csv || die "digits.obj: vertex 2 is not at x = 0.1"
printf "${sq}f 1 2 3 # a comment\nf 1 3 4# another\n" >comment.obj
$cloth -cloth_mesh_file comment.obj -cloth_scene_corners 0,3 -cloth_output c >c.txt 2>&1 || { cat c.txt; die "comment.obj: a comment after a face"; }
grep -q '^scene: comment.obj, 4 vertices, 2 triangles' c.txt || { cat c.txt; die "comment.obj: expected 2 triangles"; }

# 3. refused in one line naming the file and line, before any solve
printf "${sq}v -0.1 1 0\nf 1 2 3\nf 1 3 4\n" >unused.obj
expect_fail '^hylc: error: unused.obj:5: vertex 5 belongs to no triangle$' $cloth -cloth_mesh_file unused.obj -cloth_scene_clamp 0.05 -cloth_output never
printf 'v 0 0 0\nv 1e299 0 0\nv 1e299 1e299 0\nv 0 1e299 0\nf 1 2 3\nf 1 3 4\n' >huge.obj
expect_fail '^hylc: error: huge.obj:2: coordinate 1e\+299 m \(after -cloth_mesh_scale 1\) is not finite or beyond 1e\+06 m$' $cloth -cloth_mesh_file huge.obj -cloth_scene_corners 0,3 -cloth_output never
expect_fail '^hylc: error: g23.obj:2: coordinate 8.6956e\+09 m \(after -cloth_mesh_scale 1e\+12\)' $cloth -cloth_mesh_file g23.obj -cloth_mesh_scale 1e12 -cloth_scene_corners 0,3 -cloth_output never
printf "${sq}f 1 2 3\nf 1 3 4\nv 0.2 0 0\nv 0.3 0 0\nv 0.3 0.1 0\nf 5 6 7\n" >two.obj
expect_fail '^hylc: error: two.obj: the mesh is in 2 pieces \(the faces of lines 5 and 10 are not connected' $cloth -cloth_mesh_file two.obj -cloth_scene_clamp 0.1 -cloth_output never
printf "${sq}f 1 2 2\nf 1 3 4\n" >twice.obj
expect_fail '^hylc: error: twice.obj:5: a face with a vertex twice$' $cloth -cloth_mesh_file twice.obj -cloth_scene_corners 0 -cloth_output never
printf "${sq}v 0.2 0.2 0\nf 1 3 5\nf 1 2 3\nf 1 3 4\n" >flat.obj
expect_fail '^hylc: error: flat.obj:6: a triangle of zero area' $cloth -cloth_mesh_file flat.obj -cloth_scene_corners 0 -cloth_output never
printf "${sq}f 0 1 2\n" >zero.obj
expect_fail '^hylc: error: zero.obj:5: vertex index 0 out of range \(4 vertices so far\)$' $cloth -cloth_mesh_file zero.obj -cloth_scene_corners 0 -cloth_output never
printf "${sq}f 1/0 2 3\n" >vt0.obj
expect_fail '^hylc: error: vt0.obj:5: texture index 0 out of range' $cloth -cloth_mesh_file vt0.obj -cloth_scene_corners 0 -cloth_output never
printf "${sq}f 1 2 3x\n" >item.obj
expect_fail '^hylc: error: item.obj:5: cannot read face item 3' $cloth -cloth_mesh_file item.obj -cloth_scene_corners 0 -cloth_output never
printf "v 0 0 nan\n" >nan.obj
expect_fail '^hylc: error: nan.obj:1: coordinate nan m' $cloth -cloth_mesh_file nan.obj -cloth_scene_corners 0 -cloth_output never
printf "v 0 0\n" >short.obj
expect_fail '^hylc: error: short.obj:1: a vertex needs three coordinates' $cloth -cloth_mesh_file short.obj -cloth_scene_corners 0 -cloth_output never
printf "${sq}f 1 2 3\0\nf 1 3 4\n" >nul.obj
expect_fail '^hylc: error: nul.obj:5: a NUL byte' $cloth -cloth_mesh_file nul.obj -cloth_scene_corners 0 -cloth_output never
# 2 ranks: rank 0 reads, every rank raises the error (one line, no abort)
$MPIEXEC -n 2 $cloth -cloth_mesh_file two.obj -cloth_scene_clamp 0.1 -cloth_output never >mpi.txt 2>&1 && { cat mpi.txt; die "2 ranks: accepted"; }
[ "$(grep -c '^hylc: error' mpi.txt)" = 1 ] && grep -q '^hylc: error: two.obj: the mesh is in 2 pieces' mpi.txt || { cat mpi.txt; die "2 ranks: not one error line naming two.obj"; }
grep -q 'MPI_ABORT' mpi.txt && { cat mpi.txt; die "2 ranks: the job was aborted"; }
finish
