#!/usr/bin/env python3
"""Map of where a tile is multistable, from a samples file of `hylc-sample -sampler_start both`.

    /usr/bin/python3 examples/plot_multistable.py samples.h5 out.png [title]

Every sample of such a file was solved cold (from the rest state) and, except the first of each half-line,
continued from its predecessor's equilibrium; /samples/psi holds the lower of the two, /samples/psi_other
the other, /samples/multistable flags the samples whose two energies differ by more than -sampler_both_rtol
(docs/output-format.md). The figure has one panel per 1D term (the cold and the continued Psi against the
strain, the flagged samples ringed) and one per 2D term (the grid of samples, coloured by the relative
difference of the two starts, log scale; grey: compared within the tolerance, white: solved once). Prints
per term the share of flagged samples and the strain range they cover. Needs h5py and matplotlib.
"""
import sys

import h5py
import numpy as np

COORD = {"sx": 0, "sa": 1, "sy": 2, "II00": 3, "II11": 5}


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    path, out = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else path
    with h5py.File(path, "r") as f:
        if "samples/psi_other" not in f:
            print("%s has no /samples/psi_other: not a file of -sampler_start both" % path)
            return 1
        s = f["samples"]
        z, term, psi, po, start, ms, st, so = (s[d][:] for d in ("strain", "term", "psi", "psi_other", "start", "multistable", "status", "status_other"))
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in s.attrs["term_names"]]
    if not (ms >= 0).any():
        print("%s: no sample was solved from both starts (is it a -sampler_start both file?)" % path)
        return 1
    cold = np.where(start == 0, psi, po)
    cont = np.where(start == 1, psi, np.where(so >= 0, po, np.nan))
    rel = np.abs(psi - po) / np.maximum(np.abs(psi), np.abs(po))
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    terms = [t for t in range(1, len(names)) if (term == t).any()]
    ncol = 5
    nrow = (len(terms) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.4 * ncol, 3.0 * nrow), squeeze=False, constrained_layout=True)
    print("%s: %d samples compared, %d multistable (%.1f %%)" % (title, (ms >= 0).sum(), (ms == 1).sum(), 100.0 * (ms == 1).sum() / max((ms >= 0).sum(), 1)))
    for ax, t in zip(axes.flat, terms):
        idx = np.where(term == t)[0]
        name = names[t]
        flagged = idx[ms[idx] == 1]
        if "-" not in name:
            x = z[idx, COORD[name]]
            o = np.argsort(x)
            ax.plot(x[o], cold[idx][o], "-", color="tab:blue", lw=1, label="cold")
            ax.plot(x[o], cont[idx][o], ".", color="tab:orange", ms=4, label="continued")
            xf = z[flagged, COORD[name]]
            ax.plot(xf, psi[flagged], "o", mfc="none", mec="red", ms=7, label="multistable")
            ax.set_xlabel(name + (" (1/m)" if name.startswith("II") else ""))
            ax.set_ylabel("Psi (J/m^2)")
            rng = (xf.min(), xf.max()) if len(xf) else None
        else:
            a, b = name.split("-")
            x, y = z[idx, COORD[a]], z[idx, COORD[b]]
            both = ms[idx] >= 0
            ax.scatter(x[~both], y[~both], s=8, facecolors="none", edgecolors="0.7")
            agree = both & (ms[idx] == 0)
            ax.scatter(x[agree], y[agree], s=10, color="0.8")
            fl = ms[idx] == 1
            if fl.any():
                ax.scatter(x[fl], y[fl], s=14, c=np.log10(np.maximum(rel[idx][fl], 1e-16)), cmap="viridis", vmin=-3, vmax=0)
            ax.set_xlabel(a)
            ax.set_ylabel(b)
            rng = None
        n = (ms[idx] >= 0).sum()
        ax.set_title("%s: %d / %d" % (name, len(flagged), n), fontsize=9)
        print("  %-8s %3d of %3d compared samples multistable%s" % (name, len(flagged), n, "" if rng is None else ", %s from %.3g to %.3g" % (name, rng[0], rng[1])))
    for ax in axes.flat[len(terms):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7)
    sm = matplotlib.cm.ScalarMappable(norm=matplotlib.colors.Normalize(-3, 0), cmap="viridis")
    fig.colorbar(sm, ax=axes.ravel().tolist(), shrink=0.5, label="log10 |Psi_cold - Psi_cont| / max |Psi|")
    fig.suptitle("%s: cold and continued starts (2D panels: log10 relative difference where > tolerance)" % title, fontsize=10)
    fig.savefig(out, dpi=90)
    print("wrote %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
