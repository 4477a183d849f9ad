/* The registry of a program's files (include/hylc/files.h): inputs and outputs listed before any work and
   checked together, so that no output replaces an input or another output and no output path fails after
   the work. */
#include <hylc/files.h>
#include <petscviewer.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- the options files (plain C: also used before PetscInitialize) ---- */

#define HYLC_OPTIONS_FILES_MAX   256
#define HYLC_OPTIONS_FILES_DEPTH 8

typedef struct {
  char *seen[HYLC_OPTIONS_FILES_MAX];
  int   nseen;
  void (*fn)(const char[], const char[], int, void *);
  void *ctx;
} OptionsWalk;

static int EndsWith(const char s[], const char suffix[])
{
  size_t n = strlen(s), m = strlen(suffix);
  return n >= m && !strcasecmp(s + n - m, suffix);
}

static int IsYAMLName(const char f[]) { return EndsWith(f, ".yaml") || EndsWith(f, ".yml"); }

static void Visit(OptionsWalk *w, const char path[], const char what[], int yaml, int depth)
{
  FILE   *fp;
  char   *line = NULL;
  size_t  cap  = 0;
  ssize_t len;

  for (int i = 0; i < w->nseen; i++)
    if (!strcmp(w->seen[i], path)) return;
  if (w->nseen == HYLC_OPTIONS_FILES_MAX) return;
  if (!(w->seen[w->nseen] = strdup(path))) return;
  w->nseen++;
  w->fn(path, what, yaml, w->ctx);
  if (yaml || depth >= HYLC_OPTIONS_FILES_DEPTH || !(fp = fopen(path, "r"))) return;
  /* a plain options file: one option per line, '#' comments; "-options_file F" names another file */
  while ((len = getline(&line, &cap, fp)) >= 0) {
    char *c = strchr(line, '#'), *key, *val, *save = NULL;
    if (c) *c = 0;
    key = strtok_r(line, " \t\r\n", &save);
    val = key ? strtok_r(NULL, " \t\r\n", &save) : NULL;
    if (!key || !val) continue;
    if (!strcasecmp(key, "-options_file") || !strcasecmp(key, "-options_file_yaml")) {
      char in[PETSC_MAX_PATH_LEN + 32];
      snprintf(in, sizeof(in), "-options_file in %s", path);
      Visit(w, val, in, !strcasecmp(key, "-options_file_yaml") || IsYAMLName(val), depth + 1);
    }
  }
  free(line);
  fclose(fp);
}

/* the -options_file values in a list of arguments */
static void VisitArgs(OptionsWalk *w, int n, char **args, const char what[])
{
  for (int i = 0; i + 1 < n; i++) {
    const int yaml = !strcasecmp(args[i], "-options_file_yaml");
    if (!yaml && strcasecmp(args[i], "-options_file")) continue;
    Visit(w, args[i + 1], what, yaml || IsYAMLName(args[i + 1]), 0);
    i++;
  }
}

/* the arguments of $PETSC_OPTIONS, split at blanks (a malloc'd copy in *buf, pointers in args) */
static int EnvArgs(char **buf, char *args[], int max)
{
  const char *env  = getenv("PETSC_OPTIONS");
  char       *save = NULL, *t;
  int         n    = 0;

  *buf = env ? strdup(env) : NULL;
  if (!*buf) return 0;
  for (t = strtok_r(*buf, " \t\r\n", &save); t && n < max; t = strtok_r(NULL, " \t\r\n", &save)) args[n++] = t;
  return n;
}

void HylcOptionsFilesForEach(int argc, char **argv, void (*fn)(const char[], const char[], int, void *), void *ctx)
{
  OptionsWalk w;
  char       *env, *eargs[1024];
  int         ne, skip = 0;

  memset(&w, 0, sizeof(w));
  w.fn  = fn;
  w.ctx = ctx;
  ne    = EnvArgs(&env, eargs, 1024);
  for (int i = 1; i < argc; i++) skip = skip || !strcasecmp(argv[i], "-skip_petscrc");
  for (int i = 0; i < ne; i++) skip = skip || !strcasecmp(eargs[i], "-skip_petscrc");
  if (!skip) { /* PetscOptionsInsert() reads these first */
    const char *home = getenv("HOME");
    char        rc[PETSC_MAX_PATH_LEN];
    struct stat st;
    if (home && home[0]) {
      snprintf(rc, sizeof(rc), "%s/.petscrc", home);
      if (!stat(rc, &st) && S_ISREG(st.st_mode)) Visit(&w, rc, "PETSc's ~/.petscrc", 0, 0);
    }
    if (!stat(".petscrc", &st) && S_ISREG(st.st_mode)) Visit(&w, ".petscrc", "PETSc's .petscrc", 0, 0);
    if (!stat("petscrc", &st) && S_ISREG(st.st_mode)) Visit(&w, "petscrc", "PETSc's petscrc", 0, 0);
  }
  VisitArgs(&w, ne, eargs, "-options_file in PETSC_OPTIONS");
  VisitArgs(&w, argc, argv, "-options_file");
  free(env);
  for (int i = 0; i < w.nseen; i++) free(w.seen[i]);
}

/* ---- the registry ---- */

typedef struct {
  HylcFileRole role;
  char        *path, *what;
} Entry;

struct _n_HylcFiles {
  MPI_Comm comm;
  int      n, cap;
  Entry   *e;
};

/*@C
  HylcFilesCreate - Creates an empty registry of a program's files (include/hylc/files.h).

  Not collective

  Input Parameter:
. comm - the ranks that check it together (HylcFilesCheck())

  Output Parameter:
. files - the registry

  Level: developer
@*/
PetscErrorCode HylcFilesCreate(MPI_Comm comm, HylcFiles *files)
{
  PetscFunctionBegin;
  PetscCall(PetscNew(files));
  (*files)->comm = comm;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFilesDestroy - Frees a registry (accepts NULL; sets the handle to NULL).

  Not collective

  Level: developer
@*/
PetscErrorCode HylcFilesDestroy(HylcFiles *files)
{
  PetscFunctionBegin;
  if (!*files) PetscFunctionReturn(PETSC_SUCCESS);
  for (int i = 0; i < (*files)->n; i++) {
    PetscCall(PetscFree((*files)->e[i].path));
    PetscCall(PetscFree((*files)->e[i].what));
  }
  PetscCall(PetscFree((*files)->e));
  PetscCall(PetscFree(*files));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFilesAdd - Adds a file to the registry.

  Not collective

  Input Parameters:
+ files - the registry
. role  - HYLC_FILE_INPUT, HYLC_FILE_INPUT_OPTIONAL or HYLC_FILE_OUTPUT
. path  - the path (NULL or "": nothing is added)
- what  - the option that named it ("-fit_json"), or a phrase for the messages

  Level: developer
@*/
PetscErrorCode HylcFilesAdd(HylcFiles files, HylcFileRole role, const char path[], const char what[])
{
  PetscFunctionBegin;
  if (!path || !path[0]) PetscFunctionReturn(PETSC_SUCCESS);
  if (files->n == files->cap) {
    files->cap = files->cap ? 2 * files->cap : 16;
    PetscCall(PetscRealloc(sizeof(Entry) * (size_t)files->cap, &files->e));
  }
  files->e[files->n].role = role;
  PetscCall(PetscStrallocpy(path, &files->e[files->n].path));
  PetscCall(PetscStrallocpy(what ? what : "", &files->e[files->n].what));
  files->n++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  HylcFiles      files;
  PetscErrorCode ierr;
} AddCtx;

static void AddOptionsFile(const char path[], const char what[], int yaml, void *ctx)
{
  AddCtx *a = (AddCtx *)ctx;
  (void)yaml;
  if (!a->ierr) a->ierr = HylcFilesAdd(a->files, HYLC_FILE_INPUT, path, what);
}

/*@C
  HylcFilesAddOptionsFiles - Adds, as inputs, every options file the program read: -options_file and
  -options_file_yaml on the command line and in $PETSC_OPTIONS, the files those name, and PETSc's petscrc
  files (HylcOptionsFilesForEach()).

  Not collective

  Input Parameter:
. files - the registry

  Level: developer
@*/
PetscErrorCode HylcFilesAddOptionsFiles(HylcFiles files)
{
  int    argc = 0;
  char **args = NULL;
  AddCtx a    = {files, PETSC_SUCCESS};

  PetscFunctionBegin;
  PetscCall(PetscGetArgs(&argc, &args));
  HylcOptionsFilesForEach(argc, args, AddOptionsFile, &a);
  PetscCall(a.ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* what identifies a file: its device and inode when it exists, else its directory's and its name */
typedef struct {
  int         exists, resolved; /* resolved: the file or its directory was found */
  dev_t       dev;
  ino_t       ino;
  char        name[NAME_MAX + 1];
  const char *path;
} Identity;

static void Identify(const char path[], Identity *id)
{
  char        p[2 * PATH_MAX], dir[2 * PATH_MAX];
  struct stat st;
  const char *slash;

  memset(id, 0, sizeof(*id));
  id->path = path;
  if (!stat(path, &st)) {
    id->exists = id->resolved = 1;
    id->dev                   = st.st_dev;
    id->ino                   = st.st_ino;
    return;
  }
  snprintf(p, sizeof(p), "%s", path);
  /* a dangling symbolic link names the file it would create */
  for (int k = 0; k < 16; k++) {
    char    target[PATH_MAX];
    ssize_t n;
    if (lstat(p, &st) || !S_ISLNK(st.st_mode)) break;
    n = readlink(p, target, sizeof(target) - 1);
    if (n <= 0) break;
    target[n] = 0;
    slash     = strrchr(p, '/');
    if (target[0] == '/' || !slash)
      snprintf(dir, sizeof(dir), "%s", target);
    else
      snprintf(dir, sizeof(dir), "%.*s/%s", (int)(slash - p), p, target);
    snprintf(p, sizeof(p), "%s", dir);
  }
  slash = strrchr(p, '/');
  if (!slash)
    snprintf(dir, sizeof(dir), ".");
  else if (slash == p)
    snprintf(dir, sizeof(dir), "/");
  else
    snprintf(dir, sizeof(dir), "%.*s", (int)(slash - p), p);
  snprintf(id->name, sizeof(id->name), "%.*s", NAME_MAX, slash ? slash + 1 : p); /* longer names are refused before */
  if (!stat(dir, &st) && S_ISDIR(st.st_mode)) {
    id->resolved = 1;
    id->dev      = st.st_dev;
    id->ino      = st.st_ino;
  }
}

static int SameFile(const Identity *a, const Identity *b)
{
  if (a->exists != b->exists) return 0;
  if (a->exists) return a->dev == b->dev && a->ino == b->ino;
  if (a->resolved && b->resolved) return a->dev == b->dev && a->ino == b->ino && !strcmp(a->name, b->name);
  return !a->resolved && !b->resolved && !strcmp(a->path, b->path);
}

/* whether what names an option (looked up for its untruncated value) */
static int IsOptionName(const char what[]) { return what[0] == '-' && what[1] && !strchr(what, ' '); }

/* a path within the limits: the whole and every component; an output also with its temporary's suffix */
static PetscErrorCode CheckLength(const Entry *e)
{
  const size_t extra = e->role == HYLC_FILE_OUTPUT ? HYLC_FILES_TEMP_SUFFIX : 0;
  size_t       len   = strlen(e->path);
  const char  *c     = e->path;

  PetscFunctionBegin;
  if (IsOptionName(e->what)) {
    const char *val = NULL;
    PetscBool   set = PETSC_FALSE;
    PetscCall(PetscOptionsFindPair(NULL, NULL, e->what, &val, &set));
    if (set && val) len = PetscMax(len, strlen(val));
  }
  PetscCheck(len + extra < PATH_MAX && len < PETSC_MAX_PATH_LEN, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: the path has %zu characters, over the limit of %d%s", e->what, len, (int)PetscMin(PATH_MAX, PETSC_MAX_PATH_LEN) - 1 - (int)extra,
             extra ? " for an output (the temporary it is written through adds a suffix)" : "");
  while (*c) {
    const char  *s    = strchr(c, '/');
    const size_t n    = s ? (size_t)(s - c) : strlen(c);
    const int    last = !s;
    PetscCheck(n + (last ? extra : 0) <= NAME_MAX, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: the path component '%.24s...' has %zu characters, over the limit of %d%s", e->what, c, n, NAME_MAX - (int)(last ? extra : 0),
               last && extra ? " for an output's name (the temporary it is written through adds a suffix)" : "");
    c += n + (s ? 1 : 0);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0's checks */
static PetscErrorCode CheckAll(HylcFiles files)
{
  Identity *id;

  PetscFunctionBegin;
  for (int i = 0; i < files->n; i++) {
    const Entry *e = &files->e[i];
    struct stat  st;
    PetscCall(CheckLength(e));
    if (e->role == HYLC_FILE_INPUT || (e->role == HYLC_FILE_INPUT_OPTIONAL && !stat(e->path, &st))) PetscCall(HylcFileCheckInput(PETSC_COMM_SELF, e->path, e->what));
    if (e->role == HYLC_FILE_OUTPUT) PetscCall(HylcFileCheckOutput(PETSC_COMM_SELF, e->path, e->what));
  }
  PetscCall(PetscMalloc1(files->n + 1, &id));
  for (int i = 0; i < files->n; i++) Identify(files->e[i].path, &id[i]);
  for (int i = 0; i < files->n; i++) {
    const Entry *o = &files->e[i];
    if (o->role != HYLC_FILE_OUTPUT) continue;
    for (int j = 0; j < files->n; j++) {
      const Entry *f = &files->e[j];
      if (j == i || (f->role == HYLC_FILE_OUTPUT && j > i) || !SameFile(&id[i], &id[j])) continue;
      if (f->role != HYLC_FILE_OUTPUT) {
        PetscCall(PetscFree(id));
        SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Output %s (%s) is the input %s (%s): refusing to overwrite an input", o->path, o->what, f->path, f->what);
      }
      PetscCall(PetscFree(id));
      if (!strcmp(o->path, f->path)) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s and %s name the same file %s: one output would replace the other", f->what, o->what, o->path);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s and %s name the same file (%s, %s): one output would replace the other", f->what, o->what, f->path, o->path);
    }
  }
  PetscCall(PetscFree(id));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFilesCheck - Checks every file of the registry (include/hylc/files.h) before any work: path lengths,
  inputs readable, outputs writable, no output the same file as an input or another output. Rank 0
  checks; the first problem is raised on every rank as one PETSC_ERR_USER_INPUT or PETSC_ERR_FILE_OPEN
  error naming the option.

  Collective

  Input Parameter:
. files - the registry

  Level: developer
@*/
PetscErrorCode HylcFilesCheck(HylcFiles files)
{
  PetscMPIInt    rank;
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(files->comm, &rank));
  if (!rank) {
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CheckAll(files);
    PetscCall(PetscPopErrorHandler());
  }
  PetscCall(HylcShareError(files->comm, ierr));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFilesView - Lists the files of the registry: "input <path> (<what>)", "output <path> (<what>)".

  Collective

  Input Parameters:
+ files  - the registry
- viewer - an ASCII viewer (NULL: stdout of the registry's communicator)

  Level: developer
@*/
PetscErrorCode HylcFilesView(HylcFiles files, PetscViewer viewer)
{
  PetscFunctionBegin;
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(files->comm, &viewer));
  for (int i = 0; i < files->n; i++) PetscCall(PetscViewerASCIIPrintf(viewer, "%s %s (%s)\n", files->e[i].role == HYLC_FILE_OUTPUT ? "output" : files->e[i].role == HYLC_FILE_INPUT ? "input" : "input (optional)", files->e[i].path, files->e[i].what));
  PetscFunctionReturn(PETSC_SUCCESS);
}
