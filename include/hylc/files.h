#pragma once
/* The registry of a program's files (src/sys/files.c): every input (the options files included) and every
   output is listed before any work, then HylcFilesCheck() refuses, in one line naming the option:
   - a path over the system's limits (the whole path, a component, an option value that a path buffer
     would cut, an output together with the suffix of the temporary it is written through);
   - an input that is missing, a directory or unreadable (an optional input only when it exists);
   - an output whose directory is missing or not writable, or that is a directory;
   - an output that is an input or another output: the same file by device and inode when it exists, by
     its resolved directory (device and inode) and name when it does not (dangling links followed).
   Rank 0 checks, every rank raises the same error. */
#include <hylc/sys.h>

typedef enum {
  HYLC_FILE_INPUT,          /* read; must exist */
  HYLC_FILE_INPUT_OPTIONAL, /* read when it exists (info.txt beside a raw data.txt) */
  HYLC_FILE_OUTPUT          /* written (replaced through a temporary beside it) */
} HylcFileRole;

typedef struct _n_HylcFiles *HylcFiles;

PETSC_EXTERN PetscErrorCode HylcFilesCreate(MPI_Comm, HylcFiles *);
PETSC_EXTERN PetscErrorCode HylcFilesDestroy(HylcFiles *);
/* Adds a file: its role, its path (NULL or "": nothing added) and what named it, an option ("-fit_json",
   looked up in the options database to catch a value longer than a path buffer) or a phrase ("the
   journal of -sampler_output"). */
PETSC_EXTERN PetscErrorCode HylcFilesAdd(HylcFiles, HylcFileRole, const char path[], const char what[]);
/* Adds every options file the program read, as inputs (HylcOptionsFilesForEach()). */
PETSC_EXTERN PetscErrorCode HylcFilesAddOptionsFiles(HylcFiles);
/* Checks every file (see above). Collective. */
PETSC_EXTERN PetscErrorCode HylcFilesCheck(HylcFiles);
/* Lists the files, one per line "input|output <path> (<what>)". Collective. */
PETSC_EXTERN PetscErrorCode HylcFilesView(HylcFiles, PetscViewer);

/* The options files a program started with these arguments reads (plain C, usable before
   PetscInitialize()): -options_file F and -options_file_yaml F on the command line and in $PETSC_OPTIONS,
   -options_file lines of plain options files (nested, to depth 8), and PETSc's petscrc files that exist
   (~/.petscrc, .petscrc, petscrc) unless -skip_petscrc is given. fn(path, what, yaml, ctx) is called once
   per file (by path), what saying where it was named. */
PETSC_EXTERN void HylcOptionsFilesForEach(int argc, char **argv, void (*fn)(const char path[], const char what[], int yaml, void *ctx), void *ctx);
/* The most characters the temporary an output is written through adds to its name: ".tmp.XXXXXX" of
   HylcFileOpenTemp(), ".tmp<pid>" of hylc-eval's HDF5 output (pid_max 4194304), ".tmp" of the material
   writers. */
#define HYLC_FILES_TEMP_SUFFIX 11
