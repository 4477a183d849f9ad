#pragma once
/* Private definition of HylcSampler (src/sampler/ only). The object is split by job, as SLEPc's modules:
     sampler.c  lifecycle, sub-objects (lazy getters), View
     opts.c     setters and HylcSamplerSetFromOptions
     run.c      HylcSamplerSetUp (pattern, plan, solver, output checks, journal, reference state), HylcSamplerRun */
#include <hylc/sampler.h>
#include <hylc/reference.h>
#include <petsc/private/petscimpl.h>

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
  HylcSamplerStart    start;    /* -sampler_start */
  PetscReal           bothRtol; /* -sampler_both_rtol */
  PetscBool           stress;   /* -sampler_stress: record dPsi/dz of each converged sample */
  PetscReal           progress; /* seconds between progress lines */
  long                nsamples;
  HylcReferenceMode   refmode;
  HylcReferenceParams refpar;
  char                refout[PETSC_MAX_PATH_LEN];
  char                rawdir[PETSC_MAX_PATH_LEN]; /* export of the paper's raw layout (data.txt, info.txt) */
  PetscReal           density;                    /* volumetric yarn density for info.txt (kg/m^3) */
  PetscBool           solverSetUp, setupcalled;
};

/* the pattern set up, the plan resolved for its radius, the solver given the pattern and set up (run.c) */
PETSC_INTERN PetscErrorCode HylcSamplerSetUpSolver_Private(HylcSampler);
