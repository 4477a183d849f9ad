/* hylcmat: the table (create, free, validated setters, getters), names, errors, file dispatch (JSON or
   HDF5 by content) and Python's repr() of doubles. Plain C99 + POSIX stat; no global state. */
#include "hylcmatimpl.h"
#include <hylc/private/json.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int hm_fail(hm_err *e, int code, const char *fmt, ...)
{
  if (e && e->buf && e->len) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(e->buf, e->len, fmt, ap);
    va_end(ap);
  }
  return code;
}

void hylcmat_pair(int q, int *k0, int *k1)
{
  const int ok = q >= 0 && q < HYLCMAT_N2D;
  if (k0) *k0 = ok ? HylcmatPairs[q][0] : -1;
  if (k1) *k1 = ok ? HylcmatPairs[q][1] : -1;
}

int hylcmat_pair_index(int k0, int k1) { return HylcPairIndex(k0, k1); }

const char *hylcmat_term1d_name(int k) { return k >= 0 && k < HYLCMAT_N1D ? HylcmatNames1D[k] : NULL; }

const char *hylcmat_term2d_name(int q) { return q >= 0 && q < HYLCMAT_N2D ? HylcmatNames2D[q] : NULL; }

const char *hylcmat_strerror(int code)
{
  switch (code) {
  case HYLCMAT_OK:
    return "no error";
  case HYLCMAT_ERR_OPEN:
    return "cannot open the file";
  case HYLCMAT_ERR_READ:
    return "cannot read the file";
  case HYLCMAT_ERR_FORMAT:
    return "malformed material (JSON syntax, schema or value)";
  case HYLCMAT_ERR_CONTENT:
    return "not a hylc material file";
  case HYLCMAT_ERR_MEMORY:
    return "out of memory";
  case HYLCMAT_ERR_ARG:
    return "bad argument";
  case HYLCMAT_ERR_NO_HDF5:
    return "an HDF5 file, but hylcmat was built without HDF5";
  case HYLCMAT_ERR_HDF5:
    return "the HDF5 library failed";
  case HYLCMAT_ERR_NAN:
    return "NaN result at a finite strain";
  case HYLCMAT_ERR_MESH:
    return "a mesh the element cannot use (index out of range, non-manifold edge, inconsistent orientation)";
  case HYLCMAT_ERR_REST:
    return "an inverted, zero-area or non-finite rest triangle";
  case HYLCMAT_ERR_NONFINITE:
    return "a NaN or infinite deformed coordinate";
  case HYLCMAT_ERR_DEGENERATE:
    return "a degenerate deformed triangle or neighbour face (zero area): the strains are undefined";
  case HYLCMAT_ERR_RANGE:
    return "a result beyond the double range";
  case HYLCMAT_ERR_NOCONV:
    return "an iterative method did not converge";
  }
  return "unknown error";
}

int hylcmat_has_hdf5(void)
{
#ifdef HYLCMAT_WITH_HDF5
  return 1;
#else
  return 0;
#endif
}

/* ------------------------------------------------------------------------------------------------ */
/* Table                                                                                              */
/* ------------------------------------------------------------------------------------------------ */

static void Free1D(hylcmat *m, int k)
{
  if (m->has1[k]) {
    free((void *)m->t1[k].t);
    free((void *)m->t1[k].p);
    free((void *)m->t1[k].m);
  }
  memset(&m->t1[k], 0, sizeof(m->t1[k]));
  m->has1[k] = 0;
  m->sw1[k]  = 0;
}

/* m->ushare from the pairs present */
static void UShare(hylcmat *m)
{
  for (int q = 0; q < HYLCMAT_N2D; q++) {
    const hylcmat_term2d *a = &m->t2[q];
    m->ushare[q]            = -1;
    if (!m->has2[q]) continue;
    for (int r = 0; r < q; r++) {
      const hylcmat_term2d *b = &m->t2[r];
      if (m->has2[r] && HylcmatPairs[r][0] == HylcmatPairs[q][0] && b->nu == a->nu && b->ext == a->ext && m->ihu[r] == m->ihu[q] && !memcmp(b->tu, a->tu, sizeof(double) * (size_t)a->nu)) {
        m->ushare[q] = r;
        break;
      }
    }
  }
}

static void Free2D(hylcmat *m, int q)
{
  if (m->has2[q]) {
    free((void *)m->t2[q].tu);
    free((void *)m->t2[q].tv);
    free((void *)m->t2[q].p);
    free((void *)m->t2[q].mu);
    free((void *)m->t2[q].mv);
    free((void *)m->t2[q].muv);
  }
  memset(&m->t2[q], 0, sizeof(m->t2[q]));
  m->has2[q] = 0;
  m->sw2[q]  = 0;
  UShare(m);
}

/* the arrays of a 3D term, in the order of hylcmat_term3d */
#define T3ARRAYS(t)                                                                                                  \
  {                                                                                                                  \
    &(t)->tu, &(t)->tv, &(t)->tw, &(t)->p, &(t)->mu, &(t)->mv, &(t)->mw, &(t)->muv, &(t)->muw, &(t)->mvw, &(t)->muvw \
  }

static void Free3D(hylcmat *m, int r)
{
  if (m->has3[r]) {
    const double **a[11] = T3ARRAYS(&m->t3[r]);
    for (int i = 0; i < 11; i++) free((void *)*a[i]);
  }
  memset(&m->t3[r], 0, sizeof(m->t3[r]));
  m->has3[r] = 0;
  m->sw3[r]  = 0;
}

void hylcmat_reset(hylcmat *m)
{
  if (!m) return;
  for (int k = 0; k < HYLCMAT_N1D; k++) Free1D(m, k);
  for (int q = 0; q < HYLCMAT_N2D; q++) Free2D(m, q);
  for (int r = 0; r < HYLCMAT_N3D; r++) Free3D(m, r);
  m->density = 0;
  m->C0      = 0;
  for (int k = 0; k < 5; k++) {
    m->scale[k] = 1;
    m->shift[k] = (k == 0 || k == 2) ? 1 : 0;
  }
}

int hylcmat_create(hylcmat **m)
{
  if (!m) return HYLCMAT_ERR_ARG;
  *m = calloc(1, sizeof(**m));
  if (!*m) return HYLCMAT_ERR_MEMORY;
  hylcmat_reset(*m);
  return HYLCMAT_OK;
}

void hylcmat_free(hylcmat *m)
{
  if (!m) return;
  hylcmat_reset(m);
  free(m);
}

/* a number for messages (%.6g) */
static const char *G(char buf[32], double v)
{
  snprintf(buf, 32, "%.6g", v);
  return buf;
}

int hylcmat_set_density(hylcmat *m, double rho, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  char   b[32];

  HM_CHECK(m, &E, HYLCMAT_ERR_ARG, "hylcmat_set_density: NULL table");
  HM_CHECK(isfinite(rho) && rho >= 0 && rho <= HM_MAX_DENSITY, &E, HYLCMAT_ERR_FORMAT, "Material density must be finite and in [0, %g] kg/m^2, got %s", HM_MAX_DENSITY, G(b, rho));
  m->density = rho;
  return HYLCMAT_OK;
}

int hylcmat_set_strain_scale(hylcmat *m, const double scale[5], char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  char   b[32];

  HM_CHECK(m && scale, &E, HYLCMAT_ERR_ARG, "hylcmat_set_strain_scale: NULL argument");
  for (int k = 0; k < 5; k++) HM_CHECK(isfinite(scale[k]) && scale[k] > 0 && isfinite(1 / scale[k]), &E, HYLCMAT_ERR_FORMAT, "Strain scale %d (%s) must be finite and positive with a finite inverse, got %s", k, HylcmatNames1D[k], G(b, scale[k]));
  for (int k = 0; k < 5; k++) m->scale[k] = scale[k];
  return HYLCMAT_OK;
}

int hylcmat_set_constant(hylcmat *m, double c0, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  char   b[32];

  HM_CHECK(m, &E, HYLCMAT_ERR_ARG, "hylcmat_set_constant: NULL table");
  HM_CHECK(isfinite(c0), &E, HYLCMAT_ERR_FORMAT, "Material constant must be finite, got %s", G(b, c0));
  m->C0 = c0;
  return HYLCMAT_OK;
}

void hylcmat_set_strain_shift(hylcmat *m, const int shift[5])
{
  if (m && shift)
    for (int k = 0; k < 5; k++) m->shift[k] = shift[k];
}

double hylcmat_density(const hylcmat *m) { return m ? m->density : 0; }

double hylcmat_constant(const hylcmat *m) { return m ? m->C0 : 0; }

void hylcmat_strain_scale(const hylcmat *m, double scale[5])
{
  for (int k = 0; k < 5; k++) scale[k] = m ? m->scale[k] : 1;
}

void hylcmat_strain_shift(const hylcmat *m, int shift[5])
{
  for (int k = 0; k < 5; k++) shift[k] = m ? m->shift[k] : 0;
}

int hylcmat_term1d_get(const hylcmat *m, int k, hylcmat_term1d *t)
{
  if (!m || k < 0 || k >= HYLCMAT_N1D || !m->has1[k]) return 0;
  if (t) *t = m->t1[k];
  return 1;
}

int hylcmat_term2d_get(const hylcmat *m, int k0, int k1, hylcmat_term2d *t)
{
  const int q = hylcmat_pair_index(k0, k1);
  if (!m || q < 0 || !m->has2[q]) return 0;
  if (t) *t = m->t2[q];
  return 1;
}

/* knots: at least 2, finite, strictly increasing, spacings h with h and 1/h finite. what names the term */
static int CheckKnots(hm_err *E, const char what[], const char name[], int n, const double t[])
{
  char b0[32], b1[32];

  HM_CHECK(n >= 2, E, HYLCMAT_ERR_FORMAT, "%s: %s needs at least 2 knots, got %d", what, name, n);
  HM_CHECK(t, E, HYLCMAT_ERR_ARG, "%s: %s is NULL", what, name);
  for (int i = 0; i < n; i++) {
    HM_CHECK(isfinite(t[i]), E, HYLCMAT_ERR_FORMAT, "%s: knot %s[%d] = %s is not finite", what, name, i, G(b0, t[i]));
    HM_CHECK(i == 0 || t[i] > t[i - 1], E, HYLCMAT_ERR_FORMAT, "%s: knots %s must be strictly increasing, but %s[%d] = %s <= %s[%d] = %s", what, name, name, i, G(b0, t[i]), name, i - 1, G(b1, t[i - 1]));
    if (i > 0) { /* the evaluator divides by the spacing (docs/material.md, "Range") */
      const double h = t[i] - t[i - 1];
      HM_CHECK(isfinite(h) && isfinite(1 / h), E, HYLCMAT_ERR_FORMAT, "%s: the spacing %s[%d] - %s[%d] = %s - %s %s (knot spacings h must have h and 1/h finite)", what, name, i, name, i - 1, G(b0, t[i]), G(b1, t[i - 1]),
               isfinite(h) ? "is too small" : "overflows");
    }
  }
  return HYLCMAT_OK;
}

static int CheckFinite(hm_err *E, const char what[], const char name[], int n, const double v[])
{
  char b[32];

  HM_CHECK(v, E, HYLCMAT_ERR_ARG, "%s: %s is NULL", what, name);
  for (int i = 0; i < n; i++) HM_CHECK(isfinite(v[i]), E, HYLCMAT_ERR_FORMAT, "%s: %s[%d] = %s is not finite", what, name, i, G(b, v[i]));
  return HYLCMAT_OK;
}

static double HalfMinSpacing(int n, const double t[])
{
  double h = 1.7976931348623157e308;
  for (int i = 1; i < n; i++)
    if (t[i] - t[i - 1] < h) h = t[i] - t[i - 1];
  return 0.45 * h;
}

static double *Copy(const double *v, size_t n)
{
  double *c = malloc(n * sizeof(double) + 1);
  if (c) memcpy(c, v, n * sizeof(double));
  return c;
}

int hylcmat_set_term1d(hylcmat *m, const hylcmat_term1d *s, char *err, size_t errlen)
{
  hm_err  E = {err, errlen};
  char    what[64];
  int     k;
  double *t, *p, *mm;

  HM_CHECK(m && s, &E, HYLCMAT_ERR_ARG, "hylcmat_set_term1d: NULL argument");
  k = s->k;
  HM_CHECK(k >= 0 && k < HYLCMAT_N1D, &E, HYLCMAT_ERR_FORMAT, "1D term: k = %d is out of range (0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending)", k);
  snprintf(what, sizeof(what), "1D term %s (k = %d)", HylcmatNames1D[k], k);
  HM_CHECK(s->ext >= HYLCMAT_EXT_LINEAR && s->ext <= HYLCMAT_EXT_ZERO, &E, HYLCMAT_ERR_FORMAT, "%s: extrapolation mode %d is not 0 (linear), 1 (constant) or 2 (zero)", what, s->ext);
  HM_CALL(CheckKnots(&E, what, "t", s->n, s->t));
  HM_CALL(CheckFinite(&E, what, "p", s->n, s->p));
  HM_CALL(CheckFinite(&E, what, "m", s->n, s->m));
  t  = Copy(s->t, (size_t)s->n);
  p  = Copy(s->p, (size_t)s->n);
  mm = Copy(s->m, (size_t)s->n);
  if (!t || !p || !mm) {
    free(t);
    free(p);
    free(mm);
    return hm_fail(&E, HYLCMAT_ERR_MEMORY, "%s: out of memory", what);
  }
  Free1D(m, k);
  m->t1[k].k   = k;
  m->t1[k].n   = s->n;
  m->t1[k].ext = s->ext;
  m->t1[k].t   = t;
  m->t1[k].p   = p;
  m->t1[k].m   = mm;
  m->has1[k]   = 1;
  m->sw1[k]    = HalfMinSpacing(s->n, s->t);
  m->ih1[k]    = (s->n - 1) / (s->t[s->n - 1] - s->t[0]);
  return HYLCMAT_OK;
}

int hylcmat_set_term2d(hylcmat *m, const hylcmat_term2d *s, char *err, size_t errlen)
{
  hm_err  E = {err, errlen};
  char    what[64];
  int     q;
  size_t  N;
  double *a[6];

  HM_CHECK(m && s, &E, HYLCMAT_ERR_ARG, "hylcmat_set_term2d: NULL argument");
  q = hylcmat_pair_index(s->k0, s->k1);
  HM_CHECK(q >= 0, &E, HYLCMAT_ERR_FORMAT, "2D term: (k0, k1) = (%d, %d) is not a term of the model; the pairs are (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4)", s->k0, s->k1);
  snprintf(what, sizeof(what), "2D term %s (k0 = %d, k1 = %d)", HylcmatNames2D[q], s->k0, s->k1);
  HM_CHECK(s->ext >= HYLCMAT_EXT_LINEAR && s->ext <= HYLCMAT_EXT_ZERO, &E, HYLCMAT_ERR_FORMAT, "%s: extrapolation mode %d is not 0 (linear), 1 (constant) or 2 (zero)", what, s->ext);
  HM_CALL(CheckKnots(&E, what, "tu", s->nu, s->tu));
  HM_CALL(CheckKnots(&E, what, "tv", s->nv, s->tv));
  N = (size_t)s->nu * (size_t)s->nv;
  HM_CALL(CheckFinite(&E, what, "p", (int)N, s->p));
  HM_CALL(CheckFinite(&E, what, "mu", (int)N, s->mu));
  HM_CALL(CheckFinite(&E, what, "mv", (int)N, s->mv));
  HM_CALL(CheckFinite(&E, what, "muv", (int)N, s->muv));
  a[0] = Copy(s->tu, (size_t)s->nu);
  a[1] = Copy(s->tv, (size_t)s->nv);
  a[2] = Copy(s->p, N);
  a[3] = Copy(s->mu, N);
  a[4] = Copy(s->mv, N);
  a[5] = Copy(s->muv, N);
  for (int i = 0; i < 6; i++)
    if (!a[i]) {
      for (int j = 0; j < 6; j++) free(a[j]);
      return hm_fail(&E, HYLCMAT_ERR_MEMORY, "%s: out of memory", what);
    }
  Free2D(m, q);
  m->t2[q].k0  = s->k0;
  m->t2[q].k1  = s->k1;
  m->t2[q].nu  = s->nu;
  m->t2[q].nv  = s->nv;
  m->t2[q].ext = s->ext;
  m->t2[q].tu  = a[0];
  m->t2[q].tv  = a[1];
  m->t2[q].p   = a[2];
  m->t2[q].mu  = a[3];
  m->t2[q].mv  = a[4];
  m->t2[q].muv = a[5];
  m->has2[q]   = 1;
  m->sw2[q]    = HalfMinSpacing(s->nv, s->tv);
  m->ihu[q]    = (s->nu - 1) / (s->tu[s->nu - 1] - s->tu[0]);
  m->ihv[q]    = (s->nv - 1) / (s->tv[s->nv - 1] - s->tv[0]);
  UShare(m);
  return HYLCMAT_OK;
}

int hylcmat_term3d_get(const hylcmat *m, int k0, int k1, int k2, hylcmat_term3d *t)
{
  const int r = HylcTripleIndex(k0, k1, k2);
  if (!m || !t || r < 0 || !m->has3[r]) return 0;
  *t = m->t3[r];
  return 1;
}

void hylcmat_triple(int r, int *k0, int *k1, int *k2)
{
  const int ok = r >= 0 && r < HYLCMAT_N3D;
  if (k0) *k0 = ok ? HylcTripleCoords[r][0] : -1;
  if (k1) *k1 = ok ? HylcTripleCoords[r][1] : -1;
  if (k2) *k2 = ok ? HylcTripleCoords[r][2] : -1;
}

const char *hylcmat_term3d_name(int r) { return r >= 0 && r < HYLCMAT_N3D ? HylcTripleNames[r] : NULL; }

int hylcmat_set_term3d(hylcmat *m, const hylcmat_term3d *s, char *err, size_t errlen)
{
  hm_err                   E = {err, errlen};
  char                     what[64];
  int                      r;
  size_t                   N;
  double                  *a[11];
  const double            *src[11];
  static const char *const names[11] = {"tu", "tv", "tw", "p", "mu", "mv", "mw", "muv", "muw", "mvw", "muvw"};

  HM_CHECK(m && s, &E, HYLCMAT_ERR_ARG, "hylcmat_set_term3d: NULL argument");
  r = HylcTripleIndex(s->k0, s->k1, s->k2);
  HM_CHECK(r >= 0, &E, HYLCMAT_ERR_FORMAT, "3D term: (k0, k1, k2) = (%d, %d, %d) is not a term of the model; the triples are (0,1,2) (0,1,3) (0,1,4) (0,2,3) (0,2,4) (1,2,3) (1,2,4)", s->k0, s->k1, s->k2);
  snprintf(what, sizeof(what), "3D term %s (k0 = %d, k1 = %d, k2 = %d)", HylcTripleNames[r], s->k0, s->k1, s->k2);
  HM_CHECK(s->ext >= HYLCMAT_EXT_LINEAR && s->ext <= HYLCMAT_EXT_ZERO, &E, HYLCMAT_ERR_FORMAT, "%s: extrapolation mode %d is not 0 (linear), 1 (constant) or 2 (zero)", what, s->ext);
  HM_CALL(CheckKnots(&E, what, "tu", s->nu, s->tu));
  HM_CALL(CheckKnots(&E, what, "tv", s->nv, s->tv));
  HM_CALL(CheckKnots(&E, what, "tw", s->nw, s->tw));
  HM_CHECK((double)s->nu * s->nv * s->nw < 1e8, &E, HYLCMAT_ERR_FORMAT, "%s: %d x %d x %d nodes: too many", what, s->nu, s->nv, s->nw);
  N      = (size_t)s->nu * (size_t)s->nv * (size_t)s->nw;
  src[0] = s->tu, src[1] = s->tv, src[2] = s->tw, src[3] = s->p, src[4] = s->mu, src[5] = s->mv, src[6] = s->mw;
  src[7] = s->muv, src[8] = s->muw, src[9] = s->mvw, src[10] = s->muvw;
  for (int i = 3; i < 11; i++) HM_CALL(CheckFinite(&E, what, names[i], (int)N, src[i]));
  for (int i = 0; i < 11; i++) a[i] = Copy(src[i], i == 0 ? (size_t)s->nu : i == 1 ? (size_t)s->nv : i == 2 ? (size_t)s->nw : N);
  for (int i = 0; i < 11; i++)
    if (!a[i]) {
      for (int j = 0; j < 11; j++) free(a[j]);
      return hm_fail(&E, HYLCMAT_ERR_MEMORY, "%s: out of memory", what);
    }
  Free3D(m, r);
  {
    hylcmat_term3d *t = &m->t3[r];
    t->k0 = s->k0, t->k1 = s->k1, t->k2 = s->k2, t->nu = s->nu, t->nv = s->nv, t->nw = s->nw, t->ext = s->ext;
    t->tu = a[0], t->tv = a[1], t->tw = a[2], t->p = a[3], t->mu = a[4], t->mv = a[5], t->mw = a[6];
    t->muv = a[7], t->muw = a[8], t->mvw = a[9], t->muvw = a[10];
  }
  m->has3[r] = 1;
  m->sw3[r]  = HalfMinSpacing(s->nw, s->tw);
  m->ihu3[r] = (s->nu - 1) / (s->tu[s->nu - 1] - s->tu[0]);
  m->ihv3[r] = (s->nv - 1) / (s->tv[s->nv - 1] - s->tv[0]);
  m->ihw3[r] = (s->nw - 1) / (s->tw[s->nw - 1] - s->tw[0]);
  return HYLCMAT_OK;
}

/* ------------------------------------------------------------------------------------------------ */
/* Documents and files                                                                                */
/* ------------------------------------------------------------------------------------------------ */

void hm_doc_init(hm_doc *d, const char *name, hm_err *E)
{
  memset(d, 0, sizeof(*d));
  d->name = name;
  d->E    = E;
  for (int k = 0; k < 5; k++) {
    d->scale[k] = 1;
    d->shift[k] = (k == 0 || k == 2) ? 1 : 0;
  }
}

void hm_doc_free(hm_doc *d)
{
  for (int i = 0; i < d->n1; i++) {
    free((void *)d->s1[i].t);
    free((void *)d->s1[i].p);
    free((void *)d->s1[i].m);
  }
  for (int i = 0; i < d->n2; i++) {
    free((void *)d->s2[i].tu);
    free((void *)d->s2[i].tv);
    free((void *)d->s2[i].p);
    free((void *)d->s2[i].mu);
    free((void *)d->s2[i].mv);
    free((void *)d->s2[i].muv);
  }
  for (int i = 0; i < d->n3; i++) {
    const double **a[11] = T3ARRAYS(&d->s3[i]);
    for (int j = 0; j < 11; j++) free((void *)*a[j]);
  }
  d->n1 = d->n2 = d->n3 = 0;
}

int hm_doc_install(hm_doc *d, hylcmat **out)
{
  hm_err     *E    = d->E;
  char       *eb   = E ? E->buf : NULL;
  size_t      el   = E ? E->len : 0;
  hylcmat    *m    = NULL;
  int         r    = hylcmat_create(&m);
  const char *name = d->name;

  if (!r) r = hylcmat_set_density(m, d->density, eb, el);
  if (!r) r = hylcmat_set_strain_scale(m, d->scale, eb, el);
  if (!r) hylcmat_set_strain_shift(m, d->shift);
  if (!r) r = hylcmat_set_constant(m, d->C0, eb, el);
  for (int i = 0; i < d->n1 && !r; i++) r = hylcmat_set_term1d(m, &d->s1[i], eb, el);
  for (int i = 0; i < d->n2 && !r; i++) r = hylcmat_set_term2d(m, &d->s2[i], eb, el);
  for (int i = 0; i < d->n3 && !r; i++) r = hylcmat_set_term3d(m, &d->s3[i], eb, el);
  hm_doc_free(d);
  if (r == HYLCMAT_ERR_MEMORY && m == NULL) hm_fail(E, r, "out of memory");
  if (r && eb && el) { /* the setters' messages name the term and value: add the file */
    char msg[1024];
    snprintf(msg, sizeof(msg), "%s", eb);
    snprintf(eb, el, "%s: %s", name, msg);
  }
  if (r) {
    hylcmat_free(m);
    m = NULL;
  }
  *out = m;
  return r;
}

static const unsigned char HDF5Signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};

int hylcmat_load_memory(const char *name, const void *bytes, size_t len, hylcmat **m, char *err, size_t errlen)
{
  hm_err      E = {err, errlen};
  const char *text;
  size_t      nul;

  if (err && errlen) err[0] = 0;
  HM_CHECK(m, &E, HYLCMAT_ERR_ARG, "hylcmat_load_memory: NULL result pointer");
  *m = NULL;
  if (!name) name = "(memory)";
  HM_CHECK(bytes || !len, &E, HYLCMAT_ERR_ARG, "%s: NULL bytes", name);
  if (len >= 8 && !memcmp(bytes, HDF5Signature, 8)) {
#ifdef HYLCMAT_WITH_HDF5
    return hm_parse_hdf5(name, bytes, len, &E, m);
#else
    return hm_fail(&E, HYLCMAT_ERR_NO_HDF5, "%s: an HDF5 material file, but this hylcmat was built without HDF5 (HYLCMAT_WITH_HDF5); convert it with hylc-eval -eval_json", name);
#endif
  }
  text = bytes;
  for (nul = 0; nul < len && text[nul]; nul++) {}
  HM_CHECK(nul == len, &E, HYLCMAT_ERR_FORMAT, "%s: contains a NUL byte at offset %zu: neither a JSON nor an HDF5 material file", name, nul);
  return hm_parse_json(name, text, len, &E, m);
}

int hm_read_file(const char *path, const char *what, char **bytes, size_t *len, hm_err *E)
{
  struct stat st;
  FILE       *fp;
  long        n;

  *bytes = NULL;
  *len   = 0;
  HM_CHECK(path && path[0], E, HYLCMAT_ERR_ARG, "Cannot read a %s: no file name", what);
  if (stat(path, &st)) return hm_fail(E, HYLCMAT_ERR_OPEN, "Cannot open %s '%s': %s", what, path, strerror(errno));
  HM_CHECK(!S_ISDIR(st.st_mode), E, HYLCMAT_ERR_OPEN, "Cannot read %s '%s': it is a directory", what, path);
  HM_CHECK(S_ISREG(st.st_mode), E, HYLCMAT_ERR_OPEN, "Cannot read %s '%s': not a regular file", what, path);
  fp = fopen(path, "rb");
  if (!fp) return hm_fail(E, HYLCMAT_ERR_OPEN, "Cannot open %s '%s': %s", what, path, strerror(errno));
  if (fseek(fp, 0, SEEK_END) || (n = ftell(fp)) < 0) {
    fclose(fp);
    return hm_fail(E, HYLCMAT_ERR_READ, "Cannot read %s '%s'", what, path);
  }
  if (n >= (1L << 30)) {
    fclose(fp);
    return hm_fail(E, HYLCMAT_ERR_FORMAT, "The %s '%s' is too large (%ld bytes)", what, path, n);
  }
  rewind(fp);
  *bytes = malloc((size_t)n + 1);
  if (!*bytes) {
    fclose(fp);
    return hm_fail(E, HYLCMAT_ERR_MEMORY, "Cannot read %s '%s': out of memory", what, path);
  }
  if (fread(*bytes, 1, (size_t)n, fp) != (size_t)n) {
    fclose(fp);
    free(*bytes);
    *bytes = NULL;
    return hm_fail(E, HYLCMAT_ERR_READ, "Cannot read %s '%s'", what, path);
  }
  fclose(fp);
  (*bytes)[n] = 0;
  *len        = (size_t)n;
  return HYLCMAT_OK;
}

int hylcmat_load(const char *path, hylcmat **m, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  char  *bytes;
  size_t len;
  int    r;

  if (err && errlen) err[0] = 0;
  HM_CHECK(m, &E, HYLCMAT_ERR_ARG, "hylcmat_load: NULL result pointer");
  *m = NULL;
  HM_CHECK(path && path[0], &E, HYLCMAT_ERR_ARG, "hylcmat_load: no file name");
  HM_CALL(hm_read_file(path, "material file", &bytes, &len, &E));
  r = hylcmat_load_memory(path, bytes, len, m, err, errlen);
  free(bytes);
  return r;
}

const char *hylcmat_format_double(double x, char buf[32]) { return HylcJsonFormatDouble(x, buf); }
