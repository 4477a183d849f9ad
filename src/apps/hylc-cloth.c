static const char help[] = "hylc-cloth: the macroscale cloth solver on the C8 shell element with virtual standard fabric tests\n"
                           "(docs/fabric.md): strip tensile, bias extension, cantilever bending length, Cusick drape and a generic\n"
                           "static scene, from a material table (JSON or HDF5). Writes CSV, VTK (per step) and PNG files with the\n"
                           "-cloth_output prefix. Units: m, N, kg, s; T in N/m; curvatures in 1/m.\n\n"
                           "  hylc-cloth -cloth_material stock1.json -cloth_test tensile -cloth_output out/stock1\n"
                           "  mpiexec -n 2 hylc-cloth -cloth_material satin1.json -cloth_test drape -cloth_output out/satin1\n\n";

#include <hylc/cloth.h>

static PetscErrorCode Work(HylcCloth c)
{
  PetscBool help_only;

  PetscFunctionBeginUser;
  PetscCall(HylcClothSetFromOptions(c));
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (help_only) PetscFunctionReturn(PETSC_SUCCESS); /* -help: every option has been listed; do no work */
  PetscCall(HylcCheckOptionsUsed(PETSC_COMM_WORLD));
  { /* every input and output checked before any work (a missing table, an output over an input) */
    HylcFiles      files;
    PetscErrorCode ierr;
    PetscCall(HylcFilesCreate(PETSC_COMM_WORLD, &files));
    ierr = HylcFilesAddOptionsFiles(files);
    if (!ierr) ierr = HylcClothAddFiles(c, files);
    if (!ierr) ierr = HylcFilesCheck(files);
    PetscCall(HylcFilesDestroy(&files));
    PetscCall(ierr);
  }
  PetscCall(HylcClothSetUp(c));
  PetscCall(HylcClothRun(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcCloth      c;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcClothCreate(PETSC_COMM_WORLD, &c));
  ierr = Work(c);
  PetscCall(HylcClothDestroy(&c));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
