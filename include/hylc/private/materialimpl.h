#pragma once
/* Private definition of HylcMaterial: only src/ (and white-box tests) may include this.
   HylcMaterial is a PETSc object around a hylcmat table (include/hylcmat.h, src/hylcmat/), which holds
   the contents, validates them, reads the files and evaluates the model: one implementation. The
   fields below other than hm are read-only mirrors of the table, refreshed by every function that
   changes it (HylcMaterialSync_Private), so that the getters and the writers can use PETSc types. */
#include <hylc/material.h>
#include <hylcmat.h>
#include <petsc/private/petscimpl.h>

struct _HylcMaterialOps {
  PetscErrorCode (*view)(HylcMaterial, PetscViewer);
};

struct _p_HylcMaterial {
  PETSCHEADER(struct _HylcMaterialOps);
  hylcmat     *hm;       /* the table (owned) */
  PetscReal    density;  /* mirrors: area density rho_A (kg/m^2) */
  PetscReal    scale[5]; /* strain scale sigma_0..4 */
  PetscInt     shift[5]; /* the JSON's informational strain shift */
  PetscReal    C0;       /* constant (J/m^2) */
  PetscBool    has1[HYLC_MATERIAL_N1D], has2[HYLC_MATERIAL_N2D];
  HylcSpline1D t1[HYLC_MATERIAL_N1D];      /* term k at index k; arrays owned by hm */
  HylcSpline2D t2[HYLC_MATERIAL_N2D];      /* pair at its index in HylcMaterialPairs; arrays owned by hm */
  char         source[PETSC_MAX_PATH_LEN]; /* file it was loaded from ("" if built in memory) */
};

/* refreshes the mirrors from m->hm */
PETSC_INTERN void HylcMaterialSync_Private(HylcMaterial);
/* a hylcmat error code as a PetscErrorCode (PETSC_ERR_USER_INPUT, PETSC_ERR_FILE_OPEN, ...) */
PETSC_INTERN PetscErrorCode HylcMaterialErrorCode_Private(int);

/* JSON writer (src/material/json.c) */
PETSC_INTERN PetscErrorCode HylcMaterialFormatJSON_Private(HylcMaterial, char **text, size_t *len);
/* HDF5 writer (src/material/h5.c): build a file image */
PETSC_INTERN PetscErrorCode HylcMaterialFormatHDF5_Private(HylcMaterial, const char optionsText[], void **image, size_t *len);
/* writes len bytes to path atomically (path.tmp, fsync, rename); rank 0 writes, all ranks return its result */
PETSC_INTERN PetscErrorCode HylcMaterialWriteBytes_Private(HylcMaterial, const char path[], const char what[], const void *bytes, size_t len);

/* Python's repr() of a double (shortest round-trip digits; "1e-05", "200.0", "-0.0"): what json.dumps
   writes (hylcmat_format_double). buf needs 32 characters. Returns buf. */
PETSC_INTERN const char *HylcFormatDoubleRepr(double, char buf[32]);
