#ifndef HYLCMAT_H
#define HYLCMAT_H
/* hylcmat: the homogenized cloth material model of hylc (Sperl et al. 2020, Eq. S26) as a C99 library
   with no dependency beyond libc and libm: read a material table (ARCSim-HYLC JSON; hylc HDF5 when the
   library is built with HYLCMAT_WITH_HDF5) and evaluate Psi(s), its gradient and its Hessian with
   respect to the six strains s = (sx, sa, sy, II00, II01, II11), with exact limits at equal
   eigenvalues of II. docs/library.md describes the API, the units and the strain definitions.

   Thread safety: there is no global state. A loaded table is read-only for the evaluation functions,
   so any number of threads may evaluate one table at once; the set/load functions modify a table and
   must not run concurrently with other calls on the same table.

   Errors: functions return HYLCMAT_OK (0) or one of the HYLCMAT_ERR_* codes; those that take err and
   errlen write a one-line message (naming the file, the line and the key of a bad value) into err
   (truncated to errlen - 1 characters; err may be NULL). */
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define HYLCMAT_VERSION_MAJOR 1
#define HYLCMAT_VERSION_MINOR 0

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
  HYLCMAT_ERR_NAN     = 9  /* a NaN result at a finite strain (a defect: please report it) */
};

#define HYLCMAT_N1D 5 /* 1D terms k = 0 sx, 1 sa, 2 sy, 3 x-bending (II00), 4 y-bending (II11) */
#define HYLCMAT_N2D 9 /* 2D terms (k0, k1): (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4) */

/* extrapolation modes (the JSON key "ext") */
enum {
  HYLCMAT_EXT_LINEAR   = 0,
  HYLCMAT_EXT_CONSTANT = 1,
  HYLCMAT_EXT_ZERO     = 2
};

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
   1/h finite, finite values, k or (k0, k1) a term of the model, ext 0..2); a term replaces one of the
   same k or (k0, k1). */
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
