#pragma once
/* User tables of strains and energies (src/sys/table.c): the one reader of every text and HDF5 input that
   holds strains z = (sx, sa, sy, II00, II01, II11), with or without an energy Psi per row: the calibration
   target's CSV and data.txt, the fit's data.txt, hylc-eval's -eval_input (text and HDF5), and the
   datasets of a samples file (/samples/...) read as a target or fitted.

   Text: lines of any length; '#' starts a comment (to the end of the line); blank lines are skipped; a
   line with a comma has comma-separated fields (blanks around them allowed), any other line
   blank-separated fields; an empty field, a field that is not one finite number, a row with the wrong
   number of fields and (for strains) a strain outside the domain (finite, 1 + sx > 0, 1 + sy > 0,
   |sa| < 1) are refused with "file:line: column c (name): ...". HDF5: the dataset's kind, class, rank,
   shape and declared size (against what the file stores) are checked before anything is allocated,
   HDF5's own error printing is off, and a bad value is named by dataset, row and column. Every error is
   one line (PETSC_ERR_FILE_* or PETSC_ERR_USER_INPUT) naming the file. Not collective: errors are raised
   on PETSC_COMM_SELF. */
#include <hylc/sys.h>
#include <hdf5.h>
#include <stdio.h>

/* the most columns a table reads */
#define HYLC_TABLE_MAXCOL 16

typedef enum {
  HYLC_TABLE_NUMBERS, /* ncol numbers per line, no header */
  HYLC_TABLE_CSV      /* a header line naming the columns (any order, names matched ignoring case, other
                         columns skipped), then one row per line with as many fields as the header */
} HylcTableLayout;

/* What a table holds. */
typedef struct {
  HylcTableLayout    layout;
  int                ncol;   /* columns read, 1..HYLC_TABLE_MAXCOL */
  const char *const *names;  /* ncol names: the CSV header's, and the names in messages */
  PetscBool          strain; /* the first six columns are a strain: its domain is checked */
} HylcTableSpec;

/* A table read: n rows of ncol values, and where each row came from. */
typedef struct {
  PetscInt   n, ncol;
  PetscReal *v;    /* n x ncol, row-major */
  PetscInt  *line; /* text: the line of the row (1-based); HDF5: the row of the dataset (0-based) */
} HylcTable;

/* "sx", "sa", "sy", "II00", "II01", "II11", "psi": the names of a strain and its energy */
PETSC_EXTERN const char *const HylcTableStrainNames[7];

PETSC_EXTERN PetscErrorCode HylcTableReadText(const char path[], const char option[], const HylcTableSpec *, HylcTable *);
PETSC_EXTERN PetscErrorCode HylcTableReadStream(FILE *, const char path[], const HylcTableSpec *, HylcTable *);
PETSC_EXTERN PetscErrorCode HylcTableReadHDF5(const char path[], const char option[], const char *const datasets[], const HylcTableSpec *, HylcTable *);
/* Strains (6 columns) from a file recognized by content: HDF5 (/strain or /samples/strain, N x 6) or text
   (6 numbers per line): hylc-eval's -eval_input. */
PETSC_EXTERN PetscErrorCode HylcTableReadStrainFile(const char path[], const char option[], HylcTable *);
PETSC_EXTERN PetscErrorCode HylcTableDestroy(HylcTable *);

/* The first problem of a strain z (6 values): NULL if it is finite with 1 + sx > 0, 1 + sy > 0 and
   |sa| < 1; else a static reason ("is not finite", "the stretch factor 1 + sx must be positive", ...)
   and the component in *comp (0..5). */
PETSC_EXTERN const char *HylcStrainDomainError(const PetscReal z[6], int *comp);

/* ---- HDF5 columns: the datasets of one group, all with the same number of rows N ---- */
typedef struct {
  const char *name;     /* dataset name in the group */
  int         cols;     /* 0: a vector of N values; > 0: N x cols */
  H5T_class_t cls;      /* H5T_FLOAT or H5T_INTEGER; H5T_NO_CLASS: either */
  PetscBool   optional; /* may be absent (when present, it is checked as the others) */
} HylcTableColumn;

/* Checks the group 'group' of the open file and its datasets cols[0..n-1]: each is a dataset (not a
   group), of the class, rank and shape given, and stores the values it declares (a filtered dataset: at
   most 1100 times its storage, the bound of deflate); N is the row count of cols[0]. A problem is one
   PETSC_ERR_FILE_UNEXPECTED error "path (option): ..." naming the dataset. HDF5 prints nothing. */
PETSC_EXTERN PetscErrorCode HylcTableCheckHDF5Columns(hid_t file, const char path[], const char option[], const char group[], int n, const HylcTableColumn cols[], hsize_t *N);
/* Reads the whole dataset 'name' (checked before) into buf as memtype: a failure is a one-line
   PETSC_ERR_FILE_READ error naming the file and the dataset. */
PETSC_EXTERN PetscErrorCode HylcTableReadHDF5Column(hid_t file, const char path[], const char name[], hid_t memtype, void *buf);
