#!/usr/bin/env python3
"""Which public functions of libhylc have a manual page (docs/architecture.md, "Manual pages").

A public function is a PETSC_EXTERN PetscErrorCode Hylc* declared in include/hylc/*.h; it has a manual page
when its definition in src/ is preceded by a /*@ ... @*/ block that names it. Prints per header the number of
functions and of those without a page, then (with --list) each function without one.
    tools/manpages.py [--list]
Exit status 0; run from the repository's top directory."""
import collections
import glob
import re
import sys


def main():
    decl = {}
    for h in sorted(glob.glob("include/hylc/*.h")):
        for m in re.finditer(r"PETSC_EXTERN\s+PetscErrorCode\s+(Hylc\w+)\s*\(", open(h).read()):
            decl[m.group(1)] = h
    src = [open(f).read() for f in sorted(glob.glob("src/*/*.c"))]
    missing = []
    for fn, h in decl.items():
        page = False
        for s in src:
            m = re.search(r"^(?:[A-Z_]+ )?PetscErrorCode\s+%s\s*\(" % fn, s, re.M)
            if not m:
                continue
            before = s[: m.start()].rstrip()
            page = before.endswith("@*/") and fn in before[before.rfind("/*@") :]
            break
        if not page:
            missing.append((h, fn))
    total = collections.Counter(decl.values())
    without = collections.Counter(h for h, _ in missing)
    print("%d public functions, %d with a manual page, %d without" % (len(decl), len(decl) - len(missing), len(missing)))
    for h in sorted(total):
        print("  %-28s %3d functions, %3d without a page" % (h, total[h], without.get(h, 0)))
    if "--list" in sys.argv[1:]:
        for h, fn in missing:
            print("%s: %s" % (h, fn))


if __name__ == "__main__":
    main()
