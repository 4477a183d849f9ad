/* Concise error reports for user-input errors in hylc programs. */
#include <hylc/sys.h>
#include <hylc/files.h>
#include <unistd.h>
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static int HylcIsSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

static int HylcEndsWith(const char s[], const char suffix[])
{
  size_t n = strlen(s), m = strlen(suffix);
  return n >= m && !strcmp(s + n - m, suffix);
}

/* Where option -name was set: "file:line" of the first options file on the command line that sets it
   (YAML "name:" or plain "-name"), or "" (the command line, or not found). */
static void HylcOptionSource(const char name[], char where[], size_t len)
{
  int    argc = 0;
  char **args = NULL;

  where[0] = 0;
  if (PetscGetArgs(&argc, &args) || !args) return;
  for (int i = 1; i < argc; i++)
    if (args[i][0] == '-' && !strcmp(args[i] + 1, name)) return; /* given on the command line (last wins) */
  for (int i = 1; i + 1 < argc; i++) {
    if (strcmp(args[i], "-options_file") && strcmp(args[i], "-options_file_yaml")) continue;
    const char  *f    = args[i + 1];
    const int    yaml = !strcmp(args[i], "-options_file_yaml") || HylcEndsWith(f, ".yaml") || HylcEndsWith(f, ".yml");
    FILE        *fp   = fopen(f, "r");
    char         line[4096];
    int          lineno = 0, found = 0;
    const size_t n = strlen(name);
    if (!fp) continue;
    while (!found && fgets(line, sizeof(line), fp)) {
      const char *s = line;
      lineno++;
      while (*s == ' ' || *s == '\t') s++;
      if (yaml && !strncmp(s, name, n) && s[n] == ':') found = 1;
      if (!yaml && s[0] == '-' && !strncmp(s + 1, name, n) && (HylcIsSpace(s[n + 1]) || !s[n + 1])) found = 1;
    }
    fclose(fp);
    if (found) {
      snprintf(where, len, "%s:%d: ", f, lineno);
      return;
    }
  }
}

/* The options (up to three, "-a, -b") whose value is x or has x as one comma-separated element. */
static int HylcOptionsWithValue(const char x[], char names[], size_t len, char first[], size_t flen)
{
  char *all = NULL, *tok, *save = NULL, *prev = NULL;
  int   count = 0;

  names[0] = first[0] = 0;
  if (!x || !x[0] || PetscOptionsGetAll(NULL, &all) || !all) return 0;
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    const int isname = tok[0] == '-' && (isalpha((unsigned char)tok[1]) || tok[1] == '_');
    if (isname) {
      prev = tok;
      continue;
    }
    if (!prev) continue;
    /* tok is the value of prev: compare as a whole and element by element */
    int          hit = !strcmp(tok, x);
    const char  *e   = tok;
    const size_t m   = strlen(x);
    while (!hit && e) {
      if (!strncmp(e, x, m) && (e[m] == ',' || e[m] == 0)) hit = 1;
      e = strchr(e, ',');
      if (e) e++;
    }
    if (hit) {
      if (!count) snprintf(first, flen, "%s", prev + 1);
      if (count < 3) {
        if (count) strncat(names, " or ", len - strlen(names) - 1);
        strncat(names, prev, len - strlen(names) - 1);
      }
      count++;
    }
    prev = NULL;
  }
  PetscFree(all);
  return count;
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
  const PetscBool user = (PetscBool)(n == PETSC_ERR_USER_INPUT || n == PETSC_ERR_USER || n == PETSC_ERR_ARG_UNKNOWN_TYPE || n == PETSC_ERR_MISSING_FACTOR || n == PETSC_ERR_FILE_OPEN || n == PETSC_ERR_FILE_READ || n == PETSC_ERR_FILE_WRITE || n == PETSC_ERR_FILE_UNEXPECTED || n == PETSC_ERR_ARG_OUTOFRANGE || n == PETSC_ERR_ARG_WRONG || n == PETSC_ERR_ARG_INCOMP || n == PETSC_ERR_NOT_CONVERGED);
  char            better[PETSC_MAX_PATH_LEN + 512];
  if (!user) return PetscTraceBackErrorHandler(comm, line, fun, file, n, p, mess, NULL);
  if (p == PETSC_ERROR_INITIAL && HylcDescribeOptionError(n, mess, better, sizeof(better))) mess = better;
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

/*@C
  HylcCheckOptionsUsed - Refuses options that nothing has read (misspelt or not for this program), before
  any work is done. Collective.
@*/
PetscErrorCode HylcCheckOptionsUsed(MPI_Comm comm)
{
  PetscInt n = 0, shown = 0;
  char   **names = NULL, **values = NULL, list[1024] = "";

  PetscFunctionBegin;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  /* as many names as fit, then how many more (PETSc 3.18's PetscStrlcat writes past a nearly full buffer) */
  for (PetscInt i = 0; i < n; i++) {
    const size_t used = strlen(list), need = strlen(names[i]) + 2;
    if (used + need + 32 >= sizeof(list)) break;
    snprintf(list + used, sizeof(list) - used, " -%s", names[i]);
    shown++;
  }
  if (shown < n) snprintf(list + strlen(list), sizeof(list) - strlen(list), " and %" PetscInt_FMT " more", n - shown);
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

/* Checks one line-oriented YAML options file against the subset PETSc's option reader understands and
   hylc's configs use: comments, blank lines, "key: value" (a plain scalar, a quoted string closed on
   its line, or a one-line [list]), "key:" opening a block of more indented lines, and "- item" entries.
   Returns 0, or writes "file:line: problem" to msg and returns 1. */
static int HylcCheckYAMLFile(const char path[], char msg[], size_t len)
{
  FILE       *fp;
  char        line[4096];
  int         lineno = 0, depth = 0, indent[64], opened = 0, bad = 0;
  struct stat st;

  if (stat(path, &st) != 0) return snprintf(msg, len, "Cannot open options file %s: %s", path, strerror(errno)), 1;
  if (S_ISDIR(st.st_mode)) return snprintf(msg, len, "Cannot read options file %s: it is a directory", path), 1;
  fp = fopen(path, "r");
  if (!fp) return snprintf(msg, len, "Cannot open options file %s: %s", path, strerror(errno)), 1;
  indent[0] = 0;
  while (!bad && fgets(line, sizeof(line), fp)) {
    char  *s   = line, *key, *colon, *v;
    int    ind = 0;
    size_t n   = strlen(line);
    lineno++;
    if (n == sizeof(line) - 1 && line[n - 1] != '\n') {
      snprintf(msg, len, "%s:%d: line longer than %d characters", path, lineno, (int)sizeof(line) - 2);
      bad = 1;
      break;
    }
    if (memchr(line, 0, n) != NULL || (n && (unsigned char)line[0] == 0)) continue;
    while (*s == ' ') s++, ind++;
    if (*s == '\t') {
      snprintf(msg, len, "%s:%d: a tab in the indentation (YAML allows spaces only)", path, lineno);
      bad = 1;
      break;
    }
    /* strip a comment: '#' at the start or after a blank, outside quotes */
    {
      char q = 0;
      for (char *c = s; *c; c++) {
        if (q) {
          if (*c == q) q = 0;
        } else if (*c == '"' || *c == '\'') {
          if (c == s || HylcIsSpace(c[-1]) || c[-1] == ':' || c[-1] == '[' || c[-1] == ',') q = *c;
        } else if (*c == '#' && (c == s || HylcIsSpace(c[-1]))) {
          *c = 0;
          break;
        }
      }
    }
    n = strlen(s);
    while (n && HylcIsSpace(s[n - 1])) s[--n] = 0;
    if (!n) continue;
    if (!strcmp(s, "---") || !strcmp(s, "...")) continue;
    if (s[0] == '%') continue; /* a directive */
    /* indentation: deeper only right after "key:", shallower only back to an open level */
    if (ind > indent[depth]) {
      if (!opened) {
        snprintf(msg, len, "%s:%d: unexpected indentation ('%s' is indented but the line before is not a 'key:' opening a block)", path, lineno, s);
        bad = 1;
        break;
      }
      if (depth + 1 >= (int)(sizeof(indent) / sizeof(indent[0]))) {
        snprintf(msg, len, "%s:%d: nested too deeply", path, lineno);
        bad = 1;
        break;
      }
      indent[++depth] = ind;
    } else {
      if (opened) {
        snprintf(msg, len, "%s:%d: the block opened by the 'key:' on the line before is empty (give the key a value)", path, lineno - 1);
        bad = 1;
        break;
      }
      while (depth > 0 && ind < indent[depth]) depth--;
      if (ind != indent[depth]) {
        snprintf(msg, len, "%s:%d: inconsistent indentation (%d spaces; the enclosing block uses %d)", path, lineno, ind, indent[depth]);
        bad = 1;
        break;
      }
    }
    opened = 0;
    if (s[0] == '-' && (s[1] == 0 || s[1] == ' ')) continue; /* a sequence entry */
    key   = s;
    colon = NULL;
    for (char *c = s; *c; c++)
      if (*c == ':' && (c[1] == 0 || c[1] == ' ')) {
        colon = c;
        break;
      }
    if (!colon) {
      snprintf(msg, len, "%s:%d: expected 'key: value', found '%s'", path, lineno, s);
      bad = 1;
      break;
    }
    for (char *c = key; c < colon; c++)
      if (!(isalnum((unsigned char)*c) || *c == '_' || *c == '-' || *c == '.')) {
        snprintf(msg, len, "%s:%d: '%.*s' is not an option name (letters, digits, '_' only)", path, lineno, (int)(colon - key), key);
        bad = 1;
        break;
      }
    if (bad) break;
    if (colon == key) {
      snprintf(msg, len, "%s:%d: empty key before ':'", path, lineno);
      bad = 1;
      break;
    }
    v = colon + 1;
    while (*v == ' ') v++;
    if (!*v) {
      opened = 1; /* "key:" opens a block of more indented lines */
      continue;
    }
    if (*v == '"' || *v == '\'') {
      char *e = strchr(v + 1, *v);
      if (!e) {
        snprintf(msg, len, "%s:%d: unclosed quote in the value of '%.*s'", path, lineno, (int)(colon - key), key);
        bad = 1;
      } else if (e[1]) {
        snprintf(msg, len, "%s:%d: text '%s' after the quoted value of '%.*s'", path, lineno, e + 1, (int)(colon - key), key);
        bad = 1;
      }
    } else if (*v == '[' || *v == '{') {
      const char close = *v == '[' ? ']' : '}';
      if (v[strlen(v) - 1] != close) {
        snprintf(msg, len, "%s:%d: unclosed '%c' in the value of '%.*s' (write lists on one line)", path, lineno, *v, (int)(colon - key), key);
        bad = 1;
      }
    } else if (*v == ']' || *v == '}' || *v == '&' || *v == '*' || *v == '!' || *v == '|' || *v == '>' || *v == '@' || *v == '`') {
      snprintf(msg, len, "%s:%d: value '%s' of '%.*s' starts with '%c', which YAML reserves (quote the value)", path, lineno, v, (int)(colon - key), key, *v);
      bad = 1;
    } else {
      for (char *c = v; *c; c++)
        if (*c == ':' && (c[1] == 0 || c[1] == ' ')) {
          snprintf(msg, len, "%s:%d: a second ':' in '%s' (one 'key: value' per line)", path, lineno, s);
          bad = 1;
          break;
        }
    }
  }
  if (!bad && opened) {
    snprintf(msg, len, "%s:%d: the block opened by the last 'key:' is empty (give the key a value)", path, lineno);
    bad = 1;
  }
  if (!bad && ferror(fp)) {
    snprintf(msg, len, "Cannot read options file %s: %s", path, strerror(errno));
    bad = 1;
  }
  fclose(fp);
  return bad;
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

/* the keys of a plain options file (one "-key value" per line) or a YAML one ("key: value", nested keys
   joined with '_' as PETSc does) */
static void HylcCountFile(OptionsScan *o, const char path[], int yaml)
{
  FILE   *fp   = fopen(path, "r");
  char   *line = NULL, where[PETSC_MAX_PATH_LEN + 32];
  size_t  cap  = 0;
  ssize_t len;
  int     lineno = 0, depth = 0, indent[64];
  char    stack[64][128];

  if (!fp) return;
  while (!o->bad && (len = getline(&line, &cap, fp)) >= 0) {
    char *s   = line, *c;
    int   ind = 0;
    lineno++;
    snprintf(where, sizeof(where), "%s:%d", path, lineno);
    if (!yaml) {
      if ((c = strchr(s, '#'))) *c = 0;
      while (HylcIsSpace(*s)) s++;
      c = s;
      while (*c && !HylcIsSpace(*c)) c++;
      if (c > s && *s == '-') {
        char k = *c;
        *c     = 0;
        if (HylcValidKey(s)) HylcCountKey(o, s, strlen(s), where);
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
        HylcCountKey(o, full, strlen(full), where);
      }
    }
  }
  free(line);
  fclose(fp);
}

/* each options file: it must exist and not be a directory, a YAML file must be well formed; its keys
   are counted */
static void HylcScanOptionsFile(const char path[], const char what[], int yaml, void *ctx)
{
  OptionsScan *o = (OptionsScan *)ctx;
  struct stat  st;

  if (o->bad) return;
  if (yaml) {
    if (HylcCheckYAMLFile(path, o->msg, o->len)) {
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
  report neither file nor line). Collective on MPI_COMM_WORLD (as PetscInitialize()).
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
  PetscCall(PetscInitialize(argc, argv, file, help));
  PetscCallMPI(MPI_Comm_dup(PETSC_COMM_WORLD, &HylcErrorComm));
  PetscCall(HylcPushErrorHandler());
  return PETSC_SUCCESS;
}
