/* hylcmat: a table written as measured cloth (include/hylcmat.h, docs/measured-cloth.md, "Export"): the
   least-squares data of the measured-cloth model for the table's stretching and bending response.
   Plain C99. */
#include "hylcmatimpl.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NS 24 /* stretching unknowns: 6 rows x 4 */

/* the table's dPsi/dG = (dPsi/dG00, dPsi/dG11, dPsi/dG01) at the in-plane Green strain G (bending 0) */
static int TableDeriv(const hylcmat *m, const double G[3], double D[3])
{
  const double C00 = 1 + 2 * G[0], C11 = 1 + 2 * G[1], C01 = 2 * G[2];
  if (!(C00 > 0 && C11 > 0)) return HYLCMAT_ERR_DEGENERATE;
  const double r0 = sqrt(C00), r1 = sqrt(C11), sa = C01 / (r0 * r1);
  if (!(fabs(sa) < 1)) return HYLCMAT_ERR_DEGENERATE;
  double z[6] = {r0 - 1, sa, r1 - 1, 0, 0, 0}, psi, g[6];
  HM_CALL(hylcmat_eval(m, z, &psi, g, NULL));
  D[0] = 2 * (g[0] / (2 * r0) - 0.5 * g[1] * sa / C00);
  D[1] = 2 * (g[2] / (2 * r1) - 0.5 * g[1] * sa / C11);
  D[2] = 2 * g[1] / (r0 * r1);
  return HYLCMAT_OK;
}

/* the Green strain of the table's strain (sx, sa, sy) */
static void GreenOfStrain(const double z[3], double G[3])
{
  G[0] = 0.5 * ((1 + z[0]) * (1 + z[0]) - 1);
  G[1] = 0.5 * ((1 + z[2]) * (1 + z[2]) - 1);
  G[2] = 0.5 * z[1] * (1 + z[0]) * (1 + z[2]);
}

/* solves the symmetric n x n system A x = b (A overwritten) by elimination with partial pivoting */
static int Solve(int n, double *A, double *b, double *x)
{
  for (int c = 0; c < n; c++) {
    int p = c;
    for (int r = c + 1; r < n; r++)
      if (fabs(A[r * n + c]) > fabs(A[p * n + c])) p = r;
    if (!(fabs(A[p * n + c]) > 0)) return HYLCMAT_ERR_NOCONV;
    if (p != c) {
      for (int j = 0; j < n; j++) {
        const double t = A[c * n + j];
        A[c * n + j]   = A[p * n + j];
        A[p * n + j]   = t;
      }
      const double t = b[c];
      b[c]           = b[p];
      b[p]           = t;
    }
    for (int r = c + 1; r < n; r++) {
      const double f = A[r * n + c] / A[c * n + c];
      for (int j = c; j < n; j++) A[r * n + j] -= f * A[c * n + j];
      b[r] -= f * b[c];
    }
  }
  for (int c = n - 1; c >= 0; c--) {
    double s = b[c];
    for (int j = c + 1; j < n; j++) s -= A[c * n + j] * x[j];
    x[c] = s / A[c * n + c];
  }
  return HYLCMAT_OK;
}

/* the table's bending moment along a curvature path: dir 0 II00 = kappa, 1 II11 = kappa, 2 the mean of the
   two 45 degree diagonals (II = kappa n n^T, n = (1, -+1)/sqrt 2); in-plane strains 0 */
static int TableMoment(const hylcmat *m, int dir, double kappa, double *M)
{
  double psi, g[6];
  if (dir < 2) {
    double z[6] = {0, 0, 0, dir ? 0 : kappa, 0, dir ? kappa : 0};
    HM_CALL(hylcmat_eval(m, z, &psi, g, NULL));
    *M = dir ? g[5] : g[3];
    return HYLCMAT_OK;
  }
  *M = 0;
  for (int sgn = -1; sgn <= 1; sgn += 2) {
    double z[6] = {0, 0, 0, kappa / 2, sgn * kappa / 2, kappa / 2};
    HM_CALL(hylcmat_eval(m, z, &psi, g, NULL));
    *M += 0.5 * (0.5 * g[3] + 0.5 * g[5] + 0.5 * sgn * g[4]);
  }
  return HYLCMAT_OK;
}

/* a strain sample of the stretching fit */
typedef struct {
  double G[3], D[3];
} FitSample;

/* the strip targets of the refinement: the table's strip states along the five sample directions */
#define NPHI 5
#define NLEV 12 /* s = 0.01 .. 0.12 */
typedef struct {
  double phi, s, T, lateral;
} Target;

typedef struct {
  const Target *t;
  int           nt;
  double        bend[15];
} Strips;

#define WLAT 0.03 /* the weight of the lateral strain error (per unit stretch) against the relative T error */

/* the residuals (2 per target) of the measured-cloth data p (24): relative T error, WLAT x lateral error / s */
static int Residuals(const Strips *S, const double p[NS], double *res)
{
  hylcmat_measured *mc;
  int               r = hylcmat_measured_create(0, p, S->bend, &mc, NULL, 0);
  if (r) return r;
  for (int i = 0; i < S->nt; i++) {
    hylcmat_measured_state st;
    const Target          *t = &S->t[i];
    if (hylcmat_measured_tension_angle(mc, t->phi, t->s, HYLCMAT_MEASURED_FROZEN, &st, NULL, 0)) {
      res[2 * i] = res[2 * i + 1] = 10; /* no balance: a large error */
      continue;
    }
    res[2 * i]     = (st.T - t->T) / fabs(t->T);
    res[2 * i + 1] = WLAT * (st.lateral - t->lateral) / t->s;
  }
  hylcmat_measured_free(mc);
  return HYLCMAT_OK;
}

static double Cost(int n, const double *r)
{
  double c = 0;
  for (int i = 0; i < n; i++) c += r[i] * r[i];
  return 0.5 * c;
}

/* Levenberg-Marquardt on the unknowns p[idx[0..nv)] (the others fixed): forward-difference Jacobian
   (steps 1e-7 |p|, at least 1e-9), Marquardt's scaling diag(J^T J), at most maxJ Jacobians; p updated */
static int Marquardt(const Strips *S, double p[NS], const int *idx, int nv, int maxJ, double hrel, double *costOut)
{
  const int nr = 2 * S->nt;
  double   *r = malloc(sizeof(double) * (size_t)nr * (2 + NS)), *rt = r + nr, *J = rt + nr;
  double    mu = 1e-3, cost;
  int       rc;

  if (!r) return HYLCMAT_ERR_MEMORY;
  if ((rc = Residuals(S, p, r))) goto done;
  cost = Cost(nr, r);
  for (int it = 0; it < maxJ; it++) {
    double A[NS * NS], g[NS], D[NS], dmax = 0;
    for (int a = 0; a < nv; a++) {
      double       q[NS];
      const double h = fmax(hrel * fabs(p[idx[a]]), 1e-9);
      memcpy(q, p, sizeof(q));
      q[idx[a]] += h;
      if ((rc = Residuals(S, q, rt))) goto done;
      for (int i = 0; i < nr; i++) J[(size_t)i * NS + a] = (rt[i] - r[i]) / h;
    }
    for (int a = 0; a < nv; a++) {
      g[a] = 0;
      for (int i = 0; i < nr; i++) g[a] += J[(size_t)i * NS + a] * r[i];
      for (int b = 0; b < nv; b++) {
        double v = 0;
        for (int i = 0; i < nr; i++) v += J[(size_t)i * NS + a] * J[(size_t)i * NS + b];
        A[a * nv + b] = v;
      }
      D[a] = A[a * nv + a];
      dmax = fmax(dmax, D[a]);
    }
    if (!(dmax > 0)) break;
    int accepted = 0;
    while (!accepted && mu < 1e10) {
      double M[NS * NS], b[NS], d[NS], q[NS];
      memcpy(M, A, sizeof(double) * (size_t)(nv * nv));
      for (int a = 0; a < nv; a++) {
        M[a * nv + a] += mu * fmax(D[a], 1e-12 * dmax);
        b[a] = -g[a];
      }
      if (Solve(nv, M, b, d)) {
        mu *= 4;
        continue;
      }
      memcpy(q, p, sizeof(q));
      for (int a = 0; a < nv; a++) q[idx[a]] += d[a];
      if ((rc = Residuals(S, q, rt))) goto done;
      const double c = Cost(nr, rt);
      if (c < cost) {
        accepted         = 1;
        const double rel = (cost - c) / cost;
        memcpy(p, q, sizeof(q));
        memcpy(r, rt, sizeof(double) * (size_t)nr);
        cost = c;
        mu   = fmax(mu / 3, 1e-9);
        if (rel < 1e-8) it = maxJ; /* converged */
      } else
        mu *= 4;
    }
    if (!accepted) break;
  }
  rc = HYLCMAT_OK;
  if (costOut) *costOut = cost;
done:
  free(r);
  return rc;
}

int hylcmat_measured_fit(const hylcmat *m, hylcmat_measured **mc, double fit[5], char *err, size_t errlen)
{
  hm_err            E        = {err, errlen};
  hylcmat_measured *basis[6] = {NULL};
  FitSample        *smp      = NULL;
  double            A[NS * NS], b[NS], x[NS], st[24], be[15];
  int               ns = 0, cap = 0, r = HYLCMAT_OK;
  const int         nlev    = 17; /* s = 0.01 .. 0.16 and 1/6 */
  const double      phis[8] = {0, 22.5, 45, 67.5, 90, -22.5, -45, -67.5};

  if (err && errlen) err[0] = 0;
  HM_CHECK(m && mc, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_fit: NULL table or result");
  *mc = NULL;
  if (fit)
    for (int i = 0; i < 5; i++) fit[i] = 0;
  /* the samples: the table's strip states at the format's directions (both signs of the shear), and
     biaxial states of the same principal directions */
  cap = 8 * nlev * 3;
  smp = malloc(sizeof(*smp) * (size_t)cap);
  HM_CHECK(smp, &E, HYLCMAT_ERR_MEMORY, "hylcmat_measured_fit: out of memory");
  for (int a = 0; a < 8; a++) {
    const double phi = phis[a] * 3.14159265358979323846 / 180, c = cos(phi), sn = sin(phi);
    double       guess[2], *gp = NULL;
    for (int l = 0; l < nlev; l++) {
      const double          s = l < nlev - 1 ? 0.01 * (l + 1) : 1.0 / 6;
      hylcmat_tension_state ts;
      if (!hylcmat_tension(m, phi, s, gp, &ts, NULL, 0)) {
        GreenOfStrain(ts.strain, smp[ns].G);
        if (!TableDeriv(m, smp[ns].G, smp[ns].D)) ns++;
        guess[0] = 1 + ts.lateral, guess[1] = ts.shear, gp = guess;
      }
      for (int bi = 0; bi < 2; bi++) { /* principal stretches (1 + s, 1 + s/2) and (1 + s, 1) along phi */
        const double g1 = 0.5 * ((1 + s) * (1 + s) - 1), w2 = bi ? 1 : 1 + s / 2, g2 = 0.5 * (w2 * w2 - 1);
        double      *G = smp[ns].G;
        G[0]           = g1 * c * c + g2 * sn * sn;
        G[1]           = g1 * sn * sn + g2 * c * c;
        G[2]           = (g1 - g2) * c * sn;
        if (!TableDeriv(m, G, smp[ns].D)) ns++;
      }
    }
  }
  if (ns < 24) {
    free(smp);
    return hm_fail(&E, HYLCMAT_ERR_NOCONV, "measured-cloth export: only %d strain states of the table could be evaluated", ns);
  }
  /* the basis: k(G) = 2 sum_rows B_row(G) r_row, B_row from a material with that row all ones */
  for (int row = 0; row < 6 && !r; row++) {
    double one[24] = {0}, zb[15] = {0};
    for (int q = 0; q < 4; q++) one[4 * row + q] = 1;
    r = hylcmat_measured_create(0, one, zb, &basis[row], err, errlen);
  }
  if (!r) {
    memset(A, 0, sizeof(A));
    memset(b, 0, sizeof(b));
    for (int i = 0; i < ns; i++) {
      const double *G = smp[i].G, *D = smp[i].D;
      const double  w = 1 / fmax(sqrt(G[0] * G[0] + G[1] * G[1] + 2 * G[2] * G[2]), 1e-12);
      double        Bw[6], J[3][NS];
      for (int row = 0; row < 6; row++) {
        double k[4];
        hylcmat_measured_stiffness(basis[row], G, k, NULL);
        Bw[row] = k[0]; /* 2 B_row */
      }
      memset(J, 0, sizeof(J));
      for (int row = 0; row < 6; row++) { /* D00 = k0 G00 + k1 G11, D11 = k1 G00 + k2 G11, D01 = k3 G01 */
        J[0][4 * row + 0] = w * Bw[row] * G[0];
        J[0][4 * row + 1] = w * Bw[row] * G[1];
        J[1][4 * row + 1] = w * Bw[row] * G[0];
        J[1][4 * row + 2] = w * Bw[row] * G[1];
        J[2][4 * row + 3] = w * Bw[row] * G[2];
      }
      for (int e = 0; e < 3; e++)
        for (int p = 0; p < NS; p++) {
          if (J[e][p] == 0) continue;
          b[p] += J[e][p] * w * D[e];
          for (int q = 0; q < NS; q++) A[p * NS + q] += J[e][p] * J[e][q];
        }
    }
    double tr = 0;
    for (int p = 0; p < NS; p++) tr += A[p * NS + p];
    for (int p = 0; p < NS; p++) A[p * NS + p] += 1e-10 * tr / NS; /* unknowns no sample sees stay near 0 */
    r = Solve(NS, A, b, x);
    if (r) hm_fail(&E, r, "measured-cloth export: the least-squares system of the stretching data is singular");
  }
  for (int row = 0; row < 6; row++) hylcmat_measured_free(basis[row]);
  if (r) {
    free(smp);
    return r;
  }
  memcpy(st, x, sizeof(st));
  /* the refinement: the model's own strip states against the table's along the five sample directions */
  {
    Target    tg[NPHI * NLEV];
    Strips    S;
    int       nt   = 0, all[NS];
    const int maxJ = 60;
    for (int a = 0; a < NPHI; a++) {
      const double phi = a * 0.39269908169872414; /* 22.5 degrees */
      double       guess[2], *gp = NULL;
      for (int l = 1; l <= 2 * NLEV; l++) { /* the load path in steps of 0.005, the targets every 0.01 */
        hylcmat_tension_state ts;
        if (hylcmat_tension(m, phi, 0.005 * l, gp, &ts, NULL, 0)) continue;
        guess[0] = 1 + ts.lateral, guess[1] = ts.shear, gp = guess;
        if (l % 2 == 0 && fabs(ts.T) > 0) tg[nt].phi = phi, tg[nt].s = ts.s, tg[nt].T = ts.T, tg[nt].lateral = ts.lateral, nt++;
      }
    }
    S.t  = tg;
    S.nt = nt;
    memset(S.bend, 0, sizeof(S.bend));
    for (int a = 0; a < NS; a++) all[a] = a;
    /* the residuals have kinks (the clips, the lookup cells, jumps of the balance): the difference step
       smooths them; three steps, the lowest cost kept */
    double best = INFINITY, pbest[NS], start[NS];
    memcpy(start, st, sizeof(start));
    for (int k = 0; k < 3 && nt && !r; k++) {
      const double hrel = k == 0 ? 1e-5 : k == 1 ? 3e-5 : 1e-4;
      double       p[NS], cost = INFINITY;
      memcpy(p, start, sizeof(p));
      r = Marquardt(&S, p, all, NS, maxJ, hrel, &cost);
      for (int sweep = 0; sweep < 2 && !r; sweep++)
        for (int row = 0; row < 6 && !r; row++) {
          const int idx[4] = {4 * row, 4 * row + 1, 4 * row + 2, 4 * row + 3};
          r                = Marquardt(&S, p, idx, 4, maxJ / 2, hrel, &cost);
        }
      if (!r && cost < best) best = cost, memcpy(pbest, p, sizeof(p));
    }
    if (!r && nt) memcpy(st, pbest, sizeof(pbest));
    if (r) {
      free(smp);
      return hm_fail(&E, r, "measured-cloth export: the refinement of the stretching data failed (%s)", hylcmat_strerror(r));
    }
    if (fit && nt) {
      double *res = malloc(sizeof(double) * 2 * (size_t)nt), e2 = 0, worst = 0;
      if (res && !Residuals(&S, st, res)) {
        for (int i = 0; i < nt; i++) {
          e2 += res[2 * i] * res[2 * i];
          if (tg[i].s > 0.0199 && tg[i].s < 0.1001) worst = fmax(worst, fabs(res[2 * i]));
        }
        fit[0] = sqrt(e2 / nt);
        fit[1] = worst;
      }
      free(res);
    }
  }
  /* bending: per row, k(kappa) piecewise linear in b[0..4] at kappa = 0, 10, .., 40 fitted to the secant
     stiffness 4 M(kappa) / kappa of the odd part of the table's moment, kappa = 1, 2, .., 40 1/m */
  const int rowdir[3] = {1, 2, 0}; /* b0: edges along u, bent by II11; b1: 45 degrees; b2: along v, II00 */
  for (int row = 0; row < 3 && !r; row++) {
    double Ab[25] = {0}, bb[5] = {0}, xb[5];
    for (int i = 1; i <= 40 && !r; i++) {
      const double kappa = i;
      double       Mp, Mm;
      r = TableMoment(m, rowdir[row], kappa, &Mp);
      if (!r) r = TableMoment(m, rowdir[row], -kappa, &Mm);
      if (r) break;
      const double target = 4 * 0.5 * (Mp - Mm) / kappa, v = 0.1 * kappa;
      int          vi = (int)v;
      if (vi > 3) vi = 3;
      const double wv    = v - vi;
      double       Jb[5] = {0};
      Jb[vi]             = 1 - wv;
      Jb[vi + 1]         = wv;
      for (int p = 0; p < 5; p++) {
        bb[p] += Jb[p] * target;
        for (int q = 0; q < 5; q++) Ab[p * 5 + q] += Jb[p] * Jb[q];
      }
    }
    if (r) break;
    r = Solve(5, Ab, bb, xb);
    for (int p = 0; p < 5; p++) be[5 * row + p] = xb[p];
  }
  if (r) {
    free(smp);
    return hm_fail(&E, r, "measured-cloth export: the table's bending moment could not be evaluated (%s)", hylcmat_strerror(r));
  }
  r = hylcmat_measured_create(hylcmat_density(m), st, be, mc, err, errlen);
  if (r) {
    free(smp);
    return r;
  }
  if (fit) { /* the bending error of the material as evaluated (the clips included), the lost prestress and curl */
    double b2 = 0, psi, g[6];
    int    nb = 0;
    for (int row = 0; row < 3; row++)
      for (int i = 1; i <= 40; i++) {
        double Mp, Mm;
        if (TableMoment(m, rowdir[row], i, &Mp) || TableMoment(m, rowdir[row], -i, &Mm)) continue;
        const double du[2] = {row == 2 ? 0 : 1, row == 0 ? 0 : 1};
        const double Mmc = hylcmat_measured_bending_sample(*mc, i, du, NULL) * i / 4, t = 0.5 * (Mp - Mm);
        b2 += (Mmc - t) * (Mmc - t) / fmax(t * t, 1e-300);
        nb++;
      }
    fit[2]             = nb ? sqrt(b2 / nb) : 0;
    const double z0[6] = {0, 0, 0, 0, 0, 0};
    if (!hylcmat_eval(m, z0, &psi, g, NULL)) {
      fit[3] = fmax(fabs(g[0]), fmax(fabs(g[1]), fabs(g[2])));
      fit[4] = fmax(fabs(g[3]), fmax(fabs(g[4]), fabs(g[5])));
    }
  }
  free(smp);
  return HYLCMAT_OK;
}
