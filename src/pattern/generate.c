/* Procedural patterns: yarn centrelines -> pattern with rest data, and the woven generators. */
#include <hylc/private/patternimpl.h>
#include <hylc/geom.h>

/*@C
  HylcPatternSetFromCurves - Builds a pattern from unwrapped yarn centrelines and sets its rest data
  from the geometry, so that the result is stress free.

  Input: periods px, py, radius r; nyarns yarns, yarn k with nverts[k] vertices whose unwrapped
  coordinates are consecutive in pts (3 per vertex, yarn order) and which closes onto its first vertex
  shifted by (winding[2k] px, winding[2k+1] py).

  Vertices are wrapped into the period box [-px/2, px/2) x [-py/2, py/2) and edges get the matching
  lattice offsets. Edge twists theta = 0; rest lengths = edge lengths; reference directors are parallel
  transported along each yarn with the loop's holonomy spread evenly over its vertices (so all
  reference twists of a yarn are equal); rest twist = reference twist; rest curvature = the averaged-
  frame material curvature of the geometry. Collective; the same input on every rank.
@*/
PetscErrorCode HylcPatternSetFromCurves(HylcPattern p, PetscReal px, PetscReal py, PetscReal r, PetscInt nyarns, const PetscInt nverts[], const PetscInt winding[], const PetscReal pts[])
{
  MPI_Comm   comm = PetscObjectComm((PetscObject)p);
  PetscInt   nv = 0, off = 0;
  PetscReal *X, *theta, *RL, *RK, *RT, *D1, *RefT, *T;
  PetscInt  *next, *shift, *cell;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(px > 0 && py > 0 && r > 0, comm, PETSC_ERR_USER_INPUT, "Periods and radius must be positive, got px = %g, py = %g, r = %g", (double)px, (double)py, (double)r);
  for (PetscInt k = 0; k < nyarns; k++) {
    PetscCheck(nverts[k] >= 3, comm, PETSC_ERR_USER_INPUT, "Yarn %" PetscInt_FMT " has %" PetscInt_FMT " vertices; a closed periodic yarn needs at least 3", k, nverts[k]);
    nv += nverts[k];
  }
  PetscCall(PetscMalloc7(3 * nv, &X, nv, &theta, nv, &RL, 2 * nv, &RK, nv, &RT, 3 * nv, &D1, nv, &RefT));
  PetscCall(PetscMalloc4(nv, &next, 2 * nv, &shift, 2 * nv, &cell, 3 * nv, &T));
  for (PetscInt k = 0; k < nyarns; k++) {
    const PetscInt   n = nverts[k];
    const PetscReal *U = pts + 3 * off;
    PetscReal        H;
    /* wrap into the box and compute lattice offsets of the edges */
    for (PetscInt j = 0; j < n; j++) {
      const PetscInt v = off + j;
      cell[2 * v]      = (PetscInt)PetscFloorReal((U[3 * j] + 0.5 * px) / px);
      cell[2 * v + 1]  = (PetscInt)PetscFloorReal((U[3 * j + 1] + 0.5 * py) / py);
      X[3 * v]         = U[3 * j] - cell[2 * v] * px;
      X[3 * v + 1]     = U[3 * j + 1] - cell[2 * v + 1] * py;
      X[3 * v + 2]     = U[3 * j + 2];
      theta[v]         = 0;
    }
    for (PetscInt j = 0; j < n; j++) {
      const PetscInt v = off + j, w = off + (j + 1) % n;
      const PetscInt wx = j + 1 < n ? 0 : winding[2 * k], wy = j + 1 < n ? 0 : winding[2 * k + 1];
      PetscReal      e[3];
      next[v]          = w;
      shift[2 * v]     = cell[2 * w] + wx - cell[2 * v];
      shift[2 * v + 1] = cell[2 * w + 1] + wy - cell[2 * v + 1];
      e[0]             = U[3 * ((j + 1) % n)] + wx * px - U[3 * j];
      e[1]             = U[3 * ((j + 1) % n) + 1] + wy * py - U[3 * j + 1];
      e[2]             = U[3 * ((j + 1) % n) + 2] - U[3 * j + 2];
      RL[v]            = HylcNormalize3(e);
      PetscCheck(RL[v] > 1e-9 * r, comm, PETSC_ERR_USER_INPUT, "Yarn %" PetscInt_FMT ": vertices %" PetscInt_FMT " and %" PetscInt_FMT " coincide", k, j, (j + 1) % n);
      for (int d = 0; d < 3; d++) T[3 * v + d] = e[d];
    }
    /* reference directors: transport along the yarn, then spread the holonomy evenly */
    {
      const PetscReal ez[3] = {0, 0, 1};
      PetscReal      *d1    = D1 + 3 * off;
      for (int d = 0; d < 3; d++) d1[d] = ez[d];
      if (HylcOrthonormalizeDirector(T + 3 * off, d1) < 0.1) HylcAnyPerpendicular(T + 3 * off, d1);
      for (PetscInt j = 1; j < n; j++) {
        HylcParallelTransport(T + 3 * (off + j - 1), T + 3 * (off + j), d1 + 3 * (j - 1), d1 + 3 * j);
        HylcOrthonormalizeDirector(T + 3 * (off + j), d1 + 3 * j);
      }
      H = HylcReferenceTwist(T + 3 * (off + n - 1), d1 + 3 * (n - 1), T + 3 * off, d1);
      for (PetscInt j = 1; j < n; j++) HylcRotateAxisAngle(d1 + 3 * j, T + 3 * (off + j), j * H / n, d1 + 3 * j);
    }
    /* reference twist, rest twist and rest curvature at each vertex (incoming edge j-1, outgoing j) */
    for (PetscInt j = 0; j < n; j++) {
      const PetscInt v = off + j, u = off + (j + n - 1) % n;
      PetscReal      kb[3], d2e[3], d2f[3];
      RefT[v] = HylcReferenceTwist(T + 3 * u, D1 + 3 * u, T + 3 * v, D1 + 3 * v);
      RT[v]   = RefT[v];
      PetscCheck(HylcCurvatureBinormal(T + 3 * u, T + 3 * v, kb) > 1e-6, comm, PETSC_ERR_USER_INPUT, "Yarn %" PetscInt_FMT " folds back on itself at vertex %" PetscInt_FMT, k, j);
      HylcCross3(T + 3 * u, D1 + 3 * u, d2e);
      HylcCross3(T + 3 * v, D1 + 3 * v, d2f);
      HylcMaterialCurvature(kb, D1 + 3 * u, d2e, D1 + 3 * v, d2f, RK + 2 * v);
    }
    off += n;
  }
  PetscCall(HylcPatternSetData(p, nv, px, py, r, X, theta, next, shift, RL, RK, RT, D1, RefT));
  PetscCall(PetscFree7(X, theta, RL, RK, RT, D1, RefT));
  PetscCall(PetscFree4(next, shift, cell, T));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------------------------------------- */
/* Wovens                                                                                          */

/* Whether the x-running yarn j passes over the y-running yarn i, per weave. */
typedef PetscBool (*WeaveOverFn)(PetscInt, PetscInt);
static PetscBool OverPlain(PetscInt i, PetscInt j) { return (PetscBool)((i + j) % 2 == 0); }          /* over one, under one */
static PetscBool OverBasket(PetscInt i, PetscInt j) { return (PetscBool)((i / 2 + j / 2) % 2 == 0); } /* 2x2: pairs of threads act as one */
static PetscBool OverTwill(PetscInt i, PetscInt j) { return (PetscBool)((i + j) % 4 < 2); }           /* 2/2: over two, under two, shifted by one per thread */
static PetscBool OverSatin(PetscInt i, PetscInt j) { return (PetscBool)(i % 5 != (2 * j) % 5); }      /* 5-harness: over four, under one, move number 2 */

/* Peirce-type crimp profile of a yarn along its own axis coordinate u in [0, n s): at crossing k
   (u_k = (k + 1/2) s) it is at state[k] * h, wrapped around the crossing yarn on an arc of radius R
   centred on that yarn; consecutive crossings of equal state are joined by a straight float at the
   same height, those of opposite state by the common internal tangent of the two arcs. */
static PetscReal WeaveHeight(const PetscInt state[], PetscInt n, PetscReal s, PetscReal h, PetscReal R, PetscReal u)
{
  PetscReal       x  = u / s - 0.5;
  PetscInt        k  = (PetscInt)PetscFloorReal(x);
  const PetscReal t  = (x - k) * s;
  const PetscInt  k0 = ((k % n) + n) % n, k1 = (k0 + 1) % n;
  const PetscReal s0 = state[k0], s1 = state[k1];
  if (s0 == s1) return s0 * h;
  const PetscReal D = PetscSqrtReal(0.25 * s * s + h * h), alpha = PetscAtan2Real(h, 0.5 * s);
  const PetscReal phi = PetscAsinReal(R / D) - alpha, a = R * PetscSinReal(phi);
  PetscReal       z;
  if (t <= a)
    z = -h + PetscSqrtReal(R * R - t * t);
  else if (t >= s - a)
    z = h - PetscSqrtReal(R * R - (s - t) * (s - t));
  else
    z = -PetscTanReal(phi) * (t - 0.5 * s);
  return s0 * z;
}

/* a woven tile of the weave whose over/under rule is over and whose pattern repeats every rep threads */
static PetscErrorCode GenerateWoven(HylcPattern p, const HylcPatternGenParams *g, PetscInt rep, WeaveOverFn over)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)p);
  const char     *type = ((PetscObject)p)->type_name;
  const PetscReal r    = g->radius;
  const PetscReal s    = g->spacing > 0 ? g->spacing : 4 * r;
  const PetscReal gap  = g->gap > 0 ? g->gap : 0.1;
  const PetscReal sl   = g->seglen > 0 ? g->seglen : r;
  const PetscReal R = 2 * r * (1 + gap), h = 0.5 * R;

  PetscFunctionBegin;
  const PetscInt nx = g->size[0] > 0 ? g->size[0] : rep, ny = g->size[1] > 0 ? g->size[1] : rep;
  PetscCheck(r > 0, comm, PETSC_ERR_USER_INPUT, "-pattern_radius must be positive, got %g", (double)r);
  PetscCheck(nx % rep == 0 && ny % rep == 0, comm, PETSC_ERR_USER_INPUT, "-pattern_size %" PetscInt_FMT ",%" PetscInt_FMT ": a %s weave repeats every %" PetscInt_FMT " threads; use multiples of %" PetscInt_FMT, nx, ny, type, rep, rep);
  PetscCheck(s >= 2 * r * (1 + gap), comm, PETSC_ERR_USER_INPUT, "-pattern_spacing %g m is below the yarn diameter plus gap, %g m: neighbouring parallel yarns would overlap", (double)s, (double)(2 * r * (1 + gap)));
  PetscCheck(0.25 * s * s + h * h >= R * R, comm, PETSC_ERR_USER_INPUT, "-pattern_spacing %g m (%.3g r) is too small for crimped crossings with gap %g: need at least %.4g r", (double)s, (double)(s / r), (double)gap,
             (double)(PetscSqrtReal(3.0) * R / r));
  PetscCheck(s / sl <= 1e4 && 2.0 * nx * ny * PetscCeilReal(s / sl) <= 1e8, comm, PETSC_ERR_USER_INPUT,
             "The %s weave of size %" PetscInt_FMT ",%" PetscInt_FMT " with -pattern_seglen %g m would have %.3g vertices (at most 1e8, and at most 1e4 per spacing)", type, nx, ny, (double)sl, 2.0 * nx * ny * PetscCeilReal(s / sl));
  const PetscInt  m  = PetscMax(2, (PetscInt)PetscCeilReal(s / sl - 1e-9)); /* segments per spacing */
  const PetscReal px = nx * s, py = ny * s;
  PetscInt       *nverts, *winding, *state;
  PetscReal      *pts;
  PetscCall(PetscMalloc3(nx + ny, &nverts, 2 * (nx + ny), &winding, PetscMax(nx, ny), &state));
  PetscCall(PetscMalloc1(3 * m * (ny * nx + nx * ny), &pts));
  PetscInt k = 0, q = 0;
  for (PetscInt j = 0; j < ny; j++, k++) { /* yarns along x, at y_j */
    for (PetscInt i = 0; i < nx; i++) state[i] = over(i, j) ? 1 : -1;
    nverts[k]          = nx * m;
    winding[2 * k]     = 1;
    winding[2 * k + 1] = 0;
    for (PetscInt v = 0; v < nx * m; v++, q++) {
      const PetscReal u = 0.5 * s + v * s / m;
      pts[3 * q]        = u - 0.5 * px;
      pts[3 * q + 1]    = (j + 0.5) * s - 0.5 * py;
      pts[3 * q + 2]    = WeaveHeight(state, nx, s, h, R, u);
    }
  }
  for (PetscInt i = 0; i < nx; i++, k++) { /* yarns along y, at x_i */
    for (PetscInt j = 0; j < ny; j++) state[j] = over(i, j) ? -1 : 1;
    nverts[k]          = ny * m;
    winding[2 * k]     = 0;
    winding[2 * k + 1] = 1;
    for (PetscInt v = 0; v < ny * m; v++, q++) {
      const PetscReal u = 0.5 * s + v * s / m;
      pts[3 * q]        = (i + 0.5) * s - 0.5 * px;
      pts[3 * q + 1]    = u - 0.5 * py;
      pts[3 * q + 2]    = WeaveHeight(state, ny, s, h, R, u);
    }
  }
  PetscCall(HylcPatternSetFromCurves(p, px, py, r, nx + ny, nverts, winding, pts));
  PetscCall(PetscFree3(nverts, winding, state));
  PetscCall(PetscFree(pts));
  {
    PetscReal dmin;
    PetscCall(HylcPatternMinSegmentDistance(p, p->viewExcludeArc, &dmin, NULL));
    PetscCheck(dmin >= 2 * r, comm, PETSC_ERR_USER_INPUT, "The generated %s weave interpenetrates: minimum distance %.4g r < 2 r; increase -pattern_gap (%g) or -pattern_spacing (%.3g r), or decrease -pattern_seglen", type, (double)(dmin / r),
               (double)gap, (double)(s / r));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternGeneratePlain_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(GenerateWoven(p, g, 2, OverPlain));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternGenerateBasket_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(GenerateWoven(p, g, 4, OverBasket));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternGenerateTwill_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(GenerateWoven(p, g, 4, OverTwill));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternGenerateSatin_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(GenerateWoven(p, g, 5, OverSatin));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGenerate - Generates a pattern procedurally: plain, basket (2x2), twill (2/2), satin
  (5-harness), stockinette, rib (1x1). Parameters as in HylcPatternGenParams (docs/patterns.md).
  Wovens come out free of interpenetration (checked); knits may overlap until the reference-state
  relaxation. Collective.
@*/
PetscErrorCode HylcPatternGenerate(HylcPattern p, HylcPatternType type, const HylcPatternGenParams *g)
{
  PetscBool            file;
  char                 t[64];
  HylcPatternGenerator generator;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(PetscStrncpy(t, type, sizeof(t))); /* type may alias the object's type name */
  PetscCall(HylcPatternSetType(p, t));
  PetscCall(PetscStrcmp(t, HYLCPATTERNFILE, &file));
  PetscCheck(!file, PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "Pattern type 'file' is not a generator; use HylcPatternLoad()");
  {
    MPI_Comm        comm  = PetscObjectComm((PetscObject)p);
    const PetscReal len[] = {g->spacing, g->gap, g->wale, g->course, g->depth, g->seglen};
    const char     *nam[] = {"spacing", "gap", "wale", "course", "depth", "seglen"};
    PetscCheck(PetscIsNormalReal(g->radius) && g->radius > 0, comm, PETSC_ERR_USER_INPUT, "Generator %s: yarn radius (-pattern_radius) must be positive and finite, got %g", t, (double)g->radius);
    for (int k = 0; k < 6; k++) PetscCheck(len[k] == 0 || (PetscIsNormalReal(len[k]) && len[k] > 0), comm, PETSC_ERR_USER_INPUT, "Generator %s: -pattern_%s must be positive and finite, or 0 for the default; got %g", t, nam[k], (double)len[k]);
    PetscCheck(g->size[0] >= 0 && g->size[1] >= 0 && g->size[0] <= HYLC_PATTERN_MAX_SIZE && g->size[1] <= HYLC_PATTERN_MAX_SIZE, comm, PETSC_ERR_USER_INPUT,
               "Generator %s: tile size (-pattern_size) %" PetscInt_FMT ",%" PetscInt_FMT " out of range: integers from 1 to %d (0: the smallest repeat)", t, g->size[0], g->size[1], HYLC_PATTERN_MAX_SIZE);
  }
  PetscCall(HylcPatternFindSource_Private(t, &generator));
  PetscCall(PetscLogEventBegin(HYLC_PatternGenerate, p, 0, 0, 0));
  p->gen = *g;
  PetscCall((*generator)(p, g));
  p->filename[0] = 0;
  p->state       = HYLC_PATTERN_STATE_GENERATED;
  PetscCall(PetscLogEventEnd(HYLC_PatternGenerate, p, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetRestFromGeometry - Sets the rest data to the current geometry, so that the rods are
  stress free: rest lengths = edge lengths, rest curvatures = the averaged-frame material curvatures
  (with the twists theta), rest twists = the current twists; the reference twists are recomputed from
  the directors on the branch nearest their stored values. Collective.
@*/
PetscErrorCode HylcPatternSetRestFromGeometry(HylcPattern p)
{
  PetscReal *t;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(p->hasdata, PetscObjectComm((PetscObject)p), PETSC_ERR_ARG_WRONGSTATE, "Pattern has no data");
  PetscCall(PetscMalloc1(3 * p->nv, &t));
  for (PetscInt v = 0; v < p->nv; v++) {
    const PetscInt w = p->next[v];
    t[3 * v]         = p->X[3 * w] + p->shift[2 * v] * p->px - p->X[3 * v];
    t[3 * v + 1]     = p->X[3 * w + 1] + p->shift[2 * v + 1] * p->py - p->X[3 * v + 1];
    t[3 * v + 2]     = p->X[3 * w + 2] - p->X[3 * v + 2];
    p->restLength[v] = HylcNormalize3(t + 3 * v);
    PetscCheck(p->restLength[v] > 0, PetscObjectComm((PetscObject)p), PETSC_ERR_ARG_WRONG, "Edge leaving vertex %" PetscInt_FMT " has zero length", v);
    HylcOrthonormalizeDirector(t + 3 * v, p->refD1 + 3 * v);
  }
  for (PetscInt v = 0; v < p->nv; v++) {
    const PetscInt  u = p->prev[v];
    PetscReal       kb[3], d2e[3], d2f[3], m1e[3], m2e[3], m1f[3], m2f[3];
    const PetscReal m = HylcReferenceTwist(t + 3 * u, p->refD1 + 3 * u, t + 3 * v, p->refD1 + 3 * v);
    p->refTwist[v]    = m + 2 * PETSC_PI * round((p->refTwist[v] - m) / (2 * PETSC_PI)); /* the branch nearest the stored value */
    p->restTwist[v]   = p->refTwist[v] + p->theta[v] - p->theta[u];
    HylcCurvatureBinormal(t + 3 * u, t + 3 * v, kb);
    HylcCross3(t + 3 * u, p->refD1 + 3 * u, d2e);
    HylcCross3(t + 3 * v, p->refD1 + 3 * v, d2f);
    HylcMaterialFrame(p->refD1 + 3 * u, d2e, p->theta[u], m1e, m2e);
    HylcMaterialFrame(p->refD1 + 3 * v, d2f, p->theta[v], m1f, m2f);
    HylcMaterialCurvature(kb, m1e, m2e, m1f, m2f, p->restKappa + 2 * v);
  }
  PetscCall(PetscFree(t));
  PetscCall(HylcPatternBuildLoops_Private(p)); /* loop rest lengths */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternScaleRest - Multiplies the rest lengths by fl and the rest curvatures by fk (the tension of
  Algorithm C1). Collective.
@*/
PetscErrorCode HylcPatternScaleRest(HylcPattern p, PetscReal fl, PetscReal fk)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  for (PetscInt v = 0; v < p->nv; v++) {
    p->restLength[v] *= fl;
    p->restKappa[2 * v] *= fk;
    p->restKappa[2 * v + 1] *= fk;
  }
  PetscCall(HylcPatternBuildLoops_Private(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternRecentre - Moves the vertices so that their mean position is 0. Collective.
@*/
PetscErrorCode HylcPatternRecentre(HylcPattern p)
{
  PetscReal mean[3] = {0, 0, 0};

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  for (PetscInt v = 0; v < p->nv; v++)
    for (int d = 0; d < 3; d++) mean[d] += p->X[3 * v + d] / p->nv;
  for (PetscInt v = 0; v < p->nv; v++)
    for (int d = 0; d < 3; d++) p->X[3 * v + d] -= mean[d];
  PetscFunctionReturn(PETSC_SUCCESS);
}
