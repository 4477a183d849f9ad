#!/usr/bin/python3
"""Pictures of a material fit, in the spirit of Fig. S4 of the HYLC supplement.

    /usr/bin/python3 examples/plot_fit.py [--terms sx,sx-sa,...] [--dpi 110] SAMPLES MODEL OUTDIR

SAMPLES  the samples file of hylc-sample (HDF5; rows with status 0 are used) or the paper's raw
         layout (a directory with data.txt, or data.txt itself; 150 x 5 1D rows, then 9 n2 x n2 grids)
MODEL    the fitted material: JSON (ARCSim-HYLC layout) or HDF5 (docs/material.md), as written by
         hylc-fit -fit_json / -fit_output
OUTDIR   created if needed; receives one PNG per term:
         1D terms   <term>.png: the samples (Psi against the strain) and the model f0 + f_k(s / sigma_k)
         2D terms   <term>.png: three panels -- the samples, the model f0 + f_i + f_j + f_ij on a grid over
                    the samples' range, and the residual model - data at the samples
         and index.txt listing them with the RMS residual of each term.
--terms  draw only these terms (names as in the samples file: sx sa sy II00 II11 sx-sa ... sy-II11)
--dpi    resolution of the PNGs (default 110)

Needs Debian's python3-numpy, python3-h5py and python3-matplotlib (use /usr/bin/python3: a pyenv
python3 first on PATH will not see them). The model is evaluated by the hylc Python module (python/hylc
over build/libhylcmat.so, the evaluation of hylc-eval; docs/library.md).
"""
import json
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# the hylc Python module of this checkout (python/hylc, over build/libhylcmat.so; docs/library.md), or of
# the installation when this script is PREFIX/share/hylc/plot_fit.py (PREFIX/share/hylc/python)
_here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(_here, "..", "python"))
if not os.path.isdir(os.path.join(_here, "..", "python", "hylc")):
    sys.path.insert(0, os.path.join(_here, "python"))
import hylc  # noqa: E402

TERMS = ["zero", "sx", "sa", "sy", "II00", "II11", "sx-sa", "sx-sy", "sx-II00", "sx-II11", "sa-sy",
         "sa-II00", "sa-II11", "sy-II00", "sy-II11"]
PAIRS = [(0, 1), (0, 2), (0, 3), (0, 4), (1, 2), (1, 3), (1, 4), (2, 3), (2, 4)]
COORD = ["sx", "sa", "sy", "II00", "II11"]
STRAIN_INDEX = [0, 1, 2, 3, 5]  # position of coordinate c in (sx, sa, sy, II00, II01, II11)
UNITS = ["", "", "", " [1/m]", " [1/m]"]


# ---------------------------------------------------------------- inputs
def load_model(path):
    """dict with the material ("material": hylc.Material, evaluated by libhylcmat), const, scale[5], and the
    knots of the terms, 1D {k: spline}, 2D {(k0, k1): spline} (for drawing them)"""
    model = _load_tables(path)
    model["material"] = hylc.Material(path)
    return model


def _load_tables(path):
    with open(path, "rb") as fh:
        head = fh.read(8)
    if head.startswith(b"\x89HDF"):
        return load_model_h5(path)
    with open(path) as fh:
        d = json.load(fh)
    c = d["coeffs"]
    return {"const": float(c["const"]), "scale": [float(x) for x in d["strain scale"]],
            "1D": {int(s["k"]): s for s in c["1D"]}, "2D": {(int(s["k0"]), int(s["k1"])): s for s in c["2D"]}}


def load_model_h5(path):
    """The HDF5 material file (docs/material.md): datasets /constant and /strain_scale, groups /1D/<term>
    (attribute k; t, p, m) and /2D/<term> (attributes k0, k1; tu, tv and p, mu, mv, muv of shape
    (len(tv), len(tu)))."""
    import h5py
    model = {"1D": {}, "2D": {}}
    with h5py.File(path, "r") as f:
        model["const"] = float(f["constant"][()])
        model["scale"] = [float(x) for x in np.ravel(f["strain_scale"][()])]
        for name, g in f.get("1D", {}).items():
            model["1D"][int(g.attrs["k"])] = {k: g[k][()].ravel() for k in ("t", "p", "m")}
        for name, g in f.get("2D", {}).items():
            model["2D"][(int(g.attrs["k0"]), int(g.attrs["k1"]))] = {k: g[k][()].ravel() for k in ("tu", "tv", "p", "mu", "mv", "muv")}
    return model


def load_samples(path):
    """(strain N x 6, psi N, term N) of the usable samples"""
    if os.path.isdir(path):
        path = os.path.join(path, "data.txt")
    with open(path, "rb") as fh:
        head = fh.read(8)
    if head.startswith(b"\x89HDF"):
        s = hylc.read_samples(path)  # the usable rows (status 0)
        return s["strain"], s["psi"], s["term"]
    rows = np.loadtxt(path, ndmin=2)
    n = len(rows)
    n1 = 0
    while n1 < n and not np.any(rows[n1, 1:6]):
        n1 += 1
    n2 = int(round(np.sqrt((n - 5 * n1) / 9)))
    if 5 * n1 + 9 * n2 * n2 != n:
        sys.exit("%s: %d rows are not 5 x %d + 9 x %d^2 (the paper's raw layout)" % (path, n, n1, n2))
    term = np.concatenate([np.repeat(np.arange(1, 6), n1), np.repeat(np.arange(6, 15), n2 * n2)])
    return rows[:, :6], rows[:, 6], term


# ---------------------------------------------------------------- the model
def model_psi(model, z):
    """Psi at strains z (N x 6), by the hylc module (libhylcmat: the evaluation of hylc-eval)"""
    return model["material"].psi(np.ascontiguousarray(z, dtype=float))


def plot_1d(model, z, psi, c, out, dpi=110):
    x = z[:, STRAIN_INDEX[c]]
    lo, hi = x.min(), x.max()
    pad = 0.1 * (hi - lo)
    xs = np.linspace(lo - pad, hi + pad, 400)
    zz = np.zeros((len(xs), 6))
    zz[:, STRAIN_INDEX[c]] = xs
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.plot(x, psi, ".", ms=3, color="0.4", label="samples")
    ax.plot(xs, model_psi(model, zz), "-", color="C0", label="fit")
    if c in model["1D"]:
        t = np.asarray(model["1D"][c]["t"]) * model["scale"][c]
        zt = np.zeros((len(t), 6))
        zt[:, STRAIN_INDEX[c]] = t
        ax.plot(t, model_psi(model, zt), "o", ms=4, mfc="none", color="C1", label="knots")
    ax.axvspan(lo, hi, color="0.93", zorder=0)
    ax.set_xlabel(COORD[c] + UNITS[c])
    ax.set_ylabel("Psi [J/m^2]")
    ax.set_title(TERMS[1 + c])
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


def plot_2d(model, z, psi, t, out, dpi=110):
    ci, cj = PAIRS[t - 6]
    x, y = z[:, STRAIN_INDEX[ci]], z[:, STRAIN_INDEX[cj]]
    fit = model_psi(model, z)
    X, Y = np.meshgrid(np.linspace(x.min(), x.max(), 120), np.linspace(y.min(), y.max(), 120))
    zz = np.zeros((X.size, 6))
    zz[:, STRAIN_INDEX[ci]] = X.ravel()
    zz[:, STRAIN_INDEX[cj]] = Y.ravel()
    F = model_psi(model, zz).reshape(X.shape)
    vmin, vmax = min(psi.min(), F.min()), max(psi.max(), F.max())
    fig = plt.figure(figsize=(16, 4))  # fixed axes: much faster than a layout engine
    axs = [fig.add_axes([0.05 + 0.322 * i, 0.13, 0.2, 0.78]) for i in range(3)]
    cax = [fig.add_axes([0.05 + 0.322 * i + 0.206, 0.13, 0.0094, 0.78]) for i in (1, 2)]
    sc = axs[0].scatter(x, y, c=psi, s=8, vmin=vmin, vmax=vmax, cmap="viridis")
    axs[0].set_title(TERMS[t] + ": data")
    axs[1].contourf(X, Y, F, levels=30, vmin=vmin, vmax=vmax, cmap="viridis")
    axs[1].contour(X, Y, F, levels=12, colors="k", linewidths=0.4)
    if (ci, cj) in model["2D"]:
        s = model["2D"][(ci, cj)]
        KU, KV = np.meshgrid(np.asarray(s["tu"]) * model["scale"][ci], np.asarray(s["tv"]) * model["scale"][cj])
        axs[1].plot(KU.ravel(), KV.ravel(), "+", color="w", ms=4)
    axs[1].set_title("fit (+: knots)")
    fig.colorbar(sc, cax=cax[0], label="Psi [J/m^2]")
    r = fit - psi
    rm = max(np.abs(r).max(), 1e-300)
    rs = axs[2].scatter(x, y, c=r, s=8, cmap="RdBu_r", vmin=-rm, vmax=rm)
    axs[2].set_title("fit - data (RMS %.3g)" % np.sqrt(np.mean(r**2)))
    fig.colorbar(rs, cax=cax[1], label="J/m^2")
    for ax in axs:
        ax.set_xlabel(COORD[ci] + UNITS[ci])
        ax.set_ylabel(COORD[cj] + UNITS[cj])
    fig.savefig(out, dpi=dpi)
    plt.close(fig)


def main(argv):
    args, terms, dpi = [], None, 110
    it = iter(argv[1:])
    for a in it:
        if a in ("-h", "--help", "-help"):
            print(__doc__)
            return 0
        if a == "--terms":
            terms = next(it, "").split(",")
            bad = [t for t in terms if t not in TERMS[1:]]
            if bad:
                sys.exit("plot_fit.py: unknown term(s) %s (use %s)" % (", ".join(bad), " ".join(TERMS[1:])))
        elif a == "--dpi":
            dpi = int(next(it, "110"))
        else:
            args.append(a)
    if len(args) != 3:
        print(__doc__)
        return 2
    z, psi, term = load_samples(args[0])
    model = load_model(args[1])
    outdir = args[2]
    os.makedirs(outdir, exist_ok=True)
    lines = []
    for t in range(1, 15):
        if terms is not None and TERMS[t] not in terms:
            continue
        sel = term == t
        if not sel.any():
            lines.append("%-8s no samples" % TERMS[t])
            continue
        out = os.path.join(outdir, TERMS[t] + ".png")
        if t <= 5:
            plot_1d(model, z[sel], psi[sel], t - 1, out, dpi)
        else:
            plot_2d(model, z[sel], psi[sel], t, out, dpi)
        rms = np.sqrt(np.mean((model_psi(model, z[sel]) - psi[sel]) ** 2))
        lines.append("%-8s %-12s %5d samples  RMS residual %.4g J/m^2" % (TERMS[t], os.path.basename(out), sel.sum(), rms))
    with open(os.path.join(outdir, "index.txt"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
