static const char help[] = "hylc-eval: the homogenized material model Psi(s) and its derivatives at one strain.\n\n"
                           "  hylc-eval -material stock1.json -strain 0.1,0,0,0,0,0\n"
                           "  hylc-eval -material model.h5 -strain 0,0.2,0,50,10,-20 -derivatives\n"
                           "  hylc-eval -material stock1.json -eval_hdf5 stock1.h5     (convert; also -eval_json)\n\n"
                           "The material is an ARCSim-HYLC JSON table or a hylc HDF5 file (docs/material.md), recognized by\n"
                           "content. The strain is s = (sx, sa, sy, II00, II01, II11): stretches and shear (1), the second\n"
                           "fundamental form (1/m). Prints 'psi: <J/m^2>' and, with -derivatives, 'grad:' (dPsi/ds, 6 numbers)\n"
                           "and 'hessian:' (6 lines of 6).\n\n";

#include <hylc/material.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>

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

/* the work of hylc-eval on the material mat (created and destroyed by Run, also on an error) */
static PetscErrorCode Eval(HylcMaterial mat)
{
  char      file[PETSC_MAX_PATH_LEN] = "", strain[512] = "", json[PETSC_MAX_PATH_LEN] = "", h5[PETSC_MAX_PATH_LEN] = "", matFile[PETSC_MAX_PATH_LEN] = "";
  PetscBool hasFile, hasStrain, deriv = PETSC_FALSE, help, hasJson, hasH5, hasMatFile;
  PetscReal s[6], psi, grad[6], hess[36];

  PetscFunctionBeginUser;
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "hylc-eval options", "hylc-eval");
  PetscCall(PetscOptionsString("-material", "Material model: ARCSim-HYLC JSON or hylc HDF5 (required; same as -material_file)", "HylcMaterialLoad", file, file, sizeof(file), &hasFile));
  PetscCall(PetscOptionsString("-strain", "Strain sx,sa,sy,II00,II01,II11 (II in 1/m) at which to evaluate Psi", "HylcMaterialEvaluate", strain, strain, sizeof(strain), &hasStrain));
  PetscCall(PetscOptionsBool("-derivatives", "Also print the gradient and the Hessian of Psi with respect to the six strains", "HylcMaterialEvaluate", deriv, &deriv, NULL));
  PetscCall(PetscOptionsString("-eval_json", "Write the material as ARCSim-HYLC JSON to this file (never the input)", "HylcMaterialWriteJSON", json, json, sizeof(json), &hasJson));
  PetscCall(PetscOptionsString("-eval_hdf5", "Write the material as hylc HDF5 to this file (never the input)", "HylcMaterialWriteHDF5", h5, h5, sizeof(h5), &hasH5));
  PetscOptionsEnd();
  PetscCall(PetscOptionsGetString(NULL, NULL, "-material_file", matFile, sizeof(matFile), &hasMatFile));
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
  PetscCheck(hasStrain || hasJson || hasH5, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "Nothing to do: give -strain sx,sa,sy,II00,II01,II11 (or -eval_json / -eval_hdf5 to convert the material)");
  PetscCheck(!deriv || hasStrain, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-derivatives needs -strain");
  if (hasStrain) PetscCall(ParseStrain(strain, s));
  /* every path before any work: the input a readable regular file, each output writable, no output
     the input, and the two outputs not one file */
  {
    const char *in = hasFile ? file : matFile, *inopt = hasFile ? "-material" : "-material_file";
    PetscCall(HylcFileCheckInput(PETSC_COMM_WORLD, in, inopt));
    if (hasJson) {
      PetscCall(HylcFileCheckOutput(PETSC_COMM_WORLD, json, "-eval_json"));
      PetscCall(HylcFileCheckDistinct(PETSC_COMM_WORLD, json, "-eval_json", in, inopt));
    }
    if (hasH5) {
      PetscCall(HylcFileCheckOutput(PETSC_COMM_WORLD, h5, "-eval_hdf5"));
      PetscCall(HylcFileCheckDistinct(PETSC_COMM_WORLD, h5, "-eval_hdf5", in, inopt));
    }
    if (hasJson && hasH5) {
      PetscBool same;
      PetscCall(PetscStrcmp(json, h5, &same));
      PetscCheck(!same, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_json and -eval_hdf5 name the same file %s", json);
      PetscCall(HylcFileCheckDistinct(PETSC_COMM_WORLD, json, "-eval_json", h5, "-eval_hdf5"));
    }
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
