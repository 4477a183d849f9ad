/* HylcCalibrate: lifecycle, sub-objects (lazy getters), set-up, getters and View (include/hylc/calibrate.h,
   docs/calibrate.md); the setters and HylcCalibrateSetFromOptions are in opts.c. */
#include "calibrateimpl.h"
#include <hylc/files.h>
#include <sys/stat.h>
#include <stdio.h>
#include <string.h>

const char *const        HylcCalibrateParamNames[HYLC_CALIBRATE_NPARAM] = {"E", "Es", "G", "kc"};
const char *const        HylcCalibTargetTypes[]                         = {"auto", "table", "samples", "raw", "csv", "HylcCalibTargetType", "HYLC_CALIB_TARGET_", NULL};
static const char *const RoleNames[]                                    = {"free", "tied to E", "fixed"};

const char *HylcCalibrateTermName_Private(PetscInt t) { return t == HYLC_CALIB_OTHER ? "other" : HylcPlanTermName((int)t); }

PetscClassId  HYLC_CALIBRATE_CLASSID;
PetscLogEvent HYLC_CalibrateSetUp, HYLC_CalibrateSolve, HYLC_CalibrateEvaluate, HYLC_CalibrateGather;

static PetscBool HylcCalibratePackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcCalibrateFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcCalibratePackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateInitializePackage - Registers the class id HylcCalibrate and its log events (CALIB_SetUp, CALIB_Solve, CALIB_Evaluate, CALIB_Gather). Called by
  HylcCalibrateCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcCalibrateInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcCalibratePackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcCalibratePackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcCalibrate", &HYLC_CALIBRATE_CLASSID));
  PetscCall(PetscLogEventRegister("CALIB_SetUp", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateSetUp));
  PetscCall(PetscLogEventRegister("CALIB_Solve", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateSolve));
  PetscCall(PetscLogEventRegister("CALIB_Evaluate", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateEvaluate));
  PetscCall(PetscLogEventRegister("CALIB_Gather", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateGather));
  PetscCall(PetscRegisterFinalize(HylcCalibrateFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateCreate - Creates a calibration: free E, Es, kc with G tied to E, bounds 1/1000 to 1000 x the
  initial values, the plan's 1D terms with 15 samples each, the default yarn model as initial values.

  Collective

  Input Parameter:
. comm - the ranks that share the samples of an evaluation

  Output Parameter:
. out - the new object

  Level: beginner

.seealso: HylcCalibrateSetFromOptions(), HylcCalibrateSetUp(), HylcCalibrateSolve(), HylcCalibrateDestroy()
@*/
PetscErrorCode HylcCalibrateCreate(MPI_Comm comm, HylcCalibrate *out)
{
  HylcCalibrate C;

  PetscFunctionBegin;
  PetscValidPointer(out, 2);
  PetscCall(HylcCalibrateInitializePackage());
  PetscCall(PetscHeaderCreate(C, HYLC_CALIBRATE_CLASSID, "HylcCalibrate", "Yarn parameter calibration", "Calibrate", comm, HylcCalibrateDestroy, HylcCalibrateView));
  PetscCallMPI(MPI_Comm_rank(comm, &C->rank));
  PetscCallMPI(MPI_Comm_size(comm, &C->size));
  C->role[0] = HYLC_CALIBRATE_FREE;
  C->role[1] = HYLC_CALIBRATE_FREE;
  C->role[2] = HYLC_CALIBRATE_TIED;
  C->role[3] = HYLC_CALIBRATE_FREE;
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->blo[j] = C->bhi[j] = -1; /* -1: relative to the initial value */
  C->refmode = HYLC_REFERENCE_AUTO;
  PetscCall(HylcYarnModelDefault(&C->model));
  PetscCall(HylcReferenceParamsDefault(&C->refpar));
  C->n1         = 15;
  C->n2         = 5;
  C->terms      = (1 << 0) | (1 << 1) | (1 << 2) | (1 << 3) | (1 << 4) | (1 << 5);
  C->stride     = 1;
  C->maxSamples = 0;
  C->wzero      = 1;
  for (int t = 0; t < HYLC_CALIB_NTERM; t++) C->w[t] = 1;
  C->maxIt   = 30;
  C->lambda  = 1e-3;
  C->xtol    = 1e-6;
  C->ftol    = 1e-10;
  C->fatol   = 1e-20;
  C->flatTol = 1e-4;
  C->start   = HYLC_CALIBRATE_START_AUTO;
  C->wstat   = 0;
  C->statFD  = PETSC_TRUE;
  C->statH   = 1e-2;
  *out       = C;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateResetSamples_Private(HylcCalibrate C)
{
  PetscFunctionBegin;
  PetscCall(PetscFree3(C->z, C->tpsi, C->term));
  PetscCall(PetscFree2(C->rec0, C->rec1));
  PetscCall(PetscFree2(C->ustart, C->uorder));
  C->nunits    = 0;
  C->m         = 0;
  C->nres      = 0;
  C->hasGrad   = PETSC_FALSE;
  C->sscale[0] = C->sscale[1] = 0;
  for (int t = 0; t < HYLC_CALIB_NTERM; t++) {
    C->nt[t]    = 0;
    C->range[t] = 0;
  }
  C->setupcalled = C->solved = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateDestroy - Destroys the calibration (drops a reference; frees it, its pattern and solver with
  the last one).

  Collective

  Input Parameter:
. C - the object (may be NULL); set to NULL

  Level: beginner
@*/
PetscErrorCode HylcCalibrateDestroy(HylcCalibrate *C)
{
  PetscFunctionBegin;
  if (!*C) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*C, HYLC_CALIBRATE_CLASSID, 1);
  if (--((PetscObject)(*C))->refct > 0) {
    *C = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcCalibrateResetSamples_Private(*C));
  PetscCall(HylcMicroDestroy(&(*C)->micro));
  PetscCall(HylcPatternDestroy(&(*C)->pat));
  PetscCall(TaoDestroy(&(*C)->tao));
  PetscCall(PetscHeaderDestroy(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetOptionsPrefix - Sets the prefix of the calibration's options and of its sub-objects'
  (-<prefix>calibrate_*, -<prefix>pattern_*, -<prefix>yarn_*, -<prefix>reference_*, the plan's
  -<prefix>sampler_family and -<prefix>sampler_range_*, -<prefix>micro_* with the solver's tile
  -<prefix>periodic_*, -<prefix>macro_*).

  Not collective

  Input Parameters:
+ C      - the calibration
- prefix - the prefix (NULL: none)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetOptionsPrefix(HylcCalibrate C, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)C, prefix));
  if (C->pat) PetscCall(HylcPatternSetOptionsPrefix(C->pat, prefix));
  if (C->micro) PetscCall(HylcMicroSetOptionsPrefix(C->micro, prefix));
  if (C->tao) {
    PetscCall(TaoSetOptionsPrefix(C->tao, prefix));
    PetscCall(TaoAppendOptionsPrefix(C->tao, "calibrate_"));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetTao - The calibration's optimizer, a TAO created on first use: TAOBRGN (bounded
  Gauss-Newton; HylcCalibrateSetFromOptions() gives it Levenberg-Marquardt damping) with the options prefix
  <prefix>calibrate_, so -calibrate_tao_type, -calibrate_tao_monitor, -calibrate_tao_brgn_* reach it.
  It lives on PETSC_COMM_SELF: every rank runs the same iterations on the gathered residuals, while the
  evaluations inside them are spread over the ranks. The calibration owns it (do not destroy it).

  Not collective

  Input Parameter:
. C - the calibration

  Output Parameter:
. tao - the optimizer

  Level: intermediate

.seealso: HylcCalibrateSolve(), HylcCalibrateSetFromOptions()
@*/
PetscErrorCode HylcCalibrateGetTao(HylcCalibrate C, Tao *tao)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscValidPointer(tao, 2);
  if (!C->tao) {
    const char *prefix;
    PetscCall(TaoCreate(PETSC_COMM_SELF, &C->tao));
    PetscCall(PetscObjectGetOptionsPrefix((PetscObject)C, &prefix));
    PetscCall(TaoSetOptionsPrefix(C->tao, prefix));
    PetscCall(TaoAppendOptionsPrefix(C->tao, "calibrate_"));
    PetscCall(TaoSetType(C->tao, TAOBRGN));
    C->taoUsed = PETSC_FALSE;
  }
  *tao = C->tao;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetPattern - The tile's pattern, created (unset) on first use; HylcCalibrateSetFromOptions()
  reads its options, HylcCalibrateSetUp() loads or generates it (and may replace it by its reference state).
  Borrowed: do not destroy it.

  Collective on the first call

  Input Parameter:
. C - the calibration

  Output Parameter:
. pat - the pattern

  Level: intermediate

.seealso: HylcCalibrateGetMicro()
@*/
PetscErrorCode HylcCalibrateGetPattern(HylcCalibrate C, HylcPattern *pat)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscValidPointer(pat, 2);
  if (!C->pat) {
    PetscCall(HylcPatternCreate(PetscObjectComm((PetscObject)C), &C->pat));
    PetscCall(HylcPatternSetOptionsPrefix(C->pat, ((PetscObject)C)->prefix));
  }
  *pat = C->pat;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetMicro - This rank's solver (PETSC_COMM_SELF), created on first use;
  HylcCalibrateSetFromOptions() reads its options (-micro_*), HylcCalibrateSetUp() gives it the pattern.
  Borrowed: do not destroy it.

  Not collective

  Input Parameter:
. C - the calibration

  Output Parameter:
. micro - the solver

  Level: intermediate

.seealso: HylcCalibrateGetPattern()
@*/
PetscErrorCode HylcCalibrateGetMicro(HylcCalibrate C, HylcMicro *micro)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscValidPointer(micro, 2);
  if (!C->micro) {
    PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &C->micro));
    PetscCall(HylcMicroSetOptionsPrefix(C->micro, ((PetscObject)C)->prefix));
  }
  *micro = C->micro;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the pattern set up (and labelled), the initial parameters from the yarn model at its radius, the bounds
   resolved and checked, the plan resolved, the solver given the pattern and set up */
PetscErrorCode HylcCalibrateSetUpSolver_Private(HylcCalibrate C)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)C);
  HylcPattern pat;
  HylcMicro   micro;
  PetscReal   r;

  PetscFunctionBegin;
  PetscCall(HylcCalibrateGetPattern(C, &pat));
  PetscCall(HylcCalibrateGetMicro(C, &micro));
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcPatternGetRadius(pat, &r));
  {
    HylcPatternType type;
    PetscBool       isfile;
    const char     *file = "";
    PetscCall(HylcPatternGetType(pat, &type));
    PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
    if (isfile) PetscCall(HylcPatternGetFileName(pat, &file));
    PetscCall(PetscSNPrintf(C->patLabel, sizeof(C->patLabel), "%s%s%s", isfile ? "file " : "generated ", isfile ? file : type, ""));
  }
  {
    HylcYarnConstants k;
    PetscCall(HylcYarnModelGetConstants(&C->model, r, &k));
    C->p0[0] = k.E;
    C->p0[1] = k.Es;
    C->p0[2] = k.G;
    C->p0[3] = k.kc;
    for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->p[j] = C->p0[j];
  }
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) {
    C->lo[j] = C->blo[j] < 0 ? C->p0[j] / 1000 : C->blo[j];
    C->hi[j] = C->bhi[j] < 0 ? C->p0[j] * 1000 : C->bhi[j];
    PetscCheck(C->lo[j] <= C->hi[j], comm, PETSC_ERR_USER_INPUT, "-calibrate_bounds_%s %g,%g: inverted bounds (lo > hi)", HylcCalibrateParamNames[j], (double)C->lo[j], (double)C->hi[j]);
    if (C->role[j] == HYLC_CALIBRATE_FREE) {
      char msg[128];
      snprintf(msg, sizeof(msg), "%g (from -yarn_%s) is outside -calibrate_bounds_%s %g,%g", (double)C->p0[j], HylcCalibrateParamNames[j], HylcCalibrateParamNames[j], (double)C->lo[j], (double)C->hi[j]);
      PetscCheck(C->p0[j] >= C->lo[j] && C->p0[j] <= C->hi[j], comm, PETSC_ERR_USER_INPUT, "The initial %s = %s", HylcCalibrateParamNames[j], msg);
    }
  }
  PetscCall(HylcPlanRangesApply(comm, &C->ranges, r, &C->plan));
  C->plan.n1    = (int)C->n1;
  C->plan.n2    = (int)C->n2;
  C->plan.terms = (int)C->terms;
  PetscCall(HylcMicroSetPattern(micro, pat, &C->model)); /* the tile keeps the options read by HylcCalibrateSetFromOptions() */
  PetscCall(HylcMicroSetUp(micro));
  C->solverSetUp = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* every file before any work (include/hylc/files.h): the target (a directory: its data.txt), the pattern
   file and the options files read; the outputs writable and within the path limits, none of them an input
   or another output */
static PetscErrorCode CheckFiles(HylcCalibrate C)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)C);
  char            target[PETSC_MAX_PATH_LEN + 16], pfileopt[300];
  const char     *pfile = "", *prefix = ((PetscObject)C)->prefix;
  HylcPatternType type;
  PetscBool       isfile;
  HylcFiles       files;
  PetscErrorCode  ierr;
  PetscMPIInt     isdir = 0;

  PetscFunctionBegin;
  if (!C->rank) {
    struct stat st;
    isdir = stat(C->target, &st) == 0 && S_ISDIR(st.st_mode);
  }
  PetscCallMPI(MPI_Bcast(&isdir, 1, MPI_INT, 0, comm));
  if (isdir)
    PetscCall(PetscSNPrintf(target, sizeof(target), "%s/data.txt", C->target));
  else
    PetscCall(PetscStrncpy(target, C->target, sizeof(target)));
  PetscCall(HylcPatternGetType(C->pat, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  if (isfile) PetscCall(HylcPatternGetFileName(C->pat, &pfile));
  PetscCall(PetscSNPrintf(pfileopt, sizeof(pfileopt), "-%spattern_file", prefix ? prefix : ""));
  PetscCall(HylcFilesCreate(comm, &files));
  ierr = HylcFilesAddOptionsFiles(files);
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, target, "-calibrate_target");
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, pfile, pfileopt);
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, C->output, "-calibrate_output");
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, C->dump, "-calibrate_dump");
  if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, C->refout, "-reference_output");
  if (!ierr) ierr = HylcFilesCheck(files);
  PetscCall(HylcFilesDestroy(&files));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetUp - Loads or generates the pattern, resolves the initial values (the yarn model at its
  radius) and the bounds (the initial values must lie within those of the free parameters), resolves the
  plan and sets up the solver. Then refuses unknown options, a missing target and unwritable outputs
  (before any solve), reads the target into the list of samples, and computes the reference state of a
  generated pattern once with the initial parameters (-calibrate_reference). -calibrate_view prints the
  set-up at the end.

  Collective

  Input Parameter:
. C - the calibration

  Level: beginner

.seealso: HylcCalibrateSetFromOptions(), HylcCalibrateSolve()
@*/
PetscErrorCode HylcCalibrateSetUp(HylcCalibrate C)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)C);
  HylcPatternType type;
  PetscBool       isfile;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  if (C->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_CalibrateSetUp, C, 0, 0, 0));
  if (!C->solverSetUp) PetscCall(HylcCalibrateSetUpSolver_Private(C));
  PetscCall(HylcCheckOptionsUsed(comm));
  PetscCheck(C->target[0], comm, PETSC_ERR_USER_INPUT, "No target: give -calibrate_target <model.json | model.h5 | samples.h5 | data.txt | file.csv>");
  PetscCall(CheckFiles(C));
  PetscCall(HylcCalibrateReadTarget_Private(C)); /* checks the target's content */
  C->continued = (PetscBool)(C->start == HYLC_CALIBRATE_START_CONTINUE || (C->start == HYLC_CALIBRATE_START_AUTO && C->targetResolved == HYLC_CALIB_TARGET_SAMPLES && C->targetContinued));
  PetscCall(HylcCalibrateBuildUnits_Private(C));
  /* the gradient at the base strain (in-plane only) and the stationarity's residuals */
  C->hasGrad = (PetscBool)(C->z[3] == 0 && C->z[4] == 0 && C->z[5] == 0);
  C->nres    = C->m;
  if (C->wstat > 0) {
    PetscCheck(C->hasGrad, comm, PETSC_ERR_USER_INPUT, "-calibrate_stationary needs an in-plane base strain (II = 0); the target's base strain is (%g, %g, %g, %g, %g, %g)", (double)C->z[0], (double)C->z[1], (double)C->z[2], (double)C->z[3],
               (double)C->z[4], (double)C->z[5]);
    for (int k = 0; k < 2; k++)
      PetscCheck(C->sscale[k] > 0, comm, PETSC_ERR_USER_INPUT, "-calibrate_stationary: no scale of dPsi/d%s (the target is not a table and has no row of the %s term with %s > 0, or its energy there equals the base strain's)", k ? "sy" : "sx",
                 k ? "sy" : "sx", k ? "sy" : "sx");
    C->nres = C->m + 2;
  }
  PetscCall(PetscMalloc2(C->m * HYLC_CALIB_NRECORD, &C->rec0, C->m * HYLC_CALIB_NRECORD, &C->rec1));
  /* the reference state: a generated pattern's depends on the parameters; it is computed once, with the
     initial values, and kept fixed (docs/calibrate.md) */
  {
    HylcPattern ref;
    PetscBool   asks;
    PetscCall(HylcPatternGetType(C->pat, &type));
    PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
    PetscCall(HylcReferenceStateNeeded(C->pat, C->refmode, &asks));
    if (asks) PetscCall(PetscPrintf(comm, "[calibrate] reference state (%s) of the %s pattern with the initial parameters (kept fixed)\n", HylcReferenceModes[C->refmode], C->patLabel));
    PetscCall(HylcReferenceStateForMode(C->pat, C->refmode, &C->model, &C->refpar, C->rank ? NULL : PETSC_VIEWER_STDOUT_SELF, &ref));
    if (ref) {
      PetscCall(HylcPatternDestroy(&C->pat));
      C->pat         = ref;
      C->refComputed = PETSC_TRUE;
    }
  }
  if (C->refout[0]) PetscCall(HylcPatternWrite(C->pat, C->refout));
  C->setupcalled = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_CalibrateSetUp, C, 0, 0, 0));
  PetscCall(HylcCalibrateViewFromOptions(C, NULL, "-calibrate_view"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetParameters - Parameter values (E, Es, G, kc): the initial ones (the yarn model at the pattern's
  radius, resolved by HylcCalibrateSetUp()) and the current ones (the calibrated values after
  HylcCalibrateSolve()). Either output may be NULL.

  Not collective

  Input Parameter:
. C - the calibration

  Output Parameters:
+ initial - 4 values
- current - 4 values

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateGetParameters(HylcCalibrate C, PetscReal initial[], PetscReal current[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) {
    if (initial) initial[j] = C->p0[j];
    if (current) current[j] = C->p[j];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetObjective - Objective before and after HylcCalibrateSolve(), and the number of iterations (any output may be NULL).

  Not collective

  Input Parameter:
. C - the calibration

  Output Parameters:
+ f0  - before
. f1  - after
- its - iterations of the optimizer (TAO)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateGetObjective(HylcCalibrate C, PetscReal *f0, PetscReal *f1, PetscInt *its)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  if (f0) *f0 = C->f0;
  if (f1) *f1 = C->f1;
  if (its) *its = C->its;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetSize - Number of samples (the base sample included), after HylcCalibrateSetUp().

  Not collective

  Input Parameter:
. C - the calibration

  Output Parameter:
. m - the number of samples

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateGetSize(HylcCalibrate C, PetscInt *m)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  *m = C->m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateGetStationarity - The gradient of Psi at the base strain z_b (dPsi/dsx, dPsi/dsy, N/m, by the
  envelope theorem) before and after HylcCalibrateSolve(), and the scales S_x, S_y of the stationarity's
  residuals (-calibrate_stationary; docs/calibrate.md). Zero where the base strain is not in-plane. Any
  output may be NULL.

  Not collective

  Input Parameter:
. C - the calibration, after HylcCalibrateSolve()

  Output Parameters:
+ scale  - S_x, S_y (N/m; 0: no scale)
. before - the gradient with the initial parameters
- after  - the gradient with the calibrated parameters

  Level: intermediate

.seealso: HylcCalibrateSetStationary(), HylcCalibrateEvaluateStationarity()
@*/
PetscErrorCode HylcCalibrateGetStationarity(HylcCalibrate C, PetscReal scale[], PetscReal before[], PetscReal after[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(C->solved, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_WRONGSTATE, "Call HylcCalibrateSolve() first");
  for (int k = 0; k < 2; k++) {
    if (scale) scale[k] = C->sscale[k];
    if (before) before[k] = C->rec0[HYLC_CALIB_REC_DS + k];
    if (after) after[k] = C->rec1[HYLC_CALIB_REC_DS + k];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateEvaluateStationarity - At explicit parameter values p = (E, Es, G, kc) (no ties applied): the
  base sample solved on every rank, the gradient dPsi/dsx, dPsi/dsy at it (N/m) and the Jacobian the
  stationarity's residuals use, dlogp[2 q + k] = p_q d/dp_q of dPsi/ds_k at the fixed state of the tile (the
  energy term of p_q; the change of the equilibrium with p is left out). After HylcCalibrateSetUp(), with an
  in-plane base strain.

  Collective

  Input Parameters:
+ C - the calibration
- p - the 4 parameter values (> 0)

  Output Parameters:
+ ds    - dPsi/dsx, dPsi/dsy at the base strain
- dlogp - 8 values (may be NULL)

  Level: advanced

.seealso: HylcCalibrateGetStationarity(), HylcMicroGetStrainGradientParts()
@*/
PetscErrorCode HylcCalibrateEvaluateStationarity(HylcCalibrate C, const PetscReal p[], PetscReal ds[], PetscReal dlogp[])
{
  HylcYarnModel   model = C->model;
  HylcMicroResult res;
  PetscReal       cols[2 * HYLC_CALIBRATE_NPARAM];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(C->setupcalled, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_WRONGSTATE, "Call HylcCalibrateSetUp() first");
  PetscCheck(C->hasGrad, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_WRONGSTATE, "The base strain is not in-plane: no gradient there");
  model.E  = p[0];
  model.Es = p[1];
  model.G  = p[2];
  model.kc = p[3];
  PetscCall(HylcMicroSetPattern(C->micro, C->pat, &model));
  PetscCall(HylcMicroSetUp(C->micro));
  PetscCall(HylcMicroSolve(C->micro, C->z, &res));
  PetscCheck(res.status == HYLC_MICRO_CONVERGED, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "The base sample did not converge (%s)", HylcMicroStatuses[res.status]);
  PetscCall(HylcCalibrateStrainGradient_Private(C, ds, cols));
  if (dlogp) PetscCall(PetscArraycpy(dlogp, cols, 2 * HYLC_CALIBRATE_NPARAM));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* normalised RMS of dPsi (model - target) over term t and the least-squares factor s of target onto model
   (target ~ s model) from a record array; rows that did not converge are left out */
static void TermStats(HylcCalibrate C, const PetscReal rec[], PetscInt t, PetscReal *rms, PetscReal *scale, PetscInt *n)
{
  const PetscReal b = rec[0], bt = C->tpsi[0];
  double          s2 = 0, tm = 0, mm = 0;
  PetscInt        k = 0;

  for (PetscInt i = 1; i < C->m; i++) {
    if (C->term[i] != t || rec[HYLC_CALIB_NRECORD * i + 5] != 0) continue;
    const double dm = rec[HYLC_CALIB_NRECORD * i] - b, dt = C->tpsi[i] - bt;
    s2 += (dm - dt) * (dm - dt);
    tm += dt * dm;
    mm += dm * dm;
    k++;
  }
  *n     = k;
  *rms   = k && C->range[t] > 0 ? PetscSqrtReal(s2 / k) / C->range[t] : 0;
  *scale = mm > 0 ? tm / mm : 0;
}

/*@C
  HylcCalibrateView - Before HylcCalibrateSolve(): the set-up (pattern, target, samples, parameters). After:
  the calibrated values, flags (bound, held) and the per-term table: normalised RMS of dPsi before -> after
  and the least-squares scale factor target/model before -> after.

  Collective

  Input Parameters:
+ C      - the calibration
- viewer - an ASCII viewer (NULL: stdout of the communicator)

  Level: beginner
@*/
PetscErrorCode HylcCalibrateView(HylcCalibrate C, PetscViewer viewer)
{
  PetscBool isascii;
  char      buf[512];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)C), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &isascii));
  if (!isascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerASCIIPrintf(viewer, "calibration: pattern %s%s, target %s (%s), %" PetscInt_FMT " samples\n", C->patLabel, C->refComputed ? " (reference state computed with the initial parameters)" : "", C->target,
                                   HylcCalibTargetTypes[C->targetResolved], C->m));
  PetscCall(PetscViewerASCIIPrintf(viewer, "samples solved %s (-calibrate_start %s; %" PetscInt_FMT " units of work)\n", C->continued ? "by continuation along each 1D term's half-line from zero outward" : "cold, each from the reference state",
                                   HylcCalibrateStarts[C->start], C->nunits));
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) {
    const char *flag = "";
    if (C->solved && C->held[j])
      flag = "  HELD: not determined by the data";
    else if (C->solved && C->bound[j])
      flag = "  AT BOUND";
    snprintf(buf, sizeof(buf), "  %-2s %-9s initial %-12.6g", HylcCalibrateParamNames[j], RoleNames[C->role[j]], (double)C->p0[j]);
    PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
    if (C->solved) {
      snprintf(buf, sizeof(buf), " -> %-12.6g (x %.4f)", (double)C->p[j], (double)(C->p[j] / C->p0[j]));
      PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
    }
    if (C->role[j] == HYLC_CALIBRATE_FREE) {
      snprintf(buf, sizeof(buf), "  bounds [%g, %g]", (double)C->lo[j], (double)C->hi[j]);
      PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
    }
    PetscCall(PetscViewerASCIIPrintf(viewer, "%s\n", flag));
  }
  if (!C->solved) PetscFunctionReturn(PETSC_SUCCESS);
  snprintf(buf, sizeof(buf), "objective: %.6e -> %.6e in %d iterations, %d evaluations, %.2f s\n", (double)C->f0, (double)C->f1, (int)C->its, (int)C->nevals, (double)C->tsolve);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscCall(PetscViewerASCIIPrintf(viewer, "term        n   RMS(dPsi)/range before -> after   scale target/model before -> after\n"));
  {
    const PetscReal pt = C->tpsi[0];
    snprintf(buf, sizeof(buf), "%-8s %4d   Psi(z_b)/target %.4f -> %.4f            (target %.6g J/m^2)\n", "zero", 1, (double)(C->rec0[0] / pt), (double)(C->rec1[0] / pt), (double)pt);
    PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  }
  if (C->hasGrad) {
    const PetscReal *g0 = C->rec0 + HYLC_CALIB_REC_DS, *g1 = C->rec1 + HYLC_CALIB_REC_DS;
    for (int k = 0; k < 2; k++) {
      if (C->sscale[k] > 0)
        snprintf(buf, sizeof(buf), "%-8s %4d   dPsi/d%s(z_b) / S %+.4f -> %+.4f            (S = target's dPsi/d%s at 5 %%: %.6g N/m; -calibrate_stationary %g)\n", k ? "stat_sy" : "stat_sx", 1, k ? "sy" : "sx", (double)(g0[k] / C->sscale[k]),
                 (double)(g1[k] / C->sscale[k]), k ? "sy" : "sx", (double)C->sscale[k], (double)C->wstat);
      else
        snprintf(buf, sizeof(buf), "%-8s %4d   dPsi/d%s(z_b) %.6g -> %.6g N/m (no scale)\n", k ? "stat_sy" : "stat_sx", 1, k ? "sy" : "sx", (double)g0[k], (double)g1[k]);
      PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
    }
  }
  for (PetscInt t = 1; t < HYLC_CALIB_NTERM; t++) {
    PetscReal r0, r1, s0, s1;
    PetscInt  n0, n1;
    if (!C->nt[t]) continue;
    TermStats(C, C->rec0, t, &r0, &s0, &n0);
    TermStats(C, C->rec1, t, &r1, &s1, &n1);
    snprintf(buf, sizeof(buf), "%-8s %4d   %8.3f%% -> %8.3f%%                    %8.4f -> %8.4f%s\n", HylcCalibrateTermName_Private(t), (int)C->nt[t], (double)(100 * r0), (double)(100 * r1), (double)s0, (double)s1,
             n1 < C->nt[t] ? "  (some samples not converged)" : "");
    PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateViewFromOptions - Views the calibration if the option name (e.g. -calibrate_view) is set.

  Collective

  Input Parameters:
+ C    - the calibration
. obj  - an object whose prefix is used (NULL: the calibration's)
- name - the option

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateViewFromOptions(HylcCalibrate C, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)C, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
