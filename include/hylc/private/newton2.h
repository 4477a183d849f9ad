#pragma once
/* The damped Newton step on two strains shared by the uniaxial states of a table (src/hylcmat/uniaxial.c,
   plain C99) and of the tile (src/micro/uniaxial.c), and the 2 x 2 eigen-decomposition under it, which the
   table's free curl uses too (src/cloth/kernels.c): header-only, no PETSc. */
#include <math.h>

/* the eigen-decomposition of a symmetric 2 x 2 H (row-major; its off-diagonal taken as the mean of the
   two entries): l1 >= l2 with unit eigenvectors v1, v2 = (-v1[1], v1[0]) */
static inline void HylcSymEig2(const double H[4], double *l1, double *l2, double v1[2], double v2[2])
{
  const double a = H[0], b = 0.5 * (H[1] + H[2]), c = H[3];
  const double m = 0.5 * (a + c), r = sqrt(0.25 * (a - c) * (a - c) + b * b);
  *l1 = m + r;
  *l2 = m - r;
  if (b != 0) { /* the eigenvector of l1 */
    v1[0] = *l1 - c;
    v1[1] = b;
  } else if (a >= c) {
    v1[0] = 1;
    v1[1] = 0;
  } else {
    v1[0] = 0;
    v1[1] = 1;
  }
  const double nv = hypot(v1[0], v1[1]);
  v1[0] /= nv;
  v1[1] /= nv;
  v2[0] = -v1[1];
  v2[1] = v1[0];
}

/* d = -(V diag(l1, l2) V^T)^-1 g for the eigen-decomposition of HylcSymEig2 with l1, l2 > 0 */
static inline void HylcEigSolve2(double l1, double l2, const double v1[2], const double v2[2], const double g[2], double d[2])
{
  const double g1 = v1[0] * g[0] + v1[1] * g[1], g2 = v2[0] * g[0] + v2[1] * g[1];
  d[0] = -(g1 / l1 * v1[0] + g2 / l2 * v2[0]);
  d[1] = -(g1 / l1 * v1[1] + g2 / l2 * v2[1]);
}

/* d = -H^-1 g with H (symmetric 2 x 2, row-major) made positive definite first: eigenvalues below
   relFloor times the largest magnitude (or below 0) raised to that floor; H = 0 gives a gradient step */
static inline void HylcNewtonStep2(const double H[4], const double g[2], double relFloor, double d[2])
{
  double l1, l2, v1[2], v2[2];
  HylcSymEig2(H, &l1, &l2, v1, v2);
  const double floor = relFloor * fmax(fabs(l1), fabs(l2));
  l1                 = fmax(l1, floor);
  l2                 = fmax(l2, floor);
  if (!(l1 > 0)) l1 = 1;
  if (!(l2 > 0)) l2 = l1;
  HylcEigSolve2(l1, l2, v1, v2, g, d);
}

/* d = -H^-1 g for a symmetric n x n H (n <= 3, row-major) made positive definite first, as HylcNewtonStep2():
   eigenvalues (Jacobi rotations) below relFloor times the largest magnitude raised to it; H = 0 gives a
   gradient step */
static inline void HylcNewtonStepN(int n, const double H[9], const double g[3], double relFloor, double d[3])
{
  double A[9], V[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, lmax = 0;
  for (int i = 0; i < n * n; i++) A[i] = H[i];
  for (int i = 0; i < n; i++) V[n * i + i] = 1;
  for (int sweep = 0; sweep < 30; sweep++) {
    double off = 0, diag = 0;
    for (int i = 0; i < n; i++) {
      diag += A[n * i + i] * A[n * i + i];
      for (int j = i + 1; j < n; j++) off += A[n * i + j] * A[n * i + j];
    }
    if (off <= 1e-30 * diag) break;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++) {
        if (A[n * i + j] == 0) continue;
        const double th = 0.5 * atan2(2 * A[n * i + j], A[n * j + j] - A[n * i + i]), c = cos(th), s = sin(th);
        for (int k = 0; k < n; k++) { /* A <- A G */
          const double aki = A[n * k + i], akj = A[n * k + j];
          A[n * k + i] = c * aki - s * akj;
          A[n * k + j] = s * aki + c * akj;
        }
        for (int k = 0; k < n; k++) { /* A <- G^T A */
          const double aik = A[n * i + k], ajk = A[n * j + k];
          A[n * i + k] = c * aik - s * ajk;
          A[n * j + k] = s * aik + c * ajk;
        }
        for (int k = 0; k < n; k++) { /* V <- V G */
          const double vki = V[n * k + i], vkj = V[n * k + j];
          V[n * k + i] = c * vki - s * vkj;
          V[n * k + j] = s * vki + c * vkj;
        }
      }
  }
  for (int i = 0; i < n; i++) lmax = fmax(lmax, fabs(A[n * i + i]));
  for (int i = 0; i < n; i++) d[i] = 0;
  for (int e = 0; e < n; e++) {
    double l = fmax(A[n * e + e], relFloor * lmax), ge = 0;
    if (!(l > 0)) l = lmax > 0 ? lmax : 1;
    for (int k = 0; k < n; k++) ge += V[n * k + e] * g[k];
    for (int k = 0; k < n; k++) d[k] -= ge / l * V[n * k + e];
  }
}
