#!/usr/bin/env bash
# The area density of one tile agrees across the programs (issue 33): hylc-pattern's summary of the
# samples' reference state, hylc-fit's summary, the JSON's "density" (what a simulator uses for gravity)
# and info.txt of hylc-sample's raw export, with the shared rule 0.12 kg/m^2 / r and with a yarn density
# given to both programs; and, with the reference data, the paper's satin .pyp against its table.
set -u
cd "$HYLC_TMP"
B=$HYLC_BIN
die() { echo "FAIL: $*"; exit 1; }
mkdir -p raw
$B/hylc-sample -pattern_type stockinette -sampler_family stockinette -sampler_terms zero,sx -sampler_n1 12 \
  -sampler_output s.h5 -reference_output ref.pyp -sampler_export_raw raw >sample.txt 2>&1 || { cat sample.txt; die "sampling failed"; }
num() { sed -n "s/^ *area density: \([0-9.eE+-]*\) kg\/m^2.*/\1/p" "$1" | head -n 1; }
# same() a b what: equal to 6 significant digits (the summaries print %.6g)
same() { awk -v a="$1" -v b="$2" 'BEGIN { if (!(a > 0 && b > 0)) exit 1; d = (a - b) / b; if (d < 0) d = -d; exit !(d < 5e-6) }' || die "$3: $1 against $2"; }

for rho in default 1200; do
  popt=() fopt=()
  [ $rho = default ] || { popt=(-pattern_density $rho); fopt=(-fit_yarn_density $rho); }
  $B/hylc-pattern -pattern_file ref.pyp "${popt[@]}" >pattern.txt 2>&1 || { cat pattern.txt; die "hylc-pattern failed"; }
  $B/hylc-fit -fit_input s.h5 -fit_terms sx -fit_json m-$rho.json "${fopt[@]}" >fit.txt 2>&1 || { cat fit.txt; die "hylc-fit failed"; }
  p=$(num pattern.txt) f=$(num fit.txt)
  j=$(sed -n 's/.*"density": *\([0-9.eE+-]*\).*/\1/p' m-$rho.json | head -n 1)
  [ -n "$p" ] && [ -n "$f" ] && [ -n "$j" ] || { cat pattern.txt fit.txt; die "a density is missing (pattern '$p', fit '$f', JSON '$j')"; }
  same "$p" "$j" "hylc-pattern and the JSON ($rho)"
  same "$f" "$j" "hylc-fit and the JSON ($rho)"
  if [ $rho = default ]; then
    r=$(awk '$1 == "density" { print $2 }' raw/info.txt)
    same "$r" "$j" "the raw export's info.txt and the JSON"
    same "$j" 0.328202 "the stockinette's area density at 120 kg/m^3 (0.12 kg/m^2 / r)"
    j0=$j
  else
    same "$j" "$(awk -v a="$j0" 'BEGIN { printf "%.17g", 10 * a }')" "1200 kg/m^3 is ten times the default 120 kg/m^3"
  fi
done
# the paper's satin: its .pyp and its table (satin1.json, r = 1 mm)
pyp=$HYLC_REFDATA/patterns/hylc2020/satin.pyp json=$HYLC_REFDATA/materials/satin1.json
if [ -f "$pyp" ] && [ -f "$json" ]; then
  $B/hylc-pattern -pattern_file "$pyp" >satin.txt 2>&1 || { cat satin.txt; die "hylc-pattern satin.pyp failed"; }
  t=$(sed -n 's/.*"density": *\([0-9.eE+-]*\).*/\1/p' "$json" | head -n 1)
  awk -v a="$(num satin.txt)" -v b="$t" 'BEGIN { d = (a - b) / b; if (d < 0) d = -d; exit !(d < 1e-4) }' || die "satin: hylc-pattern $(num satin.txt) against the table's $t"
fi
exit 0
