#!/usr/bin/env bash
# hylc-cloth's dynamic mode (-cloth_dynamic, docs/fabric.md): backward Euler with damping to rest.
# 1. Where the equilibrium is unique (satin1, a strip hanging from a clamped end), the rest state of the
#    dynamics (-cloth_dynamic on, from the flat strip under full gravity) is the static equilibrium of
#    the load path (-cloth_dynamic off): coordinates within 1e-9 m; the same on 2 ranks.
# 2. The paper's stock1 drape, whose static load path fails at the first step (the knit curls), comes to
#    rest through the dynamics (-cloth_dynamic auto, the default) with a drape coefficient in (0, 1).
# 3. -cloth_vtk_dt writes the animation's VTK frames.
# 4. Bad dynamics options in one line.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc"
cloth=$HYLC_BIN/hylc-cloth
die() { echo "FAIL: $*"; exit 1; }
M=$HYLC_REFDATA/materials
[ -r "$M/satin1.json" ] && [ -r "$M/stock1.json" ] || { echo "no paper tables under $M"; exit 77; }
common="-cloth_material $M/satin1.json -cloth_test scene -cloth_length 0.1 -cloth_width 0.05 -cloth_h 0.01 -cloth_scene_clamp 0.05 -cloth_vtk 0 -cloth_plot 0"

$cloth $common -cloth_dynamic off -cloth_output s >s.txt 2>&1 || { cat s.txt; die "static scene failed"; }
$cloth $common -cloth_dynamic on -cloth_output d >d.txt 2>&1 || { cat d.txt; die "dynamic scene failed"; }
grep -q "dynamics: .* at rest in a static equilibrium" d.txt || { cat d.txt; die "the dynamics should end at rest in the static equilibrium"; }
cmp_xyz() { paste -d, "$1" "$2" | awk -F, -v tol="$3" 'NR > 1 { for (k = 5; k <= 7; k++) { d = $k - $(k + 7); if (d < 0) d = -d; if (d > tol) { print "vertex " $1 " column " k ": " $k " vs " $(k + 7); bad = 1 } } } END { exit bad }'; }
cmp_xyz s_scene.csv d_scene.csv 1e-9 || die "the dynamics' rest differs from the static equilibrium"
# the animation frames: one per 0.5 s of simulated time (the fall takes about 1.7 s)
$cloth $common -cloth_dynamic on -cloth_vtk 1 -cloth_vtk_dt 0.5 -cloth_output f >f.txt 2>&1 || { cat f.txt; die "dynamic scene with frames failed"; }
for k in 0001 0002 0003; do grep -q '^POINTS' f_dynamics_$k.vtk 2>/dev/null || { ls f_*; die "VTK frame $k missing"; }; done
$MPIEXEC -n 2 $cloth $common -cloth_dynamic on -cloth_output p >p.txt 2>&1 || { cat p.txt; die "2 ranks failed"; }
cmp_xyz s_scene.csv p_scene.csv 1e-9 || die "the dynamics on 2 ranks differs from the static equilibrium"

$cloth -cloth_material $M/stock1.json -cloth_test drape -cloth_h 0.02 -cloth_vtk 0 -cloth_plot 0 -cloth_output k >k.txt 2>&1 || { cat k.txt; die "stock1 drape failed"; }
grep -q "the static load path stops" k.txt || { cat k.txt; die "stock1: expected the static load path to fail (the test's premise)"; }
grep -q "dynamics: .* at rest" k.txt || { cat k.txt; die "stock1: the dynamics should come to rest"; }
dc=$(sed -n 's/.*drape coefficient \([0-9.]*\).*/\1/p' k.txt)
awk -v d="$dc" 'BEGIN { exit !(d > 0 && d < 1) }' || { cat k.txt; die "stock1: drape coefficient '$dc' not in (0, 1)"; }
echo "stock1 drape through the dynamics: DC $dc"

expect_fail '-cloth_dt 0\.? must be a positive time step in s' $cloth $common -cloth_dt 0 -cloth_output never
expect_fail '-cloth_dt_max 0\.0001 must be at least -cloth_dt 0\.001' $cloth $common -cloth_dt_max 1e-4 -cloth_output never
expect_fail '-cloth_rest_rtol 2\.? must be in \(0, 1\)' $cloth $common -cloth_rest_rtol 2 -cloth_output never
finish
