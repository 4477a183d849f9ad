/* hylcmat: the homogeneous states of a measured-cloth sheet (include/hylcmat.h, docs/measured-cloth.md):
   uniaxial tension along x, y and the 45 degree bias with free lateral strain, as the balance of the
   simulator's frozen-stiffness forces or as the stationarity of the energy, and the bending moment per
   unit width on a regular right-triangle mesh. Plain C99. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

/* the lateral problem of a strip along d = (c, sn), e = (-sn, c): G = Gdd d d^T + Gee e e^T + Gde (d e^T + e d^T),
   Gdd fixed; the residuals are dpsi/dGee and dpsi/dGde (the lateral stresses) */
typedef struct {
  const hylcmat_measured *mc;
  int                     mode;
  double                  c, sn;
  double                  Gdd; /* the Green strain along the strip */
  double                  Gde; /* the outer unknown while the inner one is solved */
  int                     evals;
} Lateral;

static void StripG(const Lateral *L, double Gee, double Gde, double G[3])
{
  const double c = L->c, s = L->sn;
  G[0] = L->Gdd * c * c + Gee * s * s - 2 * Gde * c * s;
  G[1] = L->Gdd * s * s + Gee * c * c + 2 * Gde * c * s;
  G[2] = (L->Gdd - Gee) * c * s + Gde * (c * c - s * s);
}

/* dpsi/d(Gdd, Gee, Gde) (frozen or energy) at the strip strain (Gee, Gde) */
static void StripDeriv(Lateral *L, double Gee, double Gde, double Dp[3])
{
  double       G[3], D[3];
  const double c = L->c, s = L->sn;
  StripG(L, Gee, Gde, G);
  L->evals++;
  hylcmat_measured_membrane(L->mc, G, NULL, L->mode == HYLCMAT_MEASURED_FROZEN ? D : NULL, L->mode == HYLCMAT_MEASURED_FROZEN ? NULL : D, NULL);
  Dp[0] = D[0] * c * c + D[1] * s * s + D[2] * c * s;
  Dp[1] = D[0] * s * s + D[1] * c * c - D[2] * c * s;
  Dp[2] = 2 * c * s * (D[1] - D[0]) + (c * c - s * s) * D[2];
}

/* inner: the stress across the strip at fixed Gde */
static double Inner(Lateral *L, double Gee)
{
  double Dp[3];
  StripDeriv(L, Gee, L->Gde, Dp);
  return Dp[1];
}

typedef double (*Fun)(Lateral *, double);

/* A root of f nearest x0: probes x0 +- h, h growing by 1.5 from h0 up to span (within (lo, hi)), the
   first sign change brackets it, then bisection and the secant (Illinois) to an interval of 1e-15.
   Returns 0 and *x, or HYLCMAT_ERR_NOCONV. A jump of f across 0 is found like a root (the residual
   there is not 0). */
static int Root(Lateral *L, Fun f, double x0, double h0, double span, double lo, double hi, double *x, double *res)
{
  double       a = x0, fa = f(L, x0), b = x0, fb = fa;
  int          found = fa == 0;
  const double h1    = h0;

  if (found) {
    *x   = x0;
    *res = 0;
    return HYLCMAT_OK;
  }
  double pl = x0, fpl = fa, pr = x0, fpr = fa; /* the last probes left and right */
  for (double h = h1; h <= span && !found; h *= 1.5) {
    if (x0 + h < hi) {
      const double xr = x0 + h, fr = f(L, xr);
      if ((fr > 0) != (fpr > 0) || fr == 0) a = pr, fa = fpr, b = xr, fb = fr, found = 1;
      pr = xr, fpr = fr;
    }
    if (!found && x0 - h > lo) {
      const double xl = x0 - h, fl = f(L, xl);
      if ((fl > 0) != (fpl > 0) || fl == 0) a = xl, fa = fl, b = pl, fb = fpl, found = 1;
      pl = xl, fpl = fl;
    }
  }
  if (!found) return HYLCMAT_ERR_NOCONV;
  /* Illinois on [a, b] with f(a), f(b) of opposite signs (or one of them 0) */
  int side = 0;
  for (int it = 0; it < 200 && fa != 0 && fb != 0 && fabs(b - a) > 1e-15; it++) {
    double c = (a * fb - b * fa) / (fb - fa);
    if (!(c > fmin(a, b) && c < fmax(a, b)) || it % 4 == 3) c = 0.5 * (a + b); /* a bisection every fourth step */
    const double fc = f(L, c);
    if (fc == 0) {
      a = b = c;
      fa = fb = 0;
      break;
    }
    if ((fc > 0) == (fb > 0)) {
      b = c, fb = fc;
      if (side == -1) fa *= 0.5;
      side = -1;
    } else {
      a = c, fa = fc;
      if (side == 1) fb *= 0.5;
      side = 1;
    }
  }
  if (fabs(fa) <= fabs(fb))
    *x = a, *res = fa;
  else
    *x = b, *res = fb;
  return HYLCMAT_OK;
}

/* outer: the shear stress with Gee solved at this Gde */
static double Outer(Lateral *L, double Gde)
{
  double Gee, res, Dp[3];
  L->Gde = Gde;
  if (Root(L, Inner, 0, 1e-3, 0.5, -0.49, 1, &Gee, &res)) return NAN;
  StripDeriv(L, Gee, Gde, Dp);
  return Dp[2];
}

int hylcmat_measured_tension_angle(const hylcmat_measured *mc, double phi, double s, int mode, hylcmat_measured_state *st, char *err, size_t errlen)
{
  hm_err       E = {err, errlen};
  Lateral      L;
  double       Gee, Gde = 0, res, rde = 0, Dp[3];
  const double span = 0.5, deg = phi * 57.295779513082323;

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc && st, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_tension: NULL material or result");
  memset(st, 0, sizeof(*st));
  HM_CHECK(isfinite(phi), &E, HYLCMAT_ERR_ARG, "measured cloth: the strip's angle must be finite");
  HM_CHECK(mode == HYLCMAT_MEASURED_FROZEN || mode == HYLCMAT_MEASURED_ENERGY, &E, HYLCMAT_ERR_ARG, "measured cloth: mode %d: must be HYLCMAT_MEASURED_FROZEN or _ENERGY", mode);
  HM_CHECK(s >= 0 && s < 1, &E, HYLCMAT_ERR_ARG, "measured cloth: tension stretch %g at %g degrees is outside [0, 1)", s, deg);
  memset(&L, 0, sizeof(L));
  L.mc   = mc;
  L.mode = mode;
  L.c    = cos(phi);
  L.sn   = sin(phi);
  if (fabs(L.sn) < 1e-15) L.c = L.c > 0 ? 1 : -1, L.sn = 0; /* the axes exactly */
  if (fabs(L.c) < 1e-15) L.sn = L.sn > 0 ? 1 : -1, L.c = 0;
  L.Gdd = 0.5 * ((1 + s) * (1 + s) - 1);
  if (L.c * L.sn != 0) { /* off the axes: the shear is free too */
    if (Root(&L, Outer, 0, 1e-3, span, -span, span, &Gde, &rde)) return hm_fail(&E, HYLCMAT_ERR_NOCONV, "measured cloth: tension at %g degrees, s = %g: no lateral balance within |G| < %g", deg, s, span);
  } /* on an axis the shear stress vanishes at Gde = 0 (symmetry: k depends on |G01|) */
  L.Gde = Gde;
  if (Root(&L, Inner, 0, 1e-3, span, -0.49, 1, &Gee, &res)) return hm_fail(&E, HYLCMAT_ERR_NOCONV, "measured cloth: tension at %g degrees, s = %g: no lateral balance within |G| < %g", deg, s, span);
  StripDeriv(&L, Gee, Gde, Dp);
  st->s           = s;
  st->T           = (1 + s) * Dp[0];
  st->lateral     = sqrt(1 + 2 * Gee) - 1;
  st->shear       = 2 * Gde / sqrt((1 + 2 * L.Gdd) * (1 + 2 * Gee));
  st->residual    = fmax(fabs(Dp[1]), fabs(Dp[2]));
  st->evaluations = L.evals;
  StripG(&L, Gee, Gde, st->G);
  hylcmat_measured_stiffness(mc, st->G, st->k, NULL);
  return HYLCMAT_OK;
}

int hylcmat_measured_tension(const hylcmat_measured *mc, int dir, double s, int mode, hylcmat_measured_state *st, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  if (err && errlen) err[0] = 0;
  HM_CHECK(dir >= 0 && dir <= 2, &E, HYLCMAT_ERR_ARG, "measured cloth: tension direction %d: must be 0 (x), 1 (y) or 2 (the 45 degree bias)", dir);
  return hylcmat_measured_tension_angle(mc, dir == 0 ? 0 : dir == 1 ? 1.57079632679489662 : 0.78539816339744831, s, mode, st, err, errlen);
}

int hylcmat_measured_bending(const hylcmat_measured *mc, int dir, double kappa, int mode, double *M, double *kout)
{
  if (M) *M = 0;
  if (kout) *kout = 0;
  if (!mc || !M || (dir != 0 && dir != 1) || !isfinite(kappa) || (mode != HYLCMAT_MEASURED_FROZEN && mode != HYLCMAT_MEASURED_ENERGY)) return HYLCMAT_ERR_ARG;
  /* the edges across the bend: along v when x curves (II00), along u when y curves */
  const double du[2] = {dir ? 1 : 0, dir ? 0 : 1};
  double       dk;
  const double k = hylcmat_measured_bending_sample(mc, kappa, du, &dk);
  *M             = k * kappa / 4 + (mode == HYLCMAT_MEASURED_ENERGY ? dk * kappa * kappa / 8 : 0);
  if (kout) *kout = k;
  return HYLCMAT_OK;
}
