/* The registry of pattern sources: "file" and the procedural generators (include/hylc/pattern.h). A new
   generator is one HylcPatternRegister() call; -pattern_type lists every registered name. */
#include <hylc/private/patternimpl.h>

PetscFunctionList HylcPatternList              = NULL;
static PetscBool  HylcPatternRegisterAllCalled = PETSC_FALSE;

/*@C
  HylcPatternRegister - Adds a pattern generator under a name, so that HylcPatternSetType(), HylcPatternGenerate()
  and -pattern_type accept it (and -help lists it).

  Not collective

  Input Parameters:
+ name      - the name (a later registration of the same name replaces the generator)
- generator - the generator: fills the pattern's data from the generator parameters (see HylcPatternGenerator)

  Notes:
  The generator is called by HylcPatternGenerate() (and so by HylcPatternSetUp()) after the parameters have
  been checked (a positive radius; lengths positive or 0 for the default; sizes 0 to 1000) and with the
  pattern's type set to name. It sets the data with HylcPatternSetFromCurves() (yarn centrelines; rest data
  from the geometry) or HylcPatternSetData().

  Level: advanced

.seealso: HylcPatternRegisterAll(), HylcPatternSetType(), HylcPatternGenerate()
@*/
PetscErrorCode HylcPatternRegister(const char name[], HylcPatternGenerator generator)
{
  PetscFunctionBegin;
  PetscCall(HylcPatternInitializePackage());
  PetscCall(PetscFunctionListAdd(&HylcPatternList, name, generator));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the source "file": the .pyp file of HylcPatternSetFileName() */
static PetscErrorCode HylcPatternLoadFile_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  (void)g;
  PetscCheck(p->filename[0], PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "Pattern type 'file' needs a file name (-pattern_file f.pyp)");
  PetscCall(HylcPatternLoad(p, p->filename));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternRegisterAll - Registers the built-in pattern sources: file (HylcPatternSetFileName()), the
  wovens plain, basket (2x2), twill (2/2), satin (5-harness) and the knits stockinette and rib (1x1), in
  this order. Called by HylcPatternInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcPatternRegister()
@*/
PetscErrorCode HylcPatternRegisterAll(void)
{
  PetscFunctionBegin;
  if (HylcPatternRegisterAllCalled) PetscFunctionReturn(PETSC_SUCCESS);
  HylcPatternRegisterAllCalled = PETSC_TRUE;
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNFILE, HylcPatternLoadFile_Private));
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNPLAIN, HylcPatternGeneratePlain_Private));
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNBASKET, HylcPatternGenerateBasket_Private));
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNTWILL, HylcPatternGenerateTwill_Private));
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNSATIN, HylcPatternGenerateSatin_Private));
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNSTOCKINETTE, HylcPatternGenerateStockinette_Private));
  PetscCall(PetscFunctionListAdd(&HylcPatternList, HYLCPATTERNRIB, HylcPatternGenerateRib_Private));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the end of the registry's life (HylcPatternFinalizePackage(), at PetscFinalize()) */
PetscErrorCode HylcPatternRegistryDestroy_Private(void)
{
  PetscFunctionBegin;
  PetscCall(PetscFunctionListDestroy(&HylcPatternList));
  HylcPatternRegisterAllCalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the source registered under type (NULL if none) */
PetscErrorCode HylcPatternFindSource_Private(const char type[], HylcPatternGenerator *fn)
{
  PetscFunctionBegin;
  PetscCall(HylcPatternInitializePackage());
  PetscCall(PetscFunctionListFind(HylcPatternList, type, fn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the registered names in registration order, joined by sep (trailing: sep after the last one too), for messages */
PetscErrorCode HylcPatternSourceNames_Private(const char sep[], PetscBool trailing, char buf[], size_t len)
{
  const char **names;
  int          n;

  PetscFunctionBegin;
  PetscCall(HylcPatternInitializePackage());
  PetscCall(PetscFunctionListGet(HylcPatternList, &names, &n));
  buf[0] = 0;
  for (int i = 0; i < n; i++) {
    if (!names[i] || !names[i][0]) continue; /* PetscFunctionListGet() may end the array with an empty entry */
    if (buf[0]) PetscCall(PetscStrlcat(buf, sep, len));
    PetscCall(PetscStrlcat(buf, names[i], len));
  }
  if (trailing) PetscCall(PetscStrlcat(buf, sep, len));
  PetscCall(PetscFree(names));
  PetscFunctionReturn(PETSC_SUCCESS);
}
