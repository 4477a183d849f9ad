/* HylcFit input: the samples HDF5 file of hylc-sample (docs/output-format.md) and the paper's raw layout
   (data.txt, info.txt; ../shared/docs/formats.md §5). */
#include <hylc/private/fitimpl.h>
#include <hylc/samples.h>
#include <hylc/table.h>
#include <hylc/private/h5util.h>
#include <hdf5.h>
#include <sys/stat.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <errno.h>
#include <stdint.h>

/* ---- HDF5: /reference and /material of a samples file, for the area density ---- */

/* the scalar double attribute 'name' of the object at 'path', or *found = 0 */
static PetscErrorCode H5ReadAttrDouble(hid_t file, const char path[], const char name[], double *v, int *found)
{
  hid_t obj, a;

  PetscFunctionBegin;
  *found = 0;
  if (H5Lexists(file, path, H5P_DEFAULT) <= 0) PetscFunctionReturn(PETSC_SUCCESS);
  obj = H5Oopen(file, path, H5P_DEFAULT);
  if (obj < 0) PetscFunctionReturn(PETSC_SUCCESS);
  if (H5Aexists(obj, name) > 0) {
    a = H5Aopen(obj, name, H5P_DEFAULT);
    if (a >= 0) {
      if (H5Aread(a, H5T_NATIVE_DOUBLE, v) >= 0) *found = 1;
      H5Aclose(a);
    }
  }
  H5Oclose(obj);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* radius, total rest length and periods of the samples file's reference pattern (0 when absent) */
static PetscErrorCode ReadReference(HylcFit fit, const char path[])
{
  hid_t       file, d, s;
  H5E_auto2_t efunc;
  void       *edata;
  double      px = 0, py = 0, r = 0, rm = 0;
  int         f1 = 0, f2 = 0, f3 = 0, f4 = 0;
  hsize_t     dims[2] = {0, 0};

  PetscFunctionBegin;
  fit->radius = fit->restLength = fit->px = fit->py = 0;
  H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file >= 0) {
    PetscCall(H5ReadAttrDouble(file, "reference", "px", &px, &f1));
    PetscCall(H5ReadAttrDouble(file, "reference", "py", &py, &f2));
    PetscCall(H5ReadAttrDouble(file, "reference", "radius", &r, &f3));
    PetscCall(H5ReadAttrDouble(file, "material", "radius", &rm, &f4));
    if (f1 && f2 && f3 && H5Lexists(file, "reference/rest_length", H5P_DEFAULT) > 0 && (d = H5Dopen2(file, "reference/rest_length", H5P_DEFAULT)) >= 0) {
      s = H5Dget_space(d);
      if (s >= 0 && H5Sget_simple_extent_ndims(s) == 1 && H5Sget_simple_extent_dims(s, dims, NULL) == 1 && dims[0] > 0) {
        double *rl;
        PetscCall(PetscMalloc1(dims[0], &rl));
        if (H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rl) >= 0) {
          double L = 0;
          for (hsize_t i = 0; i < dims[0]; i++) L += rl[i];
          fit->restLength = L;
          fit->px         = px;
          fit->py         = py;
          fit->radius     = f4 && rm > 0 ? rm : r; /* the radius the samples were computed with */
        }
        PetscCall(PetscFree(rl));
      }
      if (s >= 0) H5Sclose(s);
      H5Dclose(d);
    }
    H5Fclose(file);
  }
  H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the family of the sampling run (docs/output-format.md: /provenance/identity holds "option -<name>
   <value>" for every option that changes a result; -sampler_family absent: the sampler's default) */
PetscErrorCode HylcFitInputFamily_Private(const char path[], char family[], size_t len, PetscBool *found)
{
  HylcH5Quiet q;
  hid_t       file;
  char       *text = NULL;
  struct stat st;

  PetscFunctionBegin;
  *found    = PETSC_FALSE;
  family[0] = 0;
  if (stat(path, &st) || !S_ISREG(st.st_mode)) PetscFunctionReturn(PETSC_SUCCESS);
  HylcH5QuietBegin(&q);
  file = H5Fis_hdf5(path) > 0 ? H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT) : -1;
  if (file >= 0) {
    if (H5Lexists(file, "provenance", H5P_DEFAULT) > 0 && H5Lexists(file, "provenance/identity", H5P_DEFAULT) > 0 && HylcH5ReadString(file, "provenance/identity", &text) >= 0 && text) {
      const char *key = "option -sampler_family ", *line = text;
      *found = PETSC_TRUE;
      snprintf(family, len, "woven"); /* the sampler's default */
      for (; line && *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
        if (strncmp(line, key, strlen(key))) continue;
        line += strlen(key);
        snprintf(family, len, "%.*s", (int)strcspn(line, " \n"), line);
        break;
      }
    }
    free(text);
    H5Fclose(file);
  }
  HylcH5QuietEnd(&q);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadSamplesHDF5(HylcFit fit, const char path[])
{
  long              N;
  HylcSampleRecord *recs;
  unsigned char    *done;
  PetscInt          n    = 0;
  MPI_Comm          comm = PetscObjectComm((PetscObject)fit);

  PetscFunctionBegin;
  /* every dataset checked (kind, class, shape, declared size) before it is read: one line naming it */
  PetscCall(HylcSamplesCheckHDF5(path, "-fit_input"));
  PetscCall(HylcSamplesReadHDF5(path, &N, &recs, &done, NULL));
  PetscCall(PetscMalloc4(6 * N + 1, &fit->z, N + 1, &fit->psi, N + 1, &fit->term, N + 1, &fit->row));
  PetscCall(PetscMalloc1(6 * N + 1, &fit->stress));
  fit->nrows = (PetscInt)N;
  for (long k = 0; k < N; k++) {
    const HylcSampleRecord *r = &recs[k];
    if (!done[k]) continue;
    for (int i = 0; i < 6; i++)
      if (!PetscIsInfOrNanReal(r->z[i])) fit->zabsmax[i] = PetscMax(fit->zabsmax[i], PetscAbsReal(r->z[i]));
    if (r->status != 0) {
      fit->nskipped++;
      continue;
    }
    if (!(r->term >= 0 && r->term < HYLC_PLAN_NTERM3)) {
      PetscCall(PetscFree(recs));
      PetscCall(PetscFree(done));
      SETERRQ(comm, PETSC_ERR_FILE_UNEXPECTED, "%s: /samples/term of row %ld is %d (valid: 0..21)", path, k, r->term);
    }
    {
      int         c;
      const char *why = HylcStrainDomainError(r->z, &c);
      if (why || PetscIsInfOrNanReal(r->psi)) {
        char text[256]; /* C's %g (PETSc's appends '.' to nan) */
        if (why)
          snprintf(text, sizeof(text), "dataset /samples/strain row %ld, column %d (%s) = %.15g: %s", k, c + 1, HylcTableStrainNames[c], (double)r->z[c], why);
        else
          snprintf(text, sizeof(text), "dataset /samples/psi row %ld: %g is not finite", k, (double)r->psi);
        PetscCall(PetscFree(recs));
        PetscCall(PetscFree(done));
        SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: %s (a converged sample, status 0)", path, text);
      }
    }
    for (int i = 0; i < 6; i++) fit->z[6 * n + i] = r->z[i];
    for (int i = 0; i < 6; i++) fit->stress[6 * n + i] = r->stress[i];
    fit->psi[n]  = r->psi;
    fit->term[n] = r->term;
    fit->row[n]  = (PetscInt)k;
    n++;
  }
  fit->n = n;
  PetscCall(PetscFree(recs));
  PetscCall(PetscFree(done));
  PetscCall(PetscSNPrintf(fit->source, sizeof(fit->source), "%s (HDF5 samples)", path));
  fit->samplesFile = PETSC_TRUE;
  /* area density from the reference pattern */
  PetscCall(ReadReference(fit, path));
  if (fit->radius > 0 && fit->restLength > 0 && fit->px > 0 && fit->py > 0) {
    const PetscReal rho = fit->yarnDensity > 0 ? fit->yarnDensity : HylcDefaultYarnDensity(fit->radius);
    fit->rhoA           = rho * PETSC_PI * fit->radius * fit->radius * fit->restLength / (fit->px * fit->py);
    snprintf(fit->rhoSource, sizeof(fit->rhoSource), "yarn density %g kg/m^3%s x pi r^2 L / (px py) with r = %g m, L = %g m, px py = %g m^2 of %s/reference", (double)rho, fit->yarnDensity > 0 ? " (-fit_yarn_density)" : " (0.12 kg/m^2 / r)",
             (double)fit->radius, (double)fit->restLength, (double)(fit->px * fit->py), path);
  } else {
    fit->rhoA = -1;
    PetscCall(PetscSNPrintf(fit->rhoSource, sizeof(fit->rhoSource), "%s has no /reference pattern", path));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- the raw layout ---- */

/* reads info.txt: "density <value>" (and "area <value>") lines, or two bare numbers area density */
static PetscErrorCode ReadInfo(HylcFit fit, const char path[])
{
  FILE  *fp = fopen(path, "r");
  char   tok[256], prev[256] = "";
  double nums[2];
  int    nn = 0, haveKey = 0;
  double density = -1;

  PetscFunctionBegin;
  if (!fp) {
    fit->rhoA = -1;
    PetscCall(PetscSNPrintf(fit->rhoSource, sizeof(fit->rhoSource), "no %s", path));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  while (fscanf(fp, "%255s", tok) == 1) {
    char  *end;
    double v = strtod(tok, &end);
    if (*end) {
      PetscCall(PetscStrncpy(prev, tok, sizeof(prev)));
      continue;
    }
    if (prev[0]) {
      haveKey = 1;
      if (!strcmp(prev, "density") || !strcmp(prev, "density:") || !strcmp(prev, "area_density") || !strcmp(prev, "rho")) density = v;
      prev[0] = 0;
    } else if (nn < 2)
      nums[nn++] = v;
    else
      nn = 3;
  }
  fclose(fp);
  if (!haveKey && nn == 2) density = nums[1];
  PetscCheck(density > 0 && !PetscIsInfOrNanReal(density), PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT, "%s: no positive area density found (expected a line 'density <kg/m^2>', or two numbers: area and area density)", path);
  fit->rhoA = density;
  PetscCall(PetscSNPrintf(fit->rhoSource, sizeof(fit->rhoSource), "%s", path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadRaw(HylcFit fit, const char data[], const char info[])
{
  PetscInt            n, *lines;
  PetscReal          *z, *psi;
  MPI_Comm            comm = PetscObjectComm((PetscObject)fit);
  PetscInt            n1, n2;
  HylcTable           T;
  const HylcTableSpec spec = {HYLC_TABLE_NUMBERS, 7, HylcTableStrainNames, PETSC_TRUE};

  PetscFunctionBegin;
  /* the one table reader: lines of any length, every value a finite number, strains in the domain */
  PetscCall(HylcTableReadText(data, "-fit_input", &spec, &T));
  n = T.n;
  PetscCall(PetscMalloc3(6 * n + 1, &z, n + 1, &psi, n + 1, &lines));
  for (PetscInt k = 0; k < n; k++) {
    for (int i = 0; i < 6; i++) z[6 * k + i] = T.v[7 * k + i];
    psi[k]   = T.v[7 * k + 6];
    lines[k] = T.line[k];
  }
  PetscCall(HylcTableDestroy(&T));
  /* block sizes: rows = 5 n1 + 9 n2^2, in 64-bit with every product range-checked (an -fit_raw_n2 near
     the int range must not wrap around to a matching count) */
  {
    const int64_t N  = n;
    int64_t       a1 = fit->rawN1, a2 = fit->rawN2;
    PetscBool     ok;
    if (a1 < 0 || a1 > N || a2 < 0 || a2 > N) {
      PetscCall(PetscFree3(z, psi, lines));
      SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: -fit_raw_n1 %" PetscInt_FMT " and -fit_raw_n2 %" PetscInt_FMT " must be in 0..%" PetscInt_FMT " (the rows of the file)", data, fit->rawN1, fit->rawN2, n);
    }
    if (!a1) {
      if (a2)
        a1 = a2 * a2 <= N && 9 * a2 * a2 <= N ? (N - 9 * a2 * a2) / 5 : 0; /* a2 <= N < 2^31: a2^2 < 2^62 fits, then 9 a2^2 <= 9 N */
      else
        while (a1 < N && z[6 * a1 + 1] == 0 && z[6 * a1 + 2] == 0 && z[6 * a1 + 3] == 0 && z[6 * a1 + 4] == 0 && z[6 * a1 + 5] == 0) a1++;
    }
    if (!a2 && a1 > 0 && N >= 5 * a1) {
      const int64_t q = (N - 5 * a1) / 9;
      a2              = (int64_t)(PetscSqrtReal((PetscReal)q) + 0.5);
    }
    /* a1, a2 <= N < 2^31: a2^2 <= N keeps 9 a2^2 below 2^35 */
    ok = (PetscBool)(a1 > 0 && a2 >= 0 && a2 * a2 <= N && 5 * a1 + 9 * a2 * a2 == N);
    if (!ok) {
      PetscCall(PetscFree3(z, psi, lines));
      SETERRQ(comm, PETSC_ERR_USER_INPUT,
              "%s: %" PetscInt_FMT " rows do not make 5 1D blocks of n1 = %" PetscInt64_FMT " rows and 9 2D blocks of n2 x n2 = %" PetscInt64_FMT " x %" PetscInt64_FMT " rows (formats.md §5: 5 n1 + 9 n2^2 rows); give -fit_raw_n1 and -fit_raw_n2",
              data, n, (PetscInt64)a1, (PetscInt64)a2, (PetscInt64)a2);
    }
    n1 = (PetscInt)a1;
    n2 = (PetscInt)a2;
  }
  /* the term of each row by row order; every coordinate outside the term must be 0 */
  PetscCall(PetscMalloc4(6 * n + 1, &fit->z, n + 1, &fit->psi, n + 1, &fit->term, n + 1, &fit->row));
  PetscCall(PetscMalloc1(6 * n + 1, &fit->stress));
  for (PetscInt k = 0; k < 6 * n; k++) fit->stress[k] = (PetscReal)NAN; /* the raw layout has no stress */
  for (PetscInt k = 0; k < n; k++) {
    PetscInt t, c[2] = {-1, -1};
    if (k < 5 * n1) {
      t    = 1 + k / n1;
      c[0] = (int)t - 1;
    } else {
      int ci, cj;
      t = 6 + (k - 5 * n1) / (n2 * n2);
      HylcPlanPair((int)t, &ci, &cj);
      c[0] = ci, c[1] = cj;
    }
    for (int cc = 0; cc < HYLC_PLAN_NCOORD; cc++) {
      if (cc == c[0] || cc == c[1]) continue;
      const PetscReal v = z[6 * k + HylcPlanStrainIndex(cc)];
      if (v != 0 && !PetscIsInfOrNanReal(v)) {
        const PetscInt ln = lines[k];
        PetscCall(PetscFree3(z, psi, lines));
        SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": the row belongs to term %s by row order (n1 = %" PetscInt_FMT ", n2 = %" PetscInt_FMT ") but its %s is %g, not 0; give -fit_raw_n1 and -fit_raw_n2", data, ln,
                HylcPlanTermName((int)t), n1, n2, HylcPlanTermName(1 + cc), (double)v);
      }
    }
    for (int i = 0; i < 6; i++) fit->z[6 * k + i] = z[6 * k + i];
    fit->psi[k]  = psi[k];
    fit->term[k] = t;
    fit->row[k]  = lines[k];
  }
  fit->n = fit->nrows = n;
  PetscCall(PetscFree3(z, psi, lines));
  PetscCall(PetscSNPrintf(fit->source, sizeof(fit->source), "%s (raw: %" PetscInt_FMT " rows, 5 x %" PetscInt_FMT " + 9 x %" PetscInt_FMT "^2; rows are line numbers)", data, n, n1, n2));
  PetscCall(ReadInfo(fit, info));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcFitReadInput_Private(HylcFit fit)
{
  struct stat st;
  MPI_Comm    comm = PetscObjectComm((PetscObject)fit);
  char        data[PETSC_MAX_PATH_LEN + 16], info[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBegin;
  PetscCheck(!stat(fit->input, &st), comm, PETSC_ERR_FILE_OPEN, "-fit_input %s: %s", fit->input, strerror(errno));
  if (S_ISDIR(st.st_mode)) {
    PetscCall(PetscSNPrintf(data, sizeof(data), "%s/data.txt", fit->input));
    PetscCall(PetscSNPrintf(info, sizeof(info), "%s/info.txt", fit->input));
    PetscCheck(!stat(data, &st), comm, PETSC_ERR_FILE_OPEN, "-fit_input %s is a directory without data.txt (the paper's raw layout)", fit->input);
    PetscCall(HylcFileCheckInput(comm, data, "-fit_input"));
    if (!stat(info, &st)) PetscCall(HylcFileCheckInput(comm, info, "-fit_input")); /* optional; a directory is no info.txt */
    PetscCall(ReadRaw(fit, data, info));
  } else {
    PetscCall(HylcFileCheckInput(comm, fit->input, "-fit_input"));
    htri_t      ish5;
    H5E_auto2_t efunc;
    void       *edata;
    H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
    ish5 = H5Fis_hdf5(fit->input);
    H5Eset_auto2(H5E_DEFAULT, efunc, edata);
    if (ish5 > 0)
      PetscCall(ReadSamplesHDF5(fit, fit->input));
    else {
      char *slash;
      PetscCall(PetscStrncpy(info, fit->input, sizeof(info)));
      slash = strrchr(info, '/');
      if (slash)
        PetscCall(PetscStrcpy(slash + 1, "info.txt"));
      else
        PetscCall(PetscStrcpy(info, "info.txt"));
      if (!stat(info, &st)) PetscCall(HylcFileCheckInput(comm, info, "-fit_input"));
      PetscCall(ReadRaw(fit, fit->input, info));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
