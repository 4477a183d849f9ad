/* HylcMidsurface: the micro-midsurface phi(xi) and normal n(xi) for a macroscopic strain, closed form
   (flat or singly curved II) or Poisson solve (any II); positions x = phi + h n (docs/method.md §1.4, 1.5). */
#include <hylc/options.h>
#include <hylc/private/macroimpl.h>

const char *const HylcMidsurfaceTypes[]   = {"auto", "closed", "poisson", "HylcMidsurfaceType", "HYLC_MIDSURFACE_", NULL};
const char *const HylcMidsurfaceInterps[] = {"bilinear", "bicubic", "HylcMidsurfaceInterp", "HYLC_MIDSURFACE_INTERP_", NULL};
const char *const HylcMidsurfaceNormals[] = {"rotation", "polar", "HylcMidsurfaceNormal", "HYLC_MIDSURFACE_NORMAL_", NULL};

PetscClassId  HYLC_MIDSURFACE_CLASSID;
PetscLogEvent HYLC_MacroSetUp, HYLC_MacroPoisson, HYLC_MacroEvaluate;

static PetscBool HylcMidsurfacePackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcMidsurfaceFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcMidsurfacePackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceInitializePackage - Registers the class id HylcMidsurface and its log events (MACRO_SetUp, MACRO_Poisson, MACRO_Evaluate). Called by
  HylcMidsurfaceCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcMidsurfaceInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcMidsurfacePackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcMidsurfacePackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcMidsurface", &HYLC_MIDSURFACE_CLASSID));
  PetscCall(PetscLogEventRegister("MACRO_SetUp", HYLC_MIDSURFACE_CLASSID, &HYLC_MacroSetUp));
  PetscCall(PetscLogEventRegister("MACRO_Poisson", HYLC_MIDSURFACE_CLASSID, &HYLC_MacroPoisson));
  PetscCall(PetscLogEventRegister("MACRO_Evaluate", HYLC_MIDSURFACE_CLASSID, &HYLC_MacroEvaluate));
  PetscCall(PetscRegisterFinalize(HylcMidsurfaceFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceCreate - Creates a midsurface at zero strain on the box [-1, 1]^2. Not collective; use
  PETSC_COMM_SELF (the Poisson grid lives on one rank).
@*/
PetscErrorCode HylcMidsurfaceCreate(MPI_Comm comm, HylcMidsurface *out)
{
  HylcMidsurface  ms;
  const PetscReal z0[6] = {0, 0, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscValidPointer(out, 2);
  PetscCall(HylcMidsurfaceInitializePackage());
  PetscCall(PetscHeaderCreate(ms, HYLC_MIDSURFACE_CLASSID, "HylcMidsurface", "Micro-midsurface", "Macro", comm, HylcMidsurfaceDestroy, HylcMidsurfaceView));
  ms->type   = HYLC_MIDSURFACE_AUTO;
  ms->interp = HYLC_MIDSURFACE_INTERP_BILINEAR;
  ms->normal = HYLC_MIDSURFACE_NORMAL_ROTATION;
  ms->grid   = 96;
  ms->lo[0] = ms->lo[1] = -1;
  ms->hi[0] = ms->hi[1] = 1;
  *out                  = ms;
  PetscCall(HylcMidsurfaceSetStrain(ms, z0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceDuplicate - Creates a midsurface with the settings of another (method, interpolation, normals,
  Poisson grid size, box and options prefix) at its strain, not set up; the Poisson solution is not copied.

  Not collective

  Input Parameter:
. ms - the midsurface to copy the settings of

  Output Parameter:
. out - the new midsurface (destroy with HylcMidsurfaceDestroy())

  Level: intermediate

.seealso: HylcMidsurfaceCreate(), HylcMidsurfaceSetStrain(), HylcMidsurfaceSetUp()
@*/
PetscErrorCode HylcMidsurfaceDuplicate(HylcMidsurface ms, HylcMidsurface *out)
{
  HylcMidsurface d;
  const char    *prefix;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscValidPointer(out, 2);
  PetscCall(HylcMidsurfaceCreate(PetscObjectComm((PetscObject)ms), &d));
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)ms, &prefix));
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)d, prefix));
  d->type   = ms->type;
  d->interp = ms->interp;
  d->normal = ms->normal;
  d->grid   = ms->grid;
  for (int i = 0; i < 2; i++) d->lo[i] = ms->lo[i], d->hi[i] = ms->hi[i];
  d->strain      = ms->strain;
  d->hasStrain   = ms->hasStrain;
  d->setupcalled = PETSC_FALSE;
  *out           = d;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceDestroy - Drops a reference to the midsurface and frees it with its Poisson data at the last;
  accepts NULL and sets the handle to NULL.

  Not collective

  Input Parameter:
. ms - the midsurface

  Level: beginner

.seealso: HylcMidsurfaceCreate()
@*/
PetscErrorCode HylcMidsurfaceDestroy(HylcMidsurface *ms)
{
  PetscFunctionBegin;
  if (!*ms) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*ms, HYLC_MIDSURFACE_CLASSID, 1);
  if (--((PetscObject)(*ms))->refct > 0) {
    *ms = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcMidsurfacePoissonReset_Private(*ms));
  PetscCall(PetscHeaderDestroy(ms));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetOptionsPrefix - Sets the prefix of the midsurface's options (-<prefix>macro_*, with the
  Poisson KSP's -<prefix>macro_ksp_*, -<prefix>macro_pc_*).

  Not collective

  Input Parameters:
+ ms     - the midsurface
- prefix - the prefix (NULL: none)

  Level: intermediate

.seealso: HylcMidsurfaceSetFromOptions()
@*/
PetscErrorCode HylcMidsurfaceSetOptionsPrefix(HylcMidsurface ms, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)ms, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetFromOptions - Reads the midsurface options. Not collective.

  Options:
+ -macro_phi <auto>          - auto (closed for flat or singly curved II, else poisson), closed or poisson
. -macro_grid <96>           - Poisson grid nodes per direction (box plus xi = 0 plus 2 cells of margin)
. -macro_interp <bilinear>   - interpolation of the Poisson phi: bilinear or bicubic (Catmull-Rom)
. -macro_normal <rotation>   - normal of the Poisson midsurface: rotation (R(xi) of (S10)) or polar
                               (rotation of the polar decomposition of the FD gradient of phi)
- -macro_ksp_*, -macro_pc_*  - the Poisson KSP (default CG, ICC(0) with a positive-definite shift, rtol 1e-12)
@*/
PetscErrorCode HylcMidsurfaceSetFromOptions(HylcMidsurface ms)
{
  PetscEnum type = (PetscEnum)ms->type, interp = (PetscEnum)ms->interp, normal = (PetscEnum)ms->normal;
  PetscInt  grid = ms->grid;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscObjectOptionsBegin((PetscObject)ms);
  PetscCall(HylcOptionsEnum("-macro_phi", "Midsurface method: auto, closed (singly curved II) or poisson", "HylcMidsurfaceSetType", HylcMidsurfaceTypes, type, &type, NULL));
  PetscCall(HylcOptionsInt("-macro_grid", "Poisson grid nodes per direction", "HylcMidsurfaceSetGridSize", grid, &grid, NULL));
  PetscCall(HylcOptionsEnum("-macro_interp", "Interpolation of the Poisson phi", "HylcMidsurfaceSetInterpolation", HylcMidsurfaceInterps, interp, &interp, NULL));
  PetscCall(HylcOptionsEnum("-macro_normal", "Normal of the Poisson midsurface: rotation (S10) or polar (from the FD gradient of phi)", "HylcMidsurfaceSetNormalType", HylcMidsurfaceNormals, normal, &normal, NULL));
  PetscOptionsEnd();
  PetscCall(HylcMidsurfaceSetType(ms, (HylcMidsurfaceType)type));
  PetscCall(HylcMidsurfaceSetGridSize(ms, grid));
  PetscCall(HylcMidsurfaceSetInterpolation(ms, (HylcMidsurfaceInterp)interp));
  PetscCall(HylcMidsurfaceSetNormalType(ms, (HylcMidsurfaceNormal)normal));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetStrain - Sets the macroscopic strain whose midsurface phi and normal n are evaluated; an
  invalid strain is a PETSC_ERR_USER_INPUT error naming it.

  Not collective

  Input Parameters:
+ ms - the midsurface
- z  - the strain (sx, sa, sy, II00, II01, II11; II in 1/m)

  Level: beginner

.seealso: HylcMidsurfaceGetStrain(), HylcMidsurfaceSetUp()
@*/
PetscErrorCode HylcMidsurfaceSetStrain(HylcMidsurface ms, const PetscReal z[6])
{
  double               zd[6];
  HylcMacroStrainError e;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  for (int i = 0; i < 6; i++) zd[i] = (double)z[i];
  e = HylcMacroStrainSetUp(zd, 0, &ms->strain);
  PetscCheck(e == HYLC_MACRO_STRAIN_OK, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "Invalid macroscopic strain (sx, sa, sy, II00, II01, II11) = (%g, %g, %g, %g, %g, %g): %s", (double)z[0], (double)z[1], (double)z[2], (double)z[3],
             (double)z[4], (double)z[5], HylcMacroStrainErrorString(e));
  ms->hasStrain   = PETSC_TRUE;
  ms->setupcalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceGetStrain - The data derived from the strain (curvature class, eigen-split of II, ...).

  Not collective

  Input Parameter:
. ms - the midsurface, with a strain (HylcMidsurfaceSetStrain())

  Output Parameter:
. m - the strain data (owned by the midsurface)

  Level: developer

.seealso: HylcMidsurfaceSetStrain()
@*/
PetscErrorCode HylcMidsurfaceGetStrain(HylcMidsurface ms, const HylcMacroStrain **m)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  *m = &ms->strain;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetBox - Sets the box in xi of the points to evaluate: the Poisson grid covers it, xi = 0 and
  a margin of 2 cells. Default [-1, 1]^2.

  Not collective

  Input Parameters:
+ ms - the midsurface
. lo - the lower corner (finite)
- hi - the upper corner (finite, hi >= lo)

  Level: intermediate

.seealso: HylcMidsurfaceEvaluate()
@*/
PetscErrorCode HylcMidsurfaceSetBox(HylcMidsurface ms, const PetscReal lo[2], const PetscReal hi[2])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  for (int d = 0; d < 2; d++) {
    PetscCheck(PetscIsNormalReal(lo[d]) || lo[d] == 0, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "HylcMidsurfaceSetBox: lo[%d] = %g is not finite", d, (double)lo[d]);
    PetscCheck(PetscIsNormalReal(hi[d]) || hi[d] == 0, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "HylcMidsurfaceSetBox: hi[%d] = %g is not finite", d, (double)hi[d]);
    PetscCheck(lo[d] <= hi[d], PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "HylcMidsurfaceSetBox: lo[%d] = %g > hi[%d] = %g", d, (double)lo[d], d, (double)hi[d]);
    ms->lo[d] = lo[d];
    ms->hi[d] = hi[d];
  }
  ms->setupcalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetType - Sets how phi is computed: closed form (flat or singly curved II), Poisson, or auto
  (closed where it exists, else Poisson).

  Not collective

  Input Parameters:
+ ms   - the midsurface
- type - HYLC_MIDSURFACE_AUTO, HYLC_MIDSURFACE_CLOSED or HYLC_MIDSURFACE_POISSON

  Options Database Key:
. -macro_phi <auto> - auto, closed or poisson

  Level: intermediate

.seealso: HylcMidsurfaceGetType()
@*/
PetscErrorCode HylcMidsurfaceSetType(HylcMidsurface ms, HylcMidsurfaceType type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCheck(type >= HYLC_MIDSURFACE_AUTO && type <= HYLC_MIDSURFACE_POISSON, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "Unknown midsurface type %d", (int)type);
  if (type != ms->type) ms->setupcalled = PETSC_FALSE;
  ms->type = type;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* After SetUp the resolved type (closed or poisson), before it the requested one. */
/*@C
  HylcMidsurfaceGetType - How phi is computed: the type set, or after HylcMidsurfaceSetUp() the one auto
  resolved to.

  Not collective

  Input Parameter:
. ms - the midsurface

  Output Parameter:
. type - the type

  Level: intermediate

.seealso: HylcMidsurfaceSetType()
@*/
PetscErrorCode HylcMidsurfaceGetType(HylcMidsurface ms, HylcMidsurfaceType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  *type = ms->setupcalled ? ms->resolved : ms->type;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetGridSize - Sets the nodes per direction of the Poisson grid.

  Not collective

  Input Parameters:
+ ms - the midsurface
- n  - the nodes per direction (at least 8; default 96)

  Options Database Key:
. -macro_grid <96> - the same

  Level: intermediate

.seealso: HylcMidsurfaceSetType()
@*/
PetscErrorCode HylcMidsurfaceSetGridSize(HylcMidsurface ms, PetscInt n)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCheck(n >= 8, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "-macro_grid must be at least 8, got %" PetscInt_FMT, n);
  if (n != ms->grid) ms->setupcalled = PETSC_FALSE;
  ms->grid = n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetInterpolation - Sets the interpolation of the Poisson solution between grid nodes.

  Not collective

  Input Parameters:
+ ms     - the midsurface
- interp - HYLC_MIDSURFACE_INTERP_BILINEAR or HYLC_MIDSURFACE_INTERP_BICUBIC (Catmull-Rom)

  Options Database Key:
. -macro_interp <bilinear> - bilinear or bicubic

  Level: intermediate

.seealso: HylcMidsurfaceSetGridSize()
@*/
PetscErrorCode HylcMidsurfaceSetInterpolation(HylcMidsurface ms, HylcMidsurfaceInterp interp)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCheck(interp == HYLC_MIDSURFACE_INTERP_BILINEAR || interp == HYLC_MIDSURFACE_INTERP_BICUBIC, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "Unknown interpolation %d", (int)interp);
  if (interp != ms->interp) ms->setupcalled = PETSC_FALSE; /* phi(0) = 0 is fixed for the interpolant */
  ms->interp = interp;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetNormalType - Sets how the normal and the rotation are obtained: R(xi) of (S10), or (Poisson
  only) the polar decomposition of the difference gradient of phi.

  Not collective

  Input Parameters:
+ ms     - the midsurface
- normal - HYLC_MIDSURFACE_NORMAL_ROTATION or HYLC_MIDSURFACE_NORMAL_POLAR

  Options Database Key:
. -macro_normal <rotation> - rotation or polar

  Level: intermediate

.seealso: HylcMidsurfaceGetRotation()
@*/
PetscErrorCode HylcMidsurfaceSetNormalType(HylcMidsurface ms, HylcMidsurfaceNormal normal)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCheck(normal == HYLC_MIDSURFACE_NORMAL_ROTATION || normal == HYLC_MIDSURFACE_NORMAL_POLAR, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT, "Unknown normal type %d", (int)normal);
  ms->normal = normal;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceSetUp - Resolves the method and, for poisson, solves for phi on the grid. Not collective.
@*/
PetscErrorCode HylcMidsurfaceSetUp(HylcMidsurface ms)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  if (ms->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  if (ms->type == HYLC_MIDSURFACE_AUTO)
    ms->resolved = ms->strain.curvature == HYLC_MACRO_DOUBLY ? HYLC_MIDSURFACE_POISSON : HYLC_MIDSURFACE_CLOSED;
  else
    ms->resolved = ms->type;
  PetscCheck(ms->resolved != HYLC_MIDSURFACE_CLOSED || ms->strain.curvature != HYLC_MACRO_DOUBLY, PetscObjectComm((PetscObject)ms), PETSC_ERR_USER_INPUT,
             "-macro_phi closed needs a flat or singly curved II (det II = 0), got II = [[%g, %g], [%g, %g]]; use -macro_phi poisson or auto", (double)ms->strain.II[0], (double)ms->strain.II[1], (double)ms->strain.II[2], (double)ms->strain.II[3]);
  PetscCall(PetscLogEventBegin(HYLC_MacroSetUp, ms, 0, 0, 0)); /* after the input checks: an error must not leave the event open */
  if (ms->resolved == HYLC_MIDSURFACE_POISSON)
    PetscCall(HylcMidsurfacePoissonSetUp_Private(ms));
  else
    PetscCall(HylcMidsurfacePoissonReset_Private(ms));
  PetscCall(PetscObjectChangeTypeName((PetscObject)ms, HylcMidsurfaceTypes[ms->resolved]));
  ms->setupcalled = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_MacroSetUp, ms, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GetRotation_Private(HylcMidsurface ms, const PetscReal xi[2], PetscReal R[9])
{
  PetscFunctionBegin;
  if (ms->resolved == HYLC_MIDSURFACE_POISSON && ms->normal == HYLC_MIDSURFACE_NORMAL_POLAR) {
    PetscReal F[6];
    HylcMidsurfaceInterpolate_Private(ms, ms->grad, 6, xi, F);
    PetscCheck(HylcMacroPolarRotation(ms->strain.S, F, R) == 0, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "HylcMidsurface: the FD gradient of phi is rank deficient at xi = (%g, %g)", (double)xi[0], (double)xi[1]);
  } else
    HylcMacroRotation(ms->strain.N, xi, R, NULL, NULL);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceGetRotation - The rotation used at a point: R(xi) of (S10), or the polar estimate with
  -macro_normal polar. Sets the midsurface up if needed.

  Not collective

  Input Parameters:
+ ms - the midsurface, with a strain
- xi - the point

  Output Parameter:
. R - the rotation, 3 x 3 row-major

  Level: intermediate

.seealso: HylcMidsurfaceEvaluate(), HylcMidsurfaceSetNormalType()
@*/
PetscErrorCode HylcMidsurfaceGetRotation(HylcMidsurface ms, const PetscReal xi[2], PetscReal R[9])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCall(HylcMidsurfaceSetUp(ms));
  PetscCall(GetRotation_Private(ms, xi, R));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceEvaluate - Positions x = phi(xi) + h n(xi) of npts points xih = (xi1, xi2, h); n (3 per
  point) may be NULL. Not collective; calls HylcMidsurfaceSetUp() if needed.
@*/
PetscErrorCode HylcMidsurfaceEvaluate(HylcMidsurface ms, PetscInt npts, const PetscReal xih[], PetscReal x[], PetscReal n[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCall(HylcMidsurfaceSetUp(ms));
  PetscCall(PetscLogEventBegin(HYLC_MacroEvaluate, ms, 0, 0, 0));
  for (PetscInt p = 0; p < npts; p++) {
    const PetscReal xi[2] = {xih[3 * p], xih[3 * p + 1]}, h = xih[3 * p + 2];
    PetscReal       phi[3], nl[3];
    if (ms->resolved == HYLC_MIDSURFACE_CLOSED) {
      double xd[2] = {xi[0], xi[1]}, pd[3], nd[3];
      HylcMacroClosedPhi(&ms->strain, xd, pd, nd, NULL);
      for (int i = 0; i < 3; i++) phi[i] = pd[i], nl[i] = nd[i];
    } else {
      PetscReal R[9];
      HylcMidsurfaceInterpolate_Private(ms, ms->phi, 3, xi, phi);
      PetscCall(GetRotation_Private(ms, xi, R));
      for (int i = 0; i < 3; i++) nl[i] = R[3 * i + 2];
    }
    for (int i = 0; i < 3; i++) x[3 * p + i] = phi[i] + h * nl[i];
    if (n)
      for (int i = 0; i < 3; i++) n[3 * p + i] = nl[i];
  }
  PetscCall(PetscLogEventEnd(HYLC_MacroEvaluate, ms, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceGetSolveInfo - Statistics of the Poisson solve (0 for the closed form or before set-up).

  Not collective

  Input Parameter:
. ms - the midsurface

  Output Parameters:
+ grid - the nodes per direction (may be NULL)
- its  - the KSP iterations over the three components (may be NULL)

  Level: developer

.seealso: HylcMidsurfaceSetUp()
@*/
PetscErrorCode HylcMidsurfaceGetSolveInfo(HylcMidsurface ms, PetscInt *grid, PetscInt *its)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  if (grid) *grid = ms->setupcalled && ms->resolved == HYLC_MIDSURFACE_POISSON ? ms->M[0] : 0;
  if (its) *its = ms->setupcalled && ms->resolved == HYLC_MIDSURFACE_POISSON ? ms->its : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceView - Prints the strain, its curvature class and the method (with the Poisson grid and KSP
  when set up).

  Not collective

  Input Parameters:
+ ms     - the midsurface
- viewer - an ASCII viewer (NULL: stdout of the midsurface's communicator)

  Level: beginner

.seealso: HylcMidsurfaceViewFromOptions()
@*/
PetscErrorCode HylcMidsurfaceView(HylcMidsurface ms, PetscViewer viewer)
{
  PetscBool              iascii;
  const HylcMacroStrain *m      = &ms->strain;
  const char            *curv[] = {"flat", "singly curved", "doubly curved"};

  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)ms), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectPrintClassNamePrefixType((PetscObject)ms, viewer));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "strain (sx, sa, sy, II00, II01, II11) = (%g, %g, %g, %g, %g, %g): %s, lambda_min(I) = %g\n", m->z[0], m->z[1], m->z[2], m->z[3], m->z[4], m->z[5], curv[m->curvature], m->lambdaMin));
  if (m->curvature == HYLC_MACRO_SINGLY) PetscCall(PetscViewerASCIIPrintf(viewer, "II = H d d^T with H = %g, d = (%g, %g)\n", m->H, m->d[0], m->d[1]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "method: %s%s\n", HylcMidsurfaceTypes[ms->setupcalled ? ms->resolved : ms->type], ms->setupcalled ? "" : " (not set up)"));
  if (ms->setupcalled && ms->resolved == HYLC_MIDSURFACE_POISSON) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "grid %" PetscInt_FMT " x %" PetscInt_FMT " nodes on [%g, %g] x [%g, %g], %s interpolation, %s normals, %" PetscInt_FMT " KSP iterations\n", ms->M[0], ms->M[1], (double)ms->origin[0],
                                     (double)(ms->origin[0] + (ms->M[0] - 1) * ms->h[0]), (double)ms->origin[1], (double)(ms->origin[1] + (ms->M[1] - 1) * ms->h[1]), HylcMidsurfaceInterps[ms->interp], HylcMidsurfaceNormals[ms->normal], ms->its));
    PetscCall(KSPView(ms->ksp, viewer));
  }
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMidsurfaceViewFromOptions - Views the midsurface if the option name is given
  (PetscObjectViewFromOptions()).

  Not collective

  Input Parameters:
+ ms   - the midsurface
. obj  - an object whose prefix is used (NULL: the midsurface's)
- name - the option, e.g. "-macro_view"

  Level: intermediate

.seealso: HylcMidsurfaceView()
@*/
PetscErrorCode HylcMidsurfaceViewFromOptions(HylcMidsurface ms, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(ms, HYLC_MIDSURFACE_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)ms, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
