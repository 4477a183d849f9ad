/* Option readers that refuse options without a value, non-finite reals and extra list values
   (include/hylc/options.h). */
#include <hylc/options.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

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

/* an option given without a value ("-yarn_E" last, "-yarn_E ''", or "yarn_E:" in YAML): PETSc stores no
   value, and its readers ignore the option (numbers) or read "" (strings, choices) */
static PetscErrorCode CheckHasValue(PetscOptionItems *items, const char opt[])
{
  char        key[256];
  const char *value = NULL;
  PetscBool   set   = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(key, sizeof(key), "-%s%s", items->prefix ? items->prefix : "", opt + 1));
  PetscCall(PetscOptionsFindPair(items->options, NULL, key, &value, &set));
  PetscCheck(!set || (value && value[0]), items->comm, PETSC_ERR_USER_INPUT, "Option %s: no value", key);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsReal_Private - PetscOptionsReal() that refuses a value that is not finite and an option without
  a value (use the macro HylcOptionsReal() between PetscOptionsBegin() and PetscOptionsEnd()).

  Level: developer
@*/
PetscErrorCode HylcOptionsReal_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscReal cur, PetscReal *val, PetscBool *set)
{
  PetscBool   flg = PETSC_FALSE;
  char        key[256];
  const char *raw;

  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
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

/* -help of a list option: every value ("-sampler_range_sx <-0.6,0.6>"; PETSc's readers show the first
   only), the given ones too when the option is set ("<now -0.1,0.1 : formerly -0.6,0.6>"). A list of at
   most 6 values shows them all; a longer one (a capacity, -solve_uniaxial_strains) without its trailing
   zeros. */
static PetscBool HelpWanted(PetscOptionItems *items) { return (PetscBool)(items->printhelp && items->count == 1 && !items->alreadyprinted); }

static void FormatList(char buf[], size_t len, PetscInt n, const PetscReal *r, const PetscInt *iv)
{
  PetscInt m = n;
  if (n > 6)
    while (m > 1 && (r ? r[m - 1] == 0 : iv[m - 1] == 0)) m--;
  buf[0] = 0;
  for (PetscInt i = 0; i < m; i++) {
    size_t used = strlen(buf);
    if (used + 32 >= len) break;
    if (r)
      snprintf(buf + used, len - used, "%s%g", i ? "," : "", (double)r[i]);
    else
      snprintf(buf + used, len - used, "%s%" PetscInt_FMT, i ? "," : "", iv[i]);
  }
}

static PetscErrorCode HelpLine(PetscOptionItems *items, const char opt[], const char text[], const char man[], const char defaults[], const char now[])
{
  PetscFunctionBegin;
  if (now)
    PetscCall((*PetscHelpPrintf)(items->comm, "  -%s%s <now %s : formerly %s>: %s (%s)\n", items->prefix ? items->prefix : "", opt + 1, now, defaults, text, man));
  else
    PetscCall((*PetscHelpPrintf)(items->comm, "  -%s%s <%s>: %s (%s)\n", items->prefix ? items->prefix : "", opt + 1, defaults, text, man));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsRealArray_Private - PetscOptionsRealArray() that refuses more than *n values, values that
  are not finite and an option without a value (use the macro HylcOptionsRealArray()).

  Level: developer
@*/
PetscErrorCode HylcOptionsRealArray_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscReal v[], PetscInt *n, PetscBool *set)
{
  const PetscInt  max           = *n;
  PetscBool       flg           = PETSC_FALSE;
  const PetscBool help          = HelpWanted(items);
  char            defaults[512] = "", now[512];

  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
  if (help) FormatList(defaults, sizeof(defaults), max, v, NULL);
  items->printhelp = (PetscBool)(items->printhelp && !help); /* this reader prints the line */
  PetscCall(PetscOptionsRealArray_Private(items, opt, text, man, v, n, &flg));
  items->printhelp = (PetscBool)(items->printhelp || help);
  if (help) {
    if (flg) FormatList(now, sizeof(now), *n, v, NULL);
    PetscCall(HelpLine(items, opt, text, man, defaults, flg ? now : NULL));
  }
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
  HylcOptionsIntArray_Private - PetscOptionsIntArray() that refuses more than *n values and an option
  without a value (use the macro HylcOptionsIntArray()).

  Level: developer
@*/
PetscErrorCode HylcOptionsIntArray_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscInt v[], PetscInt *n, PetscBool *set)
{
  const PetscInt  max           = *n;
  PetscBool       flg           = PETSC_FALSE;
  const PetscBool help          = HelpWanted(items);
  char            defaults[512] = "", now[512];

  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
  if (help) FormatList(defaults, sizeof(defaults), max, NULL, v);
  items->printhelp = (PetscBool)(items->printhelp && !help); /* this reader prints the line */
  PetscCall(PetscOptionsIntArray_Private(items, opt, text, man, v, n, &flg));
  items->printhelp = (PetscBool)(items->printhelp || help);
  if (help) {
    if (flg) FormatList(now, sizeof(now), *n, NULL, v);
    PetscCall(HelpLine(items, opt, text, man, defaults, flg ? now : NULL));
  }
  if (set) *set = flg;
  if (flg) PetscCall(CheckCount(items, opt, max, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsInt_Private - PetscOptionsInt() that refuses an option without a value (use the macro
  HylcOptionsInt() between PetscOptionsBegin() and PetscOptionsEnd()).

  Level: developer
@*/
PetscErrorCode HylcOptionsInt_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscInt cur, PetscInt *val, PetscBool *set)
{
  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
  PetscCall(PetscOptionsInt_Private(items, opt, text, man, cur, val, set, PETSC_MIN_INT, PETSC_MAX_INT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsString_Private - PetscOptionsString() that refuses an option without a value, which PETSc reads
  as "" (use the macro HylcOptionsString()).

  Level: developer
@*/
PetscErrorCode HylcOptionsString_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], const char cur[], char val[], size_t len, PetscBool *set)
{
  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
  PetscCall(PetscOptionsString_Private(items, opt, text, man, cur, val, len, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsEnum_Private - PetscOptionsEnum() that refuses an option without a value (use the macro
  HylcOptionsEnum()).

  Level: developer
@*/
PetscErrorCode HylcOptionsEnum_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], const char *const *list, PetscEnum cur, PetscEnum *val, PetscBool *set)
{
  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
  PetscCall(PetscOptionsEnum_Private(items, opt, text, man, list, cur, val, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcOptionsFList_Private - PetscOptionsFList() that refuses an option without a value (use the macro
  HylcOptionsFList()).

  Level: developer
@*/
PetscErrorCode HylcOptionsFList_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscFunctionList list, const char cur[], char val[], size_t len, PetscBool *set)
{
  PetscFunctionBegin;
  PetscCall(CheckHasValue(items, opt));
  PetscCall(PetscOptionsFList_Private(items, opt, text, man, list, cur, val, len, set));
  PetscFunctionReturn(PETSC_SUCCESS);
}
