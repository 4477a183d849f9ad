/* Concise error reports for user-input errors in hylc programs. */
#include <hylc/private/sysimpl.h>
#include <hylc/files.h>
#include <hylc/private/yamlcheck.h>
#include <unistd.h>
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int HylcIsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

static void HylcOptionSource(const char name[], char where[], size_t len);

/* The options (up to three, "-a, -b") whose value is x or has x as one comma-separated element (each
   value as the database holds it, so that a value with blanks, "1e6 Pa", is found too). */
static int HylcOptionsWithValue(const char x[], char names[], size_t len, char first[], size_t flen)
{
  char *all = NULL, *tok, *save = NULL;
  int   count = 0;

  names[0] = first[0] = 0;
  if (!x || !x[0] || PetscOptionsGetAll(NULL, &all) || !all) return 0;
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    const char *val = NULL;
    PetscBool   set = PETSC_FALSE;
    if (!(tok[0] == '-' && (isalpha((unsigned char)tok[1]) || tok[1] == '_'))) continue;
    if (PetscOptionsFindPair(NULL, NULL, tok, &val, &set) || !set || !val) continue;
    /* compare as a whole and element by element */
    int          hit = !strcmp(val, x);
    const char  *e   = val;
    const size_t m   = strlen(x);
    while (!hit && e) {
      if (!strncmp(e, x, m) && (e[m] == ',' || e[m] == 0)) hit = 1;
      e = strchr(e, ',');
      if (e) e++;
    }
    if (hit && !strstr(names, tok)) {
      if (!count) snprintf(first, flen, "%s", tok + 1);
      if (count < 3) {
        if (count) strncat(names, " or ", len - strlen(names) - 1);
        strncat(names, tok, len - strlen(names) - 1);
      }
      count++;
    }
  }
  PetscFree(all);
  return count;
}

/* The first option the message names ("-name" after a blank, '(' or a quote, or at its start) that is
   set, and where an options file sets it ("file:line: "); returns 1 if one is found in a file. */
static int HylcMessageOptionSource(const char mess[], char where[], size_t len)
{
  where[0] = 0;
  for (const char *c = mess; c && *c; c++) {
    char      name[256];
    size_t    n = 0;
    PetscBool set;
    if (*c != '-' || !(c == mess || HylcIsSpace(c[-1]) || c[-1] == '(' || c[-1] == '\'' || c[-1] == '"' || c[-1] == '`')) continue;
    if (!(isalpha((unsigned char)c[1]) || c[1] == '_')) continue;
    while (n + 1 < sizeof(name) && (isalnum((unsigned char)c[n]) || c[n] == '_' || (n == 0 && c[n] == '-'))) {
      name[n] = c[n];
      n++;
    }
    name[n] = 0;
    if (PetscOptionsHasName(NULL, NULL, name, &set) || !set) continue;
    HylcOptionSource(name, where, len);
    return where[0] != 0;
  }
  return 0;
}

/* Rewrites PETSc's messages about an option's value so that they name the option (and the options file
   and line that set it): "Input string abc has no integer value" becomes
   "config.yaml:7: option -sampler_n1: 'abc' is not an integer". Returns 1 if out holds a new message. */
static int HylcDescribeOptionError(PetscErrorCode n, const char mess[], char out[], size_t len)
{
  char        x[256] = "", names[256], first[256], where[PETSC_MAX_PATH_LEN + 32];
  const char *what   = NULL;

  if (!mess) return 0;
  if (!strncmp(mess, "Input string ", 13)) {
    const char *a = mess + 13, *b = strstr(a, " has no ");
    if (!b) return 0;
    snprintf(x, sizeof(x), "%.*s", (int)PetscMin((size_t)(b - a), sizeof(x) - 1), a);
    b += 8;
    if (!strncmp(b, "integer", 7))
      what = "is not an integer";
    else if (!strncmp(b, "numeric", 7))
      what = "is not a number";
    else
      what = "is not a valid value";
  } else if (!strncmp(mess, "Unknown logical value: ", 23)) {
    snprintf(x, sizeof(x), "%s", mess + 23);
    what = "is not a boolean (true, false, yes, no, 1, 0)";
  } else if (n == PETSC_ERR_ARG_UNKNOWN_TYPE && !strncmp(mess, "Unable to find requested ", 25)) {
    const char *a = strrchr(mess, ' ');
    if (!a) return 0;
    snprintf(x, sizeof(x), "%s", a + 1);
  } else if (n == PETSC_ERR_MISSING_FACTOR && !strncmp(mess, "Could not locate solver type ", 29)) {
    const char *a = mess + 29, *b = strchr(a, ' ');
    if (!b) return 0;
    snprintf(x, sizeof(x), "%.*s", (int)PetscMin((size_t)(b - a), sizeof(x) - 1), a);
  } else
    return 0;
  /* strip trailing blanks and punctuation PETSc may have left */
  for (size_t k = strlen(x); k && (HylcIsSpace(x[k - 1]) || x[k - 1] == '.'); k--) x[k - 1] = 0;
  if (!HylcOptionsWithValue(x, names, sizeof(names), first, sizeof(first))) return 0;
  HylcOptionSource(first, where, sizeof(where));
  if (what)
    snprintf(out, len, "%soption %s: '%s' %s", where, names, x, what);
  else
    snprintf(out, len, "%s%s (option %s %s)", where, mess, names, x);
  return 1;
}

static PetscErrorCode HylcErrorHandler(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  (void)ctx;
  /* errors in what the user gave: files, options and their values (PETSC_ERR_USER: a bad choice for an
     option, "Unknown option silk for -sampler_family"; PETSC_ERR_ARG_UNKNOWN_TYPE: -micro_snes_type bogus;
     PETSC_ERR_MISSING_FACTOR: a factorization package PETSc does not have, -..._mat_solver_type nosuchsolver) */
  const PetscBool user = (PetscBool)(n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_USER || n == PETSC_ERR_ARG_UNKNOWN_TYPE || n == PETSC_ERR_MISSING_FACTOR || n == PETSC_ERR_FILE_OPEN || n == PETSC_ERR_FILE_READ || n == PETSC_ERR_FILE_WRITE ||
                                     n == PETSC_ERR_FILE_UNEXPECTED || n == PETSC_ERR_ARG_OUTOFRANGE || n == PETSC_ERR_ARG_WRONG || n == PETSC_ERR_ARG_INCOMP || n == PETSC_ERR_NOT_CONVERGED);
  char            better[PETSC_MAX_PATH_LEN + 512];
  if (!user) return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, NULL);
  if (p == PETSC_ERROR_INITIAL && HylcDescribeOptionError(n, mess, better, sizeof(better)))
    mess = better;
  else if (p == PETSC_ERROR_INITIAL && mess && strncmp(mess, "Cannot open options file", 24)) {
    /* a message about an option set in an options file names the file and line first */
    char where[PETSC_MAX_PATH_LEN + 32];
    if (HylcMessageOptionSource(mess, where, sizeof(where)) && strncmp(mess, where, strlen(where))) {
      snprintf(better, sizeof(better), "%s%s", where, mess);
      mess = better;
    }
  }
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

/*@C
  HylcPushErrorHandler - Pushes hylc's error handler: errors of user input, files and ranges
  (PETSC_ERR_USER_INPUT, PETSC_ERR_FILE_*, PETSC_ERR_ARG_OUTOFRANGE, ...) are reported as one line
  "hylc: error: <message>" on rank 0 of the communicator the error was raised on, other errors with PETSc's
  full traceback. Call right after PetscInitialize() (HylcInitialize() does).

  Not collective

  Options Database Key:
. -hylc_traceback - keep PETSc's handler for all errors

  Level: developer

.seealso: HylcInitialize(), HylcMainFinalize()
@*/
PetscErrorCode HylcPushErrorHandler(void)
{
  PetscBool tb = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-hylc_traceback", &tb, NULL));
  if (!tb) PetscCall(PetscPushErrorHandler(HylcErrorHandler, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A duplicate of PETSC_COMM_WORLD used only by HylcMainFinalize() to learn whether every rank ended with
   an error (created by HylcInitialize(); no other message ever travels on it). */
static MPI_Comm HylcErrorComm = MPI_COMM_NULL;

/* Whether every rank of PETSC_COMM_WORLD has reached HylcMainFinalize() with an error within a few
   seconds (a non-blocking barrier on HylcErrorComm, polled). */
static int HylcAllRanksFailed(void)
{
  MPI_Request req;
  int         done = 0;
  double      t0;

  if (HylcErrorComm == MPI_COMM_NULL || MPI_Ibarrier(HylcErrorComm, &req) != MPI_SUCCESS) return 0;
  t0 = MPI_Wtime();
  while (!done && MPI_Wtime() - t0 < 5.0) {
    if (MPI_Test(&req, &done, MPI_STATUS_IGNORE) != MPI_SUCCESS) return 0;
    if (!done) usleep(1000);
  }
  return done;
}

int HylcMainFinalize(PetscErrorCode ierr)
{
  PetscMPIInt size = 1;
  HylcHelpFlush(); /* -help: hylc's options, then PETSc's */
  if (ierr) {
    /* An error raised on every rank (bad input, checked collectively) ends the job normally, so that the
       message printed by rank 0 is never cut off by an abort from another rank. An error on some ranks
       only (others may wait in a collective) aborts the job once the others have not followed. */
    MPI_Comm_size(PETSC_COMM_WORLD, &size);
    if (size > 1 && !HylcAllRanksFailed()) MPI_Abort(PETSC_COMM_WORLD, (int)ierr);
    if (HylcErrorComm != MPI_COMM_NULL) MPI_Comm_free(&HylcErrorComm);
    PetscFinalize();
    return (int)ierr;
  }
  if (HylcErrorComm != MPI_COMM_NULL) MPI_Comm_free(&HylcErrorComm);
  /* misspelt options must not pass silently: every program refuses them before its work
     (HylcCheckOptionsUsed()); one still unread at the end (-help lists without reading all) is an error
     too, except with -help */
  PetscInt  n = 0, bad = 0;
  char    **names = NULL, **values = NULL;
  PetscBool help = PETSC_FALSE;
  PetscOptionsHasHelp(NULL, &help);
  if (!PetscOptionsLeftGet(NULL, &n, &names, &values)) {
    PetscMPIInt rank = 0;
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
    for (PetscInt i = 0; i < n; i++) {
      PetscBool other = PETSC_FALSE;
      if (!HylcOptionIsOtherStage(names[i], &other) && other) continue;
      bad++;
      if (!rank) fprintf(stderr, "hylc: %s: option -%s%s%s was not used (misspelt, or not for this program; -help lists the options)\n", help ? "warning" : "error", names[i], values[i] ? " " : "", values[i] ? values[i] : "");
    }
    PetscOptionsLeftRestore(NULL, &n, &names, &values);
  }
  ierr = PetscFinalize();
  if (ierr) return (int)ierr;
  return bad && !help ? (int)PETSC_ERR_USER_INPUT : 0;
}

/*@C
  HylcShareError - Raises on every rank of comm the error that rank 0 met in work it did alone. Rank 0
  runs the work with PetscReturnErrorHandler pushed (so nothing is printed there) and passes its error
  code; the other ranks pass 0. If rank 0 failed, every rank raises its code with its message, so the
  program reports it once, in one line, and no rank is left waiting in a collective. Collective.

  Input Parameters:
+ comm - the ranks
- ierr - rank 0: the work's error code; other ranks: ignored

  Level: developer
@*/
PetscErrorCode HylcShareError(MPI_Comm comm, PetscErrorCode ierr)
{
  PetscMPIInt rank;
  int         code      = 0;
  char        msg[2048] = "";

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank && ierr) {
    char *text = NULL;
    code       = (int)ierr;
    PetscCall(PetscErrorMessage(ierr, NULL, &text));
    PetscCall(PetscStrncpy(msg, text && text[0] ? text : "an error on rank 0", sizeof(msg)));
  }
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, 0, comm));
  if (!code) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Bcast(msg, (PetscMPIInt)sizeof(msg), MPI_CHAR, 0, comm));
  SETERRQ(comm, (PetscErrorCode)code, "%s", msg);
}

static int EndsWith(const char s[], const char end[])
{
  const size_t n = strlen(s), m = strlen(end);
  return n > m && !strcmp(s + n - m, end);
}

/* an option of PETSc's MUMPS interface: mat_mumps_..., with or without a prefix (cloth_mat_mumps_...) */
static int IsMumpsOption(const char s[]) { return !strncmp(s, "mat_mumps_", 10) || strstr(s, "_mat_mumps_") != NULL; }

/*@C
  HylcCheckOptionsUsed - Refuses options that nothing has read (misspelt or not for this program), before
  any work is done; the options of other hylc programs' stages only (HylcOptionIsOtherStage()) are
  ignored, so that every program reads the whole study's options file. A viewer option (a name ending in
  _view, read when its object is viewed, or in _converged_reason, read when its solve ends) and an option
  of MUMPS (mat_mumps_*, with any prefix: read at the first factorization) are left to
  HylcMainFinalize(), which refuses what is still unread at the end. Collective.
@*/
PetscErrorCode HylcCheckOptionsUsed(MPI_Comm comm)
{
  PetscInt n = 0, shown = 0, nbad = 0;
  char   **names = NULL, **values = NULL, list[1024] = "";

  PetscFunctionBegin;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  /* as many names as fit, then how many more (PETSc 3.18's PetscStrlcat writes past a nearly full buffer);
     the options of other programs' stages only are not this program's to refuse (HylcOptionIsOtherStage()) */
  for (PetscInt i = 0; i < n; i++) {
    const size_t used = strlen(list), need = strlen(names[i]) + 2;
    PetscBool    other;
    PetscCall(HylcOptionIsOtherStage(names[i], &other));
    if (other) continue;
    /* a viewer option (-mat_view, -micro_snes_view) is read when its object is viewed, and a solver's
       -..._converged_reason at the end of its solve, during the work: HylcMainFinalize() refuses either if
       it is still unread at the end */
    if (EndsWith(names[i], "_view") || EndsWith(names[i], "_converged_reason")) continue;
    /* MUMPS' options (-mat_mumps_icntl_14, -cloth_mat_mumps_cntl_1: the factor matrix's prefix, the
       solver's) are read at its first factorization, during the work: deferred the same way */
    if (IsMumpsOption(names[i])) continue;
    nbad++;
    if (used + need + 32 >= sizeof(list)) continue;
    snprintf(list + used, sizeof(list) - used, " -%s", names[i]);
    shown++;
  }
  if (shown < nbad) snprintf(list + strlen(list), sizeof(list) - strlen(list), " and %" PetscInt_FMT " more", nbad - shown);
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscCheck(!list[0], comm, PETSC_ERR_USER_INPUT, "Unknown option(s):%s (misspelt, or not for this program; -help lists the options)", list);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---------------------------------------------------------------------------------------------- */
/* Options files checked before PetscInitialize(): PETSc 3.18 reads them inside PetscInitialize(),
   before any hylc error handler exists, and reports a malformed YAML file as "YAML parser loading
   error" with neither file nor line. */

/* whether this process is rank 0 of the job, from the launcher's environment (MPI is not initialized) */
static int HylcLaunchRankZero(void)
{
  const char *vars[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", "MPI_LOCALRANKID"};
  for (size_t i = 0; i < sizeof(vars) / sizeof(vars[0]); i++) {
    const char *v = getenv(vars[i]);
    if (v && v[0]) return atoi(v) == 0;
  }
  return 1;
}

/* ---- every options file checked, and the options counted, before PetscInitialize() ---- */

/* PETSc 3.18 holds at most this many options (MAXOPTIONS of src/sys/objects/options.c); more end
   PetscInitialize() with a traceback of a thousand lines */
#define HYLC_MAX_OPTIONS 512

typedef struct {
  char  *msg;
  size_t len;
  int    bad;
  char  *keys[HYLC_MAX_OPTIONS + 1]; /* distinct option names, lower case */
  int    nkeys;
} OptionsScan;

/* PETSc's PetscOptionsValidKey(): "-" or "--", a letter, and not a number ("-inf") */
static int HylcValidKey(const char *k)
{
  char *end;
  if (!k || k[0] != '-') return 0;
  if (k[1] == '-') k++;
  if (!isalpha((unsigned char)k[1])) return 0;
  (void)strtod(k, &end);
  return !(end != k && !(*end == '_' || isalnum((unsigned char)*end)));
}

/* counts the option key (without its dashes); past the limit, writes the message naming where */
static void HylcCountKey(OptionsScan *o, const char *key, size_t n, const char where[])
{
  char name[256];
  if (o->bad) return;
  while (n && *key == '-') key++, n--;
  if (!n) return;
  if (n >= sizeof(name)) n = sizeof(name) - 1;
  for (size_t i = 0; i < n; i++) name[i] = (char)tolower((unsigned char)key[i]);
  name[n] = 0;
  /* processed by PETSc's reader, not stored */
  if (!strcmp(name, "options_file") || !strcmp(name, "options_file_yaml") || !strcmp(name, "prefix_push") || !strcmp(name, "prefix_pop")) return;
  for (int i = 0; i < o->nkeys; i++)
    if (!strcmp(o->keys[i], name)) return;
  if (o->nkeys == HYLC_MAX_OPTIONS) {
    snprintf(o->msg, o->len, "Too many options: -%s (%s) is the %dth distinct one; PETSc holds at most %d (the command line, PETSC_OPTIONS and the options files together)", name, where, HYLC_MAX_OPTIONS + 1, HYLC_MAX_OPTIONS);
    o->bad = 1;
    return;
  }
  o->keys[o->nkeys++] = strdup(name);
}

/* the keys of a list of arguments (the command line, PETSC_OPTIONS) */
static void HylcCountArgs(OptionsScan *o, int n, char **args, const char where[])
{
  for (int i = 0; i < n; i++)
    if (HylcValidKey(args[i])) HylcCountKey(o, args[i], strlen(args[i]), where);
}

/* Calls fn(key, n, path, lineno, ctx) for each option key of a plain options file (one "-key value" per
   line; key with its dash) or a YAML one ("key: value", nested keys joined with '_' as PETSc does; key
   without a dash), in file order, until fn returns non-zero. */
static void HylcWalkFileKeys(const char path[], int yaml, int (*fn)(const char *, size_t, const char[], int, void *), void *ctx)
{
  FILE   *fp   = fopen(path, "r");
  char   *line = NULL;
  size_t  cap  = 0;
  ssize_t len;
  int     lineno = 0, depth = 0, indent[64], stop = 0;
  char    stack[64][128];

  if (!fp) return;
  while (!stop && (len = getline(&line, &cap, fp)) >= 0) {
    char *s   = line, *c;
    int   ind = 0;
    lineno++;
    if (!yaml) {
      if ((c = strchr(s, '#'))) *c = 0;
      while (HylcIsSpace(*s)) s++;
      c = s;
      while (*c && !HylcIsSpace(*c)) c++;
      if (c > s && *s == '-') {
        char k = *c;
        *c     = 0;
        if (HylcValidKey(s)) stop = fn(s, strlen(s), path, lineno, ctx);
        *c = k;
      }
      continue;
    }
    while (*s == ' ') s++, ind++;
    if (*s == '#' || !*s || HylcIsSpace(*s) || (s[0] == '-' && (s[1] == ' ' || !s[1] || s[1] == '\n'))) continue;
    if (!strncmp(s, "---", 3) || !strncmp(s, "...", 3) || *s == '%') continue;
    for (c = s; *c && !(*c == ':' && (HylcIsSpace(c[1]) || !c[1])); c++) {}
    if (!*c) continue;
    while (depth > 0 && indent[depth - 1] >= ind) depth--;
    {
      char *v = c + 1;
      while (*v == ' ' || *v == '\t') v++;
      if (!*v || *v == '#' || *v == '\n' || *v == '\r') { /* "key:" opens a block */
        if (depth < 64) {
          indent[depth] = ind;
          snprintf(stack[depth], sizeof(stack[depth]), "%.*s", (int)(c - s), s);
          depth++;
        }
      } else {
        char full[256] = "";
        for (int i = 0; i < depth; i++) snprintf(full + strlen(full), sizeof(full) - strlen(full), "%.127s_", stack[i]);
        snprintf(full + strlen(full), sizeof(full) - strlen(full), "%.*s", (int)(c - s), s);
        stop = fn(full, strlen(full), path, lineno, ctx);
      }
    }
  }
  free(line);
  fclose(fp);
}

static int HylcCountFileKey(const char *key, size_t n, const char path[], int lineno, void *ctx)
{
  char where[PETSC_MAX_PATH_LEN + 32];
  snprintf(where, sizeof(where), "%s:%d", path, lineno);
  HylcCountKey((OptionsScan *)ctx, key, n, where);
  return ((OptionsScan *)ctx)->bad;
}

/* the keys of a plain or YAML options file */
static void HylcCountFile(OptionsScan *o, const char path[], int yaml) { HylcWalkFileKeys(path, yaml, HylcCountFileKey, o); }

/* ---- where an option was set ---- */

typedef struct {
  const char *name; /* without its dash */
  char       *where;
  size_t      len;
} OptionSource;

static int HylcSourceKey(const char *key, size_t n, const char path[], int lineno, void *ctx)
{
  OptionSource *o = (OptionSource *)ctx;
  while (n && *key == '-') key++, n--;
  if (n == strlen(o->name) && !strncasecmp(key, o->name, n)) snprintf(o->where, o->len, "%s:%d: ", path, lineno); /* the last one wins */
  return 0;
}

static void HylcSourceFile(const char path[], const char what[], int yaml, void *ctx)
{
  (void)what;
  HylcWalkFileKeys(path, yaml, HylcSourceKey, ctx);
}

/* Where option -name was set: "file:line: " of the options file that sets it last (a YAML "name:", with
   nested keys joined by '_', or a plain "-name"; every options file the program read, nested ones too),
   or "" when the command line sets it or no file does. */
static void HylcOptionSource(const char name[], char where[], size_t len)
{
  int          argc = 0;
  char       **args = NULL;
  OptionSource o    = {name, where, len};

  where[0] = 0;
  while (*name == '-') name++;
  o.name = name;
  if (PetscGetArgs(&argc, &args) || !args) return;
  for (int i = 1; i < argc; i++)
    if (args[i][0] == '-' && !strcasecmp(args[i] + 1, name)) return; /* given on the command line */
  HylcOptionsFilesForEach(argc, args, HylcSourceFile, &o);
}

/* each options file: it must exist and not be a directory, a YAML file must be well formed; its keys
   are counted */
static void HylcScanOptionsFile(const char path[], const char what[], int yaml, void *ctx)
{
  OptionsScan *o = (OptionsScan *)ctx;
  struct stat  st;

  if (o->bad) return;
  if (yaml) {
    if (HylcYAMLCheckFile(path, o->msg, o->len)) {
      o->bad = 1;
      return;
    }
  } else if (stat(path, &st) != 0) {
    snprintf(o->msg, o->len, "Cannot open options file %s (%s): %s", path, what, strerror(errno));
    o->bad = 1;
    return;
  } else if (S_ISDIR(st.st_mode)) {
    snprintf(o->msg, o->len, "Cannot read options file %s (%s): it is a directory", path, what);
    o->bad = 1;
    return;
  }
  HylcCountFile(o, path, yaml);
}

/* Checks every options file the program will read (HylcOptionsFilesForEach(): the command line,
   PETSC_OPTIONS, nested -options_file, petscrc): it must exist and not be a directory, and a YAML file
   must be well formed; and counts the distinct options of all sources against PETSc's limit. Returns 0
   or writes a one-line message and returns 1. */
static int HylcCheckOptionsFiles(int argc, char **argv, char msg[], size_t len)
{
  OptionsScan o;
  char       *env = getenv("PETSC_OPTIONS") ? strdup(getenv("PETSC_OPTIONS")) : NULL, *eargs[1024], *save = NULL, *t;
  int         ne = 0;

  memset(&o, 0, sizeof(o));
  o.msg = msg;
  o.len = len;
  HylcOptionsFilesForEach(argc, argv, HylcScanOptionsFile, &o);
  for (t = env ? strtok_r(env, " \t\r\n", &save) : NULL; t && ne < 1024; t = strtok_r(NULL, " \t\r\n", &save)) eargs[ne++] = t;
  HylcCountArgs(&o, ne, eargs, "PETSC_OPTIONS");
  HylcCountArgs(&o, argc - 1, argv + 1, "the command line");
  free(env);
  for (int i = 0; i < o.nkeys; i++) free(o.keys[i]);
  return o.bad;
}

/*@C
  HylcInitialize - PetscInitialize() for hylc programs, then HylcPushErrorHandler(). Before PETSc
  starts, every options file on the command line (-options_file F, -options_file_yaml F) is checked:
  a missing file, a directory or a malformed YAML file (a .yaml/.yml file outside the subset of YAML that
  option files use: "key: value" lines, comments, "key:" blocks) ends the program with one line
  "hylc: error: file:line: problem" and exit status PETSC_ERR_USER_INPUT (PETSc's own reader would
  report neither file nor line). -version prints HylcVersionView() and ends the program; -help is
  printed sorted, hylc's options before PETSc's (src/sys/help.c). Collective on MPI_COMM_WORLD (as
  PetscInitialize()).
  Programs write:  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
@*/
PetscErrorCode HylcInitialize(int *argc, char ***argv, const char file[], const char help[])
{
  char msg[PETSC_MAX_PATH_LEN + 512];

  if (argc && argv && HylcCheckOptionsFiles(*argc, *argv, msg, sizeof(msg))) {
    if (HylcLaunchRankZero()) {
      fprintf(stderr, "hylc: error: %s\n", msg);
      fflush(stderr);
    }
    exit(PETSC_ERR_USER_INPUT);
  }
  PetscBool version = PETSC_FALSE;
  if (argc && argv) { /* -version: hylc's, not only PETSc's (which PETSc would print and go on) */
    for (int i = 1; i < *argc; i++)
      if (!strcmp((*argv)[i], "-version")) {
        version = PETSC_TRUE;
        for (int j = i; j + 1 < *argc; j++) (*argv)[j] = (*argv)[j + 1];
        (*argc)--;
        i--;
      }
  }
  if (argc && argv && !version) HylcHelpCapture(*argc, *argv);
  PetscCall(PetscInitialize(argc, argv, file, help));
  if (version) {
    PetscErrorCode ierr = HylcVersionView(argc && *argc > 0 ? (*argv)[0] : NULL);
    PetscFinalize();
    exit(ierr ? (int)ierr : 0);
  }
  PetscCall(HylcSetProgramName(argc && argv && *argc > 0 ? (*argv)[0] : NULL));
  PetscCallMPI(MPI_Comm_dup(PETSC_COMM_WORLD, &HylcErrorComm));
  PetscCall(HylcPushErrorHandler());
  return PETSC_SUCCESS;
}
