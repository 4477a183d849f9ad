/* hylcmat: the homogeneous states of the standard fabric tests (include/hylcmat.h, docs/fabric-fidelity.md):
   a load path prescribes one strain (or a stretch along a rotated direction), the others are free and minimize
   Psi, so their stresses vanish. The same parametrization serves the tile (src/micro/path.c) and the table
   (hylcmat_path_state below). Plain C99. */
#include "hylcmatimpl.h"
#include <hylc/private/newton2.h>
#include <math.h>
#include <string.h>

const char *hylcmat_path_name(int kind) { return kind >= 0 && kind < 4 ? HylcPathNames[kind] : NULL; }

int hylcmat_path_nfree(const hylcmat_path *path)
{
  if (!path) return -1;
  switch (path->kind) {
  case HYLCMAT_PATH_UNIAXIAL:
    return 2;
  case HYLCMAT_PATH_EQUIBIAXIAL:
    return 1;
  case HYLCMAT_PATH_SHEAR:
    return 2;
  case HYLCMAT_PATH_BENDING:
    return 3;
  default:
    return -1;
  }
}

/* the strain of the rotated-frame in-plane strain (X' - 1, c', Y' - 1): I' = [[X'^2, c' X' Y'], [c' X' Y', Y'^2]]
   in the frame of the axes e1' = (cos a, sin a), e2' = (-sin a, cos a) is I = R I' R^T in the material frame */
static int Rotated(double a, const double zr[3], double z[3])
{
  const double X = 1 + zr[0], c = zr[1], Y = 1 + zr[2], ca = cos(a), sa = sin(a);
  const double I1[4] = {X * X, c * X * Y, c * X * Y, Y * Y}, R[4] = {ca, -sa, sa, ca};
  double       T[4], I[4];
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) T[2 * i + j] = R[2 * i] * I1[j] + R[2 * i + 1] * I1[2 + j];
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) I[2 * i + j] = T[2 * i] * R[2 * j] + T[2 * i + 1] * R[2 * j + 1];
  if (!(I[0] > 0 && I[3] > 0)) return -1;
  z[0] = sqrt(I[0]) - 1;
  z[1] = I[1] / sqrt(I[0] * I[3]);
  z[2] = sqrt(I[3]) - 1;
  return fabs(z[1]) < 1 ? 0 : -1;
}

/* the axis-aligned uniaxial paths keep the lateral strains of hylcmat_uniaxial(): (sa, sy) along x, (sa, sx)
   along y; other angles the rotated frame's (sa', sy') */
static int AxisOf(double angle) { return angle == 0 ? 0 : angle == 90 ? 1 : -1; }

static int StrainOnly(const hylcmat_path *path, double s, const double p[3], double z[6])
{
  memset(z, 0, 6 * sizeof(double));
  switch (path->kind) {
  case HYLCMAT_PATH_UNIAXIAL: {
    const int ax = AxisOf(path->angle);
    if (ax >= 0) {
      z[1]          = p[0];
      z[ax ? 2 : 0] = s;
      z[ax ? 0 : 2] = p[1];
      return 0;
    }
    const double zr[3] = {s, p[0], p[1]};
    return Rotated(path->angle * 3.14159265358979323846 / 180, zr, z);
  }
  case HYLCMAT_PATH_EQUIBIAXIAL:
    z[0] = z[2] = s;
    z[1]        = p[0];
    return 0;
  case HYLCMAT_PATH_SHEAR:
    z[0] = p[0];
    z[1] = s;
    z[2] = p[1];
    return 0;
  case HYLCMAT_PATH_BENDING:
    z[0]                   = p[0];
    z[1]                   = p[1];
    z[2]                   = p[2];
    z[path->angle ? 5 : 3] = s;
    return 0;
  }
  return -1;
}

int hylcmat_path_strain(const hylcmat_path *path, double s, const double p[], double z[6], double J[])
{
  const int nf   = hylcmat_path_nfree(path);
  double    q[3] = {0, 0, 0}, zp[6], zm[6];
  if (nf < 0 || !p || !z) return HYLCMAT_ERR_ARG;
  for (int i = 0; i < nf; i++) q[i] = p[i];
  if (StrainOnly(path, s, q, z)) return HYLCMAT_ERR_ARG;
  if (!J) return HYLCMAT_OK;
  /* dz/d(s, p) (6 x (1 + nf), row-major): exact for the linear maps, central differences for a rotation */
  for (int c = 0; c <= nf; c++) {
    const double h  = 1e-7;
    double       sp = s, sm = s, qp[3] = {q[0], q[1], q[2]}, qm[3] = {q[0], q[1], q[2]};
    if (c)
      qp[c - 1] += h, qm[c - 1] -= h;
    else
      sp += h, sm -= h;
    if (StrainOnly(path, sp, qp, zp) || StrainOnly(path, sm, qm, zm)) return HYLCMAT_ERR_ARG;
    for (int k = 0; k < 6; k++) J[k * (1 + nf) + c] = (zp[k] - zm[k]) / (2 * h);
  }
  return HYLCMAT_OK;
}

/* ---- the table's state ---- */

/* Psi, the reduced gradient gp = J_p^T g and Hessian Hp = J_p^T H J_p (+ the rotation's curvature term) and the
   path's force f = J_s^T g at the free strains p */
static int Eval(const hylcmat *m, const hylcmat_path *path, int nf, double s, const double p[3], double *psi, double gp[3], double Hp[9], double *f, double gz[6])
{
  double z[6], J[24], g[6], H[36];
  int    r = hylcmat_path_strain(path, s, p, z, J);
  if (r) return r;
  r = hylcmat_eval(m, z, psi, g, Hp ? H : NULL);
  if (r) return r;
  if (gz) memcpy(gz, g, sizeof(g));
  *f = 0;
  for (int k = 0; k < 6; k++) *f += J[k * (1 + nf)] * g[k];
  for (int a = 0; a < nf; a++) {
    gp[a] = 0;
    for (int k = 0; k < 6; k++) gp[a] += J[k * (1 + nf) + 1 + a] * g[k];
  }
  if (!Hp) return HYLCMAT_OK;
  for (int a = 0; a < nf; a++)
    for (int b = 0; b < nf; b++) {
      double v = 0;
      for (int k = 0; k < 6; k++)
        for (int l = 0; l < 6; l++) v += J[k * (1 + nf) + 1 + a] * H[6 * k + l] * J[l * (1 + nf) + 1 + b];
      Hp[nf * a + b] = v;
    }
  if (path->kind == HYLCMAT_PATH_UNIAXIAL && AxisOf(path->angle) < 0) { /* sum_k g_k d2 z_k / dp_a dp_b */
    const double h = 1e-5;
    for (int a = 0; a < nf; a++) {
      double qp[3] = {p[0], p[1], p[2]}, qm[3] = {p[0], p[1], p[2]}, Jp[24], Jm[24], zz[6];
      qp[a] += h, qm[a] -= h;
      if (hylcmat_path_strain(path, s, qp, zz, Jp) || hylcmat_path_strain(path, s, qm, zz, Jm)) return HYLCMAT_ERR_ARG;
      for (int b = 0; b < nf; b++)
        for (int k = 0; k < 6; k++) Hp[nf * a + b] += g[k] * (Jp[k * (1 + nf) + 1 + b] - Jm[k * (1 + nf) + 1 + b]) / (2 * h);
    }
    for (int a = 0; a < nf; a++)
      for (int b = 0; b < a; b++) Hp[nf * a + b] = Hp[nf * b + a] = 0.5 * (Hp[nf * a + b] + Hp[nf * b + a]);
  }
  return HYLCMAT_OK;
}

static int Admissible(const hylcmat_path *path, int nf, double s, const double p[3])
{
  double z[6];
  if (hylcmat_path_strain(path, s, p, z, NULL)) return 0;
  (void)nf;
  return fabs(z[1]) < 0.99 && z[0] > -0.99 && z[2] > -0.99;
}

int hylcmat_path_state(const hylcmat *m, const hylcmat_path *path, double s, const double guess[], hylcmat_path_result *st, char *err, size_t errlen)
{
  hm_err       E    = {err, errlen};
  const int    nf   = hylcmat_path_nfree(path);
  double       p[3] = {0, 0, 0}, psi, gp[3], H[9], f, gz[6], d[3] = {0, 0, 0};
  const double xtol = 1e-11, maxStep = 0.1;
  const int    maxIt = 200, maxRestarts = 20;
  int          r, it = 0, converged = 0, nblind = 0;
  const char  *name = path ? hylcmat_path_name(path->kind) : NULL;

  if (err && errlen) err[0] = 0;
  HM_CHECK(m && st && path, &E, HYLCMAT_ERR_ARG, "hylcmat_path_state: NULL table, path or result");
  memset(st, 0, sizeof(*st));
  HM_CHECK(nf > 0, &E, HYLCMAT_ERR_ARG, "load path kind %d: must be 0 (uniaxial), 1 (equibiaxial), 2 (shear) or 3 (bending)", path->kind);
  HM_CHECK(isfinite(s) && isfinite(path->angle), &E, HYLCMAT_ERR_ARG, "%s path: the strain %g and the angle %g must be finite", name, s, path->angle);
  HM_CHECK(path->kind != HYLCMAT_PATH_BENDING || path->angle == 0 || path->angle == 90, &E, HYLCMAT_ERR_ARG, "bending path: the axis angle %g must be 0 (II00) or 90 (II11)", path->angle);
  HM_CHECK(path->kind != HYLCMAT_PATH_UNIAXIAL || (path->angle >= 0 && path->angle <= 90), &E, HYLCMAT_ERR_ARG, "uniaxial path: the angle %g must be in [0, 90] degrees from the material x axis", path->angle);
  HM_CHECK((path->kind != HYLCMAT_PATH_UNIAXIAL && path->kind != HYLCMAT_PATH_EQUIBIAXIAL) || (s >= 0 && s < 1), &E, HYLCMAT_ERR_ARG, "%s path: the stretch %g is outside [0, 1) (a tension test: a compressed strip buckles)", name, s);
  HM_CHECK(path->kind != HYLCMAT_PATH_SHEAR || fabs(s) < 0.99, &E, HYLCMAT_ERR_ARG, "shear path: sa = %g must be in (-0.99, 0.99)", s);
  if (guess)
    for (int a = 0; a < nf; a++) {
      HM_CHECK(isfinite(guess[a]), &E, HYLCMAT_ERR_ARG, "%s path: the starting free strain %d is %g", name, a, guess[a]);
      p[a] = guess[a];
    }
  HM_CHECK(Admissible(path, nf, s, p), &E, HYLCMAT_ERR_ARG, "%s path at %g: the starting free strains give an invalid strain", name, s);
  if (!guess) { /* the lowest point of a grid of the free strains (a table can have several minima) */
    const int    K      = nf == 1 ? 50 : nf == 2 ? 25 : 8;
    const double h      = nf == 3 ? 0.05 : 0.02;
    double       best   = INFINITY;
    int          idx[3] = {-K, nf > 1 ? -K : 0, nf > 2 ? -K : 0};
    for (;;) {
      const double q[3] = {h * idx[0], h * idx[1], h * idx[2]};
      double       qpsi, qg[3], qf;
      if (Admissible(path, nf, s, q)) {
        r = Eval(m, path, nf, s, q, &qpsi, qg, NULL, &qf, NULL);
        if (r) return hm_fail(&E, r, "%s path at %g: the evaluation failed at the free strains (%g, %g, %g) (%s)", name, s, q[0], q[1], q[2], hylcmat_strerror(r));
        if (qpsi < best) best = qpsi, memcpy(p, q, sizeof(q));
      }
      int a = 0;
      while (a < nf && ++idx[a] > K) idx[a++] = -K;
      if (a == nf) break;
    }
  }
  r = Eval(m, path, nf, s, p, &psi, gp, H, &f, gz);
  if (r) return hm_fail(&E, r, "%s path at %g: the evaluation failed (%s)", name, s, hylcmat_strerror(r));
  for (int restart = 0;; restart++) {
    converged = 0;
    for (; it < maxIt; it++) {
      double nd = 0, slope = 0;
      HylcNewtonStepN(nf, H, gp, 1e-6, d);
      for (int a = 0; a < nf; a++) nd = fmax(nd, fabs(d[a])), slope += gp[a] * d[a];
      if (nd <= xtol) {
        converged = 1;
        break;
      }
      if (nd > maxStep)
        for (int a = 0; a < nf; a++) d[a] *= maxStep / nd;
      /* backtracking on Psi (Armijo 1e-4); a decrease below Psi's rounding cannot be seen: then the full
         Newton step (at most 20 in a row) */
      int blind    = -slope <= 1e-13 * fabs(psi);
      int accepted = 0;
      if (blind && ++nblind > 20) {
        converged = nd <= 1e-8;
        break;
      }
      if (!blind) nblind = 0;
      /* the Newton direction first; where its line search finds no decrease (a table's Hessian is only piecewise
         continuous and can be indefinite), the steepest descent (a stockinette's uniaxial y path at 7 % stopped
         without it, between two lateral states that its tile snaps across) */
      for (int dir = 0; dir < 2 && !accepted; dir++) {
        if (dir == 1) {
          double ng = 0;
          for (int a = 0; a < nf; a++) ng = fmax(ng, fabs(gp[a]));
          if (!(ng > 0) || blind) break;
          slope = 0;
          for (int a = 0; a < nf; a++) d[a] = -gp[a] * fmin(1, maxStep / ng), slope += gp[a] * d[a];
        }
        for (double t = 1; t > 1e-10 && !accepted; t *= 0.5) {
          double q[3] = {p[0], p[1], p[2]}, qpsi, qg[3], qH[9], qf, qz[6];
          int    same = 1;
          for (int a = 0; a < nf; a++) q[a] += t * d[a], same = same && q[a] == p[a];
          if (same || !Admissible(path, nf, s, q)) continue;
          r = Eval(m, path, nf, s, q, &qpsi, qg, qH, &qf, qz);
          if (r) return hm_fail(&E, r, "%s path at %g: the evaluation failed at the free strains (%g, %g, %g) (%s)", name, s, q[0], q[1], q[2], hylcmat_strerror(r));
          if (blind || qpsi <= psi + 1e-4 * t * fmin(slope, 0)) {
            accepted = 1;
            memcpy(p, q, sizeof(q));
            psi = qpsi, f = qf;
            memcpy(gp, qg, sizeof(qg));
            memcpy(H, qH, sizeof(qH));
            memcpy(gz, qz, sizeof(qz));
          }
        }
      }
      if (!accepted) { /* no decrease along a descent direction: Psi's rounding; a minimum if the step is tiny */
        converged = nd <= 1e-9;
        break;
      }
    }
    if (!converged || restart == maxRestarts) break;
    /* Newton stops at any stationary point, and a table's Hessian jumps at its knots: probes at distance
       1e-3 along +-each free strain and the diagonals of each pair; a lower one restarts Newton */
    double best = psi, bq[3] = {p[0], p[1], p[2]};
    for (int a = 0; a < nf; a++)
      for (int b = a; b < nf; b++)
        for (int k = 0; k < (a == b ? 2 : 4); k++) {
          double q[3] = {p[0], p[1], p[2]}, qpsi, qg[3], qf;
          q[a] += (k & 1 ? -1e-3 : 1e-3);
          if (b != a) q[b] += (k & 2 ? -1e-3 : 1e-3);
          if (!Admissible(path, nf, s, q)) continue;
          r = Eval(m, path, nf, s, q, &qpsi, qg, NULL, &qf, NULL);
          if (r) return hm_fail(&E, r, "%s path at %g: the evaluation failed at the free strains (%g, %g, %g) (%s)", name, s, q[0], q[1], q[2], hylcmat_strerror(r));
          if (qpsi < best - 1e-14 * fabs(psi)) best = qpsi, memcpy(bq, q, sizeof(q));
        }
    if (best == psi) break;
    memcpy(p, bq, sizeof(bq));
    r = Eval(m, path, nf, s, p, &psi, gp, H, &f, gz);
    if (r) return hm_fail(&E, r, "%s path at %g: the evaluation failed (%s)", name, s, hylcmat_strerror(r));
  }
  st->s     = s;
  st->force = f;
  st->psi   = psi;
  for (int a = 0; a < 3; a++) st->p[a] = a < nf ? p[a] : 0, st->gfree[a] = a < nf ? gp[a] : 0;
  (void)hylcmat_path_strain(path, s, p, st->z, NULL);
  memcpy(st->grad, gz, sizeof(gz));
  st->step = 0;
  for (int a = 0; a < nf; a++) st->step = fmax(st->step, fabs(d[a]));
  st->iterations = it;
  HM_CHECK(converged, &E, HYLCMAT_ERR_NOCONV, "%s path at %g: the minimization over the free strains did not converge (%d iterations, last step %g at (%g, %g, %g))", name, s, it, st->step, p[0], p[1], p[2]);
  return HYLCMAT_OK;
}
