#!/usr/bin/python3
"""The report of tools/hylc-material: DIR/report.md, from the files of the run in DIR.

    /usr/bin/python3 tools/material_report.py DIR OPTIONS.yaml BIN [OPTION VALUE ...]

Reads DIR/samples.h5 (counts, per-sample solve times, provenance), DIR/fit.txt (hylc-fit's summary: the
family, the area density, per term the knots, samples and residuals), DIR/plots/ (the PNGs of
examples/plot_fit.py, when drawn) and DIR/.hylc-material/cost (wall time and ranks of each sampling
invocation). Writes DIR/report.md (through a temporary, renamed). Needs numpy and h5py.
"""
import os
import re
import subprocess
import sys

import h5py
import numpy as np


def text(v):
    """An HDF5 attribute or scalar string as str."""
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray) and v.shape == ():
        return text(v[()])
    return str(v)


def fit_summary(path):
    """hylc-fit's summary: header lines (key -> value) and one dict per fitted term."""
    head, terms = {}, []
    if not os.path.exists(path):
        return head, terms
    lines = open(path).read().splitlines()
    term_re = re.compile(r"^\s+(\S+)\s+(\S+ knots)\s+(\d+) samples, (.*); RMS residual (\S+) J/m\^2 \((\S+)% of max \|psi - f0\| (\S+)\)")
    band_re = re.compile(r"relative error of psi - f0 by band \(samples\): small (.*), moderate (.*), large (.*)$")
    for line in lines:
        m = term_re.match(line)
        if m:
            terms.append({"term": m.group(1), "knots": m.group(2), "n": int(m.group(3)), "range": m.group(4),
                          "rms": m.group(5), "pct": m.group(6), "max": m.group(7)})
            continue
        m = band_re.search(line)
        if m and terms:
            terms[-1]["bands"] = m.groups()
            continue
        m = re.match(r"^\s+(type|family|area density|f0|samples|input|strain scale): (.*)$", line)
        if m:
            head[m.group(1)] = m.group(2)
        m = re.match(r"^\s+(\S+)\s+not fitted \((.*)\)$", line)
        if m:
            terms.append({"term": m.group(1), "missing": m.group(2)})
    return head, terms


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    d, cfg, bindir, extra = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    samples = os.path.join(d, "samples.h5")
    out = []
    w = out.append
    name = os.path.basename(d.rstrip("/"))
    w("# Material table: %s\n" % name)
    w("Made by `tools/hylc-material %s%s` (the study's options file, then the options given to every stage).\n"
      % (cfg, "".join(" " + a for a in extra)))
    w("| file | what |\n|---|---|")
    for f, what in [("model.json", "the table for ARCSim-HYLC (docs/material.md)"), ("model.h5", "the table as HDF5, with the fit's options"),
                    ("samples.h5", "the microscale samples (docs/output-format.md)"), ("reference.pyp", "the reference state the samples were computed on"),
                    ("fit.txt", "hylc-fit's summary"), ("sample.log", "hylc-sample's output")]:
        if os.path.exists(os.path.join(d, f)):
            w("| `%s` | %s (%d bytes) |" % (f, what, os.path.getsize(os.path.join(d, f))))
    w("")

    head, terms = fit_summary(os.path.join(d, "fit.txt"))
    w("## Fit\n")
    for k in ("family", "area density", "f0", "strain scale", "samples"):
        if k in head:
            w("- %s: %s" % (k, head[k]))
    w("")
    w("Per term: knots, samples, the RMS residual of the model against the samples (J/m², and in % of the term's")
    w("largest |ψ − f0|), and the relative error of ψ − f0 in three strain bands (small: |s| ≤ 5 %, |II| ≤ 20 1/m;")
    w("moderate: ≤ 20 %, 80 1/m; large), with their sample counts.\n")
    w("| term | knots | samples | data range | RMS residual (J/m²) | % of max | small | moderate | large |")
    w("|---|---|---|---|---|---|---|---|---|")
    for t in terms:
        if "missing" in t:
            w("| %s | not fitted (%s) | | | | | | | |" % (t["term"], t["missing"]))
            continue
        b = t.get("bands", ("", "", ""))
        w("| %s | %s | %d | %s | %s | %s | %s | %s | %s |" % (t["term"], t["knots"], t["n"], t["range"], t["rms"], t["pct"], b[0], b[1], b[2]))
    w("")
    plots = os.path.join(d, "plots")
    if os.path.isdir(plots):
        w("### Plots\n")
        w("Samples, the fitted model and (2D terms) the residual model − data, per term (examples/plot_fit.py).\n")
        for t in terms:
            png = os.path.join(plots, t["term"] + ".png")
            if os.path.exists(png):
                w("![%s](plots/%s.png)\n" % (t["term"], t["term"]))

    w("## Cost\n")
    with h5py.File(samples, "r") as f:
        n = int(f.attrs.get("nsamples", 0))
        conv = int(f.attrs.get("nconverged", 0))
        done = int(f.attrs.get("ndone", 0))
        st = f["samples/status"][()] if "samples/status" in f else np.zeros(0)
        tsolve = f["samples/time"][()] if "samples/time" in f else None
        w("- samples: %d of the plan, %d computed, %d converged (status 0), %d not converged" % (n, done, conv, int(np.sum(st > 0))))
        if tsolve is not None:
            ok = np.isfinite(tsolve) & (st >= 0)
            w("- solve time: %.1f CPU-s in all, %.4g s per sample (mean), %.4g s the slowest" % (float(np.sum(tsolve[ok])), float(np.mean(tsolve[ok])) if ok.any() else 0.0, float(np.max(tsolve[ok])) if ok.any() else 0.0))
        cost = os.path.join(d, ".hylc-material", "cost")
        if os.path.exists(cost):
            runs = [tuple(map(float, l.split())) for l in open(cost) if l.strip()]
            wall = sum(r[0] for r in runs)
            w("- sampling (the reference state included): %d invocation%s of hylc-sample, %.1f s wall, %.1f rank-s (wall x ranks)" % (len(runs), "" if len(runs) == 1 else "s", wall, sum(r[0] * r[1] for r in runs)))
        w("")

        w("## Provenance\n")
        try:
            ver = subprocess.run([os.path.join(bindir, "hylc-fit"), "-version"], capture_output=True, text=True, timeout=60).stdout.strip().splitlines()
        except (OSError, subprocess.SubprocessError):
            ver = []
        if ver:
            w("- programs: " + "; ".join(ver))
        for a in ("hylc_version", "petsc_version", "hdf5_version", "creation_date", "hostname"):
            if a in f.attrs:
                w("- samples `%s`: %s" % (a, text(f.attrs[a]).strip()))
        if "provenance" in f:
            p = f["provenance"]
            for a in ("digest", "hylc_build"):
                if a in p.attrs:
                    w("- run identity `%s`: %s" % (a, text(p.attrs[a])))
            if "options" in p:
                opts = [text(o) for o in p["options"][()]]
                w("\nThe options of the run identity (`/provenance/options`; the identity also holds the pattern bit for bit):\n")
                w("```")
                w("\n".join(opts))
                w("```")
    w("")
    tmp = os.path.join(d, "report.md.tmp")
    with open(tmp, "w") as fp:
        fp.write("\n".join(out))
    os.replace(tmp, os.path.join(d, "report.md"))


if __name__ == "__main__":
    main()
