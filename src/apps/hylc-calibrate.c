static const char help[] = "hylc-calibrate: yarn parameters (E, Es, G, kc) that best reproduce a target energy response\n"
                           "(a material table, or strain-energy pairs); PETSc's TAO (TAOBRGN, Levenberg-Marquardt damping;\n"
                           "-calibrate_tao_*) in log parameters within bounds, with the\n"
                           "envelope-theorem Jacobian (one solve per sample per iteration), samples spread over MPI ranks.\n"
                           "docs/calibrate.md.\n\n"
                           "  mpirun -n 2 hylc-calibrate -options_file config/satin_small.yaml -calibrate_target satin01.json \\\n"
                           "      -calibrate_params E,Es,kc -calibrate_output satin_small-calibrated.yaml\n"
                           "  hylc-calibrate -pattern_file ref.pyp -calibrate_target samples.h5 -calibrate_params E,Es,G,kc\n"
                           "  hylc-calibrate -pattern_file ref.pyp -calibrate_target measured.csv   (header sx,sa,sy,II00,II01,II11,psi)\n\n";

#include <hylc/calibrate.h>

/* the work of hylc-calibrate on C (created and destroyed by Run, also on an error) */
static PetscErrorCode Calibrate(HylcCalibrate C)
{
  PetscBool help_only;

  PetscFunctionBeginUser;
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (!help_only) { /* -help: every option has been listed; do no work */
    PetscCall(HylcCalibrateSetUp(C));
    PetscCall(HylcCalibrateSolve(C));
    PetscCall(HylcCalibrateView(C, PETSC_VIEWER_STDOUT_WORLD));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcCalibrate  C;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  ierr = Calibrate(C);
  PetscCall(HylcCalibrateDestroy(&C)); /* also on an error: nothing leaks */
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
