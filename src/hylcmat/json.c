/* The ARCSim-HYLC JSON material format (../shared/docs/formats.md §2, docs/material.md), reading side:
   the schema reader (unknown keys are errors) over the tree of the generic strict JSON reader
   (src/sys/json.c), with errors naming the file, the line and the key path
   (stock1.json:123: coeffs.2D[3].mu: ...); the values are validated by the setters of core.c.
   The writer (byte-identical to python's json.dumps(d, indent=2)) is in src/material/json.c. */
#include "hylcmatimpl.h"
#include <hylc/private/json.h>
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
/* Schema                                                                                             */
/* ------------------------------------------------------------------------------------------------ */

static int ExpectType(const hm_doc *d, const HylcJson *v, HylcJsonType t, const char path[])
{
  HM_CHECK(v->type == t, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected %s, got %s", d->name, v->line, path, HylcJsonTypeName(t), HylcJsonTypeName(v->type));
  return HYLCMAT_OK;
}

/* every key of obj must be one of known[]; every one of required[] must be there */
static int CheckKeys(const hm_doc *d, const HylcJson *obj, const char path[], const char *const known[], int nknown, const char *const required[], int nrequired)
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
  for (int j = 0; j < nrequired; j++) HM_CHECK(HylcJsonMember(obj, required[j]), d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s%smissing key \"%s\"", d->name, obj->line, path, path[0] ? ": " : "", required[j]);
  return HYLCMAT_OK;
}

/* an array of numbers; n < 0: any length; else exactly n (what explains n in the message) */
static int GetNumbers(const hm_doc *d, const HylcJson *v, const char path[], int n, const char what[], double **out, int *nout)
{
  HM_CALL(ExpectType(d, v, HYLC_JSON_ARRAY, path));
  HM_CHECK(n < 0 || v->n == n, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected %d numbers%s, got %d", d->name, v->line, path, n, what ? what : "", v->n);
  for (int i = 0; i < v->n; i++) HM_CHECK(v->items[i].type == HYLC_JSON_NUMBER, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: expected a number, got %s", d->name, v->items[i].line, path, i, HylcJsonTypeName(v->items[i].type));
  if (out) {
    *out = malloc(sizeof(double) * (size_t)(v->n + 1));
    if (!*out) return hm_fail(d->E, HYLCMAT_ERR_MEMORY, "%s:%d: %s: out of memory", d->name, v->line, path);
    for (int i = 0; i < v->n; i++) (*out)[i] = v->items[i].num;
  }
  if (nout) *nout = v->n;
  return HYLCMAT_OK;
}

static int GetKnots(const hm_doc *d, const HylcJson *v, const char path[], double **out, int *n)
{
  char b0[32], b1[32];

  HM_CALL(GetNumbers(d, v, path, -1, NULL, NULL, n));
  HM_CHECK(*n >= 2, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: a spline needs at least 2 knots, got %d", d->name, v->line, path, *n);
  for (int i = 1; i < *n; i++)
    HM_CHECK(v->items[i].num > v->items[i - 1].num, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: knots must be strictly increasing, but %s <= %s (the knot before)", d->name, v->items[i].line, path, i, hylcmat_format_double(v->items[i].num, b0),
             hylcmat_format_double(v->items[i - 1].num, b1));
  for (int i = 1; i < *n; i++) { /* the evaluator divides by the spacing (docs/material.md, "Range") */
    const double h = v->items[i].num - v->items[i - 1].num;
    HM_CHECK(isfinite(h) && isfinite(1 / h), d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: the knot spacing %s - %s %s (a spacing h must have h and 1/h finite)", d->name, v->items[i].line, path, i, hylcmat_format_double(v->items[i].num, b0),
             hylcmat_format_double(v->items[i - 1].num, b1), isfinite(h) ? "is too small" : "overflows");
  }
  HM_CALL(GetNumbers(d, v, path, -1, NULL, out, NULL));
  return HYLCMAT_OK;
}

static int GetInt(const hm_doc *d, const HylcJson *v, const char path[], int lo, int hi, const char what[], int *out)
{
  char b[32];

  HM_CHECK(v->type == HYLC_JSON_NUMBER, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected an integer, got %s", d->name, v->line, path, HylcJsonTypeName(v->type));
  HM_CHECK(v->num == floor(v->num) && v->num >= (double)lo && v->num <= (double)hi, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected an integer in %d..%d%s, got %s", d->name, v->line, path, lo, hi, what ? what : "", hylcmat_format_double(v->num, b));
  *out = (int)v->num;
  return HYLCMAT_OK;
}

static int GetExt(const hm_doc *d, const HylcJson *obj, const char path[], int *ext)
{
  const HylcJson *v = HylcJsonMember(obj, "ext");
  char            p[128];
  int             e = 0;

  if (v) {
    snprintf(p, sizeof(p), "%s.ext", path);
    HM_CALL(GetInt(d, v, p, 0, 2, " (0 linear, 1 constant, 2 zero extrapolation)", &e));
  }
  *ext = (int)e;
  return HYLCMAT_OK;
}

static int Read1D(hm_doc *d, const HylcJson *v, const char path[])
{
  static const char *const known[] = {"k", "t", "p", "m", "ext"};
  char                     p[128];
  hylcmat_term1d          *s = &d->s1[d->n1];
  int                      n;

  HM_CALL(ExpectType(d, v, HYLC_JSON_OBJECT, path));
  HM_CALL(CheckKeys(d, v, path, known, 5, known, 4));
  snprintf(p, sizeof(p), "%s.k", path);
  HM_CALL(GetInt(d, HylcJsonMember(v, "k"), p, 0, HYLCMAT_N1D - 1, " (0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending)", &s->k));
  HM_CALL(GetExt(d, v, path, &s->ext));
  d->n1++; /* owns its arrays from here on */
  snprintf(p, sizeof(p), "%s.t", path);
  HM_CALL(GetKnots(d, HylcJsonMember(v, "t"), p, (double **)&s->t, &s->n));
  n = s->n;
  snprintf(p, sizeof(p), "%s.p", path);
  HM_CALL(GetNumbers(d, HylcJsonMember(v, "p"), p, n, " (one per knot)", (double **)&s->p, NULL));
  snprintf(p, sizeof(p), "%s.m", path);
  HM_CALL(GetNumbers(d, HylcJsonMember(v, "m"), p, n, " (one per knot)", (double **)&s->m, NULL));
  return HYLCMAT_OK;
}

static int Read2D(hm_doc *d, const HylcJson *v, const char path[])
{
  static const char *const known[] = {"k0", "k1", "tu", "tv", "p", "mu", "mv", "muv", "ext"};
  static const char *const arr[]   = {"p", "mu", "mv", "muv"};
  char                     p[128], what[64];
  hylcmat_term2d          *s = &d->s2[d->n2];
  double                 **dst[4];

  HM_CALL(ExpectType(d, v, HYLC_JSON_OBJECT, path));
  HM_CALL(CheckKeys(d, v, path, known, 9, known, 8));
  snprintf(p, sizeof(p), "%s.k0", path);
  HM_CALL(GetInt(d, HylcJsonMember(v, "k0"), p, 0, 2, " (the in-plane coordinate: 0 sx, 1 sa, 2 sy)", &s->k0));
  snprintf(p, sizeof(p), "%s.k1", path);
  HM_CALL(GetInt(d, HylcJsonMember(v, "k1"), p, 1, 4, NULL, &s->k1));
  HM_CHECK(hylcmat_pair_index(s->k0, s->k1) >= 0, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: (k0, k1) = (%d, %d) is not a term of the model; the pairs are (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4)", d->name, v->line, path, s->k0, s->k1);
  HM_CALL(GetExt(d, v, path, &s->ext));
  d->n2++;
  snprintf(p, sizeof(p), "%s.tu", path);
  HM_CALL(GetKnots(d, HylcJsonMember(v, "tu"), p, (double **)&s->tu, &s->nu));
  snprintf(p, sizeof(p), "%s.tv", path);
  HM_CALL(GetKnots(d, HylcJsonMember(v, "tv"), p, (double **)&s->tv, &s->nv));
  snprintf(what, sizeof(what), " (len(tu) * len(tv) = %d * %d)", (int)s->nu, (int)s->nv);
  dst[0] = (double **)&s->p;
  dst[1] = (double **)&s->mu;
  dst[2] = (double **)&s->mv;
  dst[3] = (double **)&s->muv;
  for (int a = 0; a < 4; a++) {
    snprintf(p, sizeof(p), "%s.%s", path, arr[a]);
    HM_CALL(GetNumbers(d, HylcJsonMember(v, arr[a]), p, s->nu * s->nv, what, dst[a], NULL));
  }
  return HYLCMAT_OK;
}

static int ReadDoc(hm_doc *d, const HylcJson *root)
{
  static const char *const topKnown[]    = {"density", "strain scale", "strain shift", "coeffs"};
  static const char *const topRequired[] = {"density", "strain scale", "coeffs"};
  static const char *const cKnown[]      = {"const", "1D", "2D"};
  const HylcJson          *v, *coeffs;
  double                  *buf;
  char                     b[32];

  HM_CALL(ExpectType(d, root, HYLC_JSON_OBJECT, "the document"));
  HM_CALL(CheckKeys(d, root, "", topKnown, 4, topRequired, 3));
  v = HylcJsonMember(root, "density");
  HM_CHECK(v->type == HYLC_JSON_NUMBER, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: density: expected a number, got %s", d->name, v->line, HylcJsonTypeName(v->type));
  HM_CHECK(v->num >= 0 && v->num <= HM_MAX_DENSITY, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: density: the area density must be in [0, %g] kg/m^2, got %s", d->name, v->line, HM_MAX_DENSITY, hylcmat_format_double(v->num, b));
  d->density = v->num;
  v          = HylcJsonMember(root, "strain scale");
  HM_CALL(GetNumbers(d, v, "strain scale", 5, " (sigma of sx, sa, sy, II00, II11)", NULL, NULL));
  for (int k = 0; k < 5; k++)
    HM_CHECK(v->items[k].num > 0 && isfinite(1 / v->items[k].num), d->E, HYLCMAT_ERR_FORMAT, "%s:%d: strain scale[%d]: must be positive with a finite inverse, got %s", d->name, v->items[k].line, k, hylcmat_format_double(v->items[k].num, b));
  HM_CALL(GetNumbers(d, v, "strain scale", 5, NULL, &buf, NULL));
  for (int k = 0; k < 5; k++) d->scale[k] = buf[k];
  free(buf);
  if ((v = HylcJsonMember(root, "strain shift"))) {
    HM_CALL(GetNumbers(d, v, "strain shift", 5, NULL, NULL, NULL));
    for (int k = 0; k < 5; k++) {
      char p[32];
      snprintf(p, sizeof(p), "strain shift[%d]", k);
      HM_CALL(GetInt(d, &v->items[k], p, -1000000, 1000000, NULL, &d->shift[k]));
    }
  }
  coeffs = HylcJsonMember(root, "coeffs");
  HM_CALL(ExpectType(d, coeffs, HYLC_JSON_OBJECT, "coeffs"));
  HM_CALL(CheckKeys(d, coeffs, "coeffs", cKnown, 3, cKnown, 1));
  v = HylcJsonMember(coeffs, "const");
  HM_CHECK(v->type == HYLC_JSON_NUMBER, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: coeffs.const: expected a number, got %s", d->name, v->line, HylcJsonTypeName(v->type));
  d->C0 = v->num;
  if ((v = HylcJsonMember(coeffs, "1D"))) {
    HM_CALL(ExpectType(d, v, HYLC_JSON_ARRAY, "coeffs.1D"));
    HM_CHECK(v->n <= HYLCMAT_N1D, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: coeffs.1D: at most %d terms (k = 0..4), got %d", d->name, v->line, HYLCMAT_N1D, v->n);
    for (int i = 0; i < v->n; i++) {
      char p[32];
      snprintf(p, sizeof(p), "coeffs.1D[%d]", (int)i);
      HM_CALL(Read1D(d, &v->items[i], p));
      for (int j = 0; j < d->n1 - 1; j++)
        HM_CHECK(d->s1[j].k != d->s1[d->n1 - 1].k, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: a second term with k = %d (the first is coeffs.1D[%d] at line %d)", d->name, v->items[i].line, p, d->s1[j].k, j, v->items[j].line);
    }
  }
  if ((v = HylcJsonMember(coeffs, "2D"))) {
    HM_CALL(ExpectType(d, v, HYLC_JSON_ARRAY, "coeffs.2D"));
    HM_CHECK(v->n <= HYLCMAT_N2D, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: coeffs.2D: at most %d terms, got %d", d->name, v->line, HYLCMAT_N2D, v->n);
    for (int i = 0; i < v->n; i++) {
      char p[32];
      snprintf(p, sizeof(p), "coeffs.2D[%d]", (int)i);
      HM_CALL(Read2D(d, &v->items[i], p));
      for (int j = 0; j < d->n2 - 1; j++)
        HM_CHECK(d->s2[j].k0 != d->s2[d->n2 - 1].k0 || d->s2[j].k1 != d->s2[d->n2 - 1].k1, d->E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: a second term with (k0, k1) = (%d, %d) (the first is coeffs.2D[%d] at line %d)", d->name, v->items[i].line, p,
                 d->s2[j].k0, d->s2[j].k1, j, v->items[j].line);
    }
  }
  return HYLCMAT_OK;
}

int hm_parse_json(const char *name, const char *text, size_t len, hm_err *E, hylcmat **m)
{
  HylcJson root;
  hm_doc   d;
  int      ierr;

  memset(&root, 0, sizeof(root));
  hm_doc_init(&d, name, E);
  ierr = HylcJsonParse(name, "a JSON material", text, len, &root, E ? E->buf : NULL, E ? E->len : 0);
  if (ierr) ierr = ierr == HYLC_JSON_ERR_MEMORY ? HYLCMAT_ERR_MEMORY : HYLCMAT_ERR_FORMAT;
  if (!ierr) ierr = ReadDoc(&d, &root);
  HylcJsonFree(&root);
  if (ierr == HYLCMAT_ERR_MEMORY) hm_fail(E, ierr, "%s: out of memory", name);
  if (ierr) {
    hm_doc_free(&d);
    return ierr;
  }
  return hm_doc_install(&d, m);
}
