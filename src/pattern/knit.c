/* Procedural yarn centrelines of periodic weft-knit tiles; see include/hylc/private/knit.h and
   docs/knit-generators.md. */
#include <hylc/private/knit.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#ifndef M_PI
#  define M_PI 3.14159265358979323846
#endif

typedef struct {
  double w, c, d; /* wale, course, depth */
  int    rib;
} KnitCurve;

static int KnitError(char *errmsg, size_t errlen, const char *fmt, ...)
{
  if (errmsg && errlen > 0) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(errmsg, errlen, fmt, ap);
    va_end(ap);
  }
  return 1;
}

/* Course parameter T: stitch i occupies T in [2 pi i, 2 pi (i+1)); T = 2 pi i is a sinker centre,
   T = 2 pi i + pi the centre of the needle-loop head. */
static void KnitCurveEval(const KnitCurve *kc, double T, double X[3])
{
  double s = 1.0;
  if (kc->rib) s = tanh(HYLC_KNIT_SHARP * sin(0.5 * T)) / tanh(HYLC_KNIT_SHARP);
  X[0] = kc->w * (T / (2 * M_PI) + HYLC_KNIT_LEAN * sin(2 * T));
  X[1] = -HYLC_KNIT_LOOP * kc->c * cos(T);
  X[2] = -kc->d * s * cos(2 * T);
}

static double Dist3(const double a[3], const double b[3])
{
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return sqrt(dx * dx + dy * dy + dz * dz);
}

static int CheckLength(double v, const char *name, char *errmsg, size_t errlen)
{
  if (!isfinite(v)) return KnitError(errmsg, errlen, "knit: %s is not finite", name);
  return 0;
}

int HylcKnitSample(HylcKnitType type, const HylcKnitParams *p, int *nyarns, int **nverts, double **pts, double *px, double *py, char *errmsg, size_t errlen)
{
  if (errmsg && errlen > 0) errmsg[0] = 0;
  if (!p || !nyarns || !nverts || !pts || !px || !py) return KnitError(errmsg, errlen, "knit: NULL argument");
  if (type != HYLC_KNIT_STOCKINETTE && type != HYLC_KNIT_RIB) return KnitError(errmsg, errlen, "knit: unknown knit type %d", (int)type);
  if (CheckLength(p->r, "r", errmsg, errlen) || CheckLength(p->wale, "wale", errmsg, errlen) || CheckLength(p->course, "course", errmsg, errlen) || CheckLength(p->depth, "depth", errmsg, errlen) || CheckLength(p->seglen, "seglen", errmsg, errlen))
    return 1;
  if (!(p->r > 0)) return KnitError(errmsg, errlen, "knit: yarn radius r = %g must be > 0", p->r);
  if (p->nwales < 1) return KnitError(errmsg, errlen, "knit: nwales = %d must be >= 1", p->nwales);
  if (p->ncourses < 1) return KnitError(errmsg, errlen, "knit: ncourses = %d must be >= 1", p->ncourses);
  if (type == HYLC_KNIT_RIB && p->nwales % 2) return KnitError(errmsg, errlen, "knit: 1x1 rib needs an even nwales (got %d)", p->nwales);

  const double r = p->r;
  KnitCurve    kc;
  kc.w                = p->wale > 0 ? p->wale : HYLC_KNIT_DEFAULT_WALE * r;
  kc.c                = p->course > 0 ? p->course : HYLC_KNIT_DEFAULT_COURSE * r;
  kc.d                = p->depth > 0 ? p->depth : HYLC_KNIT_DEFAULT_DEPTH * r;
  kc.rib              = type == HYLC_KNIT_RIB;
  const double seglen = p->seglen > 0 ? p->seglen : r;

  /* Arc length of one stitch from a dense chord table (all stitches have the same length: for the rib,
     odd stitches are z-mirrors of even ones). */
  enum { NTAB = 8192 };
  double *tab = malloc((NTAB + 1) * sizeof(double));
  if (!tab) return KnitError(errmsg, errlen, "knit: out of memory");
  double Xa[3], Xb[3];
  tab[0] = 0;
  KnitCurveEval(&kc, 0.0, Xa);
  for (int k = 1; k <= NTAB; k++) {
    KnitCurveEval(&kc, 2 * M_PI * k / NTAB, Xb);
    tab[k] = tab[k - 1] + Dist3(Xa, Xb);
    Xa[0]  = Xb[0];
    Xa[1]  = Xb[1];
    Xa[2]  = Xb[2];
  }
  const double L     = tab[NTAB];
  const double ratio = L / seglen;
  if (!(ratio < 1e6)) {
    free(tab);
    return KnitError(errmsg, errlen, "knit: seglen = %g is too small for a stitch of length %g", seglen, L);
  }
  int m = 2 * (int)floor(0.5 * ratio + 0.5); /* even number of vertices per stitch */
  if (m < HYLC_KNIT_MIN_VERTS_PER_STITCH) {
    free(tab);
    return KnitError(errmsg, errlen, "knit: seglen = %g gives %d < %d vertices per stitch (stitch length %g)", seglen, m, HYLC_KNIT_MIN_VERTS_PER_STITCH, L);
  }
  const long long nper = (long long)m * p->nwales, ntot = nper * p->ncourses;
  if (nper > 100000000LL || ntot > 100000000LL) {
    free(tab);
    return KnitError(errmsg, errlen, "knit: tile too large (%lld vertices)", ntot);
  }

  /* Parameters of the m vertices of stitch 0 at uniform arc length (linear inversion of the table). */
  double *tpar = malloc((size_t)m * sizeof(double));
  int    *nv   = malloc((size_t)p->ncourses * sizeof(int));
  double *X    = malloc((size_t)ntot * 3 * sizeof(double));
  if (!tpar || !nv || !X) {
    free(tab);
    free(tpar);
    free(nv);
    free(X);
    return KnitError(errmsg, errlen, "knit: out of memory");
  }
  for (int k = 0, seg = 0; k < m; k++) {
    const double s = L * k / m;
    while (seg < NTAB - 1 && tab[seg + 1] <= s) seg++;
    const double ds = tab[seg + 1] - tab[seg], f = ds > 0 ? (s - tab[seg]) / ds : 0;
    tpar[k] = 2 * M_PI * (seg + f) / NTAB;
  }
  free(tab);

  /* Sample every course; course j is course 0 shifted by j*course along y. */
  double mean[3] = {0, 0, 0};
  for (int j = 0; j < p->ncourses; j++) {
    nv[j] = (int)nper;
    for (int i = 0; i < p->nwales; i++) {
      for (int k = 0; k < m; k++) {
        double *x = X + 3 * ((long long)j * nper + (long long)i * m + k);
        KnitCurveEval(&kc, 2 * M_PI * i + tpar[k], x);
        x[1] += j * kc.c;
        for (int q = 0; q < 3; q++) mean[q] += x[q];
      }
    }
  }
  free(tpar);
  for (int q = 0; q < 3; q++) mean[q] /= (double)ntot;
  for (long long v = 0; v < ntot; v++)
    for (int q = 0; q < 3; q++) X[3 * v + q] -= mean[q];

  *nyarns = p->ncourses;
  *nverts = nv;
  *pts    = X;
  *px     = p->nwales * kc.w;
  *py     = p->ncourses * kc.c;
  return 0;
}
