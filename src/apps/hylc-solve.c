static const char help[] = "hylc-solve: the equilibrium of a periodic yarn tile under one macroscopic strain.\n\n"
                           "  hylc-solve -options_file config/satin.yaml -strain 0.2,0,0,0,0,0\n"
                           "  hylc-solve -pattern_type stockinette -strain 0,0,0,100,0,0 -solve_vtk s.vtk\n\n"
                           "Prints psi (J/m^2), the energy parts, the status, the Newton iterations and the wall time.\n\n";

#include <hylc/options.h>
#include <hylc/micro.h>
#include <hylc/sys.h>
#include <hylc/files.h>

/* the work of hylc-solve on pat and micro (created and destroyed by Run, also on an error) */
static PetscErrorCode Solve(HylcPattern pat, HylcMicro micro)
{
  HylcYarnModel   model;
  HylcMicroResult res;
  PetscReal       z[6] = {0, 0, 0, 0, 0, 0};
  PetscInt        nz = 6, tiles[2] = {3, 3}, nt = 2;
  char            out[PETSC_MAX_PATH_LEN] = "", vtk[PETSC_MAX_PATH_LEN] = "";
  PetscBool       flg;

  PetscFunctionBeginUser;
  PetscCall(HylcPatternSetFromOptions(pat));
  PetscCall(HylcYarnModelDefault(&model));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, &model));
  PetscOptionsBegin(PETSC_COMM_SELF, NULL, "hylc-solve options", "hylc-solve");
  PetscCall(HylcOptionsRealArray("-strain", "Macroscopic strain sx,sa,sy,II00,II01,II11 (II in 1/m): finite, |sa| < 1, 0 < 1+sx, 1+sy <= 1e3, the midsurface turning by at most 2 pi across a period (docs/method.md)", "HylcMicroSolve", z, &nz, &flg));
  PetscCheck(!flg || nz == 6, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-strain needs 6 comma-separated values sx,sa,sy,II00,II01,II11, got %" PetscInt_FMT, nz);
  PetscCall(PetscOptionsString("-solve_output", "Write the equilibrium tile as .pyp (positions and twists; rest data unchanged)", "hylc-solve", out, out, sizeof(out), NULL));
  PetscCall(PetscOptionsString("-solve_vtk", "Write the equilibrium, tiled, as legacy-VTK polylines", "hylc-solve", vtk, vtk, sizeof(vtk), NULL));
  nt = 2;
  PetscCall(HylcOptionsIntArray("-solve_vtk_tiles", "Tile copies nx,ny in the VTK file", "hylc-solve", tiles, &nt, NULL));
  PetscOptionsEnd();
  /* every file before any work (include/hylc/files.h): the pattern file and the options files read, the
     outputs writable and within the path limits, never an input or each other */
  {
    const char     *in = "";
    HylcPatternType type;
    PetscBool       isfile;
    HylcFiles       files;
    PetscErrorCode  ierr;
    PetscCall(HylcPatternGetType(pat, &type));
    PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
    if (isfile) PetscCall(HylcPatternGetFileName(pat, &in));
    PetscCheck(!out[0] || (z[1] == 0 && z[3] == 0 && z[4] == 0 && z[5] == 0), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_output %s: a deformed tile is a .pyp pattern only without shear and bending (sa = II = 0); use -solve_vtk instead", out);
    PetscCall(HylcFilesCreate(PETSC_COMM_SELF, &files));
    ierr = HylcFilesAddOptionsFiles(files);
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, in, "-pattern_file");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, out, "-solve_output");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, vtk, "-solve_vtk");
    if (!ierr) ierr = HylcFilesCheck(files);
    PetscCall(HylcFilesDestroy(&files));
    PetscCall(ierr);
  }
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcMicroSetPattern(micro, pat, &model));
  PetscCall(HylcMicroSetFromOptions(micro));
  {
    HylcPeriodic P;
    PetscCall(HylcMicroGetPeriodic(micro, &P));
    PetscCall(HylcPeriodicCheckStrain(P, z, "-strain"));
  }
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
      HylcPattern    eq;
      PetscErrorCode ierr;
      PetscCall(HylcPeriodicCreateStatePattern(P, &eq));
      ierr = HylcPatternWrite(eq, out);
      PetscCall(HylcPatternDestroy(&eq));
      PetscCall(ierr);
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", out));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcPattern    pat   = NULL;
  HylcMicro      micro = NULL;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &pat));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &micro));
  ierr = Solve(pat, micro);
  PetscCall(HylcMicroDestroy(&micro)); /* also on an error: nothing leaks */
  PetscCall(HylcPatternDestroy(&pat));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
