#!/usr/bin/python3
"""The figures of bench_uniaxial.sh (docs/fabric-uniaxial.md): reads DIR/<p>-<d>-{tile,ours,paper}.csv
(strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2) and DIR/<p>-<d>-tile.log, prints T at s = 5, 10, 20 %
from the tile, our table and the paper's table with the relative differences to the tile and the target
(<= 3 %) met or missed, the Poisson ratio at 5 %, the tile's solve statistics and the jumps of its path, and
draws DIR/fabric-uniaxial-<p>.png (T(s) and the lateral stretch, along x and y) when matplotlib is there.

    uniaxial_compare.py DIR pattern [pattern ...]
"""
import os
import re
import sys

import numpy as np

POINTS = (0.05, 0.10, 0.20)
TARGET = 0.03
DIRS = ("x", "y")


def read(path):
    if not os.path.exists(path):
        return None
    a = np.genfromtxt(path, delimiter=",", names=True)
    return {"s": np.atleast_1d(a["strain"]), "T": np.atleast_1d(a["T_N_per_m"]),
            "sa": np.atleast_1d(a["lateral_strain_sa"]), "s2": np.atleast_1d(a["lateral_strain_s2"])}


def at(c, s, key="T"):
    i = np.flatnonzero(np.abs(c["s"] - s) < 1e-9)
    return float(c[key][i[0]]) if len(i) else float("nan")


def tile_stats(log):
    """states, not converged, gradient-test stops, solves, solves not converged, micro iterations"""
    st = dict(states=0, notconv=0, gradient=0, solves=0, failed=0, its=0)
    if not os.path.exists(log):
        return st
    for line in open(log):
        m = re.search(r"(\d+) Newton steps, (\d+) solves \((\d+) not converged\), (\d+) micro iterations", line)
        if not line.startswith("uniaxial") or not m:
            continue
        st["states"] += 1
        st["notconv"] += "NOT CONVERGED" in line
        st["gradient"] += "gradient test" in line
        st["solves"] += int(m.group(2))
        st["failed"] += int(m.group(3))
        st["its"] += int(m.group(4))
    return st


def jumps(c):
    """stretches where the tile's path jumps: T falls, or a lateral strain changes in one step by more than 0.01
    and by more than 3x its change in each neighbouring step (a discontinuity, not a steady drift)"""
    out = []
    if c is None or len(c["s"]) < 3:
        return out
    for key in ("s2", "sa"):
        d = np.abs(np.diff(c[key]))
        for i in range(len(d)):
            nb = max(d[i - 1] if i > 0 else 0, d[i + 1] if i + 1 < len(d) else 0)
            if d[i] > 0.01 and d[i] > 3 * nb:
                out.append("%s %.4g -> %.4g between s = %.4g and %.4g" % (key, c[key][i], c[key][i + 1], c["s"][i], c["s"][i + 1]))
    for i in np.flatnonzero(np.diff(c["T"]) < 0):
        out.append("T falls %.4g -> %.4g between s = %.4g and %.4g" % (c["T"][i], c["T"][i + 1], c["s"][i], c["s"][i + 1]))
    return out


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    d, pats = sys.argv[1], sys.argv[2:]
    other = {"x": "sy", "y": "sx"}
    print("== uniaxial tension, T = dPsi/ds (N/m) at the lateral strains minimizing Psi: the yarn tile (hylc-solve")
    print("   -solve_uniaxial) against our full-plan table and the paper's; differences relative to the tile;")
    print("   target |ours/tile - 1| <= %.0f %%" % (100 * TARGET))
    print("%-12s %-3s %5s %11s %11s %8s %-7s %11s %8s   %s" % ("pattern", "dir", "s", "T tile", "T ours", "ours", "target", "T paper", "paper", "lateral stretch tile / ours / paper"))
    met = missed = 0
    summary = []
    for p in pats:
        for di in DIRS:
            t = read(os.path.join(d, "%s-%s-tile.csv" % (p, di)))
            o = read(os.path.join(d, "%s-%s-ours.csv" % (p, di)))
            q = read(os.path.join(d, "%s-%s-paper.csv" % (p, di)))
            if t is None or o is None:
                print("%-12s %-3s missing curves" % (p, di))
                missed += len(POINTS)
                continue
            worst = 0
            for s in POINTS:
                tt, to = at(t, s), at(o, s)
                tq = at(q, s) if q is not None else float("nan")
                ro, rq = to / tt - 1, tq / tt - 1
                ok = abs(ro) <= TARGET
                met += ok
                missed += not ok
                worst = max(worst, abs(ro))
                print("%-12s %-3s %4.0f%% %11.4g %11.4g %+7.1f%% %-7s %11.4g %+7.1f%%   %s %+.4f / %+.4f / %+.4f" % (
                    p, di, 100 * s, tt, to, 100 * ro, "met" if ok else "MISSED", tq, 100 * rq, other[di],
                    at(t, s, "s2"), at(o, s, "s2"), at(q, s, "s2") if q is not None else float("nan")))
            summary.append((p, di, worst))
    print("target met at %d of %d points" % (met, met + missed))
    for p, di, worst in summary:
        print("  %-12s %s: largest |ours/tile - 1| %.1f %% -> %s" % (p, di, 100 * worst, "met" if worst <= TARGET else "MISSED"))
    print("== Poisson ratio -%s/s at s = 5 %% (x: -sy/sx, y: -sx/sy): tile / ours / paper" % "s2")
    for p in pats:
        for di in DIRS:
            cs = [read(os.path.join(d, "%s-%s-%s.csv" % (p, di, w))) for w in ("tile", "ours", "paper")]
            print("  %-12s %s: %s" % (p, di, " / ".join("%.3f" % (-at(c, 0.05, "s2") / 0.05) if c is not None else "-" for c in cs)))
    print("== path dependence of the tile: T on the path in steps of 2.5 % against the path in steps of 1.25 %")
    for p in pats:
        for di in DIRS:
            a = read(os.path.join(d, "%s-%s-tile.csv" % (p, di)))
            b = read(os.path.join(d, "%s-%s-tile2.csv" % (p, di)))
            if a is None or b is None:
                continue
            print("  %-12s %s: %s" % (p, di, ", ".join("%g %%: %+.3f %%" % (100 * s, 100 * (at(b, s) / at(a, s) - 1)) for s in POINTS)))
    print("== the tile's paths (16 stretches each, 1.25 % apart, each continued from the one before)")
    for p in pats:
        for di in DIRS:
            st = tile_stats(os.path.join(d, "%s-%s-tile.log" % (p, di)))
            tf = os.path.join(d, "%s-%s-tile.time" % (p, di))
            wall = open(tf).read().strip() if os.path.exists(tf) else "?"
            print("  %-12s %s: %d states, %d not converged (%d by the gradient test), %d solves (%d not converged, retried cold),"
                  " %d Newton iterations, %s s wall" % (p, di, st["states"], st["notconv"], st["gradient"], st["solves"], st["failed"], st["its"], wall))
            for j in jumps(read(os.path.join(d, "%s-%s-tile.csv" % (p, di)))):
                print("      jump: %s" % j)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("(matplotlib not installed: no plots)")
        return 0
    for p in pats:
        fig, ax = plt.subplots(2, 2, figsize=(10, 7), sharex=True, constrained_layout=True)
        for j, di in enumerate(DIRS):
            for w, style, label in (("tile", "ko-", "yarn tile (microscale)"), ("ours", "b-", "our full-plan table"), ("paper", "r--", "paper's table")):
                c = read(os.path.join(d, "%s-%s-%s.csv" % (p, di, w)))
                if c is None:
                    continue
                ax[0, j].plot(100 * c["s"], c["T"], style, ms=3, label=label)
                ax[1, j].plot(100 * c["s"], 100 * c["s2"], style, ms=3, label=label)
            ax[0, j].set_title("%s, stretch along %s" % (p, di))
            ax[0, j].set_ylabel("T = dPsi/ds (N/m)")
            ax[1, j].set_ylabel("lateral stretch %s (%%)" % other[di])
            ax[1, j].set_xlabel("stretch s (%)")
            for s in POINTS:
                ax[0, j].axvline(100 * s, color="0.85", lw=0.8, zorder=0)
            ax[0, j].legend(fontsize=8)
            ax[0, j].grid(alpha=0.3)
            ax[1, j].grid(alpha=0.3)
        png = os.path.join(d, "fabric-uniaxial-%s.png" % p)
        fig.savefig(png, dpi=90)
        plt.close(fig)
        print("wrote %s" % png)
    return 0


if __name__ == "__main__":
    sys.exit(main())
