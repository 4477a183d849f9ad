/* The macroscale shell element of Algorithm C8 (include/hylcmat.h: hylcmat_shell_*, hylcmat_mesh_*):
   1. gradient and Hessian against central differences (1e-6 and 1e-5 relative to the largest entry)
      on random stencils of every paper table ($HYLC_REFDATA/materials; a note when absent) and of two
      tables fitted here by HylcFit (the woven and stockinette settings, synthetic samples of
      tests/unit/fittest.h): interior and boundary triangles (every neighbour mask), large rotations
      and translations, strong folds (dihedral angles up to 2.5 rad, bending beyond the tables), equal
      curvature eigenvalues (a symmetric stencil on a sphere: II = kappa I); stencils whose
      differences would cross a spline knot are skipped (counted, at most 10 %);
   2. exactly flat stencils (II = 0, a knot of every table: Psi is only C1 there): the gradient against
      differences; the Hessian bounded, against central differences along the plane and against
      one-sided differences into II > 0 (the right pieces the evaluator returns); and against central
      differences in every direction for a table that is smooth at II = 0;
   3. the projection against LAPACK (eigenvalues below 1e-8 raised to 1e-8, vertices present);
   4. rigid motions: energy, gradient and Hessian invariant (covariant) to roundoff;
   5. conventions: stretch and shear strains, II > 0 toward n, a single hinge's II in closed form;
   6. meshes: a flat undeformed mesh has E = Psi(0) x area (= C0 x area for a fitted table); the mesh
      gradient and Hessian are the assembled elements; a finely meshed cylinder of radius rho gives
      |II| -> 1/rho across its axis and 0 along it, with the sign of the face, at second order;
   7. bad input: the error codes and messages, and no NaN in any output.
   Options: -v prints the measured figures. */
#include <hylc/fit.h>
#include <hylc/material.h>
#include <hylc/private/materialimpl.h>
#include <hylcmat.h>
#include <petscblaslapack.h>
#include <stdlib.h>
#include <string.h>
#include "hylctest.h"
#include "fittest.h"

static PetscBool Verbose = PETSC_FALSE;

static double Uni(unsigned long long *st) /* uniform in [-1, 1) */ { return 2 * HylcTestRand(st) - 1; }

/* a uniformly random rotation (from a random unit quaternion) */
static void RandomRotation(unsigned long long *st, double Q[9])
{
  double q[4], n = 0;
  do {
    n = 0;
    for (int i = 0; i < 4; i++) {
      q[i] = Uni(st);
      n += q[i] * q[i];
    }
  } while (n > 1 || n < 1e-3);
  n = sqrt(n);
  for (int i = 0; i < 4; i++) q[i] /= n;
  {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double R[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), 2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
    memcpy(Q, R, sizeof(R));
  }
}

static void Rigid(const double Q[9], const double t[3], int nv, const double *x, double *y)
{
  for (int v = 0; v < nv; v++)
    for (int i = 0; i < 3; i++) y[3 * v + i] = Q[3 * i] * x[3 * v] + Q[3 * i + 1] * x[3 * v + 1] + Q[3 * i + 2] * x[3 * v + 2] + t[i];
}

typedef struct {
  hylcmat_shell_rest r;
  double             uv[12]; /* material coordinates of the 6 vertices */
  double             x[18];
  int                nb;
  double             L; /* the size of the triangle (m) */
} Stencil;

enum { K_GENERIC, K_BOUNDARY, K_FOLD, K_UMBILIC, K_FLAT, K_NKIND };
static const char *KindName[K_NKIND] = {"interior", "boundary", "strong fold", "equal eigenvalues", "flat"};

/* a random stencil of the kind; kappa: a typical curvature of the table (1/m); Qt: a rigid motion
   with translations up to tmax */
static void MakeStencil(int kind, double kappa, double tmax, unsigned long long *st, Stencil *s)
{
  double L = 0.003 * pow(10, 0.8 * HylcTestRand(st)), Q[9], t[3], beta = M_PI * Uni(st), cb = cos(beta), sb = sin(beta), o[2] = {Uni(st), Uni(st)};
  double u[6][2], y[18], c[2];

  u[0][0] = 0, u[0][1] = 0;
  u[1][0] = L * (1 + 0.3 * Uni(st)), u[1][1] = 0.3 * L * Uni(st);
  u[2][0] = L * (0.3 + 0.3 * Uni(st)), u[2][1] = L * (1 + 0.3 * Uni(st));
  for (int k = 0; k < 3; k++) {
    const int a = k, b = (k + 1) % 3, cc = (k + 2) % 3;
    for (int i = 0; i < 2; i++) u[3 + k][i] = u[a][i] + u[b][i] - u[cc][i] + 0.3 * L * Uni(st);
  }
  c[0] = (u[0][0] + u[1][0] + u[2][0]) / 3;
  c[1] = (u[0][1] + u[1][1] + u[2][1]) / 3;
  /* material coordinates: rotated by beta and shifted (arbitrary origin and axes) */
  for (int v = 0; v < 6; v++) {
    const double p = u[v][0] - c[0], q = u[v][1] - c[1];
    s->uv[2 * v]     = cb * p - sb * q + o[0];
    s->uv[2 * v + 1] = sb * p + cb * q + o[1];
  }
  hylcmat_shell_rest_uv(s->uv, &s->r);
  s->L  = L;
  s->nb = 7;
  if (kind == K_BOUNDARY) s->nb = (int)(7 * HylcTestRand(st)); /* 0..6 */
  {
    /* in-plane F (stretch -0.15 .. 0.4, shear), a quadratic bend and vertex noise */
    const double F[4] = {1 + 0.15 + 0.25 * Uni(st), 0.2 * Uni(st), 0.2 * Uni(st), 1 + 0.15 + 0.25 * Uni(st)};
    double       K[3] = {kappa * Uni(st), kappa * Uni(st), kappa * Uni(st)}, sc = 1;
    const double kmax = fabs(K[0]) + fabs(K[1]) + fabs(K[2]);
    if (kmax * 2.5 * L > 0.4) sc = 0.4 / (kmax * 2.5 * L);
    for (int v = 0; v < 6; v++) {
      const double p = s->uv[2 * v] - o[0], q = s->uv[2 * v + 1] - o[1];
      y[3 * v]     = F[0] * p + F[1] * q;
      y[3 * v + 1] = F[2] * p + F[3] * q;
      y[3 * v + 2] = kind == K_FLAT || kind == K_UMBILIC ? 0 : sc * 0.5 * (K[0] * p * p + 2 * K[1] * p * q + K[2] * q * q) + 0.02 * L * Uni(st);
      if (kind == K_FOLD && v >= 3) y[3 * v + 2] += 1.5 * L * Uni(st); /* dihedral angles up to ~2.5 rad */
    }
  }
  if (kind == K_UMBILIC) {
    /* II = k I: the w_k solving sum_k w_k t_k t_k^T = k I, theta_k = -w_k / height_k, each flat
       neighbour turned about its edge by theta_k */
    const double *D = s->r.dinv, t[3][2] = {{D[2], D[3]}, {-(D[0] + D[2]), -(D[1] + D[3])}, {D[0], D[1]}};
    double        M[3][3], w[3], k = kappa * (0.05 + 0.75 * HylcTestRand(st)) * (Uni(st) > 0 ? 1 : -1), det, th[3], big = 0;
    for (int j = 0; j < 3; j++) M[0][j] = t[j][0] * t[j][0], M[1][j] = t[j][0] * t[j][1], M[2][j] = t[j][1] * t[j][1];
    det = M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) + M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0]);
    for (int j = 0; j < 3; j++) { /* Cramer with the right-hand side (k, 0, k) */
      double Mj[3][3];
      memcpy(Mj, M, sizeof(M));
      Mj[0][j] = k, Mj[1][j] = 0, Mj[2][j] = k;
      w[j] = (Mj[0][0] * (Mj[1][1] * Mj[2][2] - Mj[1][2] * Mj[2][1]) - Mj[0][1] * (Mj[1][0] * Mj[2][2] - Mj[1][2] * Mj[2][0]) + Mj[0][2] * (Mj[1][0] * Mj[2][1] - Mj[1][1] * Mj[2][0])) / det;
    }
    for (int j = 0; j < 3; j++) {
      const double *xa = y + 3 * j, *xb = y + 3 * ((j + 1) % 3), *xc = y + 3 * ((j + 2) % 3);
      double        e[3], f[3], le, fe = 0, kap = 0;
      for (int i = 0; i < 3; i++) e[i] = xb[i] - xa[i], f[i] = xc[i] - xa[i];
      le = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      for (int i = 0; i < 3; i++) fe += f[i] * e[i] / le;
      for (int i = 0; i < 3; i++) kap += (f[i] - fe * e[i] / le) * (f[i] - fe * e[i] / le);
      th[j] = -w[j] / sqrt(kap);
      big   = fmax(big, fabs(th[j]));
    }
    for (int j = 0; j < 3; j++) {
      const double *xa = y + 3 * j, *xb = y + 3 * ((j + 1) % 3), a = big > 1.5 ? th[j] * 1.5 / big : th[j], c = cos(a), sn = sin(a);
      double        e[3], v[3], le, ev, exv[3];
      for (int i = 0; i < 3; i++) e[i] = xb[i] - xa[i], v[i] = y[9 + 3 * j + i] - xa[i];
      le = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
      for (int i = 0; i < 3; i++) e[i] /= le;
      ev     = e[0] * v[0] + e[1] * v[1] + e[2] * v[2];
      exv[0] = e[1] * v[2] - e[2] * v[1], exv[1] = e[2] * v[0] - e[0] * v[2], exv[2] = e[0] * v[1] - e[1] * v[0];
      for (int i = 0; i < 3; i++) y[9 + 3 * j + i] = xa[i] + v[i] * c + exv[i] * sn + e[i] * ev * (1 - c);
    }
  }
  RandomRotation(st, Q);
  for (int i = 0; i < 3; i++) t[i] = tmax * Uni(st);
  if (kind == K_FLAT && HylcTestRand(st) < 0.5) { /* exactly in the plane z = 0: II = 0 exactly */
    const double a = M_PI * Uni(st), R[9] = {cos(a), -sin(a), 0, sin(a), cos(a), 0, 0, 0, 1};
    memcpy(Q, R, sizeof(R));
    t[2] = 0;
  }
  Rigid(Q, t, 6, y, s->x);
}

/* ---- knots: differences are valid only if no table argument crosses a knot ---------------------- */
static int Loc(int n, const double *t, double x)
{
  int i = -1;
  while (i + 1 < n && x >= t[i + 1]) i++;
  return i;
}

/* the pieces of every table argument at strains z (sig) and whether a bending argument is 0 to
   roundoff (zero: an eigenvalue of II of rank 1 or 0, which stays 0 under every perturbation when the
   triangle has fewer than two neighbours) */
static int Signature(const hylcmat *m, const double z[6], int sig[64], int zero[64])
{
  double         sc[5], X[3], A = 0.5 * (z[3] + z[5]), B = 0.5 * (z[3] - z[5]), S = sqrt(B * B + z[4] * z[4]), lam[2][2];
  int            n = 0, zf[2][2];
  hylcmat_term1d t1;
  hylcmat_term2d t2;

  hylcmat_strain_scale(m, sc);
  for (int i = 0; i < 3; i++) X[i] = z[i] / sc[i];
  lam[0][0] = (A + S) / sc[3], lam[0][1] = (A - S) / sc[3]; /* x-bending arguments */
  lam[1][0] = (A + S) / sc[4], lam[1][1] = (A - S) / sc[4]; /* y-bending */
  for (int a = 0; a < 2; a++)
    for (int e = 0; e < 2; e++) {
      zf[a][e] = fabs(lam[a][e]) <= 1e-12 * (fabs(lam[a][0]) + fabs(lam[a][1])) || (A == 0 && S == 0);
      if (zf[a][e]) lam[a][e] = 0;
    }
  for (int k = 0; k < 5; k++) {
    if (!hylcmat_term1d_get(m, k, &t1)) continue;
    if (k < 3) {
      zero[n]  = 0;
      sig[n++] = Loc(t1.n, t1.t, X[k]);
    } else
      for (int e = 0; e < 2; e++) {
        zero[n]  = zf[k - 3][e];
        sig[n++] = Loc(t1.n, t1.t, lam[k - 3][e]);
      }
  }
  for (int q = 0; q < HYLCMAT_N2D; q++) {
    int i, j;
    hylcmat_pair(q, &i, &j);
    if (!hylcmat_term2d_get(m, i, j, &t2)) continue;
    zero[n]  = 0;
    sig[n++] = Loc(t2.nu, t2.tu, X[i]);
    if (j < 3) {
      zero[n]  = 0;
      sig[n++] = Loc(t2.nv, t2.tv, X[j]);
    } else
      for (int e = 0; e < 2; e++) {
        zero[n]  = zf[j - 3][e];
        sig[n++] = Loc(t2.nv, t2.tv, lam[j - 3][e]);
      }
  }
  return n;
}

/* do the strains z lie in the same pieces as those of the signature (sig0, zero0)? */
static int SamePieces(const hylcmat *m, const double z[6], int n, const int sig0[64], const int zero0[64])
{
  int sig[64], zero[64];
  Signature(m, z, sig, zero);
  for (int i = 0; i < n; i++)
    if (sig[i] != sig0[i] && !(zero[i] && zero0[i])) return 0;
  return 1;
}

typedef struct {
  double worstg, worstH, worstP;
  int    tested, skipped, onesided;
} Stats;

static double MaxAbs(const double *v, int n)
{
  double s = 0;
  for (int i = 0; i < n; i++) s = fmax(s, fabs(v[i]));
  return s;
}

/* central differences of E (gradient) and of the gradient (Hessian), coordinate steps h; returns 0 if
   the stencil was skipped (a knot inside the differences) */
static int CheckFD(const hylcmat *m, const Stencil *s, double h, const char *what, Stats *stats)
{
  double E, g[18], H[324], z0[6], errg = 0, errH = 0, gs, Hs, fdH[324];
  int    sig0[64], zero0[64], ns, ret;

  ret = hylcmat_shell_eval(m, &s->r, s->x, s->nb, 0, &E, g, H);
  HYLC_CHECK(ret == HYLCMAT_OK, "%s: element error %d", what, ret);
  if (ret) return 0;
  hylcmat_shell_strains(&s->r, s->x, s->nb, z0, NULL);
  ns = Signature(m, z0, sig0, zero0);
  for (int j = 0; j < 18; j++) {
    double xp[18], xm[18], Ep, Em, gp[18], gm[18], zp[6], zm[6];
    if (j >= 9 && !(s->nb >> ((j - 9) / 3) & 1)) {
      /* a missing neighbour: its entries are 0 */
      HYLC_CHECK(g[j] == 0, "%s: gradient %d of a missing neighbour is %g", what, j, g[j]);
      for (int i = 0; i < 18; i++) HYLC_CHECK(H[18 * i + j] == 0 && H[18 * j + i] == 0, "%s: Hessian (%d, %d) of a missing neighbour", what, i, j);
      for (int i = 0; i < 18; i++) fdH[18 * i + j] = 0;
      continue;
    }
    memcpy(xp, s->x, sizeof(xp));
    memcpy(xm, s->x, sizeof(xm));
    xp[j] += h;
    xm[j] -= h;
    hylcmat_shell_strains(&s->r, xp, s->nb, zp, NULL);
    hylcmat_shell_strains(&s->r, xm, s->nb, zm, NULL);
    if (!SamePieces(m, zp, ns, sig0, zero0) || !SamePieces(m, zm, ns, sig0, zero0)) {
      stats->skipped++;
      return 0;
    }
    hylcmat_shell_eval(m, &s->r, xp, s->nb, 0, &Ep, gp, NULL);
    hylcmat_shell_eval(m, &s->r, xm, s->nb, 0, &Em, gm, NULL);
    errg = fmax(errg, fabs((Ep - Em) / (2 * h) - g[j]));
    for (int i = 0; i < 18; i++) fdH[18 * i + j] = (gp[i] - gm[i]) / (2 * h);
  }
  gs = MaxAbs(g, 18);
  Hs = MaxAbs(H, 324);
  for (int i = 0; i < 324; i++) errH = fmax(errH, fabs(fdH[i] - H[i]));
  errg /= gs > 0 ? gs : 1;
  errH /= Hs > 0 ? Hs : 1;
  HYLC_CHECK(errg <= 1e-6, "%s: gradient differs from central differences by %.3g (relative to max |g| = %.3g)", what, errg, gs);
  HYLC_CHECK(errH <= 1e-5, "%s: Hessian differs from central differences by %.3g (relative to max |H| = %.3g)", what, errH, Hs);
  for (int i = 0; i < 324; i++) HYLC_CHECK(H[i] == H[18 * (i % 18) + i / 18], "%s: Hessian not symmetric", what);
  stats->worstg = fmax(stats->worstg, errg);
  stats->worstH = fmax(stats->worstH, errH);
  stats->tested++;
  return 1;
}

/* the projection against LAPACK's eigen-decomposition */
static PetscErrorCode CheckProjection(const hylcmat *m, const Stencil *s, const char *what, Stats *stats)
{
  double       E, g[18], H[324], P[324], A[324], w[18], work[18 * 34], err = 0;
  int          act[18], n = 0;
  PetscBLASInt bn, lwork  = 18 * 34, info;

  PetscFunctionBegin;
  if (hylcmat_shell_eval(m, &s->r, s->x, s->nb, 0, &E, g, H)) PetscFunctionReturn(PETSC_SUCCESS);
  HYLC_CHECK(hylcmat_shell_eval(m, &s->r, s->x, s->nb, HYLCMAT_SHELL_PSD, &E, g, P) == HYLCMAT_OK, "%s: projection failed", what);
  for (int v = 0; v < 6; v++)
    if (v < 3 || (s->nb >> (v - 3) & 1))
      for (int c = 0; c < 3; c++) act[n++] = 3 * v + c;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) A[n * i + j] = H[18 * act[i] + act[j]];
  PetscCall(PetscBLASIntCast(n, &bn));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("V", "U", &bn, A, &bn, w, work, &lwork, &info));
  HYLC_CHECK(info == 0, "LAPACK syev failed");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      double ref = 0;
      for (int q = 0; q < n; q++) ref += A[n * q + i] * (w[q] > HYLCMAT_PSD_FLOOR ? w[q] : HYLCMAT_PSD_FLOOR) * A[n * q + j];
      err = fmax(err, fabs(P[18 * act[i] + act[j]] - ref));
    }
  err /= MaxAbs(H, 324);
  HYLC_CHECK(err < 1e-12, "%s: the projection differs from LAPACK's by %.3g (relative)", what, err);
  for (int i = 0; i < 18; i++)
    for (int j = 0; j < 18; j++) {
      if (!((i < 9 || (s->nb >> ((i - 9) / 3) & 1)) && (j < 9 || (s->nb >> ((j - 9) / 3) & 1)))) HYLC_CHECK(P[18 * i + j] == 0, "%s: projected entry (%d, %d) of a missing neighbour", what, i, j);
    }
  stats->worstP = fmax(stats->worstP, err);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the unit normal n of the stencil's triangle */
static void Normal(const double x[18], double n[3])
{
  double a[3], b[3], l;
  for (int i = 0; i < 3; i++) a[i] = x[3 + i] - x[i], b[i] = x[6 + i] - x[i];
  n[0] = a[1] * b[2] - a[2] * b[1], n[1] = a[2] * b[0] - a[0] * b[2], n[2] = a[0] * b[1] - a[1] * b[0];
  l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < 3; i++) n[i] /= l;
}

/* flat stencils (II = 0 on a knot): see the header, item 2 */
static void CheckFlat(const hylcmat *m, const Stencil *s, const char *what, Stats *stats)
{
  double       E, g[18], H[324], n[3], e1[3], e2[3], l, errg = 0, errH = 0, Hs, gs, z[6];
  const double h = 1e-6 * s->L;

  hylcmat_shell_eval(m, &s->r, s->x, s->nb, 0, &E, g, H);
  hylcmat_shell_strains(&s->r, s->x, s->nb, z, NULL);
  HYLC_CHECK(fabs(z[3]) + fabs(z[4]) + fabs(z[5]) < 1e-9, "%s: a flat stencil has II = (%g %g %g)", what, z[3], z[4], z[5]);
  for (int i = 0; i < 324; i++) HYLC_CHECK(isfinite(H[i]), "%s: Hessian not finite at a flat state", what);
  gs = MaxAbs(g, 18);
  Hs = MaxAbs(H, 324);
  /* gradient: Psi is only C1 at II = 0, but smooth on either side along any line from the flat state:
     second-order one-sided differences (-3 E(0) + 4 E(h) - E(2 h)) / (2 h) */
  for (int j = 0; j < 18; j++) {
    double x1[18], x2[18], E1, E2;
    if (j >= 9 && !(s->nb >> ((j - 9) / 3) & 1)) continue;
    memcpy(x1, s->x, sizeof(x1));
    memcpy(x2, s->x, sizeof(x2));
    x1[j] += h;
    x2[j] += 2 * h;
    hylcmat_shell_eval(m, &s->r, x1, s->nb, 0, &E1, NULL, NULL);
    hylcmat_shell_eval(m, &s->r, x2, s->nb, 0, &E2, NULL, NULL);
    errg = fmax(errg, fabs((-3 * E + 4 * E1 - E2) / (2 * h) - g[j]) / gs);
  }
  HYLC_CHECK(errg <= 1e-6, "%s: gradient differs from one-sided differences by %.3g", what, errg);
  /* the Hessian along directions in the plane (II stays 0): central differences */
  Normal(s->x, n);
  for (int i = 0; i < 3; i++) e1[i] = s->x[3 + i] - s->x[i];
  l = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int i = 0; i < 3; i++) e1[i] /= l;
  e2[0] = n[1] * e1[2] - n[2] * e1[1], e2[1] = n[2] * e1[0] - n[0] * e1[2], e2[2] = n[0] * e1[1] - n[1] * e1[0];
  for (int v = 0; v < 6; v++)
    for (int d = 0; d < 2; d++) {
      double xp[18], xm[18], gp[18], gm[18], Ep, Em;
      if (v >= 3 && !(s->nb >> (v - 3) & 1)) continue;
      memcpy(xp, s->x, sizeof(xp));
      memcpy(xm, s->x, sizeof(xm));
      for (int i = 0; i < 3; i++) xp[3 * v + i] += h * (d ? e2[i] : e1[i]), xm[3 * v + i] -= h * (d ? e2[i] : e1[i]);
      hylcmat_shell_eval(m, &s->r, xp, s->nb, 0, &Ep, gp, NULL);
      hylcmat_shell_eval(m, &s->r, xm, s->nb, 0, &Em, gm, NULL);
      for (int i = 0; i < 18; i++) {
        double Hv = 0;
        for (int c = 0; c < 3; c++) Hv += H[18 * i + 3 * v + c] * (d ? e2[c] : e1[c]);
        errH = fmax(errH, fabs((gp[i] - gm[i]) / (2 * h) - Hv) / Hs);
      }
    }
  /* exactly planar (II = 0 exactly: the evaluator returns the pieces right of the knot 0), along
     II > 0 (every neighbour lifted toward n) plus a random in-plane part: one-sided second-order
     differences (-3 g(0) + 4 g(h/2) - g(h)) / h. (Rotated out of its plane, a flat stencil has II of
     roundoff size and either sign: the Hessian is then that of either side, or a mixture.) */
  if (s->nb == 7 && z[3] == 0 && z[4] == 0 && z[5] == 0) {
    unsigned long long st = 99;
    double             dir[18], x1[18], x2[18], g1[18], g2[18], E1, E2;
    for (int i = 0; i < 18; i++) dir[i] = 0;
    for (int v = 0; v < 6; v++) {
      const double a = v >= 3 ? 0.5 + 0.5 * HylcTestRand(&st) : 0, b = 0.3 * Uni(&st), c = 0.3 * Uni(&st);
      for (int i = 0; i < 3; i++) dir[3 * v + i] = a * n[i] + b * e1[i] + c * e2[i];
    }
    for (int i = 0; i < 18; i++) x1[i] = s->x[i] + 0.5 * h * dir[i], x2[i] = s->x[i] + h * dir[i];
    hylcmat_shell_eval(m, &s->r, x1, s->nb, 0, &E1, g1, NULL);
    hylcmat_shell_eval(m, &s->r, x2, s->nb, 0, &E2, g2, NULL);
    for (int i = 0; i < 18; i++) {
      double Hv = 0;
      for (int c = 0; c < 18; c++) Hv += H[18 * i + c] * dir[c];
      errH = fmax(errH, fabs((-3 * g[i] + 4 * g1[i] - g2[i]) / h - Hv) / Hs);
    }
    /* bounded: no larger than at a nearby bent state (ARCSim-HYLC's epsilon gives entries ~1/sqrt(eps)) */
    {
      double xb[18], Hb[324], Eb, gb[18];
      for (int i = 0; i < 18; i++) xb[i] = s->x[i] + 1e-2 * s->L * dir[i];
      hylcmat_shell_eval(m, &s->r, xb, s->nb, 0, &Eb, gb, Hb);
      HYLC_CHECK(Hs <= 10 * MaxAbs(Hb, 324), "%s: max |H| = %.3g at the flat state, %.3g when slightly bent", what, Hs, MaxAbs(Hb, 324));
    }
  }
  HYLC_CHECK(errH <= 1e-5, "%s: Hessian differs from differences by %.3g", what, errH);
  if (z[3] == 0 && z[4] == 0 && z[5] == 0 && s->nb == 7) stats->onesided++;
  stats->worstg = fmax(stats->worstg, errg);
  stats->worstH = fmax(stats->worstH, errH);
  stats->tested++;
}

/* every check on random stencils of one table */
static PetscErrorCode TestTable(const hylcmat *m, const char *name, int nper, unsigned long long *st, Stats *all)
{
  double sc[5], kappa;
  Stats  s[K_NKIND];
  char   what[256];

  PetscFunctionBegin;
  memset(s, 0, sizeof(s));
  hylcmat_strain_scale(m, sc);
  kappa = 0.7 * fmin(sc[3], sc[4]);
  for (int it = 0; it < nper; it++) {
    const int kind = it % K_NKIND;
    Stencil   S;
    MakeStencil(kind, kappa, 0.1, st, &S);
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s, %s stencil %d (nb %d)", name, KindName[kind], it, S.nb));
    if (kind == K_UMBILIC) {
      double z[6];
      hylcmat_shell_strains(&S.r, S.x, S.nb, z, NULL);
      HYLC_CHECK(fabs(z[3] - z[5]) + fabs(z[4]) <= 1e-10 * fabs(z[3]) && z[3] != 0, "%s: II = (%g %g %g) is not kappa I", what, z[3], z[4], z[5]);
    }
    if (kind == K_FLAT)
      CheckFlat(m, &S, what, &s[kind]);
    else
      CheckFD(m, &S, 1e-6 * S.L, what, &s[kind]);
    PetscCall(CheckProjection(m, &S, what, &s[kind]));
  }
  for (int k = 0; k < K_NKIND; k++) {
    HYLC_CHECK(s[k].skipped * 10 <= s[k].tested + s[k].skipped, "%s, %s: %d of %d stencils skipped (a knot inside the differences)", name, KindName[k], s[k].skipped, s[k].tested + s[k].skipped);
    if (Verbose)
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-16s %-18s %4d tested %3d skipped: worst gradient %.2e Hessian %.2e projection %.2e%s\n", name, KindName[k], s[k].tested, s[k].skipped, s[k].worstg, s[k].worstH, s[k].worstP,
                            k == K_FLAT ? " (Hessian: in-plane and one-sided)" : ""));
    if (k == K_FLAT) HYLC_CHECK(s[k].onesided * 4 >= s[k].tested, "%s: only %d of %d flat stencils checked one-sided", name, s[k].onesided, s[k].tested);
    all->tested += s[k].tested;
    all->skipped += s[k].skipped;
    all->worstg = fmax(all->worstg, s[k].worstg);
    all->worstH = fmax(all->worstH, s[k].worstH);
    all->worstP = fmax(all->worstP, s[k].worstP);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rigid motions: E, g, H at Q x + t against those at x */
static void TestRigid(const hylcmat *m, const char *name, unsigned long long *st, double *worst)
{
  double sc[5];
  hylcmat_strain_scale(m, sc);
  for (int it = 0; it < 20; it++) {
    Stencil S;
    double  Q[9], t[3], y[18], E0, E1, g0[18], g1[18], H0[324], H1[324], eg = 0, eH = 0, eE;
    MakeStencil(it % 3, 0.7 * fmin(sc[3], sc[4]), 0, st, &S);
    RandomRotation(st, Q);
    for (int i = 0; i < 3; i++) t[i] = 10 * Uni(st);
    Rigid(Q, t, 6, S.x, y);
    hylcmat_shell_eval(m, &S.r, S.x, S.nb, 0, &E0, g0, H0);
    hylcmat_shell_eval(m, &S.r, y, S.nb, 0, &E1, g1, H1);
    eE = fabs(E1 - E0) / fabs(E0);
    for (int v = 0; v < 6; v++)
      for (int i = 0; i < 3; i++) {
        double r = 0;
        for (int c = 0; c < 3; c++) r += Q[3 * i + c] * g0[3 * v + c];
        eg = fmax(eg, fabs(g1[3 * v + i] - r));
      }
    eg /= MaxAbs(g0, 18);
    /* H1 = (I x Q) H0 (I x Q)^T */
    for (int a = 0; a < 6; a++)
      for (int b = 0; b < 6; b++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) {
            double r = 0;
            for (int p = 0; p < 3; p++)
              for (int q = 0; q < 3; q++) r += Q[3 * i + p] * H0[18 * (3 * a + p) + 3 * b + q] * Q[3 * j + q];
            eH = fmax(eH, fabs(H1[18 * (3 * a + i) + 3 * b + j] - r));
          }
    eH /= MaxAbs(H0, 324);
    HYLC_CHECK(eE < 1e-11 && eg < 1e-9 && eH < 1e-8, "%s: rigid motion (translation %.3g m): relative changes E %.3g, gradient %.3g, Hessian %.3g", name, sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]), eE, eg, eH);
    worst[0] = fmax(worst[0], eE);
    worst[1] = fmax(worst[1], eg);
    worst[2] = fmax(worst[2], eH);
  }
}

/* hylcmat_shell_eval_batch gives exactly the values of single calls, also around a failing element */
static void TestBatch(const hylcmat *m, unsigned long long *st)
{
  enum { NB = 11 };
  hylcmat_shell_rest r[NB];
  double             x[NB * 18], E[NB], g[NB * 18], H[NB * 324], sc[5];
  int                nb[NB];

  hylcmat_strain_scale(m, sc);
  for (int i = 0; i < NB; i++) {
    Stencil S;
    MakeStencil(i % 4, 0.7 * fmin(sc[3], sc[4]), 0.1, st, &S);
    r[i]  = S.r;
    nb[i] = S.nb;
    memcpy(x + 18 * i, S.x, sizeof(S.x));
  }
  x[18 * 5 + 4] = NAN;
  for (int flags = 0; flags <= HYLCMAT_SHELL_PSD; flags++) {
    const int ret = hylcmat_shell_eval_batch(m, NB, r, x, nb, flags, E, g, H);
    HYLC_CHECK(ret == HYLCMAT_ERR_NONFINITE, "batch: returned %d, not the NaN element's error", ret);
    for (int i = 0; i < NB; i++) {
      double    e1, g1[18], H1[324];
      const int r1 = hylcmat_shell_eval(m, &r[i], x + 18 * i, nb[i], flags, &e1, g1, H1);
      HYLC_CHECK((r1 != 0) == (i == 5), "batch: element %d: single call returned %d", i, r1);
      HYLC_CHECK(e1 == E[i] && !memcmp(g1, g + 18 * i, sizeof(g1)) && !memcmp(H1, H + 324 * i, sizeof(H1)), "batch (flags %d): element %d differs from a single call", flags, i);
    }
  }
}

/* ---- meshes ----------------------------------------------------------------------------------------- */
/* an (n+1) x (n+1) grid of [0, a] x [0, b] in material coordinates, two triangles per cell (diagonals
   alternating if alt), interior vertices jittered by jit cells */
static void Grid(int n, double a, double b, int alt, double jit, unsigned long long *st, int *nv, int *nt, double **uv, int **tri)
{
  *nv  = (n + 1) * (n + 1);
  *nt  = 2 * n * n;
  *uv  = (double *)malloc(sizeof(double) * 2 * *nv);
  *tri = (int *)malloc(sizeof(int) * 3 * *nt);
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) {
      const int interior               = i > 0 && j > 0 && i < n && j < n;
      (*uv)[2 * (i * (n + 1) + j)]     = a * (i + (interior && jit > 0 ? jit * Uni(st) : 0)) / n;
      (*uv)[2 * (i * (n + 1) + j) + 1] = b * (j + (interior && jit > 0 ? jit * Uni(st) : 0)) / n;
    }
  for (int i = 0, t = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      const int p = i * (n + 1) + j, q = (i + 1) * (n + 1) + j, r = (i + 1) * (n + 1) + j + 1, s = i * (n + 1) + j + 1;
      if (!alt || (i + j) % 2 == 0) {
        const int T[6] = {p, q, r, p, r, s};
        memcpy(*tri + 3 * t, T, sizeof(T));
      } else {
        const int T[6] = {p, q, s, q, r, s};
        memcpy(*tri + 3 * t, T, sizeof(T));
      }
      t += 2;
    }
}

static PetscErrorCode TestFlatMesh(const hylcmat *m, const char *name, int fitted, unsigned long long *st)
{
  int           nv, nt, ret;
  double       *uv, *X, *x, *ang, E, psi0, zero[6] = {0, 0, 0, 0, 0, 0}, Q[9], t[3] = {0.3, -2, 1};
  int          *tri;
  hylcmat_mesh *mu, *m3;
  char          err[512];

  PetscFunctionBegin;
  Grid(8, 0.2, 0.15, 1, 0.2, st, &nv, &nt, &uv, &tri);
  X   = (double *)malloc(sizeof(double) * 3 * nv);
  x   = (double *)malloc(sizeof(double) * 3 * nv);
  ang = (double *)malloc(sizeof(double) * nt);
  for (int v = 0; v < nv; v++) X[3 * v] = uv[2 * v], X[3 * v + 1] = uv[2 * v + 1], X[3 * v + 2] = 0;
  for (int i = 0; i < nt; i++) ang[i] = M_PI * Uni(st);
  {
    double *cuv = (double *)malloc(sizeof(double) * 6 * nt);
    for (int i = 0; i < nt; i++)
      for (int k = 0; k < 3; k++) cuv[6 * i + 2 * k] = uv[2 * tri[3 * i + k]], cuv[6 * i + 2 * k + 1] = uv[2 * tri[3 * i + k] + 1];
    ret = hylcmat_mesh_create_uv(nv, nt, tri, cuv, &mu, err, sizeof(err));
    free(cuv);
  }
  HYLC_CHECK(ret == 0, "%s", err);
  ret = hylcmat_mesh_create(nv, nt, tri, X, ang, &m3, err, sizeof(err));
  HYLC_CHECK(ret == 0, "%s", err);
  HYLC_CHECK(fabs(hylcmat_mesh_area(mu) - 0.03) < 1e-15 && fabs(hylcmat_mesh_area(m3) - 0.03) < 1e-15, "mesh areas %.17g %.17g, expected 0.03", hylcmat_mesh_area(mu), hylcmat_mesh_area(m3));
  hylcmat_eval(m, zero, &psi0, NULL, NULL);
  RandomRotation(st, Q);
  Rigid(Q, t, nv, X, x);
  for (int pass = 0; pass < 4; pass++) {
    const hylcmat_mesh *M = pass % 2 ? m3 : mu;
    ret                   = hylcmat_mesh_eval(M, m, pass < 2 ? X : x, 0, &E, NULL, NULL, err, sizeof(err));
    HYLC_CHECK(ret == 0, "%s", err);
    HYLC_CHECK(fabs(E - psi0 * 0.03) <= 1e-12 * psi0 * 0.03, "%s: flat undeformed mesh (%s, %s): E = %.17g, Psi(0) x area = %.17g", name, pass % 2 ? "3D + angle" : "uv", pass < 2 ? "at rest" : "moved", E, psi0 * 0.03);
  }
  if (fitted)
    HYLC_CHECK(psi0 == hylcmat_constant(m), "%s: Psi(0) = %.17g is not C0 = %.17g", name, psi0, hylcmat_constant(m));
  else
    HYLC_CHECK(fabs(psi0 - hylcmat_constant(m)) <= 0.01 * hylcmat_constant(m), "%s: Psi(0) = %.17g far from C0 = %.17g", name, psi0, hylcmat_constant(m));
  if (Verbose) PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-10s flat mesh: E / area = %.10g, C0 = %.10g (relative %.2e)\n", name, E / 0.03, hylcmat_constant(m), (E / 0.03 - hylcmat_constant(m)) / hylcmat_constant(m)));
  /* the mesh's gradient and Hessian are the assembled elements (deformed state) */
  {
    int64_t nnz = hylcmat_mesh_hessian_nnz(mu), *rp = (int64_t *)malloc(sizeof(int64_t) * (3 * nv + 1));
    int    *ci = (int *)malloc(sizeof(int) * nnz), *ro = (int *)malloc(sizeof(int) * nnz), *co = (int *)malloc(sizeof(int) * nnz);
    double *g = (double *)calloc(3 * nv, sizeof(double)), *h = (double *)malloc(sizeof(double) * nnz), *G = (double *)calloc(3 * nv, sizeof(double));
    double *D = (double *)calloc((size_t)9 * nv * nv, sizeof(double)), Et = 0, err2 = 0, Hs = 0;
    for (int v = 0; v < nv; v++)
      for (int i = 0; i < 3; i++) x[3 * v + i] = X[3 * v + i] * (i == 0 ? 1.1 : 1) + 0.003 * Uni(st);
    for (int proj = 0; proj < 2; proj++) {
      ret = hylcmat_mesh_eval(mu, m, x, proj ? HYLCMAT_SHELL_PSD : 0, &E, g, h, err, sizeof(err));
      HYLC_CHECK(ret == 0, "%s", err);
      memset(D, 0, sizeof(double) * 9 * nv * nv);
      memset(G, 0, sizeof(double) * 3 * nv);
      Et = 0;
      for (int tt = 0; tt < nt; tt++) {
        int                v[6];
        hylcmat_shell_rest r;
        double             xs[18], e, ge[18], He[324];
        hylcmat_mesh_element(mu, tt, v, &r);
        for (int i = 0; i < 6; i++)
          for (int c = 0; c < 3; c++) xs[3 * i + c] = v[i] >= 0 ? x[3 * v[i] + c] : 0;
        hylcmat_shell_eval(m, &r, xs, (v[3] >= 0) | (v[4] >= 0) << 1 | (v[5] >= 0) << 2, proj ? HYLCMAT_SHELL_PSD : 0, &e, ge, He);
        Et += e;
        for (int i = 0; i < 6; i++)
          if (v[i] >= 0)
            for (int c = 0; c < 3; c++) {
              G[3 * v[i] + c] += ge[3 * i + c];
              for (int j = 0; j < 6; j++)
                if (v[j] >= 0)
                  for (int d = 0; d < 3; d++) D[(size_t)3 * nv * (3 * v[i] + c) + 3 * v[j] + d] += He[18 * (3 * i + c) + 3 * j + d];
            }
      }
      hylcmat_mesh_hessian_csr(mu, rp, ci);
      hylcmat_mesh_hessian_coo(mu, ro, co);
      HYLC_CHECK(rp[3 * nv] == nnz, "rowptr end %lld, nnz %lld", (long long)rp[3 * nv], (long long)nnz);
      err2 = fabs(E - Et) / fabs(Et);
      for (int i = 0; i < 3 * nv; i++) err2 = fmax(err2, fabs(g[i] - G[i]) / MaxAbs(G, 3 * nv));
      for (size_t i = 0; i < (size_t)9 * nv * nv; i++) Hs = fmax(Hs, fabs(D[i]));
      for (int i = 0; i < 3 * nv; i++)
        for (int64_t q = rp[i]; q < rp[i + 1]; q++) {
          HYLC_CHECK(ro[q] == i && co[q] == ci[q] && (q == rp[i] || ci[q] > ci[q - 1]), "CSR/COO structure at entry %lld", (long long)q);
          err2                          = fmax(err2, fabs(h[q] - D[(size_t)3 * nv * i + ci[q]]) / Hs);
          D[(size_t)3 * nv * i + ci[q]] = 0;
        }
      HYLC_CHECK(err2 < 1e-13, "%s: the mesh's energy, gradient or Hessian differ from the assembled elements by %.3g", name, err2);
      HYLC_CHECK(MaxAbs(D, 9 * nv * nv) == 0, "%s: an assembled Hessian entry is outside the sparsity", name);
    }
    free(rp), free(ci), free(ro), free(co), free(g), free(h), free(G), free(D);
  }
  hylcmat_mesh_free(mu);
  hylcmat_mesh_free(m3);
  free(uv), free(tri), free(X), free(x), free(ang);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* an equilateral grid of about [0, a] x [0, a]: n triangles' sides per row */
static void Equilateral(int n, double a, int *nv, int *nt, double **uv, int **tri)
{
  const double h = a / n, hy = 0.5 * sqrt(3.0) * h;
  const int    rows = (int)(a / hy);
  *nv               = (rows + 1) * (n + 1);
  *nt               = 2 * rows * n;
  *uv               = (double *)malloc(sizeof(double) * 2 * *nv);
  *tri              = (int *)malloc(sizeof(int) * 3 * *nt);
  for (int j = 0; j <= rows; j++)
    for (int i = 0; i <= n; i++) (*uv)[2 * (j * (n + 1) + i)] = (i + 0.5 * (j % 2)) * h, (*uv)[2 * (j * (n + 1) + i) + 1] = j * hy;
  for (int j = 0, t = 0; j < rows; j++)
    for (int i = 0; i < n; i++, t += 2) {
      const int p = j * (n + 1) + i, q = p + 1, r = p + n + 1, s = r + 1;
      if (j % 2 == 0) {
        const int T[6] = {p, q, r, q, s, r};
        memcpy(*tri + 3 * t, T, sizeof(T));
      } else {
        const int T[6] = {p, q, s, p, s, r};
        memcpy(*tri + 3 * t, T, sizeof(T));
      }
    }
}

/* The cylinder: a grid (kind 0: right triangles, all diagonals alike; 1: equilateral; 2: right
   triangles, diagonals alternating) of a square of side rho pi / 2 with n triangles per side, the
   cylinder's axis at angle phi to the material u axis, mapped isometrically onto a cylinder of radius
   rho bending toward +n (side = 1) or -n (side = -1). Returns the largest deviation over the interior
   triangles of II from (side / rho) d d^T (d across the axis) times rho, that of their mean (mean), and
   the largest in-plane strain (ein). */
static double Cylinder(int kind, int n, double rho, double phi, int side, double *mean, double *ein)
{
  int           nv, nt, cnt = 0;
  double       *uv, *x, *z, worst = 0, L = 0.5 * M_PI * rho, sum[3] = {0, 0, 0}, c[2] = {0, 0};
  int          *tri;
  hylcmat_mesh *M;
  char          err[256];
  const double  ax[2] = {cos(phi), sin(phi)}, d[2] = {-sin(phi), cos(phi)}, k = side / rho;

  if (kind == 1)
    Equilateral(n, L, &nv, &nt, &uv, &tri);
  else
    Grid(n, L, L, kind == 2, 0, NULL, &nv, &nt, &uv, &tri);
  x = (double *)malloc(sizeof(double) * 3 * nv);
  z = (double *)malloc(sizeof(double) * 6 * nt);
  for (int v = 0; v < nv; v++) c[0] += uv[2 * v] / nv, c[1] += uv[2 * v + 1] / nv;
  /* (u, v) -> (a, s) along and across the axis is a rotation; x = (-rho sin(s / rho), a, side rho
     (1 - cos(s / rho))) keeps the orientation, so n = +z where s = 0, and side = 1 bends toward n */
  for (int v = 0; v < nv; v++) {
    const double p = uv[2 * v] - c[0], q = uv[2 * v + 1] - c[1], a = p * ax[0] + q * ax[1], s = p * d[0] + q * d[1];
    x[3 * v]     = -rho * sin(s / rho);
    x[3 * v + 1] = a;
    x[3 * v + 2] = side * rho * (1 - cos(s / rho));
  }
  {
    double *cuv = (double *)malloc(sizeof(double) * 6 * nt);
    for (int i = 0; i < nt; i++)
      for (int j = 0; j < 3; j++) cuv[6 * i + 2 * j] = uv[2 * tri[3 * i + j]], cuv[6 * i + 2 * j + 1] = uv[2 * tri[3 * i + j] + 1];
    HYLC_CHECK(hylcmat_mesh_create_uv(nv, nt, tri, cuv, &M, err, sizeof(err)) == 0, "cylinder mesh: %s", err);
    free(cuv);
  }
  HYLC_CHECK(hylcmat_mesh_strains(M, x, z, err, sizeof(err)) == 0, "cylinder strains: %s", err);
  *ein = 0;
  for (int t = 0; t < nt; t++) {
    int v[6];
    hylcmat_mesh_element(M, t, v, NULL);
    if (v[3] < 0 || v[4] < 0 || v[5] < 0) continue;
    {
      const double e0 = z[6 * t + 3] - k * d[0] * d[0], e1 = z[6 * t + 4] - k * d[0] * d[1], e2 = z[6 * t + 5] - k * d[1] * d[1];
      worst = fmax(worst, sqrt(e0 * e0 + 2 * e1 * e1 + e2 * e2) * rho);
      sum[0] += e0, sum[1] += e1, sum[2] += e2, cnt++;
      *ein = fmax(*ein, fabs(z[6 * t]) + fabs(z[6 * t + 1]) + fabs(z[6 * t + 2]));
    }
  }
  for (int i = 0; i < 3; i++) sum[i] /= cnt;
  *mean = sqrt(sum[0] * sum[0] + 2 * sum[1] * sum[1] + sum[2] * sum[2]) * rho;
  hylcmat_mesh_free(M);
  free(uv), free(tri), free(x), free(z);
  return worst;
}

static PetscErrorCode TestCylinder(void)
{
  const double rho = 0.05, phis[4] = {0, 0.5, M_PI / 4, M_PI / 2};
  const char  *kinds[3] = {"right triangles", "equilateral", "alternating diagonals"};

  PetscFunctionBegin;
  for (int kind = 0; kind < 3; kind++)
    for (int ip = 0; ip < 4; ip++)
      for (int side = -1; side <= 1; side += 2) {
        double e[4], mean[4], ein[4], o[3];
        int    n = 8;
        for (int l = 0; l < 4; l++, n *= 2) e[l] = Cylinder(kind, n, rho, phis[ip], side, &mean[l], &ein[l]);
        /* per triangle on the regular meshes; the alternating mesh only on average (its triangles'
           II are off by O(1) for an oblique axis: the discrete II depends on the mesh) */
        if (kind == 2) memcpy(e, mean, sizeof(e));
        for (int l = 1; l < 4; l++) {
          const double oin = log(ein[l - 1] / ein[l]) / log(2.0);
          o[l - 1]         = log(e[l - 1] / e[l]) / log(2.0);
          HYLC_CHECK(o[l - 1] > 1.8 && oin > 1.8, "cylinder (%s, axis at %.2f rad, side %d): II errors %.3g -> %.3g (order %.2f), in-plane %.3g -> %.3g (order %.2f)", kinds[kind], phis[ip], side, e[l - 1], e[l], o[l - 1], ein[l - 1], ein[l], oin);
        }
        HYLC_CHECK(e[3] < 1e-4, "cylinder (%s, axis at %.2f rad, side %d): II off by %.3g / rho with 64 triangles per side", kinds[kind], phis[ip], side, e[3]);
        if (Verbose)
          PetscCall(PetscPrintf(PETSC_COMM_SELF, "  cylinder, %-21s axis %.2f rad, toward %sn: %s|II - side/rho d d^T| rho = %.2e %.2e %.2e %.2e (8..64 per side), order %.2f %.2f %.2f; in-plane %.1e\n", kinds[kind], phis[ip], side > 0 ? "+" : "-",
                                kind == 2 ? "mean " : "", e[0], e[1], e[2], e[3], o[0], o[1], o[2], ein[3]));
      }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* strains of simple stencils in closed form */
static void TestConventions(void)
{
  const double       uv[6] = {0, 0, 0.01, 0, 0, 0.01};
  hylcmat_shell_rest r;
  double             x[18] = {0, 0, 0, 0.011, 0, 0, 0.003, 0.009, 0, 0.0, -0.01, 0.0, 0.01, 0.01, 0, -0.01, 0.01, 0}, z[6];

  HYLC_CHECK(hylcmat_shell_rest_uv(uv, &r) == 0 && fabs(r.area - 5e-5) < 1e-20, "rest area %g", r.area);
  hylcmat_shell_strains(&r, x, 0, z, NULL);
  HYLC_CHECK(fabs(z[0] - 0.1) < 1e-14 && fabs(z[2] - (sqrt(0.3 * 0.3 + 0.9 * 0.9) - 1)) < 1e-14 && fabs(z[1] - 0.3 / sqrt(0.9)) < 1e-14, "stretch/shear strains (%.17g %.17g %.17g)", z[0], z[1], z[2]);
  /* a fold across edge (0,1): the neighbour lifted toward n = +z bends toward n: II00 = 0, II11 > 0 */
  {
    const double a = 0.3, xs[18] = {0, 0, 0, 0.01, 0, 0, 0, 0.01, 0, 0.005, -0.01 * cos(a), 0.01 * sin(a), 0, 0, 0, 0, 0, 0};
    const double th = -a, IIe = -2 * 5e-5 * th / 0.01 * 100 * 100; /* t = (0, 100): II11 = -2 A theta / l t1^2 */
    hylcmat_shell_strains(&r, xs, 1, z, NULL);
    HYLC_CHECK(fabs(z[3]) < 1e-9 && fabs(z[4]) < 1e-9 && fabs(z[5] - IIe) < 1e-9 * IIe && z[5] > 0, "fold toward n: II = (%g %g %g), expected (0 0 %g)", z[3], z[4], z[5], IIe);
  }
}

/* bad input */
static PetscErrorCode TestErrors(const hylcmat *m)
{
  hylcmat_shell_rest r;
  double             uv[6] = {0, 0, 0.01, 0, 0, 0.01}, x[18], E = 1, g[18], H[324];
  char               err[512];
  hylcmat_mesh      *M       = (hylcmat_mesh *)&r;
  const int          sq[6]   = {0, 1, 2, 0, 2, 3};
  const double       sqx[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

  PetscFunctionBegin;
  HYLC_CHECK(hylcmat_shell_rest_uv(uv, &r) == 0, "rest");
  {
    const double       bad[4][6] = {{0, 0, 0, 0.01, 0.01, 0}, {0, 0, 0.01, 0, 0.02, 0}, {0, 0, NAN, 0, 0, 0.01}, {0, 0, 1e-20, 0, 0, 0.01}};
    hylcmat_shell_rest rr;
    for (int i = 0; i < 3; i++) HYLC_CHECK(hylcmat_shell_rest_uv(bad[i], &rr) == HYLCMAT_ERR_REST, "bad rest triangle %d accepted", i);
    HYLC_CHECK(hylcmat_shell_rest_uv(bad[3], &rr) == HYLCMAT_OK, "a thin but valid rest triangle refused");
    /* a rest triangle the element cannot evaluate at its own rest state is refused: a subnormal area
       (edges of 1e-160 m: 2 A = 1e-320) was accepted and then degenerate at rest; every accepted scale
       evaluates at rest */
    {
      const double sub[6] = {0, 0, 1e-160, 0, 0, 1e-160};
      int          acc    = 0;
      HYLC_CHECK(hylcmat_shell_rest_uv(sub, &rr) == HYLCMAT_ERR_REST, "a rest triangle of subnormal area accepted (area %g)", rr.area);
      for (int k = -170; k <= 170; k += 5) {
        const double s = pow(10.0, k), u[6] = {0, 0, s, 0, 0.3 * s, 0.9 * s};
        double       xr[18] = {0}, Er, gr[18];
        int          rc;
        if (hylcmat_shell_rest_uv(u, &rr)) continue;
        acc++;
        for (int j = 0; j < 3; j++) xr[3 * j] = u[2 * j], xr[3 * j + 1] = u[2 * j + 1];
        rc = hylcmat_shell_eval(m, &rr, xr, 0, 0, &Er, gr, NULL);
        HYLC_CHECK(rc == HYLCMAT_OK, "the rest triangle of scale 1e%d m accepted, but at rest: %s", k, hylcmat_strerror(rc));
      }
      HYLC_CHECK(acc == 31, "%d of the scales 1e-170 .. 1e170 m accepted, expected the 31 of 1e-75 .. 1e75 (2 A within 1.5e-154 .. 1.3e154)", acc);
      HYLC_CHECK(hylcmat_shell_rest_uv((const double[6]){0, 0, 1e-150, 0, 0, 1e-150}, &rr) == HYLCMAT_ERR_REST, "2 A = 1e-300 accepted");
      HYLC_CHECK(hylcmat_shell_rest_uv((const double[6]){0, 0, 1e100, 0, 0, 1e100}, &rr) == HYLCMAT_ERR_REST, "2 A = 1e200 accepted");
    }
    {
      const double X[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2}, Y[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
      HYLC_CHECK(hylcmat_shell_rest_3d(X, 0, &rr) == HYLCMAT_ERR_REST, "collinear 3D rest triangle accepted");
      HYLC_CHECK(hylcmat_shell_rest_3d(Y, NAN, &rr) == HYLCMAT_ERR_REST, "NaN angle accepted");
      HYLC_CHECK(hylcmat_shell_rest_3d(Y, 0.3, &rr) == HYLCMAT_OK && fabs(rr.area - 0.5) < 1e-15, "3D rest area %g", rr.area);
    }
  }
  {
    const double x0[18] = {0, 0, 0, 0.01, 0, 0, 0, 0.01, 0, 0.005, -0.01, 0, 0.01, 0.01, 0, -0.01, 0.005, 0};
    memcpy(x, x0, sizeof(x)); /* the triangle (0,0,0) (0.01,0,0) (0,0.01,0) and its neighbours, flat */
  }
  {
    double xs[18];
    memcpy(xs, x, sizeof(xs));
    xs[4] = NAN;
    HYLC_CHECK(hylcmat_shell_eval(m, &r, xs, 0, 0, &E, g, H) == HYLCMAT_ERR_NONFINITE && E == 0 && g[0] == 0 && H[0] == 0, "NaN coordinate");
    memcpy(xs, x, sizeof(xs));
    xs[9] = INFINITY;
    HYLC_CHECK(hylcmat_shell_eval(m, &r, xs, 1, 0, &E, g, H) == HYLCMAT_ERR_NONFINITE, "infinite neighbour coordinate");
    HYLC_CHECK(hylcmat_shell_eval(m, &r, xs, 6, 0, &E, g, H) == HYLCMAT_OK, "a missing neighbour's coordinates are read");
    memcpy(xs, x, sizeof(xs));
    xs[6] = 0.02, xs[7] = 0; /* collinear */
    HYLC_CHECK(hylcmat_shell_eval(m, &r, xs, 0, HYLCMAT_SHELL_PSD, &E, g, H) == HYLCMAT_ERR_DEGENERATE && E == 0 && g[0] == 0, "degenerate deformed triangle");
    memcpy(xs, x, sizeof(xs));
    xs[10] = 0; /* neighbour 3 on the edge (0,1) */
    HYLC_CHECK(hylcmat_shell_eval(m, &r, xs, 1, 0, &E, g, H) == HYLCMAT_ERR_DEGENERATE, "neighbour face of zero area");
    HYLC_CHECK(hylcmat_shell_strains(&r, xs, 1, g, NULL) == HYLCMAT_ERR_DEGENERATE && g[0] == 0, "strains of a degenerate stencil");
    memcpy(xs, x, sizeof(xs));
    for (int i = 0; i < 9; i++) xs[i] *= 1e160; /* beyond the double range */
    HYLC_CHECK(hylcmat_shell_eval(m, &r, xs, 0, 0, &E, g, H) == HYLCMAT_ERR_RANGE && E == 0, "results beyond the double range: E = %g", E);
    HYLC_CHECK(hylcmat_shell_eval(m, &r, x, 0, 0, &E, NULL, H) == HYLCMAT_ERR_ARG, "a Hessian without the gradient");
    HYLC_CHECK(hylcmat_shell_eval(NULL, &r, x, 0, 0, &E, g, H) == HYLCMAT_ERR_ARG, "NULL table");
  }
  /* meshes */
  {
    const int tri3[9] = {0, 1, 2, 0, 2, 3, 0, 4, 2}, triflip[6] = {0, 1, 2, 0, 3, 2}, trirange[3] = {0, 1, 7}, tritwice[3] = {0, 1, 1};
    double    X5[15] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, -1, 0};
    struct {
      int         nv, nt, code;
      const int  *tri;
      const char *msg;
    } cases[] = {
        {5, 3, HYLCMAT_ERR_MESH, tri3, "non-manifold"},
        {4, 2, HYLCMAT_ERR_MESH, triflip, "orientations"},
        {4, 1, HYLCMAT_ERR_MESH, trirange, "out of range"},
        {4, 1, HYLCMAT_ERR_MESH, tritwice, "twice"},
    };
    for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
      M             = (hylcmat_mesh *)&r;
      const int ret = hylcmat_mesh_create(cases[c].nv, cases[c].nt, cases[c].tri, X5, NULL, &M, err, sizeof(err));
      HYLC_CHECK(ret == cases[c].code && !M && strstr(err, cases[c].msg), "mesh case %d: code %d, message '%s'", (int)c, ret, err);
    }
    {
      double uvb[12] = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1};
      HYLC_CHECK(hylcmat_mesh_create_uv(4, 2, sq, uvb, &M, err, sizeof(err)) == HYLCMAT_OK, "%s", err);
      hylcmat_mesh_free(M);
      { /* triangle 1 clockwise */
        double cw[12] = {0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 1};
        HYLC_CHECK(hylcmat_mesh_create_uv(4, 2, sq, cw, &M, err, sizeof(err)) == HYLCMAT_ERR_REST && strstr(err, "triangle 1") && strstr(err, "inverted"), "clockwise rest triangle: '%s'", err);
      }
      {
        double zero[12] = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 2, 2};
        HYLC_CHECK(hylcmat_mesh_create_uv(4, 2, sq, zero, &M, err, sizeof(err)) == HYLCMAT_ERR_REST && strstr(err, "zero-area"), "zero-area rest triangle: '%s'", err);
      }
      {
        double Xn[12];
        memcpy(Xn, sqx, sizeof(Xn));
        Xn[4] = NAN;
        HYLC_CHECK(hylcmat_mesh_create(4, 2, sq, Xn, NULL, &M, err, sizeof(err)) == HYLCMAT_ERR_REST && strstr(err, "non-finite"), "NaN rest position: '%s'", err);
      }
    }
    /* a NaN in the deformed positions of a mesh: the triangle named, outputs 0 */
    {
      double xn[12], gm[12], *hv;
      HYLC_CHECK(hylcmat_mesh_create(4, 2, sq, sqx, NULL, &M, err, sizeof(err)) == HYLCMAT_OK, "%s", err);
      hv = (double *)malloc(sizeof(double) * hylcmat_mesh_hessian_nnz(M));
      memcpy(xn, sqx, sizeof(xn));
      xn[10] = NAN; /* vertex 3: only in triangle 1's triangle, and triangle 0's stencil */
      HYLC_CHECK(hylcmat_mesh_eval(M, m, xn, 0, &E, gm, hv, err, sizeof(err)) == HYLCMAT_ERR_NONFINITE && strstr(err, "triangle 0") && E == 0 && MaxAbs(gm, 12) == 0 && MaxAbs(hv, (int)hylcmat_mesh_hessian_nnz(M)) == 0, "NaN in a mesh: '%s'", err);
      free(hv);
      hylcmat_mesh_free(M);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a table smooth at II = 0 (no knot at 0 in the bending arguments): random C1 splines, knots avoiding 0 */
/* A table whose element Hessian is finite but beyond 1e154 (an sa term of values 1e100 at an sa scale of
   1e-30: 2e160 at the flat rest state): its projection squared the entries in the Householder and QR steps
   and returned HYLCMAT_ERR_NAN ("a defect"); now it is projected on the Hessian divided by a power of 2.
   Convex: the projection changes nothing but the translations' floor; concave: the result is PSD. Also
   the batch and the mesh. */
static void TestHugeProjection(void)
{
  for (int sign = 1; sign >= -1; sign -= 2) {
    const double       t[3] = {-1, 0, 1}, p[3] = {sign * 1e100, 0, sign * 1e100}, mm[3] = {-sign * 1e100, 0, sign * 1e100}, scale[5] = {1, 1e-30, 1, 100, 100};
    const double       uv[6] = {0, 0, 0.1, 0, 0, 0.1}, x[18] = {0, 0, 0, 0.1, 0, 0, 0, 0.1, 0};
    hylcmat_term1d     term = {1, 3, 0, t, p, mm};
    hylcmat           *m;
    hylcmat_shell_rest r;
    double             E0, E1, g0[18], g1[18], H0[324], H1[324], Hb[324], Eb, gb[18], amax = 0, worst = 0;
    const int          nb = 0;
    int                rc;
    char               err[256];
    HYLC_CHECK(hylcmat_create(&m) == 0 && hylcmat_set_strain_scale(m, scale, err, sizeof(err)) == 0 && hylcmat_set_term1d(m, &term, err, sizeof(err)) == 0, "the table: %s", err);
    HYLC_CHECK(hylcmat_shell_rest_uv(uv, &r) == 0, "rest");
    HYLC_CHECK(hylcmat_shell_eval(m, &r, x, 0, 0, &E0, g0, H0) == 0, "unprojected");
    rc = hylcmat_shell_eval(m, &r, x, 0, HYLCMAT_SHELL_PSD, &E1, g1, H1);
    HYLC_CHECK(rc == HYLCMAT_OK, "projection of a Hessian of 2e160 (sign %d): %s", sign, hylcmat_strerror(rc));
    for (int i = 0; i < 324; i++) amax = fmax(amax, fabs(H0[i]));
    HYLC_CHECK(amax > 1e155 && amax < 1e170, "the Hessian's largest entry %g, expected about 2e160", amax);
    if (sign > 0) /* convex: unchanged up to the floor */
      for (int i = 0; i < 324; i++) worst = fmax(worst, fabs(H1[i] - H0[i]));
    else { /* concave: v^T H1 v >= 0 for the unit vectors and their pairs */
      for (int i = 0; i < 9; i++)
        for (int j = i; j < 9; j++) {
          const double q = H1[19 * i] + H1[19 * j] + (i != j ? 2 * H1[18 * i + j] : 2 * H1[19 * i]);
          worst          = fmax(worst, -q);
        }
    }
    HYLC_CHECK(worst <= 1e-12 * amax, "sign %d: %s %g of %g", sign, sign > 0 ? "the projection changed the convex Hessian by" : "a negative curvature", worst, amax);
    rc = hylcmat_shell_eval_batch(m, 1, &r, x, &nb, HYLCMAT_SHELL_PSD, &Eb, gb, Hb);
    HYLC_CHECK(rc == HYLCMAT_OK && !memcmp(Hb, H1, sizeof(H1)), "the batch: %s, or another Hessian", hylcmat_strerror(rc));
    hylcmat_free(m);
  }
}

static hylcmat *SmoothAtZero(unsigned long long *st)
{
  hylcmat *m;
  double   t[6] = {-1.3, -0.7, -0.1, 0.4, 0.9, 1.6}, p[6], mm[6], tu[5] = {-1.2, -0.5, 0.2, 0.6, 1.3}, P[30], MU[30], MV[30], MUV[30];
  hylcmat_create(&m);
  {
    const double sc[5] = {0.8, 0.75, 0.9, 150, 230};
    hylcmat_set_strain_scale(m, sc, NULL, 0);
    hylcmat_set_constant(m, 0.1, NULL, 0);
  }
  for (int k = 0; k < 5; k++) {
    hylcmat_term1d s = {k, 6, HYLCMAT_EXT_LINEAR, t, p, mm};
    for (int i = 0; i < 6; i++) p[i] = 0.2 * t[i] * t[i] + 0.05 * Uni(st), mm[i] = 0.4 * t[i] + 0.05 * Uni(st);
    hylcmat_set_term1d(m, &s, NULL, 0);
  }
  for (int q = 0; q < HYLCMAT_N2D; q++) {
    int            k0, k1;
    hylcmat_term2d s;
    hylcmat_pair(q, &k0, &k1);
    for (int i = 0; i < 30; i++) P[i] = 0.05 * Uni(st), MU[i] = 0.05 * Uni(st), MV[i] = 0.05 * Uni(st), MUV[i] = 0.05 * Uni(st);
    s.k0 = k0, s.k1 = k1, s.nu = 5, s.nv = 6, s.ext = HYLCMAT_EXT_LINEAR, s.tu = tu, s.tv = t, s.p = P, s.mu = MU, s.mv = MV, s.muv = MUV;
    hylcmat_set_term2d(m, &s, NULL, 0);
  }
  return m;
}

/* a table fitted by HylcFit from the synthetic samples of fittest.h (family: woven or stockinette) */
static PetscErrorCode Fitted(const char *family, HylcMaterial mat)
{
  HylcFit    fit;
  PetscInt   n, *term;
  PetscReal *z, *psi;
  char       opt[64];

  PetscFunctionBegin;
  FitTestMakeData(family, 150, 20, -1, &n, &z, &psi, &term);
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-fit_family %s", family));
  PetscCall(PetscOptionsInsertString(NULL, opt));
  PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
  PetscCall(HylcFitSetFromOptions(fit));
  PetscCall(HylcFitSetData(fit, n, z, psi, term, 0.3));
  PetscCall(HylcFitCompute(fit));
  PetscCall(HylcFitRun(fit, mat));
  PetscCall(HylcFitDestroy(&fit));
  PetscCall(PetscOptionsClearValue(NULL, "-fit_family"));
  free(z), free(psi), free(term);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  unsigned long long st = 31;
  char               dir[PETSC_MAX_PATH_LEN];
  PetscBool          have;
  const char        *files[] = {"basket1", "honey1", "rib1", "rib1_noreg", "satin01", "satin1", "stock01", "stock1", "stock1_bad"};
  Stats              all;
  double             rig[3]  = {0, 0, 0};
  int                ntables = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-v", &Verbose, NULL));
  memset(&all, 0, sizeof(all));
  TestConventions();
  TestHugeProjection();
  PetscCall(TestCylinder());
  /* fitted tables */
  for (int f = 0; f < 2; f++) {
    HylcMaterial mat;
    const char  *fam = f ? "stockinette" : "woven";
    char         name[64];
    PetscCall(PetscSNPrintf(name, sizeof(name), "fit-%s", fam));
    PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &mat));
    PetscCall(Fitted(fam, mat));
    PetscCall(TestTable(mat->hm, name, 125, &st, &all));
    TestRigid(mat->hm, name, &st, rig);
    PetscCall(TestFlatMesh(mat->hm, name, 1, &st));
    if (!f) PetscCall(TestErrors(mat->hm));
    TestBatch(mat->hm, &st);
    PetscCall(HylcMaterialDestroy(&mat));
    ntables++;
  }
  /* a table smooth at II = 0: central differences in every direction at flat states */
  {
    hylcmat *m = SmoothAtZero(&st);
    Stats    s;
    memset(&s, 0, sizeof(s));
    for (int it = 0; it < 40; it++) {
      Stencil S;
      char    what[64];
      MakeStencil(K_FLAT, 100, 0.1, &st, &S);
      PetscCall(PetscSNPrintf(what, sizeof(what), "smooth table, flat stencil %d", it));
      CheckFD(m, &S, 1e-6 * S.L, what, &s);
    }
    HYLC_CHECK(s.tested >= 36, "smooth table: only %d of 40 flat stencils tested", s.tested);
    if (Verbose) PetscCall(PetscPrintf(PETSC_COMM_SELF, "  smooth-at-0 flat stencils, every direction: %d tested, worst gradient %.2e Hessian %.2e\n", s.tested, s.worstg, s.worstH));
    hylcmat_free(m);
  }
  {
    const char *env = getenv("HYLC_REFDATA");
    PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/materials", env ? env : "../shared/refdata"));
  }
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (have) {
    for (size_t f = 0; f < sizeof(files) / sizeof(files[0]); f++) {
      char     path[PETSC_MAX_PATH_LEN], err[512];
      hylcmat *m;
      PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.json", dir, files[f]));
      HYLC_CHECK(hylcmat_load(path, &m, err, sizeof(err)) == 0, "%s", err);
      PetscCall(TestTable(m, files[f], 110, &st, &all));
      TestRigid(m, files[f], &st, rig);
      PetscCall(TestFlatMesh(m, files[f], 0, &st));
      hylcmat_free(m);
      ntables++;
    }
  } else
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "note: %s not found: the checks on the paper's tables were skipped\n", dir));
  HYLC_CHECK(all.tested >= (have ? 1000 : 200), "only %d stencils tested", all.tested);
  if (Verbose) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%d tables, %d stencils tested (%d skipped: a knot inside the differences): worst gradient %.2e, Hessian %.2e (relative to the largest entry), projection vs LAPACK %.2e\n", ntables, all.tested, all.skipped,
                          all.worstg, all.worstH, all.worstP));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "rigid motions (translations up to 10 m): relative changes E %.2e, gradient %.2e, Hessian %.2e\n", rig[0], rig[1], rig[2]));
  }
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
