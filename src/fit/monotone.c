/* Shape-preserving kernels of the fit: Fritsch-Carlson monotone cubic, quasiconvex marching (S28) and
   the modified Carlson-Fritsch monotone bicubic of §S5 (S36-S42). See include/hylc/monotone.h and
   docs/fit.md. */
#include <hylc/monotone.h>

const char *const HylcMonotoneRules[] = {"circle", "box", "HylcMonotoneRule", "HYLC_MONOTONE_", NULL};
const char *const HylcFitCompats[]    = {"paper", "authors", "HylcFitCompat", "HYLC_FIT_COMPAT_", NULL};

static inline PetscReal Clamp(PetscReal x, PetscReal lo, PetscReal hi) { return x < lo ? lo : (x > hi ? hi : x); }

void HylcMonotoneCubic(PetscInt n, const PetscReal t[], const PetscReal p[], PetscReal m[], HylcMonotoneRule rule, PetscReal tol)
{
  /* zero slope at a local extremum of the data (neighbouring secants of opposite sign) */
  for (PetscInt i = 1; i < n - 1; i++) {
    const PetscReal dl = p[i] - p[i - 1], dr = p[i + 1] - p[i];
    if ((dl > 0 && dr < 0) || (dl < 0 && dr > 0)) m[i] = 0;
  }
  for (PetscInt i = 0; i < n - 1; i++) {
    const PetscReal dp = p[i + 1] - p[i], d = dp / (t[i + 1] - t[i]);
    PetscReal       alpha, beta;

    if (PetscAbsReal(dp) < tol) {
      m[i] = m[i + 1] = 0;
      continue;
    }
    alpha = m[i] / d;
    beta  = m[i + 1] / d;
    if (alpha < 0) alpha = 0;
    if (beta < 0) beta = 0;
    if (rule == HYLC_MONOTONE_CIRCLE) {
      const PetscReal r2 = alpha * alpha + beta * beta;
      if (r2 > 9) {
        const PetscReal tau = 3 / PetscSqrtReal(r2);
        alpha *= tau;
        beta *= tau;
      }
    } else {
      alpha = PetscMin(alpha, 3);
      beta  = PetscMin(beta, 3);
    }
    m[i]     = alpha * d;
    m[i + 1] = beta * d;
  }
}

void HylcQuasiconvex1D(PetscInt n, const PetscReal t[], PetscInt imin, PetscReal reg, PetscReal p[], PetscReal m[])
{
  for (PetscInt i = imin; i < n - 1; i++) {
    p[i + 1] = PetscMax(p[i + 1], p[i] + (t[i + 1] - t[i]) * reg);
    m[i + 1] = PetscMax(m[i + 1], reg);
  }
  for (PetscInt i = imin; i > 0; i--) {
    p[i - 1] = PetscMax(p[i - 1], p[i] + (t[i] - t[i - 1]) * reg);
    m[i - 1] = PetscMin(m[i - 1], -reg);
  }
}

typedef struct {
  PetscInt d2, i, j;
} Visit;

static int VisitCompare(const void *a, const void *b)
{
  const Visit *x = (const Visit *)a, *y = (const Visit *)b;
  if (x->d2 != y->d2) return x->d2 < y->d2 ? -1 : 1;
  if (x->j != y->j) return x->j < y->j ? -1 : 1;
  return x->i < y->i ? -1 : (x->i > y->i);
}

/*@C
  HylcQuasiconvex2D - Quasiconvex marching (S28) of a 2D table from its minimum node, in place: every other
  node, in order of squared index distance from the minimum, is raised to at least each of its neighbours
  toward the minimum plus reg times the knot distance (the 1D marching on the two grid lines through the
  minimum); then mu and mv are sign-clamped outward with |.| >= reg.

  Not collective

  Input Parameters:
+ nu, nv     - the knots along u and v
. tu, tv     - the knots (strictly increasing)
. imin, jmin - the minimum node
. reg        - the minimum outward slope (J/m^2 per normalised unit)
- compat     - HYLC_FIT_COMPAT_PAPER or HYLC_FIT_COMPAT_AUTHORS: the treatment of the minimum's own row and
               column

  Input/Output Parameters:
+ p  - the values, nu x nv (node (i, j) at j nu + i)
. mu - the slopes along u
- mv - the slopes along v

  Level: developer

.seealso: HylcQuasiconvex1D(), HylcMonotoneBicubic()
@*/
PetscErrorCode HylcQuasiconvex2D(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], PetscInt imin, PetscInt jmin, PetscReal reg, HylcFitCompat compat, PetscReal p[], PetscReal mu[], PetscReal mv[])
{
  Visit   *order;
  PetscInt nn = 0;

  PetscFunctionBegin;
  PetscCheck(imin >= 0 && imin < nu && jmin >= 0 && jmin < nv, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "minimum node (%" PetscInt_FMT ", %" PetscInt_FMT ") outside the %" PetscInt_FMT " x %" PetscInt_FMT " grid", imin, jmin, nu, nv);
  PetscCall(PetscMalloc1(nu * nv, &order));
  for (PetscInt j = 0; j < nv; j++)
    for (PetscInt i = 0; i < nu; i++) {
      if (i == imin && j == jmin) continue;
      order[nn].d2 = (i - imin) * (i - imin) + (j - jmin) * (j - jmin);
      order[nn].i  = i;
      order[nn].j  = j;
      nn++;
    }
  qsort(order, (size_t)nn, sizeof(Visit), VisitCompare);
  /* a node's neighbours toward the minimum are strictly closer, so they are final when it is visited */
  for (PetscInt q = 0; q < nn; q++) {
    const PetscInt i = order[q].i, j = order[q].j, k = j * nu + i;
    if (i != imin) {
      const PetscInt ii = i > imin ? i - 1 : i + 1;
      p[k]              = PetscMax(p[k], p[j * nu + ii] + PetscAbsReal(tu[i] - tu[ii]) * reg);
    }
    if (j != jmin) {
      const PetscInt jj = j > jmin ? j - 1 : j + 1;
      p[k]              = PetscMax(p[k], p[jj * nu + i] + PetscAbsReal(tv[j] - tv[jj]) * reg);
    }
  }
  PetscCall(PetscFree(order));
  /* slopes point away from the minimum */
  for (PetscInt j = 0; j < nv; j++)
    for (PetscInt i = 0; i < nu; i++) {
      const PetscInt k = j * nu + i;
      if (i > imin)
        mu[k] = PetscMax(mu[k], reg);
      else if (i < imin)
        mu[k] = PetscMin(mu[k], -reg);
      if (j > jmin)
        mv[k] = PetscMax(mv[k], reg);
      else if (j < jmin || compat == HYLC_FIT_COMPAT_AUTHORS)
        mv[k] = PetscMin(mv[k], -reg);
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A view of the grid for one direction of monotonicity: "along" is the direction of the monotone
   edges (index a, knots ta, stride sa), "across" the other one (index c, knots tc, stride sc). The
   x-direction problem is (u, v); the y-direction one is the transposed (v, u). */
typedef struct {
  PetscInt         na, nc, sa, sc;
  const PetscReal *ta, *tc;
} Dir;

/* sweep 1, (S36): slopes along each edge within [0, 3 delta] (or mirrored), so the edge is monotone */
static void ClampEdgeSlopes(const Dir *D, const PetscReal p[], PetscReal ma[])
{
  for (PetscInt c = 0; c < D->nc; c++)
    for (PetscInt a = 0; a < D->na - 1; a++) {
      const PetscInt  k0 = a * D->sa + c * D->sc, k1 = k0 + D->sa;
      const PetscReal d  = (p[k1] - p[k0]) / (D->ta[a + 1] - D->ta[a]);
      const PetscReal lo = PetscMin(0, 3 * d), hi = PetscMax(0, 3 * d);
      ma[k0] = Clamp(ma[k0], lo, hi);
      ma[k1] = Clamp(ma[k1], lo, hi);
    }
}

/* Fig. S6: brings (m0, m1) into l <= m1 - m0 <= u (l <= 0 <= u) without increasing |m0|, |m1| or
   changing their signs. */
static void ProjectDifference(PetscReal *m0, PetscReal *m1, PetscReal l, PetscReal u)
{
  const PetscReal a = *m0, b = *m1, s = a + b;

  if (b - a > u) {
    if (s > u) {
      *m0 = PetscMax(a, 0);
      *m1 = *m0 + u;
    } else if (s < -u) {
      *m1 = PetscMin(b, 0);
      *m0 = *m1 - u;
    } else {
      *m0 = 0.5 * (s - u);
      *m1 = 0.5 * (s + u);
    }
    return;
  }
  if (b - a < l) {
    if (s > -l) {
      *m1 = PetscMax(b, 0);
      *m0 = *m1 - l;
    } else if (s < l) {
      *m0 = PetscMin(a, 0);
      *m1 = *m0 + l;
    } else {
      *m0 = 0.5 * (s - l);
      *m1 = 0.5 * (s + l);
    }
    return;
  }
}

/* The bounds (S40), (S41) on the mixed difference m_across[a+1,c] - m_across[a,c] of edge (a, c);
   ma are the along-slopes used in b (S41). The side without a cell is unbounded, or bounded by 0
   when extrapolating (§S3.5: a cell with an edge at infinity). */
static void EdgeBounds(const Dir *D, const PetscReal p[], const PetscReal ma[], PetscInt a, PetscInt c, PetscBool extrapolate, PetscReal *l, PetscReal *u)
{
  const PetscInt  k0 = a * D->sa + c * D->sc, k1 = k0 + D->sa;
  const PetscReal h = D->ta[a + 1] - D->ta[a], dp = p[k1] - p[k0];
  const PetscReal none  = extrapolate ? 0 : PETSC_INFINITY;
  const PetscBool above = (PetscBool)(c < D->nc - 1), below = (PetscBool)(c > 0);
  const PetscReal kup = above ? D->tc[c + 1] - D->tc[c] : 0, kdn = below ? D->tc[c] - D->tc[c - 1] : 0;

  if (dp == 0) { /* a flat edge is both increasing and decreasing: each adjacent cell pins the difference to 0 */
    *l = (above || below) ? 0 : -none;
    *u = (above || below) ? 0 : none;
  } else if (dp > 0) {
    const PetscReal b = PetscMax(0, PetscMin(3 * dp, 3 * dp - h * PetscMax(ma[k0], ma[k1])));
    *l                = above ? -b / kup : -none;
    *u                = below ? b / kdn : none;
  } else {
    const PetscReal b = PetscMin(0, PetscMax(3 * dp, 3 * dp - h * PetscMin(ma[k0], ma[k1])));
    *l                = below ? b / kdn : -none;
    *u                = above ? -b / kup : none;
  }
}

static PetscBool LineFeasible(const Dir *D, const PetscReal p[], const PetscReal ma[], const PetscReal mc[], PetscInt c, PetscBool extrapolate)
{
  for (PetscInt a = 0; a < D->na - 1; a++) {
    const PetscInt k0 = a * D->sa + c * D->sc, k1 = k0 + D->sa;
    PetscReal      l, u;
    EdgeBounds(D, p, ma, a, c, extrapolate, &l, &u);
    if (mc[k1] - mc[k0] > u || mc[k1] - mc[k0] < l) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* sweep 2: project the mixed differences of the across-slopes mc on every edge of a line, forward and
   then backward (the paper's two sweeps); the pair of sweeps is repeated while an edge of the line is
   still violated (each projection only shrinks slopes, so this converges; at most 100 rounds) */
static void ProjectMixedDifferences(const Dir *D, const PetscReal p[], const PetscReal ma[], PetscReal mc[], PetscBool extrapolate)
{
  for (PetscInt c = 0; c < D->nc; c++) {
    for (PetscInt it = 0; it < 100; it++) {
      for (PetscInt pass = 0; pass < 2; pass++)
        for (PetscInt q = 0; q < D->na - 1; q++) {
          const PetscInt a  = pass == 0 ? q : D->na - 2 - q;
          const PetscInt k0 = a * D->sa + c * D->sc, k1 = k0 + D->sa;
          PetscReal      l, u;
          EdgeBounds(D, p, ma, a, c, extrapolate, &l, &u);
          ProjectDifference(&mc[k0], &mc[k1], l, u);
        }
      if (LineFeasible(D, p, ma, mc, c, extrapolate)) break;
    }
  }
}

/* sweep 3, (S42a-d): clamp the mixed derivative at every node into the constraints of the (up to four)
   adjacent cells, each expressed on the cell's edge through the node; a decreasing edge swaps the two
   bounds, so each interval is [min, max] of its two expressions */
static void ClampMixed(const Dir *D, const PetscReal p[], const PetscReal ma[], const PetscReal mc[], PetscReal muv[], const PetscReal in[])
{
  for (PetscInt c = 0; c < D->nc; c++)
    for (PetscInt a = 0; a < D->na; a++) {
      const PetscInt  k  = a * D->sa + c * D->sc;
      const PetscReal mA = ma[k];
      PetscReal       x  = in[k];

      for (PetscInt e = a - 1; e <= a; e++) { /* edges (a-1, c) and (a, c) */
        if (e < 0 || e >= D->na - 1) continue;
        const PetscInt  k0 = e * D->sa + c * D->sc, k1 = k0 + D->sa;
        const PetscReal h = D->ta[e + 1] - D->ta[e], dp = p[k1] - p[k0], dm = mc[k1] - mc[k0];
        if (c < D->nc - 1) { /* cell on the upper side: (S42a), (S42b) */
          const PetscReal kk = D->tc[c + 1] - D->tc[c];
          const PetscReal L = -3 * mA / kk, U = 3 * (dm / h + 3 * dp / (h * kk) - mA / kk);
          x = Clamp(x, PetscMin(L, U), PetscMax(L, U));
        }
        if (c > 0) { /* cell on the lower side: (S42c), (S42d) */
          const PetscReal kk = D->tc[c] - D->tc[c - 1];
          const PetscReal L = 3 * (dm / h - 3 * dp / (h * kk) + mA / kk), U = 3 * mA / kk;
          x = Clamp(x, PetscMin(L, U), PetscMax(L, U));
        }
      }
      muv[k] = x;
    }
}

/*@C
  HylcMonotoneBicubic - The modified Carlson-Fritsch monotone bicubic (S36-S42), in place on the slopes:
  sweep 1 clamps mu and mv per edge (S36), sweep 2 projects the mixed differences (S40)-(S41) with the
  six-case projection of Fig. S6, sweep 3 clamps muv (S42a-d); include/hylc/monotone.h states what is then
  monotone.

  Not collective

  Input Parameters:
+ nu, nv      - the knots along u and v
. tu, tv      - the knots (strictly increasing)
. p           - the values, nu x nv (node (i, j) at j nu + i; not changed)
. extrapolate - PETSC_TRUE: the extrapolation-side bound 0 on the boundary cells
- compat      - HYLC_FIT_COMPAT_PAPER or HYLC_FIT_COMPAT_AUTHORS (only the transposed S42 clamp)

  Input/Output Parameters:
+ mu  - the slopes along u
. mv  - the slopes along v
- muv - the mixed derivatives

  Level: developer

.seealso: HylcMonotoneCubic(), HylcQuasiconvex2D()
@*/
PetscErrorCode HylcMonotoneBicubic(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], const PetscReal p[], PetscReal mu[], PetscReal mv[], PetscReal muv[], PetscBool extrapolate, HylcFitCompat compat)
{
  const Dir  X = {nu, nv, 1, nu, tu, tv}, Y = {nv, nu, nu, 1, tv, tu};
  PetscReal *mvOld, *muvIn;

  PetscFunctionBegin;
  PetscCall(PetscMalloc2(nu * nv, &mvOld, nu * nv, &muvIn));
  /* sweep 1 */
  ClampEdgeSlopes(&X, p, mu);
  ClampEdgeSlopes(&Y, p, mv);
  /* sweep 2: differences of mv along u (bounds from mu), then of mu along v with the old mv */
  PetscCall(PetscArraycpy(mvOld, mv, nu * nv));
  ProjectMixedDifferences(&X, p, mu, mv, extrapolate);
  ProjectMixedDifferences(&Y, p, mvOld, mu, extrapolate);
  /* sweep 3 */
  PetscCall(PetscArraycpy(muvIn, muv, nu * nv));
  if (compat == HYLC_FIT_COMPAT_AUTHORS) {
    ClampMixed(&Y, p, mv, mu, muv, muvIn); /* the x-direction clamp is computed and dropped */
  } else {
    ClampMixed(&X, p, mu, mv, muv, muvIn);
    PetscCall(PetscArraycpy(muvIn, muv, nu * nv));
    ClampMixed(&Y, p, mv, mu, muv, muvIn);
  }
  PetscCall(PetscFree2(mvOld, muvIn));
  PetscFunctionReturn(PETSC_SUCCESS);
}
