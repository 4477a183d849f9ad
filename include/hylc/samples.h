#pragma once
/* Storage of microscale samples: an append-only journal that survives SIGKILL at any moment (for
   -sampler_resume), and the HDF5 output file (schema: docs/output-format.md). Rank 0 only. */
#include <hylc/micro.h>
#include <hylc/plan.h>

/* one finished sample */
typedef struct {
  long   index;  /* sample index in the plan */
  int    term;   /* 0: zero sample, 1..5: 1D terms, 6..14: 2D terms (include/hylc/plan.h) */
  int    status; /* HylcMicroStatus */
  int    iterations;
  int    retries;   /* regularization increases */
  double z[6];      /* sx, sa, sy, II00, II01, II11 */
  double psi;       /* J/m^2 */
  double parts[4];  /* stretch, bend, twist, contact energy (J) */
  double residual;  /* |z| / |z0| */
  double cresidual; /* |A y - dL| / r */
  double time;      /* wall seconds */
} HylcSampleRecord;

typedef struct _n_HylcJournal *HylcJournal;

/* ---- Journal: append-only binary file of finished samples (format: docs/output-format.md) ----
   Plain C stdio + POSIX, used by rank 0 only; errors are raised on PETSC_COMM_SELF and name the file. */

/* Opens the journal 'path' of a run of 'nsamples' samples identified by the text 'fingerprint' (any
   string that changes when the run would compute different samples: pattern, plan and solver options).
   resume = PETSC_FALSE: creates a new journal (an existing file is replaced). resume = PETSC_TRUE:
   reopens an existing journal, keeps every intact record and truncates a torn or garbled tail (left by a
   process killed mid-write) to the last good record; a journal of a different run (other fingerprint or
   sample count) or a file that is not a journal is refused; a missing file starts a new journal.
   The file is locked (flock) while open. Not collective. */
PETSC_EXTERN PetscErrorCode HylcJournalOpen(const char path[], PetscBool resume, long nsamples, const char fingerprint[], HylcJournal *);
/* Appends n records (recs[i].index in [0, nsamples)), then fflush and fsync: once it returns, the
   records survive SIGKILL and power loss. A later record of the same sample replaces an earlier one. */
PETSC_EXTERN PetscErrorCode HylcJournalAppend(HylcJournal, const HylcSampleRecord[], PetscInt);
/* The number of samples with a record and a per-sample flag array (length nsamples, 1 = done), owned
   by the journal. */
PETSC_EXTERN PetscErrorCode HylcJournalGetDone(HylcJournal, PetscInt *, const unsigned char **);
/* The records indexed by sample (length nsamples, valid where done), owned by the journal. */
PETSC_EXTERN PetscErrorCode HylcJournalGetRecords(HylcJournal, const HylcSampleRecord **);
/* The number of samples of the run and the number of records dropped from a torn tail at open. */
PETSC_EXTERN PetscErrorCode HylcJournalGetInfo(HylcJournal, long *, PetscInt *);
/* Closes the file (the journal stays on disk) and frees the object; accepts NULL. */
PETSC_EXTERN PetscErrorCode HylcJournalClose(HylcJournal *);

/* ---- HDF5 output (schema: docs/output-format.md) ---- */

/* Writes the samples file 'path' atomically (to "path.tmp", then rename): /samples (one row per sample
   of the plan; samples not done have status -1, term -1, NaN values and -1 counts), /reference (the
   reference pattern's arrays), /material (the yarn model, raw and resolved), /options (the complete
   options text; NULL: PetscOptionsGetAll of the global database) and provenance attributes on /.
   reference and model may be NULL (the groups are then omitted). Not collective (call on rank 0). */
PETSC_EXTERN PetscErrorCode HylcSamplesWriteHDF5(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[]);
/* Reads /samples of a file written by HylcSamplesWriteHDF5: the sample count, records (indexed by
   sample) and done flags (status >= 0), allocated with PetscMalloc (free with PetscFree); optionsText
   (may be NULL) receives the /options text (PetscFree). Not collective. */
PETSC_EXTERN PetscErrorCode HylcSamplesReadHDF5(const char path[], long *nsamples, HylcSampleRecord **recs, unsigned char **done, char **optionsText);
