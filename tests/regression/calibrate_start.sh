#!/usr/bin/env bash
# hylc-calibrate -calibrate_start (issue 27): auto solves the model the way the target was made. With the
# target's own yarn parameters and no iteration (-calibrate_max_it 0), the model's Psi then equals the
# target's on every sample (to 1e-8 relative: the free parameters pass through exp(log p), which moves where a solve stops): a continued samples file (hylc-sample's default) is evaluated by
# continuation along each 1D term's half-line, exactly as hylc-sample continued it, and a cold one cold.
# -calibrate_view names the start; 1 and 2 ranks give the same dump; an explicit start overrides auto;
# -calibrate_start both is refused by name.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
bin=$HYLC_BIN
model=(-pattern_type plain -yarn_kc 50)
plan=(-sampler_terms zero,sx,sa,sy,II00,II11 -sampler_n1 10)
for st in continue cold; do
  $bin/hylc-sample "${model[@]}" -sampler_reference none "${plan[@]}" -sampler_start $st -sampler_output $st.h5 >s-$st.txt 2>&1 || { cat s-$st.txt; die "hylc-sample -sampler_start $st failed"; }
done
# the dump's columns: index, term, sx, sa, sy, II00, II01, II11, target, initial, calibrated, ...
same_psi() { # dump file: target and initial (model) Psi equal on every row to 1e-8 relative (1e-12 J/m^2 absolute)
  awk -F, 'function abs(x) { return x < 0 ? -x : x }
    NR > 1 && abs($9 - $10) > 1e-8 * abs($9) + 1e-12 { bad++; if (bad < 4) print "  row " NR - 1 ": target " $9 ", model " $10 } END { exit bad > 0 }' "$1"
}
for st in continue cold; do
  for np in 1 2; do
    $MPIEXEC -n $np $bin/hylc-calibrate "${model[@]}" -calibrate_reference none -calibrate_target $st.h5 -calibrate_max_it 0 -calibrate_dump $st-$np.csv -calibrate_view >c-$st-$np.txt 2>&1 || { cat c-$st-$np.txt; die "hylc-calibrate on the $st samples ($np ranks) failed"; }
  done
  cmp -s $st-1.csv $st-2.csv || die "the $st target: 1 and 2 ranks give different dumps"
  same_psi $st-1.csv || die "the $st target with -calibrate_start auto: the model's Psi differs from the samples'"
done
grep -q 'samples solved by continuation.*-calibrate_start auto' c-continue-1.txt || { cat c-continue-1.txt; die "auto on a continued samples file did not continue"; }
grep -q 'samples solved cold.*-calibrate_start auto' c-cold-1.txt || { cat c-cold-1.txt; die "auto on a cold samples file did not solve cold"; }
# an explicit start overrides auto: the continued samples solved cold differ from the file's somewhere (so
# the comparison above can fail)
$bin/hylc-calibrate "${model[@]}" -calibrate_reference none -calibrate_target continue.h5 -calibrate_max_it 0 -calibrate_start cold -calibrate_dump x.csv -calibrate_view >x.txt 2>&1 || { cat x.txt; die "-calibrate_start cold failed"; }
grep -q 'samples solved cold.*-calibrate_start cold' x.txt || { cat x.txt; die "-calibrate_start cold not applied"; }
same_psi x.csv >/dev/null && die "the continued samples solved cold agree with the file everywhere: the test cannot tell the starts apart"
# a table target (auto: cold, as the paper's tables were computed)
$bin/hylc-fit -fit_input cold.h5 -fit_json t.json >fit.txt 2>&1 || { cat fit.txt; die "hylc-fit failed"; }
$bin/hylc-calibrate "${model[@]}" -calibrate_reference none -calibrate_target t.json -calibrate_n 4 -calibrate_max_it 0 -calibrate_view >t.txt 2>&1 || { cat t.txt; die "hylc-calibrate on a table failed"; }
grep -q 'samples solved cold.*-calibrate_start auto' t.txt || { cat t.txt; die "auto on a table did not solve cold"; }
$bin/hylc-calibrate "${model[@]}" -calibrate_reference none -calibrate_target t.json -calibrate_start both >b.txt 2>&1 && die "-calibrate_start both accepted"
grep -q 'calibrate_start' b.txt || { cat b.txt; die "-calibrate_start both: the refusal does not name the option"; }
exit 0
