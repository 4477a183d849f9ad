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
