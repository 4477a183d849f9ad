#!/usr/bin/env bash
# The run identity (issue 12, Deliver 1): a resume is refused, before any solve, when the pattern differs
# past vertex 0 (naming the field), when an option that changes results is added, removed or changed
# (naming it with its values), and for a journal of the earlier format (saying how to start over);
# options that cannot change results are accepted. The HDF5 file's /provenance holds the digest (the
# journal's), the identity text whose SHA-256 it is, the options and the pattern field digests.
set -u
cd "$HYLC_TMP"
tool=$HYLC_BIN/hylc-sample
die() { echo "FAIL: $*"; exit 1; }
$HYLC_BIN/hylc-pattern -pattern_type plain -pattern_output p.pyp >/dev/null 2>&1 || die "hylc-pattern failed"
args=(-pattern_type file -pattern_file p.pyp -yarn_kc 50 -sampler_terms zero,sx -sampler_n1 2 -sampler_progress 100 -micro_rtol 1e-8)
"$tool" "${args[@]}" -sampler_output s.h5 >run.txt 2>&1 || { cat run.txt; die "first run failed"; }
refused() { # regex args...
  local re=$1; shift
  "$tool" "$@" -sampler_output s.h5 -sampler_resume >out.txt 2>&1 && { cat out.txt; die "resume accepted: $*"; }
  grep -Eq -- "$re" out.txt || { cat out.txt; die "unclear message for: $*"; }
  [ "$(grep -c . out.txt)" = 1 ] || { cat out.txt; die "not one line: $*"; }
}
# the pattern changed past vertex 0 (the z of vertex 5; the same vertex count and periods)
awk 'NR == 10 { $3 = $3 * 1.0001 } { print }' p.pyp >q.pyp
cmp -s p.pyp q.pyp && die "q.pyp equals p.pyp"
refused "belongs to a different run: pattern field X differs(; pattern field [a-z_0-9]+ differs)*\. Resume with that run's settings, or start over with -sampler_overwrite" "${args[@]}" -pattern_file q.pyp
# options added, removed, changed; a neutral option (monitor) accepted
refused "option -periodic_slide added \('none'\)" "${args[@]}" -periodic_slide none
refused "option -micro_rtol removed \(was '1e-8'\)" "${args[@]:0:${#args[@]}-2}"
refused "option -yarn_kc changed from '50' to '50.0'" "${args[@]}" -yarn_kc 50.0
# the same settings, a different spelling of the pattern's path and neutral options: accepted
cp p.pyp copy.pyp
"$tool" "${args[@]}" -pattern_file copy.pyp -sampler_output s.h5 -sampler_resume -micro_snes_monitor_cancel -log_view_memory 0 -sampler_progress 1 >ok.txt 2>&1 || { cat ok.txt; die "a neutral change was refused"; }
grep -q '; 3 already done' ok.txt || { cat ok.txt; die "resume recomputed"; }
# /provenance
command -v h5dump >/dev/null || { echo "h5dump (hdf5-tools) not installed"; exit 77; }
digest=$(h5dump -a /provenance/digest s.h5 | sed -n 's/.*(0): "\([0-9a-f]*\)".*/\1/p')
[ ${#digest} = 64 ] || die "no digest in /provenance"
[ "$(od -An -tx1 -j32 -N32 s.h5.journal | tr -d ' \n')" = "$digest" ] || die "the journal's digest differs from the file's"
h5dump -d /provenance/options s.h5 | grep -q '"-yarn_kc 50"' || die "/provenance/options lacks -yarn_kc 50"
h5dump -d /provenance/options s.h5 | grep -q 'sampler_output\|pattern_file' && die "/provenance/options holds a neutral option"
h5dump -d /provenance/pattern s.h5 | grep -q '"X sha256:[0-9a-f]\{64\}"' || die "/provenance/pattern lacks the digest of X"
if /usr/bin/python3 -c 'import h5py' 2>/dev/null; then
  /usr/bin/python3 - s.h5 <<'PY' || die "h5py checks of /provenance failed"
import sys, h5py, hashlib
f = h5py.File(sys.argv[1], "r")
p = f["provenance"]
text = p["identity"].asstr()[()]
assert hashlib.sha256(text.encode()).hexdigest() == p.attrs["digest"], "digest is not the SHA-256 of the identity"
opts = [o.decode() if isinstance(o, bytes) else o for o in p["options"][:]]
assert "-micro_rtol 1e-8" in opts and opts == sorted(opts), opts
assert p.attrs["hylc_version"] and p.attrs["petsc_version"].count(".") == 2
PY
fi
# a journal of the previous format (version 2, records without the start) is refused, saying how to start over
printf '\002' | dd of=s.h5.journal bs=1 seek=12 conv=notrunc status=none
refused "written by an earlier hylc \(journal format 2, records without the start.*start over with -sampler_overwrite" "${args[@]}"
# a journal of the earlier format (version 1) is refused, saying how to start over
printf '\001' | dd of=s.h5.journal bs=1 seek=12 conv=notrunc status=none
refused "written by an earlier hylc \(journal format 1.*start over with -sampler_overwrite" "${args[@]}"
"$tool" "${args[@]}" -sampler_output s.h5 >out.txt 2>&1 && die "a new run replaced an old-format journal"
"$tool" "${args[@]}" -sampler_output s.h5 -sampler_overwrite >out.txt 2>&1 || { cat out.txt; die "-sampler_overwrite of an old journal failed"; }
exit 0
