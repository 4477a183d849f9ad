/* Plain kernels of the fit (include/hylc/fit.h): symlog/symexp are inverse; the MLS reproduces
   polynomials of its basis exactly (1D quadratic; 2D the 8 monomials) on scattered data and reports
   singular kernels; the knot rules reproduce the paper's stored knots; boundary clamps, residualization
   (the spline vanishes on the axes) and the zero-compression rule (plain and strict). */
#include <hylc/fit.h>
#include "hylctest.h"

static double Q1(double x) { return 0.4 - 1.3 * x + 2.1 * x * x; }
static double Q2(double u, double v) { return 0.2 - 0.7 * v + 0.3 * v * v + 1.1 * u - 0.4 * u * v + 0.9 * u * v * v - 0.6 * u * u + 0.25 * u * u * v; }

int main(void)
{
  unsigned long long st = 7;

  /* symlog / symexp */
  for (int k = -40; k <= 40; k++) {
    const double x = k * k * k * 1e-3 * (k < 0 ? 1 : 1.3);
    HYLC_CHECK_REL(HylcSymexp(HylcSymlog(x)), x, 1e-14);
    HYLC_CHECK_CLOSE(HylcSymlog(x), (x > 0 ? 1 : x < 0 ? -1 : 0) * log(1 + fabs(x)), 1e-15);
  }
  HYLC_CHECK(HylcSymlog(0) == 0 && HylcSymexp(0) == 0, "symlog(0)");
  HYLC_CHECK_CLOSE(HylcSymexp(-2.0), -(exp(2.0) - 1), 1e-14);

  /* MLS 1D: a quadratic is reproduced at any point, whatever the kernel */
  {
    double x[200], f[200], val;
    for (int i = 0; i < 200; i++) {
      x[i] = 2 * HylcTestRand(&st) - 1;
      f[i] = Q1(x[i]);
    }
    for (int q = 0; q <= 20; q++) {
      const double xq  = -0.95 + 0.095 * q;
      const int    cnt = HylcMLS1D(200, x, f, 0.3, 3, xq, &val);
      HYLC_CHECK(cnt >= 3, "count %d", cnt);
      HYLC_CHECK_CLOSE(val, Q1(xq), 1e-11);
    }
    /* a kernel with fewer than 3 points is singular */
    double xs[4] = {0, 0.5, 0.6, 1}, fs[4] = {1, 2, 3, 4};
    HYLC_CHECK(HylcMLS1D(4, xs, fs, 0.2, 3, 0.55, &val) == -1, "singular 1D kernel not reported");
    HYLC_CHECK(HylcMLS1D(4, xs, fs, 0.2, 3, 0.25, &val) == -1, "empty 1D kernel not reported");
    /* weights: a non-polynomial function gives a weighted local average between the data */
    double xl[3] = {-1, 0, 1}, fl[3] = {0, 1, 0};
    HYLC_CHECK(HylcMLS1D(3, xl, fl, 1.5, 3, 0.0, &val) == 3 && fabs(val - 1) < 1e-12, "3-point interpolation %g", val);
  }
  /* MLS 2D: every polynomial of the basis {1, y, y^2, x, xy, xy^2, x^2, x^2 y} */
  {
    double u[900], v[900], f[900], val;
    for (int i = 0; i < 900; i++) {
      u[i] = 2 * HylcTestRand(&st) - 1;
      v[i] = 1.5 * HylcTestRand(&st) - 0.5;
      f[i] = Q2(u[i], v[i]);
    }
    for (int a = 0; a <= 6; a++)
      for (int b = 0; b <= 6; b++) {
        const double uq = -0.9 + 0.3 * a, vq = -0.45 + 0.2 * b;
        const int    cnt = HylcMLS2D(900, u, v, f, 0.3, 0.25, 3, uq, vq, &val);
        HYLC_CHECK(cnt >= 8, "count %d", cnt);
        HYLC_CHECK_CLOSE(val, Q2(uq, vq), 1e-10);
      }
    /* x^2 y^2 is not in the basis: not reproduced exactly (the basis is the 8 monomials, not 9) */
    for (int i = 0; i < 900; i++) f[i] = u[i] * u[i] * v[i] * v[i];
    HylcMLS2D(900, u, v, f, 0.6, 0.6, 3, 0.3, 0.3, &val);
    HYLC_CHECK(fabs(val - 0.0081) > 1e-6, "x^2 y^2 reproduced: the basis has more than 8 terms?");
    /* points on a line are singular */
    for (int i = 0; i < 900; i++) v[i] = 0.1;
    HYLC_CHECK(HylcMLS2D(900, u, v, f, 0.3, 0.3, 3, 0, 0.1, &val) == -1, "collinear 2D data not reported singular");
  }

  /* 1D knots: the stored knots of stock1 sx (data [-0.5, 0.8]/0.8) and basket sa (symmetric) */
  {
    double    t[11];
    const int i0 = HylcFitKnots1D(-0.625, 1.0, 0.95, 11, t);
    HYLC_CHECK(i0 == 4 && t[4] == 0, "zero knot %d", i0);
    HYLC_CHECK_CLOSE(t[0], -0.6175, 1e-12);
    HYLC_CHECK_CLOSE(t[10], 0.92625, 1e-12);
    for (int i = 0; i < 10; i++) HYLC_CHECK_CLOSE(t[i + 1] - t[i], 0.154375, 1e-12);
    HYLC_CHECK(HylcFitKnots1D(-1, 1, 0.95, 11, t) == 5 && t[5] == 0, "symmetric");
    HYLC_CHECK_CLOSE(t[0], -0.95, 1e-15);
    HYLC_CHECK(HylcFitKnots1D(1, 1, 0.95, 11, t) == -1, "empty range accepted");
  }
  /* 1D knots refined towards 0 (issue 30): the paper's knots and h/2, h/4, h/8 of the first interval on each
     side, increasing; a one-sided range is refined on its side only */
  {
    double    t[32], u[11];
    PetscInt  n;
    const int i0 = HylcFitKnots1DRefined(-0.625, 1.0, 0.95, 11, 3, t, &n);
    HYLC_CHECK(n == 17 && i0 == 7 && t[7] == 0, "refined: n %d, zero knot %d", (int)n, i0);
    HylcFitKnots1D(-0.625, 1.0, 0.95, 11, u);
    for (int i = 0; i < 4; i++) HYLC_CHECK(t[i] == u[i], "refined: the paper's knot %d moved", i);
    for (int i = 5; i < 11; i++) HYLC_CHECK(t[i + 6] == u[i], "refined: the paper's knot %d moved", i);
    HYLC_CHECK_CLOSE(t[8], 0.154375 / 8, 1e-12);
    HYLC_CHECK_CLOSE(t[9], 0.154375 / 4, 1e-12);
    HYLC_CHECK_CLOSE(t[10], 0.154375 / 2, 1e-12);
    HYLC_CHECK_CLOSE(t[6], -0.154375 / 8, 1e-12);
    for (int i = 0; i + 1 < (int)n; i++) HYLC_CHECK(t[i] < t[i + 1], "refined: knots not increasing at %d", i);
    HYLC_CHECK(HylcFitKnots1DRefined(0, 1, 0.95, 11, 2, t, &n) == 0 && n == 13 && t[0] == 0 && t[1] > 0, "one-sided: n %d", (int)n);
    HYLC_CHECK(HylcFitKnots1DRefined(1, 1, 0.95, 11, 3, t, &n) == -1, "refined: empty range accepted");
  }
  /* 2D knots: basket (sx, sa) u: sx in [-0.1, 0.84] -> 2+7; stock bending pair: 0.3, 2+4 */
  {
    double   t[32];
    PetscInt n;
    int      i0 = HylcFitKnots2D(-0.1, 0.84, 0.9, 2, 7, t, &n);
    HYLC_CHECK(n == 8 && i0 == 1 && t[1] == 0, "n %d i0 %d", (int)n, i0);
    HYLC_CHECK_CLOSE(t[0], -0.09, 1e-15);
    HYLC_CHECK_CLOSE(t[2], 0.126, 1e-15);
    HYLC_CHECK_CLOSE(t[7], 0.756, 1e-15);
    i0 = HylcFitKnots2D(-0.125, 0.8375, 0.3, 2, 4, t, &n);
    HYLC_CHECK(n == 5 && i0 == 1, "stockinette n %d", (int)n);
    HYLC_CHECK_CLOSE(t[0], -0.0375, 1e-15);
    HYLC_CHECK_CLOSE(t[4], 0.25125, 1e-15);
    i0 = HylcFitKnots2D(-0.8, 0.8, 0.9, 5, 5, t, &n);
    HYLC_CHECK(n == 9 && i0 == 4 && t[4] == 0, "symmetric");
    HYLC_CHECK_CLOSE(t[0], -0.72, 1e-15);
    HYLC_CHECK_CLOSE(t[1], -0.54, 1e-15);
    i0 = HylcFitKnots2D(0.2, 0.8, 0.9, 5, 5, t, &n);
    HYLC_CHECK(n == 5 && i0 == 0 && t[0] == 0, "data only positive: %d knots", (int)n);
  }

  /* boundary rules, residualization and zero compression on random 2D data */
  {
    const PetscInt nu = 7, nv = 6, i0 = 2, j0 = 3;
    double         tu[7] = {-0.4, -0.2, 0, 0.2, 0.4, 0.6, 0.8}, tv[6] = {-0.6, -0.4, -0.2, 0, 0.3, 0.6};
    double         p[42], mu[42], mv[42], muv[42];
    for (int strict = 0; strict < 2; strict++) {
      for (int k = 0; k < 42; k++) {
        p[k]   = HylcTestRand(&st);
        mu[k]  = HylcTestRand(&st) - 0.5;
        mv[k]  = HylcTestRand(&st) - 0.5;
        muv[k] = HylcTestRand(&st) - 0.5;
      }
      HylcFitClampBoundary2D(nu, nv, 1e-8, mu, mv);
      for (int j = 0; j < nv; j++) HYLC_CHECK(mu[j * nu] <= -1e-8 && mu[j * nu + nu - 1] >= 1e-8, "mu boundary");
      for (int i = 0; i < nu; i++) HYLC_CHECK(mv[i] <= -1e-8 && mv[(nv - 1) * nu + i] >= 1e-8, "mv boundary");
      HylcFitZeroBoundaryMixed2D(nu, nv, muv);
      for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++)
          if (i == 0 || j == 0 || i == nu - 1 || j == nv - 1) HYLC_CHECK(muv[j * nu + i] == 0, "muv boundary");
      double pr[42];
      for (int k = 0; k < 42; k++) pr[k] = p[k];
      HylcFitResidualize2D(nu, nv, i0, j0, p, mu, mv, muv);
      HYLC_CHECK_CLOSE(p[5 * nu + 4], pr[5 * nu + 4] - pr[j0 * nu + 4] - pr[5 * nu + i0] + pr[j0 * nu + i0], 1e-15);
      /* the spline vanishes on both axes, with its derivative along the axis */
      for (int q = 0; q <= 200; q++) {
        const double x = -0.6 + 1.6 * q / 200, y = -0.8 + 1.6 * q / 200;
        double       g[2];
        HYLC_CHECK(fabs(HylcHermite2DEval(nu, nv, tu, tv, p, mu, mv, muv, HYLC_EXT_LINEAR, x, 0, g, NULL)) < 1e-15 && fabs(g[0]) < 1e-14, "not zero on v = 0 at u = %g", x);
        HYLC_CHECK(fabs(HylcHermite2DEval(nu, nv, tu, tv, p, mu, mv, muv, HYLC_EXT_LINEAR, 0, y, g, NULL)) < 1e-15 && fabs(g[1]) < 1e-14, "not zero on u = 0 at v = %g", y);
      }
      /* zero compression in v (an sy axis): all nodes with tv < 0 vanish; strict: the half-plane */
      HylcFitZeroCompression2D(nu, nv, tu, tv, PETSC_FALSE, PETSC_TRUE, (PetscBool)strict, p, mu, mv, muv);
      for (int j = 0; j < j0; j++)
        for (int i = 0; i < nu; i++) HYLC_CHECK(p[j * nu + i] == 0 && mu[j * nu + i] == 0 && mv[j * nu + i] == 0 && muv[j * nu + i] == 0, "node (%d, %d) not zeroed", i, j);
      double worst = 0;
      for (int a = 0; a <= 40; a++)
        for (int b = 0; b <= 40; b++) {
          const double x = -0.6 + 1.6 * a / 40, y = -0.9 + 0.9 * b / 40 - 1e-12;
          worst = fmax(worst, fabs(HylcHermite2DEval(nu, nv, tu, tv, p, mu, mv, muv, HYLC_EXT_LINEAR, x, y, NULL, NULL)));
          if (y <= tv[j0 - 1]) HYLC_CHECK(HylcHermite2DEval(nu, nv, tu, tv, p, mu, mv, muv, HYLC_EXT_LINEAR, x, y, NULL, NULL) == 0, "non-zero at (%g, %g) beyond the last compressed knot", x, y);
        }
      if (strict)
        HYLC_CHECK(worst == 0, "strict: compressed half-plane max |f| = %g", worst);
      else
        HYLC_CHECK(worst > 0, "plain rule: the last compressed cell keeps muv of the axis (expected non-zero)");
    }
  }
  return HYLC_TEST_RESULT();
}
