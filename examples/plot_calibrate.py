#!/usr/bin/python3
"""Pictures of a calibration (hylc-calibrate -calibrate_dump d.csv; docs/calibrate.md).

    /usr/bin/python3 examples/plot_calibrate.py [--dpi 110] DUMP OUTDIR

DUMP     the CSV written by hylc-calibrate -calibrate_dump: one row per sample with index, term, the strain
         (sx, sa, sy, II00, II01, II11), the target Psi and the model's Psi with the initial and with the
         calibrated parameters (J/m^2), and the two solver statuses (0 = converged). Row 0 is the base
         strain z_b; every curve is drawn as dPsi = Psi - Psi(z_b).
OUTDIR   created if needed; receives one PNG per term:
         1D terms   <term>.png: dPsi of the target, the initial and the calibrated model against the strain
         2D terms   <term>.png: dPsi of the three against the sample number (the grid in plan order)
         other      other.png (rows off the plan's axes) likewise
         and index.txt with, per term, the normalised RMS of dPsi (divided by the largest |dPsi_target|)
         before and after.

Needs Debian's python3-numpy and python3-matplotlib (use /usr/bin/python3).
"""
import csv
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COORD = {"sx": 0, "sa": 1, "sy": 2, "II00": 3, "II11": 5}
UNITS = {"sx": "", "sa": "", "sy": "", "II00": " [1/m]", "II11": " [1/m]"}


def main(argv):
    dpi = 110
    args = list(argv)
    if len(args) >= 2 and args[0] == "--dpi":
        dpi = int(args[1])
        args = args[2:]
    if len(args) != 2:
        sys.stderr.write(__doc__)
        return 2
    dump, outdir = args
    with open(dump, newline="") as fp:
        rows = list(csv.DictReader(fp))
    if not rows or "calibrated" not in rows[0]:
        sys.stderr.write("%s: not a hylc-calibrate dump (no 'calibrated' column)\n" % dump)
        return 1
    os.makedirs(outdir, exist_ok=True)
    strain = np.array([[float(r[k]) for k in ("sx", "sa", "sy", "II00", "II01", "II11")] for r in rows])
    target = np.array([float(r["target"]) for r in rows])
    init = np.array([float(r["initial"]) for r in rows])
    cal = np.array([float(r["calibrated"]) for r in rows])
    ok0 = np.array([int(r["status_initial"]) == 0 for r in rows])
    ok1 = np.array([int(r["status_calibrated"]) == 0 for r in rows])
    terms = [r["term"] for r in rows]
    dt, d0, d1 = target - target[0], init - init[0], cal - cal[0]
    lines = ["term  n  rms_before  rms_after  (normalised by max |dPsi_target|)"]
    for term in dict.fromkeys(terms[1:]):
        sel = np.array([t == term for t in terms])
        rng = np.max(np.abs(dt[sel])) or 1.0
        r0 = np.sqrt(np.mean((d0[sel & ok0] - dt[sel & ok0]) ** 2)) / rng if np.any(sel & ok0) else np.nan
        r1 = np.sqrt(np.mean((d1[sel & ok1] - dt[sel & ok1]) ** 2)) / rng if np.any(sel & ok1) else np.nan
        lines.append("%-8s %3d  %8.3f%%  %8.3f%%" % (term, sel.sum(), 100 * r0, 100 * r1))
        fig, ax = plt.subplots(figsize=(5.5, 4))
        if term in COORD:
            x = strain[sel, COORD[term]]
            order = np.argsort(x)
            xlabel = term + UNITS[term]
        else:
            x = np.arange(sel.sum())
            order = x
            xlabel = "sample of the %s term (plan order)" % term
        ax.plot(x[order], dt[sel][order], "k-o", ms=3, label="target")
        ax.plot(x[order], d0[sel][order], "--", color="tab:blue", label="initial (RMS %.2g%%)" % (100 * r0))
        ax.plot(x[order], d1[sel][order], "-", color="tab:red", label="calibrated (RMS %.2g%%)" % (100 * r1))
        bad = sel & ~ok1
        if np.any(bad):
            xb = strain[bad, COORD[term]] if term in COORD else np.flatnonzero(bad[sel])
            ax.plot(xb, d1[bad], "x", color="tab:red", label="not converged")
        ax.set_xlabel(xlabel)
        ax.set_ylabel(r"$\Delta\Psi$ [J/m$^2$]")
        ax.set_title("%s: target, initial and calibrated" % term)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(outdir, term + ".png"), dpi=dpi)
        plt.close(fig)
    lines.append("zero     Psi(z_b)/target  %.4f -> %.4f" % (init[0] / target[0], cal[0] / target[0]))
    with open(os.path.join(outdir, "index.txt"), "w") as fp:
        fp.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print("wrote %s/*.png and index.txt" % outdir)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
