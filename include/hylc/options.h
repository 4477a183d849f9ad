#pragma once
/* Option readers that refuse what PETSc's accept silently (src/sys/options.c), for use between
   PetscOptionsBegin() and PetscOptionsEnd() like PetscOptionsReal() and PetscOptionsRealArray():
   - every one: the option must have a value ("-yarn_E" given last, "-yarn_E ''" or "yarn_E:" in a YAML
     file is "Option -yarn_E: no value"; PETSc ignores such a number and reads "" for a string or choice);
   - HylcOptionsReal: the value must be finite ("inf", "nan", "1e999" are refused);
   - HylcOptionsRealArray, HylcOptionsIntArray: at most *n values (PETSc drops the extra ones), each real
     value finite;
   - HylcOptionsInt, HylcOptionsString, HylcOptionsEnum, HylcOptionsFList: PETSc's otherwise.
   A refused value is one PETSC_ERR_USER_INPUT error "Option -name value: ..." naming the option as the
   user wrote it (with the object's prefix). -help lists the options as PETSc's readers do, a list
   option with every value of its default ("-sampler_range_sx <-0.6,0.6>", trailing zeros of a list
   longer than 6 dropped). */
#include <hylc/sys.h>

#define HylcOptionsReal(opt, text, man, cur, val, set)             HylcOptionsReal_Private(PetscOptionsObject, opt, text, man, cur, val, set)
#define HylcOptionsRealArray(opt, text, man, v, n, set)            HylcOptionsRealArray_Private(PetscOptionsObject, opt, text, man, v, n, set)
#define HylcOptionsIntArray(opt, text, man, v, n, set)             HylcOptionsIntArray_Private(PetscOptionsObject, opt, text, man, v, n, set)
#define HylcOptionsInt(opt, text, man, cur, val, set)              HylcOptionsInt_Private(PetscOptionsObject, opt, text, man, cur, val, set)
#define HylcOptionsString(opt, text, man, cur, val, len, set)      HylcOptionsString_Private(PetscOptionsObject, opt, text, man, cur, val, len, set)
#define HylcOptionsEnum(opt, text, man, list, cur, val, set)       HylcOptionsEnum_Private(PetscOptionsObject, opt, text, man, list, cur, val, set)
#define HylcOptionsFList(opt, text, man, list, cur, val, len, set) HylcOptionsFList_Private(PetscOptionsObject, opt, text, man, list, cur, val, len, set)

PETSC_EXTERN PetscErrorCode HylcOptionsReal_Private(PetscOptionItems *, const char[], const char[], const char[], PetscReal, PetscReal *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsRealArray_Private(PetscOptionItems *, const char[], const char[], const char[], PetscReal[], PetscInt *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsIntArray_Private(PetscOptionItems *, const char[], const char[], const char[], PetscInt[], PetscInt *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsInt_Private(PetscOptionItems *, const char[], const char[], const char[], PetscInt, PetscInt *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsString_Private(PetscOptionItems *, const char[], const char[], const char[], const char[], char[], size_t, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsEnum_Private(PetscOptionItems *, const char[], const char[], const char[], const char *const *, PetscEnum, PetscEnum *, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcOptionsFList_Private(PetscOptionItems *, const char[], const char[], const char[], PetscFunctionList, const char[], char[], size_t, PetscBool *);
