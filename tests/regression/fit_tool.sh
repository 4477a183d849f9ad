#!/usr/bin/env bash
# hylc-fit end to end on a small samples file (the synthetic Psi of tests/unit/fittest.h on the woven
# plan with 150 1D samples and 20 x 20 2D grids, written by test_fit_input -test_write_samples): -help
# lists the options and does no work; the fit writes HDF5 and JSON and prints the per-term summary; the
# JSON has the paper's layout and hylc-eval gives f0 at zero strain; -log_view shows the fit's events;
# bad input and options are refused with messages that name them.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-fit
die() { echo "FAIL: $*"; exit 1; }
[ -x "$tool" ] || die "missing $tool (run make)"
"$HYLC_BIN/../tests/test_fit_input" -test_write_samples s.h5 >write.txt 2>&1 || { cat write.txt; die "writing s.h5 failed"; }

$tool -help >help.txt 2>&1 || { cat help.txt; die "-help failed"; }
for o in fit_input fit_output fit_json fit_family fit_reg fit_quasiconvex fit_compat fit_monotone_rule fit_flat_tol \
         fit_end_slope fit_mls_kernel fit_mls_truncation fit_mls_grow fit_symmetrize_sa fit_fd_eps fit_knots1d \
         fit_knots1d_factor fit_knots2d_factor fit_knots2d_stretch fit_knots2d_poisson fit_knots2d_symmetric \
         fit_knots2d_bend_factor fit_knots2d_bend_stretch fit_knots2d_bend_symmetric fit_zero_compression \
         fit_zero_compression_strict fit_density fit_yarn_density fit_raw_n1 fit_raw_n2 fit_min_samples_1d \
         fit_min_samples_2d fit_terms; do
  grep -q -- "-$o[ :]" help.txt || die "-help does not list -$o"
done

$tool -fit_input s.h5 -fit_output model.h5 -fit_json model.json -log_view >fit.txt 2>&1 || { cat fit.txt; die "fit failed"; }
[ -s model.h5 ] && [ -s model.json ] || die "outputs missing"
[ -e model.h5.tmp ] || [ -e model.json.tmp ] && die "temporary file left behind"
for want in 'samples: 4351 used of 4351 rows (0 not converged)' 'f0: 0.1 J/m^2 (row 0' 'strain scale: 1 0.75 1 170 170' \
            'sx       17 knots      150 samples' 'sx-sa    8x9 knots     400 samples' 'sx-sy    10x10 knots   400 samples' \
            'sa-II00  9x9 knots     400 samples' 'wrote model.h5' 'wrote model.json' FIT_MLS FIT_Monotone FIT_Term; do
  grep -qF -- "$want" fit.txt || { cat fit.txt; die "summary lacks '$want'"; }
done
# the default 1D layout is the paper's 11 knots refined by 3 on each side of 0 (issue 30); -fit_knots paper
# is the paper's, and -fit_compat authors implies it (an explicit refined layout with it is refused)
grep -q "1D knots: the paper's, refined towards 0 by 3 more on each side" fit.txt || { cat fit.txt; die "the default 1D layout is not the refined one"; }
$tool -fit_input s.h5 -fit_knots paper >paper.txt 2>&1 || { cat paper.txt; die "-fit_knots paper failed"; }
grep -qF 'sx       11 knots      150 samples' paper.txt || { cat paper.txt; die "-fit_knots paper: not 11 knots"; }
$tool -fit_input s.h5 -fit_compat authors >authors.txt 2>&1 || { cat authors.txt; die "-fit_compat authors failed"; }
grep -qF 'sx       11 knots      150 samples' authors.txt || { cat authors.txt; die "-fit_compat authors: not the paper's 11 knots"; }
$tool -fit_input s.h5 -fit_compat authors -fit_knots refined >both.txt 2>&1 && die "-fit_compat authors -fit_knots refined accepted"
grep -q "fit_compat authors.*drop -fit_knots refined" both.txt || { cat both.txt; die "-fit_compat authors -fit_knots refined: unexpected message"; }
# every term's RMS residual is below 1 % of its energy range
awk '/RMS residual/ { v = $0; sub(/.*\(/, "", v); sub(/%.*/, "", v); if (v + 0 >= 1) bad = bad " " $1 } END { if (bad) { print "large residual:" bad; exit 1 } }' fit.txt ||
  die "RMS residual above 1 %"

# the JSON's layout (keys, term order) and its evaluation at zero strain
if [ -x /usr/bin/python3 ]; then
  /usr/bin/python3 - model.json <<'PY' || die "JSON layout"
import json, sys
d = json.load(open(sys.argv[1]))
assert list(d) == ["density", "strain scale", "strain shift", "coeffs"], list(d)
c = d["coeffs"]
assert list(c) == ["const", "1D", "2D"], list(c)
assert [s["k"] for s in c["1D"]] == [0, 1, 2, 3, 4]
assert [(s["k0"], s["k1"]) for s in c["2D"]] == [(0, 1), (0, 2), (0, 3), (0, 4), (1, 2), (1, 3), (1, 4), (2, 3), (2, 4)]
assert d["strain scale"] == [1.0, 0.75, 1.0, 170.0, 170.0], d["strain scale"]
assert abs(c["const"] - 0.1) < 1e-15
for s in c["2D"]:
    assert len(s["p"]) == len(s["tu"]) * len(s["tv"])
PY
fi
if [ -x "$HYLC_BIN/hylc-eval" ]; then
  for m in model.json model.h5; do
    "$HYLC_BIN/hylc-eval" -material $m -strain 0,0,0,0,0,0 >eval.txt 2>&1 || { cat eval.txt; die "hylc-eval $m"; }
    grep -q '^psi: 0.1' eval.txt || { cat eval.txt; die "hylc-eval $m at zero strain: not f0 = 0.1"; }
  done
fi

# bad input: the message names the file / option / value
expect_fail() { # name pattern args...
  local name=$1 pat=$2; shift 2
  "$tool" "$@" >bad.txt 2>&1 && die "$name accepted"
  grep -qF -- "$pat" bad.txt || { cat bad.txt; die "$name: message lacks '$pat'"; }
}
expect_fail "missing file" "nosuch.h5" -fit_input nosuch.h5 -fit_json x.json
expect_fail "no input" "-fit_input" -fit_json x.json
expect_fail "negative reg" "-fit_reg" -fit_input s.h5 -fit_reg -1
expect_fail "unknown option" "-fit_bogus" -fit_input s.h5 -fit_bogus 1
expect_fail "unknown term" "nosuch" -fit_input s.h5 -fit_terms sx,nosuch
expect_fail "too few samples" "only 150 usable samples" -fit_input s.h5 -fit_min_samples_1d 151
printf 'not an hdf5 file\n' >junk.h5
expect_fail "not a samples file" "junk.h5" -fit_input junk.h5
[ -e x.json ] && die "x.json written by a failed run"
exit 0
