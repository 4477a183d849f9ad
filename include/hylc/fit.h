#pragma once
/* HylcFit: the fitting pipeline of Algorithms C5-C7 (seeds §S3; docs/method.md §9 and §9.1) that turns
   microscale samples into the homogenized material model (the spline tables of (S26)).

   Input: the samples file of hylc-sample (HDF5, docs/output-format.md; rows with status 0) or the
   paper's raw layout (data.txt rows "sx sa sy II00 II01 II11 Psi", info.txt with the area density;
   ../shared/docs/formats.md §5), or data set by HylcFitSetData().
   Pipeline per term: normalisation by max |strain|, f0 = Psi of the row nearest the origin, MLS in
   symlog space at the knots, central-difference Hermite data, quasiconvex marching and the monotone
   cubic / bicubic projections (include/hylc/monotone.h), increasing extrapolation, residualization
   (S29, S30) and the zero-compression rule. Details, options and choices: docs/fit.md.

   The object is serial: every rank of its communicator computes the same tables (use PETSC_COMM_SELF or
   one rank); the material writes the files from rank 0. */
#include <hylc/sys.h>
#include <hylc/spline.h>
#include <hylc/monotone.h>
#include <hylc/material.h>
#include <petscviewer.h>

typedef struct _p_HylcFit *HylcFit;

/* Registration: the class id and log events of this stage (HylcFitInitializePackage(), called by HylcFitCreate()). */
PETSC_EXTERN PetscClassId   HYLC_FIT_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_FitRun, HYLC_FitTerm, HYLC_FitMLS, HYLC_FitMonotone;
PETSC_EXTERN PetscErrorCode HylcFitInitializePackage(void);

/* Pattern families with their own fitting constants (docs/method.md §9, §S3.4): WOVEN and KNIT share the
   constants of every pattern but the stockinette; STOCKINETTE has reg 1e-2 and coarse 2D bending knots
   (factor 0.3, 2+4 and 3+3). The family is the object's type name. */
typedef enum { HYLC_FIT_FAMILY_WOVEN = 0, HYLC_FIT_FAMILY_KNIT = 1, HYLC_FIT_FAMILY_STOCKINETTE = 2 } HylcFitFamily;
PETSC_EXTERN const char *const HylcFitFamilies[];

/* The knots of the 1D terms (-fit_knots, docs/fit.md): PAPER, the authors' uniform layout (11 knots over
   0.95 x the data's range, shifted so that 0 is a knot; -fit_compat authors implies it); REFINED (hylc's
   default), the paper's layout with -fit_knots_refine more knots at h/2, h/4, ... of the first interval on
   each side of 0, their MLS kernels following the local knot spacing, so that the first few per cent of
   strain, where cloth lives, are resolved (issue 30) while the rest stays the paper's. The 2D terms keep
   the paper's layout. */
typedef enum { HYLC_FIT_KNOTS_PAPER = 0, HYLC_FIT_KNOTS_REFINED = 1 } HylcFitKnotLayout;
PETSC_EXTERN const char *const HylcFitKnotLayouts[];

/* The fitting method (-fit_method, docs/fit.md): PAPER, the paper's MLS of the values on its knot layout
   (Algorithms C6, C7); FABRIC, a weighted least-squares fit of the samples' values and stresses dPsi/dz on the
   sampling plan's graded knots, 2D residuals free across the axes (the lateral couplings), no symmetrization
   in sa (docs/fit.md "The fabric method"); AUTO (default), fabric when every sample has its stress, else paper.
   -fit_compat authors implies paper. */
typedef enum { HYLC_FIT_METHOD_AUTO = 0, HYLC_FIT_METHOD_PAPER = 1, HYLC_FIT_METHOD_FABRIC = 2 } HylcFitMethod;
PETSC_EXTERN const char *const HylcFitMethods[];

PETSC_EXTERN PetscErrorCode HylcFitCreate(MPI_Comm, HylcFit *);
PETSC_EXTERN PetscErrorCode HylcFitDestroy(HylcFit *);
PETSC_EXTERN PetscErrorCode HylcFitSetOptionsPrefix(HylcFit, const char[]);
PETSC_EXTERN PetscErrorCode HylcFitSetFromOptions(HylcFit);
PETSC_EXTERN PetscErrorCode HylcFitSetUp(HylcFit);
PETSC_EXTERN PetscErrorCode HylcFitView(HylcFit, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcFitViewFromOptions(HylcFit, PetscObject, const char[]);

/* The method (-fit_method); the one used, after HylcFitCompute() (auto resolved). */
PETSC_EXTERN PetscErrorCode HylcFitSetMethod(HylcFit, HylcFitMethod);
PETSC_EXTERN PetscErrorCode HylcFitGetMethod(HylcFit, HylcFitMethod *);
/* The stresses dPsi/dz of the rows set by HylcFitSetData() (n x 6, NaN where unknown; copied). */
PETSC_EXTERN PetscErrorCode HylcFitSetStress(HylcFit, const PetscReal[]);

/* The input file (-fit_input): an HDF5 samples file, a raw data.txt, or a directory holding data.txt
   (and info.txt). Read by HylcFitSetUp(). */
PETSC_EXTERN PetscErrorCode HylcFitSetInput(HylcFit, const char path[]);
/* Output files written by HylcFitRun() (-fit_output, -fit_json); NULL or "" for none. */
PETSC_EXTERN PetscErrorCode HylcFitSetOutputs(HylcFit, const char h5[], const char json[]);
/* The input and the outputs as set or read from the options (owned by the fit; "" for none). */
PETSC_EXTERN PetscErrorCode HylcFitGetInput(HylcFit, const char *path[]);
PETSC_EXTERN PetscErrorCode HylcFitGetOutputs(HylcFit, const char *h5[], const char *json[]);
/* The family (sets the family's defaults of -fit_reg and the 2D bending knots; call before
   HylcFitSetFromOptions to let options override them). */
PETSC_EXTERN PetscErrorCode HylcFitSetFamily(HylcFit, HylcFitFamily);

/* Data without a file: n rows of strain (n x 6: sx, sa, sy, II00, II01, II11), psi (J/m^2) and term
   (0..21 as in include/hylc/plan.h; term 0 rows only take part in f0 and the normalisation), and the
   area density (kg/m^2; <= 0: -fit_density must give it). Copied; replaces -fit_input. Not collective. */
PETSC_EXTERN PetscErrorCode HylcFitSetData(HylcFit, PetscInt n, const PetscReal strain[], const PetscReal psi[], const PetscInt term[], PetscReal areaDensity);

/* Runs the pipeline on the data read by HylcFitSetUp (called if needed). The results are then available
   from the Get functions below. Not collective (every rank computes the same). */
PETSC_EXTERN PetscErrorCode HylcFitCompute(HylcFit);
/* HylcFitCompute, then fills the material (constant, strain scale, density, the fitted terms) and writes
   -fit_output (HDF5, with the options as provenance) and -fit_json when they are set. Collective. */
PETSC_EXTERN PetscErrorCode HylcFitRun(HylcFit, HylcMaterial);

/* Results (after HylcFitCompute). Get1D(k): the 1D term k = 0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending;
   Get2D(k0, k1): the 2D term of the pair (the JSON's k0, k1); NULL for a term that was not fitted
   (no samples). The splines are owned by the fit. */
PETSC_EXTERN PetscErrorCode HylcFitGetConstant(HylcFit, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcFitGetStrainScale(HylcFit, PetscReal[5]);
PETSC_EXTERN PetscErrorCode HylcFitGetDensity(HylcFit, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcFitGet1D(HylcFit, PetscInt k, const HylcSpline1D **);
PETSC_EXTERN PetscErrorCode HylcFitGet2D(HylcFit, PetscInt k0, PetscInt k1, const HylcSpline2D **);
/* The model (S26) of the fitted tables at a strain with II01 = 0 (then the eigen-split of the bending
   terms is exact: lambda = II00 along x, II11 along y), without a HylcMaterial: f0 + the 1D terms + the
   2D terms. Used for the per-term summary; HylcMaterialEvaluate() is the general evaluator. */
PETSC_EXTERN PetscErrorCode HylcFitEvaluateAxes(HylcFit, const PetscReal z[6], PetscReal *psi);
/* Per-term statistics of the fit against its data: number of samples used, RMS of (model - data) in
   J/m^2 and the max |data - f0| of the term (0 for a term not fitted); t = 1..14 as in plan.h. */
PETSC_EXTERN PetscErrorCode HylcFitGetTermStats(HylcFit, PetscInt t, PetscInt *n, PetscReal *rms, PetscReal *range);
/* The fit's relative error against its data in strain bands, where cloth lives and beyond (issue 30): a
   sample is in band 0 if every strain of its term is small (|s| <= 5 % for sx, sa, sy; |II| <= 20 1/m),
   band 1 if none is beyond 20 % (80 1/m), else band 2; per band the number of samples and the RMS of
   (model - data) divided by the RMS of (data - f0) there (0 where the band is empty). */
#define HYLC_FIT_NBAND 3
PETSC_EXTERN const PetscReal HylcFitBandLimits[2][2]; /* [stretch or shear, curvature (1/m)][upper limit of band 0, 1] */
PETSC_EXTERN PetscErrorCode  HylcFitGetTermBandStats(HylcFit, PetscInt t, PetscInt n[HYLC_FIT_NBAND], PetscReal rel[HYLC_FIT_NBAND]);

/* ---- Plain C kernels of the pipeline (no PETSc objects; used by HylcFitCompute, tested alone) ---- */

/* symlog l(x) = sgn(x) ln(1 + |x|) and its inverse symexp e(y) = sgn(y) (exp|y| - 1) (§S3.3) */
PETSC_EXTERN PetscReal HylcSymlog(PetscReal);
PETSC_EXTERN PetscReal HylcSymexp(PetscReal);

/* MLS of §9.1 at one point. Weights: Gaussian exp(-d^2/(2 s^2)) with s = kernel / truncation, zero for
   |d| >= kernel (2D: product of the per-axis weights). Basis, not centred at the query point: 1D {1, x,
   x^2}; 2D {1, y, y^2, x, xy, xy^2, x^2, x^2 y}. Solves the weighted normal equations (partial
   pivoting) and evaluates the polynomial at the query point. Returns the number of data points with
   non-zero weight, or -1 if the normal equations are singular (too few points in the kernel). */
PETSC_EXTERN int HylcMLS1D(PetscInt n, const PetscReal x[], const PetscReal f[], PetscReal kernel, PetscReal truncation, PetscReal xq, PetscReal *value);
PETSC_EXTERN int HylcMLS2D(PetscInt n, const PetscReal x[], const PetscReal y[], const PetscReal f[], PetscReal kx, PetscReal ky, PetscReal truncation, PetscReal xq, PetscReal yq, PetscReal *value);

/* 1D knots (§9.1): linspace(factor min, factor max, n), shifted by the knot closest to 0 so that 0 is a
   knot (spacing kept). Returns the index of the 0 knot, -1 for invalid input (n < 2, min >= max). */
PETSC_EXTERN int HylcFitKnots1D(PetscReal min, PetscReal max, PetscReal factor, PetscInt n, PetscReal t[]);
/* 1D knots refined towards 0: the paper's knots (HylcFitKnots1D()) and, in the first interval on each side
   of 0 (h its length), levels more at h/2, h/4, ..., h/2^levels, so that the first few per cent of strain
   are resolved while the rest of the layout stays the paper's. t needs n + 2 levels entries; *nt gets the
   count. Returns the index of the 0 knot, -1 for invalid input. */
PETSC_EXTERN int HylcFitKnots1DRefined(PetscReal min, PetscReal max, PetscReal factor, PetscInt n, PetscInt levels, PetscReal t[], PetscInt *nt);
/* 2D knots of one axis (§9): linspace(factor min, 0, nl) and linspace(0, factor max, nr) joined at 0
   (nl + nr - 1 knots; a side with factor*min >= 0 or factor*max <= 0 contributes only the 0). Writes
   *nt knots (at most nl + nr - 1) and returns the index of the 0 knot, -1 for invalid input. */
PETSC_EXTERN int HylcFitKnots2D(PetscReal min, PetscReal max, PetscReal factor, PetscInt nl, PetscInt nr, PetscReal t[], PetscInt *nt);

/* 2D boundary slopes for increasing extrapolation: mu <= -eps on the first column, >= eps on the last;
   mv likewise on the first and last rows. */
PETSC_EXTERN void HylcFitClampBoundary2D(PetscInt nu, PetscInt nv, PetscReal eps, PetscReal mu[], PetscReal mv[]);
/* muv = 0 on the grid boundary. */
PETSC_EXTERN void HylcFitZeroBoundaryMixed2D(PetscInt nu, PetscInt nv, PetscReal muv[]);
/* Residualization (S30 as in §9.1) about the axis lines u = tu[i0], v = tv[j0]: off the axes
   p -= p(i,j0) + p(i0,j) - p(i0,j0), mu -= mu(i,j0), mv -= mv(i0,j); then p, mu, mv = 0 on the axes
   (muv kept). */
PETSC_EXTERN void HylcFitResidualize2D(PetscInt nu, PetscInt nv, PetscInt i0, PetscInt j0, PetscReal p[], PetscReal mu[], PetscReal mv[], PetscReal muv[]);
/* Zero-compression rule: p, mu, mv, muv = 0 at the nodes whose u (if zu) or v (if zv) knot is < 0;
   strict also zeroes muv on the axis line bordering the zeroed nodes, so that the spline vanishes on
   the whole compressed half-plane (not only at and beyond the last compressed knot). */
PETSC_EXTERN void HylcFitZeroCompression2D(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], PetscBool zu, PetscBool zv, PetscBool strict, PetscReal p[], PetscReal mu[], PetscReal mv[], PetscReal muv[]);
