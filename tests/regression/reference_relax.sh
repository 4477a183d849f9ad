#!/usr/bin/env bash
# -sampler_reference relax (issue 30): a stored tile under another yarn is not a minimum of the model; relax
# finds the in-plane minimum over the periods with the tile's rest data kept (no stress-free reset, no
# tension) and makes it the reference, after which dPsi/dsx and dPsi/dsy at z = 0 (central differences of
# equilibria) are below 1 % of dPsi/dsx at sx = 5 %, while before they are not. The rest data of the
# written reference equal the stored tile's. hylc-calibrate accepts -calibrate_reference relax.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
bin=$HYLC_BIN
# a stored tile: the reference state of a generated plain weave with kc = 50
$bin/hylc-sample -pattern_type plain -yarn_kc 50 -sampler_terms zero -sampler_output gen.h5 -reference_output stored.pyp >gen.txt 2>&1 || { cat gen.txt; die "writing the stored tile failed"; }
# under kc = 200 it is not a minimum; relax it
other=(-yarn_kc 200)
$bin/hylc-sample -pattern_file stored.pyp "${other[@]}" -sampler_reference relax -sampler_terms zero,sx -sampler_n1 6 -sampler_output rel.h5 -reference_output relaxed.pyp >rel.txt 2>&1 || { cat rel.txt; die "-sampler_reference relax failed"; }
grep -q "rest data kept" rel.txt || { cat rel.txt; die "relax did not keep the rest data"; }
grep -q "in-plane minimum at sx = " rel.txt || { cat rel.txt; die "relax found no in-plane minimum"; }
grep -q "stress-free round" rel.txt && die "relax ran the stress-free relaxation"
psi() { # pattern sx sy
  $bin/hylc-solve -pattern_file "$1" "${other[@]}" -strain "$2,0,$3,0,0,0" 2>/dev/null | sed -n 's/^psi: //p'
}
slope() { # pattern -> dPsi/dsx, dPsi/dsy at 0 and dPsi/dsx at sx = 0.05
  local h=1e-3
  awk -v a="$(psi "$1" $h 0)" -v b="$(psi "$1" -$h 0)" -v c="$(psi "$1" 0 $h)" -v d="$(psi "$1" 0 -$h)" -v e="$(psi "$1" 0.051 0)" -v f="$(psi "$1" 0.049 0)" -v h=$h \
    'BEGIN { if (a == "" || b == "" || c == "" || d == "" || e == "" || f == "") exit 1; printf "%.6g %.6g %.6g\n", (a - b) / (2 * h), (c - d) / (2 * h), (e - f) / 2e-3 }'
}
before=$(slope stored.pyp) || die "solves on the stored tile failed"
after=$(slope relaxed.pyp) || die "solves on the relaxed tile failed"
echo "stored tile: dPsi/dsx, dPsi/dsy at 0, dPsi/dsx at 5 %: $before"
echo "relaxed:     $after"
set -- $before
awk -v x="$1" -v y="$2" -v s="$3" 'BEGIN { exit !((x < 0 ? -x : x) > 0.01 * s || (y < 0 ? -y : y) > 0.01 * s) }' || die "the stored tile is already stationary under kc = 200: the test cannot tell"
set -- $after
awk -v x="$1" -v y="$2" -v s="$3" 'BEGIN { exit !(s > 0 && (x < 0 ? -x : x) < 0.01 * s && (y < 0 ? -y : y) < 0.01 * s) }' || die "the relaxed tile is not stationary: $after"
# the rest data are the stored tile's (only positions and periods change)
if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c 'import h5py' 2>/dev/null; then
  /usr/bin/python3 - gen.h5 rel.h5 <<'PY' || die "the relaxed reference changed the rest data"
import sys, h5py, numpy as np
a, b = (h5py.File(f, "r")["reference"] for f in sys.argv[1:3])
for d in ("rest_length", "rest_kappa", "rest_twist"):
    assert np.array_equal(a[d][:], b[d][:]), d
assert not np.array_equal(a["X"][:], b["X"][:]), "positions unchanged"
PY
fi
$bin/hylc-calibrate -pattern_file stored.pyp "${other[@]}" -calibrate_reference relax -calibrate_target rel.h5 -calibrate_max_it 0 -calibrate_view >cal.txt 2>&1 || { cat cal.txt; die "hylc-calibrate -calibrate_reference relax failed"; }
grep -q "reference state (relax)" cal.txt || { cat cal.txt; die "hylc-calibrate did not relax the reference"; }
exit 0
