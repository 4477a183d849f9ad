/* Option readers that refuse non-finite reals and extra list values (include/hylc/options.h). */
#include <hylc/options.h>
#include <math.h>

/* the option as the user wrote it (with the prefix) and its value as given */
static PetscErrorCode OptionText(PetscOptionItems *items, const char opt[], char key[], size_t klen, const char **value)
{
  PetscBool set = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(key, klen, "-%s%s", items->prefix ? items->prefix : "", opt + 1));
  *value = NULL;
  PetscCall(PetscOptionsFindPair(items->options, NULL, key, value, &set));
  if (!set || !*value) *value = "";
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsReal_Private - PetscOptionsReal() that refuses a value that is not finite (use the macro
  HylcOptionsReal() between PetscOptionsBegin() and PetscOptionsEnd()).

  Level: developer
@*/
PetscErrorCode HylcOptionsReal_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscReal cur, PetscReal *val, PetscBool *set)
{
  PetscBool   flg = PETSC_FALSE;
  char        key[256];
  const char *raw;

  PetscFunctionBegin;
  PetscCall(PetscOptionsReal_Private(items, opt, text, man, cur, val, &flg));
  if (set) *set = flg;
  if (!flg || isfinite((double)*val)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(OptionText(items, opt, key, sizeof(key), &raw));
  SETERRQ(items->comm, PETSC_ERR_USER_INPUT, "Option %s %s: not a finite number", key, raw);
}

/* n values given when at most max are read: PETSc's array readers stop at max silently; read max + 1 */
static PetscErrorCode CheckCount(PetscOptionItems *items, const char opt[], PetscInt max, PetscBool real)
{
  char        key[256];
  const char *raw;
  PetscInt    m = max + 1;
  PetscBool   set;

  PetscFunctionBegin;
  PetscCall(OptionText(items, opt, key, sizeof(key), &raw));
  if (real) {
    PetscReal *v;
    PetscCall(PetscMalloc1(m, &v));
    PetscCall(PetscOptionsGetRealArray(items->options, NULL, key, v, &m, &set));
    PetscCall(PetscFree(v));
  } else {
    PetscInt *v;
    PetscCall(PetscMalloc1(m, &v));
    PetscCall(PetscOptionsGetIntArray(items->options, NULL, key, v, &m, &set));
    PetscCall(PetscFree(v));
  }
  PetscCheck(!set || m <= max, items->comm, PETSC_ERR_USER_INPUT, "Option %s %s: more than %" PetscInt_FMT " value%s", key, raw, max, max == 1 ? "" : "s");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsRealArray_Private - PetscOptionsRealArray() that refuses more than *n values and values that
  are not finite (use the macro HylcOptionsRealArray()).

  Level: developer
@*/
PetscErrorCode HylcOptionsRealArray_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscReal v[], PetscInt *n, PetscBool *set)
{
  const PetscInt max = *n;
  PetscBool      flg = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscOptionsRealArray_Private(items, opt, text, man, v, n, &flg));
  if (set) *set = flg;
  if (!flg) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(CheckCount(items, opt, max, PETSC_TRUE));
  for (PetscInt i = 0; i < *n; i++) {
    char        key[256];
    const char *raw;
    if (isfinite((double)v[i])) continue;
    PetscCall(OptionText(items, opt, key, sizeof(key), &raw));
    SETERRQ(items->comm, PETSC_ERR_USER_INPUT, "Option %s %s: value %" PetscInt_FMT " is not a finite number", key, raw, i + 1);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsIntArray_Private - PetscOptionsIntArray() that refuses more than *n values (use the macro
  HylcOptionsIntArray()).

  Level: developer
@*/
PetscErrorCode HylcOptionsIntArray_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscInt v[], PetscInt *n, PetscBool *set)
{
  const PetscInt max = *n;
  PetscBool      flg = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscOptionsIntArray_Private(items, opt, text, man, v, n, &flg));
  if (set) *set = flg;
  if (flg) PetscCall(CheckCount(items, opt, max, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}
