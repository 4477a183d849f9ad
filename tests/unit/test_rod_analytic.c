/* Rod element kernels against exact results: rigid-motion invariance, the DER closed-form gradients
   of method spec 3.3, a polygon inscribed in a circle (discretization convergence of the bending
   energy), a uniformly twisted straight rod, and the weight factor. */
#include "rodtest.h"

/* q' = rigid motion of q (rotation R about the origin, then translation b); frames rotated too */
static void RigidMotion(const RodElem *in, const double R[9], const double b[3], RodElem *out)
{
  *out = *in;
  for (int a = 0; a < 3; a++) {
    MatVec3(R, in->q + 4 * a, out->q + 4 * a);
    for (int i = 0; i < 3; i++) out->q[4 * a + i] += b[i];
  }
  MatVec3(R, in->ref.te, out->ref.te);
  MatVec3(R, in->ref.tf, out->ref.tf);
  MatVec3(R, in->ref.d1e, out->ref.d1e);
  MatVec3(R, in->ref.d1f, out->ref.d1f);
}

static void TestInvariance(void)
{
  unsigned long long st = 4242;
  for (int trial = 0; trial < 30; trial++) {
    RodElemSpec s = {.le        = RandRange(&st, 0.05, 2),
                     .lf        = RandRange(&st, 0.05, 2),
                     .angle     = RandRange(&st, 0, 3),
                     .thetae    = RandRange(&st, -4, 4),
                     .thetaf    = RandRange(&st, -4, 4),
                     .perturb   = 0.1 * (trial % 3),
                     .mstored   = trial % 2 ? NAN : M_PI - 1e-3,
                     .nwrap     = trial % 3 - 1,
                     .restscale = 1};
    RodElem     el, mv;
    double      R[9], b[3];
    RodElemBuild(&st, &s, &el);
    RandRotation(&st, R);
    RandUnit(&st, b);
    HylcScale3(RandRange(&st, 0, 10), b);
    RigidMotion(&el, R, b, &mv);
    for (int variant = 0; variant < 2; variant++) {
      const HylcRodBendTwistParams par = {.B = 2.0, .beta = 0.7, .variant = (HylcRodCurvatureVariant)variant};
      double                       E0[2], E1[2], g0[11], g1[11], H0[121], H1[121], Rg[11];
      HylcRodBendTwist(el.q, &el.ref, &par, 1.0, HYLC_ROD_BENDTWIST, E0, g0, H0);
      HylcRodBendTwist(mv.q, &mv.ref, &par, 1.0, HYLC_ROD_BENDTWIST, E1, g1, H1);
      for (int k = 0; k < 2; k++) HYLC_CHECK(fabs(E1[k] - E0[k]) <= 1e-11 * (E0[0] + E0[1]), "invariance %d: energy %d: %.17g vs %.17g", trial, k, E1[k], E0[k]);
      double Ep[2];
      HylcRodBendTwistEnergy(mv.q, &mv.ref, &par, 1.0, Ep);
      for (int k = 0; k < 2; k++) HYLC_CHECK(fabs(Ep[k] - E0[k]) <= 1e-11 * (E0[0] + E0[1]), "invariance %d: energy-only %d: %.17g vs %.17g", trial, k, Ep[k], E0[k]);
      /* the gradient rotates with the positions; the Hessian transforms as Q H Q^T */
      memcpy(Rg, g0, sizeof Rg);
      for (int a = 0; a < 3; a++) MatVec3(R, g0 + 4 * a, Rg + 4 * a);
      HYLC_CHECK(MaxAbsDiff(Rg, g1, 11) <= 1e-10 * MaxAbs(g0, 11), "invariance %d: gradient", trial);
      double Q[121] = {0}, QH[121], QHQ[121];
      for (int a = 0; a < 3; a++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) Q[(4 * a + i) * 11 + 4 * a + j] = R[3 * i + j];
      Q[3 * 11 + 3] = Q[7 * 11 + 7] = 1;
      for (int i = 0; i < 11; i++)
        for (int j = 0; j < 11; j++) {
          double sum = 0;
          for (int k = 0; k < 11; k++) sum += Q[i * 11 + k] * H0[k * 11 + j];
          QH[i * 11 + j] = sum;
        }
      for (int i = 0; i < 11; i++)
        for (int j = 0; j < 11; j++) {
          double sum = 0;
          for (int k = 0; k < 11; k++) sum += QH[i * 11 + k] * Q[j * 11 + k];
          QHQ[i * 11 + j] = sum;
        }
      HYLC_CHECK(MaxAbsDiff(QHQ, H1, 121) <= 1e-10 * MaxAbs(H0, 121), "invariance %d: Hessian", trial);
    }
  }
}

/* At stored tangents = current tangents, the gradients equal the DER closed forms (spec 3.3). */
static void TestClosedFormGradients(void)
{
  unsigned long long st = 31337;
  for (int trial = 0; trial < 30; trial++) {
    RodElemSpec s = {.le = RandRange(&st, 0.3, 2), .lf = RandRange(&st, 0.3, 2), .angle = RandRange(&st, 0, 2.8), .thetae = RandRange(&st, -4, 4), .thetaf = RandRange(&st, -4, 4), .perturb = 0, .mstored = NAN, .restscale = 0};
    RodElem     el;
    RodElemBuild(&st, &s, &el);
    double kappa[2], tau;
    HylcRodBendTwistStrains(el.q, &el.ref, kappa, NULL, &tau, NULL);
    /* with B/lbar = 1, rest kappa - (1,0) the bending gradient is grad kappa1, and so on */
    HylcRodBendTwistParams par = {.B = el.ref.lbar, .beta = el.ref.lbar, .variant = HYLC_ROD_CURVATURE_AVERAGED};
    double                 dk[2][11], dtau[11];
    for (int c = 0; c < 2; c++) {
      el.ref.kappa0[0] = kappa[0] - (c == 0);
      el.ref.kappa0[1] = kappa[1] - (c == 1);
      HylcRodBendTwist(el.q, &el.ref, &par, 1.0, HYLC_ROD_BEND, NULL, dk[c], NULL);
    }
    el.ref.tau0 = tau - 1;
    HylcRodBendTwist(el.q, &el.ref, &par, 1.0, HYLC_ROD_TWIST, NULL, dtau, NULL);

    double e[3], f[3], te[3], tf[3], d1e[3], d2e[3], d1f[3], d2f[3], m1e[3], m2e[3], m1f[3], m2f[3], kb[3];
    HylcSub3(el.q + 4, el.q, e);
    HylcSub3(el.q + 8, el.q + 4, f);
    const double le = HylcNorm3(e), lf = HylcNorm3(f);
    memcpy(te, el.ref.te, sizeof te);
    memcpy(tf, el.ref.tf, sizeof tf);
    memcpy(d1e, el.ref.d1e, sizeof d1e);
    memcpy(d1f, el.ref.d1f, sizeof d1f);
    HylcCross3(te, d1e, d2e);
    HylcCross3(tf, d1f, d2f);
    HylcMaterialFrame(d1e, d2e, el.q[3], m1e, m2e);
    HylcMaterialFrame(d1f, d2f, el.q[7], m1f, m2f);
    const double chi = HylcCurvatureBinormal(te, tf, kb);
    double       tt[3], dt1[3], dt2[3], a[3], b[3];
    for (int i = 0; i < 3; i++) {
      tt[i]  = (te[i] + tf[i]) / chi;
      dt1[i] = (m1e[i] + m1f[i]) / chi;
      dt2[i] = (m2e[i] + m2f[i]) / chi;
    }
    double dkde[2][3], dkdf[2][3], dmde[3], dmdf[3];
    HylcCross3(tf, dt2, a);
    HylcCross3(te, dt2, b);
    for (int i = 0; i < 3; i++) {
      dkde[0][i] = (-kappa[0] * tt[i] + a[i]) / le;
      dkdf[0][i] = (-kappa[0] * tt[i] - b[i]) / lf;
    }
    HylcCross3(tf, dt1, a);
    HylcCross3(te, dt1, b);
    for (int i = 0; i < 3; i++) {
      dkde[1][i] = (-kappa[1] * tt[i] - a[i]) / le;
      dkdf[1][i] = (-kappa[1] * tt[i] + b[i]) / lf;
      dmde[i]    = kb[i] / (2 * le);
      dmdf[i]    = kb[i] / (2 * lf);
    }
    const double dkdth[2][2] = {{-0.5 * HylcDot3(kb, m1e), -0.5 * HylcDot3(kb, m1f)}, {-0.5 * HylcDot3(kb, m2e), -0.5 * HylcDot3(kb, m2f)}};
    for (int c = 0; c < 2; c++) {
      double ref[11];
      for (int i = 0; i < 3; i++) {
        ref[i]     = -dkde[c][i];
        ref[4 + i] = dkde[c][i] - dkdf[c][i];
        ref[8 + i] = dkdf[c][i];
      }
      ref[3] = dkdth[c][0];
      ref[7] = dkdth[c][1];
      HYLC_CHECK(MaxAbsDiff(ref, dk[c], 11) <= 1e-12 * MaxAbs(ref, 11) + 1e-14, "closed form grad kappa%d, trial %d: diff %.3g", c + 1, trial, MaxAbsDiff(ref, dk[c], 11));
    }
    double ref[11];
    for (int i = 0; i < 3; i++) {
      ref[i]     = -dmde[i];
      ref[4 + i] = dmde[i] - dmdf[i];
      ref[8 + i] = dmdf[i];
    }
    ref[3] = -1;
    ref[7] = 1;
    HYLC_CHECK(MaxAbsDiff(ref, dtau, 11) <= 1e-12 * MaxAbs(ref, 11), "closed form grad tau, trial %d: diff %.3g", trial, MaxAbsDiff(ref, dtau, 11));
  }
}

/* Total bending energy of a regular N-gon inscribed in a circle of radius R (rest curvature 0, rest
   lengths = edge lengths, twist-free frames: d1 = plane normal, theta = theta0 on every edge). */
static double CircleBendEnergy(int N, double R, const double Rot[9], double theta0, HylcRodCurvatureVariant variant, double *Etwist)
{
  const HylcRodBendTwistParams par  = {.B = 1.7, .beta = 0.4, .variant = variant};
  const double                 n[3] = {0, 0, 1};
  double                       Eb = 0, Et = 0;
  for (int i = 0; i < N; i++) {
    RodElem el;
    memset(&el, 0, sizeof el);
    for (int a = 0; a < 3; a++) {
      const double phi = 2 * M_PI * (i - 1 + a) / N, x[3] = {R * cos(phi), R * sin(phi), 0};
      MatVec3(Rot, x, el.q + 4 * a);
    }
    el.q[3] = el.q[7] = theta0;
    double d1[3];
    MatVec3(Rot, n, d1);
    HylcRodBendTwistRefSetFrames(el.q, d1, d1, NAN, &el.ref);
    el.ref.lbar = 2 * R * sin(M_PI / N);
    double E[2];
    HylcRodBendTwist(el.q, &el.ref, &par, 1.0, HYLC_ROD_BENDTWIST, E, NULL, NULL);
    Eb += E[0];
    Et += E[1];
  }
  *Etwist = Et;
  return Eb;
}

static void TestCircle(void)
{
  unsigned long long st = 5;
  double             Rot[9], Et, prev = 0;
  const double       B = 1.7, Rad = 0.37, exact = 0.5 * B / (Rad * Rad) * 2 * M_PI * Rad; /* 1/2 B kappa^2 L */
  RandRotation(&st, Rot);
  for (int N = 8; N <= 512; N *= 2) {
    const double E = CircleBendEnergy(N, Rad, Rot, 0.0, HYLC_ROD_CURVATURE_AVERAGED, &Et), x = M_PI / N;
    /* discrete value: N B/(2 h) (2 tan(pi/N))^2, h = 2 R sin(pi/N) */
    HYLC_CHECK_REL(E, N * B / (4 * Rad * sin(x)) * 4 * tan(x) * tan(x), 1e-10);
    HYLC_CHECK(fabs(Et) < 1e-20, "circle: twist energy %g", Et);
    const double err = E / exact - 1;
    /* err = tan^2(x)/(x sin x) - 1 = 5/6 x^2 + 183/360 x^4 + O(x^6), x = pi/N */
    HYLC_CHECK(fabs(err / (x * x) - 5.0 / 6.0) < 0.6 * x * x + 1e-6, "circle N = %d: relative error %.6g, expected ~ %.6g", N, err, 5.0 / 6.0 * x * x);
    if (prev > 0) { /* observed order; the O(N^-4) term (183/360 (pi/N)^4) still shows at N = 16 */
      const double order = log2(prev / err);
      HYLC_CHECK(fabs(order - 2) < (N <= 16 ? 0.15 : 0.03), "circle N = %d: convergence order %.4f", N, order);
    }
    prev = err;
    /* a uniform material rotation and the per-edge variant give the same energy */
    double Et2;
    HYLC_CHECK_REL(CircleBendEnergy(N, Rad, Rot, 1.234, HYLC_ROD_CURVATURE_AVERAGED, &Et2), E, 1e-10);
    HYLC_CHECK_REL(CircleBendEnergy(N, Rad, Rot, -0.4, HYLC_ROD_CURVATURE_PER_EDGE, &Et2), E, 1e-10);
  }
}

/* A straight rod twisted uniformly, theta_j = j tau l: twisting energy 1/2 beta tau^2 L, no bending. */
static void TestTwistedRod(void)
{
  unsigned long long st = 8;
  const int          N  = 12;                                          /* vertices; N - 2 interior vertices */
  const double       l = 0.25, beta = 0.8, taus[3] = {0.5, 4.0, 12.4}; /* tau l up to 3.1 per vertex */
  double             dir[3], d1[3];
  RandUnit(&st, dir);
  RandPerp(&st, dir, d1);
  for (int k = 0; k < 3; k++) {
    const HylcRodBendTwistParams par = {.B = 1.0, .beta = beta, .variant = HYLC_ROD_CURVATURE_AVERAGED};
    double                       Eb = 0, Et = 0;
    for (int i = 1; i < N - 1; i++) {
      RodElem el;
      memset(&el, 0, sizeof el);
      for (int a = 0; a < 3; a++)
        for (int c = 0; c < 3; c++) el.q[4 * a + c] = 1.0 + (i - 1 + a) * l * dir[c];
      el.q[3] = (i - 1) * taus[k] * l;
      el.q[7] = i * taus[k] * l;
      HylcRodBendTwistRefSetFrames(el.q, d1, d1, NAN, &el.ref);
      el.ref.lbar = l;
      double E[2];
      HylcRodBendTwist(el.q, &el.ref, &par, 1.0, HYLC_ROD_BENDTWIST, E, NULL, NULL);
      Eb += E[0];
      Et += E[1];
    }
    HYLC_CHECK_REL(Et, 0.5 * beta * taus[k] * taus[k] * (N - 2) * l, 1e-12);
    HYLC_CHECK(Eb < 1e-25, "twisted rod: bending energy %g", Eb);
  }
  HYLC_CHECK_REL(HylcRodTwistStiffness(3.0, 0.5), 3.0 * M_PI * 0.0625 / 2, 1e-15);
  HYLC_CHECK_REL(HylcRodBendStiffness(3.0, 0.5), 3.0 * M_PI * 0.0625 / 4, 1e-15);
}

/* E, g, H are linear in the weight */
static void TestWeight(void)
{
  unsigned long long st = 77;
  RodElemSpec        s  = {.le = 1, .lf = 0.7, .angle = 1.1, .thetae = 0.2, .thetaf = 1.3, .perturb = 0.1, .mstored = NAN, .restscale = 1};
  RodElem            el;
  RodElemBuild(&st, &s, &el);
  const HylcRodBendTwistParams par = {.B = 1, .beta = 2, .variant = HYLC_ROD_CURVATURE_AVERAGED};
  double                       E1[2], Ew[2], g1[11], gw[11], H1[121], Hw[121];
  HylcRodBendTwist(el.q, &el.ref, &par, 1.0, 3, E1, g1, H1);
  HylcRodBendTwist(el.q, &el.ref, &par, 0.25, 3, Ew, gw, Hw);
  for (int k = 0; k < 2; k++) HYLC_CHECK_REL(Ew[k], 0.25 * E1[k], 1e-15);
  for (int k = 0; k < 11; k++) HYLC_CHECK_CLOSE(gw[k], 0.25 * g1[k], 1e-15);
  for (int k = 0; k < 121; k++) HYLC_CHECK_CLOSE(Hw[k], 0.25 * H1[k], 1e-14);
  const double x[6] = {0, 0, 0, 1.1, 0.2, 0};
  double       Es1, Esw, gs1[6], gsw[6], Hs1[36], Hsw[36];
  HylcRodStretch(x, 1.0, 3.0, 1.0, &Es1, gs1, Hs1);
  HylcRodStretch(x, 1.0, 3.0, 0.5, &Esw, gsw, Hsw);
  HYLC_CHECK_REL(Esw, 0.5 * Es1, 1e-15);
  for (int k = 0; k < 6; k++) HYLC_CHECK_CLOSE(gsw[k], 0.5 * gs1[k], 1e-15);
  for (int k = 0; k < 36; k++) HYLC_CHECK_CLOSE(Hsw[k], 0.5 * Hs1[k], 1e-15);
}

int main(void)
{
  TestInvariance();
  TestClosedFormGradients();
  TestCircle();
  TestTwistedRod();
  TestWeight();
  return HYLC_TEST_RESULT();
}
