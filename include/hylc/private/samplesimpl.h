#pragma once
/* Private to the samples storage (src/samples/journal.c, src/samples/h5samples.c). */
#include <hylc/samples.h>
#include <string.h>

/* the number of HylcMicroStatus values (the names before PETSc's enum-name trailer) */
static inline int HylcSamplesNumStatuses_(void)
{
  int n = 0;
  while (HylcMicroStatuses[n] && strcmp(HylcMicroStatuses[n], "HylcMicroStatus")) n++;
  return n;
}
