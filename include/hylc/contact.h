#pragma once
/* Yarn-yarn contact: element kernels for one pair of segments and a broadphase over many segments.
   No PETSc objects (see docs/contact.md and docs/method.md §4).

   Conventions shared by the pair kernels:
   - A pair is segment a = (a0, a1) and segment b = (b0, b1); its 12 degrees of freedom are ordered
     x = (a0, a1, b0, b1), three Cartesian components each.
   - Gradients are double[12]; Hessians are double[144], dense, row-major (H[12*i + j] = d2E/dx_i dx_j),
     symmetric.
   - The penalty is f(delta) = 1/delta^2 + delta^2 - 2 for delta < 1 and 0 otherwise, delta = dist/(2 r),
     r the yarn radius: the tubes touch exactly at dist = 2 r. f is C1 at delta = 1 (f'' jumps from 8 to 0).
   - Every output (E, g, H) is multiplied by the fractional weight w (docs/method.md §5.2); w = 1 gives the
     plain energy.
   - g and H may be NULL (not computed). When given they are overwritten (not accumulated); a rejected
     pair (segment distance >= 2 r) returns E = 0 and zero-filled g and H.
   - Pure functions of their arguments; thread-safe (but see HylcGaussLegendre01). */

#include <stddef.h>

#define HYLC_GAUSS_MAX 16

/* Gauss-Legendre rule with n points (1 <= n <= HYLC_GAUSS_MAX) on [0, 1]: *nodes and *weights point to
   internal arrays of length n (nodes ascending, weights summing to 1). The rules are computed on first
   use (Newton iteration on the Legendre recurrence, to machine precision) and cached for the lifetime of
   the program. Returns 0, or -1 for n out of range (pointers set to NULL).
   The first call for a given n writes the cache: in multi-threaded code call it once up front. */
int HylcGaussLegendre01(int n, const double **nodes, const double **weights);

/* Penalty f(delta) and its first two derivatives (delta > 0); zero for delta >= 1. */
void HylcContactPenalty(double delta, double *f, double *df, double *d2f);

/* Quadrature (Kaldor) contact energy of one segment pair, docs/method.md §4.1:
     E = w k_c la lb sum_g sum_h w_g w_h f(|p_g - q_h| / (2 r)),
     p_g = (1 - s_g) a0 + s_g a1,  q_h = (1 - s_h) b0 + s_h b1,
   with (s_g, w_g) the n-point Gauss-Legendre rule on [0, 1] for both segments.
   la, lb: rest lengths of the segments (only scale the result); kc: stiffness; r: yarn radius;
   n: points per segment (1..16); w: fractional weight.
   The gradient and Hessian are the exact derivatives of this (discrete) E. If the segment-segment distance
   is >= 2 r, no quadrature point pair can be in contact and the function returns 0 immediately.
   A quadrature point pair at distance exactly 0 gives an infinite energy (f has a pole); this only
   happens for interpenetrating yarns.
   Returns E; g (12) and H (144) as described above, either may be NULL. */
double HylcContactQuadrature(const double a0[3], const double a1[3], const double b0[3], const double b1[3], double la, double lb, double kc, double r, int n, double w, double g[12], double H[144]);

/* Closest-point contact energy of one segment pair, docs/method.md §4.3:
     E = w k_c la lb f(d / (2 r)),  d = min over s, t in [0,1] of |a0 + s (a1 - a0) - b0 - t (b1 - b0)|.
   The gradient follows from the envelope theorem, the Hessian is exact: the Schur complement of the
   distance minimisation over the parameters that are not clamped at 0 or 1.
   Where d is not twice differentiable the function returns one-sided derivatives:
   - exactly (or, below a relative tolerance 1e-12 on the normal-equation determinant, nearly) parallel
     segments whose projections overlap have a whole segment of closest-point pairs; d is then not
     differentiable (its gradient depends on which pair is chosen). The kernel takes the pair that
     HylcSegmentSegmentDistance returns (s = 0 and t solved; if t clamps, s re-solved against that
     endpoint), treats every parameter not strictly inside (0,1) as fixed and returns the gradient and
     Hessian of the distance from the chosen point to the other segment: the derivative along directions
     that keep the chosen point closest (a one-sided derivative, an element
     of the generalized gradient). Energy is always exact and continuous.
   - configurations where an unconstrained minimiser lies exactly on the boundary of [0,1]^2 (kinks of
     d) are handled as clamped.
   - degenerate segments (zero length, below 1e-14) have their parameter fixed at 0.
   Returns E; g (12) and H (144) as described above, either may be NULL. If s, t are not NULL they
   receive the closest-point parameters (also for rejected pairs); if dist is not NULL it receives d. */
double HylcContactClosestPoint(const double a0[3], const double a1[3], const double b0[3], const double b1[3], double la, double lb, double kc, double r, double w, double g[12], double H[144], double *s, double *t, double *dist);

/* ---------------------------------------------------------------------------------------------------
   Broadphase.

   Segment input, for HylcBVHBuild, HylcBVHRefit and HylcBroadphaseBruteForce: x and edges.
   - edges == NULL: x holds 6 doubles per segment, x[6 i .. 6 i + 2] = start, x[6 i + 3 .. 6 i + 5] = end.
   - edges != NULL: x holds vertex positions (3 doubles each) and segment i runs from vertex edges[2 i]
     to vertex edges[2 i + 1].
   The box of a segment is the bounding box of its endpoints inflated by margin on every side (margin =
   r for contact: boxes overlap whenever the segment distance is < 2 r). Two boxes overlap when their
   closed intervals intersect on all three axes (touching counts).

   Ghost pruning: an optional per-segment flag ghost[i] != 0 means segment i has no original vertex, so
   any pair of two flagged segments has fractional weight 0. Such pairs are never reported (subtrees in
   which every segment is flagged are skipped as a whole); a pair of a flagged and an unflagged segment is
   always reported.

   Functions returning int return 0 on success and -1 on failed allocation or bad arguments. */

/* A growable list of segment pairs: pair k is (idx[2 k], idx[2 k + 1]), with idx[2 k] < idx[2 k + 1].
   Zero-initialise it ({0}) before first use; release it with HylcPairListFree. */
typedef struct {
  int   *idx;
  size_t n, cap; /* number of pairs, capacity in pairs */
} HylcPairList;

void HylcPairListFree(HylcPairList *list);
/* Sorts the pairs lexicographically (deterministic order, e.g. for comparisons or assembly locality). */
void HylcPairListSort(HylcPairList *list);

typedef struct _n_HylcBVH *HylcBVH;

/* Creates an empty static AABB hierarchy for nseg segments (nseg >= 0). */
int HylcBVHCreate(int nseg, HylcBVH *bvh);
/* Builds the hierarchy (median split on the widest axis of the box centres, up to 4 segments per leaf)
   for the given segment positions and margin. Can be called again to rebuild from scratch. */
int HylcBVHBuild(HylcBVH bvh, const double *x, const int *edges, double margin);
/* Recomputes all boxes for moved segments, keeping the tree topology (same margin as Build). Pairs are
   still exact after a refit; only the pruning efficiency degrades when segments move far. */
int HylcBVHRefit(HylcBVH bvh, const double *x, const int *edges);
/* Sets (copies) the per-segment ghost flags used for pruning; NULL disables ghost pruning. */
int HylcBVHSetGhost(HylcBVH bvh, const unsigned char *ghost);
/* Self-query: replaces the contents of *pairs by all pairs (i < j) whose boxes overlap (minus pairs of
   two ghost-flagged segments). Order: deterministic, unspecified (see HylcPairListSort). */
int HylcBVHQuery(HylcBVH bvh, HylcPairList *pairs);
/* Destroys the hierarchy and sets *bvh to NULL (accepts NULL and *bvh == NULL). */
void HylcBVHDestroy(HylcBVH *bvh);

/* O(nseg^2) reference: the same pairs as HylcBVHQuery on the same input, found by testing all boxes.
   ghost may be NULL. Replaces the contents of *pairs; pairs come in lexicographic order. */
int HylcBroadphaseBruteForce(int nseg, const double *x, const int *edges, double margin, const unsigned char *ghost, HylcPairList *pairs);
