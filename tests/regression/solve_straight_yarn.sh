#!/usr/bin/env bash
# A tile of straight periodic yarns solves with the default options (issue 12, deliver 3): the slide row
# repeats the translation row and is dropped at set-up (docs/method.md). hylc-solve on a straight yarn of
# 8 vertices along x (a .pyp written here): status converged, the analytic stretch ratio
# Psi(0.2) / Psi(0.1) = 4 (Psi = 1/2 k_s eps^2 L / A) and the bending ratio Psi(2 kappa) / Psi(kappa) = 4
# (Psi = 1/2 B kappa^2 L / A, to the discretization error). The vertices are unevenly spaced along the
# yarn (rest lengths equal), so the solver has to move them.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-solve
die() { echo "FAIL: $*"; exit 1; }

{
  echo '*pattern # px py radius num_vertedges'
  echo '0.008 0.004 0.0005 8'
  echo
  echo '*Q # dofs: x y z t'
  for k in 0 1 2 3 4 5 6 7; do echo "$(awk -v k=$k 'BEGIN { printf "%.17g", -0.0035 + 0.001 * k + 0.0002 * (k % 2) }') 0 0 0"; done
  echo
  echo '*E # edges: v0 v1 dx dy'
  echo '7 0 1 0'
  for k in 0 1 2 3 4 5 6; do echo "$k $((k + 1)) 0 0"; done
  echo
  echo '*RL # rest lengths'
  for k in 0 1 2 3 4 5 6 7; do echo 0.001; done
  echo
  echo '*RK # rest kappas'
  for k in 0 1 2 3 4 5 6 7; do echo 0 0; done
  echo
  echo '*RT # rest twists'
  for k in 0 1 2 3 4 5 6 7; do echo 0; done
  echo
  echo '*RefD1 # reference directors'
  for k in 0 1 2 3 4 5 6 7; do echo 0 0 1; done
  echo
  echo '*RefT # reference twists'
  for k in 0 1 2 3 4 5 6 7; do echo 0; done
} >straight.pyp

psi() { # strain -> psi, checks converged
  $tool -pattern_file straight.pyp -strain "$1" >"out_$1.txt" 2>&1 || { cat "out_$1.txt"; die "strain $1: hylc-solve failed"; }
  grep -q '^status: converged$' "out_$1.txt" || { cat "out_$1.txt"; die "strain $1: not converged with the default options"; }
  grep -q 'warning' "out_$1.txt" && { cat "out_$1.txt"; die "strain $1: warnings"; }
  sed -n 's/^psi: //p' "out_$1.txt"
}
a=$(psi 0.1,0,0,0,0,0) || exit 1
b=$(psi 0.2,0,0,0,0,0) || exit 1
awk -v a="$a" -v b="$b" 'BEGIN { r = b / a; exit !(r > 4 - 1e-6 && r < 4 + 1e-6) }' || die "stretch: Psi(0.2) / Psi(0.1) = $b / $a, expected 4"
c=$(psi 0,0,0,50,0,0) || exit 1
d=$(psi 0,0,0,100,0,0) || exit 1
awk -v a="$c" -v b="$d" 'BEGIN { r = b / a; exit !(r > 3.99 && r < 4.01) }' || die "bending: Psi(100) / Psi(50) = $d / $c, expected 4"
# a sheared straight yarn as well
psi 0.05,0.3,0,0,0,0 >/dev/null || exit 1
exit 0
