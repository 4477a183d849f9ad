/* HylcCalibrate: the setters of the options and HylcCalibrateSetFromOptions (docs/calibrate.md). */
#include <hylc/options.h>
#include "calibrateimpl.h"
#include <stdio.h>
#include <string.h>

/*@C
  HylcCalibrateSetYarnModel - Sets the yarn model whose E, Es, G, kc are the initial values (copied; options
  -yarn_*, read by HylcCalibrateSetFromOptions()).

  Not collective

  Input Parameters:
+ C     - the calibration
- model - the yarn model

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetYarnModel(HylcCalibrate C, const HylcYarnModel *model)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  C->model       = *model;
  C->solverSetUp = PETSC_FALSE;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetTarget - Sets the target file (option -calibrate_target): a material table (.json or
  model .h5), a samples .h5 of hylc-sample, the paper's raw data.txt (or its directory), or a .csv.

  Not collective

  Input Parameters:
+ C    - the calibration
- path - the file

  Level: beginner

.seealso: HylcCalibrateSetTargetType()
@*/
PetscErrorCode HylcCalibrateSetTarget(HylcCalibrate C, const char path[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscCall(PetscStrncpy(C->target, path ? path : "", sizeof(C->target)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetTargetType - Sets the kind of target (option -calibrate_target_type).

  Not collective

  Input Parameters:
+ C    - the calibration
- type - auto (by extension and content), table, samples, raw or csv

  Level: intermediate

.seealso: HylcCalibrateSetTarget()
@*/
PetscErrorCode HylcCalibrateSetTargetType(HylcCalibrate C, const char type[])
{
  PetscInt k = -1;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  for (PetscInt i = 0; i <= HYLC_CALIB_TARGET_CSV; i++) {
    PetscBool eq;
    PetscCall(PetscStrcasecmp(type, HylcCalibTargetTypes[i], &eq));
    if (eq) k = i;
  }
  PetscCheck(k >= 0, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_target_type: unknown type '%s' (use auto, table, samples, raw, csv)", type);
  PetscCall(HylcCalibrateResetSamples_Private(C));
  C->targetType = (HylcCalibTargetType)k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetOutputs - Sets the outputs (options -calibrate_output, -calibrate_dump).

  Not collective

  Input Parameters:
+ C    - the calibration
. yaml - the calibrated values as a YAML options file (NULL or empty: none)
- dump - per sample the strain, term, target, initial and calibrated Psi as CSV (NULL or empty: none)

  Level: beginner
@*/
PetscErrorCode HylcCalibrateSetOutputs(HylcCalibrate C, const char yaml[], const char dump[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscStrncpy(C->output, yaml ? yaml : "", sizeof(C->output)));
  PetscCall(PetscStrncpy(C->dump, dump ? dump : "", sizeof(C->dump)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetRoles - Sets the roles of E, Es, G, kc (options -calibrate_params, -calibrate_tie).

  Not collective

  Input Parameters:
+ C    - the calibration
- role - HYLC_CALIBRATE_FREE, HYLC_CALIBRATE_TIED (follows E at its initial ratio; not for E) or
         HYLC_CALIBRATE_FIXED, per parameter

  Level: beginner
@*/
PetscErrorCode HylcCalibrateSetRoles(HylcCalibrate C, const HylcCalibrateRole role[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(role[0] != HYLC_CALIBRATE_TIED, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "E cannot be tied to itself");
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) C->role[j] = role[j];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetBounds - Sets the bounds of parameter j (options -calibrate_bounds_<p>); the default is
  the initial value / 1000 to the initial value x 1000.

  Not collective

  Input Parameters:
+ C  - the calibration
. j  - the parameter: 0 E, 1 Es, 2 G, 3 kc
. lo - lower bound (> 0)
- hi - upper bound (>= lo)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetBounds(HylcCalibrate C, PetscInt j, PetscReal lo, PetscReal hi)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(j >= 0 && j < HYLC_CALIBRATE_NPARAM, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "Parameter index %" PetscInt_FMT " out of range 0..3", j);
  PetscCheck(lo > 0 && lo <= hi && !PetscIsInfOrNanReal(hi), PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "Bounds of %s must be finite with 0 < lo <= hi, got %g,%g", HylcCalibrateParamNames[j], (double)lo, (double)hi);
  C->blo[j]      = lo;
  C->bhi[j]      = hi;
  C->solverSetUp = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetMaxIterations - At most this many iterations of the optimizer (option -calibrate_max_it;
  TAO's maximum iterations, which -calibrate_tao_max_it overrides).

  Not collective

  Input Parameters:
+ C - the calibration
- n - the cap (>= 0)

  Level: beginner
@*/
PetscErrorCode HylcCalibrateSetMaxIterations(HylcCalibrate C, PetscInt n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(n >= 0, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_max_it must be >= 0");
  C->maxIt = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const HylcCalibrateStationaryJacobians[] = {"gn", "fd", "HylcCalibrateStationaryJacobian", "HYLC_CALIBRATE_STATIONARY_", NULL};
const char *const HylcCalibrateStarts[]              = {"auto", "cold", "continue", "HylcCalibrateStart", "HYLC_CALIBRATE_START_", NULL};

/*@C
  HylcCalibrateSetStart - How the samples of an evaluation are solved (option -calibrate_start): auto (the
  default: the way the target was made, so that the model is compared with the target on the same branch
  of its equilibria: continue for a samples file with continued samples, cold for one without, and cold
  for a table, raw data.txt or CSV, as the paper's tables and data were computed by cold starts), continue
  (each 1D term's half-line from the zero strain outward, each sample from its predecessor's equilibrium,
  retried cold if that does not converge, as hylc-sample's default; the base strain, 2D terms and rows off
  the axes cold) or cold (every sample from the reference state, the paper's procedure). The knits have
  several equilibria at large compressions, and the two starts reach different ones (docs/method.md,
  "Multistability"). The gradient by the envelope theorem holds for either.

  Not collective

  Input Parameters:
+ C     - the calibration
- start - HYLC_CALIBRATE_START_AUTO, HYLC_CALIBRATE_START_COLD or HYLC_CALIBRATE_START_CONTINUE

  Level: intermediate

.seealso: HylcSamplerSetStart(), HylcMicroSolveContinued()
@*/
PetscErrorCode HylcCalibrateSetStart(HylcCalibrate C, HylcCalibrateStart start)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(start >= HYLC_CALIBRATE_START_AUTO && start <= HYLC_CALIBRATE_START_CONTINUE, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "-calibrate_start: unknown start %d (auto, cold or continue)", (int)start);
  C->start = start;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetStationary - Requires the tile to be stationary at the base strain (option
  -calibrate_stationary): adds the residuals sqrt(w) dPsi/ds_k(z_b) / S_k, k = x, y, so that the objective
  gains w ((dPsi/dsx / S_x)^2 + (dPsi/dsy / S_y)^2); S_k is the target's dPsi/ds_k at s_k = 5 % (a table; for
  a file target 2 dPsi_T / s_k of its row of the 1D term nearest to s_k = 5 %, among every usable row: the
  same whatever -calibrate_stride and -calibrate_max_samples keep). The gradient is the envelope
  theorem's at the equilibrium. Its Jacobian (option -calibrate_stationary_jacobian): fd (the default), central
  differences in log p with step h (-calibrate_stationary_h, 1e-2), each a cold re-solve of the base sample
  (two per parameter not fixed, per evaluation); or gn, the energy terms' parts at the fixed state, which
  costs no solve but leaves out the change of the equilibrium with the parameters (a Gauss-Newton
  approximation that measured poor: docs/calibrate.md).

  Not collective

  Input Parameters:
+ C  - the calibration
. w  - the weight (0 <= w <= 1e8; 0: off, the default)
. fd - PETSC_TRUE: the Jacobian by central differences; PETSC_FALSE: the Gauss-Newton one
- h  - the step in log p of the differences (0 < h <= 1)

  Level: intermediate

.seealso: HylcCalibrateGetStationarity(), HylcCalibrateEvaluateStationarity()
@*/
PetscErrorCode HylcCalibrateSetStationary(HylcCalibrate C, PetscReal w, PetscBool fd, PetscReal h)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(w >= 0 && !PetscIsInfOrNanReal(w), PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_stationary must be a finite number >= 0, got %g", (double)w);
  PetscCheck(w <= 1e8, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_stationary %.6g: at most 1e8 (beyond, the stationarity alone decides and the objective loses the samples' digits; 1e300 overflowed it)", (double)w);
  PetscCheck(h > 0 && h <= 1, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_stationary_h must be in (0, 1], got %g", (double)h);
  C->wstat  = w;
  C->statFD = fd;
  C->statH  = h;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetDamping - The Levenberg-Marquardt damping of TAOBRGN (option -calibrate_lambda): its
  regularizer weight lambda, the step solving (J^T J + lambda diag J^T J) d = -J^T r; -calibrate_tao_brgn_regularizer_weight
  overrides it.

  Not collective

  Input Parameters:
+ C      - the calibration
- lambda - > 0

  Level: advanced

.seealso: HylcCalibrateGetTao(), TaoBRGNSetRegularizerWeight()
@*/
PetscErrorCode HylcCalibrateSetDamping(HylcCalibrate C, PetscReal lambda)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(lambda > 0, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_lambda must be > 0, got %g", (double)lambda);
  C->lambda = lambda;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetTolerances - Stopping tests and the flat-direction test (options -calibrate_xtol,
  -calibrate_ftol, -calibrate_fatol, -calibrate_flat_tol).

  Not collective

  Input Parameters:
+ C       - the calibration
. xtol    - stop when an iteration changes every log parameter by less than this
. ftol    - stop when an iteration decreases the objective by less than this fraction
. fatol   - stop when the objective is below this
  (tests hylc adds to TAO's own, -calibrate_tao_gatol, -calibrate_tao_grtol, -calibrate_tao_gttol)
- flatTol - a singular value of the Jacobian below this marks a flat direction (its parameter is held)

  Level: advanced
@*/
PetscErrorCode HylcCalibrateSetTolerances(HylcCalibrate C, PetscReal xtol, PetscReal ftol, PetscReal fatol, PetscReal flatTol)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(xtol >= 0 && ftol >= 0 && fatol >= 0 && flatTol >= 0, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_xtol, -calibrate_ftol, -calibrate_fatol, -calibrate_flat_tol must be >= 0");
  C->xtol    = xtol;
  C->ftol    = ftol;
  C->fatol   = fatol;
  C->flatTol = flatTol;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetPlanRanges - The plan's family and 1D ranges for a table target (options -sampler_family,
  -sampler_range_<c>, as hylc-sample); HylcCalibrateSetUp() resolves them for the yarn radius.

  Not collective

  Input Parameters:
+ C      - the calibration
- ranges - the family and the ranges

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetPlanRanges(HylcCalibrate C, const HylcPlanRanges *ranges)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(ranges->family >= 0 && ranges->family < 4, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "-sampler_family: unknown family %" PetscInt_FMT, ranges->family);
  C->ranges      = *ranges;
  C->solverSetUp = PETSC_FALSE;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetTerms - The plan's terms sampled for a table target (option -calibrate_terms); the base
  sample (term zero) is always solved.

  Not collective

  Input Parameters:
+ C     - the calibration
- terms - bit t set for term t of include/hylc/plan.h

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetTerms(HylcCalibrate C, PetscInt terms)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(terms >= 0 && terms < (1 << HYLC_PLAN_NTERM), PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "-calibrate_terms: term mask %" PetscInt_FMT " out of range", terms);
  C->terms      = terms | 1;
  C->plan.terms = (int)C->terms;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetSampleCounts - Samples per 1D term and per axis of a 2D term for a table target (options
  -calibrate_n, -calibrate_n2).

  Not collective

  Input Parameters:
+ C  - the calibration
. n1 - 2..1024
- n2 - 2..1024

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetSampleCounts(HylcCalibrate C, PetscInt n1, PetscInt n2)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(n1 >= 2 && n1 <= 1024 && n2 >= 2 && n2 <= 1024, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_n and -calibrate_n2 must be in 2..1024, got %" PetscInt_FMT " and %" PetscInt_FMT, n1, n2);
  C->n1      = n1;
  C->n2      = n2;
  C->plan.n1 = (int)n1;
  C->plan.n2 = (int)n2;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetThinning - Thinning of a file target (options -calibrate_stride, -calibrate_max_samples).

  Not collective

  Input Parameters:
+ C          - the calibration
. stride     - keep every stride-th row of each term (>= 1)
- maxSamples - at most this many rows, thinned evenly within each term (0: all)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetThinning(HylcCalibrate C, PetscInt stride, PetscInt maxSamples)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(stride >= 1, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_stride must be >= 1, got %" PetscInt_FMT, stride);
  PetscCheck(maxSamples >= 0, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_max_samples must be >= 0, got %" PetscInt_FMT, maxSamples);
  C->stride     = stride;
  C->maxSamples = maxSamples;
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetTermWeight - The weight of a term in the objective (options -calibrate_weights t=w,...;
  -calibrate_weight_zero for "zero", the relative error of Psi at the base strain).

  Not collective

  Input Parameters:
+ C    - the calibration
. term - zero, a term of the plan (sx, sa-sy, ...) or other (file rows off the plan's axes)
- w    - the weight (>= 0; default 1)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetTermWeight(HylcCalibrate C, const char term[], PetscReal w)
{
  PetscBool zero;
  int       found = -1;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(PetscStrcmp(term, "zero", &zero));
  if (zero) {
    PetscCheck(w >= 0 && !PetscIsInfOrNanReal(w), PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_weight_zero must be finite and >= 0, got %g", (double)w);
    C->wzero = w;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (int t = 1; t < HYLC_CALIB_NTERM; t++)
    if (!strcmp(term, HylcCalibrateTermName_Private(t))) found = t;
  PetscCheck(found >= 1, PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_weights: unknown term '%s' (use sx, sa, sy, II00, II11, a 2D term such as sx-sa, or other; the constant's is -calibrate_weight_zero)", term);
  PetscCheck(w >= 0 && !PetscIsInfOrNanReal(w), PetscObjectComm((PetscObject)C), PETSC_ERR_USER_INPUT, "-calibrate_weights: the weight of %s must be a finite number >= 0, got %g", term, (double)w);
  C->w[found] = w;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetReference - Whether the reference state is computed once with the initial parameters,
  and where it is written (options -calibrate_reference, -reference_output; its parameters -reference_*).

  Not collective

  Input Parameters:
+ C      - the calibration
. mode   - HYLC_REFERENCE_AUTO (for a generated pattern), HYLC_REFERENCE_COMPUTE, HYLC_REFERENCE_NONE or HYLC_REFERENCE_RELAX (the in-plane minimum of the pattern as given)
- output - .pyp file for the reference state (NULL or empty: none)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateSetReference(HylcCalibrate C, HylcReferenceMode mode, const char output[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(mode >= HYLC_REFERENCE_AUTO && mode <= HYLC_REFERENCE_RELAX, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "Unknown reference mode %d", (int)mode);
  C->refmode = mode;
  PetscCall(PetscStrncpy(C->refout, output ? output : "", sizeof(C->refout)));
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

/* the optimizer's options: hylc's (-calibrate_max_it, -calibrate_lambda) as TAO's defaults, then TAO's own
   (-calibrate_tao_*), which override them. PETSc 3.18's TAOBRGN needs three things done by hand: its
   subsolver's options prefix ignores the TAO's (it is set here to <prefix>calibrate_tao_brgn_subsolver_);
   its subsolver's line search is Armijo unless -calibrate_tao_brgn_subsolver_tao_ls_type says otherwise
   (BRGN's own unit step takes a step that raises the objective, which the hand-written LM rejected:
   measured on calibrate_recovery, docs/calibrate.md); and its regularization can be chosen only through
   an options database: unless -calibrate_tao_brgn_regularization_type is given, the TAO reads once from a
   database of its own that holds only "lm" (Levenberg-Marquardt damping). Entering that default into the
   global database instead would take one of PETSc's 512 option slots, which are the user's. */
PetscErrorCode HylcCalibrateTaoSetFromOptions_Private(HylcCalibrate C)
{
  Tao           tao, sub;
  TaoLineSearch ls;
  PetscBool     isbrgn, set;
  const char   *prefix;
  char          opt[256];
  PetscOptions  lm;

  PetscFunctionBegin;
  PetscCall(HylcCalibrateGetTao(C, &tao));
  PetscCall(TaoSetMaximumIterations(tao, C->maxIt));
  PetscCall(PetscObjectTypeCompare((PetscObject)tao, TAOBRGN, &isbrgn));
  if (isbrgn) PetscCall(TaoBRGNSetRegularizerWeight(tao, C->lambda));
  PetscCall(TaoSetFromOptions(tao));
  PetscCall(TaoGetOptionsPrefix(tao, &prefix));
  PetscCall(PetscOptionsHasName(NULL, prefix, "-tao_view", &set)); /* read by TaoSolve(), after hylc's check for unknown options */
  PetscCall(PetscObjectTypeCompare((PetscObject)tao, TAOBRGN, &isbrgn));
  if (!isbrgn) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(TaoBRGNGetSubsolver(tao, &sub));
  PetscCall(TaoSetOptionsPrefix(sub, prefix));
  PetscCall(TaoAppendOptionsPrefix(sub, "tao_brgn_subsolver_"));
  PetscCall(TaoSetFromOptions(tao)); /* the subsolver's options under their right names; the weight again */
  PetscCall(PetscOptionsHasName(NULL, prefix, "-tao_brgn_regularization_type", &set));
  if (!set) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%stao_brgn_regularization_type", prefix ? prefix : ""));
    PetscCall(PetscOptionsCreate(&lm));
    PetscCall(PetscOptionsSetValue(lm, opt, "lm"));
    PetscCall(PetscObjectSetOptions((PetscObject)tao, lm));
    PetscCall(TaoSetFromOptions(tao)); /* an option absent from lm keeps its value */
    PetscCall(PetscObjectSetOptions((PetscObject)tao, NULL));
    PetscCall(PetscOptionsDestroy(&lm));
  }
  /* after BRGN's options, which make the line search of lm a unit step */
  PetscCall(TaoGetOptionsPrefix(sub, &prefix));
  PetscCall(PetscOptionsHasName(NULL, prefix, "-tao_ls_type", &set));
  if (!set) {
    PetscCall(TaoGetLineSearch(sub, &ls));
    PetscCall(TaoLineSearchSetType(ls, TAOLINESEARCHARMIJO));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSetFromOptions - Reads the calibration's options (docs/calibrate.md has the table) and those
  of its pattern (-pattern_*), yarn model (-yarn_*, the initial values), reference state (-reference_*),
  solver (HylcMicroSetFromOptions() of HylcCalibrateGetMicro(): -micro_*, with its tile's -periodic_*,
  -macro_* and its SNES's and factorization's -micro_snes_*, -micro_factor_*) and plan ranges
  (-sampler_family, -sampler_range_*). It only reads options and checks names and values, also with
  -help: the pattern is loaded or generated, the initial values resolved and checked against the bounds,
  and the solver set up by HylcCalibrateSetUp().

  Collective

  Input Parameter:
. C - the calibration

  Options Database Keys:
+ -calibrate_target <file>          - material table (.json, model .h5), samples .h5, raw data.txt (or its directory), or .csv (HylcCalibrateSetTarget())
. -calibrate_target_type <auto>     - auto, table, samples, raw, csv (HylcCalibrateSetTargetType())
. -calibrate_output <p.yaml>        - calibrated values as a YAML options file (HylcCalibrateSetOutputs())
. -calibrate_dump <d.csv>           - per sample: strain, target, initial and calibrated Psi (HylcCalibrateSetOutputs())
. -calibrate_params <E,Es,kc>       - the free parameters (E, Es, G, kc) (HylcCalibrateSetRoles())
. -calibrate_tie <G>                - parameters that follow E at their initial ratio when not free (not E) (HylcCalibrateSetRoles())
. -calibrate_bounds_<p> lo,hi       - bounds (default initial / 1000, initial x 1000) (HylcCalibrateSetBounds())
. -calibrate_terms <zero,sx,sa,sy,II00,II11> - terms of the plan for a table target (2D terms allowed) (HylcCalibrateSetTerms())
. -calibrate_n <15>, -calibrate_n2 <5> - samples per 1D term, per axis of a 2D term (table target) (HylcCalibrateSetSampleCounts())
. -sampler_family, -sampler_range_<c> - the plan's ranges (table target), as hylc-sample (HylcCalibrateSetPlanRanges())
. -calibrate_stride <1>, -calibrate_max_samples <0> - thinning of a file target (HylcCalibrateSetThinning())
. -calibrate_weight_zero <1>, -calibrate_weights <t=w,...> - weights of Psi(z_b) and of the terms (HylcCalibrateSetTermWeight())
. -calibrate_stationary <0>        - weight of the stationarity at the base strain, (dPsi/ds_k / S_k)^2 for k = x, y (HylcCalibrateSetStationary())
. -calibrate_stationary_jacobian <fd>, -calibrate_stationary_h <1e-2> - its Jacobian: central differences over re-solves (fd) or the fixed-state parts (gn) (HylcCalibrateSetStationary())
. -calibrate_start <auto>          - auto (as the target was made), continue (each 1D term's half-line from zero outward) or cold (HylcCalibrateSetStart())
. -calibrate_max_it <30>            - iterations of the optimizer (TAO's maximum; HylcCalibrateSetMaxIterations())
. -calibrate_lambda <1e-3>          - Levenberg-Marquardt damping of TAOBRGN (HylcCalibrateSetDamping())
. -calibrate_tao_*                  - the optimizer's options (HylcCalibrateGetTao(): TAOBRGN, -calibrate_tao_brgn_regularization_type lm by default)
. -calibrate_xtol <1e-6>, -calibrate_ftol <1e-10>, -calibrate_fatol <1e-20>, -calibrate_flat_tol <1e-4> - stopping tests, flat directions (HylcCalibrateSetTolerances())
. -calibrate_reference <auto>, -reference_output <f.pyp> - reference state: auto (compute for a generated pattern), compute, none (HylcCalibrateSetReference())
- -calibrate_view                   - print the set-up at the end of HylcCalibrateSetUp() (HylcCalibrateView())

  Level: beginner

.seealso: HylcCalibrateSetUp(), HylcCalibrateGetPattern(), HylcCalibrateGetMicro()
@*/
PetscErrorCode HylcCalibrateSetFromOptions(HylcCalibrate C)
{
  MPI_Comm       comm        = PetscObjectComm((PetscObject)C);
  char           params[256] = "", tie[256] = "G", terms[512] = "", weights[1024] = "", target[PETSC_MAX_PATH_LEN], output[PETSC_MAX_PATH_LEN], dump[PETSC_MAX_PATH_LEN], refout[PETSC_MAX_PATH_LEN];
  PetscBool      set, pset, tset, ttset;
  PetscEnum      sjac = C->statFD ? 1 : 0, tt = (PetscEnum)C->targetType, rm = (PetscEnum)C->refmode, start = (PetscEnum)C->start;
  PetscInt       n1 = C->n1, n2 = C->n2, stride = C->stride, maxSamples = C->maxSamples, maxIt = C->maxIt;
  PetscReal      wzero = C->wzero, wstat = C->wstat, statH = C->statH, lambda = C->lambda, xtol = C->xtol, ftol = C->ftol, fatol = C->fatol, flatTol = C->flatTol;
  HylcPlanRanges ranges = C->ranges;
  HylcPattern    pat;
  HylcMicro      micro;
  HylcYarnModel  model = C->model;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  C->solverSetUp = PETSC_FALSE;
  if (C->refComputed) { /* the pattern was replaced by its reference state: read and build it anew */
    PetscCall(HylcPatternDestroy(&C->pat));
    C->refComputed = PETSC_FALSE;
  }
  PetscCall(PetscStrncpy(target, C->target, sizeof(target)));
  PetscCall(PetscStrncpy(output, C->output, sizeof(output)));
  PetscCall(PetscStrncpy(dump, C->dump, sizeof(dump)));
  PetscCall(PetscStrncpy(refout, C->refout, sizeof(refout)));
  /* the tile, the initial yarn model, the reference state's and the solver's options */
  PetscCall(HylcCalibrateGetPattern(C, &pat));
  PetscCall(HylcPatternSetFromOptions(pat));
  PetscCall(HylcYarnModelSetFromOptions(comm, ((PetscObject)C)->prefix, &model));
  PetscCall(HylcCalibrateSetYarnModel(C, &model));
  PetscCall(HylcReferenceParamsSetFromOptions(comm, ((PetscObject)C)->prefix, &C->refpar));
  PetscCall(HylcCalibrateGetMicro(C, &micro));
  PetscCall(HylcMicroSetFromOptions(micro));

  /* the plan's ranges under the sampler's names, so that -options_file config/<p>.yaml applies */
  PetscOptionsBegin(comm, ((PetscObject)C)->prefix, "Calibration: the plan's ranges (table target; the sampler's options)", "HylcCalibrate");
  PetscCall(HylcPlanRangesFromOptions(PetscOptionsObject, comm, "HylcCalibrateSetPlanRanges", &ranges));
  PetscCall(HylcOptionsString("-reference_output", "Write the reference state as .pyp", "HylcCalibrateSetReference", refout, refout, sizeof(refout), NULL));
  PetscOptionsEnd();

  /* the hand-written Levenberg-Marquardt's rejection limit has no counterpart in TAO (issue 33) */
  PetscCall(PetscOptionsHasName(NULL, ((PetscObject)C)->prefix, "-calibrate_max_reject", &set));
  PetscCheck(!set, comm, PETSC_ERR_USER_INPUT, "-calibrate_max_reject no longer applies: the calibration's optimizer is TAO (docs/calibrate.md); limit its evaluations with -calibrate_tao_max_funcs");

  PetscObjectOptionsBegin((PetscObject)C);
  PetscCall(HylcOptionsString("-calibrate_target", "Target: a material table (.json or model .h5), a samples .h5 of hylc-sample, the paper's raw data.txt (or its directory), or a .csv with a header naming sx,sa,sy,II00,II01,II11,psi",
                              "HylcCalibrateSetTarget", target, target, sizeof(target), NULL));
  PetscCall(HylcOptionsEnum("-calibrate_target_type", "Kind of target: auto (by extension and content), table, samples, raw, csv", "HylcCalibrateSetTargetType", HylcCalibTargetTypes, tt, &tt, &ttset));
  PetscCall(HylcOptionsString("-calibrate_output", "Write the calibrated values as a YAML options file (yarn_E, yarn_Es, yarn_G, yarn_kc; a drop-in for config/)", "HylcCalibrateSetOutputs", output, output, sizeof(output), NULL));
  PetscCall(HylcOptionsString("-calibrate_dump", "Write per sample the strain, term, target, initial and calibrated Psi as CSV (examples/plot_calibrate.py)", "HylcCalibrateSetOutputs", dump, dump, sizeof(dump), NULL));
  PetscCall(HylcOptionsString("-calibrate_params", "Free parameters, a comma list of E, Es, G, kc", "HylcCalibrateSetRoles", params, params, sizeof(params), &pset));
  PetscCall(HylcOptionsString("-calibrate_tie", "Parameters that follow E at their initial ratio when not free (Es, G, kc; 'none' for none); the others not free are fixed", "HylcCalibrateSetRoles", tie, tie, sizeof(tie), &tset));
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) {
    char      opt[64], help[160];
    PetscReal v[2] = {C->blo[j], C->bhi[j]};
    PetscInt  n    = 2;
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-calibrate_bounds_%s", HylcCalibrateParamNames[j]));
    PetscCall(PetscSNPrintf(help, sizeof(help), "Bounds lo,hi of %s (%s; default initial/1000, initial*1000)", HylcCalibrateParamNames[j], j == 3 ? "N/m" : "Pa"));
    PetscCall(HylcOptionsRealArray(opt, help, "HylcCalibrateSetBounds", v, &n, &set));
    if (set) {
      PetscCheck(n == 2, comm, PETSC_ERR_USER_INPUT, "%s needs two values lo,hi", opt);
      snprintf(help, sizeof(help), "%g,%g", (double)v[0], (double)v[1]); /* C formatting for the message */
      PetscCheck(v[0] > 0 && v[1] > 0, comm, PETSC_ERR_USER_INPUT, "%s %s: bounds must be positive (the parameters are optimised in log space)", opt, help);
      PetscCheck(v[0] <= v[1], comm, PETSC_ERR_USER_INPUT, "%s %s: inverted bounds (lo > hi)", opt, help);
      PetscCall(HylcCalibrateSetBounds(C, j, v[0], v[1]));
    }
  }
  PetscCall(HylcOptionsString("-calibrate_terms",
                              "Terms sampled for a table target: a comma list of zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, or all, or 1d (default zero,sx,sa,sy,II00,II11)",
                              "HylcCalibrateSetTerms", terms, terms, sizeof(terms), NULL));
  PetscCall(HylcOptionsInt("-calibrate_n", "Samples per 1D term (table target)", "HylcCalibrateSetSampleCounts", n1, &n1, NULL));
  PetscCall(HylcOptionsInt("-calibrate_n2", "Samples per axis of a 2D term (table target)", "HylcCalibrateSetSampleCounts", n2, &n2, NULL));
  PetscCall(HylcOptionsInt("-calibrate_stride", "File target: keep every stride-th row of each term", "HylcCalibrateSetThinning", stride, &stride, NULL));
  PetscCall(HylcOptionsInt("-calibrate_max_samples", "File target: at most this many rows (thinned evenly within each term; 0: all)", "HylcCalibrateSetThinning", maxSamples, &maxSamples, NULL));
  PetscCall(HylcOptionsReal("-calibrate_weight_zero", "Weight of the relative error of Psi at the base strain (the constant)", "HylcCalibrateSetTermWeight", wzero, &wzero, NULL));
  PetscCall(
      HylcOptionsString("-calibrate_weights", "Weights of terms, a comma list term=weight (e.g. sx=2,sa-sy=0.5; default 1 each; 'other' for file rows off the plan's axes)", "HylcCalibrateSetTermWeight", weights, weights, sizeof(weights), NULL));
  PetscCall(HylcOptionsReal("-calibrate_stationary", "Weight w of the stationarity at the base strain: adds w ((dPsi/dsx / S_x)^2 + (dPsi/dsy / S_y)^2) to the objective, dPsi/ds in N/m, S the target's dPsi/ds at 5 % stretch (0: off; at most 1e8)",
                            "HylcCalibrateSetStationary", wstat, &wstat, NULL));
  PetscCall(HylcOptionsEnum(
      "-calibrate_stationary_jacobian",
      "Jacobian of the stationarity's residuals: fd (central differences in log p, two re-solves of the base sample per parameter not fixed) or gn (the energy terms' parts at the fixed state: no solve, leaves out the equilibrium's change)",
      "HylcCalibrateSetStationary", HylcCalibrateStationaryJacobians, sjac, &sjac, NULL));
  PetscCall(HylcOptionsReal("-calibrate_stationary_h", "Step in log p of the stationarity's central differences (-calibrate_stationary_jacobian fd)", "HylcCalibrateSetStationary", statH, &statH, NULL));
  PetscCall(HylcOptionsEnum("-calibrate_start",
                            "How each evaluation's samples are solved: auto (as the target was made: a samples file's own start; cold for a table, raw data or CSV), continue (each 1D term's half-line from zero outward, as hylc-sample) or cold "
                            "(every sample from the reference state, the paper's procedure)",
                            "HylcCalibrateSetStart", HylcCalibrateStarts, start, &start, NULL));
  PetscCall(HylcOptionsInt("-calibrate_max_it", "Optimizer (TAO): at most this many iterations (-calibrate_tao_max_it overrides it)", "HylcCalibrateSetMaxIterations", maxIt, &maxIt, NULL));
  PetscCall(HylcOptionsReal("-calibrate_lambda", "Optimizer (TAOBRGN): Levenberg-Marquardt damping relative to the diagonal of J^T J (-calibrate_tao_brgn_regularizer_weight overrides it)", "HylcCalibrateSetDamping", lambda, &lambda, NULL));
  PetscCall(HylcOptionsReal("-calibrate_xtol", "Stop when an iteration changes every log parameter by less than this (with TAO's own tests, -calibrate_tao_gatol ...)", "HylcCalibrateSetTolerances", xtol, &xtol, NULL));
  PetscCall(HylcOptionsReal("-calibrate_ftol", "Stop when an iteration decreases the objective by less than this fraction", "HylcCalibrateSetTolerances", ftol, &ftol, NULL));
  PetscCall(HylcOptionsReal("-calibrate_fatol", "Stop when the objective is below this", "HylcCalibrateSetTolerances", fatol, &fatol, NULL));
  PetscCall(HylcOptionsReal("-calibrate_flat_tol", "A direction of the log parameters along which the normalised residuals change by less than this per unit (a singular value of the Jacobian) is flat: its parameter is held and reported",
                            "HylcCalibrateSetTolerances", flatTol, &flatTol, NULL));
  PetscCall(HylcOptionsEnum("-calibrate_reference",
                            "Reference state: auto (computed once with the initial parameters: Algorithm C1 for a generated pattern, relax for a stored reference state, as hylc-sample), compute, relax (only the in-plane minimum over the periods of "
                            "the pattern as given) or none (the pattern as given: the paper's tables were made so; config/profile-paper.yaml)",
                            "HylcCalibrateSetReference", HylcReferenceModes, rm, &rm, NULL));
  PetscCall(PetscOptionsName("-calibrate_view", "Print the set-up at the end of HylcCalibrateSetUp()", "HylcCalibrateView", NULL));
  PetscOptionsEnd();
  PetscCall(HylcCalibrateSetPlanRanges(C, &ranges));
  PetscCall(HylcCalibrateSetTarget(C, target));
  if (ttset) PetscCall(HylcCalibrateSetTargetType(C, HylcCalibTargetTypes[tt]));
  PetscCall(HylcCalibrateSetOutputs(C, output, dump));
  PetscCall(HylcCalibrateSetReference(C, (HylcReferenceMode)rm, refout));

  /* parameters: free, tied, fixed */
  {
    PetscBool         fr[HYLC_CALIBRATE_NPARAM], ti[HYLC_CALIBRATE_NPARAM] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};
    HylcCalibrateRole role[HYLC_CALIBRATE_NPARAM];
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
    for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) role[j] = fr[j] ? HYLC_CALIBRATE_FREE : (ti[j] ? HYLC_CALIBRATE_TIED : HYLC_CALIBRATE_FIXED);
    PetscCall(HylcCalibrateSetRoles(C, role));
  }
  /* terms */
  if (terms[0]) {
    int mask;
    PetscCall(HylcPlanTermsFromString(comm, "-calibrate_terms", terms, &mask));
    PetscCall(HylcCalibrateSetTerms(C, (PetscInt)mask));
  }
  PetscCall(HylcCalibrateSetSampleCounts(C, n1, n2));
  PetscCall(HylcCalibrateSetThinning(C, stride, maxSamples));
  PetscCall(HylcCalibrateSetTermWeight(C, "zero", wzero));
  PetscCall(HylcCalibrateSetStationary(C, wstat, (PetscBool)(sjac == 1), statH));
  if (weights[0]) {
    char *tok, *save = NULL;
    for (tok = strtok_r(weights, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
      char  *eq = strchr(tok, '='), *end = NULL;
      double v;
      PetscCheck(eq, comm, PETSC_ERR_USER_INPUT, "-calibrate_weights: '%s' is not term=weight", tok);
      *eq = 0;
      v   = strtod(eq + 1, &end);
      PetscCheck(end != eq + 1 && !*end && v >= 0 && !PetscIsInfOrNanReal(v), comm, PETSC_ERR_USER_INPUT, "-calibrate_weights: the weight of %s must be a finite number >= 0, got '%s'", tok, eq + 1);
      PetscCheck(strcmp(tok, "zero"), comm, PETSC_ERR_USER_INPUT, "-calibrate_weights: unknown term '%s' (use sx, sa, sy, II00, II11, a 2D term such as sx-sa, or other; the constant's is -calibrate_weight_zero)", tok);
      PetscCall(HylcCalibrateSetTermWeight(C, tok, v));
    }
  }
  PetscCall(HylcCalibrateSetMaxIterations(C, maxIt));
  PetscCall(HylcCalibrateSetDamping(C, lambda));
  PetscCall(HylcCalibrateSetTolerances(C, xtol, ftol, fatol, flatTol));
  PetscCall(HylcCalibrateTaoSetFromOptions_Private(C));
  PetscCall(HylcCalibrateSetStart(C, (HylcCalibrateStart)start));
  PetscCall(HylcCalibrateResetSamples_Private(C));
  PetscFunctionReturn(PETSC_SUCCESS);
}
