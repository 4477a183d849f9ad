#pragma once
/* HylcMaterial: the homogenized material model of a pattern -- the spline tables of (S26) -- and its
   evaluation Psi(s), grad Psi, Hessian Psi with respect to the six strains s = (sx, sa, sy, II00, II01,
   II11).  Files: the ARCSim-HYLC JSON (../shared/docs/formats.md §2; byte-compatible with the paper's
   tables) and HDF5 (docs/material.md).

   Model (formats.md §3), with S_k = s_k / sigma_k (k < 3), the eigenvalues l1 >= l2 of
   II = [[II00, II01], [II01, II11]] and c2 = cos^2 of the angle between the x axis and the l1
   eigenvector:
     Psi = C0 + sum_{k<3} f_k(S_k)
         + c2 f_3(l1/sigma_3) + (1-c2) f_3(l2/sigma_3) + c2 f_4(l2/sigma_4) + (1-c2) f_4(l1/sigma_4)
         + sum_{in-plane pairs} f_ij(S_i, S_j)
         + sum_{i<3} [c2 f_i3(S_i, l1/sigma_3) + (1-c2) f_i3(S_i, l2/sigma_3)]
         + sum_{i<3} [c2 f_i4(S_i, l2/sigma_4) + (1-c2) f_i4(S_i, l1/sigma_4)]
   Terms that are absent contribute 0. */
#include <hylc/sys.h>
#include <hylc/spline.h>
#include <hylc/strain.h>
#include <hylcmat.h>
#include <petscviewer.h>

typedef struct _p_HylcMaterial *HylcMaterial;

/* Registration: the class id and log events of this stage (HylcMaterialInitializePackage(), called by HylcMaterialCreate()). */
PETSC_EXTERN PetscClassId   HYLC_MATERIAL_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_MaterialLoad, HYLC_MaterialWrite;
PETSC_EXTERN PetscErrorCode HylcMaterialInitializePackage(void);

/* The terms are the shared vocabulary's (include/hylc/strain.h): 1D terms k = 0 sx, 1 sa, 2 sy, 3 x-bending
   (II00), 4 y-bending (II11); the 2D terms (k0, k1) in the order of the JSON tables and of the sampling plan,
   (0,1) (0,2) (0,3) (0,4) (1,2) (1,3) (1,4) (2,3) (2,4). */
#define HYLC_MATERIAL_N1D HYLC_NCOORD
#define HYLC_MATERIAL_N2D HYLC_NPAIR
#define HylcMaterialPairs HylcPairCoords

PETSC_EXTERN PetscErrorCode HylcMaterialCreate(MPI_Comm, HylcMaterial *);
PETSC_EXTERN PetscErrorCode HylcMaterialDestroy(HylcMaterial *);
PETSC_EXTERN PetscErrorCode HylcMaterialSetOptionsPrefix(HylcMaterial, const char[]);
PETSC_EXTERN PetscErrorCode HylcMaterialSetFromOptions(HylcMaterial);
/* The file the material's -material_file option names (after its prefix), which HylcMaterialSetFromOptions()
   loads: for a program that checks its files before any work. Not collective. */
PETSC_EXTERN PetscErrorCode HylcMaterialGetOptionsFile(HylcMaterial, char[], size_t, PetscBool *);
PETSC_EXTERN PetscErrorCode HylcMaterialView(HylcMaterial, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcMaterialViewFromOptions(HylcMaterial, PetscObject, const char[]);

/* Files. Load recognizes JSON and HDF5 by content; errors name the file and, for JSON, the line and
   key. Collective (rank 0 reads and broadcasts). Write: rank 0 writes atomically (path.tmp + rename).
   WriteJSON produces exactly the layout of the paper's tables (python json.dumps(indent=2), no final
   newline, shortest round-trip doubles), so load + write reproduces them byte for byte.
   WriteHDF5 stores optionsText (NULL: the global options database) as provenance. */
PETSC_EXTERN PetscErrorCode HylcMaterialLoad(HylcMaterial, const char path[]);
PETSC_EXTERN PetscErrorCode HylcMaterialWriteJSON(HylcMaterial, const char path[]);
PETSC_EXTERN PetscErrorCode HylcMaterialWriteHDF5(HylcMaterial, const char path[], const char optionsText[]);

/* Contents. The Set functions copy their arguments; Set1D/Set2D replace a term of the same k or (k0, k1)
   and check sizes, strictly increasing knots and finite values. Get1D/Get2D return NULL for an
   absent term (pointers owned by the material, valid until it changes). */
PETSC_EXTERN PetscErrorCode HylcMaterialSetDensity(HylcMaterial, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMaterialGetDensity(HylcMaterial, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcMaterialSetStrainScale(HylcMaterial, const PetscReal[5]);
PETSC_EXTERN PetscErrorCode HylcMaterialGetStrainScale(HylcMaterial, PetscReal[5]);
PETSC_EXTERN PetscErrorCode HylcMaterialSetConstant(HylcMaterial, PetscReal);
PETSC_EXTERN PetscErrorCode HylcMaterialGetConstant(HylcMaterial, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcMaterialSet1D(HylcMaterial, const HylcSpline1D *);
PETSC_EXTERN PetscErrorCode HylcMaterialGet1D(HylcMaterial, PetscInt k, const HylcSpline1D **);
PETSC_EXTERN PetscErrorCode HylcMaterialSet2D(HylcMaterial, const HylcSpline2D *);
PETSC_EXTERN PetscErrorCode HylcMaterialGet2D(HylcMaterial, PetscInt k0, PetscInt k1, const HylcSpline2D **);
/* The 3D terms (hylc's extension of the paper's model, docs/material.md "Three-strain terms"), through
   hylcmat's own struct: Set3D copies and checks as hylcmat_set_term3d(); Get3D returns PETSC_FALSE for an
   absent term (pointers owned by the material). */
PETSC_EXTERN PetscErrorCode HylcMaterialSet3D(HylcMaterial, const hylcmat_term3d *);
PETSC_EXTERN PetscErrorCode HylcMaterialGet3D(HylcMaterial, PetscInt k0, PetscInt k1, PetscInt k2, hylcmat_term3d *, PetscBool *);

/* Psi(s) in J/m^2; grad (may be NULL) = dPsi/ds (6), hess (may be NULL) = d2Psi/ds2 (6x6 row-major,
   symmetric). Exact limits at equal eigenvalues of II (finite and continuous where the model is):
   see docs/material.md. Not collective; thread-safe; no allocation. */
PETSC_EXTERN PetscErrorCode HylcMaterialEvaluate(HylcMaterial, const PetscReal s[6], PetscReal *psi, PetscReal grad[6], PetscReal hess[36]);
/* The homogeneous uniaxial tension state (hylcmat_uniaxial(), docs/fabric-uniaxial.md): stretch s along
   x (dir 0) or y (dir 1), the lateral strains minimizing Psi; T = dPsi/ds (N/m). Not collective. */
PETSC_EXTERN PetscErrorCode HylcMaterialUniaxial(HylcMaterial, PetscInt dir, PetscReal s, const PetscReal guess[2], PetscReal *T, PetscReal lateral[2], PetscReal *psi, PetscBool *converged);
PETSC_EXTERN PetscErrorCode HylcMaterialPathState(HylcMaterial, const hylcmat_path *, PetscReal, const PetscReal[], hylcmat_path_result *, PetscBool *);

/* Names of the terms: the shared vocabulary's (include/hylc/strain.h), as the sampling plan's (HylcPlanTermName). */
#define HylcMaterialTermNames1D HylcCoordNames
#define HylcMaterialTermNames2D HylcPairNames
/* Index of (k0, k1) in HylcMaterialPairs, or -1 if the model has no such term. */
PETSC_EXTERN PetscInt HylcMaterialPairIndex(PetscInt k0, PetscInt k1);

/* The JSON's "strain shift" (informational: "sx, sy are 0-centred"; default 1,0,1,0,0; not used by the
   evaluator, kept so that files round-trip). */
PETSC_EXTERN PetscErrorCode HylcMaterialSetStrainShift(HylcMaterial, const PetscInt[5]);
PETSC_EXTERN PetscErrorCode HylcMaterialGetStrainShift(HylcMaterial, PetscInt[5]);
/* Removes every term and resets density, strain scale (1), shift and constant to their defaults. */
PETSC_EXTERN PetscErrorCode HylcMaterialReset(HylcMaterial);
/* Parses a JSON material from text; name is used in messages. Collective: every rank passes the same text. */
PETSC_EXTERN PetscErrorCode HylcMaterialLoadFromString(HylcMaterial, const char name[], const char text[]);

/* A strip cut at angle phi (radians from material x) stretched by s: Psi minimized over the lateral
   stretch and the shear; T = dPsi/ds (N/m); lateral = (lateral strain, shear) (hylcmat_tension(),
   docs/measured-cloth.md). Not collective. */
PETSC_EXTERN PetscErrorCode HylcMaterialTension(HylcMaterial, PetscReal phi, PetscReal s, const PetscReal guess[2], PetscReal *T, PetscReal lateral[2], PetscBool *converged);
/* The material written as a measured-cloth JSON (the least-squares data of hylcmat_measured_fit());
   fit (may be NULL): its 5 figures. Collective; rank 0 writes. */
PETSC_EXTERN PetscErrorCode HylcMaterialWriteMeasured(HylcMaterial, const char path[], PetscReal fit[5]);
