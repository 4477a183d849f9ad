/* Shape-preserving kernels of the fit (include/hylc/monotone.h), as property tests:
   - on random monotone data the 1D and 2D interpolants are monotone on a dense sampling of every cell;
   - on random non-monotone data every cell whose data are monotone in x (or y) stays monotone, also in
     the extrapolated strips (with extrapolation bounds and muv = 0 on the boundary);
   - data of a cubic (1D) or bicubic (2D) with inactive constraints are reproduced exactly;
   - the six-case projection never increases a slope's magnitude or flips its sign;
   - quasiconvex marching gives increments >= reg along every ray from the minimum. */
#include <hylc/monotone.h>
#include <hylc/spline.h>
#include "hylctest.h"

#define NS 24 /* samples per cell and direction */

/* sense of a 1D edge: +1 increasing, -1 decreasing, 0 constant */
static int Sense(double a, double b) { return b > a ? 1 : (b < a ? -1 : 0); }

/* checks that x -> f is monotone with sense s on [x0, x1] (sampled), with a relative tolerance */
static int Monotone1D(int n, const double *t, const double *p, const double *m, double x0, double x1, int s, double tol)
{
  double prev = HylcHermite1DEval(n, t, p, m, HYLC_EXT_LINEAR, x0, NULL, NULL);
  for (int k = 1; k <= NS; k++) {
    const double x = x0 + (x1 - x0) * k / NS, f = HylcHermite1DEval(n, t, p, m, HYLC_EXT_LINEAR, x, NULL, NULL);
    if (s * (f - prev) < -tol) return 0;
    prev = f;
  }
  return 1;
}

static void Test1D(void)
{
  unsigned long long st = 7;
  const int          n  = 11;
  double             t[11], p[11], m[11], m0[11];

  for (int trial = 0; trial < 400; trial++) {
    const HylcMonotoneRule rule = trial % 2 ? HYLC_MONOTONE_BOX : HYLC_MONOTONE_CIRCLE;
    const int              mono = trial < 200;
    t[0]                        = -1;
    for (int i = 1; i < n; i++) t[i] = t[i - 1] + 0.05 + HylcTestRand(&st);
    p[0] = HylcTestRand(&st);
    for (int i = 1; i < n; i++) p[i] = mono ? p[i - 1] + (HylcTestRand(&st) < 0.1 ? 0 : HylcTestRand(&st)) : HylcTestRand(&st) - 0.5;
    for (int i = 0; i < n; i++) m[i] = 6 * (HylcTestRand(&st) - 0.5);
    HylcMonotoneCubic(n, t, p, m, rule, 1e-14);
    for (int i = 0; i < n - 1; i++) {
      const int s = Sense(p[i], p[i + 1]);
      if (s == 0) {
        HYLC_CHECK(m[i] == 0 && m[i + 1] == 0, "trial %d: flat interval %d keeps slopes %g %g", trial, i, m[i], m[i + 1]);
        continue;
      }
      HYLC_CHECK(Monotone1D(n, t, p, m, t[i], t[i + 1], s, 1e-13), "trial %d (%s, rule %d): interval %d not monotone", trial, mono ? "monotone" : "random", rule, i);
    }
  }
  /* a cubic with inactive constraints is reproduced exactly */
  for (int i = 0; i < n; i++) {
    t[i]  = -1 + 0.2 * i;
    p[i]  = 0.5 + t[i] + 0.1 * t[i] * t[i] * t[i];
    m[i]  = 1 + 0.3 * t[i] * t[i];
    m0[i] = m[i];
  }
  for (int rule = 0; rule < 2; rule++) {
    HylcMonotoneCubic(n, t, p, m, (HylcMonotoneRule)rule, 1e-8);
    for (int i = 0; i < n; i++) HYLC_CHECK(m[i] == m0[i], "cubic slope %d changed: %g -> %g", i, m0[i], m[i]);
    for (int k = 0; k <= 100; k++) {
      const double x = -1 + 2.0 * k / 100;
      HYLC_CHECK_CLOSE(HylcHermite1DEval(n, t, p, m, HYLC_EXT_LINEAR, x, NULL, NULL), 0.5 + x + 0.1 * x * x * x, 1e-14);
    }
  }
  /* marching: increments of at least reg * dt away from the minimum, outward slopes >= reg */
  for (int trial = 0; trial < 50; trial++) {
    const double reg  = 1e-2;
    const int    imin = trial % n;
    for (int i = 0; i < n; i++) {
      t[i] = -1 + 0.2 * i;
      p[i] = HylcTestRand(&st);
      m[i] = HylcTestRand(&st) - 0.5;
    }
    HylcQuasiconvex1D(n, t, imin, reg, p, m);
    for (int i = imin; i < n - 1; i++) HYLC_CHECK(p[i + 1] >= p[i] + 0.2 * reg * (1 - 1e-12) && m[i + 1] >= reg, "march right at %d", i);
    for (int i = imin; i > 0; i--) HYLC_CHECK(p[i - 1] >= p[i] + 0.2 * reg * (1 - 1e-12) && m[i - 1] <= -reg, "march left at %d", i);
    HylcMonotoneCubic(n, t, p, m, HYLC_MONOTONE_CIRCLE, 1e-8);
    for (int i = 0; i < n - 1; i++) HYLC_CHECK(Monotone1D(n, t, p, m, t[i], t[i + 1], i >= imin ? 1 : -1, 1e-14), "marched spline not monotone on %d", i);
  }
}

typedef struct {
  int    nu, nv;
  double tu[12], tv[12], p[144], mu[144], mv[144], muv[144];
} Grid;

static double G(const Grid *g, double u, double v) { return HylcHermite2DEval(g->nu, g->nv, g->tu, g->tv, g->p, g->mu, g->mv, g->muv, HYLC_EXT_LINEAR, u, v, NULL, NULL); }

/* monotone in u with sense s on [u0,u1] x [v0,v1] (dir 0), or in v (dir 1) */
static int MonotoneCell(const Grid *g, int dir, double u0, double u1, double v0, double v1, int s, double tol)
{
  for (int b = 0; b <= NS; b++) {
    double prev = 0;
    for (int a = 0; a <= NS; a++) {
      const double u = dir == 0 ? u0 + (u1 - u0) * a / NS : u0 + (u1 - u0) * b / NS;
      const double v = dir == 0 ? v0 + (v1 - v0) * b / NS : v0 + (v1 - v0) * a / NS;
      const double f = G(g, u, v);
      if (a > 0 && s * (f - prev) < -tol) return 0;
      prev = f;
    }
  }
  return 1;
}

static void RandomGrid(Grid *g, unsigned long long *st, int monotone)
{
  g->nu    = 5 + (int)(5 * HylcTestRand(st));
  g->nv    = 5 + (int)(5 * HylcTestRand(st));
  g->tu[0] = -1;
  g->tv[0] = -0.7;
  for (int i = 1; i < g->nu; i++) g->tu[i] = g->tu[i - 1] + 0.05 + HylcTestRand(st);
  for (int j = 1; j < g->nv; j++) g->tv[j] = g->tv[j - 1] + 0.05 + HylcTestRand(st);
  for (int j = 0; j < g->nv; j++)
    for (int i = 0; i < g->nu; i++) {
      const int k = j * g->nu + i;
      if (monotone) { /* increasing in both directions, with some flat edges */
        const double r = HylcTestRand(st) < 0.15 ? 0 : HylcTestRand(st);
        g->p[k]        = r + (i ? g->p[k - 1] : 0) + (j ? g->p[k - g->nu] : 0) - (i && j ? g->p[k - g->nu - 1] : 0);
      } else
        g->p[k] = HylcTestRand(st) - 0.5;
      g->mu[k]  = 8 * (HylcTestRand(st) - 0.5);
      g->mv[k]  = 8 * (HylcTestRand(st) - 0.5);
      g->muv[k] = 30 * (HylcTestRand(st) - 0.5);
    }
}

static void Test2D(void)
{
  unsigned long long st = 11;
  Grid               g;
  int                ncheckedU = 0, ncheckedV = 0;

  for (int trial = 0; trial < 300; trial++) {
    const int           mono   = trial < 100;
    const PetscBool     extrap = (PetscBool)(trial % 2);
    const HylcFitCompat compat = trial % 3 == 2 ? HYLC_FIT_COMPAT_AUTHORS : HYLC_FIT_COMPAT_PAPER;
    RandomGrid(&g, &st, mono);
    HYLC_CHECK(HylcMonotoneBicubic(g.nu, g.nv, g.tu, g.tv, g.p, g.mu, g.mv, g.muv, extrap, compat) == 0, "bicubic failed");
    if (extrap) { /* as the fit does: zero mixed derivative on the boundary */
      for (int j = 0; j < g.nv; j++)
        for (int i = 0; i < g.nu; i++)
          if (i == 0 || j == 0 || i == g.nu - 1 || j == g.nv - 1) g.muv[j * g.nu + i] = 0;
    }
    /* cells (including the extrapolated strips beyond the first/last knot when extrapolating) */
    for (int j = -1; j < g.nv; j++)
      for (int i = -1; i < g.nu; i++) {
        const int    inU = i >= 0 && i < g.nu - 1, inV = j >= 0 && j < g.nv - 1;
        const double u0 = i < 0 ? g.tu[0] - 0.5 : g.tu[i], u1 = i < 0 ? g.tu[0] : (i < g.nu - 1 ? g.tu[i + 1] : g.tu[i] + 0.5);
        const double v0 = j < 0 ? g.tv[0] - 0.5 : g.tv[j], v1 = j < 0 ? g.tv[0] : (j < g.nv - 1 ? g.tv[j + 1] : g.tv[j] + 0.5);
        if (!extrap && !(inU && inV)) continue;
        if (!inU && !inV) continue; /* corner regions: monotone only if both senses agree; not claimed */
        /* monotone in u: both horizontal edges of the cell (one for a strip) with one sense */
        if (inU) {
          const int ja = j < 0 ? 0 : j, jb = j < 0 ? 0 : (j < g.nv - 1 ? j + 1 : j);
          const int s0 = Sense(g.p[ja * g.nu + i], g.p[ja * g.nu + i + 1]), s1 = Sense(g.p[jb * g.nu + i], g.p[jb * g.nu + i + 1]);
          const int s = s0 ? s0 : s1;
          if (s && (s0 == s || s0 == 0) && (s1 == s || s1 == 0) && compat == HYLC_FIT_COMPAT_PAPER) {
            ncheckedU++;
            HYLC_CHECK(MonotoneCell(&g, 0, u0, u1, v0, v1, s, 1e-12), "trial %d (%s, extrap %d, compat %d): cell (%d,%d) not monotone in u", trial, mono ? "monotone" : "random", (int)extrap, (int)compat, i, j);
          }
        }
        if (inV) {
          const int ia = i < 0 ? 0 : i, ib = i < 0 ? 0 : (i < g.nu - 1 ? i + 1 : i);
          const int s0 = Sense(g.p[j * g.nu + ia], g.p[(j + 1) * g.nu + ia]), s1 = Sense(g.p[j * g.nu + ib], g.p[(j + 1) * g.nu + ib]);
          const int s = s0 ? s0 : s1;
          if (s && (s0 == s || s0 == 0) && (s1 == s || s1 == 0)) {
            ncheckedV++;
            HYLC_CHECK(MonotoneCell(&g, 1, u0, u1, v0, v1, s, 1e-12), "trial %d (%s, extrap %d, compat %d): cell (%d,%d) not monotone in v", trial, mono ? "monotone" : "random", (int)extrap, (int)compat, i, j);
          }
        }
      }
  }
  HYLC_CHECK(ncheckedU > 2000 && ncheckedV > 2000, "too few monotone cells checked: %d %d", ncheckedU, ncheckedV);

  /* a bicubic with inactive constraints is reproduced exactly */
  g.nu = 7;
  g.nv = 6;
  for (int i = 0; i < g.nu; i++) g.tu[i] = -1 + i / 3.0;
  for (int j = 0; j < g.nv; j++) g.tv[j] = -0.5 + 0.3 * j;
  for (int j = 0; j < g.nv; j++)
    for (int i = 0; i < g.nu; i++) {
      const double u = g.tu[i], v = g.tv[j];
      const int    k = j * g.nu + i;
      g.p[k]         = u + 2 * v + 0.1 * u * v + 0.05 * u * u * u + 0.03 * v * v * v + 0.02 * u * u * v;
      g.mu[k]        = 1 + 0.1 * v + 0.15 * u * u + 0.04 * u * v;
      g.mv[k]        = 2 + 0.1 * u + 0.09 * v * v + 0.02 * u * u;
      g.muv[k]       = 0.1 + 0.04 * u;
    }
  for (int compat = 0; compat < 2; compat++) {
    Grid h = g;
    HylcMonotoneBicubic(h.nu, h.nv, h.tu, h.tv, h.p, h.mu, h.mv, h.muv, PETSC_FALSE, (HylcFitCompat)compat);
    for (int k = 0; k < g.nu * g.nv; k++) HYLC_CHECK(h.mu[k] == g.mu[k] && h.mv[k] == g.mv[k] && h.muv[k] == g.muv[k], "bicubic data changed at node %d (compat %d)", k, compat);
    for (int a = 0; a <= 30; a++)
      for (int b = 0; b <= 30; b++) {
        const double u = -1 + 2.0 * a / 30 - (a == 30 ? 1e-12 : 0), v = -0.5 + 1.5 * b / 30 - (b == 30 ? 1e-12 : 0);
        HYLC_CHECK_CLOSE(G(&h, u, v), u + 2 * v + 0.1 * u * v + 0.05 * u * u * u + 0.03 * v * v * v + 0.02 * u * u * v, 1e-12);
      }
  }

  /* 2D marching: every step away from the minimum raises p by >= reg * dt along rows and columns */
  for (int trial = 0; trial < 40; trial++) {
    const double reg = 1e-3;
    RandomGrid(&g, &st, 0);
    const int imin = trial % g.nu, jmin = (3 * trial) % g.nv;
    HYLC_CHECK(HylcQuasiconvex2D(g.nu, g.nv, g.tu, g.tv, imin, jmin, reg, HYLC_FIT_COMPAT_PAPER, g.p, g.mu, g.mv) == 0, "march failed");
    for (int j = 0; j < g.nv; j++)
      for (int i = 0; i < g.nu; i++) {
        const int k = j * g.nu + i;
        if (i != imin) {
          const int ii = i > imin ? i - 1 : i + 1;
          HYLC_CHECK(g.p[k] >= g.p[j * g.nu + ii] + reg * fabs(g.tu[i] - g.tu[ii]) * (1 - 1e-12), "row step at (%d,%d)", i, j);
          HYLC_CHECK((i > imin ? g.mu[k] : -g.mu[k]) >= reg, "mu sign at (%d,%d)", i, j);
        }
        if (j != jmin) {
          const int jj = j > jmin ? j - 1 : j + 1;
          HYLC_CHECK(g.p[k] >= g.p[jj * g.nu + i] + reg * fabs(g.tv[j] - g.tv[jj]) * (1 - 1e-12), "column step at (%d,%d)", i, j);
          HYLC_CHECK((j > jmin ? g.mv[k] : -g.mv[k]) >= reg, "mv sign at (%d,%d)", i, j);
        }
      }
    /* then the monotone bicubic keeps every cell monotone away from the minimum */
    HylcMonotoneBicubic(g.nu, g.nv, g.tu, g.tv, g.p, g.mu, g.mv, g.muv, PETSC_TRUE, HYLC_FIT_COMPAT_PAPER);
    for (int j = 0; j < g.nv - 1; j++)
      for (int i = 0; i < g.nu - 1; i++) {
        if (i != imin - 1 + (i >= imin)) HYLC_CHECK(MonotoneCell(&g, 0, g.tu[i], g.tu[i + 1], g.tv[j], g.tv[j + 1], i >= imin ? 1 : -1, 1e-12), "marched cell (%d,%d) not monotone in u", i, j);
        if (j != jmin - 1 + (j >= jmin)) HYLC_CHECK(MonotoneCell(&g, 1, g.tu[i], g.tu[i + 1], g.tv[j], g.tv[j + 1], j >= jmin ? 1 : -1, 1e-12), "marched cell (%d,%d) not monotone in v", i, j);
      }
  }
}

int main(void)
{
  Test1D();
  Test2D();
  return HYLC_TEST_RESULT();
}
