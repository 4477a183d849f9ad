static const char help[] = "hylc-fit: fits the homogenized material model (the spline tables of (S26)) to microscale samples\n"
                           "(Algorithms C5-C7; docs/fit.md) and writes it as HDF5 and/or ARCSim-HYLC JSON.\n\n"
                           "  hylc-fit -fit_input samples.h5 -fit_output model.h5 -fit_json model.json\n"
                           "  hylc-fit -fit_input raw/ -fit_json model.json -fit_family stockinette   (the paper's data.txt, info.txt)\n\n";

#include <hylc/fit.h>
#include <string.h>
#include <sys/stat.h>

/* the paths of the raw layout that -fit_input in names: in/data.txt and in/info.txt for a directory,
   in and info.txt beside it for a file (n = 2), or in alone (an HDF5 file: n = 1; a missing path: 0) */
static PetscErrorCode InputPaths(const char in[], char paths[3][PETSC_MAX_PATH_LEN + 16], int *n)
{
  struct stat st;

  PetscFunctionBegin;
  *n = 0;
  if (!in[0] || stat(in, &st)) PetscFunctionReturn(PETSC_SUCCESS);
  if (S_ISDIR(st.st_mode)) {
    PetscCall(PetscSNPrintf(paths[0], sizeof(paths[0]), "%s/data.txt", in));
    PetscCall(PetscSNPrintf(paths[1], sizeof(paths[1]), "%s/info.txt", in));
    *n = 2;
  } else {
    const char *slash = strrchr(in, '/');
    PetscCall(PetscStrncpy(paths[0], in, sizeof(paths[0])));
    if (slash)
      PetscCall(PetscSNPrintf(paths[1], sizeof(paths[1]), "%.*sinfo.txt", (int)(slash - in + 1), in));
    else
      PetscCall(PetscStrncpy(paths[1], "info.txt", sizeof(paths[1])));
    *n = 2; /* info.txt is read only for raw data, but is never a fit output either */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* every output before any work: writable, not a directory, not an input, and -fit_output and -fit_json
   not the same file */
static PetscErrorCode CheckPaths(const char in[], const char h5[], const char json[])
{
  char        paths[3][PETSC_MAX_PATH_LEN + 16];
  int         n;
  const char *outs[2] = {h5, json}, *opts[2] = {"-fit_output", "-fit_json"};

  PetscFunctionBegin;
  PetscCall(InputPaths(in, paths, &n));
  for (int k = 0; k < 2; k++) {
    if (!outs[k][0]) continue;
    PetscCall(HylcFileCheckOutput(PETSC_COMM_WORLD, outs[k], opts[k]));
    PetscCall(HylcFileCheckDistinct(PETSC_COMM_WORLD, outs[k], opts[k], in, "-fit_input"));
    for (int i = 0; i < n; i++) PetscCall(HylcFileCheckDistinct(PETSC_COMM_WORLD, outs[k], opts[k], paths[i], "-fit_input"));
  }
  if (h5[0] && json[0]) {
    PetscBool same;
    PetscCall(PetscStrcmp(h5, json, &same));
    PetscCheck(!same, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-fit_output and -fit_json name the same file %s", h5);
    PetscCall(HylcFileCheckDistinct(PETSC_COMM_WORLD, json, "-fit_json", h5, "-fit_output"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the work of hylc-fit on fit (created and destroyed by Run, also on an error) */
static PetscErrorCode Fit(HylcFit fit)
{
  HylcMaterial   mat = NULL;
  PetscBool      help_only;
  PetscErrorCode ierr;
  char           in[PETSC_MAX_PATH_LEN] = "", h5[PETSC_MAX_PATH_LEN] = "", json[PETSC_MAX_PATH_LEN] = "";

  PetscFunctionBeginUser;
  PetscCall(HylcFitSetFromOptions(fit));
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (help_only) PetscFunctionReturn(PETSC_SUCCESS); /* -help: every option has been listed; do no work */
  PetscCall(HylcCheckOptionsUsed(PETSC_COMM_WORLD));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-fit_input", in, sizeof(in), NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-fit_output", h5, sizeof(h5), NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-fit_json", json, sizeof(json), NULL));
  PetscCall(CheckPaths(in, h5, json));
  PetscCall(HylcFitSetUp(fit));
  PetscCall(HylcMaterialCreate(PETSC_COMM_WORLD, &mat));
  ierr = HylcFitRun(fit, mat);
  if (!ierr) ierr = HylcFitView(fit, PETSC_VIEWER_STDOUT_WORLD);
  PetscCall(HylcMaterialDestroy(&mat));
  PetscCall(ierr);
  if (h5[0]) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", h5));
  if (json[0]) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", json));
  if (!h5[0] && !json[0]) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "nothing written (no -fit_output or -fit_json)\n"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcFit        fit;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcFitCreate(PETSC_COMM_WORLD, &fit));
  ierr = Fit(fit);
  PetscCall(HylcFitDestroy(&fit));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
