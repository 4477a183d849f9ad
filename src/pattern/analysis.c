/* Pattern analysis: yarn length, area density, contact exclusion and segment distances. */
#include <hylc/private/patternimpl.h>
#include <hylc/geom.h>

/* bounds of the periodic-image search of HylcPatternMinSegmentDistance() */
#define HYLC_PATTERN_MAX_RINGS  500
#define HYLC_PATTERN_MAX_IMAGES 1000000

/*@C
  HylcPatternGetYarnLength - Total yarn length in the tile: current (sum of edge lengths) and rest
  (sum of rest lengths), in m. Not collective. Either output may be NULL.
@*/
PetscErrorCode HylcPatternGetYarnLength(HylcPattern p, PetscReal *length, PetscReal *restLength)
{
  PetscReal L = 0, R = 0;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  for (PetscInt v = 0; v < p->nv; v++) {
    const PetscInt w = p->next[v];
    PetscReal      e[3];
    e[0] = p->X[3 * w] + p->shift[2 * v] * p->px - p->X[3 * v];
    e[1] = p->X[3 * w + 1] + p->shift[2 * v + 1] * p->py - p->X[3 * v + 1];
    e[2] = p->X[3 * w + 2] - p->X[3 * v + 2];
    L += HylcNorm3(e);
    R += p->restLength[v];
  }
  if (length) *length = L;
  if (restLength) *restLength = R;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetAreaDensity - Mass per tile area, rho * pi r^2 * (sum of rest lengths) / (px py), in
  kg/m^2, for a volumetric yarn density rho in kg/m^3 (rho <= 0: HylcDefaultYarnDensity(r)). Not collective.
@*/
PetscErrorCode HylcPatternGetAreaDensity(HylcPattern p, PetscReal rho, PetscReal *rhoA)
{
  PetscReal R;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetYarnLength(p, NULL, &R));
  if (rho <= 0) rho = HylcDefaultYarnDensity(p->radius);
  *rhoA = rho * PETSC_PI * p->radius * p->radius * R / (p->px * p->py);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rest arc length strictly between segment a (edge leaving vertex a) and the copy of segment b shifted
   by s (lattice units), when both lie on the same infinite yarn; returns -1 otherwise. */
static PetscReal ArcBetween(HylcPattern p, PetscInt a, PetscInt b, const PetscInt s[2])
{
  const PetscInt l = p->vertLoop[a];
  if (p->vertLoop[b] != l) return -1;
  const PetscInt  wx = p->winding[2 * l], wy = p->winding[2 * l + 1], n = p->loopStart[l + 1] - p->loopStart[l];
  const PetscReal L = p->loopLen[l], *arc = p->loopArc + p->loopStart[l] + l;
  PetscInt        k;
  /* in the unrolled yarn through segment a, position q lies at X[v_q] + (cum_q - cum_a) p and the
     copy of b shifted by s is at X[b] + s p: it is position pos(b) + k n iff s - cum_b + cum_a = k w */
  const PetscInt dx = s[0] - p->vertCum[2 * b] + p->vertCum[2 * a], dy = s[1] - p->vertCum[2 * b + 1] + p->vertCum[2 * a + 1];
  if (wx == 0 && wy == 0) {
    if (dx || dy) return -1;
    k = 0;
  } else {
    k = wx ? dx / wx : dy / wy;
    if (k * wx != dx || k * wy != dy) return -1;
  }
  /* unrolled positions: segment a spans [pa, pa+1], segment b' spans [pb, pb+1] with pb = pos(b) + k n */
  const PetscInt  pa = p->vertPos[a], pb = p->vertPos[b] + k * n;
  const PetscReal sa = arc[pa], ea = arc[pa + 1], sb = arc[p->vertPos[b]] + k * L, eb = arc[p->vertPos[b] + 1] + k * L;
  if (pb > pa) return sb - ea;
  if (pb < pa) return sa - eb;
  return -1; /* the same segment */
}

/*@C
  HylcPatternIsExcludedPair - Whether the pair (segment a, copy of segment b shifted by s lattice
  periods) is excluded from contact: the same segment, or the same infinite yarn with a rest arc length
  between the segments below arcFactor * r (this includes adjacent segments, arc 0).
  Segments are named by the vertex they leave. Not collective.
@*/
PetscErrorCode HylcPatternIsExcludedPair(HylcPattern p, PetscReal arcFactor, PetscInt a, PetscInt b, const PetscInt s[2], PetscBool *excluded)
{
  PetscFunctionBegin;
  if (a == b && !s[0] && !s[1]) {
    *excluded = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const PetscReal arc = ArcBetween(p, a, b, s);
  *excluded           = (PetscBool)(arc >= 0 ? arc < arcFactor * p->radius || arc < 1e-12 * p->radius : PETSC_FALSE);
  /* segments sharing a vertex through a different infinite yarn cannot happen (one edge per vertex) */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternMinSegmentDistance - Minimum centreline distance between segment pairs that are not
  excluded (see HylcPatternIsExcludedPair(), with arcFactor), over all periodic images. Returns the
  distance in m and the pair (a, b, sx, sy) that attains it (pair may be NULL). If no pair is within
  20 r, returns PETSC_INFINITY. Not collective.
@*/
PetscErrorCode HylcPatternMinSegmentDistance(HylcPattern p, PetscReal arcFactor, PetscReal *dmin, PetscInt pair[4])
{
  const PetscInt  nv  = p->nv;
  const PetscReal cut = 20 * p->radius;
  PetscReal      *seg, lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL}, best = PETSC_INFINITY;
  PetscInt        bestpair[4] = {-1, -1, 0, 0};

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(PetscLogEventBegin(HYLC_PatternDistance, p, 0, 0, 0));
  PetscCall(PetscMalloc1(6 * nv, &seg));
  for (PetscInt v = 0; v < nv; v++) {
    const PetscInt w = p->next[v];
    for (int d = 0; d < 3; d++) seg[6 * v + d] = p->X[3 * v + d];
    seg[6 * v + 3] = p->X[3 * w] + p->shift[2 * v] * p->px;
    seg[6 * v + 4] = p->X[3 * w + 1] + p->shift[2 * v + 1] * p->py;
    seg[6 * v + 5] = p->X[3 * w + 2];
    for (int d = 0; d < 2; d++) {
      lo[d] = PetscMin(lo[d], PetscMin(seg[6 * v + d], seg[6 * v + 3 + d]));
      hi[d] = PetscMax(hi[d], PetscMax(seg[6 * v + d], seg[6 * v + 3 + d]));
    }
  }
  /* periodic image rings needed to see every pair within the cut, in floating point (a tiny period
     would overflow an integer) and capped: a tile whose periods are that small against its extent and
     the contact range is not a physical tile */
  const PetscReal rx = PetscCeilReal((hi[0] - lo[0] + cut) / p->px), ry = PetscCeilReal((hi[1] - lo[1] + cut) / p->py);
  if (!(rx <= HYLC_PATTERN_MAX_RINGS && ry <= HYLC_PATTERN_MAX_RINGS && (2 * rx + 1) * (2 * ry + 1) <= HYLC_PATTERN_MAX_IMAGES)) {
    PetscCall(PetscFree(seg));
    SETERRQ(PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT,
            "%s%speriods px = %g, py = %g are too small for a tile whose vertices span %g x %g m with contact range 20 r = %g m: %.3g x %.3g periodic images to search (at most %d x %d, %d in all); not a physical tile",
            p->filename[0] ? p->filename : "", p->filename[0] ? ": " : "pattern: ", (double)p->px, (double)p->py, (double)(hi[0] - lo[0]), (double)(hi[1] - lo[1]), (double)cut, (double)(2 * rx + 1), (double)(2 * ry + 1),
            2 * HYLC_PATTERN_MAX_RINGS + 1, 2 * HYLC_PATTERN_MAX_RINGS + 1, HYLC_PATTERN_MAX_IMAGES);
  }
  const PetscInt mx = (PetscInt)rx, my = (PetscInt)ry;
  for (PetscInt sx = -mx; sx <= mx; sx++) {
    for (PetscInt sy = -my; sy <= my; sy++) {
      const PetscInt  s[2] = {sx, sy};
      const PetscReal ox = sx * p->px, oy = sy * p->py;
      /* each unordered pair once: (a, b, s) ~ (b, a, -s) */
      if (sx < 0 || (sx == 0 && sy < 0)) continue;
      for (PetscInt a = 0; a < nv; a++) {
        const PetscReal *A = seg + 6 * a;
        for (PetscInt b = (sx == 0 && sy == 0) ? a + 1 : 0; b < nv; b++) {
          const PetscReal *B     = seg + 6 * b;
          PetscReal        q0[3] = {B[0] + ox, B[1] + oy, B[2]}, q1[3] = {B[3] + ox, B[4] + oy, B[5]};
          /* box rejection at the current best distance */
          const PetscReal lim = PetscMin(best, cut);
          if (PetscMin(q0[0], q1[0]) - PetscMax(A[0], A[3]) > lim || PetscMin(A[0], A[3]) - PetscMax(q0[0], q1[0]) > lim) continue;
          if (PetscMin(q0[1], q1[1]) - PetscMax(A[1], A[4]) > lim || PetscMin(A[1], A[4]) - PetscMax(q0[1], q1[1]) > lim) continue;
          if (PetscMin(q0[2], q1[2]) - PetscMax(A[2], A[5]) > lim || PetscMin(A[2], A[5]) - PetscMax(q0[2], q1[2]) > lim) continue;
          PetscBool excl;
          PetscCall(HylcPatternIsExcludedPair(p, arcFactor, a, b, s, &excl));
          if (excl) continue;
          const PetscReal d = HylcSegmentSegmentDistance(A, A + 3, q0, q1, NULL, NULL);
          if (d < best) {
            best        = d;
            bestpair[0] = a;
            bestpair[1] = b;
            bestpair[2] = sx;
            bestpair[3] = sy;
          }
        }
      }
    }
  }
  PetscCall(PetscFree(seg));
  *dmin = best <= cut ? best : PETSC_INFINITY;
  if (pair)
    for (int k = 0; k < 4; k++) pair[k] = bestpair[k];
  PetscCall(PetscLogEventEnd(HYLC_PatternDistance, p, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
