#pragma once
/* hylc system layer: package initialization, class ids, log events and PETSc-version compatibility. */
#include <petscsys.h>

#if !defined(PETSC_SUCCESS) /* PETSc < 3.19 */
#  define PETSC_SUCCESS ((PetscErrorCode)0)
#endif

#define HYLC_VERSION_STRING "0.1.0"
/* The git revision of the build ("unknown" outside a checkout), and what -version prints: the program,
   hylc's version and revision, PETSc's, HDF5's and MPI's versions (src/sys/version.c). */
PETSC_EXTERN const char    *HylcGetRevision(void);
PETSC_EXTERN PetscErrorCode HylcVersionView(const char[]);

/* The fill-reducing ordering used for the Newton factorization unless -micro_factor_pc_factor_mat_ordering_type says otherwise. */
PETSC_EXTERN const char *HylcDefaultOrdering(void);

/* The fill-reducing ordering METIS_NodeND (METIS 5 nested dissection of the graph of A + A^T), registered
   by HylcSysInitializePackage() for sequential matrices: MatGetOrdering(A, MATORDERINGMETISND, &rperm,
   &cperm), PCFactorSetMatOrderingType(pc, MATORDERINGMETISND) or -pc_factor_mat_ordering_type metisnd.
   Row and column permutations are equal. Options: -hylc_metis_seed, -hylc_metis_nseps,
   -hylc_metis_ufactor, -hylc_metis_compress (src/sys/metis.c). Programs that use it without creating a
   hylc object call HylcInitializePackage() first. Log event ORDER_MetisND. */
#define MATORDERINGMETISND "metisnd"
PETSC_EXTERN PetscLogEvent HYLC_MetisND;
/* METIS_NodeND of a CSR graph (symmetric, no self loops): perm[new] = old (src/sys/metis.c). */
PETSC_EXTERN PetscErrorCode HylcMetisNodeND(PetscInt n, const PetscInt xadj[], const PetscInt adj[], PetscInt perm[]);
/* Reads and checks the -hylc_metis_* options (for -help and the check of unused options; collective). */
PETSC_EXTERN PetscErrorCode HylcMetisSetFromOptions(MPI_Comm);

/* Registration (src/sys/package.c). Each stage registers its own class ids, log events and registries in
   its HylcXInitializePackage(), declared in its header and called by its HylcXCreate(). What belongs to
   no stage (the ordering "metisnd") is HylcSysInitializePackage()'s; HylcInitializePackage() registers the
   whole library (every stage), for programs that use a registered name without creating an object.
   Idempotent; not collective. */
PETSC_EXTERN PetscErrorCode HylcSysInitializePackage(void);
PETSC_EXTERN PetscErrorCode HylcInitializePackage(void);

/* Installs hylc's error handler for programs: errors in user input (bad files, options, values) are
   reported as one line "hylc: error: <message>" (on rank 0 of the communicator the error was raised
   on), other errors with PETSc's full traceback. -hylc_traceback keeps PETSc's handler for all errors.
   Call right after PetscInitialize(). Not collective. */
PETSC_EXTERN PetscErrorCode HylcPushErrorHandler(void);
/* PetscInitialize() + HylcPushErrorHandler() for programs, after checking every options file on the
   command line (-options_file, -options_file_yaml): a missing file, a directory or a malformed YAML file
   ends the program with one line "hylc: error: file:line: problem" (src/sys/error.c). Collective. */
PETSC_EXTERN PetscErrorCode HylcInitialize(int *, char ***, const char[], const char[]);

/* Ends a program: on success PetscFinalize() and 0; on error (ierr != 0) the error code, after
   PetscFinalize() when every rank ended with an error within a few seconds (an error raised collectively:
   rank 0's message is never cut off), else MPI_Abort() (other ranks may wait in a collective).
   Programs write: ierr = Run(); return HylcMainFinalize(ierr); */
PETSC_EXTERN int HylcMainFinalize(PetscErrorCode);
/* fsync the directory holding path, so that a rename into it is durable (errors ignored). Not collective. */
PETSC_EXTERN void HylcSyncParentDirectory(const char path[]);
/* Path checks made before any work (src/sys/file.c). Not collective; errors on comm.
   HylcFileCheckInput: an existing readable regular file (a directory is refused as such).
   HylcFileCheckOutput: not a directory, parent directory exists and is writable.
   A program checks all its files together with the registry of include/hylc/files.h (which uses these,
   and refuses an output that is an input or another output). */
PETSC_EXTERN PetscErrorCode HylcFileCheckInput(MPI_Comm, const char[], const char[]);
PETSC_EXTERN PetscErrorCode HylcFileCheckOutput(MPI_Comm, const char[], const char[]);
/* Atomic text output: write to a unique temporary beside path, then HylcFileCommitTemp() (fsync, rename,
   fsync of the directory) or HylcFileAbortTemp() on an error path. A full disk leaves path untouched. */
PETSC_EXTERN PetscErrorCode HylcFileOpenTemp(const char[], char[], size_t, FILE **);
PETSC_EXTERN PetscErrorCode HylcFileCommitTemp(FILE **, const char[], const char[]);
PETSC_EXTERN void           HylcFileAbortTemp(FILE **, const char[]);
/* A dataset of doubles (rank 1..3; v NULL: not written) of HylcFileWriteHDF5(). */
typedef struct {
  const char      *name;
  int              rank;
  size_t           dims[3];
  const PetscReal *v;
} HylcFileH5Doubles;
/* Atomic HDF5 output (src/sys/h5file.c): the datasets built as an in-memory HDF5 image and written with
   HylcFileOpenTemp()/HylcFileCommitTemp(); what names the output in messages. Not collective. */
PETSC_EXTERN PetscErrorCode HylcFileWriteHDF5(const char path[], const char what[], int n, const HylcFileH5Doubles ds[]);
/* Raises on every rank of comm the error (code and message) that rank 0 met in work done alone with
   PetscReturnErrorHandler pushed (ierr: rank 0's code; ignored elsewhere). Collective. */
PETSC_EXTERN PetscErrorCode HylcShareError(MPI_Comm, PetscErrorCode);
/* A uniaxial curve as CSV (docs/fabric-uniaxial.md): the header strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2
   and one row per point (s2: sy for a test along x, sx along y), written atomically. Not collective. */
PETSC_EXTERN PetscErrorCode HylcWriteUniaxialCSV(const char[], PetscInt, const PetscReal[], const PetscReal[], const PetscReal[], const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcWritePathCSV(const char[], PetscInt, const PetscReal[], const PetscReal[], const PetscReal[], const PetscReal[], const PetscBool[]);
/* Refuses options nothing has read (before any work), except the options of other hylc programs' stages
   (HylcOptionIsOtherStage()): every program accepts the whole study's options file. Collective. */
PETSC_EXTERN PetscErrorCode HylcCheckOptionsUsed(MPI_Comm);
/* The running program (argv[0], recorded by HylcInitialize()) and whether an option (with or without its
   dash) is read by the stages of other hylc programs only (src/sys/programs.c). Not collective. */
PETSC_EXTERN PetscErrorCode HylcSetProgramName(const char[]);
PETSC_EXTERN PetscErrorCode HylcOptionIsOtherStage(const char[], PetscBool *);
