/* HylcFit, the fabric method (-fit_method fabric, docs/fit.md "The fabric method"): each term's Hermite data
   by a weighted least-squares fit of the values AND the stresses dPsi/dz of the samples (the envelope-theorem
   stress every sample records), on the sampling plan's graded knots, so that the slopes of the table are the
   tile's own. The 2D terms are residuals that vanish on the axes, with their slopes across the axes free: the
   lateral stress a 1D sample records (dPsi/dsy at (sx, 0, 0), the Poisson effect; dPsi/dsa at (sx, 0, 0), the
   shear a chiral tile takes under tension) is what they carry there. The 3D terms (hylc's extension) are the
   residual of the samples of a 3D grid against the 1D and 2D terms, Hermite data straight from the samples. */
#include <hylc/private/fitimpl.h>
#include <hylc/samples.h>
#include <string.h>

/* ---- a banded weighted linear least-squares problem, solved through its normal equations ---- */

typedef struct {
  PetscInt   n, kd; /* unknowns, half bandwidth of the normal matrix */
  PetscReal *N;     /* the upper band of N = A^T W A, LAPACK 'U' band storage: N[(kd + i - j) + j (kd + 1)] for j - kd <= i <= j */
  PetscReal *rhs;   /* A^T W b */
  PetscBool *fixed; /* unknowns held at their fixval */
  PetscReal *fixval;
  PetscInt   rows;
} Lsq;

static PetscErrorCode LsqCreate(PetscInt n, PetscInt kd, Lsq *L)
{
  PetscFunctionBegin;
  L->n    = n;
  L->kd   = PetscMin(kd, n - 1);
  L->rows = 0;
  PetscCall(PetscCalloc4((L->kd + 1) * n, &L->N, n, &L->rhs, n, &L->fixed, n, &L->fixval));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LsqDestroy(Lsq *L)
{
  PetscFunctionBegin;
  PetscCall(PetscFree4(L->N, L->rhs, L->fixed, L->fixval));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* one equation sum_k c[k] x[idx[k]] = b with weight w (> 0); fixed unknowns moved to the right-hand side */
static void LsqRow(Lsq *L, PetscInt nnz, const PetscInt idx[], const PetscReal c[], PetscReal b, PetscReal w)
{
  for (PetscInt a = 0; a < nnz; a++)
    if (L->fixed[idx[a]]) b -= c[a] * L->fixval[idx[a]];
  for (PetscInt a = 0; a < nnz; a++) {
    const PetscInt i = idx[a];
    if (L->fixed[i] || c[a] == 0) continue;
    L->rhs[i] += w * c[a] * b;
    for (PetscInt q = 0; q < nnz; q++) {
      const PetscInt j = idx[q];
      if (L->fixed[j] || j < i || c[q] == 0) continue; /* the upper triangle: i <= j */
      L->N[(L->kd + i - j) + j * (L->kd + 1)] += w * c[a] * c[q];
    }
  }
  L->rows++;
}

/* N x = b for the symmetric positive definite band matrix N (upper band storage as Lsq's, kd above the
   diagonal): Cholesky N = U^T U in place, then two triangular solves. Returns the first non-positive pivot's
   column + 1, or 0. */
static PetscInt BandCholeskySolve(PetscInt n, PetscInt kd, PetscReal *N, PetscReal b[])
{
  const PetscInt ld = kd + 1;
#define B(i, j) N[(kd + (i) - (j)) + (j)*ld] /* i <= j <= i + kd */
  for (PetscInt j = 0; j < n; j++) {
    for (PetscInt i = PetscMax(0, j - kd); i < j; i++) { /* U(i, j) = (N(i, j) - sum_k U(k, i) U(k, j)) / U(i, i) */
      PetscReal s = B(i, j);
      for (PetscInt k = PetscMax(0, j - kd); k < i; k++) s -= B(k, i) * B(k, j);
      B(i, j) = s / B(i, i);
    }
    PetscReal s = B(j, j);
    for (PetscInt k = PetscMax(0, j - kd); k < j; k++) s -= B(k, j) * B(k, j);
    if (!(s > 0)) return j + 1;
    B(j, j) = PetscSqrtReal(s);
  }
  for (PetscInt j = 0; j < n; j++) { /* U^T y = b */
    PetscReal s = b[j];
    for (PetscInt k = PetscMax(0, j - kd); k < j; k++) s -= B(k, j) * b[k];
    b[j] = s / B(j, j);
  }
  for (PetscInt j = n - 1; j >= 0; j--) { /* U x = y */
    PetscReal s = b[j];
    for (PetscInt k = j + 1; k <= PetscMin(n - 1, j + kd); k++) s -= B(j, k) * b[k];
    b[j] = s / B(j, j);
  }
#undef B
  return 0;
}

/* x = argmin, with Jacobi scaling of N and a ridge of relative size ridge (unknowns with no data: 0) */
static PetscErrorCode LsqSolve(Lsq *L, PetscReal ridge, PetscReal x[])
{
  const PetscInt kd = L->kd, n = L->n, ld = kd + 1;
  PetscReal     *d;
  PetscInt       bad;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(n, &d));
  for (PetscInt j = 0; j < n; j++) {
    PetscReal *njj = &L->N[kd + j * ld];
    if (L->fixed[j] || !(*njj > 0)) { /* a fixed unknown, or one no equation touches (x = 0) */
      for (PetscInt i = PetscMax(0, j - kd); i < j; i++) L->N[(kd + i - j) + j * ld] = 0;
      for (PetscInt k = j + 1; k <= PetscMin(n - 1, j + kd); k++) L->N[(kd + j - k) + k * ld] = 0;
      *njj      = 1;
      L->rhs[j] = 0;
      d[j]      = 1;
    } else
      d[j] = 1 / PetscSqrtReal(*njj);
  }
  for (PetscInt j = 0; j < n; j++) {
    for (PetscInt i = PetscMax(0, j - kd); i <= j; i++) L->N[(kd + i - j) + j * ld] *= d[i] * d[j];
    L->N[kd + j * ld] += ridge;
    L->rhs[j] *= d[j];
  }
  bad = BandCholeskySolve(n, kd, L->N, L->rhs);
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The normal equations of the fabric fit are not positive definite (pivot %" PetscInt_FMT " of %" PetscInt_FMT ")", bad, n);
  for (PetscInt j = 0; j < n; j++) x[j] = L->fixed[j] ? L->fixval[j] : L->rhs[j] * d[j];
  PetscCall(PetscFree(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- the data of a term ---- */

/* the weight of an equation whose target's scale is |y| (the tile's own value or stress there): errors
   relative to it, with a floor (-fit_fabric_floor of the term's largest) */
static inline PetscReal Weight(PetscReal y, PetscReal floor) { return 1 / PetscSqr(PetscAbsReal(y) + floor); }

static PetscBool Finite(PetscReal x) { return (PetscBool)!PetscIsInfOrNanReal(x); }

/* the knots of axis a of term t in normalised units (HylcFitFabricKnots_Private()) into K (room for nknot) */
static void TermKnots(HylcFit fit, int t, int a, PetscReal K[])
{
  const int c = HylcPlanAxisCoord(t, a);
  for (PetscInt i = 0; i < fit->nknot[t][a]; i++) K[i] = fit->knot[t][a][i] / fit->scale[HylcPlanStrainIndex(c)];
}

static PetscInt ZeroKnot(PetscInt n, const PetscReal K[])
{
  for (PetscInt i = 0; i < n; i++)
    if (K[i] == 0) return i;
  return -1;
}

/* the largest |psi - f0| and |dPsi/du_c| (normalised) of each coordinate cs[a] over the rows of term t and of
   the 1D terms of those coordinates: the scales of the floors of the equations' weights */
static void TermScales(HylcFit fit, int t, int nc, const int cs[], PetscReal *vmax, PetscReal gmax[])
{
  *vmax = 0;
  for (int a = 0; a < nc; a++) gmax[a] = 0;
  for (PetscInt k = 0; k < fit->n; k++) {
    PetscBool mine = (PetscBool)(fit->term[k] == t);
    for (int a = 0; a < nc; a++) mine = (PetscBool)(mine || fit->term[k] == 1 + cs[a]);
    if (!mine) continue;
    if (fit->term[k] == t) *vmax = PetscMax(*vmax, PetscAbsReal(fit->psi[k] - fit->f0));
    for (int a = 0; a < nc; a++) {
      const PetscInt  s = HylcPlanStrainIndex(cs[a]);
      const PetscReal g = fit->stress[6 * k + s] * fit->scale[s];
      if (Finite(g)) gmax[a] = PetscMax(gmax[a], PetscAbsReal(g));
    }
  }
}

/*
   The knots of every term with data: the samples file's /plan (the graded knots it was sampled on), else graded
   knots (HylcPlanGradedKnots() with the plan's defaults, II scaled by 1 mm / r) over the term's data range (a
   3D term: the distinct coordinates of its samples, which are its nodes).
*/
PetscErrorCode HylcFitFabricKnots_Private(HylcFit fit)
{
  HylcPlan  defaults;
  PetscInt  fromFile = 0, made = 0;
  PetscReal K[HYLC_PLAN_MAXAXIS];

  PetscFunctionBegin;
  memset(&defaults, 0, sizeof(defaults));
  HylcPlanGradedDefaults(fit->radius > 0 ? 1e-3 / fit->radius : 1, &defaults);
  for (int t = 1; t < HYLC_PLAN_NTERM3; t++) {
    PetscInt rows = 0;
    for (PetscInt k = 0; k < fit->n; k++) rows += fit->term[k] == t;
    if (!rows || !((fit->terms >> t) & 1)) continue;
    for (int a = 0; a < HylcPlanTermDim(t); a++) {
      const int      c = HylcPlanAxisCoord(t, a);
      const PetscInt s = HylcPlanStrainIndex(c);
      PetscInt       n = 0;
      if (fit->samplesFile) PetscCall(HylcSamplesReadKnots(fit->input, t, a, &n, K));
      if (n)
        fromFile++;
      else if (HylcPlanTermDim(t) == 3) { /* a 3D term's samples are its nodes: their distinct coordinates */
        for (PetscInt k = 0; k < fit->n; k++) {
          PetscInt i = 0;
          if (fit->term[k] != t) continue;
          const PetscReal x = fit->z[6 * k + s];
          while (i < n && K[i] < x) i++;
          if (i < n && K[i] == x) continue;
          PetscCheck(n < HYLC_PLAN_MAXAXIS, PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT, "%s: term %s has more than %d distinct %s values", fit->source, HylcPlanTermName(t), HYLC_PLAN_MAXAXIS, HylcCoordNames[c]);
          for (PetscInt j = n; j > i; j--) K[j] = K[j - 1];
          K[i] = x;
          n++;
        }
        made++;
      } else {
        PetscReal mn = 0, mx = 0;
        for (PetscInt k = 0; k < fit->n; k++)
          if (fit->term[k] == t) mn = PetscMin(mn, fit->z[6 * k + s]), mx = PetscMax(mx, fit->z[6 * k + s]);
        PetscCheck(mx > mn, PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT, "%s: term %s: every sample has %s = 0", fit->source, HylcPlanTermName(t), HylcCoordNames[c]);
        n = HylcPlanGradedKnots(mn, mx, PetscMin(defaults.h0[c], 0.25 * (mx - mn)), defaults.growth, PetscMax(defaults.hmax * (mx - mn), defaults.h0[c]), HYLC_PLAN_MAXAXIS, K);
        PetscCheck(n >= 2, PetscObjectComm((PetscObject)fit), PETSC_ERR_PLIB, "graded knots of term %s", HylcPlanTermName(t));
        made++;
      }
      PetscCall(PetscMalloc1(n, &fit->knot[t][a]));
      PetscCall(PetscArraycpy(fit->knot[t][a], K, n));
      fit->nknot[t][a] = n;
    }
  }
  if (made && !fromFile)
    PetscCall(PetscStrncpy(fit->knotSource, "graded over the data (no /plan knots in the input)", sizeof(fit->knotSource)));
  else if (made)
    PetscCall(PetscStrncpy(fit->knotSource, "the input's /plan, graded over the data where it has none", sizeof(fit->knotSource)));
  else
    PetscCall(PetscStrncpy(fit->knotSource, "the input's /plan (the graded knots it was sampled on)", sizeof(fit->knotSource)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- 1D ---- */

PetscErrorCode HylcFitTerm1DFabric_Private(HylcFit fit, int c)
{
  const int      t  = 1 + c;
  const PetscInt s  = HylcPlanStrainIndex(c);
  HylcSpline1D  *sp = &fit->s1[c];
  const PetscInt n  = fit->nknot[t][0];
  PetscInt       i0, nrow = 0;
  PetscReal     *K, *p, *m, *x, vmax, gmax, fv, fg;
  Lsq            L;
  MPI_Comm       comm = PetscObjectComm((PetscObject)fit);

  PetscFunctionBegin;
  PetscCheck(n >= 2, comm, PETSC_ERR_PLIB, "fabric fit: term %s has %" PetscInt_FMT " knots", HylcPlanTermName(t), n);
  PetscCall(PetscMalloc3(n, &K, n, &p, n, &m));
  sp->t = K, sp->p = p, sp->m = m; /* owned by the fit from here (freed by HylcFitResetResults_Private, also on error) */
  TermKnots(fit, t, 0, K);
  i0 = ZeroKnot(n, K);
  PetscCheck(i0 >= 0, comm, PETSC_ERR_PLIB, "fabric fit: term %s: 0 is not a knot", HylcPlanTermName(t));
  TermScales(fit, t, 1, &c, &vmax, &gmax);
  fv = fit->fabricFloor * vmax + PETSC_SMALL;
  fg = fit->fabricFloor * gmax + PETSC_SMALL;
  PetscCall(LsqCreate(2 * n, 3, &L));
  L.fixed[2 * i0] = PETSC_TRUE; /* f(0) = 0: f0 is the constant */
  PetscCall(PetscLogEventBegin(HYLC_FitMLS, fit, 0, 0, 0));
  for (PetscInt k = 0; k < fit->n; k++) {
    PetscReal a[2], b[2], da[2], db[2], cf[4];
    PetscInt  idx[4], i;
    if (fit->term[k] != t) continue;
    const PetscReal u = fit->z[6 * k + s] / fit->scale[s], v = fit->psi[k] - fit->f0, g = fit->stress[6 * k + s] * fit->scale[s];
    i      = HylcHermiteBasis(n, K, HYLC_EXT_LINEAR, u, a, b, da, db, NULL, NULL);
    idx[0] = 2 * i, idx[1] = 2 * (i + 1), idx[2] = 2 * i + 1, idx[3] = 2 * (i + 1) + 1;
    cf[0] = a[0], cf[1] = a[1], cf[2] = b[0], cf[3] = b[1];
    LsqRow(&L, 4, idx, cf, v, Weight(v, fv));
    if (Finite(g)) {
      cf[0] = da[0], cf[1] = da[1], cf[2] = db[0], cf[3] = db[1];
      LsqRow(&L, 4, idx, cf, g, Weight(g, fg));
    }
    nrow++;
  }
  PetscCall(PetscMalloc1(2 * n, &x));
  PetscCall(LsqSolve(&L, fit->fabricRidge, x));
  PetscCall(LsqDestroy(&L));
  PetscCall(PetscLogEventEnd(HYLC_FitMLS, fit, 0, 0, 0));
  {
    for (PetscInt i = 0; i < n; i++) p[i] = x[2 * i], m[i] = x[2 * i + 1];
    PetscCall(PetscFree(x));
    /* shape: increasing away from the minimum (0 for the in-plane terms, the data's minimum for a bending
       term: a knit's curl) with a floor far below any stress the tile has (the table follows the tile) */
    PetscCall(PetscLogEventBegin(HYLC_FitMonotone, fit, 0, 0, 0));
    if (fit->quasiconvex) {
      PetscInt imin = i0;
      if (c >= 3)
        for (PetscInt i = 0; i < n; i++)
          if (p[i] < p[imin]) imin = i;
      HylcQuasiconvex1D(n, K, imin, fit->fabricReg * (vmax + PETSC_SMALL), p, m);
      HylcMonotoneCubic(n, K, p, m, fit->rule, fit->flatTol);
    }
    m[0]     = PetscMin(m[0], -fit->endSlope);
    m[n - 1] = PetscMax(m[n - 1], fit->endSlope);
    {
      const PetscReal p0 = p[i0];
      for (PetscInt i = 0; i < n; i++) p[i] -= p0;
    }
    PetscCall(PetscLogEventEnd(HYLC_FitMonotone, fit, 0, 0, 0));
    sp->k   = c;
    sp->n   = n;
    sp->ext = HYLC_EXT_LINEAR;
  }
  PetscCheck(nrow >= 2, comm, PETSC_ERR_USER_INPUT, "%s: term %s: %" PetscInt_FMT " samples, too few for the fabric fit", fit->source, HylcPlanTermName(t), nrow);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- 2D ---- */

/* the 1D term of coordinate c at normalised u: value and slope (0 where the term is not in the model) */
static PetscReal Term1D(HylcFit fit, int c, PetscReal u, PetscReal *d)
{
  *d = 0;
  if (!fit->has[1 + c]) return 0;
  return HylcSpline1DEval(&fit->s1[c], u, d, NULL);
}

/* the rows of a 2D residual g(u, v) at one point: its value (when hasv), du and dv targets (NaN: none) */
static void Row2D(Lsq *L, PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], PetscReal u, PetscReal v, PetscBool hasv, PetscReal r, PetscReal wr, PetscReal ru, PetscReal wu, PetscReal rv, PetscReal wv)
{
  PetscReal      au[2], bu[2], dau[2], dbu[2], av[2], bv[2], dav[2], dbv[2];
  PetscInt       idx[16];
  PetscReal      c0[16], cu[16], cv[16];
  const PetscInt i = HylcHermiteBasis(nu, tu, HYLC_EXT_LINEAR, u, au, bu, dau, dbu, NULL, NULL);
  const PetscInt j = HylcHermiteBasis(nv, tv, HYLC_EXT_LINEAR, v, av, bv, dav, dbv, NULL, NULL);
  PetscInt       q = 0;
  for (int e = 0; e < 2; e++)
    for (int f = 0; f < 2; f++) {
      const PetscInt  node = 4 * ((j + f) * nu + (i + e)); /* p, mu, mv, muv */
      const PetscReal A[4] = {au[e] * av[f], bu[e] * av[f], au[e] * bv[f], bu[e] * bv[f]};
      const PetscReal U[4] = {dau[e] * av[f], dbu[e] * av[f], dau[e] * bv[f], dbu[e] * bv[f]};
      const PetscReal V[4] = {au[e] * dav[f], bu[e] * dav[f], au[e] * dbv[f], bu[e] * dbv[f]};
      for (int w = 0; w < 4; w++, q++) {
        idx[q] = node + w;
        c0[q]  = A[w];
        cu[q]  = U[w];
        cv[q]  = V[w];
      }
    }
  if (hasv) LsqRow(L, 16, idx, c0, r, wr);
  if (Finite(ru)) LsqRow(L, 16, idx, cu, ru, wu);
  if (Finite(rv)) LsqRow(L, 16, idx, cv, rv, wv);
}

/* the derivative at knot i of data f on knots t (3-point: central, one-sided at the ends; exact for quadratics) */
static PetscReal Deriv3(PetscInt n, const PetscReal t[], const PetscReal f[], PetscInt stride, PetscInt i)
{
  PetscInt a, b, c; /* the three points, the derivative at point i */
  if (n < 3) return (f[stride] - f[0]) / (t[1] - t[0]);
  a = i == 0 ? 0 : i == n - 1 ? n - 3 : i - 1;
  b = a + 1, c = a + 2;
  {
    const PetscReal x = t[i], ha = t[a], hb = t[b], hc = t[c];
    const PetscReal la = (2 * x - hb - hc) / ((ha - hb) * (ha - hc)), lb = (2 * x - ha - hc) / ((hb - ha) * (hb - hc)), lc = (2 * x - ha - hb) / ((hc - ha) * (hc - hb));
    return la * f[a * stride] + lb * f[b * stride] + lc * f[c * stride];
  }
}

/* muv at every node from the unknowns x (p, mu, mv, muv per node): the mean of d(mv)/du and d(mu)/dv */
static void MixedFromSlopes(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], PetscReal x[])
{
  for (PetscInt j = 0; j < nv; j++)
    for (PetscInt i = 0; i < nu; i++) {
      const PetscReal du = Deriv3(nu, tu, x + 4 * (j * nu) + 2, 4, i), dv = Deriv3(nv, tv, x + 4 * i + 1, 4 * nu, j);
      x[4 * (j * nu + i) + 3] = 0.5 * (du + dv);
    }
}

PetscErrorCode HylcFitTerm2DFabric_Private(HylcFit fit, int t)
{
  HylcSpline2D  *sp = &fit->s2[t - 6];
  int            ci, cj, cs[2];
  const PetscInt nu = fit->nknot[t][0], nv = fit->nknot[t][1];
  PetscInt       i0, j0, si, sj, nrow = 0;
  PetscReal     *tu, *tv, *p, *mu, *mv, *muv, *x, vmax, gmax[2], fv, fu, fw, d0i, d0j;
  Lsq            L;
  MPI_Comm       comm = PetscObjectComm((PetscObject)fit);

  PetscFunctionBegin;
  HylcPlanPair(t, &ci, &cj);
  cs[0] = ci, cs[1] = cj;
  si = HylcPlanStrainIndex(ci);
  sj = HylcPlanStrainIndex(cj);
  PetscCheck(nu >= 2 && nv >= 2, comm, PETSC_ERR_PLIB, "fabric fit: term %s has %" PetscInt_FMT " x %" PetscInt_FMT " knots", HylcPlanTermName(t), nu, nv);
  PetscCall(PetscMalloc6(nu, &tu, nv, &tv, nu * nv, &p, nu * nv, &mu, nu * nv, &mv, nu * nv, &muv));
  sp->tu = tu, sp->tv = tv, sp->p = p, sp->mu = mu, sp->mv = mv, sp->muv = muv; /* owned by the fit from here */
  TermKnots(fit, t, 0, tu);
  TermKnots(fit, t, 1, tv);
  i0 = ZeroKnot(nu, tu);
  j0 = ZeroKnot(nv, tv);
  PetscCheck(i0 >= 0 && j0 >= 0, comm, PETSC_ERR_PLIB, "fabric fit: term %s: 0 is not a knot", HylcPlanTermName(t));
  TermScales(fit, t, 2, cs, &vmax, gmax);
  fv = fit->fabricFloor * vmax + PETSC_SMALL;
  fu = fit->fabricFloor * gmax[0] + PETSC_SMALL;
  fw = fit->fabricFloor * gmax[1] + PETSC_SMALL;
  (void)Term1D(fit, ci, 0, &d0i);
  (void)Term1D(fit, cj, 0, &d0j);
  PetscCall(PetscMalloc1(4 * nu * nv, &x));
  PetscCall(PetscLogEventBegin(HYLC_FitMLS, fit, 0, 0, 0));
  /* The mixed slopes muv: samples at knots and midpoints see them only through differences of neighbouring
     nodes' (adding one constant to every muv changes no value or slope at such a sample), and these differences
     are noisy where the tile is multistable; a noisy muv puts wiggles between the knot lines, in the curvature
     of soft directions (a plain weave's shear) too. So muv is not fitted: it is the derivative of the fitted mv
     along u and of mu along v (3-point, exact for quadratics, averaged), and p, mu, mv are fitted again with it,
     -fit_fabric_passes times (the first with muv = 0). */
  PetscCall(PetscArrayzero(x, 4 * nu * nv));
  for (PetscInt pass = 0; pass < fit->fabricPasses; pass++) {
    if (pass) MixedFromSlopes(nu, nv, tu, tv, x);
    PetscCall(LsqCreate(4 * nu * nv, 4 * (nu + 1) + 3, &L));
    /* a residual: 0 on the axes with its slope along them; its slope across an axis is free */
    for (PetscInt j = 0; j < nv; j++) L.fixed[4 * (j * nu + i0)] = L.fixed[4 * (j * nu + i0) + 2] = PETSC_TRUE;
    for (PetscInt i = 0; i < nu; i++) L.fixed[4 * (j0 * nu + i)] = L.fixed[4 * (j0 * nu + i) + 1] = PETSC_TRUE;
    for (PetscInt q = 0; q < nu * nv && pass; q++) {
      L.fixed[4 * q + 3]  = PETSC_TRUE;
      L.fixval[4 * q + 3] = x[4 * q + 3];
    }
    nrow = 0;
    for (PetscInt k = 0; k < fit->n; k++) {
      const PetscReal *z = fit->z + 6 * k, *g = fit->stress + 6 * k;
      const PetscReal  u = z[si] / fit->scale[si], v = z[sj] / fit->scale[sj];
      PetscReal        fi, fj, di, dj;
      if (fit->term[k] == t) {
        fi                 = Term1D(fit, ci, u, &di);
        fj                 = Term1D(fit, cj, v, &dj);
        const PetscReal gi = g[si] * fit->scale[si], gj = g[sj] * fit->scale[sj];
        Row2D(&L, nu, nv, tu, tv, u, v, PETSC_TRUE, fit->psi[k] - fit->f0 - fi - fj, Weight(fit->psi[k] - fit->f0, fv), gi - di, Weight(gi, fu), gj - dj, Weight(gj, fw));
        nrow++;
      } else if (fit->term[k] == 1 + ci) { /* on the axis v = 0: the stress across it */
        const PetscReal gj = g[sj] * fit->scale[sj];
        Row2D(&L, nu, nv, tu, tv, u, 0, PETSC_FALSE, 0, 0, NAN, 0, gj - d0j, Weight(gj, fw));
      } else if (fit->term[k] == 1 + cj) { /* on the axis u = 0 */
        const PetscReal gi = g[si] * fit->scale[si];
        Row2D(&L, nu, nv, tu, tv, 0, v, PETSC_FALSE, 0, 0, gi - d0i, Weight(gi, fu), NAN, 0);
      }
    }
    PetscCall(LsqSolve(&L, fit->fabricRidge, x));
    PetscCall(LsqDestroy(&L));
  }
  PetscCall(PetscLogEventEnd(HYLC_FitMLS, fit, 0, 0, 0));
  for (PetscInt q = 0; q < nu * nv; q++) p[q] = x[4 * q], mu[q] = x[4 * q + 1], mv[q] = x[4 * q + 2], muv[q] = x[4 * q + 3];
  PetscCall(PetscFree(x));
  sp->k0 = ci, sp->k1 = cj, sp->nu = nu, sp->nv = nv;
  sp->ext = HYLC_EXT_LINEAR;
  PetscCheck(nrow >= 4, comm, PETSC_ERR_USER_INPUT, "%s: term %s: %" PetscInt_FMT " samples, too few for the fabric fit", fit->source, HylcPlanTermName(t), nrow);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- 3D ---- */

/* the 1D and 2D terms (without f0) at normalised coordinates S, with their gradient g (5) */
static PetscReal Model12(HylcFit fit, const PetscReal S[5], PetscReal g[5])
{
  PetscReal f = 0;
  for (int c = 0; c < 5; c++) {
    PetscReal d;
    g[c] = 0;
    f += Term1D(fit, c, S[c], &d);
    g[c] += d;
  }
  for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
    PetscReal gg[2];
    int       ci, cj;
    if (!fit->has[t]) continue;
    HylcPlanPair(t, &ci, &cj);
    f += HylcSpline2DEval(&fit->s2[t - 6], S[ci], S[cj], gg, NULL);
    g[ci] += gg[0];
    g[cj] += gg[1];
  }
  return f;
}

/* the index of knot x among K (within a relative 1e-9 of the spacing), -1 if x is not a knot */
static PetscInt KnotIndex(PetscInt n, const PetscReal K[], PetscReal x)
{
  for (PetscInt i = 0; i < n; i++) {
    const PetscReal h = i + 1 < n ? K[i + 1] - K[i] : K[i] - K[i - 1];
    if (PetscAbsReal(x - K[i]) <= 1e-9 * h) return i;
  }
  return -1;
}

PetscReal HylcFitTerm3DEval_Private(const hylcmat_term3d *s, PetscReal u, PetscReal v, PetscReal w, PetscReal g[3])
{
  PetscReal      A[3][2], B[3][2], dA[3][2], dB[3][2], f = 0;
  const PetscInt i    = HylcHermiteBasis(s->nu, s->tu, HYLC_EXT_LINEAR, u, A[0], B[0], dA[0], dB[0], NULL, NULL);
  const PetscInt j    = HylcHermiteBasis(s->nv, s->tv, HYLC_EXT_LINEAR, v, A[1], B[1], dA[1], dB[1], NULL, NULL);
  const PetscInt k    = HylcHermiteBasis(s->nw, s->tw, HYLC_EXT_LINEAR, w, A[2], B[2], dA[2], dB[2], NULL, NULL);
  const double  *D[8] = {s->p, s->mu, s->mv, s->muv, s->mw, s->muw, s->mvw, s->muvw}; /* bit 0: d/du, 1: d/dv, 2: d/dw */

  if (g) g[0] = g[1] = g[2] = 0;
  for (int e = 0; e < 2; e++)
    for (int f2 = 0; f2 < 2; f2++)
      for (int h = 0; h < 2; h++) {
        const PetscInt node = ((k + h) * s->nv + (j + f2)) * s->nu + (i + e);
        for (int q = 0; q < 8; q++) {
          const PetscReal bu = q & 1 ? B[0][e] : A[0][e], bv = q & 2 ? B[1][f2] : A[1][f2], bw = q & 4 ? B[2][h] : A[2][h];
          const PetscReal du = q & 1 ? dB[0][e] : dA[0][e], dv = q & 2 ? dB[1][f2] : dA[1][f2], dw = q & 4 ? dB[2][h] : dA[2][h];
          const PetscReal c = D[q][node];
          f += c * bu * bv * bw;
          if (g) {
            g[0] += c * du * bv * bw;
            g[1] += c * bu * dv * bw;
            g[2] += c * bu * bv * dw;
          }
        }
      }
  return f;
}

/* 0 on the coordinate planes (node index z0[a] on axis a) with every derivative along them */
static void ZeroPlanes(const PetscInt n[3], const PetscInt z0[3], PetscReal *D[8])
{
  for (PetscInt iw = 0; iw < n[2]; iw++)
    for (PetscInt iv = 0; iv < n[1]; iv++)
      for (PetscInt iu = 0; iu < n[0]; iu++) {
        const PetscInt node = (iw * n[1] + iv) * n[0] + iu, ix[3] = {iu, iv, iw};
        for (int a = 0; a < 3; a++)
          if (ix[a] == z0[a])
            for (int q = 0; q < 8; q++)
              if (!(q & (1 << a))) D[q][node] = 0;
      }
}

/*
   A 3D term f(u, v, w) from the samples of its grid (the plan's 3D knots, one sample per node): the node's value
   is the sample's energy less f0 and the 1D and 2D terms there, its slopes the sample's stress less theirs (the
   envelope-theorem stress: the tile's own slopes), the mixed derivatives differences of those slopes between
   neighbouring nodes (3-point, averaged over the orders). On a coordinate plane the term is 0 with every
   derivative along the plane, so the 1D and 2D terms' fits are kept exactly; the derivatives across the plane
   are free. A node without a converged sample gets 0 (counted in missing3).
*/
PetscErrorCode HylcFitTerm3DFabric_Private(HylcFit fit, int t)
{
  const int       r  = t - HYLC_PLAN_NTERM;
  hylcmat_term3d *sp = &fit->s3[r];
  int             c[3];
  PetscInt        st[3], n[3], z0[3], N, nrow = 0, offgrid = 0;
  PetscReal      *K[3], *D[8], *buf;
  PetscBool      *have;
  MPI_Comm        comm = PetscObjectComm((PetscObject)fit);

  PetscFunctionBegin;
  HylcPlanTriple(t, c);
  for (int a = 0; a < 3; a++) {
    n[a]  = fit->nknot[t][a];
    st[a] = HylcPlanStrainIndex(c[a]);
    PetscCheck(n[a] >= 2, comm, PETSC_ERR_PLIB, "fabric fit: term %s has %" PetscInt_FMT " knots on axis %d", HylcPlanTermName(t), n[a], a);
  }
  N = n[0] * n[1] * n[2];
  PetscCall(PetscFree(fit->a3[r]));
  PetscCall(PetscMalloc1(n[0] + n[1] + n[2] + 8 * N, &fit->a3[r]));
  buf  = fit->a3[r];
  K[0] = buf, K[1] = K[0] + n[0], K[2] = K[1] + n[1];
  for (int q = 0; q < 8; q++) D[q] = K[2] + n[2] + q * N; /* p, mu, mv, muv, mw, muw, mvw, muvw: bit 0 d/du, 1 d/dv, 2 d/dw */
  PetscCall(PetscArrayzero(D[0], 8 * N));
  for (int a = 0; a < 3; a++) {
    TermKnots(fit, t, a, K[a]);
    z0[a] = ZeroKnot(n[a], K[a]);
    PetscCheck(z0[a] >= 0, comm, PETSC_ERR_PLIB, "fabric fit: term %s: 0 is not a knot", HylcPlanTermName(t));
  }
  PetscCall(PetscCalloc1(N, &have));
  for (PetscInt k = 0; k < fit->n; k++) {
    const PetscReal *z = fit->z + 6 * k, *g = fit->stress + 6 * k;
    PetscReal        S[5], gm[5], fm;
    PetscInt         idx[3], node;
    if (fit->term[k] != t) continue;
    for (int q = 0; q < 5; q++) S[q] = z[HylcPlanStrainIndex(q)] / fit->scale[HylcPlanStrainIndex(q)];
    for (int a = 0; a < 3; a++) idx[a] = KnotIndex(n[a], K[a], S[c[a]]);
    if (idx[0] < 0 || idx[1] < 0 || idx[2] < 0) {
      offgrid++;
      continue;
    }
    node = (idx[2] * n[1] + idx[1]) * n[0] + idx[0];
    fm   = Model12(fit, S, gm);
    if (!(Finite(g[st[0]]) && Finite(g[st[1]]) && Finite(g[st[2]]))) continue;
    D[0][node] = fit->psi[k] - fit->f0 - fm;
    D[1][node] = g[st[0]] * fit->scale[st[0]] - gm[c[0]];
    D[2][node] = g[st[1]] * fit->scale[st[1]] - gm[c[1]];
    D[4][node] = g[st[2]] * fit->scale[st[2]] - gm[c[2]];
    have[node] = PETSC_TRUE;
    nrow++;
  }
  fit->missing3[r] = 0;
  for (PetscInt q = 0; q < N; q++) fit->missing3[r] += !have[q];
  PetscCall(PetscFree(have));
  PetscCheck(nrow >= 8, comm, PETSC_ERR_USER_INPUT, "%s: term %s: %" PetscInt_FMT " samples on its knots (%" PetscInt_FMT " off them), too few for the fabric fit", fit->source, HylcPlanTermName(t), nrow, offgrid);
  ZeroPlanes(n, z0, D); /* the data there are the 2D terms' residuals: not the 3D term's */
  {
    /* the mixed derivatives: muv from mv along u and mu along v, ...; muvw from the three pairs' */
    const PetscInt stride[3] = {1, n[0], n[0] * n[1]};
    for (int q = 3; q < 8; q++) {
      if (q == 4) continue; /* mw: data */
      for (PetscInt iw = 0; iw < n[2]; iw++)
        for (PetscInt iv = 0; iv < n[1]; iv++)
          for (PetscInt iu = 0; iu < n[0]; iu++) {
            const PetscInt node = (iw * n[1] + iv) * n[0] + iu, ix[3] = {iu, iv, iw};
            PetscReal      sum = 0;
            int            cnt = 0;
            for (int a = 0; a < 3; a++) { /* d/da of the derivative without a */
              if (!(q & (1 << a))) continue;
              const PetscInt lower = q & ~(1 << a);
              const PetscInt base  = node - ix[a] * stride[a];
              sum += Deriv3(n[a], K[a], D[lower] + base, stride[a], ix[a]);
              cnt++;
            }
            D[q][node] = sum / cnt;
          }
    }
  }
  ZeroPlanes(n, z0, D);
  sp->k0 = c[0], sp->k1 = c[1], sp->k2 = c[2];
  sp->nu = (int)n[0], sp->nv = (int)n[1], sp->nw = (int)n[2];
  /* constant beyond the sampled box: a correction known only inside it (linear extension of the tensor-product
     slopes grew like the product of the distances outside two faces: a stockinette's (sx, sa, sy) term added
     -0.24 J/m^2 at sx -0.375, sa 0.55, a spurious well below the rest state that the bias path fell into) */
  sp->ext = HYLC_EXT_CONSTANT;
  sp->tu = K[0], sp->tv = K[1], sp->tw = K[2];
  sp->p = D[0], sp->mu = D[1], sp->mv = D[2], sp->muv = D[3], sp->mw = D[4], sp->muw = D[5], sp->mvw = D[6], sp->muvw = D[7];
  PetscFunctionReturn(PETSC_SUCCESS);
}
