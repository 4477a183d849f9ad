/* Concise error reports for user-input errors in hylc programs. */
#include <hylc/sys.h>

static PetscErrorCode HylcErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  (void)ctx;
  const PetscBool user = (PetscBool)(n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_FILE_OPEN || n == PETSC_ERR_FILE_READ || n == PETSC_ERR_FILE_WRITE || n == PETSC_ERR_FILE_UNEXPECTED || n == PETSC_ERR_ARG_OUTOFRANGE || n == PETSC_ERR_ARG_WRONG || n == PETSC_ERR_ARG_INCOMP || n == PETSC_ERR_NOT_CONVERGED);
  if (!user) return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, NULL);
  if (p == PETSC_ERROR_INITIAL) {
    PetscMPIInt rank = 0, size = 1, wsize = 1, wrank = 0;
    if (comm != MPI_COMM_NULL) {
      MPI_Comm_size(comm, &size);
      MPI_Comm_rank(comm, &rank);
    }
    MPI_Comm_size(PETSC_COMM_WORLD, &wsize);
    MPI_Comm_rank(PETSC_COMM_WORLD, &wrank);
    /* an error raised on a communicator of several ranks is raised on all of them: report it once */
    if (rank == 0) {
      if (wsize > 1 && size == 1)
        fprintf(stderr, "hylc: error (rank %d): %s\n", wrank, mess ? mess : "(no message)");
      else
        fprintf(stderr, "hylc: error: %s\n", mess ? mess : "(no message)");
      fflush(stderr);
    }
  }
  return n;
}

PetscErrorCode HylcPushErrorHandler(void)
{
  PetscBool tb = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-hylc_traceback", &tb, NULL));
  if (!tb) PetscCall(PetscPushErrorHandler(HylcErrorHandler, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int HylcMainFinalize(PetscErrorCode ierr)
{
  PetscMPIInt size = 1;
  if (ierr) {
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    if (size > 1) MPI_Abort(PETSC_COMM_WORLD, (int)ierr); /* other ranks may be waiting in a collective */
    PetscFinalize();
    return (int)ierr;
  }
  /* misspelt options must not pass silently */
  PetscInt n     = 0;
  char   **names = NULL, **values = NULL;
  if (!PetscOptionsLeftGet(NULL, &n, &names, &values)) {
    PetscMPIInt rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    for (PetscInt i = 0; i < n && !rank; i++) fprintf(stderr, "hylc: warning: option -%s%s%s was not used (misspelt, or not for this program?)\n", names[i], values[i] ? " " : "", values[i] ? values[i] : "");
    PetscOptionsLeftRestore(NULL, &n, &names, &values);
  }
  return (int)PetscFinalize();
}

/*@C
  HylcCheckOptionsUsed - Refuses options that nothing has read (misspelt or not for this program), before
  any work is done. Collective.
@*/
PetscErrorCode HylcCheckOptionsUsed(MPI_Comm comm)
{
  PetscInt n     = 0;
  char   **names = NULL, **values = NULL, list[1024] = "";

  PetscFunctionBegin;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; i++) {
    PetscCall(PetscStrlcat(list, " -", sizeof(list)));
    PetscCall(PetscStrlcat(list, names[i], sizeof(list)));
  }
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(!list[0], comm, PETSC_ERR_USER_INPUT, "Unknown option(s):%s (misspelt, or not for this program; -help lists the options)", list);
  PetscFunctionReturn(PETSC_SUCCESS);
}
