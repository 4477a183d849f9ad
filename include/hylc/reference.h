#pragma once
/* The reference state of Algorithm C1 (docs/method.md §7): a stress-free relaxation (rest values reset to the
   current geometry and relaxed until E < tol), tension (knits: rest lengths x 0.9, rest curvatures x 0.8;
   wovens: rest curvatures x 0.9), the in-plane minimum of the energy over the periods (sx, sy) by
   Nelder-Mead, and recentring. */
#include <hylc/micro.h>

typedef struct {
  PetscReal etol;        /* stress-free: stop when the relaxed energy is below this (J); 1e-10 */
  PetscInt  maxRounds;   /* stress-free: at most this many reset + relax rounds; 30 */
  PetscInt  kind;        /* 0: auto (knit if every yarn runs along x), 1: knit, 2: woven */
  PetscBool stressFree;  /* the stress-free relaxation (rest values reset to the geometry); false keeps the rest data */
  PetscBool tension;     /* apply the tension factors */
  PetscBool minimum;     /* find the in-plane minimum */
  PetscReal lo, hi;      /* bounds of sx and sy for the minimum; -0.4, 0.2 */
  PetscReal xtol;        /* Nelder-Mead: simplex size tolerance in strain; 1e-4 */
  PetscInt  maxEvals;    /* Nelder-Mead: at most this many solves; 80 */
  char      prefix[256]; /* options prefix of the solvers the computation creates (-<prefix>micro_*); "" none */
} HylcReferenceParams;

/* Whether a job computes the reference state first (-sampler_reference, -calibrate_reference): auto (for a
   generated pattern; a .pyp file is its own reference state), compute, none, or relax: only the in-plane
   minimum over the periods and the recentring (C1's last steps), with the pattern's rest data as stored,
   so that a stored tile under the configured yarn becomes a minimum of the model (issue 30). */
typedef enum { HYLC_REFERENCE_AUTO = 0, HYLC_REFERENCE_COMPUTE = 1, HYLC_REFERENCE_NONE = 2, HYLC_REFERENCE_RELAX = 3 } HylcReferenceMode;
PETSC_EXTERN const char *const HylcReferenceModes[];

PETSC_EXTERN PetscErrorCode HylcReferenceParamsDefault(HylcReferenceParams *);
/* Options, after the given options prefix (NULL: none; kept in the parameters for the solvers the
   computation creates): -reference_etol, -reference_max_rounds, -reference_kind auto|knit|woven,
   -reference_stress_free, -reference_tension, -reference_minimum, -reference_bounds lo,hi,
   -reference_xtol, -reference_max_evals. */
PETSC_EXTERN PetscErrorCode HylcReferenceParamsSetFromOptions(MPI_Comm, const char[], HylcReferenceParams *);
/* Computes the reference state of a pattern with the yarn model (each solve on PETSC_COMM_SELF; every rank
   computes the same). Progress lines go to the viewer (may be NULL). Collective on the pattern's comm. */
PETSC_EXTERN PetscErrorCode HylcReferenceStateCompute(HylcPattern, const HylcYarnModel *, const HylcReferenceParams *, PetscViewer, HylcPattern *);
/* The reference state a job's mode asks for, or NULL when it asks for none (auto: a generated pattern's
   reference state, none for a file; relax: the parameters with only the in-plane minimum). Collective. */
/* Whether the mode computes a reference state for the pattern (auto: a generated pattern, or a file that
   records another state than a reference one; src/sampler/reference.c). Not collective. */
PETSC_EXTERN PetscErrorCode HylcReferenceStateNeeded(HylcPattern, HylcReferenceMode, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcReferenceStateForMode(HylcPattern, HylcReferenceMode, const HylcYarnModel *, const HylcReferenceParams *, PetscViewer, HylcPattern *);
