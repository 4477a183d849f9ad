#pragma once
/* Private definition of HylcFit: only src/ may include this. */
#include <hylc/fit.h>
#include <hylc/plan.h>
#include <petsc/private/petscimpl.h>

struct _HylcFitOps {
  PetscErrorCode (*view)(HylcFit, PetscViewer);
};

struct _p_HylcFit {
  PETSCHEADER(struct _HylcFitOps);
  /* files */
  char input[PETSC_MAX_PATH_LEN], output[PETSC_MAX_PATH_LEN], json[PETSC_MAX_PATH_LEN];
  /* constants (docs/fit.md) */
  HylcFitFamily     family;
  PetscReal         reg;                                                             /* quasiconvex marching p^x_min */
  HylcFitCompat     compat;                                                          /* paper or authors (docs/method.md §9.1) */
  HylcMonotoneRule  rule;                                                            /* 1D slope limiter */
  PetscBool         quasiconvex;                                                     /* marching on (off: the "noreg" fits) */
  PetscBool         symmetrize;                                                      /* symmetrize in sa */
  PetscBool         zeroCompression;                                                 /* zero-compression rule */
  PetscBool         zeroStrict;                                                      /* ... also muv on the bordering axis line */
  PetscReal         kernel, truncation;                                              /* MLS kernel (fraction of the span), kernel / sigma */
  PetscReal         mlsGrow;                                                         /* kernel growth factor where the MLS is singular (<= 1: error) */
  PetscReal         fdEps;                                                           /* FD width (fraction of the smallest knot spacing) */
  PetscReal         flatTol;                                                         /* 1D: |dp| below this -> flat interval */
  PetscReal         endSlope;                                                        /* boundary slopes at least this, outward */
  PetscInt          nk1;                                                             /* 1D knots of the paper's layout */
  HylcFitKnotLayout knots;                                                           /* 1D knot layout */
  PetscBool         knotsSet;                                                        /* -fit_knots given */
  PetscInt          refine;                                                          /* refined: knots added on each side of 0 */
  PetscReal         kernelSpacing;                                                   /* refined: MLS radius / the added knot's distance from 0 */
  PetscInt          kernelMin;                                                       /* refined: samples the local kernel must hold */
  PetscReal         factor1;                                                         /* 1D knot range factor */
  PetscReal         factor2, factor2bend;                                            /* 2D knot range factors (bending pairs: factor2bend) */
  PetscInt          kStretch[2], kPoisson[2], kSym[2], kBendStretch[2], kBendSym[2]; /* knots left, right of 0 */
  PetscReal         density, yarnDensity;                                            /* kg/m^2 override; kg/m^3 (<= 0: the rule 0.12 kg/m^2 / r) */
  PetscInt          rawN1, rawN2;                                                    /* raw data.txt block sizes (0: infer) */
  PetscInt          min1, min2;                                                      /* minimum samples per 1D, 2D term */
  PetscInt          terms;                                                           /* bit t: fit term t */
  HylcFitMethod     method;                                                          /* -fit_method as set */
  HylcFitMethod     methodUsed;                                                      /* auto resolved by HylcFitCompute() */
  PetscReal         fabricFloor, fabricRidge, fabricReg;                             /* the fabric fit's weight floor, ridge, marching floor */
  PetscInt          fabricPasses;                                                    /* the fabric fit's 2D passes (muv from the slopes between them) */
  /* data: the rows used (status 0), in file order */
  PetscInt   n;
  PetscReal *z, *psi;                               /* n x 6, n */
  PetscReal *stress;                                /* n x 6: dPsi/dz of each row (NaN: not recorded) */
  PetscInt  *term, *row;                            /* term, row in the file */
  PetscReal  rhoA;                                  /* resolved area density (kg/m^2), <= 0 unknown */
  char       rhoSource[PETSC_MAX_PATH_LEN + 256];   /* how rhoA was obtained */
  char       familyName[32];                        /* the family as named (-sampler_family's spelling) */
  char       familySource[PETSC_MAX_PATH_LEN + 64]; /* where the family came from */
  PetscReal  radius, restLength, px, py;            /* from the samples file's /reference (0 if absent) */
  char       source[PETSC_MAX_PATH_LEN + 64];
  PetscInt   nrows, nskipped; /* rows in the input, rows not used (status != 0) */
  PetscReal  zabsmax[6];      /* max |strain| over every computed row, converged or not (the plan's range) */
  PetscBool  dataset, setupcalled, computed;
  PetscBool  samplesFile; /* the input is a samples file of hylc-sample (HDF5) */
  /* results */
  PetscInt       nknot[HYLC_PLAN_NTERM3][3]; /* the fabric fit's knots per term and axis (physical units) */
  PetscReal     *knot[HYLC_PLAN_NTERM3][3];
  char           knotSource[PETSC_MAX_PATH_LEN + 64];
  PetscReal      scale[6], f0;
  PetscInt       f0row;
  PetscBool      has[HYLC_PLAN_NTERM3];
  HylcSpline1D   s1[5];
  HylcSpline2D   s2[9];
  hylcmat_term3d s3[HYLC_NTRIPLE];       /* the fabric fit's 3D terms (arrays in a3) */
  PetscReal     *a3[HYLC_NTRIPLE];       /* one allocation per 3D term: tu, tv, tw, then the 8 node arrays */
  PetscInt       missing3[HYLC_NTRIPLE]; /* 3D nodes without a converged sample (set to 0) */
  PetscInt       statN[HYLC_PLAN_NTERM3];
  PetscReal      statRms[HYLC_PLAN_NTERM3], statRange[HYLC_PLAN_NTERM3], statMin[HYLC_PLAN_NTERM3][3], statMax[HYLC_PLAN_NTERM3][3];
  PetscInt       statBandN[HYLC_PLAN_NTERM3][HYLC_FIT_NBAND];   /* samples per strain band (HylcFitGetTermBandStats) */
  PetscReal      statBandRel[HYLC_PLAN_NTERM3][HYLC_FIT_NBAND]; /* RMS(model - data) / RMS(data - f0) per band */
};

/* input.c: reads fit->input into the data arrays (rank-local). */
PETSC_INTERN PetscErrorCode HylcFitReadInput_Private(HylcFit);
/* the sampling family recorded in a samples file's provenance (-sampler_family, woven when the run did not
   set it); *found false for a file without provenance (or not an HDF5 samples file). Not collective. */
PETSC_INTERN PetscErrorCode HylcFitInputFamily_Private(const char[], char[], size_t, PetscBool *);
/* fit.c: frees the results */
PETSC_INTERN PetscErrorCode HylcFitResetResults_Private(HylcFit);
/* fabric.c: the fabric method's knots (the samples file's /plan, else graded over the data), 1D and 2D terms */
PETSC_INTERN PetscErrorCode HylcFitFabricKnots_Private(HylcFit);
PETSC_INTERN PetscErrorCode HylcFitTerm1DFabric_Private(HylcFit, int);
PETSC_INTERN PetscErrorCode HylcFitTerm2DFabric_Private(HylcFit, int);
PETSC_INTERN PetscErrorCode HylcFitTerm3DFabric_Private(HylcFit, int);
/* a 3D term at normalised (u, v, w) with its gradient g (may be NULL), as hylcmat evaluates it on the axes */
PETSC_INTERN PetscReal HylcFitTerm3DEval_Private(const hylcmat_term3d *, PetscReal, PetscReal, PetscReal, PetscReal[3]);
