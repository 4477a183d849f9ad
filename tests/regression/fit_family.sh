#!/usr/bin/env bash
# The fit's family comes from the samples' provenance (issue 33): a stockinette sampled with
# -sampler_family stockinette is fitted with the stockinette's constants (-fit_reg 1e-2) without
# -fit_family, a plain weave without one as woven; -fit_family takes -sampler_family's names (woven,
# stockinette, honeycomb, rib) and the former "knit", overrides the provenance and says so, and an
# unknown name is refused. A samples file without provenance keeps the default (woven).
set -u
cd "$HYLC_TMP"
B=$HYLC_BIN
die() { echo "FAIL: $*"; exit 1; }
$B/hylc-sample -pattern_type stockinette -sampler_family stockinette -sampler_terms zero,sx -sampler_n1 12 -sampler_output st.h5 >st.txt 2>&1 || { cat st.txt; die "sampling the stockinette failed"; }
$B/hylc-sample -pattern_type plain -sampler_terms zero,sx -sampler_n1 12 -sampler_output pl.h5 >pl.txt 2>&1 || { cat pl.txt; die "sampling the plain weave failed"; }

fit() { # out args...: the fit's summary in out
  local out=$1
  shift
  $B/hylc-fit -fit_terms sx "$@" >"$out" 2>&1 || { cat "$out"; die "hylc-fit $* failed"; }
}
expect() { # file line...
  local f=$1
  shift
  for want in "$@"; do grep -qF -- "$want" "$f" || { cat "$f"; die "$f lacks '$want'"; }; done
}
fit a.txt -fit_input st.h5 -fit_json st.json
expect a.txt 'type: stockinette' 'family: stockinette (the samples'"'"' provenance: -sampler_family stockinette)' 'reg 0.01,'
fit b.txt -fit_input pl.h5
expect b.txt 'type: woven' 'family: woven (the samples'"'"' provenance: -sampler_family woven)' 'reg 0.001,'
# the same table as with the family given
fit c.txt -fit_input st.h5 -fit_family stockinette -fit_json st-given.json
expect c.txt 'family: stockinette (-fit_family)'
cmp -s st.json st-given.json || die "the provenance's stockinette and -fit_family stockinette give different tables"
# -fit_family overrides, and names what the samples were computed with; later options override the family's
fit d.txt -fit_input st.h5 -fit_family woven
expect d.txt 'type: woven' 'family: woven (-fit_family; the samples were computed with -sampler_family stockinette)' 'reg 0.001,'
fit e.txt -fit_input pl.h5 -fit_family knit
expect e.txt 'type: knit' 'reg 0.001,'
fit f.txt -fit_input pl.h5 -fit_family honeycomb -fit_reg 0.5
expect f.txt 'type: honeycomb' 'family: honeycomb (-fit_family; the samples were computed with -sampler_family woven)' 'reg 0.5,'
fit g.txt -fit_input st.h5 -fit_family RIB
expect g.txt 'reg 0.001,'
fit h.txt -fit_input st.h5 -fit_reg 0.003
expect h.txt 'type: stockinette' 'reg 0.003,'
# unknown names are refused
$B/hylc-fit -fit_input st.h5 -fit_family silk >x.txt 2>&1 && die "-fit_family silk accepted"
expect x.txt 'hylc: error: -fit_family silk: unknown family (woven, stockinette, honeycomb or rib'
# a file without provenance (the unit tests' writer): the default
"$B/../tests/test_fit_input" -test_write_samples np.h5 >w.txt 2>&1 || { cat w.txt; die "writing np.h5 failed"; }
fit i.txt -fit_input np.h5
expect i.txt 'type: woven' 'family: woven (the default)'
exit 0
