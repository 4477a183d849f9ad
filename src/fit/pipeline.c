/* HylcFitCompute: the fitting pipeline of Algorithms C5-C7 as the authors' code does it (docs/method.md
   §9.1); the shape-preserving steps are the kernels of include/hylc/monotone.h. */
#include <hylc/private/fitimpl.h>
#include <hylc/samples.h>

/* the smoothed function g of (S27): symexp of the MLS of symlog(psi), symmetrized in sa */
typedef struct {
  PetscInt         n;
  const PetscReal *u, *v, *l; /* normalised coordinates (v: 2D only) and symlog(psi) */
  PetscReal        ku, kv, truncation;
  int              dim, sym; /* sym: -1 none, 0 in u, 1 in v */
  PetscInt         grown;    /* evaluations that needed a larger kernel */
  PetscReal        growMax;  /* the largest kernel factor used */
} GFun;

static int GMls(const GFun *g, PetscReal x, PetscReal y, PetscReal *val) { return g->dim == 1 ? HylcMLS1D(g->n, g->u, g->l, g->ku, g->truncation, x, val) : HylcMLS2D(g->n, g->u, g->v, g->l, g->ku, g->kv, g->truncation, x, y, val); }

/* g(x, y) with the kernel radii scaled by f; returns -1 when the MLS system at (x, y) (or its mirror)
   is singular */
static int GEval(const GFun *g, PetscReal f, PetscReal x, PetscReal y, PetscReal *val)
{
  GFun      h = *g;
  PetscReal a, b;
  h.ku *= f;
  h.kv *= f;
  if (GMls(&h, x, y, &a) < 0) return -1;
  if (g->sym == 0) {
    if (GMls(&h, -x, y, &b) < 0) return -1;
    a = 0.5 * (a + b);
  } else if (g->sym == 1) {
    if (GMls(&h, x, -y, &b) < 0) return -1;
    a = 0.5 * (a + b);
  }
  *val = HylcSymexp(a);
  return 0;
}

/* g(x, y); where the MLS is singular (too few samples in the kernel: sparse data, failed samples) the
   kernel is enlarged by -fit_mls_grow until it is not (counted in g->grown), or it is an error */
static PetscErrorCode G(HylcFit fit, GFun *g, int t, PetscReal x, PetscReal y, PetscReal *val)
{
  PetscReal f = 1;

  PetscFunctionBegin;
  if (!GEval(g, 1, x, y, val)) PetscFunctionReturn(PETSC_SUCCESS);
  if (fit->mlsGrow > 1)
    for (f = fit->mlsGrow; f < 2.0 / fit->kernel; f *= fit->mlsGrow)
      if (!GEval(g, f, x, y, val)) {
        g->grown++;
        g->growMax = PetscMax(g->growMax, f);
        PetscFunctionReturn(PETSC_SUCCESS);
      }
  {
    PetscInt cnt = 0;
    for (PetscInt i = 0; i < g->n; i++)
      if (PetscAbsReal(g->u[i] - x) < g->ku && (g->dim == 1 || PetscAbsReal(g->v[i] - y) < g->kv)) cnt++;
    if (g->dim == 1)
      SETERRQ(PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT,
              "%s: term %s: the MLS at x = %g (normalised) is singular: %" PetscInt_FMT " samples within the kernel radius %g (the quadratic basis needs 3 distinct ones)%s; the term's %" PetscInt_FMT " samples are too sparse for -fit_mls_kernel %g",
              fit->source, HylcPlanTermName(t), (double)x, cnt, (double)g->ku, fit->mlsGrow > 1 ? ", also with the kernel enlarged to the whole range" : " (-fit_mls_grow 1.5 would enlarge it)", g->n, (double)fit->kernel);
    SETERRQ(PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT,
            "%s: term %s: the MLS at (u, v) = (%g, %g) (normalised) is singular: %" PetscInt_FMT " samples within the kernel box %g x %g (the basis needs 8 in general position)%s; the term's %" PetscInt_FMT
            " samples are too sparse for -fit_mls_kernel %g",
            fit->source, HylcPlanTermName(t), (double)x, (double)y, cnt, (double)g->ku, (double)g->kv, fit->mlsGrow > 1 ? ", also with the kernel enlarged to the whole range" : " (-fit_mls_grow 1.5 would enlarge it)", g->n, (double)fit->kernel);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the warning after a term whose MLS needed a larger kernel somewhere */
static PetscErrorCode GrowWarning(HylcFit fit, const GFun *g, int t, PetscInt evals)
{
  PetscFunctionBegin;
  if (g->grown)
    PetscCall(PetscFPrintf(PetscObjectComm((PetscObject)fit), PETSC_STDERR,
                           "[fit] warning: term %s: too few samples within the MLS kernel at %" PetscInt_FMT " of %" PetscInt_FMT " evaluation points; the kernel was enlarged there (up to %g x -fit_mls_kernel)\n", HylcPlanTermName(t), g->grown,
                           evals, (double)g->growMax));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscReal MinSpacing(PetscInt n, const PetscReal t[])
{
  PetscReal h = PETSC_MAX_REAL;
  for (PetscInt i = 0; i + 1 < n; i++) h = PetscMin(h, t[i + 1] - t[i]);
  return h;
}

/* the term's data: normalised coordinates of c0 (and c1), symlog(psi) */
static PetscErrorCode Gather(HylcFit fit, int t, int c0, int c1, PetscInt *n, PetscReal **u, PetscReal **v, PetscReal **l)
{
  PetscInt m = 0;

  PetscFunctionBegin;
  for (PetscInt k = 0; k < fit->n; k++) m += fit->term[k] == t;
  PetscCall(PetscMalloc3(m + 1, u, m + 1, v, m + 1, l));
  m = 0;
  for (PetscInt k = 0; k < fit->n; k++) {
    if (fit->term[k] != t) continue;
    const PetscInt i0 = HylcPlanStrainIndex(c0);
    (*u)[m]           = fit->z[6 * k + i0] / fit->scale[i0];
    if (c1 >= 0) {
      const PetscInt i1 = HylcPlanStrainIndex(c1);
      (*v)[m]           = fit->z[6 * k + i1] / fit->scale[i1];
    } else
      (*v)[m] = 0;
    (*l)[m] = HylcSymlog(fit->psi[k]);
    m++;
  }
  *n = m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void Range(PetscInt n, const PetscReal x[], PetscReal *mn, PetscReal *mx)
{
  *mn = PETSC_MAX_REAL;
  *mx = PETSC_MIN_REAL;
  for (PetscInt i = 0; i < n; i++) {
    *mn = PetscMin(*mn, x[i]);
    *mx = PetscMax(*mx, x[i]);
  }
}

/* Algorithm C6 for the 1D term of coordinate c (term t = 1 + c) */
static PetscErrorCode Fit1D(HylcFit fit, int c, PetscInt n, const PetscReal u[], const PetscReal l[])
{
  const int       t       = 1 + c;
  HylcSpline1D   *s       = &fit->s1[c];
  const PetscBool refined = (PetscBool)(fit->knots == HYLC_FIT_KNOTS_REFINED);
  PetscReal       mn, mx, eps, *tk, *p, *m;
  PetscInt        nk = fit->nk1 + (refined ? 2 * fit->refine : 0), i0;
  GFun            g;

  PetscFunctionBegin;
  Range(n, u, &mn, &mx);
  PetscCheck(mn < mx, PetscObjectComm((PetscObject)fit), PETSC_ERR_USER_INPUT, "%s: term %s: all %" PetscInt_FMT " samples have the same %s = %g", fit->source, HylcPlanTermName(t), n, HylcPlanTermName(t),
             (double)(mn * fit->scale[HylcPlanStrainIndex(c)]));
  PetscCall(PetscLogEventBegin(HYLC_FitMLS, fit, 0, 0, 0));
  PetscCall(PetscMalloc3(nk, &tk, nk, &p, nk, &m));
  s->t = tk, s->p = p, s->m = m; /* owned by the fit from here (freed by HylcFitResetResults_Private, also on error) */
  {
    PetscReal tp[1024];
    PetscCheck(fit->nk1 <= 1024, PETSC_COMM_SELF, PETSC_ERR_PLIB, "1D knots");
    i0 = HylcFitKnots1D(mn, mx, fit->factor1, fit->nk1, tp);
    PetscCheck(i0 >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "1D knots");
    eps = fit->fdEps * MinSpacing(fit->nk1, tp); /* the width of the central difference: g at t -+ eps/2 */
    if (refined) {
      i0 = HylcFitKnots1DRefined(mn, mx, fit->factor1, fit->nk1, fit->refine, tk, &nk);
      PetscCheck(i0 >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "1D knots");
    } else
      PetscCall(PetscArraycpy(tk, tp, fit->nk1));
  }
  g = (GFun){n, u, NULL, l, fit->kernel * (mx - mn), 0, fit->truncation, 1, (c == 1 && fit->symmetrize) ? 0 : -1, 0, 1};
  for (PetscInt i = 0; i < nk; i++) {
    PetscReal a, b, e = eps;
    if (refined && PetscAbsInt((int)(i - i0)) <= fit->refine) {
      /* an added knot or 0: the MLS radius follows the distance from 0 (for 0: of the nearest added knot),
         widened until it holds kernelMin samples, never wider than the paper's (kernel x the span); the
         differences for the slope as narrow as the knots around it. The paper's knots keep the paper's
         kernel and width, so that away from 0 the fit is the paper layout's. */
      const PetscReal rmax = fit->kernel * (mx - mn);
      const PetscReal d    = i == i0 ? PetscMax(i0 > 0 ? -tk[i0 - 1] : 0, i0 + 1 < nk ? tk[i0 + 1] : 0) : PetscAbsReal(tk[i]);
      PetscReal       r    = PetscMin(rmax, fit->kernelSpacing * d);
      for (;;) {
        PetscInt cnt = 0;
        for (PetscInt k = 0; k < n; k++) cnt += PetscAbsReal(u[k] - tk[i]) < r || (c == 1 && fit->symmetrize && PetscAbsReal(u[k] + tk[i]) < r);
        if (cnt >= fit->kernelMin || r >= rmax) break;
        r = PetscMin(rmax, 1.25 * r);
      }
      g.ku = r;
      e    = fit->fdEps * PetscMin(i > 0 ? tk[i] - tk[i - 1] : PETSC_MAX_REAL, i + 1 < nk ? tk[i + 1] - tk[i] : PETSC_MAX_REAL);
    } else
      g.ku = fit->kernel * (mx - mn);
    PetscCall(G(fit, &g, t, tk[i], 0, &p[i]));
    PetscCall(G(fit, &g, t, tk[i] + 0.5 * e, 0, &a));
    PetscCall(G(fit, &g, t, tk[i] - 0.5 * e, 0, &b));
    m[i] = (a - b) / e;
  }
  if (refined) {
    /* Each knot's value is taken relative to 0 by the same kernel: the paper's knots are shifted by
       (narrow g(0) - paper g(0)), so that after p -= p(0) below they hold the paper layout's g(t) - g(0)
       of one kernel, whose smoothing bias largely cancels in the difference, and the added knots their
       own. Without this the paper's knots carry the difference of the two kernels' values at 0 as a
       constant offset over the whole range (measured on the thinned plans of basket, satin and
       stockinette: the range-normalised RMS up to 0.5 % worse than the paper layout's on 7 of their 15
       1D terms). */
    PetscReal q0;
    g.ku = fit->kernel * (mx - mn);
    PetscCall(G(fit, &g, t, tk[i0], 0, &q0));
    for (PetscInt i = 0; i < nk; i++)
      if (PetscAbsInt((int)(i - i0)) > fit->refine) p[i] += p[i0] - q0;
  }
  PetscCall(GrowWarning(fit, &g, t, 3 * nk + (refined ? 1 : 0)));
  PetscCall(PetscLogEventEnd(HYLC_FitMLS, fit, 0, 0, 0));
  PetscCall(PetscLogEventBegin(HYLC_FitMonotone, fit, 0, 0, 0));
  if (fit->quasiconvex) {
    PetscInt imin = i0;
    if (c >= 3) /* bending: the minimum of the data (first of equal values) */
      for (PetscInt i = 0; i < nk; i++)
        if (p[i] < p[imin] || (p[i] == p[imin] && i < imin)) imin = i;
    HylcQuasiconvex1D(nk, tk, imin, fit->reg, p, m);
  }
  HylcMonotoneCubic(nk, tk, p, m, fit->rule, fit->flatTol);
  m[0]      = PetscMin(m[0], -fit->endSlope);
  m[nk - 1] = PetscMax(m[nk - 1], fit->endSlope);
  {
    const PetscReal p0 = p[i0];
    for (PetscInt i = 0; i < nk; i++) p[i] -= p0;
  }
  PetscCall(PetscLogEventEnd(HYLC_FitMonotone, fit, 0, 0, 0));
  s->k   = c;
  s->n   = nk;
  s->t   = tk;
  s->p   = p;
  s->m   = m;
  s->ext = HYLC_EXT_LINEAR;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* knot counts of axis coordinate c of the pair (ci, cj) */
static void KnotCounts(HylcFit fit, int ci, int cj, int c, PetscReal *factor, PetscInt k[2])
{
  const PetscBool bending = cj >= 3, poisson = ci == 0 && cj == 2, stretch = c == 0 || c == 2;
  const PetscInt *src = poisson ? fit->kPoisson : stretch ? (bending ? fit->kBendStretch : fit->kStretch) : (bending ? fit->kBendSym : fit->kSym);
  *factor             = bending ? fit->factor2bend : fit->factor2;
  k[0]                = src[0];
  k[1]                = src[1];
}

/* Algorithm C7 for the 2D term t of the pair (ci, cj) */
static PetscErrorCode Fit2D(HylcFit fit, int t, PetscInt n, const PetscReal u[], const PetscReal v[], const PetscReal l[])
{
  HylcSpline2D   *s = &fit->s2[t - 6];
  int             ci, cj;
  PetscReal       umn, umx, vmn, vmx, fu, fv, eps, *tu, *tv, *p, *mu, *mv, *muv;
  PetscInt        ku[2], kv[2], nu, nv, i0, j0;
  GFun            g;
  const PetscBool poisson = t == 7;
  MPI_Comm        comm    = PetscObjectComm((PetscObject)fit);

  PetscFunctionBegin;
  HylcPlanPair(t, &ci, &cj);
  Range(n, u, &umn, &umx);
  Range(n, v, &vmn, &vmx);
  PetscCheck(umn < umx && vmn < vmx, comm, PETSC_ERR_USER_INPUT, "%s: term %s: the %" PetscInt_FMT " samples do not span both coordinates (%s in [%g, %g], %s in [%g, %g], normalised)", fit->source, HylcPlanTermName(t), n, HylcPlanTermName(1 + ci),
             (double)umn, (double)umx, HylcPlanTermName(1 + cj), (double)vmn, (double)vmx);
  PetscCall(PetscLogEventBegin(HYLC_FitMLS, fit, 0, 0, 0));
  KnotCounts(fit, ci, cj, ci, &fu, ku);
  KnotCounts(fit, ci, cj, cj, &fv, kv);
  {
    PetscReal bu[2048], bv[2048];
    PetscCheck(ku[0] + ku[1] < 2048 && kv[0] + kv[1] < 2048, comm, PETSC_ERR_USER_INPUT, "Too many 2D knots");
    i0 = HylcFitKnots2D(umn, umx, fu, ku[0], ku[1], bu, &nu);
    j0 = HylcFitKnots2D(vmn, vmx, fv, kv[0], kv[1], bv, &nv);
    PetscCheck(i0 >= 0 && j0 >= 0, comm, PETSC_ERR_USER_INPUT, "%s: term %s: fewer than 2 knots on an axis (data %s in [%g, %g], %s in [%g, %g] normalised; the 2D knots span [factor min, 0] and [0, factor max])", fit->source, HylcPlanTermName(t),
               HylcPlanTermName(1 + ci), (double)umn, (double)umx, HylcPlanTermName(1 + cj), (double)vmn, (double)vmx);
    PetscCall(PetscMalloc6(nu, &tu, nv, &tv, nu * nv, &p, nu * nv, &mu, nu * nv, &mv, nu * nv, &muv));
    s->tu = tu, s->tv = tv, s->p = p, s->mu = mu, s->mv = mv, s->muv = muv; /* owned by the fit from here */
    PetscCall(PetscArraycpy(tu, bu, nu));
    PetscCall(PetscArraycpy(tv, bv, nv));
  }
  eps = fit->fdEps * PetscMin(MinSpacing(nu, tu), MinSpacing(nv, tv)); /* the width of the differences */
  {
    const int sym = !fit->symmetrize ? -1 : ci == 1 ? 0 : cj == 1 ? 1 : -1;
    g             = (GFun){n, u, v, l, fit->kernel * (umx - umn), fit->kernel * (vmx - vmn), fit->truncation, 2, sym, 0, 1};
  }
  for (PetscInt j = 0; j < nv; j++)
    for (PetscInt i = 0; i < nu; i++) {
      const PetscInt  k = j * nu + i;
      const PetscReal x = tu[i], y = tv[j], e = 0.5 * eps;
      PetscReal       gpp, gpm, gmp, gmm, gp0, gm0, g0p, g0m;
      PetscCall(G(fit, &g, t, x, y, &p[k]));
      PetscCall(G(fit, &g, t, x + e, y, &gp0));
      PetscCall(G(fit, &g, t, x - e, y, &gm0));
      PetscCall(G(fit, &g, t, x, y + e, &g0p));
      PetscCall(G(fit, &g, t, x, y - e, &g0m));
      PetscCall(G(fit, &g, t, x + e, y + e, &gpp));
      PetscCall(G(fit, &g, t, x + e, y - e, &gpm));
      PetscCall(G(fit, &g, t, x - e, y + e, &gmp));
      PetscCall(G(fit, &g, t, x - e, y - e, &gmm));
      mu[k]  = (gp0 - gm0) / eps;
      mv[k]  = (g0p - g0m) / eps;
      muv[k] = (gpp - gpm - gmp + gmm) / (eps * eps);
    }
  PetscCall(GrowWarning(fit, &g, t, 9 * nu * nv));
  PetscCall(PetscLogEventEnd(HYLC_FitMLS, fit, 0, 0, 0));
  PetscCall(PetscLogEventBegin(HYLC_FitMonotone, fit, 0, 0, 0));
  if (fit->quasiconvex && !poisson) {
    PetscInt jmin = j0;
    if (cj >= 3) /* bending axis: the minimum along the u = 0 line */
      for (PetscInt j = 0; j < nv; j++)
        if (p[j * nu + i0] < p[jmin * nu + i0] || (p[j * nu + i0] == p[jmin * nu + i0] && j < jmin)) jmin = j;
    PetscCall(HylcQuasiconvex2D(nu, nv, tu, tv, i0, jmin, fit->reg, fit->compat, p, mu, mv));
  }
  HylcFitClampBoundary2D(nu, nv, fit->endSlope, mu, mv);
  PetscCall(HylcMonotoneBicubic(nu, nv, tu, tv, p, mu, mv, muv, PETSC_TRUE, fit->compat));
  HylcFitZeroBoundaryMixed2D(nu, nv, muv);
  HylcFitResidualize2D(nu, nv, i0, j0, p, mu, mv, muv);
  if (fit->zeroCompression && !poisson) HylcFitZeroCompression2D(nu, nv, tu, tv, (PetscBool)(ci == 0 || ci == 2), (PetscBool)(cj == 0 || cj == 2), fit->zeroStrict, p, mu, mv, muv);
  PetscCall(PetscLogEventEnd(HYLC_FitMonotone, fit, 0, 0, 0));
  s->k0  = ci;
  s->k1  = cj;
  s->nu  = nu;
  s->nv  = nv;
  s->tu  = tu;
  s->tv  = tv;
  s->p   = p;
  s->mu  = mu;
  s->mv  = mv;
  s->muv = muv;
  s->ext = HYLC_EXT_LINEAR;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFitCompute - Runs Algorithm C5 on the data: normalisation, f0, then every term with samples
  (Algorithms C6, C7). A requested term without samples is left out with a warning; a term with fewer
  than -fit_min_samples_1d/-2d samples is an error. Not collective. Log events FIT_Run, FIT_Term,
  FIT_MLS (knots, MLS, finite differences) and FIT_Monotone (marching, monotone projections,
  residualization).
@*/
PetscErrorCode HylcFitCompute(HylcFit fit)
{
  MPI_Comm comm;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  if (fit->computed) PetscFunctionReturn(PETSC_SUCCESS);
  comm = PetscObjectComm((PetscObject)fit);
  PetscCall(HylcFitSetUp(fit));
  PetscCall(HylcFitResetResults_Private(fit));
  PetscCall(PetscLogEventBegin(HYLC_FitRun, fit, 0, 0, 0));
  /* normalisation: max |value| per strain column over the data (an all-zero column by 1); for a
     samples file, over every computed row, converged or not: the plan's limits */
  for (int i = 0; i < 6; i++) {
    PetscReal mx = fit->zabsmax[i];
    for (PetscInt k = 0; k < fit->n; k++) mx = PetscMax(mx, PetscAbsReal(fit->z[6 * k + i]));
    fit->scale[i] = mx > 0 ? mx : 1;
  }
  for (PetscInt k = 0; k < fit->n; k++)
    PetscCheck(fit->z[6 * k + 4] == 0, comm, PETSC_ERR_USER_INPUT, "%s: row %" PetscInt_FMT " has II01 = %g; the sampling plan of C4 (and this fit) has II01 = 0", fit->source, fit->row[k], (double)fit->z[6 * k + 4]);
  /* f0: psi of the row nearest to the origin in normalised coordinates, ties to the lowest row */
  {
    PetscReal best = PETSC_MAX_REAL;
    for (PetscInt k = 0; k < fit->n; k++) {
      PetscReal d = 0;
      for (int i = 0; i < 6; i++) d += PetscSqr(fit->z[6 * k + i] / fit->scale[i]);
      if (d < best) {
        best       = d;
        fit->f0row = k;
      }
    }
    fit->f0 = fit->psi[fit->f0row];
  }
  /* the method: auto is fabric when every row has its in-plane stress ... */
  fit->methodUsed = fit->compat == HYLC_FIT_COMPAT_AUTHORS ? HYLC_FIT_METHOD_PAPER : fit->method;
  if (fit->methodUsed == HYLC_FIT_METHOD_AUTO) {
    PetscBool all = (PetscBool)(fit->n > 0);
    for (PetscInt k = 0; k < fit->n && all; k++)
      for (int i = 0; i < 3; i++)
        if (PetscIsInfOrNanReal(fit->stress[6 * k + i])) all = PETSC_FALSE;
    /* ... and was sampled on graded knots (a samples file's /plan): the paper's spacing has too few samples
       near zero for the fabric method's knots (a plain weave's sx with 10 samples: RMS 7 % of the range) */
    if (all && fit->samplesFile) {
      PetscInt  nk = 0;
      PetscReal K[HYLC_PLAN_MAXAXIS];
      for (int t = 1; t <= 5 && !nk; t++) PetscCall(HylcSamplesReadKnots(fit->input, t, 0, &nk, K));
      if (!nk) all = PETSC_FALSE;
    }
    fit->methodUsed = all ? HYLC_FIT_METHOD_FABRIC : HYLC_FIT_METHOD_PAPER;
  }
  if (fit->methodUsed == HYLC_FIT_METHOD_FABRIC) PetscCall(HylcFitFabricKnots_Private(fit));
  for (int t = 1; t < HYLC_PLAN_NTERM; t++) {
    PetscInt   n = 0;
    PetscReal *u = NULL, *v = NULL, *l = NULL;
    int        ci = t - 1, cj = -1;
    if (!((fit->terms >> t) & 1)) continue;
    if (t >= 6) HylcPlanPair(t, &ci, &cj);
    PetscCall(PetscLogEventBegin(HYLC_FitTerm, fit, 0, 0, 0));
    PetscCall(Gather(fit, t, ci, cj, &n, &u, &v, &l));
    if (n == 0)
      PetscCall(PetscFPrintf(comm, PETSC_STDERR, "[fit] warning: term %s has no samples in %s: left out of the model\n", HylcPlanTermName(t), fit->source));
    else {
      /* the paper's MLS needs its kernels filled; the fabric method's least squares only more equations than knots
         (its own checks) */
      const PetscInt need = fit->methodUsed == HYLC_FIT_METHOD_FABRIC ? (t <= 5 ? 3 : 8) : t <= 5 ? fit->min1 : fit->min2;
      if (n < need) PetscCall(PetscFree3(u, v, l));
      PetscCheck(n >= need, comm, PETSC_ERR_USER_INPUT, "%s: term %s has only %" PetscInt_FMT " usable samples (at least %" PetscInt_FMT " needed: -fit_min_samples_%s, or leave the term out with -fit_terms)", fit->source, HylcPlanTermName(t), n,
                 need, t <= 5 ? "1d" : "2d");
      PetscErrorCode ierr;
      if (fit->methodUsed == HYLC_FIT_METHOD_FABRIC)
        ierr = t <= 5 ? HylcFitTerm1DFabric_Private(fit, ci) : HylcFitTerm2DFabric_Private(fit, t);
      else
        ierr = t <= 5 ? Fit1D(fit, ci, n, u, l) : Fit2D(fit, t, n, u, v, l);
      if (ierr) PetscCall(PetscFree3(u, v, l));
      PetscCall(ierr);
      fit->has[t] = PETSC_TRUE;
    }
    PetscCall(PetscFree3(u, v, l));
    PetscCall(PetscLogEventEnd(HYLC_FitTerm, fit, 0, 0, 0));
  }
  /* the 3D terms (hylc's extension; the fabric method only): residuals of their grids against the 1D and 2D terms */
  for (int t = HYLC_PLAN_NTERM; t < HYLC_PLAN_NTERM3 && fit->methodUsed == HYLC_FIT_METHOD_FABRIC; t++) {
    PetscInt n = 0;
    if (!((fit->terms >> t) & 1)) continue;
    for (PetscInt k = 0; k < fit->n; k++) n += fit->term[k] == t;
    if (!n) continue;
    PetscCall(PetscLogEventBegin(HYLC_FitTerm, fit, 0, 0, 0));
    PetscCall(HylcFitTerm3DFabric_Private(fit, t));
    fit->has[t] = PETSC_TRUE;
    PetscCall(PetscLogEventEnd(HYLC_FitTerm, fit, 0, 0, 0));
  }
  fit->computed = PETSC_TRUE;
  /* statistics of the model against each term's data */
  for (int t = 1; t < HYLC_PLAN_NTERM3; t++) {
    PetscReal ss = 0, rng = 0, bss[HYLC_FIT_NBAND] = {0, 0, 0}, bref[HYLC_FIT_NBAND] = {0, 0, 0};
    PetscInt  cnt  = 0;
    int       c[3] = {-1, -1, -1};
    if (!fit->has[t]) continue;
    for (int b = 0; b < HYLC_FIT_NBAND; b++) fit->statBandN[t][b] = 0;
    for (int a = 0; a < HylcPlanTermDim(t); a++) c[a] = HylcPlanAxisCoord(t, a);
    for (int a = 0; a < 3; a++) {
      fit->statMin[t][a] = PETSC_MAX_REAL;
      fit->statMax[t][a] = PETSC_MIN_REAL;
    }
    for (PetscInt k = 0; k < fit->n; k++) {
      PetscReal f;
      if (fit->term[k] != t) continue;
      PetscCall(HylcFitEvaluateAxes(fit, fit->z + 6 * k, &f));
      ss += PetscSqr(f - fit->psi[k]);
      rng = PetscMax(rng, PetscAbsReal(fit->psi[k] - fit->f0));
      cnt++;
      int band = 0;
      for (int a = 0; a < 3; a++) {
        if (c[a] < 0) continue;
        const PetscReal x  = fit->z[6 * k + HylcPlanStrainIndex(c[a])];
        const int       kc = c[a] >= 3; /* a curvature */
        fit->statMin[t][a] = PetscMin(fit->statMin[t][a], x);
        fit->statMax[t][a] = PetscMax(fit->statMax[t][a], x);
        band               = PetscMax(band, PetscAbsReal(x) <= HylcFitBandLimits[kc][0] ? 0 : (PetscAbsReal(x) <= HylcFitBandLimits[kc][1] ? 1 : 2));
      }
      bss[band] += PetscSqr(f - fit->psi[k]);
      bref[band] += PetscSqr(fit->psi[k] - fit->f0);
      fit->statBandN[t][band]++;
    }
    for (int b = 0; b < HYLC_FIT_NBAND; b++) fit->statBandRel[t][b] = bref[b] > 0 ? PetscSqrtReal(bss[b] / bref[b]) : 0;
    fit->statN[t]     = cnt;
    fit->statRms[t]   = PetscSqrtReal(ss / PetscMax(cnt, 1));
    fit->statRange[t] = rng;
  }
  PetscCall(PetscLogEventEnd(HYLC_FitRun, fit, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
