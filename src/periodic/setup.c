/* HylcPeriodic: ghost extension, elimination maps, projected reference frames, the state and its getters (include/hylc/periodic.h). */
#include "periodicimpl.h"

/* the full vertex (o, s), created as a ghost if new */
static PetscErrorCode FullVertex(HylcPeriodic P, PetscInt o, PetscInt s1, PetscInt s2, PetscInt *k)
{
  PetscFunctionBegin;
  PetscCheck(PetscAbsInt(s1) <= SMAX && PetscAbsInt(s2) <= SMAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "Ghost shift (%d, %d) beyond %d periods", (int)s1, (int)s2, SMAX);
  const PetscInt key = Key(P->N, o, s1, s2);
  PetscCall(PetscHMapIGet(P->vmap, key, k));
  if (*k >= 0) PetscFunctionReturn(PETSC_SUCCESS);
  if (P->nfv == P->capfv) {
    PetscInt *fo, *fs;
    P->capfv = P->capfv ? 2 * P->capfv : 2 * P->N + 16;
    PetscCall(PetscMalloc2(P->capfv, &fo, 2 * P->capfv, &fs));
    PetscCall(PetscArraycpy(fo, P->fo, P->nfv));
    PetscCall(PetscArraycpy(fs, P->fs, 2 * P->nfv));
    PetscCall(PetscFree2(P->fo, P->fs));
    P->fo = fo;
    P->fs = fs;
  }
  *k                = P->nfv++;
  P->fo[*k]         = o;
  P->fs[2 * *k]     = s1;
  P->fs[2 * *k + 1] = s2;
  PetscCall(PetscHMapISet(P->vmap, key, *k));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the full edge leaving o in copy s (created with its vertices if new); stretch weight added separately */
static PetscErrorCode FullEdge(HylcPeriodic P, PetscInt o, PetscInt s1, PetscInt s2, PetscInt *e)
{
  PetscFunctionBegin;
  const PetscInt key = Key(P->N, o, s1, s2);
  PetscCall(PetscHMapIGet(P->emap, key, e));
  if (*e >= 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt k0, k1;
  PetscCall(FullVertex(P, o, s1, s2, &k0));
  PetscCall(FullVertex(P, P->D.next[o], s1 + P->D.shift[2 * o], s2 + P->D.shift[2 * o + 1], &k1));
  if (P->nfe == P->capfe) {
    PetscInt      *es, *eh;
    PetscReal     *sw;
    unsigned char *eg;
    P->capfe = P->capfe ? 2 * P->capfe : 2 * P->N + 16;
    PetscCall(PetscMalloc4(P->capfe, &es, P->capfe, &eh, P->capfe, &sw, P->capfe, &eg));
    PetscCall(PetscArraycpy(es, P->esrc, P->nfe));
    PetscCall(PetscArraycpy(eh, P->ehead, P->nfe));
    PetscCall(PetscArraycpy(sw, P->sw, P->nfe));
    PetscCall(PetscArraycpy(eg, P->eghost, P->nfe));
    PetscCall(PetscFree4(P->esrc, P->ehead, P->sw, P->eghost));
    P->esrc   = es;
    P->ehead  = eh;
    P->sw     = sw;
    P->eghost = eg;
  }
  *e            = P->nfe++;
  P->esrc[*e]   = k0;
  P->ehead[*e]  = k1;
  P->sw[*e]     = 0;
  P->eghost[*e] = (unsigned char)(k0 >= P->N && k1 >= P->N);
  PetscCall(PetscHMapISet(P->emap, key, *e));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* bend/twist element centred on o in copy s (deduplicated by its centre) */
static PetscErrorCode AddBend(HylcPeriodic P, PetscHMapI bmap, PetscInt o, PetscInt s1, PetscInt s2)
{
  PetscInt b;

  PetscFunctionBegin;
  const PetscInt key = Key(P->N, o, s1, s2);
  PetscCall(PetscHMapIGet(bmap, key, &b));
  if (b >= 0) PetscFunctionReturn(PETSC_SUCCESS);
  const PetscInt u = P->D.prev[o];
  PetscInt       e, f;
  PetscCall(FullEdge(P, u, s1 - P->D.shift[2 * u], s2 - P->D.shift[2 * u + 1], &e));
  PetscCall(FullEdge(P, o, s1, s2, &f));
  if (P->nbe == P->capbe) {
    BendElem *nb;
    P->capbe = P->capbe ? 2 * P->capbe : 2 * P->N + 16;
    PetscCall(PetscMalloc1(P->capbe, &nb));
    PetscCall(PetscArraycpy(nb, P->be, P->nbe));
    PetscCall(PetscFree(P->be));
    P->be = nb;
  }
  BendElem *E = P->be + P->nbe;
  E->e        = e;
  E->f        = f;
  E->v[0]     = P->esrc[e];
  E->v[1]     = P->esrc[f];
  E->v[2]     = P->ehead[f];
  E->w        = ((E->v[0] < P->N) + (E->v[1] < P->N) + (E->v[2] < P->N)) / 3.0;
  PetscCall(PetscHMapISet(bmap, key, P->nbe++));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetUp - Builds the midsurface, the extended pattern, the elimination maps, the projected
  reference frames, the initial state (x = phi + h n, u~ = 0) and the constraints for the strain set;
  nothing when already set up. -periodic_view prints the tile.

  Not collective

  Input Parameter:
. P - the periodic tile

  Level: beginner
@*/
PetscErrorCode HylcPeriodicSetUp(HylcPeriodic P)
{
  const PetscInt N = P->N;
  PetscReal      lo[2], hi[2], *x0;
  PetscHMapI     bmap;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  if (P->setup) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(P->pat, PetscObjectComm((PetscObject)P), PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetPattern() first");
  PetscCall(HylcPeriodicReset_Private(P));
  PetscCall(PetscLogEventBegin(HYLC_PeriodicSetUp, 0, 0, 0, 0));
  /* reference coordinates, recentred so that the mean of (xi1, xi2, h) is 0 (C1 step 16) */
  PetscCall(PetscMalloc1(3 * N, &P->xi));
  {
    PetscReal mean[3] = {0, 0, 0};
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) mean[i] += P->D.X[3 * o + i] / N;
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) P->xi[3 * o + i] = P->D.X[3 * o + i] - mean[i];
  }
  /* extended pattern: originals first, then every element touching an original */
  PetscCall(PetscHMapICreate(&P->vmap));
  PetscCall(PetscHMapICreate(&P->emap));
  PetscCall(PetscHMapICreate(&bmap));
  for (PetscInt o = 0; o < N; o++) {
    PetscInt k;
    PetscCall(FullVertex(P, o, 0, 0, &k));
  }
  for (PetscInt o = 0; o < N; o++) {
    const PetscInt u = P->D.prev[o], w = P->D.next[o];
    PetscInt       e;
    PetscCall(FullEdge(P, o, 0, 0, &e));
    PetscCall(FullEdge(P, u, -P->D.shift[2 * u], -P->D.shift[2 * u + 1], &e));
    PetscCall(AddBend(P, bmap, o, 0, 0));
    PetscCall(AddBend(P, bmap, u, -P->D.shift[2 * u], -P->D.shift[2 * u + 1]));
    PetscCall(AddBend(P, bmap, w, P->D.shift[2 * o], P->D.shift[2 * o + 1]));
  }
  PetscCall(PetscHMapIDestroy(&bmap));
  /* stretch weights of the chain edges; the contact ghosts come after them and carry no frame */
  P->nchain = P->nfe;
  for (PetscInt e = 0; e < P->nfe; e++) P->sw[e] = ((P->esrc[e] < N) + (P->ehead[e] < N)) / 2.0;

  /* midsurface over the reference box of the extended pattern (contact ghosts stay within one period) */
  lo[0] = lo[1] = PETSC_MAX_REAL;
  hi[0] = hi[1] = PETSC_MIN_REAL;
  for (PetscInt o = 0; o < N; o++)
    for (int i = 0; i < 2; i++) {
      lo[i] = PetscMin(lo[i], P->xi[3 * o + i]);
      hi[i] = PetscMax(hi[i], P->xi[3 * o + i]);
    }
  lo[0] -= 1.5 * P->D.px;
  hi[0] += 1.5 * P->D.px;
  lo[1] -= 1.5 * P->D.py;
  hi[1] += 1.5 * P->D.py;
  P->msbox[0] = lo[0], P->msbox[1] = lo[1], P->msbox[2] = hi[0], P->msbox[3] = hi[1];
  PetscCall(HylcMidsurfaceSetStrain(P->ms, P->z));
  PetscCall(HylcMidsurfaceSetBox(P->ms, lo, hi));
  PetscCall(HylcMidsurfaceSetUp(P->ms));

  /* contact ghosts: every copy of a tile edge in the neighbouring tiles, or with a positive margin factor
     those within the margin on the deformed initial guess (HylcPeriodicSetContactMargin()). Usually the 8
     neighbours; more rings when the stored vertices spread over more than a period (a file may store any
     periodic copy of a vertex) */
  {
    const PetscReal margin = P->marginFactor > 0 ? PetscMax(3 * P->c.r, P->marginFactor * PetscMin(P->D.px, P->D.py)) : PETSC_MAX_REAL;
    PetscReal       blo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, bhi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL};
    PetscReal      *xih, *xo, xmin[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, xmax[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL};
    PetscInt        k1, k2;
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 2; i++) {
        xmin[i] = PetscMin(xmin[i], P->xi[3 * o + i]);
        xmax[i] = PetscMax(xmax[i], P->xi[3 * o + i]);
      }
    k1                     = 1 + (PetscInt)PetscMax(0, PetscCeilReal((xmax[0] - xmin[0]) / P->D.px - 1.05));
    k2                     = 1 + (PetscInt)PetscMax(0, PetscCeilReal((xmax[1] - xmin[1]) / P->D.py - 1.05));
    const PetscInt ncopies = (2 * k1 + 1) * (2 * k2 + 1);
    PetscCall(PetscMalloc2(3 * N * ncopies * 2, &xih, 3 * N * ncopies * 2, &xo));
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) xih[3 * o + i] = P->xi[3 * o + i];
    PetscCall(HylcMidsurfaceEvaluate(P->ms, N, xih, xo, NULL));
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) {
        blo[i] = PetscMin(blo[i], xo[3 * o + i]);
        bhi[i] = PetscMax(bhi[i], xo[3 * o + i]);
      }
    PetscInt q = 0;
    for (PetscInt s1 = -k1; s1 <= k1; s1++)
      for (PetscInt s2 = -k2; s2 <= k2; s2++) {
        if (!s1 && !s2) continue;
        for (PetscInt o = 0; o < N; o++, q++) {
          const PetscInt w = P->D.next[o];
          xih[6 * q + 0]   = P->xi[3 * o] + s1 * P->D.px;
          xih[6 * q + 1]   = P->xi[3 * o + 1] + s2 * P->D.py;
          xih[6 * q + 2]   = P->xi[3 * o + 2];
          xih[6 * q + 3]   = P->xi[3 * w] + (s1 + P->D.shift[2 * o]) * P->D.px;
          xih[6 * q + 4]   = P->xi[3 * w + 1] + (s2 + P->D.shift[2 * o + 1]) * P->D.py;
          xih[6 * q + 5]   = P->xi[3 * w + 2];
        }
      }
    PetscCall(HylcMidsurfaceEvaluate(P->ms, 2 * q, xih, xo, NULL));
    q = 0;
    for (PetscInt s1 = -k1; s1 <= k1; s1++)
      for (PetscInt s2 = -k2; s2 <= k2; s2++) {
        if (!s1 && !s2) continue;
        for (PetscInt o = 0; o < N; o++, q++) {
          PetscBool near = PETSC_TRUE;
          for (int i = 0; i < 3 && margin < PETSC_MAX_REAL; i++) {
            const PetscReal a = PetscMin(xo[6 * q + i], xo[6 * q + 3 + i]), b = PetscMax(xo[6 * q + i], xo[6 * q + 3 + i]);
            if (a > bhi[i] + margin || b < blo[i] - margin) near = PETSC_FALSE;
          }
          if (near) {
            PetscInt e;
            PetscCall(FullEdge(P, o, s1, s2, &e));
          }
        }
      }
    PetscCall(PetscFree2(xih, xo));
  }

  /* elimination maps and the initial state */
  PetscCall(PetscMalloc3(9 * P->nfv, &P->T, 3 * P->nfv, &P->d, P->nfv, &P->rigidId));
  PetscCall(PetscMalloc3(4 * N, &P->y, 4 * N, &P->y0, 3 * P->nfv, &P->x));
  PetscCall(PetscMalloc1(3 * P->nfv, &x0));
  {
    PetscReal *xih;
    PetscCall(PetscMalloc1(3 * P->nfv, &xih));
    for (PetscInt k = 0; k < P->nfv; k++) RefPos(P, k, xih + 3 * k);
    PetscCall(HylcMidsurfaceEvaluate(P->ms, P->nfv, xih, x0, NULL));
    for (PetscInt k = 0; k < P->nfv; k++) {
      const PetscInt o = P->fo[k];
      PetscReal     *T = P->T + 9 * k, Ro[9], Rk[9], Tx[3];
      if (k < N) {
        for (int i = 0; i < 9; i++) T[i] = (i % 4 == 0);
        for (int i = 0; i < 3; i++) P->d[3 * k + i] = 0;
        P->rigidId[k] = PETSC_TRUE;
        continue;
      }
      PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, Ro));
      PetscCall(HylcMidsurfaceGetRotation(P->ms, xih + 3 * k, Rk));
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) T[3 * i + j] = Rk[3 * i] * Ro[3 * j] + Rk[3 * i + 1] * Ro[3 * j + 1] + Rk[3 * i + 2] * Ro[3 * j + 2];
      P->rigidId[k] = PETSC_TRUE;
      for (int i = 0; i < 9; i++)
        if (T[i] != (PetscReal)(i % 4 == 0)) P->rigidId[k] = PETSC_FALSE;
      Mat3(T, x0 + 3 * o, Tx);
      for (int i = 0; i < 3; i++) P->d[3 * k + i] = x0[3 * k + i] - Tx[i];
    }
    /* projected reference frames (24) of the chain edges: d1 <- normalize((I - t t^T) R(xi_v) d1_pattern) */
    PetscCall(PetscMalloc4(3 * P->nchain, &P->et, 3 * P->nchain, &P->ed1, 3 * P->nchain, &P->et0, 3 * P->nchain, &P->ed10));
    for (PetscInt e = 0; e < P->nchain; e++) {
      const PetscInt k0 = P->esrc[e], k1 = P->ehead[e];
      PetscReal      R[9];
      HylcSub3(x0 + 3 * k1, x0 + 3 * k0, P->et + 3 * e);
      PetscCheck(HylcNormalize3(P->et + 3 * e) > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Zero-length edge in the deformed initial guess");
      PetscCall(HylcMidsurfaceGetRotation(P->ms, xih + 3 * k0, R));
      Mat3(R, P->D.refD1 + 3 * P->fo[k0], P->ed1 + 3 * e);
      PetscCheck(HylcOrthonormalizeDirector(P->et + 3 * e, P->ed1 + 3 * e) > 1e-3, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Projected reference director of edge %" PetscInt_FMT " is parallel to its edge", P->fo[k0]);
    }
    PetscCall(PetscFree(xih));
  }
  PetscCall(PetscMalloc2(P->nbe, &P->mref, P->nbe, &P->mref0));
  for (PetscInt b = 0; b < P->nbe; b++) {
    const BendElem *E = P->be + b;
    P->mref[b]        = HylcAngleNear(HylcReferenceTwist(P->et + 3 * E->e, P->ed1 + 3 * E->e, P->et + 3 * E->f, P->ed1 + 3 * E->f), P->D.refTwist[P->fo[E->v[1]]]);
  }
  for (PetscInt o = 0; o < N; o++) {
    for (int i = 0; i < 3; i++) P->y[4 * o + i] = x0[3 * o + i];
    P->y[4 * o + 3] = P->D.theta[o];
  }
  PetscCall(PetscArraycpy(P->y0, P->y, 4 * N));
  PetscCall(HylcPeriodicSetUpConstraints_Private(P, x0));
  PetscCall(PetscFree(x0));
  PetscCall(PetscMalloc1(6 * P->nfe, &P->segx));
  P->setup = PETSC_TRUE;
  PetscCall(HylcPeriodicSetState(P, P->y));
  PetscCall(PetscLogEventEnd(HYLC_PeriodicSetUp, 0, 0, 0, 0));
  if (!P->viewed) { /* once per pattern, not at every strain of a sampling job */
    PetscCall(HylcPeriodicViewFromOptions(P, NULL, "-periodic_view"));
    P->viewed = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetState - Sets y and computes the full positions q = C y + d.

  Not collective

  Input Parameters:
+ P - the periodic tile
- y - 4 per original vertex (may be the array of HylcPeriodicGetInitialState())

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicSetState(HylcPeriodic P, const PetscReal y[])
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  if (y != P->y) {
    /* the same state again (the line search's accepted trial, evaluated next with its Hessian): x and the
       contact pairs found for it stay */
    if (P->pairsValid) {
      PetscBool same;
      PetscCall(PetscMemcmp(P->y, y, 4 * (size_t)P->N * sizeof(PetscReal), &same));
      if (same) PetscFunctionReturn(PETSC_SUCCESS);
    }
    PetscCall(PetscArraycpy(P->y, y, 4 * P->N));
  }
  P->pairsValid = PETSC_FALSE;
  for (PetscInt k = 0; k < P->nfv; k++) {
    const PetscInt   o  = P->fo[k];
    const PetscReal *xo = P->y + 4 * o;
    if (P->rigidId[k])
      for (int i = 0; i < 3; i++) P->x[3 * k + i] = xo[i] + P->d[3 * k + i];
    else {
      Mat3(P->T + 9 * k, xo, P->x + 3 * k);
      for (int i = 0; i < 3; i++) P->x[3 * k + i] += P->d[3 * k + i];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicUpdateFrames - Time-parallel transport of every chain edge's reference director to its
  current tangent (the contact ghosts carry no frame), and reference twists updated on the nearest branch.

  Not collective

  Input Parameter:
. P - the periodic tile

  Level: advanced
@*/
PetscErrorCode HylcPeriodicUpdateFrames(HylcPeriodic P)
{
  PetscFunctionBegin;
  for (PetscInt e = 0; e < P->nchain; e++) {
    PetscReal tn[3];
    HylcSub3(P->x + 3 * P->ehead[e], P->x + 3 * P->esrc[e], tn);
    PetscCheck(HylcNormalize3(tn) > 0, PETSC_COMM_SELF, PETSC_ERR_FP, "Zero-length edge");
    HylcParallelTransport(P->et + 3 * e, tn, P->ed1 + 3 * e, P->ed1 + 3 * e);
    HylcOrthonormalizeDirector(tn, P->ed1 + 3 * e);
    for (int i = 0; i < 3; i++) P->et[3 * e + i] = tn[i];
  }
  for (PetscInt b = 0; b < P->nbe; b++) {
    const BendElem *E = P->be + b;
    P->mref[b]        = HylcAngleNear(HylcReferenceTwist(P->et + 3 * E->e, P->ed1 + 3 * E->e, P->et + 3 * E->f, P->ed1 + 3 * E->f), P->mref[b]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSaveFrames - Saves the reference frames and twists (HylcPeriodicRestoreFrames() restores them).

  Not collective

  Input Parameter:
. P - the periodic tile

  Level: advanced
@*/
PetscErrorCode HylcPeriodicSaveFrames(HylcPeriodic P)
{
  PetscFunctionBegin;
  PetscCall(PetscArraycpy(P->et0, P->et, 3 * P->nchain));
  PetscCall(PetscArraycpy(P->ed10, P->ed1, 3 * P->nchain));
  PetscCall(PetscArraycpy(P->mref0, P->mref, P->nbe));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicRestoreFrames - Restores the frames saved by HylcPeriodicSaveFrames().

  Not collective

  Input Parameter:
. P - the periodic tile

  Level: advanced
@*/
PetscErrorCode HylcPeriodicRestoreFrames(HylcPeriodic P)
{
  PetscFunctionBegin;
  PetscCall(PetscArraycpy(P->et, P->et0, 3 * P->nchain));
  PetscCall(PetscArraycpy(P->ed1, P->ed10, 3 * P->nchain));
  PetscCall(PetscArraycpy(P->mref, P->mref0, P->nbe));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetSizes - Sizes of the set-up tile (any output may be NULL).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameters:
+ ny     - reduced unknowns (4 per original vertex)
. nfull  - full vertices (originals and ghosts)
. nedges - full edges
- ncons  - independent constraint rows

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetSizes(HylcPeriodic P, PetscInt *ny, PetscInt *nfull, PetscInt *nedges, PetscInt *ncons)
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  if (ny) *ny = 4 * P->N;
  if (nfull) *nfull = P->nfv;
  if (nedges) *nedges = P->nfe;
  if (ncons) *ncons = P->ncons;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetArea - The reference area px py of the tile (m^2).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. A - the area

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetArea(HylcPeriodic P, PetscReal *A)
{
  PetscFunctionBegin;
  *A = P->D.px * P->D.py;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetConstants - The yarn constants of the model at the pattern's radius.

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. c - the constants

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetConstants(HylcPeriodic P, HylcYarnConstants *c)
{
  PetscFunctionBegin;
  *c = P->c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetMacroStrain - The macroscopic strain of the midsurface (its kernels' data).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. m - the strain (borrowed)

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetMacroStrain(HylcPeriodic P, const HylcMacroStrain **m)
{
  PetscFunctionBegin;
  PetscCall(HylcMidsurfaceGetStrain(P->ms, m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicFluctuationToLocal - The fluctuation u~ = y - y0 of a state y of the set-up tile in the local
  coordinates of its macroscopic deformation: per original vertex o, the position part as
  (A^-1 w_xy, w_z) with w = R(xi_o)^T u~_o (A = sqrt(I), R the rotation field: grad phi = R [A; 0]), the
  twist part as it is. HylcPeriodicFluctuationFromLocal() maps it back at another strain: a state carried
  this way is the old one deformed by the change of the macroscopic deformation (in the plane,
  x -> A_new A_old^-1 x relative to the rest map), so pieces of yarn close to each other stay close.

  Not collective

  Input Parameters:
+ P - the periodic tile, set up
- y - a state (4 per original vertex)

  Output Parameter:
. u - the local fluctuation (4 per original vertex; may not be y)

  Level: advanced

.seealso: HylcPeriodicFluctuationFromLocal(), HylcMicroSetInitialState()
@*/
PetscErrorCode HylcPeriodicFluctuationToLocal(HylcPeriodic P, const PetscReal y[], PetscReal u[])
{
  const HylcMacroStrain *m;

  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(HylcMidsurfaceGetStrain(P->ms, &m));
  for (PetscInt o = 0; o < P->N; o++) {
    PetscReal R[9], d[3], w[3];
    PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, R));
    for (int i = 0; i < 3; i++) d[i] = y[4 * o + i] - P->y0[4 * o + i];
    for (int j = 0; j < 3; j++) w[j] = R[j] * d[0] + R[3 + j] * d[1] + R[6 + j] * d[2]; /* R^T d */
    u[4 * o + 0] = m->Ainv[0] * w[0] + m->Ainv[1] * w[1];
    u[4 * o + 1] = m->Ainv[2] * w[0] + m->Ainv[3] * w[1];
    u[4 * o + 2] = w[2];
    u[4 * o + 3] = y[4 * o + 3] - P->y0[4 * o + 3];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicFluctuationFromLocal - The state y = y0 + u~ of the set-up tile whose fluctuation has the
  local coordinates u (HylcPeriodicFluctuationToLocal(), possibly at another strain).

  Not collective

  Input Parameters:
+ P - the periodic tile, set up
- u - the local fluctuation (4 per original vertex)

  Output Parameter:
. y - the state (may not be u)

  Level: advanced

.seealso: HylcPeriodicFluctuationToLocal()
@*/
PetscErrorCode HylcPeriodicFluctuationFromLocal(HylcPeriodic P, const PetscReal u[], PetscReal y[])
{
  const HylcMacroStrain *m;

  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(HylcMidsurfaceGetStrain(P->ms, &m));
  for (PetscInt o = 0; o < P->N; o++) {
    PetscReal R[9], w[3];
    PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, R));
    w[0] = m->A[0] * u[4 * o + 0] + m->A[1] * u[4 * o + 1];
    w[1] = m->A[2] * u[4 * o + 0] + m->A[3] * u[4 * o + 1];
    w[2] = u[4 * o + 2];
    for (int i = 0; i < 3; i++) y[4 * o + i] = P->y0[4 * o + i] + R[3 * i] * w[0] + R[3 * i + 1] * w[1] + R[3 * i + 2] * w[2];
    y[4 * o + 3] = P->y0[4 * o + 3] + u[4 * o + 3];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetInitialState - The initial guess y0 (x = phi + h n, u~ = 0) of the set-up tile.

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. y - 4 per original vertex: position and twist

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetInitialState(HylcPeriodic P, PetscReal y[])
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(PetscArraycpy(y, P->y0, 4 * P->N));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetFullPositions - The positions of the full vertices of the current state (borrowed arrays; any output may be NULL).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameters:
+ n     - full vertices
. x     - 3 per full vertex
. orig  - original vertex of each full vertex
- shift - lattice shift (2 per full vertex)

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetFullPositions(HylcPeriodic P, PetscInt *n, const PetscReal **x, const PetscInt **orig, const PetscInt **shift)
{
  PetscFunctionBegin;
  if (n) *n = P->nfv;
  if (x) *x = P->x;
  if (orig) *orig = P->fo;
  if (shift) *shift = P->fs;
  PetscFunctionReturn(PETSC_SUCCESS);
}
