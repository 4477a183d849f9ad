/* hylc's version and the build's git revision (-version of every program, include/hylc/sys.h). */
#include <hylc/sys.h>
#include <hdf5.h>
#include <stdio.h>
#include <string.h>

#if !defined(HYLC_BUILD_ID)
#  define HYLC_BUILD_ID "unknown"
#endif

/*@C
  HylcGetRevision - The git revision hylc was built from (`git describe --always --dirty` of the
  checkout at build time, recorded by the Makefile; "unknown" outside a checkout). Not collective.

  Level: beginner

.seealso: HylcVersionView()
@*/
const char *HylcGetRevision(void) { return HYLC_BUILD_ID; }

/*@C
  HylcVersionView - Prints the program's name, hylc's version and git revision, and the versions of
  PETSc, HDF5 and MPI it runs with (what -version prints). Collective on PETSC_COMM_WORLD.

  Input Parameter:
. program - the program's name (NULL: "hylc")

  Level: beginner
@*/
PetscErrorCode HylcVersionView(const char program[])
{
  char        petsc[256], mpi[MPI_MAX_LIBRARY_VERSION_STRING] = "", *nl;
  unsigned    maj = 0, min = 0, rel = 0;
  int         len = 0;
  const char *slash;

  PetscFunctionBegin;
  PetscCall(PetscGetVersion(petsc, sizeof(petsc))); /* "Petsc Release Version 3.18.5, Feb 27, 2023 " */
  for (size_t n = strlen(petsc); n && petsc[n - 1] == ' '; n--) petsc[n - 1] = 0;
  PetscCallExternal(H5get_libversion, &maj, &min, &rel);
  PetscCallMPI(MPI_Get_library_version(mpi, &len));
  if ((nl = strchr(mpi, '\n'))) *nl = 0; /* the first line */
  if ((nl = strchr(mpi, ','))) *nl = 0;  /* "Open MPI v4.1.4, package: ..." */
  slash = program ? strrchr(program, '/') : NULL;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s %s (git %s)\n", slash ? slash + 1 : program ? program : "hylc", HYLC_VERSION_STRING, HYLC_BUILD_ID));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "PETSc: %s\n", strncmp(petsc, "Petsc Release Version ", 22) ? petsc : petsc + 22));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "HDF5: %u.%u.%u\n", maj, min, rel));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "MPI: %s\n", mpi));
  PetscFunctionReturn(PETSC_SUCCESS);
}
