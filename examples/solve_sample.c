/* solve_sample: libhylc from another program. Builds a built-in pattern, solves the periodic tile's
   equilibrium under one macroscopic strain (one sample of the sampling stage, docs/method.md) and
   prints the energy density psi (J/m^2). PETSc options apply (-pattern_type, -strain, ...).

     cc solve_sample.c $(pkg-config --cflags --libs hylc) -o solve_sample
     ./solve_sample -pattern_type stockinette -strain 0.05,0,0,0,0,0 */
#include <hylc/micro.h>
#include <hylc/sys.h>

static const char help[] = "solve_sample: one sample of a built-in pattern with libhylc.\n";

static PetscErrorCode Run(void)
{
  HylcPattern     pat;
  HylcYarnModel   model;
  HylcMicro       micro;
  HylcMicroResult res;
  PetscReal       z[6] = {0.05, 0, 0, 0, 0, 0};
  PetscInt        nz   = 6;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetRealArray(NULL, NULL, "-strain", z, &nz, NULL));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &pat));
  PetscCall(HylcPatternSetFromOptions(pat));
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcYarnModelDefault(&model));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, &model));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &micro));
  PetscCall(HylcMicroSetPattern(micro, pat, &model));
  PetscCall(HylcMicroSetFromOptions(micro));
  PetscCall(HylcMicroSolve(micro, z, &res));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "psi: %.10g J/m^2 at s = (%g, %g, %g, %g, %g, %g)\n", (double)res.psi, (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5]));
  PetscCall(HylcMicroDestroy(&micro));
  PetscCall(HylcPatternDestroy(&pat));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
