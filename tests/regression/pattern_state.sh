#!/usr/bin/env bash
# A .pyp written by hylc records what the tile is (issue 33): hylc-pattern's generated tile says
# "generated", the reference state of hylc-sample "reference", hylc-solve's solved tile "equilibrium",
# in the comment of the *pattern header (which every reader skips). hylc-sample computes the reference
# state of a .pyp that is not one, says which it did, and gets the same reference state and samples as
# from the generator given directly; a reference state is used as given, and a file without the record
# (the paper's .pyp files) is taken as a stored reference state and relaxed to rest under the configured
# yarn (-sampler_reference auto; issue 39), with no stress-free rounds of Algorithm C1.
set -u
cd "$HYLC_TMP"
B=$HYLC_BIN
die() { echo "FAIL: $*"; exit 1; }
run() { # out command...
  local out=$1
  shift
  "$@" >"$out" 2>&1 || { cat "$out"; die "$* failed"; }
}
has() { grep -qF -- "$2" "$1" || { cat "$1"; die "$1 lacks '$2'"; }; }
hasnt() { ! grep -qF -- "$2" "$1" || { cat "$1"; die "$1 has '$2'"; }; }
run gen.txt $B/hylc-pattern -pattern_type plain -pattern_output p.pyp
has gen.txt 'state: generated (not a reference state)'
head -n 1 p.pyp | grep -q '^\*pattern # px py radius num_vertedges; hylc state: generated' || { head -n 2 p.pyp; die "p.pyp does not record 'generated'"; }
run back.txt $B/hylc-pattern -pattern_file p.pyp
has back.txt 'state: generated (not a reference state)'

# the generated .pyp: hylc-sample computes its reference state, the same as from the generator itself
run a.txt $B/hylc-sample -pattern_file p.pyp -sampler_terms zero,sx -sampler_n1 4 -sampler_output a.h5 -reference_output ra.pyp
has a.txt '[reference] the pattern file is not a reference state (generated): computing it (Algorithm C1)'
has a.txt '[reference] reference state: periods scaled by'
run b.txt $B/hylc-sample -pattern_type plain -sampler_terms zero,sx -sampler_n1 4 -sampler_output b.h5 -reference_output rb.pyp
has b.txt '[reference] a generated pattern: computing its reference state (Algorithm C1)'
head -n 1 ra.pyp | grep -q 'hylc state: reference$' || { head -n 1 ra.pyp; die "the reference state does not record 'reference'"; }
cmp -s ra.pyp rb.pyp || die "the reference state of the generated .pyp differs from the generator's"
if command -v h5dump >/dev/null; then
  h5dump -d /samples/psi a.h5 | sed -n '/DATA {/,/}/p' | head -n 3 >psi-a.txt
  h5dump -d /samples/psi b.h5 | sed -n '/DATA {/,/}/p' | head -n 3 >psi-b.txt
  grep -q '(0): ' psi-a.txt || { cat psi-a.txt; die "no psi in a.h5"; }
  cmp -s psi-a.txt psi-b.txt || { cat psi-a.txt psi-b.txt; die "the samples of the generated .pyp differ from the generator's"; }
fi
# a reference state is used as given
run c.txt $B/hylc-sample -pattern_file ra.pyp -sampler_terms zero -sampler_output c.h5
has c.txt '[reference] the pattern file records a reference state: used as given'
hasnt c.txt 'stress-free round'
# a .pyp without the record (as the paper's files): a stored reference state, relaxed (not recomputed)
sed '1s/; hylc state: .*//' p.pyp >old.pyp
head -n 1 old.pyp | grep -qx '\*pattern # px py radius num_vertedges' || die "could not strip the record"
run d.txt $B/hylc-sample -pattern_file old.pyp -sampler_terms zero -sampler_output d.h5
has d.txt '[reference] the pattern file is a stored reference state (it records nothing, as the paper'"'"'s files): relaxed to the in-plane minimum under the configured yarn'
hasnt d.txt 'stress-free round'
run e.txt $B/hylc-pattern -pattern_file old.pyp -pattern_output old2.pyp
has e.txt 'state: not recorded in the file (taken as its own reference state)'
head -n 1 old2.pyp | grep -q 'hylc state: reference$' || die "a file without the record is not rewritten as a reference state"
# -sampler_reference still decides when given
run f.txt $B/hylc-sample -pattern_file p.pyp -sampler_reference none -sampler_terms zero -sampler_output f.h5
hasnt f.txt '[reference]'
# hylc-solve's solved tile is an equilibrium, not a reference state
run g.txt $B/hylc-solve -pattern_file ra.pyp -strain 0.02,0,0,0,0,0 -solve_output eq.pyp
head -n 1 eq.pyp | grep -q 'hylc state: equilibrium' || { head -n 1 eq.pyp; die "the solved tile does not record 'equilibrium'"; }
run h.txt $B/hylc-sample -pattern_file eq.pyp -sampler_terms zero -sampler_output h.h5
has h.txt '[reference] the pattern file is not a reference state (equilibrium): computing it (Algorithm C1)'
exit 0
