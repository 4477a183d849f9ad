/* Small file-system helpers shared by the writers of samples and materials. */
#include <hylc/sys.h>
#include <fcntl.h>
#include <string.h>
#include <unistd.h>

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
