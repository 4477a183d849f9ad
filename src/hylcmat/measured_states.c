/* hylcmat: the homogeneous states of a measured-cloth sheet (include/hylcmat.h, docs/measured-cloth.md):
   uniaxial tension along x, y and the 45 degree bias with free lateral strain, as the balance of the
   simulator's frozen-stiffness forces or as the stationarity of the energy, and the bending moment per
   unit width on a regular right-triangle mesh. Plain C99. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

/* the lateral problem: G from the unknowns, and the residuals (lateral stresses) */
typedef struct {
  const hylcmat_measured *mc;
  int                     dir, mode;
  double                  Gdd; /* the Green strain along the strip */
  double                  Gde; /* bias: the outer unknown while the inner one is solved */
  int                     evals;
} Lateral;

/* dpsi/dG (frozen or energy) at G */
static void Deriv(Lateral *L, const double G[3], double D[3])
{
  L->evals++;
  hylcmat_measured_membrane(L->mc, G, NULL, L->mode == HYLCMAT_MEASURED_FROZEN ? D : NULL, L->mode == HYLCMAT_MEASURED_FROZEN ? NULL : D, NULL);
}

/* bias: G from (Gdd, Gee, Gde) in the strip's axes d = (1, 1)/sqrt 2, e = (-1, 1)/sqrt 2 */
static void BiasG(double Gdd, double Gee, double Gde, double G[3])
{
  G[0] = 0.5 * (Gdd + Gee) - Gde;
  G[1] = 0.5 * (Gdd + Gee) + Gde;
  G[2] = 0.5 * (Gdd - Gee);
}

/* the axes: the lateral stress S_ee as a function of the lateral Green strain */
static double AxisResidual(Lateral *L, double Gee)
{
  double G[3]   = {0, 0, 0}, D[3];
  G[L->dir]     = L->Gdd;
  G[1 - L->dir] = Gee;
  Deriv(L, G, D);
  return D[1 - L->dir];
}

/* the bias, inner: S_ee = (D00 + D11 - D01) / 2 at fixed Gde */
static double BiasInner(Lateral *L, double Gee)
{
  double G[3], D[3];
  BiasG(L->Gdd, Gee, L->Gde, G);
  Deriv(L, G, D);
  return 0.5 * (D[0] + D[1] - D[2]);
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

/* the bias, outer: S_de = (D11 - D00) / 2 with Gee solved at this Gde */
static double BiasOuter(Lateral *L, double Gde)
{
  double Gee, res, G[3], D[3];
  L->Gde = Gde;
  if (Root(L, BiasInner, 0, 1e-3, 0.5, -0.49, 1, &Gee, &res)) return NAN;
  BiasG(L->Gdd, Gee, Gde, G);
  Deriv(L, G, D);
  return 0.5 * (D[1] - D[0]);
}

int hylcmat_measured_tension(const hylcmat_measured *mc, int dir, double s, int mode, hylcmat_measured_state *st, char *err, size_t errlen)
{
  hm_err       E       = {err, errlen};
  const char  *name[3] = {"x", "y", "the bias"};
  Lateral      L;
  double       G[3], D[3], res = 0;
  const double span = 0.5;

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc && st, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_tension: NULL material or result");
  memset(st, 0, sizeof(*st));
  HM_CHECK(dir >= 0 && dir <= 2, &E, HYLCMAT_ERR_ARG, "measured cloth: tension direction %d: must be 0 (x), 1 (y) or 2 (the 45 degree bias)", dir);
  HM_CHECK(mode == HYLCMAT_MEASURED_FROZEN || mode == HYLCMAT_MEASURED_ENERGY, &E, HYLCMAT_ERR_ARG, "measured cloth: mode %d: must be HYLCMAT_MEASURED_FROZEN or _ENERGY", mode);
  HM_CHECK(s >= 0 && s < 1, &E, HYLCMAT_ERR_ARG, "measured cloth: tension stretch %g along %s is outside [0, 1)", s, name[dir]);
  memset(&L, 0, sizeof(L));
  L.mc   = mc;
  L.dir  = dir;
  L.mode = mode;
  L.Gdd  = 0.5 * ((1 + s) * (1 + s) - 1);
  if (dir < 2) {
    double Gee;
    if (Root(&L, AxisResidual, 0, 1e-3, span, -0.49, 1, &Gee, &res)) return hm_fail(&E, HYLCMAT_ERR_NOCONV, "measured cloth: tension along %s at s = %g: no lateral balance within |G| < %g", name[dir], s, span);
    G[dir]     = L.Gdd;
    G[1 - dir] = Gee;
    G[2]       = 0;
    Deriv(&L, G, D);
    st->T       = (1 + s) * D[dir];
    st->lateral = sqrt(1 + 2 * Gee) - 1;
    st->shear   = 0;
    res         = fabs(D[1 - dir]);
  } else {
    double Gde, Gee, rde;
    if (Root(&L, BiasOuter, 0, 1e-3, span, -span, span, &Gde, &rde)) return hm_fail(&E, HYLCMAT_ERR_NOCONV, "measured cloth: tension along the bias at s = %g: no lateral balance within |G| < %g", s, span);
    L.Gde = Gde;
    if (Root(&L, BiasInner, 0, 1e-3, span, -0.49, 1, &Gee, &res)) return hm_fail(&E, HYLCMAT_ERR_NOCONV, "measured cloth: tension along the bias at s = %g: no lateral balance within |G| < %g", s, span);
    BiasG(L.Gdd, Gee, Gde, G);
    Deriv(&L, G, D);
    st->T       = (1 + s) * 0.5 * (D[0] + D[1] + D[2]); /* (1 + s) S_dd */
    st->lateral = sqrt(1 + 2 * Gee) - 1;
    st->shear   = 2 * Gde / sqrt((1 + 2 * L.Gdd) * (1 + 2 * Gee));
    res         = fmax(fabs(0.5 * (D[0] + D[1] - D[2])), fabs(0.5 * (D[1] - D[0])));
  }
  st->s = s;
  memcpy(st->G, G, sizeof(st->G));
  hylcmat_measured_stiffness(mc, G, st->k, NULL);
  st->residual    = res;
  st->evaluations = L.evals;
  return HYLCMAT_OK;
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
