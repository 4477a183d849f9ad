#pragma once
/* Shared helpers of the rod unit tests: random elements, rotations, finite differences. */
#include <hylc/geom.h>
#include <hylc/rod.h>
#include <string.h>
#include "hylctest.h"

static void RandUnit(unsigned long long *st, double v[3])
{
  do {
    for (int i = 0; i < 3; i++) v[i] = 2 * HylcTestRand(st) - 1;
  } while (HylcDot3(v, v) > 1 || HylcDot3(v, v) < 1e-4);
  HylcNormalize3(v);
}

static double RandRange(unsigned long long *st, double a, double b) { return a + (b - a) * HylcTestRand(st); }

/* unit vector perpendicular to unit t, random */
static void RandPerp(unsigned long long *st, const double t[3], double d[3])
{
  RandUnit(st, d);
  while (!(HylcOrthonormalizeDirector(t, d) > 0.1)) RandUnit(st, d);
}

/* random rotation matrix (row-major) */
static void RandRotation(unsigned long long *st, double R[9])
{
  double a[3], b[3], c[3];
  RandUnit(st, a);
  RandPerp(st, a, b);
  HylcCross3(a, b, c);
  for (int i = 0; i < 3; i++) {
    R[0 + i] = a[i];
    R[3 + i] = b[i];
    R[6 + i] = c[i];
  }
}

static void MatVec3(const double R[9], const double v[3], double out[3])
{
  double o[3];
  for (int i = 0; i < 3; i++) o[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
  memcpy(out, o, sizeof o);
}

typedef struct {
  double              q[11];
  HylcRodBendTwistRef ref;
} RodElem;

typedef struct {
  double le, lf; /* edge lengths */
  double angle;  /* turning angle between the tangents */
  double thetae, thetaf;
  double perturb;   /* rotation angle of the stored tangents away from the current ones */
  double mstored;   /* reference twist of the stored frames (NaN: random directors) */
  int    nwrap;     /* mref = principal value + 2 pi nwrap */
  double restscale; /* size of the random rest curvature and twist */
} RodElemSpec;

static void RodElemBuild(unsigned long long *st, const RodElemSpec *s, RodElem *el)
{
  double xi[3], te[3], tf[3], ax[3], tse[3], tsf[3], d1e[3], d1f[3];
  for (int i = 0; i < 3; i++) xi[i] = RandRange(st, -1, 1);
  RandUnit(st, te);
  RandPerp(st, te, ax);
  HylcRotateAxisAngle(te, ax, s->angle, tf);
  for (int i = 0; i < 3; i++) {
    el->q[i]     = xi[i] - s->le * te[i];
    el->q[4 + i] = xi[i];
    el->q[8 + i] = xi[i] + s->lf * tf[i];
  }
  el->q[3] = s->thetae;
  el->q[7] = s->thetaf;
  RandPerp(st, te, ax);
  HylcRotateAxisAngle(te, ax, s->perturb * RandRange(st, 0.5, 1), tse);
  RandPerp(st, tf, ax);
  HylcRotateAxisAngle(tf, ax, s->perturb * RandRange(st, 0.5, 1), tsf);
  RandPerp(st, tse, d1e);
  if (isnan(s->mstored))
    RandPerp(st, tsf, d1f);
  else {
    HylcParallelTransport(tse, tsf, d1e, d1f);
    HylcRotateAxisAngle(d1f, tsf, s->mstored, d1f);
  }
  memcpy(el->ref.te, tse, sizeof tse);
  memcpy(el->ref.tf, tsf, sizeof tsf);
  memcpy(el->ref.d1e, d1e, sizeof d1e);
  memcpy(el->ref.d1f, d1f, sizeof d1f);
  el->ref.mref = HylcReferenceTwist(tse, d1e, tsf, d1f) + 2 * M_PI * s->nwrap;
  for (int k = 0; k < 4; k++) el->ref.kappa0[k] = s->restscale * RandRange(st, -1, 1);
  el->ref.tau0 = s->restscale * RandRange(st, -1, 1) + 2 * M_PI * s->nwrap;
  el->ref.lbar = 0.5 * (s->le + s->lf) * RandRange(st, 0.8, 1.2);
}

static double MaxAbs(const double *a, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(a[i]));
  return m;
}

static double MaxAbsDiff(const double *a, const double *b, int n)
{
  double m = 0;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(a[i] - b[i]));
  return m;
}
