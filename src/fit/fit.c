/* HylcFit: lifecycle, options, viewer and results of the fitting pipeline (include/hylc/fit.h). */
#include <hylc/options.h>
#include <hylc/private/fitimpl.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

const char *const HylcFitFamilies[] = {"woven", "knit", "stockinette", "HylcFitFamily", "HYLC_FIT_FAMILY_", NULL};

/* -fit_family speaks -sampler_family's names (src/sampler/planopts.c); "knit", the fit's former name of
   every knit but the stockinette, is accepted */
static const struct {
  const char   *name;
  HylcFitFamily family;
} FamilyNames[] = {{"woven", HYLC_FIT_FAMILY_WOVEN}, {"stockinette", HYLC_FIT_FAMILY_STOCKINETTE}, {"honeycomb", HYLC_FIT_FAMILY_KNIT}, {"rib", HYLC_FIT_FAMILY_KNIT}, {"knit", HYLC_FIT_FAMILY_KNIT}};

static PetscBool FamilyByName(const char name[], HylcFitFamily *family)
{
  for (size_t i = 0; i < sizeof(FamilyNames) / sizeof(FamilyNames[0]); i++)
    if (!strcasecmp(name, FamilyNames[i].name)) {
      *family = FamilyNames[i].family;
      return PETSC_TRUE;
    }
  return PETSC_FALSE;
}

/* the family's constants (docs/method.md §9, §S3.4): everything but the stockinette shares one set; the
   family is the object's type name */
static PetscErrorCode FamilyDefaults(HylcFit fit, HylcFitFamily family)
{
  const PetscBool stock = family == HYLC_FIT_FAMILY_STOCKINETTE;

  PetscFunctionBegin;
  fit->family          = family;
  fit->reg             = stock ? 1e-2 : 1e-3;
  fit->factor2bend     = stock ? 0.3 : 0.9;
  fit->kBendStretch[0] = 2;
  fit->kBendStretch[1] = stock ? 4 : 7;
  fit->kBendSym[0]     = stock ? 3 : 5;
  fit->kBendSym[1]     = stock ? 3 : 5;
  PetscCall(PetscObjectChangeTypeName((PetscObject)fit, HylcFitFamilies[family]));
  PetscCall(PetscStrncpy(fit->familyName, HylcFitFamilies[family], sizeof(fit->familyName)));
  PetscCall(PetscStrncpy(fit->familySource, "HylcFitSetFamily()", sizeof(fit->familySource)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const HylcFitKnotLayouts[] = {"paper", "refined", "HylcFitKnotLayout", "HYLC_FIT_KNOTS_", NULL};
const char *const HylcFitMethods[]     = {"auto", "paper", "fabric", "HylcFitMethod", "HYLC_FIT_METHOD_", NULL};

PetscClassId  HYLC_FIT_CLASSID;
PetscLogEvent HYLC_FitRun, HYLC_FitTerm, HYLC_FitMLS, HYLC_FitMonotone;

static PetscBool HylcFitPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcFitFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcFitPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitInitializePackage - Registers the class id HylcFit and its log events (FIT_Run, FIT_Term, FIT_MLS, FIT_Monotone). Called by
  HylcFitCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcFitInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcFitPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcFitPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcFit", &HYLC_FIT_CLASSID));
  PetscCall(PetscLogEventRegister("FIT_Run", HYLC_FIT_CLASSID, &HYLC_FitRun));
  PetscCall(PetscLogEventRegister("FIT_Term", HYLC_FIT_CLASSID, &HYLC_FitTerm));
  PetscCall(PetscLogEventRegister("FIT_MLS", HYLC_FIT_CLASSID, &HYLC_FitMLS));
  PetscCall(PetscLogEventRegister("FIT_Monotone", HYLC_FIT_CLASSID, &HYLC_FitMonotone));
  PetscCall(PetscRegisterFinalize(HylcFitFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitCreate - Creates a fit with the constants of docs/method.md §9.1 (family woven). Not collective.
@*/
PetscErrorCode HylcFitCreate(MPI_Comm comm, HylcFit *out)
{
  HylcFit fit;

  PetscFunctionBegin;
  PetscValidPointer(out, 2);
  PetscCall(HylcFitInitializePackage());
  PetscCall(PetscHeaderCreate(fit, HYLC_FIT_CLASSID, "HylcFit", "Material fit", "Fit", comm, HylcFitDestroy, HylcFitView));
  fit->compat          = HYLC_FIT_COMPAT_PAPER;
  fit->method          = HYLC_FIT_METHOD_AUTO;
  fit->methodUsed      = HYLC_FIT_METHOD_AUTO;
  fit->fabricFloor     = 1e-4;
  fit->fabricRidge     = 1e-10;
  fit->fabricReg       = 1e-6;
  fit->fabricPasses    = 3;
  fit->rule            = HYLC_MONOTONE_CIRCLE;
  fit->quasiconvex     = PETSC_TRUE;
  fit->symmetrize      = PETSC_TRUE;
  fit->zeroCompression = PETSC_TRUE;
  fit->zeroStrict      = PETSC_FALSE;
  fit->kernel          = 0.15;
  fit->truncation      = 3;
  fit->mlsGrow         = 1.5;
  fit->fdEps           = 0.1;
  fit->flatTol         = 1e-8;
  fit->endSlope        = 1e-8;
  fit->nk1             = 11;
  fit->knots           = HYLC_FIT_KNOTS_REFINED;
  fit->refine          = 3;
  fit->kernelSpacing   = 1.6;
  fit->kernelMin       = 6;
  fit->factor1         = 0.95;
  fit->factor2         = 0.9;
  fit->kStretch[0]     = 2;
  fit->kStretch[1]     = 7;
  fit->kPoisson[0]     = 4;
  fit->kPoisson[1]     = 7;
  fit->kSym[0]         = 5;
  fit->kSym[1]         = 5;
  fit->density         = 0;
  fit->yarnDensity     = 0;
  fit->min1            = 10;
  fit->min2            = 25;
  fit->terms           = HYLC_PLAN_ALL_TERMS - 1; /* every term but the zero sample */
  fit->rhoA            = -1;
  PetscCall(FamilyDefaults(fit, HYLC_FIT_FAMILY_WOVEN));
  fit->familySource[0] = 0; /* the default */
  *out                 = fit;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcFitResetResults_Private(HylcFit fit)
{
  PetscFunctionBegin;
  for (int k = 0; k < 5; k++) {
    PetscCall(PetscFree3(fit->s1[k].t, fit->s1[k].p, fit->s1[k].m));
    PetscCall(PetscMemzero(&fit->s1[k], sizeof(fit->s1[k])));
  }
  for (int k = 0; k < 9; k++) {
    PetscCall(PetscFree6(fit->s2[k].tu, fit->s2[k].tv, fit->s2[k].p, fit->s2[k].mu, fit->s2[k].mv, fit->s2[k].muv));
    PetscCall(PetscMemzero(&fit->s2[k], sizeof(fit->s2[k])));
  }
  for (int r = 0; r < HYLC_NTRIPLE; r++) {
    PetscCall(PetscFree(fit->a3[r]));
    PetscCall(PetscMemzero(&fit->s3[r], sizeof(fit->s3[r])));
    fit->missing3[r] = 0;
  }
  for (int t = 0; t < HYLC_PLAN_NTERM3; t++)
    for (int a = 0; a < 3; a++) {
      PetscCall(PetscFree(fit->knot[t][a]));
      fit->nknot[t][a] = 0;
    }
  for (int t = 0; t < HYLC_PLAN_NTERM3; t++) {
    fit->has[t]   = PETSC_FALSE;
    fit->statN[t] = 0;
  }
  fit->computed = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ResetData(HylcFit fit)
{
  PetscFunctionBegin;
  PetscCall(PetscFree4(fit->z, fit->psi, fit->term, fit->row));
  PetscCall(PetscFree(fit->stress));
  fit->samplesFile = PETSC_FALSE;
  fit->n = fit->nrows = fit->nskipped = 0;
  for (int i = 0; i < 6; i++) fit->zabsmax[i] = 0;
  fit->dataset     = PETSC_FALSE;
  fit->setupcalled = PETSC_FALSE;
  PetscCall(HylcFitResetResults_Private(fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitDestroy - Drops a reference to the fit and frees it with its data and results at the last; accepts
  NULL and sets the handle to NULL.

  Collective

  Input Parameter:
. fit - the fit

  Level: beginner

.seealso: HylcFitCreate()
@*/
PetscErrorCode HylcFitDestroy(HylcFit *fit)
{
  PetscFunctionBegin;
  if (!*fit) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*fit, HYLC_FIT_CLASSID, 1);
  if (--((PetscObject)(*fit))->refct > 0) {
    *fit = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(ResetData(*fit));
  PetscCall(PetscHeaderDestroy(fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetOptionsPrefix - Sets the prefix of the fit's options (-<prefix>fit_*).

  Not collective

  Input Parameters:
+ fit    - the fit
- prefix - the prefix (NULL: none)

  Level: intermediate

.seealso: HylcFitSetFromOptions()
@*/
PetscErrorCode HylcFitSetOptionsPrefix(HylcFit fit, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)fit, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetInput - Sets the samples to fit: an HDF5 samples file of hylc-sample, the paper's raw data.txt
  or a directory holding data.txt (and info.txt); read by HylcFitSetUp(). Drops data set before.

  Not collective

  Input Parameters:
+ fit  - the fit
- path - the file or directory (NULL or "" for none)

  Options Database Key:
. -fit_input <path> - the same

  Level: beginner

.seealso: HylcFitGetInput(), HylcFitSetData(), HylcFitSetUp()
@*/
PetscErrorCode HylcFitSetInput(HylcFit fit, const char path[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCall(ResetData(fit));
  PetscCall(PetscStrncpy(fit->input, path ? path : "", sizeof(fit->input)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetOutputs - Sets the files HylcFitRun() writes.

  Not collective

  Input Parameters:
+ fit  - the fit
. h5   - the HDF5 material file (NULL or "" for none)
- json - the ARCSim-HYLC JSON material file (NULL or "" for none)

  Options Database Keys:
+ -fit_output <file.h5> - h5
- -fit_json <file.json> - json

  Level: beginner

.seealso: HylcFitGetOutputs(), HylcFitRun()
@*/
PetscErrorCode HylcFitSetOutputs(HylcFit fit, const char h5[], const char json[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCall(PetscStrncpy(fit->output, h5 ? h5 : "", sizeof(fit->output)));
  PetscCall(PetscStrncpy(fit->json, json ? json : "", sizeof(fit->json)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetInput - The input file of the fit (HylcFitSetInput() or -fit_input; "" if none, or if the data
  were set with HylcFitSetData()).

  Not collective

  Input Parameter:
. fit - the fit

  Output Parameter:
. path - the path (owned by the fit)

  Level: intermediate

.seealso: HylcFitSetInput(), HylcFitGetOutputs()
@*/
PetscErrorCode HylcFitGetInput(HylcFit fit, const char *path[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscValidPointer(path, 2);
  *path = fit->input;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetOutputs - The files HylcFitRun() writes (HylcFitSetOutputs(), -fit_output and -fit_json; "" for
  none).

  Not collective

  Input Parameter:
. fit - the fit

  Output Parameters:
+ h5   - the HDF5 material file (may be NULL; owned by the fit)
- json - the ARCSim-HYLC JSON file (may be NULL; owned by the fit)

  Level: intermediate

.seealso: HylcFitSetOutputs(), HylcFitGetInput()
@*/
PetscErrorCode HylcFitGetOutputs(HylcFit fit, const char *h5[], const char *json[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  if (h5) *h5 = fit->output;
  if (json) *json = fit->json;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetFamily - Sets the pattern family and with it the family's defaults of -fit_reg and of the 2D
  bending knots (call before HylcFitSetFromOptions() to let options override them); drops results.

  Not collective

  Input Parameters:
+ fit    - the fit
- family - HYLC_FIT_FAMILY_WOVEN, HYLC_FIT_FAMILY_KNIT or HYLC_FIT_FAMILY_STOCKINETTE

  Options Database Key:
. -fit_family <woven> - woven, knit or stockinette

  Level: intermediate

.seealso: HylcFitSetFromOptions()
@*/
PetscErrorCode HylcFitSetFamily(HylcFit fit, HylcFitFamily family)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCall(FamilyDefaults(fit, family));
  PetscCall(HylcFitResetResults_Private(fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "-fit_<name> left,right": knot counts left and right of 0 (both including 0) */
static PetscErrorCode KnotPairOption(PetscOptionItems *PetscOptionsObject, HylcFit fit, const char name[], const char help[], PetscInt k[2])
{
  PetscInt  v[2] = {k[0], k[1]}, n = 2;
  PetscBool set;

  PetscFunctionBegin;
  PetscCall(HylcOptionsIntArray(name, help, "HylcFitSetFromOptions", v, &n, &set));
  if (set) {
    PetscCheck(n == 2 && v[0] >= 1 && v[1] >= 1 && v[0] + v[1] >= 3, PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT, "%s needs two knot counts left,right (each >= 1, counting the 0 knot on both sides, at least 2 knots in all)", name);
    k[0] = v[0];
    k[1] = v[1];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetFromOptions - Reads the fit's options (docs/fit.md has the full table). Not collective.

  Options:
+ -fit_input <file|dir>            - samples HDF5 file, raw data.txt, or a directory with data.txt, info.txt
. -fit_output <model.h5>           - HDF5 material file written by HylcFitRun
. -fit_json <model.json>           - ARCSim-HYLC JSON written by HylcFitRun
. -fit_family <woven>              - woven, stockinette, honeycomb or rib (-sampler_family's names; knit, the
                                     former name of honeycomb and rib, is accepted); default the family of the
                                     samples file's provenance; stockinette sets the next two groups
. -fit_reg <1e-3>                  - quasiconvex marching p^x_min (stockinette 1e-2)
. -fit_knots2d_bend_factor, -fit_knots2d_bend_stretch, -fit_knots2d_bend_symmetric - 2D bending-pair knots
. -fit_compat <paper>              - paper or authors (the two departures of docs/method.md §9.1)
. -fit_mls_kernel <0.15>, -fit_mls_truncation <3> - MLS kernel (fraction of span), kernel / sigma
. -fit_mls_grow <1.5>             - kernel growth where the MLS is singular (<= 1: error)
. -fit_fd_eps <0.1>                - FD width (points at +-half of it) as a fraction of the smallest knot spacing
. -fit_knots1d <11>, -fit_knots1d_factor <0.95> - 1D knots
. -fit_knots2d_factor <0.9>, -fit_knots2d_stretch <2,7>, -fit_knots2d_poisson <4,7>, -fit_knots2d_symmetric <5,5>
. -fit_monotone_rule <circle>, -fit_flat_tol <1e-8>, -fit_end_slope <1e-8>
. -fit_quasiconvex, -fit_symmetrize_sa, -fit_zero_compression, -fit_zero_compression_strict
. -fit_density <0>, -fit_yarn_density <0> - area density (kg/m^2) or yarn density (kg/m^3)
. -fit_raw_n1 <0>, -fit_raw_n2 <0> - block sizes of a raw data.txt (0: inferred)
. -fit_min_samples_1d <10>, -fit_min_samples_2d <25> - fewer samples in a term is an error
- -fit_terms <all>                 - the terms to fit
@*/
PetscErrorCode HylcFitSetFromOptions(HylcFit fit)
{
  PetscEnum     compat = (PetscEnum)fit->compat, rule = (PetscEnum)fit->rule;
  PetscBool     set, fromFile = PETSC_FALSE, known = PETSC_TRUE;
  char          terms[512] = "all", input[PETSC_MAX_PATH_LEN], family[32], recorded[32] = "";
  HylcFitFamily fam  = fit->family;
  MPI_Comm      comm = PetscObjectComm((PetscObject)fit);

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCall(PetscStrncpy(input, fit->input, sizeof(input)));
  PetscObjectOptionsBegin((PetscObject)fit);
  PetscCall(HylcOptionsString("-fit_input", "Samples: HDF5 file of hylc-sample (status 0 rows), the paper's raw data.txt, or a directory with data.txt and info.txt", "HylcFitSetInput", input, input, sizeof(input), NULL));
  PetscCall(HylcOptionsString("-fit_output", "HDF5 material file to write (docs/material.md)", "HylcFitSetOutputs", fit->output, fit->output, sizeof(fit->output), NULL));
  PetscCall(HylcOptionsString("-fit_json", "ARCSim-HYLC JSON material file to write", "HylcFitSetOutputs", fit->json, fit->json, sizeof(fit->json), NULL));
  /* the family: given, else the one the samples were computed for (their provenance) */
  if (input[0]) PetscCall(HylcFitInputFamily_Private(input, recorded, sizeof(recorded), &fromFile));
  PetscCall(PetscStrncpy(family, fromFile ? recorded : fit->familyName, sizeof(family)));
  PetscCall(HylcOptionsString("-fit_family",
                              "Pattern family, as -sampler_family: woven, stockinette, honeycomb or rib (knit: the former name of honeycomb and rib); default the samples file's (its provenance), else woven. All but the stockinette share the "
                              "constants; stockinette: -fit_reg 1e-2 and coarse 2D bending knots (factor 0.3, 2+4 and 3+3)",
                              "HylcFitSetFamily", family, family, sizeof(family), &set));
  if (set || fromFile) {
    known = FamilyByName(family, &fam);
    if (known) {
      PetscCall(FamilyDefaults(fit, fam)); /* before the options it sets defaults for */
      PetscCall(PetscStrncpy(fit->familyName, family, sizeof(fit->familyName)));
      PetscCall(PetscObjectChangeTypeName((PetscObject)fit, family));
      if (set && fromFile && strcasecmp(family, recorded))
        PetscCall(PetscSNPrintf(fit->familySource, sizeof(fit->familySource), "-fit_family; the samples were computed with -sampler_family %s", recorded));
      else if (set)
        PetscCall(PetscStrncpy(fit->familySource, "-fit_family", sizeof(fit->familySource)));
      else
        PetscCall(PetscSNPrintf(fit->familySource, sizeof(fit->familySource), "the samples' provenance: -sampler_family %s", recorded));
    }
  }
  PetscCall(HylcOptionsReal("-fit_reg", "Quasiconvex marching: minimum outward slope p^x_min in J/m^2 per normalised unit (S28)", "HylcFitSetFromOptions", fit->reg, &fit->reg, NULL));
  PetscCall(PetscOptionsBool("-fit_quasiconvex", "Apply the quasiconvex marching (false: the unregularized fits, like rib1_noreg)", "HylcFitSetFromOptions", fit->quasiconvex, &fit->quasiconvex, NULL));
  PetscCall(
      HylcOptionsEnum("-fit_compat", "paper, or authors: the authors' code's two departures (S42 x-clamp dropped; mv <= -reg on the minimum's row); authors implies -fit_method paper", "HylcFitSetFromOptions", HylcFitCompats, compat, &compat, NULL));
  {
    PetscEnum method = (PetscEnum)fit->method;
    PetscCall(HylcOptionsEnum(
        "-fit_method",
        "auto (fabric when every sample has its stress and the plan was graded, else paper), fabric (the samples' values and stresses by weighted least squares on the plan's graded knots) or paper (the MLS of the values on the paper's knots)",
        "HylcFitSetMethod", HylcFitMethods, method, &method, NULL));
    fit->method = (HylcFitMethod)method;
  }
  PetscCall(HylcOptionsReal("-fit_fabric_floor", "fabric method: each equation's error is relative to the tile's own value or stress there, with a floor of this fraction of the term's largest (1)", "HylcFitSetFromOptions", fit->fabricFloor,
                            &fit->fabricFloor, NULL));
  PetscCall(HylcOptionsReal("-fit_fabric_ridge", "fabric method: ridge added to the scaled normal equations (1)", "HylcFitSetFromOptions", fit->fabricRidge, &fit->fabricRidge, NULL));
  PetscCall(HylcOptionsInt("-fit_fabric_passes", "fabric method: fits of each 2D term, the mixed slopes muv taken from the fitted slopes' differences between them (the first with muv = 0)", "HylcFitSetFromOptions", fit->fabricPasses,
                           &fit->fabricPasses, NULL));
  PetscCall(HylcOptionsReal("-fit_fabric_reg", "fabric method: the 1D terms' smallest outward slope, a fraction of the term's largest |Psi - f0| per normalised unit (1)", "HylcFitSetFromOptions", fit->fabricReg, &fit->fabricReg, NULL));
  PetscCall(HylcOptionsEnum("-fit_monotone_rule", "1D slope limiter: circle (alpha^2 + beta^2 <= 9, the authors') or box (0 <= alpha, beta <= 3)", "HylcFitSetFromOptions", HylcMonotoneRules, rule, &rule, NULL));
  PetscCall(HylcOptionsReal("-fit_flat_tol", "1D monotone cubic: an interval with |dp| below this gets zero slopes", "HylcFitSetFromOptions", fit->flatTol, &fit->flatTol, NULL));
  PetscCall(HylcOptionsReal("-fit_end_slope", "Boundary slopes at least this outward (increasing linear extrapolation)", "HylcFitSetFromOptions", fit->endSlope, &fit->endSlope, NULL));
  PetscCall(HylcOptionsReal("-fit_mls_kernel", "MLS kernel radius as a fraction of the term's data span per axis", "HylcFitSetFromOptions", fit->kernel, &fit->kernel, NULL));
  PetscCall(HylcOptionsReal("-fit_mls_truncation", "MLS kernel radius / Gaussian sigma (weights are zero beyond the radius)", "HylcFitSetFromOptions", fit->truncation, &fit->truncation, NULL));
  PetscCall(HylcOptionsReal("-fit_mls_grow", "Where the MLS has too few samples in its kernel (singular), enlarge the kernel by this factor until it has (with a warning); <= 1: error", "HylcFitSetFromOptions", fit->mlsGrow, &fit->mlsGrow, NULL));
  PetscCall(PetscOptionsBool("-fit_symmetrize_sa", "Symmetrize the MLS in sa: g(u) = (g(u) + g(-u)) / 2 in symlog space", "HylcFitSetFromOptions", fit->symmetrize, &fit->symmetrize, NULL));
  PetscCall(HylcOptionsReal("-fit_fd_eps", "Width of the central differences for the Hermite slopes (points at +-half of it), as a fraction of the smallest knot spacing", "HylcFitSetFromOptions", fit->fdEps, &fit->fdEps, NULL));
  {
    PetscEnum layout = (PetscEnum)fit->knots;
    PetscCall(HylcOptionsEnum(
        "-fit_knots", "1D knot layout: refined (the paper's, with -fit_knots_refine more knots towards 0 whose MLS kernels follow the knot spacing: resolves small strains) or paper (the authors' uniform layout; implied by -fit_compat authors)",
        "HylcFitSetFromOptions", HylcFitKnotLayouts, layout, &layout, &fit->knotsSet));
    fit->knots = (HylcFitKnotLayout)layout;
  }
  PetscCall(HylcOptionsInt("-fit_knots_refine", "Refined knots: knots added at h/2, h/4, ... of the first interval on each side of 0", "HylcFitSetFromOptions", fit->refine, &fit->refine, NULL));
  PetscCall(HylcOptionsReal("-fit_knots_kernel_spacing", "Refined knots: MLS kernel radius of an added knot as a multiple of its distance from 0 (at most -fit_mls_kernel of the span)", "HylcFitSetFromOptions", fit->kernelSpacing, &fit->kernelSpacing,
                            NULL));
  PetscCall(HylcOptionsInt("-fit_knots_kernel_samples", "Refined knots: the MLS kernel of an added knot is widened until it holds this many samples", "HylcFitSetFromOptions", fit->kernelMin, &fit->kernelMin, NULL));
  PetscCall(HylcOptionsInt("-fit_knots1d", "Knots of a 1D term in the paper's layout (refined: before the refinement)", "HylcFitSetFromOptions", fit->nk1, &fit->nk1, NULL));
  PetscCall(HylcOptionsReal("-fit_knots1d_factor", "1D knots span factor x [min, max] of the data (then shifted so that 0 is a knot)", "HylcFitSetFromOptions", fit->factor1, &fit->factor1, NULL));
  PetscCall(HylcOptionsReal("-fit_knots2d_factor", "2D knots span factor x [min, 0] and [0, max] of the data", "HylcFitSetFromOptions", fit->factor2, &fit->factor2, NULL));
  PetscCall(KnotPairOption(PetscOptionsObject, fit, "-fit_knots2d_stretch", "2D knots of an sx or sy axis left,right of 0 (0 counted in both)", fit->kStretch));
  PetscCall(KnotPairOption(PetscOptionsObject, fit, "-fit_knots2d_poisson", "2D knots of each axis of (sx, sy) left,right of 0", fit->kPoisson));
  PetscCall(KnotPairOption(PetscOptionsObject, fit, "-fit_knots2d_symmetric", "2D knots of an sa or bending axis left,right of 0", fit->kSym));
  PetscCall(HylcOptionsReal("-fit_knots2d_bend_factor", "2D knots span factor of the pairs with a bending axis (stockinette 0.3)", "HylcFitSetFromOptions", fit->factor2bend, &fit->factor2bend, NULL));
  PetscCall(KnotPairOption(PetscOptionsObject, fit, "-fit_knots2d_bend_stretch", "Knots of the sx or sy axis of a bending pair (stockinette 2,4)", fit->kBendStretch));
  PetscCall(KnotPairOption(PetscOptionsObject, fit, "-fit_knots2d_bend_symmetric", "Knots of the sa or bending axis of a bending pair (stockinette 3,3)", fit->kBendSym));
  PetscCall(PetscOptionsBool("-fit_zero_compression", "Zero the 2D residuals where sx or sy < 0 (not (sx, sy))", "HylcFitSetFromOptions", fit->zeroCompression, &fit->zeroCompression, NULL));
  PetscCall(PetscOptionsBool("-fit_zero_compression_strict", "Also zero muv on the axis bordering the compressed nodes, so the residual vanishes on the whole compressed half-plane", "HylcFitSetFromOptions", fit->zeroStrict, &fit->zeroStrict, NULL));
  PetscCall(HylcOptionsReal("-fit_density", "Area density of the material in kg/m^2 (> 0 overrides the input's)", "HylcFitSetFromOptions", fit->density, &fit->density, NULL));
  PetscCall(HylcOptionsReal("-fit_yarn_density", "Yarn density in kg/m^3 for the area density rho pi r^2 L / (px py) of a samples file (<= 0: 0.12 kg/m^2 / r, i.e. 120 kg/m^3 at r = 1 mm, the paper's tables)", "HylcFitSetFromOptions",
                            fit->yarnDensity, &fit->yarnDensity, NULL));
  PetscCall(HylcOptionsInt("-fit_raw_n1", "Raw data.txt: rows per 1D block (0: the leading run of sx-only rows)", "HylcFitSetFromOptions", fit->rawN1, &fit->rawN1, NULL));
  PetscCall(HylcOptionsInt("-fit_raw_n2", "Raw data.txt: grid size per axis of a 2D block (0: from the row count)", "HylcFitSetFromOptions", fit->rawN2, &fit->rawN2, NULL));
  PetscCall(HylcOptionsInt("-fit_min_samples_1d", "A 1D term with fewer samples (but some) is an error", "HylcFitSetFromOptions", fit->min1, &fit->min1, NULL));
  PetscCall(HylcOptionsInt("-fit_min_samples_2d", "A 2D term with fewer samples (but some) is an error", "HylcFitSetFromOptions", fit->min2, &fit->min2, NULL));
  PetscCall(HylcOptionsString("-fit_terms",
                              "Terms to fit: all, or a comma list of sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, sx-sa-sy, sx-sa-II00, sx-sa-II11, sx-sy-II00, sx-sy-II11, sa-sy-II00, "
                              "sa-sy-II11 (the 3D terms with the fabric method only)",
                              "HylcFitSetFromOptions", terms, terms, sizeof(terms), NULL));
  PetscOptionsEnd();
  PetscCheck(known, comm, set ? PETSC_ERR_USER_INPUT : PETSC_ERR_FILE_UNEXPECTED, "%s %s: unknown family (woven, stockinette, honeycomb or rib; knit is the former name of honeycomb and rib)", set ? "-fit_family" : "the samples' -sampler_family",
             family);
  fit->compat = (HylcFitCompat)compat;
  PetscCheck(!(fit->compat == HYLC_FIT_COMPAT_AUTHORS && fit->knotsSet && fit->knots != HYLC_FIT_KNOTS_PAPER), comm, PETSC_ERR_USER_INPUT, "-fit_compat authors reproduces the authors' fits, whose knots are the paper's layout: drop -fit_knots %s",
             HylcFitKnotLayouts[fit->knots]);
  if (fit->compat == HYLC_FIT_COMPAT_AUTHORS) fit->knots = HYLC_FIT_KNOTS_PAPER;
  PetscCheck(fit->refine >= 0 && fit->refine <= 20, comm, PETSC_ERR_USER_INPUT, "-fit_knots_refine %" PetscInt_FMT " must be in 0..20", fit->refine);
  PetscCheck(fit->kernelSpacing > 0 && fit->kernelMin >= 3, comm, PETSC_ERR_USER_INPUT, "-fit_knots_kernel_spacing must be > 0 and -fit_knots_kernel_samples >= 3");
  fit->rule = (HylcMonotoneRule)rule;
  PetscCheck(fit->reg >= 0, comm, PETSC_ERR_USER_INPUT, "-fit_reg %g must be >= 0", (double)fit->reg);
  PetscCheck(fit->fabricFloor > 0 && fit->fabricFloor <= 1, comm, PETSC_ERR_USER_INPUT, "-fit_fabric_floor %g must be in (0, 1]", (double)fit->fabricFloor);
  PetscCheck(fit->fabricRidge >= 0 && fit->fabricRidge < 1, comm, PETSC_ERR_USER_INPUT, "-fit_fabric_ridge %g must be in [0, 1)", (double)fit->fabricRidge);
  PetscCheck(fit->fabricReg >= 0 && fit->fabricReg < 1, comm, PETSC_ERR_USER_INPUT, "-fit_fabric_reg %g must be in [0, 1)", (double)fit->fabricReg);
  PetscCheck(fit->fabricPasses >= 1 && fit->fabricPasses <= 20, comm, PETSC_ERR_USER_INPUT, "-fit_fabric_passes %" PetscInt_FMT " must be in 1..20", fit->fabricPasses);
  PetscCheck(!(fit->compat == HYLC_FIT_COMPAT_AUTHORS && fit->method == HYLC_FIT_METHOD_FABRIC), comm, PETSC_ERR_USER_INPUT, "-fit_compat authors reproduces the authors' fits (the paper's method): drop -fit_method fabric");
  PetscCheck(fit->kernel > 0 && fit->kernel <= 1, comm, PETSC_ERR_USER_INPUT, "-fit_mls_kernel %g must be in (0, 1]", (double)fit->kernel);
  PetscCheck(fit->truncation > 0, comm, PETSC_ERR_USER_INPUT, "-fit_mls_truncation %g must be > 0", (double)fit->truncation);
  PetscCheck(fit->fdEps > 0 && fit->fdEps < 1, comm, PETSC_ERR_USER_INPUT, "-fit_fd_eps %g must be in (0, 1)", (double)fit->fdEps);
  PetscCheck(fit->nk1 >= 2 && fit->nk1 <= 1000, comm, PETSC_ERR_USER_INPUT, "-fit_knots1d %" PetscInt_FMT " must be in 2..1000", fit->nk1);
  PetscCheck(fit->factor1 > 0 && fit->factor2 > 0 && fit->factor2bend > 0, comm, PETSC_ERR_USER_INPUT, "-fit_knots1d_factor, -fit_knots2d_factor and -fit_knots2d_bend_factor must be > 0");
  PetscCheck(fit->flatTol >= 0 && fit->endSlope >= 0, comm, PETSC_ERR_USER_INPUT, "-fit_flat_tol and -fit_end_slope must be >= 0");
  PetscCheck(fit->rawN1 >= 0 && fit->rawN2 >= 0, comm, PETSC_ERR_USER_INPUT, "-fit_raw_n1 and -fit_raw_n2 must be >= 0");
  PetscCheck(fit->min1 >= 3 && fit->min2 >= 8, comm, PETSC_ERR_USER_INPUT, "-fit_min_samples_1d must be >= 3 and -fit_min_samples_2d >= 8 (the MLS basis sizes)");
  {
    PetscBool all;
    PetscCall(PetscStrcmp(terms, "all", &all));
    if (all)
      fit->terms = HYLC_PLAN_ALL_TERMS - 1;
    else {
      char *tok, *save = NULL;
      fit->terms = 0;
      for (tok = strtok_r(terms, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        int found = -1;
        for (int t = 1; t < HYLC_PLAN_NTERM3; t++) {
          PetscBool eq;
          PetscCall(PetscStrcmp(tok, HylcPlanTermName(t), &eq));
          if (eq) found = t;
        }
        PetscCheck(found > 0, comm, PETSC_ERR_USER_INPUT,
                   "-fit_terms: unknown term '%s' (use all or sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, sx-sa-sy, sx-sa-II00, sx-sa-II11, sx-sy-II00, sx-sy-II11, sa-sy-II00, sa-sy-II11)", tok);
        fit->terms |= 1 << found;
      }
    }
  }
  {
    PetscBool same;
    PetscCall(PetscStrcmp(input, fit->input, &same));
    if (!same) PetscCall(HylcFitSetInput(fit, input));
  }
  PetscCall(HylcFitResetResults_Private(fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetData - Gives the fit its data without a file (copied; replaces -fit_input): n rows of strain,
  energy density and term.

  Not collective

  Input Parameters:
+ fit         - the fit
. n           - the number of rows
. strain      - n x 6: sx, sa, sy, II00, II01, II11
. psi         - the energy densities (J/m^2)
. term        - the term of each row, 0..21 as in include/hylc/plan.h (term 0 rows only take part in f0 and
                the normalisation)
- areaDensity - the area density (kg/m^2; <= 0: -fit_density must give it)

  Level: intermediate

.seealso: HylcFitSetInput(), HylcFitSetUp()
@*/
PetscErrorCode HylcFitSetData(HylcFit fit, PetscInt n, const PetscReal strain[], const PetscReal psi[], const PetscInt term[], PetscReal areaDensity)
{
  MPI_Comm comm;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  comm = PetscObjectComm((PetscObject)fit);
  PetscCheck(n >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "HylcFitSetData: negative row count %" PetscInt_FMT, n);
  PetscCall(ResetData(fit));
  fit->input[0] = 0;
  PetscCall(PetscMalloc4(6 * n + 1, &fit->z, n + 1, &fit->psi, n + 1, &fit->term, n + 1, &fit->row));
  PetscCall(PetscMalloc1(6 * n + 1, &fit->stress));
  for (PetscInt k = 0; k < 6 * n; k++) fit->stress[k] = (PetscReal)NAN;
  for (PetscInt k = 0; k < n; k++) {
    PetscCheck(term[k] >= 0 && term[k] < HYLC_PLAN_NTERM3, comm, PETSC_ERR_USER_INPUT, "HylcFitSetData: row %" PetscInt_FMT " has term %" PetscInt_FMT " (valid: 0..21)", k, term[k]);
    for (int i = 0; i < 6; i++) fit->z[6 * k + i] = strain[6 * k + i];
    fit->psi[k]  = psi[k];
    fit->term[k] = term[k];
    fit->row[k]  = k;
  }
  fit->n = fit->nrows = n;
  fit->rhoA           = areaDensity;
  PetscCall(PetscStrncpy(fit->rhoSource, "given with the data", sizeof(fit->rhoSource)));
  PetscCall(PetscStrncpy(fit->source, "data set by HylcFitSetData", sizeof(fit->source)));
  fit->dataset = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetStress - The stresses dPsi/dz of the rows given by HylcFitSetData(), for the fabric method.

  Not collective

  Input Parameters:
+ fit    - the fit, after HylcFitSetData()
- stress - n x 6 (the rows' order; N/m for sx, sa, sy, N for the curvatures; NaN where unknown); copied

  Level: intermediate

.seealso: HylcFitSetData(), HylcFitSetMethod()
@*/
PetscErrorCode HylcFitSetStress(HylcFit fit, const PetscReal stress[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->dataset, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "HylcFitSetStress: call HylcFitSetData() first");
  PetscCall(PetscArraycpy(fit->stress, stress, 6 * fit->n));
  PetscCall(HylcFitResetResults_Private(fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetMethod - How the terms are fitted (option -fit_method): paper (the MLS of the values, Algorithms
  C6, C7), fabric (values and stresses by weighted least squares on graded knots) or auto (fabric when every
  sample has its stress and the samples file's plan was graded, else paper).

  Not collective

  Input Parameters:
+ fit    - the fit
- method - HYLC_FIT_METHOD_AUTO (default), HYLC_FIT_METHOD_PAPER or HYLC_FIT_METHOD_FABRIC

  Level: intermediate

.seealso: HylcFitGetMethod(), HylcFitSetStress()
@*/
PetscErrorCode HylcFitSetMethod(HylcFit fit, HylcFitMethod method)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(method >= HYLC_FIT_METHOD_AUTO && method <= HYLC_FIT_METHOD_FABRIC, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_OUTOFRANGE, "Unknown fit method %d", (int)method);
  fit->method = method;
  PetscCall(HylcFitResetResults_Private(fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetMethod - The method of the fit: after HylcFitCompute() the one used (auto resolved), before it the
  one set.

  Not collective

  Input Parameter:
. fit - the fit

  Output Parameter:
. method - the method

  Level: intermediate

.seealso: HylcFitSetMethod()
@*/
PetscErrorCode HylcFitGetMethod(HylcFit fit, HylcFitMethod *method)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  *method = fit->computed ? fit->methodUsed : fit->method;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitSetUp - Reads the input (unless data were set with HylcFitSetData) and checks it: finite
  strains and energies, at least one term. Not collective.
@*/
PetscErrorCode HylcFitSetUp(HylcFit fit)
{
  MPI_Comm comm;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  if (fit->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  comm = PetscObjectComm((PetscObject)fit);
  if (!fit->dataset) {
    PetscCheck(fit->input[0], comm, PETSC_ERR_USER_INPUT, "No input: give -fit_input <samples.h5 | data.txt | directory>");
    PetscCall(HylcFitReadInput_Private(fit));
  }
  for (PetscInt k = 0; k < fit->n; k++) {
    PetscBool finite = PetscIsInfOrNanReal(fit->psi[k]) ? PETSC_FALSE : PETSC_TRUE;
    for (int i = 0; i < 6; i++)
      if (PetscIsInfOrNanReal(fit->z[6 * k + i])) finite = PETSC_FALSE;
    PetscCheck(finite, comm, PETSC_ERR_USER_INPUT, "%s: row %" PetscInt_FMT " (term %s) has a non-finite strain or energy: (%g, %g, %g, %g, %g, %g) psi %g", fit->source, fit->row[k], HylcPlanTermName((int)fit->term[k]), (double)fit->z[6 * k],
               (double)fit->z[6 * k + 1], (double)fit->z[6 * k + 2], (double)fit->z[6 * k + 3], (double)fit->z[6 * k + 4], (double)fit->z[6 * k + 5], (double)fit->psi[k]);
  }
  PetscCheck(fit->n > 0, comm, PETSC_ERR_USER_INPUT, "%s: no usable samples (%" PetscInt_FMT " rows, %" PetscInt_FMT " not converged)", fit->source, fit->nrows, fit->nskipped);
  /* the area density */
  if (fit->density > 0) {
    fit->rhoA = fit->density;
    PetscCall(PetscStrncpy(fit->rhoSource, "-fit_density", sizeof(fit->rhoSource)));
  }
  PetscCheck(fit->rhoA > 0, comm, PETSC_ERR_USER_INPUT, "%s: no area density (%s); give -fit_density <kg/m^2>", fit->source, fit->rhoSource[0] ? fit->rhoSource : "none in the input");
  fit->setupcalled = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetConstant - The constant f0 of the fitted model (J/m^2).

  Not collective

  Input Parameter:
. fit - the fit, computed (HylcFitCompute())

  Output Parameter:
. f0 - the constant

  Level: intermediate

.seealso: HylcFitGet1D(), HylcFitGet2D()
@*/
PetscErrorCode HylcFitGetConstant(HylcFit fit, PetscReal *f0)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  *f0 = fit->f0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetStrainScale - The strain scales of the fitted model, one per coordinate (sx, sa, sy, II00, II11).

  Not collective

  Input Parameter:
. fit - the fit, computed (HylcFitCompute())

  Output Parameter:
. s - the five scales

  Level: intermediate

.seealso: HylcFitGetConstant()
@*/
PetscErrorCode HylcFitGetStrainScale(HylcFit fit, PetscReal s[5])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  for (int c = 0; c < 5; c++) s[c] = fit->scale[HylcPlanStrainIndex(c)];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetDensity - The area density of the material (kg/m^2): -fit_density, or the input's.

  Not collective

  Input Parameter:
. fit - the fit, set up (HylcFitSetUp())

  Output Parameter:
. rhoA - the area density

  Level: intermediate

.seealso: HylcFitSetUp()
@*/
PetscErrorCode HylcFitGetDensity(HylcFit fit, PetscReal *rhoA)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->setupcalled, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitSetUp() first");
  *rhoA = fit->rhoA;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGet1D - The fitted 1D term of coordinate k (0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending).

  Not collective

  Input Parameters:
+ fit - the fit, computed (HylcFitCompute())
- k   - the coordinate, 0..4

  Output Parameter:
. s - the spline (owned by the fit), NULL for a term that was not fitted (no samples)

  Level: intermediate

.seealso: HylcFitGet2D()
@*/
PetscErrorCode HylcFitGet1D(HylcFit fit, PetscInt k, const HylcSpline1D **s)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  PetscCheck(k >= 0 && k < 5, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_OUTOFRANGE, "1D term k = %" PetscInt_FMT " (valid 0..4)", k);
  *s = fit->has[1 + k] ? &fit->s1[k] : NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGet2D - The fitted 2D term of the pair (k0, k1) (include/hylc/strain.h).

  Not collective

  Input Parameters:
+ fit - the fit, computed (HylcFitCompute())
. k0  - the first coordinate of the pair
- k1  - the second (k0 < k1)

  Output Parameter:
. s - the spline (owned by the fit), NULL for a term that was not fitted (no samples)

  Level: intermediate

.seealso: HylcFitGet1D()
@*/
PetscErrorCode HylcFitGet2D(HylcFit fit, PetscInt k0, PetscInt k1, const HylcSpline2D **s)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  *s = NULL;
  for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
    int ci, cj;
    HylcPlanPair(t, &ci, &cj);
    if (ci == k0 && cj == k1) *s = fit->has[t] ? &fit->s2[t - 6] : NULL;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitEvaluateAxes - The fitted model (S26) at a strain with II01 = 0, where the eigen-split of the
  bending terms is exact, without a HylcMaterial: f0 + the 1D terms + the 2D terms. Used for the per-term
  summary; HylcMaterialEvaluate() is the general evaluator.

  Not collective

  Input Parameters:
+ fit - the fit, computed (HylcFitCompute())
- z   - the strain (sx, sa, sy, II00, II01 = 0, II11)

  Output Parameter:
. psi - the energy density (J/m^2)

  Level: developer

.seealso: HylcFitGetTermStats()
@*/
PetscErrorCode HylcFitEvaluateAxes(HylcFit fit, const PetscReal z[6], PetscReal *psi)
{
  PetscReal S[5], f;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  PetscCheck(z[4] == 0, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_OUTOFRANGE, "HylcFitEvaluateAxes needs II01 = 0, got %g", (double)z[4]);
  for (int c = 0; c < 5; c++) S[c] = z[HylcPlanStrainIndex(c)] / fit->scale[HylcPlanStrainIndex(c)];
  f = fit->f0;
  for (int c = 0; c < 5; c++)
    if (fit->has[1 + c]) f += HylcSpline1DEval(&fit->s1[c], S[c], NULL, NULL);
  for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
    int ci, cj;
    if (!fit->has[t]) continue;
    HylcPlanPair(t, &ci, &cj);
    f += HylcSpline2DEval(&fit->s2[t - 6], S[ci], S[cj], NULL, NULL);
  }
  for (int t = HYLC_PLAN_NTERM; t < HYLC_PLAN_NTERM3; t++) {
    int c[3];
    if (!fit->has[t]) continue;
    HylcPlanTriple(t, c);
    f += HylcFitTerm3DEval_Private(&fit->s3[t - HYLC_PLAN_NTERM], S[c[0]], S[c[1]], S[c[2]], NULL);
  }
  *psi = f;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitGetTermStats - Statistics of the fit of a term against its data.

  Not collective

  Input Parameters:
+ fit - the fit, computed (HylcFitCompute())
- t   - the term, 1..14 as in include/hylc/plan.h

  Output Parameters:
+ n     - the samples used (0 for a term not fitted; may be NULL)
. rms   - the RMS of model - data (J/m^2; may be NULL)
- range - the largest |data - f0| of the term (may be NULL)

  Level: developer

.seealso: HylcFitEvaluateAxes()
@*/
PetscErrorCode HylcFitGetTermStats(HylcFit fit, PetscInt t, PetscInt *n, PetscReal *rms, PetscReal *range)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  PetscCheck(t >= 1 && t < HYLC_PLAN_NTERM, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_OUTOFRANGE, "term %" PetscInt_FMT " (valid 1..14)", t);
  if (n) *n = fit->has[t] ? fit->statN[t] : 0;
  if (rms) *rms = fit->has[t] ? fit->statRms[t] : 0;
  if (range) *range = fit->has[t] ? fit->statRange[t] : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

const PetscReal HylcFitBandLimits[2][2] = {{0.05, 0.2}, {20, 80}};

/*@C
  HylcFitGetTermBandStats - The fit's relative error against its data in three strain bands (where cloth
  lives, moderate, large): a sample is in band 0 if every strain of its term is small (|s| <= 0.05 for sx,
  sa, sy; |II| <= 20 1/m), in band 1 if none exceeds 0.2 (80 1/m), else in band 2. Per band, the number of
  samples and the RMS of (model - data) over the RMS of (data - f0) there, so that a term whose energy is
  small where cloth lives is judged there and not by its largest values.

  Not collective

  Input Parameters:
+ fit - the fit, computed
- t   - the term (1..14)

  Output Parameters:
+ n   - samples per band (may be NULL)
- rel - the relative error per band (0 for an empty band; may be NULL)

  Level: intermediate

.seealso: HylcFitGetTermStats()
@*/
PetscErrorCode HylcFitGetTermBandStats(HylcFit fit, PetscInt t, PetscInt n[HYLC_FIT_NBAND], PetscReal rel[HYLC_FIT_NBAND])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCheck(fit->computed, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_WRONGSTATE, "Call HylcFitCompute() first");
  PetscCheck(t >= 1 && t < HYLC_PLAN_NTERM, PetscObjectComm((PetscObject)fit), PETSC_ERR_ARG_OUTOFRANGE, "term %" PetscInt_FMT " (valid 1..14)", t);
  for (int b = 0; b < HYLC_FIT_NBAND; b++) {
    if (n) n[b] = fit->has[t] ? fit->statBandN[t][b] : 0;
    if (rel) rel[b] = fit->has[t] ? fit->statBandRel[t][b] : 0;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* C-library formatting (PETSc's printf turns %g of 3.0 into "3."): a line on the viewer, a string */
static PetscErrorCode Line(PetscViewer viewer, const char fmt[], ...)
{
  char    buf[1024];
  va_list ap;

  PetscFunctionBegin;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof(buf), fmt, ap);
  va_end(ap);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Fmt(char buf[], size_t size, const char fmt[], ...)
{
  va_list ap;

  PetscFunctionBegin;
  va_start(ap, fmt);
  vsnprintf(buf, size, fmt, ap);
  va_end(ap);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitView - Prints the settings and, after HylcFitCompute, f0, the strain scale, the area density
  and per term: knots, data range, samples and the RMS residual of the model against the data, and the
  relative error by strain band (HylcFitGetTermBandStats(): small |s| <= 5 %, |II| <= 20 1/m; moderate
  up to 20 %, 80 1/m; large).
  Not collective (prints on the object's communicator).
@*/
PetscErrorCode HylcFitView(HylcFit fit, PetscViewer viewer)
{
  PetscBool iascii;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)fit), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectPrintClassNamePrefixType((PetscObject)fit, viewer));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(Line(viewer, "input: %s\n", fit->source[0] ? fit->source : (fit->input[0] ? fit->input : "(none)")));
  PetscCall(Line(viewer, "family: %s (%s)\n", fit->familyName, fit->familySource[0] ? fit->familySource : "the default"));
  if (fit->computed)
    PetscCall(Line(viewer, "method: %s%s\n", HylcFitMethods[fit->methodUsed], fit->method == HYLC_FIT_METHOD_AUTO ? " (auto)" : ""));
  else
    PetscCall(Line(viewer, "method: %s\n", HylcFitMethods[fit->method]));
  if (fit->computed && fit->methodUsed == HYLC_FIT_METHOD_FABRIC)
    PetscCall(Line(viewer, "fabric method: values and stresses by weighted least squares, errors relative to the tile's own with a floor of %g of each term's largest, ridge %g, outward slope floor %g; knots %s\n", (double)fit->fabricFloor,
                   (double)fit->fabricRidge, (double)fit->fabricReg, fit->knotSource));
  PetscCall(Line(viewer, "reg %g%s, compat %s, MLS kernel %g of the span (sigma = kernel/%g), FD width %g of the knot spacing\n", (double)fit->reg, fit->quasiconvex ? "" : " (marching off)", HylcFitCompats[fit->compat], (double)fit->kernel,
                 (double)fit->truncation, (double)fit->fdEps));
  if (fit->knots == HYLC_FIT_KNOTS_REFINED)
    PetscCall(Line(viewer, "1D knots: the paper's, refined towards 0 by %" PetscInt_FMT " more on each side (h/2 ... h/%d), their MLS kernels %g x the distance from 0, at least %" PetscInt_FMT " samples, at most the paper's\n", fit->refine,
                   1 << (int)fit->refine, (double)fit->kernelSpacing, fit->kernelMin));
  else
    PetscCall(Line(viewer, "1D knots: the paper's uniform layout\n"));
  PetscCall(Line(viewer,
                 "knots: 1D %" PetscInt_FMT " x %g; 2D factor %g (bending pairs %g), stretch %" PetscInt_FMT "+%" PetscInt_FMT ", poisson %" PetscInt_FMT "+%" PetscInt_FMT ", symmetric %" PetscInt_FMT "+%" PetscInt_FMT
                 ", bending pairs %" PetscInt_FMT "+%" PetscInt_FMT " / %" PetscInt_FMT "+%" PetscInt_FMT "\n",
                 fit->nk1, (double)fit->factor1, (double)fit->factor2, (double)fit->factor2bend, fit->kStretch[0], fit->kStretch[1], fit->kPoisson[0], fit->kPoisson[1], fit->kSym[0], fit->kSym[1], fit->kBendStretch[0], fit->kBendStretch[1],
                 fit->kBendSym[0], fit->kBendSym[1]));
  if (fit->setupcalled) {
    PetscCall(Line(viewer, "samples: %" PetscInt_FMT " used of %" PetscInt_FMT " rows (%" PetscInt_FMT " not converged)\n", fit->n, fit->nrows, fit->nskipped));
    PetscCall(Line(viewer, "area density: %.6g kg/m^2 (%s)\n", (double)fit->rhoA, fit->rhoSource));
  }
  if (fit->computed) {
    const PetscReal *z = fit->z + 6 * fit->f0row;
    PetscCall(Line(viewer, "f0: %.9g J/m^2 (row %" PetscInt_FMT ", strain (%g, %g, %g, %g, %g, %g))\n", (double)fit->f0, fit->row[fit->f0row], (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5]));
    PetscCall(Line(viewer, "strain scale: %g %g %g %g %g\n", (double)fit->scale[0], (double)fit->scale[1], (double)fit->scale[2], (double)fit->scale[3], (double)fit->scale[5]));
    for (int t = 1; t < HYLC_PLAN_NTERM3; t++) {
      char knots[64], range[240];
      if (!fit->has[t]) {
        if (t < HYLC_PLAN_NTERM) PetscCall(Line(viewer, "%-8s not fitted (%s)\n", HylcPlanTermName(t), (fit->terms >> t) & 1 ? "no samples" : "not in -fit_terms"));
        continue;
      }
      if (t <= 5) {
        const int c = t - 1;
        PetscCall(Fmt(knots, sizeof(knots), "%" PetscInt_FMT " knots", fit->s1[c].n));
        PetscCall(Fmt(range, sizeof(range), "%s in [%.4g, %.4g]", HylcPlanTermName(t), (double)fit->statMin[t][0], (double)fit->statMax[t][0]));
      } else if (t >= HYLC_PLAN_NTERM) {
        const hylcmat_term3d *s = &fit->s3[t - HYLC_PLAN_NTERM];
        PetscCall(Fmt(knots, sizeof(knots), "%dx%dx%d knots", s->nu, s->nv, s->nw));
        PetscCall(Fmt(range, sizeof(range), "%s in [%.4g, %.4g], %s in [%.4g, %.4g], %s in [%.4g, %.4g]%s", HylcCoordNames[s->k0], (double)fit->statMin[t][0], (double)fit->statMax[t][0], HylcCoordNames[s->k1], (double)fit->statMin[t][1],
                      (double)fit->statMax[t][1], HylcCoordNames[s->k2], (double)fit->statMin[t][2], (double)fit->statMax[t][2], fit->missing3[t - HYLC_PLAN_NTERM] ? " (nodes without a converged sample: 0)" : ""));
      } else {
        int ci, cj;
        HylcPlanPair(t, &ci, &cj);
        PetscCall(Fmt(knots, sizeof(knots), "%" PetscInt_FMT "x%" PetscInt_FMT " knots", fit->s2[t - 6].nu, fit->s2[t - 6].nv));
        PetscCall(
            Fmt(range, sizeof(range), "%s in [%.4g, %.4g], %s in [%.4g, %.4g]", HylcPlanTermName(1 + ci), (double)fit->statMin[t][0], (double)fit->statMax[t][0], HylcPlanTermName(1 + cj), (double)fit->statMin[t][1], (double)fit->statMax[t][1]));
      }
      PetscCall(Line(viewer, "%-8s %-11s %5" PetscInt_FMT " samples, %s; RMS residual %.3g J/m^2 (%.3g%% of max |psi - f0| %.3g)\n", HylcPlanTermName(t), knots, fit->statN[t], range, (double)fit->statRms[t],
                     fit->statRange[t] > 0 ? (double)(100 * fit->statRms[t] / fit->statRange[t]) : 0.0, (double)fit->statRange[t]));
      {
        char bands[3][48];
        for (int b = 0; b < HYLC_FIT_NBAND; b++) {
          if (fit->statBandN[t][b])
            PetscCall(Fmt(bands[b], sizeof(bands[b]), "%.3g%% (%" PetscInt_FMT ")", (double)(100 * fit->statBandRel[t][b]), fit->statBandN[t][b]));
          else
            PetscCall(Fmt(bands[b], sizeof(bands[b]), "-"));
        }
        PetscCall(Line(viewer, "%-8s relative error of psi - f0 by band (samples): small %s, moderate %s, large %s\n", "", bands[0], bands[1], bands[2]));
      }
    }
  }
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitViewFromOptions - Views the fit if the option name is given (PetscObjectViewFromOptions()).

  Collective

  Input Parameters:
+ fit  - the fit
. obj  - an object whose prefix is used (NULL: the fit's)
- name - the option, e.g. "-fit_view"

  Level: intermediate

.seealso: HylcFitView()
@*/
PetscErrorCode HylcFitViewFromOptions(HylcFit fit, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)fit, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
