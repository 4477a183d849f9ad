static const char help[] = "hylc-eval: the homogenized material model Psi(s) and its derivatives at one strain.\n\n"
                           "  hylc-eval -material stock1.json -strain 0.1,0,0,0,0,0\n"
                           "  hylc-eval -material model.h5 -strain 0,0.2,0,50,10,-20 -derivatives\n"
                           "  hylc-eval -material stock1.json -eval_hdf5 stock1.h5     (convert; also -eval_json)\n"
                           "  hylc-eval -material stock1.json -eval_input strains.txt -eval_output out.txt [-derivatives]\n"
                           "  hylc-eval -material stock1.json -eval_uniaxial x -eval_uniaxial_strains 0.05,0.1,0.2 -eval_uniaxial_csv x.csv\n\n"
                           "The material is an ARCSim-HYLC JSON table or a hylc HDF5 file (docs/material.md), recognized by\n"
                           "content. The strain is s = (sx, sa, sy, II00, II01, II11): stretches and shear (1), the second\n"
                           "fundamental form (1/m). Prints 'psi: <J/m^2>' and, with -derivatives, 'grad:' (dPsi/ds, 6 numbers)\n"
                           "and 'hessian:' (6 lines of 6). With -eval_uniaxial x|y: the homogeneous uniaxial tension state at each\n"
                           "stretch (Psi minimized over the two free strains; T = dPsi/ds in N/m; docs/fabric-uniaxial.md).\n\n";

#include <hylc/material.h>
#include <hylc/files.h>
#include <hylc/options.h>
#include <hylc/table.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* parses "a,b,c,d,e,f" into s[6]; errors name the option and the value */
static PetscErrorCode ParseStrain(const char text[], PetscReal s[6])
{
  const char *c = text;
  int         n = 0;

  PetscFunctionBegin;
  for (;;) {
    char  *end;
    double v;
    char   tok[64];
    size_t k = 0;
    while (c[k] && c[k] != ',' && k < sizeof(tok) - 1) {
      tok[k] = c[k];
      k++;
    }
    tok[k] = 0;
    errno  = 0;
    v      = strtod(tok, &end);
    while (*end == ' ') end++;
    /* finite is finite: a subnormal value (strtod's ERANGE on underflow) is accepted, an overflow is not */
    PetscCheck(k > 0 && end != tok && !*end && isfinite(v), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-strain %s: '%s' is not a finite number (expected 6 comma-separated values sx,sa,sy,II00,II01,II11)", text, tok);
    PetscCheck(n < 6, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-strain %s: more than 6 values (expected sx,sa,sy,II00,II01,II11)", text);
    s[n++] = v;
    c += k;
    if (*c != ',') break;
    c++;
  }
  PetscCheck(!*c, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-strain %s: a value is too long", text);
  PetscCheck(n == 6, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-strain %s: needs 6 comma-separated values sx,sa,sy,II00,II01,II11, got %d", text, n);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a line of numbers in %.17g (C printf: PETSc's appends '.' to integral %g values) */
static PetscErrorCode PrintNumbers(const char label[], int n, const PetscReal v[])
{
  char line[512] = "", num[40];

  PetscFunctionBegin;
  for (int i = 0; i < n; i++) {
    snprintf(num, sizeof(num), "%s%.17g", i || label[0] ? " " : "", (double)v[i]);
    PetscCall(PetscStrlcat(line, num, sizeof(line)));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s%s\n", label, line));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* writes psi (n), and with deriv grad (n x 6), hess (n x 36): text (one line per strain: psi, 6 grad,
   36 Hessian numbers in %.17g) or HDF5 (datasets strain, psi, grad, hessian), chosen by the suffix .h5 */
static PetscErrorCode WriteResults(const char path[], PetscInt n, const PetscReal *z, const PetscReal *psi, const PetscReal *grad, const PetscReal *hess)
{
  size_t l = strlen(path);

  PetscFunctionBegin;
  if (l > 3 && (!strcmp(path + l - 3, ".h5") || (l > 5 && !strcmp(path + l - 5, ".hdf5")))) {
    const HylcFileH5Doubles ds[4] = {{"strain", 2, {(size_t)n, 6}, z}, {"psi", 1, {(size_t)n}, psi}, {"grad", 2, {(size_t)n, 6}, grad}, {"hessian", 3, {(size_t)n, 6, 6}, hess}};
    PetscCall(HylcFileWriteHDF5(path, "-eval_output", 4, ds));
  } else {
    FILE *fp;
    char  tmp[PETSC_MAX_PATH_LEN + 32];
    PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
    fprintf(fp, "# psi%s (hylc-eval -eval_input; %%.17g)\n", grad ? ", grad (6), hessian (36, row-major)" : "");
    for (PetscInt k = 0; k < n; k++) {
      fprintf(fp, "%.17g", (double)psi[k]);
      for (int i = 0; grad && i < 6; i++) fprintf(fp, " %.17g", (double)grad[6 * k + i]);
      for (int i = 0; hess && i < 36; i++) fprintf(fp, " %.17g", (double)hess[36 * k + i]);
      fputc('\n', fp);
    }
    PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* psi (and with deriv grad, hess) at the n strains z, written by rank 0 */
static PetscErrorCode EvalStrains(HylcMaterial mat, PetscInt n, const PetscReal *z, const char out[], PetscBool deriv)
{
  PetscReal     *psi, *grad = NULL, *hess = NULL;
  PetscMPIInt    rank;
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(n + 1, &psi));
  if (deriv) PetscCall(PetscMalloc2(6 * n + 6, &grad, 36 * n + 36, &hess));
  for (PetscInt k = 0; k < n && !ierr; k++) ierr = HylcMaterialEvaluate(mat, z + 6 * k, &psi[k], grad ? grad + 6 * k : NULL, hess ? hess + 36 * k : NULL);
  if (!ierr) ierr = MPI_Comm_rank(PETSC_COMM_WORLD, &rank) ? PETSC_ERR_MPI : PETSC_SUCCESS;
  if (!ierr && rank == 0) ierr = WriteResults(out, n, z, psi, grad, hess);
  PetscCall(PetscFree(psi));
  if (deriv) PetscCall(PetscFree2(grad, hess));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode EvalBatch(HylcMaterial mat, const char in[], const char out[], PetscBool deriv)
{
  HylcTable      T;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  /* the one reader of strain tables (include/hylc/table.h): text (6 numbers per line, lines of any
     length) or HDF5 (/strain, /samples/strain); every strain finite and in the domain */
  PetscCall(HylcTableReadStrainFile(in, "-eval_input", &T));
  ierr = EvalStrains(mat, T.n, T.v, out, deriv);
  if (!ierr) ierr = PetscPrintf(PETSC_COMM_WORLD, "evaluated %" PetscInt_FMT " strains from %s, wrote %s\n", T.n, in, out);
  PetscCall(HylcTableDestroy(&T));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -eval_uniaxial: the uniaxial states at the stretches s[0..n), the first from the lowest point of a grid of the
   lateral strains, each other from the lateral strains of the one before (a loading path) */
static PetscErrorCode EvalUniaxial(HylcMaterial mat, PetscInt dir, PetscInt n, const PetscReal s[], const char csv[])
{
  PetscReal  *T, *sa, *s2, lat[2] = {0, 0};
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCall(PetscMalloc3(n, &T, n, &sa, n, &s2));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal psi;
    char      buf[256];
    PetscCall(HylcMaterialUniaxial(mat, dir, s[i], i ? lat : NULL, &T[i], lat, &psi, NULL));
    sa[i] = lat[0];
    s2[i] = lat[1];
    snprintf(buf, sizeof(buf), "uniaxial %s: s %.6g T %.9e N/m sa %.6e %s %.6e psi %.10e\n", dir ? "y" : "x", (double)s[i], (double)T[i], (double)sa[i], dir ? "sx" : "sy", (double)s2[i], (double)psi);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
  }
  for (PetscInt i = 0; i < n; i++)
    if (s[i] > 0) {
      char buf[160];
      snprintf(buf, sizeof(buf), "poisson ratio -%s/s%s at s = %g: %.6g\n", dir ? "sx" : "sy", dir ? "y" : "x", (double)s[i], (double)(-s2[i] / s[i]));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
      break;
    }
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (csv[0]) {
    if (rank == 0) PetscCall(HylcWriteUniaxialCSV(csv, n, s, T, sa, s2));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", csv));
  }
  PetscCall(PetscFree3(T, sa, s2));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the work of hylc-eval on the material mat (created and destroyed by Run, also on an error) */
static PetscErrorCode Eval(HylcMaterial mat)
{
  char      bin[PETSC_MAX_PATH_LEN] = "", bout[PETSC_MAX_PATH_LEN] = "";
  PetscBool hasIn, hasOut;
  char      file[PETSC_MAX_PATH_LEN] = "", strain[512] = "", json[PETSC_MAX_PATH_LEN] = "", h5[PETSC_MAX_PATH_LEN] = "", matFile[PETSC_MAX_PATH_LEN] = "";
  PetscBool hasFile, hasStrain, deriv = PETSC_FALSE, help, hasJson, hasH5, hasMatFile;
  PetscReal s[6], psi, grad[6], hess[36];
  char      udir[16] = "", ucsv[PETSC_MAX_PATH_LEN] = "";
  PetscBool hasUni, hasUStrains, hasUCsv;
  PetscReal ustrain[256] = {0.05, 0.1, 0.2};
  PetscInt  nu = 256, udirn = 0;

  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "hylc-eval options", "hylc-eval");
  PetscCall(HylcOptionsString("-material", "Material model: ARCSim-HYLC JSON or hylc HDF5 (required; same as -material_file)", "HylcMaterialLoad", file, file, sizeof(file), &hasFile));
  PetscCall(HylcOptionsString("-strain", "Strain sx,sa,sy,II00,II01,II11 (II in 1/m) at which to evaluate Psi", "HylcMaterialEvaluate", strain, strain, sizeof(strain), &hasStrain));
  PetscCall(PetscOptionsBool("-derivatives", "Also print the gradient and the Hessian of Psi with respect to the six strains", "HylcMaterialEvaluate", deriv, &deriv, NULL));
  PetscCall(HylcOptionsString("-eval_json", "Write the material as ARCSim-HYLC JSON to this file (never the input)", "HylcMaterialWriteJSON", json, json, sizeof(json), &hasJson));
  PetscCall(HylcOptionsString("-eval_hdf5", "Write the material as hylc HDF5 to this file (never the input)", "HylcMaterialWriteHDF5", h5, h5, sizeof(h5), &hasH5));
  PetscCall(HylcOptionsString("-eval_input", "Batch mode: evaluate at the strains of this file (text: 6 numbers per line; HDF5: dataset /strain or /samples/strain, N x 6)", "HylcMaterialEvaluate", bin, bin, sizeof(bin), &hasIn));
  PetscCall(HylcOptionsString("-eval_output", "Batch mode: write psi (and with -derivatives grad, hessian) per strain here: text, or HDF5 if it ends in .h5", "HylcMaterialEvaluate", bout, bout, sizeof(bout), &hasOut));
  PetscCall(HylcOptionsString("-eval_uniaxial", "Uniaxial tension mode: x or y, the material axis of the prescribed stretch; Psi minimized over the other two in-plane strains, bending zero (docs/fabric-uniaxial.md)", "HylcMaterialUniaxial", udir,
                              udir, sizeof(udir), &hasUni));
  PetscCall(HylcOptionsRealArray(
      "-eval_uniaxial_strains",
      "Uniaxial mode: the stretches s in [0, 1) (strain, 0 at rest; default 0.05,0.1,0.2; at most 256), in this order: the first from the lowest point of a grid of the lateral strains, each other from the lateral strains of the one before",
      "HylcMaterialUniaxial", ustrain, &nu, &hasUStrains));
  PetscCall(HylcOptionsString("-eval_uniaxial_csv", "Uniaxial mode: write strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2 (T in N/m) to this CSV file", "HylcWriteUniaxialCSV", ucsv, ucsv, sizeof(ucsv), &hasUCsv));
  PetscOptionsEnd();
  if (!hasUStrains) nu = 3;
  PetscCheck(hasUni || (!hasUStrains && !hasUCsv), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_uniaxial_strains and -eval_uniaxial_csv need -eval_uniaxial x|y");
  PetscCheck(!hasUStrains || nu > 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_uniaxial_strains: needs at least one stretch");
  PetscCheck(!hasUCsv || ucsv[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_uniaxial_csv needs a file name");
  if (hasUni) {
    PetscBool isx, isy;
    PetscCall(PetscStrcmp(udir, "x", &isx));
    PetscCall(PetscStrcmp(udir, "y", &isy));
    PetscCheck(isx || isy, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_uniaxial %s: unknown direction (x or y, the material axis of the stretch)", udir);
    udirn = isy ? 1 : 0;
    for (PetscInt i = 0; i < nu; i++)
      PetscCheck(ustrain[i] >= 0 && ustrain[i] < 1, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_uniaxial_strains: stretch %g is outside [0, 1) (a uniaxial state is a tension test; a compressed strip buckles)", (double)ustrain[i]);
  }
  PetscCall(HylcMaterialGetOptionsFile(mat, matFile, sizeof(matFile), &hasMatFile));
  PetscCheck(!(hasFile && hasMatFile), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "Both -material and -material_file were given; use one");
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) {                                   /* -help: every option has been listed; do no work */
    PetscCall(HylcMaterialSetFromOptions(mat)); /* lists -material_file, -material_view */
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(hasFile || hasMatFile, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "hylc-eval needs a material: -material model.json|model.h5 (-help lists the options)");
  PetscCheck(!hasFile || file[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-material needs a file name");
  PetscCheck(!hasMatFile || matFile[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-material_file needs a file name");
  PetscCheck(!hasStrain || strain[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-strain needs 6 comma-separated values sx,sa,sy,II00,II01,II11");
  PetscCheck(!hasJson || json[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_json needs a file name");
  PetscCheck(!hasH5 || h5[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_hdf5 needs a file name");
  PetscCheck(hasIn == hasOut, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "Batch mode needs both -eval_input strains.txt|.h5 and -eval_output out.txt|.h5");
  PetscCheck(!hasIn || (bin[0] && bout[0]), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_input and -eval_output need file names");
  PetscCheck(!(hasIn && hasStrain), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-strain and -eval_input exclude each other");
  PetscCheck(hasStrain || hasJson || hasH5 || hasIn || hasUni, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "Nothing to do: give -strain sx,sa,sy,II00,II01,II11 (or -eval_json / -eval_hdf5 to convert the material, -eval_uniaxial x|y for the uniaxial states)");
  PetscCheck(!deriv || hasStrain || hasIn, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-derivatives needs -strain");
  if (hasStrain) PetscCall(ParseStrain(strain, s));
  /* every file before any work (include/hylc/files.h): the inputs readable, the outputs writable and
     within the path limits, no output an input (the options files too) or another output */
  {
    HylcFiles      files;
    PetscErrorCode ierr;
    PetscCall(HylcFilesCreate(PETSC_COMM_WORLD, &files));
    ierr = HylcFilesAddOptionsFiles(files);
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, hasFile ? file : matFile, hasFile ? "-material" : "-material_file");
    if (!ierr && hasIn) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, bin, "-eval_input");
    if (!ierr && hasIn) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, bout, "-eval_output");
    if (!ierr && hasJson) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, json, "-eval_json");
    if (!ierr && hasH5) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, h5, "-eval_hdf5");
    if (!ierr && hasUCsv) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, ucsv, "-eval_uniaxial_csv");
    if (!ierr) ierr = HylcFilesCheck(files);
    PetscCall(HylcFilesDestroy(&files));
    PetscCall(ierr);
  }
  PetscCall(HylcMaterialSetFromOptions(mat)); /* -material_file (loads it), -material_view */
  PetscCall(HylcCheckOptionsUsed(PETSC_COMM_WORLD));
  if (hasFile) PetscCall(HylcMaterialLoad(mat, file));
  PetscCall(HylcMaterialViewFromOptions(mat, NULL, "-material_view"));
  if (hasStrain) {
    PetscBool saturated = PETSC_FALSE;
    PetscCall(HylcMaterialEvaluate(mat, s, &psi, deriv ? grad : NULL, deriv ? hess : NULL));
    saturated = (PetscBool)(PetscAbsReal(psi) == PETSC_MAX_REAL);
    for (int i = 0; deriv && i < 6; i++) saturated = (PetscBool)(saturated || PetscAbsReal(grad[i]) == PETSC_MAX_REAL);
    for (int i = 0; deriv && i < 36; i++) saturated = (PetscBool)(saturated || PetscAbsReal(hess[i]) == PETSC_MAX_REAL);
    PetscCall(PrintNumbers("psi:", 1, &psi));
    if (deriv) {
      PetscCall(PrintNumbers("grad:", 6, grad));
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "hessian:\n"));
      for (int i = 0; i < 6; i++) PetscCall(PrintNumbers("", 6, hess + 6 * i));
    }
    if (saturated) PetscCall(PetscFPrintf(PETSC_COMM_WORLD, stderr, "hylc: warning: at this strain a value exceeds the double range and is printed as +-%.17g (saturated)\n", (double)PETSC_MAX_REAL));
  }
  if (hasIn) PetscCall(EvalBatch(mat, bin, bout, deriv));
  if (hasUni) PetscCall(EvalUniaxial(mat, udirn, nu, ustrain, ucsv));
  if (hasJson) {
    PetscCall(HylcMaterialWriteJSON(mat, json));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", json));
  }
  if (hasH5) {
    PetscCall(HylcMaterialWriteHDF5(mat, h5, NULL));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", h5));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcMaterial   mat;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcMaterialCreate(PETSC_COMM_WORLD, &mat));
  ierr = Eval(mat); /* the material is destroyed on every exit, an error one too */
  PetscCall(HylcMaterialDestroy(&mat));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
