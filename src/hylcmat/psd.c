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
   eigenvalues, all of them together. (Computing only those by inverse iteration instead takes fewer
   instructions but more time: its triangular solves are serial chains, while the rotations' vector
   updates overlap the QR steps' own chain of divisions, which sets the pace.) Plain C99.

   Where the time goes (issue 31; 2026-11-27, one core of a 2.3 GHz Xeon shared with other work; TSC
   cycles per six-vertex element, the least of repeated timings of 40 elements, over the elements of
   bench_shell's mesh): forming M 0.7k (1.0k before its sums ran along H's rows), tridiagonalization
   2.6k, QR 8.0k alone (~22.5 sweeps, ~190 rotations; 12.7k before its chain lost the square root and
   the unit-at-a-time state machine gave way to a loop per sweep), the clamped eigenvectors and H's
   update 2.5k (4.8k before they were back-transformed together and added over full rows); the whole
   projection 13.9k alone, 12.5k per element in pairs (21.7k alone and 18.2k four in turn before).
   Not done, measured: a positive-definiteness test first (a Cholesky factorization) would never
   pay, since no element of the bench's stencils or of its mesh is positive definite (H = J^T Psi'' J,
   of rank <= 6 for the six strains, plus the stress term leaves ~9 eigenvalues to that term's sign;
   six are clamped in 99 % of the mesh's elements, 6 or 7 in the stencils'); the tridiagonalization
   over the full square with AVX2 and shorter chains of additions (no faster, or slower); Z's padded
   rows in the two-matrix loop and a padded column stride in BackTransform (slower). A split
   tridiagonal's upper block could be a second chain, but splits above the bottom block start 1.3 %
   of the sweeps. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

#define NMAX 15 /* 3 (6 vertices - 1) */
#define ZS   16 /* the row stride of Z (its last entry 0) */

/* GCC on x86-64 Linux (glibc's ifunc): the function also compiled for AVX2, the version chosen at load
   time; the same results (no FMA contraction in either) */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#  define AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#  define AVX2_CLONES
#endif
#define EPS 2.220446049250313e-16

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

/* Implicit QR steps on a tridiagonal (d, e) (overwritten; its eigenvalues end in d), the rotations
   accumulated into the rows of Z (set to I here), which become T's eigenvectors. An off-diagonal entry
   below eps |T| (|T| the largest |d| + 2 |e|) is negligible: the result is needed to rounding relative
   to |H| (the floor is 1e-8), not to each eigenvalue's relative accuracy, and that takes fewer steps
   when the eigenvalues span many magnitudes.

   A sweep's rotations are a chain (each rotation's bulge comes from the previous one), which sets the
   pace: the rotations' updates of Z are independent work the processor overlaps with it. The chain is
   kept short: with R = x^2 + z^2 of the bulge (x, z), c^2 = x^2 / R, s^2 = z^2 / R and c s = -x z / R
   give the new diagonal and the next x = e[k] without a square root (x = ((x^2 - z^2) b - x z
   (a - d[k + 1])) / R with a, b the d[k], e[k] being rotated: its numerator formed alongside the
   division), and the next R = e[k]^2 + s^2
   e[k + 1]^2 (the next z being -s e[k + 1]); c = x / sqrt(R) and s = -z / sqrt(R) themselves, which
   the next rotation needs only for its products x z and c e[k + 1], and the update of Z come off that
   chain (R outside (1e-290, 1e290): c and s from Norm2). The carried values (the bulge, R, the
   entries d[k + 1] and e[k + 1] being rotated) stay in registers across a sweep's loop, and two
   matrices' sweeps run in one loop (TridiagQR2) so that their chains overlap. One matrix alone updates
   Z's whole padded rows (four AVX2 vectors; measured slower in the two-matrix loop, which keeps n). */
typedef struct {
  int     n, hi, it, maxit;
  double *d, *e, *Z, tnorm;
} QRState;

/* a sweep in progress: the next rotation at k (lo <= k < hi), the bulge (x, z) with R = x^2 + z^2,
   a = d[k] and b = e[k] as rotated so far */
typedef struct {
  int    k, lo, hi;
  double x, z, a, b, R;
} Sweep;

static void QRInit(QRState *q, int n, double *d, double *e, double *Z)
{
  double tn = 0;
  memset(Z, 0, sizeof(double) * ZS * n);
  for (int i = 0; i < n; i++) Z[ZS * i + i] = 1;
  for (int i = 0; i < n; i++) tn = fmax(tn, fabs(d[i]) + fabs(e[i]) + (i ? fabs(e[i - 1]) : 0));
  q->n = n, q->hi = n - 1, q->it = 0, q->maxit = 40 * n;
  q->d = d, q->e = e, q->Z = Z, q->tnorm = 1e-300 + EPS * tn;
}

/* deflation, then the next sweep's start with Wilkinson's shift from the trailing 2 x 2; returns 1 with
   a sweep to run, 0 when the iteration is done, -1 if it did not converge */
static inline int SweepStart(QRState *restrict q, Sweep *restrict w)
{
  double *restrict d = q->d, *restrict e = q->e;

  while (q->hi > 0) {
    const int hi = q->hi;
    int       lo = hi - 1;
    if (fabs(e[hi - 1]) <= q->tnorm) {
      e[hi - 1] = 0;
      q->hi--;
      continue;
    }
    if (++q->it > q->maxit) return -1;
    while (lo > 0 && fabs(e[lo - 1]) > q->tnorm) lo--;
    if (lo > 0) e[lo - 1] = 0;
    {
      const double dd = 0.5 * (d[hi - 1] - d[hi]), b = e[hi - 1], hyp = Norm2(dd, b);
      const double mu = d[hi] - b * b / (dd + (dd >= 0 ? hyp : -hyp));
      w->x = d[lo] - mu, w->z = e[lo];
    }
    w->k = w->lo = lo, w->hi = hi, w->a = d[lo], w->b = e[lo], w->R = w->x * w->x + w->z * w->z;
    return 1;
  }
  return 0;
}

/* the rotation G = [c s; -s c] of rows and columns k, k + 1 with s x + c z = 0 */
static inline void Rotate(const QRState *restrict q, Sweep *restrict w, int nz)
{
  double *restrict d = q->d, *restrict e = q->e;
  const int    k = w->k, hi = w->hi;
  const double x = w->x, z = w->z, a = w->a, b = w->b, R = w->R, d0 = d[k + 1], e1 = k + 1 < hi ? e[k + 1] : 0;
  double       c, s, r, cc, ss, cs, en;

  if (R > 1e-290 && R < 1e290) {
    const double iR = 1 / R, xx = x * x, zz = z * z, xz = x * z;
    r = sqrt(R), cc = xx * iR, ss = zz * iR, cs = -xz * iR;
    c = x / r, s = -z / r;
    en = ((xx - zz) * b - xz * (a - d0)) * iR; /* its numerator alongside the division */
  } else {
    r = Norm2(x, z);
    if (r == 0)
      c = 1, s = 0;
    else
      c = x / r, s = -z / r;
    cc = c * c, ss = s * s, cs = c * s;
    en = cs * (a - d0) + (cc - ss) * b;
  }
  if (k > w->lo) e[k - 1] = r; /* (k - 1, k): c x - s z; (k - 1, k + 1) becomes 0 */
  d[k] = cc * a - 2 * cs * b + ss * d0;
  e[k] = en;
  w->a = ss * a + 2 * cs * b + cc * d0;
  w->R = en * en + ss * (e1 * e1);
  w->x = en;
  w->z = -s * e1;
  w->b = c * e1;
  if (k + 1 < hi) e[k + 1] = w->b;
  {
    double *restrict zk = q->Z + ZS * k, *restrict zk1 = zk + ZS;
    for (int j = 0; j < nz; j++) {
      const double u = zk[j], t = zk1[j];
      zk[j]  = c * u - s * t;
      zk1[j] = s * u + c * t;
    }
  }
  w->k = k + 1;
}

/* the QR iteration of one matrix from its state st of SweepStart (a sweep in w if st = 1); 0, or -1 if
   it did not converge */
static inline int QRFinish(QRState *restrict q, Sweep *restrict w, int st)
{
  for (; st > 0; st = SweepStart(q, w)) {
    Sweep v = *w;
    while (v.k < v.hi) Rotate(q, &v, q->n);
    q->d[v.hi] = v.a;
  }
  return st;
}

AVX2_CLONES
static int TridiagQR1(QRState *q)
{
  Sweep w;
  int   st;
  while ((st = SweepStart(q, &w)) > 0) {
    Sweep v = w;
    while (v.k < v.hi) Rotate(q, &v, ZS);
    q->d[v.hi] = v.a;
  }
  return st;
}

/* two matrices: their sweeps' rotations alternate, in one loop while both have a sweep to run (the
   same arithmetic as TridiagQR1 on each) */
AVX2_CLONES
static int TridiagQR2(QRState *q0, QRState *q1)
{
  Sweep w0, w1;
  int   s0 = SweepStart(q0, &w0), s1 = SweepStart(q1, &w1);

  while (s0 > 0 && s1 > 0) {
    Sweep     v0 = w0, v1 = w1;
    const int len = v0.hi - v0.k < v1.hi - v1.k ? v0.hi - v0.k : v1.hi - v1.k;
    for (int i = 0; i < len; i++) {
      Rotate(q0, &v0, q0->n);
      Rotate(q1, &v1, q1->n);
    }
    w0 = v0, w1 = v1;
    if (w0.k == w0.hi) q0->d[w0.hi] = w0.a, s0 = SweepStart(q0, &w0);
    if (w1.k == w1.hi) q1->d[w1.hi] = w1.a, s1 = SweepStart(q1, &w1);
  }
  if (s0 < 0 || s1 < 0) return -1;
  return s0 > 0 ? QRFinish(q0, &w0, s0) : QRFinish(q1, &w1, s1);
}

/* Y <- Q Y with Q = H_0 H_1 ... H_{n-3} kept in Vr by Tridiagonalize, for the nc columns of Y (n x nc,
   row-major): the columns' dot products with a reflection's vector side by side */
static void BackTransform(int n, const double *restrict Vr, int nc, double *restrict Y)
{
  for (int k = n - 3; k >= 0; k--) {
    const int    m           = n - k - 1;
    const double beta        = Vr[n * k + k];
    const double *restrict v = Vr + n * k + k + 1;
    double *restrict yy      = Y + nc * (k + 1);
    double t[NMAX];
    if (beta == 0) continue;
    for (int c = 0; c < nc; c++) t[c] = 0;
    for (int i = 0; i < m; i++)
      for (int c = 0; c < nc; c++) t[c] += v[i] * yy[nc * i + c];
    for (int c = 0; c < nc; c++) t[c] *= beta;
    for (int i = 0; i < m; i++)
      for (int c = 0; c < nc; c++) yy[nc * i + c] -= t[c] * v[i];
  }
}

/* the work of one element's projection */
typedef struct {
  double *H;
  double  floor; /* HYLCMAT_PSD_FLOOR in the units of H (divided by its scale) */
  int     act[6], idx[18], na, n, nm;
  double  v[6], tau, M[NMAX * NMAX], Z[ZS * NMAX], Vr[NMAX * NMAX], d[NMAX], e[NMAX];
} Proj;

/* M = the rows and columns 3.. of (P x I3) H (P x I3) over the vertices present, tridiagonalized */
static void ProjPrepare(Proj *p, double *H, int nb)
{
  double R[6][9], C[9], vv = 0;
  int    na = 0, nm;

  p->H     = H;
  p->floor = HYLCMAT_PSD_FLOOR;
  for (int i = 0; i < 3; i++) p->act[na++] = i;
  for (int k = 0; k < 3; k++)
    if (nb >> k & 1) p->act[na++] = 3 + k;
  p->na = na, p->n = 3 * na, p->nm = nm = 3 * na - 3;
  for (int i = 0; i < p->n; i++) p->idx[i] = 3 * p->act[i / 3] + i % 3;
  for (int i = 0; i < na; i++) p->v[i] = 1 / sqrt((double)na);
  p->v[0] += 1;
  for (int i = 0; i < na; i++) vv += p->v[i] * p->v[i];
  p->tau = 2 / vv;
  /* blocks B_ij of the vertices present; R_j = sum_i v_i B_ij, C = sum_j v_j R_j; then the blocks
     (i, j >= 1) of P B P: B_ij - tau v_i R_j - tau R_i^T v_j + tau^2 v_i v_j C */
  {
    const int    *act = p->act;
    const double *v = p->v, tau = p->tau;
    if (na == 6) { /* the same sums along H's rows */
      double Rr[3][18];
      for (int a = 0; a < 3; a++)
        for (int c = 0; c < 18; c++) Rr[a][c] = 0;
      for (int i = 0; i < 6; i++)
        for (int a = 0; a < 3; a++)
          for (int c = 0; c < 18; c++) Rr[a][c] += v[i] * H[18 * (3 * i + a) + c];
      for (int j = 0; j < 6; j++)
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) R[j][3 * a + b] = Rr[a][3 * j + b];
    } else
      for (int j = 0; j < na; j++)
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) {
            double t = 0;
            for (int i = 0; i < na; i++) t += v[i] * H[18 * (3 * act[i] + a) + 3 * act[j] + b];
            R[j][3 * a + b] = t;
          }
    for (int q = 0; q < 9; q++) {
      double t = 0;
      for (int j = 0; j < na; j++) t += v[j] * R[j][q];
      C[q] = t;
    }
    for (int i = 1; i < na; i++)
      for (int j = i; j < na; j++)
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) /* the lower triangle (and the upper part of diagonal blocks) */
            p->M[nm * (3 * (j - 1) + b) + 3 * (i - 1) + a] = H[18 * (3 * act[i] + a) + 3 * act[j] + b] - tau * v[i] * R[j][3 * a + b] - tau * v[j] * R[i][3 * b + a] + tau * tau * v[i] * v[j] * C[3 * a + b];
  }
  Tridiagonalize(nm, p->M, p->d, p->e, p->Vr);
}

/* H += floor / na (1 1^T x I3) + sum over the clamped eigenvalues of (floor - lambda) u u^T */
static void ProjFinish(Proj *p)
{
  const int    na = p->na, n = p->n, nm = p->nm, *act = p->act, *idx = p->idx;
  const double floor_ = p->floor, *v = p->v, tau = p->tau, *w = p->d;
  double *restrict H = p->H, Y[NMAX * NMAX], U[NMAX][18], sq[NMAX];
  int nc             = 0;

  /* the translations: + floor / na on the diagonal of every vertex block pair */
  for (int i = 0; i < na; i++)
    for (int j = 0; j < na; j++)
      for (int a = 0; a < 3; a++) H[18 * (3 * act[i] + a) + 3 * act[j] + a] += floor_ / na;
  /* the clamped eigenvalues' T eigenvectors, the columns of Y, and sqrt(floor - lambda) */
  for (int q = 0; q < nm; q++) {
    const double s = floor_ - w[q];
    if (!(s > 0)) continue;
    sq[nc++] = sqrt(s);
  }
  if (!nc) return;
  for (int q = 0, c = 0; q < nm; q++)
    if (floor_ - w[q] > 0) {
      for (int i = 0; i < nm; i++) Y[nc * i + c] = p->Z[ZS * q + i];
      c++;
    }
  /* u = sqrt(floor - lambda) (P x I3) [0; Q y], the rows of U */
  BackTransform(nm, p->Vr, nc, Y);
  for (int c = 0; c < nc; c++) {
    double *restrict u = U[c], dot[3] = {0, 0, 0};
    for (int a = 0; a < 3; a++) u[a] = 0;
    for (int i = 0; i < nm; i++) u[3 + i] = Y[nc * i + c];
    for (int i = 1; i < na; i++)
      for (int a = 0; a < 3; a++) dot[a] += v[i] * u[3 * i + a];
    for (int i = 0; i < na; i++)
      for (int a = 0; a < 3; a++) u[3 * i + a] -= tau * v[i] * dot[a];
    for (int i = 0; i < n; i++) u[i] *= sq[c];
  }
  /* H += sum u u^T, row by row (exactly symmetric: entries (i, j) and (j, i) add the same products in
     the same order); all six vertices: the rows' sums in registers (constant bounds) */
  if (n == 18)
    for (int i = 0; i < 18; i++) {
      double row[18];
      for (int j = 0; j < 18; j++) row[j] = U[0][i] * U[0][j];
      for (int c = 1; c < nc; c++) {
        const double a = U[c][i];
        for (int j = 0; j < 18; j++) row[j] += a * U[c][j];
      }
      for (int j = 0; j < 18; j++) H[18 * i + j] += row[j];
    }
  else
    for (int i = 0; i < n; i++) {
      double row[18];
      for (int j = 0; j < n; j++) row[j] = U[0][i] * U[0][j];
      for (int c = 1; c < nc; c++) {
        const double a = U[c][i];
        for (int j = 0; j < n; j++) row[j] += a * U[c][j];
      }
      for (int j = 0; j < n; j++) H[18 * idx[i] + idx[j]] += row[j];
    }
}

/* a Hessian whose largest entry exceeds this is projected divided by a power of 2 (exact) near its
   largest entry, with the floor divided alike, then multiplied back: the Householder norms and the QR
   iterations square entries, which overflow from about 1e154 (a NaN, reported as a defect before) */
#define PSD_SCALE_ABOVE 1e100

/* the power of 2 by which H (the 324 entries) is divided before the projection: 1 for ordinary sizes */
static double ProjScale(const double H[324])
{
  double amax = 0;
  int    ex;
  for (int i = 0; i < 324; i++) amax = fmax(amax, fabs(H[i]));
  if (!(amax > PSD_SCALE_ABOVE)) return 1;
  (void)frexp(amax, &ex);
  return ldexp(1.0, ex);
}

/* projects m (1..4) element Hessians H[i] with neighbour masks nb[i], their QR iterations in pairs;
   HYLCMAT_ERR_RANGE if a projected entry is beyond the double range */
int hm_psd_project_many(int m, double *const H[], const int nb[])
{
  Proj    p[4];
  QRState q[4];
  double  s[4];
  int     ret = HYLCMAT_OK;

  for (int i = 0; i < m; i++) {
    s[i] = ProjScale(H[i]);
    if (s[i] != 1)
      for (int j = 0; j < 324; j++) H[i][j] /= s[i];
    ProjPrepare(&p[i], H[i], nb[i]);
    p[i].floor = HYLCMAT_PSD_FLOOR / s[i];
    QRInit(&q[i], p[i].nm, p[i].d, p[i].e, p[i].Z);
  }
  for (int i = 0; i < m; i += 2)
    if (i + 1 < m ? TridiagQR2(&q[i], &q[i + 1]) : TridiagQR1(&q[i])) return HYLCMAT_ERR_NAN;
  for (int i = 0; i < m; i++) {
    ProjFinish(&p[i]);
    if (s[i] != 1) {
      double fin = 0;
      for (int j = 0; j < 324; j++) fin += (H[i][j] *= s[i]) * 0;
      if (fin != 0 || isnan(fin)) ret = HYLCMAT_ERR_RANGE;
    }
  }
  return ret;
}

int hm_psd_project(double H[324], int nb)
{
  double *const Hs[1] = {H};
  return hm_psd_project_many(1, Hs, &nb);
}
