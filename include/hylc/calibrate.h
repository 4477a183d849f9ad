#pragma once
/* HylcCalibrate: yarn parameters (E, Es, G, kc) from a target energy response (issue 13; docs/calibrate.md).

   Given a pattern with its options and a target -- a material table (JSON or HDF5) evaluated at the
   strains of a sampling plan, or strain-energy pairs (samples.h5, the paper's raw data.txt, a CSV) --
   finds the yarn parameters that minimise
     f(p) = w_0 ((Psi(z_b) - Psi_T(z_b)) / |Psi_T(z_b)|)^2
          + sum_t w_t (1/n_t) sum_{i in t} ((dPsi(z_i) - dPsi_T(z_i)) / R_t)^2,
   dPsi(z) = Psi(z) - Psi(z_b), z_b the base strain (0, or the target's row nearest to it), R_t the
   largest |dPsi_T| of term t. Parameters are optimised in log space by Levenberg-Marquardt; the
   Jacobian needs no extra solves: the tile energy is linear in Es (stretch), E (bend), G (twist) and
   kc (contact), so at an equilibrium dPsi/dlog p = (matching energy part) / area (envelope theorem).
   The samples of one evaluation are spread over the ranks of the object's communicator (each solved on
   PETSC_COMM_SELF from the reference state); the results do not depend on the number of ranks. */
#include <hylc/micro.h>
#include <hylc/plan.h>
#include <hylc/material.h>
#include <hylc/reference.h>

typedef struct _p_HylcCalibrate *HylcCalibrate;

/* the parameters, in this order: E (bending modulus, Pa), Es (stretching modulus, Pa), G (shear modulus,
   Pa), kc (contact stiffness, N/m) */
#define HYLC_CALIBRATE_NPARAM 4
PETSC_EXTERN const char *const HylcCalibrateParamNames[HYLC_CALIBRATE_NPARAM];

/* Role of a parameter during the calibration. */
typedef enum {
  HYLC_CALIBRATE_FREE  = 0, /* optimised */
  HYLC_CALIBRATE_TIED  = 1, /* follows E at its initial ratio p / E */
  HYLC_CALIBRATE_FIXED = 2  /* held at its initial value */
} HylcCalibrateRole;

PETSC_EXTERN PetscErrorCode HylcCalibrateCreate(MPI_Comm, HylcCalibrate *);
PETSC_EXTERN PetscErrorCode HylcCalibrateDestroy(HylcCalibrate *);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetOptionsPrefix(HylcCalibrate, const char[]);
/* Reads -calibrate_* and the options of the pattern (-pattern_*), yarn model (-yarn_*, the initial
   values), reference state (-reference_*), solver (-micro_*) and plan ranges (-sampler_family,
   -sampler_range_*). Checks parameter names and bounds. Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetFromOptions(HylcCalibrate);
/* Checks the options and paths (before any solve), reads the target, builds the list of samples and
   computes the reference state of a generated pattern (once, with the initial parameters). Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetUp(HylcCalibrate);
/* Runs the calibration, prints a line per iteration and writes -calibrate_output / -calibrate_dump.
   Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateSolve(HylcCalibrate);
/* The final per-term table (after HylcCalibrateSolve) or the set-up (before). Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateView(HylcCalibrate, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcCalibrateViewFromOptions(HylcCalibrate, PetscObject, const char[]);

/* Setters of the options (call before HylcCalibrateSetFromOptions to set defaults that options override,
   or after it to override the options). */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetTarget(HylcCalibrate, const char path[]);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetOutputs(HylcCalibrate, const char yaml[], const char dump[]);
/* roles of E, Es, G, kc (E may only be FREE or FIXED) */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetRoles(HylcCalibrate, const HylcCalibrateRole[]);
/* bounds of parameter j (0 < lo <= hi) */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetBounds(HylcCalibrate, PetscInt j, PetscReal lo, PetscReal hi);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetMaxIterations(HylcCalibrate, PetscInt);

/* The objective f at explicit parameter values p = (E, Es, G, kc) (no ties applied) and its gradient
   grad[j] = df / dlog p_j by the envelope theorem (may be NULL); one solve per sample. *nfailed (may be
   NULL) receives the number of samples left out because they did not converge. After
   HylcCalibrateSetUp. Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateEvaluate(HylcCalibrate, const PetscReal p[], PetscReal *f, PetscReal grad[], PetscInt *nfailed);
/* Parameter values: the initial ones (resolved yarn model) and the current ones (the calibrated values
   after HylcCalibrateSolve). Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetParameters(HylcCalibrate, PetscReal initial[], PetscReal current[]);
/* Objective before and after HylcCalibrateSolve, and the number of iterations. Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetObjective(HylcCalibrate, PetscReal *f0, PetscReal *f1, PetscInt *its);
/* Number of samples (the base sample included). Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetSize(HylcCalibrate, PetscInt *);
