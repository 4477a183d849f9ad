/* Knit generators (stockinette, 1x1 rib): centrelines from src/pattern/knit.c. */
#include <hylc/private/patternimpl.h>

PetscErrorCode HylcPatternGenerateKnit_Private(HylcPattern p, HylcPatternType type, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  (void)g;
  SETERRQ(PetscObjectComm((PetscObject)p), PETSC_ERR_SUP, "Knit generator '%s' is being integrated", type);
}
