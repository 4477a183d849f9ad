"""hylc: Python access to the hylc cloth material model (libhylcmat, through ctypes) and readers of
hylc's HDF5 files (through h5py).

    import hylc
    m = hylc.Material("stock1.json")            # or a hylc HDF5 material (model.h5)
    psi, grad, hess = m.evaluate(strains)       # strains (..., 6) -> (...), (..., 6), (..., 6, 6)
    psi, grad = m.evaluate(strains, hessian=False)
    mesh = hylc.Mesh(triangles, rest=X)         # or uv=...: the shell element of Algorithm C8
    E, grad, H = mesh.evaluate(m, x)            # (), (nv, 3), scipy.sparse (3 nv x 3 nv)

Strains are s = (sx, sa, sy, II00, II01, II11): stretches sx, sy (0 at rest), sa the cosine of the
angle between the deformed material axes, II the second fundamental form in 1/m. Psi is in J/m^2
(docs/library.md). The library is found through $HYLCMAT_LIB, then inside this package (the copy that
`pip install ./python` builds, python/setup.py), then next to it (a checkout's build/, an installed
prefix's lib/), then the system's library path; `hylc.library_path` says which one was loaded.
"""
import ctypes
import ctypes.util
import os

import numpy as np

from ._version import __version__

__all__ = ["Material", "Mesh", "HylcError", "read_material_h5", "read_samples", "library_path", "__version__"]

_HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"
TERMS_1D = ["sx", "sa", "sy", "II00", "II11"]
TERMS_2D = ["sx-sa", "sx-sy", "sx-II00", "sx-II11", "sa-sy", "sa-II00", "sa-II11", "sy-II00", "sy-II11"]
PAIRS = [(0, 1), (0, 2), (0, 3), (0, 4), (1, 2), (1, 3), (1, 4), (2, 3), (2, 4)]


class HylcError(RuntimeError):
    """An error reported by libhylcmat: .code is its HYLCMAT_ERR_* code, the message names the file,
    line and key."""

    def __init__(self, code, message):
        super().__init__(message)
        self.code = code


def _candidates():
    env = os.environ.get("HYLCMAT_LIB")
    if env:
        yield env
    here = os.path.dirname(os.path.abspath(__file__))
    yield os.path.join(here, "libhylcmat.so")                                # pip install ./python
    build = os.environ.get("BUILD", "build")
    yield os.path.join(here, "..", "..", build, "libhylcmat.so")          # a checkout: python/hylc
    yield os.path.join(here, "..", "..", "..", "..", "lib", "libhylcmat.so")  # PREFIX/share/hylc/python/hylc
    found = ctypes.util.find_library("hylcmat")
    if found:
        yield found


def _load_library():
    tried = []
    for path in _candidates():
        if os.path.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            path = os.path.normpath(path) if os.path.sep in path else path
            return ctypes.CDLL(path), path
        except OSError as e:
            tried.append("%s (%s)" % (path, e))
    raise ImportError("hylc: libhylcmat.so not found (build it with 'make hylcmat' or set HYLCMAT_LIB); tried: " + ", ".join(tried))


_lib, library_path = _load_library()
_dp = ctypes.POINTER(ctypes.c_double)
_vp = ctypes.c_void_p
_lib.hylcmat_load.argtypes = [ctypes.c_char_p, ctypes.POINTER(_vp), ctypes.c_char_p, ctypes.c_size_t]
_lib.hylcmat_load.restype = ctypes.c_int
_lib.hylcmat_create.argtypes = [ctypes.POINTER(_vp)]
_lib.hylcmat_create.restype = ctypes.c_int
_lib.hylcmat_free.argtypes = [_vp]
_lib.hylcmat_free.restype = None
_lib.hylcmat_has_hdf5.argtypes = []
_lib.hylcmat_has_hdf5.restype = ctypes.c_int
_lib.hylcmat_eval_batch.argtypes = [_vp, ctypes.c_size_t, _vp, _vp, _vp, _vp]
_lib.hylcmat_eval_batch.restype = ctypes.c_int
_lib.hylcmat_strerror.argtypes = [ctypes.c_int]
_lib.hylcmat_strerror.restype = ctypes.c_char_p
_lib.hylcmat_density.argtypes = [_vp]
_lib.hylcmat_density.restype = ctypes.c_double
_lib.hylcmat_constant.argtypes = [_vp]
_lib.hylcmat_constant.restype = ctypes.c_double
_lib.hylcmat_strain_scale.argtypes = [_vp, _dp]
_lib.hylcmat_strain_scale.restype = None
for _f in ("hylcmat_set_density", "hylcmat_set_constant"):
    getattr(_lib, _f).argtypes = [_vp, ctypes.c_double, ctypes.c_char_p, ctypes.c_size_t]
    getattr(_lib, _f).restype = ctypes.c_int
_lib.hylcmat_set_strain_scale.argtypes = [_vp, _dp, ctypes.c_char_p, ctypes.c_size_t]
_lib.hylcmat_set_strain_scale.restype = ctypes.c_int
_lib.hylcmat_set_strain_shift.argtypes = [_vp, ctypes.POINTER(ctypes.c_int)]
_lib.hylcmat_set_strain_shift.restype = None


_ip = ctypes.POINTER(ctypes.c_int)
_i64p = ctypes.POINTER(ctypes.c_int64)
for _f, _args in (("hylcmat_mesh_create", [ctypes.c_int, ctypes.c_int, _vp, _vp, _vp, ctypes.POINTER(_vp), ctypes.c_char_p, ctypes.c_size_t]),
                  ("hylcmat_mesh_create_uv", [ctypes.c_int, ctypes.c_int, _vp, _vp, ctypes.POINTER(_vp), ctypes.c_char_p, ctypes.c_size_t]),
                  ("hylcmat_mesh_strains", [_vp, _vp, _vp, ctypes.c_char_p, ctypes.c_size_t]),
                  ("hylcmat_mesh_eval", [_vp, _vp, _vp, ctypes.c_int, _dp, _vp, _vp, ctypes.c_char_p, ctypes.c_size_t]),
                  ("hylcmat_mesh_element", [_vp, ctypes.c_int, _vp, _vp])):
    getattr(_lib, _f).argtypes = _args
    getattr(_lib, _f).restype = ctypes.c_int
_lib.hylcmat_mesh_free.argtypes = [_vp]
_lib.hylcmat_mesh_free.restype = None
for _f in ("hylcmat_mesh_nv", "hylcmat_mesh_nt"):
    getattr(_lib, _f).argtypes = [_vp]
    getattr(_lib, _f).restype = ctypes.c_int
_lib.hylcmat_mesh_area.argtypes = [_vp]
_lib.hylcmat_mesh_area.restype = ctypes.c_double
_lib.hylcmat_mesh_hessian_nnz.argtypes = [_vp]
_lib.hylcmat_mesh_hessian_nnz.restype = ctypes.c_int64
_lib.hylcmat_mesh_hessian_csr.argtypes = [_vp, _vp, _vp]
_lib.hylcmat_mesh_hessian_csr.restype = None
_lib.hylcmat_mesh_hessian_coo.argtypes = [_vp, _vp, _vp]
_lib.hylcmat_mesh_hessian_coo.restype = None
for _f in ("hylcmat_term1d_get", "hylcmat_term2d_get"):
    getattr(_lib, _f).restype = ctypes.c_int
_lib.hylcmat_term1d_get.argtypes = [_vp, ctypes.c_int, _vp]
_lib.hylcmat_term2d_get.argtypes = [_vp, ctypes.c_int, ctypes.c_int, _vp]
PSD = 1  # HYLCMAT_SHELL_PSD


class _Term1D(ctypes.Structure):
    _fields_ = [("k", ctypes.c_int), ("n", ctypes.c_int), ("ext", ctypes.c_int), ("t", _dp), ("p", _dp), ("m", _dp)]


class _Term2D(ctypes.Structure):
    _fields_ = [("k0", ctypes.c_int), ("k1", ctypes.c_int), ("nu", ctypes.c_int), ("nv", ctypes.c_int), ("ext", ctypes.c_int),
                ("tu", _dp), ("tv", _dp), ("p", _dp), ("mu", _dp), ("mv", _dp), ("muv", _dp)]


_lib.hylcmat_set_term1d.argtypes = [_vp, ctypes.POINTER(_Term1D), ctypes.c_char_p, ctypes.c_size_t]
_lib.hylcmat_set_term1d.restype = ctypes.c_int
_lib.hylcmat_set_term2d.argtypes = [_vp, ctypes.POINTER(_Term2D), ctypes.c_char_p, ctypes.c_size_t]
_lib.hylcmat_set_term2d.restype = ctypes.c_int


def _check(code, err=None):
    if code:
        msg = err.value.decode("utf-8", "replace") if err is not None and err.value else _lib.hylcmat_strerror(code).decode()
        raise HylcError(code, msg)


def _live(obj):
    """the library handle of a Material or Mesh; a HylcError (HYLCMAT_ERR_ARG) once it has been freed"""
    h = getattr(obj, "_h", None)
    if not h:
        raise HylcError(6, "hylc.%s: used after it was freed" % type(obj).__name__)
    return h


def _darr(a):
    a = np.ascontiguousarray(np.asarray(a, dtype=np.float64).ravel())
    return a, a.ctypes.data_as(_dp)


class Material:
    """A material table (ARCSim-HYLC JSON or hylc HDF5), evaluated by libhylcmat. Read-only after
    loading; evaluate() may be called from several threads (it releases the GIL in the C call)."""

    def __init__(self, path):
        self.path = os.fspath(path)
        self._h = _vp()
        with open(self.path, "rb") as fh:
            head = fh.read(8)
        if head == _HDF5_SIGNATURE and not _lib.hylcmat_has_hdf5():
            self._from_h5(self.path)
        else:
            err = ctypes.create_string_buffer(1024)
            _check(_lib.hylcmat_load(self.path.encode(), ctypes.byref(self._h), err, len(err)), err)

    def _from_h5(self, path):
        """builds the table from an HDF5 material read with h5py: every array's length is checked here
        (libhylcmat gets bare pointers and lengths), libhylcmat validates every value"""
        d = read_material_h5(path)
        _check_material_shapes(path, d)
        err = ctypes.create_string_buffer(1024)
        try:
            self._install_h5(d, err)
        except HylcError as e:  # libhylcmat's message names the term and the value: add the file
            raise HylcError(e.code, "%s: %s" % (path, e)) from None

    def _install_h5(self, d, err):
        """the contents read by _from_h5 through libhylcmat's validating setters"""
        _check(_lib.hylcmat_create(ctypes.byref(self._h)))
        _check(_lib.hylcmat_set_density(self._h, d["density"], err, len(err)), err)
        _check(_lib.hylcmat_set_constant(self._h, d["constant"], err, len(err)), err)
        sc, p = _darr(d["strain_scale"])
        _check(_lib.hylcmat_set_strain_scale(self._h, p, err, len(err)), err)
        if "strain_shift" in d:
            sh = (ctypes.c_int * 5)(*[int(x) for x in d["strain_shift"]])
            _lib.hylcmat_set_strain_shift(self._h, sh)
        for name, g in d["1D"].items():
            arrs = [_darr(g[k]) for k in ("t", "p", "m")]
            t = _Term1D(int(g["k"]), len(arrs[0][0]), int(g["ext"]), *[a[1] for a in arrs])
            _check(_lib.hylcmat_set_term1d(self._h, ctypes.byref(t), err, len(err)), err)
        for name, g in d["2D"].items():
            arrs = [_darr(g[k]) for k in ("tu", "tv", "p", "mu", "mv", "muv")]
            t = _Term2D(int(g["k0"]), int(g["k1"]), len(arrs[0][0]), len(arrs[1][0]), int(g["ext"]), *[a[1] for a in arrs])
            _check(_lib.hylcmat_set_term2d(self._h, ctypes.byref(t), err, len(err)), err)

    def __del__(self):
        h = getattr(self, "_h", None)
        if h:
            _lib.hylcmat_free(h)
            self._h = _vp()

    @property
    def density(self):
        """area density rho_A (kg/m^2)"""
        return _lib.hylcmat_density(_live(self))

    @property
    def constant(self):
        """the constant C0 of the table (J/m^2): Psi = C0 + the sum of its terms"""
        return _lib.hylcmat_constant(_live(self))

    @property
    def strain_scale(self):
        """the 5 strain scales (sx, sa, sy, II00, II11) by which a strain is divided before the splines"""
        s = (ctypes.c_double * 5)()
        _lib.hylcmat_strain_scale(_live(self), s)
        return np.array(s[:])

    def evaluate(self, strains, hessian=True, gradient=True):
        """Psi and its derivatives at strains of any shape (..., 6) (sx, sa, sy, II00, II01, II11).

        Returns psi (...) in J/m^2, dPsi/ds (..., 6) and d2Psi/ds2 (..., 6, 6): the leading axes of the
        input are kept, so (N, 6) gives (N,), (N, 6), (N, 6, 6), a grid (nx, ny, 6) gives (nx, ny), ...,
        and one strain (6,) gives a scalar psi, a (6,) gradient and a (6, 6) Hessian. hessian=False
        returns (psi, grad); gradient=False as well returns psi alone. A strain that is not finite or lies
        outside the domain (1 + sx > 0, 1 + sy > 0, |sa| < 1) raises HylcError naming the first such
        strain; the GIL is released during the C call."""
        h = _live(self)
        s = np.asarray(strains, dtype=np.float64)
        if s.ndim == 0 or s.shape[-1] != 6:
            raise ValueError("strains must have shape (..., 6) (sx, sa, sy, II00, II01, II11), got %s" % (np.shape(strains),))
        lead = s.shape[:-1]
        flat = np.ascontiguousarray(s.reshape(-1, 6))
        n = flat.shape[0]
        ok = np.all(np.isfinite(flat), axis=1) & (flat[:, 0] > -1) & (flat[:, 2] > -1) & (np.abs(flat[:, 1]) < 1)
        if not np.all(ok):
            i = int(np.argmin(ok))
            where = " %s" % (tuple(int(k) for k in np.unravel_index(i, lead)),) if lead else ""
            raise HylcError(6, "strain%s (%s): %s" % (where, ", ".join("%.17g" % v for v in flat[i]),
                            "not finite" if not np.all(np.isfinite(flat[i])) else "outside the domain 1 + sx > 0, 1 + sy > 0, |sa| < 1"))
        psi = np.empty(n)
        grad = np.empty((n, 6)) if (gradient or hessian) else None
        hess = np.empty((n, 6, 6)) if hessian else None
        if n:
            r = _lib.hylcmat_eval_batch(h, n, flat.ctypes.data, psi.ctypes.data, grad.ctypes.data if grad is not None else None,
                                        hess.ctypes.data if hess is not None else None)
            _check(r)
        psi = psi[0] if lead == () else psi.reshape(lead)
        grad = grad.reshape(lead + (6,)) if grad is not None else None
        hess = hess.reshape(lead + (6, 6)) if hess is not None else None
        if hessian:
            return psi, grad, hess
        if gradient:
            return psi, grad
        return psi

    def psi(self, strains):
        """Psi alone (J/m^2) at strains (..., 6): an array of shape (...), a scalar for one strain (6,)."""
        return self.evaluate(strains, hessian=False, gradient=False)

    def terms(self):
        """The names of the table's terms, 1D first ("sx", ..., "II11"), then 2D ("sx-sa", ...), in the
        order of the JSON tables; a term absent from the table is not listed."""
        h = _live(self)
        one = [TERMS_1D[k] for k in range(5) if _lib.hylcmat_term1d_get(h, k, None)]
        two = [TERMS_2D[q] for q, (k0, k1) in enumerate(PAIRS) if _lib.hylcmat_term2d_get(h, k0, k1, None)]
        return one + two

    def __repr__(self):
        if not getattr(self, "_h", None):
            return "<hylc.Material %r: freed>" % (getattr(self, "path", None),)
        t = self.terms()
        n1 = sum(1 for x in t if "-" not in x)
        return "<hylc.Material %r: density %.6g kg/m^2, C0 %.6g J/m^2, %d 1D + %d 2D terms, strain scale %s>" % (
            self.path, self.density, self.constant, n1, len(t) - n1, np.array2string(self.strain_scale, separator=", "))


class Mesh:
    """A triangle mesh of shell elements (Algorithm C8, libhylcmat's hylcmat_mesh): the adjacency, the
    rest data and the Hessian's sparsity are computed once.

        Mesh(triangles, rest=X, angle=None)   # rest positions (nv, 3) in m, material angle per
                                              # triangle (radians from the edge x1 - x0; None: 0)
        Mesh(triangles, uv=U)                 # material coordinates (m): per vertex (nv, 2) or per
                                              # triangle corner (nt, 3, 2)

    triangles: (nt, 3) vertex indices, counter-clockwise in material coordinates (this fixes the
    normal n: II > 0 bends toward n). An edge of one triangle is a boundary edge. Errors (non-manifold
    edge, inverted or zero-area rest triangle, ...) raise HylcError with the triangle in the message."""

    def __init__(self, triangles, rest=None, angle=None, uv=None):
        t = np.asarray(triangles)
        if t.ndim != 2 or t.shape[1] != 3:
            raise ValueError("triangles must have shape (nt, 3), got %s" % (np.shape(triangles),))
        if t.dtype.kind not in "iu":
            raise TypeError("triangles must be integer vertex indices, got %s" % t.dtype)
        if t.size and (t.min() < 0 or t.max() >= np.iinfo(np.int32).max):
            bad = t.min() if t.min() < 0 else t.max()
            raise HylcError(10, "mesh: vertex index %d is out of range" % bad)
        tri = np.ascontiguousarray(t, dtype=np.int32)
        self._h = _vp()
        err = ctypes.create_string_buffer(1024)
        nt = tri.shape[0]
        if (rest is None) == (uv is None):
            raise ValueError("give either rest (nv, 3) or uv (nv, 2) / (nt, 3, 2)")
        if rest is not None:
            X = np.ascontiguousarray(rest, dtype=np.float64)
            if X.ndim != 2 or X.shape[1] != 3:
                raise ValueError("rest must have shape (nv, 3), got %s" % (X.shape,))
            nv = X.shape[0]
            ang = None
            if angle is not None:
                ang = np.ascontiguousarray(np.broadcast_to(np.asarray(angle, dtype=np.float64), (nt,)))
            _check(_lib.hylcmat_mesh_create(nv, nt, tri.ctypes.data, X.ctypes.data, ang.ctypes.data if ang is not None else None,
                                            ctypes.byref(self._h), err, len(err)), err)
        else:
            U = np.asarray(uv, dtype=np.float64)
            if U.ndim == 2 and U.shape[1] == 2:
                nv = U.shape[0]
                if tri.size and (tri.min() < 0 or tri.max() >= nv):
                    raise HylcError(10, "mesh: a vertex index is out of range (%d vertices)" % nv)
                U = U[tri]
            elif U.ndim == 3 and U.shape[1:] == (3, 2) and U.shape[0] == nt:
                nv = int(tri.max()) + 1 if tri.size else 0
            else:
                raise ValueError("uv must have shape (nv, 2) or (nt, 3, 2), got %s" % (U.shape,))
            U = np.ascontiguousarray(U.reshape(nt, 6))
            _check(_lib.hylcmat_mesh_create_uv(nv, nt, tri.ctypes.data, U.ctypes.data, ctypes.byref(self._h), err, len(err)), err)
        self.nv = _lib.hylcmat_mesh_nv(self._h)
        self.nt = _lib.hylcmat_mesh_nt(self._h)
        self.nnz = int(_lib.hylcmat_mesh_hessian_nnz(self._h))
        self._csr = None

    def __repr__(self):
        if not getattr(self, "_h", None):
            return "<hylc.Mesh: freed>"
        return "<hylc.Mesh: %d vertices, %d triangles, rest area %.6g m^2, %d Hessian nonzeros>" % (self.nv, self.nt, self.area, self.nnz)

    def __del__(self):
        h = getattr(self, "_h", None)
        if h:
            _lib.hylcmat_mesh_free(h)
            self._h = _vp()

    @property
    def area(self):
        """the total rest area (m^2)"""
        return _lib.hylcmat_mesh_area(_live(self))

    @property
    def stencils(self):
        """(nt, 6) vertex indices of each triangle's stencil: its vertices, then the neighbours across
        the edges (0,1), (1,2), (2,0); -1 on a boundary edge"""
        h = _live(self)
        st = np.empty((self.nt, 6), dtype=np.int32)
        for t in range(self.nt):
            _check(_lib.hylcmat_mesh_element(h, t, st[t].ctypes.data, None))
        return st

    def hessian_structure(self):
        """(indptr (3 nv + 1,), indices (nnz,)): the CSR sparsity of the Hessian, in the order of the
        values of evaluate()"""
        h = _live(self)
        if self._csr is None:
            indptr = np.empty(3 * self.nv + 1, dtype=np.int64)
            indices = np.empty(self.nnz, dtype=np.int32)
            _lib.hylcmat_mesh_hessian_csr(h, indptr.ctypes.data, indices.ctypes.data)
            self._csr = (indptr, indices)
        return self._csr

    def hessian_triplets(self):
        """(rows, cols) (nnz each): the COO sparsity of the Hessian, in the order of evaluate()'s values"""
        h = _live(self)
        rows = np.empty(self.nnz, dtype=np.int32)
        cols = np.empty(self.nnz, dtype=np.int32)
        _lib.hylcmat_mesh_hessian_coo(h, rows.ctypes.data, cols.ctypes.data)
        return rows, cols

    def _positions(self, x):
        x = np.ascontiguousarray(x, dtype=np.float64)
        if x.shape != (self.nv, 3):
            raise ValueError("positions must have shape (%d, 3), got %s" % (self.nv, x.shape))
        return x

    def strains(self, x):
        """the strains (nt, 6) (sx, sa, sy, II00, II01, II11) of every triangle at positions x (nv, 3)"""
        h = _live(self)
        x = self._positions(x)
        z = np.empty((self.nt, 6))
        err = ctypes.create_string_buffer(1024)
        _check(_lib.hylcmat_mesh_strains(h, x.ctypes.data, z.ctypes.data, err, len(err)), err)
        return z

    def evaluate(self, material, x, gradient=True, hessian=True, project=False, sparse=None):
        """The total energy E (J) at positions x (nv, 3) (m), its gradient dE/dx (nv, 3) and Hessian
        (3 nv x 3 nv, vertex-major: row 3 i + c is coordinate c of vertex i). project=True projects each
        element Hessian to positive semidefinite first. The Hessian is a scipy.sparse.csr_matrix when
        scipy is importable (sparse=None) or sparse=True, else the triplets (rows, cols, values).
        Returns E, (E, grad) or (E, grad, H) as asked. material must be a hylc.Material (TypeError
        otherwise)."""
        if not isinstance(material, Material):
            raise TypeError("Mesh.evaluate: material must be a hylc.Material, got %s" % type(material).__name__)
        meh, mah = _live(self), _live(material)
        x = self._positions(x)
        E = ctypes.c_double()
        g = np.empty((self.nv, 3)) if (gradient or hessian) else None
        h = np.empty(self.nnz) if hessian else None
        err = ctypes.create_string_buffer(1024)
        _check(_lib.hylcmat_mesh_eval(meh, mah, x.ctypes.data, PSD if project else 0, ctypes.byref(E),
                                      g.ctypes.data if g is not None else None, h.ctypes.data if h is not None else None,
                                      err, len(err)), err)
        if not hessian:
            return (E.value, g) if gradient else E.value
        if sparse is None or sparse:
            try:
                import scipy.sparse
            except ImportError:
                if sparse:
                    raise
                sparse = False
            else:
                indptr, indices = self.hessian_structure()
                H = scipy.sparse.csr_matrix((h, indices, indptr), shape=(3 * self.nv, 3 * self.nv))
                return E.value, g, H
        rows, cols = self.hessian_triplets()
        return E.value, g, (rows, cols, h)


# ---------------------------------------------------------------- HDF5 files (h5py)
def _attr(v):
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.ndarray) and v.shape == ():
        return v.item()
    return v


def _shape_error(path, msg):
    return HylcError(4, "%s: %s" % (path, msg))


def _check_material_shapes(path, d):
    """the lengths of the arrays of a material read by read_material_h5 (the shape checks of the one table
    reader, src/sys/table.c, on the Python side): a scalar density and constant, 5 strain scales (and
    shifts), a 1D term's t, p, m of one length n >= 2, a 2D term's p, mu, mv, muv of len(tu) x len(tv)
    with len(tu), len(tv) >= 2; a HylcError naming the dataset otherwise"""
    for name in ("density", "constant"):
        if np.size(d[name]) != 1:
            raise _shape_error(path, "/%s has %d values, expected one" % (name, np.size(d[name])))
    for name in ("strain_scale", "strain_shift"):
        if name in d and len(d[name]) != 5:
            raise _shape_error(path, "/%s has %d values, expected 5 (sx, sa, sy, II00, II11)" % (name, len(d[name])))
    for term, g in d["1D"].items():
        n = len(g["t"])
        if n < 2:
            raise _shape_error(path, "/1D/%s/t has %d knots, expected at least 2" % (term, n))
        for k in ("p", "m"):
            if len(g[k]) != n:
                raise _shape_error(path, "/1D/%s/%s has %d values, expected %d (the length of /1D/%s/t)" % (term, k, len(g[k]), n, term))
    for term, g in d["2D"].items():
        nu, nv = len(g["tu"]), len(g["tv"])
        for k, n in (("tu", nu), ("tv", nv)):
            if n < 2:
                raise _shape_error(path, "/2D/%s/%s has %d knots, expected at least 2" % (term, k, n))
        for k in ("p", "mu", "mv", "muv"):
            if len(g[k]) != nu * nv:
                raise _shape_error(path, "/2D/%s/%s has %d values, expected %d x %d = %d (the lengths of /2D/%s/tu and /2D/%s/tv)" % (term, k, len(g[k]), nu, nv, nu * nv, term, term))


def _numbers(path, node, name):
    """the dataset name of the group node as a flat float array; a HylcError naming it when it is
    missing, a group, or not numbers"""
    import h5py
    full = (node.name.rstrip("/") + "/" + name) if node.name != "/" else "/" + name
    if name not in node:
        raise _shape_error(path, "no dataset %s" % full)
    obj = node[name]
    if not isinstance(obj, h5py.Dataset):
        raise _shape_error(path, "%s is a group, not a dataset" % full)
    if obj.dtype.kind not in "fiu":
        raise _shape_error(path, "dataset %s holds %s, expected numbers" % (full, obj.dtype))
    return np.asarray(obj[()], float).ravel()


def _int_attr(path, node, name):
    """the integer attribute name of node; a HylcError naming it when it is missing or not one integer"""
    v = node.attrs.get(name)
    if v is None or np.size(v) != 1 or np.asarray(v).dtype.kind not in "iu":
        raise _shape_error(path, "%s@%s: %s" % (node.name, name, "missing" if v is None else "not one integer"))
    return int(np.asarray(v).ravel()[0])


def read_material_h5(path):
    """The hylc HDF5 material file (docs/material.md) as a dict: density, constant, strain_scale,
    strain_shift, root attributes under 'attrs', and '1D' / '2D' {term name: {k or k0, k1, ext, t, p, m
    or tu, tv, p, mu, mv, muv (node arrays flattened, iv * len(tu) + iu)}}. A missing or misshapen
    dataset or attribute is a HylcError naming it."""
    import h5py
    d = {"1D": {}, "2D": {}}
    with h5py.File(path, "r") as f:
        fmt = _attr(f.attrs.get("format", b""))
        if fmt != "hylc-material":
            raise HylcError(4, "%s: an HDF5 file of format '%s', not a hylc material file ('hylc-material')" % (path, fmt))
        d["attrs"] = {k: _attr(v) for k, v in f.attrs.items()}
        for name in ("density", "constant"):
            v = _numbers(path, f, name)
            if v.size != 1:
                raise _shape_error(path, "/%s has %d values, expected one" % (name, v.size))
            d[name] = float(v[0])
        d["strain_scale"] = _numbers(path, f, "strain_scale")
        if "strain_shift" in f:
            d["strain_shift"] = _numbers(path, f, "strain_shift").astype(int)
        for dim, keys in (("1D", ("t", "p", "m")), ("2D", ("tu", "tv", "p", "mu", "mv", "muv"))):
            if dim not in f:
                continue
            if not isinstance(f[dim], h5py.Group):
                raise _shape_error(path, "/%s is a dataset, not a group" % dim)
            for name, g in f[dim].items():
                if not isinstance(g, h5py.Group):
                    raise _shape_error(path, "/%s/%s is a dataset, not a group" % (dim, name))
                idx = {"k": _int_attr(path, g, "k")} if dim == "1D" else {"k0": _int_attr(path, g, "k0"), "k1": _int_attr(path, g, "k1")}
                d[dim][name] = {**idx, "ext": _int_attr(path, g, "ext"), **{k: _numbers(path, g, k) for k in keys}}
    return d


def read_samples(path, usable=True):
    """The samples file of hylc-sample (docs/output-format.md) as a dict of numpy arrays: every dataset
    of the group /samples (strain (N, 6), psi, term, status, ...) and the root attributes under 'attrs'.
    usable=True keeps the rows with status 0 only."""
    import h5py
    out = {}
    with h5py.File(path, "r") as f:
        out["attrs"] = {k: _attr(v) for k, v in f.attrs.items()}
        g = f["samples"]
        for k, v in g.items():
            if isinstance(v, h5py.Dataset):
                out[k] = v[()]
    if usable and "status" in out:
        ok = out["status"] == 0
        n = len(ok)
        for k, v in list(out.items()):
            if isinstance(v, np.ndarray) and v.ndim >= 1 and len(v) == n:
                out[k] = v[ok]
    return out


# ---------------------------------------------------------------- measured cloth (libhylcmat)
class _MeasuredHinge(ctypes.Structure):
    _fields_ = [("theta", ctypes.c_double), ("kappa", ctypes.c_double), ("length", ctypes.c_double), ("area", ctypes.c_double),
                ("k", ctypes.c_double), ("shape", ctypes.c_double)]


class _MeasuredState(ctypes.Structure):
    _fields_ = [("s", ctypes.c_double), ("T", ctypes.c_double), ("lateral", ctypes.c_double), ("shear", ctypes.c_double),
                ("G", ctypes.c_double * 3), ("k", ctypes.c_double * 4), ("residual", ctypes.c_double), ("evaluations", ctypes.c_int)]


class _TensionState(ctypes.Structure):
    _fields_ = [("s", ctypes.c_double), ("T", ctypes.c_double), ("lateral", ctypes.c_double), ("shear", ctypes.c_double),
                ("strain", ctypes.c_double * 3), ("psi", ctypes.c_double), ("grad", ctypes.c_double * 2), ("iterations", ctypes.c_int)]


class _ShellRest(ctypes.Structure):
    _fields_ = [("dinv", ctypes.c_double * 4), ("area", ctypes.c_double)]


_cs = ctypes.c_char_p
_sz = ctypes.c_size_t
for _f, _args, _res in (
        ("hylcmat_measured_load", [_cs, ctypes.POINTER(_vp), _cs, _sz], ctypes.c_int),
        ("hylcmat_measured_create", [ctypes.c_double, _vp, _vp, ctypes.POINTER(_vp), _cs, _sz], ctypes.c_int),
        ("hylcmat_measured_free", [_vp], None),
        ("hylcmat_measured_data", [_vp, _vp, _vp], None),
        ("hylcmat_measured_density", [_vp], ctypes.c_double),
        ("hylcmat_measured_scale", [_vp, ctypes.c_double, ctypes.c_double, ctypes.c_double, _cs, _sz], ctypes.c_int),
        ("hylcmat_measured_write", [_vp, _cs, _cs, _sz], ctypes.c_int),
        ("hylcmat_measured_sample", [_vp, _vp, _vp], None),
        ("hylcmat_measured_stiffness", [_vp, _vp, _vp, _vp], None),
        ("hylcmat_measured_membrane", [_vp, _vp, _vp, _vp, _vp, _vp], None),
        ("hylcmat_measured_face", [_vp, _vp, _vp, _vp, _vp, _vp, _vp], ctypes.c_int),
        ("hylcmat_measured_bending_sample", [_vp, ctypes.c_double, _vp, _vp], ctypes.c_double),
        ("hylcmat_measured_edge", [_vp, _vp, _vp, ctypes.c_double, _vp, _vp, _vp], ctypes.c_int),
        ("hylcmat_measured_tension", [_vp, ctypes.c_int, ctypes.c_double, ctypes.c_int, _vp, _cs, _sz], ctypes.c_int),
        ("hylcmat_measured_tension_angle", [_vp, ctypes.c_double, ctypes.c_double, ctypes.c_int, _vp, _cs, _sz], ctypes.c_int),
        ("hylcmat_measured_bending", [_vp, ctypes.c_int, ctypes.c_double, ctypes.c_int, _vp, _vp], ctypes.c_int),
        ("hylcmat_measured_fit", [_vp, ctypes.POINTER(_vp), _vp, _cs, _sz], ctypes.c_int),
        ("hylcmat_tension", [_vp, ctypes.c_double, ctypes.c_double, _vp, _vp, _cs, _sz], ctypes.c_int),
        ("hylcmat_uniaxial", [_vp, ctypes.c_int, ctypes.c_double, _vp, _vp, _cs, _sz], ctypes.c_int),
        ("hylcmat_shell_rest_uv", [_vp, _vp], ctypes.c_int)):
    getattr(_lib, _f).argtypes = _args
    getattr(_lib, _f).restype = _res

FROZEN, ENERGY = 0, 1  # HYLCMAT_MEASURED_FROZEN, HYLCMAT_MEASURED_ENERGY
_DIRS = {"x": 0, "y": 1, "bias": 2, 0: 0, 1: 1, 2: 2}


def _mode(energy):
    return ENERGY if energy else FROZEN


def _vec(a, n, what):
    v = np.ascontiguousarray(np.asarray(a, dtype=np.float64).ravel())
    if v.shape != (n,):
        raise ValueError("%s must have %d values, got shape %s" % (what, n, np.shape(a)))
    return v


class MeasuredMaterial:
    """A measured-cloth material: the data-driven elastic model of Wang, O'Brien and Ramamoorthi
    (SIGGRAPH 2011) in the JSON of ARCSim (density kg/m^2, stretching 6 x 4, bending 3 x 5), evaluated as
    ARCSim evaluates it (docs/measured-cloth.md). Green strains G = (G00, G11, G01) in material axes.

        mc = hylc.MeasuredMaterial("11oz-black-denim.json")
        mc = hylc.MeasuredMaterial(density=0.3, stretching=S, bending=B)   # from data
        mc = hylc.MeasuredMaterial.fit(hylc.Material("stock1.json"))       # a table exported
        k = mc.stiffness(G)                      # (..., 3) -> (..., 4), the simulator's lookup
        psi, frozen, energy = mc.membrane(G)     # J/m^2, dpsi/dG at fixed k, dpsi/dG itself
        E, force, grad = mc.face(uv, x)          # one triangle: -dE/dx at fixed k, +dE/dx
        st = mc.tension("bias", 0.05)            # the homogeneous strip state (a dict)
        M = mc.bending_moment("x", 20.0)         # N m / m on the right-triangle mesh
    """

    def __init__(self, path=None, density=None, stretching=None, bending=None):
        self._h = _vp()
        err = ctypes.create_string_buffer(1024)
        if path is not None:
            if density is not None or stretching is not None or bending is not None:
                raise ValueError("give either a file or density, stretching and bending")
            self.path = os.fspath(path)
            _check(_lib.hylcmat_measured_load(self.path.encode(), ctypes.byref(self._h), err, len(err)), err)
        else:
            if density is None or stretching is None or bending is None:
                raise ValueError("give a file, or density, stretching (6, 4) and bending (3, 5)")
            self.path = None
            st = _vec(stretching, 24, "stretching")
            be = _vec(bending, 15, "bending")
            _check(_lib.hylcmat_measured_create(float(density), st.ctypes.data, be.ctypes.data, ctypes.byref(self._h), err, len(err)), err)

    @classmethod
    def fit(cls, material):
        """The least-squares measured-cloth data of a table (a hylc.Material): returns (MeasuredMaterial,
        report dict: rms_tension, worst_tension (2-10 %), rms_moment (relative), prestress (N/m), rest_moment (N))"""
        obj = cls.__new__(cls)
        obj._h = _vp()
        obj.path = None
        err = ctypes.create_string_buffer(1024)
        rep = np.zeros(5)
        _check(_lib.hylcmat_measured_fit(material._h, ctypes.byref(obj._h), rep.ctypes.data, err, len(err)), err)
        return obj, dict(rms_tension=rep[0], worst_tension=rep[1], rms_moment=rep[2], prestress=rep[3], rest_moment=rep[4])

    def __del__(self):
        h = getattr(self, "_h", None)
        if h:
            _lib.hylcmat_measured_free(h)
            self._h = _vp()

    def __repr__(self):
        return "<hylc.MeasuredMaterial %r: density %.6g kg/m^2>" % (self.path, self.density)

    @property
    def density(self):
        """area density (kg/m^2)"""
        return _lib.hylcmat_measured_density(self._h)

    @property
    def stretching(self):
        """the stretching data (6, 4)"""
        st = np.empty(24)
        _lib.hylcmat_measured_data(self._h, st.ctypes.data, None)
        return st.reshape(6, 4)

    @property
    def bending(self):
        """the bending data (3, 5): rows edges along u, at 45 degrees, along v; columns kappa 0..40 1/m"""
        be = np.empty(15)
        _lib.hylcmat_measured_data(self._h, None, be.ctypes.data)
        return be.reshape(3, 5)

    def scale(self, density=1.0, stretching=1.0, bending=1.0):
        """multiplies the data (a scene's density_mult, stretching_mult, bending_mult) in place"""
        err = ctypes.create_string_buffer(1024)
        _check(_lib.hylcmat_measured_scale(self._h, float(density), float(stretching), float(bending), err, len(err)), err)

    def write(self, path):
        """writes the data-driven JSON"""
        err = ctypes.create_string_buffer(1024)
        _check(_lib.hylcmat_measured_write(self._h, os.fspath(path).encode(), err, len(err)), err)

    def _map(self, G, nout, fn):
        G = np.asarray(G, dtype=np.float64)
        if G.ndim == 0 or G.shape[-1] != 3:
            raise ValueError("Green strains must have shape (..., 3) (G00, G11, G01), got %s" % (np.shape(G),))
        lead = G.shape[:-1]
        flat = np.ascontiguousarray(G.reshape(-1, 3))
        outs = [np.empty((flat.shape[0], n)) for n in nout]
        for i in range(flat.shape[0]):
            fn(flat[i], [o[i] for o in outs])
        return [o.reshape(lead + (n,)) if n > 1 else o.reshape(lead) for o, n in zip(outs, nout)]

    def sample(self, G):
        """the stiffness sample khat(G) (..., 4) (N/m) at Green strains (..., 3)"""
        return self._map(G, [4], lambda g, o: _lib.hylcmat_measured_sample(self._h, g.ctypes.data, o[0].ctypes.data))[0]

    def stiffness(self, G, derivative=False):
        """the simulator's stiffness k(G) (..., 4): the trilinear lookup of khat on the 30^3 grid; with
        derivative=True also dk/dG (..., 4, 3)"""
        def f(g, o):
            _lib.hylcmat_measured_stiffness(self._h, g.ctypes.data, o[0].ctypes.data, o[1].ctypes.data)
        k, dk = self._map(G, [4, 12], f)
        return (k, dk.reshape(dk.shape[:-1] + (4, 3))) if derivative else k

    def membrane(self, G):
        """psi (...) J/m^2, dpsi/dG at fixed k (..., 3) and dpsi/dG of the energy itself (..., 3)"""
        def f(g, o):
            _lib.hylcmat_measured_membrane(self._h, g.ctypes.data, o[0].ctypes.data, o[1].ctypes.data, o[2].ctypes.data, None)
        return tuple(self._map(G, [1, 3, 3], f))

    def face(self, uv, x):
        """one triangle, material coordinates uv (3, 2) counter-clockwise and positions x (3, 3) (m):
        E (J), force = -dE/dx at fixed k (3, 3) (the simulator's force), grad = +dE/dx (3, 3)"""
        uv = _vec(uv, 6, "uv")
        x = _vec(x, 9, "x")
        r = _ShellRest()
        _check(_lib.hylcmat_shell_rest_uv(uv.ctypes.data, ctypes.byref(r)))
        E = ctypes.c_double()
        fo, gr = np.empty(9), np.empty(9)
        _check(_lib.hylcmat_measured_face(self._h, ctypes.byref(r), x.ctypes.data, ctypes.byref(E), fo.ctypes.data, gr.ctypes.data, None))
        return E.value, fo.reshape(3, 3), gr.reshape(3, 3)

    def bending_sample(self, kappa, du):
        """the bending stiffness sample (N m) of an edge of material direction du (2,) at curvature kappa (1/m)"""
        du = _vec(du, 2, "du")
        return _lib.hylcmat_measured_bending_sample(self._h, float(kappa), du.ctypes.data, None)

    def edge(self, uv, x, theta_rest=0.0):
        """one hinge: vertices a, b (the edge), p0 (face (a, b, p0)), p1 (face (b, a, p1)); uv (4, 2), x (4, 3).
        Returns E (J), force = -dE/dx with k and the shape factor fixed (4, 3), and a dict (theta, kappa,
        length, area, k, shape)"""
        uv = _vec(uv, 8, "uv")
        x = _vec(x, 12, "x")
        E = ctypes.c_double()
        fo = np.empty(12)
        info = _MeasuredHinge()
        _check(_lib.hylcmat_measured_edge(self._h, uv.ctypes.data, x.ctypes.data, float(theta_rest), ctypes.byref(E), fo.ctypes.data, ctypes.byref(info)))
        return E.value, fo.reshape(4, 3), {k: getattr(info, k) for k, _ in _MeasuredHinge._fields_}

    def tension(self, direction, s, energy=False):
        """the homogeneous strip state stretched by s along direction "x", "y" or "bias" (45 degrees),
        lateral strain free: the balance of the frozen-stiffness forces (energy=False, the simulator's
        state) or the stationarity of the energy itself (energy=True). A dict: s, T (N/m per unit
        reference width), lateral (strain across), poisson (-lateral / s), shear, G, k, residual"""
        if direction not in _DIRS:
            raise ValueError("direction must be 'x', 'y' or 'bias', got %r" % (direction,))
        st = _MeasuredState()
        err = ctypes.create_string_buffer(1024)
        _check(_lib.hylcmat_measured_tension(self._h, _DIRS[direction], float(s), _mode(energy), ctypes.byref(st), err, len(err)), err)
        return dict(s=st.s, T=st.T, lateral=st.lateral, poisson=(-st.lateral / st.s if st.s > 0 else float("nan")), shear=st.shear,
                    G=np.array(st.G[:]), k=np.array(st.k[:]), residual=st.residual)

    def bending_moment(self, direction, kappa, energy=False):
        """the bending moment per unit width (N m / m) at curvature kappa (1/m) along "x" (II00) or "y"
        (II11), on a regular right-triangle mesh with edges along u and v (docs/measured-cloth.md)"""
        if direction not in ("x", "y", 0, 1):
            raise ValueError("direction must be 'x' or 'y', got %r" % (direction,))
        M = ctypes.c_double()
        _check(_lib.hylcmat_measured_bending(self._h, _DIRS[direction], float(kappa), _mode(energy), ctypes.byref(M), None))
        return M.value


def table_tension(material, angle, s, guess=None):
    """The uniaxial strip state of a table (a hylc.Material) cut at angle (radians from material x) and
    stretched by s: Psi minimized over the lateral strains. A dict: s, T (N/m), lateral, poisson, shear,
    strain (sx, sa, sy), psi"""
    st = _TensionState()
    err = ctypes.create_string_buffer(1024)
    g = None
    if guess is not None:
        g = _vec(guess, 2, "guess")
    _check(_lib.hylcmat_tension(material._h, float(angle), float(s), g.ctypes.data if g is not None else None, ctypes.byref(st), err, len(err)), err)
    return dict(s=st.s, T=st.T, lateral=st.lateral, poisson=(-st.lateral / st.s if st.s > 0 else float("nan")), shear=st.shear,
                strain=np.array(st.strain[:]), psi=st.psi)

__all__ += ["MeasuredMaterial", "table_tension", "FROZEN", "ENERGY"]
