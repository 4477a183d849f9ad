#!/usr/bin/env bash
# hylc-eval end to end: psi of a small hand-made JSON material (known value), the -derivatives layout,
# conversion JSON -> HDF5 -> JSON (byte-identical, same psi), clear errors for a missing material, a bad
# file name, a malformed -strain and unknown options, -help, and the same output on 2 ranks. With
# $HYLC_REFDATA: every paper table converts to HDF5 and back byte for byte and gives the same psi and
# derivatives from both formats.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-eval
die() { echo "FAIL: $*"; exit 1; }

# f_3(x) on [0, 1] is the Hermite cubic of (0, 0) and (1, 1): f_3(0.5) = 0.375; the 2D term vanishes on u = 0
cat > small.json <<'JSON'
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
$tool -material small.json -strain 0,0,0,50,0,50 >out.txt 2>&1 || { cat out.txt; die "evaluation failed"; }
[ "$(cat out.txt)" = "psi: 0.875" ] || { cat out.txt; die "psi of small.json at II = 50 I: expected 0.875"; }

$tool -material small.json -strain 0.1,0.2,-0.1,30,-20,10 -derivatives >der.txt 2>&1 || { cat der.txt; die "-derivatives failed"; }
num='-?[0-9.]+(e[-+][0-9]+)?'
grep -Eq "^psi: $num$" der.txt || { cat der.txt; die "psi line"; }
grep -Eq "^grad:( $num){6}$" der.txt || { cat der.txt; die "grad line"; }
[ "$(sed -n '3p' der.txt)" = "hessian:" ] || { cat der.txt; die "hessian header"; }
[ "$(sed -n '4,9p' der.txt | grep -Ec "^$num( $num){5}$")" = 6 ] || { cat der.txt; die "hessian rows"; }
[ "$(wc -l <der.txt)" = 9 ] || { cat der.txt; die "expected 9 lines"; }

# conversion and round trips
$tool -material small.json -eval_json a.json -eval_hdf5 a.h5 >conv.txt 2>&1 || { cat conv.txt; die "conversion failed"; }
grep -q '^wrote a.json$' conv.txt && grep -q '^wrote a.h5$' conv.txt || { cat conv.txt; die "conversion messages"; }
[ -e a.json.tmp ] || [ -e a.h5.tmp ] && die "temporary file left behind"
$tool -material a.h5 -eval_json b.json >/dev/null 2>&1 || die "HDF5 -> JSON failed"
cmp -s a.json b.json || die "JSON -> HDF5 -> JSON changed the file"
$tool -material a.json -eval_json c.json >/dev/null 2>&1 && cmp -s a.json c.json || die "JSON -> JSON changed our own file"
for f in a.json a.h5; do
  $tool -material $f -strain 0.1,0.2,-0.1,30,-20,10 -derivatives >d2.txt 2>&1 || { cat d2.txt; die "$f evaluation failed"; }
  cmp -s der.txt d2.txt || { diff der.txt d2.txt; die "$f evaluates differently from small.json"; }
done
$tool -material_file a.h5 -strain 0,0,0,50,0,50 -material_view >view.txt 2>&1 || { cat view.txt; die "-material_file/-material_view failed"; }
grep -q '^psi: 0.875$' view.txt && grep -q 'source: a.h5' view.txt && grep -q '1D II00 .* 3 knots' view.txt && grep -q '2D sx-II00 .* 2 x  2 knots' view.txt || { cat view.txt; die "-material_view summary"; }
if command -v h5dump >/dev/null 2>&1; then
  h5dump -H a.h5 >schema.txt 2>&1 || { cat schema.txt; die "h5dump -H failed"; }
  for want in 'ATTRIBUTE "format"' 'ATTRIBUTE "format_version"' 'ATTRIBUTE "hylc_version"' 'ATTRIBUTE "creation_date"' 'ATTRIBUTE "options"' \
              'DATASET "density"' 'DATASET "constant"' 'DATASET "strain_scale"' 'DATASET "strain_shift"' 'GROUP "1D"' 'GROUP "II00"' \
              'GROUP "2D"' 'GROUP "sx-II00"' 'DATASET "muv"' 'SIMPLE { ( 2, 2 ) / ( 2, 2 ) }' 'ATTRIBUTE "units"'; do
    grep -qF "$want" schema.txt || die "h5dump -H lacks $want"
  done
  h5dump -a /format a.h5 | grep -q '"hylc-material"' || die "format attribute"
fi

# errors name the option or file and the value
expect_error() { # message-regex command...
  local want=$1; shift
  "$@" >err.txt 2>&1 && { cat err.txt; die "accepted: $*"; }
  grep -Eq -- "$want" err.txt || { cat err.txt; die "unclear message for: $* (expected /$want/)"; }
  grep -q 'PETSC ERROR' err.txt && { cat err.txt; die "traceback instead of a one-line message for: $*"; }
  return 0
}
expect_error 'needs a material: -material' $tool -strain 0,0,0,0,0,0
expect_error "Cannot open nosuch.json \(-material\): No such file" $tool -material nosuch.json -strain 0,0,0,0,0,0
expect_error '-strain 0,0,0: needs 6 comma-separated values' $tool -material small.json -strain 0,0,0
expect_error "-strain 0,a,0,0,0,0: 'a' is not a finite number" $tool -material small.json -strain 0,a,0,0,0,0
expect_error '-strain 0,0,0,0,0,0,0: more than 6 values' $tool -material small.json -strain 0,0,0,0,0,0,0
expect_error "-strain 0,,0,0,0,0: '' is not a finite number" $tool -material small.json -strain 0,,0,0,0,0
expect_error 'Unknown option\(s\): -derivative ' $tool -material small.json -strain 0,0,0,0,0,0 -derivative
expect_error 'Nothing to do' $tool -material small.json
expect_error '-derivatives needs -strain' $tool -material small.json -derivatives -eval_json x.json
expect_error 'Both -material and -material_file' $tool -material small.json -material_file small.json -strain 0,0,0,0,0,0
expect_error 'Cannot write no/such/dir/x.json \(-eval_json\): directory no/such/dir does not exist' $tool -material small.json -eval_json no/such/dir/x.json
printf '{"density": 0.3,\n "strain scale": [1, 1, 1, 1, 1],\n "coeffs": {"const": 0, "1D": [{"k": 0, "t": [0, 1], "p": [0, 1], "m": [0]}]}}' >bad.json
expect_error 'bad.json:3: coeffs.1D\[0\].m: expected 2 numbers \(one per knot\), got 1' $tool -material bad.json -strain 0,0,0,0,0,0

# -help lists the options and does no work
$tool -help -material nosuch.json >help.txt 2>&1 || { cat help.txt; die "-help failed"; }
for want in -material -strain -derivatives -eval_json -eval_hdf5 -material_file -material_view; do
  grep -q -- "^ *$want[ :<]" help.txt || die "-help lacks $want"
done

# 2 ranks: rank 0 reads and broadcasts, prints once
$MPIEXEC -n 2 $tool -material a.h5 -strain 0.1,0.2,-0.1,30,-20,10 -derivatives >np2.txt 2>&1 || { cat np2.txt; die "2-rank run failed"; }
cmp -s der.txt np2.txt || { cat np2.txt; die "2-rank output differs"; }
$MPIEXEC -n 2 $tool -material small.json -eval_json np2.json -eval_hdf5 np2.h5 >np2w.txt 2>&1 || { cat np2w.txt; die "2-rank conversion failed"; }
[ "$(grep -c '^wrote' np2w.txt)" = 2 ] || { cat np2w.txt; die "2-rank conversion: expected one message per file"; }
cmp -s a.json np2.json || die "2-rank JSON differs"
$tool -material np2.h5 -eval_json np2b.json >/dev/null 2>&1 && cmp -s a.json np2b.json || die "2-rank HDF5 differs"

# the paper's tables
ref=${HYLC_REFDATA:-../shared/refdata}/materials
if [ ! -d "$ref" ]; then
  echo "skipped the paper's tables: $ref not found"
  exit 0
fi
for f in "$ref"/*.json; do
  b=$(basename "$f" .json)
  $tool -material "$f" -eval_hdf5 $b.h5 -strain 0.05,-0.1,0.2,-30,15,60 -derivatives >$b.json.txt 2>&1 || { cat $b.json.txt; die "$b: failed"; }
  $tool -material $b.h5 -eval_json $b.json -strain 0.05,-0.1,0.2,-30,15,60 -derivatives >$b.h5.txt 2>&1 || { cat $b.h5.txt; die "$b.h5: failed"; }
  cmp -s "$f" $b.json || die "$b: JSON -> HDF5 -> JSON is not byte-identical"
  [ "$(grep -v wrote $b.json.txt)" = "$(grep -v wrote $b.h5.txt)" ] || die "$b: JSON and HDF5 evaluate differently"
done
exit 0
