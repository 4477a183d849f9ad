static const char help[] = "hylc-pattern: load or generate a periodic yarn pattern, print a summary, and write it as .pyp or VTK.\n\n"
                           "  hylc-pattern -pattern_file f.pyp                         summary of a pattern file\n"
                           "  hylc-pattern -pattern_type satin -pattern_output s.pyp   generate and write\n"
                           "  hylc-pattern -pattern_file f.pyp -pattern_vtk f.vtk -pattern_vtk_tiles 3,3\n\n";

#include <hylc/options.h>
#include <hylc/pattern.h>
#include <hylc/sys.h>
#include <hylc/files.h>

static PetscErrorCode RunPattern(HylcPattern pat)
{
  char      out[PETSC_MAX_PATH_LEN] = "", vtk[PETSC_MAX_PATH_LEN] = "";
  PetscInt  tiles[2] = {1, 1}, nt = 2;
  PetscBool flg;

  PetscFunctionBeginUser;
  PetscCall(HylcPatternSetFromOptions(pat));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "hylc-pattern output options", "hylc-pattern");
  PetscCall(HylcOptionsString("-pattern_output", "Write the pattern to this .pyp file", "HylcPatternWrite", out, out, sizeof(out), NULL));
  PetscCall(HylcOptionsString("-pattern_vtk", "Write the tiled pattern as legacy-VTK polylines to this file", "HylcPatternWriteVTK", vtk, vtk, sizeof(vtk), NULL));
  PetscCall(HylcOptionsIntArray("-pattern_vtk_tiles", "Number of tile copies nx,ny in the VTK file", "HylcPatternWriteVTK", tiles, &nt, &flg));
  PetscOptionsEnd();
  PetscCheck(!flg || (nt == 2 && tiles[0] >= 1 && tiles[1] >= 1), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-pattern_vtk_tiles needs two positive integers nx,ny");
  PetscCheck((double)tiles[0] * tiles[1] <= 1e6, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-pattern_vtk_tiles %" PetscInt_FMT ",%" PetscInt_FMT ": at most 1e6 tile copies", tiles[0], tiles[1]);
  {
    PetscBool help_only;
    PetscCall(PetscOptionsHasHelp(NULL, &help_only));
    if (help_only) PetscFunctionReturn(PETSC_SUCCESS); /* -help: every option has been listed; do no work */
  }
  PetscCall(HylcCheckOptionsUsed(PETSC_COMM_WORLD)); /* a misspelt option is an error, another stage's is not */
  /* every file before any work (include/hylc/files.h): the pattern file and the options files read, the
     outputs writable and within the path limits, never an input or each other */
  {
    HylcPatternType type;
    PetscBool       isfile;
    const char     *in = "";
    HylcFiles       files;
    PetscErrorCode  ierr;
    PetscCall(HylcPatternGetType(pat, &type));
    PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
    if (isfile) PetscCall(HylcPatternGetFileName(pat, &in));
    PetscCall(HylcFilesCreate(PETSC_COMM_WORLD, &files));
    ierr = HylcFilesAddOptionsFiles(files);
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, in, "-pattern_file");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, out, "-pattern_output");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, vtk, "-pattern_vtk");
    if (!ierr) ierr = HylcFilesCheck(files);
    PetscCall(HylcFilesDestroy(&files));
    PetscCall(ierr);
  }
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcPatternView(pat, PETSC_VIEWER_STDOUT_WORLD));
  if (out[0]) {
    PetscCall(HylcPatternWrite(pat, out));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", out));
  }
  if (vtk[0]) {
    PetscCall(HylcPatternWriteVTK(pat, vtk, tiles[0], tiles[1]));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s (%" PetscInt_FMT " x %" PetscInt_FMT " tiles)\n", vtk, tiles[0], tiles[1]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcPattern    pat = NULL;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &pat));
  ierr = RunPattern(pat);
  PetscCall(HylcPatternDestroy(&pat)); /* also on an error: nothing leaks */
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
