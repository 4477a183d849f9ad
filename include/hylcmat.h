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
#define HYLCMAT_VERSION_MINOR 3

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
/* 3D terms (k0, k1, k2): (0,1,2) (0,1,3) (0,1,4) (0,2,3) (0,2,4) (1,2,3) (1,2,4), the in-plane triple and each
   in-plane pair with each bending coordinate: hylc's extension of the paper's model, not in the ARCSim-HYLC JSON
   (docs/material.md, "Three-strain terms") */
#define HYLCMAT_N3D 7

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

/* A 3D term f_k0k1k2(u, v, w) (hylc's extension): knots tu (nu), tv (nv), tw (nw); node (iu, iv, iw) at
   (iw*nv + iv)*nu + iu of p and its derivatives mu, mv, mw, muv, muw, mvw, muvw (tricubic Hermite). A bending
   coordinate (k2 = 3, 4) enters through the eigen-split of II as in the 2D terms. */
typedef struct {
  int           k0, k1, k2, nu, nv, nw, ext;
  const double *tu, *tv, *tw, *p, *mu, *mv, *mw, *muv, *muw, *mvw, *muvw;
} hylcmat_term3d;

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
int  hylcmat_set_term3d(hylcmat *m, const hylcmat_term3d *t, char *err, size_t errlen);

double hylcmat_density(const hylcmat *m);  /* area density rho_A, kg/m^2 */
double hylcmat_constant(const hylcmat *m); /* C0, J/m^2 */
void   hylcmat_strain_scale(const hylcmat *m, double scale[5]);
void   hylcmat_strain_shift(const hylcmat *m, int shift[5]);
/* 1 and *t filled (pointers owned by the table, valid until it changes) if the term is present, else 0 */
int hylcmat_term1d_get(const hylcmat *m, int k, hylcmat_term1d *t);
int hylcmat_term2d_get(const hylcmat *m, int k0, int k1, hylcmat_term2d *t);
int hylcmat_term3d_get(const hylcmat *m, int k0, int k1, int k2, hylcmat_term3d *t);

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

/* ---- the homogeneous states of the standard fabric tests (docs/fabric-fidelity.md) -----------------
   A load path prescribes one quantity s and leaves p free (1 to 3 strains), which minimize Psi: their stresses
   vanish, as in the homogeneous zone of the test. The path's force is d(min Psi)/ds, the derivative of the
   minimized Psi (by the envelope theorem dPsi/dz . dz/ds at the state):
     HYLCMAT_PATH_UNIAXIAL   stretch s along the material direction at angle degrees from x (0 strip tensile
                             along x, 90 along y, 45 the bias test); p: the other two in-plane strains (at 0:
                             sa, sy; at 90: sa, sx; otherwise the shear cosine and stretch of the rotated frame);
                             force: T, N/m of reference width;
     HYLCMAT_PATH_EQUIBIAXIAL sx = sy = s; p: sa; force: dPsi/dsx + dPsi/dsy (N/m; the gradient has each);
     HYLCMAT_PATH_SHEAR      sa = s (the cosine of the angle between the deformed axes); p: sx, sy; force:
                             dPsi/dsa (N/m);
     HYLCMAT_PATH_BENDING    II00 = s (angle 0) or II11 = s (angle 90), 1/m; p: sx, sa, sy; force: the moment
                             per unit width dPsi/dII (N). */
enum { HYLCMAT_PATH_UNIAXIAL = 0, HYLCMAT_PATH_EQUIBIAXIAL = 1, HYLCMAT_PATH_SHEAR = 2, HYLCMAT_PATH_BENDING = 3 };
typedef struct {
  int    kind;  /* HYLCMAT_PATH_* */
  double angle; /* degrees: the uniaxial direction from material x (0..90); the bending axis (0 or 90) */
} hylcmat_path;
typedef struct {
  double s;          /* the prescribed value */
  double force;      /* d(min Psi)/ds at the state */
  double p[3];       /* the free strains (nfree of them) */
  double z[6];       /* the strain of the state */
  double psi;        /* Psi there (J/m^2) */
  double grad[6];    /* dPsi/dz there */
  double gfree[3];   /* dPsi/dp there (0 up to rounding) */
  double step;       /* the last Newton step */
  int    iterations; /* Newton iterations */
} hylcmat_path_result;
/* "uniaxial", "equibiaxial", "shear", "bending"; NULL for another kind */
const char *hylcmat_path_name(int kind);
/* the number of free strains of a path (2, 1, 2, 3), or -1 */
int hylcmat_path_nfree(const hylcmat_path *path);
/* the strain z of the path at s with the free strains p and, if J is not NULL, dz/d(s, p) (6 x (1 + nfree),
   row-major). HYLCMAT_ERR_ARG for an invalid path or a strain outside the domain. */
int hylcmat_path_strain(const hylcmat_path *path, double s, const double p[], double z[6], double J[]);
/* The state of a table on a path at s: Newton's method in the free strains with the table's exact Hessian
   (and the rotation's curvature for an oblique uniaxial path), made positive definite, steps of at most 0.1,
   backtracking on Psi, to a step below 1e-11, then probes (a lower one restarts), as hylcmat_uniaxial(). From
   guess (the free strains of a nearby state along a loading path), or with guess NULL from the lowest point of
   a grid of the free strains. Errors as hylcmat_uniaxial()'s; no allocation; thread-safe. */
int hylcmat_path_state(const hylcmat *m, const hylcmat_path *path, double s, const double guess[], hylcmat_path_result *st, char *err, size_t errlen);

/* ---- a strip cut at any angle: uniaxial tension of a table -------------------------------------------
   A strip whose length runs at angle phi (radians, from the material x axis toward y) stretched by s
   along its length, bending zero, free to contract across and to shear: Psi is minimized over the two
   lateral unknowns of the in-plane strain at fixed s (the right Cauchy-Green tensor's component along
   the strip, C_dd = (1 + s)^2, is held; C_ee across and C_de are free), so the lateral stresses vanish,
   and T = dPsi/ds (N/m per unit reference width). phi = 0 and pi/2 give hylcmat_uniaxial's states;
   phi = pi/4 is the bias test (docs/measured-cloth.md). */
typedef struct {
  double s;          /* the prescribed stretch along the strip (0 at rest) */
  double T;          /* dPsi/ds at the state (N/m) */
  double lateral;    /* the engineering strain across the strip, sqrt(C_ee) - 1 */
  double shear;      /* the cosine of the angle between the deformed length and width directions */
  double strain[3];  /* the state's (sx, sa, sy) */
  double psi;        /* Psi there (J/m^2) */
  double grad[2];    /* dPsi/d(lateral, shear) there (0 up to rounding) */
  int    iterations; /* Newton iterations */
} hylcmat_tension_state;

/* The state at stretch s of a strip at angle phi: Newton's method on the two lateral unknowns
   (sqrt(C_ee), C_de / sqrt(C_dd C_ee)) with a difference Hessian made positive definite, steps of at most
   0.1 and a backtracking line search on Psi, from guess (those two unknowns; NULL: the lowest point of
   the grid |sqrt(C_ee) - 1|, |shear| <= 0.5 in steps of 0.02), to a step below 1e-10, then probes around
   the point as hylcmat_uniaxial. Errors: HYLCMAT_ERR_ARG (NULL, s outside [0, 1), phi not finite),
   HYLCMAT_ERR_NOCONV (st holds the last iterate), an evaluation's error. No allocation; thread-safe. */
int hylcmat_tension(const hylcmat *m, double phi, double s, const double guess[2], hylcmat_tension_state *st, char *err, size_t errlen);

/* ---- measured cloth: the data-driven elastic model of Wang, O'Brien, Ramamoorthi (SIGGRAPH 2011) ---
   evaluated as ARCSim (Narain et al. 2012) evaluates it; docs/measured-cloth.md states every convention
   with its formula. Green strain G = (G00, G11, G01) in material axes (G01 the off-diagonal entry of
   G = (F^T F - I) / 2). A measured material is read-only after loading: thread-safe evaluation. */
typedef struct hylcmat_measured hylcmat_measured;

#define HYLCMAT_MEASURED_GRID 30 /* the stiffness lookup grid: 30 x 30 x 30 points */

/* Reads an ARCSim data-driven JSON ("density" kg/m^2, "stretching" 6 x 4, "bending" 3 x 5); errors name
   the file, the line and the key (HYLCMAT_ERR_OPEN, _READ, _FORMAT, _MEMORY). *mc is NULL on an error. */
int hylcmat_measured_load(const char *path, hylcmat_measured **mc, char *err, size_t errlen);
int hylcmat_measured_load_memory(const char *name, const void *bytes, size_t len, hylcmat_measured **mc, char *err, size_t errlen);
/* A material from its data: stretching (6 rows of 4, row-major), bending (3 rows of 5), density >= 0;
   every value finite (HYLCMAT_ERR_FORMAT otherwise). */
int  hylcmat_measured_create(double density, const double stretching[24], const double bending[15], hylcmat_measured **mc, char *err, size_t errlen);
void hylcmat_measured_free(hylcmat_measured *mc);
/* the data (either may be NULL) and the area density (kg/m^2) */
void   hylcmat_measured_data(const hylcmat_measured *mc, double stretching[24], double bending[15]);
double hylcmat_measured_density(const hylcmat_measured *mc);
/* A scene's multipliers (ARCSim's density_mult, stretching_mult, bending_mult, each times its thicken):
   the data scaled and the lookup grid rebuilt. Each multiplier finite and > 0. */
int hylcmat_measured_scale(hylcmat_measured *mc, double density_mult, double stretching_mult, double bending_mult, char *err, size_t errlen);
/* Writes the material as the data-driven JSON (the numbers in shortest round-trip form). */
int hylcmat_measured_write(const hylcmat_measured *mc, const char *path, char *err, size_t errlen);
/* The same JSON text into buf (buflen bytes, NUL-terminated, truncated if short; buf may be NULL);
   returns its full length (without the NUL), as snprintf does. */
size_t hylcmat_measured_format(const hylcmat_measured *mc, char *buf, size_t buflen);

/* The stiffness sample khat(G) (4 values, N/m): principal stretch and direction of C = 2G + I, the
   bilinear interpolation of the data with its clamps, each value clipped at 0, times 2. */
void hylcmat_measured_sample(const hylcmat_measured *mc, const double G[3], double khat[4]);
/* The stiffness k(G) as the simulator uses it: the trilinear interpolation of khat on the 30^3 grid.
   dk (4 x 3 row-major, may be NULL): dk_i/dG_j of that interpolation (0 where a coordinate is clamped;
   the G01 column at G01 = 0 is 0, the mean of its one-sided values). */
void hylcmat_measured_stiffness(const hylcmat_measured *mc, const double G[3], double k[4], double dk[12]);
/* The membrane energy density psi = (k0 G00^2 + 2 k1 G00 G11 + k2 G11^2 + k3 G01^2) / 2 with k = k(G)
   (J/m^2); frozen (may be NULL) = dpsi/dG with k held fixed = (k0 G00 + k1 G11, k1 G00 + k2 G11, k3 G01);
   energy (may be NULL) = the total derivative (k varying); k (may be NULL) the stiffness used. */
void hylcmat_measured_membrane(const hylcmat_measured *mc, const double G[3], double *psi, double frozen[3], double energy[3], double k[4]);
/* The Green strain of a triangle (rest data as for the shell element, hylcmat_shell_rest_uv; x 3 x 3
   deformed positions, m). HYLCMAT_ERR_NONFINITE for a NaN/inf coordinate. */
int hylcmat_measured_green(const hylcmat_shell_rest *r, const double x[9], double G[3]);
/* One face: E = A psi(G) (J, A the rest area), force (9, may be NULL) = -dE/dx with k held fixed (the
   simulator's force), grad (9, may be NULL) = +dE/dx of the energy itself, G (may be NULL). Errors as
   hylcmat_measured_green (outputs 0). No allocation; thread-safe. */
int hylcmat_measured_face(const hylcmat_measured *mc, const hylcmat_shell_rest *r, const double x[9], double *E, double force[9], double grad[9], double G[3]);

/* The mass of a face (kg): density times its rest area; lumped, a third at each vertex (gravity m g/3). */
double hylcmat_measured_face_mass(const hylcmat_measured *mc, const hylcmat_shell_rest *r);

/* The bending stiffness sample of an edge of material direction du (2, any length) at the curvature
   coordinate kappa (1/m): the bilinear interpolation of the 3 x 5 data (rows: edges along u, at 45
   degrees, along v; columns kappa = 0, 10, 20, 30, 40 1/m), clamped and clipped at 0 (N m). dkdkappa
   (may be NULL): its derivative with respect to kappa (0 where clamped or clipped). */
double hylcmat_measured_bending_sample(const hylcmat_measured *mc, double kappa, const double du[2], double *dkdkappa);

/* The hinge of an interior edge: vertices a = 0, b = 1 of the edge, p0 = 2 across it in face 0 = (a, b,
   p0), p1 = 3 in face 1 = (b, a, p1), both counter-clockwise in material coordinates uv (4 x 2, m). */
typedef struct {
  double theta;  /* the dihedral angle (rad), > 0 when the surface bends toward its normal n */
  double kappa;  /* the curvature coordinate theta l / (A0 + A1) (1/m) */
  double length; /* l, the edge's material length (m) */
  double area;   /* A0 + A1, the faces' material areas (m^2) */
  double k;      /* the bending stiffness sample used (N m) */
  double shape;  /* l^2 / (2 (A0 + A1)) */
} hylcmat_measured_hinge;

/* One hinge: E = k shape (theta - theta_rest)^2 / 4 (J), force (12, may be NULL) = -dE/dx with k and
   shape held fixed, info (may be NULL). HYLCMAT_ERR_NONFINITE, HYLCMAT_ERR_DEGENERATE (a zero-area face,
   deformed or rest, or a zero-length edge; outputs 0). No allocation; thread-safe. */
int hylcmat_measured_edge(const hylcmat_measured *mc, const double uv[8], const double x[12], double theta_rest, double *E, double force[12], hylcmat_measured_hinge *info);

/* ---- measured cloth: the homogeneous states of a fabric sheet (docs/measured-cloth.md) -------------- */
enum {
  HYLCMAT_MEASURED_FROZEN = 0, /* the balance of the simulator's forces (k held fixed at the state) */
  HYLCMAT_MEASURED_ENERGY = 1  /* the stationarity of the energy itself (k varying) */
};

typedef struct {
  double s;           /* the prescribed stretch along the strip (0 at rest) */
  double T;           /* the force per unit reference width (N/m) */
  double lateral;     /* the engineering strain across the strip */
  double shear;       /* the cosine of the angle between the deformed length and width directions */
  double G[3];        /* the Green strain (G00, G11, G01) in material axes */
  double k[4];        /* the stiffness at the state */
  double residual;    /* the largest lateral stress left (N/m; 0 up to rounding, unless the root is a jump) */
  int    evaluations; /* stiffness evaluations */
} hylcmat_measured_state;

/* Uniaxial tension of a strip along dir (0: material x, 1: y, 2: the 45 degree bias from x toward y) by
   the stretch s in [0, 1), free to contract (and, on the bias, to shear): the lateral stresses of mode's
   derivative vanish; on the axes G01 = 0 by symmetry. The root nearest the unstrained lateral state.
   Errors: HYLCMAT_ERR_ARG, HYLCMAT_ERR_NOCONV (no lateral root within |G| < 0.5). */
int hylcmat_measured_tension(const hylcmat_measured *mc, int dir, double s, int mode, hylcmat_measured_state *st, char *err, size_t errlen);
/* The same for a strip at angle phi (radians from material x toward y; the shear is free off the axes). */
int hylcmat_measured_tension_angle(const hylcmat_measured *mc, double phi, double s, int mode, hylcmat_measured_state *st, char *err, size_t errlen);
/* The bending moment per unit width (N m / m = N) of a sheet in cylindrical bending of curvature kappa
   (1/m, > 0 toward n) along dir (0: the material x axis curves, II00 = kappa; 1: y) on a regular mesh of
   right triangles with edges along u and v: M = k kappa / 4 (frozen) or d/dkappa (k kappa^2 / 8)
   (energy), k the sample of the edges across the bend (along v for dir 0, along u for dir 1) at kappa.
   k (may be NULL) returns that sample. HYLCMAT_ERR_ARG for a bad argument. */
int hylcmat_measured_bending(const hylcmat_measured *mc, int dir, double kappa, int mode, double *M, double *k);

/* ---- a table written as measured cloth -------------------------------------------------------------
   The measured-cloth data of a table (docs/measured-cloth.md, "Export"): the stretching data start as the
   linear least-squares fit of the model's stress to the table's at the table's strip and biaxial states,
   then are refined (Levenberg-Marquardt, the least squares of the relative error of the model's own
   strip tension and 0.03 x its lateral strain error per unit stretch, against the table's strip states
   along 0, 22.5, 45, 67.5, 90 degrees at s = 1 .. 12 %); the bending data are the least-squares fit of
   the secant stiffness 4 M / kappa of the odd part of the table's moments, kappa = 1 .. 40 1/m; the
   density is copied. fit (may be NULL; 5 values): the RMS and the largest (over s = 2 .. 10 %) relative
   strip tension error, the RMS relative moment error, the table's largest in-plane dPsi/ds at rest (N/m,
   a prestress the format cannot hold) and its largest dPsi/dII at rest (N, a natural curvature it
   cannot hold). About 10 s for a paper table. */
int hylcmat_measured_fit(const hylcmat *m, hylcmat_measured **mc, double fit[5], char *err, size_t errlen);

/* ---- names -------------------------------------------------------------------------------------- */
/* (k0, k1) of 2D term q (0..8), in the order of the JSON tables */
void hylcmat_pair(int q, int *k0, int *k1);
/* index of (k0, k1) among the pairs, or -1 */
int hylcmat_pair_index(int k0, int k1);
/* "sx" "sa" "sy" "II00" "II11" (k = 0..4); "sx-sa" ... "sy-II11" (q = 0..8); NULL out of range */
const char *hylcmat_term1d_name(int k);
const char *hylcmat_term2d_name(int q);
/* (k0, k1, k2) of 3D term r (0..6); "sx-sa-sy" "sx-sa-II00" ... "sa-sy-II11"; NULL out of range */
void        hylcmat_triple(int r, int *k0, int *k1, int *k2);
const char *hylcmat_term3d_name(int r);
/* a short description of an error code */
const char *hylcmat_strerror(int code);
/* Python's repr() of a double (shortest round-trip digits: "1e-05", "200.0", "-0.0"), what the JSON
   writers of the paper's tables write. buf needs 32 characters; returns buf. */
const char *hylcmat_format_double(double x, char buf[32]);

#ifdef __cplusplus
}
#endif
#endif
