#pragma once
/* Storage of microscale samples: an append-only journal that survives SIGKILL at any moment (for
   -sampler_resume), and the HDF5 output file (schema: docs/output-format.md). Rank 0 only. */
#include <hylc/micro.h>
#include <hylc/plan.h>

/* one finished sample */
typedef struct {
  long   index;      /* sample index in the plan */
  int    term;       /* 0: zero sample, 1..5: 1D terms, 6..14: 2D terms (include/hylc/plan.h) */
  int    status;     /* HylcMicroStatus */
  int    iterations;
  int    retries;    /* regularization increases */
  double z[6];       /* sx, sa, sy, II00, II01, II11 */
  double psi;        /* J/m^2 */
  double parts[4];   /* stretch, bend, twist, contact energy (J) */
  double residual;   /* |z| / |z0| */
  double cresidual;  /* |A y - dL| / r */
  double time;       /* wall seconds */
} HylcSampleRecord;

typedef struct _n_HylcJournal *HylcJournal;
