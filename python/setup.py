"""Builds the hylc Python package with its own copy of libhylcmat (pyproject.toml holds the metadata).

The module loads libhylcmat through ctypes. So that an installed package works on its own, the build puts
hylc/libhylcmat.so into the package, taken from (first found):
  1. $HYLCMAT_LIB (a libhylcmat.so built elsewhere);
  2. the sources of a checkout (../src/hylcmat, ../src/sys/json.c and strain.c), compiled here with the system C
     compiler ($CC, default cc) and the flags of the Makefile's `hylcmat` target: C99, libc and libm only;
  3. an installed prefix (this directory is PREFIX/share/hylc/python after `make install`):
     PREFIX/lib/libhylcmat.so.
Setuptools' build directories go to a temporary directory, so the source tree (or the installed prefix)
is left as it was.
"""
import atexit
import glob
import os
import shutil
import subprocess
import tempfile

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
# the files the Makefile compiles at -O3 (HM_FAST), the rest at -O2
FAST = {"eval.c", "shell.c", "psd.c", "mesh.c"}


def compile_library(dest, workdir):
    """compiles libhylcmat from the checkout's sources into dest; False if there are none"""
    sources = sorted(glob.glob(os.path.join(TOP, "src", "hylcmat", "*.c")))
    json_c = os.path.join(TOP, "src", "sys", "json.c")
    strain_c = os.path.join(TOP, "src", "sys", "strain.c")  # the names of strains and terms (include/hylc/strain.h)
    if not sources or not os.path.exists(json_c) or not os.path.exists(strain_c):
        return False
    cc = os.environ.get("CC", "cc")
    common = ["-std=c99", "-D_POSIX_C_SOURCE=200809L", "-g", "-fPIC", "-fvisibility=default", "-I", os.path.join(TOP, "include")]
    objects = []
    for src in sources + [json_c, strain_c]:
        obj = os.path.join(workdir, "%d-%s.o" % (len(objects), os.path.basename(src)[:-2]))
        opt = "-O3" if os.path.basename(src) in FAST and src not in (json_c, strain_c) else "-O2"
        cmd = [cc, opt] + common + ["-c", src, "-o", obj]
        print(" ".join(cmd))
        subprocess.check_call(cmd)
        objects.append(obj)
    cmd = [cc, "-shared", "-Wl,-soname,libhylcmat.so.1", "-o", dest] + objects + ["-lm"]
    print(" ".join(cmd))
    subprocess.check_call(cmd)
    return True


def provide_library(dest):
    env = os.environ.get("HYLCMAT_LIB")
    if env:
        shutil.copyfile(env, dest)
        return "copied from $HYLCMAT_LIB=" + env
    work = tempfile.mkdtemp(prefix="hylcmat-build-")
    try:
        if compile_library(dest, work):
            return "compiled from " + os.path.join(TOP, "src", "hylcmat")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    installed = os.path.normpath(os.path.join(HERE, "..", "..", "..", "lib", "libhylcmat.so"))
    if os.path.exists(installed):
        shutil.copyfile(installed, dest)  # follows the symlink to libhylcmat.so.1
        return "copied from " + installed
    raise SystemExit("hylc: no libhylcmat to put into the package: not in a checkout (%s missing), no %s, "
                     "and $HYLCMAT_LIB is not set" % (os.path.join(TOP, "src", "hylcmat"), installed))


class BuildPyWithLibrary(build_py):
    """build_py, then hylc/libhylcmat.so next to the modules"""

    def run(self):
        super().run()
        dest = os.path.join(self.build_lib, "hylc", "libhylcmat.so")
        os.makedirs(os.path.dirname(dest), exist_ok=True)
        print("hylc: libhylcmat.so " + provide_library(dest))


class BinaryDistribution(Distribution):
    """the wheel holds a shared library: tag it for this platform, not as pure Python"""

    def has_ext_modules(self):
        return True


_tmp = tempfile.mkdtemp(prefix="hylc-pybuild-")
atexit.register(shutil.rmtree, _tmp, True)
setup(cmdclass={"build_py": BuildPyWithLibrary}, distclass=BinaryDistribution,
      options={"build": {"build_base": os.path.join(_tmp, "build")}, "egg_info": {"egg_base": _tmp}})
