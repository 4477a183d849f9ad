/* What belongs to no stage (the "metisnd" ordering), and the registration of the whole library.
   Each stage registers its own class ids, log events and registries in its HylcXInitializePackage()
   (next to HylcXCreate(), which calls it); HylcInitializePackage() calls them all, as PETSc's and SLEPc's
   dynamic-library registration does (SLEPc's src/sys/dlregisslepc.c). */
#include <hylc/sys.h>
#include <hylc/pattern.h>
#include <hylc/periodic.h>
#include <hylc/chol.h>
#include <hylc/micro.h>
#include <hylc/sampler.h>
#include <hylc/fit.h>
#include <hylc/material.h>
#include <hylc/calibrate.h>
#include <hylc/cloth.h>

const char *HylcDefaultOrdering(void) { return MATORDERINGMETISND; }

PETSC_INTERN PetscErrorCode HylcMetisRegister(void);

static PetscBool HylcSysPackageInitialized = PETSC_FALSE;
static PetscBool HylcPackageInitialized    = PETSC_FALSE;

static PetscErrorCode HylcSysFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcSysPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode HylcFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSysInitializePackage - Registers what belongs to no stage: the fill-reducing ordering "metisnd"
  (MATORDERINGMETISND, src/sys/metis.c) and its log event ORDER_MetisND. Called by the initializers of the
  stages that order matrices (HylcCholInitializePackage(), HylcMicroInitializePackage()) and by
  HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcSysInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcSysPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcSysPackageInitialized = PETSC_TRUE;
  PetscCall(HylcMetisRegister());
  PetscCall(PetscRegisterFinalize(HylcSysFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcInitializePackage - Registers the whole library: HylcSysInitializePackage() and every stage's class
  ids, log events and registries (HylcPatternInitializePackage(), HylcMidsurfaceInitializePackage(),
  HylcPeriodicInitializePackage(), HylcCholInitializePackage() with the solver type MATSOLVERHYLC,
  HylcMicroInitializePackage(), HylcSamplerInitializePackage(), HylcMaterialInitializePackage(),
  HylcFitInitializePackage(), HylcCalibrateInitializePackage(), HylcClothInitializePackage()). Each stage's HylcXCreate() calls its own
  initializer, so a program that creates objects need not call this; one that uses a registered name
  without creating a hylc object (the solver type "hylc" or the ordering "metisnd" in a plain PETSc
  solver) calls it first. Idempotent.

  Not collective

  Level: intermediate

.seealso: HylcSysInitializePackage(), HylcInitialize()
@*/
PetscErrorCode HylcInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcPackageInitialized = PETSC_TRUE;
  PetscCall(HylcSysInitializePackage());
  PetscCall(HylcPatternInitializePackage());
  PetscCall(HylcPeriodicInitializePackage());
  PetscCall(HylcSamplerInitializePackage());
  PetscCall(HylcMicroInitializePackage());
  PetscCall(HylcCholInitializePackage());
  PetscCall(HylcMidsurfaceInitializePackage());
  PetscCall(HylcMaterialInitializePackage());
  PetscCall(HylcFitInitializePackage());
  PetscCall(HylcCalibrateInitializePackage());
  PetscCall(HylcClothInitializePackage());
  PetscCall(PetscRegisterFinalize(HylcFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}
