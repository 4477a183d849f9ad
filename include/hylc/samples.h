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
  int    retries;     /* regularization increases */
  double z[6];        /* sx, sa, sy, II00, II01, II11 */
  double psi;         /* J/m^2 */
  double parts[4];    /* stretch, bend, twist, contact energy (J) */
  double residual;    /* |z| / |z0| */
  double cresidual;   /* |A y - dL| / r */
  double time;        /* wall seconds (both solves of a sample retried cold) */
  int    start;       /* HylcSampleStart: 0 cold, 1 continued, 2 continued, did not converge, retried cold */
  int    negcurv;     /* negative eigenvalues of the projected Hessian at the final state (HylcMicroResult); -1 not tested */
  int    escapes;     /* saddle escapes of the kept solve (HylcMicroResult) */
  double psiOther;    /* -sampler_start both: Psi of the start not kept (J/m^2); NaN if it was not solved */
  int    statusOther; /* its HylcMicroStatus; -1 not solved (other starts, or the first sample of a half-line) */
  int    multistable; /* both starts converged and their Psi differ by more than -sampler_both_rtol: 1; 0 if not; -1 not compared */
  double stress[6];   /* dPsi/dz of the kept equilibrium (envelope theorem, HylcMicroGetStrainGradient()): N/m for sx, sa, sy, N for the curvatures; NaN where not converged or not recorded */
} HylcSampleRecord;

/* how a sample's solve started (/samples/start) */
typedef enum { HYLC_SAMPLE_START_COLD = 0, HYLC_SAMPLE_START_CONTINUED = 1, HYLC_SAMPLE_START_RETRIED = 2 } HylcSampleStart;

typedef struct _n_HylcJournal *HylcJournal;

/* ---- Journal: append-only binary file of finished samples (format: docs/output-format.md) ----
   Plain C stdio + POSIX, used by rank 0 only; errors are raised on PETSC_COMM_SELF and name the file. */

/* How HylcJournalOpen treats an existing journal. */
typedef enum {
  HYLC_JOURNAL_NEW,      /* a new run: an existing journal holding samples is refused (say -sampler_resume or -sampler_overwrite) */
  HYLC_JOURNAL_RESUME,   /* continue the run of an existing journal (a missing or empty one starts a new journal) */
  HYLC_JOURNAL_OVERWRITE /* start over: an existing journal is emptied */
} HylcJournalMode;

/* Opens the journal 'path' of a run of 'nsamples' samples identified by the text 'identity' (the run's
   identity, HylcSamplesIdentity(): lines "kind name value"; the journal stores it with its SHA-256).
   The first thing done is an exclusive lock (flock) of the journal file itself, held until
   HylcJournalClose (or process exit): a second process on the same journal is refused with "in use by
   another job (pid N)" before it reads, creates or changes anything. Then, by mode (HylcJournalMode):
   a new journal is written in place (header, fsync); on resume every intact record is kept and a torn
   or garbled tail (left by a process killed mid-write) is truncated to the last good record; a journal of
   a different run (other identity digest or sample count) is refused with the differences named
   (HylcSamplesIdentityDiff), as is an older journal format or a file that is not a journal.
   Not collective. */
PETSC_EXTERN PetscErrorCode HylcJournalOpen(const char path[], HylcJournalMode mode, long nsamples, const char identity[], HylcJournal *);
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

/* ---- The identity of a run (src/samples/identity.c, docs/output-format.md) ----
   A canonical text of everything that can change a sample's result: versions (hylc, its build, PETSc),
   the pattern (every field of HylcPatternData; arrays as SHA-256 of their bytes) and every option of the
   global database except the neutral ones (HylcSamplesOptionIsNeutral), sorted. Not collective. */
PETSC_EXTERN PetscErrorCode HylcSamplesIdentity(HylcPattern, char **);
PETSC_EXTERN void           HylcSamplesIdentityDigest(const char[], char[65]);
PETSC_EXTERN PetscErrorCode HylcSamplesIdentityDiff(const char was[], const char now[], char **);
PETSC_EXTERN PetscBool      HylcSamplesOptionIsNeutral(const char[]);

/* ---- HDF5 output (schema: docs/output-format.md) ---- */

/* Writes the samples file 'path' atomically (built in memory, written to a unique temporary beside it,
   fsync, rename; on any failure the temporary is removed, every HDF5 id closed, and path untouched): /samples (one row per sample
   of the plan; samples not done have status -1, term -1, NaN values and -1 counts), /reference (the
   reference pattern's arrays), /material (the yarn model, raw and resolved), /options (the complete
   options text; NULL: PetscOptionsGetAll of the global database) and provenance attributes on /.
   reference and model may be NULL (the groups are then omitted). Not collective (call on rank 0). */
PETSC_EXTERN PetscErrorCode HylcSamplesWriteHDF5(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[]);
/* The same, and /provenance from the run's identity text (HylcSamplesIdentity; NULL: no /provenance), /plan
   from the plan (its spacing; graded: its parameters and knots; NULL: no /plan). */
PETSC_EXTERN PetscErrorCode HylcSamplesWriteHDF5WithIdentity(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[],
                                                             const char identity[], const HylcPlan *plan);
/* The graded knots of axis a of term t stored in a samples file's /plan (n = 0: none). */
PETSC_EXTERN PetscErrorCode HylcSamplesReadKnots(const char path[], int t, int a, PetscInt *n, PetscReal K[]);
/* Reads /samples of a file written by HylcSamplesWriteHDF5: the sample count, records (indexed by
   sample) and done flags (status >= 0), allocated with PetscMalloc (free with PetscFree); optionsText
   (may be NULL) receives the /options text (PetscFree). Every dataset is checked first as by
   HylcSamplesCheckHDF5() (values are not: a sample not computed holds NaN). Not collective. */
PETSC_EXTERN PetscErrorCode HylcSamplesReadHDF5(const char path[], long *nsamples, HylcSampleRecord **recs, unsigned char **done, char **optionsText);
/* Checks the datasets of /samples (each present, a dataset of the format's class and shape with one row
   per sample, storing the values it declares; include/hylc/table.h) without reading them: a problem is
   one PETSC_ERR_FILE_UNEXPECTED error "path (option): ..." naming the dataset. Not collective. */
PETSC_EXTERN PetscErrorCode HylcSamplesCheckHDF5(const char path[], const char option[]);
