/* Small file-system helpers shared by the writers of samples and materials. */
#include <hylc/sys.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* " (-option)" for messages, or "" (a small ring of buffers: several may appear in one message) */
static const char *W(const char option[])
{
  static char buf[4][PETSC_MAX_PATH_LEN];
  static int  k;
  if (!option || !option[0]) return "";
  k = (k + 1) % 4;
  snprintf(buf[k], sizeof(buf[k]), " (%s)", option);
  return buf[k];
}

/* the process's file-creation mask (read without changing it for good) */
static mode_t HylcUmask(void)
{
  mode_t m = umask(022);
  umask(m);
  return m;
}

/* fsync the directory holding path, so that a rename into it is durable (errors ignored: some file
   systems do not support it) */
void HylcSyncParentDirectory(const char path[])
{
  char        dir[PETSC_MAX_PATH_LEN];
  const char *slash = strrchr(path, '/');
  int         fd;

  if (!slash)
    snprintf(dir, sizeof(dir), ".");
  else if (slash == path)
    snprintf(dir, sizeof(dir), "/");
  else
    snprintf(dir, sizeof(dir), "%.*s", (int)(slash - path), path);
  fd = open(dir, O_RDONLY);
  if (fd >= 0) {
    (void)fsync(fd);
    close(fd);
  }
}

/*@C
  HylcFileCheckInput - Checks that an input path names a readable regular file (not a directory).
  Not collective.

  Input Parameters:
+ comm   - communicator the error is raised on
. path   - the path
- option - the option that named it (for the message), or NULL

  Level: developer
@*/
PetscErrorCode HylcFileCheckInput(MPI_Comm comm, const char path[], const char option[])
{
  struct stat st;

  PetscFunctionBegin;
  PetscCheck(path && path[0], comm, PETSC_ERR_USER_INPUT, "Empty input path%s%s", option ? " for " : "", option ? option : "");
  PetscCheck(stat(path, &st) == 0, comm, PETSC_ERR_FILE_OPEN, "Cannot open %s%s: %s", path, W(option), strerror(errno));
  PetscCheck(!S_ISDIR(st.st_mode), comm, PETSC_ERR_FILE_OPEN, "Cannot read %s%s: it is a directory", path, W(option));
  PetscCheck(S_ISREG(st.st_mode), comm, PETSC_ERR_FILE_OPEN, "Cannot read %s%s: not a regular file", path, W(option));
  PetscCheck(access(path, R_OK) == 0, comm, PETSC_ERR_FILE_OPEN, "Cannot read %s%s: %s", path, W(option), strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFileCheckOutput - Checks, before any work, that a file can be written at path: the path is not a
  directory, its parent directory exists and is writable. Not collective.

  Input Parameters:
+ comm   - communicator the error is raised on
. path   - the path of the file to be written
- option - the option that named it (for the message), or NULL

  Level: developer
@*/
PetscErrorCode HylcFileCheckOutput(MPI_Comm comm, const char path[], const char option[])
{
  char        dir[PETSC_MAX_PATH_LEN];
  const char *slash;
  struct stat st;

  PetscFunctionBegin;
  PetscCheck(path && path[0], comm, PETSC_ERR_USER_INPUT, "Empty output path%s%s", option ? " for " : "", option ? option : "");
  slash = strrchr(path, '/');
  PetscCheck(slash == NULL || slash[1] != 0, comm, PETSC_ERR_FILE_OPEN, "Cannot write %s%s: it names a directory", path, W(option));
  PetscCheck(stat(path, &st) != 0 || !S_ISDIR(st.st_mode), comm, PETSC_ERR_FILE_OPEN, "Cannot write %s%s: it is a directory", path, W(option));
  if (!slash)
    PetscCall(PetscStrncpy(dir, ".", sizeof(dir)));
  else if (slash == path)
    PetscCall(PetscStrncpy(dir, "/", sizeof(dir)));
  else
    PetscCall(PetscSNPrintf(dir, sizeof(dir), "%.*s", (int)(slash - path), path));
  PetscCheck(stat(dir, &st) == 0, comm, PETSC_ERR_FILE_OPEN, "Cannot write %s%s: directory %s does not exist", path, W(option), dir);
  PetscCheck(S_ISDIR(st.st_mode), comm, PETSC_ERR_FILE_OPEN, "Cannot write %s%s: %s is not a directory", path, W(option), dir);
  PetscCheck(access(dir, W_OK | X_OK) == 0, comm, PETSC_ERR_FILE_OPEN, "Cannot write %s%s: directory %s is not writable", path, W(option), dir);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFileOpenTemp - Opens a new temporary file beside path (same directory, unique name), to be
  renamed onto path by HylcFileCommitTemp() once completely written, or removed by HylcFileAbortTemp().
  A crash or a full disk never leaves a partial file at path. Not collective.

  Input Parameters:
+ path   - the final path
- len    - size of tmp

  Output Parameters:
+ tmp    - the temporary path
- fp     - the open stream

  Level: developer
@*/
PetscErrorCode HylcFileOpenTemp(const char path[], char tmp[], size_t len, FILE **fp)
{
  int fd;

  PetscFunctionBegin;
  *fp = NULL;
  PetscCall(PetscSNPrintf(tmp, len, "%s.tmp.XXXXXX", path));
  fd = mkstemp(tmp);
  PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write %s: %s", path, strerror(errno));
  (void)fchmod(fd, 0644 & ~HylcUmask());
  *fp = fdopen(fd, "w");
  if (!*fp) {
    close(fd);
    unlink(tmp);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write %s: %s", path, strerror(errno));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFileCommitTemp - Flushes, syncs and closes a stream from HylcFileOpenTemp() and renames it onto
  path; on any failure (a full disk, say) removes the temporary and raises PETSC_ERR_FILE_WRITE, leaving
  path as it was. Not collective.
@*/
PetscErrorCode HylcFileCommitTemp(FILE **fp, const char tmp[], const char path[])
{
  int bad;

  PetscFunctionBegin;
  if (!*fp) PetscFunctionReturn(PETSC_SUCCESS);
  bad = ferror(*fp) || fflush(*fp) != 0 || fsync(fileno(*fp)) != 0;
  bad = (fclose(*fp) != 0) || bad;
  *fp = NULL;
  if (!bad) bad = rename(tmp, path) != 0;
  if (bad) {
    int e = errno;
    unlink(tmp);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write %s: %s", path, strerror(e));
  }
  HylcSyncParentDirectory(path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFileAbortTemp - Closes and removes a temporary from HylcFileOpenTemp() (on an error path; never
  raises). Not collective.
@*/
void HylcFileAbortTemp(FILE **fp, const char tmp[])
{
  if (*fp) fclose(*fp);
  *fp = NULL;
  if (tmp && tmp[0]) unlink(tmp);
}

/*@C
  HylcWriteUniaxialCSV - Writes a uniaxial tension curve as CSV (docs/fabric-uniaxial.md): the header line
  "strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2" and one line per point, 17 significant digits.
  strain is the prescribed stretch s (0 at rest), T = dPsi/ds the force per unit width (N/m), sa the
  cosine of the angle between the material axes and s2 the lateral stretch (sy for a test along x, sx
  along y). Written atomically (HylcFileOpenTemp()). Not collective.

  Input Parameters:
+ path   - the file
. n      - the number of points
. strain - the stretches
. T      - the forces per unit width (N/m)
. sa     - the shears
- s2     - the lateral stretches

  Level: intermediate
@*/
PetscErrorCode HylcWriteUniaxialCSV(const char path[], PetscInt n, const PetscReal strain[], const PetscReal T[], const PetscReal sa[], const PetscReal s2[])
{
  char  tmp[PETSC_MAX_PATH_LEN + 32];
  FILE *fp;

  PetscFunctionBegin;
  PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
  fprintf(fp, "strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2\n");
  for (PetscInt i = 0; i < n; i++) fprintf(fp, "%.17g,%.17g,%.17g,%.17g\n", (double)strain[i], (double)T[i], (double)sa[i], (double)s2[i]);
  PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcWritePathCSV - Writes the states of a load path as CSV (docs/fabric-fidelity.md): the header line
  "value,force,sx,sa,sy,II00,II11,psi,converged" and one line per state, 17 significant digits: value the
  prescribed quantity (a stretch, sa, or a curvature in 1/m), force d(min Psi)/ds (N/m; N for a bending path), the
  state's strain (II in 1/m), Psi (J/m^2) and 1 or 0. Written atomically (HylcFileOpenTemp()). Not collective.

  Input Parameters:
+ path  - the file
. n     - the number of states
. value - the prescribed values
. force - the forces
. z     - the strains (n x 6: sx, sa, sy, II00, II01, II11)
. psi   - the energies
- conv  - whether each state converged

  Level: intermediate

.seealso: HylcWriteUniaxialCSV(), HylcMicroSolvePath(), HylcMaterialPathState()
@*/
PetscErrorCode HylcWritePathCSV(const char path[], PetscInt n, const PetscReal value[], const PetscReal force[], const PetscReal z[], const PetscReal psi[], const PetscBool conv[])
{
  char  tmp[PETSC_MAX_PATH_LEN + 32];
  FILE *fp;

  PetscFunctionBegin;
  PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
  fprintf(fp, "value,force,sx,sa,sy,II00,II11,psi,converged\n");
  for (PetscInt i = 0; i < n; i++)
    fprintf(fp, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n", (double)value[i], (double)force[i], (double)z[6 * i], (double)z[6 * i + 1], (double)z[6 * i + 2], (double)z[6 * i + 3], (double)z[6 * i + 5], (double)psi[i], conv[i] ? 1 : 0);
  PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  PetscFunctionReturn(PETSC_SUCCESS);
}
