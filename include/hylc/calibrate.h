#pragma once
/* HylcCalibrate: yarn parameters (E, Es, G, kc) from a target energy response (issue 13; docs/calibrate.md).

   Given a pattern with its options and a target -- a material table (JSON or HDF5) evaluated at the
   strains of a sampling plan, or strain-energy pairs (samples.h5, the paper's raw data.txt, a CSV) --
   finds the yarn parameters that minimise
     f(p) = w_0 ((Psi(z_b) - Psi_T(z_b)) / |Psi_T(z_b)|)^2
          + sum_t w_t (1/n_t) sum_{i in t} ((dPsi(z_i) - dPsi_T(z_i)) / R_t)^2,
   dPsi(z) = Psi(z) - Psi(z_b), z_b the base strain (0, or the target's row nearest to it), R_t the
   largest |dPsi_T| of term t. Parameters are optimised in log space by PETSc's TAO (TAOBRGN with
   Levenberg-Marquardt damping by default, options -calibrate_tao_*; HylcCalibrateGetTao()); the
   Jacobian needs no extra solves: the tile energy is linear in Es (stretch), E (bend), G (twist) and
   kc (contact), so at an equilibrium dPsi/dlog p = (matching energy part) / area (envelope theorem).
   The samples of one evaluation are spread over the ranks of the object's communicator (each solved on
   PETSC_COMM_SELF from the reference state); the results do not depend on the number of ranks. */
#include <hylc/micro.h>
#include <hylc/plan.h>
#include <hylc/material.h>
#include <hylc/reference.h>
#include <petsctao.h>

typedef struct _p_HylcCalibrate *HylcCalibrate;

/* Registration: the class id and log events of this stage (HylcCalibrateInitializePackage(), called by HylcCalibrateCreate()). */
PETSC_EXTERN PetscClassId   HYLC_CALIBRATE_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_CalibrateSetUp, HYLC_CalibrateSolve, HYLC_CalibrateEvaluate, HYLC_CalibrateGather;
PETSC_EXTERN PetscErrorCode HylcCalibrateInitializePackage(void);

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

/* lifecycle (src/calibrate/calibrate.c; each function's manual block there). SetFromOptions only reads
   options; SetUp loads or generates the pattern, resolves the initial values and bounds, sets up the
   solver, checks the outputs, reads the target and computes the reference state. */
PETSC_EXTERN PetscErrorCode HylcCalibrateCreate(MPI_Comm, HylcCalibrate *);
PETSC_EXTERN PetscErrorCode HylcCalibrateDestroy(HylcCalibrate *);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetOptionsPrefix(HylcCalibrate, const char[]);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetFromOptions(HylcCalibrate);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetUp(HylcCalibrate);
/* Runs the calibration, prints a line per iteration and writes -calibrate_output / -calibrate_dump.
   Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateSolve(HylcCalibrate);
/* The final per-term table (after HylcCalibrateSolve) or the set-up (before). Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateView(HylcCalibrate, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcCalibrateViewFromOptions(HylcCalibrate, PetscObject, const char[]);
/* sub-objects, created on first use (the pattern on the object's communicator, the solver on PETSC_COMM_SELF) */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetPattern(HylcCalibrate, HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcCalibrateGetMicro(HylcCalibrate, HylcMicro *);

/* Setters of the options (call before HylcCalibrateSetFromOptions to set defaults that options override,
   or after it to override the options). */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetYarnModel(HylcCalibrate, const HylcYarnModel *);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetTarget(HylcCalibrate, const char path[]);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetTargetType(HylcCalibrate, const char type[]);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetOutputs(HylcCalibrate, const char yaml[], const char dump[]);
/* roles of E, Es, G, kc (E may only be FREE or FIXED) */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetRoles(HylcCalibrate, const HylcCalibrateRole[]);
/* bounds of parameter j (0 < lo <= hi) */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetBounds(HylcCalibrate, PetscInt j, PetscReal lo, PetscReal hi);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetMaxIterations(HylcCalibrate, PetscInt);
/* -calibrate_start: how each evaluation's samples are solved: auto (the way the target was made: a samples
   file's own start, cold for a table, raw data or CSV, as the paper's were computed), cold, or continue */
typedef enum { HYLC_CALIBRATE_START_AUTO = 0, HYLC_CALIBRATE_START_COLD = 1, HYLC_CALIBRATE_START_CONTINUE = 2 } HylcCalibrateStart;
PETSC_EXTERN const char *const HylcCalibrateStarts[];
PETSC_EXTERN PetscErrorCode    HylcCalibrateSetStart(HylcCalibrate, HylcCalibrateStart);
/* the Levenberg-Marquardt damping of TAOBRGN (its regularizer weight, relative to diag J^T J) */
PETSC_EXTERN PetscErrorCode HylcCalibrateSetDamping(HylcCalibrate, PetscReal lambda);
/* the optimizer (TAO, options prefix calibrate_), owned by the calibration */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetTao(HylcCalibrate, Tao *);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetTolerances(HylcCalibrate, PetscReal xtol, PetscReal ftol, PetscReal fatol, PetscReal flatTol);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetPlanRanges(HylcCalibrate, const HylcPlanRanges *);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetTerms(HylcCalibrate, PetscInt terms);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetSampleCounts(HylcCalibrate, PetscInt n1, PetscInt n2);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetThinning(HylcCalibrate, PetscInt stride, PetscInt maxSamples);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetTermWeight(HylcCalibrate, const char term[], PetscReal w);
PETSC_EXTERN PetscErrorCode HylcCalibrateSetReference(HylcCalibrate, HylcReferenceMode, const char output[]);
/* -calibrate_stationary: weight w of the stationarity at the base strain, w ((dPsi/dsx / S_x)^2 + (dPsi/dsy / S_y)^2) (0: off);
   its Jacobian by central differences with step h in log p (fd, -calibrate_stationary_jacobian fd) or the fixed-state parts (gn) */
PETSC_EXTERN const char *const HylcCalibrateStationaryJacobians[];
PETSC_EXTERN PetscErrorCode    HylcCalibrateSetStationary(HylcCalibrate, PetscReal w, PetscBool fd, PetscReal h);
/* the scales S_x, S_y and dPsi/dsx, dPsi/dsy at the base strain before and after HylcCalibrateSolve (N/m; any may be NULL). Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetStationarity(HylcCalibrate, PetscReal scale[], PetscReal before[], PetscReal after[]);
/* at explicit p (no ties): dPsi/dsx, dPsi/dsy at the base strain and dlogp[2 q + k] = p_q d/dp_q of dPsi/ds_k at the fixed state. Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateEvaluateStationarity(HylcCalibrate, const PetscReal p[], PetscReal ds[], PetscReal dlogp[]);

/* The objective f at explicit parameter values p = (E, Es, G, kc) (no ties applied) and its gradient
   grad[j] = df / dlog p_j by the envelope theorem (may be NULL); one solve per sample. *nfailed (may be
   NULL) receives the number of samples left out because they did not converge. After
   HylcCalibrateSetUp. Collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateEvaluate(HylcCalibrate, const PetscReal p[], PetscReal *f, PetscReal grad[], PetscInt *nfailed);
/* Parameter values (after HylcCalibrateSetUp): the initial ones (resolved yarn model) and the current ones (the calibrated values
   after HylcCalibrateSolve). Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetParameters(HylcCalibrate, PetscReal initial[], PetscReal current[]);
/* Objective before and after HylcCalibrateSolve, and the number of iterations. Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetObjective(HylcCalibrate, PetscReal *f0, PetscReal *f1, PetscInt *its);
/* Number of samples (the base sample included). Not collective. */
PETSC_EXTERN PetscErrorCode HylcCalibrateGetSize(HylcCalibrate, PetscInt *);
