/* Shared set-up of the libFuzzer harnesses (docs/testing.md): PETSc is initialized once, with an error
   handler that returns quietly, so that a rejected input is an ordinary return and only a crash, a
   sanitizer report, a leak or a hang is a finding. */
#pragma once
#include <hylc/sys.h>
#if defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    define HYLC_FUZZ_LSAN 1
#  endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#  define HYLC_FUZZ_LSAN 1
#endif
#if defined(HYLC_FUZZ_LSAN)
#  include <sanitizer/lsan_interface.h>
#endif
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* Every allocation of PetscMalloc2/3/4 is a block of its own (coalesced blocks would hide overruns from
   ASan); PETSc's signal handler is off (ASan reports the fault); errors return without printing.
   What MPI_Init, PetscInitialize and the harness's warm-up (the class registration of the first object)
   allocate for the life of the process is not checked for leaks: call HylcFuzzInitEnd() after the
   warm-up. */
static inline void HylcFuzzInit(int *argc, char ***argv)
{
  static char *args[] = {NULL, (char *)"-no_signal_handler", (char *)"-malloc_coalesce", (char *)"0", NULL};
  int          n      = 4;
  char       **a      = args;

  args[0] = (*argc > 0) ? (*argv)[0] : (char *)"fuzz";
#if defined(HYLC_FUZZ_LSAN)
  __lsan_disable();
#endif
  if (PetscInitialize(&n, &a, NULL, NULL)) abort();
  if (PetscPushErrorHandler(PetscReturnErrorHandler, NULL)) abort();
}

static inline void HylcFuzzInitEnd(void)
{
#if defined(HYLC_FUZZ_LSAN)
  __lsan_enable();
#endif
}

/* For the replay driver (replay.c); libFuzzer itself exits without finalizing. */
static inline void HylcFuzzFinalize(void)
{
  if (PetscFinalize()) abort();
}

/* A NUL-terminated copy of the input (NULL if the input holds a NUL byte: the file readers refuse those
   before parsing). */
static inline char *HylcFuzzText(const uint8_t *data, size_t size)
{
  char *s;
  if (memchr(data, 0, size)) return NULL;
  s = (char *)malloc(size + 1);
  if (!s) abort();
  memcpy(s, data, size);
  s[size] = 0;
  return s;
}
