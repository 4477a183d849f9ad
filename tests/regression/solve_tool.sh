#!/usr/bin/env bash
# hylc-solve end to end: the output lines, a converged analytic-free sample, .pyp and VTK outputs,
# clear errors for bad strains, and the same result on 1 and 2 ranks.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-solve
die() { echo "FAIL: $*"; exit 1; }

$tool -pattern_type plain -yarn_kc 50 -strain 0.1,0,0,0,0,0 -solve_output eq.pyp -solve_vtk eq.vtk >out1.txt 2>&1 || { cat out1.txt; die "solve failed"; }
for want in '^psi: [0-9.e+-]+$' '^energy_parts: [0-9.e+-]+ [0-9.e+-]+ [0-9.e+-]+ [0-9.e+-]+$' '^status: converged$' '^iterations: [0-9]+$' '^time: ' 'wrote eq.vtk' 'wrote eq.pyp'; do
  grep -Eq "$want" out1.txt || { cat out1.txt; die "output lacks /$want/"; }
done
# the equilibrium file is a valid pattern with the stretched period (8 mm x 1.1)
$HYLC_BIN/hylc-pattern -pattern_file eq.pyp >pat.txt 2>&1 || { cat pat.txt; die "equilibrium .pyp does not load"; }
grep -q 'periods: 0.0088 0.008' pat.txt || { cat pat.txt; die "equilibrium periods"; }
grep -q '^POINTS' eq.vtk || die "VTK output"

# bent tiles can be written as VTK but not as .pyp
$tool -pattern_type plain -strain 0,0,0,100,0,0 -solve_vtk bent.vtk >out2.txt 2>&1 || { cat out2.txt; die "bent solve failed"; }
grep -q '^status: converged$' out2.txt || { cat out2.txt; die "bent sample did not converge"; }
$tool -pattern_type plain -strain 0,0,0,100,0,0 -solve_output bent.pyp >bad.txt 2>&1 && die "bent .pyp accepted"
grep -q 'only without shear and bending' bad.txt || { cat bad.txt; die "unclear message for bent .pyp"; }

# bad strains are refused clearly
$tool -pattern_type plain -strain 0,1.5,0,0,0,0 >bad.txt 2>&1 && die "|sa| >= 1 accepted"
grep -q -- '-strain: sa = 1.5: |sa| must be below 1' bad.txt || { cat bad.txt; die "unclear message for sa"; }
$tool -pattern_type plain -strain 0,0,0 >bad.txt 2>&1 && die "3 strain values accepted"
grep -q 'needs 6' bad.txt || { cat bad.txt; die "unclear message for -strain"; }

# the same on 2 ranks (each rank solves the sample on PETSC_COMM_SELF)
$MPIEXEC -n 2 $tool -pattern_type plain -yarn_kc 50 -strain 0.1,0,0,0,0,0 >out3.txt 2>&1 || { cat out3.txt; die "2-rank run failed"; }
[ "$(grep -c '^psi: ' out3.txt)" = 2 ] || { cat out3.txt; die "expected one psi line per rank"; }
[ "$(grep '^psi: ' out3.txt | sort -u)" = "$(grep '^psi: ' out1.txt)" ] || die "ranks disagree with the 1-rank result"

# PETSc's Cholesky instead of HylcChol (-micro_factor_pc_factor_mat_solver_type petsc): the same equilibrium to rounding
$tool -pattern_type plain -yarn_kc 50 -strain 0.1,0,0,0,0,0 -micro_factor_pc_factor_mat_solver_type petsc >out4.txt 2>&1 || { cat out4.txt; die "solve with the petsc solver type failed"; }
a=$(sed -n 's/^psi: //p' out1.txt); b=$(sed -n 's/^psi: //p' out4.txt)
awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-9 * a) }' || die "psi with HylcChol $a, with PETSc's Cholesky $b"
# the removed -micro_factor_type is an error that names its replacement
$tool -pattern_type plain -strain 0.1,0,0,0,0,0 -micro_factor_type petsc >bad.txt 2>&1 && die "-micro_factor_type accepted"
grep -q -- "-micro_factor_type was removed: choose the factorization with -micro_factor_pc_factor_mat_solver_type" bad.txt || { cat bad.txt; die "unclear message for -micro_factor_type"; }
[ "$(wc -l <bad.txt)" -le 2 ] || { cat bad.txt; die "-micro_factor_type: more than two lines of output"; }
exit 0
