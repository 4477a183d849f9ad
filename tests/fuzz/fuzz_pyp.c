/* libFuzzer harness: the .pyp pattern reader (HylcPatternLoadFromString, the parser behind
   HylcPatternLoad). An error return is fine; a crash, a sanitizer report, a leak or a hang is a finding. */
#include "fuzzcommon.h"
#include <hylc/pattern.h>

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  HylcPattern p;
  HylcFuzzInit(argc, argv);
  /* registers the class once, so that its permanent allocations are not counted against an input */
  if (HylcPatternCreate(PETSC_COMM_SELF, &p) || HylcPatternDestroy(&p)) abort();
  HylcFuzzInitEnd();
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  HylcPattern p;
  char       *text = HylcFuzzText(data, size);

  if (!text) return 0;
  if (HylcPatternCreate(PETSC_COMM_SELF, &p)) abort();
  (void)HylcPatternLoadFromString(p, "fuzz.pyp", text);
  if (HylcPatternDestroy(&p)) abort();
  free(text);
  return 0;
}
