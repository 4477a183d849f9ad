#pragma once
/* Private definition of HylcCloth: only src/cloth/ (and white-box tests) may include this. */
#include <hylc/cloth.h>
#include <hylc/private/materialimpl.h>
#include <petscsnes.h>
#include <petsctao.h>
#include <petscts.h>
#include <petsc/private/petscimpl.h>

#define HYLC_CLOTH_MAX_RESULTS 64
#define HYLC_CLOTH_MAX_CLAMPS  8
#define CLOTH_COMM_PRIVATE(c)  PetscObjectComm((PetscObject)(c))
/* the energy of a state the elements or the supports refuse: HylcClothEnergy_Private returns
   PETSC_INFINITY (PETSc's "infinity", PETSC_MAX_REAL / 4, finite; TAO takes it for a refused point) or,
   summed over ranks, more */
#define HylcClothInfeasible(E) (PetscIsInfOrNanReal(E) || (E) >= PETSC_INFINITY)

struct _HylcClothOps {
  PetscErrorCode (*view)(HylcCloth, PetscViewer);
};

/* a rigid support: the plane {z <= z0} (kind 0) or a pedestal of radius R with a rounded rim of radius
   rho and its top at z0, centred at (cx, cy) (kind 1); contact by a barrier on the signed distance */
typedef struct {
  PetscInt  kind;
  PetscReal z0, cx, cy, R, rho;
} HylcClothSupport;

/* a clamp: a set of vertices (global, original numbering) moved rigidly by t * disp from their rest
   positions (t the load parameter) */
typedef struct {
  PetscInt  n;
  PetscInt *v;
  PetscReal disp[3];
  PetscBool onlyz; /* fix only the z coordinate */
} HylcClothClamp;

struct _p_HylcCloth {
  PETSCHEADER(struct _HylcClothOps);
  /* ---- parameters (options) ---- */
  char               materialFile[PETSC_MAX_PATH_LEN];
  HylcMaterial       material;
  HylcClothTest      test;
  HylcClothFace      face;
  PetscBool          faceDefault;
  HylcClothDirection direction;
  PetscReal          angle; /* degrees, material x to the specimen's length; < -360: the test's default */
  PetscReal          length, width, h;
  char               meshFile[PETSC_MAX_PATH_LEN];
  PetscReal          meshScale;
  PetscReal          strainMax;
  PetscInt           strainSteps;
  PetscReal          gravity; /* m/s^2; < 0: the test's default */
  PetscBool          planar, planarDefault;
  char               output[PETSC_MAX_PATH_LEN];
  PetscBool          vtk, plot;
  char               plotScript[PETSC_MAX_PATH_LEN];
  HylcClothSolver    solver;
  HylcClothHessian   hessian;
  PetscReal          rtol, atol, atolUsed;
  PetscInt           maxit, loadSteps;
  PetscReal          cantAngle, cantWidth;
  PetscInt           cantN;
  PetscReal          drapeD, discD, rimRadius;
  HylcClothDynamics  dynamics;
  PetscReal          dt, dtMax, tmax, damping, restTol, restRtol, vtkDt; /* the dynamic mode: s, s, s, 1/s, m/s, 1, s */
  PetscReal          sceneClamp;
  PetscInt           ncorners, corners[4];
  PetscReal          barrierDist, barrierStiff;
  PetscBool          monitor, lsMonitor;
  /* ---- the mesh (replicated) in original numbering ---- */
  PetscInt   nv, nt;
  PetscInt  *tri;   /* nt x 3 */
  PetscReal *X;     /* nv x 3 rest positions */
  PetscReal *uv;    /* nt x 6 material coordinates per corner */
  PetscReal  area;  /* rest area */
  PetscReal *vmass; /* nv lumped area (m^2) per vertex */
  /* ---- the model ---- */
  const hylcmat   *hm;
  PetscReal        rhoA; /* kg/m^2: the table's density */
  PetscReal        g[3]; /* gravity vector */
  HylcClothSupport support[2];
  PetscInt         nsupport;
  HylcClothClamp   clamp[HYLC_CLOTH_MAX_CLAMPS];
  PetscInt         nclamp;
  PetscReal        load;   /* load parameter t in [0, 1] of the clamps */
  PetscReal        gscale; /* gravity scale (load stepping) */
  PetscReal        kappaB; /* barrier stiffness per unit area (J/m^2 per m^2 of the barrier's shape) */
  /* ---- partition ---- */
  PetscMPIInt         rank, size;
  PetscInt           *perm, *iperm;      /* perm[old] = new global vertex, iperm[new] = old */
  PetscInt            vstart, vend;      /* owned vertices [vstart, vend) in the new numbering */
  PetscInt           *vranges;           /* size + 1 */
  PetscInt            ne;                /* owned elements */
  PetscInt           *elem;              /* owned elements (original triangle ids) */
  PetscInt            nloc;              /* local vertices: owned then ghosts */
  PetscInt           *loc2glob;          /* new global index of each local vertex */
  PetscInt           *stencil;           /* ne x 6 local vertex indices (-1: no neighbour) */
  int                *mask;              /* ne neighbour masks */
  hylcmat_shell_rest *rest;              /* ne */
  PetscReal          *xs, *Es, *gs, *Hs; /* work: ne x 18, ne, ne x 18, ne x 324 */
  Vec                 Xloc;              /* local (owned + ghost) coordinates, sequential */
  VecScatter          scatter;           /* global -> local */
  PetscInt           *fixed;             /* 3 * owned: 1 if that coordinate is prescribed */
  PetscReal          *xprescribed;       /* 3 * owned: its value at load 1 minus rest (the displacement per unit load) */
  PetscCount          ncoo;
  PetscReal          *coo;     /* values in the COO order */
  PetscInt           *cooElem; /* per element entry: offset of its 18x18 block's present entries */
  Mat                 H;       /* the Hessian (MPIAIJ, COO) */
  Vec                 x, x0;   /* the state and the rest positions (global, new numbering) */
  /* ---- solvers ---- */
  SNES      snes;
  Tao       tao;
  Vec       xprev;      /* last accepted iterate (feasibility check of TAO's trial points) */
  PetscInt  nnegPivots; /* from the last factorization (MUMPS) */
  PetscInt  newtonIts, lsFails, hessExact, hessProj, lastIts, lastReason, loadStepsDone;
  PetscBool lastExact; /* the last Hessian assembled was the exact one */
  PetscReal Escale;    /* an energy scale for the rounding test of the line search (J) */
  /* ---- the dynamic mode (dynamic.c): the backward Euler step's incremental potential is on while
     dynamic is set ---- */
  PetscBool dynamic;
  PetscReal dtcur, time, restResidual; /* restResidual: the static gradient norm / force scale at rest */
  Vec       xn, vn;                    /* the state and velocity at the start of the step */
  PetscInt  timeSteps, timeStepFails, polishes;
  /* ---- results ---- */
  PetscInt   nresults;
  char       rname[HYLC_CLOTH_MAX_RESULTS][32];
  PetscReal  rvalue[HYLC_CLOTH_MAX_RESULTS];
  PetscReal *xgather; /* nv x 3 (original numbering) */
  PetscBool  setupcalled, meshbuilt;
};

/* mesh.c */
PETSC_INTERN PetscErrorCode HylcClothMeshStrip_Private(HylcCloth, PetscReal x0, PetscReal L, PetscReal W, PetscReal h);
PETSC_INTERN PetscErrorCode HylcClothMeshStripN_Private(HylcCloth, PetscReal x0, PetscReal L, PetscReal W, PetscInt nx, PetscInt ny);
PETSC_INTERN PetscErrorCode HylcClothMeshStripAcross_Private(HylcCloth, PetscReal x0, PetscReal L, PetscReal W, PetscInt nx, PetscInt ny);
PETSC_INTERN PetscErrorCode HylcClothMeshDisc_Private(HylcCloth, PetscReal R, PetscReal Rsnap, PetscReal h);
PETSC_INTERN PetscErrorCode HylcClothMeshReadOBJ_Private(HylcCloth, const char path[], PetscReal scale);
PETSC_INTERN PetscErrorCode HylcClothMeshMaterial_Private(HylcCloth, PetscReal angleRad, PetscBool faceDown);
PETSC_INTERN PetscErrorCode HylcClothMeshReset_Private(HylcCloth);
/* setup.c: partition, scatters, Hessian pattern; clamps on the mesh */
PETSC_INTERN PetscErrorCode HylcClothBuild_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothLayoutReset_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothAddClamp_Private(HylcCloth, PetscInt n, const PetscInt v[], const PetscReal disp[3], PetscBool onlyz);
PETSC_INTERN PetscErrorCode HylcClothClampsReset_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothApplyClamps_Private(HylcCloth, Vec);
/* energy.c */
PETSC_INTERN PetscErrorCode HylcClothEnergy_Private(HylcCloth, Vec X, PetscReal *E, Vec G);
PETSC_INTERN PetscErrorCode HylcClothHessian_Private(HylcCloth, Vec X, PetscBool project, Mat H);
PETSC_INTERN PetscErrorCode HylcClothFeasible_Private(HylcCloth, Vec X0, Vec X1, PetscBool *ok);
PETSC_INTERN PetscErrorCode HylcClothReaction_Private(HylcCloth, Vec X, PetscInt clamp, PetscReal F[3]);
PETSC_INTERN PetscErrorCode HylcClothStrains_Private(HylcCloth, Vec X, PetscReal *z);
PETSC_INTERN PetscErrorCode HylcClothGather_Private(HylcCloth, Vec X);
/* solve.c */
PETSC_INTERN PetscErrorCode HylcClothSolveStatic_Private(HylcCloth, PetscBool *converged);
PETSC_INTERN PetscErrorCode HylcClothSolverReset_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothForceScale_Private(HylcCloth, Vec X, PetscReal *F);
PETSC_INTERN PetscErrorCode HylcClothSolverOptions_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothLoadPath_Private(HylcCloth, PetscReal load, PetscReal gscale, PetscInt nsteps, PetscBool *converged);
PETSC_INTERN PetscErrorCode HylcClothBacktrack_Private(HylcCloth, Vec X, PetscReal E0, Vec F, Vec Y, Vec W, Vec G, PetscReal *lambda, PetscBool *ok);
PETSC_INTERN PetscErrorCode HylcClothFormHessian_Private(HylcCloth, Vec X, Mat H);
PETSC_INTERN PetscErrorCode HylcClothDefaultKSP_Private(KSP, PetscBool preonly);
PETSC_INTERN PetscErrorCode HylcClothFactor_Private(KSP);
/* dynamic.c */
PETSC_INTERN PetscErrorCode HylcClothSettle_Private(HylcCloth, PetscBool *rest);
PETSC_INTERN PetscErrorCode HylcClothEquilibrium_Private(HylcCloth, PetscInt nsteps, PetscBool *converged);
PETSC_INTERN PetscErrorCode HylcClothDynamicReset_Private(HylcCloth);
/* output.c */
PETSC_INTERN PetscErrorCode HylcClothWriteVTK_Private(HylcCloth, const char path[]);
PETSC_INTERN PetscErrorCode HylcClothOutputName_Private(HylcCloth, const char suffix[], char path[], size_t len);
PETSC_INTERN PetscErrorCode HylcClothPlot_Private(HylcCloth, const char kind[], const char csv[]);
PETSC_INTERN PetscErrorCode HylcClothResult_Private(HylcCloth, const char name[], PetscReal value);
/* a CSV text built in memory and written (rank 0, atomically) at the end of a test */
typedef struct {
  char  *s;
  size_t len, cap;
} HylcClothText;
PETSC_INTERN PetscErrorCode HylcClothTextAppend_Private(HylcClothText *, const char fmt[], ...) PETSC_ATTRIBUTE_FORMAT(2, 3);
PETSC_INTERN PetscErrorCode HylcClothTextWrite_Private(HylcCloth, HylcClothText *, const char path[]);
/* tests.c */
PETSC_INTERN PetscErrorCode HylcClothRunTensile_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothRunBias_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothRunCantilever_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothRunDrape_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothRunScene_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothRunUniaxial_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothRunCurl_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothVerticesInBox_Private(HylcCloth, PetscReal, PetscReal, PetscReal, PetscReal, PetscInt *, PetscInt **);
PETSC_INTERN PetscErrorCode HylcClothStrip_Private(HylcCloth, PetscReal x0, PetscReal L, PetscReal W, PetscReal h, PetscReal angle, PetscBool faceDown);
PETSC_INTERN PetscErrorCode HylcClothPrepare_Private(HylcCloth);
PETSC_INTERN PetscErrorCode HylcClothZoneMean_Private(HylcCloth, const PetscReal *z, PetscReal, PetscReal, PetscReal, PetscReal, PetscReal mean[6]);
/* kernels.c */
PETSC_INTERN double HylcClothBarrier_Private(double g, double gh, double *d1, double *d2);
PETSC_INTERN double HylcClothSupportDistance_Private(const HylcClothSupport *, const double p[3], double grad[3], double hess[9]);
