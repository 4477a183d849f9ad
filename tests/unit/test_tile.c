/* HylcTile: finite-difference checks of the tile gradient and Hessian (including contact across periodic
   boundaries), translation invariance, the tile versus its 2x1 and 1x2 supercells, and a straight
   periodic yarn stretched by eps (E = 1/2 ks eps^2 L). */
#include "tile.h"
#include "hylctest.h"

/* a compressed plain weave: spacing 4r compressed to 3.6r so that yarns touch */
static PetscErrorCode MakeWeave(HylcPattern *p)
{
  HylcPatternGenParams g;

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  g.radius = 1e-3;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, p));
  PetscCall(HylcPatternGenerate(*p, HYLCPATTERNPLAIN, &g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Perturb(PetscInt n, PetscReal q[], PetscReal amp, PetscReal tamp, unsigned long long *st)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) q[i] += (i % 4 == 3 ? tamp : amp) * (2 * HylcTestRand(st) - 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* FD check of g and H at the tile's current state (frames fixed). */
static PetscErrorCode CheckDerivatives(HylcTile T, const char *what, PetscReal r)
{
  PetscInt   n;
  PetscReal *q, *g, *gp, *gm, parts[4], Ep[4], Em[4];
  Mat        H;

  PetscFunctionBegin;
  PetscCall(HylcTileGetSize(T, &n));
  PetscCall(PetscMalloc4(n, &q, n, &g, n, &gp, n, &gm));
  PetscCall(HylcTileCreateMatrix(T, &H));
  PetscCall(HylcTileGetState(T, q));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, parts, g, H));
  PetscReal gmax = 0, gerr = 0, hmax = 0, herr = 0;
  for (PetscInt i = 0; i < n; i++) gmax = PetscMax(gmax, PetscAbsReal(g[i]));
  PetscCall(MatNorm(H, NORM_MAX, &hmax));
  for (PetscInt i = 0; i < n; i++) {
    const PetscReal h = (i % 4 == 3) ? 1e-6 : 1e-6 * r, q0 = q[i];
    q[i] = q0 + h;
    PetscCall(HylcTileSetState(T, q));
    PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, Ep, gp, NULL));
    q[i] = q0 - h;
    PetscCall(HylcTileSetState(T, q));
    PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, Em, gm, NULL));
    q[i]               = q0;
    const PetscReal fd = ((Ep[0] + Ep[1] + Ep[2] + Ep[3]) - (Em[0] + Em[1] + Em[2] + Em[3])) / (2 * h);
    gerr               = PetscMax(gerr, PetscAbsReal(fd - g[i]));
    /* column i of H against the FD of the gradient (H is symmetric) */
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(H, i, &nc, &cols, &vals));
    PetscInt c = 0;
    for (PetscInt j = 0; j < n; j++) {
      PetscReal hij = 0;
      while (c < nc && cols[c] < j) c++;
      if (c < nc && cols[c] == j) hij = PetscRealPart(vals[c]);
      herr = PetscMax(herr, PetscAbsReal((gp[j] - gm[j]) / (2 * h) - hij) * ((i % 4 == 3) == (j % 4 == 3) ? 1.0 : 1.0));
    }
    PetscCall(MatRestoreRow(H, i, &nc, &cols, &vals));
  }
  PetscCall(HylcTileSetState(T, q));
  HYLC_CHECK(gerr <= 1e-6 * gmax, "%s: gradient FD error %g relative to max |g| %g", what, (double)gerr, (double)gmax);
  HYLC_CHECK(herr <= 1e-5 * hmax, "%s: Hessian FD error %g relative to max |H| %g", what, (double)herr, (double)hmax);
  PetscCall(MatDestroy(&H));
  PetscCall(PetscFree4(q, g, gp, gm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestDerivatives(void)
{
  HylcPattern        p;
  HylcTile           T;
  HylcYarnModel      m;
  PetscInt           n, np;
  PetscReal         *q;
  unsigned long long st = 7;

  PetscFunctionBegin;
  PetscCall(MakeWeave(&p));
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50; /* strong contact so that every term matters */
  for (int variant = 0; variant < 2; variant++) {
    m.contactType = variant ? HYLC_CONTACT_CLOSEST : HYLC_CONTACT_QUADRATURE;
    PetscCall(HylcTileCreate(p, &m, &T));
    /* compress the lattice by 12% so that crossing yarns overlap, also across the periodic boundary */
    const PetscReal L1[3] = {0.88 * 8e-3, 0, 0}, L2[3] = {0, 0.88 * 8e-3, 0};
    PetscCall(HylcTileSetLattice(T, L1, L2));
    PetscCall(HylcTileGetSize(T, &n));
    PetscCall(PetscMalloc1(n, &q));
    PetscCall(HylcTileGetState(T, q));
    for (PetscInt v = 0; v < n / 4; v++) {
      q[4 * v] *= 0.88;
      q[4 * v + 1] *= 0.88;
    }
    PetscCall(Perturb(n, q, 0.05e-3, 0.3, &st));
    PetscCall(HylcTileSetState(T, q));
    PetscCall(HylcTileGetNumContactPairs(T, &np));
    HYLC_CHECK(np > 8, "too few contact pairs (%d) for a meaningful test", (int)np);
    PetscCall(CheckDerivatives(T, variant ? "closest-point contact" : "quadrature contact", 1e-3));
    PetscCall(PetscFree(q));
    PetscCall(HylcTileDestroy(&T));
  }
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal Sum(const PetscReal e[4]) { return e[0] + e[1] + e[2] + e[3]; }

/* Translation invariance and tile vs supercell at random periodic states. */
static PetscErrorCode TestSupercellAndTranslation(HylcPattern p, const char *what, PetscReal compress)
{
  HylcTile           T, S;
  HylcPattern        sp;
  HylcYarnModel      m;
  PetscInt           n, ns;
  PetscReal         *q, *qs, e[4], es[4], px, py, r;
  unsigned long long st = 11;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcPatternGetPeriods(p, &px, &py));
  PetscCall(HylcPatternGetRadius(p, &r));
  for (int dir = 0; dir < 2; dir++) {
    const PetscInt nx = dir ? 1 : 2, ny = dir ? 2 : 1;
    PetscCall(HylcPatternCreateSupercell(p, nx, ny, &sp));
    PetscCall(HylcTileCreate(p, &m, &T));
    PetscCall(HylcTileCreate(sp, &m, &S));
    const PetscReal L1[3] = {compress * px, 0, 0}, L2[3] = {0, compress * py, 0}, L1s[3] = {nx * compress * px, 0, 0}, L2s[3] = {0, ny * compress * py, 0};
    PetscCall(HylcTileSetLattice(T, L1, L2));
    PetscCall(HylcTileSetLattice(S, L1s, L2s));
    PetscCall(HylcTileGetSize(T, &n));
    PetscCall(HylcTileGetSize(S, &ns));
    PetscCall(PetscMalloc2(n, &q, ns, &qs));
    PetscCall(HylcTileGetState(T, q));
    for (PetscInt v = 0; v < n / 4; v++) {
      q[4 * v] *= compress;
      q[4 * v + 1] *= compress;
    }
    PetscCall(Perturb(n, q, 0.1 * r, 0.5, &st));
    for (PetscInt c = 0; c < nx * ny; c++)
      for (PetscInt i = 0; i < n; i++) qs[c * n + i] = q[i];
    for (PetscInt c = 0; c < nx * ny; c++)
      for (PetscInt v = 0; v < n / 4; v++) {
        qs[c * n + 4 * v] += (c % nx) * compress * px;
        qs[c * n + 4 * v + 1] += (c / nx) * compress * py;
      }
    PetscCall(HylcTileSetState(T, q));
    PetscCall(HylcTileSetState(S, qs));
    PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, NULL, NULL));
    PetscCall(HylcTileEvaluate(S, HYLC_TERM_ALL, es, NULL, NULL));
    HYLC_CHECK(e[3] > 0, "%s: no contact energy in the test state", what);
    for (int k = 0; k < 4; k++) HYLC_CHECK(PetscAbsReal(es[k] - 2 * e[k]) <= 1e-12 * PetscAbsReal(es[k]) + 1e-300, "%s %dx%d: part %d: supercell %.17g vs 2 x tile %.17g", what, (int)nx, (int)ny, k, (double)es[k], (double)(2 * e[k]));
    /* rigid translation of the whole state */
    for (PetscInt v = 0; v < n / 4; v++) {
      q[4 * v] += 0.37 * px;
      q[4 * v + 1] -= 1.3 * py;
      q[4 * v + 2] += 2 * r;
    }
    PetscCall(HylcTileSetState(T, q));
    PetscReal et[4];
    PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, et, NULL, NULL));
    HYLC_CHECK(PetscAbsReal(Sum(et) - Sum(e)) <= 1e-11 * Sum(e), "%s: translation changes the energy: %.17g vs %.17g", what, (double)Sum(et), (double)Sum(e));
    PetscCall(PetscFree2(q, qs));
    PetscCall(HylcTileDestroy(&T));
    PetscCall(HylcTileDestroy(&S));
    PetscCall(HylcPatternDestroy(&sp));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A straight periodic yarn along x stretched by eps: E = 1/2 ks eps^2 L. */
static PetscErrorCode TestStretchedYarn(void)
{
  const PetscInt    N  = 8;
  const PetscReal   px = 8e-3, py = 5e-3, r = 1e-3, eps = 0.07;
  PetscReal         pts[3 * 8];
  PetscInt          nv[1] = {N}, w[2] = {1, 0};
  HylcPattern       p;
  HylcTile          T;
  HylcYarnModel     m;
  HylcYarnConstants c;
  PetscReal         q[4 * 8], e[4], g[4 * 8];

  PetscFunctionBegin;
  for (PetscInt k = 0; k < N; k++) {
    pts[3 * k]     = -0.5 * px + (k + 0.5) * px / N;
    pts[3 * k + 1] = 0;
    pts[3 * k + 2] = 0;
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternSetFromCurves(p, px, py, r, 1, nv, w, pts));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcTileCreate(p, &m, &T));
  PetscCall(HylcTileGetConstants(T, &c));
  const PetscReal L1[3] = {(1 + eps) * px, 0, 0}, L2[3] = {0, py, 0};
  PetscCall(HylcTileSetLattice(T, L1, L2));
  PetscCall(HylcTileGetState(T, q));
  for (PetscInt v = 0; v < N; v++) q[4 * v] *= 1 + eps;
  PetscCall(HylcTileSetState(T, q));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e, g, NULL));
  const PetscReal exact = 0.5 * c.ks * eps * eps * px;
  HYLC_CHECK(PetscAbsReal(e[0] - exact) <= 1e-12 * exact, "stretched yarn: %.17g vs %.17g", (double)e[0], (double)exact);
  HYLC_CHECK(PetscAbsReal(e[1]) + PetscAbsReal(e[2]) + PetscAbsReal(e[3]) <= 1e-20, "stretched yarn: bend/twist/contact %g %g %g", (double)e[1], (double)e[2], (double)e[3]);
  PetscReal gmax = 0;
  for (PetscInt i = 0; i < 4 * N; i++) gmax = PetscMax(gmax, PetscAbsReal(g[i]));
  HYLC_CHECK(gmax <= 1e-12 * c.ks * eps, "stretched yarn is not in equilibrium: max |g| = %g", (double)gmax);
  PetscCall(HylcTileDestroy(&T));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* frames: after UpdateFrames at a new state the energy is unchanged and the reference twist has no 2 pi jumps */
static PetscErrorCode TestFrameUpdate(void)
{
  HylcPattern        p;
  HylcTile           T;
  HylcYarnModel      m;
  PetscInt           n;
  PetscReal         *q, e0[4], e1[4];
  unsigned long long st = 3;

  PetscFunctionBegin;
  PetscCall(MakeWeave(&p));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcTileCreate(p, &m, &T));
  PetscCall(HylcTileGetSize(T, &n));
  PetscCall(PetscMalloc1(n, &q));
  PetscCall(HylcTileGetState(T, q));
  for (int step = 0; step < 20; step++) { /* a path of small moves with large accumulated twist */
    PetscCall(Perturb(n, q, 0.02e-3, 0.4, &st));
    PetscCall(HylcTileSetState(T, q));
    PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e0, NULL, NULL));
    PetscCall(HylcTileUpdateFrames(T));
    PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, e1, NULL, NULL));
    for (int k = 0; k < 4; k++) HYLC_CHECK(PetscAbsReal(e1[k] - e0[k]) <= 1e-9 * PetscAbsReal(e0[k]) + 1e-30, "frame update changes energy part %d: %.17g vs %.17g", k, (double)e1[k], (double)e0[k]);
  }
  PetscCall(PetscFree(q));
  PetscCall(HylcTileDestroy(&T));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  HylcPattern p;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestDerivatives());
  PetscCall(TestStretchedYarn());
  PetscCall(TestFrameUpdate());
  PetscCall(MakeWeave(&p));
  PetscCall(TestSupercellAndTranslation(p, "plain weave", 0.9));
  PetscCall(HylcPatternDestroy(&p));
  {
    HylcPatternGenParams g;
    PetscCall(HylcPatternGenParamsDefault(&g));
    PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
    PetscCall(HylcPatternGenerate(p, HYLCPATTERNSTOCKINETTE, &g));
    PetscCall(TestSupercellAndTranslation(p, "stockinette", 1.0));
    PetscCall(HylcPatternDestroy(&p));
  }
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
