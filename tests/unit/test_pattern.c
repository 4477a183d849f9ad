/* Pattern module: the paper's patterns load with the right sizes, generators produce valid patterns
   that round-trip exactly through .pyp, rest data matches the generated geometry, wovens are free of
   interpenetration, and the loader gives the same pattern on every rank.
   hylc-test: nprocs=2 */
#include <hylc/pattern.h>
#include <hylc/geom.h>
#include "hylctest.h"

typedef struct {
  const char *file;
  PetscInt    nv, nloops, loopsize[4], nsizes; /* distinct loop sizes expected, in loop order pattern */
} RefCase;

/* Expected counts: ../shared/refdata/SOURCES.md and docs/formats.md */
static const RefCase refcases[] = {
    {"stockinette.pyp", 100, 2, {50}, 1},       {"cartridge_belt_rib.pyp", 356, 4, {89}, 1}, {"slip_stitch_honeycomb.pyp", 182, 4, {31, 31, 60, 60}, 4}, {"basket.pyp", 80, 8, {10}, 1}, {"satin.pyp", 130, 10, {13}, 1},
    {"stockinette_small.pyp", 100, 2, {50}, 1}, {"satin_small.pyp", 250, 10, {25}, 1},
};

static PetscErrorCode CheckSamePattern(HylcPattern a, HylcPattern b, const char *what)
{
  HylcPatternData A, B;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetData(a, &A));
  PetscCall(HylcPatternGetData(b, &B));
  HYLC_CHECK(A.nv == B.nv && A.px == B.px && A.py == B.py && A.radius == B.radius, "%s: header differs", what);
  if (A.nv != B.nv) PetscFunctionReturn(PETSC_SUCCESS);
  int bad = 0;
  for (PetscInt v = 0; v < A.nv; v++) {
    for (int d = 0; d < 3; d++) bad += A.X[3 * v + d] != B.X[3 * v + d] || A.refD1[3 * v + d] != B.refD1[3 * v + d];
    for (int d = 0; d < 2; d++) bad += A.restKappa[2 * v + d] != B.restKappa[2 * v + d] || A.shift[2 * v + d] != B.shift[2 * v + d];
    bad += A.theta[v] != B.theta[v] || A.restLength[v] != B.restLength[v] || A.restTwist[v] != B.restTwist[v] || A.refTwist[v] != B.refTwist[v] || A.next[v] != B.next[v];
  }
  HYLC_CHECK(bad == 0, "%s: %d values differ after the round trip", what, bad);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestRefPatterns(const char *dir)
{
  PetscFunctionBegin;
  for (size_t c = 0; c < sizeof(refcases) / sizeof(refcases[0]); c++) {
    char        path[PETSC_MAX_PATH_LEN], out[PETSC_MAX_PATH_LEN];
    HylcPattern p, q;
    PetscInt    nv, nl;
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, refcases[c].file));
    PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &p));
    PetscCall(HylcPatternLoad(p, path));
    PetscCall(HylcPatternGetNumVertices(p, &nv));
    PetscCall(HylcPatternGetNumLoops(p, &nl));
    HYLC_CHECK(nv == refcases[c].nv, "%s: %d vertices, expected %d", refcases[c].file, (int)nv, (int)refcases[c].nv);
    HYLC_CHECK(nl == refcases[c].nloops, "%s: %d loops, expected %d", refcases[c].file, (int)nl, (int)refcases[c].nloops);
    for (PetscInt l = 0; l < nl; l++) {
      PetscInt n, w[2];
      PetscCall(HylcPatternGetLoop(p, l, &n, NULL, w));
      const PetscInt want = refcases[c].nsizes == 1 ? refcases[c].loopsize[0] : refcases[c].loopsize[l];
      HYLC_CHECK(n == want, "%s: loop %d has %d vertices, expected %d", refcases[c].file, (int)l, (int)n, (int)want);
      HYLC_CHECK(PetscAbsInt(w[0]) + PetscAbsInt(w[1]) == 1, "%s: loop %d winding (%d, %d)", refcases[c].file, (int)l, (int)w[0], (int)w[1]);
    }
    /* contact-relevant pairs at the stored state sit at 1.87-1.98 r (docs/method.md §2.3) */
    PetscReal dmin, r;
    PetscCall(HylcPatternGetRadius(p, &r));
    PetscCall(HylcPatternMinSegmentDistance(p, 3.0, &dmin, NULL));
    HYLC_CHECK(dmin > 1.85 * r && dmin < 2.0 * r, "%s: min distance %g r", refcases[c].file, (double)(dmin / r));
    /* exact round trip */
    PetscCall(PetscSNPrintf(out, sizeof(out), "rt_%s", refcases[c].file));
    PetscCall(HylcPatternWrite(p, out));
    PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &q));
    PetscCall(HylcPatternLoad(q, out));
    PetscCall(CheckSamePattern(p, q, refcases[c].file));
    PetscCall(HylcPatternDestroy(&q));
    PetscCall(HylcPatternDestroy(&p));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Rest data of a generated pattern must describe its own geometry: RL = edge length, RK = material
   curvature, RT = reference twist (theta = 0), d1 unit and perpendicular. */
static PetscErrorCode CheckRestData(HylcPattern p, const char *what)
{
  HylcPatternData D;
  PetscReal       maxerr = 0;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetData(p, &D));
  for (PetscInt v = 0; v < D.nv; v++) {
    const PetscInt u = D.prev[v], w = D.next[v];
    PetscReal      te[3], tf[3], kb[3], d2e[3], d2f[3], kap[2];
    for (int d = 0; d < 3; d++) {
      te[d] = D.X[3 * v + d] - D.X[3 * u + d];
      tf[d] = D.X[3 * w + d] - D.X[3 * v + d];
    }
    te[0] += D.shift[2 * u] * D.px;
    te[1] += D.shift[2 * u + 1] * D.py;
    tf[0] += D.shift[2 * v] * D.px;
    tf[1] += D.shift[2 * v + 1] * D.py;
    const PetscReal lf = HylcNormalize3(tf);
    HylcNormalize3(te);
    maxerr = PetscMax(maxerr, PetscAbsReal(lf - D.restLength[v]) / D.restLength[v]);
    maxerr = PetscMax(maxerr, PetscAbsReal(HylcDot3(tf, D.refD1 + 3 * v)));
    maxerr = PetscMax(maxerr, PetscAbsReal(HylcNorm3(D.refD1 + 3 * v) - 1));
    HylcCurvatureBinormal(te, tf, kb);
    HylcCross3(te, D.refD1 + 3 * u, d2e);
    HylcCross3(tf, D.refD1 + 3 * v, d2f);
    HylcMaterialCurvature(kb, D.refD1 + 3 * u, d2e, D.refD1 + 3 * v, d2f, kap);
    maxerr = PetscMax(maxerr, PetscAbsReal(kap[0] - D.restKappa[2 * v]) + PetscAbsReal(kap[1] - D.restKappa[2 * v + 1]));
    maxerr = PetscMax(maxerr, PetscAbsReal(HylcReferenceTwist(te, D.refD1 + 3 * u, tf, D.refD1 + 3 * v) - D.refTwist[v]));
    maxerr = PetscMax(maxerr, PetscAbsReal(D.refTwist[v] - D.restTwist[v]) + PetscAbsReal(D.theta[v]));
  }
  HYLC_CHECK(maxerr < 1e-10, "%s: rest data differs from the geometry by %g", what, (double)maxerr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestGenerators(void)
{
  const char    *types[] = {HYLCPATTERNPLAIN, HYLCPATTERNBASKET, HYLCPATTERNTWILL, HYLCPATTERNSATIN, HYLCPATTERNSTOCKINETTE, HYLCPATTERNRIB};
  const PetscInt rep[]   = {2, 4, 4, 5, 1, 2};

  PetscFunctionBegin;
  for (size_t t = 0; t < sizeof(types) / sizeof(types[0]); t++) {
    HylcPatternGenParams g;
    HylcPattern          p, q;
    char                 out[64];
    PetscBool            woven = (PetscBool)(t < 4);
    PetscCall(HylcPatternGenParamsDefault(&g));
    for (int sz = 0; sz < 2; sz++) {
      g.radius  = sz ? 1e-4 : 1e-3;
      g.size[0] = rep[t] * (sz ? 2 : 1);
      g.size[1] = rep[t] * (woven ? 1 : 2);
      PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &p));
      PetscCall(HylcPatternGenerate(p, types[t], &g));
      PetscCall(CheckRestData(p, types[t]));
      /* loops: wovens have size[1] x-yarns and size[0] y-yarns; knits one yarn per course */
      PetscInt nl;
      PetscCall(HylcPatternGetNumLoops(p, &nl));
      HYLC_CHECK(nl == (woven ? g.size[0] + g.size[1] : g.size[1]), "%s: %d loops", types[t], (int)nl);
      if (woven) {
        PetscReal dmin;
        PetscCall(HylcPatternMinSegmentDistance(p, 3.0, &dmin, NULL));
        HYLC_CHECK(dmin >= 2 * g.radius, "%s: interpenetrates, min distance %g r", types[t], (double)(dmin / g.radius));
      }
      PetscCall(PetscSNPrintf(out, sizeof(out), "gen_%s_%d.pyp", types[t], sz));
      PetscCall(HylcPatternWrite(p, out));
      PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &q));
      PetscCall(HylcPatternLoad(q, out)); /* passes the reader's validation */
      PetscCall(CheckSamePattern(p, q, types[t]));
      PetscCall(HylcPatternDestroy(&q));
      PetscCall(HylcPatternDestroy(&p));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The same file gives the same pattern on every rank. */
static PetscErrorCode TestParallelConsistency(void)
{
  HylcPattern          p;
  HylcPatternGenParams g;
  HylcPatternData      D;
  PetscReal            sum = 0, mn, mx;

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNTWILL, &g));
  PetscCall(HylcPatternWrite(p, "par.pyp"));
  PetscCall(HylcPatternLoad(p, "par.pyp"));
  PetscCall(HylcPatternGetData(p, &D));
  for (PetscInt k = 0; k < 3 * D.nv; k++) sum += D.X[k] * (k + 1) + D.refD1[k];
  PetscCall(MPIU_Allreduce(&sum, &mn, 1, MPIU_REAL, MPIU_MIN, PETSC_COMM_WORLD));
  PetscCall(MPIU_Allreduce(&sum, &mx, 1, MPIU_REAL, MPIU_MAX, PETSC_COMM_WORLD));
  HYLC_CHECK(mn == mx, "ranks disagree: %.17g vs %.17g", (double)mn, (double)mx);
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char      dir[PETSC_MAX_PATH_LEN] = "";
  PetscBool have;
  int       skipped = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  {
    const char *env = getenv("HYLC_REFDATA");
    PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  }
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (have)
    PetscCall(TestRefPatterns(dir));
  else
    skipped = 1;
  PetscCall(TestGenerators());
  PetscCall(TestParallelConsistency());
  int fails = hylc_test_failures, all;
  MPI_Allreduce(&fails, &all, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD);
  if (skipped && !all) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "note: %s not found: the paper-pattern checks were skipped\n", dir));
  PetscCall(PetscFinalize());
  return all ? 1 : 0;
}
