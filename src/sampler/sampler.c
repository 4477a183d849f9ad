/* HylcSampler: lifecycle, sub-objects, View (include/hylc/sampler.h). */
#include "samplerimpl.h"

PetscClassId  HYLC_SAMPLER_CLASSID;
PetscLogEvent HYLC_SamplerRun;

static PetscBool HylcSamplerPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcSamplerFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcSamplerPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerInitializePackage - Registers the class id HylcSampler and its log events (SAMPLER_Run). Called by
  HylcSamplerCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcSamplerInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcSamplerPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcSamplerPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcSampler", &HYLC_SAMPLER_CLASSID));
  PetscCall(PetscLogEventRegister("SAMPLER_Run", HYLC_SAMPLER_CLASSID, &HYLC_SamplerRun));
  PetscCall(PetscRegisterFinalize(HylcSamplerFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

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
  PetscCall(HylcSamplerInitializePackage());
  PetscCall(PetscHeaderCreate(S, HYLC_SAMPLER_CLASSID, "HylcSampler", "Sampling job", "Sampler", comm, HylcSamplerDestroy, HylcSamplerView));
  PetscCallMPI(MPI_Comm_rank(comm, &S->rank));
  PetscCallMPI(MPI_Comm_size(comm, &S->size));
  PetscCall(PetscStrncpy(S->output, "samples.h5", sizeof(S->output)));
  S->n1             = 150;
  S->n2             = 50;
  S->terms          = HYLC_PLAN_ALL_TERMS;
  S->batch          = 1;
  S->progress       = 5;
  S->start          = HYLC_SAMPLER_START_CONTINUE;
  S->bothRtol       = 1e-3;
  S->stress         = PETSC_TRUE;
  S->density        = 0;
  S->ranges.spacing = HYLC_PLAN_SPACING_GRADED; /* the fabric fit's knots (-sampler_spacing) */
  S->refmode        = HYLC_REFERENCE_AUTO;
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
  PetscCall(PetscFree((*s)->done));
  PetscCall(PetscFree((*s)->recs));
  PetscCall(HylcMicroDestroy(&(*s)->micro));
  PetscCall(HylcPatternDestroy(&(*s)->pat));
  PetscCall(PetscHeaderDestroy(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetOptionsPrefix - Sets the prefix of the sampler's options and of its sub-objects'
  (-<prefix>sampler_*, -<prefix>pattern_*, -<prefix>yarn_*, -<prefix>reference_*, -<prefix>micro_* with the
  solver's tile -<prefix>periodic_*, -<prefix>macro_*).

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
  if (S->pat) PetscCall(HylcPatternSetOptionsPrefix(S->pat, prefix));
  if (S->micro) PetscCall(HylcMicroSetOptionsPrefix(S->micro, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerGetPattern - The sampler's pattern, created (unset, with the sampler's prefix) on first use; HylcSamplerSetFromOptions()
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
  if (!S->pat) {
    PetscCall(HylcPatternCreate(PetscObjectComm((PetscObject)S), &S->pat));
    PetscCall(HylcPatternSetOptionsPrefix(S->pat, ((PetscObject)S)->prefix));
  }
  *pat = S->pat;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerGetMicro - The solver of this rank's samples (on PETSC_COMM_SELF), created with the sampler's prefix on first use;
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
  if (!S->micro) {
    PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &S->micro));
    PetscCall(HylcMicroSetOptionsPrefix(S->micro, ((PetscObject)S)->prefix));
  }
  *micro = S->micro;
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
  char      terms[512] = "", count[64];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)S), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  for (int t = 0; t < HYLC_PLAN_NTERM3; t++)
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
  if (S->ranges.spacing == HYLC_PLAN_SPACING_GRADED) {
    HylcPlan p;
    PetscCheck(!HylcPlanDefaults(HylcPlanFamilies[S->ranges.family], 1, &p), PETSC_COMM_SELF, PETSC_ERR_PLIB, "family");
    if (S->setupcalled) p = S->plan;
    PetscCall(PetscViewerASCIIPrintf(viewer, "plan: family %s, graded spacing (h0 %g %g %g %g %g 1/m%s, growth %g, hmax %g of the range, %d samples per knot interval), terms %s%s\n", HylcPlanFamilies[S->ranges.family], p.h0[0], p.h0[1], p.h0[2],
                                     p.h0[3], p.h0[4], S->setupcalled ? "" : " at r = 1 mm", p.growth, p.hmax, p.sub, terms, count));
  } else
    PetscCall(PetscViewerASCIIPrintf(viewer, "plan: family %s, paper spacing, %" PetscInt_FMT " samples per 1D term, %" PetscInt_FMT " per 2D axis, terms %s%s\n", HylcPlanFamilies[S->ranges.family], S->n1, S->n2, terms, count));
  if (S->start == HYLC_SAMPLER_START_BOTH)
    PetscCall(PetscViewerASCIIPrintf(viewer, "start: both (units: half-lines from the zero strain outward; every sample also cold, the lower Psi kept, multistable where they differ by more than %g)\n", (double)S->bothRtol));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "start: %s%s\n", HylcSamplerStarts[S->start], S->start == HYLC_SAMPLER_START_CONTINUE ? " (units: half-lines from the zero strain outward)" : " (every sample from u~ = 0)"));
  PetscCall(PetscViewerASCIIPrintf(viewer, "%d ranks, batches of %" PetscInt_FMT ", progress every %g s, reference state %s%s%s\n", (int)S->size, S->batch, (double)S->progress, HylcReferenceModes[S->refmode], S->refout[0] ? " written to " : "",
                                   S->refout));
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
