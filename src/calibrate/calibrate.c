/* HylcCalibrate: lifecycle, options, setters and getters (include/hylc/calibrate.h, docs/calibrate.md). */
#include "calibrateimpl.h"
#include <hylc/sampler.h>
#include <stdio.h>
#include <string.h>

const char *const        HylcCalibrateParamNames[HYLC_CALIBRATE_NPARAM] = {"E", "Es", "G", "kc"};
const char *const        HylcCalibTargetTypes[]                         = {"auto", "table", "samples", "raw", "csv", "HylcCalibTargetType", "HYLC_CALIB_TARGET_", NULL};
static const char *const RefModes[]                                     = {"auto", "compute", "none", "HylcCalibrateReference", "", NULL};
static const char *const RoleNames[]                                    = {"free", "tied to E", "fixed"};

const char *HylcCalibrateTermName_Private(PetscInt t) { return t == HYLC_CALIB_OTHER ? "other" : HylcPlanTermName((int)t); }

/*@C
  HylcCalibrateCreate - Creates a calibration: free E, Es, kc with G tied to E, bounds 1/1000 to 1000 x the
  initial values, the plan's 1D terms with 15 samples each. Collective.
@*/
PetscErrorCode HylcCalibrateCreate(MPI_Comm comm, HylcCalibrate *out)
{
  HylcCalibrate C;

  PetscFunctionBegin;
  PetscValidPointer(out, 2);
  PetscCall(HylcInitializePackage());
  PetscCall(PetscHeaderCreate(C, HYLC_CALIBRATE_CLASSID, "HylcCalibrate", "Yarn parameter calibration", "Calibrate", comm, HylcCalibrateDestroy, HylcCalibrateView));
  PetscCallMPI(MPI_Comm_rank(comm, &C->rank));
  PetscCallMPI(MPI_Comm_size(comm, &C->size));
  C->role[0] = HYLC_CALIBRATE_FREE;
  C->role[1] = HYLC_CALIBRATE_FREE;
  C->role[2] = HYLC_CALIBRATE_TIED;
  C->role[3] = HYLC_CALIBRATE_FREE;
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->lo[j] = C->hi[j] = -1; /* -1: relative to the initial value */
  C->n1         = 15;
  C->n2         = 5;
  C->terms      = (1 << 0) | (1 << 1) | (1 << 2) | (1 << 3) | (1 << 4) | (1 << 5);
  C->stride     = 1;
  C->maxSamples = 0;
  C->wzero      = 1;
  for (int t = 0; t < HYLC_CALIB_NTERM; t++) C->w[t] = 1;
  C->maxIt     = 30;
  C->maxReject = 8;
  C->lambda0   = 1e-3;
  C->xtol      = 1e-6;
  C->ftol      = 1e-10;
  C->fatol     = 1e-20;
  C->flatTol   = 1e-4;
  *out         = C;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ResetSamples(HylcCalibrate C)
{
  PetscFunctionBegin;
  PetscCall(PetscFree3(C->z, C->tpsi, C->term));
  PetscCall(PetscFree2(C->rec0, C->rec1));
  C->m = 0;
  for (int t = 0; t < HYLC_CALIB_NTERM; t++) {
    C->nt[t]    = 0;
    C->range[t] = 0;
  }
  C->setupcalled = C->solved = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateDestroy(HylcCalibrate *C)
{
  PetscFunctionBegin;
  if (!*C) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*C, HYLC_CALIBRATE_CLASSID, 1);
  if (--((PetscObject)(*C))->refct > 0) {
    *C = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(ResetSamples(*C));
  PetscCall(HylcMicroDestroy(&(*C)->micro));
  PetscCall(HylcPatternDestroy(&(*C)->pat));
  PetscCall(PetscHeaderDestroy(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSetOptionsPrefix(HylcCalibrate C, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)C, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSetTarget(HylcCalibrate C, const char path[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(ResetSamples(C));
  PetscCall(PetscStrncpy(C->target, path ? path : "", sizeof(C->target)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSetOutputs(HylcCalibrate C, const char yaml[], const char dump[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscStrncpy(C->output, yaml ? yaml : "", sizeof(C->output)));
  PetscCall(PetscStrncpy(C->dump, dump ? dump : "", sizeof(C->dump)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSetRoles(HylcCalibrate C, const HylcCalibrateRole role[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(role[0] != HYLC_CALIBRATE_TIED, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "E cannot be tied to itself");
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->role[j] = role[j];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSetBounds(HylcCalibrate C, PetscInt j, PetscReal lo, PetscReal hi)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(j >= 0 && j < HYLC_CALIBRATE_NPARAM, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "Parameter index %" PetscInt_FMT " out of range 0..3", j);
  PetscCheck(lo > 0 && lo <= hi, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "Bounds of %s must be 0 < lo <= hi, got %g,%g", HylcCalibrateParamNames[j], (double)lo, (double)hi);
  C->lo[j] = lo;
  C->hi[j] = hi;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSetMaxIterations(HylcCalibrate C, PetscInt n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  C->maxIt = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a comma list of parameter names -> flags; unknown names are an error naming the option */
static PetscErrorCode ParseParamList(MPI_Comm comm, const char opt[], const char list[], PetscBool flag[])
{
  char      buf[256], *tok, *save = NULL;
  PetscBool any = PETSC_FALSE;

  PetscFunctionBegin;
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) flag[j] = PETSC_FALSE;
  PetscCall(PetscStrncpy(buf, list, sizeof(buf)));
  for (tok = strtok_r(buf, ", ", &save); tok; tok = strtok_r(NULL, ", ", &save)) {
    int found = -1;
    for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++)
      if (!strcasecmp(tok, HylcCalibrateParamNames[j]) || (j == 1 && !strcasecmp(tok, "E_s")) || (j == 3 && !strcasecmp(tok, "k_c"))) found = j;
    PetscCheck(found >= 0, comm, PETSC_ERR_USER_INPUT, "%s: unknown parameter '%s' (use E, Es, G, kc)", opt, tok);
    flag[found] = PETSC_TRUE;
    any         = PETSC_TRUE;
  }
  (void)any;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetFromOptions - Options (docs/calibrate.md has the table); besides -pattern_*, -yarn_*
  (the initial values), -reference_*, -micro_*:
+ -calibrate_target <file>          - material table (.json, model .h5), samples .h5, raw data.txt (or its directory), or .csv
. -calibrate_target_type <auto>     - auto, table, samples, raw, csv
. -calibrate_output <p.yaml>        - calibrated values as a YAML options file
. -calibrate_dump <d.csv>           - per sample: strain, target, initial and calibrated Psi
. -calibrate_params <E,Es,kc>       - the free parameters (E, Es, G, kc)
. -calibrate_tie <G>                - parameters that follow E at their initial ratio when not free (not E)
. -calibrate_bounds_<p> lo,hi       - bounds (default initial / 1000, initial x 1000)
. -calibrate_terms <zero,sx,sa,sy,II00,II11> - terms of the plan for a table target (2D terms allowed)
. -calibrate_n <15>, -calibrate_n2 <5> - samples per 1D term, per axis of a 2D term (table target)
. -sampler_family, -sampler_range_<c> - the plan's ranges (table target), as hylc-sample
. -calibrate_stride <1>, -calibrate_max_samples <0> - thinning of a file target
. -calibrate_weight_zero <1>, -calibrate_weights <t=w,...> - weights of Psi(z_b) and of the terms
. -calibrate_max_it <30>, -calibrate_max_reject <8>, -calibrate_lambda <1e-3> - Levenberg-Marquardt
. -calibrate_xtol <1e-6>, -calibrate_ftol <1e-10>, -calibrate_fatol <1e-20> - stopping tests
. -calibrate_flat_tol <1e-4>        - singular value of the Jacobian below which a direction is flat
- -calibrate_reference <auto>       - reference state: auto (compute for a generated pattern), compute, none
@*/
PetscErrorCode HylcCalibrateSetFromOptions(HylcCalibrate C)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)C);
  PetscReal r;
  char      params[256] = "", tie[256] = "G", terms[512] = "", weights[1024] = "";
  PetscBool set, pset, tset;
  PetscEnum tt = (PetscEnum)C->targetType, rm = (PetscEnum)C->refmode;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  /* the tile and the initial yarn model */
  PetscCall(HylcPatternDestroy(&C->pat));
  PetscCall(HylcPatternCreate(comm, &C->pat));
  PetscCall(HylcPatternSetFromOptions(C->pat));
  PetscCall(HylcPatternSetUp(C->pat));
  PetscCall(HylcPatternGetRadius(C->pat, &r));
  {
    HylcPatternType type;
    PetscBool       isfile;
    char            file[PETSC_MAX_PATH_LEN] = "";
    PetscCall(HylcPatternGetType(C->pat, &type));
    PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
    if (isfile) PetscCall(PetscOptionsGetString(NULL, NULL, "-pattern_file", file, sizeof(file), NULL));
    PetscCall(PetscSNPrintf(C->patLabel, sizeof(C->patLabel), "%s%s%s", isfile ? "file " : "generated ", isfile ? file : type, ""));
  }
  PetscCall(HylcYarnModelDefault(&C->model));
  PetscCall(HylcYarnModelSetFromOptions(comm, NULL, &C->model));
  {
    HylcYarnConstants k;
    PetscCall(HylcYarnModelGetConstants(&C->model, r, &k));
    C->p0[0] = k.E;
    C->p0[1] = k.Es;
    C->p0[2] = k.G;
    C->p0[3] = k.kc;
    for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->p[j] = C->p0[j];
  }
  PetscCall(HylcReferenceParamsDefault(&C->refpar));
  PetscCall(HylcReferenceParamsSetFromOptions(comm, &C->refpar));
  PetscCall(HylcMicroDestroy(&C->micro));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &C->micro));
  PetscCall(HylcMicroSetPattern(C->micro, C->pat, &C->model));
  PetscCall(HylcMicroSetFromOptions(C->micro));
  PetscCall(HylcMicroSetUp(C->micro));

  /* the plan's ranges under the sampler's names, so that -options_file config/<p>.yaml applies */
  PetscOptionsBegin(comm, NULL, "Calibration: the plan's ranges (table target; the sampler's options)", "HylcCalibrate");
  PetscCall(HylcPlanRangesFromOptions(PetscOptionsObject, comm, r, "HylcCalibrate", &C->plan));
  PetscCall(PetscOptionsString("-reference_output", "Write the reference state as .pyp", "HylcCalibrate", C->refout, C->refout, sizeof(C->refout), NULL));
  PetscOptionsEnd();

  PetscObjectOptionsBegin((PetscObject)C);
  PetscCall(PetscOptionsString("-calibrate_target", "Target: a material table (.json or model .h5), a samples .h5 of hylc-sample, the paper's raw data.txt (or its directory), or a .csv with a header naming sx,sa,sy,II00,II01,II11,psi", "HylcCalibrateSetTarget", C->target, C->target, sizeof(C->target), NULL));
  PetscCall(PetscOptionsEnum("-calibrate_target_type", "Kind of target: auto (by extension and content), table, samples, raw, csv", "HylcCalibrateSetTarget", HylcCalibTargetTypes, tt, &tt, NULL));
  PetscCall(PetscOptionsString("-calibrate_output", "Write the calibrated values as a YAML options file (yarn_E, yarn_Es, yarn_G, yarn_kc; a drop-in for config/)", "HylcCalibrateSetOutputs", C->output, C->output, sizeof(C->output), NULL));
  PetscCall(PetscOptionsString("-calibrate_dump", "Write per sample the strain, term, target, initial and calibrated Psi as CSV (examples/plot_calibrate.py)", "HylcCalibrateSetOutputs", C->dump, C->dump, sizeof(C->dump), NULL));
  PetscCall(PetscOptionsString("-calibrate_params", "Free parameters, a comma list of E, Es, G, kc", "HylcCalibrateSetRoles", params, params, sizeof(params), &pset));
  PetscCall(PetscOptionsString("-calibrate_tie", "Parameters that follow E at their initial ratio when not free (Es, G, kc; 'none' for none); the others not free are fixed", "HylcCalibrateSetRoles", tie, tie, sizeof(tie), &tset));
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) {
    char      opt[64], help[160];
    PetscReal v[2] = {C->lo[j], C->hi[j]};
    PetscInt  n    = 2;
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-calibrate_bounds_%s", HylcCalibrateParamNames[j]));
    PetscCall(PetscSNPrintf(help, sizeof(help), "Bounds lo,hi of %s (%s; default initial/1000, initial*1000)", HylcCalibrateParamNames[j], j == 3 ? "N/m" : "Pa"));
    PetscCall(PetscOptionsRealArray(opt, help, "HylcCalibrateSetBounds", v, &n, &set));
    if (set) {
      PetscCheck(n == 2, comm, PETSC_ERR_USER_INPUT, "%s needs two values lo,hi", opt);
      snprintf(help, sizeof(help), "%g,%g", (double)v[0], (double)v[1]); /* C formatting for the message */
      PetscCheck(v[0] > 0 && v[1] > 0, comm, PETSC_ERR_USER_INPUT, "%s %s: bounds must be positive (the parameters are optimised in log space)", opt, help);
      PetscCheck(v[0] <= v[1], comm, PETSC_ERR_USER_INPUT, "%s %s: inverted bounds (lo > hi)", opt, help);
      C->lo[j] = v[0];
      C->hi[j] = v[1];
    }
  }
  PetscCall(PetscOptionsString("-calibrate_terms", "Terms sampled for a table target: a comma list of zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, or all, or 1d (default zero,sx,sa,sy,II00,II11)", "HylcCalibrate", terms, terms, sizeof(terms), NULL));
  PetscCall(PetscOptionsInt("-calibrate_n", "Samples per 1D term (table target)", "HylcCalibrate", C->n1, &C->n1, NULL));
  PetscCall(PetscOptionsInt("-calibrate_n2", "Samples per axis of a 2D term (table target)", "HylcCalibrate", C->n2, &C->n2, NULL));
  PetscCall(PetscOptionsInt("-calibrate_stride", "File target: keep every stride-th row of each term", "HylcCalibrate", C->stride, &C->stride, NULL));
  PetscCall(PetscOptionsInt("-calibrate_max_samples", "File target: at most this many rows (thinned evenly within each term; 0: all)", "HylcCalibrate", C->maxSamples, &C->maxSamples, NULL));
  PetscCall(PetscOptionsReal("-calibrate_weight_zero", "Weight of the relative error of Psi at the base strain (the constant)", "HylcCalibrate", C->wzero, &C->wzero, NULL));
  PetscCall(PetscOptionsString("-calibrate_weights", "Weights of terms, a comma list term=weight (e.g. sx=2,sa-sy=0.5; default 1 each; 'other' for file rows off the plan's axes)", "HylcCalibrate", weights, weights, sizeof(weights), NULL));
  PetscCall(PetscOptionsInt("-calibrate_max_it", "Levenberg-Marquardt: at most this many iterations (accepted steps)", "HylcCalibrateSetMaxIterations", C->maxIt, &C->maxIt, NULL));
  PetscCall(PetscOptionsInt("-calibrate_max_reject", "Levenberg-Marquardt: stop after this many rejected trial steps in a row", "HylcCalibrate", C->maxReject, &C->maxReject, NULL));
  PetscCall(PetscOptionsReal("-calibrate_lambda", "Levenberg-Marquardt: initial damping (relative to the diagonal of J^T J)", "HylcCalibrate", C->lambda0, &C->lambda0, NULL));
  PetscCall(PetscOptionsReal("-calibrate_xtol", "Stop when an accepted step changes every log parameter by less than this", "HylcCalibrate", C->xtol, &C->xtol, NULL));
  PetscCall(PetscOptionsReal("-calibrate_ftol", "Stop when an accepted step decreases the objective by less than this fraction", "HylcCalibrate", C->ftol, &C->ftol, NULL));
  PetscCall(PetscOptionsReal("-calibrate_fatol", "Stop when the objective is below this", "HylcCalibrate", C->fatol, &C->fatol, NULL));
  PetscCall(PetscOptionsReal("-calibrate_flat_tol", "A direction of the log parameters along which the normalised residuals change by less than this per unit (a singular value of the Jacobian) is flat: its parameter is held and reported", "HylcCalibrate", C->flatTol, &C->flatTol, NULL));
  PetscCall(PetscOptionsEnum("-calibrate_reference", "Reference state: auto (compute it once with the initial parameters for a generated pattern; a .pyp file is its own), compute, none", "HylcCalibrate", RefModes, rm, &rm, NULL));
  PetscOptionsEnd();
  C->targetType = (HylcCalibTargetType)tt;
  C->refmode    = (PetscInt)rm;

  /* parameters: free, tied, fixed */
  {
    PetscBool fr[HYLC_CALIBRATE_NPARAM], ti[HYLC_CALIBRATE_NPARAM] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};
    if (pset) {
      PetscCall(ParseParamList(comm, "-calibrate_params", params, fr));
    } else
      for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) fr[j] = C->role[j] == HYLC_CALIBRATE_FREE;
    if (tset) {
      PetscBool none;
      PetscCall(PetscStrcasecmp(tie, "none", &none));
      if (!none) PetscCall(ParseParamList(comm, "-calibrate_tie", tie, ti));
      PetscCheck(!ti[0], comm, PETSC_ERR_USER_INPUT, "-calibrate_tie: E cannot be tied to itself (tie Es, G or kc to E)");
    } else
      for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) ti[j] = C->role[j] == HYLC_CALIBRATE_TIED;
    PetscCheck(fr[0] || fr[1] || fr[2] || fr[3], comm, PETSC_ERR_USER_INPUT, "-calibrate_params: no free parameter (use a comma list of E, Es, G, kc)");
    for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->role[j] = fr[j] ? HYLC_CALIBRATE_FREE : (ti[j] ? HYLC_CALIBRATE_TIED : HYLC_CALIBRATE_FIXED);
  }
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) {
    if (C->lo[j] < 0) C->lo[j] = C->p0[j] / 1000;
    if (C->hi[j] < 0) C->hi[j] = C->p0[j] * 1000;
    PetscCheck(C->lo[j] <= C->hi[j], comm, PETSC_ERR_USER_INPUT, "-calibrate_bounds_%s %g,%g: inverted bounds (lo > hi)", HylcCalibrateParamNames[j], (double)C->lo[j], (double)C->hi[j]);
    if (C->role[j] == HYLC_CALIBRATE_FREE) {
      char msg[128];
      snprintf(msg, sizeof(msg), "%g (from -yarn_%s) is outside -calibrate_bounds_%s %g,%g", (double)C->p0[j], HylcCalibrateParamNames[j], HylcCalibrateParamNames[j], (double)C->lo[j], (double)C->hi[j]);
      PetscCheck(C->p0[j] >= C->lo[j] && C->p0[j] <= C->hi[j], comm, PETSC_ERR_USER_INPUT, "The initial %s = %s", HylcCalibrateParamNames[j], msg);
    }
  }
  /* terms */
  if (terms[0]) {
    int mask;
    PetscCall(HylcPlanTermsFromString(comm, "-calibrate_terms", terms, &mask));
    C->terms = (PetscInt)mask;
  }
  C->terms |= 1; /* the base sample is always solved */
  PetscCheck(C->n1 >= 2 && C->n1 <= 1024 && C->n2 >= 2 && C->n2 <= 1024, comm, PETSC_ERR_USER_INPUT, "-calibrate_n and -calibrate_n2 must be in 2..1024, got %" PetscInt_FMT " and %" PetscInt_FMT, C->n1, C->n2);
  C->plan.n1    = (int)C->n1;
  C->plan.n2    = (int)C->n2;
  C->plan.terms = (int)C->terms;
  PetscCheck(C->stride >= 1, comm, PETSC_ERR_USER_INPUT, "-calibrate_stride must be >= 1, got %" PetscInt_FMT, C->stride);
  PetscCheck(C->maxSamples >= 0, comm, PETSC_ERR_USER_INPUT, "-calibrate_max_samples must be >= 0, got %" PetscInt_FMT, C->maxSamples);
  PetscCheck(C->wzero >= 0, comm, PETSC_ERR_USER_INPUT, "-calibrate_weight_zero must be >= 0, got %g", (double)C->wzero);
  if (weights[0]) {
    char *tok, *save = NULL;
    for (tok = strtok_r(weights, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
      char  *eq = strchr(tok, '='), *end = NULL;
      int    found = -1;
      double v;
      PetscCheck(eq, comm, PETSC_ERR_USER_INPUT, "-calibrate_weights: '%s' is not term=weight", tok);
      *eq = 0;
      v   = strtod(eq + 1, &end);
      PetscCheck(end != eq + 1 && !*end && v >= 0, comm, PETSC_ERR_USER_INPUT, "-calibrate_weights: the weight of %s must be a number >= 0, got '%s'", tok, eq + 1);
      for (int t = 1; t < HYLC_CALIB_NTERM; t++)
        if (!strcmp(tok, HylcCalibrateTermName_Private(t))) found = t;
      PetscCheck(found >= 1, comm, PETSC_ERR_USER_INPUT, "-calibrate_weights: unknown term '%s' (use sx, sa, sy, II00, II11, a 2D term such as sx-sa, or other; the constant's is -calibrate_weight_zero)", tok);
      C->w[found] = v;
    }
  }
  PetscCheck(C->maxIt >= 0 && C->maxReject >= 1, comm, PETSC_ERR_USER_INPUT, "-calibrate_max_it must be >= 0 and -calibrate_max_reject >= 1");
  PetscCheck(C->lambda0 > 0 && C->xtol >= 0 && C->ftol >= 0 && C->fatol >= 0 && C->flatTol >= 0, comm, PETSC_ERR_USER_INPUT, "-calibrate_lambda must be > 0 and -calibrate_xtol, -calibrate_ftol, -calibrate_fatol, -calibrate_flat_tol >= 0");
  PetscCall(ResetSamples(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetUp - Refuses unknown options, a missing target and unwritable outputs (before any solve),
  reads the target into the list of samples, then computes the reference state of a generated pattern once
  with the initial parameters (-calibrate_reference). Collective.
@*/
PetscErrorCode HylcCalibrateSetUp(HylcCalibrate C)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)C);
  HylcPatternType type;
  PetscBool       isfile;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  if (C->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(C->micro, comm, PETSC_ERR_ARG_WRONGSTATE, "Call HylcCalibrateSetFromOptions() first");
  PetscCall(PetscLogEventBegin(HYLC_CalibrateSetUp, C, 0, 0, 0));
  PetscCall(HylcCheckOptionsUsed(comm));
  PetscCheck(C->target[0], comm, PETSC_ERR_USER_INPUT, "No target: give -calibrate_target <model.json | model.h5 | samples.h5 | data.txt | file.csv>");
  if (C->output[0]) PetscCall(HylcFileCheckOutput(comm, C->output, "-calibrate_output"));
  if (C->dump[0]) PetscCall(HylcFileCheckOutput(comm, C->dump, "-calibrate_dump"));
  if (C->refout[0]) PetscCall(HylcFileCheckOutput(comm, C->refout, "-reference_output"));
  PetscCall(HylcCalibrateReadTarget_Private(C)); /* checks the target's path and content */
  if (C->output[0]) PetscCall(HylcFileCheckDistinct(comm, C->output, "-calibrate_output", C->target, "-calibrate_target"));
  if (C->dump[0]) PetscCall(HylcFileCheckDistinct(comm, C->dump, "-calibrate_dump", C->target, "-calibrate_target"));
  PetscCall(PetscMalloc2(C->m * HYLC_CALIB_NRECORD, &C->rec0, C->m * HYLC_CALIB_NRECORD, &C->rec1));
  /* the reference state: a generated pattern's depends on the parameters; it is computed once, with the
     initial values, and kept fixed (docs/calibrate.md) */
  PetscCall(HylcPatternGetType(C->pat, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  if (C->refmode == 1 || (C->refmode == 0 && !isfile)) {
    HylcPattern ref;
    PetscCall(PetscPrintf(comm, "[calibrate] reference state of the %s pattern with the initial parameters (kept fixed)\n", C->patLabel));
    PetscCall(HylcReferenceStateCompute(C->pat, &C->model, &C->refpar, C->rank ? NULL : PETSC_VIEWER_STDOUT_SELF, &ref));
    PetscCall(HylcPatternDestroy(&C->pat));
    C->pat         = ref;
    C->refComputed = PETSC_TRUE;
  }
  if (C->refout[0]) PetscCall(HylcPatternWrite(C->pat, C->refout));
  C->setupcalled = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_CalibrateSetUp, C, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

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

PetscErrorCode HylcCalibrateGetObjective(HylcCalibrate C, PetscReal *f0, PetscReal *f1, PetscInt *its)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  if (f0) *f0 = C->f0;
  if (f1) *f1 = C->f1;
  if (its) *its = C->its;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateGetSize(HylcCalibrate C, PetscInt *m)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  *m = C->m;
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
  HylcCalibrateView - Before HylcCalibrateSolve: the set-up (pattern, target, samples, parameters). After:
  the calibrated values, flags (bound, held) and the per-term table: normalised RMS of dPsi before -> after
  and the least-squares scale factor target/model before -> after. Collective.
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
  PetscCall(PetscViewerASCIIPrintf(viewer, "calibration: pattern %s%s, target %s (%s), %" PetscInt_FMT " samples\n", C->patLabel, C->refComputed ? " (reference state computed with the initial parameters)" : "", C->target, HylcCalibTargetTypes[C->targetResolved], C->m));
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
  for (PetscInt t = 1; t < HYLC_CALIB_NTERM; t++) {
    PetscReal r0, r1, s0, s1;
    PetscInt  n0, n1;
    if (!C->nt[t]) continue;
    TermStats(C, C->rec0, t, &r0, &s0, &n0);
    TermStats(C, C->rec1, t, &r1, &s1, &n1);
    snprintf(buf, sizeof(buf), "%-8s %4d   %8.3f%% -> %8.3f%%                    %8.4f -> %8.4f%s\n", HylcCalibrateTermName_Private(t), (int)C->nt[t], (double)(100 * r0), (double)(100 * r1), (double)s0, (double)s1, n1 < C->nt[t] ? "  (some samples not converged)" : "");
    PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateViewFromOptions(HylcCalibrate C, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)C, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
