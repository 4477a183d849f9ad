#!/usr/bin/env bash
# -calibrate_stationary's scale S_k of a file target (2 dPsi_T / s_k of its sx or sy row nearest 5 %) was
# taken from the rows that survived the thinning of -calibrate_max_samples / -calibrate_stride, so one
# target gave another S at each setting (here 0.47, 1.19 and 3.36 N/m), or "no scale" when the thinning kept
# no row with s_k > 0. Now S comes from every usable row: the same at every thinning. A weight of 1e300
# ended in TAO's "User provided compute function generated Inf or NaN"; now at most 1e8 is accepted.
set -u
cd "$HYLC_TMP"
. "$HYLC_ROOT/tests/regression/probe_common.inc" || exit 1
FORBID='PETSC ERROR|\[calibrate\] it'
die() { echo "FAIL: $*"; exit 1; }
B=$HYLC_BIN
# a target of 43 rows: the base, 16 sx and 16 sy rows from -0.3 to 0.3 (sx, sy = 0.0375 nearest 5 %), 10 sa
# rows; Psi of a smooth table
printf '{"density": 0.3, "strain scale": [1, 1, 1, 100, 100], "coeffs": {"const": 0.5, "1D": [{"k": 0, "t": [-0.4, 0, 0.4], "p": [0.4, 0, 0.9], "m": [-1.2, 0, 4]}, {"k": 1, "t": [-1, 0, 1], "p": [1, 0, 1], "m": [-2, 0, 2]}, {"k": 2, "t": [-0.4, 0, 0.4], "p": [0.3, 0, 0.7], "m": [-1, 0, 3]}], "2D": []}}\n' >m.json
awk 'BEGIN { print "0 0 0 0 0 0"; for (c = 0; c < 3; c += 2) for (i = 0; i <= 16; i++) { s = -0.3 + i * 0.0375; if (i == 8) continue; if (c == 0) print s, 0, 0, 0, 0, 0; else print 0, 0, s, 0, 0, 0 }
  for (i = 0; i <= 10; i++) { s = -0.5 + i * 0.1; if (i != 5) print 0, s, 0, 0, 0, 0 } }' >st.txt
$B/hylc-eval -material m.json -eval_input st.txt -eval_output st.psi >e.txt 2>&1 || { cat e.txt; die "hylc-eval"; }
{ echo 'sx,sa,sy,II00,II01,II11,psi'; paste -d' ' st.txt <(grep -v '^#' st.psi) | tr ' ' ,; } >st.csv
[ "$(grep -c '' st.csv)" = 44 ] || die "st.csv: expected 43 rows"
cal=($B/hylc-calibrate -pattern_type plain -calibrate_reference none -calibrate_target st.csv -calibrate_stationary 1 -calibrate_max_it 0)
scales() { "${cal[@]}" "$@" >c.txt 2>&1 || { cat c.txt; die "hylc-calibrate $*"; }; sed -n 's/.*(S = target.s dPsi\/ds\([xy]\) at 5 %: \([^ ]*\) N\/m.*/\1 \2/p' c.txt | tr '\n' ' '; }
ref=$(scales)
echo "S at every row: $ref"
[ "$(echo "$ref" | wc -w)" = 4 ] || { cat c.txt; die "no S_x and S_y printed"; }
for opt in "-calibrate_max_samples 20" "-calibrate_max_samples 12" "-calibrate_max_samples 4" "-calibrate_stride 3" "-calibrate_stride 5 -calibrate_max_samples 3"; do
  s=$(scales $opt)
  [ "$s" = "$ref" ] || die "$opt: S $s, expected $ref (every row)"
done
expect_fail '^hylc: error: -calibrate_stationary 1e\+300: at most 1e8' "${cal[@]}" -calibrate_stationary 1e300
expect_fail '^hylc: error: -calibrate_stationary 1.5e\+08: at most 1e8' "${cal[@]}" -calibrate_stationary 1.5e8
"${cal[@]}" -calibrate_stationary 1e8 >c.txt 2>&1 || { cat c.txt; die "-calibrate_stationary 1e8 must be accepted"; }
finish
