#!/usr/bin/env bash
# Probe item 4.10 (issue 12), hylc-solve: a strain that gives no valid, representable deformed tile is
# refused before the solve with one line naming -strain and the component (not blamed on the constraint
# rows): non-finite, |sa| >= 1, a stretch factor 1 + s <= 0 or > 1e3, a bending that turns the midsurface
# by more than 2 pi across a period. Subnormal components (1e-320) are valid and give a finite psi equal to
# psi at zero strain to rounding.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-solve
die() { echo "FAIL: $*"; exit 1; }

refuse() { # strain expected-message-part
  $tool -pattern_type plain -strain "$1" >out.txt 2>&1 && { cat out.txt; die "strain $1 accepted"; }
  grep -qF -- "$2" out.txt || { cat out.txt; die "strain $1: message lacks '$2'"; }
  [ "$(wc -l <out.txt)" -le 3 ] || { cat out.txt; die "strain $1: more than 3 lines"; }
  grep -q 'linearly dependent' out.txt && die "strain $1 blamed on the constraint rows"
}
refuse 1e300,0,0,0,0,0 '-strain: sx = 1e+300: the stretch factor 1 + sx must be at most 1e3'
refuse 0,0,1e300,0,0,0 '-strain: sy = 1e+300'
refuse 1000,0,0,0,0,0 '-strain: sx = 1000:'
refuse -1,0,0,0,0,0 '-strain: sx = -1: the stretch factor 1 + sx must be positive'
refuse 0,0,-2.5,0,0,0 '-strain: sy = -2.5'
refuse 0,1,0,0,0,0 '-strain: sa = 1: |sa| must be below 1'
refuse 0,-1e300,0,0,0,0 '-strain: sa = -1e+300'
refuse 0,0,0,1e300,0,0 '-strain: II00 = 1e+300: the midsurface would turn by'
refuse 0,0,0,0,-1e300,0 '-strain: II01 = -1e+300'
refuse 0,0,0,0,0,1e5 '-strain: II11 = 100000'
refuse 0,0,0,inf,0,0 'Option -strain 0,0,0,inf,0,0: value 4 is not a finite number'
refuse nan,0,0,0,0,0 'Option -strain nan,0,0,0,0,0: value 1 is not a finite number'

psi0=$($tool -pattern_type plain -strain 0,0,0,0,0,0 | sed -n 's/^psi: //p')
for z in 1e-320,0,0,0,0,0 0,-1e-320,0,0,0,0 0,0,1e-320,0,0,0 0,0,0,1e-320,0,0 0,0,0,0,0,-1e-320 1e-320,1e-320,1e-320,1e-320,0,1e-320 4.9e-324,0,0,0,0,0; do
  $tool -pattern_type plain -strain $z >out.txt 2>&1 || { cat out.txt; die "subnormal strain $z refused"; }
  grep -q '^status: converged$' out.txt || { cat out.txt; die "subnormal strain $z: not converged"; }
  p=$(sed -n 's/^psi: //p' out.txt)
  awk -v p="$p" -v q="$psi0" 'BEGIN { exit !(p == p + 0 && p - q < 1e-20 && q - p < 1e-20) }' || die "subnormal strain $z: psi $p, at zero strain $psi0"
done
# valid large values still solve
$tool -pattern_type plain -strain 0,0,0,400,0,0 >out.txt 2>&1 || { cat out.txt; die "II00 = 400 refused"; }
exit 0
