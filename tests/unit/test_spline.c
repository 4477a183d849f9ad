/* Hermite spline kernels (include/hylc/spline.h): exact reproduction of cubic and bicubic polynomials,
   derivatives against finite differences, the three extrapolation modes, C1 continuity at knots. */
#include <hylc/spline.h>
#include "hylctest.h"

static double P1(double x) { return 0.3 - 1.1 * x + 0.7 * x * x - 0.4 * x * x * x; }
static double dP1(double x) { return -1.1 + 1.4 * x - 1.2 * x * x; }
/* a bicubic polynomial: sum c_ab u^a v^b, a, b <= 3 */
static double C2[4][4] = {{0.2, -0.5, 0.3, 0.1}, {0.7, 0.25, -0.6, 0.05}, {-0.3, 0.4, 0.15, -0.2}, {0.11, -0.07, 0.3, 0.09}};
static double P2(double u, double v, int du, int dv)
{
  double s = 0;
  for (int a = du; a < 4; a++)
    for (int b = dv; b < 4; b++) {
      double c = C2[a][b];
      for (int k = 0; k < du; k++) c *= a - k;
      for (int k = 0; k < dv; k++) c *= b - k;
      s += c * pow(u, a - du) * pow(v, b - dv);
    }
  return s;
}

int main(void)
{
  const double t[6] = {-1.0, -0.55, -0.1, 0.0, 0.4, 1.3};
  double       p[6], m[6];

  for (int i = 0; i < 6; i++) {
    p[i] = P1(t[i]);
    m[i] = dP1(t[i]);
  }
  HYLC_CHECK(HylcSplineLocate(6, t, -2) == -1 && HylcSplineLocate(6, t, -1) == 0 && HylcSplineLocate(6, t, 0) == 3 && HylcSplineLocate(6, t, 1.3) == 5 && HylcSplineLocate(6, t, 0.39) == 3, "locate");
  HYLC_CHECK(HylcSplineLocate(6, t, NAN) == -1, "locate NaN");
  for (int k = 0; k <= 400; k++) {
    const double x = -1 + 2.3 * k / 400.0;
    double       d1, d2;
    const double f = HylcHermite1DEval(6, t, p, m, HYLC_EXT_LINEAR, x, &d1, &d2);
    HYLC_CHECK_CLOSE(f, P1(x), 1e-14);
    HYLC_CHECK_CLOSE(d1, dP1(x), 1e-13);
    if (x < 1.3) HYLC_CHECK_CLOSE(d2, 1.4 - 2.4 * x, 1e-12);
  }
  /* extrapolation */
  {
    HylcSpline1D s = {0, 6, (PetscReal *)t, p, m, HYLC_EXT_LINEAR};
    double       d1, d2;
    HYLC_CHECK_CLOSE(HylcSpline1DEval(&s, -3, &d1, &d2), p[0] - 2 * m[0], 1e-14);
    HYLC_CHECK(d1 == m[0] && d2 == 0, "left slope %g", d1);
    HYLC_CHECK_CLOSE(HylcSpline1DEval(&s, 2.3, &d1, &d2), p[5] + m[5], 1e-14);
    HYLC_CHECK(d1 == m[5] && d2 == 0, "right slope %g", d1);
    s.ext = HYLC_EXT_CONSTANT;
    HYLC_CHECK(HylcSpline1DEval(&s, 2.3, &d1, NULL) == p[5] && d1 == 0, "constant extrapolation");
    s.ext = HYLC_EXT_ZERO;
    HYLC_CHECK(HylcSpline1DEval(&s, -1.5, &d1, NULL) == 0 && d1 == 0, "zero extrapolation");
  }
  /* C1 across a knot for arbitrary (non-polynomial) data */
  {
    unsigned long long st = 42;
    for (int i = 0; i < 6; i++) {
      p[i] = HylcTestRand(&st) - 0.5;
      m[i] = 4 * HylcTestRand(&st) - 2;
    }
    for (int i = 0; i < 6; i++) {
      double       dl, dr;
      const double fl = HylcHermite1DEval(6, t, p, m, HYLC_EXT_LINEAR, t[i] - 1e-12, &dl, NULL);
      const double fr = HylcHermite1DEval(6, t, p, m, HYLC_EXT_LINEAR, t[i], &dr, NULL);
      HYLC_CHECK(fabs(fr - p[i]) < 1e-15 && fabs(dr - m[i]) < 1e-13, "node %d interpolation", i);
      HYLC_CHECK(fabs(fl - fr) < 1e-10 && fabs(dl - dr) < 1e-9, "C1 at knot %d", i);
    }
  }
  /* bicubic reproduction, derivatives, and linear extrapolation */
  {
    const double tu[4] = {-0.8, -0.2, 0.0, 0.9}, tv[5] = {-0.5, 0.0, 0.3, 0.35, 1.0};
    double       P[20], U[20], V[20], W[20];
    for (int j = 0; j < 5; j++)
      for (int i = 0; i < 4; i++) {
        P[j * 4 + i] = P2(tu[i], tv[j], 0, 0);
        U[j * 4 + i] = P2(tu[i], tv[j], 1, 0);
        V[j * 4 + i] = P2(tu[i], tv[j], 0, 1);
        W[j * 4 + i] = P2(tu[i], tv[j], 1, 1);
      }
    HylcSpline2D s = {0, 1, 4, 5, (PetscReal *)tu, (PetscReal *)tv, P, U, V, W, HYLC_EXT_LINEAR};
    for (int a = 0; a <= 40; a++)
      for (int b = 0; b <= 40; b++) {
        const double u = -0.8 + 1.7 * a / 40.0 - (a == 40 ? 1e-13 : 0), v = -0.5 + 1.5 * b / 40.0 - (b == 40 ? 1e-13 : 0);
        double       g[2], H[3];
        const double f = HylcSpline2DEval(&s, u, v, g, H);
        HYLC_CHECK_CLOSE(f, P2(u, v, 0, 0), 1e-13);
        HYLC_CHECK_CLOSE(g[0], P2(u, v, 1, 0), 1e-12);
        HYLC_CHECK_CLOSE(g[1], P2(u, v, 0, 1), 1e-12);
        HYLC_CHECK_CLOSE(H[0], P2(u, v, 2, 0), 1e-10);
        HYLC_CHECK_CLOSE(H[1], P2(u, v, 1, 1), 1e-10);
        HYLC_CHECK_CLOSE(H[2], P2(u, v, 0, 2), 1e-10);
      }
    /* outside: linear along u with the edge slope, derivatives match FD */
    {
      const double v = 0.2, u = 1.5, e = 1e-6;
      double       g[2], H[3];
      const double f = HylcSpline2DEval(&s, u, v, g, H);
      double       ge[2];
      const double fe = HylcSpline2DEval(&s, 0.9, v, ge, NULL);
      HYLC_CHECK_CLOSE(f, fe + 0.6 * ge[0], 1e-13);
      HYLC_CHECK_CLOSE(g[0], ge[0], 1e-13);
      HYLC_CHECK(H[0] == 0, "f_uu outside %g", H[0]);
      HYLC_CHECK_CLOSE(g[1], (HylcSpline2DEval(&s, u, v + e, NULL, NULL) - HylcSpline2DEval(&s, u, v - e, NULL, NULL)) / (2 * e), 1e-7);
      /* corner: bilinear in the outside offsets */
      const double fc = HylcSpline2DEval(&s, -1.0, -0.7, g, H);
      HYLC_CHECK_CLOSE(fc, P[0] - 0.2 * U[0] - 0.2 * V[0] + 0.04 * W[0], 1e-13);
      HYLC_CHECK_CLOSE(H[1], W[0], 1e-13);
    }
  }
  return HYLC_TEST_RESULT();
}
