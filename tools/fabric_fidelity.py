#!/usr/bin/env python3
"""The fabric-fidelity report: does a table behave like the yarn tile it was made from, in the states the
standard fabric tests put cloth in?

    /usr/bin/python3 tools/fabric_fidelity.py [options] CONFIG.yaml MATERIAL_DIR
    /usr/bin/python3 tools/fabric_fidelity.py --collect OUT.md RESULT.json ...

CONFIG.yaml is the study's options file (the yarn model; config/satin.yaml), MATERIAL_DIR the output of
tools/hylc-material (reference.pyp, the tile the table was sampled on; model.h5, the table, else model.json;
samples.h5). For the tile (hylc-solve -solve_path on reference.pyp) and the table (hylc-eval -eval_path on
model.h5), the ARCSim-HYLC JSON export beside it when the table has terms the JSON leaves out (hylc's 3D terms),
and the paper's table where one exists (--paper TABLE.json, automatic for the paper's patterns when the reference data
are present), each state continued along its loading path from rest:
  - uniaxial tension along x, y and the 45-degree bias (the other in-plane strains free, bending 0) at
    s = 1, 2, 5, 10, 20 %: the force per unit width T, the lateral strain, the shear;
  - equibiaxial tension s = 2, 5, 10 % (sx = sy, sa free): the tension in x and in y;
  - shear sa = 0.02, 0.05, 0.1, 0.2 (the stretches free): dPsi/dsa;
  - bending II00 and II11 = +-5, +-10, +-20, +-50 1/m (the in-plane strains free): the moment per unit width;
  - the tile's stationarity at z = 0 (|dPsi/dsx|, |dPsi/dsy| of the zero sample, from the samples' stress)
    over T at 5 %.
Every figure as a relative error of the table against the tile, with an absolute floor where the tile's value
is near 0 (named in the report); the targets: uniaxial T within 5 % at 2-20 % (10 % at 1 %), lateral strain
within 0.005, bias T and shear within 10 %, bending moment within 5 % at |II| = 10-50 1/m, stationarity below 1 %.
Writes RESULT.json (--json, default MATERIAL_DIR/fidelity.json), a Markdown section (--markdown, default
MATERIAL_DIR/fidelity.md) and PNGs (MATERIAL_DIR/fidelity-*.png; matplotlib). --collect writes one document
of several results. Needs the programs built (BUILD=dir, default build) and /usr/bin/python3 with numpy, h5py.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
REF = os.environ.get("HYLC_REFDATA", os.path.join(ROOT, "..", "shared", "refdata"))
BIN = os.environ.get("HYLC_BIN", os.path.join(ROOT, os.environ.get("BUILD", "build"), "bin"))
PAPER = {"basket": "basket1", "satin": "satin1", "satin_small": "satin01", "stockinette": "stock1",
         "stockinette_small": "stock01", "cartridge_belt_rib": "rib1", "slip_stitch_honeycomb": "honey1"}

UNI = [0.005, 0.01, 0.02, 0.035, 0.05, 0.075, 0.1, 0.125, 0.15, 0.175, 0.2]  # continued in these steps
UNI_REPORT = [0.01, 0.02, 0.05, 0.1, 0.2]
EQUI = [0.01, 0.02, 0.035, 0.05, 0.075, 0.1]
EQUI_REPORT = [0.02, 0.05, 0.1]
SHEAR = [0.01, 0.02, 0.035, 0.05, 0.075, 0.1, 0.15, 0.2]
SHEAR_REPORT = [0.02, 0.05, 0.1, 0.2]
BEND = [2.5, 5, 10, 15, 20, 30, 40, 50]
BEND_REPORT = [5, 10, 20, 50]

# (name, path kind, angle, values continued, values reported, sign of the values)
PATHS = [("uniaxial x", "uniaxial", 0, UNI, UNI_REPORT, 1), ("uniaxial y", "uniaxial", 90, UNI, UNI_REPORT, 1),
         ("bias 45", "uniaxial", 45, UNI, UNI_REPORT, 1), ("equibiaxial", "equibiaxial", 0, EQUI, EQUI_REPORT, 1),
         ("shear", "shear", 0, SHEAR, SHEAR_REPORT, 1),
         ("bending II00 +", "bending", 0, BEND, BEND_REPORT, 1), ("bending II00 -", "bending", 0, BEND, BEND_REPORT, -1),
         ("bending II11 +", "bending", 90, BEND, BEND_REPORT, 1), ("bending II11 -", "bending", 90, BEND, BEND_REPORT, -1)]

# targets: relative error of the force, and what it is reported at
TARGET = {"uniaxial": 0.05, "uniaxial1": 0.10, "bias": 0.10, "equibiaxial": 0.05, "shear": 0.10, "bending": 0.05, "lateral": 0.005}


def die(msg):
    print("fabric_fidelity.py: error: " + msg, file=sys.stderr)
    sys.exit(1)


def read_csv(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            rows.append({k: float(v) for k, v in r.items()})
    return rows


def run(cmd, log):
    with open(log, "w") as f:
        p = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT)
    if p.returncode:
        with open(log) as f:
            tail = f.read()[-2000:]
        die("%s failed (%s):\n%s" % (" ".join(cmd), log, tail))


def tile_path(cfg, pyp, kind, angle, values, work, tag):
    out = os.path.join(work, "tile-%s.csv" % tag)
    run([os.path.join(BIN, "hylc-solve"), "-options_file", cfg, "-pattern_file", pyp, "-solve_path", kind, "-solve_path_angle", str(angle),
         "-solve_path_values", ",".join("%.10g" % v for v in values), "-solve_path_csv", out], os.path.join(work, "tile-%s.log" % tag))
    return read_csv(out)


def table_path(table, kind, angle, values, work, tag):
    out = os.path.join(work, "table-%s.csv" % tag)
    run([os.path.join(BIN, "hylc-eval"), "-material", table, "-eval_path", kind, "-eval_path_angle", str(angle),
         "-eval_path_values", ",".join("%.10g" % v for v in values), "-eval_path_csv", out], os.path.join(work, "table-%s.log" % tag))
    return read_csv(out)


def has_3d(path):
    """whether an HDF5 table holds 3D terms (hylc's extension, which the JSON export leaves out)"""
    try:
        import h5py
        with h5py.File(path, "r") as f:
            return "3D" in f and len(f["3D"]) > 0
    except (OSError, ImportError):
        return False


def rel(table, tile, floor):
    """the relative error of table against tile, the denominator at least floor"""
    return (table - tile) / max(abs(tile), floor)


def measure(args):
    cfg, mat = args.config, args.material
    pyp, samples = os.path.join(mat, "reference.pyp"), os.path.join(mat, "samples.h5")
    model, export = os.path.join(mat, "model.h5"), os.path.join(mat, "model.json")
    if not os.path.isfile(model):
        model, export = export, ""
    elif not (os.path.isfile(export) and has_3d(model)):
        export = ""
    for f in (cfg, pyp, model):
        if not os.path.isfile(f):
            die("cannot read %s (MATERIAL_DIR must hold the output of tools/hylc-material)" % f)
    name = args.name or os.path.basename(os.path.normpath(mat))
    paper = args.paper
    if paper is None and name in PAPER:
        cand = os.path.join(REF, "materials", PAPER[name] + ".json")
        paper = cand if os.path.isfile(cand) else ""
    work = tempfile.mkdtemp(prefix="fidelity-" + name + "-")
    # the tile is reference.pyp under the study's yarn: the options without the pattern's source (a generated
    # pattern's -pattern_type, a stored one's -pattern_file, the radius the .pyp holds)
    tile_cfg = os.path.join(work, "tile.yaml")
    with open(cfg) as fi, open(tile_cfg, "w") as fo:
        for line in fi:
            if line.split(":")[0].strip() not in ("pattern_type", "pattern_file", "pattern_radius"):
                fo.write(line)
    cfg_given, cfg = cfg, tile_cfg
    jobs = []
    for (label, kind, angle, values, report, sign) in PATHS:
        vals = [sign * v for v in values]
        tag = label.replace(" ", "_").replace("+", "p").replace("-", "m")
        jobs.append((label, kind, angle, vals, [sign * v for v in report], tag))
    results = {"name": name, "config": cfg_given, "material": mat, "model": model, "export": export, "paper": paper or "", "paths": {}}
    with ThreadPoolExecutor(max_workers=args.np) as ex:
        tile_f = {j[0]: ex.submit(tile_path, cfg, pyp, j[1], j[2], j[3], work, j[5]) for j in jobs}
        table_f = {j[0]: ex.submit(table_path, model, j[1], j[2], j[3], work, j[5]) for j in jobs}
        paper_f = {j[0]: ex.submit(table_path, paper, j[1], j[2], j[3], work, j[5] + "-paper") for j in jobs} if paper else {}
        export_f = {j[0]: ex.submit(table_path, export, j[1], j[2], j[3], work, j[5] + "-export") for j in jobs} if export else {}
        for (label, kind, angle, vals, report, tag) in jobs:
            results["paths"][label] = {"kind": kind, "angle": angle, "values": vals, "report": report, "tile": tile_f[label].result(),
                                       "table": table_f[label].result(), "paper": paper_f[label].result() if paper else None,
                                       "export": export_f[label].result() if export else None}
    # the tile's stationarity at z = 0: the zero sample's stress against T at 5 %
    try:
        import h5py
        import numpy as np
    except ImportError:
        die("needs numpy and h5py (Debian: python3-h5py) for the samples' stress: run it with /usr/bin/python3")
    results["stress0"], results["cpu_s"], results["nsamples"] = None, None, None
    try:
        with h5py.File(samples, "r") as f:
            s = f["samples"]
            term, st = s["term"][:], s["stress"][:] if "stress" in s else None
            k = int(np.where(term == 0)[0][0]) if st is not None and (term == 0).any() else -1
            results["stress0"] = [float(v) for v in st[k]] if k >= 0 else None
            if "time" in s:
                results["cpu_s"], results["nsamples"] = float(np.nansum(s["time"][:])), int(len(term))
    except (OSError, KeyError) as e:
        print("fabric_fidelity.py: warning: %s: %s (no stationarity check)" % (samples, e), file=sys.stderr)
    return results


def at(rows, v):
    for r in rows:
        if abs(r["value"] - v) < 1e-12:
            return r
    return None


def lateral_of(kind, angle, r):
    """(lateral stretch, shear) of a uniaxial state: sy along x, sx along y, for the bias the strains"""
    if kind != "uniaxial":
        return None, r["sa"]
    if angle == 0:
        return r["sy"], r["sa"]
    if angle == 90:
        return r["sx"], r["sa"]
    return r["sy"], r["sa"]


def evaluate(res):
    """the comparisons and the verdict per target"""
    rows, checks = [], []
    p = res["paths"]
    t5 = {}
    for label in ("uniaxial x", "uniaxial y"):
        r = at(p[label]["tile"], 0.05)
        t5[label] = r["force"] if r else float("nan")
    s0 = res.get("stress0")
    for label, d in p.items():
        kind, angle = d["kind"], d["angle"]
        forces = [abs(r["force"]) for r in d["tile"] if r["converged"]]
        fmax = max(forces) if forces else 1
        floor = 0.02 * fmax  # a force near 0 is judged against 2 % of the path's largest
        if kind == "bending" and s0:  # and a moment against the tile's moment at rest (a curled tile's moment crosses 0)
            floor = max(floor, abs(s0[3 if angle == 0 else 5]))
        for v in d["report"]:
            a, b, c = at(d["tile"], v), at(d["table"], v), at(d["paper"], v) if d["paper"] else None
            x = at(d["export"], v) if d.get("export") else None
            if not a or not b:
                continue
            e = rel(b["force"], a["force"], floor)
            ep = rel(c["force"], a["force"], floor) if c else None
            ex = rel(x["force"], a["force"], floor) if x else None
            lat_a, sh_a = lateral_of(kind, angle, a)
            lat_b, sh_b = lateral_of(kind, angle, b)
            row = {"path": label, "value": v, "tile": a["force"], "table": b["force"], "err": e, "paper": c["force"] if c else None, "err_paper": ep,
                   "err_export": ex, "tile_conv": bool(a["converged"]), "table_conv": bool(b["converged"]), "lat_tile": lat_a, "lat_table": lat_b, "shear_tile": sh_a, "shear_table": sh_b}
            rows.append(row)
            if kind == "uniaxial" and angle in (0, 90):
                tol = TARGET["uniaxial1"] if abs(v) < 0.015 else TARGET["uniaxial"]
                checks.append(("uniaxial T", label, v, abs(e) <= tol, e, tol))
                if lat_a is not None:
                    checks.append(("lateral strain", label, v, abs(lat_b - lat_a) <= TARGET["lateral"], lat_b - lat_a, TARGET["lateral"]))
            elif kind == "uniaxial":
                checks.append(("bias T", label, v, abs(e) <= TARGET["bias"], e, TARGET["bias"]))
            elif kind == "equibiaxial":
                checks.append(("equibiaxial T", label, v, abs(e) <= TARGET["equibiaxial"], e, TARGET["equibiaxial"]))
            elif kind == "shear":
                checks.append(("shear", label, v, abs(e) <= TARGET["shear"], e, TARGET["shear"]))
            elif kind == "bending" and abs(v) >= 10:
                checks.append(("bending moment", label, v, abs(e) <= TARGET["bending"], e, TARGET["bending"]))
    stat = None
    if res.get("stress0"):
        s0 = res["stress0"]
        stat = (abs(s0[0]) / max(abs(t5.get("uniaxial x", 0)), 1e-12), abs(s0[2]) / max(abs(t5.get("uniaxial y", 0)), 1e-12))
        checks.append(("stationarity", "z = 0", 0, max(stat) <= 0.01, max(stat), 0.01))
    return rows, checks, stat


def fmt_pct(e):
    return "" if e is None else "%+.1f %%" % (100 * e)


def markdown(res):
    rows, checks, stat = evaluate(res)
    name = res["name"]
    ok = sum(1 for c in checks if c[3])
    out = ["## %s" % name, ""]
    out.append("Table `%s` against its tile `%s` (options `%s`)%s%s: **%d of %d checks met**." % (
        res.get("model", os.path.join(res["material"], "model.json")), os.path.join(res["material"], "reference.pyp"), res["config"],
        "; its ARCSim-HYLC JSON export `%s` (the paper's terms only) beside it" % os.path.basename(res["export"]) if res.get("export") else "",
        "; the paper's table `%s` beside it" % os.path.basename(res["paper"]) if res["paper"] else "", ok, len(checks)))
    out.append("")
    by = {}
    for c in checks:
        by.setdefault(c[0], []).append(c)
    out.append("| check | met | worst |")
    out.append("|---|---|---|")
    for k, cs in by.items():
        worst = max(cs, key=lambda c: abs(c[4]) / c[5])
        unit = "" if k == "lateral strain" or k == "stationarity" else " %"
        w = worst[4] if unit == "" else 100 * worst[4]
        out.append("| %s (target %s) | %d of %d | %+.3g%s (%s at %g) |" % (k, ("%g" % worst[5]) if unit == "" else "%g %%" % (100 * worst[5]), sum(c[3] for c in cs), len(cs), w, unit, worst[1], worst[2]))
    out.append("")
    if stat:
        s0 = res["stress0"]
        out.append("Stationarity of the tile at z = 0: |dPsi/dsx| / T_x(5 %%) = %.4f, |dPsi/dsy| / T_y(5 %%) = %.4f. Its moments at rest "
                   "(the bending floor): dPsi/dII00 = %.3g N, dPsi/dII11 = %.3g N." % (stat[0], stat[1], s0[3], s0[5]))
        out.append("")
    exp = bool(res.get("export"))
    out.append("| path | value | tile | table | table vs tile |%s paper vs tile | lateral tile / table | shear tile / table |" % (" JSON export vs tile |" if exp else ""))
    out.append("|---|---|---|---|---|%s---|---|---|" % ("---|" if exp else ""))
    for r in rows:
        unit = "N" if r["path"].startswith("bending") else "N/m"
        lat = "" if r["lat_tile"] is None else "%.4f / %.4f" % (r["lat_tile"], r["lat_table"])
        conv = "" if r["tile_conv"] and r["table_conv"] else " (not converged: %s)" % ("tile" if not r["tile_conv"] else "table")
        out.append("| %s | %g | %.4g %s | %.4g | %s%s |%s %s | %s | %.4f / %.4f |" % (r["path"], r["value"], r["tile"], unit, r["table"], fmt_pct(r["err"]), conv, (" %s |" % fmt_pct(r.get("err_export"))) if exp else "",
                                                                           fmt_pct(r["err_paper"]), lat, r["shear_tile"], r["shear_table"]))
    out.append("")
    return "\n".join(out), checks


CHECK_ORDER = ["uniaxial T", "lateral strain", "bias T", "equibiaxial T", "shear", "bending moment", "stationarity"]


def preamble(summary, met, total):
    """the document's head: what is compared, the default pipeline, and one line per pattern"""
    import datetime
    out = ["# Fabric fidelity: each table against its own yarn tile", "",
           "Written by `make fidelity` (tools/fidelity_all.sh, then `tools/fabric_fidelity.py --collect`) on %s: "
           "**%d of %d checks met** over %d patterns." % (datetime.date.today().isoformat(), met, total, len(summary)), "",
           "Each table is made by the default pipeline, `tools/hylc-material CONFIG.yaml` with no plan, reference or fit "
           "option: the reference state `-sampler_reference auto` (Algorithm C1 for a generated pattern; a stored tile "
           "relaxed to the in-plane minimum under its configured yarn), the graded plan with hylc's 3D terms "
           "(`-sampler_spacing graded`, the sampler's default), continuation, every sample's stress, and "
           "`-fit_method auto` (the fabric method). Table and tile are then put in the states the standard fabric tests "
           "make (ISO 13934-1 strip tensile along x, y and the 45-degree bias, equibiaxial tension, shear with the "
           "stretches free, bending with the in-plane strains free as in a cantilever or a drape), each continued "
           "along its loading path from rest: the tile by `hylc-solve -solve_path` (the force by the envelope "
           "theorem), the table by `hylc-eval -eval_path` on the HDF5 table (its ARCSim-HYLC JSON export, which "
           "keeps only the paper's terms, and the paper's own table beside it where one exists).", "",
           "Targets: uniaxial T within 5 % of the tile at 2-20 % (10 % at 1 %), the lateral strain within 0.005, bias "
           "T, equibiaxial T and the shear within 10 % (5 % equibiaxial), the bending moment within 5 % at "
           "|II| = 10-50 1/m, and the tile's stationarity at z = 0 below 1 % of T at 5 %. A force near 0 is judged "
           "against a floor: 2 % of the largest |force| on its path, and for a bending moment at least the tile's "
           "moment at rest (the moment of its curl, dPsi/dII at z = 0), so a moment that passes through 0 where a "
           "curled tile's natural curvature is does not give an infinite error.", "",
           "| pattern | met | " + " | ".join(CHECK_ORDER) + " | samples | sampling CPU-s |",
           "|---|---|" + "---|" * len(CHECK_ORDER) + "---|---|"]
    for res, checks in summary:
        by = {}
        for c in checks:
            by.setdefault(c[0], []).append(c)
        cells = ["%d/%d" % (sum(c[3] for c in by[k]), len(by[k])) if k in by else "-" for k in CHECK_ORDER]
        cpu = "%.0f" % res["cpu_s"] if res.get("cpu_s") else "-"
        ns = "{:,}".format(res["nsamples"]) if res.get("nsamples") else "-"
        out.append("| %s | %d/%d | %s | %s | %s |" % (res["name"], sum(c[3] for c in checks), len(checks), " | ".join(cells), ns, cpu))
    out.append("")
    return "\n".join(out) + "\n"


def plots(res, prefix):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return []
    made = []
    groups = [("tension", ["uniaxial x", "uniaxial y", "bias 45", "equibiaxial"], "strain s", "force per width (N/m)"),
              ("shear", ["shear"], "sa", "dPsi/dsa (N/m)"),
              ("bending", ["bending II00 +", "bending II00 -", "bending II11 +", "bending II11 -"], "curvature (1/m)", "moment per width (N)")]
    for (g, labels, xl, yl) in groups:
        fig, ax = plt.subplots(figsize=(6, 4))
        for i, label in enumerate(labels):
            d = res["paths"].get(label)
            if not d:
                continue
            col = "C%d" % i
            for key, style, suffix in (("tile", "o-", " tile"), ("table", "--", " table"), ("paper", ":", " paper")):
                rows = d.get(key)
                if not rows:
                    continue
                ax.plot([r["value"] for r in rows], [r["force"] for r in rows], style, color=col, label=label + suffix, ms=3)
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
        ax.set_title("%s: %s" % (res["name"], g))
        ax.legend(fontsize=6)
        ax.grid(alpha=0.3)
        f = "%s-%s.png" % (prefix, g)
        fig.tight_layout()
        fig.savefig(f, dpi=90)
        plt.close(fig)
        made.append(f)
    return made


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1], formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("config", nargs="?", help="the study's options file")
    ap.add_argument("material", nargs="?", help="the material directory of tools/hylc-material")
    ap.add_argument("--name", help="the pattern's name (default the directory's)")
    ap.add_argument("--paper", help="the paper's table to show beside (default: automatic for the paper's patterns)")
    ap.add_argument("--np", type=int, default=2, help="programs run at a time (default 2)")
    ap.add_argument("--json", help="write the measurements here (default MATERIAL_DIR/fidelity.json)")
    ap.add_argument("--markdown", help="write the section here (default MATERIAL_DIR/fidelity.md)")
    ap.add_argument("--collect", metavar="OUT.md", help="write one document of the results given as arguments")
    ap.add_argument("--plots-dir", help="--collect: copy each result's plots here and link them (default: no plots)")
    ap.add_argument("results", nargs="*", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.collect:
        files = [f for f in [args.config, args.material] + args.results if f]
        parts, total, met, summary = [], 0, 0, []
        for f in files:
            with open(f) as fh:
                res = json.load(fh)
            md, checks = markdown(res)
            # the section's plots sit beside its result
            for g in ("tension", "shear", "bending"):
                png = os.path.join(os.path.dirname(os.path.abspath(f)), "fidelity-%s-%s.png" % (res["name"], g))
                if args.plots_dir and os.path.isfile(png):
                    os.makedirs(args.plots_dir, exist_ok=True)
                    dst = os.path.join(args.plots_dir, os.path.basename(png))
                    with open(png, "rb") as a, open(dst + ".tmp", "wb") as b:
                        b.write(a.read())
                    os.replace(dst + ".tmp", dst)
                    md += "\n![%s](%s)" % (os.path.basename(png), os.path.relpath(dst, os.path.dirname(os.path.abspath(args.collect))))
            parts.append(md + "\n")
            total += len(checks)
            met += sum(c[3] for c in checks)
            summary.append((res, checks))
        with open(args.collect + ".tmp", "w") as fh:
            fh.write(preamble(summary, met, total))
            fh.write("\n".join(parts))
        os.replace(args.collect + ".tmp", args.collect)
        print("wrote %s: %d results, %d of %d checks met" % (args.collect, len(files), met, total))
        return
    if not args.config or not args.material:
        ap.error("CONFIG.yaml and MATERIAL_DIR are needed (or --collect)")
    res = measure(args)
    js = args.json or os.path.join(args.material, "fidelity.json")
    with open(js + ".tmp", "w") as fh:
        json.dump(res, fh, indent=1)
    os.replace(js + ".tmp", js)
    md, checks = markdown(res)
    mdf = args.markdown or os.path.join(args.material, "fidelity.md")
    made = plots(res, os.path.join(os.path.dirname(os.path.abspath(mdf)), "fidelity-%s" % res["name"]))
    if made:
        md += "\n" + "\n".join("![%s](%s)" % (os.path.basename(f), os.path.basename(f)) for f in made) + "\n"
    with open(mdf + ".tmp", "w") as fh:
        fh.write(md)
    os.replace(mdf + ".tmp", mdf)
    print(md)
    print("wrote %s, %s: %d of %d checks met" % (js, mdf, sum(c[3] for c in checks), len(checks)))


if __name__ == "__main__":
    main()
