#!/usr/bin/env python3
"""Draws the pictures of docs/gallery.md: the yarn centrelines of every pattern generator of hylc-pattern
(at its default parameters) and of every paper pattern ($HYLC_REFDATA/patterns/hylc2020/*.pyp, read in
place, never copied), seen from above, 2 x 2 periods, one colour per yarn loop, the yarns drawn with
0.6 of their diameter and in the order of their height (the upper yarn covers the lower one where they cross),
the tile's period as a dashed box. Prints the size of each pattern (the summary of hylc-pattern) as rows
of the gallery's table.

    /usr/bin/python3 tools/gallery.py [--bin build/bin] [--refdata ../shared/refdata] [--out docs/img]

Needs Debian's python3-matplotlib (and numpy); writes docs/img/gallery-<name>.png (< 100 kB each).
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

GENERATORS = ["plain", "basket", "twill", "satin", "stockinette", "rib"]
PAPER = ["basket", "satin", "stockinette", "cartridge_belt_rib", "slip_stitch_honeycomb", "satin_small", "stockinette_small"]


def read_pyp(path):
    """periods, radius, positions (N, 3) and edges (N, 4) of a .pyp file (docs/patterns.md)"""
    blocks, name = {}, None
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            if line.startswith("*"):
                name = line[1:].split()[0]
                blocks[name] = []
            elif name:
                blocks[name].append([float(x) for x in line.split()])
    px, py, r, n = blocks["pattern"][0]
    Q = np.array(blocks["Q"])[:, :3]
    E = np.array(blocks["E"]).astype(int)
    return px, py, r, Q, E


def loops_of(E, n):
    """the loop index of every vertex, following each vertex's outgoing edge"""
    nxt = {int(v0): int(v1) for v0, v1, _, _ in E}
    loop = -np.ones(n, int)
    k = 0
    for v in range(n):
        if loop[v] >= 0:
            continue
        while loop[v] < 0:
            loop[v] = k
            v = nxt[v]
        k += 1
    return loop, k


def summary(hylc_pattern, args):
    """the pattern summary lines of hylc-pattern (vertices, loops, periods, radius)"""
    out = subprocess.run([hylc_pattern] + args, check=True, capture_output=True, text=True).stdout
    get = lambda key: re.search(r"^\s*%s: (.*)$" % key, out, re.M).group(1)
    px, py = (float(x) for x in get("periods").split())
    return {"vertices": int(get("vertices")), "loops": int(get("loops")), "px": px, "py": py, "radius": float(get("radius"))}


def draw(path, title, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Rectangle

    px, py, r, Q, E = read_pyp(path)
    loop, nloops = loops_of(E, len(Q))
    cmap = plt.get_cmap("tab10")
    segs, cols, zs = [], [], []
    zmin, zmax = Q[:, 2].min(), Q[:, 2].max()
    for v0, v1, di, dj in E:
        a = Q[v0]
        b = Q[v1] + np.array([di * px, dj * py, 0.0])
        base = np.array(cmap(loop[v0] % 10)[:3])
        h = 0.5 if zmax <= zmin else ((a[2] + b[2]) / 2 - zmin) / (zmax - zmin)
        col = base * (0.55 + 0.45 * h)  # lower parts darker
        for ti in range(2):
            for tj in range(2):
                s = np.array([ti * px, tj * py])
                segs.append([a[:2] + s, b[:2] + s])
                cols.append(col)
                zs.append((a[2] + b[2]) / 2)
    order = np.argsort(zs, kind="stable")
    lo = np.min(np.array(segs).reshape(-1, 2), axis=0) - r
    hi = np.max(np.array(segs).reshape(-1, 2), axis=0) + r
    size = 3.0  # inches
    fig, ax = plt.subplots(figsize=(size, size * (hi[1] - lo[1]) / (hi[0] - lo[0]) + 0.35))
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    fig.canvas.draw()
    bbox = ax.get_window_extent()
    pts_per_m = bbox.width / fig.dpi * 72 / (hi[0] - lo[0])
    lw = max(0.5, 0.6 * 2 * r * pts_per_m)  # 0.6 of the diameter: the centrelines stay visible
    # lowest segments first, in chunks (one collection per segment would be slow)
    chunks = np.array_split(order, max(1, min(40, len(order) // 8)))
    for c in chunks:
        ax.add_collection(LineCollection([segs[i] for i in c], colors=[cols[i] for i in c], linewidths=lw, capstyle="round"))
    x0 = Q[:, 0].min()
    y0 = Q[:, 1].min()
    ax.add_patch(Rectangle((x0, y0), px, py, fill=False, ls="--", lw=0.9, ec="k", zorder=10))
    ax.set_title("%s (%d loops)" % (title, nloops), fontsize=8)
    ax.set_xticks([])
    ax.set_yticks([])
    fig.tight_layout(pad=0.2)
    fig.savefig(png, dpi=80)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--bin", default=os.path.join(top, "build", "bin"))
    ap.add_argument("--refdata", default=os.environ.get("HYLC_REFDATA", os.path.join(top, "..", "shared", "refdata")))
    ap.add_argument("--out", default=os.path.join(top, "docs", "img"))
    a = ap.parse_args()
    hp = os.path.join(a.bin, "hylc-pattern")
    os.makedirs(a.out, exist_ok=True)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for g in GENERATORS:
            pyp = os.path.join(tmp, g + ".pyp")
            s = summary(hp, ["-pattern_type", g, "-pattern_output", pyp])
            png = os.path.join(a.out, "gallery-gen-%s.png" % g)
            draw(pyp, "generator %s" % g, png)
            rows.append(("generator `%s`" % g, s, png))
        pdir = os.path.join(a.refdata, "patterns", "hylc2020")
        for p in PAPER:
            pyp = os.path.join(pdir, p + ".pyp")
            if not os.path.exists(pyp):
                print("note: %s not found: the paper patterns are not drawn (README: the paper's patterns and tables)" % pyp, file=sys.stderr)
                break
            s = summary(hp, ["-pattern_file", pyp])
            png = os.path.join(a.out, "gallery-paper-%s.png" % p)
            draw(pyp, "paper %s" % p, png)
            rows.append(("paper `%s`" % p, s, png))
    for name, s, png in rows:
        print("| %s | %.3f x %.3f | %.3g | %d | %d | %d kB |" % (name, s["px"] * 1e3, s["py"] * 1e3, s["radius"] * 1e3, s["vertices"], s["loops"],
                                                            (os.path.getsize(png) + 1023) // 1024))


if __name__ == "__main__":
    main()
