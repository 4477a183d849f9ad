#pragma once
/* HylcCloth: the macroscale cloth solver on the shell element of Algorithm C8 (include/hylcmat.h,
   docs/library.md) and the virtual standard fabric tests (docs/fabric.md): strip tensile, bias extension,
   cantilever bending length, Cusick drape and a generic static scene.

   The cloth is a triangle mesh (generated for a specimen or read from an .obj file) with the energy of a
   material table (JSON or HDF5, ours or the paper's), gravity from the table's area density, clamps with
   prescribed motion, pinned vertices and rigid supports (plane, disc) with frictionless barrier contact.
   Equilibria by Newton's method (SNES, an energy line search that refuses penetration) or a trust region
   (TAO); where no static path reaches an equilibrium (a drape, a curling knit), the backward Euler
   dynamics with damping brings the cloth to rest (-cloth_dynamic, docs/fabric.md). The mesh is replicated on every
   rank and partitioned with METIS: every rank evaluates its own triangles and owns a contiguous block of
   vertices of the global vectors and matrices.

   Conventions: the rest mesh lies in the plane z = 0 for the generated specimens; n, the side from which
   the material axes appear counter-clockwise, is +z ("face up") or -z ("face down"); II > 0 bends toward
   n (docs/library.md). Lengths in m, forces in N, energies in J. */
#include <hylc/sys.h>
#include <hylc/material.h>
#include <hylc/files.h>
#include <petscviewer.h>
#include <petscvec.h>
#include <hylcmat.h>

typedef struct _p_HylcCloth *HylcCloth;

/* Registered by HylcClothInitializePackage() (called by HylcClothCreate()). */
PETSC_EXTERN PetscClassId   HYLC_CLOTH_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_ClothSetUp, HYLC_ClothAssemble, HYLC_ClothSolve, HYLC_ClothLineSearch, HYLC_ClothStep, HYLC_ClothOutput;
PETSC_EXTERN PetscErrorCode HylcClothInitializePackage(void);

/* The virtual tests (-cloth_test). UNIAXIAL is the homogeneous uniaxial curve of the table alone
   (no mesh): the reference of the strip's central zone. */
typedef enum { HYLC_CLOTH_TEST_TENSILE = 0, HYLC_CLOTH_TEST_BIAS = 1, HYLC_CLOTH_TEST_CANTILEVER = 2, HYLC_CLOTH_TEST_DRAPE = 3, HYLC_CLOTH_TEST_SCENE = 4, HYLC_CLOTH_TEST_UNIAXIAL = 5, HYLC_CLOTH_TEST_CURL = 6 } HylcClothTest;
PETSC_EXTERN const char *const HylcClothTests[];

/* Which fabric face is up: n = +z (UP) or n = -z (DOWN); BOTH runs the cantilever with each. */
typedef enum { HYLC_CLOTH_FACE_UP = 0, HYLC_CLOTH_FACE_DOWN = 1, HYLC_CLOTH_FACE_BOTH = 2 } HylcClothFace;
PETSC_EXTERN const char *const HylcClothFaces[];

/* The material direction along the specimen's length (tensile, cantilever): material x (courses of a
   knit, warp of a woven) or y; both runs both. */
typedef enum { HYLC_CLOTH_DIR_X = 0, HYLC_CLOTH_DIR_Y = 1, HYLC_CLOTH_DIR_BOTH = 2 } HylcClothDirection;
PETSC_EXTERN const char *const HylcClothDirections[];

/* Equilibrium solver: NEWTON = SNES newtonls with the energy line search; TRUST = TAO's trust-region
   Newton (TAONTR, Steihaug CG preconditioned by the factorized projected Hessian). */
typedef enum { HYLC_CLOTH_SOLVER_NEWTON = 0, HYLC_CLOTH_SOLVER_TRUST = 1 } HylcClothSolver;
PETSC_EXTERN const char *const HylcClothSolvers[];

/* Hessian used by the Newton solver: every element Hessian projected to PSD (PROJECTED); the exact
   Hessian (EXACT); or the exact one whenever its factorization shows no negative pivot and the projected
   one otherwise (AUTO). */
typedef enum { HYLC_CLOTH_HESSIAN_PROJECTED = 0, HYLC_CLOTH_HESSIAN_EXACT = 1, HYLC_CLOTH_HESSIAN_AUTO = 2 } HylcClothHessian;
PETSC_EXTERN const char *const HylcClothHessians[];

/* When the equilibrium under gravity comes from the backward Euler dynamics (dynamic.c): never (OFF: the
   static load path only), when the static load path fails (AUTO), or always (ON: the cloth released at
   rest from its flat state under full gravity, as the specimen of a drape test is). */
typedef enum { HYLC_CLOTH_DYNAMICS_OFF = 0, HYLC_CLOTH_DYNAMICS_AUTO = 1, HYLC_CLOTH_DYNAMICS_ON = 2 } HylcClothDynamics;
PETSC_EXTERN const char *const HylcClothDynamicsTypes[];

PETSC_EXTERN PetscErrorCode HylcClothCreate(MPI_Comm, HylcCloth *);
PETSC_EXTERN PetscErrorCode HylcClothDestroy(HylcCloth *);
PETSC_EXTERN PetscErrorCode HylcClothSetOptionsPrefix(HylcCloth, const char[]);
PETSC_EXTERN PetscErrorCode HylcClothSetFromOptions(HylcCloth);
PETSC_EXTERN PetscErrorCode HylcClothSetUp(HylcCloth);
PETSC_EXTERN PetscErrorCode HylcClothView(HylcCloth, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcClothViewFromOptions(HylcCloth, PetscObject, const char[]);

/* Setters, one per option (docs/fabric.md has the table). */
PETSC_EXTERN PetscErrorCode HylcClothSetMaterialFile(HylcCloth, const char[]);
PETSC_EXTERN PetscErrorCode HylcClothSetMaterial(HylcCloth, HylcMaterial);
PETSC_EXTERN PetscErrorCode HylcClothGetMaterial(HylcCloth, HylcMaterial *);
PETSC_EXTERN PetscErrorCode HylcClothSetTest(HylcCloth, HylcClothTest);
PETSC_EXTERN PetscErrorCode HylcClothGetTest(HylcCloth, HylcClothTest *);
PETSC_EXTERN PetscErrorCode HylcClothSetFace(HylcCloth, HylcClothFace);
PETSC_EXTERN PetscErrorCode HylcClothSetDirection(HylcCloth, HylcClothDirection);
PETSC_EXTERN PetscErrorCode HylcClothSetAngle(HylcCloth, PetscReal degrees);
PETSC_EXTERN PetscErrorCode HylcClothSetSize(HylcCloth, PetscReal length, PetscReal width);
PETSC_EXTERN PetscErrorCode HylcClothSetMeshSize(HylcCloth, PetscReal h);
PETSC_EXTERN PetscErrorCode HylcClothSetMeshFile(HylcCloth, const char[], PetscReal scale);
PETSC_EXTERN PetscErrorCode HylcClothSetStrains(HylcCloth, PetscReal max, PetscInt steps);
PETSC_EXTERN PetscErrorCode HylcClothSetGravity(HylcCloth, PetscReal);
PETSC_EXTERN PetscErrorCode HylcClothSetPlanar(HylcCloth, PetscBool);
PETSC_EXTERN PetscErrorCode HylcClothSetOutput(HylcCloth, const char prefix[]);
PETSC_EXTERN PetscErrorCode HylcClothSetOutputFormats(HylcCloth, PetscBool vtk, PetscBool plot);
PETSC_EXTERN PetscErrorCode HylcClothSetSolver(HylcCloth, HylcClothSolver, HylcClothHessian);
PETSC_EXTERN PetscErrorCode HylcClothSetTolerances(HylcCloth, PetscReal rtol, PetscInt maxit);
PETSC_EXTERN PetscErrorCode HylcClothSetLoadSteps(HylcCloth, PetscInt);
PETSC_EXTERN PetscErrorCode HylcClothSetCantilever(HylcCloth, PetscReal angleDegrees, PetscReal width);
PETSC_EXTERN PetscErrorCode HylcClothSetDrape(HylcCloth, PetscReal specimenDiameter, PetscReal discDiameter);
PETSC_EXTERN PetscErrorCode HylcClothSetScene(HylcCloth, PetscReal clampLength, PetscInt ncorners, const PetscInt corners[]);
PETSC_EXTERN PetscErrorCode HylcClothSetBarrier(HylcCloth, PetscReal distance, PetscReal stiffness);
PETSC_EXTERN PetscErrorCode HylcClothSetDynamics(HylcCloth, HylcClothDynamics, PetscReal dt, PetscReal damping, PetscReal tmax, PetscReal restTol);

/* Lists the material and mesh files (inputs) and the test's CSV (output) in a file registry. */
PETSC_EXTERN PetscErrorCode HylcClothAddFiles(HylcCloth, HylcFiles);

/* Runs the selected test (SetUp if needed): solves, writes the CSV, VTK and PNG outputs of the
   -cloth_output prefix, prints a summary and stores the scalar results. Collective. */
PETSC_EXTERN PetscErrorCode HylcClothRun(HylcCloth);
/* The scalar results of the last HylcClothRun (names such as "T5_x", "nu5_x", "c_x_up", "G_x_up",
   "DC", "nodes"); a name that the test did not produce is an error. Not collective. */
PETSC_EXTERN PetscErrorCode HylcClothGetResult(HylcCloth, const char name[], PetscReal *value);
PETSC_EXTERN PetscErrorCode HylcClothGetResultNames(HylcCloth, PetscInt *n, const char *const **names);

/* The mesh of the last solve: vertices (nv x 3, current positions, gathered on every rank) and
   triangles (nt x 3). Collective (gathers). The arrays are owned by the cloth. */
PETSC_EXTERN PetscErrorCode HylcClothGetMesh(HylcCloth, PetscInt *nv, PetscInt *nt, const PetscReal **x, const PetscInt **tri);

/* ---- Plain C kernels (no PETSc objects; tested alone) ---- */

/* The homogeneous uniaxial state of a table is hylcmat_uniaxial() (include/hylcmat.h). */

/* The table's free curl: II00 and II11 (1/m, II01 = 0, in-plane strains 0) that minimize Psi; II > 0
   bends toward n (the paper's stock1: II00 < 0, II11 > 0). 0 on success. */
PETSC_EXTERN int HylcClothTableCurl(const hylcmat *m, double *II00, double *II11, double *psi);

/* Moment per unit width M(kappa) >= 0 for a curvature kappa >= 0 of the bending away from the upper
   face: the callback's contract for the elastica below. */
typedef int (*HylcClothMomentFn)(void *ctx, double kappa, double *M, double *dMdk);
/* The table's bending moment along material direction dir (0: II00, 1: II11) with the other strains 0,
   for the strip bending down with n = +z (faceDown = 0: II = -kappa) or n = -z (faceDown = 1: II = +kappa).
   ctx points to a HylcClothMomentCtx. */
typedef struct {
  const hylcmat *m;
  int            dir, faceDown;
} HylcClothMomentCtx;
PETSC_EXTERN int HylcClothTableMoment(void *ctx, double kappa, double *M, double *dMdk);
/* The elastica of an inextensible cantilever of length l (m), clamped horizontally at the root, free at
   the tip, under its own weight w per unit area (N/m^2), with the moment-curvature relation M(kappa):
   the tip's position (x, y: y <= 0 below the root) from n RK4 steps. 0 on success, -1 if the shooting
   fails (M does not reach the root moment). */
PETSC_EXTERN int HylcClothElasticaTip(HylcClothMomentFn M, void *ctx, double w, double l, int n, double *xtip, double *ytip);
/* The overhang l at which the chord from the root to the tip makes angle (radians) below the horizontal;
   the bending length of ASTM D1388 is l / 2 at 41.5 degrees. 0 on success, -1 on failure. */
PETSC_EXTERN int HylcClothElasticaOverhang(HylcClothMomentFn M, void *ctx, double w, double angle, int n, double *l);
