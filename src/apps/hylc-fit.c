static const char help[] = "hylc-fit: fits the homogenized material model (the spline tables of (S26)) to microscale samples\n"
                           "(Algorithms C5-C7; docs/fit.md) and writes it as HDF5 and/or ARCSim-HYLC JSON.\n\n"
                           "  hylc-fit -fit_input samples.h5 -fit_output model.h5 -fit_json model.json\n"
                           "  hylc-fit -fit_input raw/ -fit_json model.json -fit_family stockinette   (the paper's data.txt, info.txt)\n\n";

#include <hylc/fit.h>

static PetscErrorCode Run(void)
{
  HylcFit      fit;
  HylcMaterial mat;
  PetscBool    help_only;
  char         h5[PETSC_MAX_PATH_LEN] = "", json[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCall(HylcFitCreate(PETSC_COMM_WORLD, &fit));
  PetscCall(HylcFitSetFromOptions(fit));
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (!help_only) { /* -help: every option has been listed; do no work */
    PetscCall(HylcCheckOptionsUsed(PETSC_COMM_WORLD));
    PetscCall(PetscOptionsGetString(NULL, NULL, "-fit_output", h5, sizeof(h5), NULL));
    PetscCall(PetscOptionsGetString(NULL, NULL, "-fit_json", json, sizeof(json), NULL));
    PetscCall(HylcFitSetUp(fit));
    PetscCall(HylcMaterialCreate(PETSC_COMM_WORLD, &mat));
    PetscCall(HylcFitRun(fit, mat));
    PetscCall(HylcFitView(fit, PETSC_VIEWER_STDOUT_WORLD));
    if (h5[0]) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", h5));
    if (json[0]) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", json));
    if (!h5[0] && !json[0]) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "nothing written (no -fit_output or -fit_json)\n"));
    PetscCall(HylcMaterialDestroy(&mat));
  }
  PetscCall(HylcFitDestroy(&fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
