/* Unit tests of the contact pair kernels (include/hylc/contact.h): Gauss rules, finite-difference checks of
   gradients and Hessians of both variants at random and hard configurations, convergence of the
   quadrature to an independently integrated double integral, rigid-motion invariance, rejection. */
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <stdlib.h>
#include <string.h>
#include "hylctest.h"

typedef enum { QUAD, CLOSEST } Variant;

typedef struct {
  Variant v;
  int     n;
  double  la, lb, kc, r, w;
} Model;

static double Eval(const Model *m, const double x[12], double g[12], double H[144])
{
  if (m->v == QUAD) return HylcContactQuadrature(x, x + 3, x + 6, x + 9, m->la, m->lb, m->kc, m->r, m->n, m->w, g, H);
  return HylcContactClosestPoint(x, x + 3, x + 6, x + 9, m->la, m->lb, m->kc, m->r, m->w, g, H, NULL, NULL, NULL);
}

static double MaxAbs(const double *a, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++)
    if (fabs(a[i]) > m) m = fabs(a[i]);
  return m;
}

/* Central finite differences with step h: relative errors max|fd - exact| / max|exact| of the gradient
   (from E) and of the Hessian (from g). Also checks the Hessian's symmetry. */
static void FDErrors(const Model *m, const double x0[12], double h, double *errg, double *errH)
{
  double g[12], H[144], x[12], gp[12], gm[12], gfd[12], Hfd[144];
  Eval(m, x0, g, H);
  for (int i = 0; i < 12; i++) {
    memcpy(x, x0, sizeof(x));
    x[i]            = x0[i] + h;
    const double ep = Eval(m, x, gp, NULL);
    x[i]            = x0[i] - h;
    const double em = Eval(m, x, gm, NULL);
    gfd[i]          = (ep - em) / (2 * h);
    for (int j = 0; j < 12; j++) Hfd[j * 12 + i] = (gp[j] - gm[j]) / (2 * h);
  }
  double dg = 0, dH = 0, asym = 0;
  for (int i = 0; i < 12; i++) dg = fmax(dg, fabs(gfd[i] - g[i]));
  for (int i = 0; i < 144; i++) dH = fmax(dH, fabs(Hfd[i] - H[i]));
  for (int i = 0; i < 12; i++)
    for (int j = 0; j < 12; j++) asym = fmax(asym, fabs(H[i * 12 + j] - H[j * 12 + i]));
  const double sg = MaxAbs(g, 12), sH = MaxAbs(H, 144);
  *errg = sg > 0 ? dg / sg : dg;
  *errH = sH > 0 ? dH / sH : dH;
  HYLC_CHECK(asym <= 1e-13 * sH, "Hessian not symmetric: %g (max %g)", asym, sH);
}

static double maxerr_g, maxerr_H; /* worst FD errors seen (printed with HYLC_TEST_VERBOSE) */

#define CHECK_FD(m, x, h, label)                                                                                \
  do {                                                                                                          \
    double eg_, eH_;                                                                                            \
    FDErrors(m, x, h, &eg_, &eH_);                                                                              \
    maxerr_g = fmax(maxerr_g, eg_);                                                                             \
    maxerr_H = fmax(maxerr_H, eH_);                                                                             \
    HYLC_CHECK(eg_ < 1e-6, "%s (%s): gradient FD rel err %g", label, (m)->v == QUAD ? "quad" : "closest", eg_); \
    HYLC_CHECK(eH_ < 1e-5, "%s (%s): Hessian FD rel err %g", label, (m)->v == QUAD ? "quad" : "closest", eH_);  \
  } while (0)

static void RandUnit(unsigned long long *st, double v[3])
{
  do {
    for (int i = 0; i < 3; i++) v[i] = 2 * HylcTestRand(st) - 1;
  } while (HylcNorm3(v) < 0.1 || HylcNorm3(v) > 1);
  HylcNormalize3(v);
}

static double SegDist(const double x[12]) { return HylcSegmentSegmentDistance(x, x + 3, x + 6, x + 9, NULL, NULL); }

/* random pair with segment lengths in [0.5, 2] r and distance in (dlo, dhi) 2r */
static void RandomPair(unsigned long long *st, double r, double dlo, double dhi, double x[12])
{
  for (;;) {
    double ua[3], ub[3], off[3];
    RandUnit(st, ua);
    RandUnit(st, ub);
    RandUnit(st, off);
    const double la = r * (0.5 + 1.5 * HylcTestRand(st)), lb = r * (0.5 + 1.5 * HylcTestRand(st));
    const double sa = HylcTestRand(st), sb = HylcTestRand(st), dist = 2 * r * HylcTestRand(st);
    for (int k = 0; k < 3; k++) {
      x[k]     = 0.1 * r * k - sa * la * ua[k];
      x[3 + k] = x[k] + la * ua[k];
      x[6 + k] = 0.1 * r * k + dist * off[k] - sb * lb * ub[k];
      x[9 + k] = x[6 + k] + lb * ub[k];
    }
    const double d = SegDist(x) / (2 * r);
    if (d > dlo && d < dhi) return;
  }
}

/* ---------------------------------------------------------------- reference integral */

/* Kaldor's integral over straight segments a(s) = A + s ua (s in [0, La]) and b(t) = B + t ub
   (t in [0, Lb]), unit ua, ub, skew lines: the inner integral over t in closed form, the outer one by
   adaptive Simpson. Returns int int f(|a(s) - b(t)|/(2r)) ds dt. */
typedef struct {
  double A[3], ua[3], B[3], ub[3], La, Lb, r;
} RefSetup;

static double Inner(const RefSetup *R, double s)
{
  double P[3];
  for (int k = 0; k < 3; k++) P[k] = R->A[k] + s * R->ua[k] - R->B[k];
  /* |P - t ub|^2 = (t - c)^2 + rho^2 */
  const double c = HylcDot3(P, R->ub), rho2 = HylcDot3(P, P) - c * c, rr = 4 * R->r * R->r;
  if (!(rho2 < rr)) return 0;
  const double half = sqrt(rr - rho2), rho = sqrt(rho2);
  double       u0 = -c, u1 = R->Lb - c; /* u = t - c */
  if (u0 < -half) u0 = -half;
  if (u1 > half) u1 = half;
  if (!(u1 > u0)) return 0;
#define F(u) (rr / rho * atan((u) / rho) + (rho2 * (u) + (u) * (u) * (u) / 3) / rr - 2 * (u))
  return F(u1) - F(u0);
#undef F
}

static double Simpson(const RefSetup *R, double a, double b, double fa, double fm, double fb, double whole, double tol, int depth)
{
  const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
  const double flm = Inner(R, lm), frm = Inner(R, rm);
  const double left = (b - a) / 12 * (fa + 4 * flm + fm), right = (b - a) / 12 * (fm + 4 * frm + fb);
  if (depth <= 0 || fabs(left + right - whole) <= 15 * tol) return left + right + (left + right - whole) / 15;
  return Simpson(R, a, m, fa, flm, fm, left, tol / 2, depth - 1) + Simpson(R, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}

static double RefIntegral(const RefSetup *R, double tol)
{
  /* split the outer range into many panels so that no feature is missed by the adaptive rule */
  const int np  = 64;
  double    sum = 0;
  for (int p = 0; p < np; p++) {
    const double a = R->La * p / np, b = R->La * (p + 1) / np, fa = Inner(R, a), fb = Inner(R, b), fm = Inner(R, 0.5 * (a + b));
    sum += Simpson(R, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tol / np, 40);
  }
  return sum;
}

static void SetupToX(const RefSetup *R, double x[12])
{
  for (int k = 0; k < 3; k++) {
    x[k]     = R->A[k];
    x[3 + k] = R->A[k] + R->La * R->ua[k];
    x[6 + k] = R->B[k];
    x[9 + k] = R->B[k] + R->Lb * R->ub[k];
  }
}

/* ---------------------------------------------------------------- rigid motions */

static void RandomRotation(unsigned long long *st, double Q[9])
{
  double ax[3];
  RandUnit(st, ax);
  const double phi = 2 * M_PI * HylcTestRand(st);
  for (int j = 0; j < 3; j++) {
    double e[3] = {0, 0, 0}, c[3];
    e[j]        = 1;
    HylcRotateAxisAngle(e, ax, phi, c);
    for (int i = 0; i < 3; i++) Q[i * 3 + j] = c[i];
  }
}

int main(void)
{
  unsigned long long st = 20240607;
  const double       r = 0.5e-3, kc = 70;

  /* Gauss-Legendre: weights sum to 1, exact for degree 2n-1, symmetric, ascending in (0, 1) */
  for (int n = 1; n <= HYLC_GAUSS_MAX; n++) {
    const double *xg, *wg;
    HYLC_CHECK(HylcGaussLegendre01(n, &xg, &wg) == 0, "n = %d", n);
    for (int deg = 0; deg <= 2 * n - 1; deg++) {
      double q = 0;
      for (int i = 0; i < n; i++) q += wg[i] * pow(xg[i], deg);
      HYLC_CHECK_CLOSE(q, 1.0 / (deg + 1), 4e-15);
    }
    for (int i = 0; i < n; i++) {
      HYLC_CHECK(xg[i] > 0 && xg[i] < 1 && wg[i] > 0, "n = %d node %d: %g %g", n, i, xg[i], wg[i]);
      if (i) HYLC_CHECK(xg[i] > xg[i - 1], "n = %d not ascending", n);
      HYLC_CHECK_CLOSE(xg[i] + xg[n - 1 - i], 1.0, 1e-15);
      HYLC_CHECK_CLOSE(wg[i], wg[n - 1 - i], 1e-15);
    }
    /* not exact for degree 2n (the error is below rounding for large n) */
    double q = 0;
    if (n > 8) continue;
    for (int i = 0; i < n; i++) q += wg[i] * pow(xg[i], 2 * n);
    HYLC_CHECK(fabs(q - 1.0 / (2 * n + 1)) > 1e-15, "n = %d exact at degree 2n?", n);
  }
  {
    const double *xg, *wg;
    HYLC_CHECK(HylcGaussLegendre01(0, &xg, &wg) == -1 && !xg && !wg, "n = 0 accepted");
    HYLC_CHECK(HylcGaussLegendre01(17, &xg, &wg) == -1, "n = 17 accepted");
  }

  /* penalty: C1 at delta = 1, derivatives by FD */
  {
    double f, df, d2f;
    HylcContactPenalty(1.0, &f, &df, &d2f);
    HYLC_CHECK(f == 0 && df == 0 && d2f == 0, "f(1) = %g %g %g", f, df, d2f);
    HylcContactPenalty(1.0 - 1e-9, &f, &df, &d2f);
    HYLC_CHECK(fabs(f) < 1e-16 && fabs(df) < 1e-8 && fabs(d2f - 8) < 1e-6, "f(1-) = %g %g %g", f, df, d2f);
    for (int k = 2; k < 10; k++) {
      double fp, fm, dfp, dfm, h = 1e-6, dl = 0.1 * k;
      HylcContactPenalty(dl, &f, &df, &d2f);
      HylcContactPenalty(dl + h, &fp, &dfp, NULL);
      HylcContactPenalty(dl - h, &fm, &dfm, NULL);
      HYLC_CHECK_REL((fp - fm) / (2 * h), df, 1e-8);
      HYLC_CHECK_REL((dfp - dfm) / (2 * h), d2f, 1e-8);
    }
  }

  Model mq = {QUAD, 4, 0, 0, kc, r, 0.75}, mc = {CLOSEST, 0, 0, 0, kc, r, 0.75};

  /* random configurations in contact */
  for (int trial = 0; trial < 200; trial++) {
    double x[12];
    RandomPair(&st, r, 0.3, 0.97, x);
    mq.la = mc.la = 1.1 * r;
    mq.lb = mc.lb = 0.9 * r;
    mq.n          = 1 + trial % 8;
    CHECK_FD(&mq, x, 1e-6 * r, "random");
    CHECK_FD(&mc, x, 1e-6 * r, "random");
  }
  mq.n = 4;

  /* hard configurations */
  {
    /* crossing segments (skew, at several angles), closest points interior to both */
    for (int k = 0; k < 6; k++) {
      const double th = 0.3 + 0.5 * k, h = (0.6 + 0.25 * k) * r;
      double       x[12] = {-r, 0.1 * r, 0, r, 0.1 * r, 0, -r * cos(th), -r * sin(th), h, r * cos(th), r * sin(th), h};
      CHECK_FD(&mq, x, 1e-6 * r, "crossing");
      CHECK_FD(&mc, x, 1e-6 * r, "crossing");
    }
    /* nearly parallel, overlapping, offset 1.3 r (angle 1e-4 and 1e-7) */
    for (int k = 0; k < 2; k++) {
      const double ang   = k ? 1e-7 : 1e-4;
      double       x[12] = {0, 0, 0, 2 * r, 0, 0, 0.5 * r, 1.3 * r, 0, 2.5 * r, 1.3 * r + 2 * r * ang, 0};
      CHECK_FD(&mq, x, 1e-6 * r, "nearly parallel");
      CHECK_FD(&mc, x, 1e-6 * r, "nearly parallel");
      /* tilted out of plane as well */
      x[11] = 2 * r * ang;
      CHECK_FD(&mq, x, 1e-6 * r, "nearly parallel 3d");
      CHECK_FD(&mc, x, 1e-6 * r, "nearly parallel 3d");
    }
    /* exactly parallel, offset: the quadrature energy is smooth there */
    {
      double x[12] = {0, 0, 0, 2 * r, 0, 0, 0.5 * r, 1.3 * r, 0.2 * r, 2.5 * r, 1.3 * r, 0.2 * r};
      CHECK_FD(&mq, x, 1e-6 * r, "parallel");
      /* closest point: the documented one-sided derivative. Here s = 0.5 ... the pair (a, b0) is chosen:
         E, g and H equal those of the point b0 against segment a, which is the closest-point energy of
         the configuration with b1 moved away (a degenerate segment b = (b0, b0) would do as well). */
      double       g[12], H[144], gref[12], Href[144], s, t, d;
      const double E = HylcContactClosestPoint(x, x + 3, x + 6, x + 9, r, r, kc, r, 1, g, H, &s, &t, &d);
      HYLC_CHECK_CLOSE(d, sqrt(1.3 * 1.3 + 0.2 * 0.2) * r, 1e-15);
      HYLC_CHECK(t == 0 && s == 0.25, "parallel: s = %g t = %g", s, t);
      double xr[12];
      memcpy(xr, x, sizeof(xr));
      xr[9]             = xr[6] + 2 * r; /* b turned away: b0 stays the unique closest point */
      xr[10]            = xr[7] + 2 * r;
      const double Eref = HylcContactClosestPoint(xr, xr + 3, xr + 6, xr + 9, r, r, kc, r, 1, gref, Href, NULL, NULL, NULL);
      HYLC_CHECK_REL(E, Eref, 1e-14);
      for (int i = 0; i < 9; i++) HYLC_CHECK_CLOSE(g[i], gref[i], 1e-12 * MaxAbs(gref, 12));
      for (int i = 0; i < 9; i++)
        for (int j = 0; j < 9; j++) HYLC_CHECK_CLOSE(H[i * 12 + j], Href[i * 12 + j], 1e-12 * MaxAbs(Href, 144));
      /* forces balance and act along the normal */
      double fa[3] = {0, 0, 0}, fb[3] = {0, 0, 0};
      for (int k = 0; k < 3; k++) {
        fa[k] = g[k] + g[3 + k];
        fb[k] = g[6 + k] + g[9 + k];
        HYLC_CHECK_CLOSE(fa[k] + fb[k], 0, 1e-14 * MaxAbs(g, 12));
      }
      HYLC_CHECK_CLOSE(fa[0], 0, 1e-14 * MaxAbs(g, 12));
      /* the energy is continuous through the parallel configuration */
      x[10] += 1e-9 * r;
      HYLC_CHECK_REL(HylcContactClosestPoint(x, x + 3, x + 6, x + 9, r, r, kc, r, 1, NULL, NULL, NULL, NULL, NULL), E, 1e-6);
    }
    /* right around the threshold 2 r: below (E > 0, FD), at and above (exact zeros) */
    for (int side = -1; side <= 1; side++) {
      const double d = 2 * r * (1 + side * 1e-3);
      /* parallel aligned pair: every quadrature pair (g, g) is at distance d */
      double xp[12] = {0, 0, 0, r, 0, 0, 0, 0, d, r, 0, 0};
      xp[11]        = d;
      /* crossing pair */
      double xc[12] = {-r, 0, 0, r, 0, 0, 0, -r, d, 0, r, d};
      double g[12], H[144];
      for (int v = 0; v < 2; v++) {
        Model       *m  = v ? &mc : &mq;
        const double Ep = Eval(m, xp, g, H), Ec = Eval(m, xc, NULL, NULL);
        if (side < 0) {
          HYLC_CHECK(Ep > 0 && (v == 0 || Ec > 0), "below threshold: E = %g %g", Ep, Ec);
          if (v)
            CHECK_FD(m, xc, 1e-8 * r, "threshold-"); /* xp is exactly parallel: not differentiable */
          else
            CHECK_FD(m, xp, 1e-8 * r, "threshold-");
        } else {
          HYLC_CHECK(Ep == 0 && Ec == 0 && MaxAbs(g, 12) == 0 && MaxAbs(H, 144) == 0, "at/above threshold: E = %g %g", Ep, Ec);
        }
      }
      if (side == 0) { /* exactly 2r: rejected */
        double x0[12] = {0, 0, 0, r, 0, 0, 0, 0, 2 * r, r, 0, 2 * r};
        HYLC_CHECK(Eval(&mq, x0, NULL, NULL) == 0 && Eval(&mc, x0, NULL, NULL) == 0, "d = 2r not rejected");
      }
    }
    /* very short segments: one of length 1e-3 r, and both */
    for (int k = 0; k < 2; k++) {
      const double ls    = 1e-3 * r;
      double       x[12] = {0.1 * r, 0.2 * r, 0, 0.1 * r + 0.6 * ls, 0.2 * r + 0.8 * ls, 0.3 * ls, -r, 0.05 * r, 1.1 * r, r, -0.1 * r, 1.2 * r};
      if (k) {
        x[6]  = 0.3 * r;
        x[7]  = 0.1 * r;
        x[8]  = 1.2 * r;
        x[9]  = x[6] + 0.5 * ls;
        x[10] = x[7] - 0.7 * ls;
        x[11] = x[8] + 0.5 * ls;
      }
      mq.la = mc.la = ls;
      CHECK_FD(&mq, x, 1e-5 * ls, "short");
      CHECK_FD(&mc, x, 1e-5 * ls, "short");
      /* tiny segments: the quadrature tends to the closest-point (point-point) energy */
      const double Eq = Eval(&mq, x, NULL, NULL), Ec = Eval(&mc, x, NULL, NULL);
      if (k) HYLC_CHECK_REL(Eq, Ec, 1e-2);
    }
    mq.la = mc.la = 1.1 * r;
    /* zero-length segment: quadrature derivatives exact, closest point finite */
    {
      double x[12] = {0.1 * r, 0.2 * r, 0.05 * r, 0.1 * r, 0.2 * r, 0.05 * r, -r, 0.05 * r, 1.1 * r, r, -0.1 * r, 1.2 * r};
      CHECK_FD(&mq, x, 1e-6 * r, "zero length");
      double       g[12], H[144];
      const double E = Eval(&mc, x, g, H);
      HYLC_CHECK(E > 0 && isfinite(MaxAbs(g, 12)) && isfinite(MaxAbs(H, 144)), "zero length closest: E = %g", E);
    }
  }

  /* convergence of the quadrature to the exact double integral (skew crossing segments) */
  {
    const double th = 1.1, h = 0.8 * r;
    RefSetup     R = {{-1.3 * r, 0.2 * r, 0}, {1, 0, 0}, {0.3 * r - 1.2 * r * cos(th), -1.2 * r * sin(th), h}, {cos(th), sin(th), 0}, 2.7 * r, 2.4 * r, r};
    double       x[12], err[HYLC_GAUSS_MAX + 1];
    SetupToX(&R, x);
    const double I = kc * RefIntegral(&R, 1e-12 * r * r);
    Model        m = {QUAD, 1, R.La, R.Lb, kc, r, 1};
    for (int n = 1; n <= HYLC_GAUSS_MAX; n++) {
      m.n    = n;
      err[n] = fabs(Eval(&m, x, NULL, NULL) - I) / I;
    }
    if (getenv("HYLC_TEST_VERBOSE"))
      for (int n = 1; n <= HYLC_GAUSS_MAX; n++) printf("crossing n = %2d rel err %.3e\n", n, err[n]);
    HYLC_CHECK(err[4] < 1e-2 && err[8] < 2e-4 && err[16] < 1e-5, "crossing: rel errors n=4 %g, n=8 %g, n=16 %g", err[4], err[8], err[16]);
    HYLC_CHECK(err[16] < err[4] / 1000 && err[16] < err[8] / 10, "crossing: no convergence %g %g %g", err[4], err[8], err[16]);

    /* both segments entirely inside the contact range: smooth integrand, spectral convergence */
    RefSetup S = {{-0.4 * r, 0.1 * r, 0}, {1, 0, 0}, {0.1 * r - 0.3 * r * cos(th), -0.3 * r * sin(th), 0.9 * r}, {cos(th), sin(th), 0}, 0.8 * r, 0.6 * r, r};
    SetupToX(&S, x);
    const double J = kc * RefIntegral(&S, 1e-14 * r * r);
    m.la           = S.La;
    m.lb           = S.Lb;
    for (int n = 1; n <= HYLC_GAUSS_MAX; n++) {
      m.n    = n;
      err[n] = fabs(Eval(&m, x, NULL, NULL) - J) / J;
      if (getenv("HYLC_TEST_VERBOSE")) printf("inside n = %2d rel err %.3e\n", n, err[n]);
    }
    HYLC_CHECK(err[8] < 1e-10 && err[12] < 1e-13, "inside: rel err n=8 %g, n=12 %g", err[8], err[12]);
  }

  /* invariance under rigid motions; gradient and Hessian transform covariantly; translation invariance
     (forces sum to 0); linear in the weight */
  for (int trial = 0; trial < 50; trial++) {
    double x[12], y[12], Q[9], tr[3], g[12], H[144], gy[12], Hy[144];
    RandomPair(&st, r, 0.2, 0.95, x);
    RandomRotation(&st, Q);
    for (int k = 0; k < 3; k++) tr[k] = 10 * r * (2 * HylcTestRand(&st) - 1);
    for (int I = 0; I < 4; I++)
      for (int i = 0; i < 3; i++) {
        y[3 * I + i] = tr[i];
        for (int j = 0; j < 3; j++) y[3 * I + i] += Q[3 * i + j] * x[3 * I + j];
      }
    for (int v = 0; v < 2; v++) {
      Model       *m = v ? &mc : &mq;
      const double E = Eval(m, x, g, H), Ey = Eval(m, y, gy, Hy);
      HYLC_CHECK_REL(Ey, E, 1e-10);
      const double sg = MaxAbs(g, 12), sH = MaxAbs(H, 144);
      for (int I = 0; I < 4; I++)
        for (int i = 0; i < 3; i++) {
          double Qg = 0;
          for (int j = 0; j < 3; j++) Qg += Q[3 * i + j] * g[3 * I + j];
          HYLC_CHECK_CLOSE(gy[3 * I + i], Qg, 1e-9 * sg);
        }
      /* Hy = Qb H Qb^T with Qb = blockdiag(Q) */
      double dH = 0;
      for (int a = 0; a < 12; a++)
        for (int b = 0; b < 12; b++) {
          double s = 0;
          for (int c = 0; c < 3; c++)
            for (int d = 0; d < 3; d++) s += Q[3 * (a % 3) + c] * H[(3 * (a / 3) + c) * 12 + 3 * (b / 3) + d] * Q[3 * (b % 3) + d];
          dH = fmax(dH, fabs(s - Hy[a * 12 + b]));
        }
      HYLC_CHECK(dH <= 1e-9 * sH, "Hessian not covariant: %g of %g", dH, sH);
      for (int k = 0; k < 3; k++) HYLC_CHECK_CLOSE(g[k] + g[3 + k] + g[6 + k] + g[9 + k], 0, 1e-12 * sg);
      for (int i = 0; i < 12; i++) { /* rows of H annihilate translations */
        for (int k = 0; k < 3; k++) HYLC_CHECK_CLOSE(H[i * 12 + k] + H[i * 12 + 3 + k] + H[i * 12 + 6 + k] + H[i * 12 + 9 + k], 0, 1e-10 * sH);
      }
      const double w0 = m->w;
      m->w            = 2 * w0;
      HYLC_CHECK_REL(Eval(m, x, NULL, NULL), 2 * E, 1e-15);
      m->w = w0;
    }
  }

  /* rejection far away and the optional outputs */
  {
    double x[12] = {0, 0, 0, r, 0, 0, 0, 0, 5 * r, r, 0, 5 * r}, g[12], H[144], s, t, d;
    for (int i = 0; i < 12; i++) g[i] = 1;
    for (int i = 0; i < 144; i++) H[i] = 1;
    HYLC_CHECK(Eval(&mq, x, g, H) == 0 && MaxAbs(g, 12) == 0 && MaxAbs(H, 144) == 0, "quad: far pair not zeroed");
    HYLC_CHECK(HylcContactClosestPoint(x, x + 3, x + 6, x + 9, r, r, kc, r, 1, NULL, NULL, &s, &t, &d) == 0 && d == 5 * r, "closest: far pair");
    Model bad = mq;
    bad.n     = 0;
    HYLC_CHECK(isnan(Eval(&bad, x, NULL, NULL)), "n = 0 not rejected");
  }
  if (getenv("HYLC_TEST_VERBOSE")) printf("worst FD relative errors: gradient %.2e, Hessian %.2e\n", maxerr_g, maxerr_H);
  return HYLC_TEST_RESULT();
}
