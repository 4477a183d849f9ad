/* HylcSampler: the MPI sampling job (include/hylc/sampler.h). */
#include <hylc/sampler.h>
#include <hylc/reference.h>
#include <petsctime.h>
#include <petsc/private/petscimpl.h>
#include <unistd.h>
#include <string.h>
#include <sys/stat.h>

#define TAG_RECORDS 7301
#define TAG_DONE    7302

struct _HylcSamplerOps {
  PetscErrorCode (*view)(HylcSampler, PetscViewer);
};

struct _p_HylcSampler {
  PETSCHEADER(struct _HylcSamplerOps);
  PetscMPIInt         rank, size;
  HylcPattern         pat;   /* created by HylcSamplerGetPattern(), set up by HylcSamplerSetUp() */
  HylcYarnModel       model; /* -yarn_* */
  HylcMicro           micro; /* created by HylcSamplerGetMicro(), given the pattern by HylcSamplerSetUp() */
  HylcPlanRanges      ranges;
  PetscInt            n1, n2, terms; /* samples per 1D term and 2D axis; bit t: term t */
  HylcPlan            plan;          /* after HylcSamplerSetUp() (its ranges depend on the yarn radius) */
  char                output[PETSC_MAX_PATH_LEN];
  PetscBool           resume, overwrite;
  HylcJournal         journal;  /* rank 0: open and locked from HylcSamplerSetUp() to the end of the run */
  char               *identity; /* rank 0: the run's identity text (HylcSamplesIdentity) */
  unsigned char      *done;     /* HylcSamplerRun's scratch (owned here, so an error exit frees it too): */
  HylcSampleRecord   *recs;     /* samples done, and one batch of records */
  PetscInt            batch;
  PetscReal           progress; /* seconds between progress lines */
  long                nsamples;
  HylcReferenceMode   refmode;
  HylcReferenceParams refpar;
  char                refout[PETSC_MAX_PATH_LEN];
  char                rawdir[PETSC_MAX_PATH_LEN]; /* export of the paper's raw layout (data.txt, info.txt) */
  PetscReal           density;                    /* volumetric yarn density for info.txt (kg/m^3) */
  PetscBool           solverSetUp, setupcalled;
};

/*@C
  HylcSamplerCreate - Creates the sampling job: output samples.h5, the woven family's ranges, every term
  with 150 samples per 1D term and 50 per axis of a 2D term, batches of 1, progress every 5 s, the
  reference state computed for generated patterns (auto), the default yarn model.

  Collective

  Input Parameter:
. comm - the ranks that share the work

  Output Parameter:
. s - the new sampler

  Level: beginner

.seealso: HylcSamplerSetFromOptions(), HylcSamplerSetUp(), HylcSamplerRun(), HylcSamplerDestroy()
@*/
PetscErrorCode HylcSamplerCreate(MPI_Comm comm, HylcSampler *s)
{
  HylcSampler S;

  PetscFunctionBegin;
  PetscValidPointer(s, 2);
  *s = NULL;
  PetscCall(HylcInitializePackage());
  PetscCall(PetscHeaderCreate(S, HYLC_SAMPLER_CLASSID, "HylcSampler", "Sampling job", "Sampler", comm, HylcSamplerDestroy, HylcSamplerView));
  PetscCallMPI(MPI_Comm_rank(comm, &S->rank));
  PetscCallMPI(MPI_Comm_size(comm, &S->size));
  PetscCall(PetscStrncpy(S->output, "samples.h5", sizeof(S->output)));
  S->n1       = 150;
  S->n2       = 50;
  S->terms    = (1 << HYLC_PLAN_NTERM) - 1;
  S->batch    = 1;
  S->progress = 5;
  S->density  = 0;
  S->refmode  = HYLC_REFERENCE_AUTO;
  PetscCall(HylcYarnModelDefault(&S->model));
  PetscCall(HylcReferenceParamsDefault(&S->refpar));
  *s = S;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerDestroy - Destroys the sampler (drops a reference; frees it, its pattern, solver and journal
  with the last one).

  Collective

  Input Parameter:
. s - the sampler (may be NULL); set to NULL

  Level: beginner

.seealso: HylcSamplerCreate()
@*/
PetscErrorCode HylcSamplerDestroy(HylcSampler *s)
{
  PetscFunctionBegin;
  if (!*s) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*s, HYLC_SAMPLER_CLASSID, 1);
  if (--((PetscObject)(*s))->refct > 0) {
    *s = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcJournalClose(&(*s)->journal));
  PetscCall(PetscFree((*s)->identity));
  PetscCall(PetscFree2((*s)->done, (*s)->recs));
  PetscCall(HylcMicroDestroy(&(*s)->micro));
  PetscCall(HylcPatternDestroy(&(*s)->pat));
  PetscCall(PetscHeaderDestroy(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetOptionsPrefix - Sets the prefix of the sampler's own options (-<prefix>sampler_*,
  -<prefix>sampler_view).

  Not collective

  Input Parameters:
+ S      - the sampler
- prefix - the prefix (NULL: none)

  Level: intermediate

.seealso: HylcSamplerSetFromOptions()
@*/
PetscErrorCode HylcSamplerSetOptionsPrefix(HylcSampler S, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)S, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerGetPattern - The sampler's pattern, created (unset) on first use; HylcSamplerSetFromOptions()
  reads its options and HylcSamplerSetUp() loads or generates it (and may replace it by its reference
  state). Borrowed: do not destroy it.

  Collective on the first call

  Input Parameter:
. S - the sampler

  Output Parameter:
. pat - the pattern

  Level: intermediate

.seealso: HylcSamplerGetMicro()
@*/
PetscErrorCode HylcSamplerGetPattern(HylcSampler S, HylcPattern *pat)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscValidPointer(pat, 2);
  if (!S->pat) PetscCall(HylcPatternCreate(PetscObjectComm((PetscObject)S), &S->pat));
  *pat = S->pat;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerGetMicro - The solver of this rank's samples (on PETSC_COMM_SELF), created on first use;
  HylcSamplerSetFromOptions() reads its options and HylcSamplerSetUp() gives it the pattern and sets it up.
  Borrowed: do not destroy it.

  Not collective

  Input Parameter:
. S - the sampler

  Output Parameter:
. micro - the solver

  Level: intermediate

.seealso: HylcSamplerGetPattern()
@*/
PetscErrorCode HylcSamplerGetMicro(HylcSampler S, HylcMicro *micro)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscValidPointer(micro, 2);
  if (!S->micro) PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &S->micro));
  *micro = S->micro;
  PetscFunctionReturn(PETSC_SUCCESS);
}

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
- terms - bit t set for term t of include/hylc/plan.h (0 zero, 1..5 the 1D terms, 6..14 the 2D terms)

  Level: beginner
@*/
PetscErrorCode HylcSamplerSetTerms(HylcSampler S, PetscInt terms)
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(terms > 0 && terms < (1 << HYLC_PLAN_NTERM), PetscObjectComm((PetscObject)S), PETSC_ERR_USER_INPUT, "The sampling plan is empty (-sampler_terms)");
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
. mode   - HYLC_REFERENCE_AUTO (for generated patterns), HYLC_REFERENCE_COMPUTE or HYLC_REFERENCE_NONE
- output - .pyp file for the reference state (NULL or empty: none)

  Level: intermediate
@*/
PetscErrorCode HylcSamplerSetReference(HylcSampler S, HylcReferenceMode mode, const char output[])
{
  SAMPLER_SETTER_BEGIN;
  PetscCheck(mode >= HYLC_REFERENCE_AUTO && mode <= HYLC_REFERENCE_NONE, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_OUTOFRANGE, "Unknown reference mode %d", (int)mode);
  S->refmode = mode;
  PetscCall(PetscStrncpy(S->refout, output ? output : "", sizeof(S->refout)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the pattern set up, the plan resolved for its radius, the solver given the pattern and set up */
static PetscErrorCode SamplerSetUpSolver(HylcSampler S)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)S);
  HylcPattern pat;
  HylcMicro   micro;
  PetscReal   r;

  PetscFunctionBegin;
  PetscCall(HylcSamplerGetPattern(S, &pat));
  PetscCall(HylcSamplerGetMicro(S, &micro));
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcPatternGetRadius(pat, &r));
  PetscCall(HylcPlanRangesApply(comm, &S->ranges, r, &S->plan));
  S->plan.n1    = (int)S->n1;
  S->plan.n2    = (int)S->n2;
  S->plan.terms = (int)S->terms;
  PetscCall(HylcMicroSetPattern(micro, pat, &S->model));
  PetscCall(HylcMicroSetFromOptions(micro));
  PetscCall(HylcMicroSetUp(micro));
  S->nsamples = HylcPlanSize(&S->plan);
  PetscCheck(S->nsamples > 0, comm, PETSC_ERR_USER_INPUT, "The sampling plan is empty (-sampler_terms)");
  S->solverSetUp = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetFromOptions - Reads the options of the sampling job and of its pattern (-pattern_*), yarn
  model (-yarn_*), reference state (-reference_*) and solver (-micro_*). It only reads options: the pattern
  is loaded or generated and the solver set up by HylcSamplerSetUp(). (With -help it also sets them up,
  so that -help lists the solver's options, which exist only then: -periodic_*, -macro_*, -micro_snes_*.)

  Collective

  Input Parameter:
. S - the sampler

  Options Database Keys:
+ -sampler_output <samples.h5>    - the HDF5 output (its journal: <output>.journal) (HylcSamplerSetOutput())
. -sampler_resume                 - continue an interrupted run from its journal (refused if its settings differ) (HylcSamplerSetResume())
. -sampler_overwrite              - start over: replace an existing output and its journal (without either
                                    option an existing output or a journal holding samples is refused) (HylcSamplerSetOverwrite())
. -sampler_family <woven>         - default ranges of method-spec §8: woven, stockinette, honeycomb, rib (HylcSamplerSetPlanRanges())
. -sampler_range_<c> min,max      - 1D range of c = sx, sa, sy, II00, II11 (II in 1/m; 2D ranges follow) (HylcSamplerSetPlanRanges())
. -sampler_n1 <150>, -sampler_n2 <50> - samples per 1D term, per axis of a 2D term (HylcSamplerSetSampleCounts())
. -sampler_terms <all>            - comma list of terms: zero, sx, sa, sy, II00, II11, sx-sa, sx-sy,
                                    sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, or all (HylcSamplerSetTerms())
. -sampler_batch <1>              - samples per batch (the unit of work handed to a rank) (HylcSamplerSetBatchSize())
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
  PetscReal      progress = S->progress, density = S->density;
  PetscBool      resume = S->resume, overwrite = S->overwrite, tset, help;
  PetscEnum      mode   = (PetscEnum)S->refmode;
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
  PetscCall(HylcYarnModelSetFromOptions(comm, NULL, &model));
  PetscCall(HylcSamplerSetYarnModel(S, &model));
  PetscCall(HylcReferenceParamsSetFromOptions(comm, &S->refpar));
  PetscObjectOptionsBegin((PetscObject)S);
  PetscCall(PetscOptionsEnum("-sampler_reference", "Reference state (Algorithm C1): auto (compute for generated patterns, not for files), compute, none", "HylcSamplerSetReference", HylcReferenceModes, mode, &mode, NULL));
  PetscCall(PetscOptionsString("-reference_output", "Write the reference state as .pyp", "HylcSamplerSetReference", refout, refout, sizeof(refout), NULL));
  PetscCall(PetscOptionsString("-sampler_output", "HDF5 output file (the journal is <output>.journal)", "HylcSamplerSetOutput", output, output, sizeof(output), NULL));
  PetscCall(PetscOptionsBool("-sampler_resume", "Continue an interrupted run from its journal <output>.journal (refused, naming the differences, if any setting that changes results differs)", "HylcSamplerSetResume", resume, &resume, NULL));
  PetscCall(PetscOptionsBool("-sampler_overwrite", "Start over: replace an existing output and its journal (without -sampler_resume or this, an existing output or journal with samples is refused)", "HylcSamplerSetOverwrite", overwrite, &overwrite, NULL));
  PetscCall(HylcPlanRangesFromOptions(PetscOptionsObject, comm, "HylcSamplerSetPlanRanges", &ranges));
  PetscCall(PetscOptionsInt("-sampler_n1", "Samples per 1D term", "HylcSamplerSetSampleCounts", n1, &n1, NULL));
  PetscCall(PetscOptionsInt("-sampler_n2", "Samples per axis of a 2D term", "HylcSamplerSetSampleCounts", n2, &n2, NULL));
  PetscCall(PetscOptionsString("-sampler_terms", "Terms to sample: all, or a comma list of zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11", "HylcSamplerSetTerms", terms, terms, sizeof(terms), &tset));
  PetscCall(PetscOptionsInt("-sampler_batch", "Samples per batch (unit of work of a rank)", "HylcSamplerSetBatchSize", batch, &batch, NULL));
  PetscCall(PetscOptionsReal("-sampler_progress", "Seconds between progress lines", "HylcSamplerSetProgressInterval", progress, &progress, NULL));
  PetscCall(PetscOptionsString("-sampler_export_raw", "Also write the paper's raw layout into this directory: data.txt (rows sx sa sy II00 II01 II11 Psi in the order of C4) and info.txt (area, area density)", "HylcSamplerSetExportRaw", rawdir, rawdir, sizeof(rawdir), NULL));
  PetscCall(PetscOptionsReal("-sampler_density", "Volumetric yarn density for the area density of info.txt (kg/m^3; <= 0: 0.12 kg/m^2 / r, as hylc-fit)", "HylcSamplerSetExportRaw", density, &density, NULL));
  PetscCall(PetscOptionsName("-sampler_view", "Print the sampling job after its set-up", "HylcSamplerView", NULL));
  PetscOptionsEnd();
  PetscCall(HylcSamplerSetReference(S, (HylcReferenceMode)mode, refout));
  PetscCall(HylcSamplerSetOutput(S, output));
  PetscCall(HylcSamplerSetResume(S, resume));
  PetscCall(HylcSamplerSetOverwrite(S, overwrite));
  PetscCall(HylcSamplerSetPlanRanges(S, &ranges));
  PetscCall(HylcSamplerSetSampleCounts(S, n1, n2));
  PetscCall(HylcSamplerSetBatchSize(S, batch));
  PetscCall(HylcSamplerSetProgressInterval(S, progress));
  PetscCall(HylcSamplerSetExportRaw(S, rawdir, density));
  if (tset) {
    int mask;
    PetscCall(HylcPlanTermsFromString(comm, "-sampler_terms", terms, &mask));
    PetscCall(HylcSamplerSetTerms(S, (PetscInt)mask));
  }
  PetscCall(HylcSamplerGetMicro(S, &micro));
  PetscCall(HylcMicroSetFromOptions(micro));
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) PetscCall(SamplerSetUpSolver(S));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0, before any solve: every output path writable and none of them an input, the existing output
   and journal as the mode allows, then the journal locked and opened (resume: the identity checked) */
static PetscErrorCode CheckOutputsAndLock(HylcSampler S)
{
  char        jpath[PETSC_MAX_PATH_LEN + 16], pfile[PETSC_MAX_PATH_LEN] = "", raw[2][PETSC_MAX_PATH_LEN + 16];
  PetscBool   haspf = PETSC_FALSE;
  struct stat st;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(jpath, sizeof(jpath), "%s.journal", S->output));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-pattern_file", pfile, sizeof(pfile), &haspf));
  PetscCall(HylcFileCheckOutput(PETSC_COMM_SELF, S->output, "-sampler_output"));
  PetscCall(HylcFileCheckOutput(PETSC_COMM_SELF, jpath, "the journal of -sampler_output"));
  PetscCall(HylcFileCheckDistinct(PETSC_COMM_SELF, S->output, "-sampler_output", pfile, "-pattern_file"));
  PetscCall(HylcFileCheckDistinct(PETSC_COMM_SELF, jpath, "the journal of -sampler_output", pfile, "-pattern_file"));
  if (S->refout[0]) {
    PetscCall(HylcFileCheckOutput(PETSC_COMM_SELF, S->refout, "-reference_output"));
    PetscCall(HylcFileCheckDistinct(PETSC_COMM_SELF, S->refout, "-reference_output", pfile, "-pattern_file"));
    PetscCall(HylcFileCheckDistinct(PETSC_COMM_SELF, S->refout, "-reference_output", S->output, "-sampler_output"));
    PetscCall(HylcFileCheckDistinct(PETSC_COMM_SELF, S->refout, "-reference_output", jpath, "the journal of -sampler_output"));
    PetscCheck(strcmp(S->refout, S->output) && strcmp(S->refout, jpath), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-reference_output %s is the samples file or its journal", S->refout);
  }
  if (S->rawdir[0]) {
    PetscCheck(stat(S->rawdir, &st) == 0 && S_ISDIR(st.st_mode), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write into -sampler_export_raw %s: %s", S->rawdir, stat(S->rawdir, &st) ? "no such directory (create it first)" : "not a directory");
    PetscCall(PetscSNPrintf(raw[0], sizeof(raw[0]), "%s/data.txt", S->rawdir));
    PetscCall(PetscSNPrintf(raw[1], sizeof(raw[1]), "%s/info.txt", S->rawdir));
    for (int i = 0; i < 2; i++) {
      PetscCall(HylcFileCheckOutput(PETSC_COMM_SELF, raw[i], "-sampler_export_raw"));
      PetscCall(HylcFileCheckDistinct(PETSC_COMM_SELF, raw[i], "-sampler_export_raw", pfile, "-pattern_file"));
    }
  }
  if (!S->resume && !S->overwrite) PetscCheck(access(S->output, F_OK) != 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Output %s exists: start over with -sampler_overwrite, or continue its run with -sampler_resume", S->output);
  if (S->resume) PetscCheck(access(S->output, F_OK) != 0 || access(jpath, F_OK) == 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-sampler_resume: output %s exists but its journal %s does not, so there is no run to continue: start over with -sampler_overwrite", S->output, jpath);
  PetscCall(HylcSamplesIdentity(S->pat, &S->identity));
  PetscCall(HylcJournalOpen(jpath, S->resume ? HYLC_JOURNAL_RESUME : (S->overwrite ? HYLC_JOURNAL_OVERWRITE : HYLC_JOURNAL_NEW), S->nsamples, S->identity, &S->journal));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetUp - Loads or generates the pattern, resolves the plan for its yarn radius and sets up the
  solver. Then, before any solve: refuses unknown options, checks every output path (writable, not a
  directory, not an input), locks and opens the journal (a resume with other settings is refused here,
  naming them); the verdict of rank 0 is shared, so every rank raises the same error. Then computes the
  reference state when asked for (Algorithm C1). -sampler_view prints the job at the end.

  Collective

  Input Parameter:
. S - the sampler

  Level: beginner

.seealso: HylcSamplerSetFromOptions(), HylcSamplerRun()
@*/
PetscErrorCode HylcSamplerSetUp(HylcSampler S)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)S);
  HylcPatternType type;
  PetscBool       isfile;
  int             code      = 0;
  char            msg[2048] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  if (S->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  if (!S->solverSetUp) PetscCall(SamplerSetUpSolver(S));
  PetscCall(HylcCheckOptionsUsed(comm));
  PetscCheck(!(S->resume && S->overwrite), comm, PETSC_ERR_USER_INPUT, "-sampler_resume (continue the run) and -sampler_overwrite (start over) exclude each other");
  if (!S->rank) {
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CheckOutputsAndLock(S);
    PetscCall(PetscPopErrorHandler());
    if (ierr) {
      char *text = NULL;
      code       = (int)ierr;
      PetscCall(PetscErrorMessage(ierr, NULL, &text));
      PetscCall(PetscStrncpy(msg, text && text[0] ? text : "checking the outputs failed", sizeof(msg)));
    }
  }
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, 0, comm));
  if (code) {
    PetscCallMPI(MPI_Bcast(msg, (PetscMPIInt)sizeof(msg), MPI_CHAR, 0, comm));
    SETERRQ(comm, (PetscErrorCode)code, "%s", msg);
  }
  PetscCall(HylcPatternGetType(S->pat, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  if (S->refmode == HYLC_REFERENCE_COMPUTE || (S->refmode == HYLC_REFERENCE_AUTO && !isfile)) {
    HylcPattern ref;
    PetscCall(HylcReferenceStateCompute(S->pat, &S->model, &S->refpar, S->rank ? NULL : PETSC_VIEWER_STDOUT_SELF, &ref));
    PetscCall(HylcPatternDestroy(&S->pat));
    S->pat = ref;
    PetscCall(HylcMicroSetPattern(S->micro, S->pat, &S->model));
    PetscCall(HylcMicroSetFromOptions(S->micro));
  }
  if (S->refout[0]) PetscCall(HylcPatternWrite(S->pat, S->refout));
  S->setupcalled = PETSC_TRUE;
  PetscCall(HylcSamplerViewFromOptions(S, NULL, "-sampler_view"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerGetPlan - The sampling plan (its ranges resolved by HylcSamplerSetUp()).

  Not collective

  Input Parameter:
. S - the sampler

  Output Parameter:
. plan - the plan (borrowed)

  Level: intermediate
@*/
PetscErrorCode HylcSamplerGetPlan(HylcSampler S, const HylcPlan **plan)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscCheck(S->solverSetUp, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_WRONGSTATE, "Call HylcSamplerSetUp() first (the plan's ranges depend on the yarn radius)");
  *plan = &S->plan;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerView - Prints the sampling job: output and journal mode, plan (family, samples per term, terms,
  number of samples after the set-up), batch size, reference state, ranks.

  Collective

  Input Parameters:
+ S      - the sampler
- viewer - an ASCII viewer (NULL: stdout of the sampler's communicator)

  Level: beginner

.seealso: HylcSamplerViewFromOptions()
@*/
PetscErrorCode HylcSamplerView(HylcSampler S, PetscViewer viewer)
{
  PetscBool iascii;
  char      terms[256] = "", count[64];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)S), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  for (int t = 0; t < HYLC_PLAN_NTERM; t++)
    if (S->terms & (1 << t)) {
      PetscCall(PetscStrlcat(terms, terms[0] ? "," : "", sizeof(terms)));
      PetscCall(PetscStrlcat(terms, HylcPlanTermName(t), sizeof(terms)));
    }
  {
    const char *prefix = ((PetscObject)S)->prefix;
    PetscCall(PetscViewerASCIIPrintf(viewer, "HylcSampler Object%s%s%s: %d MPI process%s\n", prefix ? " (" : "", prefix ? prefix : "", prefix ? ")" : "", (int)S->size, S->size > 1 ? "es" : ""));
  }
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "output %s (journal %s.journal, %s)\n", S->output, S->output, S->resume ? "resume" : (S->overwrite ? "overwrite" : "new run")));
  if (S->solverSetUp)
    PetscCall(PetscSNPrintf(count, sizeof(count), ": %ld samples", S->nsamples));
  else
    PetscCall(PetscStrncpy(count, " (ranges not resolved: not set up)", sizeof(count)));
  PetscCall(PetscViewerASCIIPrintf(viewer, "plan: family %s, %" PetscInt_FMT " samples per 1D term, %" PetscInt_FMT " per 2D axis, terms %s%s\n", HylcPlanFamilies[S->ranges.family], S->n1, S->n2, terms, count));
  PetscCall(PetscViewerASCIIPrintf(viewer, "%d ranks, batches of %" PetscInt_FMT ", progress every %g s, reference state %s%s%s\n", (int)S->size, S->batch, (double)S->progress, HylcReferenceModes[S->refmode], S->refout[0] ? " written to " : "", S->refout));
  if (S->rawdir[0]) PetscCall(PetscViewerASCIIPrintf(viewer, "raw layout exported to %s\n", S->rawdir));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerViewFromOptions - Views the sampler if the option name (e.g. -sampler_view) is set.

  Collective

  Input Parameters:
+ S    - the sampler
. obj  - an object whose prefix is used (NULL: the sampler's)
- name - the option

  Level: intermediate

.seealso: HylcSamplerView()
@*/
PetscErrorCode HylcSamplerViewFromOptions(HylcSampler S, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)S, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SolveSample(HylcSampler S, long k, HylcSampleRecord *rec)
{
  HylcMicroResult r;
  double          z[6];
  int             term;

  PetscFunctionBegin;
  PetscCheck(!HylcPlanSample(&S->plan, k, z, &term), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Sample %ld outside the plan", k);
  PetscCall(HylcMicroSolve(S->micro, z, &r));
  PetscCall(PetscMemzero(rec, sizeof(*rec)));
  rec->index      = k;
  rec->term       = term;
  rec->status     = (int)r.status;
  rec->iterations = (int)r.iterations;
  rec->retries    = (int)r.retries;
  for (int i = 0; i < 6; i++) rec->z[i] = z[i];
  rec->psi = r.psi;
  for (int i = 0; i < 4; i++) rec->parts[i] = r.parts[i];
  rec->residual  = r.residual;
  rec->cresidual = r.cresidual;
  rec->time      = r.time;
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  long           done, total, failed, converged0;
  PetscLogDouble t0, last;
} Progress;

static PetscErrorCode Report(HylcSampler S, Progress *pg, PetscBool force)
{
  PetscLogDouble now;

  PetscFunctionBegin;
  PetscCall(PetscTime(&now));
  if (!force && now - pg->last < S->progress) PetscFunctionReturn(PETSC_SUCCESS);
  pg->last               = now;
  const double rate      = (pg->done - pg->converged0) / PetscMax(now - pg->t0, 1e-9);
  const double remaining = rate > 0 ? (pg->total - pg->done) / rate : 0;
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] %ld/%ld samples (%.1f%%), %ld not converged, %.2f samples/s, ETA %.0f s\n", pg->done, pg->total, 100.0 * pg->done / PetscMax(pg->total, 1), pg->failed, rate, remaining));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0: receive whatever records have arrived, append them to the journal */
static PetscErrorCode Drain(HylcSampler S, HylcJournal J, Progress *pg, PetscInt *finished, PetscBool wait)
{
  HylcSampleRecord *buf;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(S->batch, &buf));
  for (;;) {
    PetscMPIInt flag, count;
    MPI_Status  st;
    if (wait) {
      PetscCallMPI(MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, PetscObjectComm((PetscObject)S), &st));
      flag = 1;
    } else
      PetscCallMPI(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, PetscObjectComm((PetscObject)S), &flag, &st));
    if (!flag) break;
    if (st.MPI_TAG == TAG_DONE) {
      int dummy;
      PetscCallMPI(MPI_Recv(&dummy, 1, MPI_INT, st.MPI_SOURCE, TAG_DONE, PetscObjectComm((PetscObject)S), MPI_STATUS_IGNORE));
      (*finished)++;
    } else {
      PetscCallMPI(MPI_Get_count(&st, MPI_BYTE, &count));
      const PetscInt n = count / (PetscMPIInt)sizeof(HylcSampleRecord);
      PetscCallMPI(MPI_Recv(buf, count, MPI_BYTE, st.MPI_SOURCE, TAG_RECORDS, PetscObjectComm((PetscObject)S), MPI_STATUS_IGNORE));
      PetscCall(HylcJournalAppend(J, buf, n));
      for (PetscInt i = 0; i < n; i++) pg->failed += buf[i].status != HYLC_MICRO_CONVERGED;
      pg->done += n;
    }
    if (wait) break;
  }
  PetscCall(PetscFree(buf));
  PetscCall(Report(S, pg, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the raw layout of the paper's fitting scripts: data.txt rows "sx sa sy II00 II01 II11 Psi" in the order of
   C4 (the 1D terms, then the 2D terms; the zero sample is not a row), info.txt with the tile area (m^2)
   and the area density (kg/m^2) */
static PetscErrorCode ExportRaw(HylcSampler S, const HylcSampleRecord *all, const unsigned char *done)
{
  char      path[PETSC_MAX_PATH_LEN + 16], tmp[PETSC_MAX_PATH_LEN + 32];
  FILE     *fp;
  PetscReal px, py, rhoA;
  long      rows = 0, skipped = 0;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/data.txt", S->rawdir));
  PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
  for (long k = 0; k < S->nsamples; k++) {
    if (!done[k] || all[k].term == 0) continue;
    if (all[k].status != HYLC_MICRO_CONVERGED) skipped++;
    fprintf(fp, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", all[k].z[0], all[k].z[1], all[k].z[2], all[k].z[3], all[k].z[4], all[k].z[5], all[k].psi);
    rows++;
  }
  PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  PetscCall(HylcPatternGetPeriods(S->pat, &px, &py));
  PetscCall(HylcPatternGetAreaDensity(S->pat, S->density, &rhoA));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/info.txt", S->rawdir));
  PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
  fprintf(fp, "area %.17g\ndensity %.17g\n", (double)(px * py), (double)rhoA);
  PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] wrote %s/data.txt (%ld rows%s) and info.txt\n", S->rawdir, rows, skipped ? ", some not converged: see /samples/status" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerRun - Solves every sample of the plan not yet in the journal, gathers the records on rank 0
  and writes the HDF5 output (and the raw layout of -sampler_export_raw).

  Collective

  Input Parameter:
. S - the sampler, set up

  Level: beginner

.seealso: HylcSamplerSetUp()
@*/
PetscErrorCode HylcSamplerRun(HylcSampler S)
{
  char              jpath[PETSC_MAX_PATH_LEN + 16];
  HylcJournal       J = S->journal;
  unsigned char    *done;
  HylcSampleRecord *recs;
  Progress          pg;
  PetscInt          finished = 0;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscCheck(S->setupcalled, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_WRONGSTATE, "Call HylcSamplerSetUp() first");
  PetscCall(PetscLogEventBegin(HYLC_SamplerRun, S, 0, 0, 0));
  PetscCall(PetscSNPrintf(jpath, sizeof(jpath), "%s.journal", S->output));
  PetscCheck(S->rank || J, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcSamplerSetUp() first");
  PetscCall(PetscFree2(S->done, S->recs));
  PetscCall(PetscMalloc2(S->nsamples + 1, &S->done, S->batch, &S->recs));
  done = S->done;
  recs = S->recs;
  PetscCall(PetscArrayzero(done, S->nsamples + 1));
  PetscCall(PetscMemzero(&pg, sizeof(pg)));
  pg.total = S->nsamples;
  if (!S->rank) {
    const unsigned char *jd;
    PetscInt             nd;
    PetscCall(HylcJournalGetDone(J, &nd, &jd));
    PetscCall(PetscArraycpy(done, jd, S->nsamples));
    pg.done = pg.converged0 = nd;
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] %ld samples in %ld batches on %d ranks; %ld already done (%s)\n", S->nsamples, (S->nsamples + S->batch - 1) / S->batch, (int)S->size, (long)nd, jpath));
  }
  PetscCallMPI(MPI_Bcast(done, (PetscMPIInt)S->nsamples, MPI_UNSIGNED_CHAR, 0, PetscObjectComm((PetscObject)S)));
  PetscCall(PetscTime(&pg.t0));
  pg.last = pg.t0;
  /* dynamic scheduling: the next batch comes from a shared counter on rank 0 (MPI one-sided atomic
     fetch-and-add, no involvement of rank 0); which rank solves a sample does not change its result */
  const long nb      = (S->nsamples + S->batch - 1) / S->batch;
  long      *counter = NULL, one = 1, b;
  MPI_Win    win;
  PetscCallMPI(MPI_Win_allocate(S->rank ? 0 : (MPI_Aint)sizeof(long), sizeof(long), MPI_INFO_NULL, PetscObjectComm((PetscObject)S), &counter, &win));
  if (!S->rank) *counter = 0;
  PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)S)));
  PetscCallMPI(MPI_Win_lock_all(0, win));
  for (;;) {
    PetscCallMPI(MPI_Fetch_and_op(&one, &b, MPI_LONG, 0, 0, MPI_SUM, win));
    PetscCallMPI(MPI_Win_flush(0, win));
    if (b >= nb) break;
    PetscInt n = 0;
    for (long k = b * S->batch; k < PetscMin((b + 1) * S->batch, S->nsamples); k++) {
      if (done[k]) continue;
      PetscCall(SolveSample(S, k, &recs[n++]));
      if (!S->rank) PetscCall(Drain(S, J, &pg, &finished, PETSC_FALSE));
    }
    if (!n) continue;
    if (S->rank)
      PetscCallMPI(MPI_Send(recs, (PetscMPIInt)(n * sizeof(HylcSampleRecord)), MPI_BYTE, 0, TAG_RECORDS, PetscObjectComm((PetscObject)S)));
    else {
      PetscCall(HylcJournalAppend(J, recs, n));
      for (PetscInt i = 0; i < n; i++) pg.failed += recs[i].status != HYLC_MICRO_CONVERGED;
      pg.done += n;
      PetscCall(Report(S, &pg, PETSC_FALSE));
    }
  }
  PetscCallMPI(MPI_Win_unlock_all(win));
  if (S->rank) {
    int fin = 1;
    PetscCallMPI(MPI_Send(&fin, 1, MPI_INT, 0, TAG_DONE, PetscObjectComm((PetscObject)S)));
  } else {
    while (finished < S->size - 1) PetscCall(Drain(S, J, &pg, &finished, PETSC_TRUE));
    PetscCall(Report(S, &pg, PETSC_TRUE));
    /* the HDF5 file from the journal: every sample of the plan, failures included */
    const HylcSampleRecord *all;
    const unsigned char    *jd;
    PetscInt                nd;
    char                   *opts = NULL;
    PetscErrorCode          ierr;
    PetscCall(HylcJournalGetDone(J, &nd, &jd));
    PetscCall(HylcJournalGetRecords(J, &all));
    PetscCall(PetscOptionsGetAll(NULL, &opts));
    ierr = HylcSamplesWriteHDF5WithIdentity(S->output, S->nsamples, all, jd, S->pat, &S->model, opts, S->identity);
    PetscCall(PetscFree(opts));
    PetscCall(ierr);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] wrote %s: %ld samples, %ld not converged\n", S->output, (long)nd, pg.failed));
    if (S->rawdir[0]) PetscCall(ExportRaw(S, all, jd));
    PetscCall(HylcJournalClose(&S->journal));
  }
  PetscCall(PetscFree2(S->done, S->recs));
  PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)S)));
  PetscCallMPI(MPI_Win_free(&win));
  PetscCall(PetscLogEventEnd(HYLC_SamplerRun, S, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
