/* Unit tests of the small geometry kernels (include/hylc/geom.h). */
#include <hylc/geom.h>
#include "hylctest.h"

static void RandUnit(unsigned long long *st, double v[3])
{
  for (int i = 0; i < 3; i++) v[i] = 2 * HylcTestRand(st) - 1;
  HylcNormalize3(v);
}

/* brute-force segment distance by dense sampling + local refinement */
static double BruteSegDist(const double p0[3], const double p1[3], const double q0[3], const double q1[3])
{
  double    best = INFINITY;
  const int n    = 400;
  for (int i = 0; i <= n; i++) {
    for (int j = 0; j <= n; j++) {
      double s = (double)i / n, t = (double)j / n, v[3];
      for (int k = 0; k < 3; k++) v[k] = p0[k] + s * (p1[k] - p0[k]) - q0[k] - t * (q1[k] - q0[k]);
      double d = HylcNorm3(v);
      if (d < best) best = d;
    }
  }
  return best;
}

int main(void)
{
  unsigned long long st = 12345;

  /* parallel transport maps a to b, preserves length and is a rotation */
  for (int trial = 0; trial < 100; trial++) {
    double a[3], b[3], v[3], pa[3], pv[3];
    RandUnit(&st, a);
    RandUnit(&st, b);
    RandUnit(&st, v);
    HylcParallelTransport(a, b, a, pa);
    for (int k = 0; k < 3; k++) HYLC_CHECK_CLOSE(pa[k], b[k], 1e-12);
    HylcParallelTransport(a, b, v, pv);
    HYLC_CHECK_CLOSE(HylcNorm3(pv), 1.0, 1e-12);
    HYLC_CHECK_CLOSE(HylcDot3(pv, pa), HylcDot3(v, a), 1e-12);
    /* a vector perpendicular to both a and b is unchanged */
    double k[3];
    HylcCross3(a, b, k);
    HylcNormalize3(k);
    HylcParallelTransport(a, b, k, pv);
    for (int i = 0; i < 3; i++) HYLC_CHECK_CLOSE(pv[i], k[i], 1e-12);
  }

  /* signed angle and rotation are inverse to each other */
  for (int trial = 0; trial < 100; trial++) {
    double t[3], u[3], v[3];
    RandUnit(&st, t);
    HylcAnyPerpendicular(t, u);
    HYLC_CHECK_CLOSE(HylcDot3(u, t), 0.0, 1e-14);
    const double phi = (2 * HylcTestRand(&st) - 1) * 3.1;
    HylcRotateAxisAngle(u, t, phi, v);
    HYLC_CHECK_CLOSE(HylcSignedAngle(u, v, t), phi, 1e-12);
  }

  /* curvature binormal of a planar bend: |kb| = 2 tan(phi/2) */
  {
    const double phi = 0.7, te[3] = {1, 0, 0}, tf[3] = {cos(phi), sin(phi), 0};
    double       kb[3];
    HylcCurvatureBinormal(te, tf, kb);
    HYLC_CHECK_CLOSE(kb[2], 2 * tan(phi / 2), 1e-14);
    HYLC_CHECK_CLOSE(kb[0], 0, 1e-14);
  }

  /* reference twist of a frame transported then rotated by psi is psi */
  for (int trial = 0; trial < 50; trial++) {
    double te[3], tf[3], d1e[3], d1f[3];
    RandUnit(&st, te);
    RandUnit(&st, tf);
    HylcAnyPerpendicular(te, d1e);
    HylcParallelTransport(te, tf, d1e, d1f);
    const double psi = (2 * HylcTestRand(&st) - 1) * 3;
    HylcRotateAxisAngle(d1f, tf, psi, d1f);
    HYLC_CHECK_CLOSE(HylcReferenceTwist(te, d1e, tf, d1f), psi, 1e-11);
  }

  /* segment distance against brute force, including parallel and degenerate cases */
  for (int trial = 0; trial < 60; trial++) {
    double p0[3], p1[3], q0[3], q1[3], s, t;
    for (int k = 0; k < 3; k++) {
      p0[k] = HylcTestRand(&st);
      p1[k] = HylcTestRand(&st);
      q0[k] = HylcTestRand(&st);
      q1[k] = HylcTestRand(&st);
    }
    if (trial % 4 == 1) /* parallel */
      for (int k = 0; k < 3; k++) q1[k] = q0[k] + 0.7 * (p1[k] - p0[k]);
    if (trial % 4 == 2) /* degenerate */
      for (int k = 0; k < 3; k++) q1[k] = q0[k];
    const double d  = HylcSegmentSegmentDistance(p0, p1, q0, q1, &s, &t);
    const double db = BruteSegDist(p0, p1, q0, q1);
    HYLC_CHECK(d <= db + 1e-12 && d >= db - 2e-3, "trial %d: d = %g, brute %g", trial, d, db);
    double v[3];
    for (int k = 0; k < 3; k++) v[k] = p0[k] + s * (p1[k] - p0[k]) - q0[k] - t * (q1[k] - q0[k]);
    HYLC_CHECK_CLOSE(HylcNorm3(v), d, 1e-12);
  }
  /* small dense inverse, and detection of a singular matrix */
  {
    double A[25], B[25], Ai[25];
    for (int i = 0; i < 25; i++) A[i] = B[i] = 2 * HylcTestRand(&st) - 1 + (i % 6 == 0 ? 3 : 0);
    HYLC_CHECK(HylcDenseInverse(5, B, Ai, 1e-12) == 0, "regular matrix reported singular");
    for (int i = 0; i < 5; i++)
      for (int j = 0; j < 5; j++) {
        double s = 0;
        for (int k = 0; k < 5; k++) s += A[i * 5 + k] * Ai[k * 5 + j];
        HYLC_CHECK_CLOSE(s, i == j ? 1.0 : 0.0, 1e-13);
      }
    for (int j = 0; j < 5; j++) A[3 * 5 + j] = 2 * A[1 * 5 + j]; /* row 3 = 2 row 1 */
    HYLC_CHECK(HylcDenseInverse(5, A, Ai, 1e-12) != 0, "singular matrix not detected");
  }
  return HYLC_TEST_RESULT();
}
