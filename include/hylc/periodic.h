#pragma once
/* HylcPeriodic: a periodic yarn tile under a macroscopic strain z = (sx, sa, sy, II00, II01, II11), in the
   reduced unknowns of the co-rotated periodic boundary conditions (docs/method.md §5, seeds S1.2, S2.1).

   - The extended pattern: every stretch, bend and twist element touching an original vertex, with the
     ghost vertices it needs, plus copies of edges from the neighbouring tiles within a margin for contact;
     each ghost is (original o, lattice shift s), unique; every element carries the fractional weight
     (#original vertices)/(#vertices) (seed Fig. S1), so the weights of the copies of a physical element
     sum to 1.
   - Elimination q = C y + d: the unknowns y are (x_o, theta_o) of the original vertices (4 per vertex);
     a ghost (o, s) sits at x = T x_o + d with T = R(xi_o + S) R(xi_o)^T and
     d = phi(xi_o + S) + h_o n(xi_o + S) - T (phi(xi_o) + h_o n(xi_o)) (S20), and a ghost edge has the
     twist of its original (S21).
   - Constraints A y = dL: translation (S17, 3 rows) and the slide constraint (none | global | per_yarn).
   - Reduced energy, gradient g_y = C^T grad E and Hessian H_y = C^T H C, assembled without forming the
     full Hessian.
   Everything lives on one rank (PETSC_COMM_SELF). */
#include <hylc/pattern.h>
#include <hylc/yarn.h>
#include <hylc/macro.h>
#include <hylc/strain.h>
#include <petscmat.h>

typedef struct _p_HylcPeriodic *HylcPeriodic;

/* Registration: the class id and log events of this stage (HylcPeriodicInitializePackage(), called by HylcPeriodicCreate()). */
PETSC_EXTERN PetscClassId   HYLC_PERIODIC_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_PeriodicSetUp, HYLC_PeriodicEvaluate, HYLC_TileBroadphase, HYLC_TileContact, HYLC_TileAssemble, HYLC_TileEvaluate;
PETSC_EXTERN PetscErrorCode HylcPeriodicInitializePackage(void);

typedef enum {
  HYLC_SLIDE_NONE       = 0,
  HYLC_SLIDE_GLOBAL     = 1,
  HYLC_SLIDE_PER_YARN   = 2,
  HYLC_SLIDE_PER_FAMILY = 3 /* one row per yarn family (loops of the same winding direction), each yarn in its canonical direction */
} HylcSlideConstraint;
PETSC_EXTERN const char *const HylcSlideConstraints[];

/* lifecycle (src/periodic/periodic.c; each function's manual block there) */
PETSC_EXTERN PetscErrorCode HylcPeriodicCreate(MPI_Comm, HylcPeriodic *);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetPattern(HylcPeriodic, HylcPattern, const HylcYarnModel *);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetPattern(HylcPeriodic, HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcPeriodicDestroy(HylcPeriodic *);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetOptionsPrefix(HylcPeriodic, const char[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetFromOptions(HylcPeriodic);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetContactMargin(HylcPeriodic, PetscReal);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetPairMargin(HylcPeriodic, PetscReal);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetConstraintTolerance(HylcPeriodic, PetscReal);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetStrain(HylcPeriodic, const PetscReal[6]);
/* the largest stretch factor 1 + sx, 1 + sy that HylcPeriodicCheckStrain() accepts */
#define HYLC_PERIODIC_MAX_STRETCH 1e3 /* the message of HylcPeriodicCheckStrain() says 1e3 */
PETSC_EXTERN PetscErrorCode HylcPeriodicCheckStrain(HylcPeriodic, const PetscReal[6], const char[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetSlideConstraint(HylcPeriodic, HylcSlideConstraint);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetUp(HylcPeriodic);
PETSC_EXTERN PetscErrorCode HylcPeriodicView(HylcPeriodic, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcPeriodicViewFromOptions(HylcPeriodic, PetscObject, const char[]);

PETSC_EXTERN PetscErrorCode HylcPeriodicGetSizes(HylcPeriodic, PetscInt *, PetscInt *, PetscInt *, PetscInt *);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetArea(HylcPeriodic, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetConstants(HylcPeriodic, HylcYarnConstants *);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetMacroStrain(HylcPeriodic, const HylcMacroStrain **);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetInitialState(HylcPeriodic, PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicSetState(HylcPeriodic, const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicFluctuationToLocal(HylcPeriodic, const PetscReal[], PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicFluctuationFromLocal(HylcPeriodic, const PetscReal[], PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetFullPositions(HylcPeriodic, PetscInt *, const PetscReal **, const PetscInt **, const PetscInt **);
PETSC_EXTERN PetscErrorCode HylcPeriodicCreateMatrix(HylcPeriodic, Mat *);
PETSC_EXTERN PetscErrorCode HylcPeriodicEvaluate(HylcPeriodic, int, PetscReal[4], PetscReal[], Mat);
PETSC_EXTERN PetscErrorCode HylcPeriodicEvaluateFinite(HylcPeriodic, int, PetscReal[4], PetscReal[], Mat, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcPeriodicEvaluateStrainDerivative(HylcPeriodic, int, int, PetscReal[4], PetscReal[], PetscReal[6], PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicUpdateFrames(HylcPeriodic);
PETSC_EXTERN PetscErrorCode HylcPeriodicSaveFrames(HylcPeriodic);
PETSC_EXTERN PetscErrorCode HylcPeriodicRestoreFrames(HylcPeriodic);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetConstraints(HylcPeriodic, PetscInt *, const PetscReal **, const PetscReal **, const PetscReal **);
PETSC_EXTERN PetscErrorCode HylcPeriodicConstraintResidual(HylcPeriodic, const PetscReal[], PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetNumContactPairs(HylcPeriodic, PetscInt *);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetClearance(HylcPeriodic, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcPeriodicCreateStatePattern(HylcPeriodic, HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcPeriodicWriteVTK(HylcPeriodic, const char[], PetscInt, PetscInt);
PETSC_EXTERN PetscErrorCode HylcPeriodicGetTimes(HylcPeriodic, PetscLogDouble *, PetscLogDouble *, PetscLogDouble *);
