"""The version of the hylc Python package: hylc's own (HYLC_VERSION_STRING of include/hylc/sys.h; the
test tests/regression/python_package.sh keeps the two equal). Read by pyproject.toml without importing
the package."""
__version__ = "0.1.0"
