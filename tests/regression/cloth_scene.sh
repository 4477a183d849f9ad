#!/usr/bin/env bash
# hylc-cloth -cloth_test scene (docs/fabric.md) on the paper's satin1 table: a 0.2 x 0.1 m rectangle
# clamped along its end x = 0 and one hung from two corners, under gravity: the coordinates CSV (one row
# per vertex), the cloth below its clamp and above the length it could fall, the clamped vertices where
# they were, the same CSV on 2 ranks (1e-8); an .obj square; bad input in one line (a clamp outside the
# mesh, nothing holding the cloth, a non-manifold .obj).
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] || { echo "no paper tables under $M"; exit 77; }
common="-cloth_material $M/satin1.json -cloth_test scene -cloth_length 0.2 -cloth_width 0.1 -cloth_h 0.02 -cloth_vtk 0"

$cloth $common -cloth_scene_clamp 0.1 -cloth_output c1 >c1.txt 2>&1 || { cat c1.txt; die "clamped scene failed"; }
nv=$(sed -n 's/^scene: rectangle, \([0-9]*\) vertices.*/\1/p' c1.txt)
[ -n "$nv" ] && [ "$(tail -n +2 c1_scene.csv | wc -l)" = "$nv" ] || { cat c1.txt; die "expected one CSV row per vertex"; }
# z below 0 somewhere, never below -1.1 L; the clamped end (X = 0) unmoved
awk -F, 'NR > 1 { if ($7 < zmin) zmin = $7; if ($7 < -0.22) bad = 1; if ($2 == 0 && (($5 - $2) ^ 2 + ($6 - $3) ^ 2 + ($7 - $4) ^ 2) > 1e-20) bad = 1 } END { exit bad || !(zmin < -0.05) }' c1_scene.csv || { head c1_scene.csv; die "the clamped cloth: z range or clamp"; }
$cloth $common -cloth_scene_corners 2,3 -cloth_output c2 >c2.txt 2>&1 || { cat c2.txt; die "corner scene failed"; }
grep -q "lowest z -" c2.txt || { cat c2.txt; die "the hung cloth should sag"; }

$MPIEXEC -n 2 $cloth $common -cloth_scene_clamp 0.1 -cloth_output p2 >p2.txt 2>&1 || { cat p2.txt; die "2 ranks failed"; }
paste -d, c1_scene.csv p2_scene.csv | awk -F, 'NR > 1 { for (k = 5; k <= 7; k++) { d = $k - $(k + 7); if (d < 0) d = -d; m = $k < 0 ? -$k : $k; if (d > 1e-8 * m + 1e-12) { print "vertex " $1 " column " k ": " $k " vs " $(k + 7); bad = 1 } } } END { exit bad }' || die "2 ranks differ from 1 rank"

printf 'v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nf 1 2 3\nf 1 3 4\n' >sq.obj
$cloth -cloth_material $M/satin1.json -cloth_test scene -cloth_mesh_file sq.obj -cloth_scene_corners 0,3 -cloth_vtk 0 -cloth_output o1 >o1.txt 2>&1 || { cat o1.txt; die ".obj scene failed"; }
[ "$(tail -n +2 o1_scene.csv | wc -l)" = 4 ] || die ".obj: expected 4 vertices"

printf 'v 0 0 0\nv 0.1 0 0\nv 0.1 0.1 0\nv 0 0.1 0\nv 0.05 0.05 0.05\nf 1 2 3\nf 1 3 4\nf 1 3 5\n' >nm.obj
expect_fail 'nm.obj: .*non-manifold edge' $cloth -cloth_material $M/satin1.json -cloth_test scene -cloth_mesh_file nm.obj -cloth_scene_corners 0 -cloth_output never
expect_fail '-cloth_scene_clamp 0.3 m is outside the mesh' $cloth $common -cloth_scene_clamp 0.3 -cloth_output never
expect_fail 'scene: nothing holds the cloth' $cloth $common -cloth_output never
finish
