/* The ARCSim-HYLC JSON material format (../shared/docs/formats.md §2, docs/material.md), writing side:
   byte-identical to python's json.dumps(d, indent=2), doubles as Python's repr() (hylcmat_format_double).
   The reader (strict parser and schema) is hylcmat's: src/hylcmat/json.c. */
#include <hylc/private/materialimpl.h>
#include <hylc/private/json.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char *HylcFormatDoubleRepr(double x, char buf[32]) { return HylcJsonFormatDouble(x, buf); }

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
