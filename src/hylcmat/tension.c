/* hylcmat: uniaxial tension of a table's strip cut at any angle to the material axes (the bias test at 45
   degrees): Psi minimized over the two lateral unknowns of the in-plane strain (include/hylcmat.h,
   docs/measured-cloth.md, "A table's sheet"). Plain C99. */
#include "hylcmatimpl.h"
#include <hylc/private/newton2.h>
#include <math.h>
#include <string.h>

typedef struct {
  const hylcmat *m;
  double         c, sn, s; /* cos, sin of the strip's angle; the stretch */
} Strip;

/* Psi, dPsi/dp, T and the strains (sx, sa, sy) at the unknowns p = (lambda, c): lambda = sqrt(C_ee) the
   lateral stretch, c = C_de / sqrt(C_dd C_ee) the cosine of the deformed angle between length and width */
static int Eval(const Strip *S, const double p[2], double *psi, double g[2], double *T, double z3[3])
{
  const double Cdd = (1 + S->s) * (1 + S->s), Cee = p[0] * p[0], Cde = p[1] * (1 + S->s) * p[0];
  const double c = S->c, sn = S->sn, cc = c * c, ss = sn * sn, cs = c * sn;
  const double C00 = Cdd * cc + Cee * ss - 2 * Cde * cs, C11 = Cdd * ss + Cee * cc + 2 * Cde * cs, C01 = (Cdd - Cee) * cs + Cde * (cc - ss);
  if (!(C00 > 0 && C11 > 0)) return HYLCMAT_ERR_DEGENERATE;
  const double r0 = sqrt(C00), r1 = sqrt(C11), sa = C01 / (r0 * r1);
  if (!(fabs(sa) < 1)) return HYLCMAT_ERR_DEGENERATE;
  double z[6] = {r0 - 1, sa, r1 - 1, 0, 0, 0}, gz[6];
  int    r    = hylcmat_eval(S->m, z, psi, gz, NULL);
  if (r) return r;
  /* dPsi/dC00, dPsi/dC11, dPsi/dC01 (C01 the one off-diagonal value) */
  const double P00 = gz[0] / (2 * r0) - 0.5 * gz[1] * sa / C00, P11 = gz[2] / (2 * r1) - 0.5 * gz[1] * sa / C11, P01 = gz[1] / (r0 * r1);
  const double Pdd = P00 * cc + P11 * ss + P01 * cs, Pee = P00 * ss + P11 * cc - P01 * cs, Pde = 2 * cs * (P11 - P00) + (cc - ss) * P01;
  if (g) {
    g[0] = Pee * 2 * p[0] + Pde * p[1] * (1 + S->s);
    g[1] = Pde * (1 + S->s) * p[0];
  }
  if (T) *T = Pdd * 2 * (1 + S->s) + Pde * p[1] * p[0]; /* dPsi/ds at fixed p */
  if (z3) z3[0] = z[0], z3[1] = z[1], z3[2] = z[2];
  return HYLCMAT_OK;
}

/* the Hessian by central differences of the gradient */
static int Hess(const Strip *S, const double p[2], double H[4])
{
  const double h = 1e-6;
  for (int j = 0; j < 2; j++) {
    double q[2] = {p[0], p[1]}, gp[2], gm[2], psi;
    q[j]        = p[j] + h;
    HM_CALL(Eval(S, q, &psi, gp, NULL, NULL));
    q[j] = p[j] - h;
    HM_CALL(Eval(S, q, &psi, gm, NULL, NULL));
    H[j]     = (gp[0] - gm[0]) / (2 * h);
    H[2 + j] = (gp[1] - gm[1]) / (2 * h);
  }
  H[1] = H[2] = 0.5 * (H[1] + H[2]);
  return HYLCMAT_OK;
}

static int Inside(const double q[2]) { return q[0] > 0.01 && fabs(q[1]) < 0.99; }

int hylcmat_tension(const hylcmat *m, double phi, double s, const double guess[2], hylcmat_tension_state *st, char *err, size_t errlen)
{
  hm_err       E = {err, errlen};
  Strip        S;
  double       p[2], psi = 0, g[2] = {0, 0}, H[4], T = 0, d[2] = {0, 0}, z3[3] = {0, 0, 0};
  const double xtol = 1e-10, maxStep = 0.1;
  const int    maxIt = 200, maxRestarts = 20;
  int          r, it = 0, converged = 0;

  if (err && errlen) err[0] = 0;
  HM_CHECK(m && st, &E, HYLCMAT_ERR_ARG, "hylcmat_tension: NULL table or result");
  memset(st, 0, sizeof(*st));
  HM_CHECK(isfinite(phi), &E, HYLCMAT_ERR_ARG, "tension: the strip's angle must be finite");
  HM_CHECK(s >= 0 && s < 1, &E, HYLCMAT_ERR_ARG, "tension: stretch %g at %g degrees is outside [0, 1) (a compressed strip buckles)", s, phi * 57.295779513082323);
  S.m  = m;
  S.c  = cos(phi);
  S.sn = sin(phi);
  S.s  = s;
  if (guess) {
    p[0] = guess[0], p[1] = guess[1];
    HM_CHECK(Inside(p), &E, HYLCMAT_ERR_ARG, "tension: starting lateral stretch %g and shear %g: need a stretch > 0.01 and |shear| < 0.99", p[0], p[1]);
  } else { /* the lowest point of a grid: tables can have several lateral minima */
    double best = INFINITY;
    p[0] = 1, p[1] = 0;
    for (int i = -25; i <= 25; i++)
      for (int j = -25; j <= 25; j++) {
        const double q[2] = {1 + 0.02 * i, 0.02 * j};
        double       qpsi;
        if (Eval(&S, q, &qpsi, NULL, NULL, NULL)) continue;
        if (qpsi < best) best = qpsi, p[0] = q[0], p[1] = q[1];
      }
  }
  r = Eval(&S, p, &psi, g, &T, z3);
  if (!r) r = Hess(&S, p, H);
  if (r) return hm_fail(&E, r, "tension at %g degrees, s = %g: the evaluation failed at the lateral stretch %g, shear %g (%s)", phi * 57.295779513082323, s, p[0], p[1], hylcmat_strerror(r));
  for (int restart = 0;; restart++) {
    converged = 0;
    for (; it < maxIt; it++) {
      HylcNewtonStep2(H, g, 1e-6, d);
      double nd = fmax(fabs(d[0]), fabs(d[1]));
      if (nd <= xtol) {
        converged = 1;
        break;
      }
      if (nd > maxStep) d[0] *= maxStep / nd, d[1] *= maxStep / nd, nd = maxStep;
      const double slope    = g[0] * d[0] + g[1] * d[1];
      const int    blind    = -slope <= 1e-13 * fabs(psi);
      int          accepted = 0;
      for (double t = 1; t > 1e-10 && !accepted; t *= 0.5) {
        const double q[2] = {p[0] + t * d[0], p[1] + t * d[1]};
        double       qpsi, qg[2], qT, qz[3], qH[4];
        if (!Inside(q) || (q[0] == p[0] && q[1] == p[1])) continue;
        if (Eval(&S, q, &qpsi, qg, &qT, qz)) continue;
        if (blind || qpsi <= psi + 1e-4 * t * fmin(slope, 0)) {
          if (Hess(&S, q, qH)) continue;
          accepted = 1;
          p[0] = q[0], p[1] = q[1];
          psi = qpsi, T = qT;
          memcpy(g, qg, sizeof(g));
          memcpy(H, qH, sizeof(H));
          memcpy(z3, qz, sizeof(z3));
        }
      }
      if (!accepted || (blind && nd <= 1e-8)) {
        converged = nd <= 1e-8;
        break;
      }
    }
    if (!converged || restart == maxRestarts) break;
    /* probes at distance 1e-3 in 8 directions: a lower one restarts Newton (a kink of the table) */
    double best = psi, bq[2] = {p[0], p[1]};
    for (int k = 0; k < 8; k++) {
      const double a = k * 0.78539816339744831, q[2] = {p[0] + 1e-3 * cos(a), p[1] + 1e-3 * sin(a)};
      double       qpsi;
      if (!Inside(q) || Eval(&S, q, &qpsi, NULL, NULL, NULL)) continue;
      if (qpsi < best - 1e-14 * fabs(psi)) best = qpsi, bq[0] = q[0], bq[1] = q[1];
    }
    if (best == psi) break;
    p[0] = bq[0], p[1] = bq[1];
    r = Eval(&S, p, &psi, g, &T, z3);
    if (!r) r = Hess(&S, p, H);
    if (r) return hm_fail(&E, r, "tension at %g degrees, s = %g: the evaluation failed (%s)", phi * 57.295779513082323, s, hylcmat_strerror(r));
  }
  st->s       = s;
  st->T       = T;
  st->lateral = p[0] - 1;
  st->shear   = p[1];
  memcpy(st->strain, z3, sizeof(z3));
  st->psi        = psi;
  st->grad[0]    = g[0];
  st->grad[1]    = g[1];
  st->iterations = it;
  HM_CHECK(converged, &E, HYLCMAT_ERR_NOCONV, "tension at %g degrees, s = %g: the minimization over the lateral strains did not converge (%d iterations, at the lateral stretch %g, shear %g)", phi * 57.295779513082323, s, it, p[0], p[1]);
  return HYLCMAT_OK;
}
