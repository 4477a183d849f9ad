/* Benchmark (issue 33): the reference state's in-plane minimum (Algorithm C1 step 3, src/sampler/reference.c:
   hylc's own Nelder-Mead over (sx, sy) in [-0.4, 0.2]^2, starting simplex (0,0), (0.02,0), (0,0.02), one
   microscale solve per point) against PETSc's TAONM on the same objective, the same start and step
   (-tao_nm_lambda 0.02), points outside the box +1e30. The patterns: the generated plain weave, twill and
   satin after C1's stress-free relaxation and tension (HylcReferenceStateCompute with -reference_minimum
   off), with the yarn model of test_reference (kc 50). Printed per pattern: solves and the minimum of each,
   and the solves TAONM needs to come within 1e-4 (strain) of hylc's minimum. Solves are the cost. */
#include <hylc/reference.h>
#include <hylc/micro.h>
#include <petsctao.h>
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

typedef struct {
  HylcMicro M;
  PetscReal lo, hi;
  PetscInt  n;
  PetscReal xs[400][2], fs[400];
} Ctx;

static PetscErrorCode Objective(Tao tao, Vec X, PetscReal *f, void *ctx)
{
  Ctx               *c = (Ctx *)ctx;
  const PetscScalar *x;
  HylcMicroResult    r;

  PetscFunctionBegin;
  (void)tao;
  PetscCall(VecGetArrayRead(X, &x));
  const PetscReal sx = PetscRealPart(x[0]), sy = PetscRealPart(x[1]);
  PetscCall(VecRestoreArrayRead(X, &x));
  if (sx < c->lo || sx > c->hi || sy < c->lo || sy > c->hi) {
    *f = 1e30;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  const PetscReal z[6] = {sx, 0, sy, 0, 0, 0};
  PetscCall(HylcMicroSolve(c->M, z, &r));
  *f = r.status == HYLC_MICRO_CONVERGED ? r.energy : 1e30;
  if (c->n < 400) {
    c->xs[c->n][0] = sx;
    c->xs[c->n][1] = sy;
    c->fs[c->n]    = *f;
  }
  c->n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(HylcPatternType type)
{
  HylcPattern          p, tens, ref;
  HylcPatternGenParams g;
  HylcYarnModel        m;
  HylcReferenceParams  rp;
  PetscViewer          sv;
  Ctx                  c;
  Tao                  tao;
  Vec                  X;
  char                 buf[4096] = "";
  double               hx = 0, hy = 0, hE = 0;
  int                  hn    = 0;
  PetscInt             reach = -1;
  const PetscScalar   *x;

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, type, &g));
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50;
  /* C1 steps 1, 2 (stress free, tension) only */
  PetscCall(HylcReferenceParamsDefault(&rp));
  rp.minimum = PETSC_FALSE;
  PetscCall(HylcReferenceStateCompute(p, &m, &rp, NULL, &tens));
  /* hylc's Nelder-Mead alone on that state: its progress line gives the minimum and the solves */
  rp.stressFree = PETSC_FALSE;
  rp.tension    = PETSC_FALSE;
  rp.minimum    = PETSC_TRUE;
  {
    char  path[] = "/tmp/bench_reference_tao.XXXXXX";
    int   fd     = mkstemp(path);
    FILE *fp;
    PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "mkstemp failed");
    close(fd);
    PetscCall(PetscViewerASCIIOpen(PETSC_COMM_SELF, path, &sv));
    PetscCall(HylcReferenceStateCompute(tens, &m, &rp, sv, &ref));
    PetscCall(PetscViewerDestroy(&sv));
    fp = fopen(path, "r");
    if (fp) {
      size_t n = fread(buf, 1, sizeof(buf) - 1, fp);
      buf[n]   = 0;
      fclose(fp);
    }
    unlink(path);
  }
  {
    const char *s = strstr(buf, "in-plane minimum at sx = ");
    PetscCheck(s && sscanf(s, "in-plane minimum at sx = %lf, sy = %lf (E = %lf J, %d solves)", &hx, &hy, &hE, &hn) == 4, PETSC_COMM_SELF, PETSC_ERR_PLIB, "no in-plane minimum line in: %s", buf);
  }
  /* TAONM on the same objective */
  PetscCall(PetscMemzero(&c, sizeof(c)));
  c.lo = rp.lo;
  c.hi = rp.hi;
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &c.M));
  PetscCall(HylcMicroSetPattern(c.M, tens, &m));
  PetscCall(HylcMicroSetFromOptions(c.M));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2, &X));
  PetscCall(VecSet(X, 0));
  PetscCall(TaoCreate(PETSC_COMM_SELF, &tao));
  PetscCall(TaoSetType(tao, TAONM));
  PetscCall(TaoSetSolution(tao, X));
  PetscCall(TaoSetObjective(tao, Objective, &c));
  PetscCall(TaoSetMaximumFunctionEvaluations(tao, 200));
  PetscCall(TaoSetFromOptions(tao));
  PetscCall(TaoSolve(tao));
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt k = 0; k < PetscMin(c.n, 400); k++)
    if (reach < 0 && PetscAbsReal(c.xs[k][0] - hx) < 1e-4 && PetscAbsReal(c.xs[k][1] - hy) < 1e-4) reach = k + 1;
  {
    PetscReal fb = 1e300, xb[2] = {0, 0};
    for (PetscInt k = 0; k < PetscMin(c.n, 400); k++)
      if (c.fs[k] < fb) fb = c.fs[k], xb[0] = c.xs[k][0], xb[1] = c.xs[k][1];
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "%-6s hylc NM: %3d solves, minimum at (%.6f, %.6f), E %.9e J | TAONM: %3" PetscInt_FMT " solves, best at (%.6f, %.6f), E %.9e J (ends at %.6f, %.6f); within 1e-4 of hylc's minimum after %s%" PetscInt_FMT " solves\n", type,
                          hn, hx, hy, hE, c.n, (double)xb[0], (double)xb[1], (double)fb, (double)PetscRealPart(x[0]), (double)PetscRealPart(x[1]), reach < 0 ? "never, " : "", reach < 0 ? c.n : reach));
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(TaoDestroy(&tao));
  PetscCall(VecDestroy(&X));
  PetscCall(HylcMicroDestroy(&c.M));
  PetscCall(HylcPatternDestroy(&ref));
  PetscCall(HylcPatternDestroy(&tens));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsInsertString(NULL, "-tao_nm_lambda 0.02"));
  PetscCall(Run(HYLCPATTERNPLAIN));
  PetscCall(Run(HYLCPATTERNTWILL));
  PetscCall(Run(HYLCPATTERNSATIN));
  PetscCall(PetscFinalize());
  return 0;
}
