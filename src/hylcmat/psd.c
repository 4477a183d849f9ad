/* Projection of an element Hessian (18 x 18) to positive semidefinite: eigenvalues below
   HYLCMAT_PSD_FLOOR raised to it, on the coordinates of the vertices present (src/hylcmat/shell.c has
   the outline). The symmetric eigensolver (n <= 15 after the translations are split off):
   Householder tridiagonalization with the reflections accumulated, then the implicit symmetric QR
   step with Wilkinson's shift (Golub and Van Loan, Matrix Computations, 4th ed., 8.3.1-8.3.3), the
   rotations applied to the rows of the accumulated transform (eigenvectors as rows). Plain C99. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

#define NMAX 18

/* A (n x n, row-major, symmetric; overwritten) = Z^T diag(w) Z: eigenvalues w, eigenvectors the rows
   of Z. Returns 0, or -1 if the QR iteration did not converge (never seen; the caller fails). */
static int SymEig(int n, double *A, double *w, double *Z)
{
  double d[NMAX], e[NMAX], v[NMAX], p[NMAX], beta[NMAX];

  /* tridiagonalize: for column k, the reflection I - beta v v^T of rows k+1.. (v stored in A's column k) */
  for (int k = 0; k + 2 < n; k++) {
    const int m  = n - k - 1; /* length of the vector */
    double    xn = 0, alpha, vv, K;
    double   *x  = v;
    for (int i = 0; i < m; i++) {
      x[i] = A[n * (k + 1 + i) + k];
      xn += x[i] * x[i];
    }
    xn = sqrt(xn);
    if (xn == 0) {
      beta[k] = 0;
      e[k]    = 0;
      for (int i = 0; i < m; i++) A[n * (k + 1 + i) + k] = 0;
      continue;
    }
    alpha = x[0] > 0 ? -xn : xn;
    x[0] -= alpha;
    vv = 0;
    for (int i = 0; i < m; i++) vv += x[i] * x[i];
    beta[k] = 2 / vv;
    e[k]    = alpha;
    /* p = beta A22 v; K = beta p.v / 2; q = p - K v; A22 -= v q^T + q v^T (lower triangle used) */
    for (int i = 0; i < m; i++) {
      const double *row = A + n * (k + 1 + i) + k + 1;
      double        s   = 0;
      for (int j = 0; j < m; j++) s += row[j] * x[j];
      p[i] = beta[k] * s;
    }
    K = 0;
    for (int i = 0; i < m; i++) K += p[i] * x[i];
    K *= 0.5 * beta[k];
    for (int i = 0; i < m; i++) p[i] -= K * x[i];
    for (int i = 0; i < m; i++) {
      double *row = A + n * (k + 1 + i) + k + 1;
      for (int j = 0; j < m; j++) row[j] -= x[i] * p[j] + p[i] * x[j];
    }
    for (int i = 0; i < m; i++) A[n * (k + 1 + i) + k] = x[i];
  }
  for (int k = 0; k < n; k++) d[k] = A[n * k + k];
  if (n >= 2) e[n - 2] = A[n * (n - 1) + n - 2];
  e[n - 1] = 0;
  /* Q = H_0 H_1 ... H_{n-3} (T = Q^T A Q); Z = Q^T = H_{n-3} ... H_0, built as Z <- Z H_k from k = n-3
     down (rows 0..k of Z are still those of I there, zero in the columns k+1.. that H_k mixes) */
  memset(Z, 0, sizeof(double) * n * n);
  for (int i = 0; i < n; i++) Z[n * i + i] = 1;
  for (int k = n - 3; k >= 0; k--) {
    const int m = n - k - 1;
    if (beta[k] == 0) continue;
    for (int i = 0; i < m; i++) v[i] = A[n * (k + 1 + i) + k];
    for (int i = k + 1; i < n; i++) {
      double *row = Z + n * i + k + 1, s = 0;
      for (int j = 0; j < m; j++) s += row[j] * v[j];
      s *= beta[k];
      for (int j = 0; j < m; j++) row[j] -= s * v[j];
    }
  }
  /* the eigenvectors of A are Q s for those s of T; as rows s^T Q^T = s^T Z: each rotation G of T
     (T <- G^T T G) updates Z <- G^T Z, two rows */
  {
    int       hi = n - 1, it = 0;
    const int maxit = 40 * n;
    while (hi > 0) {
      int lo;
      /* deflate negligible off-diagonals at the bottom */
      if (fabs(e[hi - 1]) <= 1e-300 + 2.220446049250313e-16 * (fabs(d[hi - 1]) + fabs(d[hi]))) {
        e[hi - 1] = 0;
        hi--;
        continue;
      }
      if (++it > maxit) return -1;
      /* the unreduced block lo..hi */
      lo = hi - 1;
      while (lo > 0 && fabs(e[lo - 1]) > 1e-300 + 2.220446049250313e-16 * (fabs(d[lo - 1]) + fabs(d[lo]))) lo--;
      if (lo > 0) e[lo - 1] = 0;
      {
        /* Wilkinson shift from the trailing 2 x 2 */
        const double dd = 0.5 * (d[hi - 1] - d[hi]), b = e[hi - 1], hyp = hypot(dd, b);
        const double mu = d[hi] - b * b / (dd + (dd >= 0 ? hyp : -hyp));
        double       x = d[lo] - mu, z = e[lo];
        for (int k = lo; k < hi; k++) {
          double c, s, r, a0, b0, d0;
          /* G = [c s; -s c] with s x + c z = 0 */
          if (z == 0) {
            c = 1;
            s = 0;
            r = x;
          } else {
            r = hypot(x, z);
            c = x / r;
            s = -z / r;
          }
          if (k > lo) e[k - 1] = c * e[k - 1] - s * z; /* (k-1, k); (k-1, k+1) becomes 0 */
          (void)r;
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
          {
            double *zk = Z + n * k, *zk1 = Z + n * (k + 1);
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

int hm_psd_project(double H[324], int nb)
{
  int    act[6], na = 0, n;
  double Hc[NMAX * NMAX], v[6], vv = 0, Z[NMAX * NMAX], w[NMAX], M[(NMAX - 3) * (NMAX - 3)];
  double floor_ = HYLCMAT_PSD_FLOOR;

  for (int i = 0; i < 3; i++) act[na++] = i;
  for (int k = 0; k < 3; k++)
    if (nb >> k & 1) act[na++] = 3 + k;
  n = 3 * na;
  for (int i = 0; i < na; i++)
    for (int a = 0; a < 3; a++)
      for (int j = 0; j < na; j++)
        for (int b = 0; b < 3; b++) Hc[n * (3 * i + a) + 3 * j + b] = H[18 * (3 * act[i] + a) + 3 * act[j] + b];
  /* the reflection P = I - 2 v v^T / v.v over the vertices, v = e_0 + 1 / sqrt(na): P e_0 = -1/sqrt(na) */
  for (int i = 0; i < na; i++) v[i] = 1 / sqrt((double)na);
  v[0] += 1;
  for (int i = 0; i < na; i++) vv += v[i] * v[i];
  /* Hc <- (P x I3) Hc (P x I3): rows, then columns */
  for (int pass = 0; pass < 2; pass++) {
    for (int c = 0; c < n; c++)
      for (int a = 0; a < 3; a++) {
        double s = 0;
        for (int i = 0; i < na; i++) s += v[i] * (pass ? Hc[n * c + 3 * i + a] : Hc[n * (3 * i + a) + c]);
        s *= 2 / vv;
        for (int i = 0; i < na; i++) {
          if (pass)
            Hc[n * c + 3 * i + a] -= s * v[i];
          else
            Hc[n * (3 * i + a) + c] -= s * v[i];
        }
      }
  }
  /* the translations: first vertex block -> floor I, its coupling -> 0 */
  {
    const int nm = n - 3;
    for (int i = 0; i < nm; i++)
      for (int j = 0; j < nm; j++) M[nm * i + j] = Hc[n * (3 + i) + 3 + j];
    if (SymEig(nm, M, w, Z)) return HYLCMAT_ERR_NAN;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < n; j++) Hc[n * i + j] = Hc[n * j + i] = 0;
    for (int i = 0; i < 3; i++) Hc[n * i + i] = floor_;
    for (int q = 0; q < nm; q++) {
      const double s = floor_ - w[q];
      if (!(s > 0)) continue;
      for (int i = 0; i < nm; i++)
        for (int j = 0; j < nm; j++) Hc[n * (3 + i) + 3 + j] += s * Z[nm * q + i] * Z[nm * q + j];
    }
  }
  /* undo the reflection */
  for (int pass = 0; pass < 2; pass++) {
    for (int c = 0; c < n; c++)
      for (int a = 0; a < 3; a++) {
        double s = 0;
        for (int i = 0; i < na; i++) s += v[i] * (pass ? Hc[n * c + 3 * i + a] : Hc[n * (3 * i + a) + c]);
        s *= 2 / vv;
        for (int i = 0; i < na; i++) {
          if (pass)
            Hc[n * c + 3 * i + a] -= s * v[i];
          else
            Hc[n * (3 * i + a) + c] -= s * v[i];
        }
      }
  }
  for (int i = 0; i < n; i++)
    for (int j = i + 1; j < n; j++) Hc[n * i + j] = Hc[n * j + i] = 0.5 * (Hc[n * i + j] + Hc[n * j + i]);
  for (int i = 0; i < na; i++)
    for (int a = 0; a < 3; a++)
      for (int j = 0; j < na; j++)
        for (int b = 0; b < 3; b++) H[18 * (3 * act[i] + a) + 3 * act[j] + b] = Hc[n * (3 * i + a) + 3 * j + b];
  return HYLCMAT_OK;
}
