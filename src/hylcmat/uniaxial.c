/* hylcmat: the homogeneous uniaxial tension state of a table (include/hylcmat.h, docs/fabric-uniaxial.md).
   Plain C99. */
#include "hylcmatimpl.h"
#include <hylc/private/newton2.h>
#include <math.h>
#include <string.h>

/* the strain of lateral strains p at stretch s: dir 0 (x): (s, p0, p1), dir 1 (y): (p1, p0, s) */
static void StrainOf(int dir, double s, const double p[2], double z[6])
{
  memset(z, 0, 6 * sizeof(double));
  z[1]           = p[0];
  z[dir ? 2 : 0] = s;
  z[dir ? 0 : 2] = p[1];
}

/* Psi, the lateral gradient gl and Hessian Hl (2 x 2) and T at the lateral strains p */
static int Eval(const hylcmat *m, int dir, double s, const double p[2], double *psi, double gl[2], double Hl[4], double *T)
{
  double z[6], g[6], H[36];
  int    r;
  StrainOf(dir, s, p, z);
  r = hylcmat_eval(m, z, psi, g, Hl ? H : NULL);
  if (r) return r;
  const int o = dir ? 0 : 2; /* the other stretch */
  gl[0]       = g[1];
  gl[1]       = g[o];
  if (T) *T = g[dir ? 2 : 0];
  if (Hl) {
    Hl[0] = H[6 * 1 + 1];
    Hl[1] = H[6 * 1 + o];
    Hl[2] = H[6 * o + 1];
    Hl[3] = H[6 * o + o];
  }
  return HYLCMAT_OK;
}

int hylcmat_uniaxial(const hylcmat *m, int dir, double s, const double guess[2], hylcmat_uniaxial_state *st, char *err, size_t errlen)
{
  hm_err       E       = {err, errlen};
  const char  *name[2] = {"x (sx = s)", "y (sy = s)"};
  double       p[2], psi, gl[2], H[4], T, d[2] = {0, 0};
  const double xtol = 1e-11, maxStep = 0.1;
  const int    maxIt = 200, maxRestarts = 20;
  int          r, it = 0, converged = 0, nblind = 0;

  if (err && errlen) err[0] = 0;
  HM_CHECK(m && st, &E, HYLCMAT_ERR_ARG, "hylcmat_uniaxial: NULL table or result");
  memset(st, 0, sizeof(*st));
  HM_CHECK(dir == 0 || dir == 1, &E, HYLCMAT_ERR_ARG, "uniaxial direction %d: must be 0 (x, the stretch sx) or 1 (y, the stretch sy)", dir);
  HM_CHECK(s >= 0 && s < 1, &E, HYLCMAT_ERR_ARG, "uniaxial stretch %g along %s is outside [0, 1): a uniaxial state is a tension test (a compressed strip buckles)", s, name[dir]);
  {
    hylcmat_term1d t;
    const int      k = dir ? 2 : 0;
    if (hylcmat_term1d_get(m, k, &t)) { /* within the sampled range of the stretch's term */
      const double lo = t.t[0] * m->scale[k], hi = t.t[t.n - 1] * m->scale[k];
      HM_CHECK(s >= lo && s <= hi, &E, HYLCMAT_ERR_ARG, "uniaxial stretch %g along %s is outside the table's range [%g, %g] of %s (its knots times its strain scale)", s, name[dir], lo, hi, hylcmat_term1d_name(k));
    }
  }
  p[0] = guess ? guess[0] : 0;
  p[1] = guess ? guess[1] : 0;
  HM_CHECK(isfinite(p[0]) && isfinite(p[1]) && fabs(p[0]) < 0.99 && p[1] > -0.99, &E, HYLCMAT_ERR_ARG, "uniaxial starting lateral strains (%g, %g): need finite values, |sa| < 0.99 and a stretch > -0.99", p[0], p[1]);
  if (!guess) { /* no guess: start from the lowest point of a grid (tables can have several lateral minima) */
    double best = INFINITY;
    for (int i = -25; i <= 25; i++)
      for (int j = -25; j <= 25; j++) {
        const double q[2] = {0.02 * i, 0.02 * j};
        double       qpsi, qg[2];
        r = Eval(m, dir, s, q, &qpsi, qg, NULL, NULL);
        if (r) return hm_fail(&E, r, "uniaxial state along %s at s = %g: the evaluation failed at the lateral strains (%g, %g) (%s)", name[dir], s, q[0], q[1], hylcmat_strerror(r));
        if (qpsi < best) best = qpsi, p[0] = q[0], p[1] = q[1];
      }
  }
  r = Eval(m, dir, s, p, &psi, gl, H, &T);
  if (r) return hm_fail(&E, r, "uniaxial state along %s at s = %g: the evaluation failed (%s)", name[dir], s, hylcmat_strerror(r));
  for (int restart = 0;; restart++) {
    converged = 0;
    for (; it < maxIt; it++) {
      HylcNewtonStep2(H, gl, 1e-6, d);
      if (fmax(fabs(d[0]), fabs(d[1])) <= xtol) {
        converged = 1;
        break;
      }
      const double nd = fmax(fabs(d[0]), fabs(d[1]));
      if (nd > maxStep) d[0] *= maxStep / nd, d[1] *= maxStep / nd;
      /* backtracking on Psi (Armijo 1e-4); a decrease below Psi's rounding cannot be seen: then the full
         Newton step (at most 20 in a row) */
      const double slope    = gl[0] * d[0] + gl[1] * d[1];
      const int    blind    = -slope <= 1e-13 * fabs(psi);
      int          accepted = 0;
      if (blind && ++nblind > 20) {
        converged = nd <= 1e-8;
        break;
      }
      if (!blind) nblind = 0;
      for (double t = 1; t > 1e-10 && !accepted; t *= 0.5) {
        const double q[2] = {p[0] + t * d[0], p[1] + t * d[1]};
        double       qpsi, qg[2], qH[4], qT;
        if (!(fabs(q[0]) < 0.99 && q[1] > -0.99) || (q[0] == p[0] && q[1] == p[1])) continue;
        r = Eval(m, dir, s, q, &qpsi, qg, qH, &qT);
        if (r) return hm_fail(&E, r, "uniaxial state along %s at s = %g: the evaluation failed at the lateral strains (%g, %g) (%s)", name[dir], s, q[0], q[1], hylcmat_strerror(r));
        if (blind || qpsi <= psi + 1e-4 * t * fmin(slope, 0)) {
          accepted = 1;
          p[0] = q[0], p[1] = q[1];
          psi = qpsi, T = qT;
          memcpy(gl, qg, sizeof(gl));
          memcpy(H, qH, sizeof(H));
        }
      }
      if (!accepted) { /* no decrease along a descent direction: Psi's rounding; a minimum if the step is tiny */
        converged = fmax(fabs(d[0]), fabs(d[1])) <= 1e-9;
        break;
      }
    }
    if (!converged || restart == maxRestarts) break;
    /* Newton stops at any stationary point: the table's Hessian jumps at knots, so a point can be a minimum
       for the one-sided Hessian returned there and not for Psi (our fits have dPsi/dsy = 0 on sy = 0 for
       every sx, a stationary line). Probes at distance 1e-3 in 8 directions; a lower one restarts Newton. */
    double best = psi, bq[2] = {p[0], p[1]};
    for (int k = 0; k < 8; k++) {
      const double a = k * 0.78539816339744831, q[2] = {p[0] + 1e-3 * cos(a), p[1] + 1e-3 * sin(a)};
      double       qpsi, qg[2];
      if (!(fabs(q[0]) < 0.99 && q[1] > -0.99)) continue;
      r = Eval(m, dir, s, q, &qpsi, qg, NULL, NULL);
      if (r) return hm_fail(&E, r, "uniaxial state along %s at s = %g: the evaluation failed at the lateral strains (%g, %g) (%s)", name[dir], s, q[0], q[1], hylcmat_strerror(r));
      if (qpsi < best - 1e-14 * fabs(psi)) best = qpsi, bq[0] = q[0], bq[1] = q[1];
    }
    if (best == psi) break;
    p[0] = bq[0], p[1] = bq[1];
    r = Eval(m, dir, s, p, &psi, gl, H, &T);
    if (r) return hm_fail(&E, r, "uniaxial state along %s at s = %g: the evaluation failed (%s)", name[dir], s, hylcmat_strerror(r));
  }
  st->s          = s;
  st->T          = T;
  st->lateral[0] = p[0];
  st->lateral[1] = p[1];
  st->psi        = psi;
  st->grad[0]    = gl[0];
  st->grad[1]    = gl[1];
  st->step       = fmax(fabs(d[0]), fabs(d[1]));
  st->iterations = it;
  HM_CHECK(converged, &E, HYLCMAT_ERR_NOCONV, "uniaxial state along %s at s = %g: the minimization over the lateral strains did not converge (%d iterations, last step %g at (%g, %g))", name[dir], s, it, st->step, p[0], p[1]);
  return HYLCMAT_OK;
}
