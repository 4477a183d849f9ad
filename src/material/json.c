/* The ARCSim-HYLC JSON material format (../shared/docs/formats.md §2, docs/material.md):
   - a small strict JSON parser (RFC 8259) building a tree with the line of every value, so that errors
     name the file, the line and the key path (stock1.json:123: coeffs.2D[3].mu: ...);
   - the schema reader (unknown keys are errors);
   - the writer, byte-identical to python's json.dumps(d, indent=2): doubles as Python's repr(). */
#include <hylc/private/materialimpl.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------------------------------------ */
/* Python repr() of doubles                                                                           */
/* ------------------------------------------------------------------------------------------------ */

/* mantissa digits of "%.*e" output: the sign, the digits without the point, the exponent */
static void SplitE(const char *e, int *neg, char digits[24], int *exp10)
{
  int k = 0;

  *neg = (*e == '-');
  if (*e == '-' || *e == '+') e++;
  for (; *e && *e != 'e'; e++)
    if (*e != '.') digits[k++] = *e;
  digits[k] = 0;
  *exp10    = *e ? atoi(e + 1) : 0;
}

/* adds delta (+1 or -1) to the last digit of a digit string; 0 if the number of digits would change */
static int StepDigits(char digits[24], int delta)
{
  int i = (int)strlen(digits) - 1;

  for (; i >= 0; i--) {
    int d = digits[i] - '0' + delta;
    if (d >= 0 && d <= 9) {
      digits[i] = (char)('0' + d);
      break;
    }
    digits[i] = delta > 0 ? '0' : '9';
  }
  return i >= 0 && digits[0] != '0';
}

static double FromDigits(int neg, const char digits[], int exp10)
{
  char s[48];
  snprintf(s, sizeof(s), "%s%c.%se%d", neg ? "-" : "", digits[0], digits + 1, exp10);
  return strtod(s, NULL);
}

const char *HylcFormatDoubleRepr(double x, char buf[32])
{
  char digits[24] = "", e[40];
  int  neg = 0, exp10 = 0, nd, found = 0;

  if (isnan(x)) return strcpy(buf, "NaN");
  if (isinf(x)) return strcpy(buf, x > 0 ? "Infinity" : "-Infinity");
  if (x == 0) return strcpy(buf, signbit(x) ? "-0.0" : "0.0");
  /* the shortest digit string that reads back as x; among those of that length, the closest to x (the
     correctly rounded one, or when that one does not read back, its neighbour that does) */
  for (int p = 1; p <= 17 && !found; p++) {
    snprintf(e, sizeof(e), "%.*e", p - 1, x);
    SplitE(e, &neg, digits, &exp10);
    if (strtod(e, NULL) == x) found = 1;
    for (int delta = -1; delta <= 1 && !found && p < 17; delta += 2) {
      char alt[24];
      strcpy(alt, digits);
      if (StepDigits(alt, delta) && FromDigits(neg, alt, exp10) == x) {
        strcpy(digits, alt);
        found = 1;
      }
    }
  }
  nd = (int)strlen(digits);
  while (nd > 1 && digits[nd - 1] == '0') digits[--nd] = 0;
  {
    char *o = buf;
    if (neg) *o++ = '-';
    if (exp10 < -4 || exp10 >= 16) { /* d[.ddd]e-XX */
      *o++ = digits[0];
      if (nd > 1) {
        *o++ = '.';
        for (int i = 1; i < nd; i++) *o++ = digits[i];
      }
      char ex[16];
      snprintf(ex, sizeof(ex), "e%c%02d", exp10 < 0 ? '-' : '+', exp10 < 0 ? -exp10 : exp10);
      strcpy(o, ex);
    } else if (exp10 < 0) { /* 0.000ddd */
      *o++ = '0';
      *o++ = '.';
      for (int i = 0; i < -exp10 - 1; i++) *o++ = '0';
      for (int i = 0; i < nd; i++) *o++ = digits[i];
      *o = 0;
    } else { /* ddd.ddd, with ".0" for integral values */
      for (int i = 0; i <= exp10; i++) *o++ = i < nd ? digits[i] : '0';
      *o++ = '.';
      if (nd > exp10 + 1)
        for (int i = exp10 + 1; i < nd; i++) *o++ = digits[i];
      else
        *o++ = '0';
      *o = 0;
    }
  }
  return buf;
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
  PetscBool    isint; /* a number written without fraction or exponent */
  double       num;   /* number; bool: 0 or 1 */
  char        *str;   /* string value */
  PetscInt     n, cap;
  struct JVal *items; /* array elements, object member values */
  char       **keys;  /* object member names */
} JVal;

typedef struct {
  const char *name; /* file name for messages */
  MPI_Comm    comm;
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
  for (PetscInt i = 0; i < v->n; i++) {
    JFree(&v->items[i]);
    if (v->keys) PetscFree(v->keys[i]);
  }
  PetscFree(v->items);
  PetscFree(v->keys);
  PetscFree(v->str);
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
static PetscErrorCode Append(JVal *v, JVal **slot)
{
  PetscFunctionBegin;
  if (v->n == v->cap) {
    PetscInt cap = v->cap ? 2 * v->cap : 8;
    PetscCall(PetscRealloc(sizeof(JVal) * (size_t)cap, &v->items));
    if (v->type == JOBJ) PetscCall(PetscRealloc(sizeof(char *) * (size_t)cap, &v->keys));
    v->cap = cap;
  }
  PetscCall(PetscMemzero(&v->items[v->n], sizeof(JVal)));
  if (v->type == JOBJ) v->keys[v->n] = NULL;
  *slot = &v->items[v->n++];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PutUTF8(char *out, size_t *k, unsigned cp)
{
  PetscFunctionBegin;
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
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Hex4(JParser *P, const char *h, unsigned *cp)
{
  PetscFunctionBegin;
  *cp = 0;
  PetscCheck(h + 4 <= P->end, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: incomplete \\u escape in a string", P->name, P->line);
  for (int i = 0; i < 4; i++) {
    const char c = h[i];
    int        d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10
                                                  : (c >= 'A' && c <= 'F')   ? c - 'A' + 10
                                                                             : -1;
    PetscCheck(d >= 0, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: invalid \\u escape in a string (4 hex digits expected)", P->name, P->line);
    *cp = 16 * *cp + (unsigned)d;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a string at P->s (the opening quote); the decoded text (UTF-8) in *out */
static PetscErrorCode ParseString(JParser *P, char **out)
{
  const char *s = P->s + 1;
  size_t      k = 0, cap;
  char       *buf;

  PetscFunctionBegin;
  for (cap = 0; s + cap < P->end && s[cap] != '"'; cap++)
    if (s[cap] == '\\') cap++;
  PetscCall(PetscMalloc1(cap + 8, &buf));
  *out = buf;
  for (;;) {
    PetscCheck(s < P->end, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: unterminated string", P->name, P->line);
    const unsigned char c = (unsigned char)*s;
    if (c == '"') break;
    PetscCheck(c >= 0x20, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: control character (code %d) inside a string (unterminated string?)", P->name, P->line, (int)c);
    if (c != '\\') {
      buf[k++] = (char)c;
      s++;
      continue;
    }
    PetscCheck(s + 1 < P->end, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: unterminated string", P->name, P->line);
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
      PetscCall(Hex4(P, s + 2, &cp));
      s += 4;
      if (cp >= 0xD800 && cp < 0xDC00) { /* high surrogate: a low one must follow */
        unsigned lo;
        PetscCheck(s + 2 < P->end && s[2] == '\\' && s[3] == 'u', P->comm, PETSC_ERR_USER_INPUT, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
        PetscCall(Hex4(P, s + 4, &lo));
        PetscCheck(lo >= 0xDC00 && lo < 0xE000, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
        s += 6;
      } else
        PetscCheck(cp < 0xDC00 || cp >= 0xE000, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
      PetscCall(PutUTF8(buf, &k, cp));
    } break;
    default:
      SETERRQ(P->comm, PETSC_ERR_USER_INPUT, "%s:%d: invalid escape '\\%c' in a string", P->name, P->line, (s[1] >= 32 && s[1] < 127) ? s[1] : '?');
    }
    s += 2;
  }
  buf[k] = 0;
  P->s   = s + 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ParseNumber(JParser *P, JVal *v)
{
  const char *s = P->s, *start = P->s;
  char        tok[400], ex[24];
  size_t      len;
  PetscBool   isint = PETSC_TRUE;

  PetscFunctionBegin;
  if (s < P->end && *s == '-') s++;
  if (s < P->end && *s == '0')
    s++;
  else if (s < P->end && *s >= '1' && *s <= '9')
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  else {
    P->s = start;
    SETERRQ(P->comm, PETSC_ERR_USER_INPUT, "%s:%d: expected a value, found %s (JSON numbers are like -1.5e-3; NaN and Infinity are not allowed)", P->name, P->line, Excerpt(P, ex));
  }
  if (s < P->end && *s == '.') {
    isint = PETSC_FALSE;
    s++;
    PetscCheck(s < P->end && *s >= '0' && *s <= '9', P->comm, PETSC_ERR_USER_INPUT, "%s:%d: malformed number (a digit must follow the decimal point)", P->name, P->line);
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  }
  if (s < P->end && (*s == 'e' || *s == 'E')) {
    isint = PETSC_FALSE;
    s++;
    if (s < P->end && (*s == '+' || *s == '-')) s++;
    PetscCheck(s < P->end && *s >= '0' && *s <= '9', P->comm, PETSC_ERR_USER_INPUT, "%s:%d: malformed number (digits must follow the exponent)", P->name, P->line);
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  }
  len = (size_t)(s - start);
  PetscCheck(len < sizeof(tok), P->comm, PETSC_ERR_USER_INPUT, "%s:%d: number too long (%zu characters)", P->name, P->line, len);
  memcpy(tok, start, len);
  tok[len] = 0;
  errno    = 0;
  v->num   = strtod(tok, NULL);
  PetscCheck(isfinite(v->num), P->comm, PETSC_ERR_USER_INPUT, "%s:%d: number %s is out of the range of doubles", P->name, P->line, tok);
  v->type  = JNUM;
  v->isint = isint;
  P->s     = s;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ParseValue(JParser *P, JVal *v);

static PetscErrorCode ParseContainer(JParser *P, JVal *v)
{
  const char close = *P->s == '{' ? '}' : ']';
  const int  open  = P->line;
  char       ex[24];

  PetscFunctionBegin;
  v->type = close == '}' ? JOBJ : JARR;
  PetscCheck(++P->depth <= JSON_MAX_DEPTH, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: nesting deeper than %d levels", P->name, P->line, JSON_MAX_DEPTH);
  P->s++;
  SkipSpace(P);
  if (P->s < P->end && *P->s == close) {
    P->s++;
    P->depth--;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (;;) {
    JVal *slot = NULL;
    SkipSpace(P);
    PetscCall(Append(v, &slot));
    if (v->type == JOBJ) {
      const char *key;
      PetscCheck(P->s < P->end && *P->s == '"', P->comm, PETSC_ERR_USER_INPUT, "%s:%d: expected a key in double quotes, found %s", P->name, P->line, Excerpt(P, ex));
      PetscCall(ParseString(P, &v->keys[v->n - 1]));
      key = v->keys[v->n - 1];
      for (PetscInt i = 0; i < v->n - 1; i++) PetscCheck(strcmp(v->keys[i], key), P->comm, PETSC_ERR_USER_INPUT, "%s:%d: duplicate key \"%s\" (also at line %d)", P->name, P->line, key, v->items[i].line);
      SkipSpace(P);
      PetscCheck(P->s < P->end && *P->s == ':', P->comm, PETSC_ERR_USER_INPUT, "%s:%d: expected ':' after the key \"%s\", found %s", P->name, P->line, key, Excerpt(P, ex));
      P->s++;
      SkipSpace(P);
    }
    PetscCall(ParseValue(P, slot));
    SkipSpace(P);
    PetscCheck(P->s < P->end, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: end of file inside the %s opened at line %d", P->name, P->line, v->type == JOBJ ? "object" : "array", open);
    if (*P->s == ',') {
      P->s++;
      SkipSpace(P);
      PetscCheck(P->s >= P->end || *P->s != close, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: trailing comma before '%c'", P->name, P->line, close);
      continue;
    }
    PetscCheck(*P->s == close, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: expected ',' or '%c' in the %s opened at line %d, found %s", P->name, P->line, close, v->type == JOBJ ? "object" : "array", open, Excerpt(P, ex));
    P->s++;
    break;
  }
  P->depth--;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ParseValue(JParser *P, JVal *v)
{
  char ex[24];

  PetscFunctionBegin;
  SkipSpace(P);
  v->line = P->line;
  PetscCheck(P->s < P->end, P->comm, PETSC_ERR_USER_INPUT, "%s:%d: unexpected end of file (expected a value)", P->name, P->line);
  switch (*P->s) {
  case '{':
  case '[':
    PetscCall(ParseContainer(P, v));
    break;
  case '"':
    v->type = JSTR;
    PetscCall(ParseString(P, &v->str));
    break;
  case 't':
  case 'f':
  case 'n': {
    const char *lit[3] = {"true", "false", "null"};
    int         w      = *P->s == 't' ? 0 : *P->s == 'f' ? 1
                                                         : 2;
    size_t      l      = strlen(lit[w]);
    PetscCheck((size_t)(P->end - P->s) >= l && !strncmp(P->s, lit[w], l), P->comm, PETSC_ERR_USER_INPUT, "%s:%d: expected a value, found %s", P->name, P->line, Excerpt(P, ex));
    v->type = w == 2 ? JNULL : JBOOL;
    v->num  = w == 0;
    P->s += l;
  } break;
  default:
    PetscCall(ParseNumber(P, v));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* parses a whole document into root (which the caller frees with JFree, also after an error) */
static PetscErrorCode ParseDocument(const char name[], MPI_Comm comm, const char *text, size_t len, JVal *root)
{
  JParser P;
  char    ex[24];

  PetscFunctionBegin;
  P.name  = name;
  P.comm  = comm;
  P.s     = text;
  P.end   = text + len;
  P.line  = 1;
  P.depth = 0;
  SkipSpace(&P);
  PetscCheck(P.s < P.end, comm, PETSC_ERR_USER_INPUT, "%s: empty file (expected a JSON material)", name);
  PetscCall(ParseValue(&P, root));
  SkipSpace(&P);
  PetscCheck(P.s == P.end, comm, PETSC_ERR_USER_INPUT, "%s:%d: unexpected text after the end of the JSON document: %s", name, P.line, Excerpt(&P, ex));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ------------------------------------------------------------------------------------------------ */
/* Schema                                                                                             */
/* ------------------------------------------------------------------------------------------------ */

static JVal *Member(const JVal *obj, const char key[])
{
  for (PetscInt i = 0; i < obj->n; i++)
    if (!strcmp(obj->keys[i], key)) return &obj->items[i];
  return NULL;
}

static PetscErrorCode ExpectType(const HylcMaterialDoc *d, const JVal *v, JType t, const char path[])
{
  PetscFunctionBegin;
  PetscCheck(v->type == t, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: expected %s, got %s", d->name, v->line, path, TypeName(t), TypeName(v->type));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* every key of obj must be one of known[]; every one of required[] must be there */
static PetscErrorCode CheckKeys(const HylcMaterialDoc *d, const JVal *obj, const char path[], const char *const known[], int nknown, const char *const required[], int nrequired)
{
  char list[256] = "";

  PetscFunctionBegin;
  for (int i = 0; i < nknown; i++) {
    PetscCall(PetscStrlcat(list, i ? ", \"" : "\"", sizeof(list)));
    PetscCall(PetscStrlcat(list, known[i], sizeof(list)));
    PetscCall(PetscStrlcat(list, "\"", sizeof(list)));
  }
  for (PetscInt i = 0; i < obj->n; i++) {
    PetscBool ok = PETSC_FALSE;
    for (int j = 0; j < nknown; j++) ok = (PetscBool)(ok || !strcmp(obj->keys[i], known[j]));
    PetscCheck(ok, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s%sunknown key \"%s\" (the keys here are %s)", d->name, obj->items[i].line, path, path[0] ? ": " : "", obj->keys[i], list);
  }
  for (int j = 0; j < nrequired; j++) PetscCheck(Member(obj, required[j]), d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s%smissing key \"%s\"", d->name, obj->line, path, path[0] ? ": " : "", required[j]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* an array of numbers; n < 0: any length; else exactly n (what explains n in the message) */
static PetscErrorCode GetNumbers(const HylcMaterialDoc *d, const JVal *v, const char path[], PetscInt n, const char what[], PetscReal **out, PetscInt *nout)
{
  PetscFunctionBegin;
  PetscCall(ExpectType(d, v, JARR, path));
  PetscCheck(n < 0 || v->n == n, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: expected %" PetscInt_FMT " numbers%s, got %" PetscInt_FMT, d->name, v->line, path, n, what ? what : "", v->n);
  for (PetscInt i = 0; i < v->n; i++) PetscCheck(v->items[i].type == JNUM, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s[%" PetscInt_FMT "]: expected a number, got %s", d->name, v->items[i].line, path, i, TypeName(v->items[i].type));
  if (out) {
    PetscCall(PetscMalloc1(v->n + 1, out));
    for (PetscInt i = 0; i < v->n; i++) (*out)[i] = v->items[i].num;
  }
  if (nout) *nout = v->n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GetKnots(const HylcMaterialDoc *d, const JVal *v, const char path[], PetscReal **out, PetscInt *n)
{
  char b0[32], b1[32];

  PetscFunctionBegin;
  PetscCall(GetNumbers(d, v, path, -1, NULL, NULL, n));
  PetscCheck(*n >= 2, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: a spline needs at least 2 knots, got %" PetscInt_FMT, d->name, v->line, path, *n);
  for (PetscInt i = 1; i < *n; i++)
    PetscCheck(v->items[i].num > v->items[i - 1].num, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s[%" PetscInt_FMT "]: knots must be strictly increasing, but %s <= %s (the knot before)", d->name, v->items[i].line, path, i, HylcFormatDoubleRepr(v->items[i].num, b0),
               HylcFormatDoubleRepr(v->items[i - 1].num, b1));
  for (PetscInt i = 1; i < *n; i++) { /* the evaluator divides by the spacing (docs/material.md, "Range") */
    const double h = v->items[i].num - v->items[i - 1].num;
    PetscCheck(isfinite(h) && isfinite(1 / h), d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s[%" PetscInt_FMT "]: the knot spacing %s - %s %s (a spacing h must have h and 1/h finite)", d->name, v->items[i].line, path, i, HylcFormatDoubleRepr(v->items[i].num, b0), HylcFormatDoubleRepr(v->items[i - 1].num, b1),
               isfinite(h) ? "is too small" : "overflows");
  }
  PetscCall(GetNumbers(d, v, path, -1, NULL, out, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GetInt(const HylcMaterialDoc *d, const JVal *v, const char path[], PetscInt lo, PetscInt hi, const char what[], PetscInt *out)
{
  char b[32];

  PetscFunctionBegin;
  PetscCheck(v->type == JNUM, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: expected an integer, got %s", d->name, v->line, path, TypeName(v->type));
  PetscCheck(v->num == floor(v->num) && v->num >= (double)lo && v->num <= (double)hi, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: expected an integer in %" PetscInt_FMT "..%" PetscInt_FMT "%s, got %s", d->name, v->line, path, lo, hi, what ? what : "", HylcFormatDoubleRepr(v->num, b));
  *out = (PetscInt)v->num;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode GetExt(const HylcMaterialDoc *d, const JVal *obj, const char path[], HylcSplineExt *ext)
{
  const JVal *v = Member(obj, "ext");
  char        p[128];
  PetscInt    e = 0;

  PetscFunctionBegin;
  if (v) {
    snprintf(p, sizeof(p), "%s.ext", path);
    PetscCall(GetInt(d, v, p, 0, 2, " (0 linear, 1 constant, 2 zero extrapolation)", &e));
  }
  *ext = (HylcSplineExt)e;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Read1D(HylcMaterialDoc *d, const JVal *v, const char path[])
{
  static const char *const known[] = {"k", "t", "p", "m", "ext"};
  char                     p[128];
  HylcSpline1D            *s = &d->s1[d->n1];
  PetscInt                 n;

  PetscFunctionBegin;
  PetscCall(ExpectType(d, v, JOBJ, path));
  PetscCall(CheckKeys(d, v, path, known, 5, known, 4));
  snprintf(p, sizeof(p), "%s.k", path);
  PetscCall(GetInt(d, Member(v, "k"), p, 0, HYLC_MATERIAL_N1D - 1, " (0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending)", &s->k));
  PetscCall(GetExt(d, v, path, &s->ext));
  d->n1++; /* owns its arrays from here on */
  snprintf(p, sizeof(p), "%s.t", path);
  PetscCall(GetKnots(d, Member(v, "t"), p, &s->t, &s->n));
  n = s->n;
  snprintf(p, sizeof(p), "%s.p", path);
  PetscCall(GetNumbers(d, Member(v, "p"), p, n, " (one per knot)", &s->p, NULL));
  snprintf(p, sizeof(p), "%s.m", path);
  PetscCall(GetNumbers(d, Member(v, "m"), p, n, " (one per knot)", &s->m, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Read2D(HylcMaterialDoc *d, const JVal *v, const char path[])
{
  static const char *const known[] = {"k0", "k1", "tu", "tv", "p", "mu", "mv", "muv", "ext"};
  static const char *const arr[]   = {"p", "mu", "mv", "muv"};
  char                     p[128], what[64];
  HylcSpline2D            *s = &d->s2[d->n2];
  PetscReal              **dst[4];

  PetscFunctionBegin;
  PetscCall(ExpectType(d, v, JOBJ, path));
  PetscCall(CheckKeys(d, v, path, known, 9, known, 8));
  snprintf(p, sizeof(p), "%s.k0", path);
  PetscCall(GetInt(d, Member(v, "k0"), p, 0, 2, " (the in-plane coordinate: 0 sx, 1 sa, 2 sy)", &s->k0));
  snprintf(p, sizeof(p), "%s.k1", path);
  PetscCall(GetInt(d, Member(v, "k1"), p, 1, 4, NULL, &s->k1));
  PetscCheck(HylcMaterialPairIndex(s->k0, s->k1) >= 0, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: (k0, k1) = (%" PetscInt_FMT ", %" PetscInt_FMT ") is not a term of the model; the pairs are (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4)", d->name, v->line, path, s->k0, s->k1);
  PetscCall(GetExt(d, v, path, &s->ext));
  d->n2++;
  snprintf(p, sizeof(p), "%s.tu", path);
  PetscCall(GetKnots(d, Member(v, "tu"), p, &s->tu, &s->nu));
  snprintf(p, sizeof(p), "%s.tv", path);
  PetscCall(GetKnots(d, Member(v, "tv"), p, &s->tv, &s->nv));
  snprintf(what, sizeof(what), " (len(tu) * len(tv) = %d * %d)", (int)s->nu, (int)s->nv);
  dst[0] = &s->p;
  dst[1] = &s->mu;
  dst[2] = &s->mv;
  dst[3] = &s->muv;
  for (int a = 0; a < 4; a++) {
    snprintf(p, sizeof(p), "%s.%s", path, arr[a]);
    PetscCall(GetNumbers(d, Member(v, arr[a]), p, s->nu * s->nv, what, dst[a], NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadDoc(HylcMaterialDoc *d, const JVal *root)
{
  static const char *const topKnown[]    = {"density", "strain scale", "strain shift", "coeffs"};
  static const char *const topRequired[] = {"density", "strain scale", "coeffs"};
  static const char *const cKnown[]      = {"const", "1D", "2D"};
  const JVal              *v, *coeffs;
  PetscReal               *buf;
  char                     b[32];

  PetscFunctionBegin;
  PetscCall(ExpectType(d, root, JOBJ, "the document"));
  PetscCall(CheckKeys(d, root, "", topKnown, 4, topRequired, 3));
  v = Member(root, "density");
  PetscCheck(v->type == JNUM, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: density: expected a number, got %s", d->name, v->line, TypeName(v->type));
  PetscCheck(v->num >= 0, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: density: the area density must be >= 0 (kg/m^2), got %s", d->name, v->line, HylcFormatDoubleRepr(v->num, b));
  d->density = v->num;
  v          = Member(root, "strain scale");
  PetscCall(GetNumbers(d, v, "strain scale", 5, " (sigma of sx, sa, sy, II00, II11)", NULL, NULL));
  for (int k = 0; k < 5; k++) PetscCheck(v->items[k].num > 0 && isfinite(1 / v->items[k].num), d->comm, PETSC_ERR_USER_INPUT, "%s:%d: strain scale[%d]: must be positive with a finite inverse, got %s", d->name, v->items[k].line, k, HylcFormatDoubleRepr(v->items[k].num, b));
  PetscCall(GetNumbers(d, v, "strain scale", 5, NULL, &buf, NULL));
  for (int k = 0; k < 5; k++) d->scale[k] = buf[k];
  PetscCall(PetscFree(buf));
  if ((v = Member(root, "strain shift"))) {
    PetscCall(GetNumbers(d, v, "strain shift", 5, NULL, NULL, NULL));
    for (int k = 0; k < 5; k++) {
      char p[32];
      snprintf(p, sizeof(p), "strain shift[%d]", k);
      PetscCall(GetInt(d, &v->items[k], p, -1000000, 1000000, NULL, &d->shift[k]));
    }
  }
  coeffs = Member(root, "coeffs");
  PetscCall(ExpectType(d, coeffs, JOBJ, "coeffs"));
  PetscCall(CheckKeys(d, coeffs, "coeffs", cKnown, 3, cKnown, 1));
  v = Member(coeffs, "const");
  PetscCheck(v->type == JNUM, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: coeffs.const: expected a number, got %s", d->name, v->line, TypeName(v->type));
  d->C0 = v->num;
  if ((v = Member(coeffs, "1D"))) {
    PetscCall(ExpectType(d, v, JARR, "coeffs.1D"));
    PetscCheck(v->n <= HYLC_MATERIAL_N1D, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: coeffs.1D: at most %d terms (k = 0..4), got %" PetscInt_FMT, d->name, v->line, HYLC_MATERIAL_N1D, v->n);
    for (PetscInt i = 0; i < v->n; i++) {
      char p[32];
      snprintf(p, sizeof(p), "coeffs.1D[%d]", (int)i);
      PetscCall(Read1D(d, &v->items[i], p));
      for (PetscInt j = 0; j < d->n1 - 1; j++)
        PetscCheck(d->s1[j].k != d->s1[d->n1 - 1].k, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: a second term with k = %" PetscInt_FMT " (the first is coeffs.1D[%" PetscInt_FMT "] at line %d)", d->name, v->items[i].line, p, d->s1[j].k, j, v->items[j].line);
    }
  }
  if ((v = Member(coeffs, "2D"))) {
    PetscCall(ExpectType(d, v, JARR, "coeffs.2D"));
    PetscCheck(v->n <= HYLC_MATERIAL_N2D, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: coeffs.2D: at most %d terms, got %" PetscInt_FMT, d->name, v->line, HYLC_MATERIAL_N2D, v->n);
    for (PetscInt i = 0; i < v->n; i++) {
      char p[32];
      snprintf(p, sizeof(p), "coeffs.2D[%d]", (int)i);
      PetscCall(Read2D(d, &v->items[i], p));
      for (PetscInt j = 0; j < d->n2 - 1; j++)
        PetscCheck(d->s2[j].k0 != d->s2[d->n2 - 1].k0 || d->s2[j].k1 != d->s2[d->n2 - 1].k1, d->comm, PETSC_ERR_USER_INPUT, "%s:%d: %s: a second term with (k0, k1) = (%" PetscInt_FMT ", %" PetscInt_FMT ") (the first is coeffs.2D[%" PetscInt_FMT "] at line %d)", d->name, v->items[i].line, p, d->s2[j].k0,
                   d->s2[j].k1, j, v->items[j].line);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialParseJSON_Private(HylcMaterial m, const char name[], const char *text, size_t len)
{
  JVal            root;
  HylcMaterialDoc d;
  PetscErrorCode  ierr;

  PetscFunctionBegin;
  PetscCall(PetscMemzero(&root, sizeof(root)));
  HylcMaterialDocInit(&d, m, name);
  ierr = ParseDocument(name, d.comm, text, len, &root);
  if (!ierr) ierr = ReadDoc(&d, &root);
  JFree(&root);
  if (ierr) HylcMaterialDocFree(&d);
  PetscCall(ierr);
  PetscCall(HylcMaterialDocInstall(m, &d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ------------------------------------------------------------------------------------------------ */
/* Writer                                                                                             */
/* ------------------------------------------------------------------------------------------------ */

typedef struct {
  char  *buf;
  size_t len, cap;
} Out;

static PetscErrorCode Put(Out *o, const char *s)
{
  size_t l = strlen(s);

  PetscFunctionBegin;
  if (o->len + l + 1 > o->cap) {
    size_t cap = PetscMax(2 * o->cap, o->len + l + 4096);
    PetscCall(PetscRealloc(cap, &o->buf));
    o->cap = cap;
  }
  memcpy(o->buf + o->len, s, l + 1);
  o->len += l;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Indent(Out *o, int level)
{
  char sp[64];
  int  n = PetscMin(2 * level, 62);

  PetscFunctionBegin;
  memset(sp, ' ', (size_t)n);
  sp[n] = 0;
  PetscCall(Put(o, "\n"));
  PetscCall(Put(o, sp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* "key": at the given level (after a newline and indentation); comma: preceded by ',' */
static PetscErrorCode Key(Out *o, int level, const char key[], PetscBool comma)
{
  PetscFunctionBegin;
  if (comma) PetscCall(Put(o, ","));
  PetscCall(Indent(o, level));
  PetscCall(Put(o, "\""));
  PetscCall(Put(o, key));
  PetscCall(Put(o, "\": "));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Real(Out *o, PetscReal v)
{
  char b[32];

  PetscFunctionBegin;
  PetscCall(Put(o, HylcFormatDoubleRepr((double)v, b)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Int(Out *o, PetscInt v)
{
  char b[32];

  PetscFunctionBegin;
  snprintf(b, sizeof(b), "%" PetscInt_FMT, v);
  PetscCall(Put(o, b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* an array value of n reals (or ints, if iv) whose key is at level */
static PetscErrorCode Array(Out *o, int level, PetscInt n, const PetscReal rv[], const PetscInt iv[])
{
  PetscFunctionBegin;
  if (!n) {
    PetscCall(Put(o, "[]"));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(Put(o, "["));
  for (PetscInt i = 0; i < n; i++) {
    if (i) PetscCall(Put(o, ","));
    PetscCall(Indent(o, level + 1));
    if (iv)
      PetscCall(Int(o, iv[i]));
    else
      PetscCall(Real(o, rv[i]));
  }
  PetscCall(Indent(o, level));
  PetscCall(Put(o, "]"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ',\n<indent>"key": [numbers]' of a spline entry (level 4) */
static PetscErrorCode Member4(Out *o, const char key[], PetscInt n, const PetscReal v[])
{
  PetscFunctionBegin;
  PetscCall(Key(o, 4, key, PETSC_TRUE));
  PetscCall(Array(o, 4, n, v, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialFormatJSON_Private(HylcMaterial m, char **text, size_t *len)
{
  Out      o = {NULL, 0, 0};
  PetscInt cnt;

  PetscFunctionBegin;
  PetscCall(Put(&o, "{"));
  PetscCall(Key(&o, 1, "density", PETSC_FALSE));
  PetscCall(Real(&o, m->density));
  PetscCall(Key(&o, 1, "strain scale", PETSC_TRUE));
  PetscCall(Array(&o, 1, 5, m->scale, NULL));
  PetscCall(Key(&o, 1, "strain shift", PETSC_TRUE));
  PetscCall(Array(&o, 1, 5, NULL, m->shift));
  PetscCall(Key(&o, 1, "coeffs", PETSC_TRUE));
  PetscCall(Put(&o, "{"));
  PetscCall(Key(&o, 2, "const", PETSC_FALSE));
  PetscCall(Real(&o, m->C0));
  PetscCall(Key(&o, 2, "1D", PETSC_TRUE));
  cnt = 0;
  for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) cnt += m->has1[k];
  if (!cnt)
    PetscCall(Put(&o, "[]"));
  else {
    PetscCall(Put(&o, "["));
    cnt = 0;
    for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) {
      const HylcSpline1D *s = &m->t1[k];
      if (!m->has1[k]) continue;
      if (cnt++) PetscCall(Put(&o, ","));
      PetscCall(Indent(&o, 3));
      PetscCall(Put(&o, "{"));
      PetscCall(Key(&o, 4, "k", PETSC_FALSE));
      PetscCall(Int(&o, s->k));
      PetscCall(Member4(&o, "t", s->n, s->t));
      PetscCall(Member4(&o, "p", s->n, s->p));
      PetscCall(Member4(&o, "m", s->n, s->m));
      if (s->ext != HYLC_EXT_LINEAR) {
        PetscCall(Key(&o, 4, "ext", PETSC_TRUE));
        PetscCall(Int(&o, (PetscInt)s->ext));
      }
      PetscCall(Indent(&o, 3));
      PetscCall(Put(&o, "}"));
    }
    PetscCall(Indent(&o, 2));
    PetscCall(Put(&o, "]"));
  }
  PetscCall(Key(&o, 2, "2D", PETSC_TRUE));
  cnt = 0;
  for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) cnt += m->has2[q];
  if (!cnt)
    PetscCall(Put(&o, "[]"));
  else {
    PetscCall(Put(&o, "["));
    cnt = 0;
    for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) {
      const HylcSpline2D *s = &m->t2[q];
      const PetscInt      N = s->nu * s->nv;
      if (!m->has2[q]) continue;
      if (cnt++) PetscCall(Put(&o, ","));
      PetscCall(Indent(&o, 3));
      PetscCall(Put(&o, "{"));
      PetscCall(Key(&o, 4, "k0", PETSC_FALSE));
      PetscCall(Int(&o, s->k0));
      PetscCall(Key(&o, 4, "k1", PETSC_TRUE));
      PetscCall(Int(&o, s->k1));
      PetscCall(Member4(&o, "tu", s->nu, s->tu));
      PetscCall(Member4(&o, "tv", s->nv, s->tv));
      PetscCall(Member4(&o, "p", N, s->p));
      PetscCall(Member4(&o, "mu", N, s->mu));
      PetscCall(Member4(&o, "mv", N, s->mv));
      PetscCall(Member4(&o, "muv", N, s->muv));
      if (s->ext != HYLC_EXT_LINEAR) {
        PetscCall(Key(&o, 4, "ext", PETSC_TRUE));
        PetscCall(Int(&o, (PetscInt)s->ext));
      }
      PetscCall(Indent(&o, 3));
      PetscCall(Put(&o, "}"));
    }
    PetscCall(Indent(&o, 2));
    PetscCall(Put(&o, "]"));
  }
  PetscCall(Indent(&o, 1));
  PetscCall(Put(&o, "}"));
  PetscCall(Indent(&o, 0));
  PetscCall(Put(&o, "}"));
  *text = o.buf;
  *len  = o.len;
  PetscFunctionReturn(PETSC_SUCCESS);
}
