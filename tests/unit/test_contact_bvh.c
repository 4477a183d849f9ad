/* Unit tests of the contact broadphase (include/hylc/contact.h): the AABB hierarchy's self-query returns
   exactly the brute-force pairs, with and without ghost pruning, after refits and rebuilds, for both
   input layouts, and for degenerate inputs; every pair closer than 2r is found with margin r. */
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <stdlib.h>
#include <string.h>
#include "hylctest.h"

static int SamePairs(HylcPairList *a, HylcPairList *b)
{
  HylcPairListSort(a);
  HylcPairListSort(b);
  if (a->n != b->n) return 0;
  return a->n == 0 || !memcmp(a->idx, b->idx, 2 * a->n * sizeof(int));
}

static int Contains(const HylcPairList *sorted, int i, int j)
{
  size_t lo = 0, hi = sorted->n;
  while (lo < hi) {
    const size_t m = (lo + hi) / 2;
    const int   *p = sorted->idx + 2 * m;
    if (p[0] < i || (p[0] == i && p[1] < j))
      lo = m + 1;
    else
      hi = m;
  }
  return lo < sorted->n && sorted->idx[2 * lo] == i && sorted->idx[2 * lo + 1] == j;
}

/* nseg random segments of length ~ r in a cube holding about 3 neighbours within 2r per segment
   (6 doubles per segment) */
static void RandomSegments(unsigned long long *st, int nseg, double r, double *x)
{
  const double L = cbrt(nseg * 20.0) * r;
  for (int i = 0; i < nseg; i++) {
    double u[3], c[3];
    for (int k = 0; k < 3; k++) {
      u[k] = 2 * HylcTestRand(st) - 1;
      c[k] = L * HylcTestRand(st);
    }
    HylcNormalize3(u);
    const double len = r * (0.5 + HylcTestRand(st));
    for (int k = 0; k < 3; k++) {
      x[6 * i + k]     = c[k] - 0.5 * len * u[k];
      x[6 * i + 3 + k] = c[k] + 0.5 * len * u[k];
    }
  }
}

/* Builds (or refits) the tree for (x, edges), queries with and without the ghost flags and compares to
   brute force. */
static void CompareAll(HylcBVH bvh, int nseg, const double *x, const int *edges, double margin, const unsigned char *ghost, const char *label)
{
  HylcPairList t = {0}, b = {0};
  HYLC_CHECK(HylcBVHSetGhost(bvh, NULL) == 0, "%s", label);
  HYLC_CHECK(HylcBVHQuery(bvh, &t) == 0, "%s", label);
  HYLC_CHECK(HylcBroadphaseBruteForce(nseg, x, edges, margin, NULL, &b) == 0, "%s", label);
  HYLC_CHECK(SamePairs(&t, &b), "%s: tree %zu pairs, brute force %zu pairs", label, t.n, b.n);
  if (ghost) {
    HYLC_CHECK(HylcBVHSetGhost(bvh, ghost) == 0, "%s", label);
    HYLC_CHECK(HylcBVHQuery(bvh, &t) == 0, "%s", label);
    HYLC_CHECK(HylcBroadphaseBruteForce(nseg, x, edges, margin, ghost, &b) == 0, "%s", label);
    HYLC_CHECK(SamePairs(&t, &b), "%s (ghost): tree %zu pairs, brute force %zu pairs", label, t.n, b.n);
    size_t mixed = 0;
    for (size_t k = 0; k < t.n; k++) {
      const int i = t.idx[2 * k], j = t.idx[2 * k + 1];
      HYLC_CHECK(!(ghost[i] && ghost[j]), "%s: ghost-ghost pair (%d, %d) reported", label, i, j);
      mixed += (ghost[i] != 0) != (ghost[j] != 0);
    }
    HYLC_CHECK(mixed > 0 || nseg < 100, "%s: no ghost/original pairs", label);
  }
  HylcPairListFree(&t);
  HylcPairListFree(&b);
}

static int PairLess(const void *a, const void *b)
{
  const int *p = (const int *)a, *q = (const int *)b;
  return p[0] != q[0] ? (p[0] < q[0] ? -1 : 1) : p[1] != q[1] ? (p[1] < q[1] ? -1 : 1) : 0;
}

/* HylcPairListSort (a counting sort, qsort for negative indices) against qsort: random pairs with
   repeats, both index orders, and lists of 0, 1 and 2 pairs */
static void TestSort(unsigned long long *st)
{
  const size_t sizes[]  = {0, 1, 2, 7, 1000, 20000};
  const int    ranges[] = {1, 3, 50, 9000};
  for (size_t a = 0; a < sizeof(sizes) / sizeof(sizes[0]); a++)
    for (size_t b = 0; b < sizeof(ranges) / sizeof(ranges[0]); b++)
      for (int neg = 0; neg < 2; neg++) {
        const size_t n    = sizes[a];
        HylcPairList list = {0};
        int         *ref  = (int *)malloc((2 * n + 1) * sizeof(int));
        list.idx          = (int *)malloc((2 * n + 1) * sizeof(int));
        list.n = list.cap = n;
        for (size_t p = 0; p < 2 * n; p++) list.idx[p] = (int)(HylcTestRand(st) * ranges[b]) - (neg && p == n ? 1 : 0);
        memcpy(ref, list.idx, 2 * n * sizeof(int));
        qsort(ref, n, 2 * sizeof(int), PairLess);
        HylcPairListSort(&list);
        HYLC_CHECK(n == 0 || !memcmp(ref, list.idx, 2 * n * sizeof(int)), "sort of %zu pairs in [0, %d)%s differs from qsort", n, ranges[b], neg ? " with a negative index" : "");
        free(ref);
        HylcPairListFree(&list);
      }
}

int main(void)
{
  unsigned long long st = 77;
  const double       r  = 0.5e-3;

  TestSort(&st);

  /* random segments, several sizes; ghost flags random and spatially clustered; refit and rebuild */
  const int sizes[] = {0, 1, 2, 5, 17, 300, 3000};
  for (size_t sz = 0; sz < sizeof(sizes) / sizeof(sizes[0]); sz++) {
    const int      nseg = sizes[sz];
    double        *x    = (double *)malloc(6 * (nseg + 1) * sizeof(double));
    unsigned char *gr = (unsigned char *)malloc(nseg + 1), *gc = (unsigned char *)malloc(nseg + 1);
    HylcBVH        bvh;
    RandomSegments(&st, nseg, r, x);
    const double L = cbrt(nseg * 20.0) * r;
    for (int i = 0; i < nseg; i++) {
      gr[i] = HylcTestRand(&st) < 0.4;
      gc[i] = x[6 * i] > 0.6 * L; /* a whole region of ghosts: whole subtrees prune */
    }
    HYLC_CHECK(HylcBVHCreate(nseg, &bvh) == 0, "create %d", nseg);
    HYLC_CHECK(HylcBVHBuild(bvh, x, NULL, r) == 0, "build %d", nseg);
    CompareAll(bvh, nseg, x, NULL, r, gr, "random ghosts");
    CompareAll(bvh, nseg, x, NULL, r, gc, "clustered ghosts");

    /* every pair with segment distance < 2r is found (margin r) */
    if (nseg <= 3000) {
      HylcPairList t = {0};
      HylcBVHSetGhost(bvh, NULL);
      HylcBVHQuery(bvh, &t);
      HylcPairListSort(&t);
      size_t close = 0;
      for (int i = 0; i < nseg; i++)
        for (int j = i + 1; j < nseg; j++) {
          const double d = HylcSegmentSegmentDistance(x + 6 * i, x + 6 * i + 3, x + 6 * j, x + 6 * j + 3, NULL, NULL);
          if (d < 2 * r) {
            close++;
            HYLC_CHECK(Contains(&t, i, j), "pair (%d, %d) at distance %g < 2r missed", i, j, d);
          }
        }
      if (nseg == 3000) { /* realistic density: a few neighbours per segment */
        const double nb = 2.0 * close / nseg;
        HYLC_CHECK(nb > 1 && nb < 6, "neighbours within 2r per segment: %g", nb);
      }
      HylcPairListFree(&t);
    }

    /* small motions, then large ones (segments shuffled across the domain): refit keeps pairs exact */
    for (int i = 0; i < 6 * nseg; i++) x[i] += 0.3 * r * (2 * HylcTestRand(&st) - 1);
    HYLC_CHECK(HylcBVHRefit(bvh, x, NULL) == 0, "refit");
    CompareAll(bvh, nseg, x, NULL, r, gr, "refit small");
    RandomSegments(&st, nseg, r, x);
    HYLC_CHECK(HylcBVHRefit(bvh, x, NULL) == 0, "refit");
    CompareAll(bvh, nseg, x, NULL, r, gc, "refit large");
    /* rebuild with another margin */
    HYLC_CHECK(HylcBVHBuild(bvh, x, NULL, 1.5 * r) == 0, "rebuild");
    CompareAll(bvh, nseg, x, NULL, 1.5 * r, gr, "rebuild");
    HylcBVHDestroy(&bvh);
    HYLC_CHECK(bvh == NULL, "destroy");
    free(x);
    free(gr);
    free(gc);
  }

  /* vertex + edge input: random-walk yarns, the extended chains carrying ghost segments at both ends */
  {
    const int      nyarn = 40, nper = 60, nv = nyarn * (nper + 1), nseg = nyarn * nper;
    double        *xv    = (double *)malloc(3 * nv * sizeof(double));
    int           *edges = (int *)malloc(2 * nseg * sizeof(int));
    unsigned char *ghost = (unsigned char *)malloc(nseg);
    const double   L     = cbrt(nseg * 20.0) * r;
    for (int y = 0; y < nyarn; y++) {
      double p[3], u[3] = {1, 0, 0};
      for (int k = 0; k < 3; k++) p[k] = L * HylcTestRand(&st);
      for (int v = 0; v <= nper; v++) {
        const int iv = y * (nper + 1) + v;
        for (int k = 0; k < 3; k++) xv[3 * iv + k] = p[k];
        double du[3];
        for (int k = 0; k < 3; k++) du[k] = u[k] + 0.6 * (2 * HylcTestRand(&st) - 1);
        HylcNormalize3(du);
        memcpy(u, du, sizeof(u));
        for (int k = 0; k < 3; k++) p[k] += 0.8 * r * u[k];
        if (v < nper) {
          const int e      = y * nper + v;
          edges[2 * e]     = iv;
          edges[2 * e + 1] = iv + 1;
          ghost[e]         = v < 8 || v >= nper - 8 || y % 5 == 0;
        }
      }
    }
    HylcBVH bvh;
    HYLC_CHECK(HylcBVHCreate(nseg, &bvh) == 0, "create");
    HYLC_CHECK(HylcBVHBuild(bvh, xv, edges, r) == 0, "build");
    CompareAll(bvh, nseg, xv, edges, r, ghost, "yarns");
    /* adjacent segments share a vertex: their boxes always overlap */
    {
      HylcPairList t = {0};
      HylcBVHSetGhost(bvh, NULL);
      HylcBVHQuery(bvh, &t);
      HylcPairListSort(&t);
      for (int e = 0; e + 1 < nseg; e++)
        if (edges[2 * e + 1] == edges[2 * (e + 1)]) HYLC_CHECK(Contains(&t, e, e + 1), "adjacent pair %d missing", e);
      HylcPairListFree(&t);
    }
    for (int i = 0; i < 3 * nv; i++) xv[i] = 1.2 * xv[i] + 0.2 * r * (2 * HylcTestRand(&st) - 1);
    HYLC_CHECK(HylcBVHRefit(bvh, xv, edges) == 0, "refit");
    CompareAll(bvh, nseg, xv, edges, r, ghost, "yarns refit");
    HylcBVHDestroy(&bvh);
    free(xv);
    free(edges);
    free(ghost);
  }

  /* degenerate inputs: all segments identical (ties in every split), all on a line, all ghost */
  {
    const int      nseg = 200;
    double        *x    = (double *)malloc(6 * nseg * sizeof(double));
    unsigned char *g    = (unsigned char *)malloc(nseg);
    HylcBVH        bvh;
    for (int i = 0; i < nseg; i++) {
      const double s[6] = {0, 0, 0, r, 0, 0};
      memcpy(x + 6 * i, s, sizeof(s));
      g[i] = i % 3 == 0;
    }
    HylcBVHCreate(nseg, &bvh);
    HylcBVHBuild(bvh, x, NULL, r);
    CompareAll(bvh, nseg, x, NULL, r, g, "identical");
    {
      HylcPairList t = {0};
      HylcBVHQuery(bvh, &t);
      HYLC_CHECK(t.n == (size_t)nseg * (nseg - 1) / 2 - (size_t)67 * 66 / 2, "identical: %zu pairs", t.n);
      HylcPairListFree(&t);
    }
    for (int i = 0; i < nseg; i++) {
      x[6 * i]     = 0.9 * r * i;
      x[6 * i + 3] = 0.9 * r * (i + 1);
      g[i]         = 1;
    }
    HylcBVHBuild(bvh, x, NULL, 0.0);
    CompareAll(bvh, nseg, x, NULL, 0.0, NULL, "line");
    HylcBVHSetGhost(bvh, g);
    {
      HylcPairList t = {0};
      HylcBVHQuery(bvh, &t);
      HYLC_CHECK(t.n == 0, "all ghost: %zu pairs", t.n);
      HylcPairListFree(&t);
    }
    HylcBVHDestroy(&bvh);
    HylcBVHDestroy(&bvh); /* idempotent */
    HylcBVHDestroy(NULL);
    HYLC_CHECK(HylcBVHCreate(-1, &bvh) == -1 && bvh == NULL, "negative size accepted");
    free(x);
    free(g);
  }
  return HYLC_TEST_RESULT();
}
