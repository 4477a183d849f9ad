/* A small strict JSON reader (RFC 8259; include/hylc/private/json.h): a tree with the line of every value,
   so that errors name the file and the line; and Python's repr() of doubles for the JSON writers. Plain
   C99, no PETSc: compiled into libhylc and into libhylcmat (the material schema is src/hylcmat/json.c). */
#include <hylc/private/json.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------------------------------------ */
/* Parser                                                                                             */
/* ------------------------------------------------------------------------------------------------ */

typedef struct {
  const char *name; /* file name for messages */
  char       *err;  /* the message buffer (may be NULL) */
  size_t      errlen;
  const char *s, *end;
  int         line, depth;
} JParser;

/* formats the message into P's buffer and returns code */
static int Fail(const JParser *P, int code, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static int Fail(const JParser *P, int code, const char *fmt, ...)
{
  if (P->err && P->errlen) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(P->err, P->errlen, fmt, ap);
    va_end(ap);
  }
  return code;
}

#define CHECK(cond, ...)                                            \
  do {                                                              \
    if (!(cond)) return Fail(P, HYLC_JSON_ERR_SYNTAX, __VA_ARGS__); \
  } while (0)
#define CALL(x)         \
  do {                  \
    const int r_ = (x); \
    if (r_) return r_;  \
  } while (0)

#define JSON_MAX_DEPTH 64

const char *HylcJsonTypeName(HylcJsonType t)
{
  switch (t) {
  case HYLC_JSON_NULL:
    return "null";
  case HYLC_JSON_BOOL:
    return "true/false";
  case HYLC_JSON_NUMBER:
    return "a number";
  case HYLC_JSON_STRING:
    return "a string";
  case HYLC_JSON_ARRAY:
    return "an array";
  case HYLC_JSON_OBJECT:
    return "an object";
  }
  return "?";
}

void HylcJsonFree(HylcJson *v)
{
  if (!v) return;
  for (int i = 0; i < v->n; i++) {
    HylcJsonFree(&v->items[i]);
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
static int Append(HylcJson *v, HylcJson **slot)
{
  if (v->n == v->cap) {
    int       cap   = v->cap ? 2 * v->cap : 8;
    HylcJson *items = realloc(v->items, sizeof(HylcJson) * (size_t)cap);
    if (!items) return HYLC_JSON_ERR_MEMORY;
    v->items = items;
    if (v->type == HYLC_JSON_OBJECT) {
      char **keys = realloc(v->keys, sizeof(char *) * (size_t)cap);
      if (!keys) return HYLC_JSON_ERR_MEMORY;
      v->keys = keys;
    }
    v->cap = cap;
  }
  memset(&v->items[v->n], 0, sizeof(HylcJson));
  if (v->type == HYLC_JSON_OBJECT) v->keys[v->n] = NULL;
  *slot = &v->items[v->n++];
  return HYLC_JSON_OK;
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
  return HYLC_JSON_OK;
}

static int Hex4(JParser *P, const char *h, unsigned *cp)
{
  *cp = 0;
  CHECK(h + 4 <= P->end, "%s:%d: incomplete \\u escape in a string", P->name, P->line);
  for (int i = 0; i < 4; i++) {
    const char c = h[i];
    int        d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'a' && c <= 'f') ? c - 'a' + 10 : (c >= 'A' && c <= 'F') ? c - 'A' + 10 : -1;
    CHECK(d >= 0, "%s:%d: invalid \\u escape in a string (4 hex digits expected)", P->name, P->line);
    *cp = 16 * *cp + (unsigned)d;
  }
  return HYLC_JSON_OK;
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
  if (!buf) return Fail(P, HYLC_JSON_ERR_MEMORY, "%s:%d: out of memory", P->name, P->line);
  *out = buf;
  for (;;) {
    CHECK(s < P->end, "%s:%d: unterminated string", P->name, P->line);
    const unsigned char c = (unsigned char)*s;
    if (c == '"') break;
    CHECK(c >= 0x20, "%s:%d: control character (code %d) inside a string (unterminated string?)", P->name, P->line, (int)c);
    if (c != '\\') {
      buf[k++] = (char)c;
      s++;
      continue;
    }
    CHECK(s + 1 < P->end, "%s:%d: unterminated string", P->name, P->line);
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
      CALL(Hex4(P, s + 2, &cp));
      s += 4;
      if (cp >= 0xD800 && cp < 0xDC00) { /* high surrogate: a low one must follow */
        unsigned lo;
        CHECK(s + 2 < P->end && s[2] == '\\' && s[3] == 'u', "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
        CALL(Hex4(P, s + 4, &lo));
        CHECK(lo >= 0xDC00 && lo < 0xE000, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
        s += 6;
      } else
        CHECK(cp < 0xDC00 || cp >= 0xE000, "%s:%d: unpaired UTF-16 surrogate in a \\u escape", P->name, P->line);
      CALL(PutUTF8(buf, &k, cp));
    } break;
    default:
      return Fail(P, HYLC_JSON_ERR_SYNTAX, "%s:%d: invalid escape '\\%c' in a string", P->name, P->line, (s[1] >= 32 && s[1] < 127) ? s[1] : '?');
    }
    s += 2;
  }
  buf[k] = 0;
  P->s   = s + 1;
  return HYLC_JSON_OK;
}

static int ParseNumber(JParser *P, HylcJson *v)
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
    return Fail(P, HYLC_JSON_ERR_SYNTAX, "%s:%d: expected a value, found %s (JSON numbers are like -1.5e-3; NaN and Infinity are not allowed)", P->name, P->line, Excerpt(P, ex));
  }
  if (s < P->end && *s == '.') {
    isint = 0;
    s++;
    CHECK(s < P->end && *s >= '0' && *s <= '9', "%s:%d: malformed number (a digit must follow the decimal point)", P->name, P->line);
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  }
  if (s < P->end && (*s == 'e' || *s == 'E')) {
    isint = 0;
    s++;
    if (s < P->end && (*s == '+' || *s == '-')) s++;
    CHECK(s < P->end && *s >= '0' && *s <= '9', "%s:%d: malformed number (digits must follow the exponent)", P->name, P->line);
    while (s < P->end && *s >= '0' && *s <= '9') s++;
  }
  len = (size_t)(s - start);
  CHECK(len < sizeof(tok), "%s:%d: number too long (%zu characters)", P->name, P->line, len);
  memcpy(tok, start, len);
  tok[len] = 0;
  errno    = 0;
  v->num   = strtod(tok, NULL);
  CHECK(isfinite(v->num), "%s:%d: number %s is out of the range of doubles", P->name, P->line, tok);
  v->type  = HYLC_JSON_NUMBER;
  v->isint = isint;
  P->s     = s;
  return HYLC_JSON_OK;
}

static int ParseValue(JParser *P, HylcJson *v);

static int ParseContainer(JParser *P, HylcJson *v)
{
  const char close = *P->s == '{' ? '}' : ']';
  const int  open  = P->line;
  char       ex[24];

  v->type = close == '}' ? HYLC_JSON_OBJECT : HYLC_JSON_ARRAY;
  CHECK(++P->depth <= JSON_MAX_DEPTH, "%s:%d: nesting deeper than %d levels", P->name, P->line, JSON_MAX_DEPTH);
  P->s++;
  SkipSpace(P);
  if (P->s < P->end && *P->s == close) {
    P->s++;
    P->depth--;
    return HYLC_JSON_OK;
  }
  for (;;) {
    HylcJson *slot = NULL;
    SkipSpace(P);
    CALL(Append(v, &slot));
    if (v->type == HYLC_JSON_OBJECT) {
      const char *key;
      CHECK(P->s < P->end && *P->s == '"', "%s:%d: expected a key in double quotes, found %s", P->name, P->line, Excerpt(P, ex));
      CALL(ParseString(P, &v->keys[v->n - 1]));
      key = v->keys[v->n - 1];
      for (int i = 0; i < v->n - 1; i++) CHECK(strcmp(v->keys[i], key), "%s:%d: duplicate key \"%s\" (also at line %d)", P->name, P->line, key, v->items[i].line);
      SkipSpace(P);
      CHECK(P->s < P->end && *P->s == ':', "%s:%d: expected ':' after the key \"%s\", found %s", P->name, P->line, key, Excerpt(P, ex));
      P->s++;
      SkipSpace(P);
    }
    CALL(ParseValue(P, slot));
    SkipSpace(P);
    CHECK(P->s < P->end, "%s:%d: end of file inside the %s opened at line %d", P->name, P->line, v->type == HYLC_JSON_OBJECT ? "object" : "array", open);
    if (*P->s == ',') {
      P->s++;
      SkipSpace(P);
      CHECK(P->s >= P->end || *P->s != close, "%s:%d: trailing comma before '%c'", P->name, P->line, close);
      continue;
    }
    CHECK(*P->s == close, "%s:%d: expected ',' or '%c' in the %s opened at line %d, found %s", P->name, P->line, close, v->type == HYLC_JSON_OBJECT ? "object" : "array", open, Excerpt(P, ex));
    P->s++;
    break;
  }
  P->depth--;
  return HYLC_JSON_OK;
}

static int ParseValue(JParser *P, HylcJson *v)
{
  char ex[24];

  SkipSpace(P);
  v->line = P->line;
  CHECK(P->s < P->end, "%s:%d: unexpected end of file (expected a value)", P->name, P->line);
  switch (*P->s) {
  case '{':
  case '[':
    CALL(ParseContainer(P, v));
    break;
  case '"':
    v->type = HYLC_JSON_STRING;
    CALL(ParseString(P, &v->str));
    break;
  case 't':
  case 'f':
  case 'n': {
    const char *lit[3] = {"true", "false", "null"};
    int         w      = *P->s == 't' ? 0 : *P->s == 'f' ? 1 : 2;
    size_t      l      = strlen(lit[w]);
    CHECK((size_t)(P->end - P->s) >= l && !strncmp(P->s, lit[w], l), "%s:%d: expected a value, found %s", P->name, P->line, Excerpt(P, ex));
    v->type = w == 2 ? HYLC_JSON_NULL : HYLC_JSON_BOOL;
    v->num  = w == 0;
    P->s += l;
  } break;
  default:
    CALL(ParseNumber(P, v));
  }
  return HYLC_JSON_OK;
}

int HylcJsonParse(const char name[], const char what[], const char *text, size_t len, HylcJson *root, char *err, size_t errlen)
{
  JParser P_, *P = &P_;
  char    ex[24];

  memset(root, 0, sizeof(*root));
  P->name   = name;
  P->err    = err;
  P->errlen = errlen;
  P->s      = text;
  P->end    = text + len;
  P->line   = 1;
  P->depth  = 0;
  SkipSpace(P);
  CHECK(P->s < P->end, "%s: empty file (expected %s)", name, what);
  CALL(ParseValue(P, root));
  SkipSpace(P);
  CHECK(P->s == P->end, "%s:%d: unexpected text after the end of the JSON document: %s", name, P->line, Excerpt(P, ex));
  return HYLC_JSON_OK;
}

const HylcJson *HylcJsonMember(const HylcJson *obj, const char key[])
{
  for (int i = 0; i < obj->n; i++)
    if (!strcmp(obj->keys[i], key)) return &obj->items[i];
  return NULL;
}

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

const char *HylcJsonFormatDouble(double x, char buf[32])
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
      char ex[16];
      *o++ = digits[0];
      if (nd > 1) {
        *o++ = '.';
        for (int i = 1; i < nd; i++) *o++ = digits[i];
      }
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
