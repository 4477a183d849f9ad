/* HylcSampler: the setters of the options and HylcSamplerSetFromOptions. */
#include <hylc/options.h>
#include "samplerimpl.h"

#define SAMPLER_SETTER_BEGIN                            \
  PetscFunctionBegin;                                   \
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1); \
  PetscCheck(!S->setupcalled, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_WRONGSTATE, "Set the sampler's options before HylcSamplerSetUp()")

/*@C
  HylcSamplerSetYarnModel - Sets the yarn model (copied; options -yarn_*, read by HylcSamplerSetFromOptions()).

  Not collective

  Input Parameters:
+ S     - the sampler
- model - the yarn model

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetYarnModel(HylcSampler S, const HylcYarnModel *model)
{
  SAMPLER_SETTER_BEGIN;
  S->model = *model;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetOutput - Sets the HDF5 output (option -sampler_output; its journal is <output>.journal).

  Not collective

  Input Parameters:
+ S      - the sampler
- output - the path

  Level: beginner
@*/
PetscErrorCode HylcSamplerSetOutput(HylcSampler S, const char output[])
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(output && output[0], PetscObjectComm((PetscObject)S), PETSC_ERR_USER_INPUT, "-sampler_output: empty path");
  PetscCall(PetscStrncpy(S->output, output, sizeof(S->output)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetResume - Continue an interrupted run from its journal (option -sampler_resume).

  Not collective

  Input Parameters:
+ S   - the sampler
- flg - resume or not

  Level: intermediate

.seealso: HylcSamplerSetOverwrite()
@*/
PetscErrorCode HylcSamplerSetResume(HylcSampler S, PetscBool flg)
{
  SAMPLER_SETTER_BEGIN;
  S->resume = flg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetOverwrite - Start over, replacing an existing output and its journal (option -sampler_overwrite).

  Not collective

  Input Parameters:
+ S   - the sampler
- flg - overwrite or not

  Level: intermediate

.seealso: HylcSamplerSetResume()
@*/
PetscErrorCode HylcSamplerSetOverwrite(HylcSampler S, PetscBool flg)
{
  SAMPLER_SETTER_BEGIN;
  S->overwrite = flg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetPlanRanges - Sets the family and 1D ranges of the plan (options -sampler_family,
  -sampler_range_<c>); HylcSamplerSetUp() resolves them for the yarn radius (HylcPlanRangesApply()).

  Not collective

  Input Parameters:
+ S      - the sampler
- ranges - the family and the ranges

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetPlanRanges(HylcSampler S, const HylcPlanRanges *ranges)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(ranges->family >= 0 && ranges->family < 4, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_OUTOFRANGE, "-sampler_family: unknown family %" PetscInt_FMT, ranges->family);
  S->ranges = *ranges;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetSampleCounts - Samples per 1D term and per axis of a 2D term (options -sampler_n1, -sampler_n2).

  Not collective

  Input Parameters:
+ S  - the sampler
. n1 - samples per 1D term (1..1024)
- n2 - samples per axis of a 2D term (1..1024)

  Level: beginner
@*/
PetscErrorCode HylcSamplerSetSampleCounts(HylcSampler S, PetscInt n1, PetscInt n2)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(n1 >= 1 && n1 <= 1024 && n2 >= 1 && n2 <= 1024, PetscObjectComm((PetscObject)S), PETSC_ERR_USER_INPUT, "-sampler_n1 and -sampler_n2 must be in 1..1024");
  S->n1 = n1;
  S->n2 = n2;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetTerms - The terms to sample (option -sampler_terms, a list parsed by HylcPlanTermsFromString()).

  Not collective

  Input Parameters:
+ S     - the sampler
- terms - bit t set for term t of include/hylc/plan.h (0 zero, 1..5 the 1D terms, 6..14 the 2D terms, 15..21 the 3D terms)

  Level: beginner
@*/
PetscErrorCode HylcSamplerSetTerms(HylcSampler S, PetscInt terms)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(terms > 0 && terms <= HYLC_PLAN_ALL_TERMS, PetscObjectComm((PetscObject)S), PETSC_ERR_USER_INPUT, "The sampling plan is empty (-sampler_terms)");
  S->terms = terms;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetBatchSize - Samples per batch, the unit of work handed to a rank (option -sampler_batch).

  Not collective

  Input Parameters:
+ S     - the sampler
- batch - at least 1

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetBatchSize(HylcSampler S, PetscInt batch)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(batch >= 1, PetscObjectComm((PetscObject)S), PETSC_ERR_USER_INPUT, "-sampler_batch must be at least 1");
  S->batch = batch;
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const HylcSamplerStarts[] = {"cold", "continue", "both", "HylcSamplerStart", "HYLC_SAMPLER_START_", NULL};

/*@C
  HylcSamplerSetStart - How each sample's solve starts (option -sampler_start): continue (the default), cold
  (from u~ = 0, the paper's procedure) or both.
  With continue, the unit of work handed to a rank is a half-line of the plan (HylcPlanUnits(): each 1D term
  and each line of a 2D grid split at zero, going outward); a unit's first sample starts cold, each other one
  from its predecessor's equilibrium if that converged (else cold); a continued solve that does not converge
  is retried cold. With both, the units are the same and every sample is solved cold and, where its
  predecessor converged, continued: the lower Psi of the converged ones is kept (and continued from), the
  other start's Psi and status are recorded, and samples whose two Psi differ by more than
  HylcSamplerSetBothTolerance() are flagged multistable. -sampler_batch is used only by cold.

  Not collective

  Input Parameters:
+ S     - the sampler
- start - HYLC_SAMPLER_START_CONTINUE, HYLC_SAMPLER_START_COLD or HYLC_SAMPLER_START_BOTH

  Level: intermediate

.seealso: HylcMicroSetInitialFluctuation(), HylcPlanUnits(), HylcSamplerSetBothTolerance()
@*/
PetscErrorCode HylcSamplerSetStart(HylcSampler S, HylcSamplerStart start)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(start == HYLC_SAMPLER_START_COLD || start == HYLC_SAMPLER_START_CONTINUE || start == HYLC_SAMPLER_START_BOTH, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_OUTOFRANGE, "-sampler_start: unknown start %d (continue, cold or both)",
             (int)start);
  S->start = start;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetBothTolerance - With -sampler_start both, the relative difference of the two starts' Psi
  above which a sample is flagged multistable (option -sampler_both_rtol): |Psi_cold - Psi_continued| >
  rtol max(|Psi_cold|, |Psi_continued|).

  Not collective

  Input Parameters:
+ S    - the sampler
- rtol - finite and positive (default 1e-3)

  Level: intermediate

.seealso: HylcSamplerSetStart()
@*/
PetscErrorCode HylcSamplerSetBothTolerance(HylcSampler S, PetscReal rtol)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(rtol > 0 && !PetscIsInfOrNanReal(rtol), PetscObjectComm((PetscObject)S), PETSC_ERR_USER_INPUT, "-sampler_both_rtol %g: must be finite and positive", (double)rtol);
  S->bothRtol = rtol;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetStress - Whether each converged sample records its stress dPsi/dz (all six components, by the
  envelope theorem at the equilibrium: HylcMicroGetStrainGradient(); option -sampler_stress). The stress is
  what hylc-fit's fabric method fits the slopes of its splines to.

  Not collective

  Input Parameters:
+ S      - the sampler
- stress - PETSC_TRUE (default) to record it, PETSC_FALSE to write NaN

  Level: intermediate

.seealso: HylcMicroGetStrainGradient(), HylcSamplerRun()
@*/
PetscErrorCode HylcSamplerSetStress(HylcSampler S, PetscBool stress)
{
  SAMPLER_SETTER_BEGIN;
  S->stress = stress;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetProgressInterval - Seconds between progress lines (option -sampler_progress).

  Not collective

  Input Parameters:
+ S       - the sampler
- seconds - the interval

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetProgressInterval(HylcSampler S, PetscReal seconds)
{
  SAMPLER_SETTER_BEGIN;
  S->progress = seconds;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetExportRaw - Also write the paper's raw layout (data.txt, info.txt) into a directory
  (options -sampler_export_raw, -sampler_density).

  Not collective

  Input Parameters:
+ S       - the sampler
. dir     - the directory (NULL or empty: no export)
- density - volumetric yarn density for the area density of info.txt (kg/m^3; <= 0: 0.12 kg/m^2 / r)

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetExportRaw(HylcSampler S, const char dir[], PetscReal density)
{
  SAMPLER_SETTER_BEGIN;
  PetscCall(PetscStrncpy(S->rawdir, dir ? dir : "", sizeof(S->rawdir)));
  S->density = density;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetReference - Whether the reference state (Algorithm C1) is computed first, and where it is
  written (options -sampler_reference, -reference_output; its parameters are -reference_*).

  Not collective

  Input Parameters:
+ S      - the sampler
. mode   - HYLC_REFERENCE_AUTO (for generated patterns), HYLC_REFERENCE_COMPUTE, HYLC_REFERENCE_NONE or HYLC_REFERENCE_RELAX (the in-plane minimum of the pattern as given)
- output - .pyp file for the reference state (NULL or empty: none)

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetReference(HylcSampler S, HylcReferenceMode mode, const char output[])
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(mode >= HYLC_REFERENCE_AUTO && mode <= HYLC_REFERENCE_RELAX, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_OUTOFRANGE, "Unknown reference mode %d", (int)mode);
  S->refmode = mode;
  PetscCall(PetscStrncpy(S->refout, output ? output : "", sizeof(S->refout)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetFromOptions - Reads the options of the sampling job and of its pattern (-pattern_*), yarn
  model (-yarn_*), reference state (-reference_*) and solver (HylcMicroSetFromOptions() of
  HylcSamplerGetMicro(): -micro_*, with its tile's -periodic_*, -macro_* and its SNES's and
  factorization's -micro_snes_*, -micro_factor_*). It only reads options, also with -help: the pattern is
  loaded or generated and the solver set up by HylcSamplerSetUp().

  Collective

  Input Parameter:
. S - the sampler

  Options Database Keys:
+ -sampler_output <samples.h5>    - the HDF5 output (its journal: <output>.journal) (HylcSamplerSetOutput())
. -sampler_resume                 - continue an interrupted run from its journal (refused if its settings differ) (HylcSamplerSetResume())
. -sampler_overwrite              - start over: replace an existing output and its journal (without either
                                    option an existing output or a journal holding samples is refused) (HylcSamplerSetOverwrite())
. -sampler_family <woven>         - default ranges of docs/method.md §8: woven, stockinette, honeycomb, rib (HylcSamplerSetPlanRanges())
. -sampler_range_<c> min,max      - 1D range of c = sx, sa, sy, II00, II11 (II in 1/m; 2D ranges follow) (HylcSamplerSetPlanRanges())
. -sampler_n1 <150>, -sampler_n2 <50> - samples per 1D term, per axis of a 2D term (HylcSamplerSetSampleCounts())
. -sampler_terms <all>            - comma list of terms: zero, sx, sa, sy, II00, II11, sx-sa, sx-sy,
                                    sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, sx-sa-sy, sx-sa-II00,
                                    sx-sa-II11, sx-sy-II00, sx-sy-II11, sa-sy-II00, sa-sy-II11, or all (with graded spacing the 3D terms too), paper (the paper's 15), 1d
                                    (HylcSamplerSetTerms())
. -sampler_batch <1>              - samples per batch (the unit of work handed to a rank) (HylcSamplerSetBatchSize())
. -sampler_start <continue>       - continue (half-lines from the zero strain outward), cold (the paper's) or both (HylcSamplerSetStart())
. -sampler_both_rtol <1e-3>       - both: relative difference of the two Psi flagged multistable (HylcSamplerSetBothTolerance())
. -sampler_progress <5>           - seconds between progress lines (HylcSamplerSetProgressInterval())
. -sampler_export_raw <dir>, -sampler_density <0> - the paper's raw layout (HylcSamplerSetExportRaw())
. -sampler_reference <auto>, -reference_output <f.pyp> - reference state (HylcSamplerSetReference())
- -sampler_view                   - print the job after its set-up (HylcSamplerView())

  Level: beginner

.seealso: HylcSamplerSetUp(), HylcSamplerGetPattern(), HylcSamplerGetMicro()
@*/
PetscErrorCode HylcSamplerSetFromOptions(HylcSampler S)
{
  MPI_Comm       comm       = PetscObjectComm((PetscObject)S);
  char           terms[512] = "all", output[PETSC_MAX_PATH_LEN], refout[PETSC_MAX_PATH_LEN], rawdir[PETSC_MAX_PATH_LEN];
  PetscInt       n1 = S->n1, n2 = S->n2, batch = S->batch;
  PetscReal      progress = S->progress, density = S->density, bothRtol = S->bothRtol;
  PetscBool      resume = S->resume, overwrite = S->overwrite, stress = S->stress, tset;
  PetscEnum      mode = (PetscEnum)S->refmode, start = (PetscEnum)S->start;
  HylcPlanRanges ranges = S->ranges;
  HylcPattern    pat;
  HylcMicro      micro;
  HylcYarnModel  model;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscCheck(!S->setupcalled, comm, PETSC_ERR_ARG_WRONGSTATE, "HylcSamplerSetFromOptions() after HylcSamplerSetUp()");
  S->solverSetUp = PETSC_FALSE;
  PetscCall(PetscStrncpy(output, S->output, sizeof(output)));
  PetscCall(PetscStrncpy(refout, S->refout, sizeof(refout)));
  PetscCall(PetscStrncpy(rawdir, S->rawdir, sizeof(rawdir)));
  PetscCall(HylcSamplerGetPattern(S, &pat));
  PetscCall(HylcPatternSetFromOptions(pat));
  model = S->model;
  PetscCall(HylcYarnModelSetFromOptions(comm, ((PetscObject)S)->prefix, &model));
  PetscCall(HylcSamplerSetYarnModel(S, &model));
  PetscCall(HylcReferenceParamsSetFromOptions(comm, ((PetscObject)S)->prefix, &S->refpar));
  PetscObjectOptionsBegin((PetscObject)S);
  PetscCall(HylcOptionsEnum("-sampler_reference",
                            "Reference state: auto (Algorithm C1 for a generated pattern; relax for a stored reference state, a .pyp as the paper's: the tile at rest at z = 0), compute (C1), relax (only the in-plane minimum over the periods of the "
                            "pattern as given: a stored tile made a minimum of the configured yarn) or none (the pattern as given: the paper's procedure, config/profile-paper.yaml)",
                            "HylcSamplerSetReference", HylcReferenceModes, mode, &mode, NULL));
  PetscCall(HylcOptionsString("-reference_output", "Write the reference state as .pyp", "HylcSamplerSetReference", refout, refout, sizeof(refout), NULL));
  PetscCall(HylcOptionsString("-sampler_output", "HDF5 output file (the journal is <output>.journal)", "HylcSamplerSetOutput", output, output, sizeof(output), NULL));
  PetscCall(PetscOptionsBool("-sampler_resume", "Continue an interrupted run from its journal <output>.journal (refused, naming the differences, if any setting that changes results differs)", "HylcSamplerSetResume", resume, &resume, NULL));
  PetscCall(
      PetscOptionsBool("-sampler_overwrite", "Start over: replace an existing output and its journal (without -sampler_resume or this, an existing output or journal with samples is refused)", "HylcSamplerSetOverwrite", overwrite, &overwrite, NULL));
  PetscCall(HylcPlanRangesFromOptions(PetscOptionsObject, comm, "HylcSamplerSetPlanRanges", &ranges));
  {
    PetscBool s1, s2;
    PetscCall(HylcOptionsInt("-sampler_n1", "Samples per 1D term (paper spacing; giving it selects paper spacing unless -sampler_spacing is given)", "HylcSamplerSetSampleCounts", n1, &n1, &s1));
    PetscCall(HylcOptionsInt("-sampler_n2", "Samples per axis of a 2D term (paper spacing; as -sampler_n1)", "HylcSamplerSetSampleCounts", n2, &n2, &s2));
    if ((s1 || s2) && !ranges.spacingSet) ranges.spacing = HYLC_PLAN_SPACING_PAPER;
  }
  PetscCall(HylcOptionsString("-sampler_terms",
                              "Terms to sample: all (with graded spacing the 3D terms too), paper (the paper's 15: zero, 1D, 2D), 1d, or a comma list of zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, "
                              "sy-II00, sy-II11, sx-sa-sy, sx-sa-II00, sx-sa-II11, sx-sy-II00, sx-sy-II11, sa-sy-II00, sa-sy-II11",
                              "HylcSamplerSetTerms", terms, terms, sizeof(terms), &tset));
  PetscCall(HylcOptionsInt("-sampler_batch", "Samples per batch (unit of work of a rank)", "HylcSamplerSetBatchSize", batch, &batch, NULL));
  PetscCall(HylcOptionsEnum("-sampler_start",
                            "How each sample's solve starts: continue (half-lines of the plan from the zero strain outward, each sample from its predecessor's equilibrium, retried cold if it does not converge; the unit of work is a half-line), "
                            "cold (every sample from u~ = 0: the paper's procedure) or both (every sample from both, the lower Psi kept, the other in /samples/psi_other: a map of multistability)",
                            "HylcSamplerSetStart", HylcSamplerStarts, start, &start, NULL));
  PetscCall(HylcOptionsReal("-sampler_both_rtol", "-sampler_start both: relative difference of the two starts' Psi above which a sample is flagged multistable (1)", "HylcSamplerSetBothTolerance", bothRtol, &bothRtol, NULL));
  PetscCall(PetscOptionsBool("-sampler_stress", "Record each converged sample's stress dPsi/dz (six components, N/m and N; envelope theorem, no re-solve) in /samples/stress", "HylcSamplerSetStress", stress, &stress, NULL));
  PetscCall(HylcOptionsReal("-sampler_progress", "Seconds between progress lines", "HylcSamplerSetProgressInterval", progress, &progress, NULL));
  PetscCall(HylcOptionsString("-sampler_export_raw", "Also write the paper's raw layout into this directory: data.txt (rows sx sa sy II00 II01 II11 Psi in the order of C4) and info.txt (area, area density)", "HylcSamplerSetExportRaw", rawdir, rawdir,
                              sizeof(rawdir), NULL));
  PetscCall(HylcOptionsReal("-sampler_density", "Volumetric yarn density for the area density of info.txt (kg/m^3; <= 0: 0.12 kg/m^2 / r, as hylc-fit)", "HylcSamplerSetExportRaw", density, &density, NULL));
  PetscCall(PetscOptionsName("-sampler_view", "Print the sampling job after its set-up", "HylcSamplerView", NULL));
  PetscOptionsEnd();
  PetscCall(HylcSamplerSetReference(S, (HylcReferenceMode)mode, refout));
  PetscCall(HylcSamplerSetOutput(S, output));
  PetscCall(HylcSamplerSetResume(S, resume));
  PetscCall(HylcSamplerSetOverwrite(S, overwrite));
  PetscCall(HylcSamplerSetPlanRanges(S, &ranges));
  PetscCall(HylcSamplerSetSampleCounts(S, n1, n2));
  PetscCall(HylcSamplerSetBatchSize(S, batch));
  PetscCall(HylcSamplerSetStart(S, (HylcSamplerStart)start));
  PetscCall(HylcSamplerSetBothTolerance(S, bothRtol));
  PetscCall(HylcSamplerSetStress(S, stress));
  PetscCall(HylcSamplerSetProgressInterval(S, progress));
  PetscCall(HylcSamplerSetExportRaw(S, rawdir, density));
  if (tset) {
    int mask;
    PetscCall(HylcPlanTermsFromString(comm, "-sampler_terms", terms, &mask));
    PetscCall(HylcSamplerSetTerms(S, (PetscInt)mask));
  }
  PetscCall(HylcSamplerGetMicro(S, &micro));
  PetscCall(HylcMicroSetFromOptions(micro));
  PetscFunctionReturn(PETSC_SUCCESS);
}
