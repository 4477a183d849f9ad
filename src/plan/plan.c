/* The sampling plan of Algorithm C4 (include/hylc/plan.h). */
#include <hylc/plan.h>
#include <math.h>
#include <string.h>

/* the terms are the shared vocabulary's (include/hylc/strain.h) after the zero sample: 1..5 its coordinates,
   6..14 its pairs, 15..21 its triples */
const char *HylcPlanTermName(int t)
{
  if (t == 0) return "zero";
  if (t >= 1 && t <= HYLC_NCOORD) return HylcCoordNames[t - 1];
  if (t > HYLC_NCOORD && t < HYLC_PLAN_NTERM) return HylcPairNames[t - 1 - HYLC_NCOORD];
  if (t >= HYLC_PLAN_NTERM && t < HYLC_PLAN_NTERM3) return HylcTripleNames[t - HYLC_PLAN_NTERM];
  return "unknown";
}

int HylcPlanTermDim(int t)
{
  if (t == 0) return 0;
  if (t >= 1 && t <= HYLC_NCOORD) return 1;
  if (t > HYLC_NCOORD && t < HYLC_PLAN_NTERM) return 2;
  if (t >= HYLC_PLAN_NTERM && t < HYLC_PLAN_NTERM3) return 3;
  return -1;
}

void HylcPlanPair(int t, int *ci, int *cj)
{
  *ci = HylcPairCoords[t - 1 - HYLC_NCOORD][0];
  *cj = HylcPairCoords[t - 1 - HYLC_NCOORD][1];
}

void HylcPlanTriple(int t, int c[3])
{
  for (int a = 0; a < 3; a++) c[a] = HylcTripleCoords[t - HYLC_PLAN_NTERM][a];
}

int HylcPlanAxisCoord(int t, int a)
{
  const int d = HylcPlanTermDim(t);
  if (d < 1 || a < 0 || a >= d) return -1;
  if (d == 1) return t - 1;
  if (d == 2) return HylcPairCoords[t - 1 - HYLC_NCOORD][a];
  return HylcTripleCoords[t - HYLC_PLAN_NTERM][a];
}

int HylcPlanStrainIndex(int c) { return HylcCoordStrain[c]; }

int HylcSampleRange(int c, double zmin, double zmax, int N, double Z[])
{
  if (N < 1 || !(zmin <= zmax) || c < 0 || c >= HYLC_PLAN_NCOORD) return -1;
  if (c == 0 || c == 2) {
    if (!(zmin > -1)) return -1;
    const double a = pow(zmin + 1, 0.1), b = pow(zmax + 1, 0.1);
    for (int k = 0; k < N; k++) {
      const double t = N > 1 ? a + (b - a) * k / (N - 1) : a;
      Z[k]           = pow(t, 10) - 1;
    }
    Z[0] = zmin; /* exact end points */
    if (N > 1) Z[N - 1] = zmax;
  } else {
    if (zmin > 0 || zmax < 0) return -1; /* the sgn(t) t^2 spacing spans 0 */
    const double a = -sqrt(fabs(zmin)), b = sqrt(fabs(zmax));
    for (int k = 0; k < N; k++) {
      const double t = N > 1 ? a + (b - a) * k / (N - 1) : a;
      Z[k]           = (t > 0 ? 1 : t < 0 ? -1 : 0) * t * t;
    }
    Z[0] = zmin; /* exact end points */
    if (N > 1) Z[N - 1] = zmax;
  }
  return 0;
}

int HylcPlanGradedKnots(double mn, double mx, double h0, double g, double hmax, int cap, double K[])
{
  double L[HYLC_PLAN_MAXAXIS], R[HYLC_PLAN_MAXAXIS];
  int    nl = 0, nr = 0, n = 0;
  if (!(mn <= 0 && mx >= 0 && mn < mx && h0 > 0 && g >= 1 && hmax >= h0) || cap < 1) return -1;
  for (int side = 0; side < 2; side++) {
    const double end = side ? mx : -mn;
    double      *T = side ? R : L, t = 0, h = h0;
    int          m = 0;
    while (end > 0 && t < end) {
      if (m == HYLC_PLAN_MAXAXIS) return -1;
      if (t + h >= end || end - (t + h) < 0.5 * fmin(h * g, hmax))
        t = end; /* the last interval: to the end point */
      else
        t += h;
      T[m++] = t;
      h      = h * g < hmax ? h * g : hmax;
    }
    if (side)
      nr = m;
    else
      nl = m;
  }
  if (nl + nr + 1 > cap) return -1;
  for (int i = nl - 1; i >= 0; i--) K[n++] = -L[i];
  K[n++] = 0;
  for (int i = 0; i < nr; i++) K[n++] = R[i];
  return n;
}

/* the range of axis a of term t */
static int AxisRange(const HylcPlan *p, int t, int a, int *c, double *mn, double *mx)
{
  const int d = HylcPlanTermDim(t);
  if (d < 1 || a < 0 || a >= d) return -1;
  *c = HylcPlanAxisCoord(t, a);
  if (d == 1) {
    *mn = p->min1[*c];
    *mx = p->max1[*c];
  } else if (d == 2) {
    *mn = p->min2[t - 6][a];
    *mx = p->max2[t - 6][a];
  } else {
    *mn = p->min3[t - HYLC_PLAN_NTERM][a];
    *mx = p->max3[t - HYLC_PLAN_NTERM][a];
  }
  return 0;
}

int HylcPlanAxisKnots(const HylcPlan *p, int t, int a, double K[HYLC_PLAN_MAXAXIS])
{
  int    c;
  double mn, mx;
  if (p->spacing != HYLC_PLAN_SPACING_GRADED || AxisRange(p, t, a, &c, &mn, &mx)) return -1;
  if (HylcPlanTermDim(t) == 3) { /* coarser: 2 h0 at 0, an in-plane axis growing by at least HYLC_PLAN_GROWTH3 */
    const double g = c >= 3 || p->growth > HYLC_PLAN_GROWTH3 ? p->growth : HYLC_PLAN_GROWTH3;
    return HylcPlanGradedKnots(mn, mx, 2 * p->h0[c], g, p->hmax * (mx - mn) > 2 * p->h0[c] ? p->hmax * (mx - mn) : 2 * p->h0[c], HYLC_PLAN_MAXAXIS, K);
  }
  return HylcPlanGradedKnots(mn, mx, p->h0[c], p->growth, p->hmax * (mx - mn), HYLC_PLAN_MAXAXIS, K);
}

int HylcPlanAxis(const HylcPlan *p, int t, int a, double Z[HYLC_PLAN_MAXAXIS])
{
  int    c, n;
  double mn, mx;
  if (AxisRange(p, t, a, &c, &mn, &mx)) return -1;
  if (p->spacing == HYLC_PLAN_SPACING_PAPER) {
    if (t >= HYLC_PLAN_NTERM) return -1;
    n = t <= 5 ? p->n1 : p->n2;
    if (n > HYLC_PLAN_MAXAXIS || HylcSampleRange(c, mn, mx, n, Z)) return -1;
    return n;
  }
  if (p->spacing != HYLC_PLAN_SPACING_GRADED || p->sub < 1) return -1;
  {
    double    K[HYLC_PLAN_MAXAXIS];
    const int nk  = HylcPlanAxisKnots(p, t, a, K);
    const int sub = t >= HYLC_PLAN_NTERM ? 1 : p->sub;
    if (nk < 1 || (long)(nk - 1) * sub + 1 > HYLC_PLAN_MAXAXIS) return -1;
    n = 0;
    for (int i = 0; i + 1 < nk; i++)
      for (int q = 0; q < sub; q++) Z[n++] = q ? K[i] + (K[i + 1] - K[i]) * q / sub : K[i];
    Z[n++] = K[nk - 1];
    return n;
  }
}

long HylcPlanTermSize(const HylcPlan *p, int t)
{
  double    Z[HYLC_PLAN_MAXAXIS];
  long      n = 1;
  const int d = HylcPlanTermDim(t);
  if (d < 0 || !(p->terms & (1 << t))) return 0;
  for (int a = 0; a < d; a++) {
    const long m = HylcPlanAxis(p, t, a, Z);
    if (m < 0) return 0;
    n *= m;
  }
  return n;
}

long HylcPlanSize(const HylcPlan *p)
{
  long n = 0;
  for (int t = 0; t < HYLC_PLAN_NTERM3; t++) n += HylcPlanTermSize(p, t);
  return n;
}

int HylcPlanSample(const HylcPlan *p, long k, double z[6], int *term)
{
  double Z[HYLC_PLAN_MAXAXIS];
  for (int i = 0; i < 6; i++) z[i] = 0;
  if (k < 0) return -1;
  for (int t = 0; t < HYLC_PLAN_NTERM3; t++) {
    const long n = HylcPlanTermSize(p, t);
    const int  d = HylcPlanTermDim(t);
    if (k >= n) {
      k -= n;
      continue;
    }
    *term = t;
    /* the last axis innermost */
    for (int a = d - 1; a >= 0; a--) {
      const int m = HylcPlanAxis(p, t, a, Z);
      if (m < 1) return -1;
      z[HylcPlanStrainIndex(HylcPlanAxisCoord(t, a))] = Z[k % m];
      k /= m;
    }
    return 0;
  }
  return -1;
}

int HylcPlanDefaults(const char *family, double scale, HylcPlan *p)
{
  /* 1D limits of docs/method.md §8: sx = sy range, sa, II00, II11 (1/m at r = 1 mm) */
  double s0, s1, sa, b0, b1;
  if (!strcmp(family, "woven"))
    s0 = -0.60, s1 = 1.00, sa = 0.75, b0 = 170, b1 = 170;
  else if (!strcmp(family, "stockinette"))
    s0 = -0.50, s1 = 0.80, sa = 0.75, b0 = 200, b1 = 230;
  else if (!strcmp(family, "honeycomb"))
    s0 = -0.50, s1 = 0.80, sa = 0.75, b0 = 120, b1 = 120;
  else if (!strcmp(family, "rib"))
    s0 = -0.65, s1 = 1.00, sa = 0.60, b0 = 100, b1 = 80;
  else
    return -1;
  memset(p, 0, sizeof(*p));
  p->n1 = 150;
  p->n2 = 50;
  HylcPlanGradedDefaults(scale, p);
  p->terms           = HYLC_PLAN_ALL_TERMS;
  const double lo[5] = {s0, -sa, s0, -b0 * scale, -b1 * scale}, hi[5] = {s1, sa, s1, b0 * scale, b1 * scale};
  for (int c = 0; c < 5; c++) {
    p->min1[c] = lo[c];
    p->max1[c] = hi[c];
  }
  for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
    int ci, cj, c[2];
    HylcPlanPair(t, &ci, &cj);
    c[0] = ci;
    c[1] = cj;
    for (int a = 0; a < 2; a++) {
      const int other = c[1 - a], x = c[a];
      double    mn, mx;
      if (x == 0 || x == 2) {
        if (other == 0 || other == 2)
          mn = 0.74 * lo[x], mx = hi[x]; /* the Poisson pair (sx, sy) */
        else
          mn = -0.1, mx = 0.84 * hi[x];
      } else if (x == 1)
        mn = 0.8 * lo[x], mx = 0.8 * hi[x];
      else {
        const double f = ((x == 3 && other == 0) || (x == 4 && other == 2)) ? 0.72 : 0.8; /* same axis */
        mn = f * lo[x], mx = f * hi[x];
      }
      p->min2[t - 6][a] = mn;
      p->max2[t - 6][a] = mx;
    }
  }
  for (int r = 0; r < HYLC_NTRIPLE; r++) { /* where cloth lives: tension with free contraction, bias, drape */
    const int bending = HylcTripleCoords[r][2] >= 3;
    for (int a = 0; a < 3; a++) {
      const int x = HylcTripleCoords[r][a];
      double    mn, mx;
      if (x == 0 || x == 2)
        mn = (bending ? 0.2 : 0.45) * lo[x], mx = (bending ? 0.15 : 0.3) * hi[x];
      else if (x == 1)
        mn = (bending ? 0.25 : 0.55) * lo[x], mx = (bending ? 0.25 : 0.55) * hi[x];
      else
        mn = 0.35 * lo[x], mx = 0.35 * hi[x];
      p->min3[r][a] = mn;
      p->max3[r][a] = mx;
    }
  }
  return 0;
}

/* the first non-negative sample of an ascending axis (n if none): where it is split at the zero strain */
static int FirstNonNegative(const double Z[], int n)
{
  int i0 = 0;
  while (i0 < n && Z[i0] < 0) i0++;
  return i0;
}

/* appends the half-lines of one line (samples base + stride * i, i = 0..n-1, ascending values Z) split at zero */
static void HalfLines(const double Z[], int n, long base, long stride, long *nu, long *pos, long start[], long order[])
{
  const int i0 = FirstNonNegative(Z, n);
  if (i0 < n) {
    if (start) start[*nu] = *pos;
    (*nu)++;
    for (int i = i0; i < n; i++, (*pos)++)
      if (order) order[*pos] = base + stride * i;
  }
  if (i0 > 0) {
    if (start) start[*nu] = *pos;
    (*nu)++;
    for (int i = i0 - 1; i >= 0; i--, (*pos)++)
      if (order) order[*pos] = base + stride * i;
  }
}

long HylcPlanUnits(const HylcPlan *p, long start[], long order[])
{
  double Z[HYLC_PLAN_MAXAXIS];
  long   nu = 0, pos = 0, off = 0;
  for (int t = 0; t < HYLC_PLAN_NTERM3; t++) {
    const long n = HylcPlanTermSize(p, t);
    const int  d = HylcPlanTermDim(t);
    if (!n) continue;
    if (d == 0) {
      if (start) start[nu] = pos;
      if (order) order[pos] = off;
      nu++, pos++;
    } else {
      const int m = HylcPlanAxis(p, t, d - 1, Z); /* lines along the innermost coordinate */
      if (m < 1) return -1;
      for (long a = 0; a < n / m; a++) HalfLines(Z, m, off + a * m, 1, &nu, &pos, start, order);
    }
    off += n;
  }
  if (start) start[nu] = pos;
  return nu;
}

void HylcPlanGradedDefaults(double scale, HylcPlan *p)
{
  for (int c = 0; c < HYLC_PLAN_NCOORD; c++) p->h0[c] = c < 3 ? 0.01 : 2.5 * scale;
  p->growth = 1.5;
  p->hmax   = 0.15;
  p->sub    = 2;
}
