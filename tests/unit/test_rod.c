/* Unit tests of the rod element kernels (include/hylc/rod.h): finite-difference checks of every
   gradient and Hessian at random and hard configurations, consistency of the two energy paths,
   reference-twist branch selection, and the stretching special cases. */
#include "rodtest.h"

static const char *const term_name[4] = {"", "bend", "twist", "bend+twist"};

static double EnergySel(const double q[11], const HylcRodBendTwistRef *ref, const HylcRodBendTwistParams *par, double w, int terms)
{
  double E[2];
  HylcRodBendTwistEnergy(q, ref, par, w, E);
  return ((terms & HYLC_ROD_BEND) ? E[0] : 0) + ((terms & HYLC_ROD_TWIST) ? E[1] : 0);
}

/* Central differences of the energy (plain-arithmetic path) against g, and of g against H. */
static void CheckBendTwistFD(const RodElem *el, const HylcRodBendTwistParams *par, double w, double hscale, const char *label)
{
  const double lmin = fmin(HylcNorm3((double[3]){el->q[4] - el->q[0], el->q[5] - el->q[1], el->q[6] - el->q[2]}), HylcNorm3((double[3]){el->q[8] - el->q[4], el->q[9] - el->q[5], el->q[10] - el->q[6]}));
  for (int terms = 1; terms <= 3; terms++) {
    double E[2], E2[2], g[11], H[121], gfd[11], Hfd[121], q[11];
    int    ierr = HylcRodBendTwist(el->q, &el->ref, par, w, terms, E, g, H);
    HYLC_CHECK(ierr == 0, "%s: element reported degenerate", label);
    if (ierr) return;
    HylcRodBendTwistEnergy(el->q, &el->ref, par, w, E2);
    for (int k = 0; k < 2; k++) HYLC_CHECK(fabs(E[k] - E2[k]) <= 1e-10 * (fabs(E2[k]) + 1e-12 * (fabs(E2[0]) + fabs(E2[1]))), "%s: energy %d %.17g (hyper-dual) vs %.17g (plain)", label, k, E[k], E2[k]);
    for (int k = 0; k < 11; k++) {
      const double h = (k == 3 || k == 7 ? 1e-6 : 1e-6 * lmin) * hscale;
      double       gp[11], gm[11];
      memcpy(q, el->q, sizeof q);
      q[k] += h;
      const double Ep = EnergySel(q, &el->ref, par, w, terms);
      HylcRodBendTwist(q, &el->ref, par, w, terms, NULL, gp, NULL);
      q[k] -= 2 * h;
      const double Em = EnergySel(q, &el->ref, par, w, terms);
      HylcRodBendTwist(q, &el->ref, par, w, terms, NULL, gm, NULL);
      gfd[k] = (Ep - Em) / (2 * h);
      for (int i = 0; i < 11; i++) Hfd[i * 11 + k] = (gp[i] - gm[i]) / (2 * h);
    }
    /* errors relative to the largest entry; near a stationary point (exactly straight at zero rest
       curvature) the gradient is measured against the size H l 1e-4 of a gradient 1e-4 l away from it */
    const double Hn = MaxAbs(H, 121), gn = fmax(MaxAbs(g, 11), 1e-4 * lmin * Hn);
    const double eg = MaxAbsDiff(g, gfd, 11) / gn, eH = MaxAbsDiff(H, Hfd, 121) / Hn;
    HYLC_CHECK(gn > 0 && eg < 1e-6, "%s (%s, variant %d): gradient rel. error %.3g (|g| %.3g)", label, term_name[terms], (int)par->variant, eg, gn);
    HYLC_CHECK(Hn > 0 && eH < 1e-5, "%s (%s, variant %d): Hessian rel. error %.3g (|H| %.3g)", label, term_name[terms], (int)par->variant, eH, Hn);
    double asym = 0;
    for (int i = 0; i < 11; i++)
      for (int j = 0; j < 11; j++) asym = fmax(asym, fabs(H[i * 11 + j] - H[j * 11 + i]));
    HYLC_CHECK(asym <= 1e-14 * Hn, "%s: Hessian not symmetric (%.3g)", label, asym);
  }
  /* the separate terms add up to the combined one */
  double gb[11], gt[11], gbt[11], Hb[121], Ht[121], Hbt[121];
  HylcRodBendTwist(el->q, &el->ref, par, w, HYLC_ROD_BEND, NULL, gb, Hb);
  HylcRodBendTwist(el->q, &el->ref, par, w, HYLC_ROD_TWIST, NULL, gt, Ht);
  HylcRodBendTwist(el->q, &el->ref, par, w, HYLC_ROD_BENDTWIST, NULL, gbt, Hbt);
  for (int i = 0; i < 11; i++) HYLC_CHECK(fabs(gb[i] + gt[i] - gbt[i]) <= 1e-13 * MaxAbs(gbt, 11), "%s: bend + twist gradient", label);
  for (int i = 0; i < 121; i++) HYLC_CHECK(fabs(Hb[i] + Ht[i] - Hbt[i]) <= 1e-13 * MaxAbs(Hbt, 121), "%s: bend + twist Hessian", label);
}

static void CheckBothVariants(const RodElem *el, double w, double hscale, const char *label)
{
  HylcRodBendTwistParams par = {.B = 1.3, .beta = 0.9, .variant = HYLC_ROD_CURVATURE_AVERAGED};
  CheckBendTwistFD(el, &par, w, hscale, label);
  par.variant = HYLC_ROD_CURVATURE_PER_EDGE;
  CheckBendTwistFD(el, &par, w, hscale, label);
}

static void TestBendTwistFD(void)
{
  unsigned long long st = 20240607;
  RodElem            el;
  char               label[128];

  /* random configurations */
  for (int trial = 0; trial < 40; trial++) {
    RodElemSpec s = {.le        = RandRange(&st, 0.5, 2),
                     .lf        = RandRange(&st, 0.5, 2),
                     .angle     = RandRange(&st, 0, 2.5),
                     .thetae    = RandRange(&st, -4, 4),
                     .thetaf    = RandRange(&st, -4, 4),
                     .perturb   = trial % 2 ? 0.2 : 0.0,
                     .mstored   = NAN,
                     .nwrap     = trial % 3 - 1,
                     .restscale = 1.0};
    RodElemBuild(&st, &s, &el);
    snprintf(label, sizeof label, "random %d", trial);
    CheckBothVariants(&el, RandRange(&st, 0.2, 1), 1.0, label);
  }
  /* nearly straight (and exactly straight); zero and nonzero rest values */
  const double small[4] = {0.0, 1e-8, 1e-5, 1e-3};
  for (int k = 0; k < 4; k++)
    for (int r = 0; r < 2; r++) {
      RodElemSpec s = {.le = 1, .lf = 1.3, .angle = small[k], .thetae = 0.3, .thetaf = -0.2, .perturb = r ? 0.05 : 0, .mstored = 0.1, .restscale = r ? 0.5 : 0.0};
      RodElemBuild(&st, &s, &el);
      snprintf(label, sizeof label, "nearly straight %g rest %d", small[k], r);
      CheckBothVariants(&el, 1.0, 1.0, label);
    }
  /* sharply bent: 1 + cos(angle) down to ~1e-3 */
  const double sharp[4] = {2.8, 3.0, 3.1, 3.13};
  for (int k = 0; k < 4; k++) {
    RodElemSpec s = {.le = 0.8, .lf = 1.1, .angle = sharp[k], .thetae = 1.0, .thetaf = 2.0, .perturb = 0.01, .mstored = NAN, .restscale = 1.0};
    RodElemBuild(&st, &s, &el);
    snprintf(label, sizeof label, "sharply bent %g", sharp[k]);
    CheckBothVariants(&el, 1.0, 1.0, label);
  }
  /* large twists: theta differences near +-pi, stored reference twist near +-pi (branch crossing) */
  for (int k = 0; k < 8; k++) {
    const double sg = k % 2 ? 1 : -1;
    RodElemSpec  s  = {.le = 1, .lf = 1, .angle = 0.7, .thetae = 0.1, .thetaf = 0.1 + sg * (M_PI - 1e-3), .perturb = 0.05, .mstored = sg * (M_PI - 1e-3 * k), .nwrap = k / 2 - 2, .restscale = 1.0};
    RodElemBuild(&st, &s, &el);
    snprintf(label, sizeof label, "large twist %d", k);
    CheckBothVariants(&el, 1.0, 1.0, label);
  }
  /* edges of very different lengths */
  for (int k = 0; k < 4; k++) {
    RodElemSpec s = {.le = k % 2 ? 1.0 : 0.01, .lf = k % 2 ? 0.01 : 1.0, .angle = k < 2 ? 0.5 : 2.0, .thetae = -0.4, .thetaf = 0.6, .perturb = 0.1, .mstored = NAN, .restscale = 1.0};
    RodElemBuild(&st, &s, &el);
    snprintf(label, sizeof label, "different lengths %d", k);
    CheckBothVariants(&el, 0.5, 1.0, label);
  }
}

/* The reference twist follows the stored branch continuously across +-pi. */
static void TestBranch(void)
{
  unsigned long long st = 99;
  RodElem            el;
  for (int k = 0; k < 20; k++) {
    const double mst = (k % 2 ? 1 : -1) * (M_PI - 1e-4);
    RodElemSpec  s   = {.le = 1, .lf = 1, .angle = 1.0, .thetae = 0, .thetaf = 0, .perturb = 0.02, .mstored = mst, .nwrap = k % 5 - 2, .restscale = 0};
    RodElemBuild(&st, &s, &el);
    double m, tau;
    HylcRodBendTwistStrains(el.q, &el.ref, NULL, NULL, &tau, &m);
    HYLC_CHECK(fabs(m - el.ref.mref) < 0.2, "branch: m = %g far from stored %g", m, el.ref.mref);
    HYLC_CHECK_CLOSE(tau, m + el.q[7] - el.q[3], 1e-14);
  }
  HYLC_CHECK_CLOSE(HylcAngleNear(0.5, 4 * M_PI + 0.4), 4 * M_PI + 0.5, 1e-14);
  HYLC_CHECK_CLOSE(HylcAngleNear(-3.1, 3.1), 2 * M_PI - 3.1, 1e-14);
  HYLC_CHECK_CLOSE(HylcAngleNear(1.0, NAN), 1.0, 0);
}

/* Degenerate elements are reported, not computed. */
static void TestDegenerate(void)
{
  HylcRodBendTwistParams par   = {.B = 1, .beta = 1, .variant = HYLC_ROD_CURVATURE_AVERAGED};
  HylcRodBendTwistRef    ref   = {.te = {1, 0, 0}, .d1e = {0, 1, 0}, .tf = {1, 0, 0}, .d1f = {0, 1, 0}, .lbar = 1};
  double                 q[11] = {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0}, E[2], g[11], H[121];
  HYLC_CHECK(HylcRodBendTwist(q, &ref, &par, 1, 3, E, g, H) == -1 && E[0] == HUGE_VAL && g[0] == 0, "folded element not reported");
  HYLC_CHECK(HylcRodBendTwistEnergy(q, &ref, &par, 1, E) == -1 && E[1] == HUGE_VAL, "folded element not reported (energy)");
  const double x[6] = {1, 2, 3, 1, 2, 3};
  double       Es, gs[6], Hs[36];
  HYLC_CHECK(HylcRodStretch(x, 1, 1, 1, &Es, gs, Hs) == -1 && Es == HUGE_VAL, "zero-length edge not reported");
}

static void TestStretch(void)
{
  unsigned long long st = 777;
  /* finite differences at random lengths, compressed and extended */
  for (int trial = 0; trial < 50; trial++) {
    double x[6], g[6], H[36], gfd[6], Hfd[36], E;
    for (int i = 0; i < 6; i++) x[i] = RandRange(&st, -1, 1);
    const double l    = HylcNorm3((double[3]){x[3] - x[0], x[4] - x[1], x[5] - x[2]});
    const double lbar = l * RandRange(&st, 0.5, 1.5), ks = RandRange(&st, 0.5, 5), w = RandRange(&st, 0.1, 1);
    HylcRodStretch(x, lbar, ks, w, &E, g, H);
    HYLC_CHECK_REL(E, 0.5 * w * ks * lbar * (l / lbar - 1) * (l / lbar - 1), 1e-13);
    for (int k = 0; k < 6; k++) {
      double       xp[6], gp[6], gm[6];
      const double h = 1e-6 * l;
      memcpy(xp, x, sizeof xp);
      xp[k] += h;
      const double Ep = HylcRodStretchEnergy(xp, lbar, ks, w);
      HylcRodStretch(xp, lbar, ks, w, NULL, gp, NULL);
      xp[k] -= 2 * h;
      const double Em = HylcRodStretchEnergy(xp, lbar, ks, w);
      HylcRodStretch(xp, lbar, ks, w, NULL, gm, NULL);
      gfd[k] = (Ep - Em) / (2 * h);
      for (int i = 0; i < 6; i++) Hfd[i * 6 + k] = (gp[i] - gm[i]) / (2 * h);
    }
    const double eg = MaxAbsDiff(g, gfd, 6) / MaxAbs(g, 6), eH = MaxAbsDiff(H, Hfd, 36) / MaxAbs(H, 36);
    HYLC_CHECK(eg < 1e-6, "stretch %d: gradient rel. error %.3g", trial, eg);
    HYLC_CHECK(eH < 1e-5, "stretch %d: Hessian rel. error %.3g", trial, eH);
    /* invariance under a rigid motion */
    double R[9], y[6], b[3];
    RandRotation(&st, R);
    RandUnit(&st, b);
    MatVec3(R, x, y);
    MatVec3(R, x + 3, y + 3);
    for (int i = 0; i < 3; i++) {
      y[i] += 3 * b[i];
      y[3 + i] += 3 * b[i];
    }
    HYLC_CHECK_REL(HylcRodStretchEnergy(y, lbar, ks, w), E, 1e-12);
  }
  /* a straight rod of N edges stretched by eps: N * 1/2 ks eps^2 lbar */
  {
    const int    N    = 10;
    const double lbar = 0.3, eps = 0.02, ks = HylcRodStretchStiffness(2.0, 0.1), dir[3] = {0.6, 0, 0.8};
    double       Etot = 0;
    for (int j = 0; j < N; j++) {
      double x[6];
      for (int i = 0; i < 3; i++) {
        x[i]     = j * (1 + eps) * lbar * dir[i];
        x[3 + i] = (j + 1) * (1 + eps) * lbar * dir[i];
      }
      Etot += HylcRodStretchEnergy(x, lbar, ks, 1.0);
    }
    HYLC_CHECK_REL(Etot, N * 0.5 * ks * eps * eps * lbar, 1e-12);
    HYLC_CHECK_REL(ks, 2.0 * M_PI * 0.01, 1e-15);
  }
}

int main(void)
{
  TestStretch();
  TestBendTwistFD();
  TestBranch();
  TestDegenerate();
  return HYLC_TEST_RESULT();
}
