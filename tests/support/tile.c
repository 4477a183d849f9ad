/* HylcTile: energy, gradient and Hessian of a translation-periodic yarn tile (see tests/support/tile.h). */
#include "tile.h"
#include <hylc/periodic.h> /* the log event TILE_Evaluate */
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <hylc/rod.h>

struct _n_HylcTile {
  HylcPattern            pat;
  HylcPatternData        D;
  HylcYarnModel          model;
  HylcYarnConstants      c;
  HylcRodBendTwistParams btpar;
  PetscInt               nv;
  PetscReal              L[2][3]; /* lattice vectors */
  PetscReal             *q;       /* 4 per vertex: x, y, z, theta of the outgoing edge */
  PetscReal             *t, *d1;  /* stored unit tangent and reference director per edge (3 each) */
  PetscReal             *mref;    /* stored reference twist per vertex */
  /* broadphase over the tile and its periodic copies */
  PetscInt       nshift, capshift, *shifts; /* shifts[0] = (0,0), then the copies */
  double        *segx;                      /* 6 per segment of the extended list */
  unsigned char *ghost;
  PetscInt       nseg;
  HylcBVH        bvh;
  HylcPairList   cand;
  /* contact pairs (a, b, s1, s2): segment a and the copy of segment b shifted by s */
  PetscInt npairs, cappairs, *pairs;
  /* COO structure of the Hessian for the pair list it was built for */
  PetscInt     ncoo, capcoo, *cooi, *cooj;
  PetscScalar *coov;
  PetscInt     coonpairs, *coopairs;
  Mat          cooMat; /* the matrix the preallocation was set on (not referenced) */
};

static inline void LatticeShift(const HylcTile T, PetscReal s1, PetscReal s2, PetscReal o[3])
{
  for (int d = 0; d < 3; d++) o[d] = s1 * T->L[0][d] + s2 * T->L[1][d];
}

/* endpoints of the edge leaving v, in the copy shifted by (s1, s2) */
static inline void EdgeEnds(const HylcTile T, PetscInt v, PetscInt s1, PetscInt s2, double a0[3], double a1[3])
{
  const PetscInt w = T->D.next[v];
  PetscReal      o0[3], o1[3];
  LatticeShift(T, s1, s2, o0);
  LatticeShift(T, s1 + T->D.shift[2 * v], s2 + T->D.shift[2 * v + 1], o1);
  for (int d = 0; d < 3; d++) {
    a0[d] = T->q[4 * v + d] + o0[d];
    a1[d] = T->q[4 * w + d] + o1[d];
  }
}

/*@C
  HylcTileCreate - Creates the energy of a periodic tile of the pattern with the yarn model; the state
  starts at the pattern's positions and twists, with its reference directors and reference twists, and
  the lattice at rest. Not collective (the tile lives on one rank); the pattern is referenced.
@*/
PetscErrorCode HylcTileCreate(HylcPattern pat, const HylcYarnModel *model, HylcTile *tile)
{
  HylcTile T;

  PetscFunctionBegin;
  PetscCall(HylcPeriodicInitializePackage()); /* TILE_Evaluate is registered with the periodic tile's events */
  PetscCall(PetscNew(&T));
  PetscCall(PetscObjectReference((PetscObject)pat));
  T->pat   = pat;
  T->model = *model;
  PetscCall(HylcPatternGetData(pat, &T->D));
  PetscCall(HylcYarnModelGetConstants(model, T->D.radius, &T->c));
  T->btpar.B       = T->c.B;
  T->btpar.beta    = T->c.beta;
  T->btpar.variant = model->curvature;
  T->nv            = T->D.nv;
  PetscCall(PetscMalloc4(4 * T->nv, &T->q, 3 * T->nv, &T->t, 3 * T->nv, &T->d1, T->nv, &T->mref));
  for (PetscInt v = 0; v < T->nv; v++) {
    for (int d = 0; d < 3; d++) T->q[4 * v + d] = T->D.X[3 * v + d];
    T->q[4 * v + 3] = T->D.theta[v];
  }
  const PetscReal L1[3] = {T->D.px, 0, 0}, L2[3] = {0, T->D.py, 0};
  PetscCall(HylcTileSetLattice(T, L1, L2));
  /* stored frames: the pattern's directors on the current tangents, reference twists on the branch of RefT */
  for (PetscInt v = 0; v < T->nv; v++) {
    double a0[3], a1[3];
    EdgeEnds(T, v, 0, 0, a0, a1);
    HylcSub3(a1, a0, T->t + 3 * v);
    HylcNormalize3(T->t + 3 * v);
    for (int d = 0; d < 3; d++) T->d1[3 * v + d] = T->D.refD1[3 * v + d];
    HylcOrthonormalizeDirector(T->t + 3 * v, T->d1 + 3 * v);
  }
  for (PetscInt v = 0; v < T->nv; v++) {
    const PetscInt u = T->D.prev[v];
    T->mref[v]       = HylcAngleNear(HylcReferenceTwist(T->t + 3 * u, T->d1 + 3 * u, T->t + 3 * v, T->d1 + 3 * v), T->D.refTwist[v]);
  }
  *tile = T;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcTileDestroy(HylcTile *tile)
{
  HylcTile T = *tile;

  PetscFunctionBegin;
  if (!T) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree4(T->q, T->t, T->d1, T->mref));
  PetscCall(PetscFree(T->shifts));
  PetscCall(PetscFree2(T->segx, T->ghost));
  HylcBVHDestroy(&T->bvh);
  HylcPairListFree(&T->cand);
  PetscCall(PetscFree(T->pairs));
  PetscCall(PetscFree3(T->cooi, T->cooj, T->coov));
  PetscCall(PetscFree(T->coopairs));
  PetscCall(HylcPatternDestroy(&T->pat));
  PetscCall(PetscFree(T));
  *tile = NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcTileGetSize(HylcTile T, PetscInt *n)
{
  PetscFunctionBegin;
  *n = 4 * T->nv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcTileGetConstants(HylcTile T, HylcYarnConstants *c)
{
  PetscFunctionBegin;
  *c = T->c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTileSetLattice - Sets the lattice vectors: the copy of the tile shifted by (s1, s2) periods sits at
  x + s1 L1 + s2 L2. L1 and L2 must span the xy-plane. Not collective.
@*/
PetscErrorCode HylcTileSetLattice(HylcTile T, const PetscReal L1[3], const PetscReal L2[3])
{
  PetscFunctionBegin;
  PetscCheck(PetscAbsReal(L1[0] * L2[1] - L1[1] * L2[0]) > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Lattice vectors must span the xy-plane");
  for (int d = 0; d < 3; d++) {
    T->L[0][d] = L1[d];
    T->L[1][d] = L2[d];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcTileSetState(HylcTile T, const PetscReal q[])
{
  PetscFunctionBegin;
  PetscCall(PetscArraycpy(T->q, q, 4 * T->nv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcTileGetState(HylcTile T, PetscReal q[])
{
  PetscFunctionBegin;
  PetscCall(PetscArraycpy(q, T->q, 4 * T->nv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTileUpdateFrames - Time-parallel transport of the stored reference directors to the current edge
  tangents, and update of the stored reference twists on the branch nearest their previous values (no
  2 pi jumps). Call after accepting a new state. Not collective.
@*/
PetscErrorCode HylcTileUpdateFrames(HylcTile T)
{
  PetscFunctionBegin;
  for (PetscInt v = 0; v < T->nv; v++) {
    double a0[3], a1[3], tn[3];
    EdgeEnds(T, v, 0, 0, a0, a1);
    HylcSub3(a1, a0, tn);
    PetscCheck(HylcNormalize3(tn) > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "Edge leaving vertex %" PetscInt_FMT " has zero length", v);
    HylcParallelTransport(T->t + 3 * v, tn, T->d1 + 3 * v, T->d1 + 3 * v);
    HylcOrthonormalizeDirector(tn, T->d1 + 3 * v);
    for (int d = 0; d < 3; d++) T->t[3 * v + d] = tn[d];
  }
  for (PetscInt v = 0; v < T->nv; v++) {
    const PetscInt u = T->D.prev[v];
    T->mref[v]       = HylcAngleNear(HylcReferenceTwist(T->t + 3 * u, T->d1 + 3 * u, T->t + 3 * v, T->d1 + 3 * v), T->mref[v]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Periodic copies that can come within contact distance of the tile; fills the extended segment list. */
static PetscErrorCode TileUpdateCopies(HylcTile T)
{
  const PetscReal cut   = 2 * T->c.r * 1.01;
  PetscReal       lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL};
  PetscInt        m[2];

  PetscFunctionBegin;
  for (PetscInt v = 0; v < T->nv; v++) {
    double a0[3], a1[3];
    EdgeEnds(T, v, 0, 0, a0, a1);
    for (int d = 0; d < 2; d++) {
      lo[d] = PetscMin(lo[d], PetscMin(a0[d], a1[d]));
      hi[d] = PetscMax(hi[d], PetscMax(a0[d], a1[d]));
    }
  }
  /* s L in (box - box) + ball(cut): bound |s| through the inverse of the in-plane lattice matrix */
  {
    const PetscReal W = hi[0] - lo[0] + cut, H = hi[1] - lo[1] + cut;
    const PetscReal det       = T->L[0][0] * T->L[1][1] - T->L[0][1] * T->L[1][0];
    const PetscReal inv[2][2] = {{T->L[1][1] / det, -T->L[1][0] / det}, {-T->L[0][1] / det, T->L[0][0] / det}};
    for (int k = 0; k < 2; k++) m[k] = (PetscInt)PetscCeilReal(PetscAbsReal(inv[k][0]) * W + PetscAbsReal(inv[k][1]) * H);
  }
  const PetscInt nshift = (2 * m[0] + 1) * (2 * m[1] + 1);
  if (nshift > T->capshift) {
    PetscCall(PetscFree(T->shifts));
    PetscCall(PetscMalloc1(2 * nshift, &T->shifts));
    T->capshift = nshift;
  }
  T->nshift                    = 0;
  T->shifts[2 * T->nshift]     = 0;
  T->shifts[2 * T->nshift + 1] = 0;
  T->nshift++;
  for (PetscInt s1 = -m[0]; s1 <= m[0]; s1++)
    for (PetscInt s2 = -m[1]; s2 <= m[1]; s2++) {
      if (!s1 && !s2) continue;
      T->shifts[2 * T->nshift]     = s1;
      T->shifts[2 * T->nshift + 1] = s2;
      T->nshift++;
    }
  const PetscInt nseg = T->nshift * T->nv;
  if (nseg != T->nseg) {
    PetscCall(PetscFree2(T->segx, T->ghost));
    PetscCall(PetscMalloc2(6 * nseg, &T->segx, nseg, &T->ghost));
    HylcBVHDestroy(&T->bvh);
    T->nseg = nseg;
  }
  for (PetscInt k = 0; k < T->nshift; k++)
    for (PetscInt v = 0; v < T->nv; v++) {
      const PetscInt i = k * T->nv + v;
      EdgeEnds(T, v, T->shifts[2 * k], T->shifts[2 * k + 1], T->segx + 6 * i, T->segx + 6 * i + 3);
      T->ghost[i] = (unsigned char)(k > 0);
    }
  if (!T->bvh) {
    PetscCheck(!HylcBVHCreate((int)nseg, &T->bvh), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot create the broadphase");
    PetscCheck(!HylcBVHBuild(T->bvh, T->segx, NULL, T->c.r), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the broadphase");
    PetscCheck(!HylcBVHSetGhost(T->bvh, T->ghost), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot set ghost flags");
  } else
    PetscCheck(!HylcBVHRefit(T->bvh, T->segx, NULL), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot refit the broadphase");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Contact pairs: broadphase candidates, each unordered pair (a, copy of b shifted by s) once, minus the
   same-yarn exclusions. */
static PetscErrorCode TileFindPairs(HylcTile T)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_TileBroadphase, 0, 0, 0, 0));
  PetscCall(TileUpdateCopies(T));
  PetscCheck(!HylcBVHQuery(T->bvh, &T->cand), PETSC_COMM_SELF, PETSC_ERR_MEM, "Broadphase query failed");
  HylcPairListSort(&T->cand);
  T->npairs = 0;
  for (size_t k = 0; k < T->cand.n; k++) {
    const PetscInt i = T->cand.idx[2 * k], j = T->cand.idx[2 * k + 1];
    const PetscInt ki = i / T->nv, kj = j / T->nv;
    PetscInt       a, b, s[2];
    if (ki && kj) continue;
    if (!ki && !kj) { /* both in the tile: i < j */
      a    = i;
      b    = j;
      s[0] = s[1] = 0;
    } else {
      /* one in the tile; keep only the representation with a lexicographically positive shift */
      const PetscInt kk = ki ? ki : kj;
      s[0]              = T->shifts[2 * kk];
      s[1]              = T->shifts[2 * kk + 1];
      if (s[0] < 0 || (s[0] == 0 && s[1] < 0)) continue;
      a = ki ? j % T->nv : i % T->nv; /* the tile segment */
      b = ki ? i % T->nv : j % T->nv; /* the shifted one */
    }
    PetscBool excl;
    PetscCall(HylcPatternIsExcludedPair(T->pat, T->model.excludeArc, a, b, s, &excl));
    if (excl) continue;
    if (T->npairs == T->cappairs) {
      PetscInt *np;
      T->cappairs = T->cappairs ? 2 * T->cappairs : 256;
      PetscCall(PetscMalloc1(4 * T->cappairs, &np));
      PetscCall(PetscArraycpy(np, T->pairs, 4 * T->npairs));
      PetscCall(PetscFree(T->pairs));
      T->pairs = np;
    }
    PetscInt *P = T->pairs + 4 * T->npairs++;
    P[0]        = a;
    P[1]        = b;
    P[2]        = s[0];
    P[3]        = s[1];
  }
  PetscCall(PetscLogEventEnd(HYLC_TileBroadphase, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcTileGetNumContactPairs(HylcTile T, PetscInt *n)
{
  PetscFunctionBegin;
  PetscCall(TileFindPairs(T));
  *n = T->npairs;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* global dof indices of the three element kinds */
static inline void StretchDofs(const HylcTile T, PetscInt v, PetscInt idx[6])
{
  const PetscInt w = T->D.next[v];
  for (int d = 0; d < 3; d++) {
    idx[d]     = 4 * v + d;
    idx[3 + d] = 4 * w + d;
  }
}
static inline void BendTwistDofs(const HylcTile T, PetscInt v, PetscInt idx[11])
{
  const PetscInt u = T->D.prev[v], w = T->D.next[v];
  for (int d = 0; d < 3; d++) {
    idx[d]     = 4 * u + d;
    idx[4 + d] = 4 * v + d;
    idx[8 + d] = 4 * w + d;
  }
  idx[3] = 4 * u + 3;
  idx[7] = 4 * v + 3;
}
static inline void ContactDofs(const HylcTile T, const PetscInt P[4], PetscInt idx[12])
{
  const PetscInt vs[4] = {P[0], T->D.next[P[0]], P[1], T->D.next[P[1]]};
  for (int k = 0; k < 4; k++)
    for (int d = 0; d < 3; d++) idx[3 * k + d] = 4 * vs[k] + d;
}

/*@C
  HylcTileCreateMatrix - Creates a sequential AIJ matrix of the tile's size for HylcTileEvaluate().
@*/
PetscErrorCode HylcTileCreateMatrix(HylcTile T, Mat *H)
{
  PetscFunctionBegin;
  PetscCall(MatCreate(PETSC_COMM_SELF, H));
  PetscCall(MatSetSizes(*H, 4 * T->nv, 4 * T->nv, 4 * T->nv, 4 * T->nv));
  PetscCall(MatSetType(*H, MATSEQAIJ));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* (Re)builds the COO structure when the pair list changed or the matrix is new. */
static PetscErrorCode TileSetCOO(HylcTile T, Mat H)
{
  PetscBool same = (PetscBool)(H == T->cooMat && T->coonpairs == T->npairs);

  PetscFunctionBegin;
  if (same) PetscCall(PetscArraycmp(T->coopairs, T->pairs, 4 * T->npairs, &same));
  if (same) PetscFunctionReturn(PETSC_SUCCESS);
  const PetscInt n = T->nv * (36 + 121) + T->npairs * 144;
  if (n > T->capcoo) {
    PetscCall(PetscFree3(T->cooi, T->cooj, T->coov));
    T->capcoo = n + n / 4;
    PetscCall(PetscMalloc3(T->capcoo, &T->cooi, T->capcoo, &T->cooj, T->capcoo, &T->coov));
  }
  PetscInt k = 0, idx[12];
  for (PetscInt v = 0; v < T->nv; v++) {
    StretchDofs(T, v, idx);
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++, k++) {
        T->cooi[k] = idx[i];
        T->cooj[k] = idx[j];
      }
  }
  for (PetscInt v = 0; v < T->nv; v++) {
    BendTwistDofs(T, v, idx);
    for (int i = 0; i < 11; i++)
      for (int j = 0; j < 11; j++, k++) {
        T->cooi[k] = idx[i];
        T->cooj[k] = idx[j];
      }
  }
  for (PetscInt p = 0; p < T->npairs; p++) {
    ContactDofs(T, T->pairs + 4 * p, idx);
    for (int i = 0; i < 12; i++)
      for (int j = 0; j < 12; j++, k++) {
        T->cooi[k] = idx[i];
        T->cooj[k] = idx[j];
      }
  }
  T->ncoo = k;
  PetscCall(MatSetPreallocationCOO(H, T->ncoo, T->cooi, T->cooj));
  PetscCall(PetscFree(T->coopairs));
  PetscCall(PetscMalloc1(4 * T->npairs + 1, &T->coopairs));
  PetscCall(PetscArraycpy(T->coopairs, T->pairs, 4 * T->npairs));
  T->coonpairs = T->npairs;
  T->cooMat    = H;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTileEvaluate - Energy of the current state (parts[4] = stretch, bend, twist, contact, for the terms
  in mask), and optionally its gradient g (4 per vertex, overwritten) and Hessian H (from
  HylcTileCreateMatrix(), overwritten). Not collective.
  Fails with PETSC_ERR_FP when an element is degenerate (zero-length edge, folded or reversed edge).
@*/
PetscErrorCode HylcTileEvaluate(HylcTile T, int mask, PetscReal parts[4], PetscReal g[], Mat H)
{
  PetscInt  k    = 0, idx[12];
  PetscReal E[4] = {0, 0, 0, 0};
  double    x[12], ge[12], He[144];

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_TileEvaluate, 0, 0, 0, 0));
  if (g) PetscCall(PetscArrayzero(g, 4 * T->nv));
  if (mask & HYLC_TERM_CONTACT)
    PetscCall(TileFindPairs(T));
  else
    T->npairs = 0;
  if (H) PetscCall(TileSetCOO(T, H));
  PetscScalar *hv = T->coov;
  /* stretching, one element per edge */
  for (PetscInt v = 0; v < T->nv; v++) {
    EdgeEnds(T, v, 0, 0, x, x + 3);
    StretchDofs(T, v, idx);
    if (mask & HYLC_TERM_STRETCH) {
      double e;
      PetscCheck(!HylcRodStretch(x, T->D.restLength[v], T->c.ks, 1.0, &e, g ? ge : NULL, H ? He : NULL), PETSC_COMM_SELF, PETSC_ERR_FP, "Edge leaving vertex %" PetscInt_FMT " has zero length", v);
      E[0] += e;
      if (g)
        for (int i = 0; i < 6; i++) g[idx[i]] += ge[i];
      if (H)
        for (int i = 0; i < 36; i++) hv[k + i] = He[i];
    } else if (H)
      for (int i = 0; i < 36; i++) hv[k + i] = 0;
    k += 36;
  }
  /* bending and twisting, one element per vertex */
  const int bt = ((mask & HYLC_TERM_BEND) ? HYLC_ROD_BEND : 0) | ((mask & HYLC_TERM_TWIST) ? HYLC_ROD_TWIST : 0);
  for (PetscInt v = 0; v < T->nv; v++) {
    const PetscInt      u = T->D.prev[v];
    HylcRodBendTwistRef ref;
    double              e[2], a0[3], a1[3], b1[3];
    EdgeEnds(T, u, -T->D.shift[2 * u], -T->D.shift[2 * u + 1], a0, a1); /* incoming edge, ending at x_v */
    EdgeEnds(T, v, 0, 0, a1, b1);
    for (int d = 0; d < 3; d++) {
      x[d]       = a0[d];
      x[4 + d]   = a1[d];
      x[8 + d]   = b1[d];
      ref.te[d]  = T->t[3 * u + d];
      ref.d1e[d] = T->d1[3 * u + d];
      ref.tf[d]  = T->t[3 * v + d];
      ref.d1f[d] = T->d1[3 * v + d];
    }
    x[3]          = T->q[4 * u + 3];
    x[7]          = T->q[4 * v + 3];
    ref.mref      = T->mref[v];
    ref.kappa0[0] = T->D.restKappa[2 * v];
    ref.kappa0[1] = T->D.restKappa[2 * v + 1];
    ref.kappa0[2] = ref.kappa0[0];
    ref.kappa0[3] = ref.kappa0[1];
    ref.tau0      = T->D.restTwist[v];
    ref.lbar      = 0.5 * (T->D.restLength[u] + T->D.restLength[v]);
    BendTwistDofs(T, v, idx);
    if (bt) {
      const int err = (g || H) ? HylcRodBendTwist(x, &ref, &T->btpar, 1.0, bt, e, g ? ge : NULL, H ? He : NULL) : HylcRodBendTwistEnergy(x, &ref, &T->btpar, 1.0, e);
      PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_FP, "Bending element at vertex %" PetscInt_FMT " is degenerate", v);
      if (mask & HYLC_TERM_BEND) E[1] += e[0];
      if (mask & HYLC_TERM_TWIST) E[2] += e[1];
      if (g)
        for (int i = 0; i < 11; i++) g[idx[i]] += ge[i];
      if (H)
        for (int i = 0; i < 121; i++) hv[k + i] = He[i];
    } else if (H)
      for (int i = 0; i < 121; i++) hv[k + i] = 0;
    k += 121;
  }
  /* contact, one element per pair */
  PetscCall(PetscLogEventBegin(HYLC_TileContact, 0, 0, 0, 0));
  for (PetscInt p = 0; p < T->npairs; p++) {
    const PetscInt *P = T->pairs + 4 * p;
    double          e;
    EdgeEnds(T, P[0], 0, 0, x, x + 3);
    EdgeEnds(T, P[1], P[2], P[3], x + 6, x + 9);
    ContactDofs(T, P, idx);
    if (T->model.contactType == HYLC_CONTACT_QUADRATURE)
      e = HylcContactQuadrature(x, x + 3, x + 6, x + 9, T->D.restLength[P[0]], T->D.restLength[P[1]], T->c.kc, T->c.r, (int)T->model.contactPoints, 1.0, g ? ge : NULL, H ? He : NULL);
    else
      e = HylcContactClosestPoint(x, x + 3, x + 6, x + 9, T->D.restLength[P[0]], T->D.restLength[P[1]], T->c.kc, T->c.r, 1.0, g ? ge : NULL, H ? He : NULL, NULL, NULL, NULL);
    E[3] += e;
    if (g)
      for (int i = 0; i < 12; i++) g[idx[i]] += ge[i];
    if (H)
      for (int i = 0; i < 144; i++) hv[k + i] = He[i];
    k += 144;
  }
  PetscCall(PetscLogEventEnd(HYLC_TileContact, 0, 0, 0, 0));
  if (H) {
    PetscCall(PetscLogEventBegin(HYLC_TileAssemble, 0, 0, 0, 0));
    PetscCall(MatSetValuesCOO(H, T->coov, INSERT_VALUES));
    PetscCall(PetscLogEventEnd(HYLC_TileAssemble, 0, 0, 0, 0));
  }
  for (int i = 0; i < 4; i++) parts[i] = E[i];
  PetscCheck(PetscIsNormalReal(E[0] + E[1] + E[2] + E[3]) || E[0] + E[1] + E[2] + E[3] == 0, PETSC_COMM_SELF, PETSC_ERR_FP, "Tile energy is not finite: stretch %g, bend %g, twist %g, contact %g", (double)E[0], (double)E[1], (double)E[2],
             (double)E[3]);
  PetscCall(PetscLogEventEnd(HYLC_TileEvaluate, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
