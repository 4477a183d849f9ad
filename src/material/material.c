/* HylcMaterial: object lifecycle, contents (validated setters and getters), options, viewer, and the
   file dispatch (JSON or HDF5 by content; atomic writes by rank 0). */
#include <hylc/private/materialimpl.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const PetscInt HylcMaterialPairs[HYLC_MATERIAL_N2D][2] = {
    {0, 1},
    {0, 2},
    {0, 3},
    {0, 4},
    {1, 2},
    {1, 3},
    {1, 4},
    {2, 3},
    {2, 4}};
const char *const HylcMaterialTermNames1D[HYLC_MATERIAL_N1D] = {"sx", "sa", "sy", "II00", "II11"};
const char *const HylcMaterialTermNames2D[HYLC_MATERIAL_N2D] = {"sx-sa", "sx-sy", "sx-II00", "sx-II11", "sa-sy", "sa-II00", "sa-II11", "sy-II00", "sy-II11"};

PetscInt HylcMaterialPairIndex(PetscInt k0, PetscInt k1)
{
  for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++)
    if (HylcMaterialPairs[q][0] == k0 && HylcMaterialPairs[q][1] == k1) return q;
  return -1;
}

/* a number for messages and views (C printf: PETSc's appends '.' to integral %g values) */
static const char *G(char buf[32], PetscReal v)
{
  snprintf(buf, 32, "%.6g", (double)v);
  return buf;
}

static const char *const ExtNames[] = {"linear", "constant", "zero"};

/*@C
  HylcMaterialCreate - Creates an empty material model: no terms (Psi = 0), density 0, strain scale 1,
  strain shift 1,0,1,0,0. Collective.
@*/
PetscErrorCode HylcMaterialCreate(MPI_Comm comm, HylcMaterial *mat)
{
  HylcMaterial m;

  PetscFunctionBegin;
  PetscValidPointer(mat, 2);
  PetscCall(HylcInitializePackage());
  PetscCall(PetscHeaderCreate(m, HYLC_MATERIAL_CLASSID, "HylcMaterial", "Homogenized cloth material model", "Material", comm, HylcMaterialDestroy, HylcMaterialView));
  PetscCall(HylcMaterialReset(m));
  *mat = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Free1D(HylcMaterial m, PetscInt k)
{
  PetscFunctionBegin;
  if (m->has1[k]) PetscCall(PetscFree3(m->t1[k].t, m->t1[k].p, m->t1[k].m));
  PetscCall(PetscMemzero(&m->t1[k], sizeof(m->t1[k])));
  m->has1[k] = PETSC_FALSE;
  m->sw1[k]  = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Free2D(HylcMaterial m, PetscInt q)
{
  PetscFunctionBegin;
  if (m->has2[q]) {
    PetscCall(PetscFree2(m->t2[q].tu, m->t2[q].tv));
    PetscCall(PetscFree4(m->t2[q].p, m->t2[q].mu, m->t2[q].mv, m->t2[q].muv));
  }
  PetscCall(PetscMemzero(&m->t2[q], sizeof(m->t2[q])));
  m->has2[q] = PETSC_FALSE;
  m->sw2[q]  = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialReset - Removes every term; density 0, strain scale 1, strain shift 1,0,1,0,0, constant 0.
  Not collective.
@*/
PetscErrorCode HylcMaterialReset(HylcMaterial m)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) PetscCall(Free1D(m, k));
  for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) PetscCall(Free2D(m, q));
  m->density = 0;
  m->C0      = 0;
  for (PetscInt k = 0; k < 5; k++) {
    m->scale[k] = 1;
    m->shift[k] = (k == 0 || k == 2) ? 1 : 0;
  }
  m->source[0] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void HylcMaterialDocInit(HylcMaterialDoc *d, HylcMaterial m, const char name[])
{
  memset(d, 0, sizeof(*d));
  d->name = name;
  d->comm = PetscObjectComm((PetscObject)m);
  for (int k = 0; k < 5; k++) d->shift[k] = (k == 0 || k == 2) ? 1 : 0;
}

void HylcMaterialDocFree(HylcMaterialDoc *d)
{
  for (PetscInt i = 0; i < d->n1; i++) {
    PetscFree(d->s1[i].t);
    PetscFree(d->s1[i].p);
    PetscFree(d->s1[i].m);
  }
  for (PetscInt i = 0; i < d->n2; i++) {
    PetscFree(d->s2[i].tu);
    PetscFree(d->s2[i].tv);
    PetscFree(d->s2[i].p);
    PetscFree(d->s2[i].mu);
    PetscFree(d->s2[i].mv);
    PetscFree(d->s2[i].muv);
  }
  d->n1 = d->n2 = 0;
}

PetscErrorCode HylcMaterialDocInstall(HylcMaterial m, HylcMaterialDoc *d)
{
  PetscErrorCode ierr;

  PetscFunctionBegin;
  ierr = HylcMaterialReset(m);
  if (!ierr) ierr = HylcMaterialSetDensity(m, d->density);
  if (!ierr) ierr = HylcMaterialSetStrainScale(m, d->scale);
  if (!ierr) ierr = HylcMaterialSetStrainShift(m, d->shift);
  if (!ierr) ierr = HylcMaterialSetConstant(m, d->C0);
  for (PetscInt i = 0; i < d->n1 && !ierr; i++) ierr = HylcMaterialSet1D(m, &d->s1[i]);
  for (PetscInt i = 0; i < d->n2 && !ierr; i++) ierr = HylcMaterialSet2D(m, &d->s2[i]);
  HylcMaterialDocFree(d);
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialDestroy - Destroys a material. Accepts NULL; sets the handle to NULL. Collective.
@*/
PetscErrorCode HylcMaterialDestroy(HylcMaterial *m)
{
  PetscFunctionBegin;
  if (!*m) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*m, HYLC_MATERIAL_CLASSID, 1);
  if (--((PetscObject)(*m))->refct > 0) {
    *m = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcMaterialReset(*m));
  PetscCall(PetscHeaderDestroy(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialSetOptionsPrefix(HylcMaterial m, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)m, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSetFromOptions - Reads the material options. Collective.

  Options (after the object's prefix, if any):
+ -material_file <model.json|model.h5> - load this material (HylcMaterialLoad)
- -material_view                       - print a summary (HylcMaterialViewFromOptions, called by the programs)
@*/
PetscErrorCode HylcMaterialSetFromOptions(HylcMaterial m)
{
  char      file[PETSC_MAX_PATH_LEN] = "";
  PetscBool flg;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscObjectOptionsBegin((PetscObject)m);
  PetscCall(PetscOptionsString("-material_file", "Material model to load: ARCSim-HYLC JSON or hylc HDF5 (recognized by content)", "HylcMaterialLoad", m->source, file, sizeof(file), &flg));
  PetscCall(PetscOptionsName("-material_view", "Print a summary of the material", "HylcMaterialViewFromOptions", NULL));
  PetscCall(PetscObjectProcessOptionsHandlers((PetscObject)m, PetscOptionsObject));
  PetscOptionsEnd();
  if (flg) {
    PetscCheck(file[0], PetscObjectComm((PetscObject)m), PETSC_ERR_USER_INPUT, "-material_file needs a file name");
    PetscCall(HylcMaterialLoad(m, file));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialView - Prints a summary: source, density, strain scale, constant, and each term's grid.
  Collective on the viewer.
@*/
PetscErrorCode HylcMaterialView(HylcMaterial m, PetscViewer viewer)
{
  PetscBool iascii;
  char      b[6][32];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)m), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  {
    const char *prefix = ((PetscObject)m)->prefix;
    PetscCall(PetscViewerASCIIPrintf(viewer, "HylcMaterial%s%s: homogenized cloth material (spline tables)\n", prefix ? " " : "", prefix ? prefix : ""));
  }
  PetscCall(PetscViewerASCIIPushTab(viewer));
  if (m->source[0]) PetscCall(PetscViewerASCIIPrintf(viewer, "source: %s\n", m->source));
  PetscCall(PetscViewerASCIIPrintf(viewer, "density: %s kg/m^2, constant: %s J/m^2\n", G(b[0], m->density), G(b[1], m->C0)));
  PetscCall(PetscViewerASCIIPrintf(viewer, "strain scale (sx sa sy II00 II11): %s %s %s %s %s\n", G(b[0], m->scale[0]), G(b[1], m->scale[1]), G(b[2], m->scale[2]), G(b[3], m->scale[3]), G(b[4], m->scale[4])));
  for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) {
    const HylcSpline1D *s = &m->t1[k];
    if (!m->has1[k]) {
      PetscCall(PetscViewerASCIIPrintf(viewer, "1D %-8s absent\n", HylcMaterialTermNames1D[k]));
      continue;
    }
    PetscCall(PetscViewerASCIIPrintf(viewer, "1D %-8s %2" PetscInt_FMT " knots on [%s, %s], %s extrapolation\n", HylcMaterialTermNames1D[k], s->n, G(b[0], s->t[0]), G(b[1], s->t[s->n - 1]), ExtNames[s->ext]));
  }
  for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) {
    const HylcSpline2D *s = &m->t2[q];
    if (!m->has2[q]) {
      PetscCall(PetscViewerASCIIPrintf(viewer, "2D %-8s absent\n", HylcMaterialTermNames2D[q]));
      continue;
    }
    PetscCall(PetscViewerASCIIPrintf(viewer, "2D %-8s %2" PetscInt_FMT " x %2" PetscInt_FMT " knots on [%s, %s] x [%s, %s], %s extrapolation\n", HylcMaterialTermNames2D[q], s->nu, s->nv, G(b[0], s->tu[0]), G(b[1], s->tu[s->nu - 1]), G(b[2], s->tv[0]), G(b[3], s->tv[s->nv - 1]),
                                     ExtNames[s->ext]));
  }
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialViewFromOptions(HylcMaterial m, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)m, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ------------------------------------------------------------------------------------------------ */
/* Contents                                                                                           */
/* ------------------------------------------------------------------------------------------------ */

PetscErrorCode HylcMaterialSetDensity(HylcMaterial m, PetscReal rho)
{
  char b[32];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCheck(!PetscIsInfOrNanReal(rho) && rho >= 0, PetscObjectComm((PetscObject)m), PETSC_ERR_USER_INPUT, "Material density must be finite and >= 0, got %s", G(b, rho));
  m->density = rho;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialGetDensity(HylcMaterial m, PetscReal *rho)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  *rho = m->density;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialSetStrainScale(HylcMaterial m, const PetscReal scale[5])
{
  char b[32];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < 5; k++) PetscCheck(isfinite(scale[k]) && scale[k] > 0 && isfinite(1 / scale[k]), PetscObjectComm((PetscObject)m), PETSC_ERR_USER_INPUT, "Strain scale %" PetscInt_FMT " (%s) must be finite and positive with a finite inverse, got %s", k, HylcMaterialTermNames1D[k], G(b, scale[k]));
  for (PetscInt k = 0; k < 5; k++) m->scale[k] = scale[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialGetStrainScale(HylcMaterial m, PetscReal scale[5])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < 5; k++) scale[k] = m->scale[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialSetStrainShift(HylcMaterial m, const PetscInt shift[5])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < 5; k++) m->shift[k] = shift[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialGetStrainShift(HylcMaterial m, PetscInt shift[5])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < 5; k++) shift[k] = m->shift[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialSetConstant(HylcMaterial m, PetscReal c)
{
  char b[32];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCheck(!PetscIsInfOrNanReal(c), PetscObjectComm((PetscObject)m), PETSC_ERR_USER_INPUT, "Material constant must be finite, got %s", G(b, c));
  m->C0 = c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialGetConstant(HylcMaterial m, PetscReal *c)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  *c = m->C0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* knots: at least 2, finite, strictly increasing; values finite. what names the term in messages. */
static PetscErrorCode CheckKnots(MPI_Comm comm, const char what[], const char name[], PetscInt n, const PetscReal t[])
{
  char b0[32], b1[32];

  PetscFunctionBegin;
  PetscCheck(n >= 2, comm, PETSC_ERR_USER_INPUT, "%s: %s needs at least 2 knots, got %" PetscInt_FMT, what, name, n);
  for (PetscInt i = 0; i < n; i++) {
    PetscCheck(!PetscIsInfOrNanReal(t[i]), comm, PETSC_ERR_USER_INPUT, "%s: knot %s[%" PetscInt_FMT "] = %s is not finite", what, name, i, G(b0, t[i]));
    PetscCheck(i == 0 || t[i] > t[i - 1], comm, PETSC_ERR_USER_INPUT, "%s: knots %s must be strictly increasing, but %s[%" PetscInt_FMT "] = %s <= %s[%" PetscInt_FMT "] = %s", what, name, name, i, G(b0, t[i]), name, i - 1, G(b1, t[i - 1]));
    if (i > 0) { /* the evaluator divides by the spacing (docs/material.md, "Range") */
      const PetscReal h = t[i] - t[i - 1];
      PetscCheck(isfinite(h) && isfinite(1 / h), comm, PETSC_ERR_USER_INPUT, "%s: the spacing %s[%" PetscInt_FMT "] - %s[%" PetscInt_FMT "] = %s - %s %s (knot spacings h must have h and 1/h finite)", what, name, i, name, i - 1, G(b0, t[i]), G(b1, t[i - 1]),
                 isfinite(h) ? "is too small" : "overflows");
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode CheckFinite(MPI_Comm comm, const char what[], const char name[], PetscInt n, const PetscReal v[])
{
  char b[32];

  PetscFunctionBegin;
  for (PetscInt i = 0; i < n; i++) PetscCheck(!PetscIsInfOrNanReal(v[i]), comm, PETSC_ERR_USER_INPUT, "%s: %s[%" PetscInt_FMT "] = %s is not finite", what, name, i, G(b, v[i]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal HalfMinSpacing(PetscInt n, const PetscReal t[])
{
  PetscReal h = PETSC_MAX_REAL;
  for (PetscInt i = 1; i < n; i++) h = PetscMin(h, t[i] - t[i - 1]);
  return 0.45 * h;
}

/*@C
  HylcMaterialSet1D - Sets (copies) the 1D term s->k, replacing one of the same k. Checks k in 0..4,
  n >= 2, strictly increasing finite knots, finite values and slopes, a known extrapolation mode.
  Not collective (call it with the same data on every rank).
@*/
PetscErrorCode HylcMaterialSet1D(HylcMaterial m, const HylcSpline1D *s)
{
  MPI_Comm comm;
  char     what[64];
  PetscInt k;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidPointer(s, 2);
  comm = PetscObjectComm((PetscObject)m);
  k    = s->k;
  PetscCheck(k >= 0 && k < HYLC_MATERIAL_N1D, comm, PETSC_ERR_USER_INPUT, "1D term: k = %" PetscInt_FMT " is out of range (0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending)", k);
  snprintf(what, sizeof(what), "1D term %s (k = %d)", HylcMaterialTermNames1D[k], (int)k);
  PetscCheck(s->ext >= HYLC_EXT_LINEAR && s->ext <= HYLC_EXT_ZERO, comm, PETSC_ERR_USER_INPUT, "%s: extrapolation mode %d is not 0 (linear), 1 (constant) or 2 (zero)", what, (int)s->ext);
  PetscCall(CheckKnots(comm, what, "t", s->n, s->t));
  PetscCall(CheckFinite(comm, what, "p", s->n, s->p));
  PetscCall(CheckFinite(comm, what, "m", s->n, s->m));
  PetscCall(Free1D(m, k));
  m->t1[k].k   = k;
  m->t1[k].n   = s->n;
  m->t1[k].ext = s->ext;
  PetscCall(PetscMalloc3(s->n, &m->t1[k].t, s->n, &m->t1[k].p, s->n, &m->t1[k].m));
  PetscCall(PetscArraycpy(m->t1[k].t, s->t, s->n));
  PetscCall(PetscArraycpy(m->t1[k].p, s->p, s->n));
  PetscCall(PetscArraycpy(m->t1[k].m, s->m, s->n));
  m->has1[k] = PETSC_TRUE;
  m->sw1[k]  = HalfMinSpacing(s->n, s->t);
  m->ih1[k]  = (s->n - 1) / (s->t[s->n - 1] - s->t[0]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSet2D - Sets (copies) the 2D term (s->k0, s->k1), replacing one of the same pair. Checks
  that the pair is one of HylcMaterialPairs, nu, nv >= 2, strictly increasing finite knots, finite node
  data. Not collective.
@*/
PetscErrorCode HylcMaterialSet2D(HylcMaterial m, const HylcSpline2D *s)
{
  MPI_Comm comm;
  char     what[64];
  PetscInt q, N;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidPointer(s, 2);
  comm = PetscObjectComm((PetscObject)m);
  q    = HylcMaterialPairIndex(s->k0, s->k1);
  PetscCheck(q >= 0, comm, PETSC_ERR_USER_INPUT, "2D term: (k0, k1) = (%" PetscInt_FMT ", %" PetscInt_FMT ") is not a term of the model; the pairs are (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4)", s->k0, s->k1);
  snprintf(what, sizeof(what), "2D term %s (k0 = %d, k1 = %d)", HylcMaterialTermNames2D[q], (int)s->k0, (int)s->k1);
  PetscCheck(s->ext >= HYLC_EXT_LINEAR && s->ext <= HYLC_EXT_ZERO, comm, PETSC_ERR_USER_INPUT, "%s: extrapolation mode %d is not 0 (linear), 1 (constant) or 2 (zero)", what, (int)s->ext);
  PetscCall(CheckKnots(comm, what, "tu", s->nu, s->tu));
  PetscCall(CheckKnots(comm, what, "tv", s->nv, s->tv));
  N = s->nu * s->nv;
  PetscCall(CheckFinite(comm, what, "p", N, s->p));
  PetscCall(CheckFinite(comm, what, "mu", N, s->mu));
  PetscCall(CheckFinite(comm, what, "mv", N, s->mv));
  PetscCall(CheckFinite(comm, what, "muv", N, s->muv));
  PetscCall(Free2D(m, q));
  m->t2[q].k0  = s->k0;
  m->t2[q].k1  = s->k1;
  m->t2[q].nu  = s->nu;
  m->t2[q].nv  = s->nv;
  m->t2[q].ext = s->ext;
  PetscCall(PetscMalloc2(s->nu, &m->t2[q].tu, s->nv, &m->t2[q].tv));
  PetscCall(PetscMalloc4(N, &m->t2[q].p, N, &m->t2[q].mu, N, &m->t2[q].mv, N, &m->t2[q].muv));
  PetscCall(PetscArraycpy(m->t2[q].tu, s->tu, s->nu));
  PetscCall(PetscArraycpy(m->t2[q].tv, s->tv, s->nv));
  PetscCall(PetscArraycpy(m->t2[q].p, s->p, N));
  PetscCall(PetscArraycpy(m->t2[q].mu, s->mu, N));
  PetscCall(PetscArraycpy(m->t2[q].mv, s->mv, N));
  PetscCall(PetscArraycpy(m->t2[q].muv, s->muv, N));
  m->has2[q] = PETSC_TRUE;
  m->sw2[q]  = HalfMinSpacing(s->nv, s->tv);
  m->ihu[q]  = (s->nu - 1) / (s->tu[s->nu - 1] - s->tu[0]);
  m->ihv[q]  = (s->nv - 1) / (s->tv[s->nv - 1] - s->tv[0]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialGet1D(HylcMaterial m, PetscInt k, const HylcSpline1D **s)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCheck(k >= 0 && k < HYLC_MATERIAL_N1D, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "1D term k = %" PetscInt_FMT " is out of range 0..4", k);
  *s = m->has1[k] ? &m->t1[k] : NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialGet2D(HylcMaterial m, PetscInt k0, PetscInt k1, const HylcSpline2D **s)
{
  const PetscInt q = HylcMaterialPairIndex(k0, k1);

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCheck(q >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "(k0, k1) = (%" PetscInt_FMT ", %" PetscInt_FMT ") is not a 2D term of the model", k0, k1);
  *s = m->has2[q] ? &m->t2[q] : NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ------------------------------------------------------------------------------------------------ */
/* Files                                                                                              */
/* ------------------------------------------------------------------------------------------------ */

static const char HDF5Signature[8] = {'\211', 'H', 'D', 'F', '\r', '\n', '\032', '\n'};

/*@C
  HylcMaterialLoadFromString - Parses a JSON material (formats.md §2) from text; name is used in
  messages. Replaces the contents. Collective: every rank passes the same text.
@*/
PetscErrorCode HylcMaterialLoadFromString(HylcMaterial m, const char name[], const char text[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCall(HylcMaterialParseJSON_Private(m, name, text, strlen(text)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialLoad - Reads a material file, ARCSim-HYLC JSON or hylc HDF5 (docs/material.md), recognized
  by content (the HDF5 signature), and replaces the contents. Errors name the file and, for JSON, the line
  and the key. Collective: rank 0 reads the file and broadcasts its bytes; every rank parses them.
@*/
PetscErrorCode HylcMaterialLoad(HylcMaterial m, const char path[])
{
  MPI_Comm       comm;
  PetscMPIInt    rank;
  long           len = 0;
  int            err = 0;
  char          *bytes;
  PetscErrorCode ierr;
  FILE          *fp = NULL;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  comm = PetscObjectComm((PetscObject)m);
  PetscCall(PetscLogEventBegin(HYLC_MaterialLoad, m, 0, 0, 0));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    struct stat st;
    fp = fopen(path, "rb");
    if (!fp)
      err = errno;
    else if (fstat(fileno(fp), &st) || !S_ISREG(st.st_mode)) { /* a directory opens, and has no size */
      err = errno ? errno : EIO;
      if (!fstat(fileno(fp), &st)) err = S_ISDIR(st.st_mode) ? EISDIR : EINVAL;
      fclose(fp);
      fp = NULL;
    }
    if (fp && fseek(fp, 0, SEEK_END) == 0)
      len = ftell(fp);
    else if (fp)
      len = -1;
    if (fp) rewind(fp);
    if (!fp || len < 0) len = -1;
  }
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_LONG, 0, comm));
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(err != EISDIR, comm, PETSC_ERR_FILE_OPEN, "Cannot read material file '%s': it is a directory", path);
  PetscCheck(err != EINVAL, comm, PETSC_ERR_FILE_OPEN, "Cannot read material file '%s': not a regular file", path);
  PetscCheck(len >= 0, comm, PETSC_ERR_FILE_OPEN, "Cannot open material file '%s'%s%s", path, err ? ": " : "", err ? strerror(err) : "");
  PetscCheck(len < (1L << 30), comm, PETSC_ERR_USER_INPUT, "Material file '%s' is too large (%ld bytes)", path, len);
  PetscCall(PetscMalloc1(len + 1, &bytes));
  if (rank == 0) {
    size_t got = fread(bytes, 1, (size_t)len, fp);
    fclose(fp);
    if ((long)got != len) len = -1;
  }
  PetscCallMPI(MPI_Bcast(&len, 1, MPI_LONG, 0, comm));
  PetscCheck(len >= 0, comm, PETSC_ERR_FILE_READ, "Cannot read material file '%s'", path);
  if (len) PetscCallMPI(MPI_Bcast(bytes, (PetscMPIInt)len, MPI_CHAR, 0, comm));
  bytes[len] = 0;
  if (len >= 8 && !memcmp(bytes, HDF5Signature, 8))
    ierr = HylcMaterialParseHDF5_Private(m, path, bytes, (size_t)len);
  else if (strlen(bytes) != (size_t)len) {
    const size_t at = strlen(bytes);
    PetscCall(PetscFree(bytes));
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: contains a NUL byte at offset %zu: neither a JSON nor an HDF5 material file", path, at);
  } else
    ierr = HylcMaterialParseJSON_Private(m, path, bytes, (size_t)len);
  PetscCall(PetscFree(bytes));
  PetscCall(ierr);
  PetscCall(PetscStrncpy(m->source, path, sizeof(m->source)));
  PetscCall(PetscLogEventEnd(HYLC_MaterialLoad, m, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0 writes the bytes to path.tmp, syncs and renames it to path; every rank returns the outcome */
PetscErrorCode HylcMaterialWriteBytes_Private(HylcMaterial m, const char path[], const char what[], const void *bytes, size_t len)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)m);
  PetscMPIInt rank;
  int         err = 0;
  char        tmp[PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  PetscCheck(strlen(path) + 5 <= sizeof(tmp), comm, PETSC_ERR_ARG_OUTOFRANGE, "Output path too long: %s", path);
  snprintf(tmp, sizeof(tmp), "%s.tmp", path);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    FILE *fp = fopen(tmp, "wb");
    if (!fp)
      err = errno ? errno : EIO;
    else {
      if (len && fwrite(bytes, 1, len, fp) != len) err = errno ? errno : EIO;
      if (!err && fflush(fp)) err = errno ? errno : EIO;
      if (!err && fsync(fileno(fp))) err = errno ? errno : EIO;
      if (fclose(fp) && !err) err = errno ? errno : EIO;
      if (!err && rename(tmp, path)) err = errno ? errno : EIO;
      if (err)
        remove(tmp);
      else
        HylcSyncParentDirectory(path);
    }
  }
  PetscCallMPI(MPI_Bcast(&err, 1, MPI_INT, 0, comm));
  PetscCheck(!err, comm, PETSC_ERR_FILE_WRITE, "Cannot write the %s file '%s': %s", what, path, strerror(err));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialWriteJSON - Writes the material as ARCSim-HYLC JSON, exactly as python's
  json.dumps(d, indent=2) (no final newline, shortest round-trip doubles), so that load + write
  reproduces the paper's files byte for byte. Collective; rank 0 writes atomically (path.tmp + rename).
@*/
PetscErrorCode HylcMaterialWriteJSON(HylcMaterial m, const char path[])
{
  char          *text;
  size_t         len;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCall(PetscLogEventBegin(HYLC_MaterialWrite, m, 0, 0, 0));
  PetscCall(HylcMaterialFormatJSON_Private(m, &text, &len));
  ierr = HylcMaterialWriteBytes_Private(m, path, "JSON material", text, len);
  PetscCall(PetscFree(text));
  PetscCall(ierr);
  PetscCall(PetscLogEventEnd(HYLC_MaterialWrite, m, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialWriteHDF5 - Writes the material as HDF5 (docs/material.md), with provenance and
  optionsText (NULL: the whole options database). Collective: every rank builds the file image in
  memory; rank 0 writes it atomically (path.tmp + rename).
@*/
PetscErrorCode HylcMaterialWriteHDF5(HylcMaterial m, const char path[], const char optionsText[])
{
  void          *image;
  size_t         len;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCall(PetscLogEventBegin(HYLC_MaterialWrite, m, 0, 0, 0));
  PetscCall(HylcMaterialFormatHDF5_Private(m, optionsText, &image, &len));
  ierr = HylcMaterialWriteBytes_Private(m, path, "HDF5 material", image, len);
  PetscCall(PetscFree(image));
  PetscCall(ierr);
  PetscCall(PetscLogEventEnd(HYLC_MaterialWrite, m, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
