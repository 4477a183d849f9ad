#pragma once
/* Small dense geometry kernels on plain double arrays (3-vectors stored as double[3]).
   No PETSc objects: these are the building blocks of the pattern, rod and contact modules and
   are unit-tested in isolation. All functions are pure and thread-safe. */

#include <math.h>

static inline double HylcDot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline double HylcNorm3(const double a[3]) { return sqrt(HylcDot3(a, a)); }
static inline void   HylcCross3(const double a[3], const double b[3], double c[3])
{
  const double c0 = a[1] * b[2] - a[2] * b[1], c1 = a[2] * b[0] - a[0] * b[2], c2 = a[0] * b[1] - a[1] * b[0];
  c[0] = c0;
  c[1] = c1;
  c[2] = c2;
}
static inline void HylcSub3(const double a[3], const double b[3], double c[3])
{
  c[0] = a[0] - b[0];
  c[1] = a[1] - b[1];
  c[2] = a[2] - b[2];
}
static inline void HylcAxpy3(double alpha, const double x[3], double y[3])
{
  y[0] += alpha * x[0];
  y[1] += alpha * x[1];
  y[2] += alpha * x[2];
}
static inline void HylcScale3(double alpha, double x[3])
{
  x[0] *= alpha;
  x[1] *= alpha;
  x[2] *= alpha;
}
/* Normalizes x in place and returns its former length (0 leaves x unchanged). */
static inline double HylcNormalize3(double x[3])
{
  const double n = HylcNorm3(x);
  if (n > 0) HylcScale3(1.0 / n, x);
  return n;
}

/* Parallel transport of v along the rotation taking unit vector a to unit vector b
   (the minimal rotation about a x b): P(v) = c v + k x v + k (k.v)/(1+c), c = a.b, k = a x b.
   For antiparallel a, b (c <= -1 + 1e-12) the transport is undefined; the function rotates by pi about
   an axis perpendicular to a and returns -1, otherwise 0. v and out may alias. */
int HylcParallelTransport(const double a[3], const double b[3], const double v[3], double out[3]);

/* Signed angle from u to v about the unit axis t (u, v perpendicular to t, not necessarily unit). */
double HylcSignedAngle(const double u[3], const double v[3], const double t[3]);

/* Rotates v about the unit axis t by angle phi (Rodrigues). v and out may alias. */
void HylcRotateAxisAngle(const double v[3], const double t[3], double phi, double out[3]);

/* Makes d1 unit and perpendicular to the unit tangent t (Gram-Schmidt); returns the length of the
   perpendicular part of the input d1 relative to |d1| (0 if d1 is parallel to t or zero). */
double HylcOrthonormalizeDirector(const double t[3], double d1[3]);

/* A unit vector perpendicular to unit t, chosen deterministically (for initializing frames). */
void HylcAnyPerpendicular(const double t[3], double d[3]);

/* Curvature binormal at a vertex between unit tangents te (incoming edge) and tf (outgoing edge):
   kb = 2 te x tf / (1 + te.tf). Returns 1 + te.tf (callers check it is not near 0). */
double HylcCurvatureBinormal(const double te[3], const double tf[3], double kb[3]);

/* Material curvature (kappa1, kappa2) at a vertex in the averaged-frame convention of the .pyp rest
   data: with mbar_a = (m_a^e + m_a^f)/2, kappa = (kb . mbar2, -kb . mbar1).
   m1e, m2e: material frame of the incoming edge; m1f, m2f: of the outgoing edge. */
void HylcMaterialCurvature(const double kb[3], const double m1e[3], const double m2e[3], const double m1f[3], const double m2f[3], double kappa[2]);

/* Material frame from reference frame (d1, d2 = t x d1) and twist angle theta:
   m1 = cos(theta) d1 + sin(theta) d2, m2 = -sin(theta) d1 + cos(theta) d2. */
void HylcMaterialFrame(const double d1[3], const double d2[3], double theta, double m1[3], double m2[3]);

/* Reference twist at a vertex: the signed angle about tf from the parallel transport (te -> tf) of the
   incoming reference director d1e to the outgoing reference director d1f. */
double HylcReferenceTwist(const double te[3], const double d1e[3], const double tf[3], const double d1f[3]);

/* Closest points of segments [p0,p1] and [q0,q1]: parameters s, t in [0,1] (clamped; for (nearly)
   parallel segments a valid minimizer is returned) and the distance. Robust for degenerate segments. */
double HylcSegmentSegmentDistance(const double p0[3], const double p1[3], const double q0[3], const double q1[3], double *s, double *t);

/* Inverse of a small dense m x m matrix A (row-major, overwritten: LAPACK's work array) into Ainv by
   LAPACK's LU with partial pivoting (getrf, getri through petscblaslapack.h; general, not only SPD: the
   micro solver's Schur matrix is not symmetric). Returns -1 - c if the pivot of column c falls below tol
   times the largest |diagonal entry| of the input (numerically singular), -1 - m if out of memory, else 0. */
int HylcDenseInverse(int m, double *A, double *Ainv, double tol);
