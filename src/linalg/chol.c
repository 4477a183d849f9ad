/* HylcChol: supernodal sparse Cholesky on a block structure (see include/hylc/chol.h; src/linalg/matsolver.c wires it
   into PETSc as the solver type "hylc").

   Symbolic phase, on the graph of the nb = n / bs blocks ("vertices"):
     1. the block graph of A and its METIS nested-dissection ordering perm (new -> old);
     2. the elimination tree (Liu's algorithm with path compression);
     3. the column structures of L: struct(j) = {i > j : A_ij != 0} U (U_children c struct(c) \ {j});
     4. fundamental supernodes: j joins the supernode of j - 1 when j - 1 is its only child and
        struct(j - 1) = {j} U struct(j);
        then relaxed: neighbouring supernodes of a chain merge while the explicit zeros stay few;
     5. for each supernode s with block columns [f, f + w) its block rows R_s = [f, f + w) U struct(f + w - 1), and
        a dense column-major panel of bs |R_s| rows and bs w columns;
     6. amap: the position in the panels of every entry of A on or below the permuted diagonal.
   Numeric phase (right-looking over supernodes): scatter A into the panels; for each supernode s:
     a. the dense factorization of its panel (diagonal block and the rows below it), left-looking by block
        columns: the product of the block column's rows with the previous columns (vector kernels of 8 or
        4 rows by the bs columns, for bs <= 4), then an unblocked step on its bs columns;
     b. the update of the ancestors, the standard supernodal one: the m rows below the panel, B (m x W,
        W = bs w), packed by groups of 8 rows; for each target supernode t (a run of R_s) its columns of
        U = B S B^T (S the pivot signs) from the diagonal down, four columns at a time: computed into a
        small contiguous temporary by an 8 x 4 register-blocked micro-kernel (GCC vector extensions; those
        columns of B S packed by quadruples), then subtracted from t's panel through the relative
        positions of R_s's rows in t's row list.
     On x86-64 with AVX-512 (checked at run time) a second copy of the numeric phase, compiled for
     x86-64-v4, packs B by groups of 16 rows and runs the micro-kernel on 16 x 4 tiles of 8-wide vectors;
     elsewhere HYLC_TARGET_CLONES (AVX2 or the baseline).
   Every entry of a product is summed over k from zero in increasing order and then subtracted from its
   target (no contraction into FMA), the order of the former per-block loops, so the factor is the same to
   the last bit on every path and as before 2026-11-27. */
#include <hylc/chol.h>
#include <hylc/private/clones.h>
#include <string.h>

struct _n_HylcChol {
  HylcCholOrdering ordering;
  Mat              A; /* the matrix of the symbolic phase (referenced), and its nonzero state then */
  PetscObjectState nzstate;
  PetscInt         n, bs, nb, nnzA;
  PetscInt        *perm, *iperm; /* blocks: new -> old, old -> new */
  PetscInt         nsup, *sfirst, *snode, *rptr, *rows;
  PetscCount      *voff;       /* start of each panel in L */
  PetscInt        *amap;       /* per entry of A: index into L, or -1 (above the diagonal) */
  PetscReal       *L, *y, *tw; /* panels; solve work (ycap entries each) */
  PetscInt         ycap;
  PetscReal       *sg, *dA; /* pivot signs, |diagonal of A| (permuted) */
  PetscInt         nneg;    /* negative pivots of the last factorization */
  PetscBool        indefinite;
  PetscBool        relax; /* relaxed supernodes */
  PetscInt        *relpos;
  PetscBool        factored;
  HylcCholInfo     info;
};

PetscClassId  HYLC_CHOL_CLASSID;
PetscLogEvent HYLC_CholSymbolic, HYLC_CholNumeric, HYLC_CholSolve;

static PetscBool HylcCholPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcCholFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcCholPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholInitializePackage - Registers the class id HylcChol and its log events (CHOL_Symbolic,
  CHOL_Numeric, CHOL_Solve), the ordering METIS_NodeND uses (HylcSysInitializePackage()) and the solver
  type MATSOLVERHYLC (HylcCholRegisterSolverType()). Called by HylcCholCreate() and by
  HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage(), HylcCholRegisterSolverType()
@*/
PetscErrorCode HylcCholInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcCholPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcCholPackageInitialized = PETSC_TRUE;
  PetscCall(HylcSysInitializePackage());
  PetscCall(PetscClassIdRegister("HylcChol", &HYLC_CHOL_CLASSID));
  PetscCall(PetscLogEventRegister("CHOL_Symbolic", HYLC_CHOL_CLASSID, &HYLC_CholSymbolic));
  PetscCall(PetscLogEventRegister("CHOL_Numeric", HYLC_CHOL_CLASSID, &HYLC_CholNumeric));
  PetscCall(PetscLogEventRegister("CHOL_Solve", HYLC_CHOL_CLASSID, &HYLC_CholSolve));
  PetscCall(HylcCholRegisterSolverType());
  PetscCall(PetscRegisterFinalize(HylcCholFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholCreate - Creates a supernodal Cholesky factorization (sequential; a plain handle, not a PETSc
  object): METIS ordering, no relaxed supernodes, indefinite matrices refused.

  Not collective

  Output Parameter:
. chol - the factorization

  Level: developer

.seealso: HylcCholFactor(), HylcCholDestroy(), MATSOLVERHYLC
@*/
PetscErrorCode HylcCholCreate(HylcChol *chol)
{
  PetscFunctionBegin;
  PetscCall(HylcCholInitializePackage());
  PetscCall(PetscNew(chol));
  (*chol)->ordering = HYLC_CHOL_ORDERING_METIS;
  (*chol)->relax    = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CholReset(HylcChol C)
{
  PetscFunctionBegin;
  PetscCall(PetscFree2(C->perm, C->iperm));
  PetscCall(PetscFree4(C->sfirst, C->snode, C->rptr, C->voff));
  PetscCall(PetscFree(C->rows));
  PetscCall(PetscFree(C->amap));
  PetscCall(PetscFree4(C->L, C->relpos, C->sg, C->dA));
  PetscCall(MatDestroy(&C->A));
  C->factored = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholDestroy - Frees the factorization; accepts NULL.

  Not collective

  Input Parameter:
. chol - the factorization

  Level: developer

.seealso: HylcCholCreate()
@*/
PetscErrorCode HylcCholDestroy(HylcChol *chol)
{
  PetscFunctionBegin;
  if (!*chol) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CholReset(*chol));
  PetscCall(PetscFree2((*chol)->y, (*chol)->tw));
  PetscCall(PetscFree(*chol));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholSetOrdering - Sets the fill-reducing ordering (a change drops the symbolic phase).

  Not collective

  Input Parameters:
+ C   - the factorization
- ord - HYLC_CHOL_ORDERING_METIS (METIS_NodeND of the block graph, the default) or HYLC_CHOL_ORDERING_NATURAL

  Level: developer

.seealso: HylcCholFactorSymbolic()
@*/
PetscErrorCode HylcCholSetOrdering(HylcChol C, HylcCholOrdering ord)
{
  PetscFunctionBegin;
  if (ord != C->ordering) PetscCall(CholReset(C));
  C->ordering = ord;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* appends v to a growing array */
static PetscErrorCode Push(PetscInt **a, PetscInt *n, PetscInt *cap, PetscInt v)
{
  PetscFunctionBegin;
  if (*n == *cap) {
    PetscInt *b;
    *cap = *cap ? 2 * *cap : 1024;
    PetscCall(PetscMalloc1(*cap, &b));
    PetscCall(PetscArraycpy(b, *a, *n));
    PetscCall(PetscFree(*a));
    *a = b;
  }
  (*a)[(*n)++] = v;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CholSymbolic(HylcChol C, Mat A, PetscInt bs)
{
  PetscInt        n, nb, *xadj, *adj, *mark, *parent, *anc, *head, *next, *cstart, *ccnt, *cs = NULL, ncs = 0, capcs = 0;
  const PetscInt *ia, *ja;
  PetscBool       done;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_CholSymbolic, 0, 0, 0, 0));
  PetscCall(CholReset(C));
  PetscCall(MatGetRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_SUP, "HylcChol: cannot get the row structure of the matrix");
  PetscCheck(bs >= 1 && n % bs == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "HylcChol: block size %" PetscInt_FMT " does not divide the order %" PetscInt_FMT, bs, n);
  nb   = n / bs;
  C->n = n, C->bs = bs, C->nb = nb, C->nnzA = ia[n];

  /* 1. the block graph (without self loops) and its ordering */
  PetscCall(PetscMalloc3(nb + 1, &xadj, ia[n] + 1, &adj, nb, &mark));
  for (PetscInt BI = 0; BI < nb; BI++) mark[BI] = -1;
  xadj[0] = 0;
  for (PetscInt BI = 0; BI < nb; BI++) {
    PetscInt k = xadj[BI];
    for (PetscInt i = bs * BI; i < bs * (BI + 1); i++)
      for (PetscInt t = ia[i]; t < ia[i + 1]; t++) {
        const PetscInt BJ = ja[t] / bs;
        if (BJ != BI && mark[BJ] != BI) {
          mark[BJ] = BI;
          adj[k++] = BJ;
        }
      }
    xadj[BI + 1] = k;
  }
  PetscCall(PetscMalloc2(nb, &C->perm, nb, &C->iperm));
  if (C->ordering == HYLC_CHOL_ORDERING_METIS)
    PetscCall(HylcMetisNodeND(nb, xadj, adj, C->perm));
  else
    for (PetscInt BI = 0; BI < nb; BI++) C->perm[BI] = BI;
  for (PetscInt k = 0; k < nb; k++) C->iperm[C->perm[k]] = k;

  /* 2. elimination tree, in the new numbering */
  PetscCall(PetscMalloc6(nb, &parent, nb, &anc, nb, &head, nb, &next, nb + 1, &cstart, nb, &ccnt));
  for (PetscInt k = 0; k < nb; k++) {
    const PetscInt old = C->perm[k];
    parent[k] = anc[k] = -1;
    for (PetscInt t = xadj[old]; t < xadj[old + 1]; t++) {
      PetscInt i = C->iperm[adj[t]];
      while (i != -1 && i < k) {
        const PetscInt inext = anc[i];
        anc[i]               = k;
        if (inext == -1) parent[i] = k;
        i = inext;
      }
    }
  }
  for (PetscInt k = 0; k < nb; k++) head[k] = -1;
  for (PetscInt k = nb - 1; k >= 0; k--)
    if (parent[k] >= 0) {
      next[k]         = head[parent[k]];
      head[parent[k]] = k;
    }

  /* 3. column structures (rows below the diagonal, sorted) */
  for (PetscInt k = 0; k < nb; k++) mark[k] = -1;
  for (PetscInt j = 0; j < nb; j++) {
    const PetscInt old = C->perm[j];
    cstart[j]          = ncs;
    for (PetscInt t = xadj[old]; t < xadj[old + 1]; t++) {
      const PetscInt i = C->iperm[adj[t]];
      if (i > j && mark[i] != j) {
        mark[i] = j;
        PetscCall(Push(&cs, &ncs, &capcs, i));
      }
    }
    for (PetscInt c = head[j]; c != -1; c = next[c])
      for (PetscInt t = cstart[c]; t < cstart[c] + ccnt[c]; t++) {
        const PetscInt i = cs[t];
        if (i > j && mark[i] != j) {
          mark[i] = j;
          PetscCall(Push(&cs, &ncs, &capcs, i));
        }
      }
    ccnt[j] = ncs - cstart[j];
    PetscCall(PetscSortInt(ccnt[j], cs + cstart[j]));
  }

  /* 4. fundamental supernodes */
  PetscCall(PetscMalloc4(nb + 1, &C->sfirst, nb, &C->snode, nb + 1, &C->rptr, nb + 1, &C->voff));
  C->nsup = 0;
  for (PetscInt j = 0; j < nb; j++) {
    const PetscBool join = (PetscBool)(j > 0 && parent[j - 1] == j && head[j] == j - 1 && next[j - 1] == -1 && ccnt[j - 1] == ccnt[j] + 1);
    if (!join) C->sfirst[C->nsup++] = j;
    C->snode[j] = C->nsup - 1;
  }
  C->sfirst[C->nsup] = nb;
  /* relaxed supernodes: a supernode joins the next one when the next one holds the parent of its last
     column, if the explicit zeros this adds stay few (the rule of CHOLMOD's defaults, in scalar columns:
     up to 16 columns with < 80 % zeros, up to 48 with < 10 %, any with < 5 %) */
  if (C->relax) {
    PetscInt       ns   = 0;
    PetscLogDouble real = 0; /* true nonzero blocks of the current group (lower triangle) */
    for (PetscInt s = 0; s < C->nsup; s++) {
      const PetscInt f = C->sfirst[s], l = C->sfirst[s + 1] - 1;
      PetscLogDouble rs = 0;
      for (PetscInt j = f; j <= l; j++) rs += 1 + ccnt[j];
      if (ns > 0) {
        const PetscInt gf = C->sfirst[ns - 1], gl = f - 1; /* the open group: columns [gf, gl] */
        if (parent[gl] == f) {
          const PetscInt       w      = l - gf + 1;
          const PetscLogDouble stored = 0.5 * w * (w + 1) + (PetscLogDouble)w * ccnt[l], z = (stored - real - rs) / stored;
          const PetscInt       cols = bs * w;
          if ((cols <= 16 && z < 0.8) || (cols <= 48 && z < 0.1) || z < 0.05) {
            real += rs;
            continue;
          }
        }
      }
      C->sfirst[ns++] = f;
      real            = rs;
    }
    C->nsup            = ns;
    C->sfirst[C->nsup] = nb;
    for (PetscInt t = 0; t < C->nsup; t++)
      for (PetscInt j = C->sfirst[t]; j < C->sfirst[t + 1]; j++) C->snode[j] = t;
  }

  /* 5. row lists and panels */
  C->rptr[0]    = 0;
  C->voff[0]    = 0;
  C->info.flops = 0;
  for (PetscInt s = 0; s < C->nsup; s++) {
    const PetscInt f = C->sfirst[s], w = C->sfirst[s + 1] - f, nr = w + ccnt[f + w - 1];
    C->rptr[s + 1] = C->rptr[s] + nr;
    C->voff[s + 1] = C->voff[s] + (PetscCount)(bs * nr) * (bs * w);
    /* flops: the panel factorization, then the updates (2 bs^2 W per block pair r >= c below the panel) */
    const PetscInt W = bs * w, ld = bs * nr, nbelow = nr - w;
    for (PetscInt k = 0; k < W; k++) C->info.flops += 1 + (ld - k - 1) + (PetscLogDouble)(W - k - 1) * (2 * ld - W - k);
    C->info.flops += (2.0 * bs * bs * W + bs * bs) * nbelow * (nbelow + 1) / 2;
  }
  PetscCall(PetscMalloc1(C->rptr[C->nsup] + 1, &C->rows));
  for (PetscInt s = 0; s < C->nsup; s++) {
    const PetscInt f = C->sfirst[s], w = C->sfirst[s + 1] - f;
    for (PetscInt j = 0; j < w; j++) C->rows[C->rptr[s] + j] = f + j;
    PetscCall(PetscArraycpy(C->rows + C->rptr[s] + w, cs + cstart[f + w - 1], ccnt[f + w - 1]));
  }

  /* 6. where each entry of A goes */
  PetscCall(PetscMalloc1(ia[n] + 1, &C->amap));
  for (PetscInt i = 0; i < n; i++) {
    const PetscInt BI = C->iperm[i / bs], ii = i % bs;
    PetscInt       lastBJ = -1, pos = -1; /* the columns of a block are adjacent in the row: one search per block */
    for (PetscInt t = ia[i]; t < ia[i + 1]; t++) {
      const PetscInt BJ = C->iperm[ja[t] / bs], jj = ja[t] % bs;
      C->amap[t] = -1;
      if (BI < BJ || (BI == BJ && ii < jj)) continue;
      const PetscInt s = C->snode[BJ], nr = C->rptr[s + 1] - C->rptr[s];
      if (BJ != lastBJ) {
        PetscCall(PetscFindInt(BI, nr, C->rows + C->rptr[s], &pos));
        lastBJ = BJ;
      }
      PetscCheck(pos >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "HylcChol: entry (%" PetscInt_FMT ", %" PetscInt_FMT ") outside the symbolic structure", i, ja[t]);
      C->amap[t] = (PetscInt)(C->voff[s] + (PetscCount)(bs * (BJ - C->sfirst[s]) + jj) * (bs * nr) + bs * pos + ii);
    }
  }
  PetscCall(MatRestoreRowIJ(A, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  PetscCall(PetscMalloc4(C->voff[C->nsup], &C->L, nb, &C->relpos, C->n, &C->sg, C->n, &C->dA));
  C->info.n      = C->n;
  C->info.bs     = bs;
  C->info.nsuper = C->nsup;
  C->info.nnzL   = C->voff[C->nsup];
  C->info.nnzA   = C->nnzA;
  C->info.nsymbolic++;
  PetscCall(PetscFree(cs));
  PetscCall(PetscFree6(parent, anc, head, next, cstart, ccnt));
  PetscCall(PetscFree3(xadj, adj, mark));
  PetscCall(PetscObjectReference((PetscObject)A));
  C->A = A;
  PetscCall(MatGetNonzeroState(A, &C->nzstate));
  PetscCall(PetscLogEventEnd(HYLC_CholSymbolic, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Dense kernels of the numeric phase. Every entry of a product is summed over k in increasing order from
   zero and then subtracted from its target (one multiply and one add per term, no contraction), so the
   vector code and the scalar fallback give the same values. */
#if defined(__GNUC__)
/* four doubles as one value (GCC and Clang vector extensions): an AVX register in the x86-64-v3 clone, two
   SSE2 registers otherwise; loads and stores through memcpy, so no alignment is assumed */
typedef PetscReal V4 __attribute__((vector_size(4 * sizeof(PetscReal))));
#  define V4LOAD(v, p)  memcpy(&(v), (p), sizeof(V4))
#  define V4STORE(p, v) memcpy((p), &(v), sizeof(V4))
#  define V4BCAST(s) \
    (V4) { (s), (s), (s), (s) }
#  define V4SUBFROM(p, c) \
    do {                  \
      V4 t_;              \
      V4LOAD(t_, p);      \
      t_ -= (c);          \
      V4STORE(p, t_);     \
    } while (0)

/* the micro-kernel of the update: c (8 x 4, column-major with leading dimension ldc) = sum_k a_k b_k^T over
   K terms, a and b packed (a_k = a[8k + 0..7], b_k = b[4k + 0..3]) */
static inline __attribute__((always_inline)) void Kern8x4(PetscInt K, const PetscReal *a, const PetscReal *b, PetscReal *c, PetscInt ldc)
{
  V4 c00 = {0}, c01 = {0}, c02 = {0}, c03 = {0}, c10 = {0}, c11 = {0}, c12 = {0}, c13 = {0};
  for (PetscInt k = 0; k < K; k++, a += 8, b += 4) {
    V4       a0, a1;
    const V4 b0 = V4BCAST(b[0]), b1 = V4BCAST(b[1]), b2 = V4BCAST(b[2]), b3 = V4BCAST(b[3]);
    V4LOAD(a0, a);
    V4LOAD(a1, a + 4);
    c00 += a0 * b0, c01 += a0 * b1, c02 += a0 * b2, c03 += a0 * b3;
    c10 += a1 * b0, c11 += a1 * b1, c12 += a1 * b2, c13 += a1 * b3;
  }
  V4STORE(c, c00), V4STORE(c + 4, c10);
  V4STORE(c + ldc, c01), V4STORE(c + ldc + 4, c11);
  V4STORE(c + 2 * ldc, c02), V4STORE(c + 2 * ldc + 4, c12);
  V4STORE(c + 3 * ldc, c03), V4STORE(c + 3 * ldc + 4, c13);
}

#  if !defined(__clang__) && defined(__x86_64__)
/* with AVX-512 (a separate copy of the numeric phase, chosen at run time): eight doubles as one value,
   and the micro-kernel on 16 x 4 tiles (a packed by groups of 16 rows), the same operations per entry */
#    define HYLC_CHOL_WIDE 1
typedef PetscReal V8 __attribute__((vector_size(8 * sizeof(PetscReal))));
#    define V8BCAST(s) \
      (V8) { (s), (s), (s), (s), (s), (s), (s), (s) }
static inline __attribute__((always_inline)) void Kern16x4(PetscInt K, const PetscReal *a, const PetscReal *b, PetscReal *c, PetscInt ldc)
{
  V8 c00 = {0}, c01 = {0}, c02 = {0}, c03 = {0}, c10 = {0}, c11 = {0}, c12 = {0}, c13 = {0};
  for (PetscInt k = 0; k < K; k++, a += 16, b += 4) {
    V8       a0, a1;
    const V8 b0 = V8BCAST(b[0]), b1 = V8BCAST(b[1]), b2 = V8BCAST(b[2]), b3 = V8BCAST(b[3]);
    memcpy(&a0, a, sizeof(V8));
    memcpy(&a1, a + 8, sizeof(V8));
    c00 += a0 * b0, c01 += a0 * b1, c02 += a0 * b2, c03 += a0 * b3;
    c10 += a1 * b0, c11 += a1 * b1, c12 += a1 * b2, c13 += a1 * b3;
  }
  memcpy(c, &c00, sizeof(V8)), memcpy(c + 8, &c10, sizeof(V8));
  memcpy(c + ldc, &c01, sizeof(V8)), memcpy(c + ldc + 8, &c11, sizeof(V8));
  memcpy(c + 2 * ldc, &c02, sizeof(V8)), memcpy(c + 2 * ldc + 8, &c12, sizeof(V8));
  memcpy(c + 3 * ldc, &c03, sizeof(V8)), memcpy(c + 3 * ldc + 8, &c13, sizeof(V8));
}
#  endif

/* the panel's block column update: t[i + j ld] -= sum_k a[i + k ld] s_k b[j + k ld] for the nv (1 or 2) row
   quadruples i < 4 nv and the NC (1 to 4, a constant) columns j, over K columns k of the panel (s_k = sg[k],
   or 1 without sg) */
static inline __attribute__((always_inline)) void PanelKern(const PetscInt NC, const PetscInt nv, PetscInt K, PetscInt ld, const PetscReal *a, const PetscReal *b, const PetscReal *sg, PetscReal *t)
{
  V4 c00 = {0}, c01 = {0}, c02 = {0}, c03 = {0}, c10 = {0}, c11 = {0}, c12 = {0}, c13 = {0};
  for (PetscInt k = 0; k < K; k++, a += ld, b += ld) {
    const PetscReal s = sg ? sg[k] : 1.0;
    V4              a0, a1, bb;
    V4LOAD(a0, a);
    if (nv == 2) V4LOAD(a1, a + 4);
    bb = V4BCAST(s * b[0]), c00 += a0 * bb;
    if (nv == 2) c10 += a1 * bb;
    if (NC > 1) {
      bb = V4BCAST(s * b[1]), c01 += a0 * bb;
      if (nv == 2) c11 += a1 * bb;
    }
    if (NC > 2) {
      bb = V4BCAST(s * b[2]), c02 += a0 * bb;
      if (nv == 2) c12 += a1 * bb;
    }
    if (NC > 3) {
      bb = V4BCAST(s * b[3]), c03 += a0 * bb;
      if (nv == 2) c13 += a1 * bb;
    }
  }
  V4SUBFROM(t, c00);
  if (nv == 2) V4SUBFROM(t + 4, c10);
  if (NC > 1) {
    V4SUBFROM(t + ld, c01);
    if (nv == 2) V4SUBFROM(t + ld + 4, c11);
  }
  if (NC > 2) {
    V4SUBFROM(t + 2 * ld, c02);
    if (nv == 2) V4SUBFROM(t + 2 * ld + 4, c12);
  }
  if (NC > 3) {
    V4SUBFROM(t + 3 * ld, c03);
    if (nv == 2) V4SUBFROM(t + 3 * ld + 4, c13);
  }
}
#else
static inline void Kern8x4(PetscInt K, const PetscReal *a, const PetscReal *b, PetscReal *c, PetscInt ldc)
{
  for (PetscInt j = 0; j < 4; j++)
    for (PetscInt i = 0; i < 8; i++) c[j * ldc + i] = 0;
  for (PetscInt k = 0; k < K; k++)
    for (PetscInt j = 0; j < 4; j++)
      for (PetscInt i = 0; i < 8; i++) c[j * ldc + i] += a[8 * k + i] * b[4 * k + j];
}

static inline void PanelKern(const PetscInt NC, const PetscInt nv, PetscInt K, PetscInt ld, const PetscReal *a, const PetscReal *b, const PetscReal *sg, PetscReal *t)
{
  PetscReal c[4][8] = {{0}};
  for (PetscInt k = 0; k < K; k++) {
    const PetscReal s = sg ? sg[k] : 1.0;
    for (PetscInt j = 0; j < NC; j++)
      for (PetscInt i = 0; i < 4 * nv; i++) c[j][i] += a[k * ld + i] * (s * b[k * ld + j]);
  }
  for (PetscInt j = 0; j < NC; j++)
    for (PetscInt i = 0; i < 4 * nv; i++) t[j * ld + i] -= c[j][i];
}
#endif

/* the same for nrow < 4 rows and NC <= 4 columns, one pass over the K columns */
static inline void PanelKernRem(const PetscInt NC, PetscInt nrow, PetscInt K, PetscInt ld, const PetscReal *a, const PetscReal *b, const PetscReal *sg, PetscReal *t)
{
  PetscReal c[4][4] = {{0}};
  for (PetscInt k = 0; k < K; k++, a += ld, b += ld) {
    const PetscReal s = sg ? sg[k] : 1.0;
    for (PetscInt j = 0; j < NC; j++) {
      const PetscReal bj = s * b[j];
      for (PetscInt i = 0; i < nrow; i++) c[j][i] += a[i] * bj;
    }
  }
  for (PetscInt j = 0; j < NC; j++)
    for (PetscInt i = 0; i < nrow; i++) t[j * ld + i] -= c[j][i];
}

/* any number nc of columns and nrow of rows */
static inline void PanelKernScalar(PetscInt nc, PetscInt nrow, PetscInt K, PetscInt ld, const PetscReal *a, const PetscReal *b, const PetscReal *sg, PetscReal *t)
{
  for (PetscInt j = 0; j < nc; j++)
    for (PetscInt i = 0; i < nrow; i++) {
      PetscReal c = 0;
      for (PetscInt k = 0; k < K; k++) c += a[k * ld + i] * ((sg ? sg[k] : 1.0) * b[k * ld + j]);
      t[j * ld + i] -= c;
    }
}

/* the left-looking update of the panel's block column: its NC columns t at the nrow rows from a (the same
   rows of the K previous columns; b: the block column's own rows there) */
static inline __attribute__((always_inline)) void PanelUpdate(const PetscInt NC, PetscInt nrow, PetscInt K, PetscInt ld, const PetscReal *a, const PetscReal *b, const PetscReal *sg, PetscReal *t)
{
  PetscInt i = 0;
  if (sg) {
    for (; i + 8 <= nrow; i += 8) PanelKern(NC, 2, K, ld, a + i, b, sg, t + i);
    if (i + 4 <= nrow) PanelKern(NC, 1, K, ld, a + i, b, sg, t + i), i += 4;
  } else {
    for (; i + 8 <= nrow; i += 8) PanelKern(NC, 2, K, ld, a + i, b, NULL, t + i);
    if (i + 4 <= nrow) PanelKern(NC, 1, K, ld, a + i, b, NULL, t + i), i += 4;
  }
  if (i < nrow) PanelKernRem(NC, nrow - i, K, ld, a + i, b, sg, t + i);
}

/* packs the m x W block a (column-major, leading dimension ld) by groups of G (16, 8 or 4) rows: p[G (W o + k)
   + i] = s_k a[G o + i + k ld] (s_k = sg[k], or 1 without sg), zero below row m */
static void Pack(PetscInt G, PetscInt m, PetscInt W, PetscInt ld, const PetscReal *a, const PetscReal *sg, PetscReal *p)
{
  for (PetscInt o = 0; G * o < m; o++) {
    const PetscInt nr = m - G * o < G ? m - G * o : G;
    for (PetscInt k = 0; k < W; k++, p += G) {
      const PetscReal *ak = a + G * o + k * ld;
      const PetscReal  s  = sg ? sg[k] : 1.0;
      PetscInt         i  = 0;
      for (; i < nr; i++) p[i] = s * ak[i];
      for (; i < G; i++) p[i] = 0;
    }
  }
}

/* The signed factorization A = L S L^T, S = diag(+-1) (the sign of each pivot): L_kk = sqrt(|d_k|). With
   positive pivots only it is the Cholesky factorization. A pivot that is zero or tiny against the diagonal
   of A (|d_k| <= 1e-14 |A_kk|), not finite, or negative when indefinite matrices are refused, stops it. */

static inline __attribute__((always_inline)) PetscErrorCode CholNumericBody(HylcChol C, Mat A, PetscBool *ok, const PetscInt KMR)
{
  const PetscInt     bs = C->bs;
  const PetscScalar *av;
  PetscReal         *sg = C->sg, *dA = C->dA, *Ap, *Bp, *U;
  PetscInt          *off, mmax       = 0;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_CholNumeric, 0, 0, 0, 0));
  *ok         = PETSC_TRUE;
  C->factored = PETSC_FALSE;
  C->nneg     = 0;
  PetscCall(PetscArrayzero(C->L, C->voff[C->nsup]));
  PetscCall(MatSeqAIJGetArrayRead(A, &av));
  for (PetscInt t = 0; t < C->nnzA; t++)
    if (C->amap[t] >= 0) C->L[C->amap[t]] = PetscRealPart(av[t]);
  PetscCall(MatSeqAIJRestoreArrayRead(A, &av));
  for (PetscInt s = 0; s < C->nsup; s++) {
    const PetscInt ld = bs * (C->rptr[s + 1] - C->rptr[s]), c0 = bs * C->sfirst[s], W = bs * (C->sfirst[s + 1] - C->sfirst[s]);
    for (PetscInt k = 0; k < W; k++) dA[c0 + k] = PetscAbsReal(C->L[C->voff[s] + k * ld + k]);
    mmax = PetscMax(mmax, ld - W);
  }
  {
    /* work: the packed rows below a panel, the packed (signed) columns of one target, four columns of an
       update U (rows padded to a multiple of KMR, 8 or 16) and the target offsets of the rows */
    const PetscInt mp   = KMR * ((mmax + KMR - 1) / KMR);
    PetscCount     wmax = 0;
    for (PetscInt s = 0; s < C->nsup; s++) {
      const PetscInt nr = C->rptr[s + 1] - C->rptr[s], W = bs * (C->sfirst[s + 1] - C->sfirst[s]);
      wmax = PetscMax(wmax, (PetscCount)W * KMR * ((bs * (nr - (C->sfirst[s + 1] - C->sfirst[s])) + KMR - 1) / KMR));
    }
    PetscCall(PetscMalloc4(wmax + 1, &Ap, wmax + 8 * mmax + 1, &Bp, (PetscCount)4 * mp + 1, &U, C->nb + 1, &off));
  }
  for (PetscInt s = 0; s < C->nsup && *ok; s++) {
    const PetscInt  f = C->sfirst[s], w = C->sfirst[s + 1] - f, nr = C->rptr[s + 1] - C->rptr[s], ld = bs * nr, W = bs * w, c0 = bs * f;
    const PetscInt  m = ld - W, mp = KMR * ((m + KMR - 1) / KMR);
    const PetscInt *R   = C->rows + C->rptr[s];
    PetscReal      *P   = C->L + C->voff[s];
    PetscBool       neg = PETSC_FALSE;
    /* the panel: dense factorization of the diagonal block and triangular solve of the rows below,
       left-looking by block columns (the product of the previous columns, then an unblocked step) */
    for (PetscInt jb = 0; jb < w && *ok; jb++) {
      PetscReal       *cjb  = P + (PetscCount)bs * jb * ld;
      const PetscInt   nrow = ld - bs * jb, K = bs * jb;
      const PetscReal *sk = neg ? sg + c0 : NULL;
      if (jb) {
        if (bs == 3)
          PanelUpdate(3, nrow, K, ld, P + bs * jb, P + bs * jb, sk, cjb + bs * jb);
        else if (bs == 4)
          PanelUpdate(4, nrow, K, ld, P + bs * jb, P + bs * jb, sk, cjb + bs * jb);
        else if (bs == 2)
          PanelUpdate(2, nrow, K, ld, P + bs * jb, P + bs * jb, sk, cjb + bs * jb);
        else if (bs == 1)
          PanelUpdate(1, nrow, K, ld, P + bs * jb, P + bs * jb, sk, cjb + bs * jb);
        else
          PanelKernScalar(bs, nrow, K, ld, P + bs * jb, P + bs * jb, sk, cjb + bs * jb);
      }
      for (PetscInt k = bs * jb; k < bs * (jb + 1); k++) {
        PetscReal *ck = P + k * ld, d = ck[k];
        if (!PetscIsNormalReal(d) || PetscAbsReal(d) <= 1e-14 * dA[c0 + k] || (d < 0 && !C->indefinite)) {
          *ok = PETSC_FALSE;
          break;
        }
        sg[c0 + k] = d < 0 ? -1.0 : 1.0;
        if (d < 0) neg = PETSC_TRUE, C->nneg++;
        ck[k]               = PetscSqrtReal(PetscAbsReal(d));
        const PetscReal inv = sg[c0 + k] / ck[k];
        for (PetscInt i = k + 1; i < ld; i++) ck[i] *= inv;
        for (PetscInt j = k + 1; j < bs * (jb + 1); j++) {
          PetscReal      *cj = P + j * ld;
          const PetscReal l  = ck[j] * sg[c0 + k];
          for (PetscInt i = j; i < ld; i++) cj[i] -= ck[i] * l;
        }
      }
    }
    if (!*ok) break;
    if (!m) continue;
    /* the update of the ancestors: the rows below the panel, B (m x W), packed by groups of KMR rows; then for each
       target supernode (a run of R, block columns [p, q1)) the columns [bs (p - w), bs (q1 - w)) of
       U = B S B^T (those columns of B packed by quadruples, with the pivot signs), four at a time: from the
       group of the first one's row down by KMR x 4 tiles into the work U (cache-resident), then scattered
       into the target's panel at the relative positions of R_s's rows in its row list */
    Pack(KMR, m, W, ld, P + W, NULL, Ap);
    for (PetscInt p = w; p < nr;) {
      const PetscInt  t = C->snode[R[p]], ft = C->sfirst[t], lt = C->sfirst[t + 1], nrt = C->rptr[t + 1] - C->rptr[t], ldt = bs * nrt;
      const PetscInt *Rt = C->rows + C->rptr[t];
      PetscReal      *Pt = C->L + C->voff[t];
      PetscInt        q1 = p;
      while (q1 < nr && R[q1] < lt) q1++;
      for (PetscInt i = 0; i < nrt; i++) C->relpos[Rt[i]] = i;
      for (PetscInt r = p; r < nr; r++) off[r] = bs * C->relpos[R[r]];
      const PetscInt jbase = bs * (p - w), jend = bs * (q1 - w);
      Pack(4, jend - jbase, W, ld, P + W + jbase, neg ? sg + c0 : NULL, Bp);
      for (PetscInt j0 = jbase; j0 < jend; j0 += 4) {
        const PetscReal *b = Bp + (PetscCount)W * (j0 - jbase);
#if defined(HYLC_CHOL_WIDE)
        if (KMR == 16)
          for (PetscInt i0 = 16 * (j0 / 16); i0 < mp; i0 += 16) Kern16x4(W, Ap + (PetscCount)W * i0, b, U + i0, mp);
        else
#endif
          for (PetscInt i0 = 8 * (j0 / 8); i0 < mp; i0 += 8) Kern8x4(W, Ap + (PetscCount)W * i0, b, U + i0, mp);
        for (PetscInt c = j0; c < j0 + 4 && c < jend; c++) {
          const PetscInt   q = w + c / bs, jj = c % bs;
          const PetscReal *u    = U + (PetscCount)(c - j0) * mp - bs * w;
          PetscReal       *tcol = Pt + (PetscCount)(bs * (R[q] - ft) + jj) * ldt;
          if (bs == 3)
            for (PetscInt r = q; r < nr; r++) {
              PetscReal       *d = tcol + off[r];
              const PetscReal *e = u + 3 * r;
              d[0] -= e[0], d[1] -= e[1], d[2] -= e[2];
            }
          else
            for (PetscInt r = q; r < nr; r++)
              for (PetscInt i = 0; i < bs; i++) tcol[off[r] + i] -= u[bs * r + i];
        }
      }
      p = q1;
    }
  }
  PetscCall(PetscFree4(Ap, Bp, U, off));
  C->factored = *ok;
  C->info.nnumeric++;
  PetscCall(PetscLogFlops(C->info.flops));
  PetscCall(PetscLogEventEnd(HYLC_CholNumeric, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

HYLC_TARGET_CLONES static PetscErrorCode CholNumericNarrow(HylcChol C, Mat A, PetscBool *ok) { return CholNumericBody(C, A, ok, 8); }

#if defined(HYLC_CHOL_WIDE)
__attribute__((target("arch=x86-64-v4"))) static PetscErrorCode CholNumericWide(HylcChol C, Mat A, PetscBool *ok) { return CholNumericBody(C, A, ok, 16); }
#endif

/* the numeric phase: with AVX-512 when the processor has it (HYLC_CHOL_WIDE), else by HYLC_TARGET_CLONES */
static PetscErrorCode CholNumeric(HylcChol C, Mat A, PetscBool *ok)
{
#if defined(HYLC_CHOL_WIDE)
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl")) return CholNumericWide(C, A, ok);
#endif
  return CholNumericNarrow(C, A, ok);
}

static PetscErrorCode CheckSeqAIJ(Mat A)
{
  PetscBool aij;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATSEQAIJ, &aij));
  PetscCheck(aij, PETSC_COMM_SELF, PETSC_ERR_SUP, "HylcChol: the matrix must be MATSEQAIJ");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholFactorSymbolic - The symbolic phase alone (ordering, elimination tree, supernodes);
  HylcCholFactor() then runs only the numeric phase while the nonzero pattern of A stays the same.

  Not collective

  Input Parameters:
+ C  - the factorization
. A  - a MATSEQAIJ matrix
- bs - the block size

  Level: developer

.seealso: HylcCholFactor()
@*/
PetscErrorCode HylcCholFactorSymbolic(HylcChol C, Mat A, PetscInt bs)
{
  PetscFunctionBegin;
  PetscCall(CheckSeqAIJ(A));
  PetscCall(CholSymbolic(C, A, bs));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholFactor - Factors A as A = P^T L S L^T P, S = diag(+-1) the signs of the pivots (the Cholesky
  factorization when A is positive definite); the symbolic phase is run again only when A, its nonzero
  pattern or bs changed.

  Not collective

  Input Parameters:
+ C  - the factorization
. A  - a MATSEQAIJ matrix, both triangles stored
- bs - the block size, which must divide the order of A

  Output Parameter:
. ok - PETSC_FALSE, and the factor unusable, when a pivot is zero or tiny (|d| <= 1e-14 |A_kk|), not
       finite, or negative while indefinite matrices are refused

  Level: developer

.seealso: HylcCholFactorSymbolic(), HylcCholSolve(), HylcCholSetIndefinite()
@*/
PetscErrorCode HylcCholFactor(HylcChol C, Mat A, PetscInt bs, PetscBool *ok)
{
  PetscObjectState st;

  PetscFunctionBegin;
  PetscCall(CheckSeqAIJ(A));
  PetscCall(MatGetNonzeroState(A, &st));
  if (A != C->A || st != C->nzstate || bs != C->bs) PetscCall(CholSymbolic(C, A, bs));
  PetscCall(CholNumeric(C, A, ok));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholGetInertia - The inertia of the last factored matrix (Sylvester's law: the signs of the pivots).

  Not collective

  Input Parameter:
. C - the factorization, after a successful HylcCholFactor()

  Output Parameters:
+ nneg - the negative eigenvalues (may be NULL)
- npos - the positive eigenvalues (may be NULL)

  Level: developer

.seealso: HylcCholSetIndefinite()
@*/
PetscErrorCode HylcCholGetInertia(HylcChol C, PetscInt *nneg, PetscInt *npos)
{
  PetscFunctionBegin;
  PetscCheck(C->factored, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "HylcCholGetInertia: no successful factorization");
  if (nneg) *nneg = C->nneg;
  if (npos) *npos = C->n - C->nneg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholSetRelaxed - Sets whether supernodes are merged along the elimination tree at the price of a few
  explicit zeros (a change drops the symbolic phase). Default false.

  Not collective

  Input Parameters:
+ C     - the factorization
- relax - PETSC_TRUE to relax

  Level: developer

.seealso: HylcCholSetOrdering()
@*/
PetscErrorCode HylcCholSetRelaxed(HylcChol C, PetscBool relax)
{
  PetscFunctionBegin;
  if (relax != C->relax) PetscCall(CholReset(C));
  C->relax = relax;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholSetIndefinite - Sets whether negative pivots are accepted (no pivoting: only for matrices whose
  leading principal minors do not vanish, as regularized Hessians). Default false.

  Not collective

  Input Parameters:
+ C     - the factorization
- allow - PETSC_TRUE to accept indefinite matrices

  Level: developer

.seealso: HylcCholGetInertia()
@*/
PetscErrorCode HylcCholSetIndefinite(HylcChol C, PetscBool allow)
{
  PetscFunctionBegin;
  C->indefinite = allow;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The triangular solves on the permuted right-hand sides, interleaved: y[m g + j]. Columns are taken
   SOLVE_CHUNK at a time with their values in local arrays, and the function is inlined with a constant m
   (1, 4) in HylcCholSolveMany, so that the loops over the right-hand sides vectorize. */
#define SOLVE_CHUNK 8
static inline __attribute__((always_inline)) void SolveInterleaved(HylcChol C, const PetscInt m, PetscReal *y)
{
  const PetscInt bs = C->bs, n = C->n;
  PetscReal     *t = C->tw; /* nb (ld - W) entries, nb <= m */

  for (PetscInt j0 = 0; j0 < m; j0 += SOLVE_CHUNK) {
    const PetscInt nb = m - j0 < SOLVE_CHUNK ? m - j0 : SOLVE_CHUNK;
    /* L z = y, a supernode at a time: the triangular solve with the diagonal block, then the rows below as
       one dense product t = L_below z_s, subtracted from y at the rows R_s */
    for (PetscInt s = 0; s < C->nsup; s++) {
      const PetscInt   f = C->sfirst[s], w = C->sfirst[s + 1] - f, nr = C->rptr[s + 1] - C->rptr[s], ld = bs * nr, W = bs * w;
      const PetscInt  *R = C->rows + C->rptr[s];
      const PetscReal *P = C->L + C->voff[s];
      PetscReal       *X = y + m * bs * f + j0;
      for (PetscInt k = 0; k < W; k++) {
        const PetscReal *ck = P + k * ld;
        PetscReal        xv[SOLVE_CHUNK];
        for (PetscInt j = 0; j < nb; j++) X[m * k + j] = xv[j] = X[m * k + j] / ck[k];
        for (PetscInt i = k + 1; i < W; i++)
          for (PetscInt j = 0; j < nb; j++) X[m * i + j] -= ck[i] * xv[j];
      }
      if (ld == W) continue;
      for (PetscInt i = 0; i < nb * (ld - W); i++) t[i] = 0;
      for (PetscInt k = 0; k < W; k++) {
        const PetscReal *ck = P + k * ld + W;
        PetscReal        xv[SOLVE_CHUNK];
        for (PetscInt j = 0; j < nb; j++) xv[j] = X[m * k + j];
        for (PetscInt i = 0; i < ld - W; i++)
          for (PetscInt j = 0; j < nb; j++) t[nb * i + j] += ck[i] * xv[j];
      }
      for (PetscInt r = w; r < nr; r++)
        for (PetscInt i = 0; i < bs; i++) {
          PetscReal       *yr = y + m * (bs * R[r] + i) + j0;
          const PetscReal *tr = t + nb * (bs * (r - w) + i);
          for (PetscInt j = 0; j < nb; j++) yr[j] -= tr[j];
        }
    }
    /* S z */
    if (C->nneg)
      for (PetscInt g = 0; g < n; g++)
        if (C->sg[g] < 0)
          for (PetscInt j = 0; j < nb; j++) y[m * g + j0 + j] = -y[m * g + j0 + j];
    /* L^T x = S z: gather the solution at the rows below, then dot products and the diagonal block */
    for (PetscInt s = C->nsup - 1; s >= 0; s--) {
      const PetscInt   f = C->sfirst[s], w = C->sfirst[s + 1] - f, nr = C->rptr[s + 1] - C->rptr[s], ld = bs * nr, W = bs * w;
      const PetscInt  *R = C->rows + C->rptr[s];
      const PetscReal *P = C->L + C->voff[s];
      PetscReal       *X = y + m * bs * f + j0;
      for (PetscInt r = w; r < nr; r++)
        for (PetscInt i = 0; i < bs; i++) {
          const PetscReal *yr = y + m * (bs * R[r] + i) + j0;
          PetscReal       *tr = t + nb * (bs * (r - w) + i);
          for (PetscInt j = 0; j < nb; j++) tr[j] = yr[j];
        }
      for (PetscInt k = W - 1; k >= 0; k--) {
        const PetscReal *ck = P + k * ld;
        PetscReal        acc[SOLVE_CHUNK];
        for (PetscInt j = 0; j < nb; j++) acc[j] = X[m * k + j];
        for (PetscInt i = 0; i < ld - W; i++)
          for (PetscInt j = 0; j < nb; j++) acc[j] -= ck[W + i] * t[nb * i + j];
        for (PetscInt i = k + 1; i < W; i++)
          for (PetscInt j = 0; j < nb; j++) acc[j] -= ck[i] * X[m * i + j];
        for (PetscInt j = 0; j < nb; j++) X[m * k + j] = acc[j] / ck[k];
      }
    }
  }
}

/*@C
  HylcCholSolveMany - Solves A x = b for nrhs right-hand sides stored one after the other (b[j n + i]) with
  the last successful factorization, all of them in one pass over L.

  Not collective

  Input Parameters:
+ C    - the factorization
. nrhs - the number of right-hand sides
- b    - the right-hand sides

  Output Parameter:
. x - the solutions (may be b)

  Level: developer

.seealso: HylcCholSolve()
@*/
HYLC_TARGET_CLONES PetscErrorCode HylcCholSolveMany(HylcChol C, PetscInt nrhs, const PetscScalar b[], PetscScalar x[])
{
  const PetscInt bs = C->bs, n = C->n, m = nrhs;
  PetscReal     *y;

  PetscFunctionBegin;
  PetscCheck(C->factored, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "HylcCholSolve: no successful factorization");
  if (m <= 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_CholSolve, 0, 0, 0, 0));
  if (n * m > C->ycap) {
    PetscCall(PetscFree2(C->y, C->tw));
    C->ycap = n * m;
    PetscCall(PetscMalloc2(C->ycap, &C->y, C->ycap, &C->tw));
  }
  y = C->y; /* permuted, the right-hand sides interleaved: y[m g + j] */
  for (PetscInt BI = 0; BI < C->nb; BI++)
    for (PetscInt i = 0; i < bs; i++)
      for (PetscInt j = 0; j < m; j++) y[m * (bs * C->iperm[BI] + i) + j] = PetscRealPart(b[j * n + bs * BI + i]);
  if (m == 1)
    SolveInterleaved(C, 1, y);
  else if (m == 4)
    SolveInterleaved(C, 4, y); /* the Schur complement's right-hand sides of the Newton solver */
  else
    SolveInterleaved(C, m, y);
  for (PetscInt BI = 0; BI < C->nb; BI++)
    for (PetscInt i = 0; i < bs; i++)
      for (PetscInt j = 0; j < m; j++) x[j * n + bs * BI + i] = y[m * (bs * C->iperm[BI] + i) + j];
  PetscCall(PetscLogFlops(4.0 * m * (PetscLogDouble)C->voff[C->nsup]));
  PetscCall(PetscLogEventEnd(HYLC_CholSolve, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholSolve - Solves A x = b with the last successful factorization.

  Not collective

  Input Parameters:
+ C - the factorization
- b - the right-hand side

  Output Parameter:
. x - the solution (may be b)

  Level: developer

.seealso: HylcCholSolveMany(), HylcCholFactor()
@*/
PetscErrorCode HylcCholSolve(HylcChol C, const PetscScalar b[], PetscScalar x[])
{
  PetscFunctionBegin;
  PetscCall(HylcCholSolveMany(C, 1, b, x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholGetInfo - Statistics of the factorization: order, block size, supernodes, stored entries of L,
  flops per numeric factorization and the phases run.

  Not collective

  Input Parameter:
. C - the factorization

  Output Parameter:
. info - the statistics

  Level: developer

.seealso: HylcCholView()
@*/
PetscErrorCode HylcCholGetInfo(HylcChol C, HylcCholInfo *info)
{
  PetscFunctionBegin;
  *info = C->info;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholView - Prints the statistics of the factorization (one line).

  Not collective

  Input Parameters:
+ C      - the factorization
- viewer - an ASCII viewer (NULL: stdout)

  Level: developer

.seealso: HylcCholGetInfo()
@*/
PetscErrorCode HylcCholView(HylcChol C, PetscViewer viewer)
{
  char buf[256];

  PetscFunctionBegin;
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PETSC_COMM_SELF, &viewer));
  snprintf(buf, sizeof(buf), "HylcChol: order %d, block size %d, ordering %s, %d supernodes, %.0f stored entries of L, %.3g flops per factorization, %d symbolic / %d numeric phases\n", (int)C->info.n, (int)C->info.bs,
           C->ordering == HYLC_CHOL_ORDERING_METIS ? "metis" : "natural", (int)C->info.nsuper, (double)C->info.nnzL, (double)C->info.flops, (int)C->info.nsymbolic, (int)C->info.nnumeric);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}
