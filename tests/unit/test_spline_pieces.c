/* Local polynomial forms of the Hermite splines (include/hylc/spline.h): HylcHermite1DPiece reproduces the
   spline and its derivatives on every piece (also extrapolating, in the three modes, and read from a
   slice with an index offset), HylcHermite1DKnotJump is the difference of the neighbouring pieces (exactly
   C1 where it must be), and HylcHermite2DSliceV is the restriction of a 2D spline to fixed u, with its
   u-derivatives. */
#include <hylc/spline.h>
#include "hylctest.h"

/* value and derivatives of sum c[k] (x - x0)^k at x */
static double PolyEval(const double c[4], double x0, double x, double *d1, double *d2)
{
  const double e = x - x0;
  *d1            = c[1] + e * (2 * c[2] + 3 * e * c[3]);
  *d2            = 2 * c[2] + 6 * e * c[3];
  return c[0] + e * (c[1] + e * (c[2] + e * c[3]));
}

int main(void)
{
  const double       t[6] = {-1.0, -0.55, -0.1, 0.0, 0.4, 1.3};
  double             p[6], m[6];
  unsigned long long st = 7;

  for (int i = 0; i < 6; i++) {
    p[i] = HylcTestRand(&st) - 0.5;
    m[i] = 4 * HylcTestRand(&st) - 2;
  }
  for (int ext = 0; ext < 3; ext++) {
    /* every piece against the evaluator, expanded about a few points */
    for (int k = 0; k <= 600; k++) {
      const double x = -2 + 4.5 * k / 600.0;
      double       f1, f2, c[4], g1, g2;
      const double f   = HylcHermite1DEval(6, t, p, m, (HylcSplineExt)ext, x, &f1, &f2);
      const int    loc = (int)HylcSplineLocate(6, t, x);
      for (int o = 0; o < 3; o++) {
        const double x0 = x + (o - 1) * 0.37 * HylcTestRand(&st);
        HylcHermite1DPiece(6, t, p, m, 0, (HylcSplineExt)ext, loc, x0, c);
        const double g = PolyEval(c, x0, x, &g1, &g2);
        HYLC_CHECK(fabs(g - f) < 1e-13 && fabs(g1 - f1) < 1e-12 && fabs(g2 - f2) < 1e-10, "ext %d piece %d at x = %g (about %g): %g %g %g vs %g %g %g", ext, loc, x, x0, g, g1, g2, f, f1, f2);
      }
    }
    /* jumps: right piece minus left piece at every knot; C1 parts exactly zero */
    for (int k = 0; k < 6; k++) {
      double L[4], R[4], J[4];
      HylcHermite1DPiece(6, t, p, m, 0, (HylcSplineExt)ext, k - 1, t[k], L);
      HylcHermite1DPiece(6, t, p, m, 0, (HylcSplineExt)ext, k, t[k], R);
      HylcHermite1DKnotJump(6, t, p, m, 0, (HylcSplineExt)ext, k, J);
      for (int r = 0; r < 4; r++) HYLC_CHECK(fabs(J[r] - (R[r] - L[r])) < 1e-11, "ext %d knot %d jump[%d] %g vs %g", ext, k, r, J[r], R[r] - L[r]);
      if (ext == HYLC_EXT_LINEAR || (k > 0 && k < 5)) HYLC_CHECK(J[0] == 0 && J[1] == 0, "ext %d knot %d: C1 jump not exactly zero (%g, %g)", ext, k, J[0], J[1]);
    }
    /* a slice with an offset: nodes 2..4 only */
    {
      double c0[4], c1[4];
      HylcHermite1DPiece(6, t, p, m, 0, (HylcSplineExt)ext, 3, 0.2, c0);
      HylcHermite1DPiece(6, t, p + 2, m + 2, 2, (HylcSplineExt)ext, 3, 0.2, c1);
      for (int r = 0; r < 4; r++) HYLC_CHECK(c0[r] == c1[r], "offset slice coefficient %d", r);
    }
  }
  /* 2D slices: the 1D spline of the slice equals the 2D spline at fixed u; u-derivatives by differences */
  {
    const double tu[4] = {-0.8, -0.2, 0.0, 0.9}, tv[5] = {-0.5, 0.0, 0.3, 0.35, 1.0};
    double       P[20], U[20], V[20], W[20];
    for (int i = 0; i < 20; i++) {
      P[i] = HylcTestRand(&st) - 0.5;
      U[i] = HylcTestRand(&st) - 0.5;
      V[i] = HylcTestRand(&st) - 0.5;
      W[i] = HylcTestRand(&st) - 0.5;
    }
    for (int ext = 0; ext < 3; ext++) {
      for (int k = 0; k < 200; k++) {
        const double u = -1.2 + 2.5 * HylcTestRand(&st), v = -1 + 2.5 * HylcTestRand(&st);
        double       sP[5], sM[5], sPu[5], sMu[5], sPuu[5], sMuu[5], g[2], H[3], d1, d2;
        HylcHermite2DSliceV(4, 5, tu, P, U, V, W, (HylcSplineExt)ext, u, 0, 4, sP, sM, sPu, sMu, sPuu, sMuu);
        const double f  = HylcHermite2DEval(4, 5, tu, tv, P, U, V, W, (HylcSplineExt)ext, u, v, g, H);
        const double f1 = HylcHermite1DEval(5, tv, sP, sM, (HylcSplineExt)ext, v, &d1, &d2);
        HYLC_CHECK(fabs(f - f1) < 1e-13 && fabs(d1 - g[1]) < 1e-12, "ext %d slice at (%g, %g): %g vs %g", ext, u, v, f1, f);
        const double fu  = HylcHermite1DEval(5, tv, sPu, sMu, (HylcSplineExt)ext, v, &d1, NULL);
        const double fuu = HylcHermite1DEval(5, tv, sPuu, sMuu, (HylcSplineExt)ext, v, NULL, NULL);
        HYLC_CHECK(fabs(fu - g[0]) < 1e-12 && fabs(d1 - H[1]) < 1e-11 && fabs(fuu - H[0]) < 1e-10, "ext %d slice u-derivatives at (%g, %g)", ext, u, v);
        /* a partial slice j0..j1 equals the corresponding part of the full one */
        HylcHermite2DSliceV(4, 5, tu, P, U, V, W, (HylcSplineExt)ext, u, 2, 3, sP, sM, NULL, NULL, NULL, NULL);
        {
          double qP[5], qM[5];
          HylcHermite2DSliceV(4, 5, tu, P, U, V, W, (HylcSplineExt)ext, u, 0, 4, qP, qM, NULL, NULL, NULL, NULL);
          HYLC_CHECK(sP[0] == qP[2] && sP[1] == qP[3] && sM[0] == qM[2] && sM[1] == qM[3], "partial slice");
        }
      }
    }
  }
  return HYLC_TEST_RESULT();
}
