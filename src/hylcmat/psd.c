/* Projection of an element Hessian (18 x 18) to positive semidefinite: eigenvalues below
   HYLCMAT_PSD_FLOOR raised to it, on the coordinates of the vertices present.

   The translations t (one per axis) are exact null vectors of H (E depends on edge vectors only). With
   the reflection P = I - tau v v^T over the na vertices present (v = e_0 + 1/sqrt(na), so P e_0 is the
   unit translation), (P x I3) H (P x I3) has a zero first vertex block row and column; its remaining
   (3 na - 3)-square block M holds the rest of the spectrum. M = Z^T diag(lambda) Z by the symmetric
   eigensolver below, and with u_q = (P x I3) [0; z_q] (the eigenvectors in the original coordinates)
       H+ = H + floor / na (1 1^T x I3) + sum over lambda_q < floor of (floor - lambda_q) u_q u_q^T,
   the first term raising the translations' zero eigenvalues to the floor: the same as clamping the
   eigenvalues of the whole matrix.

   The eigensolver (n <= 15; Golub and Van Loan, Matrix Computations, 4th ed., 8.3): Householder
   tridiagonalization T = Q^T M Q (the reflections kept; only the lower triangle is read and updated),
   implicit symmetric QR steps with Wilkinson's shift on T with the rotations accumulated into T's
   eigenvectors (rows of Z, from the identity), and Q applied only to the eigenvectors of the clamped
   eigenvalues. (Computing only those by inverse iteration instead takes fewer instructions but more
   time: its triangular solves are serial chains, while the rotations' vector updates overlap the QR
   steps' own chain of square roots and divisions, which sets the pace.) Plain C99. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

#define NMAX 15 /* 3 (6 vertices - 1) */
#define EPS  2.220446049250313e-16

/* sqrt(x^2 + z^2) without overflow or underflow of the squares */
static inline double Norm2(double x, double z)
{
  const double r = sqrt(x * x + z * z);
  if (r > 1e-290 && r < 1e290) return r; /* the squares did not overflow or underflow */
  {
    const double ax = fabs(x), az = fabs(z), mx = ax > az ? ax : az;
    if (mx == 0) return 0;
    return mx * sqrt((x / mx) * (x / mx) + (z / mx) * (z / mx));
  }
}

/* Householder tridiagonalization of A (n x n, row-major, symmetric: only its lower triangle is read;
   overwritten): T = Q^T A Q with
   diagonal d and off-diagonal e (e[n-1] = 0); the reflections of Q in the rows of Vr (row k: beta_k at
   k, the vector from k + 1), which BackTransform applies */
static void Tridiagonalize(int n, double *restrict A, double *restrict d, double *restrict e, double *restrict Vr)
{
  double beta[NMAX];

  /* tridiagonalize: for column k, the reflection I - beta v v^T of rows k+1.. (v kept in column k) */
  for (int k = 0; k + 2 < n; k++) {
    const int m = n - k - 1;
    double    x[NMAX], p[NMAX], xn = 0, alpha, vv, K = 0;
    for (int i = 0; i < m; i++) {
      x[i] = A[n * (k + 1 + i) + k];
      xn += x[i] * x[i];
    }
    xn = sqrt(xn);
    if (xn == 0) {
      beta[k] = 0;
      e[k]    = 0;
      continue;
    }
    alpha = x[0] > 0 ? -xn : xn;
    x[0] -= alpha;
    vv = xn * xn - 2 * alpha * (x[0] + alpha) + alpha * alpha; /* |x - alpha e0|^2 = |x|^2 - 2 alpha x0 + alpha^2 */
    if (!(vv > 0)) {
      vv = 0;
      for (int i = 0; i < m; i++) vv += x[i] * x[i];
    }
    beta[k] = 2 / vv;
    e[k]    = alpha;
    /* p = beta A22 v from A22's lower triangle; K = beta p.v / 2; p -= K v; A22 -= v p^T + p v^T (lower) */
    for (int i = 0; i < m; i++) p[i] = 0;
    for (int i = 0; i < m; i++) {
      const double *restrict row = A + n * (k + 1 + i) + k + 1;
      const double xi            = x[i];
      double       t             = row[i] * xi;
      for (int j = 0; j < i; j++) {
        t += row[j] * x[j];
        p[j] += row[j] * xi;
      }
      p[i] += t;
    }
    for (int i = 0; i < m; i++) p[i] *= beta[k];
    for (int i = 0; i < m; i++) K += p[i] * x[i];
    K *= 0.5 * beta[k];
    for (int i = 0; i < m; i++) p[i] -= K * x[i];
    for (int i = 0; i < m; i++) {
      double *restrict row = A + n * (k + 1 + i) + k + 1;
      const double xi = x[i], pi = p[i];
      for (int j = 0; j <= i; j++) row[j] -= xi * p[j] + pi * x[j];
    }
    for (int i = 0; i < m; i++) Vr[n * k + k + 1 + i] = x[i];
  }
  for (int k = 0; k + 2 < n; k++) Vr[n * k + k] = beta[k];
  for (int k = 0; k < n; k++) d[k] = A[n * k + k];
  if (n >= 2) e[n - 2] = A[n * (n - 1) + n - 2];
  e[n - 1] = 0;
}

/* the eigenvalues w (unsorted) of the tridiagonal (d, e) (overwritten) by implicit QR steps; with Z (n x n,
   set to I here) the rotations are accumulated into its rows, which become T's eigenvectors. Returns 0,
   or -1 if the iteration did not converge. */
static int TridiagQR(int n, double *restrict d, double *restrict e, double *restrict w, double *restrict Z)
{
  if (Z) {
    memset(Z, 0, sizeof(double) * n * n);
    for (int i = 0; i < n; i++) Z[n * i + i] = 1;
  }
  /* implicit QR steps on the trailing unreduced block; each rotation G of T (T <- G^T T G) updates
     Z <- G^T Z, two rows. An off-diagonal entry below eps |T| (the largest |d| + 2 |e|) is negligible:
     the result is needed to rounding relative to |H| (the floor is 1e-8), not to each eigenvalue's own
     relative accuracy, and that takes fewer steps when the eigenvalues span many magnitudes */
  {
    int    hi = n - 1, it = 0;
    double tnorm = 0;
    for (int i = 0; i < n; i++) tnorm = fmax(tnorm, fabs(d[i]) + fabs(e[i]) + (i ? fabs(e[i - 1]) : 0));
    tnorm           = 1e-300 + EPS * tnorm;
    const int maxit = 40 * n;
    while (hi > 0) {
      int lo;
      if (fabs(e[hi - 1]) <= tnorm) {
        e[hi - 1] = 0;
        hi--;
        continue;
      }
      if (++it > maxit) return -1;
      lo = hi - 1;
      while (lo > 0 && fabs(e[lo - 1]) > tnorm) lo--;
      if (lo > 0) e[lo - 1] = 0;
      {
        /* Wilkinson's shift from the trailing 2 x 2 */
        const double dd = 0.5 * (d[hi - 1] - d[hi]), b = e[hi - 1], hyp = Norm2(dd, b);
        const double mu = d[hi] - b * b / (dd + (dd >= 0 ? hyp : -hyp));
        double       x = d[lo] - mu, z = e[lo];
        for (int k = lo; k < hi; k++) {
          double c = 1, s = 0, a0, b0, d0;
          /* G = [c s; -s c] with s x + c z = 0 */
          if (z != 0) {
            const double ir = 1 / Norm2(x, z);
            c               = x * ir;
            s               = -z * ir;
          }
          if (k > lo) e[k - 1] = c * e[k - 1] - s * z; /* (k-1, k); (k-1, k+1) becomes 0 */
          a0       = d[k];
          b0       = e[k];
          d0       = d[k + 1];
          d[k]     = c * c * a0 - 2 * c * s * b0 + s * s * d0;
          d[k + 1] = s * s * a0 + 2 * c * s * b0 + c * c * d0;
          e[k]     = c * s * (a0 - d0) + (c * c - s * s) * b0;
          if (k + 1 < hi) {
            z = -s * e[k + 1];
            e[k + 1] *= c;
            x = e[k];
          }
          if (Z) {
            double *restrict zk = Z + n * k, *restrict zk1 = Z + n * (k + 1);
            for (int j = 0; j < n; j++) {
              const double u = zk[j], t = zk1[j];
              zk[j]  = c * u - s * t;
              zk1[j] = s * u + c * t;
            }
          }
        }
      }
    }
  }
  for (int i = 0; i < n; i++) w[i] = d[i];
  return 0;
}

/* z <- Q z with Q = H_0 H_1 ... H_{n-3} kept in Vr by Tridiagonalize */
static void BackTransform(int n, const double *restrict Vr, double *restrict z)
{
  for (int k = n - 3; k >= 0; k--) {
    const int    m           = n - k - 1;
    const double beta        = Vr[n * k + k];
    const double *restrict v = Vr + n * k + k + 1;
    double *restrict zz      = z + k + 1;
    double t                 = 0;
    if (beta == 0) continue;
    for (int i = 0; i < m; i++) t += v[i] * zz[i];
    t *= beta;
    for (int i = 0; i < m; i++) zz[i] -= t * v[i];
  }
}

int hm_psd_project(double H[324], int nb)
{
  int          act[6], idx[18], na = 0, n, nm;
  double       v[6], vv = 0, tau, R[6][9], C[9], M[NMAX * NMAX], Z[NMAX * NMAX], Vr[NMAX * NMAX], w[NMAX], W[18 * 18];
  const double floor_ = HYLCMAT_PSD_FLOOR;

  for (int i = 0; i < 3; i++) act[na++] = i;
  for (int k = 0; k < 3; k++)
    if (nb >> k & 1) act[na++] = 3 + k;
  n  = 3 * na;
  nm = n - 3;
  for (int i = 0; i < n; i++) idx[i] = 3 * act[i / 3] + i % 3;
  for (int i = 0; i < na; i++) v[i] = 1 / sqrt((double)na);
  v[0] += 1;
  for (int i = 0; i < na; i++) vv += v[i] * v[i];
  tau = 2 / vv;
  /* blocks B_ij of the vertices present; R_j = sum_i v_i B_ij, C = sum_j v_j R_j; then the blocks
     (i, j >= 1) of P B P: B_ij - tau v_i R_j - tau R_i^T v_j + tau^2 v_i v_j C */
  for (int j = 0; j < na; j++)
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        double t = 0;
        for (int i = 0; i < na; i++) t += v[i] * H[18 * (3 * act[i] + a) + 3 * act[j] + b];
        R[j][3 * a + b] = t;
      }
  for (int q = 0; q < 9; q++) {
    double s = 0;
    for (int j = 0; j < na; j++) s += v[j] * R[j][q];
    C[q] = s;
  }
  for (int i = 1; i < na; i++)
    for (int j = i; j < na; j++)
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
          const double t                              = H[18 * (3 * act[i] + a) + 3 * act[j] + b] - tau * v[i] * R[j][3 * a + b] - tau * v[j] * R[i][3 * b + a] + tau * tau * v[i] * v[j] * C[3 * a + b];
          M[nm * (3 * (j - 1) + b) + 3 * (i - 1) + a] = t; /* lower triangle (and the upper part of diagonal blocks) */
        }
  {
    double d[NMAX], e[NMAX];
    Tridiagonalize(nm, M, d, e, Vr);
    if (TridiagQR(nm, d, e, w, Z)) return HYLCMAT_ERR_NAN;
  }
  /* the translations: + floor / na on the diagonal of every vertex block pair */
  for (int i = 0; i < na; i++)
    for (int j = 0; j < na; j++)
      for (int a = 0; a < 3; a++) H[18 * (3 * act[i] + a) + 3 * act[j] + a] += floor_ / na;
  /* the clamped eigenvalues: u = (P x I3) [0; Q s]; W = sum (floor - lambda) u u^T (compact, upper
     triangle), then added to H */
  {
    int clamped = 0;
    for (int q = 0; q < nm; q++) {
      const double s = floor_ - w[q];
      double       u[18], dot[3] = {0, 0, 0};
      if (!(s > 0)) continue;
      if (!clamped++) memset(W, 0, sizeof(double) * n * n);
      for (int a = 0; a < 3; a++) u[a] = 0;
      for (int i = 0; i < nm; i++) u[3 + i] = Z[nm * q + i];
      BackTransform(nm, Vr, u + 3);
      for (int i = 1; i < na; i++)
        for (int a = 0; a < 3; a++) dot[a] += v[i] * u[3 * i + a];
      for (int i = 0; i < na; i++)
        for (int a = 0; a < 3; a++) u[3 * i + a] -= tau * v[i] * dot[a];
      for (int i = 0; i < n; i++) {
        double *restrict row = W + n * i;
        const double su      = s * u[i];
        for (int j = i; j < n; j++) row[j] += su * u[j];
      }
    }
    if (clamped)
      for (int i = 0; i < n; i++) {
        double *restrict row = H + 18 * idx[i];
        row[idx[i]] += W[n * i + i];
        for (int j = i + 1; j < n; j++) {
          row[idx[j]] += W[n * i + j];
          H[18 * idx[j] + idx[i]] = row[idx[j]];
        }
      }
  }
  return HYLCMAT_OK;
}
