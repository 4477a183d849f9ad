#ifndef HYLCMAT_H
#define HYLCMAT_H
/* hylcmat: the homogenized cloth material model of hylc (Sperl et al. 2020, Eq. S26) as a C99 library
   with no dependency beyond libc and libm: read a material table (ARCSim-HYLC JSON; hylc HDF5 when the
   library is built with HYLCMAT_WITH_HDF5) and evaluate Psi(s), its gradient and its Hessian with
   respect to the six strains s = (sx, sa, sy, II00, II01, II11), with exact limits at equal
   eigenvalues of II; and the macroscale shell element of Algorithm C8 (energy, gradient, Hessian of a
   triangle and its edge neighbours, and of a whole mesh). docs/library.md describes the API, the
   units, the strain definitions and the element's conventions.

   Thread safety: there is no global state. A loaded table is read-only for the evaluation functions,
   so any number of threads may evaluate one table at once; the set/load functions modify a table and
   must not run concurrently with other calls on the same table.

   Errors: functions return HYLCMAT_OK (0) or one of the HYLCMAT_ERR_* codes; those that take err and
   errlen write a one-line message (naming the file, the line and the key of a bad value) into err
   (truncated to errlen - 1 characters; err may be NULL). */
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HYLCMAT_VERSION_MAJOR 1
#define HYLCMAT_VERSION_MINOR 2

enum {
  HYLCMAT_OK          = 0,
  HYLCMAT_ERR_OPEN    = 1, /* the file cannot be opened (missing, a directory, not a regular file) */
  HYLCMAT_ERR_READ    = 2, /* reading failed, or the file is not HDF5 that the library can open */
  HYLCMAT_ERR_FORMAT  = 3, /* malformed JSON, or a value the schema or the model refuses */
  HYLCMAT_ERR_CONTENT = 4, /* an HDF5 file whose contents are not a hylc material */
  HYLCMAT_ERR_MEMORY  = 5, /* out of memory */
  HYLCMAT_ERR_ARG     = 6, /* a bad argument (NULL table, term index out of range, ...) */
  HYLCMAT_ERR_NO_HDF5 = 7, /* an HDF5 file, but the library was built without HDF5 */
  HYLCMAT_ERR_HDF5    = 8, /* the HDF5 library failed */
  HYLCMAT_ERR_NAN     = 9, /* a NaN result at a finite strain (a defect: please report it) */
  /* the shell element and the mesh */
  HYLCMAT_ERR_MESH = 10,       /* a mesh the element cannot use: vertex index out of range, a vertex twice
                                  in a triangle, an edge of more than two triangles (non-manifold), two
                                  neighbours of opposite orientation */
  HYLCMAT_ERR_REST       = 11, /* an inverted (clockwise), zero-area or non-finite rest triangle */
  HYLCMAT_ERR_NONFINITE  = 12, /* a NaN or infinite deformed coordinate */
  HYLCMAT_ERR_DEGENERATE = 13, /* a deformed triangle or neighbour face of zero area, or a zero-length
                                  material axis: the strains are undefined */
  HYLCMAT_ERR_RANGE  = 14,     /* a result beyond the double range (outputs set to 0) */
  HYLCMAT_ERR_NOCONV = 15      /* an iterative method (hylcmat_uniaxial) did not converge */
};

#define HYLCMAT_N1D 5 /* 1D terms k = 0 sx, 1 sa, 2 sy, 3 x-bending (II00), 4 y-bending (II11) */
#define HYLCMAT_N2D 9 /* 2D terms (k0, k1): (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4) */

/* extrapolation modes (the JSON key "ext") */
enum { HYLCMAT_EXT_LINEAR = 0, HYLCMAT_EXT_CONSTANT = 1, HYLCMAT_EXT_ZERO = 2 };

typedef struct hylcmat hylcmat;

/* A 1D term f_k(x): n knots t, values p, slopes m (cubic Hermite). */
typedef struct {
  int           k, n, ext;
  const double *t, *p, *m;
} hylcmat_term1d;

/* A 2D term f_k0k1(u, v): knots tu (nu), tv (nv); node (iu, iv) at iv*nu + iu of p, mu = df/du,
   mv = df/dv, muv = d2f/dudv (bicubic Hermite). */
typedef struct {
  int           k0, k1, nu, nv, ext;
  const double *tu, *tv, *p, *mu, *mv, *muv;
} hylcmat_term2d;

/* ---- reading ---------------------------------------------------------------------------------- */
/* Reads a JSON or (when built with HDF5) HDF5 material, recognized by content. *m is a new table, NULL
   on an error. */
int hylcmat_load(const char *path, hylcmat **m, char *err, size_t errlen);
/* The same from the bytes of a file (len bytes; JSON need not be NUL-terminated); name is used in
   messages. */
int hylcmat_load_memory(const char *name, const void *bytes, size_t len, hylcmat **m, char *err, size_t errlen);
/* 1 if this build reads HDF5 files, else 0 */
int  hylcmat_has_hdf5(void);
void hylcmat_free(hylcmat *m);

/* ---- evaluation ------------------------------------------------------------------------------- */
/* Psi(s) in J/m^2 at s = (sx, sa, sy, II00, II01, II11); grad (6, may be NULL) = dPsi/ds; hess (36,
   may be NULL) = d2Psi/ds2, row-major and symmetric. For finite strains every result is finite: a
   value beyond the double range is returned as +-DBL_MAX (saturated). NaN or infinite strains
   propagate (results NaN/inf, return HYLCMAT_OK). Returns HYLCMAT_ERR_NAN only on a defect.
   No allocation; thread-safe. */
int hylcmat_eval(const hylcmat *m, const double s[6], double *psi, double grad[6], double hess[36]);
/* n strains at once: strains n x 6 (row-major), psi n (may be NULL), grad n x 6 (may be NULL), hess
   n x 36 (may be NULL). Returns the first error (after evaluating every strain), else HYLCMAT_OK. */
int hylcmat_eval_batch(const hylcmat *m, size_t n, const double *strains, double *psi, double *grad, double *hess);

/* ---- contents --------------------------------------------------------------------------------- */
/* An empty table: Psi = 0, density 0, strain scale 1, strain shift 1,0,1,0,0. */
int hylcmat_create(hylcmat **m);
/* removes every term and restores the defaults of hylcmat_create */
void hylcmat_reset(hylcmat *m);
/* Setters copy and validate (at least 2 strictly increasing finite knots whose spacings h have h and
   1/h finite, finite values, k or (k0, k1) a term of the model, ext 0..2; the density in [0, 1e6]
   kg/m^2); a term replaces one of the same k or (k0, k1). */
int  hylcmat_set_density(hylcmat *m, double rho, char *err, size_t errlen);
int  hylcmat_set_strain_scale(hylcmat *m, const double scale[5], char *err, size_t errlen);
int  hylcmat_set_constant(hylcmat *m, double c0, char *err, size_t errlen);
void hylcmat_set_strain_shift(hylcmat *m, const int shift[5]);
int  hylcmat_set_term1d(hylcmat *m, const hylcmat_term1d *t, char *err, size_t errlen);
int  hylcmat_set_term2d(hylcmat *m, const hylcmat_term2d *t, char *err, size_t errlen);

double hylcmat_density(const hylcmat *m);  /* area density rho_A, kg/m^2 */
double hylcmat_constant(const hylcmat *m); /* C0, J/m^2 */
void   hylcmat_strain_scale(const hylcmat *m, double scale[5]);
void   hylcmat_strain_shift(const hylcmat *m, int shift[5]);
/* 1 and *t filled (pointers owned by the table, valid until it changes) if the term is present, else 0 */
int hylcmat_term1d_get(const hylcmat *m, int k, hylcmat_term1d *t);
int hylcmat_term2d_get(const hylcmat *m, int k0, int k1, hylcmat_term2d *t);

/* ---- the shell element (Algorithm C8) -------------------------------------------------------------
   A triangle and the vertices across its edges, 6 vertices, 18 coordinates x (m, vertex i at 3i..3i+2):
   0, 1, 2 the triangle (counter-clockwise in material coordinates), 3 across edge (0,1), 4 across (1,2),
   5 across (2,0) (docs/library.md has a figure). nbmask: bit k set if vertex 3+k exists; a missing
   neighbour (boundary edge) drops that edge's bending term, its coordinates are not read and its
   gradient entries and Hessian rows and columns are 0.
   Strains (docs/method.md §10, the conventions of ARCSim-HYLC): F = [x1 - x0 | x2 - x0] Dm^-1 =
   [x_u | x_v]; sx = |x_u| - 1, sa = x_u.x_v / (|x_u| |x_v|), sy = |x_v| - 1;
   II = -2 A_def sum_k theta_k / l_k t_k t_k^T over the edges with a neighbour (A_def the deformed area,
   l_k the deformed edge length, t_k the material gradient of the barycentric coordinate of the vertex
   opposite edge k, theta_k = atan2((n x m).e, n.m) the signed dihedral angle with n the unit normal of
   (x1 - x0) x (x2 - x0), e the unit edge a -> b, m the unit normal of the neighbour face (b, a, p)).
   II > 0 bends the surface toward n. Energy E = A Psi(z) with the rest area A; gradient +dE/dx.
   Everything is computed from edge vectors (translation-exact); the Hessian is exact (the chain rule
   with the exact second derivatives of the strains, and hylcmat_eval's exact equal-eigenvalue limits),
   so it is bounded at flat states. */

/* flag of hylcmat_shell_eval / hylcmat_mesh_eval: project each element Hessian to positive
   semidefinite (its eigenvalues below HYLCMAT_PSD_FLOOR raised to it, as ARCSim-HYLC does) */
#define HYLCMAT_SHELL_PSD 1
#define HYLCMAT_PSD_FLOOR 1e-8

/* The rest data of one element: Dm^-1 (row-major) with Dm = [u1 - u0 | u2 - u0] the columns of the
   material coordinates (m) of the triangle's vertices, and the rest area A = det(Dm) / 2 > 0 (m^2). */
typedef struct {
  double dinv[4];
  double area;
} hylcmat_shell_rest;

/* Rest data from material coordinates uv = (u0, v0, u1, v1, u2, v2) (m). HYLCMAT_ERR_REST for a
   non-finite, clockwise (inverted) or zero-area triangle (sine of its angle at vertex 0 below 1e-13),
   or one the element cannot evaluate at its own rest state: an edge or twice the area (m, m^2) below
   1.49e-154 or above 1.34e154 (their squares beyond the normal doubles: a subnormal area is refused);
   HYLCMAT_ERR_ARG for NULL. */
int hylcmat_shell_rest_uv(const double uv[6], hylcmat_shell_rest *r);
/* Rest data from the 3D rest positions X (3 x 3, vertex-major, m) and the material angle (radians):
   the material u axis lies in the triangle's plane at that angle from the edge x1 - x0, turning toward
   x2 (counter-clockwise about the rest normal); v is u turned by +90 degrees. Errors as above. */
int hylcmat_shell_rest_3d(const double X[9], double angle, hylcmat_shell_rest *r);
/* The strains z = (sx, sa, sy, II00, II01, II11) of a stencil, and (J != NULL) their Jacobian
   J = dz/dx (6 x 18, row-major). Returns HYLCMAT_ERR_NONFINITE, HYLCMAT_ERR_DEGENERATE (outputs 0) or
   HYLCMAT_OK. No allocation; thread-safe. */
int hylcmat_shell_strains(const hylcmat_shell_rest *r, const double x[18], int nbmask, double z[6], double J[108]);
/* The element energy E = A Psi(z), its gradient grad = dE/dx (18, may be NULL) and Hessian hess
   (18 x 18 row-major, symmetric, may be NULL; needs grad); flags: HYLCMAT_SHELL_PSD projects hess (on
   the coordinates of the vertices present; the translations get HYLCMAT_PSD_FLOOR; a Hessian with
   entries beyond 1e100 is projected divided by a power of 2 and multiplied back, _RANGE if the
   projection then leaves the double range). On an error
   (HYLCMAT_ERR_NONFINITE, _DEGENERATE, _RANGE, _NAN, _ARG) E, grad and hess are set to 0: never NaN.
   No allocation; thread-safe. */
int hylcmat_shell_eval(const hylcmat *m, const hylcmat_shell_rest *r, const double x[18], int nbmask, int flags, double *E, double grad[18], double hess[324]);
/* n elements at once (rest data r[n], coordinates x (n x 18), neighbour masks nbmask[n]): E (n), grad
   (n x 18, may be NULL), hess (n x 324, may be NULL; needs grad), the same values as n calls of
   hylcmat_shell_eval. With HYLCMAT_SHELL_PSD it is faster on one core: the QR iterations of two
   elements run in one loop, overlapping their latency-bound chains. Returns the first error after
   evaluating every element (a failed element's outputs are 0). No allocation; thread-safe. */
int hylcmat_shell_eval_batch(const hylcmat *m, size_t n, const hylcmat_shell_rest *r, const double *x, const int *nbmask, int flags, double *E, double *grad, double *hess);

/* ---- a mesh of shell elements ------------------------------------------------------------------
   Triangles tri (nt x 3 vertex indices, 0-based, counter-clockwise in material coordinates); the
   adjacency (each triangle's stencil), the rest data and the sparsity of the Hessian are computed once.
   Edges of one triangle are boundary edges (no bending term). Read-only after creation: any number of
   threads may evaluate one mesh at once. */
typedef struct hylcmat_mesh hylcmat_mesh;

/* A mesh from rest positions X (nv x 3, m) and per-triangle material angles (nt, radians, as
   hylcmat_shell_rest_3d; NULL: all 0). Errors (with a message naming the triangle or edge):
   HYLCMAT_ERR_MESH, HYLCMAT_ERR_REST, HYLCMAT_ERR_ARG (nv < 3, nt < 1, NULL arrays),
   HYLCMAT_ERR_MEMORY. *mesh is NULL on an error. */
int hylcmat_mesh_create(int nv, int nt, const int *tri, const double *X, const double *angle, hylcmat_mesh **mesh, char *err, size_t errlen);
/* A mesh from material coordinates per triangle corner: uv (nt x 6: u0 v0 u1 v1 u2 v2, m; a seam may
   give one vertex different coordinates in different triangles). Errors as hylcmat_mesh_create. */
int  hylcmat_mesh_create_uv(int nv, int nt, const int *tri, const double *uv, hylcmat_mesh **mesh, char *err, size_t errlen);
void hylcmat_mesh_free(hylcmat_mesh *mesh);
int  hylcmat_mesh_nv(const hylcmat_mesh *mesh); /* number of vertices */
int  hylcmat_mesh_nt(const hylcmat_mesh *mesh); /* number of triangles */
/* the total rest area (m^2) */
double hylcmat_mesh_area(const hylcmat_mesh *mesh);
/* the stencil of triangle t: its 6 vertex indices (-1 for a missing neighbour) and its rest data
   (either pointer may be NULL); HYLCMAT_ERR_ARG if t is out of range */
int hylcmat_mesh_element(const hylcmat_mesh *mesh, int t, int v[6], hylcmat_shell_rest *r);
/* The sparsity of the Hessian (3 nv x 3 nv, symmetric, both triangles stored, columns sorted in each
   row): the number of entries, and its CSR arrays rowptr (3 nv + 1) and colind (nnz) or its COO rows
   and cols (nnz each), all in the order of the values of hylcmat_mesh_eval. */
int64_t hylcmat_mesh_hessian_nnz(const hylcmat_mesh *mesh);
void    hylcmat_mesh_hessian_csr(const hylcmat_mesh *mesh, int64_t *rowptr, int *colind);
void    hylcmat_mesh_hessian_coo(const hylcmat_mesh *mesh, int *rows, int *cols);
/* the strains of every triangle at positions x (nv x 3): z (nt x 6). Errors as hylcmat_shell_strains,
   with the triangle in the message. */
int hylcmat_mesh_strains(const hylcmat_mesh *mesh, const double *x, double *z, char *err, size_t errlen);
/* The total energy E = sum of the elements' A Psi at positions x (nv x 3), its gradient grad (nv x 3,
   may be NULL) and the Hessian's values hval (nnz, in the order of hylcmat_mesh_hessian_csr/coo; may
   be NULL; needs grad). flags: HYLCMAT_SHELL_PSD projects every element Hessian before assembly. On an
   error (as hylcmat_shell_eval; the message names the triangle) the outputs are 0. Serial (one
   thread); no allocation. */
int hylcmat_mesh_eval(const hylcmat_mesh *mesh, const hylcmat *m, const double *x, int flags, double *E, double *grad, double *hval, char *err, size_t errlen);

/* ---- the homogeneous uniaxial tension state --------------------------------------------------------
   A strip of the material stretched along its material x axis (dir 0: sx = s; sa and sy free) or y axis
   (dir 1: sy = s; sa and sx free), bending zero, the lateral strains free to contract: they minimize Psi
   at the fixed s, so the lateral stresses vanish, and T = dPsi/ds there is the force per unit width of
   the strip's homogeneous central zone (N/m). This is the state a strip tensile test (ISO 13934-1) has
   away from its grips, and what hylc-solve -solve_uniaxial computes from the yarn tile directly
   (docs/fabric-uniaxial.md). */
typedef struct {
  double s;          /* the prescribed stretch (0 at rest) */
  double T;          /* dPsi/ds at the state (N/m) */
  double lateral[2]; /* the free strains: (sa, sy) for dir 0, (sa, sx) for dir 1 */
  double psi;        /* Psi there (J/m^2) */
  double grad[2];    /* dPsi/d(lateral) there (N/m; 0 up to rounding) */
  double step;       /* the last Newton step (max norm, strain) */
  int    iterations; /* Newton iterations */
} hylcmat_uniaxial_state;

/* The uniaxial state at the stretch s along dir (0 x, 1 y): Newton's method in the two lateral strains
   with the table's exact Hessian (made positive definite where it is not), steps of at most 0.1 and a
   backtracking line search on Psi, to a Newton step below 1e-11, then probes around the point (a lower
   one restarts Newton: tables have stationary lines on the axes). It starts from guess (the lateral
   strains, e.g. the state of a nearby s along a loading path: the local minimum reached from it), or
   with guess NULL from the lowest point of the grid |sa|, |s2| <= 0.5 in steps of 0.02 (tables can
   have several lateral minima; our stockinette at s = 0.2 along x: sy = +0.003 and -0.119). Errors (with a message in err): HYLCMAT_ERR_ARG for a NULL
   argument, dir not 0 or 1, s outside [0, 1) or outside the table's range of the stretch's 1D term (its
   knots times its strain scale), or a bad guess; HYLCMAT_ERR_NOCONV if the minimization does not
   converge in 200 iterations (st holds the last iterate); an evaluation's error. No allocation;
   thread-safe. */
int hylcmat_uniaxial(const hylcmat *m, int dir, double s, const double guess[2], hylcmat_uniaxial_state *st, char *err, size_t errlen);

/* ---- names -------------------------------------------------------------------------------------- */
/* (k0, k1) of 2D term q (0..8), in the order of the JSON tables */
void hylcmat_pair(int q, int *k0, int *k1);
/* index of (k0, k1) among the pairs, or -1 */
int hylcmat_pair_index(int k0, int k1);
/* "sx" "sa" "sy" "II00" "II11" (k = 0..4); "sx-sa" ... "sy-II11" (q = 0..8); NULL out of range */
const char *hylcmat_term1d_name(int k);
const char *hylcmat_term2d_name(int q);
/* a short description of an error code */
const char *hylcmat_strerror(int code);
/* Python's repr() of a double (shortest round-trip digits: "1e-05", "200.0", "-0.0"), what the JSON
   writers of the paper's tables write. buf needs 32 characters; returns buf. */
const char *hylcmat_format_double(double x, char buf[32]);

#ifdef __cplusplus
}
#endif
#endif
