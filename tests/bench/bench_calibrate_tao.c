/* Benchmark (issue 33): the calibration's optimizer as hylc runs it (HylcCalibrateSolve, src/calibrate/
   solve.c: TAOBRGN with Levenberg-Marquardt damping, an Armijo line search, hylc's stopping tests and held
   flat directions) against a bare TAOBRGN (-tao_brgn_regularization_type lm, its own unit step and
   tolerances) on the same objective: the same log parameters, bounds, residuals and Jacobian (one
   microscale solve per sample per point, the Jacobian by the envelope theorem). Until issue 33,
   HylcCalibrateSolve was a hand-written Levenberg-Marquardt, and this benchmark measured it against TAO
   (docs/calibrate.md, "TAO against the hand-written optimizers"). The cost of a calibration is the
   number of evaluations (each solves every sample), so both are compared by evaluations and by the
   objective they reach: printed per bare-TAO evaluation, and as the evaluations it needs to come within
   0.1 % of hylc's result. The calibration is given by hylc-calibrate's options; without -calibrate_target
   the demo's case is used when out/demo exists (make demo), else the benchmark is skipped.
   The bare TAO is given at most 60 evaluations.
     mpiexec -n 2 build/bench/bench_calibrate_tao [hylc-calibrate options] */
#include "../../src/calibrate/calibrateimpl.h"
#include <petsctao.h>
#include <petsctime.h>

typedef struct {
  HylcCalibrate C;
  int           act[HYLC_CALIBRATE_NPARAM], na;
  PetscReal    *rec, *r, *J;
  PetscReal     xc[HYLC_CALIBRATE_NPARAM]; /* the point of the cached r, J */
  PetscBool     cached;
  PetscInt      nevals;
  PetscReal     best, hist[1000];
} Ctx;

static void Expand(HylcCalibrate C, const int act[], int na, const PetscScalar x[], PetscReal p[])
{
  PetscReal lx[HYLC_CALIBRATE_NPARAM];
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) lx[j] = PetscLogReal(C->p0[j]);
  for (int a = 0; a < na; a++) lx[act[a]] = PetscRealPart(x[a]);
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) p[j] = C->role[j] == HYLC_CALIBRATE_FIXED ? C->p0[j] : PetscExpReal(lx[j]);
  for (int j = 1; j < HYLC_CALIBRATE_NPARAM; j++)
    if (C->role[j] == HYLC_CALIBRATE_TIED) p[j] = C->p0[j] * (p[0] / C->p0[0]);
}

/* r and J at x, solved unless x is the cached point */
static PetscErrorCode EvalAt(Ctx *c, Vec X)
{
  const PetscScalar *x;
  PetscReal          p[HYLC_CALIBRATE_NPARAM], f;
  PetscBool          same = c->cached;

  PetscFunctionBegin;
  PetscCall(VecGetArrayRead(X, &x));
  for (int a = 0; a < c->na; a++) same = same && PetscRealPart(x[a]) == c->xc[a];
  if (!same) {
    Expand(c->C, c->act, c->na, x, p);
    PetscCall(HylcCalibrateSolveSamples_Private(c->C, p, c->rec));
    PetscCall(HylcCalibrateResiduals_Private(c->C, c->rec, c->r, c->J, &f, NULL));
    for (int a = 0; a < c->na; a++) c->xc[a] = PetscRealPart(x[a]);
    c->cached = PETSC_TRUE;
    if (c->nevals < 1000) c->hist[c->nevals] = f;
    c->nevals++;
    c->best = PetscMin(c->best, f);
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Residual(Tao tao, Vec X, Vec F, void *ctx)
{
  Ctx         *c = (Ctx *)ctx;
  PetscScalar *f;

  PetscFunctionBegin;
  (void)tao;
  PetscCall(EvalAt(c, X));
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < c->C->nres; i++) f[i] = c->r[i];
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Jacobian(Tao tao, Vec X, Mat J, Mat Jpre, void *ctx)
{
  Ctx *c = (Ctx *)ctx;

  PetscFunctionBegin;
  (void)tao;
  (void)Jpre;
  PetscCall(EvalAt(c, X));
  for (PetscInt i = 0; i < c->C->nres; i++)
    for (int a = 0; a < c->na; a++) PetscCall(MatSetValue(J, i, a, c->J[i * HYLC_CALIBRATE_NPARAM + c->act[a]], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcCalibrate  C;
  Ctx            c;
  Tao            tao;
  Vec            X, XL, XU, F;
  Mat            J;
  PetscReal      pin[HYLC_CALIBRATE_NPARAM], plm[HYLC_CALIBRATE_NPARAM], f0, flm, ptao[HYLC_CALIBRATE_NPARAM];
  PetscInt       its, nlm, reach = -1;
  PetscLogDouble t0, t1, t2;
  PetscBool      has;

  PetscFunctionBegin;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-calibrate_target", &has));
  if (!has) {
    PetscBool demo;
    PetscCall(PetscTestFile("out/demo/samples.h5", 'r', &demo));
    if (!demo) {
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "bench_calibrate_tao: no -calibrate_target and no out/demo/samples.h5 (make demo); skipped\n"));
      PetscFunctionReturn(PETSC_SUCCESS);
    }
    /* the calibration of make demo (examples/demo.sh) */
    PetscCall(PetscOptionsInsertString(NULL, "-pattern_file out/demo/reference.pyp -calibrate_target out/demo/samples.h5 -calibrate_max_samples 60 -yarn_E 2e6 -yarn_Es 5e5 -yarn_kc 20 -calibrate_params E,Es,kc"));
  }
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateSetUp(C));
  PetscCall(PetscMemzero(&c, sizeof(c)));
  c.C    = C;
  c.best = PETSC_INFINITY;
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++)
    if (C->role[j] == HYLC_CALIBRATE_FREE) c.act[c.na++] = j;
  PetscCall(PetscMalloc3(C->m * HYLC_CALIB_NRECORD, &c.rec, C->nres, &c.r, C->nres * HYLC_CALIBRATE_NPARAM, &c.J));

  /* TAO first (HylcCalibrateSolve writes its outputs and marks the object solved) */
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, c.na, &X));
  PetscCall(VecDuplicate(X, &XL));
  PetscCall(VecDuplicate(X, &XU));
  for (int a = 0; a < c.na; a++) {
    const int j = c.act[a];
    PetscCall(VecSetValue(X, a, PetscLogReal(C->p0[j]), INSERT_VALUES));
    PetscCall(VecSetValue(XL, a, PetscLogReal(C->lo[j]), INSERT_VALUES));
    PetscCall(VecSetValue(XU, a, PetscLogReal(C->hi[j]), INSERT_VALUES));
  }
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, C->nres, &F));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, C->nres, c.na, NULL, &J));
  PetscCall(TaoCreate(PETSC_COMM_SELF, &tao));
  PetscCall(TaoSetType(tao, TAOBRGN));
  PetscCall(TaoSetSolution(tao, X));
  PetscCall(TaoSetVariableBounds(tao, XL, XU));
  PetscCall(TaoSetResidualRoutine(tao, F, Residual, &c));
  PetscCall(TaoSetJacobianResidualRoutine(tao, J, J, Jacobian, &c));
  PetscCall(TaoSetMaximumFunctionEvaluations(tao, 60));
  /* inserted after HylcCalibrateSetUp(), which refuses options no part of hylc reads */
  PetscCall(PetscOptionsInsertString(NULL, "-tao_brgn_regularization_type lm"));
  PetscCall(TaoSetFromOptions(tao));
  PetscCall(PetscTime(&t0));
  PetscCall(TaoSolve(tao));
  PetscCall(PetscTime(&t1));
  {
    const PetscScalar *x;
    TaoConvergedReason reason;
    PetscCall(TaoGetConvergedReason(tao, &reason));
    PetscCall(VecGetArrayRead(X, &x));
    Expand(C, c.act, c.na, x, ptao);
    PetscCall(VecRestoreArrayRead(X, &x));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "bare TAO brgn (lm): %" PetscInt_FMT " evaluations, best objective %.6e, %.1f s, %s; E %.4g Es %.4g G %.4g kc %.4g (last point)\n", c.nevals, (double)c.best, t1 - t0, TaoConvergedReasons[reason],
                          (double)ptao[0], (double)ptao[1], (double)ptao[2], (double)ptao[3]));
  }
  PetscCall(HylcCalibrateSolve(C));
  PetscCall(PetscTime(&t2));
  PetscCall(HylcCalibrateGetParameters(C, pin, plm));
  PetscCall(HylcCalibrateGetObjective(C, &f0, &flm, &its));
  nlm = C->nevals;
  for (PetscInt k = 0; k < PetscMin(c.nevals, 1000); k++)
    if (reach < 0 && c.hist[k] <= flm * (1 + 1e-3)) reach = k + 1;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "hylc-calibrate (TAO): %" PetscInt_FMT " evaluations, objective %.6e -> %.6e, %.1f s; E %.4g Es %.4g G %.4g kc %.4g\n", nlm, (double)f0, (double)flm, t2 - t1, (double)plm[0], (double)plm[1], (double)plm[2],
                        (double)plm[3]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "bare TAO objective per evaluation:"));
  for (PetscInt k = 0; k < PetscMin(c.nevals, 1000); k++) PetscCall(PetscPrintf(PETSC_COMM_WORLD, " %.4e", (double)c.hist[k]));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\nTAO within 0.1 %% of hylc-calibrate's objective after: %s%" PetscInt_FMT " evaluations (hylc-calibrate: %" PetscInt_FMT ")\n", reach < 0 ? "never, " : "", reach < 0 ? c.nevals : reach, nlm));
  PetscCall(TaoDestroy(&tao));
  PetscCall(MatDestroy(&J));
  PetscCall(VecDestroy(&X));
  PetscCall(VecDestroy(&XL));
  PetscCall(VecDestroy(&XU));
  PetscCall(VecDestroy(&F));
  PetscCall(PetscFree3(c.rec, c.r, c.J));
  PetscCall(HylcCalibrateDestroy(&C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(Run());
  PetscCall(PetscFinalize());
  return 0;
}
