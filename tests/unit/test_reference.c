/* The reference state of Algorithm C1 on a generated plain weave: the result is stress free apart from
   the tension, its periods are an in-plane energy minimum (the energy grows when the periods are
   stretched or compressed by 1 %), it is recentred, and the tension factors were applied. */
#include <hylc/reference.h>
#include "hylctest.h"

int main(int argc, char **argv)
{
  HylcPattern          p, ref;
  HylcPatternGenParams g;
  HylcYarnModel        m;
  HylcReferenceParams  rp;
  HylcMicro            M;
  HylcMicroResult      r0, r;
  HylcPatternData      D0, D;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNPLAIN, &g));
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50;
  PetscCall(HylcReferenceParamsDefault(&rp));
  PetscCall(HylcReferenceStateCompute(p, &m, &rp, NULL, &ref));
  PetscCall(HylcPatternGetData(p, &D0));
  PetscCall(HylcPatternGetData(ref, &D));
  /* tension of a woven: rest curvatures x 0.9 of the stress-free state, rest lengths unchanged */
  HYLC_CHECK(D.nv == D0.nv, "vertex count changed");
  PetscReal mean[3] = {0, 0, 0};
  for (PetscInt v = 0; v < D.nv; v++)
    for (int d = 0; d < 3; d++) mean[d] += D.X[3 * v + d] / D.nv;
  for (int d = 0; d < 3; d++) HYLC_CHECK(PetscAbsReal(mean[d]) < 1e-15, "not recentred: mean[%d] = %g", d, (double)mean[d]);
  /* an in-plane minimum: +-1 % in sx or sy does not lower the energy (beyond the minimizer's tolerance) */
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, ref, &m));
  const PetscReal z0[6] = {0, 0, 0, 0, 0, 0};
  PetscCall(HylcMicroSolve(M, z0, &r0));
  HYLC_CHECK(r0.status == HYLC_MICRO_CONVERGED && r0.iterations <= 3, "reference state is not an equilibrium: %s after %d iterations", HylcMicroStatuses[r0.status], (int)r0.iterations);
  HYLC_CHECK(r0.energy > 0, "tension left no energy");
  for (int k = 0; k < 4; k++) {
    PetscReal z[6]   = {0, 0, 0, 0, 0, 0};
    z[k < 2 ? 0 : 2] = (k % 2) ? 0.01 : -0.01;
    PetscCall(HylcMicroSolve(M, z, &r));
    HYLC_CHECK(r.status == HYLC_MICRO_CONVERGED && r.energy >= r0.energy * (1 - 1e-6), "not an in-plane minimum: E(%g, %g) = %.10g < E(0) = %.10g", (double)z[0], (double)z[2], (double)r.energy, (double)r0.energy);
  }
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&ref));
  PetscCall(HylcPatternDestroy(&p));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
