#pragma once
/* HylcSampler: the sampling job of Algorithm C4 over MPI (the main program, hylc-sample).
   Every rank takes batches of the plan's samples from a shared counter (dynamic scheduling by MPI
   one-sided fetch-and-add) and solves them with one HylcMicro on PETSC_COMM_SELF; with -sampler_start cold
   each from u~ = 0, so results do not depend on the number of ranks.
   With -sampler_start continue (the default) or both, the unit of work is a half-line of the plan
   (HylcPlanUnits), solved whole by one rank, each sample from its predecessor's equilibrium (both: and
   cold): results still do not depend on the ranks.
   Rank 0 gathers the records as they arrive, appends them to a journal (survives SIGKILL; -sampler_resume
   continues without recomputing finished samples), reports progress, and writes the HDF5 file at the end
   (docs/output-format.md). A sample that fails is recorded with its status, never dropped. */
#include <hylc/samples.h>
#include <hylc/reference.h>

typedef struct _p_HylcSampler *HylcSampler;

/* Registration: the class id and log events of this stage (HylcSamplerInitializePackage(), called by HylcSamplerCreate()). */
PETSC_EXTERN PetscClassId   HYLC_SAMPLER_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_SamplerRun;
PETSC_EXTERN PetscErrorCode HylcSamplerInitializePackage(void);

/* lifecycle and work (src/sampler/sampler.c; each function's manual block there) */
PETSC_EXTERN PetscErrorCode HylcSamplerCreate(MPI_Comm, HylcSampler *);
PETSC_EXTERN PetscErrorCode HylcSamplerDestroy(HylcSampler *);
PETSC_EXTERN PetscErrorCode HylcSamplerSetOptionsPrefix(HylcSampler, const char[]);
PETSC_EXTERN PetscErrorCode HylcSamplerSetFromOptions(HylcSampler);
PETSC_EXTERN PetscErrorCode HylcSamplerSetUp(HylcSampler);
PETSC_EXTERN PetscErrorCode HylcSamplerRun(HylcSampler);
PETSC_EXTERN PetscErrorCode HylcSamplerView(HylcSampler, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcSamplerViewFromOptions(HylcSampler, PetscObject, const char[]);
/* sub-objects, created on first use (the pattern on the sampler's communicator, the solver on PETSC_COMM_SELF) */
PETSC_EXTERN PetscErrorCode HylcSamplerGetPattern(HylcSampler, HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcSamplerGetMicro(HylcSampler, HylcMicro *);
PETSC_EXTERN PetscErrorCode HylcSamplerGetPlan(HylcSampler, const HylcPlan **);
/* setters of the options */
PETSC_EXTERN PetscErrorCode HylcSamplerSetYarnModel(HylcSampler, const HylcYarnModel *);
PETSC_EXTERN PetscErrorCode HylcSamplerSetOutput(HylcSampler, const char[]);
PETSC_EXTERN PetscErrorCode HylcSamplerSetResume(HylcSampler, PetscBool);
PETSC_EXTERN PetscErrorCode HylcSamplerSetOverwrite(HylcSampler, PetscBool);
PETSC_EXTERN PetscErrorCode HylcSamplerSetPlanRanges(HylcSampler, const HylcPlanRanges *);
PETSC_EXTERN PetscErrorCode HylcSamplerSetSampleCounts(HylcSampler, PetscInt, PetscInt);
PETSC_EXTERN PetscErrorCode HylcSamplerSetTerms(HylcSampler, PetscInt);
PETSC_EXTERN PetscErrorCode HylcSamplerSetBatchSize(HylcSampler, PetscInt);
/* -sampler_start: cold (every sample from u~ = 0), continue (half-lines from the zero strain outward, each
   sample from its predecessor's equilibrium; HylcPlanUnits) or both (every sample from both starts, the
   lower Psi kept, the other recorded: a map of where the tile is multistable) */
typedef enum { HYLC_SAMPLER_START_COLD = 0, HYLC_SAMPLER_START_CONTINUE = 1, HYLC_SAMPLER_START_BOTH = 2 } HylcSamplerStart;
PETSC_EXTERN const char *const HylcSamplerStarts[];
PETSC_EXTERN PetscErrorCode    HylcSamplerSetStart(HylcSampler, HylcSamplerStart);
PETSC_EXTERN PetscErrorCode    HylcSamplerSetBothTolerance(HylcSampler, PetscReal);
PETSC_EXTERN PetscErrorCode    HylcSamplerSetStress(HylcSampler, PetscBool);
PETSC_EXTERN PetscErrorCode    HylcSamplerSetProgressInterval(HylcSampler, PetscReal);
PETSC_EXTERN PetscErrorCode    HylcSamplerSetExportRaw(HylcSampler, const char[], PetscReal);
PETSC_EXTERN PetscErrorCode    HylcSamplerSetReference(HylcSampler, HylcReferenceMode, const char[]);
