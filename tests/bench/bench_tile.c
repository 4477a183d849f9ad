/* Benchmark: one full energy + gradient + Hessian evaluation of the paper's stockinette and rib tiles
   (HylcTile: stretch, bend, twist, quadrature contact with 4x4 points, broadphase, COO assembly), and
   the broadphase's speed-up over brute force on the tile with its periodic copies. Prints its figures. */
#include "tile.h"
#include <hylc/contact.h>
#include <petsctime.h>

static PetscErrorCode Bench(const char *dir, const char *name)
{
  char           path[PETSC_MAX_PATH_LEN];
  HylcPattern    p;
  HylcTile       T;
  HylcYarnModel  m;
  Mat            H;
  PetscInt       n, np, reps = 50;
  PetscReal     *g, e[4];
  PetscLogDouble t0, t1, tE, tEg, tEgH, tFirst;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.pyp", dir, name));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternLoad(p, path));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcTileCreate(p, &m, &T));
  PetscCall(HylcTileGetSize(T, &n));
  PetscCall(PetscMalloc1(n, &g));
  PetscCall(HylcTileCreateMatrix(T, &H));
  PetscCall(PetscTime(&t0));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, g, H));
  PetscCall(PetscTime(&t1));
  tFirst = t1 - t0;
  PetscCall(HylcTileGetNumContactPairs(T, &np));
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, NULL, NULL));
  PetscCall(PetscTime(&t1));
  tE = (t1 - t0) / reps;
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, g, NULL));
  PetscCall(PetscTime(&t1));
  tEg = (t1 - t0) / reps;
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, g, H));
  PetscCall(PetscTime(&t1));
  tEgH = (t1 - t0) / reps;
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-20s %4d vertices, %4d contact pairs: E %.3f ms, E+g %.3f ms, E+g+H %.3f ms (first call with Hessian preallocation %.3f ms)\n", name, (int)(n / 4), (int)np, 1e3 * tE, 1e3 * tEg, 1e3 * tEgH, 1e3 * tFirst));

  /* broadphase vs brute force over the tile and its 8 neighbouring copies */
  {
    HylcPatternData D;
    const PetscInt  N = n / 4, S = 9 * N;
    double         *x;
    unsigned char  *ghost;
    HylcPairList    a = {0}, b = {0};
    HylcBVH         bvh;
    PetscInt        k = 0;
    PetscCall(HylcPatternGetData(p, &D));
    PetscCall(PetscMalloc2(6 * S, &x, S, &ghost));
    for (PetscInt s1 = -1; s1 <= 1; s1++)
      for (PetscInt s2 = -1; s2 <= 1; s2++)
        for (PetscInt v = 0; v < N; v++, k++) {
          const PetscInt w = D.next[v];
          for (int d = 0; d < 3; d++) {
            x[6 * k + d]     = D.X[3 * v + d] + (d == 0 ? s1 * D.px : d == 1 ? s2 * D.py : 0);
            x[6 * k + 3 + d] = D.X[3 * w + d] + (d == 0 ? (s1 + D.shift[2 * v]) * D.px : d == 1 ? (s2 + D.shift[2 * v + 1]) * D.py : 0);
          }
          ghost[k] = (unsigned char)(s1 || s2);
        }
    PetscCheck(!HylcBVHCreate((int)S, &bvh) && !HylcBVHBuild(bvh, x, NULL, D.radius) && !HylcBVHSetGhost(bvh, ghost), PETSC_COMM_SELF, PETSC_ERR_MEM, "BVH");
    PetscCall(PetscTime(&t0));
    for (PetscInt r = 0; r < reps; r++) {
      PetscCheck(!HylcBVHRefit(bvh, x, NULL), PETSC_COMM_SELF, PETSC_ERR_MEM, "BVH");
      PetscCheck(!HylcBVHQuery(bvh, &a), PETSC_COMM_SELF, PETSC_ERR_MEM, "BVH");
    }
    PetscCall(PetscTime(&t1));
    const PetscLogDouble tb = (t1 - t0) / reps;
    PetscCall(PetscTime(&t0));
    for (PetscInt r = 0; r < 5; r++) PetscCheck(!HylcBroadphaseBruteForce((int)S, x, NULL, D.radius, ghost, &b), PETSC_COMM_SELF, PETSC_ERR_MEM, "brute");
    PetscCall(PetscTime(&t1));
    const PetscLogDouble tbf = (t1 - t0) / 5;
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-20s broadphase over %d segments (tile + 8 copies): %zu candidate pairs, refit+query %.3f ms, brute force %.3f ms, speed-up %.1fx\n", name, (int)S, a.n, 1e3 * tb, 1e3 * tbf, tbf / tb));
    HylcPairListFree(&a);
    HylcPairListFree(&b);
    HylcBVHDestroy(&bvh);
    PetscCall(PetscFree2(x, ghost));
  }
  PetscCall(MatDestroy(&H));
  PetscCall(PetscFree(g));
  PetscCall(HylcTileDestroy(&T));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char      dir[PETSC_MAX_PATH_LEN];
  PetscBool have;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  const char *env = getenv("HYLC_REFDATA");
  PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (!have)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "bench_tile: %s not found; skipped\n", dir));
  else {
    PetscCall(Bench(dir, "stockinette"));
    PetscCall(Bench(dir, "cartridge_belt_rib"));
    PetscCall(Bench(dir, "satin_small"));
  }
  PetscCall(PetscFinalize());
  return 0;
}
