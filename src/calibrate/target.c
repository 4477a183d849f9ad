/* HylcCalibrate: the target (a material table sampled along the plan's terms, or strain-energy pairs from
   samples.h5, the paper's raw data.txt or a CSV) and the list of samples (docs/calibrate.md). */
#include "calibrateimpl.h"
#include <hylc/samples.h>
#include <hylc/table.h>
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

/* rows of a file target (rank 0): strain, energy, term and where the row is in the file */
static PetscErrorCode RowsAdd(HylcCalibRows *R, const PetscReal z[6], PetscReal psi, PetscInt term, PetscInt line)
{
  PetscFunctionBegin;
  if (R->n == R->cap) {
    PetscInt cap = R->cap ? 2 * R->cap : 256;
    PetscCheck(R->cap <= PETSC_MAX_INT / 12, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "More than %" PetscInt_FMT " target rows", R->cap);
    PetscCall(PetscRealloc(sizeof(PetscReal) * 6 * (size_t)cap, &R->z));
    PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)cap, &R->psi));
    PetscCall(PetscRealloc(sizeof(PetscInt) * (size_t)cap, &R->term));
    PetscCall(PetscRealloc(sizeof(PetscInt) * (size_t)cap, &R->line));
    R->cap = cap;
  }
  for (int i = 0; i < 6; i++) R->z[6 * R->n + i] = z[i];
  R->psi[R->n]  = psi;
  R->term[R->n] = term;
  R->line[R->n] = line;
  R->n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibRowsDestroy_Private(HylcCalibRows *R)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(R->z));
  PetscCall(PetscFree(R->psi));
  PetscCall(PetscFree(R->term));
  PetscCall(PetscFree(R->line));
  R->n = R->cap = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a CSV with a header line naming (at least) sx, sa, sy, II00, II01, II11, psi in any order, or the paper's
   raw data.txt (rows "sx sa sy II00 II01 II11 Psi"): the one table reader (include/hylc/table.h) */
static PetscErrorCode ReadText(const char path[], HylcCalibTargetType kind, HylcCalibRows *R)
{
  const HylcTableSpec spec = {kind == HYLC_CALIB_TARGET_CSV ? HYLC_TABLE_CSV : HYLC_TABLE_NUMBERS, 7, HylcTableStrainNames, PETSC_TRUE};
  HylcTable           T;
  PetscErrorCode      ierr = PETSC_SUCCESS;

  PetscFunctionBegin;
  PetscCall(HylcTableReadText(path, "-calibrate_target", &spec, &T));
  for (PetscInt i = 0; i < T.n && !ierr; i++) ierr = RowsAdd(R, T.v + 7 * i, T.v[7 * i + 6], Classify(T.v + 7 * i), T.line[i]);
  PetscCall(HylcTableDestroy(&T));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* samples.h5 of hylc-sample: the converged rows with their terms; their strains and energies checked */
static PetscErrorCode ReadSamples(const char path[], HylcCalibRows *R, PetscInt *nskipped)
{
  long              n;
  HylcSampleRecord *recs;
  unsigned char    *done;
  PetscErrorCode    ierr = PETSC_SUCCESS;

  PetscFunctionBegin;
  PetscCall(HylcSamplesCheckHDF5(path, "-calibrate_target"));
  PetscCall(HylcSamplesReadHDF5(path, &n, &recs, &done, NULL));
  for (long k = 0; k < n; k++)
    if (done[k] && (recs[k].start == HYLC_SAMPLE_START_CONTINUED || recs[k].start == HYLC_SAMPLE_START_RETRIED)) R->continued = PETSC_TRUE;
  for (long k = 0; k < n && !ierr; k++) {
    int         c;
    const char *why;
    if (!done[k] || recs[k].status != HYLC_MICRO_CONVERGED) {
      (*nskipped)++;
      continue;
    }
    why = HylcStrainDomainError(recs[k].z, &c);
    if (why) {
      char num[32]; /* C's %g (PETSc's appends '.' to nan) */
      snprintf(num, sizeof(num), "%.15g", recs[k].z[c]);
      ierr = PETSC_ERR_USER_INPUT;
      (void)PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, ierr, PETSC_ERROR_INITIAL, "%s: dataset /samples/strain row %ld, column %d (%s) = %s: %s (a converged sample)", path, k, c + 1, HylcTableStrainNames[c], num, why);
    } else if (PetscIsInfOrNanReal(recs[k].psi)) {
      char num[32];
      snprintf(num, sizeof(num), "%g", recs[k].psi);
      ierr = PETSC_ERR_USER_INPUT;
      (void)PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, ierr, PETSC_ERROR_INITIAL, "%s: dataset /samples/psi row %ld: %s is not finite (a converged sample)", path, k, num);
    } else {
      PetscInt t = recs[k].term >= 0 && recs[k].term < HYLC_PLAN_NTERM ? recs[k].term : Classify(recs[k].z);
      PetscCheck(k <= PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: too many rows", path);
      ierr = RowsAdd(R, recs[k].z, recs[k].psi, t, (PetscInt)k);
    }
  }
  PetscCall(PetscFree(recs));
  PetscCall(PetscFree(done));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* base row (the first zero strain, else the row nearest 0 in |s|^2 + (r II)^2; the first row if every
   distance overflows), then the rows of the terms in file order, thinned */
static PetscErrorCode SelectRows(const char path[], HylcCalibRows *R, PetscReal radius, PetscInt stride, PetscInt maxSamples, HylcCalibRows *S, PetscInt *nskipped)
{
  PetscInt  base = -1, keep = 0, stride2 = 1, local[HYLC_CALIB_NTERM];
  PetscReal best = PETSC_MAX_REAL;

  PetscFunctionBegin;
  PetscCheck(R->n > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: no usable rows (%" PetscInt_FMT " not converged)", path, *nskipped);
  for (PetscInt i = 0; i < R->n; i++) {
    const PetscReal *z = R->z + 6 * i;
    PetscReal        d = z[0] * z[0] + z[1] * z[1] + z[2] * z[2] + radius * radius * (z[3] * z[3] + 2 * z[4] * z[4] + z[5] * z[5]);
    if (base < 0 || d < best) {
      best = d;
      base = i;
    }
  }
  PetscCall(RowsAdd(S, R->z + 6 * base, R->psi[base], 0, R->line[base]));
  /* the stationarity's scale S_k (-calibrate_stationary): 2 dPsi_T / s_k of the row of the 1D term s_k > 0
     nearest to 5 % (the slope there of a quadratic), among every usable row: the same whatever the
     thinning below keeps */
  for (int k = 0; k < 2; k++) {
    PetscReal near = PETSC_MAX_REAL;
    S->sscale[k]   = 0;
    for (PetscInt i = 0; i < R->n; i++) {
      const PetscReal sk = R->z[6 * i + 2 * k];
      if (i == base || R->term[i] != (k ? 3 : 1) || sk <= 0 || PetscAbsReal(sk - 0.05) >= near) continue;
      near         = PetscAbsReal(sk - 0.05);
      S->sscale[k] = PetscAbsReal(2 * (R->psi[i] - R->psi[base]) / sk);
    }
  }
  for (int pass = 0; pass < 2; pass++) {
    keep = 0;
    for (PetscInt t = 0; t < HYLC_CALIB_NTERM; t++) local[t] = 0;
    for (PetscInt i = 0; i < R->n; i++) {
      if (i == base || R->term[i] == 0) continue;
      const PetscInt j = local[R->term[i]]++;
      if (j % stride || (j / stride) % stride2) continue;
      if (pass) PetscCall(RowsAdd(S, R->z + 6 * i, R->psi[i], R->term[i], R->line[i]));
      keep++;
    }
    if (!pass && maxSamples > 0 && keep > maxSamples) stride2 = (keep + maxSamples - 1) / maxSamples;
  }
  *nskipped += R->n - 1 - keep;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  HylcCalibrateReadFileTarget_Private - rank 0's part of a file target: the rows of a CSV, raw data.txt or
  samples file (the one table reader: every value finite, strains in the domain), the base row and the
  rows kept (stride, maxSamples), each selected strain checked against the tile P (NULL: not checked;
  HylcPeriodicCheckStrain(), the message naming the file and line or row). S holds the selected rows
  (S->line: the line or row of each); *nrows the usable rows read, *nskipped those not used.
*/
PetscErrorCode HylcCalibrateReadFileTarget_Private(const char path[], HylcCalibTargetType kind, PetscReal radius, PetscInt stride, PetscInt maxSamples, HylcPeriodic P, HylcCalibRows *S, PetscInt *nrows, PetscInt *nskipped)
{
  HylcCalibRows  R    = {0};
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBegin;
  PetscCall(PetscMemzero(S, sizeof(*S)));
  *nrows = *nskipped = 0;
  if (kind == HYLC_CALIB_TARGET_SAMPLES)
    ierr = ReadSamples(path, &R, nskipped);
  else
    ierr = ReadText(path, kind, &R);
  if (!ierr) {
    *nrows       = R.n + *nskipped;
    ierr         = SelectRows(path, &R, radius, stride, maxSamples, S, nskipped);
    S->continued = R.continued;
  }
  for (PetscInt i = 0; !ierr && P && i < S->n; i++) {
    char where[PETSC_MAX_PATH_LEN + 64];
    if (kind == HYLC_CALIB_TARGET_SAMPLES)
      snprintf(where, sizeof(where), "%s: dataset /samples/strain row %" PetscInt_FMT, path, S->line[i]);
    else
      snprintf(where, sizeof(where), "%s:%" PetscInt_FMT, path, S->line[i]);
    ierr = HylcPeriodicCheckStrain(P, S->z + 6 * i, where);
  }
  PetscCall(HylcCalibRowsDestroy_Private(&R));
  if (ierr) PetscCall(HylcCalibRowsDestroy_Private(S));
  PetscCall(ierr);
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
  for (int k = 0; k < 2; k++) { /* the scale of the stationarity: the table's dPsi/ds_k at s_k = 5 % */
    PetscReal z[6] = {0, 0, 0, 0, 0, 0}, psi, g[6];
    z[2 * k]       = 0.05;
    PetscCall(HylcMaterialEvaluate(mat, z, &psi, g, NULL));
    C->sscale[k] = PetscAbsReal(g[2 * k]);
  }
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
    PetscInt       head[4]   = {0, 0, 0, 0};
    PetscReal      sscale[2] = {0, 0};
    PetscErrorCode ierr      = PETSC_SUCCESS;
    if (!C->rank) {
      HylcCalibRows S = {0};
      HylcPeriodic  P;
      /* rank 0 reads; its error, if any, is raised on every rank (one line, no rank left waiting) */
      PetscCall(HylcMicroGetPeriodic(C->micro, &P));
      PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
      ierr = HylcCalibrateReadFileTarget_Private(path, (HylcCalibTargetType)kind, radius, C->stride, C->maxSamples, P, &S, &C->nrows, &C->nskipped);
      PetscCall(PetscPopErrorHandler());
      if (!ierr) {
        C->m = S.n;
        PetscCall(PetscMalloc3(6 * C->m, &C->z, C->m, &C->tpsi, C->m, &C->term));
        PetscCall(PetscArraycpy(C->z, S.z, 6 * S.n));
        PetscCall(PetscArraycpy(C->tpsi, S.psi, S.n));
        PetscCall(PetscArraycpy(C->term, S.term, S.n));
        head[3]   = S.continued;
        sscale[0] = S.sscale[0];
        sscale[1] = S.sscale[1];
        PetscCall(HylcCalibRowsDestroy_Private(&S));
        head[0] = C->m;
        head[1] = C->nrows;
        head[2] = C->nskipped;
      }
    }
    PetscCall(HylcShareError(comm, ierr));
    PetscCallMPI(MPI_Bcast(head, 4, MPIU_INT, 0, comm));
    PetscCallMPI(MPI_Bcast(sscale, 2, MPIU_REAL, 0, comm));
    C->targetContinued = (PetscBool)head[3];
    C->sscale[0]       = sscale[0];
    C->sscale[1]       = sscale[1];
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
