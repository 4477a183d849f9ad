/* HylcPeriodic: contact pairs, the structure of the reduced Hessian (SetCOO) and the reduced evaluation (include/hylc/periodic.h). */
#include "periodicimpl.h"
#include <hylc/geom.h>

/* contact pairs among the full edges: broadphase with boxes inflated by pairMargin r, zero-weight pairs
   pruned, same-yarn pairs excluded; the candidates for the Hessian's structure are the segment pairs closer
   than 2 pairMargin r, the pairs that can touch those closer than 2 r */
static PetscErrorCode PushPair(PetscInt *n, PetscInt *cap, PetscInt **pairs, PetscReal **w, PetscInt i, PetscInt j, PetscReal wt)
{
  PetscFunctionBegin;
  if (*n == *cap) {
    PetscInt  *np;
    PetscReal *nw;
    *cap = *cap ? 2 * *cap : 256;
    PetscCall(PetscMalloc2(2 * *cap, &np, *cap, &nw));
    PetscCall(PetscArraycpy(np, *pairs, 2 * *n));
    PetscCall(PetscArraycpy(nw, *w, *n));
    PetscCall(PetscFree2(*pairs, *w));
    *pairs = np;
    *w     = nw;
  }
  (*pairs)[2 * *n]     = i;
  (*pairs)[2 * *n + 1] = j;
  (*w)[(*n)++]         = wt;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FindPairs(HylcPeriodic P)
{
  PetscFunctionBegin;
  if (P->pairsValid) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_TileBroadphase, 0, 0, 0, 0));
  for (PetscInt e = 0; e < P->nfe; e++)
    for (int i = 0; i < 3; i++) {
      P->segx[6 * e + i]     = P->x[3 * P->esrc[e] + i];
      P->segx[6 * e + 3 + i] = P->x[3 * P->ehead[e] + i];
    }
  if (!P->bvh) {
    PetscCheck(!HylcBVHCreate((int)P->nfe, &P->bvh), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot create the broadphase");
    PetscCheck(!HylcBVHBuild(P->bvh, P->segx, NULL, P->pairMargin * P->c.r), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the broadphase");
    PetscCheck(!HylcBVHSetGhost(P->bvh, P->eghost), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot set ghost flags");
  } else
    PetscCheck(!HylcBVHRefit(P->bvh, P->segx, NULL), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot refit the broadphase");
  PetscCheck(!HylcBVHQuery(P->bvh, &P->cand), PETSC_COMM_SELF, PETSC_ERR_MEM, "Broadphase query failed");
  HylcPairListSort(&P->cand);
  P->npairs = P->ncand = 0;
  P->clearance         = 2 * P->pairMargin * P->c.r;
  for (size_t c = 0; c < P->cand.n; c++) {
    const PetscInt i = P->cand.idx[2 * c], j = P->cand.idx[2 * c + 1];
    const PetscInt ki = P->esrc[i], kj = P->esrc[j];
    const PetscInt s[2] = {P->fs[2 * kj] - P->fs[2 * ki], P->fs[2 * kj + 1] - P->fs[2 * ki + 1]};
    PetscBool      excl;
    PetscCall(HylcPatternIsExcludedPair(P->pat, P->model.excludeArc, P->fo[ki], P->fo[kj], s, &excl));
    if (excl) continue;
    const PetscInt nor = (P->esrc[i] < P->N) + (P->ehead[i] < P->N) + (P->esrc[j] < P->N) + (P->ehead[j] < P->N);
    if (!nor) continue;
    /* by the distance of the segments (the broadphase's boxes are a coarse superset): the structure keeps
       the pairs closer than 2 m r (m >= 1 the pair margin), the contact terms are evaluated on the pairs
       closer than 2 r, both with a relative slack of 1e-6 for the rounding of the kernels' own test (a
       pair at distance >= 2 r has E = 0, g = 0 and H = 0, include/hylc/contact.h), so that the touching
       pairs are always in the structure */
    double          sp, tp;
    const PetscReal d = HylcSegmentSegmentDistance(P->segx + 6 * i, P->segx + 6 * i + 3, P->segx + 6 * j, P->segx + 6 * j + 3, &sp, &tp), slack = 1 + 1e-6;
    if (!(d < 2 * P->pairMargin * P->c.r * slack)) continue;
    P->clearance = PetscMin(P->clearance, d);
    PetscCall(PushPair(&P->ncand, &P->capcand, &P->cpairs, &P->cw, i, j, nor / 4.0));
    if (d < 2 * P->c.r * slack) PetscCall(PushPair(&P->npairs, &P->cappairs, &P->pairs, &P->pw, i, j, nor / 4.0));
  }
  P->pairsValid = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_TileBroadphase, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetNumContactPairs - The number of contact pairs that can touch in the current state: segment
  pairs closer than 2 r (runs the broadphase).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. n - the number of pairs

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetNumContactPairs(HylcPeriodic P, PetscInt *n)
{
  PetscFunctionBegin;
  PetscCall(FindPairs(P));
  *n = P->npairs;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetClearance - The smallest distance between the centerlines of two yarn segments that may
  come into contact, in the current state (runs the broadphase, which computes it with the pair lists): the
  minimum over the segment pairs (same-yarn neighbours excluded as for contact), or 2 m r (m the pair
  margin) if that is smaller. If every vertex moves by less than half of it along a
  straight step, no two centerlines cross during the step (the distance of two segments is 2-Lipschitz in
  the largest vertex displacement), the basis of the clearance step limit (HylcMicroSetStepLimit()).

  Not collective

  Input Parameter:
. P - the periodic tile (its state set by HylcPeriodicSetState())

  Output Parameter:
. d - the clearance (m)

  Level: developer

.seealso: HylcPeriodicSetState(), HylcPeriodicGetNumContactPairs()
@*/
PetscErrorCode HylcPeriodicGetClearance(HylcPeriodic P, PetscReal *d)
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(FindPairs(P));
  *d = P->clearance;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* local element layout: a list of "slots", each a full vertex position (3 dofs) or a twist (1 dof) */
typedef struct {
  PetscInt n;       /* number of local dofs */
  PetscInt vert[4]; /* full vertex of each position slot (-1 none) */
  PetscInt pos[4];  /* local offset of each position slot */
  PetscInt npos;
  PetscInt twist[2]; /* local offset of twist dofs and their original vertex */
  PetscInt two[2];
  PetscInt ntw;
} Layout;

static void LayoutDofs(const HylcPeriodic P, const Layout *L, PetscInt idx[])
{
  for (PetscInt a = 0; a < L->npos; a++)
    for (int i = 0; i < 3; i++) idx[L->pos[a] + i] = 4 * P->fo[L->vert[a]] + i;
  for (PetscInt a = 0; a < L->ntw; a++) idx[L->twist[a]] = 4 * L->two[a] + 3;
}

/* g_loc <- B^T g_loc and H_loc <- B^T H_loc B for the rotation blocks T of the position slots */
static void Reduce(const HylcPeriodic P, const Layout *L, double g[], double H[])
{
  const PetscInt n = L->n;
  for (PetscInt a = 0; a < L->npos; a++) {
    const PetscInt k = L->vert[a], o = L->pos[a];
    if (P->rigidId[k]) continue;
    const PetscReal *T = P->T + 9 * k;
    if (g) {
      PetscReal t[3];
      MatT3(T, g + o, t);
      for (int i = 0; i < 3; i++) g[o + i] = t[i];
    }
    if (H) {
      /* rows: H[o+i, :] <- sum_m T[m, i] H[o+m, :]; columns likewise */
      for (PetscInt c = 0; c < n; c++) {
        PetscReal t[3];
        for (int i = 0; i < 3; i++) t[i] = T[i] * H[(o + 0) * n + c] + T[3 + i] * H[(o + 1) * n + c] + T[6 + i] * H[(o + 2) * n + c];
        for (int i = 0; i < 3; i++) H[(o + i) * n + c] = t[i];
      }
      for (PetscInt r = 0; r < n; r++) {
        PetscReal t[3];
        for (int i = 0; i < 3; i++) t[i] = H[r * n + o] * T[i] + H[r * n + o + 1] * T[3 + i] + H[r * n + o + 2] * T[6 + i];
        for (int i = 0; i < 3; i++) H[r * n + o + i] = t[i];
      }
    }
  }
}

static void StretchLayout(const HylcPeriodic P, PetscInt e, Layout *L)
{
  L->n       = 6;
  L->npos    = 2;
  L->vert[0] = P->esrc[e];
  L->vert[1] = P->ehead[e];
  L->pos[0]  = 0;
  L->pos[1]  = 3;
  L->ntw     = 0;
}
static void BendLayout(const HylcPeriodic P, const BendElem *E, Layout *L)
{
  L->n        = 11;
  L->npos     = 3;
  L->vert[0]  = E->v[0];
  L->vert[1]  = E->v[1];
  L->vert[2]  = E->v[2];
  L->pos[0]   = 0;
  L->pos[1]   = 4;
  L->pos[2]   = 8;
  L->ntw      = 2;
  L->twist[0] = 3;
  L->twist[1] = 7;
  L->two[0]   = P->fo[E->v[0]];
  L->two[1]   = P->fo[E->v[1]];
}
static void ContactLayout(const HylcPeriodic P, PetscInt i, PetscInt j, Layout *L)
{
  L->n       = 12;
  L->npos    = 4;
  L->vert[0] = P->esrc[i];
  L->vert[1] = P->ehead[i];
  L->vert[2] = P->esrc[j];
  L->vert[3] = P->ehead[j];
  for (int a = 0; a < 4; a++) L->pos[a] = 3 * a;
  L->ntw = 0;
}

/*@C
  HylcPeriodicCreateMatrix - Creates the matrix for the reduced Hessian H_y (MATSEQAIJ, 4N x 4N; its structure is
  set by HylcPeriodicEvaluate()).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. H - the matrix

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicCreateMatrix(HylcPeriodic P, Mat *H)
{
  PetscFunctionBegin;
  PetscCall(MatCreate(PETSC_COMM_SELF, H));
  PetscCall(MatSetSizes(*H, 4 * P->N, 4 * P->N, 4 * P->N, 4 * P->N));
  PetscCall(MatSetType(*H, MATSEQAIJ));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* is every touching pair in the COO structure? (both lists sorted lexicographically) */
static PetscBool PairsCovered(const HylcPeriodic P)
{
  PetscInt a = 0;
  for (PetscInt p = 0; p < P->npairs; p++) {
    const PetscInt i = P->pairs[2 * p], j = P->pairs[2 * p + 1];
    while (a < P->coonpairs && (P->coopairs[2 * a] < i || (P->coopairs[2 * a] == i && P->coopairs[2 * a + 1] < j))) a++;
    if (a == P->coonpairs || P->coopairs[2 * a] != i || P->coopairs[2 * a + 1] != j) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* Visits the elements in the order of the assembled values: stretch elements, bend-twist elements, then
   the pairs of the structure; returns the global dofs of element k in idx and its size in n. */
static PetscInt NumStructElements(const HylcPeriodic P) { return P->nfe + P->nbe + P->coonpairs; }
static void     StructElementDofs(const HylcPeriodic P, PetscInt k, PetscInt idx[12], PetscInt *n)
{
  Layout L;
  if (k < P->nfe) {
    StretchLayout(P, k, &L);
    if (P->sw[k] == 0) L.n = 0; /* no original vertex: not assembled */
  } else if (k < P->nfe + P->nbe)
    BendLayout(P, P->be + (k - P->nfe), &L);
  else {
    const PetscInt p = k - P->nfe - P->nbe;
    ContactLayout(P, P->coopairs[2 * p], P->coopairs[2 * p + 1], &L);
  }
  if (L.n) LayoutDofs(P, &L, idx);
  *n = L.n;
}

/* The structure of H_y: stencils plus a superset of the touching contact pairs, as 4x4 blocks of coupled
   vertices in a CSR matrix, and the position in its value array of every element-matrix entry. It is
   rebuilt only when a touching pair falls outside it; the matrix's nonzero pattern, hence the symbolic
   factorization, is then reused. (This replaces MatSetPreallocationCOO, whose sort of all element entries
   cost as much as ten evaluations.) The rows are built one vertex at a time from the elements incident to
   it, so every lookup of a neighbour block is O(1). */
static PetscErrorCode SetCOO(HylcPeriodic P, Mat H)
{
  const PetscInt  N = P->N;
  PetscInt       *doff, *dof, *koff, *sel, *istart, *inc, *start, *nbr, *mark, *where, *vpos, maxdeg = 0;
  unsigned short *mask;

  PetscFunctionBegin;
  if (H == P->cooMat && PairsCovered(P)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree2(P->coopairs, P->coopw));
  PetscCall(PetscMalloc2(2 * P->ncand + 1, &P->coopairs, P->ncand + 1, &P->coopw));
  PetscCall(PetscArraycpy(P->coopairs, P->cpairs, 2 * P->ncand));
  PetscCall(PetscArraycpy(P->coopw, P->cw, P->ncand));
  P->coonpairs        = P->ncand;
  const PetscInt nent = P->nfe * 36 + P->nbe * 121 + P->coonpairs * 144, nel = NumStructElements(P);
  if (nent > P->capcoo) {
    PetscCall(PetscFree(P->coopos));
    P->capcoo = nent + nent / 4;
    PetscCall(PetscMalloc1(P->capcoo, &P->coopos));
  }
  /* the dofs of every element (dof[doff[e] + p], p < n), and the offset koff[e] of its first entry in the
     element order of coopos: entry (p, q) of element e is coopos[koff[e] + p n + q] */
  PetscCall(PetscMalloc3(nel + 1, &doff, 12 * nel + 1, &dof, nel + 1, &koff));
  doff[0] = koff[0] = 0;
  for (PetscInt e = 0; e < nel; e++) {
    PetscInt n;
    StructElementDofs(P, e, dof + doff[e], &n);
    doff[e + 1] = doff[e] + n;
    koff[e + 1] = koff[e] + n * n;
  }
  const PetscInt ndof = doff[nel], ncoo = koff[nel];
  /* incidence: the element dof slots s (index into dof) of every vertex a, inc[istart[a] .. istart[a+1]),
     and the element sel[s] of each slot */
  PetscCall(PetscMalloc2(ndof + 1, &sel, ndof + 1, &inc));
  PetscCall(PetscCalloc2(N + 1, &istart, N + 1, &start));
  for (PetscInt e = 0; e < nel; e++)
    for (PetscInt s = doff[e]; s < doff[e + 1]; s++) {
      sel[s] = e;
      istart[dof[s] / 4 + 1]++;
    }
  for (PetscInt a = 0; a < N; a++) istart[a + 1] += istart[a];
  for (PetscInt s = 0; s < ndof; s++) inc[istart[dof[s] / 4]++] = s;
  for (PetscInt a = N; a > 0; a--) istart[a] = istart[a - 1];
  istart[0] = 0;
  /* vertex adjacency, the sorted neighbours nbr[start[a] .. start[a+1]) of each vertex (distinct via the
     marker mark[b] == a; where[b] is b's position in the row being built), and which of the 16 entries of
     each vertex block are used (positions do not couple with twists in stretch and contact elements): a
     16-bit mask per block. A row has at most its incident entries as neighbours, hence the bound ncoo. */
  PetscCall(PetscMalloc4(ncoo + 1, &nbr, ncoo + 1, &mask, N, &mark, N, &where));
  for (PetscInt b = 0; b < N; b++) mark[b] = -1;
  for (PetscInt a = 0; a < N; a++) {
    PetscInt *row = nbr + start[a], m = 0;
    for (PetscInt t = istart[a]; t < istart[a + 1]; t++) {
      const PetscInt e = sel[inc[t]];
      for (PetscInt s = doff[e]; s < doff[e + 1]; s++) {
        const PetscInt b = dof[s] / 4;
        if (mark[b] != a) {
          mark[b]  = a;
          row[m++] = b;
        }
      }
    }
    PetscCall(PetscSortInt(m, row));
    start[a + 1] = start[a] + m;
    maxdeg       = PetscMax(maxdeg, m);
    for (PetscInt q = 0; q < m; q++) {
      where[row[q]]      = q;
      mask[start[a] + q] = 0;
    }
    for (PetscInt t = istart[a]; t < istart[a + 1]; t++) {
      const PetscInt sp = inc[t], e = sel[sp], i = dof[sp] % 4; /* the slot sp is row 4a + i of element e */
      for (PetscInt s = doff[e]; s < doff[e + 1]; s++) mask[start[a] + where[dof[s] / 4]] |= (unsigned short)(1u << (4 * i + dof[s] % 4));
    }
  }
  /* CSR of the scalar rows: row 4a + i has, for every neighbour block, the columns its mask uses, entry
     (i, j) of the row's block q at the position vpos[16q + 4i + j] of the CSR values; then where each
     element entry of row vertex a goes */
  PetscCall(PetscFree2(P->rowptr, P->colind));
  PetscInt nnz = 0;
  for (PetscInt q = 0; q < start[N]; q++) nnz += __builtin_popcount(mask[q]);
  PetscCall(PetscMalloc2(4 * N + 1, &P->rowptr, nnz + 1, &P->colind));
  PetscCall(PetscMalloc1(16 * maxdeg + 1, &vpos));
  P->rowptr[0] = 0;
  for (PetscInt a = 0; a < N; a++) {
    const PetscInt        deg = start[a + 1] - start[a], *row = nbr + start[a];
    const unsigned short *rmask = mask + start[a];
    for (PetscInt i = 0; i < 4; i++) {
      const PetscInt r = 4 * a + i;
      PetscInt       c = P->rowptr[r];
      for (PetscInt q = 0; q < deg; q++) {
        for (PetscInt j = 0; j < 4; j++)
          if (rmask[q] & (1u << (4 * i + j))) {
            vpos[16 * q + 4 * i + j] = c;
            P->colind[c++]           = 4 * row[q] + j;
          }
      }
      P->rowptr[r + 1] = c;
    }
    for (PetscInt q = 0; q < deg; q++) where[row[q]] = q;
    for (PetscInt t = istart[a]; t < istart[a + 1]; t++) {
      const PetscInt sp = inc[t], e = sel[sp], n = doff[e + 1] - doff[e], i = dof[sp] % 4;
      PetscInt       k = koff[e] + (sp - doff[e]) * n;
      for (PetscInt s = doff[e]; s < doff[e + 1]; s++, k++) P->coopos[k] = vpos[16 * where[dof[s] / 4] + 4 * i + dof[s] % 4];
    }
  }
  P->nnz  = nnz;
  P->ncoo = ncoo;
  PetscCall(PetscFree(vpos));
  PetscCall(PetscFree4(nbr, mask, mark, where));
  PetscCall(PetscFree2(istart, start));
  PetscCall(PetscFree2(sel, inc));
  PetscCall(PetscFree3(doff, dof, koff));
  PetscCall(MatSeqAIJSetPreallocationCSR(H, P->rowptr, P->colind, NULL));
  P->cooMat = H;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* accumulate a reduced element gradient and Hessian: the Hessian's entries straight into the CSR values v
   of H_y at their positions pos (P->coopos of the element) */
static inline void Scatter(const HylcPeriodic P, const Layout *L, double ge[], double He[], PetscReal gy[], PetscScalar *v, const PetscInt *pos)
{
  PetscInt idx[12];
  if (P->gfull)
    for (PetscInt a = 0; a < L->npos; a++)
      for (int i = 0; i < 3; i++) P->gfull[3 * L->vert[a] + i] += ge[L->pos[a] + i];
  Reduce(P, L, gy ? ge : NULL, v ? He : NULL);
  if (gy) {
    LayoutDofs(P, L, idx);
    for (PetscInt i = 0; i < L->n; i++) gy[idx[i]] += ge[i];
  }
  if (v)
    for (PetscInt i = 0; i < L->n * L->n; i++) v[pos[i]] += He[i];
}

/* the evaluation; a degenerate element or a non-finite energy is no error: *bad = 1 (zero-length edge at
   original vertex *badv), 2 (degenerate bending element at *badv) or 3 (non-finite energy), parts = +inf */
static PetscErrorCode PeriodicEvaluate(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], Mat H, int *bad, PetscInt *badv)
{
  PetscReal    E[4] = {0, 0, 0, 0};
  double       x[12], ge[12], He[144];
  Layout       L;
  PetscScalar *hv = NULL; /* the CSR values of H */
  PetscInt     k  = 0;    /* the element's first entry in P->coopos */

  PetscFunctionBegin;
  *bad  = 0;
  *badv = -1;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscLogDouble t0, t1, tc0, tc1;
  PetscCall(PetscLogEventBegin(HYLC_PeriodicEvaluate, 0, 0, 0, 0));
  PetscCall(PetscTime(&t0));
  if (gy) PetscCall(PetscArrayzero(gy, 4 * P->N));
  if (mask & HYLC_TERM_CONTACT)
    PetscCall(FindPairs(P));
  else {
    P->npairs     = 0;
    P->pairsValid = PETSC_FALSE;
  }
  if (H) {
    PetscCall(SetCOO(P, H));
    PetscCall(MatSeqAIJGetArray(H, &hv));
    PetscCall(PetscArrayzero(hv, P->nnz));
  }
  for (PetscInt e = 0; e < P->nfe; e++) {
    if (P->sw[e] == 0) continue;
    StretchLayout(P, e, &L);
    for (int i = 0; i < 3; i++) {
      x[i]     = P->x[3 * P->esrc[e] + i];
      x[3 + i] = P->x[3 * P->ehead[e] + i];
    }
    if (mask & HYLC_TERM_STRETCH) {
      double en;
      if (HylcRodStretch(x, P->D.restLength[P->fo[P->esrc[e]]], P->c.ks, P->sw[e], &en, gy ? ge : NULL, H ? He : NULL)) {
        *bad  = 1;
        *badv = P->fo[P->esrc[e]];
        break;
      }
      E[0] += en;
      Scatter(P, &L, ge, He, gy, hv, P->coopos + k);
    }
    k += 36;
  }
  const int bt = ((mask & HYLC_TERM_BEND) ? HYLC_ROD_BEND : 0) | ((mask & HYLC_TERM_TWIST) ? HYLC_ROD_TWIST : 0);
  for (PetscInt b = 0; b < P->nbe && !*bad; b++) {
    const BendElem     *B  = P->be + b;
    const PetscInt      oc = P->fo[B->v[1]], ou = P->fo[B->v[0]];
    HylcRodBendTwistRef ref;
    double              en[2];
    BendLayout(P, B, &L);
    for (int i = 0; i < 3; i++) {
      x[i]       = P->x[3 * B->v[0] + i];
      x[4 + i]   = P->x[3 * B->v[1] + i];
      x[8 + i]   = P->x[3 * B->v[2] + i];
      ref.te[i]  = P->et[3 * B->e + i];
      ref.d1e[i] = P->ed1[3 * B->e + i];
      ref.tf[i]  = P->et[3 * B->f + i];
      ref.d1f[i] = P->ed1[3 * B->f + i];
    }
    x[3]          = P->y[4 * ou + 3];
    x[7]          = P->y[4 * oc + 3];
    ref.mref      = P->mref[b];
    ref.kappa0[0] = ref.kappa0[2] = P->D.restKappa[2 * oc];
    ref.kappa0[1] = ref.kappa0[3] = P->D.restKappa[2 * oc + 1];
    ref.tau0                      = P->D.restTwist[oc];
    ref.lbar                      = 0.5 * (P->D.restLength[ou] + P->D.restLength[oc]);
    if (bt) {
      const int err = (gy || H) ? HylcRodBendTwist(x, &ref, &P->btpar, B->w, bt, en, gy ? ge : NULL, H ? He : NULL) : HylcRodBendTwistEnergy(x, &ref, &P->btpar, B->w, en);
      if (err) {
        *bad  = 2;
        *badv = oc;
        break;
      }
      if (mask & HYLC_TERM_BEND) E[1] += en[0];
      if (mask & HYLC_TERM_TWIST) E[2] += en[1];
      if (P->gtfull) { /* before Scatter reduces ge */
        P->gtfull[B->e] += ge[3];
        P->gtfull[B->f] += ge[7];
      }
      Scatter(P, &L, ge, He, gy, hv, P->coopos + k);
    }
    k += 121;
  }
  PetscCall(PetscLogEventBegin(HYLC_TileContact, 0, 0, 0, 0));
  PetscCall(PetscTime(&tc0));
  const PetscInt   np = *bad ? 0 : H ? P->coonpairs : P->npairs; /* with a Hessian: every pair of its structure (the others give 0) */
  const PetscInt  *pl = H ? P->coopairs : P->pairs;
  const PetscReal *pw = H ? P->coopw : P->pw;
  for (PetscInt p = 0; p < np; p++) {
    const PetscInt i = pl[2 * p], j = pl[2 * p + 1];
    double         en;
    ContactLayout(P, i, j, &L);
    for (int a = 0; a < 4; a++)
      for (int c = 0; c < 3; c++) x[3 * a + c] = P->x[3 * L.vert[a] + c];
    const PetscReal la = P->D.restLength[P->fo[P->esrc[i]]], lb = P->D.restLength[P->fo[P->esrc[j]]];
    if (P->model.contactType == HYLC_CONTACT_QUADRATURE)
      en = HylcContactQuadrature(x, x + 3, x + 6, x + 9, la, lb, P->c.kc, P->c.r, (int)P->model.contactPoints, pw[p], gy ? ge : NULL, H ? He : NULL);
    else
      en = HylcContactClosestPoint(x, x + 3, x + 6, x + 9, la, lb, P->c.kc, P->c.r, pw[p], gy ? ge : NULL, H ? He : NULL, NULL, NULL, NULL);
    E[3] += en;
    Scatter(P, &L, ge, He, gy, hv, P->coopos + k);
    k += 144;
  }
  PetscCall(PetscTime(&tc1));
  P->tContact += tc1 - tc0;
  PetscCall(PetscLogEventEnd(HYLC_TileContact, 0, 0, 0, 0));
  if (H) {
    PetscCall(PetscLogEventBegin(HYLC_TileAssemble, 0, 0, 0, 0));
    PetscCall(PetscTime(&tc0));
    PetscCall(MatSeqAIJRestoreArray(H, &hv));
    PetscCall(PetscTime(&tc1));
    P->tAssemble += tc1 - tc0;
    PetscCall(PetscLogEventEnd(HYLC_TileAssemble, 0, 0, 0, 0));
  }
  PetscCall(PetscTime(&t1));
  P->tEval += t1 - t0;
  if (!*bad && !(PetscIsNormalReal(E[0] + E[1] + E[2] + E[3]) || E[0] + E[1] + E[2] + E[3] == 0)) *bad = 3;
  for (int i = 0; i < 4; i++) parts[i] = *bad == 1 || *bad == 2 ? PETSC_INFINITY : E[i];
  PetscCall(PetscLogEventEnd(HYLC_PeriodicEvaluate, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicEvaluate - Energy of the current state (parts: stretch, bend, twist, contact, for the terms
  in mask), and optionally the reduced gradient g_y (4 per original vertex, overwritten) and reduced
  Hessian H_y (from HylcPeriodicCreateMatrix(), overwritten). A degenerate geometry or a non-finite energy
  is a PETSC_ERR_FP error (see HylcPeriodicEvaluateFinite()).

  Not collective

  Input Parameters:
+ P    - the periodic tile
- mask - terms: HYLC_TERM_STRETCH | HYLC_TERM_BEND | HYLC_TERM_TWIST | HYLC_TERM_CONTACT (HYLC_TERM_ALL)

  Output Parameters:
+ parts - energy of each term (J)
. gy    - the reduced gradient (may be NULL)
- H     - the reduced Hessian (may be NULL)

  Level: beginner
@*/
PetscErrorCode HylcPeriodicEvaluate(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], Mat H)
{
  int      bad;
  PetscInt v;

  PetscFunctionBegin;
  PetscCall(PeriodicEvaluate(P, mask, parts, gy, H, &bad, &v));
  PetscCheck(bad != 1, PETSC_COMM_SELF, PETSC_ERR_FP, "Zero-length edge at vertex %" PetscInt_FMT, v);
  PetscCheck(bad != 2, PETSC_COMM_SELF, PETSC_ERR_FP, "Bending element at vertex %" PetscInt_FMT " is degenerate", v);
  PetscCheck(bad != 3, PETSC_COMM_SELF, PETSC_ERR_FP, "Energy is not finite: stretch %g, bend %g, twist %g, contact %g", (double)parts[0], (double)parts[1], (double)parts[2], (double)parts[3]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicEvaluateFinite - HylcPeriodicEvaluate() for a solver's trial states: a degenerate geometry
  (a zero-length edge, a degenerate bending element) or a non-finite energy is a result, not an error:
  *finite = PETSC_FALSE and the energy counts as +inf (gy and H are then undefined). Any other failure
  is an error.

  Not collective

  Input Parameters:
+ P    - the periodic tile
- mask - terms (as HylcPeriodicEvaluate())

  Output Parameters:
+ parts  - energy of each term (J)
. gy     - the reduced gradient (may be NULL)
. H      - the reduced Hessian (may be NULL)
- finite - whether the state is valid and its energy finite

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicEvaluateFinite(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], Mat H, PetscBool *finite)
{
  int      bad;
  PetscInt v;

  PetscFunctionBegin;
  PetscCall(PeriodicEvaluate(P, mask, parts, gy, H, &bad, &v));
  *finite = (PetscBool)!bad;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The evaluation with the gradient of E with respect to every full vertex's position accumulated in gfull (3
   per full vertex, the elements' gradients with their fractional weights) and with respect to the twist of
   every full chain edge in gtfull: the forces and moments on the ghosts that the strain derivatives need. A degenerate geometry or a non-finite energy is an error. */
PetscErrorCode HylcPeriodicEvaluateFull_Private(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], PetscReal gfull[], PetscReal gtfull[])
{
  int            bad;
  PetscInt       v;
  PetscReal     *gw;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(gy ? 0 : 4 * P->N, &gw)); /* the element gradients are formed only with a reduced gradient */
  PetscCall(PetscArrayzero(gfull, 3 * P->nfv));
  PetscCall(PetscArrayzero(gtfull, P->nchain));
  P->gfull  = gfull;
  P->gtfull = gtfull;
  ierr      = PeriodicEvaluate(P, mask, parts, gy ? gy : gw, NULL, &bad, &v);
  P->gfull  = NULL;
  P->gtfull = NULL;
  PetscCall(PetscFree(gw));
  PetscCall(ierr);
  PetscCheck(bad != 1, PETSC_COMM_SELF, PETSC_ERR_FP, "Zero-length edge at vertex %" PetscInt_FMT, v);
  PetscCheck(bad != 2, PETSC_COMM_SELF, PETSC_ERR_FP, "Bending element at vertex %" PetscInt_FMT " is degenerate", v);
  PetscCheck(bad != 3, PETSC_COMM_SELF, PETSC_ERR_FP, "Energy is not finite: stretch %g, bend %g, twist %g, contact %g", (double)parts[0], (double)parts[1], (double)parts[2], (double)parts[3]);
  PetscFunctionReturn(PETSC_SUCCESS);
}
