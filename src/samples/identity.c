/* The identity of a sampling run (include/hylc/samples.h, docs/output-format.md): a canonical text of
   everything that can change a sample's result -- the versions, the pattern bit for bit and every
   option of PETSc's database but a short list that cannot change a result -- and its SHA-256 digest.
   The journal stores it (a resume of another run is refused, naming the differences) and the HDF5 file
   records it under /provenance. */
#include <hylc/samples.h>
#include <hylc/sha256.h>
#include <petsc/private/petscimpl.h>
#include <ctype.h>
#include <stdarg.h>
#include <string.h>
#include <strings.h>

#if !defined(HYLC_BUILD_ID)
#  define HYLC_BUILD_ID "unknown"
#endif

/* Options that cannot change a sample's result (names without the dash; '*' at the end: any suffix).
   Keep in step with docs/output-format.md. */
static const char *const Neutral[] = {/* output paths */
                                      "sampler_output", "sampler_export_raw", "reference_output",
                                      /* how the job runs, not what it computes */
                                      "sampler_resume", "sampler_overwrite", "sampler_progress", "sampler_batch", "sampler_density",
                                      /* inputs whose content is in the identity (the pattern digests; the options it holds) */
                                      "pattern_file", "options_file*",
                                      /* diagnostics, logging, debugging */
                                      "help", "h", "version", "info*", "log_*", "malloc*", "memory_view", "options_left", "options_monitor*", "options_view", "hylc_traceback", "no_signal_handler", "on_error_*", "start_in_debugger",
                                      "stop_for_debugger", "debugger_*", "display", "petsc_sleep", NULL};

/*@C
  HylcSamplesOptionIsNeutral - Whether an option (name with or without the leading dash) is one of the
  options that cannot change a sample's result and are left out of the run identity: output paths,
  -sampler_resume/-sampler_overwrite/-sampler_progress/-sampler_batch/-sampler_density, -pattern_file
  and -options_file (their contents are in the identity), monitors, views, logging and debugging
  options (any name containing "_monitor", "_view" or "converged_reason"). Not collective.
@*/
PetscBool HylcSamplesOptionIsNeutral(const char name[])
{
  while (*name == '-') name++;
  if (strstr(name, "_monitor") || strstr(name, "_view") || strstr(name, "converged_reason")) return PETSC_TRUE;
  for (int i = 0; Neutral[i]; i++) {
    size_t n = strlen(Neutral[i]);
    if (Neutral[i][n - 1] == '*') {
      if (!strncasecmp(name, Neutral[i], n - 1)) return PETSC_TRUE;
    } else if (!strcasecmp(name, Neutral[i]))
      return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* a token of PetscOptionsGetAll that starts an option: "-" or "--" and a letter, and not a number such
   as -inf or -nan */
static PetscBool IsKey(const char *t)
{
  if (t[0] != '-') return PETSC_FALSE;
  if (t[1] == '-') t++;
  if (!isalpha((unsigned char)t[1])) return PETSC_FALSE;
  if (!strcasecmp(t + 1, "inf") || !strcasecmp(t + 1, "infinity") || !strcasecmp(t + 1, "nan")) return PETSC_FALSE;
  return PETSC_TRUE;
}

typedef struct {
  char *name, *value;
} Opt;

static int CmpOpt(const void *a, const void *b) { return strcmp(((const Opt *)a)->name, ((const Opt *)b)->name); }

/* appends to a growing string */
typedef struct {
  char  *s;
  size_t n, cap;
} Buf;

static PetscErrorCode BufAdd(Buf *b, const char *fmt, ...)
{
  va_list ap;
  int     k;

  PetscFunctionBegin;
  for (;;) {
    va_start(ap, fmt);
    k = vsnprintf(b->s ? b->s + b->n : NULL, b->s ? b->cap - b->n : 0, fmt, ap);
    va_end(ap);
    PetscCheck(k >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "vsnprintf failed");
    if (b->s && b->n + (size_t)k < b->cap) break;
    {
      size_t cap = 2 * (b->cap + (size_t)k) + 256;
      char  *s;
      PetscCall(PetscMalloc1(cap, &s));
      if (b->s) memcpy(s, b->s, b->n);
      s[b->n] = 0;
      PetscCall(PetscFree(b->s));
      b->s   = s;
      b->cap = cap;
    }
  }
  b->n += (size_t)k;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AddArray(Buf *b, const char name[], const void *data, size_t bytes)
{
  char hex[65];

  PetscFunctionBegin;
  HylcSha256Hex(data, bytes, hex);
  PetscCall(BufAdd(b, "pattern %s sha256:%s\n", name, hex));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesIdentity - The canonical identity text of a run on 'pattern' with the options of the global
  database: lines "format identity 1", "version hylc|build|petsc <v>", "pattern <field> <value or
  sha256:digest>" for every field of HylcPatternData (arrays bit for bit in their native layout),
  and "option -<name> <value>" for every option but the neutral ones (HylcSamplesOptionIsNeutral),
  sorted by name. Free with PetscFree. Not collective.
@*/
PetscErrorCode HylcSamplesIdentity(HylcPattern pattern, char **text)
{
  HylcPatternData d;
  Buf             b   = {NULL, 0, 0};
  char           *all = NULL, *tok, *save = NULL;
  Opt            *opts;
  PetscInt        nopt = 0, cap = 16;
  size_t          nv;

  PetscFunctionBegin;
  PetscValidPointer(text, 2);
  PetscCall(BufAdd(&b, "format identity 1\n"));
  PetscCall(BufAdd(&b, "version hylc %s\nversion build %s\nversion petsc %d.%d.%d\n", HYLC_VERSION_STRING, HYLC_BUILD_ID, PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR, PETSC_VERSION_SUBMINOR));
  if (pattern) {
    PetscCall(HylcPatternGetData(pattern, &d));
    nv = (size_t)d.nv;
    PetscCall(BufAdd(&b, "pattern nv %lld\npattern px %.17g\npattern py %.17g\npattern radius %.17g\n", (long long)d.nv, (double)d.px, (double)d.py, (double)d.radius));
    PetscCall(AddArray(&b, "X", d.X, 3 * nv * sizeof(PetscReal)));
    PetscCall(AddArray(&b, "theta", d.theta, nv * sizeof(PetscReal)));
    PetscCall(AddArray(&b, "next", d.next, nv * sizeof(PetscInt)));
    PetscCall(AddArray(&b, "prev", d.prev, nv * sizeof(PetscInt)));
    PetscCall(AddArray(&b, "shift", d.shift, 2 * nv * sizeof(PetscInt)));
    PetscCall(AddArray(&b, "rest_length", d.restLength, nv * sizeof(PetscReal)));
    PetscCall(AddArray(&b, "rest_kappa", d.restKappa, 2 * nv * sizeof(PetscReal)));
    PetscCall(AddArray(&b, "rest_twist", d.restTwist, nv * sizeof(PetscReal)));
    PetscCall(AddArray(&b, "ref_d1", d.refD1, 3 * nv * sizeof(PetscReal)));
    PetscCall(AddArray(&b, "ref_twist", d.refTwist, nv * sizeof(PetscReal)));
  }
  /* the options: PetscOptionsGetAll gives " -name value ..." (a value may hold spaces) */
  PetscCall(PetscOptionsGetAll(NULL, &all));
  PetscCall(PetscMalloc1(cap, &opts));
  for (tok = strtok_r(all, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
    if (IsKey(tok)) {
      if (nopt == cap) {
        Opt *o;
        PetscCall(PetscMalloc1(2 * cap, &o));
        PetscCall(PetscArraycpy(o, opts, cap));
        PetscCall(PetscFree(opts));
        opts = o;
        cap *= 2;
      }
      opts[nopt].name  = tok;
      opts[nopt].value = NULL;
      nopt++;
    } else if (nopt) { /* a value, or a further word of it */
      if (!opts[nopt - 1].value)
        opts[nopt - 1].value = tok;
      else
        for (char *c = opts[nopt - 1].value; c < tok; c++)
          if (!*c) *c = ' '; /* rejoin "x y": the words are adjacent in 'all' */
    }
  }
  qsort(opts, (size_t)nopt, sizeof(Opt), CmpOpt);
  for (PetscInt i = 0; i < nopt; i++) {
    if (HylcSamplesOptionIsNeutral(opts[i].name)) continue;
    PetscCall(BufAdd(&b, "option %s%s%s\n", opts[i].name, opts[i].value ? " " : "", opts[i].value ? opts[i].value : ""));
  }
  PetscCall(PetscFree(opts));
  PetscCall(PetscFree(all));
  *text = b.s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesIdentityDigest - SHA-256 of an identity text, as 64 hexadecimal digits. Not collective.
@*/
void HylcSamplesIdentityDigest(const char text[], char hex[65]) { HylcSha256Hex(text, strlen(text), hex); }

/* the line of 'text' whose first two words are those of 'line' (key), or NULL; *vlen, *v: its value */
static const char *FindKey(const char *text, const char *key, size_t klen)
{
  for (const char *l = text; l && *l; l = strchr(l, '\n'), l = l ? l + 1 : NULL) {
    if (!strncmp(l, key, klen) && (l[klen] == ' ' || l[klen] == '\n' || l[klen] == 0)) return l;
  }
  return NULL;
}

/* the key of a line: its first two words ("option -micro_rtol") */
static size_t KeyLength(const char *l)
{
  const char *sp = strchr(l, ' '), *nl = strchr(l, '\n');
  size_t      end = nl ? (size_t)(nl - l) : strlen(l);
  if (!sp || (size_t)(sp - l) >= end) return end;
  sp = strchr(sp + 1, ' ');
  return sp && (size_t)(sp - l) < end ? (size_t)(sp - l) : end;
}

/* the value of a line (after its key) as "%.*s" */
static void Value(const char *l, size_t klen, const char **v, int *vlen)
{
  const char *nl  = strchr(l, '\n');
  size_t      end = nl ? (size_t)(nl - l) : strlen(l);
  *v              = l + klen + (klen < end ? 1 : 0);
  *vlen           = (int)(end - (size_t)(*v - l));
}

static PetscErrorCode AddDiff(Buf *b, int *nitem, const char *l, size_t klen, const char *how, const char *v0, int n0, const char *v1, int n1)
{
  const int maxItems = 8;

  PetscFunctionBegin;
  (*nitem)++;
  if (*nitem > maxItems) PetscFunctionReturn(PETSC_SUCCESS);
  if (*nitem > 1) PetscCall(BufAdd(b, "; "));
  if (!strncmp(l, "pattern ", 8) && !strcmp(how, "changed")) {
    if (!strncmp(v0, "sha256:", 7) || !strncmp(v1, "sha256:", 7))
      PetscCall(BufAdd(b, "pattern field %.*s differs", (int)klen - 8, l + 8));
    else
      PetscCall(BufAdd(b, "pattern field %.*s differs (%.*s, now %.*s)", (int)klen - 8, l + 8, n0, v0, n1, v1));
  } else if (!strcmp(how, "changed"))
    PetscCall(BufAdd(b, "%.*s changed from '%.*s' to '%.*s'", (int)klen, l, n0, v0, n1, v1));
  else if (!strcmp(how, "added"))
    PetscCall(BufAdd(b, "%.*s added%s%.*s%s", (int)klen, l, n1 ? " ('" : "", n1, v1, n1 ? "')" : ""));
  else
    PetscCall(BufAdd(b, "%.*s removed%s%.*s%s", (int)klen, l, n0 ? " (was '" : "", n0, v0, n0 ? "')" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesIdentityDiff - A short description of how identity text 'now' differs from 'was': items
  "option -x added ('v')", "option -x removed (was 'v')", "option -x changed from 'a' to 'b'",
  "pattern field X differs", "version build changed from ...", separated by "; " (at most 8, then "and N
  more"). Empty when the texts hold the same lines. Free with PetscFree. Not collective.
@*/
PetscErrorCode HylcSamplesIdentityDiff(const char was[], const char now[], char **diff)
{
  Buf b     = {NULL, 0, 0};
  int nitem = 0;

  PetscFunctionBegin;
  PetscCall(BufAdd(&b, "%s", ""));
  for (int pass = 0; pass < 2; pass++) { /* pass 0: lines of 'now' (added, changed); 1: lines only in 'was' */
    const char *src = pass ? was : now, *other = pass ? now : was;
    for (const char *l = src; l && *l; l = strchr(l, '\n'), l = l ? l + 1 : NULL) {
      size_t      klen = KeyLength(l);
      const char *o, *v, *ov;
      int         n, on;
      if (!klen) continue;
      o = FindKey(other, l, klen);
      Value(l, klen, &v, &n);
      if (!o) {
        if (pass)
          PetscCall(AddDiff(&b, &nitem, l, klen, "removed", v, n, "", 0));
        else
          PetscCall(AddDiff(&b, &nitem, l, klen, "added", "", 0, v, n));
      } else if (!pass) {
        Value(o, klen, &ov, &on);
        if (on != n || strncmp(ov, v, (size_t)n)) PetscCall(AddDiff(&b, &nitem, l, klen, "changed", ov, on, v, n));
      }
    }
  }
  if (nitem > 8) PetscCall(BufAdd(&b, "; and %d more", nitem - 8));
  *diff = b.s;
  PetscFunctionReturn(PETSC_SUCCESS);
}
