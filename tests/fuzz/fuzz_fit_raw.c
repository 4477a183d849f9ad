/* libFuzzer harness: the raw data.txt reader of the fit (src/fit/input.c, the paper's layout: a directory
   with data.txt and info.txt). The input is written to <tmp>/data.txt; a line "%%info.txt" splits it, the
   rest going to <tmp>/info.txt (absent otherwise). A first line "#fuzz n1 n2" sets -fit_raw_n1/-fit_raw_n2
   (values that HylcFitSetFromOptions accepts, >= 0). An error return is fine; a crash, a sanitizer report,
   a leak or a hang is a finding. */
#define _GNU_SOURCE /* memmem */
#include "fuzzcommon.h"
#include <hylc/private/fitimpl.h>
#include <stdio.h>
#include <unistd.h>

static char dir[64], dataPath[128], infoPath[128];

static void RemoveDir(void)
{
  unlink(dataPath);
  unlink(infoPath);
  rmdir(dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  HylcFit f;
  HylcFuzzInit(argc, argv);
  snprintf(dir, sizeof(dir), "%s", "/tmp/hylc-fuzz-fit.XXXXXX");
  if (!mkdtemp(dir)) abort();
  snprintf(dataPath, sizeof(dataPath), "%s/data.txt", dir);
  snprintf(infoPath, sizeof(infoPath), "%s/info.txt", dir);
  atexit(RemoveDir);
  if (HylcFitCreate(PETSC_COMM_SELF, &f) || HylcFitDestroy(&f)) abort();
  HylcFuzzInitEnd();
  return 0;
}

static void WriteFile(const char path[], const uint8_t *data, size_t size)
{
  FILE *fp = fopen(path, "wb");
  if (!fp || fwrite(data, 1, size, fp) != size || fclose(fp)) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static const char sep[] = "\n%%info.txt\n";
  const uint8_t    *cut   = memmem(data, size, sep, sizeof(sep) - 1);
  HylcFit           f;
  long              n1 = 0, n2 = 0;

  if (cut) {
    WriteFile(dataPath, data, (size_t)(cut - data) + 1);
    WriteFile(infoPath, cut + sizeof(sep) - 1, size - (size_t)(cut - data) - (sizeof(sep) - 1));
  } else {
    WriteFile(dataPath, data, size);
    unlink(infoPath);
  }
  if (size > 6 && !memcmp(data, "#fuzz ", 6)) {
    char head[64] = "";
    memcpy(head, data, size < sizeof(head) - 1 ? size : sizeof(head) - 1);
    if (sscanf(head + 6, "%ld %ld", &n1, &n2) != 2 || n1 < 0 || n2 < 0 || n1 > PETSC_MAX_INT || n2 > PETSC_MAX_INT) n1 = n2 = 0;
  }
  if (HylcFitCreate(PETSC_COMM_SELF, &f)) abort();
  if (HylcFitSetInput(f, dir)) abort();
  f->rawN1 = (PetscInt)n1;
  f->rawN2 = (PetscInt)n2;
  (void)HylcFitReadInput_Private(f);
  if (HylcFitDestroy(&f)) abort();
  return 0;
}
