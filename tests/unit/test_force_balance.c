/* Force balance of the paper's stored patterns with the per-pattern yarn parameters of config/<name>.yaml
   (docs/method.md §11): ||net force|| / ||bend + twist forces|| over all vertex positions, where the net force
   is the gradient of stretch + bend + twist + contact energy of the periodic tile. The stored patterns are
   (near) equilibria of the paper's model, so this ratio measures how well our model matches theirs.
   HYLC_REPORT=1 prints the table (docs/method.md). Checks: satin_small and honeycomb, whose parameters are
   known with high confidence, balance to better than 15 % (the spec measured 5-10 %). satin_small is checked
   both with its docs/method.md §11 values (given here) and with the values calibrated against the paper's
   table that config/satin_small.yaml holds (docs/method.md). */
#include "tile.h"
#include "hylctest.h"

typedef struct {
  const char *name;
  PetscReal   limit;      /* required ratio, or 0 for report only */
  PetscBool   consistent; /* load with -pattern_consistent_periods (else the stored periods) */
  const char *yarn;       /* yarn values overriding the config (NULL: the config's) */
} Case;

static const Case cases[] = {
    {"satin_small", 0.15, PETSC_FALSE, "-yarn_E 1e6 -yarn_Es 1e6 -yarn_G 4e5 -yarn_kc 70"},
    {"satin_small", 0.15, PETSC_FALSE, NULL},
    {"slip_stitch_honeycomb", 0.15, PETSC_FALSE, NULL},
    {"satin", 0, PETSC_FALSE, NULL},
    {"basket", 0, PETSC_FALSE, NULL},
    {"basket", 0, PETSC_TRUE, NULL},
    {"stockinette_small", 0, PETSC_FALSE, NULL},
    {"stockinette", 0, PETSC_FALSE, NULL},
    {"cartridge_belt_rib", 0, PETSC_FALSE, NULL},
};

static PetscErrorCode Balance(const char *root, const char *dir, const Case *c, PetscBool report)
{
  char          path[PETSC_MAX_PATH_LEN];
  PetscOptions  opt;
  HylcYarnModel m;
  HylcPattern   p;
  HylcTile      T;
  PetscInt      n;
  PetscReal    *g, *gbt, *gs, *gc, *gt, e[4];

  PetscFunctionBegin;
  /* the yarn model from the pattern's config file */
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/config/%s.yaml", root, c->name));
  PetscCall(PetscOptionsCreate(&opt));
  PetscCall(PetscOptionsInsertFile(PETSC_COMM_SELF, opt, path, PETSC_TRUE));
  /* explicit either way: config/basket.yaml sets the consistent periods, the stored ones are a case too */
  PetscCall(PetscOptionsSetValue(opt, "-pattern_consistent_periods", c->consistent ? "true" : "false"));
  if (c->yarn) PetscCall(PetscOptionsInsertString(opt, c->yarn));
  PetscCall(PetscOptionsPush(opt));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, &m));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternSetFromOptions(p)); /* the config's pattern options (its file path is relative to the repository) */
  PetscCall(PetscOptionsPop());
  PetscCall(PetscOptionsDestroy(&opt));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.pyp", dir, c->name));
  PetscCall(HylcPatternLoad(p, path));
  PetscCall(HylcTileCreate(p, &m, &T));
  PetscCall(HylcTileGetSize(T, &n));
  PetscCall(PetscMalloc5(n, &g, n, &gbt, n, &gs, n, &gc, n, &gt));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, g, NULL));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_BEND | HYLC_TERM_TWIST, e, gbt, NULL));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_STRETCH, e, gs, NULL));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_TWIST, e, gt, NULL));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_CONTACT, e, gc, NULL));
  PetscReal net = 0, bt = 0, st = 0, ct = 0, tnet = 0, tbt = 0;
  for (PetscInt i = 0; i < n; i++) {
    if (i % 4 == 3) { /* twist dofs: dE/dtheta */
      tnet += g[i] * g[i];
      tbt += gt[i] * gt[i];
      continue;
    }
    net += g[i] * g[i];
    bt += gbt[i] * gbt[i];
    st += gs[i] * gs[i];
    ct += gc[i] * gc[i];
  }
  const PetscReal ratio = PetscSqrtReal(net / bt);
  if (report)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "| %s%s%s | %.3g | %.3g | %.3g | %.3g | %.3g |\n", c->name, c->consistent ? " (consistent periods)" : "", c->yarn ? " (docs/method.md §11 values)" : "", (double)ratio, (double)PetscSqrtReal(st / bt),
                          (double)PetscSqrtReal(ct / bt), (double)PetscSqrtReal(tnet / PetscMax(tbt, 1e-300)), (double)(e[3])));
  if (c->limit > 0) HYLC_CHECK(ratio < c->limit, "%s: ||net force|| / ||bend + twist forces|| = %.3g, expected < %g", c->name, (double)ratio, (double)c->limit);
  PetscCall(PetscFree5(g, gbt, gs, gc, gt));
  PetscCall(HylcTileDestroy(&T));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char        dir[PETSC_MAX_PATH_LEN];
  PetscBool   have, report = (PetscBool)(getenv("HYLC_REPORT") != NULL);
  const char *env = getenv("HYLC_REFDATA"), *root = getenv("HYLC_ROOT");

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (!have) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "skipped: %s not found (the paper's patterns)\n", dir));
    PetscCall(PetscFinalize());
    return 77;
  }
  if (report) PetscCall(PetscPrintf(PETSC_COMM_SELF, "| pattern | net / (bend+twist) | stretch / (bend+twist) | contact / (bend+twist) | dE/dtheta: net / twist part | contact energy (J) |\n|---|---|---|---|---|---|\n"));
  for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) PetscCall(Balance(root ? root : ".", dir, &cases[k], report));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
