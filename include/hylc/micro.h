#pragma once
/* HylcMicro: the microscale equilibrium of a periodic yarn tile under a macroscopic strain (Algorithms
   C2, C3; docs/method.md §6), a constrained, regularized Newton method on PETSc SNES:
   - unknowns: the scaled reduced unknowns y^ = M^-1 y (M = 1 per position, mu per twist);
   - objective: the total energy E; residual: M g_y;
   - Jacobian: K = M H_y M + alpha I with alpha = alpha^_i ||M g_y||_inf (S22);
   - linear solve: the constrained KKT system (S22) by a Schur complement around a sparse Cholesky
     factorization of K (a PCSHELL around a PCCHOLESKY, options -micro_factor_pc_*, solver type hylc by
     default: -micro_factor_pc_factor_mat_solver_type hylc|petsc|cholmod|mumps); if the direction is
     not a descent direction of positive curvature (K indefinite), alpha is multiplied by 10 and K
     refactored;
   - line search: the step limit of S2.2, then backtracking by 0.1 until the energy strictly decreases;
     reference frames are transported after each accepted step (trial states are evaluated against the
     stored frames, which the kernels transport internally, so nothing has to be restored);
   - convergence: |z| < rtol |z0| for the projected gradient z (S23-S25) and |A y - dL| < ctol r; then the
     second-order test (HylcMicroSetSaddleEscape(), on by default): a saddle point is left along its
     direction of most negative curvature and the iteration resumes.
   A sample that does not converge is data, not an error: see HylcMicroResult.status. An error inside the
   solve is an error (the sample has no result): only a failed factorization (the regularization's job)
   and a degenerate or non-finite trial state (energy +inf) are outcomes of the method. */
#include <hylc/periodic.h>
#include <hylcmat.h>
#include <petscsnes.h>

typedef struct _p_HylcMicro *HylcMicro;

/* Registration: the class id and log events of this stage (HylcMicroInitializePackage(), called by HylcMicroCreate()). */
PETSC_EXTERN PetscClassId   HYLC_MICRO_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_MicroSetUp, HYLC_MicroSolve, HYLC_MicroFactor, HYLC_MicroSaddle, HYLC_MicroLineSearch;
PETSC_EXTERN PetscErrorCode HylcMicroInitializePackage(void);

typedef enum {
  HYLC_MICRO_CONVERGED = 0,
  HYLC_MICRO_MAX_IT    = 1, /* iteration cap */
  HYLC_MICRO_MAX_TIME  = 2, /* wall-time cap */
  HYLC_MICRO_STALLED   = 3, /* line search found no decrease several times in a row */
  HYLC_MICRO_NONFINITE = 4  /* non-finite energy or gradient */
  /* 5 is reserved (was "failed"): an error inside a solve (a bug, no memory, a bad option) is an error of
     HylcMicroSolve(), never a status; a Newton matrix that cannot be factored after every increase of
     alpha ends the solve as stalled (nonfinite if the matrix is not finite) */
} HylcMicroStatus;
PETSC_EXTERN const char *const HylcMicroStatuses[];

/* the regularization schedule of alpha^ (docs/method.md, "Newton solver"): the paper's geometric decay over
   the iteration count, or a trust-region-like adaptation to the agreement of each step with its model */
typedef enum {
  HYLC_MICRO_ALPHA_PAPER    = 0,
  HYLC_MICRO_ALPHA_ADAPTIVE = 1,
  HYLC_MICRO_ALPHA_HYBRID   = 2 /* the paper's decay until ||M g||_inf falls below switch x its initial value, then adaptive */
} HylcMicroAlphaSchedule;
PETSC_EXTERN const char *const HylcMicroAlphaSchedules[];

typedef struct {
  PetscReal       z[6];     /* the strain */
  PetscReal       psi;      /* E / A (J/m^2) */
  PetscReal       energy;   /* E (J) */
  PetscReal       parts[4]; /* stretch, bend, twist, contact energy (J) */
  HylcMicroStatus status;
  PetscInt        iterations;                                /* Newton iterations */
  PetscInt        retries;                                   /* alpha increases for indefinite K */
  PetscInt        stalls;                                    /* line searches without decrease */
  PetscInt        escapes;                                   /* saddle escapes (HylcMicroSetSaddleEscape()) */
  PetscInt        negcurv;                                   /* negative eigenvalues of the projected Hessian at the end; -1 not tested */
  PetscBool       fallback;                                  /* the adaptive or hybrid schedule did not converge: solved again from the same start with the paper schedule (HylcMicroSetRegularizationFallback()) */
  PetscReal       residual;                                  /* |z| / |z0| at the end */
  PetscReal       cresidual;                                 /* |A y - dL| / r at the end */
  PetscLogDouble  time;                                      /* wall time of the solve (s) */
  PetscLogDouble  tAssembly, tContact, tFactor, tLineSearch; /* parts of it (s) */
} HylcMicroResult;

/* the homogeneous uniaxial tension state of the tile (HylcMicroSolveUniaxial(), docs/fabric-uniaxial.md): the
   stretch s prescribed along the material x axis (sx = s; sa, sy free) or y axis (sy = s; sx, sa free),
   bending zero, Psi minimized over the two free (lateral) strains */
typedef enum { HYLC_UNIAXIAL_X = 0, HYLC_UNIAXIAL_Y = 1 } HylcUniaxialDirection;
PETSC_EXTERN const char *const HylcUniaxialDirections[];

/* how HylcMicroSolveUniaxial() gets dPsi/dz: the envelope theorem at each equilibrium
   (HylcMicroGetStrainGradient(), one solve per point) or central differences of Psi over continued solves
   (six more solves per point; for checks) */
typedef enum { HYLC_MICRO_UNIAXIAL_ENVELOPE = 0, HYLC_MICRO_UNIAXIAL_FD = 1 } HylcMicroUniaxialGradient;
PETSC_EXTERN const char *const HylcMicroUniaxialGradients[];

typedef struct {
  HylcUniaxialDirection dir;
  PetscReal             s;               /* the prescribed stretch */
  PetscReal             z[6];            /* the strain of the state returned: z[0] (x) or z[2] (y) = s, II = 0 */
  PetscReal             lateral[2];      /* the free strains there: (sa, sy) for x, (sa, sx) for y */
  PetscReal             psi;             /* Psi (J/m^2) */
  PetscReal             T;               /* dPsi/ds, the force per unit width of a strip (N/m) */
  PetscReal             grad[3];         /* dPsi/d(sx, sa, sy) (N/m) */
  PetscReal             step;            /* the Newton step to the minimizer predicted at the state returned, max norm (strain) */
  PetscBool             converged;       /* step <= xtol, or a line search failed with |lateral gradient| <= gtol |T| (gradientStop); the state's solve converged */
  PetscBool             gradientStop;    /* converged by the gradient test after a failed line search (Psi's noise, nearby equilibria) */
  PetscInt              iterations;      /* accepted Newton steps in the lateral strains */
  PetscInt              solves;          /* microscale solves (HylcMicroSolve) */
  PetscInt              microIterations; /* their Newton iterations, summed */
  PetscInt              failedSolves;    /* solves that did not converge (continued and cold) */
  PetscLogDouble        time;            /* wall time (s) */
} HylcMicroUniaxialResult;

/* the homogeneous state of the tile on a load path (HylcMicroSolvePath(), include/hylcmat.h, docs/fabric-fidelity.md) */
typedef struct {
  hylcmat_path   path;
  PetscReal      s;               /* the prescribed value */
  PetscReal      force;           /* d(min Psi)/ds: N/m, or N (the moment per unit width) for bending */
  PetscReal      p[3];            /* the free strains (hylcmat_path_nfree()) */
  PetscReal      z[6];            /* the strain of the state */
  PetscReal      psi;             /* Psi (J/m^2) */
  PetscReal      grad[6];         /* dPsi/dz there (the components the path moves; 0 for the others) */
  PetscReal      gfree[3];        /* dPsi/dp there */
  PetscReal      step;            /* the Newton step to the minimizer predicted at the state returned, max norm */
  PetscBool      converged;       /* as HylcMicroUniaxialResult */
  PetscBool      gradientStop;    /* converged by the gradient test after a failed line search */
  PetscInt       iterations;      /* accepted Newton steps */
  PetscInt       solves;          /* microscale solves */
  PetscInt       microIterations; /* their Newton iterations */
  PetscInt       failedSolves;    /* solves that did not converge */
  PetscLogDouble time;            /* wall time (s) */
} HylcMicroPathResult;

PETSC_EXTERN PetscErrorCode HylcMicroCreate(MPI_Comm, HylcMicro *);
PETSC_EXTERN PetscErrorCode HylcMicroDestroy(HylcMicro *);
PETSC_EXTERN PetscErrorCode HylcMicroSetPattern(HylcMicro, HylcPattern, const HylcYarnModel *);
PETSC_EXTERN PetscErrorCode HylcMicroSetOptionsPrefix(HylcMicro, const char[]);
PETSC_EXTERN PetscErrorCode HylcMicroSetRegularization(HylcMicro, PetscReal start, PetscReal end, PetscInt its, PetscInt retries);
PETSC_EXTERN PetscErrorCode HylcMicroSetRegularizationSchedule(HylcMicro, HylcMicroAlphaSchedule, PetscReal factor, PetscReal min, PetscReal max);
PETSC_EXTERN PetscErrorCode HylcMicroSetRegularizationSwitch(HylcMicro, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMicroSetRegularizationFallback(HylcMicro, PetscBool);
PETSC_EXTERN PetscErrorCode HylcMicroSetStepClearance(HylcMicro, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMicroSetTwistScale(HylcMicro, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMicroSetStepLimit(HylcMicro, PetscReal p0, PetscReal p1);
PETSC_EXTERN PetscErrorCode HylcMicroSetLineSearch(HylcMicro, PetscReal factor, PetscInt trials, PetscInt maxStalls);
PETSC_EXTERN PetscErrorCode HylcMicroSetTolerances(HylcMicro, PetscReal rtol, PetscReal atol, PetscReal ctol, PetscReal maxTime);
PETSC_EXTERN PetscErrorCode HylcMicroSetIndefinite(HylcMicro, PetscBool);
PETSC_EXTERN PetscErrorCode HylcMicroSetSaddleEscape(HylcMicro, PetscBool, PetscInt, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMicroSetFromOptions(HylcMicro);
PETSC_EXTERN PetscErrorCode HylcMicroGetSNES(HylcMicro, SNES *);
PETSC_EXTERN PetscErrorCode HylcMicroGetFactorPC(HylcMicro, PC *);
PETSC_EXTERN PetscErrorCode HylcMicroView(HylcMicro, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcMicroViewFromOptions(HylcMicro, PetscObject, const char[]);
PETSC_EXTERN PetscErrorCode HylcMicroSetUp(HylcMicro);
PETSC_EXTERN PetscErrorCode HylcMicroSolve(HylcMicro, const PetscReal[6], HylcMicroResult *);
PETSC_EXTERN PetscErrorCode HylcMicroGetPeriodic(HylcMicro, HylcPeriodic *);
PETSC_EXTERN PetscErrorCode HylcMicroGetState(HylcMicro, PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcMicroSetInitialState(HylcMicro, const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcMicroSetInitialFluctuation(HylcMicro, const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcMicroGetFluctuation(HylcMicro, const PetscReal[], PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcMicroSolveContinued(HylcMicro, const PetscReal[6], const PetscReal[], HylcMicroResult *, PetscReal[], PetscBool *);
PETSC_EXTERN PetscErrorCode HylcMicroGetContinued(HylcMicro, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcMicroGetEnergyHistory(HylcMicro, PetscInt *, const PetscReal **);
PETSC_EXTERN PetscErrorCode HylcMicroResultView(const HylcMicroResult *, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcMicroGetStrainGradient(HylcMicro, int, PetscReal[6]);
PETSC_EXTERN PetscErrorCode HylcMicroSolvePath(HylcMicro, const hylcmat_path *, PetscReal, const PetscReal[], const PetscReal[], HylcMicroPathResult *, PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcMicroPathResultView(const HylcMicroPathResult *, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcMicroGetStrainGradientParts(HylcMicro, int, PetscReal[6], PetscReal[24]);
PETSC_EXTERN PetscErrorCode HylcMicroSetUniaxial(HylcMicro, HylcMicroUniaxialGradient, PetscReal, PetscInt, PetscReal, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMicroSetUniaxialTolerances(HylcMicro, PetscReal, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMicroSolveUniaxial(HylcMicro, HylcUniaxialDirection, PetscReal, const PetscReal[2], const PetscReal[], HylcMicroUniaxialResult *, PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcMicroUniaxialResultView(const HylcMicroUniaxialResult *, PetscViewer);
