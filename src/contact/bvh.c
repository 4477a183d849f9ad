/* Broadphase for segment contact: a static AABB hierarchy (built once, refit per evaluation) with a
   tree-against-itself query, ghost pruning, and the O(n^2) reference. See include/hylc/contact.h. */
#include <hylc/contact.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LEAF_SIZE 4

typedef struct {
  double        lo[3], hi[3];
  int           left, right;  /* children (node indices), -1 for a leaf */
  int           start, count; /* segments perm[start .. start + count) */
  unsigned char allghost;     /* every segment of the subtree is ghost-flagged */
} BVHNode;

struct _n_HylcBVH {
  int            nseg, nnode, built;
  double         margin;
  int           *perm;  /* leaf order -> segment index */
  double        *sbox;  /* boxes in leaf order, 6 per segment (lo, hi) */
  double        *cent;  /* box centres (build only) */
  BVHNode       *nodes; /* preorder: children have larger indices than their parent */
  unsigned char *ghost; /* per segment (original numbering), NULL: no pruning */
};

/* ---------------------------------------------------------------- pair lists */

void HylcPairListFree(HylcPairList *list)
{
  if (!list) return;
  free(list->idx);
  list->idx = NULL;
  list->n = list->cap = 0;
}

static int PairListPush(HylcPairList *list, int i, int j)
{
  if (list->n == list->cap) {
    const size_t cap = list->cap ? 2 * list->cap : 1024;
    int         *idx = (int *)realloc(list->idx, 2 * cap * sizeof(int));
    if (!idx) return -1;
    list->idx = idx;
    list->cap = cap;
  }
  list->idx[2 * list->n]     = i < j ? i : j;
  list->idx[2 * list->n + 1] = i < j ? j : i;
  list->n++;
  return 0;
}

static int PairCompare(const void *a, const void *b)
{
  const int *p = (const int *)a, *q = (const int *)b;
  if (p[0] != q[0]) return p[0] < q[0] ? -1 : 1;
  if (p[1] != q[1]) return p[1] < q[1] ? -1 : 1;
  return 0;
}

/* Lexicographic order: a two-pass counting sort (by the second index, then stably by the first), linear in
   the pairs and the largest index; qsort if the indices are negative or the work arrays cannot be had. The
   order is a total one, so both give the same list. */
void HylcPairListSort(HylcPairList *list)
{
  size_t *cnt = NULL;
  int    *tmp = NULL, vmax = 0, vmin = 0;

  if (!list || list->n < 2) return;
  const size_t n = list->n;
  for (size_t p = 0; p < 2 * n; p++) {
    if (list->idx[p] > vmax) vmax = list->idx[p];
    if (list->idx[p] < vmin) vmin = list->idx[p];
  }
  if (vmin >= 0) {
    cnt = (size_t *)malloc(((size_t)vmax + 2) * sizeof(*cnt));
    tmp = (int *)malloc(2 * n * sizeof(*tmp));
  }
  if (!cnt || !tmp) {
    free(cnt);
    free(tmp);
    qsort(list->idx, n, 2 * sizeof(int), PairCompare);
    return;
  }
  for (int pass = 1; pass >= 0; pass--) { /* pass 1: key idx[2p + 1] into tmp; pass 0: key idx[2p] back */
    const int *src = pass ? list->idx : tmp;
    int       *dst = pass ? tmp : list->idx;
    memset(cnt, 0, ((size_t)vmax + 2) * sizeof(*cnt));
    for (size_t p = 0; p < n; p++) cnt[src[2 * p + pass] + 1]++;
    for (int v = 0; v <= vmax; v++) cnt[v + 1] += cnt[v];
    for (size_t p = 0; p < n; p++) {
      const size_t q = cnt[src[2 * p + pass]]++;
      dst[2 * q]     = src[2 * p];
      dst[2 * q + 1] = src[2 * p + 1];
    }
  }
  free(cnt);
  free(tmp);
}

/* ---------------------------------------------------------------- boxes */

/* The one definition of a segment's box, shared by the tree and the brute-force reference. */
static inline void SegmentBox(const double *x, const int *edges, int i, double margin, double box[6])
{
  const double *p = edges ? x + 3 * (size_t)edges[2 * i] : x + 6 * (size_t)i;
  const double *q = edges ? x + 3 * (size_t)edges[2 * i + 1] : p + 3;
  for (int k = 0; k < 3; k++) {
    box[k]     = (p[k] < q[k] ? p[k] : q[k]) - margin;
    box[3 + k] = (p[k] < q[k] ? q[k] : p[k]) + margin;
  }
}

static inline int BoxOverlap(const double *a, const double *b) { return a[0] <= b[3] && b[0] <= a[3] && a[1] <= b[4] && b[1] <= a[4] && a[2] <= b[5] && b[2] <= a[5]; }

static inline int NodeOverlap(const BVHNode *a, const BVHNode *b) { return a->lo[0] <= b->hi[0] && b->lo[0] <= a->hi[0] && a->lo[1] <= b->hi[1] && b->lo[1] <= a->hi[1] && a->lo[2] <= b->hi[2] && b->lo[2] <= a->hi[2]; }

static void NodeBoxFromSegments(HylcBVH bvh, BVHNode *nd)
{
  for (int k = 0; k < 3; k++) {
    nd->lo[k] = INFINITY;
    nd->hi[k] = -INFINITY;
  }
  for (int m = nd->start; m < nd->start + nd->count; m++) {
    const double *b = bvh->sbox + 6 * (size_t)m;
    for (int k = 0; k < 3; k++) {
      if (b[k] < nd->lo[k]) nd->lo[k] = b[k];
      if (b[3 + k] > nd->hi[k]) nd->hi[k] = b[3 + k];
    }
  }
}

static void NodeBoxFromChildren(BVHNode *nodes, BVHNode *nd)
{
  const BVHNode *l = &nodes[nd->left], *r = &nodes[nd->right];
  for (int k = 0; k < 3; k++) {
    nd->lo[k] = l->lo[k] < r->lo[k] ? l->lo[k] : r->lo[k];
    nd->hi[k] = l->hi[k] > r->hi[k] ? l->hi[k] : r->hi[k];
  }
}

/* ---------------------------------------------------------------- build */

int HylcBVHCreate(int nseg, HylcBVH *bvh)
{
  HylcBVH b;
  if (!bvh || nseg < 0) return -1;
  *bvh = NULL;
  b    = (HylcBVH)calloc(1, sizeof(*b));
  if (!b) return -1;
  const size_t n = nseg > 0 ? (size_t)nseg : 1;
  b->nseg        = nseg;
  b->perm        = (int *)malloc(n * sizeof(int));
  b->sbox        = (double *)malloc(6 * n * sizeof(double));
  b->cent        = (double *)malloc(3 * n * sizeof(double));
  b->nodes       = (BVHNode *)malloc(2 * n * sizeof(BVHNode));
  if (!b->perm || !b->sbox || !b->cent || !b->nodes) {
    HylcBVHDestroy(&b);
    return -1;
  }
  *bvh = b;
  return 0;
}

void HylcBVHDestroy(HylcBVH *bvh)
{
  if (!bvh || !*bvh) return;
  free((*bvh)->perm);
  free((*bvh)->sbox);
  free((*bvh)->cent);
  free((*bvh)->nodes);
  free((*bvh)->ghost);
  free(*bvh);
  *bvh = NULL;
}

/* Reorders perm[lo..hi) so that perm[k] holds the element of rank k by cent[3 perm + axis]
   (Hoare-partition quickselect with median-of-three pivots; ties in any order). */
static void SelectKth(int *perm, const double *cent, int axis, int lo, int hi, int k)
{
#define KEY(m) cent[3 * (size_t)perm[m] + axis]
  hi--;
  while (hi > lo) {
    const int mid = lo + (hi - lo) / 2;
    double    a = KEY(lo), b = KEY(mid), c = KEY(hi);
    double    pivot = a < b ? (b < c ? b : (a < c ? c : a)) : (a < c ? a : (b < c ? c : b));
    int       i = lo, j = hi;
    while (i <= j) {
      while (KEY(i) < pivot) i++;
      while (KEY(j) > pivot) j--;
      if (i <= j) {
        const int tmp = perm[i];
        perm[i]       = perm[j];
        perm[j]       = tmp;
        i++;
        j--;
      }
    }
    if (k <= j)
      hi = j;
    else if (k >= i)
      lo = i;
    else
      break;
  }
#undef KEY
}

static int BuildNode(HylcBVH bvh, int start, int count)
{
  const int node = bvh->nnode++;
  BVHNode  *nd   = &bvh->nodes[node];
  nd->start      = start;
  nd->count      = count;
  nd->left = nd->right = -1;
  nd->allghost         = 0;
  if (count <= LEAF_SIZE) return node; /* boxes are filled in leaf order by the refit after the build */
  double clo[3] = {INFINITY, INFINITY, INFINITY}, chi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int m = start; m < start + count; m++) {
    const double *c = bvh->cent + 3 * (size_t)bvh->perm[m];
    for (int k = 0; k < 3; k++) {
      if (c[k] < clo[k]) clo[k] = c[k];
      if (c[k] > chi[k]) chi[k] = c[k];
    }
  }
  int axis = 0;
  for (int k = 1; k < 3; k++)
    if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
  const int half = count / 2;
  SelectKth(bvh->perm, bvh->cent, axis, start, start + count, start + half);
  const int left  = BuildNode(bvh, start, half);
  const int right = BuildNode(bvh, start + half, count - half);
  nd              = &bvh->nodes[node];
  nd->left        = left;
  nd->right       = right;
  return node;
}

static void UpdateGhostFlags(HylcBVH bvh)
{
  for (int m = bvh->nnode - 1; m >= 0; m--) {
    BVHNode *nd = &bvh->nodes[m];
    if (!bvh->ghost)
      nd->allghost = 0;
    else if (nd->left < 0) {
      nd->allghost = 1;
      for (int k = nd->start; k < nd->start + nd->count; k++)
        if (!bvh->ghost[bvh->perm[k]]) nd->allghost = 0;
    } else
      nd->allghost = bvh->nodes[nd->left].allghost && bvh->nodes[nd->right].allghost;
  }
}

int HylcBVHRefit(HylcBVH bvh, const double *x, const int *edges)
{
  if (!bvh || !bvh->built || (!x && bvh->nseg > 0)) return -1;
  for (int m = 0; m < bvh->nseg; m++) SegmentBox(x, edges, bvh->perm[m], bvh->margin, bvh->sbox + 6 * (size_t)m);
  for (int m = bvh->nnode - 1; m >= 0; m--) {
    BVHNode *nd = &bvh->nodes[m];
    if (nd->left < 0)
      NodeBoxFromSegments(bvh, nd);
    else
      NodeBoxFromChildren(bvh->nodes, nd);
  }
  return 0;
}

int HylcBVHBuild(HylcBVH bvh, const double *x, const int *edges, double margin)
{
  if (!bvh || (!x && bvh->nseg > 0)) return -1;
  bvh->margin = margin;
  bvh->nnode  = 0;
  for (int i = 0; i < bvh->nseg; i++) {
    double box[6];
    SegmentBox(x, edges, i, margin, box);
    for (int k = 0; k < 3; k++) bvh->cent[3 * (size_t)i + k] = 0.5 * (box[k] + box[3 + k]);
    bvh->perm[i] = i;
  }
  if (bvh->nseg > 0) BuildNode(bvh, 0, bvh->nseg);
  bvh->built = 1;
  UpdateGhostFlags(bvh);
  return HylcBVHRefit(bvh, x, edges);
}

int HylcBVHSetGhost(HylcBVH bvh, const unsigned char *ghost)
{
  if (!bvh) return -1;
  if (!ghost) {
    free(bvh->ghost);
    bvh->ghost = NULL;
  } else {
    if (!bvh->ghost) {
      bvh->ghost = (unsigned char *)malloc(bvh->nseg > 0 ? (size_t)bvh->nseg : 1);
      if (!bvh->ghost) return -1;
    }
    memcpy(bvh->ghost, ghost, (size_t)bvh->nseg);
  }
  if (bvh->built) UpdateGhostFlags(bvh);
  return 0;
}

/* ---------------------------------------------------------------- query */

typedef struct {
  HylcBVH       bvh;
  HylcPairList *out;
  int           err;
} QueryCtx;

static inline void TestPair(QueryCtx *q, int mi, int mj)
{
  HylcBVH bvh = q->bvh;
  if (!BoxOverlap(bvh->sbox + 6 * (size_t)mi, bvh->sbox + 6 * (size_t)mj)) return;
  const int i = bvh->perm[mi], j = bvh->perm[mj];
  if (bvh->ghost && bvh->ghost[i] && bvh->ghost[j]) return;
  if (PairListPush(q->out, i, j)) q->err = -1;
}

static void QueryCross(QueryCtx *q, int a, int b)
{
  const BVHNode *A = &q->bvh->nodes[a], *B = &q->bvh->nodes[b];
  if (!NodeOverlap(A, B)) return;
  if (A->allghost && B->allghost) return;
  const int aleaf = A->left < 0, bleaf = B->left < 0;
  if (aleaf && bleaf) {
    for (int mi = A->start; mi < A->start + A->count; mi++)
      for (int mj = B->start; mj < B->start + B->count; mj++) TestPair(q, mi, mj);
  } else if (bleaf || (!aleaf && A->count >= B->count)) {
    QueryCross(q, A->left, b);
    QueryCross(q, A->right, b);
  } else {
    QueryCross(q, a, B->left);
    QueryCross(q, a, B->right);
  }
}

static void QuerySelf(QueryCtx *q, int a)
{
  const BVHNode *A = &q->bvh->nodes[a];
  if (A->allghost) return;
  if (A->left < 0) {
    for (int mi = A->start; mi < A->start + A->count; mi++)
      for (int mj = mi + 1; mj < A->start + A->count; mj++) TestPair(q, mi, mj);
    return;
  }
  QuerySelf(q, A->left);
  QuerySelf(q, A->right);
  QueryCross(q, A->left, A->right);
}

int HylcBVHQuery(HylcBVH bvh, HylcPairList *pairs)
{
  if (!bvh || !pairs || !bvh->built) return -1;
  QueryCtx q = {bvh, pairs, 0};
  pairs->n   = 0;
  if (bvh->nnode > 0) QuerySelf(&q, 0);
  return q.err;
}

int HylcBroadphaseBruteForce(int nseg, const double *x, const int *edges, double margin, const unsigned char *ghost, HylcPairList *pairs)
{
  if (!pairs || nseg < 0 || (!x && nseg > 0)) return -1;
  double *box = (double *)malloc(6 * (size_t)(nseg > 0 ? nseg : 1) * sizeof(double));
  if (!box) return -1;
  for (int i = 0; i < nseg; i++) SegmentBox(x, edges, i, margin, box + 6 * (size_t)i);
  pairs->n = 0;
  int err  = 0;
  for (int i = 0; i < nseg && !err; i++)
    for (int j = i + 1; j < nseg; j++) {
      if (!BoxOverlap(box + 6 * (size_t)i, box + 6 * (size_t)j)) continue;
      if (ghost && ghost[i] && ghost[j]) continue;
      if (PairListPush(pairs, i, j)) {
        err = -1;
        break;
      }
    }
  free(box);
  return err;
}
