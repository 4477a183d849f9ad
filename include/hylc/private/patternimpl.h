#pragma once
/* Private definition of HylcPattern: only src/ may include this. */
#include <hylc/pattern.h>
#include <petsc/private/petscimpl.h>

struct _HylcPatternOps {
  PetscErrorCode (*view)(HylcPattern, PetscViewer);
};

struct _p_HylcPattern {
  PETSCHEADER(struct _HylcPatternOps);
  /* source */
  char                 filename[PETSC_MAX_PATH_LEN]; /* .pyp file (type "file") */
  HylcPatternGenParams gen;                          /* generator parameters */
  PetscBool            setupcalled;
  PetscBool            hasdata;
  PetscReal            viewDensity;       /* volumetric density used by the summary (kg/m^3) */
  PetscReal            viewExcludeArc;    /* same-yarn exclusion arc for the summary's distance (units of r) */
  PetscBool            consistentPeriods; /* loader: replace the stored periods by those the periodic edges' rest lengths imply */
  HylcPatternState     state;             /* reference, generated, equilibrium, or unrecorded (a file without the record) */
  /* data */
  PetscInt   nv;
  PetscReal  px, py, radius;
  PetscReal *X, *theta, *restLength, *restKappa, *restTwist, *refD1, *refTwist;
  PetscInt  *next, *prev, *shift;
  /* yarn loops (derived) */
  PetscInt   nloops;
  PetscInt  *loopStart; /* nloops+1 offsets into loopVerts */
  PetscInt  *loopVerts; /* vertices of each loop in yarn order */
  PetscInt  *winding;   /* 2 per loop */
  PetscInt  *vertLoop;  /* loop of each vertex */
  PetscInt  *vertPos;   /* position of each vertex inside its loop */
  PetscInt  *vertCum;   /* 2 per vertex: lattice shift accumulated along its loop from the loop start */
  PetscReal *loopArc;   /* loopStart-indexed cumulative rest length: arc from the loop start to vertex k */
  PetscReal *loopLen;   /* rest length of each loop */
};

/* Builds the loops (cycles of next[]) and derived data; validates the connectivity. */
PETSC_INTERN PetscErrorCode HylcPatternBuildLoops_Private(HylcPattern);
/* Frees the data arrays. */
PETSC_INTERN PetscErrorCode HylcPatternReset_Private(HylcPattern);
/* Allocates the data arrays for nv vertices. */
PETSC_INTERN PetscErrorCode HylcPatternAllocate_Private(HylcPattern, PetscInt);
/* The built-in generators (generate.c: wovens; knitgen.c: knits), registered by HylcPatternRegisterAll() */
PETSC_INTERN PetscErrorCode HylcPatternGeneratePlain_Private(HylcPattern, const HylcPatternGenParams *);
PETSC_INTERN PetscErrorCode HylcPatternGenerateBasket_Private(HylcPattern, const HylcPatternGenParams *);
PETSC_INTERN PetscErrorCode HylcPatternGenerateTwill_Private(HylcPattern, const HylcPatternGenParams *);
PETSC_INTERN PetscErrorCode HylcPatternGenerateSatin_Private(HylcPattern, const HylcPatternGenParams *);
PETSC_INTERN PetscErrorCode HylcPatternGenerateStockinette_Private(HylcPattern, const HylcPatternGenParams *);
PETSC_INTERN PetscErrorCode HylcPatternGenerateRib_Private(HylcPattern, const HylcPatternGenParams *);
/* The registry (registry.c): the source of a type (NULL if none registered), the registered names joined by
   sep (trailing: also after the last one), and the list's end at PetscFinalize() */
PETSC_INTERN PetscErrorCode HylcPatternFindSource_Private(const char[], HylcPatternGenerator *);
PETSC_INTERN PetscErrorCode HylcPatternSourceNames_Private(const char[], PetscBool, char[], size_t);
PETSC_INTERN PetscErrorCode HylcPatternRegistryDestroy_Private(void);

/* Rank-0-only work (reading a file, writing one) reported on every rank: push
   HylcPatternKeepMessage_Private with a char[HYLC_PATTERN_MSG_LEN] as context on rank 0, keep the error
   code, pop, then HylcPatternRaiseFromRank0_Private(comm, code, msg) on every rank. */
#define HYLC_PATTERN_MSG_LEN (PETSC_MAX_PATH_LEN + 512)
PETSC_INTERN PetscErrorCode HylcPatternKeepMessage_Private(MPI_Comm, int, const char *, const char *, PetscErrorCode, PetscErrorType, const char *, void *);
PETSC_INTERN PetscErrorCode HylcPatternRaiseFromRank0_Private(MPI_Comm, PetscErrorCode, char[]);
/* Largest tile size (threads or stitches per direction) the generators accept. */
#define HYLC_PATTERN_MAX_SIZE 1000
