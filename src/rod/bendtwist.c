/* Bending and twisting element of Discrete Elastic Rods at an interior vertex (11 local dofs).

   Derivatives are exact: every quantity is carried as a hyper-dual number (value, gradient, Hessian).
   The work is split by dependence:
   1. per edge (3 variables, the edge vector): the tangent t and the transported reference frame
      (d1, d2), as Hd3 numbers;
   2. the vertex (6 variables, both edge vectors): seven dot products between the two edges' frame
      vectors, from which kb . d1^e, kb . d2^e, kb . d1^f, kb . d2^f and the reference twist follow in
      closed form (Hd6 numbers);
   3. the twist angles enter through rotations only and are added analytically (8-variable jets over
      e, f, theta^e, theta^f), and the chain rule e = x_i - x_{i-1}, f = x_{i+1} - x_i gives the 11 dofs.

   Identities used (frames orthonormal, P = parallel transport t^e -> t^f, c = t^e . t^f, chi = 1 + c):
     kb . d1^e = -2 (t^f . d2^e)/chi     kb . d2^e = 2 (t^f . d1^e)/chi
     kb . d1^f =  2 (t^e . d2^f)/chi     kb . d2^f = -2 (t^e . d1^f)/chi
     P d1^e . d1^f =   c (d1^e . d1^f) - (t^f . d1^e)(t^e . d1^f) - (t^f . d2^e)(t^e . d2^f)/chi
     P d1^e . d2^f =   c (d1^e . d2^f) - (t^f . d1^e)(t^e . d2^f) + (t^f . d2^e)(t^e . d1^f)/chi
     m = atan2(-P d1^e . d2^f, P d1^e . d1^f)
   and for a vector v perpendicular to unit a, P_a^b v = v - (b . v)/(1 + a . b) (a + b). */
#include <hylc/rod.h>
#include <hylc/geom.h>
#include <hylc/private/hyperdual.h>
#include <string.h>

#define TWO_PI 6.28318530717958647692

/* degeneracy thresholds on 1 + cos(angle) */
#define CHI_MIN 1e-12

double HylcAngleNear(double phi, double near)
{
  if (!isfinite(near)) return phi;
  return phi + TWO_PI * nearbyint((near - phi) / TWO_PI);
}

/* Orthonormal stored frame (ts, d1s, d2s) from a stored tangent and director. Returns 0 or -1. */
static int StoredFrame(const double t_in[3], const double d1_in[3], double ts[3], double d1s[3], double d2s[3])
{
  for (int i = 0; i < 3; i++) {
    ts[i]  = t_in[i];
    d1s[i] = d1_in[i];
  }
  if (!(HylcNormalize3(ts) > 0)) return -1;
  if (!(HylcOrthonormalizeDirector(ts, d1s) > 0)) return -1;
  HylcCross3(ts, d1s, d2s);
  return 0;
}

/* Plain-double frame of an edge: t = e/|e|, (d1, d2) transported from the stored frame. */
static int EdgeFrame(const double e[3], const double ts[3], const double d1s[3], const double d2s[3], double t[3], double d1[3], double d2[3])
{
  for (int i = 0; i < 3; i++) t[i] = e[i];
  if (!(HylcNormalize3(t) > 0)) return -1;
  const double chi = 1.0 + HylcDot3(ts, t);
  if (!(chi > CHI_MIN)) return -1;
  const double f1 = HylcDot3(t, d1s) / chi, f2 = HylcDot3(t, d2s) / chi;
  for (int i = 0; i < 3; i++) {
    d1[i] = d1s[i] - f1 * (ts[i] + t[i]);
    d2[i] = d2s[i] - f2 * (ts[i] + t[i]);
  }
  return 0;
}

/* Hyper-dual frame of an edge over the 3 components of e. */
static int EdgeFrameHd(const double e[3], const double ts[3], const double d1s[3], const double d2s[3], Hd3 t[3], Hd3 d1[3], Hd3 d2[3])
{
  double       tv[3] = {e[0], e[1], e[2]};
  const double l     = HylcNormalize3(tv);
  if (!(l > 0)) return -1;
  const double il = 1.0 / l, il2 = il * il;
  /* t_i = e_i/l: dt_i/de_j = (delta_ij - t_i t_j)/l,
     d2t_i/de_j de_k = -(delta_ik t_j + delta_jk t_i + delta_ij t_k - 3 t_i t_j t_k)/l^2 */
  for (int i = 0; i < 3; i++) {
    t[i].v = tv[i];
    for (int j = 0; j < 3; j++) t[i].g[j] = ((i == j) - tv[i] * tv[j]) * il;
    for (int j = 0, k = 0; j < 3; j++)
      for (int m = j; m < 3; m++, k++) t[i].h[k] = -((i == m) * tv[j] + (j == m) * tv[i] + (i == j) * tv[m] - 3.0 * tv[i] * tv[j] * tv[m]) * il2;
  }
  Hd3 chi, p1, p2, ichi, f1, f2, sum;
  memset(&chi, 0, sizeof chi);
  memset(&p1, 0, sizeof p1);
  memset(&p2, 0, sizeof p2);
  chi.v = 1.0;
  for (int i = 0; i < 3; i++) {
    Hd3Axpy(&chi, ts[i], &t[i]);
    Hd3Axpy(&p1, d1s[i], &t[i]);
    Hd3Axpy(&p2, d2s[i], &t[i]);
  }
  if (!(chi.v > CHI_MIN)) return -1;
  Hd3Recip(&ichi, &chi);
  Hd3Mul(&f1, &p1, &ichi);
  Hd3Mul(&f2, &p2, &ichi);
  for (int i = 0; i < 3; i++) { /* d = ds - f (ts + t) */
    sum = t[i];
    sum.v += ts[i];
    Hd3Mul(&d1[i], &f1, &sum);
    Hd3Scale(&d1[i], -1.0);
    d1[i].v += d1s[i];
    Hd3Mul(&d2[i], &f2, &sum);
    Hd3Scale(&d2[i], -1.0);
    d2[i].v += d2s[i];
  }
  return 0;
}

int HylcRodBendTwistStrains(const double q[11], const HylcRodBendTwistRef *ref, double kappa[2], double kappa_edges[4], double *tau, double *mout)
{
  double tse[3], d1se[3], d2se[3], tsf[3], d1sf[3], d2sf[3];
  double e[3], f[3], te[3], d1e[3], d2e[3], tf[3], d1f[3], d2f[3], kb[3], m1e[3], m2e[3], m1f[3], m2f[3];

  if (StoredFrame(ref->te, ref->d1e, tse, d1se, d2se) || StoredFrame(ref->tf, ref->d1f, tsf, d1sf, d2sf)) return -1;
  HylcSub3(q + 4, q, e);
  HylcSub3(q + 8, q + 4, f);
  if (EdgeFrame(e, tse, d1se, d2se, te, d1e, d2e) || EdgeFrame(f, tsf, d1sf, d2sf, tf, d1f, d2f)) return -1;
  if (!(HylcCurvatureBinormal(te, tf, kb) > CHI_MIN)) return -1;
  HylcMaterialFrame(d1e, d2e, q[3], m1e, m2e);
  HylcMaterialFrame(d1f, d2f, q[7], m1f, m2f);
  if (kappa) HylcMaterialCurvature(kb, m1e, m2e, m1f, m2f, kappa);
  if (kappa_edges) {
    kappa_edges[0] = HylcDot3(kb, m2e);
    kappa_edges[1] = -HylcDot3(kb, m1e);
    kappa_edges[2] = HylcDot3(kb, m2f);
    kappa_edges[3] = -HylcDot3(kb, m1f);
  }
  if (tau || mout) {
    const double m = HylcAngleNear(HylcReferenceTwist(te, d1e, tf, d1f), ref->mref);
    if (mout) *mout = m;
    if (tau) *tau = m + q[7] - q[3];
  }
  return 0;
}

int HylcRodBendTwistEnergy(const double q[11], const HylcRodBendTwistRef *ref, const HylcRodBendTwistParams *par, double w, double E[2])
{
  double kappa[2], ke[4], tau;
  int    ierr;

  if (par->variant == HYLC_ROD_CURVATURE_PER_EDGE)
    ierr = HylcRodBendTwistStrains(q, ref, NULL, ke, &tau, NULL);
  else
    ierr = HylcRodBendTwistStrains(q, ref, kappa, NULL, &tau, NULL);
  if (ierr) {
    E[0] = E[1] = HUGE_VAL;
    return -1;
  }
  const double il = 1.0 / ref->lbar;
  if (par->variant == HYLC_ROD_CURVATURE_PER_EDGE) {
    double s = 0;
    for (int j = 0; j < 4; j++) s += (ke[j] - ref->kappa0[j]) * (ke[j] - ref->kappa0[j]);
    E[0] = 0.25 * w * par->B * il * s;
  } else {
    const double a = kappa[0] - ref->kappa0[0], b = kappa[1] - ref->kappa0[1];
    E[0] = 0.5 * w * par->B * il * (a * a + b * b);
  }
  const double dt = tau - ref->tau0;
  E[1]            = 0.5 * w * par->beta * il * dt * dt;
  return 0;
}

void HylcRodBendTwistRefSetFrames(const double q[11], const double d1e[3], const double d1f[3], double mref_near, HylcRodBendTwistRef *ref)
{
  HylcSub3(q + 4, q, ref->te);
  HylcSub3(q + 8, q + 4, ref->tf);
  HylcNormalize3(ref->te);
  HylcNormalize3(ref->tf);
  for (int i = 0; i < 3; i++) {
    ref->d1e[i] = d1e[i];
    ref->d1f[i] = d1f[i];
  }
  HylcOrthonormalizeDirector(ref->te, ref->d1e);
  HylcOrthonormalizeDirector(ref->tf, ref->d1f);
  ref->mref = HylcAngleNear(HylcReferenceTwist(ref->te, ref->d1e, ref->tf, ref->d1f), mref_near);
}

/* ---- 8-variable jets over (e[3], f[3], theta^e, theta^f) ---- */
typedef struct {
  double v, g[8], H[64];
} Jet8;

/* J += s * jet of u, where u depends on (e, f) through the Hd6 number u and on theta^j (index th = 6
   or 7) by rotation with partner sv * v: du/dtheta = sv v, d2u/dtheta2 = -u. */
static void JetAddRot(Jet8 *J, double s, const Hd6 *u, const Hd6 *v, double sv, int th)
{
  J->v += s * u->v;
  for (int i = 0; i < 6; i++) J->g[i] += s * u->g[i];
  J->g[th] += s * sv * v->v;
  for (int i = 0, k = 0; i < 6; i++) {
    for (int j = i; j < 6; j++, k++) {
      J->H[i * 8 + j] += s * u->h[k];
      if (j != i) J->H[j * 8 + i] += s * u->h[k];
    }
    J->H[i * 8 + th] += s * sv * v->g[i];
    J->H[th * 8 + i] += s * sv * v->g[i];
  }
  J->H[th * 8 + th] -= s * u->v;
}

/* E += 1/2 c r^2, g += c r grad, H += c (grad grad^T + r Hess), r = J.v - rest (g NULL: energy only) */
static void EnergyAddSquare(const Jet8 *J, double rest, double c, double *E, double g[8], double H[64], int want_h)
{
  const double r = J->v - rest;
  *E += 0.5 * c * r * r;
  if (!g) return;
  for (int i = 0; i < 8; i++) g[i] += c * r * J->g[i];
  if (want_h)
    for (int i = 0; i < 8; i++)
      for (int j = 0; j < 8; j++) H[i * 8 + j] += c * (J->g[i] * J->g[j] + r * J->H[i * 8 + j]);
}

/* g11 = J g8, H11 = J H8 J^T for e = x_i - x_{i-1}, f = x_{i+1} - x_i (11-dof layout of rod.h) */
static void MapTo11(const double g8[8], const double H8[64], double w, double g[11], double H[121])
{
  static const int    xoff[3]  = {0, 4, 8};  /* 11-index of x_{i-1}, x_i, x_{i+1} */
  static const double ce[3]    = {-1, 1, 0}; /* d e / d x_a */
  static const double cf[3]    = {0, -1, 1}; /* d f / d x_a */
  static const int    thoff[2] = {3, 7};     /* 11-index of theta^e, theta^f */

  if (g) {
    for (int a = 0; a < 3; a++)
      for (int i = 0; i < 3; i++) g[xoff[a] + i] = w * (ce[a] * g8[i] + cf[a] * g8[3 + i]);
    g[3] = w * g8[6];
    g[7] = w * g8[7];
  }
  if (H) {
    for (int a = 0; a < 3; a++) {
      for (int b = 0; b < 3; b++) {
        const double cee = ce[a] * ce[b], cef = ce[a] * cf[b], cfe = cf[a] * ce[b], cff = cf[a] * cf[b];
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) H[(xoff[a] + i) * 11 + xoff[b] + j] = w * (cee * H8[i * 8 + j] + cef * H8[i * 8 + 3 + j] + cfe * H8[(3 + i) * 8 + j] + cff * H8[(3 + i) * 8 + 3 + j]);
      }
      for (int t = 0; t < 2; t++)
        for (int i = 0; i < 3; i++) {
          const double h                   = w * (ce[a] * H8[i * 8 + 6 + t] + cf[a] * H8[(3 + i) * 8 + 6 + t]);
          H[(xoff[a] + i) * 11 + thoff[t]] = h;
          H[thoff[t] * 11 + xoff[a] + i]   = h;
        }
    }
    for (int s = 0; s < 2; s++)
      for (int t = 0; t < 2; t++) H[thoff[s] * 11 + thoff[t]] = w * H8[(6 + s) * 8 + 6 + t];
  }
}

int HylcRodBendTwist(const double q[11], const HylcRodBendTwistRef *ref, const HylcRodBendTwistParams *par, double w, int terms, double E[2], double g[11], double H[121])
{
  double tse[3], d1se[3], d2se[3], tsf[3], d1sf[3], d2sf[3], e[3], f[3];
  Hd3    te[3], d1e[3], d2e[3], tf[3], d1f[3], d2f[3];

  HylcSub3(q + 4, q, e);
  HylcSub3(q + 8, q + 4, f);
  if (StoredFrame(ref->te, ref->d1e, tse, d1se, d2se) || StoredFrame(ref->tf, ref->d1f, tsf, d1sf, d2sf) || EdgeFrameHd(e, tse, d1se, d2se, te, d1e, d2e) || EdgeFrameHd(f, tsf, d1sf, d2sf, tf, d1f, d2f)) goto degenerate;

  /* vertex quantities over (e, f) */
  Hd6 c, P1, P2, Q1, Q2, D11, D12, ichi, U, k1e, k2e, k1f, k2f, C, S, T1, T2, m;
  Hd6MixedDot3(&c, te, tf);
  if (!(1.0 + c.v > CHI_MIN)) goto degenerate;
  Hd6MixedDot3(&P1, d1e, tf);
  Hd6MixedDot3(&P2, d2e, tf);
  Hd6MixedDot3(&Q1, te, d1f);
  Hd6MixedDot3(&Q2, te, d2f);
  Hd6MixedDot3(&D11, d1e, d1f);
  Hd6MixedDot3(&D12, d1e, d2f);
  ichi   = c;
  ichi.v = 1.0 + c.v;
  Hd6Recip(&ichi, &ichi);

  /* per-edge halves of the averaged curvature, kappa1 = k1e + k1f, kappa2 = k2e + k2f:
     k1e = 1/2 kb . m2^e = (t^f . m1^e)/chi,  k2e = -1/2 kb . m1^e = (t^f . m2^e)/chi,
     k1f = 1/2 kb . m2^f = -(t^e . m1^f)/chi, k2f = -1/2 kb . m1^f = -(t^e . m2^f)/chi */
  const double cse = cos(q[3]), sne = sin(q[3]), csf = cos(q[7]), snf = sin(q[7]);
  Hd6Lin(&U, cse, &P1, sne, &P2);
  Hd6Mul(&k1e, &U, &ichi);
  Hd6Lin(&U, -sne, &P1, cse, &P2);
  Hd6Mul(&k2e, &U, &ichi);
  Hd6Lin(&U, -csf, &Q1, -snf, &Q2);
  Hd6Mul(&k1f, &U, &ichi);
  Hd6Lin(&U, snf, &Q1, -csf, &Q2);
  Hd6Mul(&k2f, &U, &ichi);

  /* reference twist m = atan2(S, C) */
  Hd6Mul(&C, &c, &D11);
  Hd6Mul(&T1, &P1, &Q1);
  Hd6Axpy(&C, -1.0, &T1);
  Hd6Mul(&T1, &P2, &Q2);
  Hd6Mul(&T2, &T1, &ichi);
  Hd6Axpy(&C, -1.0, &T2);
  Hd6Mul(&S, &c, &D12);
  Hd6Mul(&T1, &P1, &Q2);
  Hd6Axpy(&S, -1.0, &T1);
  Hd6Mul(&T1, &P2, &Q1);
  Hd6Mul(&T2, &T1, &ichi);
  Hd6Axpy(&S, 1.0, &T2);
  Hd6Scale(&S, -1.0);
  Hd6Atan2(&m, &S, &C);
  m.v = HylcAngleNear(m.v, ref->mref);

  const int    want_h = H != NULL;
  const double il     = 1.0 / ref->lbar;
  double       Eb = 0, Et = 0, g8[8] = {0}, H8[64] = {0};
  double      *gb = (terms & HYLC_ROD_BEND) ? g8 : NULL, *gt = (terms & HYLC_ROD_TWIST) ? g8 : NULL;
  Jet8         J;

  /* bending */
  if (par->variant == HYLC_ROD_CURVATURE_PER_EDGE) {
    const Hd6   *u[4] = {&k1e, &k2e, &k1f, &k2f}, *v[4] = {&k2e, &k1e, &k2f, &k1f};
    const double sv[4] = {1, -1, 1, -1};
    for (int k = 0; k < 4; k++) {
      memset(&J, 0, sizeof J);
      JetAddRot(&J, 2.0, u[k], v[k], sv[k], k < 2 ? 6 : 7);
      EnergyAddSquare(&J, ref->kappa0[k], 0.5 * par->B * il, &Eb, gb, H8, want_h);
    }
  } else {
    memset(&J, 0, sizeof J);
    JetAddRot(&J, 1.0, &k1e, &k2e, 1.0, 6);
    JetAddRot(&J, 1.0, &k1f, &k2f, 1.0, 7);
    EnergyAddSquare(&J, ref->kappa0[0], par->B * il, &Eb, gb, H8, want_h);
    memset(&J, 0, sizeof J);
    JetAddRot(&J, 1.0, &k2e, &k1e, -1.0, 6);
    JetAddRot(&J, 1.0, &k2f, &k1f, -1.0, 7);
    EnergyAddSquare(&J, ref->kappa0[1], par->B * il, &Eb, gb, H8, want_h);
  }
  /* twisting: tau = m + theta^f - theta^e */
  memset(&J, 0, sizeof J);
  J.v = m.v + q[7] - q[3];
  for (int i = 0; i < 6; i++) J.g[i] = m.g[i];
  J.g[6] = -1.0;
  J.g[7] = 1.0;
  for (int i = 0, k = 0; i < 6; i++)
    for (int j = i; j < 6; j++, k++) J.H[i * 8 + j] = J.H[j * 8 + i] = m.h[k];
  EnergyAddSquare(&J, ref->tau0, par->beta * il, &Et, gt, H8, want_h);

  if (E) {
    E[0] = w * Eb;
    E[1] = w * Et;
  }
  MapTo11(g8, H8, w, g, H);
  return 0;

degenerate:
  if (E) E[0] = E[1] = HUGE_VAL;
  if (g)
    for (int i = 0; i < 11; i++) g[i] = 0;
  if (H)
    for (int i = 0; i < 121; i++) H[i] = 0;
  return -1;
}
