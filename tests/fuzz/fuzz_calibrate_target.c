/* libFuzzer harness: the calibration's file targets (src/calibrate/target.c on the one table reader,
   src/sys/table.c): the input is written to <tmp>/target and read by HylcCalibrateReadFileTarget_Private
   twice, as a CSV (a header naming sx,sa,sy,II00,II01,II11,psi) and as the paper's raw data.txt: the rows,
   the base row, the thinning and each selected strain checked against the tile of a generated plain
   pattern (HylcPeriodicCheckStrain). A first line "#fuzz stride max" sets the thinning (-calibrate_stride,
   -calibrate_max_samples; values the options accept). An error return is fine; a crash, a sanitizer
   report, a leak or a hang is a finding. */
#include "fuzzcommon.h"
#include "../../src/calibrate/calibrateimpl.h"
#include <stdio.h>
#include <unistd.h>

static char         dir[64], path[128];
static HylcPattern  pat;
static HylcMicro    micro;
static HylcPeriodic tile;

static void Cleanup(void)
{
  unlink(path);
  rmdir(dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  HylcYarnModel m;
  HylcFuzzInit(argc, argv);
  snprintf(dir, sizeof(dir), "%s", "/tmp/hylc-fuzz-calib.XXXXXX");
  if (!mkdtemp(dir)) abort();
  snprintf(path, sizeof(path), "%s/target", dir);
  atexit(Cleanup);
  /* the tile the strains are checked against, kept for the life of the process */
  if (HylcPatternCreate(PETSC_COMM_SELF, &pat) || HylcPatternSetType(pat, "plain") || HylcPatternSetUp(pat)) abort();
  if (HylcYarnModelDefault(&m) || HylcMicroCreate(PETSC_COMM_SELF, &micro) || HylcMicroSetPattern(micro, pat, &m) || HylcMicroSetUp(micro) || HylcMicroGetPeriodic(micro, &tile)) abort();
  HylcFuzzInitEnd();
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static const HylcCalibTargetType kinds[2] = {HYLC_CALIB_TARGET_CSV, HYLC_CALIB_TARGET_RAW};
  FILE                            *fp       = fopen(path, "wb");
  long                             stride = 1, max = 0;

  if (!fp || fwrite(data, 1, size, fp) != size || fclose(fp)) abort();
  if (size > 6 && !memcmp(data, "#fuzz ", 6)) {
    char head[64] = "";
    memcpy(head, data, size < sizeof(head) - 1 ? size : sizeof(head) - 1);
    if (sscanf(head + 6, "%ld %ld", &stride, &max) != 2 || stride < 1 || max < 0 || stride > PETSC_MAX_INT || max > PETSC_MAX_INT) stride = 1, max = 0;
  }
  for (int k = 0; k < 2; k++) {
    HylcCalibRows S;
    PetscInt      nrows, nskipped;
    if (!HylcCalibrateReadFileTarget_Private(path, kinds[k], 1e-3, (PetscInt)stride, (PetscInt)max, tile, &S, &nrows, &nskipped)) {
      if (S.n < 1 || S.n > nrows || S.term[0] != 0) abort(); /* the base row first, no more rows than read */
      if (HylcCalibRowsDestroy_Private(&S)) abort();
    }
  }
  return 0;
}
