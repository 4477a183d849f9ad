/* libFuzzer harness: hylc-eval's text input (-eval_input; HylcTableReadStrainFile, the one table reader of
   src/sys/table.c): the input is written to <tmp>/strains and read; each strain read (at most 64) is
   evaluated on a small material, as hylc-eval does. An input that starts with the HDF5 signature is
   skipped: it would fuzz the HDF5 library's file parser, not hylc's reader (the HDF5 datasets are checked
   by tests/unit/test_table.c and probe_eval_input_hdf5.sh). An error return is fine; a crash, a
   sanitizer report, a leak, a hang, or a non-finite psi at an accepted strain is a finding. */
#include "fuzzcommon.h"
#include <hylc/material.h>
#include <hylc/table.h>
#include <math.h>
#include <stdio.h>
#include <unistd.h>

static char         dir[64], path[128];
static HylcMaterial mat;

static void Cleanup(void)
{
  unlink(path);
  rmdir(dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  static const char json[] = "{\"density\": 0.3, \"strain scale\": [1.0, 0.75, 1.0, 100.0, 100.0], \"coeffs\": {\"const\": 0.5,"
                             " \"1D\": [{\"k\": 0, \"t\": [-1, 0, 1], \"p\": [1, 0, 1], \"m\": [-1, 0, 1]}, {\"k\": 3, \"t\": [-1, 0, 1], \"p\": [1, 0, 1], \"m\": [-1, 0, 1]}],"
                             " \"2D\": [{\"k0\": 0, \"k1\": 3, \"tu\": [0, 1], \"tv\": [0, 1], \"p\": [0, 0, 0, 1], \"mu\": [0, 0, 0, 0], \"mv\": [0, 0, 0, 0], \"muv\": [0, 0, 0, 0]}]}}";
  HylcFuzzInit(argc, argv);
  snprintf(dir, sizeof(dir), "%s", "/tmp/hylc-fuzz-eval.XXXXXX");
  if (!mkdtemp(dir)) abort();
  snprintf(path, sizeof(path), "%s/strains", dir);
  atexit(Cleanup);
  if (HylcMaterialCreate(PETSC_COMM_SELF, &mat) || HylcMaterialLoadFromString(mat, "fuzz.json", json)) abort();
  HylcFuzzInitEnd();
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  FILE     *fp;
  HylcTable T;

  if (size >= 8 && !memcmp(data, "\211HDF\r\n\032\n", 8)) return 0;
  fp = fopen(path, "wb");
  if (!fp || fwrite(data, 1, size, fp) != size || fclose(fp)) abort();
  if (HylcTableReadStrainFile(path, "-eval_input", &T)) return 0;
  if (T.ncol != 6) abort();
  for (PetscInt i = 0; i < T.n && i < 64; i++) {
    PetscReal psi, g[6], h[36];
    if (!HylcMaterialEvaluate(mat, T.v + 6 * i, &psi, g, h) && !isfinite((double)psi)) abort();
  }
  if (HylcTableDestroy(&T)) abort();
  return 0;
}
