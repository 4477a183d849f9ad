#pragma once
/* Macroscopic deformation of the tile (docs/method.md §1, supplementary §S1.1): the strain coordinates
   z = (sx, sa, sy, II00, II01, II11), the first fundamental form I, its upper-triangular factor
   A = sqrt(I) (A^T A = I), S = [A; 0], the normal derivatives N = [n_{i,alpha}] = -A^{-T} II (S12), the
   rotation field R(xi) (S10), and the micro-midsurface phi with grad phi = R S: an exact closed form
   for singly curved II and a Poisson solve (HylcMidsurface) for general II.

   Conventions (see docs/macro.md):
     2x2 matrices are row-major double[4]: M[2*i + j]; 3x3 are double[9]: M[3*i + j]; S is 3x2 double[6]:
     S[2*i + alpha]. N has rows i (component of n) and columns alpha (derivative direction); with
     (a, b)^T = N xi the rotation is R = exp(W), W = [[0,0,a],[0,0,b],[-a,-b,0]], and n = R e3.
     II > 0 bends the surface toward +n: II = diag(H, 0) gives phi_3 ~ H xi1^2 / 2.

   The kernels below are pure functions on plain arrays (no PETSc objects), thread-safe. */
#include <hylc/sys.h>
#include <petscviewer.h>

/* ---------------------------------------------------------------------------------------------- */
/* Strain kernels                                                                                  */

/* Result of validating a strain vector (0 = valid). */
typedef enum {
  HYLC_MACRO_STRAIN_OK        = 0,
  HYLC_MACRO_STRAIN_NONFINITE = 1, /* a component is NaN or infinite */
  HYLC_MACRO_STRAIN_SHEAR     = 2, /* |sa| >= 1: the warp and weft directions are parallel */
  HYLC_MACRO_STRAIN_STRETCH_X = 3, /* 1 + sx <= 0 */
  HYLC_MACRO_STRAIN_STRETCH_Y = 4  /* 1 + sy <= 0 */
} HylcMacroStrainError;

/* Kind of the second fundamental form. */
typedef enum {
  HYLC_MACRO_FLAT   = 0, /* II = 0 */
  HYLC_MACRO_SINGLY = 1, /* II = H d d^T (rank one): cylinder, exact closed-form phi */
  HYLC_MACRO_DOUBLY = 2  /* rank two: Poisson phi, R(xi) approximate */
} HylcMacroCurvature;

/* Validates z; returns HYLC_MACRO_STRAIN_OK or the first violated condition. */
HylcMacroStrainError HylcMacroStrainValidate(const double z[6]);
/* A one-line description of a validation result ("ok", "|sa| >= 1 ...", ...). */
const char *HylcMacroStrainErrorString(HylcMacroStrainError);

/* I = [[X^2, sa X Y], [sa X Y, Y^2]] with X = 1+sx, Y = 1+sy. */
void HylcMacroFirstForm(const double z[6], double I1[4]);
/* A = [[X, sa Y], [0, sqrt(1-sa^2) Y]] (upper triangular, A^T A = I). */
void HylcMacroSqrtFirstForm(const double z[6], double A[4]);
/* S = [A; 0 0] (3x2, row-major S[2*i + alpha]). */
void HylcMacroStretchMatrix(const double z[6], double S[6]);
/* Smallest eigenvalue of I, computed as det(I) / lambda_max (no cancellation). */
double HylcMacroLambdaMin(const double z[6]);
/* N = [n_{i,alpha}] = -A^{-T} II (S12), rows i, columns alpha. */
void HylcMacroNormalDerivatives(const double z[6], double N[4]);
/* Classifies II = [[II00, II01], [II01, II11]]: flat if II = 0, singly curved if
   |det II| <= tol max|II_ab|^2 (tol <= 0 selects 1e-12); for singly curved II returns H and the unit d
   with II ~ H d d^T (d is chosen with a non-negative largest component). H, d may be NULL. */
HylcMacroCurvature HylcMacroClassifyII(const double II[3], double tol, double *H, double d[2]);

/* Everything derived from one strain vector. */
typedef struct {
  double             z[6];
  double             I1[4], A[4], Ainv[4], S[6], II[4], N[4];
  double             lambdaMin;
  HylcMacroCurvature curvature;
  double             H, d[2], dperp[2]; /* II = H d d^T, dperp = (-d2, d1) (singly curved; d = e1 if flat) */
  double             ab[2], rho;        /* (a', b') = N d and rho = |N d| (singly curved) */
} HylcMacroStrain;

/* Validates z and fills m; tol as in HylcMacroClassifyII. Returns the validation result (m is only
   filled when it is HYLC_MACRO_STRAIN_OK). */
HylcMacroStrainError HylcMacroStrainSetUp(const double z[6], double tol, HylcMacroStrain *m);

/* ---------------------------------------------------------------------------------------------- */
/* Robust scalar functions (Taylor series near 0)                                                  */

/* sinc x = sin x / x (series for |x| < 1e-4). */
double HylcMacroSinc(double x);
/* sinc^2(x/2) = 2 (1 - cos x) / x^2, evaluated without cancellation. */
double HylcMacroSinc2Half(double x);
/* g(x) = (1 - sinc x) / x^2 (series for |x| < 1). */
double HylcMacroG(double x);
/* sinc'(r) / r = (cos r - sinc r) / r^2 and (d/dr sinc^2(r/2)) / r (series for r < 1). */
double HylcMacroSincPrimeOverR(double r);
double HylcMacroSinc2HalfPrimeOverR(double r);

/* ---------------------------------------------------------------------------------------------- */
/* Rotation field (S10)                                                                            */

/* R = exp(W(a, b)) (S10). Optional outputs (NULL to skip): D = R - I evaluated without cancellation
   (accurate relative to |a|, |b| even for r ~ 1e-300), dRa = dR/da, dRb = dR/db. */
void HylcMacroRotationAB(double a, double b, double R[9], double D[9], double dRa[9], double dRb[9]);
/* R(xi) with (a, b) = N xi. Optional D = R - I and dR[9*alpha + 3*i + j] = dR_ij/dxi_alpha. */
void HylcMacroRotation(const double N[4], const double xi[2], double R[9], double D[9], double dR[18]);
/* n(xi) = R(xi) e3 and optionally dn[3*alpha + i] = dn_i/dxi_alpha (NULL to skip). */
void HylcMacroNormal(const double N[4], const double xi[2], double n[3], double dn[6]);

/* ---------------------------------------------------------------------------------------------- */
/* Closed-form midsurface (flat or singly curved II)                                               */

/* phi(xi) = J(s) S d + w S dperp with s = d.xi, w = dperp.xi and
   J(s) = s I + s^2/2 sinc^2(rho s/2) W' + s^3 g(rho s) W'^2; phi(0) = 0 and grad phi = R S exactly.
   Optional outputs: n = R(xi) e3, dphi[2*i + alpha] = dphi_i/dxi_alpha (= (R S)_{i alpha}).
   Returns 0, or -1 (outputs untouched) if m is doubly curved. */
int HylcMacroClosedPhi(const HylcMacroStrain *m, const double xi[2], double phi[3], double n[3], double dphi[6]);
/* x(xi, h) = phi(xi) + h n(xi); n optional. Returns 0, or -1 if m is doubly curved. */
int HylcMacroClosedPosition(const HylcMacroStrain *m, const double xi[2], double h, double x[3], double n[3]);

/* ---------------------------------------------------------------------------------------------- */
/* HylcMidsurface: phi and n for any II, on PETSC_COMM_SELF                                        */

typedef struct _p_HylcMidsurface *HylcMidsurface;

/* Registration: the class id and log events of this stage (HylcMidsurfaceInitializePackage(), called by HylcMidsurfaceCreate()). */
PETSC_EXTERN PetscClassId   HYLC_MIDSURFACE_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_MacroSetUp, HYLC_MacroPoisson, HYLC_MacroEvaluate;
PETSC_EXTERN PetscErrorCode HylcMidsurfaceInitializePackage(void);

typedef enum {
  HYLC_MIDSURFACE_AUTO    = 0, /* closed for flat or singly curved II, else poisson */
  HYLC_MIDSURFACE_CLOSED  = 1,
  HYLC_MIDSURFACE_POISSON = 2
} HylcMidsurfaceType;
PETSC_EXTERN const char *const HylcMidsurfaceTypes[];

typedef enum {
  HYLC_MIDSURFACE_INTERP_BILINEAR = 0,
  HYLC_MIDSURFACE_INTERP_BICUBIC  = 1 /* Catmull-Rom */
} HylcMidsurfaceInterp;
PETSC_EXTERN const char *const HylcMidsurfaceInterps[];

typedef enum {
  HYLC_MIDSURFACE_NORMAL_ROTATION = 0, /* n = R(xi) e3 from (S10) */
  HYLC_MIDSURFACE_NORMAL_POLAR    = 1  /* Poisson only: R from the polar decomposition of the FD gradient of phi */
} HylcMidsurfaceNormal;
PETSC_EXTERN const char *const HylcMidsurfaceNormals[];

/* Lifecycle. Create is not collective (use PETSC_COMM_SELF); Destroy accepts NULL. */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceCreate(MPI_Comm, HylcMidsurface *);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceDestroy(HylcMidsurface *);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceDuplicate(HylcMidsurface, HylcMidsurface *);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetOptionsPrefix(HylcMidsurface, const char[]);
/* Options: -macro_phi <auto|closed|poisson>, -macro_grid <96> (nodes per direction, >= 8),
   -macro_interp <bilinear|bicubic>, -macro_normal <rotation|polar>, -macro_ksp_* / -macro_pc_* for
   the Poisson KSP (default CG + ICC, rtol 1e-12). */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetFromOptions(HylcMidsurface);
/* Strain z = (sx, sa, sy, II00, II01, II11); invalid z is a PETSC_ERR_USER_INPUT error. */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetStrain(HylcMidsurface, const PetscReal[6]);
/* Bounding box [lo, hi] in xi of the points to evaluate (the Poisson grid covers it, xi = 0 and a margin
   of 2 cells); default [-1, 1]^2. */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetBox(HylcMidsurface, const PetscReal[2], const PetscReal[2]);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetType(HylcMidsurface, HylcMidsurfaceType);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceGetType(HylcMidsurface, HylcMidsurfaceType *);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetGridSize(HylcMidsurface, PetscInt);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetInterpolation(HylcMidsurface, HylcMidsurfaceInterp);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetNormalType(HylcMidsurface, HylcMidsurfaceNormal);
/* Resolves the type and, for poisson, builds the grid and solves the three Poisson problems. */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceSetUp(HylcMidsurface);
/* For npts points xih = (xi1, xi2, h) (3 per point): x = phi(xi) + h n(xi) and n (3 per point; n may be
   NULL). Calls SetUp if needed. */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceEvaluate(HylcMidsurface, PetscInt, const PetscReal[], PetscReal[], PetscReal[]);
/* The rotation used at xi (3x3 row-major): R(xi) of (S10), or the polar estimate with -macro_normal polar. */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceGetRotation(HylcMidsurface, const PetscReal[2], PetscReal[9]);
/* The derived strain data (valid after SetStrain). */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceGetStrain(HylcMidsurface, const HylcMacroStrain **);
/* Poisson statistics: nodes per direction, total KSP iterations over the 3 components (0 for closed). */
PETSC_EXTERN PetscErrorCode HylcMidsurfaceGetSolveInfo(HylcMidsurface, PetscInt *, PetscInt *);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceView(HylcMidsurface, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcMidsurfaceViewFromOptions(HylcMidsurface, PetscObject, const char[]);
