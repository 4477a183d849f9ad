#pragma once
/* Cubic and bicubic Hermite splines: the building blocks of the fitted material tables.
   Plain C kernels on plain arrays (no PETSc objects): evaluation with first and second derivatives,
   and the three extrapolation modes of the ARCSim-HYLC JSON ("ext": 0 linear, 1 constant, 2 zero).

   1D: knots t[0] < ... < t[n-1], values p[i] and slopes m[i] = df/dx at t[i]. On [t[i], t[i+1]) the
   spline is the cubic Hermite interpolant of (p[i], m[i]) and (p[i+1], m[i+1]); a point exactly on an
   inner knot uses the interval to its right, as ARCSim-HYLC does (f and f' do not depend on this, the
   splines are C1; f'' does).  Outside [t[0], t[n-1]] (and at x = t[n-1]):
     linear   (ext 0): f = p_end + m_end (x - t_end)   -- the default, used by every paper table
     constant (ext 1): f = p_end
     zero     (ext 2): f = 0
   2D: knots tu[0..nu-1] (first coordinate u) and tv[0..nv-1] (second coordinate v); node (iu, iv) is
   stored at iv*nu + iu (row-major, v outermost: the JSON layout). p, mu = df/du, mv = df/dv and
   muv = d2f/dudv at the nodes; the spline is the tensor product of the 1D Hermite bases, each axis
   extrapolated by its own mode, so the linear mode extrapolates linearly along each axis (bilinearly in
   the corners, with the mixed term muv), exactly as ARCSim-HYLC's HermiteSpline2D with MextL/MextR. */
#include <petscsys.h>

/* Extrapolation modes (the values of the JSON key "ext"). */
typedef enum { HYLC_EXT_LINEAR = 0, HYLC_EXT_CONSTANT = 1, HYLC_EXT_ZERO = 2 } HylcSplineExt;

/* One-dimensional term f_k(x) of the material: k = 0 sx, 1 sa, 2 sy, 3 x-bending, 4 y-bending. */
typedef struct {
  PetscInt      k;
  PetscInt      n; /* number of knots, >= 2 */
  PetscReal    *t, *p, *m;
  HylcSplineExt ext;
} HylcSpline1D;

/* Two-dimensional term f_{k0 k1}(u, v); arrays of nu*nv node values, index iv*nu + iu. */
typedef struct {
  PetscInt      k0, k1;
  PetscInt      nu, nv; /* >= 2 each */
  PetscReal    *tu, *tv, *p, *mu, *mv, *muv;
  HylcSplineExt ext;
} HylcSpline2D;

/* Interval of x in the knots t[0..n-1]: -1 below t[0], n-1 at or above t[n-1], otherwise the i with
   t[i] <= x < t[i+1]. Binary search; t strictly increasing. */
PETSC_EXTERN PetscInt HylcSplineLocate(PetscInt n, const PetscReal t[], PetscReal x);

/* The 1D Hermite basis at x: the spline is sum_{c=0,1} a[c] p[i+c] + b[c] m[i+c], with i returned
   (clamped to [0, n-2]; when extrapolating, only the end knot (c = 0 on the left, c = 1 on the
   right) has non-zero weights).
   da, db, dda, ddb (any may be NULL) receive the first and second x-derivatives of a and b. */
PETSC_EXTERN PetscInt HylcHermiteBasis(PetscInt n, const PetscReal t[], HylcSplineExt ext, PetscReal x, PetscReal a[2], PetscReal b[2], PetscReal da[2], PetscReal db[2], PetscReal dda[2], PetscReal ddb[2]);

/* Value of a 1D spline at x; d1, d2 (may be NULL) receive f'(x), f''(x). */
PETSC_EXTERN PetscReal HylcSpline1DEval(const HylcSpline1D *, PetscReal x, PetscReal *d1, PetscReal *d2);

/* Value of a 2D spline at (u, v); g (may be NULL) receives (f_u, f_v), H (may be NULL) receives
   (f_uu, f_uv, f_vv). */
PETSC_EXTERN PetscReal HylcSpline2DEval(const HylcSpline2D *, PetscReal u, PetscReal v, PetscReal g[2], PetscReal H[3]);

/* Raw-array forms of the same evaluations (for the fitting kernels, which work on bare arrays). */
PETSC_EXTERN PetscReal HylcHermite1DEval(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], HylcSplineExt ext, PetscReal x, PetscReal *d1, PetscReal *d2);
PETSC_EXTERN PetscReal HylcHermite2DEval(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], const PetscReal p[], const PetscReal mu[], const PetscReal mv[], const PetscReal muv[], HylcSplineExt ext, PetscReal u, PetscReal v,
                                         PetscReal g[2], PetscReal H[3]);

/* Local polynomial form of the pieces of a 1D Hermite spline (for the exact divided differences of the
   material evaluator). Piece i is the cubic (or, extrapolating, linear/constant/zero) polynomial the
   spline follows on its interval: i = -1 left of t[0], i = 0..n-2 on [t[i], t[i+1]), i = n-1 from t[n-1]
   on (the numbering of HylcSplineLocate). Node data are read as p[j - j0], m[j - j0] (j0 = 0 for whole
   arrays; a caller holding only the nodes j0, j0+1, ... of a slice passes its first node), and only
   the nodes max(i, 0)..min(i + 1, n - 1) of the piece are touched.
   HylcHermite1DPiece: c[0..3] with piece_i(x) = sum_k c[k] (x - x0)^k, for any x0.
   HylcHermite1DKnotJump: J[0..3] with piece_k(x) - piece_{k-1}(x) = sum_r J[r] (x - t[k])^r, the jump
   of the spline's polynomial across knot k (0 <= k <= n-1); J[0] = J[1] = 0 exactly wherever the
   spline is C1 (every inner knot; the end knots with linear extrapolation). */
PETSC_EXTERN void HylcHermite1DPiece(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], PetscInt j0, HylcSplineExt ext, PetscInt i, PetscReal x0, PetscReal c[4]);
PETSC_EXTERN void HylcHermite1DKnotJump(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], PetscInt j0, HylcSplineExt ext, PetscInt k, PetscReal J[4]);

/* The restriction v -> f(u, v) of a 2D spline at fixed u is the 1D Hermite spline on tv (same extrapolation
   mode) with node values P[j] and slopes M[j] = df/dv; this returns them for the v-nodes j = j0..j1 (into
   P[j - j0], M[j - j0]) and, where Pu/Mu and Puu/Muu are not NULL, their first and second u-derivatives. */
PETSC_EXTERN void HylcHermite2DSliceV(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal p[], const PetscReal mu[], const PetscReal mv[], const PetscReal muv[], HylcSplineExt ext, PetscReal u, PetscInt j0, PetscInt j1, PetscReal P[],
                                      PetscReal M[], PetscReal Pu[], PetscReal Mu[], PetscReal Puu[], PetscReal Muu[]);
