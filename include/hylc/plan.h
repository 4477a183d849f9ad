#pragma once
/* The sampling plan of Algorithm C4 (docs/method.md §8), as pure functions on plain arrays (src/plan/plan.c),
   and the plan's options shared by hylc-sample and hylc-calibrate (src/plan/planopts.c).

   Coordinates (index c): 0 = sx, 1 = sa, 2 = sy, 3 = II00, 4 = II11; in the 6-vector strain
   z = (sx, sa, sy, II00, II01, II11) they sit at positions 0, 1, 2, 3, 5 (II01 is never sampled).
   Terms: 0 = the zero sample; 1..5 = the 1D terms of coordinates 0..4; 6..14 = the 2D terms of the pairs
   (sx,sa) (sx,sy) (sx,II00) (sx,II11) (sa,sy) (sa,II00) (sa,II11) (sy,II00) (sy,II11).
   Sample order: the zero sample, then the 1D terms in order (n1 samples each, ascending), then the 2D
   terms in order, each an n2 x n2 grid with the first coordinate outer. */

#include <hylc/sys.h>
#include <hylc/strain.h>

#define HYLC_PLAN_NCOORD HYLC_NCOORD                    /* the vocabulary's coordinates (include/hylc/strain.h) */
#define HYLC_PLAN_NTERM  (1 + HYLC_NCOORD + HYLC_NPAIR) /* zero, the 1D terms, the 2D terms */

typedef struct {
  double min1[HYLC_PLAN_NCOORD], max1[HYLC_PLAN_NCOORD]; /* 1D ranges per coordinate */
  double min2[9][2], max2[9][2];                         /* 2D ranges per pair and coordinate */
  int    n1, n2;                                         /* samples per 1D term, per 2D axis (150, 50) */
  int    terms;                                          /* bit t set: term t is sampled (all: (1 << 15) - 1) */
} HylcPlan;

/* the name of term t: zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11,
   sy-II00, sy-II11 (used by -sampler_terms and in the HDF5 file) */
const char *HylcPlanTermName(int t);
/* the two coordinates of 2D term t (6..14) */
void HylcPlanPair(int t, int *ci, int *cj);
/* position of coordinate c in the 6-vector strain */
int HylcPlanStrainIndex(int c);
/* SampleRange of Algorithm C4: N values from zmin to zmax, (linspace((zmin+1)^(1/10), (zmax+1)^(1/10)))^10 - 1
   for sx and sy (dense toward compression), sgn(t) t^2 with t = linspace(-sqrt|zmin|, sqrt|zmax|) otherwise
   (dense near 0). End points are exact. Returns -1 for invalid input (N < 1, zmin > zmax, zmin <= -1 for
   sx/sy, a range not containing 0 for the other coordinates). */
int HylcSampleRange(int c, double zmin, double zmax, int N, double Z[]);
/* number of samples of term t (0 if not selected) and of the whole plan */
long HylcPlanTermSize(const HylcPlan *, int t);
long HylcPlanSize(const HylcPlan *);
/* strain z[6] and term of sample k (0 <= k < HylcPlanSize); returns -1 if k is out of range */
int HylcPlanSample(const HylcPlan *, long k, double z[6], int *term);
/* The units of work of continuation (-sampler_start continue): half-lines ordered from the zero strain
   outward. The zero sample is a unit; each 1D term is split at zero into the half-line of its non-negative
   samples (ascending) and that of its negative ones (descending); each 2D grid is cut into its lines along
   the second (inner) coordinate, one per value of the first, each split the same way in the inner
   coordinate. Within a unit one coordinate varies, and each sample is strictly farther from zero in it than
   its predecessor. Fills start[0..nunits] (offsets into order; start[nunits] = the plan's size) and order
   (the plan's sample indices, unit after unit); either may be NULL (to count). Returns the number of units
   (at most 1 + 10 + 18 n2), or -1 for an invalid plan. Depends only on the plan. */
long HylcPlanUnits(const HylcPlan *, long start[], long order[]);
/* the default ranges of docs/method.md §8 for a named pattern family: "woven" (basket, satin), "stockinette",
   "honeycomb", "rib"; II ranges scale with 1/r relative to r = 1 mm (scale = 1e-3 / r). Returns -1 for an
   unknown family. 2D ranges: stretch axes paired with sa or a bending [-0.1, 0.84 max], (sx, sy) both
   [0.74 min, max], sa in 2D +-0.8 max, bending in 2D +-0.8 max (+-0.72 max on the same axis). */
int HylcPlanDefaults(const char *family, double scale, HylcPlan *);

/* ---- The plan's options (src/plan/planopts.c) ---- */

/* The plan's ranges as options give them (HylcPlanRangesFromOptions), before the yarn radius is known. */
typedef struct {
  PetscInt  family;                /* index into HylcPlanFamilies: woven, stockinette, honeycomb, rib */
  PetscBool set[HYLC_PLAN_NCOORD]; /* 1D range of coordinate c given (else the family's default) */
  PetscReal min[HYLC_PLAN_NCOORD], max[HYLC_PLAN_NCOORD];
} HylcPlanRanges;

/* Family names, -sampler_family and -sampler_range_<c> inside a PetscOptionsBegin/End block (only read;
   ranges resolved and checked for a radius by HylcPlanRangesApply), and a term list ("all", "1d" or
   comma-separated names). Collective. */
PETSC_EXTERN const char *const HylcPlanFamilies[];
PETSC_EXTERN PetscErrorCode    HylcPlanRangesFromOptions(PetscOptionItems *, MPI_Comm, const char[], HylcPlanRanges *);
PETSC_EXTERN PetscErrorCode    HylcPlanRangesApply(MPI_Comm, const HylcPlanRanges *, PetscReal, HylcPlan *);
PETSC_EXTERN PetscErrorCode    HylcPlanTermsFromString(MPI_Comm, const char[], const char[], int *);
