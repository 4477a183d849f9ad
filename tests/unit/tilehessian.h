#pragma once
/* Test and benchmark helper: the reduced Hessian H_y of a periodic tile (HylcPeriodic, default yarn model)
   at its initial guess u~ = 0 under the strain z, as a new SeqAIJ matrix. Used by test_metis, test_chol
   and bench_ordering. */
#include <hylc/periodic.h>

static inline PetscErrorCode HylcTestTileHessian(HylcPattern p, const PetscReal z[6], Mat *H)
{
  HylcYarnModel m;
  HylcPeriodic  P;
  PetscInt      n;
  PetscReal    *y, e[4];

  PetscFunctionBegin;
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
  PetscCall(HylcPeriodicSetPattern(P, p, &m));
  PetscCall(HylcPeriodicSetStrain(P, z));
  PetscCall(HylcPeriodicSetUp(P));
  PetscCall(HylcPeriodicGetSizes(P, &n, NULL, NULL, NULL));
  PetscCall(PetscMalloc1(n, &y));
  PetscCall(HylcPeriodicGetInitialState(P, y));
  PetscCall(HylcPeriodicSetState(P, y));
  PetscCall(HylcPeriodicCreateMatrix(P, H));
  PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, e, NULL, *H));
  PetscCall(PetscFree(y));
  PetscCall(HylcPeriodicDestroy(&P));
  PetscFunctionReturn(PETSC_SUCCESS);
}
