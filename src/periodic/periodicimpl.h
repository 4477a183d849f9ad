#pragma once
/* Private definition of HylcPeriodic (src/periodic/ only): the object, its inline index and matrix helpers
   and the functions shared between its files:
     periodic.c     lifecycle, options, setters, View
     setup.c        ghost extension, elimination maps, reference frames, state, the getters of the set-up
     constraints.c  translation and slide constraints, their reduction to independent rows
     assembly.c     contact pairs, the Hessian's structure (SetCOO), the reduced evaluation
     output.c       the state as a pattern, VTK */
#include <hylc/periodic.h>
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <hylc/rod.h>
#include <petsc/private/hashmapi.h>
#include <petsctime.h>
#include <petsc/private/petscimpl.h>

#define SMAX 8 /* |lattice shift| bound of ghosts */

typedef struct {
  PetscInt  e, f; /* incoming and outgoing full edges */
  PetscInt  v[3]; /* full vertices prev, centre, next */
  PetscReal w;    /* fractional weight */
} BendElem;

struct _HylcPeriodicOps {
  PetscErrorCode (*view)(HylcPeriodic, PetscViewer);
};

struct _p_HylcPeriodic {
  PETSCHEADER(struct _HylcPeriodicOps);
  HylcPattern            pat;
  HylcPatternData        D;
  HylcYarnModel          model;
  HylcYarnConstants      c;
  HylcRodBendTwistParams btpar;
  HylcMidsurface         ms;
  HylcMidsurface         msfd;     /* the midsurface at perturbed strains (strain derivatives at II != 0; created on first use) */
  PetscReal              msbox[4]; /* the box in xi of ms: lo[2], hi[2] */
  PetscReal              z[6];
  HylcSlideConstraint    slide;
  PetscReal              marginFactor; /* contact ghosts: every copy in the neighbouring tiles (0) or those within max(3 r, factor min(px, py)) */
  PetscBool              setup;
  PetscBool              viewed; /* -periodic_view printed for this pattern */
  PetscInt               N;      /* original vertices */
  PetscReal             *xi;     /* reference (xi1, xi2, h) of the originals, recentred */
  /* full vertices: original o, shift s; the first N are the originals */
  PetscInt   nfv, capfv, *fo, *fs;
  PetscReal *T, *d;      /* per full vertex: T (9), d (3) */
  PetscBool *rigidId;    /* T == I exactly */
  PetscHMapI vmap, emap; /* (o, s) -> full vertex / full edge */
  /* full edges: source full vertex (edge leaving o(src) in copy s(src)) and head */
  PetscInt       nfe, capfe, *esrc, *ehead;
  PetscInt       nchain;                /* the chain edges (stretch and bend-twist elements) come first, the contact ghosts after them */
  PetscReal     *et, *ed1, *et0, *ed10; /* frames per chain edge (and saved copy) */
  PetscReal     *sw;                    /* stretch weight per full edge (0: contact-only edge) */
  unsigned char *eghost;                /* edge has no original vertex */
  /* bend/twist elements */
  PetscInt   nbe, capbe;
  BendElem  *be;
  PetscReal *mref, *mref0;
  /* state */
  PetscReal *y, *y0, *x; /* y and the initial guess y0: 4 N; x: 3 per full vertex */
  /* constraints */
  PetscInt   ncons, ndropped; /* independent constraint rows kept, linearly dependent rows dropped */
  PetscReal  crtol;           /* relative tolerance of the dependence test (-periodic_constraint_rtol) */
  PetscReal *A, *dL, *AAtinv;
  PetscInt  *crow; /* the row (before the reduction) of each kept constraint row */
  /* contact */
  HylcBVH      bvh;
  double      *segx;
  HylcPairList cand;
  PetscInt     npairs, cappairs, *pairs; /* pairs that can touch (segments closer than 2 r): full edges i, j */
  PetscInt     ncand, capcand, *cpairs;  /* candidates for the Hessian's structure (closer than 2 pairMargin r) */
  PetscReal   *cw;
  PetscReal    pairMargin;
  PetscReal   *pw;         /* pair weights */
  PetscBool    pairsValid; /* the pair lists are those of the current x (FindPairs is skipped) */
  PetscReal    clearance;  /* min(2 pairMargin r, the smallest distance of a structure pair), set with the lists */
  /* COO */
  PetscInt     ncoo, capcoo, *coopos; /* where each element entry goes in the CSR values of H_y */
  PetscInt    *rowptr, *colind, nnz; /* the CSR structure of H_y: 4x4 blocks of coupled vertices */
  PetscInt     coonpairs, *coopairs; /* the pairs of the current COO structure, a superset of the touching ones */
  PetscReal   *coopw;                /* their weights */
  Mat          cooMat;
  PetscReal   *gfull;  /* when set, the evaluation also accumulates the gradient per full vertex (3 each) here */
  PetscReal   *gtfull; /* ... and dE/dtheta per full chain edge here (the twist of that copy of the edge) */
  /* accumulated wall times (s): evaluations with a Hessian, contact (broadphase + pairs), assembly */
  PetscLogDouble tEval, tContact, tAssemble;
};

static inline PetscInt Key(PetscInt N, PetscInt o, PetscInt s1, PetscInt s2) { return o + N * ((s1 + SMAX) + (2 * SMAX + 1) * (s2 + SMAX)); }

/* reference position (xi1, xi2, h) of full vertex k */
static inline void RefPos(const HylcPeriodic P, PetscInt k, PetscReal xih[3])
{
  const PetscInt o = P->fo[k];
  xih[0]           = P->xi[3 * o] + P->fs[2 * k] * P->D.px;
  xih[1]           = P->xi[3 * o + 1] + P->fs[2 * k + 1] * P->D.py;
  xih[2]           = P->xi[3 * o + 2];
}

static inline void MatT3(const PetscReal M[9], const PetscReal v[3], PetscReal out[3])
{
  for (int i = 0; i < 3; i++) out[i] = M[i] * v[0] + M[3 + i] * v[1] + M[6 + i] * v[2];
}
static inline void Mat3(const PetscReal M[9], const PetscReal v[3], PetscReal out[3])
{
  for (int i = 0; i < 3; i++) out[i] = M[3 * i] * v[0] + M[3 * i + 1] * v[1] + M[3 * i + 2] * v[2];
}

/* the derivatives of A = sqrt(I) = [[X, sa Y], [0, sqrt(1 - sa^2) Y]] (row-major, X = 1 + sx, Y = 1 + sy)
   with respect to sx, sa, sy: dA[4 j .. 4 j + 3] for z_j, j = 0, 1, 2 (docs/method.md §1.1) */
static inline void StretchDerivatives(const PetscReal z[6], PetscReal dA[12])
{
  const PetscReal Y = 1 + z[2], c = z[1], q = PetscSqrtReal(1 - c * c);
  dA[0] = 1, dA[1] = 0, dA[2] = 0, dA[3] = 0;
  dA[4] = 0, dA[5] = Y, dA[6] = 0, dA[7] = -c * Y / q;
  dA[8] = 0, dA[9] = c, dA[10] = 0, dA[11] = q;
}

/* frees everything SetUp built (periodic.c) */
PETSC_INTERN PetscErrorCode HylcPeriodicReset_Private(HylcPeriodic);
/* the constraint rows A, dL and (A A^T)^-1 at the initial guess x0 (3 per full vertex) (constraints.c) */
PETSC_INTERN PetscErrorCode HylcPeriodicSetUpConstraints_Private(HylcPeriodic, const PetscReal *);
/* dc/dz_j at fixed y of the kept constraint rows c = A y - dL for the in-plane strains (II = 0): m x 3,
   row-major (constraints.c) */
PETSC_INTERN PetscErrorCode HylcPeriodicConstraintStrainDerivative_Private(HylcPeriodic, PetscReal[]);
/* the kept constraint residuals c = A y - dL at the state y for the strain of the set-up midsurface ms, the
   rows and their right-hand side rebuilt from ms (the same rows as P's); x0 the deformed initial guess of the
   originals at that strain (3 per original) (constraints.c) */
PETSC_INTERN PetscErrorCode HylcPeriodicConstraintResidualAt_Private(HylcPeriodic, HylcMidsurface, const PetscReal *, const PetscReal[], PetscReal[]);
/* the reduced evaluation with the gradient per full vertex (3 each) and dE/dtheta per full chain edge (assembly.c) */
PETSC_INTERN PetscErrorCode HylcPeriodicEvaluateFull_Private(HylcPeriodic, int, PetscReal[4], PetscReal[], PetscReal[], PetscReal[]);
