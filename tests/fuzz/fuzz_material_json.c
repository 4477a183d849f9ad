/* libFuzzer harness: the JSON material reader (HylcMaterialLoadFromString, the parser of src/material/json.c
   behind HylcMaterialLoad). An error return is fine; a crash, a sanitizer report, a leak or a hang is a
   finding. A loaded material is also evaluated at a few strains (finite input, so finite output is
   expected; see docs/testing.md). */
#include "fuzzcommon.h"
#include <hylc/material.h>

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  HylcMaterial m;
  HylcFuzzInit(argc, argv);
  if (HylcMaterialCreate(PETSC_COMM_SELF, &m) || HylcMaterialDestroy(&m)) abort();
  HylcFuzzInitEnd();
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  HylcMaterial m;
  char        *text = HylcFuzzText(data, size);

  if (!text) return 0;
  if (HylcMaterialCreate(PETSC_COMM_SELF, &m)) abort();
  if (!HylcMaterialLoadFromString(m, "fuzz.json", text)) {
    static const PetscReal s[][6] = {
        {0, 0, 0, 0, 0, 0},
        {0.1, 0.02, -0.05, 10, -5, 3},
        {-0.3, 0.4, 0.5, -100, 50, 200},
    };
    for (size_t i = 0; i < sizeof(s) / sizeof(s[0]); i++) {
      PetscReal psi, g[6], h[36];
      (void)HylcMaterialEvaluate(m, s[i], &psi, g, h);
    }
  }
  if (HylcMaterialDestroy(&m)) abort();
  free(text);
  return 0;
}
