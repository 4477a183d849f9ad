/* A main() for the libFuzzer harnesses without libFuzzer: runs LLVMFuzzerTestOneInput once on each file
   named on the command line (tests/regression/fuzz_regressions.sh replays tests/fuzz/regressions/ and the
   seeds with it in the gcc build, plain or ASAN=1). Exit 0 when every input returned. */
#include "fuzzcommon.h"
#include <stdio.h>

int main(int argc, char **argv)
{
  if (LLVMFuzzerInitialize(&argc, &argv)) return 2;
  for (int i = 1; i < argc; i++) {
    FILE    *fp = fopen(argv[i], "rb");
    uint8_t *buf;
    long     len;
    if (!fp || fseek(fp, 0, SEEK_END) || (len = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET)) {
      fprintf(stderr, "replay: cannot read %s\n", argv[i]);
      return 2;
    }
    buf = (uint8_t *)malloc((size_t)len + 1);
    if (!buf || fread(buf, 1, (size_t)len, fp) != (size_t)len) {
      fprintf(stderr, "replay: cannot read %s\n", argv[i]);
      return 2;
    }
    fclose(fp);
    printf("replay: %s (%ld bytes)\n", argv[i], len);
    fflush(stdout);
    (void)LLVMFuzzerTestOneInput(buf, (size_t)len);
    free(buf);
  }
  HylcFuzzFinalize();
  return 0;
}
