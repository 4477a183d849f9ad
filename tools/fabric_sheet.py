#!/usr/bin/env python3
"""The fabric sheet (issue 32, Deliver 4): runs hylc-cloth's virtual tests on the paper's seven tables
and on any further tables given, and writes docs/fabric-sheet.md with the measured figures side by side.

    python3 tools/fabric_sheet.py [NAME=TABLE.json|TABLE.h5 ...]
    make fabric-sheet FABRIC_TABLES="ours-satin=/tmp/fs/satin.json ..."

Per table (face up; coarse but converged settings, stated in the sheet):
  strip tensile along x and along y (h 10 mm, 10 steps to 10 %, planar): T(5 %), T(10 %), Poisson(5 %);
  cantilever bending length along x and along y (ASTM D1388 A, 10 mm strip, 16 spacings): c and G, and
  the elastica of the table's bending term (on satin1 the shell is within 0.7 % of it from 16 spacings);
  the free curl (3 x 2 cm strip): the central zone's II00, II11 and the table's own free curl;
  the Cusick drape (0.3 m on 0.18 m, h 10 mm; the static load path, and hylc-cloth's backward Euler
  dynamics where it fails): drape coefficient and node count.
A test that finds no equilibrium (or exceeds the time limit) is reported as such, with hylc-cloth's
message. Environment: HYLC_REFDATA (the paper's tables: $HYLC_REFDATA/materials), HYLC_FABRIC_TABLES
(more NAME=PATH, space separated), HYLC_FABRIC_JOBS (parallel runs, default 2), HYLC_FABRIC_TIMEOUT
(s per run, default 300; the drapes HYLC_FABRIC_DRAPE_TIMEOUT, default 1200), HYLC_FABRIC_OUT (the sheet, default docs/fabric-sheet.md), HYLC_FABRIC_NOTE
(a paragraph on how the extra tables were made), HYLC_FABRIC_PNG (the tables whose tensile and drape
PNGs go to docs/img/fabric-*.png, default "satin1 stock1").
"""
import concurrent.futures as cf
import datetime
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
CLOTH = os.path.join(ROOT, "build", "bin", "hylc-cloth")
REF = os.environ.get("HYLC_REFDATA", os.path.join(ROOT, "..", "shared", "refdata"))
PAPER = ["basket1", "satin1", "stock1", "rib1", "honey1", "satin01", "stock01"]
JOBS = int(os.environ.get("HYLC_FABRIC_JOBS", "2"))
TIMEOUT = float(os.environ.get("HYLC_FABRIC_TIMEOUT", "300"))
DRAPE_TIMEOUT = float(os.environ.get("HYLC_FABRIC_DRAPE_TIMEOUT", "1200"))
OUT = os.environ.get("HYLC_FABRIC_OUT", os.path.join(ROOT, "docs", "fabric-sheet.md"))
PNG = os.environ.get("HYLC_FABRIC_PNG", "satin1 stock1").split()

TENSILE_H = os.environ.get("HYLC_FABRIC_TENSILE_H", "0.01")
STEPS = "10"
CANT_W = "0.01"
CANT_N = os.environ.get("HYLC_FABRIC_CANT_N", "16")
DRAPE_H = os.environ.get("HYLC_FABRIC_DRAPE_H", "0.01")
TESTS = {
    "tensile_x": ["-cloth_test", "tensile", "-cloth_direction", "x", "-cloth_h", TENSILE_H, "-cloth_strain_steps", STEPS],
    "tensile_y": ["-cloth_test", "tensile", "-cloth_direction", "y", "-cloth_h", TENSILE_H, "-cloth_strain_steps", STEPS],
    "cant_x": ["-cloth_test", "cantilever", "-cloth_direction", "x", "-cloth_face", "up", "-cloth_cantilever_width", CANT_W, "-cloth_cantilever_n", CANT_N],
    "cant_y": ["-cloth_test", "cantilever", "-cloth_direction", "y", "-cloth_face", "up", "-cloth_cantilever_width", CANT_W, "-cloth_cantilever_n", CANT_N],
    "curl": ["-cloth_test", "curl", "-cloth_face", "up"],
    "drape": ["-cloth_test", "drape", "-cloth_face", "up", "-cloth_h", DRAPE_H],
}


def run(job):
    name, table, test, tmp = job
    prefix = os.path.join(tmp, f"{name}_{test}")
    plot = name in PNG and test in ("tensile_x", "drape")
    cmd = [CLOTH, "-cloth_material", table] + TESTS[test] + ["-cloth_output", prefix, "-cloth_plot", "1" if plot else "0", "-cloth_vtk", "1" if plot and test == "drape" else "0"]
    t0 = time.time()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=DRAPE_TIMEOUT if test == "drape" else TIMEOUT)
        out, rc = p.stdout, p.returncode
    except subprocess.TimeoutExpired as e:
        out, rc = (e.stdout.decode() if isinstance(e.stdout, bytes) else (e.stdout or "")), "timeout"
    return name, test, out, rc, time.time() - t0, prefix


def shrink(png):
    """a PNG of 100 kB or more made smaller in place: 256 colours (Pillow, which matplotlib needs)"""
    code = ("import sys; from PIL import Image; im = Image.open(sys.argv[1]).convert('RGB'); "
            "im.quantize(256).save(sys.argv[1], optimize=True)")
    for py in ("/usr/bin/python3", "python3"):
        if subprocess.run([py, "-c", code, png], stderr=subprocess.DEVNULL).returncode == 0:
            return


def err_line(out):
    """hylc-cloth's own message where it found no equilibrium (PETSc's error line), or ''"""
    for line in out.splitlines():
        if ("error" in line.lower() or "ERROR" in line) and ("equilibrium" in line or "not converged" in line.lower() or "not at rest" in line):
            return re.sub(r"^.*(ERROR|error):\s*", "", line).strip()
    return ""


def parse(test, out, rc):
    """the figures of one run as strings, or the reason there are none"""
    if rc == "timeout":
        return {"fail": f"not at rest in {DRAPE_TIMEOUT if test == 'drape' else TIMEOUT:.0f} s"}
    r = {}
    if test.startswith("tensile"):
        m = re.search(r"T\(5%\) ([^,]+), T\(10%\) ([^,]+), dT/de\(5%\) [^,]+, Poisson\(5%\) ([^;]+);", out)
        if m:
            r.update(T5=m.group(1).replace(" N/m", ""), T10=m.group(2).replace(" N/m", ""), nu5=m.group(3))
        m = re.search(r"no equilibrium found at strain ([0-9.e-]+): the curve ends at ([0-9.e-]+)", out)
        if m:
            r["note"] = f"no equilibrium at {100 * float(m.group(1)):.3g} %"
        m = re.search(r"(\d+) vertices, (\d+) triangles", out)
        if m:
            r["tri"] = m.group(2)
    elif test.startswith("cant"):
        m = re.search(r"bending length c ([0-9.e+-]+) mm, G = W c\^3 ([0-9.e+-]+) uN m; elastica of the table's bending term: c ([^ ]+) mm", out)
        if m:
            r.update(c=m.group(1), G=m.group(2), ce=m.group(3))
            if r["ce"] == "nan":
                r["ce"] = "none (nan)"
        else:
            m = re.search(r"no equilibrium of the strip at overhang ([0-9.e+-]+) mm", out)
            if m:
                r["fail"] = f"no equilibrium of the strip at overhang {m.group(1)} mm (static load path and dynamics; the strip curls)"
            m = re.search(r"the chord angle does not reach ([0-9.]+) deg \(([0-9.e+-]+) deg at the last overhang, ([0-9.e+-]+) mm", out)
            if m:
                r["fail"] = f"the tip angle {m.group(1)}° is not reached ({m.group(2)}° at a {m.group(3)} mm overhang: the strip curls up)"
        m = re.search(r"elastica of the table's bending term: c ([^ ]+) mm", out)
        if m and "ce" not in r:
            r["ce"] = "none (nan)" if m.group(1) == "nan" else m.group(1)
    elif test == "curl":
        m = re.search(r"central zone: II00 ([0-9.e+-]+) 1/m, II11 ([0-9.e+-]+) 1/m; the table's free curl: II00 ([0-9.e+-]+) 1/m, II11 ([0-9.e+-]+) 1/m", out)
        if m:
            r.update(z0=m.group(1), z1=m.group(2), t0=m.group(3), t1=m.group(4))
    elif test == "drape":
        m = re.search(r"drape coefficient ([0-9.]+) .*?, (\d+) nodes", out)
        if m:
            r.update(dc=m.group(1), nodes=m.group(2))
        m = re.search(r"(\d+) vertices, (\d+) triangles", out)
        if m:
            r["tri"] = m.group(2)
    if "fail" not in r and (rc != 0 or not any(k in r for k in ("T5", "c", "z0", "dc"))):
        e = err_line(out)
        r["fail"] = "no equilibrium" + (f" ({e})" if e else f" (exit {rc})")
    return r


def cell(r, key, fmt=None):
    if "fail" in r and key not in r:
        return "not at rest" if r["fail"].startswith("not at rest") else ("curls: no c" if "curls" in r["fail"] else "no equilibrium")
    v = r.get(key, "—")
    if fmt and v not in ("—", "not reached"):
        try:
            v = fmt % float(v)
            return "0.000" if v == "-0.000" else v
        except ValueError:
            return v
    return v


def main(argv):
    extra = argv[1:] + os.environ.get("HYLC_FABRIC_TABLES", "").split()
    tables = []
    for n in PAPER:
        p = os.path.join(REF, "materials", n + ".json")
        if os.path.isfile(p):
            tables.append((n, p, "paper"))
        else:
            print(f"fabric_sheet: {p} not found; skipped")
    for e in extra:
        n, _, p = e.partition("=")
        if not p or not os.path.isfile(p):
            sys.exit(f"fabric_sheet: extra table '{e}' is not NAME=PATH of an existing file")
        tables.append((n, p, "ours"))
    if not tables:
        print("fabric_sheet: no tables; skipped")
        return 0
    if any(os.path.abspath(p) == os.path.abspath(OUT) for _, p, _ in tables):
        sys.exit(f"fabric_sheet: the output {OUT} is one of the tables")
    if not os.path.isdir(os.path.dirname(os.path.abspath(OUT))):
        sys.exit(f"fabric_sheet: the output's directory {os.path.dirname(OUT)} does not exist")
    if not os.access(CLOTH, os.X_OK):
        sys.exit(f"fabric_sheet: {CLOTH} not found (run make)")
    tmp = tempfile.mkdtemp(prefix="fabric-sheet-")
    load0 = open("/proc/loadavg").read().split()[:3]
    t0 = time.time()
    res, secs = {}, {}
    jobs = [(n, p, t, tmp) for n, p, _ in tables for t in TESTS]
    jobs.sort(key=lambda j: j[2] != "drape")  # the long runs first
    with cf.ThreadPoolExecutor(JOBS) as ex:
        for name, test, out, rc, dt, prefix in ex.map(run, jobs):
            r = parse(test, out, rc)
            res[(name, test)], secs[(name, test)] = r, dt
            print(f"{name:14s} {test:10s} {dt:6.1f} s  {r}", flush=True)
            if name in PNG and test in ("tensile_x", "drape"):
                kind = "tensile" if test.startswith("tensile") else "drape"
                for png in sorted(f for f in os.listdir(tmp) if f.startswith(f"{name}_{test}") and f.endswith(".png")):
                    src = os.path.join(tmp, png)
                    if os.path.getsize(src) >= 100_000:
                        shrink(src)
                    if os.path.getsize(src) < 100_000:
                        dst = os.path.join(ROOT, "docs", "img", f"fabric-{name}-{kind}.png")
                        os.makedirs(os.path.dirname(dst), exist_ok=True)
                        shutil.copyfile(src, dst)
                        r["png"] = os.path.relpath(dst, os.path.dirname(OUT))
                    else:
                        print(f"fabric_sheet: {png} is {os.path.getsize(src)} bytes (> 100 kB): not kept")
    wall = time.time() - t0
    load1 = open("/proc/loadavg").read().split()[:3]
    shutil.rmtree(tmp, ignore_errors=True)

    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    L = []
    L.append("# Fabric sheet: hylc-cloth's virtual tests on the paper's tables and ours\n")
    L.append(f"Generated by `tools/fabric_sheet.py` (`make fabric-sheet`) on {date}, {wall:.0f} s wall for "
             f"{len(jobs)} runs ({JOBS} at a time, 1 rank each; load average {' '.join(load0)} before, "
             f"{' '.join(load1)} after, 2 cores). Every figure below is the measured output of that run; "
             "do not edit by hand, rerun the script. The method and the tests are in [fabric.md](fabric.md).\n")
    L.append("Settings (coarse, chosen to keep the sheet within about 40 minutes; docs/fabric.md has the mesh studies): face up "
             f"(n = +z) for every test; strip tensile 0.2 × 0.05 m, h = {TENSILE_H} m, planar, 10 steps to 10 % "
             "(stock1 x, docs/fabric.md: T(5 %) 1.41209 N/m at h = 10 mm, 1.40769 at 5 mm, 1.40611 at 2.5 mm); cantilever ASTM D1388 A, 10 mm wide strip, "
             f"{CANT_N} spacings over the overhang (on satin1 16 spacings are 0.4 % short of the elastica "
             "along x and y, 64 spacings 0.6–0.7 %, docs/fabric.md; the elastica of the table's bending "
             "term is given beside it); free curl of a "
             f"3 × 2 cm strip, h = 2 mm; Cusick drape, 0.3 m on 0.18 m, h = {DRAPE_H} m (the static load path, and the backward Euler dynamics where it fails: `-cloth_dynamic auto`; 0.01 m: "
             "1,590 triangles; the drape coefficient is not shown mesh-converged: satin1 gave 0.19 at h = 20 mm). "
             f"Each run is stopped after {TIMEOUT:.0f} s, a drape after {DRAPE_TIMEOUT:.0f} s.\n")
    note = os.environ.get("HYLC_FABRIC_NOTE", "")
    if any(k == "ours" for _, _, k in tables):
        L.append("Our tables (\"ours-…\"): " + (note or "given on the command line.") + "\n")
    L.append("## Tensile (ISO 13934-1 strip) and drape\n")
    L.append("| table | source | T x 5 % (N/m) | T x 10 % | T y 5 % | T y 10 % | Poisson x 5 % | Poisson y 5 % | drape coefficient | nodes |")
    L.append("|---|---|---|---|---|---|---|---|---|---|")
    for n, p, k in tables:
        tx, ty, d = res[(n, "tensile_x")], res[(n, "tensile_y")], res[(n, "drape")]

        def tnote(r, key):
            c = cell(r, key)
            return c + (f" ({r['note']})" if "note" in r and c == "not reached" else "")
        L.append(f"| {n} | {k} | {tnote(tx, 'T5')} | {tnote(tx, 'T10')} | {tnote(ty, 'T5')} | {tnote(ty, 'T10')} | "
                 f"{cell(tx, 'nu5', '%.3f')} | {cell(ty, 'nu5', '%.3f')} | {cell(d, 'dc')} | {cell(d, 'nodes')} |")
    L.append("")
    L.append("## Bending (ASTM D1388 A cantilever, face up) and the free curl\n")
    L.append("G = W c³ (W the table's weight per area). The free curl: the curvatures of a free 3 × 2 cm strip's "
             "central zone against the table's own free curl (Ψ minimal over II00, II11 at zero in-plane "
             "strain); > 0 bends toward n.\n")
    L.append("| table | source | c x (mm) | G x (µN·m) | c y (mm) | G y (µN·m) | elastica c x / c y (mm) | curl II00, II11 (1/m) | table's free curl II00, II11 (1/m) |")
    L.append("|---|---|---|---|---|---|---|---|---|")
    for n, p, k in tables:
        cx, cy, cu = res[(n, "cant_x")], res[(n, "cant_y")], res[(n, "curl")]
        L.append(f"| {n} | {k} | {cell(cx, 'c')} | {cell(cx, 'G')} | {cell(cy, 'c')} | {cell(cy, 'G')} | "
                 f"{cell(cx, 'ce')} / {cell(cy, 'ce')} | {cell(cu, 'z0')}, {cell(cu, 'z1')} | {cell(cu, 't0')}, {cell(cu, 't1')} |")
    L.append("")
    fails = [(n, t, res[(n, t)]) for n, _, _ in tables for t in TESTS if "fail" in res[(n, t)] or "note" in res[(n, t)]]
    if fails:
        L.append("## Where no equilibrium was found\n")
        L.append("hylc-cloth's message per run (\"no equilibrium\" or \"not reached\" above). The static solver "
                 "(load stepping with Newton, a failed step halved) stops where the load path has no nearby "
                 "equilibrium it can reach, e.g. where a fold or curl forms; there the backward Euler dynamics "
                 "takes over (`-cloth_dynamic auto`) and may still find none (a strip that curls tighter than "
                 "its overhang: ASTM D1388 leaves such fabrics out) or not come to rest within the time limit; "
                 "cloth self-contact is not modelled (docs/fabric.md).\n")
        for n, t, r in fails:
            L.append(f"- {n}, {t}: {r.get('fail', '')}{'; ' if 'fail' in r and 'note' in r else ''}{r.get('note', '')}")
        L.append("")
    pngs = [(n, t, res[(n, t)]["png"]) for n, _, _ in tables for t in ("tensile_x", "drape") if "png" in res.get((n, t), {})]
    if pngs:
        L.append("## Plots\n")
        for n, t, f in pngs:
            L.append(f"- {n}, {'strip tensile along x' if t == 'tensile_x' else 'Cusick drape, top view'}: [{os.path.basename(f)}]({f})")
        L.append("")
    L.append("## Run times (s)\n")
    L.append("| table | " + " | ".join(TESTS) + " |")
    L.append("|---|" + "---|" * len(TESTS))
    for n, _, _ in tables:
        L.append(f"| {n} | " + " | ".join(f"{secs[(n, t)]:.1f}" for t in TESTS) + " |")
    L.append("")
    L.append("Commands (one per cell; PATH the table): `hylc-cloth -cloth_material PATH " + "`, `".join(
        " ".join(TESTS[t]) for t in TESTS) + "`, each with `-cloth_output PREFIX -cloth_plot 0 -cloth_vtk 0`.\n")
    with open(OUT + ".tmp", "w") as f:
        f.write("\n".join(L))
    os.replace(OUT + ".tmp", OUT)
    print(f"fabric_sheet: wrote {OUT} ({wall:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
