static const char help[] = "hylc-solve: the equilibrium of a periodic yarn tile under one macroscopic strain.\n\n"
                           "  hylc-solve -options_file config/satin.yaml -strain 0.2,0,0,0,0,0\n"
                           "  hylc-solve -pattern_type stockinette -strain 0,0,0,100,0,0 -solve_vtk s.vtk\n\n"
                           "Prints psi (J/m^2), the energy parts, the status, the Newton iterations and the wall time.\n\n";

#include <hylc/micro.h>

static PetscErrorCode Run(void)
{
  HylcPattern     pat;
  HylcYarnModel   model;
  HylcMicro       micro;
  HylcMicroResult res;
  PetscReal       z[6] = {0, 0, 0, 0, 0, 0};
  PetscInt        nz = 6, tiles[2] = {3, 3}, nt = 2;
  char            out[PETSC_MAX_PATH_LEN] = "", vtk[PETSC_MAX_PATH_LEN] = "";
  PetscBool       flg;

  PetscFunctionBeginUser;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &pat));
  PetscCall(HylcPatternSetFromOptions(pat));
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcYarnModelDefault(&model));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, &model));
  PetscOptionsBegin(PETSC_COMM_SELF, NULL, "hylc-solve options", "hylc-solve");
  PetscCall(PetscOptionsRealArray("-strain", "Macroscopic strain sx,sa,sy,II00,II01,II11 (II in 1/m)", "HylcMicroSolve", z, &nz, &flg));
  PetscCheck(!flg || nz == 6, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-strain needs 6 comma-separated values sx,sa,sy,II00,II01,II11, got %" PetscInt_FMT, nz);
  PetscCall(PetscOptionsString("-solve_output", "Write the equilibrium tile as .pyp (positions and twists; rest data unchanged)", "hylc-solve", out, out, sizeof(out), NULL));
  PetscCall(PetscOptionsString("-solve_vtk", "Write the equilibrium, tiled, as legacy-VTK polylines", "hylc-solve", vtk, vtk, sizeof(vtk), NULL));
  nt = 2;
  PetscCall(PetscOptionsIntArray("-solve_vtk_tiles", "Tile copies nx,ny in the VTK file", "hylc-solve", tiles, &nt, NULL));
  PetscOptionsEnd();
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &micro));
  PetscCall(HylcMicroSetPattern(micro, pat, &model));
  PetscCall(HylcMicroSetFromOptions(micro));
  PetscCall(HylcMicroSolve(micro, z, &res));
  PetscCall(HylcMicroResultView(&res, PETSC_VIEWER_STDOUT_SELF));
  if (out[0] || vtk[0]) {
    HylcPeriodic P;
    PetscCall(HylcMicroGetPeriodic(micro, &P));
    if (vtk[0]) {
      PetscCall(HylcPeriodicWriteVTK(P, vtk, tiles[0], tiles[1]));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", vtk));
    }
    if (out[0]) {
      HylcPattern eq;
      PetscCall(HylcPeriodicCreateStatePattern(P, &eq));
      PetscCall(HylcPatternWrite(eq, out));
      PetscCall(HylcPatternDestroy(&eq));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", out));
    }
  }
  PetscCall(HylcMicroDestroy(&micro));
  PetscCall(HylcPatternDestroy(&pat));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
