static const char help[] = "hylc-fit: fits the homogenized material model (the spline tables of (S26)) to microscale samples\n"
                           "(Algorithms C5-C7; docs/fit.md) and writes it as HDF5 and/or ARCSim-HYLC JSON.\n\n"
                           "  hylc-fit -fit_input samples.h5 -fit_output model.h5 -fit_json model.json\n"
                           "  hylc-fit -fit_input raw/ -fit_json model.json -fit_family stockinette   (the paper's data.txt, info.txt)\n\n";

#include <hylc/fit.h>
#include <hylc/files.h>
#include <string.h>
#include <sys/stat.h>

/* every file before any work (include/hylc/files.h): the input (a directory: its data.txt and, when
   there, info.txt; a file: it and the info.txt beside it, which a raw input reads), the options files,
   the outputs writable and within the path limits, no output an input or the other output */
static PetscErrorCode CheckPaths(const char in[], const char h5[], const char json[])
{
  char           data[PETSC_MAX_PATH_LEN + 16] = "", info[PETSC_MAX_PATH_LEN + 16] = "";
  struct stat    st;
  HylcFiles      files;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  if (in[0] && !stat(in, &st) && S_ISDIR(st.st_mode)) {
    PetscCall(PetscSNPrintf(data, sizeof(data), "%s/data.txt", in));
    PetscCall(PetscSNPrintf(info, sizeof(info), "%s/info.txt", in));
    PetscCheck(!stat(data, &st), PETSC_COMM_WORLD, PETSC_ERR_FILE_OPEN, "-fit_input %s is a directory without data.txt (the paper's raw layout)", in);
  } else if (in[0]) {
    const char *slash = strrchr(in, '/');
    PetscCall(PetscStrncpy(data, in, sizeof(data)));
    if (slash)
      PetscCall(PetscSNPrintf(info, sizeof(info), "%.*sinfo.txt", (int)(slash - in + 1), in));
    else
      PetscCall(PetscStrncpy(info, "info.txt", sizeof(info)));
  }
  PetscCall(HylcFilesCreate(PETSC_COMM_WORLD, &files));
  ierr = HylcFilesAddOptionsFiles(files);
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, data, "-fit_input");
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT_OPTIONAL, info, "-fit_input");
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, h5, "-fit_output");
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, json, "-fit_json");
  if (!ierr) ierr = HylcFilesCheck(files);
  PetscCall(HylcFilesDestroy(&files));
  PetscCall(ierr);
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
