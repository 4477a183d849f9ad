#pragma once
/* HylcSampler: the sampling job of Algorithm C4 over MPI (the main program, hylc-sample).
   Every rank takes batches of the plan's samples from a shared counter (dynamic scheduling by MPI
   one-sided fetch-and-add) and solves them with one HylcMicro on PETSC_COMM_SELF, each from u~ = 0, so results do not depend on the number of ranks.
   Rank 0 gathers the records as they arrive, appends them to a journal (survives SIGKILL; -sampler_resume
   continues without recomputing finished samples), reports progress, and writes the HDF5 file at the end
   (docs/output-format.md). A sample that fails is recorded with its status, never dropped. */
#include <hylc/samples.h>

typedef struct _n_HylcSampler *HylcSampler;

PETSC_EXTERN PetscErrorCode HylcSamplerCreate(MPI_Comm, HylcSampler *);
PETSC_EXTERN PetscErrorCode HylcSamplerDestroy(HylcSampler *);
PETSC_EXTERN PetscErrorCode HylcSamplerSetFromOptions(HylcSampler);
PETSC_EXTERN PetscErrorCode HylcSamplerSetUp(HylcSampler);
PETSC_EXTERN PetscErrorCode HylcSamplerRun(HylcSampler);
PETSC_EXTERN PetscErrorCode HylcSamplerGetPlan(HylcSampler, const HylcPlan **);

/* The plan's options, shared by hylc-sample and hylc-calibrate (src/sampler/planopts.c): family names,
   -sampler_family and -sampler_range_<c> inside a PetscOptionsBegin/End block (ranges checked), and a term
   list ("all", "1d" or comma-separated names). Collective. */
PETSC_EXTERN const char *const HylcPlanFamilies[];
PETSC_EXTERN PetscErrorCode    HylcPlanRangesFromOptions(PetscOptionItems *, MPI_Comm, PetscReal, const char[], HylcPlan *);
PETSC_EXTERN PetscErrorCode    HylcPlanTermsFromString(MPI_Comm, const char[], const char[], int *);
