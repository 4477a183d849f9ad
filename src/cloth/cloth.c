/* HylcCloth: registration, lifecycle, options, setters, viewer and results (include/hylc/cloth.h). */
#include <hylc/private/clothimpl.h>

PetscClassId  HYLC_CLOTH_CLASSID;
PetscLogEvent HYLC_ClothSetUp, HYLC_ClothAssemble, HYLC_ClothSolve, HYLC_ClothLineSearch, HYLC_ClothStep, HYLC_ClothOutput;

const char *const HylcClothTests[]      = {"tensile", "bias", "cantilever", "drape", "scene", "uniaxial", "curl", "HylcClothTest", "HYLC_CLOTH_TEST_", NULL};
const char *const HylcClothFaces[]      = {"up", "down", "both", "HylcClothFace", "HYLC_CLOTH_FACE_", NULL};
const char *const HylcClothDirections[] = {"x", "y", "both", "HylcClothDirection", "HYLC_CLOTH_DIR_", NULL};
const char *const HylcClothSolvers[]    = {"newton", "trust", "HylcClothSolver", "HYLC_CLOTH_SOLVER_", NULL};
const char *const HylcClothHessians[]   = {"projected", "exact", "auto", "HylcClothHessian", "HYLC_CLOTH_HESSIAN_", NULL};

static PetscBool HylcClothPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcClothFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcClothPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothInitializePackage - Registers the cloth's class id and log events (CLOTH_SetUp,
  CLOTH_Assemble, CLOTH_Solve, CLOTH_LineSearch, CLOTH_Step, CLOTH_Output). Called by HylcClothCreate();
  idempotent. Not collective.

  Level: developer
@*/
PetscErrorCode HylcClothInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcClothPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcClothPackageInitialized = PETSC_TRUE;
  PetscCall(HylcInitializePackage()); /* the material's class */
  PetscCall(PetscClassIdRegister("HylcCloth", &HYLC_CLOTH_CLASSID));
  PetscCall(PetscLogEventRegister("CLOTH_SetUp", HYLC_CLOTH_CLASSID, &HYLC_ClothSetUp));
  PetscCall(PetscLogEventRegister("CLOTH_Assemble", HYLC_CLOTH_CLASSID, &HYLC_ClothAssemble));
  PetscCall(PetscLogEventRegister("CLOTH_Solve", HYLC_CLOTH_CLASSID, &HYLC_ClothSolve));
  PetscCall(PetscLogEventRegister("CLOTH_LineSearch", HYLC_CLOTH_CLASSID, &HYLC_ClothLineSearch));
  PetscCall(PetscLogEventRegister("CLOTH_Step", HYLC_CLOTH_CLASSID, &HYLC_ClothStep));
  PetscCall(PetscLogEventRegister("CLOTH_Output", HYLC_CLOTH_CLASSID, &HYLC_ClothOutput));
  PetscCall(PetscRegisterFinalize(HylcClothFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothCreate - Creates a cloth with the default options (test tensile; the test's own specimen,
  mesh size, gravity and faces). Collective.

  Input Parameter:
. comm - the communicator (the mesh is partitioned over its ranks)

  Output Parameter:
. out - the cloth

  Level: beginner
@*/
PetscErrorCode HylcClothCreate(MPI_Comm comm, HylcCloth *out)
{
  HylcCloth c;

  PetscFunctionBegin;
  PetscValidPointer(out, 2);
  PetscCall(HylcClothInitializePackage());
  PetscCall(PetscHeaderCreate(c, HYLC_CLOTH_CLASSID, "HylcCloth", "Cloth solver and virtual fabric tests", "Cloth", comm, HylcClothDestroy, HylcClothView));
  c->test          = HYLC_CLOTH_TEST_TENSILE;
  c->face          = HYLC_CLOTH_FACE_UP;
  c->faceDefault   = PETSC_TRUE; /* the test's default */
  c->direction     = HYLC_CLOTH_DIR_BOTH;
  c->angle         = -1000;
  c->length        = -1;
  c->width         = -1;
  c->h             = -1;
  c->meshScale     = 1;
  c->strainMax     = 0.1;
  c->strainSteps   = 10;
  c->gravity       = -1;
  c->planar        = PETSC_FALSE;
  c->planarDefault = PETSC_TRUE;
  c->vtk           = PETSC_TRUE;
  c->plot          = PETSC_TRUE;
  c->solver        = HYLC_CLOTH_SOLVER_NEWTON;
  c->hessian       = HYLC_CLOTH_HESSIAN_AUTO;
  c->rtol          = 1e-10;
  c->atol          = -1;
  c->maxit         = 25;
  c->loadSteps     = -1;
  c->cantAngle     = 41.5;
  c->cantWidth     = 0.025;
  c->cantN         = 40;
  c->drapeD        = 0.30;
  c->discD         = 0.18;
  c->rimRadius     = 0.002;
  c->dynamics      = HYLC_CLOTH_DYNAMICS_AUTO;
  c->dt            = 1e-3;
  c->dtMax         = 0.1;
  c->tmax          = 30;
  c->damping       = 2;
  c->restTol       = 1e-3;
  c->restRtol      = 1e-4;
  c->sceneClamp    = 0;
  c->ncorners      = 0;
  c->barrierDist   = 1e-3;
  c->barrierStiff  = 0;
  c->gscale        = 1;
  PetscCall(PetscStrncpy(c->output, "cloth", sizeof(c->output)));
  *out = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothDestroy - Drops a reference; frees the cloth with the last one and sets the handle to NULL.
  Collective.

  Level: beginner
@*/
PetscErrorCode HylcClothDestroy(HylcCloth *c)
{
  PetscFunctionBegin;
  if (!*c) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*c, HYLC_CLOTH_CLASSID, 1);
  if (--((PetscObject)(*c))->refct > 0) {
    *c = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcClothSolverReset_Private(*c));
  PetscCall(HylcClothLayoutReset_Private(*c));
  PetscCall(HylcClothClampsReset_Private(*c));
  PetscCall(HylcClothMeshReset_Private(*c));
  PetscCall(HylcMaterialDestroy(&(*c)->material));
  PetscCall(PetscHeaderDestroy(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetOptionsPrefix - Sets a prefix for the cloth's options (none by default: the keys are
  spelled -cloth_*; the embedded SNES, KSP, TAO and TS get the prefix followed by "cloth_"). Logically
  collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetOptionsPrefix(HylcCloth c, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(c, HYLC_CLOTH_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)c, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define CLOTH_CHECK(c) PetscValidHeaderSpecific(c, HYLC_CLOTH_CLASSID, 1)
#define CLOTH_COMM(c)  PetscObjectComm((PetscObject)(c))

/*@C
  HylcClothSetMaterialFile - The material table (-cloth_material): JSON or HDF5 (docs/material.md),
  loaded by HylcClothSetUp(). Logically collective.

  Level: beginner
@*/
PetscErrorCode HylcClothSetMaterialFile(HylcCloth c, const char path[])
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCall(PetscStrncpy(c->materialFile, path ? path : "", sizeof(c->materialFile)));
  PetscCall(HylcMaterialDestroy(&c->material));
  c->setupcalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetMaterial - A material already loaded (referenced, replaces -cloth_material). Logically
  collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetMaterial(HylcCloth c, HylcMaterial m)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCall(PetscObjectReference((PetscObject)m));
  PetscCall(HylcMaterialDestroy(&c->material));
  c->material        = m;
  c->materialFile[0] = 0;
  c->setupcalled     = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothGetMaterial - The material (after HylcClothSetUp(), or set by HylcClothSetMaterial()); not a
  new reference. Not collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothGetMaterial(HylcCloth c, HylcMaterial *m)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  *m = c->material;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetTest - The virtual test run by HylcClothRun() (-cloth_test). Logically collective.

  Level: beginner
@*/
PetscErrorCode HylcClothSetTest(HylcCloth c, HylcClothTest t)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(t >= HYLC_CLOTH_TEST_TENSILE && t <= HYLC_CLOTH_TEST_CURL, CLOTH_COMM(c), PETSC_ERR_ARG_OUTOFRANGE, "-cloth_test: unknown test %d", (int)t);
  c->test = t;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothGetTest - The selected test. Not collective.

  Level: beginner
@*/
PetscErrorCode HylcClothGetTest(HylcCloth c, HylcClothTest *t)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  *t = c->test;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetFace - Which fabric face is up (-cloth_face up|down|both): n = +z or -z. Logically
  collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetFace(HylcCloth c, HylcClothFace f)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(f >= HYLC_CLOTH_FACE_UP && f <= HYLC_CLOTH_FACE_BOTH, CLOTH_COMM(c), PETSC_ERR_ARG_OUTOFRANGE, "-cloth_face: unknown face %d", (int)f);
  c->face        = f;
  c->faceDefault = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetDirection - The material direction along the specimen (-cloth_direction x|y|both) of the
  tensile and cantilever tests. Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetDirection(HylcCloth c, HylcClothDirection d)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(d >= HYLC_CLOTH_DIR_X && d <= HYLC_CLOTH_DIR_BOTH, CLOTH_COMM(c), PETSC_ERR_ARG_OUTOFRANGE, "-cloth_direction: unknown direction %d", (int)d);
  c->direction = d;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetAngle - The angle in degrees from the specimen's length (mesh x) to the material x axis
  (-cloth_angle); overrides -cloth_direction and the bias test's 45. Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetAngle(HylcCloth c, PetscReal deg)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(PetscIsNormalReal(deg) || deg == 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_angle %g is not a finite angle", (double)deg);
  c->angle = deg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetSize - The specimen's length and width in m (-cloth_length, -cloth_width; the drape's
  specimen diameter is -cloth_drape_diameter). Logically collective.

  Level: beginner
@*/
PetscErrorCode HylcClothSetSize(HylcCloth c, PetscReal length, PetscReal width)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(length > 0 && width > 0 && PetscIsNormalReal(length) && PetscIsNormalReal(width), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_length %g and -cloth_width %g must be positive sizes in m", (double)length, (double)width);
  c->length = length;
  c->width  = width;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetMeshSize - The target edge length h of the generated meshes in m (-cloth_h). Logically
  collective.

  Level: beginner
@*/
PetscErrorCode HylcClothSetMeshSize(HylcCloth c, PetscReal h)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(h > 0 && PetscIsNormalReal(h), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_h %g must be a positive length in m", (double)h);
  c->h = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetMeshFile - A triangle mesh from a Wavefront .obj file for the scene test
  (-cloth_mesh_file, -cloth_mesh_scale: the factor to m of its coordinates and texture coordinates).
  Texture coordinates, when every corner has one, are the material coordinates. Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetMeshFile(HylcCloth c, const char path[], PetscReal scale)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(scale > 0 && PetscIsNormalReal(scale), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_mesh_scale %g must be positive", (double)scale);
  PetscCall(PetscStrncpy(c->meshFile, path ? path : "", sizeof(c->meshFile)));
  c->meshScale = scale;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetStrains - The tensile and bias tests' nominal strains: steps equal steps up to max
  (-cloth_strain_max, -cloth_strain_steps). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetStrains(HylcCloth c, PetscReal max, PetscInt steps)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(max > 0 && max < 10, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_strain_max %g must be in (0, 10)", (double)max);
  PetscCheck(steps >= 1 && steps <= 100000, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_strain_steps %" PetscInt_FMT " must be in 1..100000", steps);
  c->strainMax   = max;
  c->strainSteps = steps;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetGravity - The gravitational acceleration in m/s^2, along -z (-cloth_gravity; default 9.81,
  0 for the tensile and bias tests). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetGravity(HylcCloth c, PetscReal g)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(g >= 0 && PetscIsNormalReal(g + 1), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_gravity %g must be >= 0 (m/s^2, acting along -z)", (double)g);
  c->gravity = g;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetPlanar - Holds every vertex in its rest plane z = 0 (-cloth_planar): in-plane tests
  without curl or wrinkles. Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetPlanar(HylcCloth c, PetscBool planar)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  c->planar        = planar;
  c->planarDefault = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetOutput - The prefix of every output file (-cloth_output; default "cloth": cloth_<test>.csv,
  cloth_<test>_<case>_<step>.vtk, cloth_<test>.png); "" writes nothing. Logically collective.

  Level: beginner
@*/
PetscErrorCode HylcClothSetOutput(HylcCloth c, const char prefix[])
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCall(PetscStrncpy(c->output, prefix ? prefix : "", sizeof(c->output)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetOutputFormats - Whether to write VTK files per step (-cloth_vtk) and PNG plots
  (-cloth_plot, by examples/plot_cloth.py; -cloth_plot_script names another). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetOutputFormats(HylcCloth c, PetscBool vtk, PetscBool plot)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  c->vtk  = vtk;
  c->plot = plot;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetSolver - The equilibrium solver (-cloth_solver newton|trust) and the Hessian it uses
  (-cloth_hessian projected|exact|auto). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetSolver(HylcCloth c, HylcClothSolver s, HylcClothHessian h)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(s == HYLC_CLOTH_SOLVER_NEWTON || s == HYLC_CLOTH_SOLVER_TRUST, CLOTH_COMM(c), PETSC_ERR_ARG_OUTOFRANGE, "-cloth_solver: unknown solver %d", (int)s);
  PetscCheck(h >= HYLC_CLOTH_HESSIAN_PROJECTED && h <= HYLC_CLOTH_HESSIAN_AUTO, CLOTH_COMM(c), PETSC_ERR_ARG_OUTOFRANGE, "-cloth_hessian: unknown Hessian %d", (int)h);
  if (s != c->solver) PetscCall(HylcClothSolverReset_Private(c));
  c->solver  = s;
  c->hessian = h;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetTolerances - Newton's relative tolerance on the gradient norm and its iteration limit per
  load step (-cloth_rtol, -cloth_max_it; -cloth_atol the absolute one in N, default 1e-12 times the
  cloth's weight or 1e-12 N). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetTolerances(HylcCloth c, PetscReal rtol, PetscInt maxit)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(rtol > 0 && rtol < 1, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_rtol %g must be in (0, 1)", (double)rtol);
  PetscCheck(maxit >= 1, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_max_it %" PetscInt_FMT " must be >= 1", maxit);
  c->rtol  = rtol;
  c->maxit = maxit;
  PetscCall(HylcClothSolverReset_Private(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetLoadSteps - The number of load steps of gravity and of the clamps' motion (-cloth_load_steps;
  default: the test's). A step that fails is halved. Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetLoadSteps(HylcCloth c, PetscInt n)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(n >= 1, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_load_steps %" PetscInt_FMT " must be >= 1", n);
  c->loadSteps = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetCantilever - The cantilever's tip angle in degrees (-cloth_cantilever_angle, 41.5 in ASTM
  D1388) and strip width in m (-cloth_cantilever_width, 0.025). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetCantilever(HylcCloth c, PetscReal angle, PetscReal width)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(angle > 0 && angle < 90, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_cantilever_angle %g must be in (0, 90) degrees", (double)angle);
  PetscCheck(width > 0 && PetscIsNormalReal(width), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_cantilever_width %g must be a positive width in m", (double)width);
  c->cantAngle = angle;
  c->cantWidth = width;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetDrape - The Cusick test's specimen and disc diameters in m (-cloth_drape_diameter 0.30,
  -cloth_drape_disc 0.18). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetDrape(HylcCloth c, PetscReal D, PetscReal d)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(D > 0 && d > 0 && d < D && PetscIsNormalReal(D) && PetscIsNormalReal(d), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_drape_diameter %g and -cloth_drape_disc %g: need 0 < disc < specimen (m)", (double)D, (double)d);
  c->drapeD = D;
  c->discD  = d;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetScene - The scene test's supports: clamped along clampLength (m) of its end x = 0, centred
  (-cloth_scene_clamp), and/or pinned at the given corners (-cloth_scene_corners, 0: (0,0), 1: (L,0),
  2: (L,W), 3: (0,W)). Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetScene(HylcCloth c, PetscReal clampLength, PetscInt n, const PetscInt corners[])
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(clampLength >= 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_scene_clamp %g must be >= 0 (m)", (double)clampLength);
  PetscCheck(n >= 0 && n <= 4, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_scene_corners: at most 4 corners");
  for (PetscInt i = 0; i < n; i++) PetscCheck(corners[i] >= 0 && corners[i] <= 3, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_scene_corners: corner %" PetscInt_FMT " is not one of 0 1 2 3", corners[i]);
  c->sceneClamp = clampLength;
  c->ncorners   = n;
  for (PetscInt i = 0; i < n; i++) c->corners[i] = corners[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetBarrier - The contact barrier's activation distance (m) and stiffness (J/m^2 per m^2 of
  the barrier's shape; 0: rho_A g_0 / distance, which carries the cloth's weight at about half the
  distance) (-cloth_barrier_distance, -cloth_barrier_stiffness). Logically collective.

  Level: advanced
@*/
PetscErrorCode HylcClothSetBarrier(HylcCloth c, PetscReal dist, PetscReal stiff)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(dist > 0 && stiff >= 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_barrier_distance %g must be > 0 and -cloth_barrier_stiffness %g >= 0", (double)dist, (double)stiff);
  c->barrierDist  = dist;
  c->barrierStiff = stiff;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetDynamics - How the equilibria under gravity are reached (-cloth_dynamic off|auto|on: the
  static load path only; the backward Euler dynamics where it fails; the dynamics from the flat state
  always) and the dynamics' parameters: the first time step dt (-cloth_dt, s), the mass-proportional
  damping (-cloth_damping, 1/s), the longest simulated time (-cloth_tmax, s) and the largest vertex speed
  at rest (-cloth_rest_tol, m/s). A value < 0 keeps the current one. -cloth_dt_max (s) bounds the time
  step as it grows. Logically collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothSetDynamics(HylcCloth c, HylcClothDynamics mode, PetscReal dt, PetscReal damping, PetscReal tmax, PetscReal restTol)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(mode >= HYLC_CLOTH_DYNAMICS_OFF && mode <= HYLC_CLOTH_DYNAMICS_ON, CLOTH_COMM(c), PETSC_ERR_ARG_OUTOFRANGE, "-cloth_dynamic: unknown mode %d", (int)mode);
  PetscCheck(!PetscIsInfOrNanReal(dt) && !PetscIsInfOrNanReal(damping) && !PetscIsInfOrNanReal(tmax) && !PetscIsInfOrNanReal(restTol), CLOTH_COMM(c), PETSC_ERR_USER_INPUT,
             "-cloth_dt %g, -cloth_damping %g, -cloth_tmax %g, -cloth_rest_tol %g must be finite", (double)dt, (double)damping, (double)tmax, (double)restTol);
  c->dynamics = mode;
  if (dt >= 0) {
    PetscCheck(dt > 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_dt %g must be a positive time step in s", (double)dt);
    c->dt = dt;
  }
  if (damping >= 0) c->damping = damping;
  if (tmax >= 0) {
    PetscCheck(tmax > 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_tmax %g must be a positive time in s", (double)tmax);
    c->tmax = tmax;
  }
  if (restTol >= 0) {
    PetscCheck(restTol > 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_rest_tol %g must be a positive speed in m/s", (double)restTol);
    c->restTol = restTol;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetFromOptions - Reads the cloth's options (docs/fabric.md has the table); builds nothing.
  Collective.

  Options (units in the -help text):
+ -cloth_material <file>   - the material table (JSON or HDF5)
. -cloth_test <tensile>    - tensile, bias, cantilever, drape, scene, uniaxial (the table's own curve), curl
. -cloth_face, -cloth_direction, -cloth_angle - orientation of the fabric and of its material axes
. -cloth_length, -cloth_width, -cloth_h, -cloth_mesh_file, -cloth_mesh_scale - the specimen and its mesh
. -cloth_strain_max, -cloth_strain_steps, -cloth_gravity, -cloth_planar - loads
. -cloth_solver, -cloth_hessian, -cloth_rtol, -cloth_atol, -cloth_max_it, -cloth_load_steps - the solver
. -cloth_dynamic, -cloth_dt, -cloth_dt_max, -cloth_damping, -cloth_tmax, -cloth_rest_tol, -cloth_rest_rtol, -cloth_vtk_dt - the dynamics (backward Euler)
. -cloth_cantilever_angle, -cloth_cantilever_width, -cloth_cantilever_n - the cantilever
. -cloth_drape_diameter, -cloth_drape_disc, -cloth_rim_radius - the drape
. -cloth_scene_clamp, -cloth_scene_corners - the scene's supports
. -cloth_barrier_distance, -cloth_barrier_stiffness, -cloth_rim_radius - contact
- -cloth_output, -cloth_vtk, -cloth_plot, -cloth_plot_script, -cloth_monitor, -cloth_view - output

  Level: beginner
@*/
PetscErrorCode HylcClothSetFromOptions(HylcCloth c)
{
  PetscEnum test = (PetscEnum)c->test, face = (PetscEnum)c->face, dir = (PetscEnum)c->direction, solver = (PetscEnum)c->solver, hess = (PetscEnum)c->hessian;
  PetscBool set, set2, b2;
  char      path[PETSC_MAX_PATH_LEN];
  PetscReal a, b;
  PetscInt  n, corners[4];

  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscObjectOptionsBegin((PetscObject)c);
  PetscCall(PetscOptionsString("-cloth_material", "Material table: JSON (ARCSim-HYLC layout, the paper's tables) or HDF5 (docs/material.md)", "HylcClothSetMaterialFile", c->materialFile, path, sizeof(path), &set));
  if (set) PetscCall(HylcClothSetMaterialFile(c, path));
  PetscCall(PetscOptionsEnum(
      "-cloth_test",
      "Virtual test: tensile (strip, ISO 13934-1), bias (45 deg extension), cantilever (ASTM D1388 A), drape (Cusick), scene (rectangle or .obj under gravity), uniaxial (the table's homogeneous uniaxial curve, no mesh), curl (free strip)",
      "HylcClothSetTest", HylcClothTests, test, &test, &set));
  if (set) PetscCall(HylcClothSetTest(c, (HylcClothTest)test));
  PetscCall(PetscOptionsEnum("-cloth_face", "Fabric face up: up (n = +z), down (n = -z), both (the cantilever's default; other tests: up)", "HylcClothSetFace", HylcClothFaces, face, &face, &set));
  if (set) PetscCall(HylcClothSetFace(c, (HylcClothFace)face));
  PetscCall(PetscOptionsEnum("-cloth_direction", "Material direction along the specimen (tensile, cantilever): x, y or both", "HylcClothSetDirection", HylcClothDirections, dir, &dir, &set));
  if (set) PetscCall(HylcClothSetDirection(c, (HylcClothDirection)dir));
  PetscCall(PetscOptionsReal("-cloth_angle", "Angle (degrees) from the specimen's length to the material x axis; overrides -cloth_direction (bias default 45)", "HylcClothSetAngle", c->angle, &a, &set));
  if (set) PetscCall(HylcClothSetAngle(c, a));
  a = c->length;
  b = c->width;
  PetscCall(PetscOptionsReal("-cloth_length", "Specimen length (m; tensile 0.2 gauge, bias 0.15, scene 0.5)", "HylcClothSetSize", c->length, &a, &set));
  PetscCall(PetscOptionsReal("-cloth_width", "Specimen width (m; tensile 0.05, bias 0.05, scene 0.5)", "HylcClothSetSize", c->width, &b, &set2));
  if (set || set2) {
    PetscCheck(a > 0 && b > 0, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_length %g and -cloth_width %g must be positive sizes in m (both given)", (double)a, (double)b);
    PetscCall(HylcClothSetSize(c, a, b));
  }
  PetscCall(PetscOptionsReal("-cloth_h", "Target edge length of the generated mesh (m; tensile 0.0025, bias 0.0025, drape 0.006, scene 0.01; cantilever: overhang / -cloth_cantilever_n)", "HylcClothSetMeshSize", c->h, &a, &set));
  if (set) PetscCall(HylcClothSetMeshSize(c, a));
  a = c->meshScale;
  PetscCall(PetscOptionsString("-cloth_mesh_file", "Triangle mesh (.obj: v, vt, f lines) for the scene test instead of the rectangle", "HylcClothSetMeshFile", c->meshFile, path, sizeof(path), &set));
  PetscCall(PetscOptionsReal("-cloth_mesh_scale", "Factor to m of the .obj coordinates", "HylcClothSetMeshFile", c->meshScale, &a, &set2));
  if (set || set2) PetscCall(HylcClothSetMeshFile(c, set ? path : c->meshFile, a));
  a = c->strainMax;
  n = c->strainSteps;
  PetscCall(PetscOptionsReal("-cloth_strain_max", "Largest nominal strain of the tensile and bias tests", "HylcClothSetStrains", c->strainMax, &a, &set));
  PetscCall(PetscOptionsInt("-cloth_strain_steps", "Equal strain steps up to -cloth_strain_max", "HylcClothSetStrains", c->strainSteps, &n, &set2));
  if (set || set2) PetscCall(HylcClothSetStrains(c, a, n));
  PetscCall(PetscOptionsReal("-cloth_gravity", "Gravity (m/s^2) along -z; default 9.81, 0 for tensile and bias", "HylcClothSetGravity", c->gravity, &a, &set));
  if (set) PetscCall(HylcClothSetGravity(c, a));
  PetscCall(PetscOptionsBool("-cloth_planar", "Hold every vertex in the plane z = 0 (in-plane test: no curl, no wrinkles; default for tensile and bias)", "HylcClothSetPlanar", c->planar, &b2, &set));
  if (set) PetscCall(HylcClothSetPlanar(c, b2));
  PetscCall(PetscOptionsEnum("-cloth_solver", "Equilibrium solver: newton (SNES newtonls, energy line search) or trust (TAO ntr)", "HylcClothSetSolver", HylcClothSolvers, solver, &solver, &set));
  PetscCall(PetscOptionsEnum("-cloth_hessian", "Hessian: projected (every element's PSD), exact, auto (exact unless its factorization has negative pivots)", "HylcClothSetSolver", HylcClothHessians, hess, &hess, &set2));
  if (set || set2) PetscCall(HylcClothSetSolver(c, (HylcClothSolver)solver, (HylcClothHessian)hess));
  a = c->rtol;
  n = c->maxit;
  PetscCall(PetscOptionsReal("-cloth_rtol", "Newton: relative decrease of the gradient norm per load step", "HylcClothSetTolerances", c->rtol, &a, &set));
  PetscCall(PetscOptionsInt("-cloth_max_it", "Newton: iterations per load step", "HylcClothSetTolerances", c->maxit, &n, &set2));
  if (set || set2) PetscCall(HylcClothSetTolerances(c, a, n));
  PetscCall(PetscOptionsReal("-cloth_atol", "Newton: absolute gradient norm (N; < 0: 1e-12 x the cloth's weight, at least 1e-14 N)", "HylcClothSetTolerances", c->atol, &c->atol, NULL));
  PetscCall(PetscOptionsInt("-cloth_load_steps", "Load steps of gravity (cantilever, scene) and of the clamps (< 0: the test's)", "HylcClothSetLoadSteps", c->loadSteps, &n, &set));
  if (set) PetscCall(HylcClothSetLoadSteps(c, n));
  {
    PetscEnum mode = (PetscEnum)c->dynamics;
    PetscReal dt = c->dt, damp = c->damping, tmax = c->tmax, rtol = c->restTol;
    PetscBool s1, s2, s3, s4, s5;
    PetscCall(PetscOptionsEnum("-cloth_dynamic", "Equilibria under gravity: off (static load path), auto (backward Euler dynamics where the load path fails), on (dynamics from the flat state)", "HylcClothSetDynamics", HylcClothDynamicsTypes, mode,
                               &mode, &s1));
    PetscCall(PetscOptionsReal("-cloth_dt", "Dynamics: first time step (s)", "HylcClothSetDynamics", c->dt, &dt, &s2));
    PetscCall(PetscOptionsReal("-cloth_damping", "Dynamics: mass-proportional damping (1/s)", "HylcClothSetDynamics", c->damping, &damp, &s3));
    PetscCall(PetscOptionsReal("-cloth_tmax", "Dynamics: longest simulated time (s)", "HylcClothSetDynamics", c->tmax, &tmax, &s4));
    PetscCall(PetscOptionsReal("-cloth_rest_tol", "Dynamics: largest vertex speed at rest (m/s)", "HylcClothSetDynamics", c->restTol, &rtol, &s5));
    if (s1 || s2 || s3 || s4 || s5) PetscCall(HylcClothSetDynamics(c, (HylcClothDynamics)mode, dt, damp, tmax, rtol));
    PetscCall(PetscOptionsReal("-cloth_rest_rtol", "Dynamics: largest static residual (gradient norm over the force scale) of a state at rest that Newton does not polish", "HylcClothSetDynamics", c->restRtol, &c->restRtol, NULL));
    PetscCheck(c->restRtol > 0 && c->restRtol < 1, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_rest_rtol %g must be in (0, 1)", (double)c->restRtol);
    PetscCall(PetscOptionsReal("-cloth_vtk_dt", "Dynamics: simulated time between VTK frames (s; 0: none), <output>_dynamics_NNNN.vtk", "", c->vtkDt, &c->vtkDt, NULL));
    PetscCheck(c->vtkDt >= 0 && !PetscIsInfOrNanReal(c->vtkDt), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_vtk_dt %g must be >= 0 (s)", (double)c->vtkDt);
    PetscCall(PetscOptionsReal("-cloth_dt_max", "Dynamics: largest time step as it grows (s)", "HylcClothSetDynamics", c->dtMax, &c->dtMax, NULL));
    PetscCheck(c->dtMax >= c->dt && PetscIsNormalReal(c->dtMax), CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_dt_max %g must be at least -cloth_dt %g (s)", (double)c->dtMax, (double)c->dt);
  }
  a = c->cantAngle;
  b = c->cantWidth;
  PetscCall(PetscOptionsReal("-cloth_cantilever_angle", "Cantilever: chord angle below the horizontal at the measured overhang (degrees)", "HylcClothSetCantilever", c->cantAngle, &a, &set));
  PetscCall(PetscOptionsReal("-cloth_cantilever_width", "Cantilever: strip width (m)", "HylcClothSetCantilever", c->cantWidth, &b, &set2));
  if (set || set2) PetscCall(HylcClothSetCantilever(c, a, b));
  PetscCall(PetscOptionsInt("-cloth_cantilever_n", "Cantilever: lattice spacings along the overhang", "HylcClothSetCantilever", c->cantN, &c->cantN, NULL));
  PetscCheck(c->cantN >= 4 && c->cantN <= 10000, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_cantilever_n %" PetscInt_FMT " must be in 4..10000", c->cantN);
  a = c->drapeD;
  b = c->discD;
  PetscCall(PetscOptionsReal("-cloth_drape_diameter", "Drape: specimen diameter (m)", "HylcClothSetDrape", c->drapeD, &a, &set));
  PetscCall(PetscOptionsReal("-cloth_drape_disc", "Drape: support disc diameter (m)", "HylcClothSetDrape", c->discD, &b, &set2));
  if (set || set2) PetscCall(HylcClothSetDrape(c, a, b));
  PetscCall(PetscOptionsReal("-cloth_rim_radius", "Drape: rounding radius of the support disc's rim (m)", "HylcClothSetDrape", c->rimRadius, &c->rimRadius, NULL));
  PetscCheck(c->rimRadius > 0 && c->rimRadius < 0.5 * c->discD, CLOTH_COMM(c), PETSC_ERR_USER_INPUT, "-cloth_rim_radius %g must be in (0, disc radius)", (double)c->rimRadius);
  a = c->sceneClamp;
  n = 4;
  for (PetscInt i = 0; i < 4; i++) corners[i] = i < c->ncorners ? c->corners[i] : 0; /* -help shows the first */
  PetscCall(PetscOptionsReal("-cloth_scene_clamp", "Scene: clamped length (m) of the end x = 0, centred (0: none)", "HylcClothSetScene", c->sceneClamp, &a, &set));
  PetscCall(PetscOptionsIntArray("-cloth_scene_corners", "Scene: pinned corners, a list of 0 (0,0) 1 (L,0) 2 (L,W) 3 (0,W)", "HylcClothSetScene", corners, &n, &set2));
  if (set || set2) PetscCall(HylcClothSetScene(c, a, set2 ? n : c->ncorners, set2 ? corners : c->corners));
  a = c->barrierDist;
  b = c->barrierStiff;
  PetscCall(PetscOptionsReal("-cloth_barrier_distance", "Contact: barrier activation distance (m)", "HylcClothSetBarrier", c->barrierDist, &a, &set));
  PetscCall(PetscOptionsReal("-cloth_barrier_stiffness", "Contact: barrier stiffness (J/m^4; 0: rho_A g / distance)", "HylcClothSetBarrier", c->barrierStiff, &b, &set2));
  if (set || set2) PetscCall(HylcClothSetBarrier(c, a, b));
  PetscCall(PetscOptionsString("-cloth_output", "Prefix of the output files (CSV, VTK, PNG); empty: none", "HylcClothSetOutput", c->output, c->output, sizeof(c->output), NULL));
  PetscCall(PetscOptionsBool("-cloth_vtk", "Write a VTK file per step (ParaView)", "HylcClothSetOutputFormats", c->vtk, &c->vtk, NULL));
  PetscCall(PetscOptionsBool("-cloth_plot", "Write PNG plots (python3 + matplotlib, examples/plot_cloth.py)", "HylcClothSetOutputFormats", c->plot, &c->plot, NULL));
  PetscCall(PetscOptionsString("-cloth_plot_script", "The plotting script (default: examples/plot_cloth.py beside the program's checkout or installation)", "HylcClothSetOutputFormats", c->plotScript, c->plotScript, sizeof(c->plotScript), NULL));
  PetscCall(PetscOptionsBool("-cloth_monitor", "Print every load or time step", "", c->monitor, &c->monitor, NULL));
  PetscCall(PetscOptionsBool("-cloth_linesearch_monitor", "Print every line search: step, Hessian used, energies", "", c->lsMonitor, &c->lsMonitor, NULL));
  PetscOptionsEnd();
  PetscCall(HylcClothSolverOptions_Private(c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothSetUp - Loads the material (-cloth_material) and resolves the test's defaults. The meshes are
  built by HylcClothRun(), per case. -cloth_view prints the cloth here. Collective.

  Level: beginner
@*/
PetscErrorCode HylcClothSetUp(HylcCloth c)
{
  MPI_Comm comm = CLOTH_COMM(c);

  PetscFunctionBegin;
  CLOTH_CHECK(c);
  if (c->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_ClothSetUp, c, 0, 0, 0));
  if (!c->material) {
    PetscCheck(c->materialFile[0], comm, PETSC_ERR_USER_INPUT, "no material table: give -cloth_material <file.json|file.h5>");
    PetscCall(HylcFileCheckInput(comm, c->materialFile, "-cloth_material"));
    PetscCall(HylcMaterialCreate(comm, &c->material));
    PetscCall(HylcMaterialLoad(c->material, c->materialFile));
  }
  c->hm   = c->material->hm;
  c->rhoA = hylcmat_density(c->hm);
  PetscCheck(c->rhoA > 0 || c->test == HYLC_CLOTH_TEST_TENSILE || c->test == HYLC_CLOTH_TEST_BIAS || c->test == HYLC_CLOTH_TEST_UNIAXIAL || c->test == HYLC_CLOTH_TEST_CURL, comm, PETSC_ERR_USER_INPUT,
             "%s: the table's density is %g kg/m^2; the %s test needs its weight", c->materialFile[0] ? c->materialFile : "material", (double)c->rhoA, HylcClothTests[c->test]);
  /* the test's defaults */
  if (c->gravity < 0) c->gravity = (c->test == HYLC_CLOTH_TEST_TENSILE || c->test == HYLC_CLOTH_TEST_BIAS || c->test == HYLC_CLOTH_TEST_CURL) ? 0 : 9.81;
  c->g[0] = c->g[1] = 0;
  c->g[2]           = -c->gravity;
  if (c->planarDefault) c->planar = (c->test == HYLC_CLOTH_TEST_TENSILE || c->test == HYLC_CLOTH_TEST_BIAS) ? PETSC_TRUE : PETSC_FALSE;
  if (c->faceDefault) c->face = c->test == HYLC_CLOTH_TEST_CANTILEVER ? HYLC_CLOTH_FACE_BOTH : HYLC_CLOTH_FACE_UP;
  if (c->length < 0) {
    switch (c->test) {
    case HYLC_CLOTH_TEST_TENSILE:
      c->length = 0.2;
      c->width  = 0.05;
      break;
    case HYLC_CLOTH_TEST_BIAS:
      c->length = 0.15;
      c->width  = 0.05;
      break;
    case HYLC_CLOTH_TEST_CURL:
      c->length = 0.03;
      c->width  = 0.02;
      break;
    default:
      c->length = 0.5;
      c->width  = 0.5;
    }
  }
  if (c->h < 0) {
    switch (c->test) {
    case HYLC_CLOTH_TEST_DRAPE:
      c->h = 0.006;
      break;
    case HYLC_CLOTH_TEST_SCENE:
      c->h = 0.01;
      break;
    case HYLC_CLOTH_TEST_CURL:
      c->h = 0.002;
      break;
    default:
      c->h = 0.0025;
    }
  }
  c->kappaB      = c->barrierStiff > 0 ? c->barrierStiff : (c->rhoA > 0 ? c->rhoA : 0.3) * 9.81 / c->barrierDist;
  c->setupcalled = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_ClothSetUp, c, 0, 0, 0));
  PetscCall(HylcClothViewFromOptions(c, NULL, "-cloth_view"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothView - Prints the cloth's test, material, specimen, solver and (after a run) its results.
  Collective.

  Level: beginner
@*/
PetscErrorCode HylcClothView(HylcCloth c, PetscViewer viewer)
{
  PetscBool iascii;

  PetscFunctionBegin;
  CLOTH_CHECK(c);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(CLOTH_COMM(c), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectPrintClassNamePrefixType((PetscObject)c, viewer));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "test: %s, material: %s", HylcClothTests[c->test], c->materialFile[0] ? c->materialFile : "(set in memory)"));
  if (c->hm) PetscCall(PetscViewerASCIIPrintf(viewer, " (area density %g kg/m^2, the table's \"density\")", (double)c->rhoA));
  PetscCall(PetscViewerASCIIPrintf(viewer, "\n"));
  PetscCall(PetscViewerASCIIPrintf(viewer, "face up: %s, direction: %s, angle: %s\n", c->faceDefault && !c->setupcalled ? "(test default)" : HylcClothFaces[c->face], HylcClothDirections[c->direction], c->angle < -360 ? "(test default)" : "set"));
  PetscCall(PetscViewerASCIIPrintf(viewer, "specimen: %g x %g m, h %g m%s%s, gravity %g m/s^2%s\n", (double)c->length, (double)c->width, (double)c->h, c->meshFile[0] ? ", mesh " : "", c->meshFile, (double)c->gravity, c->planar ? ", planar" : ""));
  if (c->nv) PetscCall(PetscViewerASCIIPrintf(viewer, "mesh: %" PetscInt_FMT " vertices, %" PetscInt_FMT " triangles, area %g m^2, on %d ranks\n", c->nv, c->nt, (double)c->area, (int)c->size));
  PetscCall(PetscViewerASCIIPrintf(viewer, "solver: %s, Hessian %s, rtol %g, max_it %" PetscInt_FMT "\n", HylcClothSolvers[c->solver], HylcClothHessians[c->hessian], (double)c->rtol, c->maxit));
  PetscCall(PetscViewerASCIIPrintf(viewer, "contact barrier: distance %g m, stiffness %g J/m^4\n", (double)c->barrierDist, (double)c->kappaB));
  PetscCall(PetscViewerASCIIPrintf(viewer, "dynamics: %s; backward Euler, first step %g s (at most %g s), damping %g 1/s, at most %g s, at rest below %g m/s\n", HylcClothDynamicsTypes[c->dynamics], (double)c->dt, (double)c->dtMax, (double)c->damping,
                                   (double)c->tmax, (double)c->restTol));
  if (c->test == HYLC_CLOTH_TEST_DRAPE) PetscCall(PetscViewerASCIIPrintf(viewer, "drape (static): specimen %g m on a disc of %g m (rim radius %g m)\n", (double)c->drapeD, (double)c->discD, (double)c->rimRadius));
  if (c->test == HYLC_CLOTH_TEST_CANTILEVER) PetscCall(PetscViewerASCIIPrintf(viewer, "cantilever: tip angle %g deg, width %g m, %" PetscInt_FMT " spacings along the overhang\n", (double)c->cantAngle, (double)c->cantWidth, c->cantN));
  PetscCall(PetscViewerASCIIPrintf(viewer, "output: %s\n", c->output[0] ? c->output : "(none)"));
  for (PetscInt i = 0; i < c->nresults; i++) PetscCall(PetscViewerASCIIPrintf(viewer, "%s = %.6g\n", c->rname[i], (double)c->rvalue[i]));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothViewFromOptions - HylcClothView() when the option name (with the cloth's prefix) is set.
  Collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothViewFromOptions(HylcCloth c, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCall(PetscObjectViewFromOptions((PetscObject)c, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcClothResult_Private(HylcCloth c, const char name[], PetscReal value)
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < c->nresults; i++) {
    PetscBool same;
    PetscCall(PetscStrcmp(c->rname[i], name, &same));
    if (same) {
      c->rvalue[i] = value;
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  PetscCheck(c->nresults < HYLC_CLOTH_MAX_RESULTS, PETSC_COMM_SELF, PETSC_ERR_PLIB, "too many results");
  PetscCall(PetscStrncpy(c->rname[c->nresults], name, sizeof(c->rname[0])));
  c->rvalue[c->nresults++] = value;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothGetResult - A scalar result of the last HylcClothRun() by name (HylcClothGetResultNames()
  lists them). Not collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothGetResult(HylcCloth c, const char name[], PetscReal *value)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  for (PetscInt i = 0; i < c->nresults; i++) {
    PetscBool same;
    PetscCall(PetscStrcmp(c->rname[i], name, &same));
    if (same) {
      *value = c->rvalue[i];
      PetscFunctionReturn(PETSC_SUCCESS);
    }
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "the %s test gave no result named %s", HylcClothTests[c->test], name);
}

/*@C
  HylcClothGetResultNames - The names of the results of the last HylcClothRun(). Not collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothGetResultNames(HylcCloth c, PetscInt *n, const char *const **names)
{
  static const char *list[HYLC_CLOTH_MAX_RESULTS];

  PetscFunctionBegin;
  CLOTH_CHECK(c);
  for (PetscInt i = 0; i < c->nresults; i++) list[i] = c->rname[i];
  *n     = c->nresults;
  *names = list;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothGetMesh - The mesh of the last solve: current positions (nv x 3, original vertex order,
  gathered on every rank) and triangles (nt x 3). Collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothGetMesh(HylcCloth c, PetscInt *nv, PetscInt *nt, const PetscReal **x, const PetscInt **tri)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCheck(c->x, CLOTH_COMM(c), PETSC_ERR_ORDER, "no mesh: call HylcClothRun() first");
  PetscCall(HylcClothGather_Private(c, c->x));
  if (nv) *nv = c->nv;
  if (nt) *nt = c->nt;
  if (x) *x = c->xgather;
  if (tri) *tri = c->tri;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothRun - Runs the selected test (calls HylcClothSetUp() if needed): builds its meshes, solves,
  measures, writes -cloth_output's CSV, VTK and PNG files and prints a summary. Collective.

  Level: beginner
@*/
PetscErrorCode HylcClothRun(HylcCloth c)
{
  PetscFunctionBegin;
  CLOTH_CHECK(c);
  PetscCall(HylcClothSetUp(c));
  c->nresults  = 0;
  c->newtonIts = c->lsFails = c->hessExact = c->hessProj = c->loadStepsDone = 0;
  c->timeSteps = c->timeStepFails = c->polishes = 0;
  switch (c->test) {
  case HYLC_CLOTH_TEST_TENSILE:
    PetscCall(HylcClothRunTensile_Private(c));
    break;
  case HYLC_CLOTH_TEST_BIAS:
    PetscCall(HylcClothRunBias_Private(c));
    break;
  case HYLC_CLOTH_TEST_CANTILEVER:
    PetscCall(HylcClothRunCantilever_Private(c));
    break;
  case HYLC_CLOTH_TEST_DRAPE:
    PetscCall(HylcClothRunDrape_Private(c));
    break;
  case HYLC_CLOTH_TEST_SCENE:
    PetscCall(HylcClothRunScene_Private(c));
    break;
  case HYLC_CLOTH_TEST_UNIAXIAL:
    PetscCall(HylcClothRunUniaxial_Private(c));
    break;
  case HYLC_CLOTH_TEST_CURL:
    PetscCall(HylcClothRunCurl_Private(c));
    break;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcClothAddFiles - Lists the cloth's files in a registry (include/hylc/files.h) for its checks before
  any work: the material table and the .obj mesh as inputs, the CSV of the selected test as an output
  (the VTK and PNG files beside it share its prefix, -cloth_output). Call after HylcClothSetFromOptions().
  Collective.

  Level: intermediate
@*/
PetscErrorCode HylcClothAddFiles(HylcCloth c, HylcFiles files)
{
  char        path[PETSC_MAX_PATH_LEN + 64], csv[64];
  const char *name[] = {"tensile", "bias", "cantilever", "drape", "scene", "uniaxial", "curl"};

  PetscFunctionBegin;
  CLOTH_CHECK(c);
  if (c->materialFile[0]) PetscCall(HylcFilesAdd(files, HYLC_FILE_INPUT, c->materialFile, "-cloth_material"));
  if (c->meshFile[0]) PetscCall(HylcFilesAdd(files, HYLC_FILE_INPUT, c->meshFile, "-cloth_mesh_file"));
  PetscCall(PetscSNPrintf(csv, sizeof(csv), "%s.csv", name[c->test]));
  PetscCall(HylcClothOutputName_Private(c, csv, path, sizeof(path)));
  if (path[0]) PetscCall(HylcFilesAdd(files, HYLC_FILE_OUTPUT, path, "-cloth_output"));
  PetscFunctionReturn(PETSC_SUCCESS);
}
