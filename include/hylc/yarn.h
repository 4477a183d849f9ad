#pragma once
/* HylcYarnModel: the material and contact parameters of the yarns (docs/method.md §3.2, §4, §11).
   A plain struct with options; every value has a documented default (docs/method.md). */
#include <hylc/sys.h>
#include <hylc/rod.h>
#include <petscviewer.h>

typedef enum {
  HYLC_CONTACT_QUADRATURE = 0, /* Kaldor's penalty integrated over both segments (Gauss-Legendre) */
  HYLC_CONTACT_CLOSEST    = 1  /* one closest-point sample per segment pair */
} HylcContactType;

typedef struct {
  PetscReal               E;             /* bending Young's modulus (Pa) */
  PetscReal               Es;            /* stretching modulus (Pa); <= 0 means E */
  PetscReal               G;             /* shear modulus (Pa); <= 0 means E/2.5 */
  PetscReal               kc;            /* contact stiffness (N/m); <= 0 means 0.7 E r */
  PetscReal               radius;        /* > 0 overrides the pattern's yarn radius (m) */
  PetscInt                contactPoints; /* Gauss points per segment for the quadrature contact */
  HylcContactType         contactType;   /* quadrature (default) or closest point */
  PetscReal               excludeArc;    /* same-yarn pairs closer than this rest arc (units of r) do not interact */
  HylcRodCurvatureVariant curvature;     /* averaged-frame (default, matches .pyp RK) or per-edge */
} HylcYarnModel;

/* Resolved constants for a yarn of radius r. */
typedef struct {
  PetscReal r, ks, B, beta, kc, E, Es, G;
} HylcYarnConstants;

PETSC_EXTERN PetscErrorCode HylcYarnModelDefault(HylcYarnModel *);
/* Options (prefix "-yarn_"): -yarn_E, -yarn_Es, -yarn_G, -yarn_kc, -yarn_radius, -yarn_contact_points,
   -yarn_contact_type quadrature|closest, -yarn_exclude_arc, -yarn_curvature averaged|per_edge. Collective. */
PETSC_EXTERN PetscErrorCode HylcYarnModelSetFromOptions(MPI_Comm, const char[], HylcYarnModel *);
/* Constants for a pattern radius r (the override applies when set). Not collective. */
PETSC_EXTERN PetscErrorCode HylcYarnModelGetConstants(const HylcYarnModel *, PetscReal, HylcYarnConstants *);
PETSC_EXTERN PetscErrorCode HylcYarnModelView(const HylcYarnModel *, PetscReal, PetscViewer);

/* the energy parts of a yarn tile (stretch, bend, twist, contact), also a mask of the terms to evaluate
   (HylcPeriodicEvaluate; the reference HylcTile of tests/support) */
enum { HYLC_TERM_STRETCH = 1, HYLC_TERM_BEND = 2, HYLC_TERM_TWIST = 4, HYLC_TERM_CONTACT = 8, HYLC_TERM_ALL = 15 };
