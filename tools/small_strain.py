#!/usr/bin/env python3
"""The small-strain report (issue 30): where cloth lives, the tile against the tables.

    /usr/bin/python3 tools/small_strain.py [--ours DIR] [--np N] [--markdown] PATTERN ...

For each paper pattern (config/PATTERN.yaml, the pattern from ../shared/refdata or $HYLC_REFDATA):
  - dPsi = Psi(z) - Psi(0) (J/m^2) at the probes sx, sy = +-0.02, +-0.05, +-0.1; sa = +-0.05, +-0.1;
    II00, II11 = +-10, +-20, +-40 1/m, from the tile (hylc-solve, one cold equilibrium per probe, the
    config's solver settings), from our fitted table (DIR/PATTERN.json, if --ours is given) and from the
    paper's table (materials/<table>.json); the tables' dPsi as a ratio of the tile's;
  - the gradient of Psi at z = 0 from the tile (central differences of equilibria, h = 1e-3 for the
    stretches, 1 1/m for the curvatures; at a reference state that is a minimum of the model, dPsi/dsx and
    dPsi/dsy vanish), next to the same derivative at sx = 5 % for scale;
  - the linear stiffness: the diagonal of the Hessian of Psi at 0 from the tile (second differences over
    the same h) beside the tables' (hylc-eval -derivatives; one-sided where a table has a knot at 0).
  - the stationarity ratios |dPsi/dsx(0)| / dPsi/dsx(sx = 5 %) and |dPsi/dsy(0)| / dPsi/dsy(sy = 5 %) (issue 30
    asks for both below 1 %);
  - with --samples DIR (DIR/PATTERN.h5, the samples the table was fitted to): issue 30's probe criterion, the
    probes whose tile |dPsi| exceeds 1 % of the term's range of Psi - f0 in the samples, and how many of them
    have our table within 10 % of the tile.
    Also, per 1D term, the range-normalised RMS of our table against those samples beside that of a fit of
    the same samples with the paper's knot layout (hylc-fit -fit_knots paper), issue 30's "no worse" check.
Prints a Markdown report. hylc-solve runs on N processes at a time (default 2). --tiles DIR takes the tiles
from DIR/PATTERN.pyp instead (e.g. the relaxed reference states of hylc-sample -sampler_reference relax
-reference_output). Needs the programs built.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REF = os.environ.get("HYLC_REFDATA", os.path.join(ROOT, "..", "shared", "refdata"))
BIN = os.path.join(ROOT, os.environ.get("BUILD", "build"), "bin")
TABLE = {"basket": "basket1", "satin": "satin1", "satin_small": "satin01", "stockinette": "stock1",
         "stockinette_small": "stock01", "cartridge_belt_rib": "rib1", "slip_stitch_honeycomb": "honey1"}
NAMES = ["sx", "sa", "sy", "II00", "II01", "II11"]
PROBES = [("sx", v) for v in (-0.1, -0.05, -0.02, 0.02, 0.05, 0.1)] + \
         [("sy", v) for v in (-0.1, -0.05, -0.02, 0.02, 0.05, 0.1)] + \
         [("sa", v) for v in (-0.1, -0.05, 0.05, 0.1)] + \
         [("II00", v) for v in (-40, -20, -10, 10, 20, 40)] + \
         [("II11", v) for v in (-40, -20, -10, 10, 20, 40)]
H = {"sx": 1e-3, "sa": 1e-3, "sy": 1e-3, "II00": 1.0, "II11": 1.0}


def strain(name, v):
    z = [0.0] * 6
    z[NAMES.index(name)] = v
    return z


PATTERNS = os.path.join(REF, "patterns", "hylc2020")


def solve(pattern, z):
    """Psi of the tile's equilibrium at z (cold, the config's settings); None if it did not converge."""
    cmd = [os.path.join(BIN, "hylc-solve"), "-options_file", os.path.join(ROOT, "config", pattern + ".yaml"),
           "-pattern_file", os.path.join(PATTERNS, pattern + ".pyp"),
           "-strain", ",".join("%.17g" % x for x in z)]
    out = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
    psi, status = None, None
    for line in out.stdout.splitlines():
        if line.startswith("psi:"):
            psi = float(line.split()[1])
        elif line.startswith("status:"):
            status = line.split()[1]
    if out.returncode != 0 or status != "converged":
        sys.stderr.write("small_strain: %s at %s: %s\n" % (pattern, z, (out.stdout + out.stderr).strip().splitlines()[-1:]))
        return None
    return psi


def table_psi(table, zs, derivatives=False):
    """Psi (and with derivatives the gradient and Hessian) of a table at the strains zs (hylc-eval)."""
    with tempfile.TemporaryDirectory() as d:
        inp, outp = os.path.join(d, "z.txt"), os.path.join(d, "psi.txt")
        with open(inp, "w") as f:
            for z in zs:
                f.write(" ".join("%.17g" % x for x in z) + "\n")
        cmd = [os.path.join(BIN, "hylc-eval"), "-material", table, "-eval_input", inp, "-eval_output", outp]
        if derivatives:
            cmd.append("-derivatives")
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode:
            raise SystemExit("small_strain: hylc-eval %s: %s" % (table, (r.stdout + r.stderr).strip()))
        rows = []
        with open(outp) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    rows.append([float(x) for x in line.split()])
    return rows


def term_ranges(path):
    """max |Psi - f0| over the converged samples of each 1D term of a samples file, f0 the zero sample's Psi
    (the term's range, as hylc-fit prints it)."""
    try:
        import h5py
    except ImportError:
        raise SystemExit("small_strain: --samples needs h5py (python3-h5py)")
    try:
        with h5py.File(path, "r") as f:
            s = f["samples"]
            term, psi, status = s["term"][:], s["psi"][:], s["status"][:]
    except (OSError, KeyError) as e:
        raise SystemExit("small_strain: %s: not a samples file of hylc-sample (%s)" % (path, e))
    zero = [k for k in range(len(term)) if term[k] == 0]
    if not zero:
        raise SystemExit("small_strain: %s has no zero sample" % path)
    f0 = psi[zero[0]]
    out = {}
    for t, n in enumerate(("sx", "sa", "sy", "II00", "II11"), start=1):
        v = [abs(psi[k] - f0) for k in range(len(term)) if term[k] == t and status[k] == 0]
        if not v:
            raise SystemExit("small_strain: %s has no converged sample of term %s" % (path, n))
        out[n] = max(v)
    return out


def layout_rms(path, ours):
    """per 1D term: RMS of (table - Psi) over the converged samples / the term's range, for our table and for
    hylc-fit -fit_knots paper of the same samples (the family is the samples' own)"""
    import h5py
    with h5py.File(path, "r") as f:
        s = f["samples"]
        term, psi, status = s["term"][:], s["psi"][:], s["status"][:]
    f0 = psi[[k for k in range(len(term)) if term[k] == 0][0]]
    with tempfile.TemporaryDirectory() as d:
        paper = os.path.join(d, "paper.json")
        r = subprocess.run([os.path.join(BIN, "hylc-fit"), "-fit_input", path, "-fit_knots", "paper", "-fit_json", paper], capture_output=True, text=True)
        if r.returncode:
            raise SystemExit("small_strain: hylc-fit -fit_knots paper %s: %s" % (path, (r.stdout + r.stderr).strip().splitlines()[-1:]))
        vals = {}
        for label, table in (("ours", ours), ("paper", paper)):
            outp = os.path.join(d, label + ".txt")
            r = subprocess.run([os.path.join(BIN, "hylc-eval"), "-material", table, "-eval_input", path, "-eval_output", outp], capture_output=True, text=True)
            if r.returncode:
                raise SystemExit("small_strain: hylc-eval %s: %s" % (table, (r.stdout + r.stderr).strip()))
            with open(outp) as f:
                vals[label] = [float(line.split()[-1]) for line in f if line.strip() and not line.startswith("#")]
    out = []
    for t, n in enumerate(("sx", "sa", "sy", "II00", "II11"), start=1):
        rows = [k for k in range(len(term)) if term[k] == t and status[k] == 0]
        rng = max(abs(psi[k] - f0) for k in rows)
        rms = {lab: 100 * (sum((vals[lab][k] - psi[k]) ** 2 for k in rows) / len(rows)) ** 0.5 / rng for lab in vals}
        out.append((n, rms["ours"], rms["paper"]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("patterns", nargs="*", default=list(TABLE))
    ap.add_argument("--ours", help="directory with our fitted tables, PATTERN.json")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--samples", help="directory with the samples our tables were fitted to, PATTERN.h5 (for the probe criterion; needs h5py)")
    ap.add_argument("--tiles", help="directory with the tiles, PATTERN.pyp (default: the paper's; e.g. reference states written by hylc-sample -sampler_reference relax -reference_output)")
    a = ap.parse_args()
    global PATTERNS
    if a.tiles:
        PATTERNS = a.tiles
    for p in a.patterns:
        if p not in TABLE:
            raise SystemExit("small_strain: unknown pattern %s (one of %s)" % (p, ", ".join(TABLE)))
    for p in a.patterns:
        for d, ext, opt in ((a.ours, ".json", "--ours"), (a.samples, ".h5", "--samples")):
            if d and not os.path.isfile(os.path.join(d, p + ext)):
                raise SystemExit("small_strain: %s: no such file (%s)" % (os.path.join(d, p + ext), opt))
    if not os.path.isdir(os.path.join(REF, "patterns", "hylc2020")):
        print("small_strain: the paper's reference data (%s) is absent; skipped" % REF)
        return 0
    for p in a.patterns:
        zs = [[0.0] * 6] + [strain(n, v) for n, v in PROBES]
        fd = []
        for n in ("sx", "sa", "sy", "II00", "II11"):
            fd += [strain(n, H[n]), strain(n, -H[n])]
        fd += [strain("sx", 0.05 + 1e-3), strain("sx", 0.05 - 1e-3), strain("sy", 0.05 + 1e-3), strain("sy", 0.05 - 1e-3)]
        with ThreadPoolExecutor(max_workers=a.np) as ex:
            tile = list(ex.map(lambda z: solve(p, z), zs + fd))
        t0 = tile[0]
        tprobe, tfd = tile[1:len(zs)], tile[len(zs):]
        paper = table_psi(os.path.join(REF, "materials", TABLE[p] + ".json"), zs)
        ours = table_psi(os.path.join(a.ours, p + ".json"), zs) if a.ours else None
        print("\n### %s (paper's table %s%s)\n" % (p, TABLE[p], ", ours %s/%s.json" % (a.ours, p) if a.ours else ""))
        print("Psi(0): tile %.6g, %sthe paper's table %.6g J/m^2\n" % (t0, "our table %.6g, " % ours[0][-1] if ours else "", paper[0][-1]))
        print("| probe | tile dPsi | %spaper's table dPsi (x tile) |" % ("our table dPsi (x tile) | " if ours else ""))
        print("|---|---|%s---|" % ("---|" if ours else ""))
        for i, (n, v) in enumerate(PROBES):
            d = None if tprobe[i] is None or t0 is None else tprobe[i] - t0
            cells = ["%s = %g%s" % (n, v, " /m" if n.startswith("II") else ""), "n/c" if d is None else "%.3g" % d]
            for tab in ([ours] if ours else []) + [paper]:
                dt = tab[i + 1][-1] - tab[0][-1]
                cells.append("%.3g%s" % (dt, "" if d is None or d == 0 else " (%.2f)" % (dt / d)))
            print("| " + " | ".join(cells) + " |")
        if ours and a.samples:
            rng = term_ranges(os.path.join(a.samples, p + ".h5"))
            counted, ok, miss = 0, 0, []
            for i, (n, v) in enumerate(PROBES):
                d = None if tprobe[i] is None or t0 is None else tprobe[i] - t0
                if d is None or abs(d) <= 0.01 * rng[n]:
                    continue
                counted += 1
                r = (ours[i + 1][-1] - ours[0][-1]) / d
                if abs(r - 1) <= 0.1:
                    ok += 1
                else:
                    miss.append("%s = %g: %.2f" % (n, v, r))
            print("\nProbe criterion (issue 30; the term's range of Psi - f0 in %s: %s J/m^2): %d of %d probes above 1 %% of it "
                  "have our table within 10 %% of the tile%s." % (os.path.join(a.samples, p + ".h5"), ", ".join("%s %.3g" % (n, rng[n]) for n in ("sx", "sa", "sy", "II00", "II11")),
                                                                   ok, counted, "; outside: " + ", ".join(miss) if miss else ""))
            rows = layout_rms(os.path.join(a.samples, p + ".h5"), os.path.join(a.ours, p + ".json"))
            print("\n| 1D term | RMS of our table against the samples (% of the range) | the same, paper's knot layout | ours vs paper |")
            print("|---|---|---|---|")
            for n, r_ours, r_paper in rows:
                print("| %s | %.4f | %.4f | %+.2g %% |" % (n, r_ours, r_paper, 100 * (r_ours / r_paper - 1)))
        # the tile's gradient and stiffness at 0 by differences; the tables' by hylc-eval -derivatives
        print("\n| at z = 0 | dPsi/dsx | dPsi/dsa | dPsi/dsy | dPsi/dII00 | dPsi/dII11 | dPsi/dsx at sx = 5 % |")
        print("|---|---|---|---|---|---|---|")
        g, k = [], []
        for j, n in enumerate(("sx", "sa", "sy", "II00", "II11")):
            pl, mi = tfd[2 * j], tfd[2 * j + 1]
            if None in (pl, mi, t0):
                g.append(None)
                k.append(None)
            else:
                g.append((pl - mi) / (2 * H[n]))
                k.append((pl - 2 * t0 + mi) / H[n] ** 2)
        g5 = None if None in tfd[-4:-2] else (tfd[-4] - tfd[-3]) / 2e-3
        g5y = None if None in tfd[-2:] else (tfd[-2] - tfd[-1]) / 2e-3
        print("| tile (differences) | " + " | ".join("n/c" if x is None else "%.3g" % x for x in g) + " | %s |" % ("n/c" if g5 is None else "%.3g" % g5))
        dz = [[0.0] * 6, strain("sx", 0.05)]
        for label, path in ([("our table", os.path.join(a.ours, p + ".json"))] if a.ours else []) + [("paper's table", os.path.join(REF, "materials", TABLE[p] + ".json"))]:
            r = table_psi(path, dz, derivatives=True)
            grad0, grad5 = r[0][1:7], r[1][1:7]
            print("| %s | %s | %.3g |" % (label, " | ".join("%.3g" % grad0[NAMES.index(n)] for n in ("sx", "sa", "sy", "II00", "II11")), grad5[0]))
        if None not in (g[0], g[2], g5, g5y):
            print("\nStationarity of the tile at z = 0 (issue 30: below 1 %%): |dPsi/dsx(0)| / dPsi/dsx(sx = 5 %%) = %.2f %%, "
                  "|dPsi/dsy(0)| / dPsi/dsy(sy = 5 %%) = %.2f %% (dPsi/dsy at sy = 5 %%: %.3g N/m)." % (100 * abs(g[0]) / g5, 100 * abs(g[2]) / g5y, g5y))
        print("\n| linear stiffness d2Psi/dz2 at 0 | sx | sa | sy | II00 | II11 |")
        print("|---|---|---|---|---|---|")
        print("| tile (second differences) | " + " | ".join("n/c" if x is None else "%.3g" % x for x in k) + " |")
        for label, path in ([("our table", os.path.join(a.ours, p + ".json"))] if a.ours else []) + [("paper's table", os.path.join(REF, "materials", TABLE[p] + ".json"))]:
            r = table_psi(path, [[0.0] * 6], derivatives=True)
            hess = r[0][7:43]
            print("| %s | %s |" % (label, " | ".join("%.3g" % hess[7 * NAMES.index(n)] for n in ("sx", "sa", "sy", "II00", "II11"))))
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
