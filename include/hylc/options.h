#pragma once
/* Option readers that refuse what PETSc's accept silently (src/sys/options.c), for use between
   PetscOptionsBegin() and PetscOptionsEnd() like PetscOptionsReal() and PetscOptionsRealArray():
   - HylcOptionsReal: the value must be finite ("inf", "nan", "1e999" are refused);
   - HylcOptionsRealArray, HylcOptionsIntArray: at most *n values (PETSc drops the extra ones), each real
     value finite.
   A refused value is one PETSC_ERR_USER_INPUT error "Option -name value: ..." naming the option as the
   user wrote it (with the object's prefix). -help lists the options as PETSc's readers do. */
#include <hylc/sys.h>

#define HylcOptionsReal(opt, text, man, cur, val, set)  HylcOptionsReal_Private(PetscOptionsObject, opt, text, man, cur, val, set)
#define HylcOptionsRealArray(opt, text, man, v, n, set) HylcOptionsRealArray_Private(PetscOptionsObject, opt, text, man, v, n, set)
#define HylcOptionsIntArray(opt, text, man, v, n, set)  HylcOptionsIntArray_Private(PetscOptionsObject, opt, text, man, v, n, set)

PETSC_EXTERN PetscErrorCode HylcOptionsReal_Private(PetscOptionItems *, const char[], const char[], const char[], PetscReal, PetscReal *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsRealArray_Private(PetscOptionItems *, const char[], const char[], const char[], PetscReal[], PetscInt *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsIntArray_Private(PetscOptionItems *, const char[], const char[], const char[], PetscInt[], PetscInt *, PetscBool *);
