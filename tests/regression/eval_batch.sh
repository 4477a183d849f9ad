#!/usr/bin/env bash
# hylc-eval batch mode: -eval_input strains.txt|.h5 -eval_output out.txt|.h5 gives, per strain, the
# numbers of the one-strain mode; a bad line is named with file:line.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-eval
die() { echo "FAIL: $*"; exit 1; }
cat >small.json <<'JSON'
{"density": 0.3, "strain scale": [1.0, 1.0, 1.0, 100.0, 100.0],
 "coeffs": {"const": 0.5, "1D": [{"k": 3, "t": [-1.0, 0.0, 1.0], "p": [1, 0, 1], "m": [-1, 0, 1]}],
  "2D": [{"k0": 0, "k1": 3, "tu": [0, 1], "tv": [0, 1], "p": [0, 0, 0, 1], "mu": [0, 0, 0, 0], "mv": [0, 0, 0, 0], "muv": [0, 0, 0, 0]}]}}
JSON
printf '# strains\n0,0,0,50,0,50\n\n0.1 0.2 -0.1 30 -20 10\n0.5,0,0,40,0,40 # equal eigenvalues\n' >s.txt
$tool -material small.json -eval_input s.txt -eval_output o.txt -derivatives >log.txt 2>&1 || { cat log.txt; die "batch failed"; }
[ "$(grep -vc '^#' o.txt)" = 3 ] || { cat o.txt; die "expected 3 result lines"; }
[ "$(grep -v '^#' o.txt | head -1 | cut -d' ' -f1)" = 0.875 ] || die "psi at II = 50 I: expected 0.875"
i=0
for s in 0,0,0,50,0,50 0.1,0.2,-0.1,30,-20,10 0.5,0,0,40,0,40; do
  i=$((i + 1))
  one=$(echo $($tool -material small.json -strain $s -derivatives | sed 's/^[a-z]*://'))
  got=$(grep -v '^#' o.txt | sed -n ${i}p)
  [ "$one" = "$got" ] || { echo "one: $one"; echo "got: $got"; die "batch line $i differs from -strain $s"; }
done
$tool -material small.json -eval_input s.txt -eval_output o.h5 >log.txt 2>&1 || { cat log.txt; die "HDF5 output failed"; }
$tool -material small.json -eval_input o.h5 -eval_output o2.txt >log.txt 2>&1 || { cat log.txt; die "HDF5 input (dataset /strain) failed"; }
[ "$(grep -v '^#' o2.txt | cut -d' ' -f1 | tr '\n' ' ')" = "$(grep -v '^#' o.txt | cut -d' ' -f1 | tr '\n' ' ')" ] || die "HDF5 round trip of the strains changes psi"
printf '0 0 0 0 0 0\n0 0 x 0 0 0\n' >bad.txt
$tool -material small.json -eval_input bad.txt -eval_output b.txt >err.txt 2>&1 && die "a bad line was accepted"
grep -q "bad.txt:2: column 3 (sy): 'x' is not a number" err.txt || { cat err.txt; die "message for a bad line"; }
[ ! -e b.txt ] || die "output written despite the error"
echo "batch mode: ok"
