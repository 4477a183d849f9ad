#pragma once
/* hylc system layer: package initialization, class ids, log events and PETSc-version compatibility. */
#include <petscsys.h>

#if !defined(PETSC_SUCCESS) /* PETSc < 3.19 */
  #define PETSC_SUCCESS ((PetscErrorCode)0)
#endif

#define HYLC_VERSION_STRING "0.1.0"

/* Class ids and log events, registered by HylcInitializePackage(). */
PETSC_EXTERN PetscClassId  HYLC_PATTERN_CLASSID;
PETSC_EXTERN PetscLogEvent HYLC_PatternLoad, HYLC_PatternWrite, HYLC_PatternGenerate, HYLC_PatternDistance;

/* Registers hylc's classes and log events (idempotent; called by every XCreate). Not collective. */
PETSC_EXTERN PetscErrorCode HylcInitializePackage(void);
