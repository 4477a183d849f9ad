static const char help[] = "hylc-eval: the homogenized material model Psi(s) and its derivatives at one strain.\n\n"
                           "  hylc-eval -material stock1.json -strain 0.1,0,0,0,0,0\n"
                           "  hylc-eval -material model.h5 -strain 0,0.2,0,50,10,-20 -derivatives\n"
                           "  hylc-eval -material stock1.json -eval_hdf5 stock1.h5     (convert; also -eval_json)\n"
                           "  hylc-eval -material stock1.json -eval_input strains.txt -eval_output out.txt [-derivatives]\n"
                           "  hylc-eval -material stock1.json -eval_uniaxial x -eval_uniaxial_strains 0.05,0.1,0.2 -eval_uniaxial_csv x.csv\n"
                           "  hylc-eval -measured 11oz-black-denim.json -eval_sheet     (measured cloth: the fabric sheet; also a table's)\n"
                           "  hylc-eval -material stock1.json -eval_measured_json stock1-mc.json   (a table written as measured cloth)\n\n"
                           "The material is an ARCSim-HYLC JSON table or a hylc HDF5 file (docs/material.md), recognized by\n"
                           "content. The strain is s = (sx, sa, sy, II00, II01, II11): stretches and shear (1), the second\n"
                           "fundamental form (1/m). Prints 'psi: <J/m^2>' and, with -derivatives, 'grad:' (dPsi/ds, 6 numbers)\n"
                           "and 'hessian:' (6 lines of 6). With -eval_uniaxial x|y: the homogeneous uniaxial tension state at each\n"
                           "stretch (Psi minimized over the two free strains; T = dPsi/ds in N/m; docs/fabric-uniaxial.md).\n"
                           "-eval_sheet prints a fabric sheet (strip tension along x, y and the 45 degree bias, Poisson ratio, bending\n"
                           "moment, density) of a table or of a measured-cloth material (-measured: the data-driven model of Wang,\n"
                           "O'Brien, Ramamoorthi 2011 as ARCSim evaluates it; docs/measured-cloth.md).\n\n";

#include <hylc/material.h>
#include <hylc/files.h>
#include <hylc/options.h>
#include <hylc/table.h>
#include <hylcmat.h>
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

/* -eval_path: the states of a load path at the values s[0..n), the first from the lowest point of a grid of the
   free strains, each other from the free strains of the one before (a loading path) */
static PetscErrorCode EvalPath(HylcMaterial mat, const hylcmat_path *path, PetscInt n, const PetscReal s[], const char csv[])
{
  PetscReal  *F, *Z, *psi, p[3] = {0, 0, 0};
  PetscBool  *conv;
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCall(PetscMalloc4(n, &F, 6 * n, &Z, n, &psi, n, &conv));
  for (PetscInt i = 0; i < n; i++) {
    hylcmat_path_result r;
    char                buf[320];
    PetscCall(HylcMaterialPathState(mat, path, s[i], i ? p : NULL, &r, &conv[i]));
    F[i]   = r.force;
    psi[i] = r.psi;
    for (int k = 0; k < 6; k++) Z[6 * i + k] = r.z[k];
    for (int a = 0; a < 3; a++) p[a] = r.p[a];
    snprintf(buf, sizeof(buf), "%s %g: s %.6g force %.9e %s z %.6e %.6e %.6e %.6e %.6e %.6e psi %.10e%s\n", hylcmat_path_name(path->kind), path->angle, (double)s[i], (double)F[i], path->kind == HYLCMAT_PATH_BENDING ? "N" : "N/m", (double)r.z[0],
             (double)r.z[1], (double)r.z[2], (double)r.z[3], (double)r.z[4], (double)r.z[5], (double)psi[i], conv[i] ? "" : " NOT CONVERGED");
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
  }
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (csv[0]) {
    if (rank == 0) PetscCall(HylcWritePathCSV(csv, n, s, F, Z, psi, conv));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", csv));
  }
  PetscCall(PetscFree4(F, Z, psi, conv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- the fabric sheet (-eval_sheet) ------------------------------------------------------------ */
#define SHEET_MAX 64
typedef struct {
  PetscReal T, lateral, shear;
  PetscBool ok;
} SheetState;

typedef struct {
  PetscBool  measured, energy;
  PetscInt   ns, nk;
  PetscReal  s[SHEET_MAX], kappa[SHEET_MAX], density;
  SheetState t[3][SHEET_MAX], te[3][SHEET_MAX]; /* x, y, bias: the balance (frozen) and, measured cloth, the energy's */
  PetscReal  M[2][SHEET_MAX], Me[2][SHEET_MAX];
} Sheet;

static const char *const SheetDir[3] = {"x", "y", "bias"};

/* a measured-cloth material's sheet */
static PetscErrorCode SheetMeasured(const char path[], Sheet *sh)
{
  hylcmat_measured *mc;
  char              err[1024];
  int               r;

  PetscFunctionBegin;
  r = hylcmat_measured_load(path, &mc, err, sizeof(err));
  PetscCheck(!r, PETSC_COMM_WORLD, r == HYLCMAT_ERR_OPEN ? PETSC_ERR_FILE_OPEN : r == HYLCMAT_ERR_READ ? PETSC_ERR_FILE_READ : r == HYLCMAT_ERR_MEMORY ? PETSC_ERR_MEM : PETSC_ERR_USER_INPUT, "%s", err[0] ? err : hylcmat_strerror(r));
  sh->density = hylcmat_measured_density(mc);
  for (int d = 0; d < 3; d++)
    for (PetscInt i = 0; i < sh->ns; i++)
      for (int mode = 0; mode < (sh->energy ? 2 : 1); mode++) {
        hylcmat_measured_state st;
        SheetState            *o = mode ? &sh->te[d][i] : &sh->t[d][i];
        o->ok                    = (PetscBool)!hylcmat_measured_tension(mc, d, (double)sh->s[i], mode ? HYLCMAT_MEASURED_ENERGY : HYLCMAT_MEASURED_FROZEN, &st, NULL, 0);
        o->T                     = st.T;
        o->lateral               = st.lateral;
        o->shear                 = st.shear;
      }
  for (int d = 0; d < 2; d++)
    for (PetscInt i = 0; i < sh->nk; i++) {
      double M, Me;
      hylcmat_measured_bending(mc, d, (double)sh->kappa[i], HYLCMAT_MEASURED_FROZEN, &M, NULL);
      hylcmat_measured_bending(mc, d, (double)sh->kappa[i], HYLCMAT_MEASURED_ENERGY, &Me, NULL);
      sh->M[d][i]  = M;
      sh->Me[d][i] = Me;
    }
  hylcmat_measured_free(mc);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a table's sheet: each direction along the load path s = 0.005, 0.01, ... (and the stretches asked),
   each state continued from the one before; bending dPsi/dII at zero in-plane strain */
static PetscErrorCode SheetTable(HylcMaterial mat, Sheet *sh)
{
  PetscReal smax = 0;

  PetscFunctionBegin;
  PetscCall(HylcMaterialGetDensity(mat, &sh->density));
  for (PetscInt i = 0; i < sh->ns; i++) smax = PetscMax(smax, sh->s[i]);
  for (int d = 0; d < 3; d++) {
    const PetscReal phi = d == 0 ? 0 : d == 1 ? PETSC_PI / 2 : PETSC_PI / 4;
    PetscReal       guess[2], *gp = NULL, prev = 0;
    for (;;) { /* the next stretch: the smaller of the next path point and the next one asked */
      PetscReal next = PetscFloorReal(prev / 0.005 + 1 + 1e-9) * 0.005;
      for (PetscInt i = 0; i < sh->ns; i++)
        if (sh->s[i] > prev + 1e-12 && sh->s[i] < next) next = sh->s[i];
      if (next > smax + 1e-12) break;
      PetscReal T, lat[2];
      PetscBool conv;
      PetscCall(HylcMaterialTension(mat, phi, next, gp, &T, lat, &conv));
      if (conv) {
        guess[0] = 1 + lat[0], guess[1] = lat[1], gp = guess;
      }
      for (PetscInt i = 0; i < sh->ns; i++)
        if (PetscAbsReal(sh->s[i] - next) <= 1e-12) {
          sh->t[d][i].ok      = conv;
          sh->t[d][i].T       = T;
          sh->t[d][i].lateral = lat[0];
          sh->t[d][i].shear   = lat[1];
        }
      prev = next;
    }
  }
  for (int d = 0; d < 2; d++)
    for (PetscInt i = 0; i < sh->nk; i++) {
      PetscReal z[6] = {0, 0, 0, 0, 0, 0}, psi, g[6];
      z[d ? 5 : 3]   = sh->kappa[i];
      PetscCall(HylcMaterialEvaluate(mat, z, &psi, g, NULL));
      sh->M[d][i] = g[d ? 5 : 3];
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SheetPrint(const char name[], const Sheet *sh)
{
  char buf[512];

  PetscFunctionBegin;
  if (sh->measured)
    snprintf(buf, sizeof(buf), "sheet of the measured cloth %s: strips at the balance of the frozen-stiffness forces%s; bending on a regular mesh of right triangles with edges along u and v\n", name,
             sh->energy ? " (and, marked energy, at the stationarity of the energy itself)" : "");
  else
    snprintf(buf, sizeof(buf), "sheet of the table %s: strips with Psi minimized over the lateral strains (load path in steps of 0.005); bending dPsi/dII at zero in-plane strain\n", name);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
  snprintf(buf, sizeof(buf), "density: %.6g kg/m^2\n", (double)sh->density);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
  for (int d = 0; d < 3; d++)
    for (PetscInt i = 0; i < sh->ns; i++)
      for (int mode = 0; mode < (sh->energy ? 2 : 1); mode++) {
        const SheetState *o = mode ? &sh->te[d][i] : &sh->t[d][i];
        if (!o->ok)
          snprintf(buf, sizeof(buf), "tension %s%s: s %g not reached (no lateral balance)\n", SheetDir[d], mode ? " energy" : "", (double)sh->s[i]);
        else {
          int n = snprintf(buf, sizeof(buf), "tension %s%s: s %g T %.6e N/m lateral %.6e poisson %.6g shear %.6e", SheetDir[d], mode ? " energy" : "", (double)sh->s[i], (double)o->T, (double)o->lateral, (double)(-o->lateral / sh->s[i]),
                           (double)o->shear);
          if (mode && sh->t[d][i].ok) snprintf(buf + n, sizeof(buf) - (size_t)n, " (T %+.2f %% against the balance)", (double)(100 * (o->T / sh->t[d][i].T - 1)));
          PetscCall(PetscStrlcat(buf, "\n", sizeof(buf)));
        }
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
      }
  for (int d = 0; d < 2; d++)
    for (PetscInt i = 0; i < sh->nk; i++) {
      snprintf(buf, sizeof(buf), "bending %s: kappa %g 1/m M %.6e N m/m\n", SheetDir[d], (double)sh->kappa[i], (double)sh->M[d][i]);
      PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
      if (sh->measured && sh->energy) {
        snprintf(buf, sizeof(buf), "bending %s energy: kappa %g 1/m M %.6e N m/m\n", SheetDir[d], (double)sh->kappa[i], (double)sh->Me[d][i]);
        PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
      }
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the figures as JSON (rank 0 writes); a state not reached is null */
static PetscErrorCode SheetWriteJSON(const char path[], const char name[], const Sheet *sh)
{
  PetscMPIInt rank;
  FILE       *fp;
  char        tmp[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  if (rank == 0) {
    PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
    fprintf(fp, "{\n  \"material\": \"");
    for (const char *c = name; *c; c++) fprintf(fp, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
    fprintf(fp, "\",\n  \"kind\": \"%s\",\n  \"density\": %.17g,\n", sh->measured ? "measured" : "table", (double)sh->density);
    for (int mode = 0; mode < (sh->energy ? 2 : 1); mode++) {
      fprintf(fp, "  \"%s\": {", mode ? "tension_energy" : "tension");
      for (int d = 0; d < 3; d++) {
        fprintf(fp, "%s\n    \"%s\": [", d ? "," : "", SheetDir[d]);
        for (PetscInt i = 0; i < sh->ns; i++) {
          const SheetState *o = mode ? &sh->te[d][i] : &sh->t[d][i];
          if (o->ok)
            fprintf(fp, "%s{\"s\": %.17g, \"T\": %.17g, \"lateral\": %.17g, \"poisson\": %.17g, \"shear\": %.17g}", i ? ", " : "", (double)sh->s[i], (double)o->T, (double)o->lateral, (double)(-o->lateral / sh->s[i]), (double)o->shear);
          else
            fprintf(fp, "%s{\"s\": %.17g, \"T\": null}", i ? ", " : "", (double)sh->s[i]);
        }
        fprintf(fp, "]");
      }
      fprintf(fp, "\n  },\n");
    }
    for (int mode = 0; mode < (sh->measured && sh->energy ? 2 : 1); mode++) {
      fprintf(fp, "  \"%s\": {", mode ? "bending_energy" : "bending");
      for (int d = 0; d < 2; d++) {
        fprintf(fp, "%s\n    \"%s\": [", d ? "," : "", SheetDir[d]);
        for (PetscInt i = 0; i < sh->nk; i++) fprintf(fp, "%s{\"kappa\": %.17g, \"M\": %.17g}", i ? ", " : "", (double)sh->kappa[i], (double)(mode ? sh->Me[d][i] : sh->M[d][i]));
        fprintf(fp, "]");
      }
      fprintf(fp, "\n  }%s\n", mode == 0 && sh->measured && sh->energy ? "," : "");
    }
    fprintf(fp, "}\n");
    PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the work of hylc-eval on the material mat (created and destroyed by Run, also on an error) */
static PetscErrorCode Eval(HylcMaterial mat)
{
  char         bin[PETSC_MAX_PATH_LEN] = "", bout[PETSC_MAX_PATH_LEN] = "";
  PetscBool    hasIn, hasOut;
  char         file[PETSC_MAX_PATH_LEN] = "", strain[512] = "", json[PETSC_MAX_PATH_LEN] = "", h5[PETSC_MAX_PATH_LEN] = "", matFile[PETSC_MAX_PATH_LEN] = "";
  PetscBool    hasFile, hasStrain, deriv = PETSC_FALSE, help, hasJson, hasH5, hasMatFile;
  PetscReal    s[6], psi, grad[6], hess[36];
  char         udir[16] = "", ucsv[PETSC_MAX_PATH_LEN] = "";
  PetscBool    hasUni, hasUStrains, hasUCsv;
  PetscReal    ustrain[256] = {0.05, 0.1, 0.2};
  PetscInt     nu = 256, udirn = 0, npv = 256;
  char         pcsv[PETSC_MAX_PATH_LEN] = "";
  PetscBool    pathSet, hasPathValues;
  PetscReal    pvalues[256];
  PetscEnum    pkind                        = 0;
  hylcmat_path path                         = {HYLCMAT_PATH_UNIAXIAL, 0};
  char         measured[PETSC_MAX_PATH_LEN] = "", sjson[PETSC_MAX_PATH_LEN] = "", mjson[PETSC_MAX_PATH_LEN] = "";
  PetscBool    hasMeasured, doSheet = PETSC_FALSE, sheetEnergy = PETSC_FALSE, hasSJson, hasMJson, hasSStrains, hasSKappa;
  Sheet        sheet, *sh = &sheet; /* about 20 kB */
  PetscInt     nss = SHEET_MAX, nsk = SHEET_MAX;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(sh, sizeof(*sh)));
  sh->s[0] = 0.02, sh->s[1] = 0.05, sh->s[2] = 0.1;
  sh->kappa[0] = 10, sh->kappa[1] = 20, sh->kappa[2] = 40;
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
  PetscCall(HylcOptionsEnum("-eval_path",
                            "Load path mode (docs/fabric-fidelity.md): uniaxial (stretch along -eval_path_angle, the other in-plane strains free), equibiaxial (sx = sy, sa free), shear (sa given, sx, sy free) or bending (II00, or II11 with "
                            "-eval_path_angle 90, in-plane strains free)",
                            "HylcMaterialPathState", HylcPathNames, pkind, &pkind, &pathSet));
  PetscCall(HylcOptionsReal("-eval_path_angle", "Path mode: the uniaxial direction in degrees from the material x axis (0 strip along x, 90 along y, 45 bias), or the bending axis (0: II00, 90: II11)", "HylcMaterialPathState", path.angle, &path.angle,
                            NULL));
  PetscCall(HylcOptionsRealArray(
      "-eval_path_values",
      "Path mode: the prescribed values (stretches in [0, 1), sa in (-0.99, 0.99), or curvatures in 1/m), in this order: the first from the lowest point of a grid of the free strains, each other from the one before (at most 256)",
      "HylcMaterialPathState", pvalues, &npv, &hasPathValues));
  PetscCall(HylcOptionsString("-eval_path_csv", "Path mode: write value,force,sx,sa,sy,II00,II11,psi,converged (force in N/m, N for bending) to this CSV file", "HylcWritePathCSV", pcsv, pcsv, sizeof(pcsv), NULL));
  PetscCall(HylcOptionsString("-measured", "A measured-cloth material (the data-driven JSON of Wang, O'Brien, Ramamoorthi 2011 that ARCSim reads: density kg/m^2, stretching 6 x 4, bending 3 x 5) for -eval_sheet, instead of -material",
                              "hylcmat_measured_load", measured, measured, sizeof(measured), &hasMeasured));
  PetscCall(PetscOptionsBool("-eval_sheet",
                             "Print the fabric sheet of the material: strip tension T (N/m) along x, y and the 45 degree bias with the lateral strain and Poisson ratio, bending moment (N m/m), density (kg/m^2) (docs/measured-cloth.md)",
                             "hylcmat_measured_tension", doSheet, &doSheet, NULL));
  PetscCall(HylcOptionsRealArray("-eval_sheet_strains", "Sheet: the strip stretches s in (0, 1) (strain, 0 at rest; default 0.02,0.05,0.1; at most 64)", "hylcmat_measured_tension", sh->s, &nss, &hasSStrains));
  PetscCall(HylcOptionsRealArray("-eval_sheet_curvatures", "Sheet: the curvatures of the bending moments (1/m; default 10,20,40; at most 64)", "hylcmat_measured_bending", sh->kappa, &nsk, &hasSKappa));
  PetscCall(PetscOptionsBool("-eval_sheet_energy", "Sheet of a measured-cloth material: also the states at the stationarity of its energy (k varying), beside the balance of the simulator's frozen-stiffness forces", "hylcmat_measured_tension",
                             sheetEnergy, &sheetEnergy, NULL));
  PetscCall(HylcOptionsString("-eval_sheet_json", "Sheet: write its figures as JSON to this file (T in N/m, M in N m/m, density in kg/m^2)", "hylcmat_measured_tension", sjson, sjson, sizeof(sjson), &hasSJson));
  PetscCall(HylcOptionsString("-eval_measured_json", "Write the table (-material) as a measured-cloth JSON to this file: the least-squares data of docs/measured-cloth.md, \"Export\" (about 20 s)", "HylcMaterialWriteMeasured", mjson, mjson,
                              sizeof(mjson), &hasMJson));
  PetscOptionsEnd();
  sh->ns       = hasSStrains ? nss : 3;
  sh->nk       = hasSKappa ? nsk : 3;
  sh->energy   = sheetEnergy;
  sh->measured = hasMeasured;
  PetscCheck(doSheet || (!hasSStrains && !hasSKappa && !sheetEnergy && !hasSJson), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_sheet_strains, -eval_sheet_curvatures, -eval_sheet_energy and -eval_sheet_json need -eval_sheet");
  PetscCheck(!hasSStrains || nss > 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_sheet_strains: needs at least one stretch");
  PetscCheck(!hasSKappa || nsk > 0, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_sheet_curvatures: needs at least one curvature");
  for (PetscInt i = 0; i < sh->ns; i++) PetscCheck(sh->s[i] > 0 && sh->s[i] < 1, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_sheet_strains: stretch %g is outside (0, 1) (a strip tension test)", (double)sh->s[i]);
  PetscCheck(!hasSJson || sjson[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_sheet_json needs a file name");
  PetscCheck(!hasMJson || mjson[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_measured_json needs a file name");
  PetscCheck(!sheetEnergy || hasMeasured, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_sheet_energy is for a measured-cloth material (-measured); a table's states are the minima of its energy");
  path.kind = (int)pkind;
  PetscCheck(pathSet || (!hasPathValues && !pcsv[0]), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_path_values and -eval_path_csv need -eval_path uniaxial|equibiaxial|shear|bending");
  PetscCheck(!pathSet || (hasPathValues && npv > 0), PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-eval_path %s needs -eval_path_values", HylcPathNames[path.kind]);
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
  if (hasMeasured) { /* a measured-cloth material: its sheet only */
    PetscErrorCode ierr;
    PetscCheck(measured[0], PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-measured needs a file name");
    PetscCheck(!hasFile && !hasMatFile, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "-measured and -material exclude each other (one material per run)");
    PetscCheck(!hasStrain && !hasIn && !hasOut && !hasJson && !hasH5 && !hasUni && !hasMJson, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
               "-measured takes -eval_sheet only (-strain, -eval_input, -eval_json, -eval_hdf5, -eval_uniaxial, -eval_measured_json are for a table)");
    PetscCheck(doSheet, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT, "Nothing to do with -measured: give -eval_sheet");
    {
      HylcFiles files;
      PetscCall(HylcFilesCreate(PETSC_COMM_WORLD, &files));
      ierr = HylcFilesAddOptionsFiles(files);
      if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, measured, "-measured");
      if (!ierr && hasSJson) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, sjson, "-eval_sheet_json");
      if (!ierr) ierr = HylcFilesCheck(files);
      PetscCall(HylcFilesDestroy(&files));
      PetscCall(ierr);
    }
    PetscCall(HylcCheckOptionsUsed(PETSC_COMM_WORLD));
    ierr = SheetMeasured(measured, sh);
    if (!ierr) ierr = SheetPrint(measured, sh);
    if (!ierr && hasSJson) ierr = SheetWriteJSON(sjson, measured, sh);
    PetscCall(ierr);
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
  PetscCheck(hasStrain || hasJson || hasH5 || hasIn || hasUni || pathSet || doSheet || hasMJson, PETSC_COMM_WORLD, PETSC_ERR_USER_INPUT,
             "Nothing to do: give -strain sx,sa,sy,II00,II01,II11 (or -eval_json / -eval_hdf5 to convert the material, -eval_uniaxial x|y for the uniaxial states, -eval_path for a fabric test's states, -eval_sheet for the fabric sheet, "
             "-eval_measured_json to write it as measured cloth)");
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
    if (!ierr && pcsv[0]) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, pcsv, "-eval_path_csv");
    if (!ierr && hasSJson) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, sjson, "-eval_sheet_json");
    if (!ierr && hasMJson) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, mjson, "-eval_measured_json");
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
  if (pathSet) PetscCall(EvalPath(mat, &path, npv, pvalues, pcsv));
  if (hasJson) {
    PetscCall(HylcMaterialWriteJSON(mat, json));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", json));
  }
  if (hasH5) {
    PetscCall(HylcMaterialWriteHDF5(mat, h5, NULL));
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "wrote %s\n", h5));
  }
  if (doSheet) {
    PetscErrorCode ierr = SheetTable(mat, sh);
    if (!ierr) ierr = SheetPrint(hasFile ? file : matFile, sh);
    if (!ierr && hasSJson) ierr = SheetWriteJSON(sjson, hasFile ? file : matFile, sh);
    PetscCall(ierr);
  }
  if (hasMJson) {
    PetscReal fit[5];
    char      buf[512];
    PetscCall(HylcMaterialWriteMeasured(mat, mjson, fit));
    snprintf(
        buf, sizeof(buf),
        "wrote %s (measured cloth: strip tension error RMS %.3g %%, largest %.3g %% at 2-10 %% over 0, 22.5, 45, 67.5, 90 degrees; bending moment error RMS %.3g %%; not representable: a prestress at rest of %.3g N/m, a rest moment of %.3g N m/m)\n",
        mjson, (double)(100 * fit[0]), (double)(100 * fit[1]), (double)(100 * fit[2]), (double)fit[3], (double)fit[4]);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s", buf));
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
