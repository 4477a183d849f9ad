#!/usr/bin/env bash
# tools/fabric_fidelity.py, the fabric-fidelity report (issue 39), on one pattern: a generated plain weave
# through tools/hylc-material on a coarse graded plan (3D terms included, about 1,700 samples, seconds), then
# the report: every path of the standard fabric tests for tile and table, the JSON export and the checks;
# the plain weave's strip tension along x and y within 5 % of its tile at 2-20 % with the lateral strain
# within 0.005 (what the fabric fit gives even on this plan); the collected document with its summary line;
# the tool's refusal of a directory without a table.
set -u
cd "$HYLC_TMP"
die() { echo "FAIL: $*"; exit 1; }
py=/usr/bin/python3
$py -c 'import h5py, numpy' 2>/dev/null || { echo "python3-h5py not installed"; exit 77; }
tool=$HYLC_ROOT/tools/fabric_fidelity.py
export HYLC_BIN MPIEXEC
printf 'pattern_type: plain\npattern_radius: 1.0e-3\nyarn_kc: 50\nsampler_family: woven\nsampler_graded_h0: 0.03,0.03,0.03,8,8\nsampler_graded_growth: 2.5\nsampler_graded_hmax: 0.4\nsampler_graded_sub: 1\n' >plain.yaml
$HYLC_ROOT/tools/hylc-material -no_plots -o m plain.yaml >m.txt 2>&1 || { cat m.txt; die "hylc-material failed"; }
for f in reference.pyp samples.h5 model.h5 model.json; do [ -s m/$f ] || die "m/$f missing"; done
grep -q 'leaves out the 3D terms sx-sa-sy' m/fit.txt || { cat m/fit.txt; die "the fit does not say what the JSON leaves out"; }

$py "$tool" --name plain plain.yaml m >r.txt 2>&1 || { cat r.txt; die "the report failed"; }
[ -s m/fidelity.json ] && [ -s m/fidelity.md ] || die "fidelity.json or fidelity.md missing"
grep -q 'checks met' m/fidelity.md || die "fidelity.md has no verdict"
grep -q 'JSON export `model.json`' m/fidelity.md || die "fidelity.md does not show the JSON export"
$py - <<'EOF' || die "the report's content"
import json, sys
r = json.load(open("m/fidelity.json"))
paths = r["paths"]
want = ["uniaxial x", "uniaxial y", "bias 45", "equibiaxial", "shear", "bending II00 +", "bending II00 -", "bending II11 +", "bending II11 -"]
assert sorted(paths) == sorted(want), sorted(paths)
for k, d in paths.items():
    assert len(d["tile"]) == len(d["values"]) and len(d["table"]) == len(d["values"]), k
    assert d["export"] is not None and len(d["export"]) == len(d["values"]), k
    assert all(row["converged"] == 1 for row in d["tile"]), "the tile's %s path did not converge" % k
assert r["stress0"] is not None and r["cpu_s"] > 0 and r["nsamples"] > 1000, (r["stress0"], r["cpu_s"], r["nsamples"])
for k in ("uniaxial x", "uniaxial y"):
    d = paths[k]
    lat = "sy" if k.endswith("x") else "sx"
    for a, b in zip(d["tile"], d["table"]):
        if a["value"] < 0.015:
            continue
        e = (b["force"] - a["force"]) / a["force"]
        print("%s at %g: T tile %.6g, table %.6g (%+.3f %%), lateral %.5f / %.5f" % (k, a["value"], a["force"], b["force"], 100 * e, a[lat], b[lat]))
        assert abs(e) <= 0.05, "%s at %g: T %+.2f %% off the tile" % (k, a["value"], 100 * e)
        assert abs(a[lat] - b[lat]) <= 0.005, "%s at %g: lateral %g, tile %g" % (k, a["value"], b[lat], a[lat])
EOF
$py "$tool" --collect doc.md m/fidelity.json >c.txt 2>&1 || { cat c.txt; die "--collect failed"; }
grep -q '^| plain | [0-9]*/45 |' doc.md || { head -20 doc.md; die "the summary line"; }
grep -q '^## plain' doc.md || die "the pattern's section"

# refusal: a directory without a table
mkdir -p empty
$py "$tool" plain.yaml empty >e.txt 2>&1 && die "a directory without a table was accepted"
grep -q 'cannot read empty/reference.pyp' e.txt || { cat e.txt; die "the message for a directory without a table"; }
echo "fabric_fidelity tool: $(tail -n 1 r.txt)"
