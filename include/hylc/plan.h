#pragma once
/* The sampling plan of Algorithm C4 (docs/method.md §8), as pure functions on plain arrays (src/plan/plan.c),
   and the plan's options shared by hylc-sample and hylc-calibrate (src/plan/planopts.c).

   Coordinates (index c): 0 = sx, 1 = sa, 2 = sy, 3 = II00, 4 = II11; in the 6-vector strain
   z = (sx, sa, sy, II00, II01, II11) they sit at positions 0, 1, 2, 3, 5 (II01 is never sampled).
   Terms: 0 = the zero sample; 1..5 = the 1D terms of coordinates 0..4; 6..14 = the 2D terms of the pairs
   (sx,sa) (sx,sy) (sx,II00) (sx,II11) (sa,sy) (sa,II00) (sa,II11) (sy,II00) (sy,II11); 15..21 = the 3D terms
   of the triples (sx,sa,sy) (sx,sa,II00) (sx,sa,II11) (sx,sy,II00) (sx,sy,II11) (sa,sy,II00) (sa,sy,II11) (hylc's
   extension, sampled with graded spacing only).
   Sample order: the zero sample, then the 1D terms in order (ascending), then the 2D terms in order, each a
   grid with the first coordinate outer, then the 3D terms, each a grid with the first coordinate outermost. */

#include <hylc/sys.h>
#include <hylc/strain.h>

#define HYLC_PLAN_NCOORD      HYLC_NCOORD                      /* the vocabulary's coordinates (include/hylc/strain.h) */
#define HYLC_PLAN_NTERM       (1 + HYLC_NCOORD + HYLC_NPAIR)   /* the paper's terms: zero, the 1D terms, the 2D terms */
#define HYLC_PLAN_NTERM3      (HYLC_PLAN_NTERM + HYLC_NTRIPLE) /* and the 3D terms 15..21 (graded spacing only) */
#define HYLC_PLAN_PAPER_TERMS ((1 << HYLC_PLAN_NTERM) - 1)     /* the term mask of the paper's terms */
#define HYLC_PLAN_ALL_TERMS   ((1 << HYLC_PLAN_NTERM3) - 1)

/* How the samples of an axis are spaced. paper: n1 (1D) or n2 (2D) samples of Algorithm C4's SampleRange.
   graded: the knots of HylcPlanGradedKnots() over the axis's range (dense near 0, where fabric lives), each
   interval cut into sub equal parts: the knots of the fabric fit are samples (hylc-fit -fit_method fabric). */
typedef enum { HYLC_PLAN_SPACING_PAPER = 0, HYLC_PLAN_SPACING_GRADED = 1 } HylcPlanSpacing;

#define HYLC_PLAN_MAXAXIS 1024 /* samples per axis at most */

typedef struct {
  double min1[HYLC_PLAN_NCOORD], max1[HYLC_PLAN_NCOORD]; /* 1D ranges per coordinate */
  double min2[9][2], max2[9][2];                         /* 2D ranges per pair and coordinate */
  double min3[HYLC_NTRIPLE][3], max3[HYLC_NTRIPLE][3];   /* 3D ranges per triple and coordinate */
  int    n1, n2;                                         /* paper spacing: samples per 1D term, per 2D axis (150, 50) */
  int    terms;                                          /* bit t set: term t is sampled (HYLC_PLAN_ALL_TERMS) */
  int    spacing;                                        /* HylcPlanSpacing */
  double h0[HYLC_PLAN_NCOORD];                           /* graded: the knot spacing at 0 per coordinate (II in 1/m) */
  double growth;                                         /* graded: ratio of consecutive knot spacings away from 0 (>= 1) */
  double hmax;                                           /* graded: the largest knot spacing, as a fraction of the axis's range */
  int    sub;                                            /* graded: samples per knot interval (1: the knots only) */
} HylcPlan;

/* the name of term t: zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11,
   sy-II00, sy-II11, sx-sa-sy, sx-sa-II00, sx-sa-II11, sx-sy-II00, sx-sy-II11, sa-sy-II00, sa-sy-II11 (used by -sampler_terms and in the HDF5 file) */
const char *HylcPlanTermName(int t);
/* the number of coordinates term t varies: 0 (the zero sample), 1, 2 or 3; -1 out of range */
int HylcPlanTermDim(int t);
/* the two coordinates of 2D term t (6..14) */
void HylcPlanPair(int t, int *ci, int *cj);
/* the three coordinates of 3D term t (15..21) */
void HylcPlanTriple(int t, int c[3]);
/* the coordinate of axis a of term t (1..21), -1 out of range */
int HylcPlanAxisCoord(int t, int a);
/* position of coordinate c in the 6-vector strain */
int HylcPlanStrainIndex(int c);
/* SampleRange of Algorithm C4: N values from zmin to zmax, (linspace((zmin+1)^(1/10), (zmax+1)^(1/10)))^10 - 1
   for sx and sy (dense toward compression), sgn(t) t^2 with t = linspace(-sqrt|zmin|, sqrt|zmax|) otherwise
   (dense near 0). End points are exact. Returns -1 for invalid input (N < 1, zmin > zmax, zmin <= -1 for
   sx/sy, a range not containing 0 for the other coordinates). */
int HylcSampleRange(int c, double zmin, double zmax, int N, double Z[]);
/* The graded knots of [mn, mx] (mn <= 0 <= mx, mn < mx): 0, then on each side spacings h0, h0 g, h0 g^2, ...
   (each at most hmax), the last interval on a side ending at the end point (merged with the one before when
   it would be shorter than half of that one's). Ascending, 0 included; returns the count, or -1 for invalid
   input (h0 <= 0, g < 1, hmax < h0, more than cap knots). */
int HylcPlanGradedKnots(double mn, double mx, double h0, double g, double hmax, int cap, double K[]);
/* The samples of axis a (0 .. dim - 1) of term t (1..21), ascending; returns their count, or -1 for an invalid
   plan. paper: HylcSampleRange with n1 / n2 (a 3D term has no samples: -1); graded: the knots cut sub times (a 3D
   term: its knots only). */
int HylcPlanAxis(const HylcPlan *, int t, int a, double Z[HYLC_PLAN_MAXAXIS]);
/* The knots of axis a of term t under graded spacing (what the samples subdivide); -1 for paper spacing or an
   invalid plan. A 3D term's knots are coarser: spacing 2 h0 at 0, an in-plane axis growing by at least 2
   (HYLC_PLAN_GROWTH3), a curvature axis by the plan's growth. */
#define HYLC_PLAN_GROWTH3 2.0
int HylcPlanAxisKnots(const HylcPlan *, int t, int a, double K[HYLC_PLAN_MAXAXIS]);
/* number of samples of term t (0 if not selected) and of the whole plan */
long HylcPlanTermSize(const HylcPlan *, int t);
long HylcPlanSize(const HylcPlan *);
/* strain z[6] and term of sample k (0 <= k < HylcPlanSize); returns -1 if k is out of range */
int HylcPlanSample(const HylcPlan *, long k, double z[6], int *term);
/* The units of work of continuation (-sampler_start continue): half-lines ordered from the zero strain
   outward. The zero sample is a unit; each 1D term is split at zero into the half-line of its non-negative
   samples (ascending) and that of its negative ones (descending); each 2D grid is cut into its lines along
   the second (inner) coordinate, one per value of the first, each split the same way in the inner
   coordinate; each 3D grid into its lines along the innermost coordinate, split the same way. Within a unit one
   coordinate varies, and each sample is strictly farther from zero in it than
   its predecessor. Fills start[0..nunits] (offsets into order; start[nunits] = the plan's size) and order
   (the plan's sample indices, unit after unit); either may be NULL (to count). Returns the number of units
   or -1 for an invalid plan. Depends only on the plan. */
long HylcPlanUnits(const HylcPlan *, long start[], long order[]);
/* the default ranges of docs/method.md §8 for a named pattern family: "woven" (basket, satin), "stockinette",
   "honeycomb", "rib"; II ranges scale with 1/r relative to r = 1 mm (scale = 1e-3 / r). Returns -1 for an
   unknown family. 2D ranges: stretch axes paired with sa or a bending [-0.1, 0.84 max], (sx, sy) both
   [0.74 min, max], sa in 2D +-0.8 max, bending in 2D +-0.8 max (+-0.72 max on the same axis). 3D ranges (where
   cloth lives): in (sx, sa, sy) the stretches [0.45 min, 0.3 max] and sa +-0.55 max; in an in-plane pair with
   a curvature the stretches [0.2 min, 0.15 max], sa +-0.25 max and the curvature +-0.35 max. The spacing is paper's (n1 150, n2 50); the
   graded parameters are set to their defaults (HylcPlanGradedDefaults()). */
int HylcPlanDefaults(const char *family, double scale, HylcPlan *);
/* The graded spacing's defaults: h0 = 0.01 in sx, sa, sy and 2.5 1/m x scale in the curvatures (scale = 1e-3 / r,
   as the ranges), growth 1.5, hmax 0.15, sub 2. */
void HylcPlanGradedDefaults(double scale, HylcPlan *);

/* ---- The plan's options (src/plan/planopts.c) ---- */

/* The plan's ranges as options give them (HylcPlanRangesFromOptions), before the yarn radius is known. */
typedef struct {
  PetscInt  family;                /* index into HylcPlanFamilies: woven, stockinette, honeycomb, rib */
  PetscBool set[HYLC_PLAN_NCOORD]; /* 1D range of coordinate c given (else the family's default) */
  PetscReal min[HYLC_PLAN_NCOORD], max[HYLC_PLAN_NCOORD];
  PetscInt  spacing;    /* HylcPlanSpacing (the caller's default: the sampler's graded, the calibration's paper) */
  PetscBool spacingSet; /* -sampler_spacing given */
  PetscBool h0set;      /* graded: h0 given (else HylcPlanGradedDefaults(), II scaled by 1 mm / r) */
  PetscReal h0[HYLC_PLAN_NCOORD];
  PetscReal growth, hmax; /* graded: 0 for the defaults */
  PetscInt  sub;          /* graded: 0 for the default */
} HylcPlanRanges;

/* Family names, -sampler_family and -sampler_range_<c> inside a PetscOptionsBegin/End block (only read;
   ranges resolved and checked for a radius by HylcPlanRangesApply), and a term list ("all", "1d" or
   comma-separated names). Collective. */
PETSC_EXTERN const char *const HylcPlanFamilies[];
PETSC_EXTERN const char *const HylcPlanSpacings[];
PETSC_EXTERN PetscErrorCode    HylcPlanRangesFromOptions(PetscOptionItems *, MPI_Comm, const char[], HylcPlanRanges *);
PETSC_EXTERN PetscErrorCode    HylcPlanRangesApply(MPI_Comm, const HylcPlanRanges *, PetscReal, HylcPlan *);
PETSC_EXTERN PetscErrorCode    HylcPlanTermsFromString(MPI_Comm, const char[], const char[], int *);
