#pragma once
/* Private definition of HylcMaterial: only src/ (and white-box tests) may include this. */
#include <hylc/material.h>
#include <petsc/private/petscimpl.h>

struct _HylcMaterialOps {
  PetscErrorCode (*view)(HylcMaterial, PetscViewer);
};

struct _p_HylcMaterial {
  PETSCHEADER(struct _HylcMaterialOps);
  PetscReal    density;  /* area density rho_A (kg/m^2) */
  PetscReal    scale[5]; /* strain scale sigma_0..4 */
  PetscInt     shift[5]; /* the JSON's informational strain shift */
  PetscReal    C0;       /* constant (J/m^2) */
  PetscBool    has1[HYLC_MATERIAL_N1D], has2[HYLC_MATERIAL_N2D];
  HylcSpline1D t1[HYLC_MATERIAL_N1D]; /* term k at index k */
  HylcSpline2D t2[HYLC_MATERIAL_N2D]; /* pair at its index in HylcMaterialPairs */
  /* evaluator: below sw (table units) the bending divided differences of a term use the
     piecewise-polynomial form (docs/material.md); ih = (n - 1) / (t[n-1] - t[0]) of each knot vector
     is the first guess of the interval search */
  PetscReal sw1[HYLC_MATERIAL_N1D], sw2[HYLC_MATERIAL_N2D];
  PetscReal ih1[HYLC_MATERIAL_N1D], ihu[HYLC_MATERIAL_N2D], ihv[HYLC_MATERIAL_N2D];
  char      source[PETSC_MAX_PATH_LEN]; /* file it was loaded from ("" if built in memory) */
};

/* The contents of a material file as read by the JSON and HDF5 parsers, before they are installed. */
typedef struct {
  const char  *name; /* file name, for messages */
  MPI_Comm     comm;
  PetscReal    density, scale[5], C0;
  PetscInt     shift[5];
  PetscInt     n1, n2; /* terms read so far */
  HylcSpline1D s1[HYLC_MATERIAL_N1D];
  HylcSpline2D s2[HYLC_MATERIAL_N2D];
} HylcMaterialDoc;
/* empty document for file 'name' of material m (strain shift [1,0,1,0,0]) */
PETSC_INTERN void HylcMaterialDocInit(HylcMaterialDoc *, HylcMaterial, const char name[]);
/* frees the term arrays */
PETSC_INTERN void HylcMaterialDocFree(HylcMaterialDoc *);
/* replaces the material's contents by the document (validated by the Set functions), then frees it */
PETSC_INTERN PetscErrorCode HylcMaterialDocInstall(HylcMaterial, HylcMaterialDoc *);

/* JSON (src/material/json.c) */
PETSC_INTERN PetscErrorCode HylcMaterialParseJSON_Private(HylcMaterial, const char name[], const char *text, size_t len);
PETSC_INTERN PetscErrorCode HylcMaterialFormatJSON_Private(HylcMaterial, char **text, size_t *len);
/* HDF5 (src/material/h5.c): parse a file image; build one */
PETSC_INTERN PetscErrorCode HylcMaterialParseHDF5_Private(HylcMaterial, const char name[], const void *image, size_t len);
PETSC_INTERN PetscErrorCode HylcMaterialFormatHDF5_Private(HylcMaterial, const char optionsText[], void **image, size_t *len);
/* writes len bytes to path atomically (path.tmp, fsync, rename); rank 0 writes, all ranks return its result */
PETSC_INTERN PetscErrorCode HylcMaterialWriteBytes_Private(HylcMaterial, const char path[], const char what[], const void *bytes, size_t len);

/* Python's repr() of a double (shortest round-trip digits; "1e-05", "200.0", "-0.0"): what json.dumps
   writes. buf needs 32 characters. Returns buf. */
PETSC_INTERN const char *HylcFormatDoubleRepr(double, char buf[32]);
