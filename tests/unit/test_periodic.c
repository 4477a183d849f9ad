/* HylcPeriodic: ghost extension with fractional weights, elimination and reduced assembly.
   - II = 0: the energy equals the translation-periodic HylcTile energy, and a tile has half the energy of
     its 2x1 (and 1x2) supercell, at random periodic states, for a woven and a knitted pattern; also with
     every vertex moved by up to 3 r (contacts with copies that were far on the initial guess: with the
     former pruning of the contact ghosts on the initial guess, -periodic_margin 0.25, the supercell
     check fails here);
   - finite-difference checks of g_y and H_y at bent and sheared strains, with contact across the periodic
     boundaries;
   - a straight periodic yarn bent by II00 = kappa has bending energy 1/2 B kappa^2 L at the initial guess,
     with a discretization error of second order in the edge length;
   - the constraints hold at the initial guess;
   - straight yarns (one, two parallel, two crossing families, diagonal): with every slide variant the rows
     that repeat the translation (or each other) are dropped, flat, sheared and bent. */
#include <hylc/periodic.h>
#include "tile.h"
#include "hylctest.h"

static PetscErrorCode Perturb(PetscInt n, PetscReal q[], PetscReal amp, PetscReal tamp, unsigned long long *st)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) q[i] += (i % 4 == 3 ? tamp : amp) * (2 * HylcTestRand(st) - 1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Generate(const char *type, PetscReal spacingFactor, HylcPattern *p)
{
  HylcPatternGenParams g;

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  if (spacingFactor > 0) g.spacing = spacingFactor * g.radius;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, p));
  PetscCall(HylcPatternGenerate(*p, type, &g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal Sum(const PetscReal e[4]) { return e[0] + e[1] + e[2] + e[3]; }

/* II = 0: HylcPeriodic vs HylcTile, and tile vs supercell */
static PetscErrorCode TestFlat(HylcPattern p, const char *what, const PetscReal z[6], PetscReal amp, PetscReal margin)
{
  HylcYarnModel          m;
  HylcPeriodic           P, Q;
  HylcTile               T;
  HylcPattern            sp;
  PetscInt               n, ns;
  PetscReal             *y, *ys, e[4], et[4], es[4], px, py;
  const HylcMacroStrain *ms;
  unsigned long long     st = 5;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcPatternGetPeriods(p, &px, &py));
  PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
  PetscCall(HylcPeriodicSetPattern(P, p, &m));
  PetscCall(HylcPeriodicSetStrain(P, z));
  PetscCall(HylcPeriodicSetContactMargin(P, margin));
  PetscCall(HylcPeriodicSetUp(P));
  PetscCall(HylcPeriodicGetSizes(P, &n, NULL, NULL, NULL));
  PetscCall(PetscMalloc1(n, &y));
  PetscCall(HylcPeriodicGetInitialState(P, y));
  PetscCall(Perturb(n, y, amp, 0.4, &st));
  PetscCall(HylcPeriodicSetState(P, y));
  PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, e, NULL, NULL));
  HYLC_CHECK(e[3] > 0, "%s: no contact in the test state", what);
  /* the same state in HylcTile with the lattice S (px, 0), S (0, py) */
  PetscCall(HylcPeriodicGetMacroStrain(P, &ms));
  PetscCall(HylcTileCreate(p, &m, &T));
  {
    const PetscReal L1[3] = {ms->A[0] * px, ms->A[2] * px, 0}, L2[3] = {ms->A[1] * py, ms->A[3] * py, 0};
    PetscCall(HylcTileSetLattice(T, L1, L2));
  }
  PetscCall(HylcTileSetState(T, y));
  PetscCall(HylcTileEvaluate(T, HYLC_TERM_ALL, et, NULL, NULL));
  /* the two assemble the same elements; bend and twist depend on the stored reference frames, which
     are the same only at z = 0 (HylcPeriodic projects them onto the deformed initial guess) */
  const PetscBool zero = (PetscBool)(!z[0] && !z[1] && !z[2]);
  for (int k = 0; k < 4; k++)
    if (zero || k == 0 || k == 3) HYLC_CHECK(PetscAbsReal(e[k] - et[k]) <= 1e-9 * PetscAbsReal(et[k]) + 1e-30, "%s: part %d: periodic %.17g vs tile %.17g", what, k, (double)e[k], (double)et[k]);
  /* supercells */
  for (int dir = 0; dir < 2; dir++) {
    const PetscInt nx = dir ? 1 : 2, ny = dir ? 2 : 1;
    PetscCall(HylcPatternCreateSupercell(p, nx, ny, &sp));
    PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &Q));
    PetscCall(HylcPeriodicSetPattern(Q, sp, &m));
    PetscCall(HylcPeriodicSetStrain(Q, z));
    PetscCall(HylcPeriodicSetUp(Q));
    PetscCall(HylcPeriodicGetSizes(Q, &ns, NULL, NULL, NULL));
    PetscCall(PetscMalloc1(ns, &ys));
    /* the periodic state of the tile, repeated: copy c at y + S (i px, j py) */
    for (PetscInt c = 0; c < nx * ny; c++)
      for (PetscInt v = 0; v < n / 4; v++) {
        const PetscReal sx = (c % nx) * px, sy = (c / nx) * py;
        ys[c * n + 4 * v + 0] = y[4 * v + 0] + ms->A[0] * sx + ms->A[1] * sy;
        ys[c * n + 4 * v + 1] = y[4 * v + 1] + ms->A[2] * sx + ms->A[3] * sy;
        ys[c * n + 4 * v + 2] = y[4 * v + 2];
        ys[c * n + 4 * v + 3] = y[4 * v + 3];
      }
    PetscCall(HylcPeriodicSetState(Q, ys));
    PetscCall(HylcPeriodicEvaluate(Q, HYLC_TERM_ALL, es, NULL, NULL));
    for (int k = 0; k < 4; k++) HYLC_CHECK(PetscAbsReal(es[k] - 2 * e[k]) <= 1e-12 * PetscAbsReal(es[k]) + 1e-30, "%s %dx%d: part %d: supercell %.17g vs 2 x tile %.17g", what, (int)nx, (int)ny, k, (double)es[k], (double)(2 * e[k]));
    HYLC_CHECK(PetscAbsReal(Sum(es) - 2 * Sum(e)) <= 1e-12 * Sum(es), "%s: total", what);
    PetscCall(PetscFree(ys));
    PetscCall(HylcPeriodicDestroy(&Q));
    PetscCall(HylcPatternDestroy(&sp));
  }
  PetscCall(PetscFree(y));
  PetscCall(HylcTileDestroy(&T));
  PetscCall(HylcPeriodicDestroy(&P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* FD check of the reduced gradient and Hessian */
static PetscErrorCode TestDerivatives(HylcPattern p, const char *what, const PetscReal z[6], HylcContactType ct)
{
  HylcYarnModel      m;
  HylcPeriodic       P;
  PetscInt           n, np;
  PetscReal         *y, *g, *gp, *gm, e[4], ep[4], em[4], r;
  Mat                H;
  unsigned long long st = 9;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelDefault(&m));
  m.kc          = 30;
  m.contactType = ct;
  PetscCall(HylcPatternGetRadius(p, &r));
  PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
  PetscCall(HylcPeriodicSetPattern(P, p, &m));
  PetscCall(HylcPeriodicSetStrain(P, z));
  PetscCall(HylcPeriodicSetUp(P));
  PetscCall(HylcPeriodicGetSizes(P, &n, NULL, NULL, NULL));
  PetscCall(PetscMalloc4(n, &y, n, &g, n, &gp, n, &gm));
  PetscCall(HylcPeriodicGetInitialState(P, y));
  PetscCall(Perturb(n, y, 0.05 * r, 0.3, &st));
  PetscCall(HylcPeriodicSetState(P, y));
  PetscCall(HylcPeriodicGetNumContactPairs(P, &np));
  PetscCall(HylcPeriodicCreateMatrix(P, &H));
  PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, e, g, H));
  HYLC_CHECK(e[3] > 0 && np > 4, "%s: no contact in the test state", what);
  { /* pairs closer than 2 r exist, so the clearance (computed with the pair lists) is below 2 r */
    PetscReal d;
    PetscCall(HylcPeriodicGetClearance(P, &d));
    HYLC_CHECK(d > 0 && d < 2 * r, "%s: clearance %g with %d pairs closer than 2 r = %g", what, (double)d, (int)np, (double)(2 * r));
  }
  PetscReal gmax = 0, hmax, gerr = 0, herr = 0;
  for (PetscInt i = 0; i < n; i++) gmax = PetscMax(gmax, PetscAbsReal(g[i]));
  PetscCall(MatNorm(H, NORM_MAX, &hmax));
  for (PetscInt i = 0; i < n; i++) {
    const PetscReal h = (i % 4 == 3) ? 1e-6 : 1e-6 * r, y0 = y[i];
    y[i] = y0 + h;
    PetscCall(HylcPeriodicSetState(P, y));
    PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, ep, gp, NULL));
    y[i] = y0 - h;
    PetscCall(HylcPeriodicSetState(P, y));
    PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, em, gm, NULL));
    y[i] = y0;
    gerr = PetscMax(gerr, PetscAbsReal((Sum(ep) - Sum(em)) / (2 * h) - g[i]));
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(H, i, &nc, &cols, &vals));
    PetscInt c = 0;
    for (PetscInt j = 0; j < n; j++) {
      PetscReal hij = 0;
      while (c < nc && cols[c] < j) c++;
      if (c < nc && cols[c] == j) hij = PetscRealPart(vals[c]);
      herr = PetscMax(herr, PetscAbsReal((gp[j] - gm[j]) / (2 * h) - hij));
    }
    PetscCall(MatRestoreRow(H, i, &nc, &cols, &vals));
  }
  HYLC_CHECK(gerr <= 1e-6 * gmax, "%s: gradient FD error %g, max |g| %g", what, (double)gerr, (double)gmax);
  HYLC_CHECK(herr <= 1e-5 * hmax, "%s: Hessian FD error %g, max |H| %g", what, (double)herr, (double)hmax);
  /* constraints hold at the initial guess */
  {
    PetscInt  nc;
    PetscReal c[64], y0[4 * 1024];
    PetscCheck(n <= 4 * 1024, PETSC_COMM_SELF, PETSC_ERR_SUP, "test buffer");
    PetscCall(HylcPeriodicGetConstraints(P, &nc, NULL, NULL, NULL));
    PetscCall(HylcPeriodicGetInitialState(P, y0));
    PetscCall(HylcPeriodicConstraintResidual(P, y0, c));
    for (PetscInt i = 0; i < nc; i++) HYLC_CHECK(PetscAbsReal(c[i]) <= 1e-12 * r, "%s: constraint %d residual %g at the initial guess", what, (int)i, (double)c[i]);
  }
  PetscCall(MatDestroy(&H));
  PetscCall(PetscFree4(y, g, gp, gm));
  PetscCall(HylcPeriodicDestroy(&P));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* straight periodic yarn along x bent by II00 = kappa */
static PetscErrorCode BentYarnEnergy(PetscInt N, PetscReal kappa, PetscReal *Eb, PetscReal *exact)
{
  const PetscReal   px = 8e-3, py = 20e-3, r = 1e-3;
  PetscReal        *pts;
  PetscInt          nv[1] = {N}, w[2] = {1, 0};
  HylcPattern       p;
  HylcPeriodic      P;
  HylcYarnModel     m;
  HylcYarnConstants c;
  PetscReal         e[4], z[6] = {0, 0, 0, kappa, 0, 0};

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(3 * N, &pts));
  for (PetscInt k = 0; k < N; k++) {
    pts[3 * k]     = -0.5 * px + (k + 0.5) * px / N;
    pts[3 * k + 1] = 0;
    pts[3 * k + 2] = 0;
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternSetFromCurves(p, px, py, r, 1, nv, w, pts));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
  PetscCall(HylcPeriodicSetPattern(P, p, &m));
  PetscCall(HylcPeriodicSetStrain(P, z));
  PetscCall(HylcPeriodicSetUp(P)); /* default slide constraint: its row repeats the translation and is dropped */
  PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, e, NULL, NULL));
  PetscCall(HylcPeriodicGetConstants(P, &c));
  *Eb    = e[1];
  *exact = 0.5 * c.B * kappa * kappa * px;
  HYLC_CHECK(e[2] <= 1e-12 * e[1], "bent yarn has twist energy %g", (double)e[2]);
  HYLC_CHECK(e[3] == 0, "bent yarn has contact energy %g", (double)e[3]);
  PetscCall(HylcPeriodicDestroy(&P));
  PetscCall(HylcPatternDestroy(&p));
  PetscCall(PetscFree(pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestBentYarn(void)
{
  PetscReal err[3], Eb = 0, ex = 1;
  PetscInt  Ns[3] = {8, 16, 32};

  PetscFunctionBegin;
  for (int i = 0; i < 3; i++) {
    PetscCall(BentYarnEnergy(Ns[i], 150.0, &Eb, &ex));
    err[i] = PetscAbsReal(Eb - ex) / ex;
  }
  HYLC_CHECK(err[2] < 1e-3, "bent yarn: relative error %g at 32 edges", (double)err[2]);
  for (int i = 0; i < 2; i++) {
    const PetscReal order = PetscLog2Real(err[i] / err[i + 1]);
    HYLC_CHECK(order > 1.9 && order < 2.1, "bent yarn: convergence order %g (errors %g, %g)", (double)order, (double)err[i], (double)err[i + 1]);
  }
  if (getenv("HYLC_REPORT")) PetscCall(PetscPrintf(PETSC_COMM_SELF, "bent yarn, kappa = 150/m: relative errors %.3e %.3e %.3e for 8, 16, 32 edges\n", (double)err[0], (double)err[1], (double)err[2]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the three slide-constraint variants: row counts, residual 0 at the initial guess, A A^T (A A^T)^-1 = I */
static PetscErrorCode TestConstraints(HylcPattern p)
{
  HylcYarnModel   m;
  const PetscReal z[6] = {0.1, 0.2, 0, 100, 0, 0};
  PetscInt        nloops;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcPatternGetNumLoops(p, &nloops));
  for (int sl = 0; sl < 3; sl++) {
    HylcPeriodic     P;
    PetscInt         n, nc;
    const PetscReal *A, *dL, *Ai;
    PetscReal       *y, c[64];
    PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
    PetscCall(HylcPeriodicSetPattern(P, p, &m));
    PetscCall(HylcPeriodicSetStrain(P, z));
    PetscCall(HylcPeriodicSetSlideConstraint(P, (HylcSlideConstraint)sl));
    PetscCall(HylcPeriodicSetUp(P));
    PetscCall(HylcPeriodicGetSizes(P, &n, NULL, NULL, &nc));
    PetscCall(HylcPeriodicGetConstraints(P, &nc, &A, &dL, &Ai));
    HYLC_CHECK(nc == 3 + (sl == 0 ? 0 : sl == 1 ? 1 : nloops), "slide %s: %d constraint rows", HylcSlideConstraints[sl], (int)nc);
    PetscCall(PetscMalloc1(n, &y));
    PetscCall(HylcPeriodicGetInitialState(P, y));
    PetscCall(HylcPeriodicConstraintResidual(P, y, c));
    for (PetscInt i = 0; i < nc; i++) HYLC_CHECK(PetscAbsReal(c[i]) <= 1e-12 * PetscAbsReal(dL[i]) + 1e-20, "slide %s: residual %g in row %d", HylcSlideConstraints[sl], (double)c[i], (int)i);
    for (PetscInt i = 0; i < nc; i++)
      for (PetscInt j = 0; j < nc; j++) {
        PetscReal s = 0;
        for (PetscInt k = 0; k < nc; k++) {
          PetscReal aat = 0;
          for (PetscInt q = 0; q < n; q++) aat += A[i * n + q] * A[k * n + q];
          s += aat * Ai[k * nc + j];
        }
        HYLC_CHECK(PetscAbsReal(s - (i == j)) < 1e-9, "slide %s: (A A^T)(A A^T)^-1 differs from I at (%d, %d): %g", HylcSlideConstraints[sl], (int)i, (int)j, (double)s);
      }
    PetscCall(PetscFree(y));
    PetscCall(HylcPeriodicDestroy(&P));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* straight yarns: the slide rows that repeat translation rows are dropped, for every slide variant, flat,
   sheared and bent; the kept rows vanish at the initial guess and (A A^T)^-1 is their inverse. Tiles:
   0: one yarn along x; 1: two parallel yarns along x; 2: a yarn along x and one along y (3 r above it);
   3: one diagonal yarn (winding (1, 1)) */
static PetscErrorCode TestStraightConstraints(void)
{
  const PetscReal px = 8e-3, py = 8e-3, r = 5e-4;
  const PetscInt  N        = 8;
  const PetscReal zs[3][6] = {{0, 0, 0, 0, 0, 0}, {0.1, 0.3, -0.05, 0, 0, 0}, {0.05, 0.1, 0, 80, 0, 40}};
  /* independent rows per tile and slide variant (none, global, per_yarn, per_family): a slide row that is
     a combination of translation rows goes; the relative slide of two parallel yarns (per_yarn) and the
     slide rows of crossing families stay */
  const PetscInt expect[4][4] = {{3, 3, 3, 3}, {3, 3, 4, 3}, {3, 4, 5, 5}, {3, 3, 3, 3}};
  HylcYarnModel  m;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelDefault(&m));
  for (int t = 0; t < 4; t++) {
    PetscReal   pts[3 * 16];
    PetscInt    nv[2] = {N, N}, w[4] = {1, 0, 1, 0}, nl = (t == 1 || t == 2) ? 2 : 1;
    HylcPattern p;
    for (PetscInt k = 0; k < N; k++) {
      const PetscReal s = (k + 0.5) / (PetscReal)N - 0.5;
      pts[3 * k] = s * px, pts[3 * k + 1] = t == 3 ? s * py : (t == 1 ? -0.25 * py : 0), pts[3 * k + 2] = 0;
      if (t == 1) pts[3 * (N + k)] = s * px, pts[3 * (N + k) + 1] = 0.25 * py, pts[3 * (N + k) + 2] = 0;
      if (t == 2) pts[3 * (N + k)] = 0.25 * px, pts[3 * (N + k) + 1] = s * py, pts[3 * (N + k) + 2] = 3 * r;
    }
    if (t == 2) w[2] = 0, w[3] = 1;
    if (t == 3) w[1] = 1;
    PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
    PetscCall(HylcPatternSetFromCurves(p, px, py, r, nl, nv, w, pts));
    for (int sl = 0; sl < 4; sl++)
      for (int iz = 0; iz < 3; iz++) {
        HylcPeriodic     P;
        PetscInt         n, nc;
        const PetscReal *A, *dL, *Ai;
        PetscReal       *y, c[8];
        PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
        PetscCall(HylcPeriodicSetPattern(P, p, &m));
        PetscCall(HylcPeriodicSetStrain(P, zs[iz]));
        PetscCall(HylcPeriodicSetSlideConstraint(P, (HylcSlideConstraint)sl));
        PetscCall(HylcPeriodicSetUp(P));
        PetscCall(HylcPeriodicGetSizes(P, &n, NULL, NULL, NULL));
        PetscCall(HylcPeriodicGetConstraints(P, &nc, &A, &dL, &Ai));
        HYLC_CHECK(nc == expect[t][sl], "straight tile %d, slide %s, strain %d: %d constraint rows kept, expected %d", t, HylcSlideConstraints[sl], iz, (int)nc, (int)expect[t][sl]);
        PetscCall(PetscMalloc1(n, &y));
        PetscCall(HylcPeriodicGetInitialState(P, y));
        PetscCall(HylcPeriodicConstraintResidual(P, y, c));
        for (PetscInt i = 0; i < nc; i++) HYLC_CHECK(PetscAbsReal(c[i]) <= 1e-12 * r, "straight tile %d, slide %s: residual %g in row %d", t, HylcSlideConstraints[sl], (double)c[i], (int)i);
        for (PetscInt i = 0; i < nc; i++)
          for (PetscInt j = 0; j < nc; j++) {
            PetscReal s = 0;
            for (PetscInt k = 0; k < nc; k++) {
              PetscReal aat = 0;
              for (PetscInt q = 0; q < n; q++) aat += A[i * n + q] * A[k * n + q];
              s += aat * Ai[k * nc + j];
            }
            HYLC_CHECK(PetscAbsReal(s - (i == j)) < 1e-9, "straight tile %d: (A A^T)(A A^T)^-1 differs from I at (%d, %d): %g", t, (int)i, (int)j, (double)s);
          }
        PetscCall(PetscFree(y));
        PetscCall(HylcPeriodicDestroy(&P));
      }
    PetscCall(HylcPatternDestroy(&p));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  HylcPattern     weave, knit;
  const PetscReal flat0[6] = {0, 0, 0, 0, 0, 0}, flat1[6] = {-0.1, 0.15, 0.05, 0, 0, 0};
  const PetscReal bentx[6] = {0.05, 0.1, -0.05, 120, 0, 0}, benty[6] = {0, -0.2, 0.1, 0, 0, -90}, bent2[6] = {0, 0, 0, 40, 15, -25};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(Generate(HYLCPATTERNTWILL, 3.9, &weave));
  PetscCall(Generate(HYLCPATTERNSTOCKINETTE, 0, &knit));
  PetscCall(TestFlat(weave, "twill, z = 0", flat0, 0.25e-3, 0));
  PetscCall(TestFlat(weave, "twill, in-plane strain", flat1, 0.25e-3, 0));
  PetscCall(TestFlat(knit, "stockinette, z = 0", flat0, 0.25e-3, 0));
  PetscCall(TestFlat(knit, "stockinette, in-plane strain", flat1, 0.25e-3, 0));
  PetscCall(TestFlat(knit, "stockinette, large displacements", flat1, 3e-3, 0));
  PetscCall(TestDerivatives(knit, "stockinette bent in x", bentx, HYLC_CONTACT_QUADRATURE));
  PetscCall(TestDerivatives(knit, "stockinette bent in y", benty, HYLC_CONTACT_CLOSEST));
  PetscCall(TestDerivatives(weave, "twill bent in x", bentx, HYLC_CONTACT_QUADRATURE));
  PetscCall(TestDerivatives(knit, "stockinette doubly curved", bent2, HYLC_CONTACT_QUADRATURE));
  PetscCall(TestBentYarn());
  PetscCall(TestConstraints(knit));
  PetscCall(TestStraightConstraints());
  PetscCall(HylcPatternDestroy(&weave));
  PetscCall(HylcPatternDestroy(&knit));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
