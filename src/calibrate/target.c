/* HylcCalibrate: the target (a material table sampled along the plan's terms, or strain-energy pairs from
   samples.h5, the paper's raw data.txt or a CSV) and the list of samples (docs/calibrate.md). */
#include "calibrateimpl.h"
#include <hylc/samples.h>
#include <hdf5.h>
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* the term of a strain off the plan: 0 if zero, the 1D term of the only non-zero coordinate, the 2D term of
   the only two, or "other" (II01 != 0 or three or more) */
static PetscInt Classify(const PetscReal z[6])
{
  int nz = 0, c[5];
  if (z[4] != 0) return HYLC_CALIB_OTHER;
  for (int k = 0; k < HYLC_PLAN_NCOORD; k++)
    if (z[HylcPlanStrainIndex(k)] != 0) c[nz++] = k;
  if (nz == 0) return 0;
  if (nz == 1) return 1 + c[0];
  if (nz == 2)
    for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
      int ci, cj;
      HylcPlanPair(t, &ci, &cj);
      if (ci == c[0] && cj == c[1]) return t;
    }
  return HYLC_CALIB_OTHER;
}

/* growable row arrays (rank 0) */
typedef struct {
  PetscInt   n, cap;
  PetscReal *z, *psi;
  PetscInt  *term;
} Rows;

static PetscErrorCode RowsAdd(Rows *R, const PetscReal z[6], PetscReal psi, PetscInt term)
{
  PetscFunctionBegin;
  if (R->n == R->cap) {
    PetscInt   cap = R->cap ? 2 * R->cap : 256;
    PetscReal *nz, *np;
    PetscInt  *nt;
    PetscCall(PetscMalloc3(6 * cap, &nz, cap, &np, cap, &nt));
    if (R->n) {
      PetscCall(PetscArraycpy(nz, R->z, 6 * R->n));
      PetscCall(PetscArraycpy(np, R->psi, R->n));
      PetscCall(PetscArraycpy(nt, R->term, R->n));
    }
    PetscCall(PetscFree3(R->z, R->psi, R->term));
    R->z    = nz;
    R->psi  = np;
    R->term = nt;
    R->cap  = cap;
  }
  for (int i = 0; i < 6; i++) R->z[6 * R->n + i] = z[i];
  R->psi[R->n]  = psi;
  R->term[R->n] = term;
  R->n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static char *Trim(char *s)
{
  char *e;
  while (isspace((unsigned char)*s)) s++;
  e = s + strlen(s);
  while (e > s && isspace((unsigned char)e[-1])) *--e = 0;
  return s;
}

/* the paper's raw data.txt: rows "sx sa sy II00 II01 II11 Psi" */
static PetscErrorCode ReadRaw(const char path[], Rows *R)
{
  FILE *fp = fopen(path, "r");
  char  line[4096];
  long  ln = 0;

  PetscFunctionBegin;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open the target %s: %s", path, strerror(errno));
  while (fgets(line, sizeof(line), fp)) {
    char     *s = Trim(line), *end;
    PetscReal v[7], z[6];
    int       k = 0;
    ln++;
    if (!*s || *s == '#') continue;
    for (; k < 7; k++) {
      v[k] = strtod(s, &end);
      if (end == s) break;
      s = end;
    }
    if (k < 7 || *Trim(s)) {
      fclose(fp);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s:%ld: expected 7 numbers \"sx sa sy II00 II01 II11 Psi\" (the paper's raw data.txt)", path, ln);
    }
    for (int i = 0; i < 6; i++) z[i] = v[i];
    PetscCall(RowsAdd(R, z, v[6], Classify(z)));
  }
  fclose(fp);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a CSV with a header line naming (at least) sx, sa, sy, II00, II01, II11, psi in any order */
static PetscErrorCode ReadCSV(const char path[], Rows *R)
{
  static const char *names[7] = {"sx", "sa", "sy", "II00", "II01", "II11", "psi"};
  FILE              *fp       = fopen(path, "r");
  char               line[8192];
  long               ln = 0;
  int                col[7], ncol = 0, header = 0;

  PetscFunctionBegin;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open the target %s: %s", path, strerror(errno));
  for (int i = 0; i < 7; i++) col[i] = -1;
  while (fgets(line, sizeof(line), fp)) {
    char *s = Trim(line), *tok, *save = NULL;
    int   k = 0;
    ln++;
    if (!*s || *s == '#') continue;
    if (!header) {
      for (tok = strtok_r(s, ",", &save); tok; tok = strtok_r(NULL, ",", &save), k++) {
        char *name = Trim(tok);
        for (int i = 0; i < 7; i++)
          if (!strcasecmp(name, names[i])) col[i] = k;
      }
      ncol = k;
      for (int i = 0; i < 7; i++)
        if (col[i] < 0) {
          fclose(fp);
          SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s:%ld: the header has no column '%s' (needs sx,sa,sy,II00,II01,II11,psi)", path, ln, names[i]);
        }
      header = 1;
      continue;
    }
    PetscReal v[7] = {0}, z[6];
    for (tok = strtok_r(s, ",", &save); tok; tok = strtok_r(NULL, ",", &save), k++) {
      for (int i = 0; i < 7; i++)
        if (col[i] == k) {
          char *t = Trim(tok), *end;
          v[i]    = strtod(t, &end);
          if (end == t || *end || PetscIsInfOrNanReal(v[i])) {
            fclose(fp);
            SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s:%ld: column %s: '%s' is not a finite number", path, ln, names[i], t);
          }
        }
    }
    if (k != ncol) {
      fclose(fp);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s:%ld: %d fields, the header has %d", path, ln, k, ncol);
    }
    for (int i = 0; i < 6; i++) z[i] = v[i];
    PetscCall(RowsAdd(R, z, v[6], Classify(z)));
  }
  fclose(fp);
  PetscCheck(header, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s: empty CSV (needs a header sx,sa,sy,II00,II01,II11,psi and rows)", path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* samples.h5 of hylc-sample: the converged rows with their terms */
static PetscErrorCode ReadSamples(const char path[], Rows *R, PetscInt *nskipped, PetscBool *continued)
{
  long              n;
  HylcSampleRecord *recs;
  unsigned char    *done;

  PetscFunctionBegin;
  PetscCall(HylcSamplesReadHDF5(path, &n, &recs, &done, NULL));
  *continued = PETSC_FALSE;
  for (long k = 0; k < n; k++) {
    if (done[k] && (recs[k].start == HYLC_SAMPLE_START_CONTINUED || recs[k].start == HYLC_SAMPLE_START_RETRIED)) *continued = PETSC_TRUE;
    if (!done[k] || recs[k].status != HYLC_MICRO_CONVERGED) {
      (*nskipped)++;
      continue;
    }
    PetscInt t = recs[k].term >= 0 && recs[k].term < HYLC_PLAN_NTERM ? recs[k].term : Classify(recs[k].z);
    PetscCall(RowsAdd(R, recs[k].z, recs[k].psi, t));
  }
  PetscCall(PetscFree(recs));
  PetscCall(PetscFree(done));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0: base row (the first zero strain, else the row nearest 0 in |s|^2 + (r II)^2), then the rows of the
   terms in file order, thinned */
static PetscErrorCode SelectRows(HylcCalibrate C, Rows *R, PetscReal radius, Rows *S)
{
  PetscInt  base = -1, keep = 0, stride2 = 1, *local;
  PetscReal best = PETSC_MAX_REAL;

  PetscFunctionBegin;
  PetscCheck(R->n > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s: no usable rows (%" PetscInt_FMT " not converged)", C->target, C->nskipped);
  for (PetscInt i = 0; i < R->n; i++) {
    const PetscReal *z = R->z + 6 * i;
    PetscReal        d = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + radius * radius * (z[3] * z[3] + 2 * z[4] * z[4] + z[5] * z[5]);
    if (d < best) {
      best = d;
      base = i;
    }
  }
  PetscCall(RowsAdd(S, R->z + 6 * base, R->psi[base], 0));
  PetscCall(PetscCalloc1(HYLC_CALIB_NTERM, &local));
  for (int pass = 0; pass < 2; pass++) {
    keep = 0;
    for (PetscInt t = 0; t < HYLC_CALIB_NTERM; t++) local[t] = 0;
    for (PetscInt i = 0; i < R->n; i++) {
      if (i == base || R->term[i] == 0) continue;
      const PetscInt j = local[R->term[i]]++;
      if (j % C->stride || (j / C->stride) % stride2) continue;
      if (pass) PetscCall(RowsAdd(S, R->z + 6 * i, R->psi[i], R->term[i]));
      keep++;
    }
    if (!pass && C->maxSamples > 0 && keep > C->maxSamples) stride2 = (keep + C->maxSamples - 1) / C->maxSamples;
  }
  PetscCall(PetscFree(local));
  C->nrows = R->n + C->nskipped;
  C->nskipped += R->n - 1 - keep;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the table's knot range of coordinate c (1D term) in strain units */
static PetscErrorCode KnotRange1D(HylcMaterial mat, const PetscReal sig[5], int c, PetscReal *lo, PetscReal *hi, PetscBool *has)
{
  const HylcSpline1D *s;

  PetscFunctionBegin;
  PetscCall(HylcMaterialGet1D(mat, c, &s));
  *has = s ? PETSC_TRUE : PETSC_FALSE;
  if (s) {
    *lo = s->t[0] * sig[c];
    *hi = s->t[s->n - 1] * sig[c];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void Clip(int c, PetscReal klo, PetscReal khi, double *mn, double *mx)
{
  *mn = PetscMax(*mn, klo);
  *mx = PetscMin(*mx, khi);
  if (c != 0 && c != 2) { /* SampleRange: the range must contain 0 */
    *mn = PetscMin(*mn, 0);
    *mx = PetscMax(*mx, 0);
  }
  if (*mn > *mx) *mn = *mx;
}

/* a table: the plan's terms over the plan's ranges clipped to the knots, Psi_T by HylcMaterialEvaluate */
static PetscErrorCode SampleTable(HylcCalibrate C)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)C);
  HylcMaterial mat;
  PetscReal    sig[5], klo[5] = {0}, khi[5] = {0};
  PetscBool    has[5];
  HylcPlan     plan = C->plan;
  long         n;

  PetscFunctionBegin;
  PetscCall(HylcMaterialCreate(comm, &mat));
  PetscCall(HylcMaterialLoad(mat, C->target));
  PetscCall(HylcMaterialGetStrainScale(mat, sig));
  for (int c = 0; c < 5; c++) {
    PetscCall(KnotRange1D(mat, sig, c, &klo[c], &khi[c], &has[c]));
    if (C->terms & (1 << (c + 1))) {
      PetscCheck(has[c], comm, PETSC_ERR_USER_INPUT, "The target table %s has no %s term; leave it out of -calibrate_terms", C->target, HylcPlanTermName(c + 1));
      Clip(c, klo[c], khi[c], &plan.min1[c], &plan.max1[c]);
    }
  }
  for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
    int                 ci, cj;
    const HylcSpline2D *s;
    if (!(C->terms & (1 << t))) continue;
    HylcPlanPair(t, &ci, &cj);
    PetscCall(HylcMaterialGet2D(mat, ci, cj, &s));
    if (s) {
      Clip(ci, s->tu[0] * sig[ci], s->tu[s->nu - 1] * sig[ci], &plan.min2[t - 6][0], &plan.max2[t - 6][0]);
      Clip(cj, s->tv[0] * sig[cj], s->tv[s->nv - 1] * sig[cj], &plan.min2[t - 6][1], &plan.max2[t - 6][1]);
    } else { /* no 2D residual in the table: its response is the sum of the 1D terms; clip to those knots */
      PetscCheck(has[ci] && has[cj], comm, PETSC_ERR_USER_INPUT, "The target table %s has neither the %s term nor both of its 1D terms; leave it out of -calibrate_terms", C->target, HylcPlanTermName(t));
      Clip(ci, klo[ci], khi[ci], &plan.min2[t - 6][0], &plan.max2[t - 6][0]);
      Clip(cj, klo[cj], khi[cj], &plan.min2[t - 6][1], &plan.max2[t - 6][1]);
    }
  }
  C->plan = plan;
  n       = HylcPlanSize(&plan);
  C->m    = (PetscInt)n;
  PetscCall(PetscMalloc3(6 * C->m, &C->z, C->m, &C->tpsi, C->m, &C->term));
  for (long k = 0; k < n; k++) {
    double z[6];
    int    term;
    PetscCheck(!HylcPlanSample(&plan, k, z, &term), comm, PETSC_ERR_USER_INPUT, "Invalid clipped sampling range of a term (-sampler_range_*)");
    for (int i = 0; i < 6; i++) C->z[6 * k + i] = z[i];
    C->term[k] = term;
    PetscCall(HylcMaterialEvaluate(mat, C->z + 6 * k, &C->tpsi[k], NULL, NULL));
  }
  C->nrows = C->m;
  PetscCall(HylcMaterialDestroy(&mat));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateReadTarget_Private(HylcCalibrate C)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)C);
  char      path[PETSC_MAX_PATH_LEN + 16];
  int       kind = (int)C->targetType, isdir = 0;
  PetscReal radius;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetRadius(C->pat, &radius));
  if (!C->rank) {
    struct stat st;
    isdir = stat(C->target, &st) == 0 && S_ISDIR(st.st_mode);
  }
  PetscCallMPI(MPI_Bcast(&isdir, 1, MPI_INT, 0, comm));
  PetscCall(PetscStrncpy(path, C->target, sizeof(path)));
  if (isdir) {
    PetscCheck(kind == HYLC_CALIB_TARGET_AUTO || kind == HYLC_CALIB_TARGET_RAW, comm, PETSC_ERR_USER_INPUT, "-calibrate_target %s is a directory (only a raw target, a directory holding data.txt, may be one)", C->target);
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/data.txt", C->target));
    kind = HYLC_CALIB_TARGET_RAW;
  }
  PetscCall(HylcFileCheckInput(comm, path, "-calibrate_target"));
  if (kind == HYLC_CALIB_TARGET_AUTO) {
    if (!C->rank) {
      size_t      len = strlen(path);
      const char *ext = strrchr(path, '.');
      if (ext && !strcasecmp(ext, ".json"))
        kind = HYLC_CALIB_TARGET_TABLE;
      else if (ext && !strcasecmp(ext, ".csv"))
        kind = HYLC_CALIB_TARGET_CSV;
      else if (ext && !strcasecmp(ext, ".txt"))
        kind = HYLC_CALIB_TARGET_RAW;
      else {
        htri_t      is;
        H5E_auto2_t fn;
        void       *data;
        H5Eget_auto2(H5E_DEFAULT, &fn, &data);
        H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
        is = H5Fis_hdf5(path);
        if (is > 0) {
          hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
          kind    = (f >= 0 && H5Lexists(f, "samples", H5P_DEFAULT) > 0) ? HYLC_CALIB_TARGET_SAMPLES : HYLC_CALIB_TARGET_TABLE;
          if (f >= 0) H5Fclose(f);
        } else
          kind = HYLC_CALIB_TARGET_TABLE; /* JSON without the extension: the material reader says what is wrong */
        H5Eset_auto2(H5E_DEFAULT, fn, data);
      }
      (void)len;
    }
    PetscCallMPI(MPI_Bcast(&kind, 1, MPI_INT, 0, comm));
  }
  C->targetResolved  = (HylcCalibTargetType)kind;
  C->nskipped        = 0;
  C->targetContinued = PETSC_FALSE;
  if (kind == HYLC_CALIB_TARGET_TABLE)
    PetscCall(SampleTable(C));
  else {
    PetscInt head[4] = {0, 0, 0, 0};
    if (!C->rank) {
      Rows R = {0}, S = {0};
      if (kind == HYLC_CALIB_TARGET_SAMPLES)
        PetscCall(ReadSamples(path, &R, &C->nskipped, &C->targetContinued));
      else if (kind == HYLC_CALIB_TARGET_RAW)
        PetscCall(ReadRaw(path, &R));
      else
        PetscCall(ReadCSV(path, &R));
      PetscCall(SelectRows(C, &R, radius, &S));
      PetscCall(PetscFree3(R.z, R.psi, R.term));
      C->m = S.n;
      PetscCall(PetscMalloc3(6 * C->m, &C->z, C->m, &C->tpsi, C->m, &C->term));
      PetscCall(PetscArraycpy(C->z, S.z, 6 * S.n));
      PetscCall(PetscArraycpy(C->tpsi, S.psi, S.n));
      PetscCall(PetscArraycpy(C->term, S.term, S.n));
      PetscCall(PetscFree3(S.z, S.psi, S.term));
      head[0] = C->m;
      head[1] = C->nrows;
      head[2] = C->nskipped;
      head[3] = C->targetContinued;
    }
    PetscCallMPI(MPI_Bcast(head, 4, MPIU_INT, 0, comm));
    C->targetContinued = (PetscBool)head[3];
    if (C->rank) {
      C->m        = head[0];
      C->nrows    = head[1];
      C->nskipped = head[2];
      PetscCall(PetscMalloc3(6 * C->m, &C->z, C->m, &C->tpsi, C->m, &C->term));
    }
    PetscCallMPI(MPI_Bcast(C->z, (PetscMPIInt)(6 * C->m), MPIU_REAL, 0, comm));
    PetscCallMPI(MPI_Bcast(C->tpsi, (PetscMPIInt)C->m, MPIU_REAL, 0, comm));
    PetscCallMPI(MPI_Bcast(C->term, (PetscMPIInt)C->m, MPIU_INT, 0, comm));
  }
  /* per-term counts and ranges of the target's dPsi */
  {
    PetscReal rmax = 0;
    for (PetscInt t = 0; t < HYLC_CALIB_NTERM; t++) C->nt[t] = 0, C->range[t] = 0;
    for (PetscInt i = 0; i < C->m; i++) {
      const PetscReal d = PetscAbsReal(C->tpsi[i] - C->tpsi[0]);
      PetscCheck(!PetscIsInfOrNanReal(C->tpsi[i]), comm, PETSC_ERR_USER_INPUT, "%s: the target energy of sample %" PetscInt_FMT " is not finite", C->target, i);
      C->nt[C->term[i]]++;
      if (C->term[i]) C->range[C->term[i]] = PetscMax(C->range[C->term[i]], d);
    }
    for (PetscInt t = 1; t < HYLC_CALIB_NTERM; t++) rmax = PetscMax(rmax, C->range[t]);
    PetscCheck(C->m > 1 && rmax > 0, comm, PETSC_ERR_USER_INPUT, "%s: the target has no sample with an energy different from the base strain's (%" PetscInt_FMT " samples)", C->target, C->m);
    for (PetscInt t = 1; t < HYLC_CALIB_NTERM; t++)
      if (C->nt[t] && C->range[t] == 0) {
        PetscCall(PetscPrintf(comm, "[calibrate] warning: the target's %s term is flat (dPsi = 0); it is normalised by the largest range of the other terms\n", HylcCalibrateTermName_Private(t)));
        C->range[t] = rmax;
      }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
