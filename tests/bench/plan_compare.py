#!/usr/bin/env python3
"""Compares the fits of a pattern's continued and cold samples on the plan's strains (bench_plan.sh, issue 27).

    plan_compare.py PATTERN SAMPLES.h5 PSI_COLD.txt PSI_CONT.txt PSI_PAPER.txt PAPER.json

SAMPLES.h5 gives the plan's strains and terms (row k of each PSI file is Psi at sample k, hylc-eval's
output). Per term t of the plan:
  - |Psi_cont - Psi_cold| / R_t at the term's strains, R_t = max |Psi_cold(z) - Psi_cold(0)| over the
    term (the term's range of Psi - C0, so that values of Psi near zero do not blow the measure up): the
    median and the 95th percentile, per term and pooled over the pattern's terms;
  - each fit's normalised RMS against the paper's table: the RMS of dPsi_fit - dPsi_paper (dPsi = Psi(z) -
    Psi(0)) over the term's strains inside the table's knot range, divided by max |dPsi_paper| there, in
    per cent, as examples/compare_tables.sh normalises.
Prints a Markdown table and one verdict line against the issue's targets (pooled median <= 0.5 %, pooled
95th percentile <= 5 %, the continued fit's NRMS at most 1 point above the cold fit's on every term).
Exit status 0 (the verdict is information, not a failure).
"""
import json
import sys

import h5py
import numpy as np


def load_psi(path):
    a = np.atleast_1d(np.loadtxt(path))
    return a[:, -1] if a.ndim > 1 else a


def knot_ranges(table):
    """The paper table's knot ranges in strain units: 1D per coordinate (0 sx, 1 sa, 2 sy, 3 II00, 4 II11)
    and 2D per pair of coordinates."""
    with open(table) as f:
        j = json.load(f)
    sig = j.get("strain scale", [1, 1, 1, 1, 1])
    r1 = {}
    for term in j["coeffs"].get("1D", []):
        k, t = term["k"], term["t"]
        r1[k] = (t[0] * sig[k], t[-1] * sig[k])
    r2 = {}
    for term in j["coeffs"].get("2D", []):
        a, b = term["k0"], term["k1"]
        r2[(a, b)] = ((term["tu"][0] * sig[a], term["tu"][-1] * sig[a]), (term["tv"][0] * sig[b], term["tv"][-1] * sig[b]))
    return r1, r2


COORD = [0, 1, 2, 3, 5]  # the table's coordinates in z = (sx, sa, sy, II00, II01, II11)
PAIRS = [(0, 1), (0, 2), (0, 3), (0, 4), (1, 2), (1, 3), (1, 4), (2, 3), (2, 4)]


def inside(z, ranges):
    ok = np.ones(len(z), bool)
    for c, (lo, hi) in ranges:
        x = z[:, COORD[c]]
        ok &= (x >= lo - 1e-12 * max(1.0, abs(lo))) & (x <= hi + 1e-12 * max(1.0, abs(hi)))
    return ok


def main():
    pattern, samples, fcold, fcont, fpaper, table = sys.argv[1:7]
    with h5py.File(samples, "r") as f:
        s = f["samples"]
        z, term = s["strain"][:], s["term"][:]
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in s.attrs["term_names"]]
    cold, cont, paper = load_psi(fcold), load_psi(fcont), load_psi(fpaper)
    zero = np.where(term == 0)[0]
    if len(zero) == 0:
        print("  %s: the plan has no zero sample; no comparison" % pattern)
        return 0
    i0 = zero[0]
    r1, r2 = knot_ranges(table)
    rows, pooled, worse = [], [], []
    for t in range(1, len(names)):
        idx = np.where(term == t)[0]
        if len(idx) == 0:
            continue
        rng = np.max(np.abs(cold[idx] - cold[i0]))
        d = np.abs(cont[idx] - cold[idx]) / rng if rng > 0 else np.zeros(len(idx))
        pooled.append(d)
        if t <= 5:
            c = t - 1
            ranges = [(c, r1[c])] if c in r1 else None
        else:
            a, b = PAIRS[t - 6]
            if (a, b) in r2:
                ranges = [(a, r2[(a, b)][0]), (b, r2[(a, b)][1])]
            elif a in r1 and b in r1:
                ranges = [(a, r1[a]), (b, r1[b])]
            else:
                ranges = None
        nrms = [float("nan"), float("nan")]
        if ranges is not None:
            k = idx[inside(z[idx], ranges)]
            dp = paper[k] - paper[i0]
            scale = np.max(np.abs(dp)) if len(k) else 0
            if scale > 0:
                for j, fit in enumerate((cold, cont)):
                    nrms[j] = 100 * np.sqrt(np.mean((fit[k] - fit[i0] - dp) ** 2)) / scale
        if nrms[1] > nrms[0] + 1:
            worse.append(names[t])
        rows.append((names[t], len(idx), 100 * np.median(d), 100 * np.percentile(d, 95), nrms[0], nrms[1]))
    allp = np.concatenate(pooled)
    med, p95 = 100 * np.median(allp), 100 * np.percentile(allp, 95)
    print("  %s: fits of the continued and the cold samples at the plan's %d strains (|Psi_cont - Psi_cold| / the term's range of Psi - C0), and each fit's normalised RMS against the paper's table (%%):" % (pattern, len(z)))
    print("  | term | n | median | 95th pct. | NRMS cold fit | NRMS continued fit |")
    print("  |---|---|---|---|---|---|")
    for name, n, m, p, a, b in rows:
        print("  | %s | %d | %.3f %% | %.2f %% | %.2f | %.2f%s |" % (name, n, m, p, a, b, " (> +1)" if b > a + 1 else ""))
    print("  | all | %d | %.3f %% | %.2f %% | | |" % (len(allp), med, p95))
    verdict = med <= 0.5 and p95 <= 5 and not worse
    print("  %s: pooled median %.3f %% (target <= 0.5 %%), 95th percentile %.2f %% (target <= 5 %%); continued NRMS more than 1 point above cold on %s: %s"
          % (pattern, med, p95, ", ".join(worse) if worse else "no term", "met" if verdict else "MISSED"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
