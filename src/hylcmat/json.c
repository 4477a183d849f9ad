/* The ARCSim-HYLC JSON material format (../shared/docs/formats.md §2, docs/material.md), reading side:
   - a small strict JSON parser (RFC 8259) building a tree with the line of every value, so that errors
     name the file, the line and the key path (stock1.json:123: coeffs.2D[3].mu: ...);
   - the schema reader (unknown keys are errors); the values are validated by the setters of core.c.
   The writer (byte-identical to python's json.dumps(d, indent=2)) is in src/material/json.c. */
#include "hylcmatimpl.h"
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* strlcat: appends src to dst (size bytes), truncating */
static void StrCat(char *dst, const char *src, size_t size)
{
  size_t l = strlen(dst);
  if (l + 1 < size) snprintf(dst + l, size - l, "%s", src);
}

/* ------------------------------------------------------------------------------------------------ */
/* Parser                                                                                             */
/* ------------------------------------------------------------------------------------------------ */

typedef enum {
  JNULL,
  JBOOL,
  JNUM,
  JSTR,
  JARR,
  JOBJ
} JType;

typedef struct JVal {
  JType        type;
  int          line;
  int          isint; /* a number written without fraction or exponent */
  double       num;   /* number; bool: 0 or 1 */
  char        *str;   /* string value */
  int          n, cap;
  struct JVal *items; /* array elements, object member values */
  char       **keys;  /* object member names */
} JVal;

typedef struct {
  const char *name; /* file name for messages */
  hm_err     *E;
  const char *s, *end;
  int         line, depth;
} JParser;

#define JSON_MAX_DEPTH 64

static const char *TypeName(JType t)
{
  switch (t) {
  case JNULL:
    return "null";
  case JBOOL:
    return "true/false";
  case JNUM:
    return "a number";
  case JSTR:
    return "a string";
  case JARR:
    return "an array";
  case JOBJ:
    return "an object";
  }
  return "?";
}

static void JFree(JVal *v)
{
  if (!v) return;
  for (int i = 0; i < v->n; i++) {
    JFree(&v->items[i]);
    if (v->keys) free(v->keys[i]);
  }
  free(v->items);
  free(v->keys);
  free(v->str);
  v->items = NULL;
  v->keys  = NULL;
  v->str   = NULL;
  v->n = v->cap = 0;
}

static void SkipSpace(JParser *P)
{
  while (P->s < P->end) {
    const char c = *P->s;
    if (c == '\n')
      P->line++;
    else if (c != ' ' && c != '\t' && c != '\r')
      break;
    P->s++;
  }
}

/* a short printable excerpt of the text at s for messages */
static const char *Excerpt(const JParser *P, char buf[24])
{
  size_t k = 0;
  if (P->s >= P->end) return strcpy(buf, "end of file");
  buf[k++] = '\'';
  for (const char *c = P->s; c < P->end && k < 12 && *c != '\n' && *c != '\r'; c++) buf[k++] = (*c >= 32 && *c < 127) ? *c : '?';
  buf[k++] = '\'';
  buf[k]   = 0;
  return buf;
}

/* appends an empty slot to an array or object; returns it (valid until the next append) */
static int Append(JVal *v, JVal **slot)
{
  if (v->n == v->cap) {
    int   cap   = v->cap ? 2 * v->cap : 8;
    JVal *items = realloc(v->items, sizeof(JVal) * (size_t)cap);
    if (!items) return HYLCMAT_ERR_MEMORY;
    v->items = items;
    if (v->type == JOBJ) {
      char **keys = realloc(v->keys, sizeof(char *) * (size_t)cap);
      if (!keys) return HYLCMAT_ERR_MEMORY;
      v->keys = keys;
    }
    v->cap = cap;
  }
  memset(&v->items[v->n], 0, sizeof(JVal));
  if (v->type == JOBJ) v->keys[v->n] = NULL;
  *slot = &v->items[v->n++];
  return HYLCMAT_OK;
}

static int PutUTF8(char *out, size_t *k, unsigned cp)
{
  if (cp < 0x80)
    out[(*k)++] = (char)cp;
  else if (cp < 0x800) {
    out[(*k)++] = (char)(0xC0 | (cp >> 6));
    out[(*k)++] = (char)(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out[(*k)++] = (char)(0xE0 | (cp >> 12));
    out[(*k)++] = (char)(0x80 | ((cp >> 6) & 0x3F));
    out[(*k)++] = (char)(0x80 | (cp & 0x3F));
  } else {
    out[(*k)++] = (char)(0xF0 | (cp >> 18));
    out[(*k)++] = (char)(0x80 | ((cp >> 12) & 0x3F));
    out[(*k)++] = (char)(0x80 | ((cp >> 6) & 0x3F));
    out[(*k)++] = (char)(0x80 | (cp & 0x3F));
  }
  return HYLCMAT_OK;
}

static int Hex4(JParser *P, const char *h, unsigned *cp)
{
  *cp = 0;
  HM_CHECK(h + 4 <= P->end, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: incomplete \\u escape in a string", P->name, P->line);
  for (int i = 0; i < 4; i++) {
    const char c = h[i];
    int        d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10
                                                  : (c >= 'A' && c <= 'F')   ? c - 'A' + 10
                                                                             : -1;
    HM_CHECK(d >= 0, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: invalid \\u escape in a string (4 hex digits expected)", P->name, P->line);
    *cp = 16 * *cp + (unsigned)d;
  }
  return HYLCMAT_OK;
}

/* a string at P->s (the opening quote); the decoded text (UTF-8) in *out */
static int ParseString(JParser *P, char **out)
{
  const char *s = P->s + 1;
  size_t      k = 0, cap;
  char       *buf;

  for (cap = 0; s + cap < P->end && s[cap] != '"'; cap++)
    if (s[cap] == '\\') cap++;
  buf = malloc(cap + 8);
  if (!buf) return hm_fail(P->E, HYLCMAT_ERR_MEMORY, "%s:%d: out of memory", P->name, P->line);
  *out = buf;
  for (;;) {
    HM_CHECK(s < P->end, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: unterminated string", P->name, P->line);
    const unsigned char c = (unsigned char)*s;
    if (c == '"') break;
    HM_CHECK(c >= 0x20, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: control character (code %d) inside a string (unterminated string?)", P->name, P->line, (int)c);
    if (c != '\\') {
      buf[k++] = (char)c;
      s++;
      continue;
    }
    HM_CHECK(s + 1 < P->end, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: unterminated string", P->name, P->line);
    switch (s[1]) {
    case '"':
    case '\\':
    case '/':
      buf[k++] = s[1];
      break;
    case 'b':
      buf[k++] = '\b';
      break;
    case 'f':
      buf[k++] = '\f';
      break;
    case 'n':
      buf[k++] = '\n';
      break;
    case 'r':
      buf[k++] = '\r';
      break;
    case 't':
      buf[k++] = '\t';
      break;
    case 'u': {
      unsigned cp;
      HM_CALL(Hex4(P, s + 2, &cp));
      s += 4;
      if (cp >= 0xD800 && cp < 0xDC00) { /* high surrogate: a low one must follow */
        unsigned lo;
        HM_CHECK(s + 2 < P->end && s[2] == '\\' && s[3] == 'u', P->E, HYLCMAT_ERR_FORMAT, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
        HM_CALL(Hex4(P, s + 4, &lo));
        HM_CHECK(lo >= 0xDC00 && lo < 0xE000, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
        s += 6;
      } else
        HM_CHECK(cp < 0xDC00 || cp >= 0xE000, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
      HM_CALL(PutUTF8(buf, &k, cp));
    } break;
    default:
      return hm_fail(P->E, HYLCMAT_ERR_FORMAT, "%s:%d: invalid escape '\\%c' in a string", P->name, P->line, (s[1] >= 32 && s[1] < 127) ? s[1] : '?');
    }
    s += 2;
  }
  buf[k] = 0;
  P->s   = s + 1;
  return HYLCMAT_OK;
}

static int ParseNumber(JParser *P, JVal *v)
{
  const char *s = P->s, *start = P->s;
  char        tok[400], ex[24];
  size_t      len;
  int         isint = 1;

  if (s < P->end && *s == '-') s++;
  if (s < P->end && *s == '0')
    s++;
  else if (s < P->end && *s >= '1' && *s <= '9')
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  else {
    P->s = start;
    return hm_fail(P->E, HYLCMAT_ERR_FORMAT, "%s:%d: expected a value, found %s (JSON numbers are like -1.5e-3; NaN and Infinity are not allowed)", P->name, P->line, Excerpt(P, ex));
  }
  if (s < P->end && *s == '.') {
    isint = 0;
    s++;
    HM_CHECK(s < P->end && *s >= '0' && *s <= '9', P->E, HYLCMAT_ERR_FORMAT, "%s:%d: malformed number (a digit must follow the decimal point)", P->name, P->line);
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  }
  if (s < P->end && (*s == 'e' || *s == 'E')) {
    isint = 0;
    s++;
    if (s < P->end && (*s == '+' || *s == '-')) s++;
    HM_CHECK(s < P->end && *s >= '0' && *s <= '9', P->E, HYLCMAT_ERR_FORMAT, "%s:%d: malformed number (digits must follow the exponent)", P->name, P->line);
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  }
  len = (size_t)(s - start);
  HM_CHECK(len < sizeof(tok), P->E, HYLCMAT_ERR_FORMAT, "%s:%d: number too long (%zu characters)", P->name, P->line, len);
  memcpy(tok, start, len);
  tok[len] = 0;
  errno    = 0;
  v->num   = strtod(tok, NULL);
  HM_CHECK(isfinite(v->num), P->E, HYLCMAT_ERR_FORMAT, "%s:%d: number %s is out of the range of doubles", P->name, P->line, tok);
  v->type  = JNUM;
  v->isint = isint;
  P->s     = s;
  return HYLCMAT_OK;
}

static int ParseValue(JParser *P, JVal *v);

static int ParseContainer(JParser *P, JVal *v)
{
  const char close = *P->s == '{' ? '}' : ']';
  const int  open  = P->line;
  char       ex[24];

  v->type = close == '}' ? JOBJ : JARR;
  HM_CHECK(++P->depth <= JSON_MAX_DEPTH, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: nesting deeper than %d levels", P->name, P->line, JSON_MAX_DEPTH);
  P->s++;
  SkipSpace(P);
  if (P->s < P->end && *P->s == close) {
    P->s++;
    P->depth--;
    return HYLCMAT_OK;
  }
  for (;;) {
    JVal *slot = NULL;
    SkipSpace(P);
    HM_CALL(Append(v, &slot));
    if (v->type == JOBJ) {
      const char *key;
      HM_CHECK(P->s < P->end && *P->s == '"', P->E, HYLCMAT_ERR_FORMAT, "%s:%d: expected a key in double quotes, found %s", P->name, P->line, Excerpt(P, ex));
      HM_CALL(ParseString(P, &v->keys[v->n - 1]));
      key = v->keys[v->n - 1];
      for (int i = 0; i < v->n - 1; i++) HM_CHECK(strcmp(v->keys[i], key), P->E, HYLCMAT_ERR_FORMAT, "%s:%d: duplicate key \"%s\" (also at line %d)", P->name, P->line, key, v->items[i].line);
      SkipSpace(P);
      HM_CHECK(P->s < P->end && *P->s == ':', P->E, HYLCMAT_ERR_FORMAT, "%s:%d: expected ':' after the key \"%s\", found %s", P->name, P->line, key, Excerpt(P, ex));
      P->s++;
      SkipSpace(P);
    }
    HM_CALL(ParseValue(P, slot));
    SkipSpace(P);
    HM_CHECK(P->s < P->end, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: end of file inside the %s opened at line %d", P->name, P->line, v->type == JOBJ ? "object" : "array", open);
    if (*P->s == ',') {
      P->s++;
      SkipSpace(P);
      HM_CHECK(P->s >= P->end || *P->s != close, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: trailing comma before '%c'", P->name, P->line, close);
      continue;
    }
    HM_CHECK(*P->s == close, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: expected ',' or '%c' in the %s opened at line %d, found %s", P->name, P->line, close, v->type == JOBJ ? "object" : "array", open, Excerpt(P, ex));
    P->s++;
    break;
  }
  P->depth--;
  return HYLCMAT_OK;
}

static int ParseValue(JParser *P, JVal *v)
{
  char ex[24];

  SkipSpace(P);
  v->line = P->line;
  HM_CHECK(P->s < P->end, P->E, HYLCMAT_ERR_FORMAT, "%s:%d: unexpected end of file (expected a value)", P->name, P->line);
  switch (*P->s) {
  case '{':
  case '[':
    HM_CALL(ParseContainer(P, v));
    break;
  case '"':
    v->type = JSTR;
    HM_CALL(ParseString(P, &v->str));
    break;
  case 't':
  case 'f':
  case 'n': {
    const char *lit[3] = {"true", "false", "null"};
    int         w      = *P->s == 't' ? 0 : *P->s == 'f' ? 1
                                                         : 2;
    size_t      l      = strlen(lit[w]);
    HM_CHECK((size_t)(P->end - P->s) >= l && !strncmp(P->s, lit[w], l), P->E, HYLCMAT_ERR_FORMAT, "%s:%d: expected a value, found %s", P->name, P->line, Excerpt(P, ex));
    v->type = w == 2 ? JNULL : JBOOL;
    v->num  = w == 0;
    P->s += l;
  } break;
  default:
    HM_CALL(ParseNumber(P, v));
  }
  return HYLCMAT_OK;
}

/* parses a whole document into root (which the caller frees with JFree, also after an error) */
static int ParseDocument(const char name[], hm_err *E, const char *text, size_t len, JVal *root)
{
  JParser P;
  char    ex[24];

  P.name  = name;
  P.E     = E;
  P.s     = text;
  P.end   = text + len;
  P.line  = 1;
  P.depth = 0;
  SkipSpace(&P);
  HM_CHECK(P.s < P.end, E, HYLCMAT_ERR_FORMAT, "%s: empty file (expected a JSON material)", name);
  HM_CALL(ParseValue(&P, root));
  SkipSpace(&P);
  HM_CHECK(P.s == P.end, E, HYLCMAT_ERR_FORMAT, "%s:%d: unexpected text after the end of the JSON document: %s", name, P.line, Excerpt(&P, ex));
  return HYLCMAT_OK;
}

/* ------------------------------------------------------------------------------------------------ */
/* Schema                                                                                             */
/* ------------------------------------------------------------------------------------------------ */

static JVal *Member(const JVal *obj, const char key[])
{
  for (int i = 0; i < obj->n; i++)
    if (!strcmp(obj->keys[i], key)) return &obj->items[i];
  return NULL;
}

static int ExpectType(const hm_doc *d, const JVal *v, JType t, const char path[])
{
  HM_CHECK(v->type == t, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected %s, got %s", d->name, v->line, path, TypeName(t), TypeName(v->type));
  return HYLCMAT_OK;
}

/* every key of obj must be one of known[]; every one of required[] must be there */
static int CheckKeys(const hm_doc *d, const JVal *obj, const char path[], const char *const known[], int nknown, const char *const required[], int nrequired)
{
  char list[256] = "";

  for (int i = 0; i < nknown; i++) {
    StrCat(list, i ? ", \"" : "\"", sizeof(list));
    StrCat(list, known[i], sizeof(list));
    StrCat(list, "\"", sizeof(list));
  }
  for (int i = 0; i < obj->n; i++) {
    int ok = 0;
    for (int j = 0; j < nknown; j++) ok = (int)(ok || !strcmp(obj->keys[i], known[j]));
    HM_CHECK(ok, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s%sunknown key \"%s\" (the keys here are %s)", d->name, obj->items[i].line, path, path[0] ? ": " : "", obj->keys[i], list);
  }
  for (int j = 0; j < nrequired; j++) HM_CHECK(Member(obj, required[j]), d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s%smissing key \"%s\"", d->name, obj->line, path, path[0] ? ": " : "", required[j]);
  return HYLCMAT_OK;
}

/* an array of numbers; n < 0: any length; else exactly n (what explains n in the message) */
static int GetNumbers(const hm_doc *d, const JVal *v, const char path[], int n, const char what[], double **out, int *nout)
{
  HM_CALL(ExpectType(d, v, JARR, path));
  HM_CHECK(n < 0 || v->n == n, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected %d numbers%s, got %d", d->name, v->line, path, n, what ? what : "", v->n);
  for (int i = 0; i < v->n; i++) HM_CHECK(v->items[i].type == JNUM, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: expected a number, got %s", d->name, v->items[i].line, path, i, TypeName(v->items[i].type));
  if (out) {
    *out = malloc(sizeof(double) * (size_t)(v->n + 1));
    if (!*out) return hm_fail(d->E, HYLCMAT_ERR_MEMORY, "%s:%d: %s: out of memory", d->name, v->line, path);
    for (int i = 0; i < v->n; i++) (*out)[i] = v->items[i].num;
  }
  if (nout) *nout = v->n;
  return HYLCMAT_OK;
}

static int GetKnots(const hm_doc *d, const JVal *v, const char path[], double **out, int *n)
{
  char b0[32], b1[32];

  HM_CALL(GetNumbers(d, v, path, -1, NULL, NULL, n));
  HM_CHECK(*n >= 2, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: a spline needs at least 2 knots, got %d", d->name, v->line, path, *n);
  for (int i = 1; i < *n; i++)
    HM_CHECK(v->items[i].num > v->items[i - 1].num, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: knots must be strictly increasing, but %s <= %s (the knot before)", d->name, v->items[i].line, path, i, hylcmat_format_double(v->items[i].num, b0),
             hylcmat_format_double(v->items[i - 1].num, b1));
  for (int i = 1; i < *n; i++) { /* the evaluator divides by the spacing (docs/material.md, "Range") */
    const double h = v->items[i].num - v->items[i - 1].num;
    HM_CHECK(isfinite(h) && isfinite(1 / h), d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: the knot spacing %s - %s %s (a spacing h must have h and 1/h finite)", d->name, v->items[i].line, path, i, hylcmat_format_double(v->items[i].num, b0), hylcmat_format_double(v->items[i - 1].num, b1),
             isfinite(h) ? "is too small" : "overflows");
  }
  HM_CALL(GetNumbers(d, v, path, -1, NULL, out, NULL));
  return HYLCMAT_OK;
}

static int GetInt(const hm_doc *d, const JVal *v, const char path[], int lo, int hi, const char what[], int *out)
{
  char b[32];

  HM_CHECK(v->type == JNUM, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected an integer, got %s", d->name, v->line, path, TypeName(v->type));
  HM_CHECK(v->num == floor(v->num) && v->num >= (double)lo && v->num <= (double)hi, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected an integer in %d..%d%s, got %s", d->name, v->line, path, lo, hi, what ? what : "", hylcmat_format_double(v->num, b));
  *out = (int)v->num;
  return HYLCMAT_OK;
}

static int GetExt(const hm_doc *d, const JVal *obj, const char path[], int *ext)
{
  const JVal *v = Member(obj, "ext");
  char        p[128];
  int         e = 0;

  if (v) {
    snprintf(p, sizeof(p), "%s.ext", path);
    HM_CALL(GetInt(d, v, p, 0, 2, " (0 linear, 1 constant, 2 zero extrapolation)", &e));
  }
  *ext = (int)e;
  return HYLCMAT_OK;
}

static int Read1D(hm_doc *d, const JVal *v, const char path[])
{
  static const char *const known[] = {"k", "t", "p", "m", "ext"};
  char                     p[128];
  hylcmat_term1d          *s = &d->s1[d->n1];
  int                      n;

  HM_CALL(ExpectType(d, v, JOBJ, path));
  HM_CALL(CheckKeys(d, v, path, known, 5, known, 4));
  snprintf(p, sizeof(p), "%s.k", path);
  HM_CALL(GetInt(d, Member(v, "k"), p, 0, HYLCMAT_N1D - 1, " (0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending)", &s->k));
  HM_CALL(GetExt(d, v, path, &s->ext));
  d->n1++; /* owns its arrays from here on */
  snprintf(p, sizeof(p), "%s.t", path);
  HM_CALL(GetKnots(d, Member(v, "t"), p, (double **)&s->t, &s->n));
  n = s->n;
  snprintf(p, sizeof(p), "%s.p", path);
  HM_CALL(GetNumbers(d, Member(v, "p"), p, n, " (one per knot)", (double **)&s->p, NULL));
  snprintf(p, sizeof(p), "%s.m", path);
  HM_CALL(GetNumbers(d, Member(v, "m"), p, n, " (one per knot)", (double **)&s->m, NULL));
  return HYLCMAT_OK;
}

static int Read2D(hm_doc *d, const JVal *v, const char path[])
{
  static const char *const known[] = {"k0", "k1", "tu", "tv", "p", "mu", "mv", "muv", "ext"};
  static const char *const arr[]   = {"p", "mu", "mv", "muv"};
  char                     p[128], what[64];
  hylcmat_term2d          *s = &d->s2[d->n2];
  double                 **dst[4];

  HM_CALL(ExpectType(d, v, JOBJ, path));
  HM_CALL(CheckKeys(d, v, path, known, 9, known, 8));
  snprintf(p, sizeof(p), "%s.k0", path);
  HM_CALL(GetInt(d, Member(v, "k0"), p, 0, 2, " (the in-plane coordinate: 0 sx, 1 sa, 2 sy)", &s->k0));
  snprintf(p, sizeof(p), "%s.k1", path);
  HM_CALL(GetInt(d, Member(v, "k1"), p, 1, 4, NULL, &s->k1));
  HM_CHECK(hylcmat_pair_index(s->k0, s->k1) >= 0, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: (k0, k1) = (%d, %d) is not a term of the model; the pairs are (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4)", d->name, v->line, path, s->k0, s->k1);
  HM_CALL(GetExt(d, v, path, &s->ext));
  d->n2++;
  snprintf(p, sizeof(p), "%s.tu", path);
  HM_CALL(GetKnots(d, Member(v, "tu"), p, (double **)&s->tu, &s->nu));
  snprintf(p, sizeof(p), "%s.tv", path);
  HM_CALL(GetKnots(d, Member(v, "tv"), p, (double **)&s->tv, &s->nv));
  snprintf(what, sizeof(what), " (len(tu) * len(tv) = %d * %d)", (int)s->nu, (int)s->nv);
  dst[0] = (double **)&s->p;
  dst[1] = (double **)&s->mu;
  dst[2] = (double **)&s->mv;
  dst[3] = (double **)&s->muv;
  for (int a = 0; a < 4; a++) {
    snprintf(p, sizeof(p), "%s.%s", path, arr[a]);
    HM_CALL(GetNumbers(d, Member(v, arr[a]), p, s->nu * s->nv, what, dst[a], NULL));
  }
  return HYLCMAT_OK;
}

static int ReadDoc(hm_doc *d, const JVal *root)
{
  static const char *const topKnown[]    = {"density", "strain scale", "strain shift", "coeffs"};
  static const char *const topRequired[] = {"density", "strain scale", "coeffs"};
  static const char *const cKnown[]      = {"const", "1D", "2D"};
  const JVal              *v, *coeffs;
  double                  *buf;
  char                     b[32];

  HM_CALL(ExpectType(d, root, JOBJ, "the document"));
  HM_CALL(CheckKeys(d, root, "", topKnown, 4, topRequired, 3));
  v = Member(root, "density");
  HM_CHECK(v->type == JNUM, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: density: expected a number, got %s", d->name, v->line, TypeName(v->type));
  HM_CHECK(v->num >= 0, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: density: the area density must be >= 0 (kg/m^2), got %s", d->name, v->line, hylcmat_format_double(v->num, b));
  d->density = v->num;
  v          = Member(root, "strain scale");
  HM_CALL(GetNumbers(d, v, "strain scale", 5, " (sigma of sx, sa, sy, II00, II11)", NULL, NULL));
  for (int k = 0; k < 5; k++) HM_CHECK(v->items[k].num > 0 && isfinite(1 / v->items[k].num), d->E, HYLCMAT_ERR_FORMAT, "%s:%d: strain scale[%d]: must be positive with a finite inverse, got %s", d->name, v->items[k].line, k, hylcmat_format_double(v->items[k].num, b));
  HM_CALL(GetNumbers(d, v, "strain scale", 5, NULL, &buf, NULL));
  for (int k = 0; k < 5; k++) d->scale[k] = buf[k];
  free(buf);
  if ((v = Member(root, "strain shift"))) {
    HM_CALL(GetNumbers(d, v, "strain shift", 5, NULL, NULL, NULL));
    for (int k = 0; k < 5; k++) {
      char p[32];
      snprintf(p, sizeof(p), "strain shift[%d]", k);
      HM_CALL(GetInt(d, &v->items[k], p, -1000000, 1000000, NULL, &d->shift[k]));
    }
  }
  coeffs = Member(root, "coeffs");
  HM_CALL(ExpectType(d, coeffs, JOBJ, "coeffs"));
  HM_CALL(CheckKeys(d, coeffs, "coeffs", cKnown, 3, cKnown, 1));
  v = Member(coeffs, "const");
  HM_CHECK(v->type == JNUM, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: coeffs.const: expected a number, got %s", d->name, v->line, TypeName(v->type));
  d->C0 = v->num;
  if ((v = Member(coeffs, "1D"))) {
    HM_CALL(ExpectType(d, v, JARR, "coeffs.1D"));
    HM_CHECK(v->n <= HYLCMAT_N1D, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: coeffs.1D: at most %d terms (k = 0..4), got %d", d->name, v->line, HYLCMAT_N1D, v->n);
    for (int i = 0; i < v->n; i++) {
      char p[32];
      snprintf(p, sizeof(p), "coeffs.1D[%d]", (int)i);
      HM_CALL(Read1D(d, &v->items[i], p));
      for (int j = 0; j < d->n1 - 1; j++)
        HM_CHECK(d->s1[j].k != d->s1[d->n1 - 1].k, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: a second term with k = %d (the first is coeffs.1D[%d] at line %d)", d->name, v->items[i].line, p, d->s1[j].k, j, v->items[j].line);
    }
  }
  if ((v = Member(coeffs, "2D"))) {
    HM_CALL(ExpectType(d, v, JARR, "coeffs.2D"));
    HM_CHECK(v->n <= HYLCMAT_N2D, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: coeffs.2D: at most %d terms, got %d", d->name, v->line, HYLCMAT_N2D, v->n);
    for (int i = 0; i < v->n; i++) {
      char p[32];
      snprintf(p, sizeof(p), "coeffs.2D[%d]", (int)i);
      HM_CALL(Read2D(d, &v->items[i], p));
      for (int j = 0; j < d->n2 - 1; j++)
        HM_CHECK(d->s2[j].k0 != d->s2[d->n2 - 1].k0 || d->s2[j].k1 != d->s2[d->n2 - 1].k1, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: a second term with (k0, k1) = (%d, %d) (the first is coeffs.2D[%d] at line %d)", d->name, v->items[i].line, p, d->s2[j].k0,
                 d->s2[j].k1, j, v->items[j].line);
    }
  }
  return HYLCMAT_OK;
}

int hm_parse_json(const char *name, const char *text, size_t len, hm_err *E, hylcmat **m)
{
  JVal   root;
  hm_doc d;
  int    ierr;

  memset(&root, 0, sizeof(root));
  hm_doc_init(&d, name, E);
  ierr = ParseDocument(name, E, text, len, &root);
  if (!ierr) ierr = ReadDoc(&d, &root);
  JFree(&root);
  if (ierr == HYLCMAT_ERR_MEMORY) hm_fail(E, ierr, "%s: out of memory", name);
  if (ierr) {
    hm_doc_free(&d);
    return ierr;
  }
  return hm_doc_install(&d, m);
}
