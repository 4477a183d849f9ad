/* Broadphase on the paper's seven patterns with their periodic copies: for every pattern the segments of
   the tile and of its eight neighbouring copies (shifts (sx, sy) in {-1, 0, 1}^2, the copies flagged
   ghost) are given to the AABB hierarchy; its self-query must return exactly the pairs brute force
   finds (with and without ghost pruning), every pair of segments closer than 2r must be among them, and
   this must stay so after all vertices are moved randomly by up to 0.3 r per coordinate (keeping the
   tile periodic) and the tree is refitted, and after a rebuild with a larger margin.
   Exits 77 when ../shared/refdata (or $HYLC_REFDATA) is absent.
   hylc-test: nprocs=1 */
#include <hylc/pattern.h>
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <stdlib.h>
#include <string.h>
#include "hylctest.h"

static const char *const patterns[] = {"basket", "satin", "stockinette", "cartridge_belt_rib", "slip_stitch_honeycomb", "satin_small", "stockinette_small"};

/* PetscPrintf sink while loading (the loader's expected basket.pyp warnings stay out of the output) */
static PetscErrorCode Discard(FILE *fp, const char fmt[], va_list ap)
{
  (void)fp;
  (void)fmt;
  (void)ap;
  return PETSC_SUCCESS;
}

/* Segment list (6 doubles per segment) of the tile at vertex positions X and its 8 periodic copies;
   copy c = 3 (sy + 1) + (sx + 1) holds segments c nv .. (c + 1) nv - 1; all but (0, 0) are ghosts. */
static void Segments(const HylcPatternData *D, const double *X, double *x, unsigned char *ghost)
{
  for (int sy = -1; sy <= 1; sy++)
    for (int sx = -1; sx <= 1; sx++) {
      const int c = 3 * (sy + 1) + (sx + 1);
      for (PetscInt v = 0; v < D->nv; v++) {
        const PetscInt w = D->next[v], s = c * D->nv + v;
        double        *seg = x + 6 * s;
        for (int d = 0; d < 3; d++) {
          seg[d]     = X[3 * v + d];
          seg[3 + d] = X[3 * w + d];
        }
        seg[3] += D->shift[2 * v] * D->px;
        seg[4] += D->shift[2 * v + 1] * D->py;
        for (int k = 0; k < 2; k++) {
          seg[3 * k] += sx * D->px;
          seg[3 * k + 1] += sy * D->py;
        }
        ghost[s] = sx != 0 || sy != 0;
      }
    }
}

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

/* Tree vs brute force with and without ghost pruning; every pair (not both ghost) closer than 2r is
   reported. Returns the number of pairs with pruning. */
static size_t Compare(HylcBVH bvh, int nseg, const double *x, double margin, const unsigned char *ghost, double r, const char *name, const char *stage)
{
  HylcPairList t = {0}, b    = {0};
  size_t       npairs, close = 0, mixed = 0;

  HYLC_CHECK(HylcBVHSetGhost(bvh, NULL) == 0 && HylcBVHQuery(bvh, &t) == 0, "%s %s", name, stage);
  HYLC_CHECK(HylcBroadphaseBruteForce(nseg, x, NULL, margin, NULL, &b) == 0, "%s %s", name, stage);
  HYLC_CHECK(SamePairs(&t, &b), "%s %s: tree %zu pairs, brute force %zu (no pruning)", name, stage, t.n, b.n);
  HYLC_CHECK(HylcBVHSetGhost(bvh, ghost) == 0 && HylcBVHQuery(bvh, &t) == 0, "%s %s", name, stage);
  HYLC_CHECK(HylcBroadphaseBruteForce(nseg, x, NULL, margin, ghost, &b) == 0, "%s %s", name, stage);
  HYLC_CHECK(SamePairs(&t, &b), "%s %s: tree %zu pairs, brute force %zu (ghost pruning)", name, stage, t.n, b.n);
  npairs = t.n;
  for (size_t k = 0; k < t.n; k++) {
    const int i = t.idx[2 * k], j = t.idx[2 * k + 1];
    HYLC_CHECK(!(ghost[i] && ghost[j]), "%s %s: ghost-ghost pair (%d, %d)", name, stage, i, j);
    mixed += (ghost[i] != 0) != (ghost[j] != 0);
  }
  HYLC_CHECK(mixed > 0, "%s %s: no pair across the tile boundary", name, stage);
  for (int i = 0; i < nseg; i++)
    for (int j = i + 1; j < nseg; j++) {
      if (ghost[i] && ghost[j]) continue;
      const double d = HylcSegmentSegmentDistance(x + 6 * i, x + 6 * i + 3, x + 6 * j, x + 6 * j + 3, NULL, NULL);
      if (d < 2 * r) {
        close++;
        HYLC_CHECK(Contains(&t, i, j), "%s %s: pair (%d, %d) at %g r not reported", name, stage, i, j, d / r);
      }
    }
  HYLC_CHECK(close > 0, "%s %s: no close pairs at all", name, stage);
  HylcPairListFree(&t);
  HylcPairListFree(&b);
  return npairs;
}

static PetscErrorCode TestPattern(const char *path, const char *name, unsigned long long *st)
{
  PetscErrorCode (*saved)(FILE *, const char[], va_list) = PetscVFPrintf;
  HylcPattern     p;
  HylcPatternData D;
  PetscErrorCode  ierr;

  PetscFunctionBegin;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscVFPrintf = Discard;
  ierr          = HylcPatternLoad(p, path);
  PetscVFPrintf = saved;
  PetscCall(ierr);
  PetscCall(HylcPatternGetData(p, &D));

  const int      nseg = 9 * (int)D.nv;
  const double   r    = D.radius;
  double        *x, *X;
  unsigned char *ghost;
  HylcBVH        bvh;
  PetscCall(PetscMalloc3(6 * nseg, &x, 3 * D.nv, &X, nseg, &ghost));
  PetscCall(PetscArraycpy(X, D.X, 3 * D.nv));
  Segments(&D, X, x, ghost);
  HYLC_CHECK(HylcBVHCreate(nseg, &bvh) == 0 && HylcBVHBuild(bvh, x, NULL, r) == 0, "%s: build", name);
  const size_t n0 = Compare(bvh, nseg, x, r, ghost, r, name, "stored state");
  /* every tile segment has its two neighbours along the yarn (boxes of adjacent segments touch) */
  HYLC_CHECK(n0 >= (size_t)D.nv, "%s: only %zu pairs", name, n0);

  /* random periodic perturbation of every vertex by up to 0.3 r per coordinate, refit */
  for (PetscInt k = 0; k < 3 * D.nv; k++) X[k] += 0.3 * r * (2 * HylcTestRand(st) - 1);
  Segments(&D, X, x, ghost);
  HYLC_CHECK(HylcBVHRefit(bvh, x, NULL) == 0, "%s: refit", name);
  Compare(bvh, nseg, x, r, ghost, r, name, "perturbed, refit");
  /* rebuild with a larger margin */
  HYLC_CHECK(HylcBVHBuild(bvh, x, NULL, 1.5 * r) == 0, "%s: rebuild", name);
  Compare(bvh, nseg, x, 1.5 * r, ghost, r, name, "perturbed, rebuilt with margin 1.5 r");
  /* perturb again (0.3 r more), refit the rebuilt tree */
  for (PetscInt k = 0; k < 3 * D.nv; k++) X[k] += 0.3 * r * (2 * HylcTestRand(st) - 1);
  Segments(&D, X, x, ghost);
  HYLC_CHECK(HylcBVHRefit(bvh, x, NULL) == 0, "%s: refit", name);
  Compare(bvh, nseg, x, 1.5 * r, ghost, r, name, "perturbed twice, refit");

  HylcBVHDestroy(&bvh);
  PetscCall(PetscFree3(x, X, ghost));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char               dir[PETSC_MAX_PATH_LEN];
  PetscBool          have;
  const char        *env = getenv("HYLC_REFDATA");
  unsigned long long st  = 2020;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (!have) {
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "skipped: %s not found\n", dir));
    PetscCall(PetscFinalize());
    return 77;
  }
  for (size_t i = 0; i < sizeof(patterns) / sizeof(patterns[0]); i++) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.pyp", dir, patterns[i]));
    PetscCall(TestPattern(path, patterns[i], &st));
  }
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
