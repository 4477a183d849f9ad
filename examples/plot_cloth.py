#!/usr/bin/env python3
"""Plots of hylc-cloth's virtual fabric tests (docs/fabric.md), one PNG beside each CSV.

    python3 examples/plot_cloth.py KIND FILE.csv

KIND is the test that wrote FILE.csv: tensile, uniaxial, bias, cantilever or drape. hylc-cloth runs this
script itself after each test (-cloth_plot, default on; -cloth_plot_script names another script). The
PNG is FILE.png. Needs numpy and matplotlib (Debian: python3-numpy, python3-matplotlib).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    """The CSV's comment lines (without '# ') and its rows as dicts of strings."""
    comments, lines = [], []
    with open(path, newline="") as f:
        for line in f:
            (comments if line.startswith("#") else lines).append(line.lstrip("# ").rstrip("\n") if line.startswith("#") else line)
    return comments, list(csv.DictReader(lines))


def col(rows, key, where=None):
    return [float(r[key]) for r in rows if where is None or where(r)]


def tensile(rows, title):
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    for d in sorted({r["direction"] for r in rows}):
        for face in sorted({r["face"] for r in rows}):
            sel = [r for r in rows if r["direction"] == d and r["face"] == face]
            if not sel:
                continue
            e = [0.0] + col(sel, "strain")
            a.plot(e, [0.0] + col(sel, "T_N_per_m"), "o-", ms=3, label=f"strip, {d} ({face})")
            a.plot(e, [0.0] + col(sel, "T_table"), "k--", lw=0.8, label=f"table's uniaxial state, {d}" if face == sorted({r['face'] for r in rows})[0] else None)
            b.plot(col(sel, "strain"), col(sel, "poisson"), "o-", ms=3, label=f"{d} ({face})")
    a.set(xlabel="nominal strain", ylabel="force per unit width T (N/m)", title="strip tensile")
    b.set(xlabel="nominal strain", ylabel="Poisson ratio (central zone)", title="lateral contraction")
    a.legend(fontsize=8)
    b.legend(fontsize=8)
    fig.suptitle(title, fontsize=9)
    return fig


def uniaxial(rows, title):
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    for d in sorted({r["direction"] for r in rows}):
        sel = [r for r in rows if r["direction"] == d]
        a.plot(col(sel, "strain"), col(sel, "T_N_per_m"), "o-", ms=3, label=d)
        b.plot(col(sel, "strain"), col(sel, "lateral_strain"), "o-", ms=3, label=d)
    a.set(xlabel="strain along the direction", ylabel="T (N/m)", title="the table's homogeneous uniaxial state")
    b.set(xlabel="strain along the direction", ylabel="lateral strain")
    a.legend()
    b.legend()
    fig.suptitle(title, fontsize=9)
    return fig


def bias(rows, title):
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    e = col(rows, "strain")
    a.plot(e, col(rows, "force_N"), "o-", ms=3)
    a.set(xlabel="extension / clamp distance", ylabel="force F (N)", title="bias extension (45 degrees)")
    b.plot(e, col(rows, "shear_deg"), "o-", ms=3, label="central zone")
    b.plot(e, col(rows, "shear_kinematic_deg"), "k--", lw=0.8, label="inextensible yarns (pin-jointed net)")
    b.set(xlabel="extension / clamp distance", ylabel="shear angle (degrees)")
    b.legend(fontsize=8)
    fig.suptitle(title, fontsize=9)
    return fig


def cantilever(rows, title):
    fig, a = plt.subplots(figsize=(6, 4))
    labels = [f"{r['direction']}, face {r['face']}" for r in rows]
    x = range(len(rows))
    a.bar([i - 0.2 for i in x], col(rows, "c_mm"), 0.4, label="shell (hylc-cloth)")
    a.bar([i + 0.2 for i in x], col(rows, "c_elastica_mm"), 0.4, label="elastica of the table's bending term")
    a.set_xticks(list(x))
    a.set_xticklabels(labels)
    a.set(ylabel="bending length c (mm)", title="cantilever, ASTM D1388 (41.5 degrees)")
    a.legend(fontsize=8)
    fig.suptitle(title, fontsize=9)
    return fig


def drape(rows, comments, title):
    fig = plt.figure(figsize=(5, 5))
    a = fig.add_subplot(projection="polar")
    th = [math.radians(t) for t in col(rows, "sector_deg")]
    r = col(rows, "r_m")
    a.plot(th + th[:1], r + r[:1], "-", label="shadow (largest radius per sector)")
    info = {}
    for c in comments:
        for part in c.split(","):
            words = part.split()
            if len(words) >= 2:
                try:
                    info[words[0]] = float(words[-2] if words[-1] == "m^2" else words[-1])
                except ValueError:
                    pass
    t = [2 * math.pi * i / 256 for i in range(257)]
    for key, style, name in (("specimen", "k:", "specimen"), ("disc", "k--", "disc")):
        if key in info:
            a.plot(t, [math.sqrt(info[key] / math.pi)] * len(t), style, lw=0.8, label=name)
    a.set_title("Cusick drape, top view" + (f": DC {info['drape']:.3f}" if "drape" in info else ""))
    a.legend(fontsize=7, loc="lower right")
    fig.suptitle(title, fontsize=9)
    return fig


def main(argv):
    if len(argv) != 3 or argv[1] not in ("tensile", "uniaxial", "bias", "cantilever", "drape"):
        sys.exit(__doc__)
    kind, path = argv[1], argv[2]
    comments, rows = read(path)
    if not rows:
        sys.exit(f"plot_cloth.py: {path}: no rows")
    title = path
    if kind == "drape":
        fig = drape(rows, comments, title)
    else:
        fig = {"tensile": tensile, "uniaxial": uniaxial, "bias": bias, "cantilever": cantilever}[kind](rows, title)
    out = path[:-4] + ".png" if path.endswith(".csv") else path + ".png"
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
