/* HylcMaterial: object lifecycle, contents (validated setters and getters), options, viewer, and the
   file dispatch (JSON or HDF5 by content; atomic writes by rank 0). */
#include <hylc/options.h>
#include <hylc/private/materialimpl.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

PetscInt HylcMaterialPairIndex(PetscInt k0, PetscInt k1) { return HylcPairIndex((int)k0, (int)k1); }

/* a number for messages and views (C printf: PETSc's appends '.' to integral %g values) */
static const char *G(char buf[32], PetscReal v)
{
  snprintf(buf, 32, "%.6g", (double)v);
  return buf;
}

static const char *const ExtNames[] = {"linear", "constant", "zero"};

PetscClassId  HYLC_MATERIAL_CLASSID;
PetscLogEvent HYLC_MaterialLoad, HYLC_MaterialWrite;

static PetscBool HylcMaterialPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcMaterialFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcMaterialPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialInitializePackage - Registers the class id HylcMaterial and its log events (MATERIAL_Load, MATERIAL_Write). Called by
  HylcMaterialCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcMaterialInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcMaterialPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcMaterialPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcMaterial", &HYLC_MATERIAL_CLASSID));
  PetscCall(PetscLogEventRegister("MATERIAL_Load", HYLC_MATERIAL_CLASSID, &HYLC_MaterialLoad));
  PetscCall(PetscLogEventRegister("MATERIAL_Write", HYLC_MATERIAL_CLASSID, &HYLC_MaterialWrite));
  PetscCall(PetscRegisterFinalize(HylcMaterialFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialCreate - Creates an empty material model: no terms (Psi = 0), density 0, strain scale 1,
  strain shift 1,0,1,0,0. Collective.
@*/
PetscErrorCode HylcMaterialCreate(MPI_Comm comm, HylcMaterial *mat)
{
  HylcMaterial m;

  PetscFunctionBegin;
  PetscValidPointer(mat, 2);
  PetscCall(HylcMaterialInitializePackage());
  PetscCall(PetscHeaderCreate(m, HYLC_MATERIAL_CLASSID, "HylcMaterial", "Homogenized cloth material model", "Material", comm, HylcMaterialDestroy, HylcMaterialView));
  PetscCheck(hylcmat_create(&m->hm) == HYLCMAT_OK, comm, PETSC_ERR_MEM, "Cannot allocate a material table");
  PetscCall(HylcMaterialReset(m));
  *mat = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

void HylcMaterialSync_Private(HylcMaterial m)
{
  double s5[5];
  int    i5[5];

  m->density = hylcmat_density(m->hm);
  m->C0      = hylcmat_constant(m->hm);
  hylcmat_strain_scale(m->hm, s5);
  hylcmat_strain_shift(m->hm, i5);
  for (int k = 0; k < 5; k++) {
    m->scale[k] = s5[k];
    m->shift[k] = i5[k];
  }
  for (int k = 0; k < HYLC_MATERIAL_N1D; k++) {
    hylcmat_term1d t;
    HylcSpline1D  *v = &m->t1[k];
    m->has1[k]       = hylcmat_term1d_get(m->hm, k, &t) ? PETSC_TRUE : PETSC_FALSE;
    memset(v, 0, sizeof(*v));
    if (!m->has1[k]) continue;
    v->k   = t.k;
    v->n   = t.n;
    v->ext = (HylcSplineExt)t.ext;
    v->t   = (PetscReal *)t.t;
    v->p   = (PetscReal *)t.p;
    v->m   = (PetscReal *)t.m;
  }
  for (int q = 0; q < HYLC_MATERIAL_N2D; q++) {
    hylcmat_term2d t;
    HylcSpline2D  *v = &m->t2[q];
    m->has2[q]       = hylcmat_term2d_get(m->hm, (int)HylcMaterialPairs[q][0], (int)HylcMaterialPairs[q][1], &t) ? PETSC_TRUE : PETSC_FALSE;
    memset(v, 0, sizeof(*v));
    if (!m->has2[q]) continue;
    v->k0  = t.k0;
    v->k1  = t.k1;
    v->nu  = t.nu;
    v->nv  = t.nv;
    v->ext = (HylcSplineExt)t.ext;
    v->tu  = (PetscReal *)t.tu;
    v->tv  = (PetscReal *)t.tv;
    v->p   = (PetscReal *)t.p;
    v->mu  = (PetscReal *)t.mu;
    v->mv  = (PetscReal *)t.mv;
    v->muv = (PetscReal *)t.muv;
  }
}

PetscErrorCode HylcMaterialErrorCode_Private(int code)
{
  switch (code) {
  case HYLCMAT_OK:
    return PETSC_SUCCESS;
  case HYLCMAT_ERR_OPEN:
    return PETSC_ERR_FILE_OPEN;
  case HYLCMAT_ERR_READ:
    return PETSC_ERR_FILE_READ;
  case HYLCMAT_ERR_FORMAT:
    return PETSC_ERR_USER_INPUT;
  case HYLCMAT_ERR_CONTENT:
    return PETSC_ERR_FILE_UNEXPECTED;
  case HYLCMAT_ERR_MEMORY:
    return PETSC_ERR_MEM;
  case HYLCMAT_ERR_ARG:
    return PETSC_ERR_ARG_OUTOFRANGE;
  case HYLCMAT_ERR_NO_HDF5:
    return PETSC_ERR_SUP;
  case HYLCMAT_ERR_HDF5:
    return PETSC_ERR_LIB;
  case HYLCMAT_ERR_NOCONV:
    return PETSC_ERR_NOT_CONVERGED;
  default:
    return PETSC_ERR_PLIB;
  }
}

/* CallHM(comm, call with err, sizeof(err)): a hylcmat error becomes a PETSc error with its message */
#define CallHM(comm, ...)                                                                                           \
  do {                                                                                                              \
    const int hm_r_ = (__VA_ARGS__);                                                                                \
    if (hm_r_) SETERRQ((comm), HylcMaterialErrorCode_Private(hm_r_), "%s", err[0] ? err : hylcmat_strerror(hm_r_)); \
  } while (0)

/*@C
  HylcMaterialReset - Removes every term; density 0, strain scale 1, strain shift 1,0,1,0,0, constant 0.
  Not collective.
@*/
PetscErrorCode HylcMaterialReset(HylcMaterial m)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  hylcmat_reset(m->hm);
  HylcMaterialSync_Private(m);
  m->source[0] = 0;
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
  hylcmat_free((*m)->hm);
  (*m)->hm = NULL;
  PetscCall(PetscHeaderDestroy(m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSetOptionsPrefix - Sets the prefix of the material's options (-<prefix>material_*).

  Not collective

  Input Parameters:
+ m      - the material
- prefix - the prefix (NULL: none)

  Level: intermediate

.seealso: HylcMaterialSetFromOptions()
@*/
PetscErrorCode HylcMaterialSetOptionsPrefix(HylcMaterial m, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)m, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGetOptionsFile - The material file that the material's option -material_file names (after the
  material's prefix), which HylcMaterialSetFromOptions() will load; for a program that checks all its files
  before any work (include/hylc/files.h). Loads nothing.

  Not collective

  Input Parameters:
+ m   - the material
- len - the size of file

  Output Parameters:
+ file - the path ("" if the option is not given or has no value)
- set  - whether the option is given

  Level: intermediate

.seealso: HylcMaterialSetFromOptions(), HylcMaterialLoad()
@*/
PetscErrorCode HylcMaterialGetOptionsFile(HylcMaterial m, char file[], size_t len, PetscBool *set)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidCharPointer(file, 2);
  PetscValidBoolPointer(set, 4);
  file[0] = 0;
  PetscCall(PetscOptionsGetString(((PetscObject)m)->options, ((PetscObject)m)->prefix, "-material_file", file, len, set));
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
  PetscCall(HylcOptionsString("-material_file", "Material model to load: ARCSim-HYLC JSON or hylc HDF5 (recognized by content)", "HylcMaterialLoad", m->source, file, sizeof(file), &flg));
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
    PetscCall(PetscViewerASCIIPrintf(viewer, "2D %-8s %2" PetscInt_FMT " x %2" PetscInt_FMT " knots on [%s, %s] x [%s, %s], %s extrapolation\n", HylcMaterialTermNames2D[q], s->nu, s->nv, G(b[0], s->tu[0]), G(b[1], s->tu[s->nu - 1]),
                                     G(b[2], s->tv[0]), G(b[3], s->tv[s->nv - 1]), ExtNames[s->ext]));
  }
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialViewFromOptions - Views the material if the option name is given (PetscObjectViewFromOptions()).

  Collective

  Input Parameters:
+ m    - the material
. obj  - an object whose prefix is used (NULL: the material's)
- name - the option, e.g. "-material_view"

  Level: intermediate

.seealso: HylcMaterialView()
@*/
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

/*@C
  HylcMaterialSetDensity - Sets the area density of the material (checked by hylcmat_set_density()).

  Not collective

  Input Parameters:
+ m   - the material
- rho - the area density (kg/m^2)

  Level: intermediate

.seealso: HylcMaterialGetDensity()
@*/
PetscErrorCode HylcMaterialSetDensity(HylcMaterial m, PetscReal rho)
{
  char err[512] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  CallHM(PetscObjectComm((PetscObject)m), hylcmat_set_density(m->hm, (double)rho, err, sizeof(err)));
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGetDensity - The area density of the material.

  Not collective

  Input Parameter:
. m - the material

  Output Parameter:
. rho - the area density (kg/m^2)

  Level: intermediate

.seealso: HylcMaterialSetDensity()
@*/
PetscErrorCode HylcMaterialGetDensity(HylcMaterial m, PetscReal *rho)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  *rho = m->density;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSetStrainScale - Sets the strain scales of the tables, one per coordinate (sx, sa, sy, II00,
  II11; finite and positive with a finite inverse).

  Not collective

  Input Parameters:
+ m     - the material
- scale - the five scales (copied)

  Level: intermediate

.seealso: HylcMaterialGetStrainScale()
@*/
PetscErrorCode HylcMaterialSetStrainScale(HylcMaterial m, const PetscReal scale[5])
{
  char   err[512] = "";
  double s5[5];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (int k = 0; k < 5; k++) s5[k] = (double)scale[k];
  CallHM(PetscObjectComm((PetscObject)m), hylcmat_set_strain_scale(m->hm, s5, err, sizeof(err)));
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGetStrainScale - The strain scales of the tables, one per coordinate.

  Not collective

  Input Parameter:
. m - the material

  Output Parameter:
. scale - the five scales

  Level: intermediate

.seealso: HylcMaterialSetStrainScale()
@*/
PetscErrorCode HylcMaterialGetStrainScale(HylcMaterial m, PetscReal scale[5])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < 5; k++) scale[k] = m->scale[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSetStrainShift - Sets the JSON's informational "strain shift" (not used by the evaluator; kept
  so that files round-trip).

  Not collective

  Input Parameters:
+ m     - the material
- shift - the five values (default 1, 0, 1, 0, 0)

  Level: developer

.seealso: HylcMaterialGetStrainShift()
@*/
PetscErrorCode HylcMaterialSetStrainShift(HylcMaterial m, const PetscInt shift[5])
{
  int i5[5];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (int k = 0; k < 5; k++) i5[k] = (int)shift[k];
  hylcmat_set_strain_shift(m->hm, i5);
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGetStrainShift - The JSON's informational "strain shift".

  Not collective

  Input Parameter:
. m - the material

  Output Parameter:
. shift - the five values

  Level: developer

.seealso: HylcMaterialSetStrainShift()
@*/
PetscErrorCode HylcMaterialGetStrainShift(HylcMaterial m, PetscInt shift[5])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  for (PetscInt k = 0; k < 5; k++) shift[k] = m->shift[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSetConstant - Sets the constant term of the energy density.

  Not collective

  Input Parameters:
+ m - the material
- c - the constant (J/m^2, finite)

  Level: intermediate

.seealso: HylcMaterialGetConstant()
@*/
PetscErrorCode HylcMaterialSetConstant(HylcMaterial m, PetscReal c)
{
  char err[512] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  CallHM(PetscObjectComm((PetscObject)m), hylcmat_set_constant(m->hm, (double)c, err, sizeof(err)));
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGetConstant - The constant term of the energy density.

  Not collective

  Input Parameter:
. m - the material

  Output Parameter:
. c - the constant (J/m^2)

  Level: intermediate

.seealso: HylcMaterialSetConstant()
@*/
PetscErrorCode HylcMaterialGetConstant(HylcMaterial m, PetscReal *c)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  *c = m->C0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSet1D - Sets (copies) the 1D term s->k, replacing one of the same k. Checks k in 0..4,
  n >= 2, strictly increasing finite knots, finite values and slopes, a known extrapolation mode
  (hylcmat_set_term1d). Not collective (call it with the same data on every rank).
@*/
PetscErrorCode HylcMaterialSet1D(HylcMaterial m, const HylcSpline1D *s)
{
  char           err[512] = "";
  hylcmat_term1d t;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidPointer(s, 2);
  t.k   = (int)s->k;
  t.n   = (int)s->n;
  t.ext = (int)s->ext;
  t.t   = s->t;
  t.p   = s->p;
  t.m   = s->m;
  CallHM(PetscObjectComm((PetscObject)m), hylcmat_set_term1d(m->hm, &t, err, sizeof(err)));
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSet2D - Sets (copies) the 2D term (s->k0, s->k1), replacing one of the same pair. Checks
  that the pair is one of HylcMaterialPairs, nu, nv >= 2, strictly increasing finite knots, finite node
  data (hylcmat_set_term2d). Not collective.
@*/
PetscErrorCode HylcMaterialSet2D(HylcMaterial m, const HylcSpline2D *s)
{
  char           err[512] = "";
  hylcmat_term2d t;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidPointer(s, 2);
  t.k0  = (int)s->k0;
  t.k1  = (int)s->k1;
  t.nu  = (int)s->nu;
  t.nv  = (int)s->nv;
  t.ext = (int)s->ext;
  t.tu  = s->tu;
  t.tv  = s->tv;
  t.p   = s->p;
  t.mu  = s->mu;
  t.mv  = s->mv;
  t.muv = s->muv;
  CallHM(PetscObjectComm((PetscObject)m), hylcmat_set_term2d(m->hm, &t, err, sizeof(err)));
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialSet3D - Sets a 3D term f_k0k1k2 (hylc's extension of the paper's model, a tricubic Hermite spline
  in the normalized strains; docs/material.md, "Three-strain terms"), replacing one of the same triple.

  Not collective

  Input Parameters:
+ m - the material
- t - the term (copied; checked as hylcmat_set_term3d(): a triple of the model, strictly increasing knots,
      finite values)

  Level: intermediate

.seealso: HylcMaterialGet3D(), HylcMaterialSet2D()
@*/
PetscErrorCode HylcMaterialSet3D(HylcMaterial m, const hylcmat_term3d *t)
{
  char err[512] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidPointer(t, 2);
  CallHM(PetscObjectComm((PetscObject)m), hylcmat_set_term3d(m->hm, t, err, sizeof(err)));
  HylcMaterialSync_Private(m);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGet3D - The 3D term of the triple (k0, k1, k2) (include/hylc/strain.h, HylcTripleCoords).

  Not collective

  Input Parameters:
+ m  - the material
- k0, k1, k2 - the triple

  Output Parameters:
+ t   - the term (pointers owned by the material, valid until it changes)
- has - PETSC_FALSE when the material has no such term

  Level: intermediate

.seealso: HylcMaterialSet3D()
@*/
PetscErrorCode HylcMaterialGet3D(HylcMaterial m, PetscInt k0, PetscInt k1, PetscInt k2, hylcmat_term3d *t, PetscBool *has)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidPointer(t, 5);
  PetscValidBoolPointer(has, 6);
  *has = (PetscBool)hylcmat_term3d_get(m->hm, (int)k0, (int)k1, (int)k2, t);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGet1D - The 1D term of coordinate k (include/hylc/strain.h: 0 sx, 1 sa, 2 sy, 3 II00, 4 II11).

  Not collective

  Input Parameters:
+ m - the material
- k - the coordinate, 0..4

  Output Parameter:
. s - the spline (owned by the material, valid until it changes), NULL for an absent term

  Level: intermediate

.seealso: HylcMaterialSet1D(), HylcMaterialGet2D()
@*/
PetscErrorCode HylcMaterialGet1D(HylcMaterial m, PetscInt k, const HylcSpline1D **s)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscCheck(k >= 0 && k < HYLC_MATERIAL_N1D, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "1D term k = %" PetscInt_FMT " is out of range 0..4", k);
  *s = m->has1[k] ? &m->t1[k] : NULL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialGet2D - The 2D term of the pair (k0, k1) (include/hylc/strain.h).

  Not collective

  Input Parameters:
+ m  - the material
. k0 - the first coordinate of the pair
- k1 - the second (k0 < k1; a pair that is no term of the model is an error)

  Output Parameter:
. s - the spline (owned by the material, valid until it changes), NULL for an absent term

  Level: intermediate

.seealso: HylcMaterialSet2D(), HylcMaterialGet1D()
@*/
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

/*@C
  HylcMaterialLoadFromString - Parses a JSON material (formats.md §2) from text; name is used in
  messages. Replaces the contents. Collective: every rank passes the same text.
@*/
PetscErrorCode HylcMaterialLoadFromString(HylcMaterial m, const char name[], const char text[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  {
    hylcmat *hm        = NULL;
    char     err[1024] = "";
    int      r         = hylcmat_load_memory(name, text, strlen(text), &hm, err, sizeof(err));
    if (r) SETERRQ(PetscObjectComm((PetscObject)m), HylcMaterialErrorCode_Private(r), "%s", err[0] ? err : hylcmat_strerror(r));
    hylcmat_free(m->hm);
    m->hm = hm;
    HylcMaterialSync_Private(m);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialLoad - Reads a material file, ARCSim-HYLC JSON or hylc HDF5 (docs/material.md), recognized
  by content (the HDF5 signature), and replaces the contents. Errors name the file and, for JSON, the line
  and the key. Collective: rank 0 reads the file and broadcasts its bytes; every rank parses them.
@*/
PetscErrorCode HylcMaterialLoad(HylcMaterial m, const char path[])
{
  MPI_Comm    comm;
  PetscMPIInt rank;
  long        len = 0;
  int         err = 0;
  char       *bytes;
  FILE       *fp = NULL;

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
  {
    hylcmat *hm        = NULL;
    char     err[1024] = "";
    int      r         = hylcmat_load_memory(path, bytes, (size_t)len, &hm, err, sizeof(err));
    PetscCall(PetscFree(bytes));
    /* an HDF5 call that fails on the user's file (the message names the call and the file) is a file the
       reader cannot use, not a defect: one line */
    if (r) SETERRQ(comm, r == HYLCMAT_ERR_HDF5 ? PETSC_ERR_FILE_UNEXPECTED : HylcMaterialErrorCode_Private(r), "%s", err[0] ? err : hylcmat_strerror(r));
    hylcmat_free(m->hm);
    m->hm = hm;
    HylcMaterialSync_Private(m);
  }
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
