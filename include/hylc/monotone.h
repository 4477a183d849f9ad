#pragma once
/* Shape-preserving kernels of the fit (seeds §S3, §S5; docs/method.md §9): quasiconvex marching (S28),
   the Fritsch-Carlson monotone cubic, and the modified Carlson-Fritsch monotone bicubic (S36-S42).
   Plain C on plain arrays, in place; 2D arrays have nu*nv entries, node (i, j) at j*nu + i (u = first
   coordinate, index i; v = second, index j), as in include/hylc/spline.h.
   Knots are strictly increasing. The 1D kernels do not allocate; the 2D kernels allocate their own
   scratch and return an error code only when that fails. */
#include <hylc/sys.h>

/* How the 1D slopes are limited on an interval with secant d != 0, alpha = m_i/d, beta = m_{i+1}/d:
   CIRCLE: alpha^2 + beta^2 <= 9 (Fritsch-Carlson, the authors' code); BOX: 0 <= alpha, beta <= 3
   (consistent with (S36)). Negative alpha or beta are set to 0 first in both cases. */
typedef enum { HYLC_MONOTONE_CIRCLE = 0, HYLC_MONOTONE_BOX = 1 } HylcMonotoneRule;
PETSC_EXTERN const char *const HylcMonotoneRules[];

/* Which variant of the two places where the authors' code departs from the paper (docs/method.md §9.1):
   PAPER: the S42 mixed-derivative clamps of both directions are applied, and in the 2D marching the
   slopes on the minimum's own row/column are not sign-clamped; AUTHORS: as their code (only the
   transposed S42 clamp reaches the output; mv <= -reg on the minimum's row). */
typedef enum { HYLC_FIT_COMPAT_PAPER = 0, HYLC_FIT_COMPAT_AUTHORS = 1 } HylcFitCompat;
PETSC_EXTERN const char *const HylcFitCompats[];

/* Fritsch-Carlson monotone slopes, in place on m[0..n-1]: m_i = 0 where the neighbouring secants change
   sign (or one is zero); on each interval with |p_{i+1} - p_i| < tol both slopes are set to 0;
   slopes of the wrong sign are set to 0; then the rule limits (alpha, beta). The result is monotone on
   every interval whose data are monotone. */
PETSC_EXTERN void HylcMonotoneCubic(PetscInt n, const PetscReal t[], const PetscReal p[], PetscReal m[], HylcMonotoneRule rule, PetscReal tol);

/* Quasiconvex marching (S28) of a 1D table from the minimum node imin outward: for a node i and its
   outward neighbour i', p_{i'} >= p_i + |t_{i'} - t_i| reg, and the outward slope of i' (m on the right
   of imin, -m on the left) >= reg. The slope at imin is left alone. */
PETSC_EXTERN void HylcQuasiconvex1D(PetscInt n, const PetscReal t[], PetscInt imin, PetscReal reg, PetscReal p[], PetscReal m[]);

/* Quasiconvex marching of a 2D table from (imin, jmin): every other node, in order of squared index
   distance from the minimum, is raised to at least each of its neighbours toward the minimum (in i
   and in j) plus reg times the knot distance; on the two grid lines through the minimum this is the
   1D marching. Then mu and mv are sign-clamped by the direction from the minimum (|.| >= reg,
   outward); compat selects the treatment of the minimum's own row/column (see HylcFitCompat). */
PETSC_EXTERN PetscErrorCode HylcQuasiconvex2D(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], PetscInt imin, PetscInt jmin, PetscReal reg, HylcFitCompat compat, PetscReal p[], PetscReal mu[], PetscReal mv[]);

/* The modified Carlson-Fritsch monotone bicubic (§S5), in place on mu, mv, muv (p is not changed):
   sweep 1 clamps mu and mv per edge to (S36); sweep 2 projects the mixed differences of mv along u
   (and of mu along v) to (S40)-(S41) with the six-case projection of Fig. S6, forward then backward
   along each row (columns use the old values); sweep 3 clamps muv to (S42a-d) of its adjacent cells.
   extrapolate = PETSC_TRUE uses the extrapolation-side bound 0 of §S3.5 on the boundary cells.
   With compat = PAPER the interpolant is then monotone in u on every cell whose data are monotone in u
   along both of its horizontal edges (an edge with equal end values counts as either sense), and
   likewise in v; with extrapolate and muv = 0 on the boundary this extends to the linearly
   extrapolated strips. With compat = AUTHORS only the v statement holds (tests/unit/test_monotone.c).
   Sweep 2 repeats its forward/backward pair on a line while an edge is still violated (never needed
   in the tests; a safety net). */
PETSC_EXTERN PetscErrorCode HylcMonotoneBicubic(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], const PetscReal p[], PetscReal mu[], PetscReal mv[], PetscReal muv[], PetscBool extrapolate, HylcFitCompat compat);
