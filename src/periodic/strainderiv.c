/* HylcPeriodic: the derivatives of the tile energy and of the constraint residuals with respect to the
   macroscopic strain at a fixed state (include/hylc/periodic.h): what the envelope theorem needs for the stress
   dPsi/dz of an equilibrium (HylcMicroGetStrainGradient()). */
#include "periodicimpl.h"

/* The ghosts' positions (full vertices N.., 3 each), their maps' rotations T (9 each) and the kept constraint
   residuals at the state P->y for the strain z, through the midsurface msfd: x_k = T_k (y_o - x0_o) + x0_k with T_k = R(xi_k) R(xi_o)^T and x0 the
   deformed initial guess phi(xi) + h n(xi) at z (the elimination of docs/method.md §5.3 at that strain). */
static PetscErrorCode MapAt(HylcPeriodic P, const PetscReal z[6], PetscReal xg[], PetscReal Tg[], PetscReal c[], PetscReal xih[], PetscReal x0[])
{
  const PetscInt N = P->N;

  PetscFunctionBegin;
  PetscCall(HylcMidsurfaceSetStrain(P->msfd, z));
  PetscCall(HylcMidsurfaceSetBox(P->msfd, P->msbox, P->msbox + 2));
  PetscCall(HylcMidsurfaceSetUp(P->msfd));
  for (PetscInt k = 0; k < P->nfv; k++) RefPos(P, k, xih + 3 * k);
  PetscCall(HylcMidsurfaceEvaluate(P->msfd, P->nfv, xih, x0, NULL));
  for (PetscInt k = N; k < P->nfv; k++) {
    const PetscInt o = P->fo[k];
    PetscReal      Ro[9], Rk[9], *T = Tg + 9 * (k - N), d[3], Td[3];
    PetscCall(HylcMidsurfaceGetRotation(P->msfd, P->xi + 3 * o, Ro));
    PetscCall(HylcMidsurfaceGetRotation(P->msfd, xih + 3 * k, Rk));
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) T[3 * i + j] = Rk[3 * i] * Ro[3 * j] + Rk[3 * i + 1] * Ro[3 * j + 1] + Rk[3 * i + 2] * Ro[3 * j + 2];
    for (int i = 0; i < 3; i++) d[i] = P->y[4 * o + i] - x0[3 * o + i];
    Mat3(T, d, Td);
    for (int i = 0; i < 3; i++) xg[3 * (k - N) + i] = Td[i] + x0[3 * k + i];
  }
  PetscCall(HylcPeriodicConstraintResidualAt_Private(P, P->msfd, x0, P->y, c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* II (II00, II01, II11) reduced to its principal curvature of larger magnitude: lambda v v^T */
static void RankOne(const PetscReal II[3], PetscReal out[3])
{
  const PetscReal a = II[0], b = II[1], c = II[2], m = 0.5 * (a + c), r = PetscSqrtReal(0.25 * (a - c) * (a - c) + b * b);
  const PetscReal l1 = m + r, l2 = m - r, l = PetscAbsReal(l1) >= PetscAbsReal(l2) ? l1 : l2;
  PetscReal       v[2];
  if (PetscAbsReal(a - l) + PetscAbsReal(b) >= PetscAbsReal(c - l) + PetscAbsReal(b))
    v[0] = -b, v[1] = a - l; /* (a - l, b) . v = 0 */
  else
    v[0] = c - l, v[1] = -b;
  {
    const PetscReal n = PetscSqrtReal(v[0] * v[0] + v[1] * v[1]);
    if (n == 0) { /* a multiple of the identity: keep it */
      out[0] = a, out[1] = b, out[2] = c;
      return;
    }
    v[0] /= n, v[1] /= n;
  }
  out[0] = l * v[0] * v[0];
  out[1] = l * v[0] * v[1];
  out[2] = l * v[1] * v[1];
}

/* How the derivative along the curvature component j (3 II00, 4 II01, 5 II11) is formed at the strain z:
   sum_i w[i] (map(II + h B_i) - map(II - h B_i)) / 2h over n terms, each perturbed II made rank one (trunc)
   where the closed form is to be used. The perturbation E_j: at a flat II its eigen-decomposition (the map is
   linear in II to first order: II01's E = u u^T - v v^T, u, v = (1, +-1)/sqrt 2); at a singly curved
   II = kappa d d^T a perturbation with no part across d (d_perp . E d_perp = 0) changes kappa and turns d, the
   second principal curvature being O(h^2) and even in h, so the rank-one truncation leaves the central
   difference exact to O(h^2). Otherwise (a curvature across a bent strain, or a doubly curved strain) the
   perturbed strain is doubly curved: *poisson. */
static void CurvatureDirections(const PetscReal z[6], int j, PetscInt *n, PetscReal w[2], PetscReal B[2][3], PetscBool *trunc, PetscBool *poisson)
{
  const PetscReal E[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, *Ej = E[j - 3];
  double          H, d[2];
  const double    II[3] = {z[3], z[4], z[5]};

  *trunc = *poisson = PETSC_FALSE;
  *n                = 1;
  w[0]              = 1;
  for (int k = 0; k < 3; k++) B[0][k] = Ej[k];
  switch (HylcMacroClassifyII(II, 0, &H, d)) {
  case HYLC_MACRO_FLAT:
    if (j == 4) {
      *n      = 2;
      w[1]    = -1;
      B[0][0] = B[0][1] = B[0][2] = 0.5;
      B[1][0] = B[1][2] = 0.5;
      B[1][1]           = -0.5;
    }
    *trunc = PETSC_TRUE; /* rank one already; keeps the rounding of h B classified singly */
    break;
  case HYLC_MACRO_SINGLY: {
    const PetscReal dp[2] = {-d[1], d[0]}, across = dp[0] * dp[0] * Ej[0] + 2 * dp[0] * dp[1] * Ej[1] + dp[1] * dp[1] * Ej[2];
    if (PetscAbsReal(across) <= 1e-12)
      *trunc = PETSC_TRUE;
    else
      *poisson = PETSC_TRUE;
  } break;
  default:
    *poisson = PETSC_TRUE;
  }
}

/*@C
  HylcPeriodicEvaluateStrainDerivative - The partial derivatives of the tile energy E and of the constraint
  residuals c = A y - dL with respect to the strain z = (sx, sa, sy, II00, II01, II11), at fixed reduced
  unknowns y (the originals' positions and twists): with y fixed only the ghosts move, a ghost k of the
  original o at x_k = T_k(z) y_o + d_k(z) (the co-rotated periodic map), and the constraint rows move with
  R(xi; z) and the deformed reference. With the multipliers lambda of an equilibrium (g_y + A^T lambda = 0)
  the envelope theorem gives dE_eq/dz_j = dE/dz_j + lambda . dc/dz_j for the equilibrium energy E_eq(z)
  (HylcMicroGetStrainGradient()).

  Not collective

  Input Parameters:
+ P     - the periodic tile, set up, its state set (HylcPeriodicSetState())
. mask  - energy terms (as HylcPeriodicEvaluate())
- comps - the strain components to compute: bit j for z_j (HYLC_STRAIN_ALL_BITS = 63 for all six), or'ed with
          HYLC_STRAIN_NO_POISSON to leave NaN a component that needs a Poisson midsurface at a flat or singly
          curved strain (below)

  Output Parameters:
+ parts - the energy of each term (J)
. gy    - the reduced gradient (4 per original vertex; may be NULL)
. dEdz  - dE/dz_j, j = 0..5 (J, and J m for the curvatures); NaN for a component not computed
- dcdz  - dc/dz_j of the kept constraint rows, m x 6 row-major (HylcPeriodicGetConstraints(); may be NULL)

  Notes:
  dE/dz_j is the virial of the ghosts: the sum over the ghosts k of g_k . dx_k/dz_j, g_k the gradient of E
  with respect to the position of ghost k (the elements' gradients accumulated per full vertex, fractional
  weights included; the kernels' gradients account for the time-parallel transport of the ghosts' reference
  frames, ghost twists equal their originals'), plus, where the map turns (II != 0), the twist moment of each
  ghost edge times the turn of its frame about its tangent: a ghost's frame is its original's turned by T_k.

  At II = 0 the in-plane components are exact: the map is the translation by A (s1 px, s2 py) and
  dx_k/dz_j = (dA/dz_j (s1 px, s2 py), 0). The others are central differences of the map (steps 1e-6 in sx,
  sa, sy and 1e-6 / max(px, py) in the curvatures), on the closed-form midsurface wherever the perturbed strains
  are flat or singly curved or can be made so without changing the derivative: at a flat strain a curvature
  perturbation is split into rank-one ones (the map is linear in II to first order), at a singly curved
  strain a perturbation that only changes its curvature or turns its axis (II01 at a bent sample) is made
  rank one (the second principal curvature is O(h^2) and even in h). A curvature across the axis of a bent
  strain (II11 at II00 != 0), and every curvature component of a doubly curved strain, need two Poisson
  midsurfaces (about 0.1 s each at the default grid): with HYLC_STRAIN_NO_POISSON they are left NaN at a flat or
  singly curved strain. The differenced functions are smooth, so their error is far below the solve's. A
  degenerate geometry or a non-finite energy is an error, as in HylcPeriodicEvaluate().

  Level: advanced

.seealso: HylcPeriodicEvaluate(), HylcPeriodicGetConstraints(), HylcMicroGetStrainGradient()
@*/
PetscErrorCode HylcPeriodicEvaluateStrainDerivative(HylcPeriodic P, int mask, int comps, PetscReal parts[4], PetscReal gy[], PetscReal dEdz[6], PetscReal dcdz[])
{
  const PetscInt  N = P->N, ng = P->nfv - N, m = P->ncons;
  const PetscBool flat   = (PetscBool)(P->z[3] == 0 && P->z[4] == 0 && P->z[5] == 0);
  const double    IIz[3] = {P->z[3], P->z[4], P->z[5]};
  const PetscBool doubly = (PetscBool)(HylcMacroClassifyII(IIz, 0, NULL, NULL) == HYLC_MACRO_DOUBLY);
  PetscReal      *gfull, *gtfull, *xp, *xm, *Tp, *Tm, *cp, *cm, *xih, *x0, dA[12];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(PetscMalloc7(3 * P->nfv, &gfull, 3 * ng, &xp, 3 * ng, &xm, m, &cp, m, &cm, 3 * P->nfv, &xih, 3 * P->nfv, &x0));
  PetscCall(PetscMalloc3(P->nchain, &gtfull, 9 * ng, &Tp, 9 * ng, &Tm));
  PetscCall(HylcPeriodicEvaluateFull_Private(P, mask, parts, gy, gfull, gtfull));
  if (flat) StretchDerivatives(P->z, dA);
  if (flat && dcdz && (comps & 7)) { /* the in-plane columns, exact */
    PetscReal *d3;
    PetscCall(PetscMalloc1(3 * m, &d3));
    PetscCall(HylcPeriodicConstraintStrainDerivative_Private(P, d3));
    for (PetscInt i = 0; i < m; i++)
      for (int j = 0; j < 3; j++) dcdz[6 * i + j] = d3[3 * i + j];
    PetscCall(PetscFree(d3));
  }
  for (int j = 0; j < 6; j++) {
    PetscInt  nt    = 1;
    PetscReal wt[2] = {1, 0}, B[2][3], s = 0;
    PetscBool trunc = PETSC_FALSE, poisson = doubly;
    if (j >= 3) CurvatureDirections(P->z, j, &nt, wt, B, &trunc, &poisson);
    if (!(comps & (1 << j)) || (poisson && !doubly && (comps & HYLC_STRAIN_NO_POISSON))) {
      dEdz[j] = (PetscReal)NAN;
      if (dcdz)
        for (PetscInt i = 0; i < m; i++) dcdz[6 * i + j] = (PetscReal)NAN;
      continue;
    }
    if (flat && j < 3) {
      for (PetscInt k = N; k < P->nfv; k++) {
        const PetscReal sh[2] = {P->fs[2 * k] * P->D.px, P->fs[2 * k + 1] * P->D.py}, *g = gfull + 3 * k;
        s += g[0] * (dA[4 * j] * sh[0] + dA[4 * j + 1] * sh[1]) + g[1] * (dA[4 * j + 2] * sh[0] + dA[4 * j + 3] * sh[1]);
      }
      dEdz[j] = s;
      continue;
    }
    if (!P->msfd) {
      PetscCall(HylcMidsurfaceDuplicate(P->ms, &P->msfd));
      PetscCall(HylcMidsurfaceSetType(P->msfd, HYLC_MIDSURFACE_AUTO)); /* closed where the strain allows, else Poisson */
    }
    if (dcdz)
      for (PetscInt i = 0; i < m; i++) dcdz[6 * i + j] = 0;
    for (PetscInt q = 0; q < nt; q++) {
      const PetscReal h = j < 3 ? 1e-6 : 1e-6 / PetscMax(P->D.px, P->D.py);
      PetscReal       zp[6], zm[6];
      for (int i = 0; i < 6; i++) zp[i] = zm[i] = P->z[i];
      if (j < 3)
        zp[j] += h, zm[j] -= h;
      else {
        for (int i = 0; i < 3; i++) zp[3 + i] += h * B[q][i], zm[3 + i] -= h * B[q][i];
        if (trunc) {
          PetscReal r[3];
          RankOne(zp + 3, r);
          for (int i = 0; i < 3; i++) zp[3 + i] = r[i];
          RankOne(zm + 3, r);
          for (int i = 0; i < 3; i++) zm[3 + i] = r[i];
        }
      }
      PetscCall(MapAt(P, zp, xp, Tp, cp, xih, x0));
      PetscCall(MapAt(P, zm, xm, Tm, cm, xih, x0));
      for (PetscInt k = N; k < P->nfv; k++)
        for (int i = 0; i < 3; i++) s += wt[q] * gfull[3 * k + i] * (xp[3 * (k - N) + i] - xm[3 * (k - N) + i]) / (2 * h);
      /* a ghost edge's frame is its original's turned by the map's T (HylcPeriodicSetUp() projects them so,
         time-parallel transport keeps it): turning T by W = dT T^T (skew, axial vector w) turns the frame
         about the edge's tangent t by w . t beyond the transport the positions' gradient accounts for, and
         turning an edge's reference frame by d at fixed twist is a change d of its twist */
      for (PetscInt e = 0; e < P->nchain; e++) {
        const PetscInt k = P->esrc[e];
        if (k < N || gtfull[e] == 0) continue;
        const PetscReal *T = P->T + 9 * k, *tp = Tp + 9 * (k - N), *tm = Tm + 9 * (k - N), *t = P->et + 3 * e;
        PetscReal        W[9], w[3];
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) {
            PetscReal v = 0;
            for (int c = 0; c < 3; c++) v += (tp[3 * a + c] - tm[3 * a + c]) / (2 * h) * T[3 * b + c];
            W[3 * a + b] = v;
          }
        w[0] = 0.5 * (W[7] - W[5]);
        w[1] = 0.5 * (W[2] - W[6]);
        w[2] = 0.5 * (W[3] - W[1]);
        s += wt[q] * gtfull[e] * (w[0] * t[0] + w[1] * t[1] + w[2] * t[2]);
      }
      if (dcdz)
        for (PetscInt i = 0; i < m; i++) dcdz[6 * i + j] += wt[q] * (cp[i] - cm[i]) / (2 * h);
    }
    dEdz[j] = s;
  }
  PetscCall(PetscFree7(gfull, xp, xm, cp, cm, xih, x0));
  PetscCall(PetscFree3(gtfull, Tp, Tm));
  PetscFunctionReturn(PETSC_SUCCESS);
}
