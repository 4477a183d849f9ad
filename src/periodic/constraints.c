/* HylcPeriodic: translation and slide constraints, reduced to independent rows (include/hylc/periodic.h). */
#include "periodicimpl.h"

/* per_family: the family (row) and the sign of each loop. A loop's canonical direction is its winding
   divided by the gcd of its components, made lexicographically positive (sign -1 if that reverses it);
   loops of equal canonical direction form a family; loops that close inside the tile (zero winding) form
   their own family with their stored direction. */
static PetscErrorCode SlideFamilies(HylcPattern pat, PetscInt nloops, PetscInt fam[], PetscReal sgn[], PetscInt *nfam)
{
  PetscInt *dir;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(2 * nloops, &dir));
  *nfam = 0;
  for (PetscInt l = 0; l < nloops; l++) {
    PetscInt w[2], a, b, g;
    PetscCall(HylcPatternGetLoop(pat, l, NULL, NULL, w));
    a = PetscAbsInt(w[0]), b = PetscAbsInt(w[1]);
    while (b) {
      const PetscInt t = a % b;
      a = b, b = t;
    }
    g      = a ? a : 1;
    sgn[l] = (w[0] < 0 || (w[0] == 0 && w[1] < 0)) ? -1.0 : 1.0;
    w[0] = (PetscInt)sgn[l] * w[0] / g, w[1] = (PetscInt)sgn[l] * w[1] / g;
    fam[l] = -1;
    for (PetscInt f = 0; f < *nfam; f++)
      if (dir[2 * f] == w[0] && dir[2 * f + 1] == w[1]) fam[l] = f;
    if (fam[l] < 0) {
      dir[2 * *nfam] = w[0], dir[2 * *nfam + 1] = w[1];
      fam[l] = (*nfam)++;
    }
  }
  PetscCall(PetscFree(dir));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Reduces the m constraint rows of A (and dL) to an independent set, in order: modified Gram-Schmidt with
   one reorthogonalization on the rows of A (not on A A^T, which would square the condition); row i is
   dropped when its distance to the span of the rows kept before it is at most crtol |a_i|. The translation
   rows come first and are independent, so a slide row that repeats them (straight yarns; parallel straight
   yarns under per_yarn) is the one dropped. Dropping a dependent row does not change the feasible set: at
   the initial guess every row vanishes, and a dependent row is a combination of the kept ones. When no row
   is dropped, A and dL are untouched (bitwise). */
static PetscErrorCode ReduceConstraints(HylcPeriodic P, PetscInt *m)
{
  const PetscInt n = 4 * P->N, m0 = *m;
  PetscReal     *Q, *r;
  PetscInt       nq = 0, kept = 0;

  PetscFunctionBegin;
  PetscCall(PetscMalloc2(m0 * n, &Q, n, &r));
  for (PetscInt i = 0; i < m0; i++) {
    const PetscReal *a  = P->A + i * n;
    PetscReal        a2 = 0, r2 = 0, scale = 0;
    for (PetscInt k = 0; k < n; k++) scale = PetscMax(scale, PetscAbsReal(a[k]));
    PetscCheck(scale > 0 && !PetscIsInfOrNanReal(scale) && !PetscIsInfOrNanReal(P->dL[i]), PETSC_COMM_SELF, PETSC_ERR_FP, "Constraint row %" PetscInt_FMT " is zero or not finite (|a| max %g, dL %g): is the strain representable?", i, (double)scale,
               (double)P->dL[i]);
    for (PetscInt k = 0; k < n; k++) {
      r[k] = a[k] / scale; /* scaled: no overflow or underflow in the squares */
      a2 += r[k] * r[k];
    }
    for (int pass = 0; pass < 2; pass++)
      for (PetscInt q = 0; q < nq; q++) {
        PetscReal d = 0;
        for (PetscInt k = 0; k < n; k++) d += Q[q * n + k] * r[k];
        for (PetscInt k = 0; k < n; k++) r[k] -= d * Q[q * n + k];
      }
    for (PetscInt k = 0; k < n; k++) r2 += r[k] * r[k];
    if (r2 <= P->crtol * P->crtol * a2) {
      PetscCall(PetscInfo(NULL, "constraint row %" PetscInt_FMT " dropped: linearly dependent on the rows before it (relative distance %g <= %g)\n", i, (double)PetscSqrtReal(r2 / a2), (double)P->crtol));
      continue;
    }
    const PetscReal rn = PetscSqrtReal(r2);
    for (PetscInt k = 0; k < n; k++) Q[nq * n + k] = r[k] / rn;
    nq++;
    if (kept != i) {
      PetscCall(PetscArraycpy(P->A + kept * n, a, n));
      P->dL[kept] = P->dL[i];
    }
    P->crow[kept++] = i;
  }
  PetscCall(PetscFree2(Q, r));
  P->ndropped = m0 - kept;
  P->ncons = *m = kept;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the slide row of vertex o (before the reduction), its sign, and the reference tangent t = te + tf at o
   in (xi1, xi2, h) (the sum of the unit vectors of the edges into and out of o) */
static PetscErrorCode SlideRow(HylcPeriodic P, PetscInt o, const PetscInt fam[], const PetscReal sgn[], PetscInt *row, PetscReal *s, PetscReal t[3])
{
  const PetscInt u = P->D.prev[o], w = P->D.next[o];
  PetscReal      te[3], tf[3];
  PetscInt       l;

  PetscFunctionBegin;
  for (int i = 0; i < 3; i++) {
    te[i] = P->xi[3 * o + i] - P->xi[3 * u + i];
    tf[i] = P->xi[3 * w + i] - P->xi[3 * o + i];
  }
  te[0] += P->D.shift[2 * u] * P->D.px;
  te[1] += P->D.shift[2 * u + 1] * P->D.py;
  tf[0] += P->D.shift[2 * o] * P->D.px;
  tf[1] += P->D.shift[2 * o + 1] * P->D.py;
  HylcNormalize3(te);
  HylcNormalize3(tf);
  for (int i = 0; i < 3; i++) t[i] = te[i] + tf[i];
  *row = 3;
  *s   = 1;
  PetscCall(HylcPatternGetVertexLoop(P->pat, o, &l, NULL));
  if (P->slide == HYLC_SLIDE_PER_YARN) *row += l;
  if (P->slide == HYLC_SLIDE_PER_FAMILY) *row += fam[l], *s = sgn[l];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the families of the slide rows (per_family) and the number of rows before the reduction */
static PetscErrorCode ConstraintLayout(HylcPeriodic P, PetscInt *nloops, PetscInt **fam, PetscReal **sgn, PetscInt *m)
{
  PetscInt nfam = 0;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetNumLoops(P->pat, nloops));
  PetscCall(PetscMalloc2(*nloops, fam, *nloops, sgn));
  if (P->slide == HYLC_SLIDE_PER_FAMILY) PetscCall(SlideFamilies(P->pat, *nloops, *fam, *sgn, &nfam));
  *m = 3 + (P->slide == HYLC_SLIDE_PER_YARN ? *nloops : P->slide == HYLC_SLIDE_PER_FAMILY ? nfam : P->slide == HYLC_SLIDE_GLOBAL ? 1 : 0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicSetUpConstraints_Private(HylcPeriodic P, const PetscReal *x0)
{
  const PetscInt         N = P->N;
  PetscInt               nloops, m, *fam;
  PetscReal             *sgn;
  const HylcMacroStrain *ms;

  PetscFunctionBegin;
  PetscCall(ConstraintLayout(P, &nloops, &fam, &sgn, &m));
  P->ncons = m;
  PetscCall(PetscCalloc3(m * 4 * N, &P->A, m, &P->dL, m * m, &P->AAtinv));
  PetscCall(PetscMalloc1(m, &P->crow));
  PetscCall(HylcMidsurfaceGetStrain(P->ms, &ms));
  for (PetscInt o = 0; o < N; o++) {
    const PetscInt  u  = P->D.prev[o];
    const PetscReal wo = 0.5 * (P->D.restLength[u] + P->D.restLength[o]); /* rest Voronoi length */
    PetscReal       R[9], Rtx[3], tau[3], t[3], Rtau[3], s;
    PetscInt        row;
    PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, R));
    MatT3(R, x0 + 3 * o, Rtx);
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) P->A[i * 4 * N + 4 * o + j] = wo * R[3 * j + i]; /* rows of R^T */
      P->dL[i] += wo * Rtx[i];
    }
    if (P->slide == HYLC_SLIDE_NONE) continue;
    /* reference unit tangent at o in (xi1, xi2, h), deformed in-plane by S3 = [[A, 0], [0, 1]] */
    PetscCall(SlideRow(P, o, fam, sgn, &row, &s, t));
    tau[0] = ms->A[0] * t[0] + ms->A[1] * t[1];
    tau[1] = ms->A[2] * t[0] + ms->A[3] * t[1];
    tau[2] = t[2];
    PetscCheck(HylcNormalize3(tau) > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Yarn folds back at vertex %" PetscInt_FMT ": no tangent for the slide constraint", o);
    Mat3(R, tau, Rtau);
    for (int j = 0; j < 3; j++) P->A[row * 4 * N + 4 * o + j] = s * wo * Rtau[j];
    P->dL[row] += s * wo * HylcDot3(tau, Rtx);
  }
  PetscCall(PetscFree2(fam, sgn));
  PetscCall(ReduceConstraints(P, &m));
  /* (A A^T)^-1 of the small SPD matrix */
  {
    PetscReal *M, *I1;
    PetscCall(PetscCalloc2(m * m, &M, m * m, &I1));
    for (PetscInt i = 0; i < m; i++) {
      I1[i * m + i] = 1;
      for (PetscInt j = 0; j < m; j++)
        for (PetscInt k = 0; k < 4 * N; k++) M[i * m + j] += P->A[i * 4 * N + k] * P->A[j * 4 * N + k];
    }
    /* the kept rows are independent to crtol (sin of the angle to the span of the others): the pivots of
       A A^T are at least about crtol^2 times its diagonal */
    const int err = HylcDenseInverse((int)m, M, I1, 1e-2 * P->crtol * P->crtol);
    PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The reduced constraint rows are numerically dependent (row %d) although they passed the dependence test with -periodic_constraint_rtol %g", -1 - err, (double)P->crtol);
    PetscCall(PetscArraycpy(P->AAtinv, I1, m * m));
    PetscCall(PetscFree2(M, I1));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* dc/dz_j (j = sx, sa, sy) at fixed y of the kept rows, for a flat strain (II = 0: R = I, x0 = (A xi, h) at
   the originals). Translation rows: c = sum_o w_o (y_o - x0_o), so dc/dz_j = -sum_o w_o dx0_o/dz_j with
   dx0_o/dz_j = (dA_j xi_o, 0). Slide rows: c = sum_o s w_o tau_o . (y_o - x0_o) with tau_o = v / |v|,
   v = (A t_xy, t_z), so dc/dz_j = sum_o s w_o [dtau_j . (y_o - x0_o) - tau_o . dx0_o/dz_j] with
   dtau_j = (I - tau tau^T) (dA_j t_xy, 0) / |v|. */
PetscErrorCode HylcPeriodicConstraintStrainDerivative_Private(HylcPeriodic P, PetscReal dcdz[])
{
  const PetscInt         N = P->N;
  PetscInt               nloops, m, *fam;
  PetscReal             *sgn, *full, dA[12];
  const HylcMacroStrain *ms;

  PetscFunctionBegin;
  PetscCall(ConstraintLayout(P, &nloops, &fam, &sgn, &m));
  PetscCall(PetscCalloc1(3 * m, &full));
  PetscCall(HylcMidsurfaceGetStrain(P->ms, &ms));
  StretchDerivatives(P->z, dA);
  for (PetscInt o = 0; o < N; o++) {
    const PetscInt   u  = P->D.prev[o];
    const PetscReal  wo = 0.5 * (P->D.restLength[u] + P->D.restLength[o]);
    const PetscReal *xi = P->xi + 3 * o, *y = P->y + 4 * o, *x0 = P->y0 + 4 * o;
    PetscReal        dx0[3][3], ut[3];
    for (int j = 0; j < 3; j++) {
      dx0[j][0] = dA[4 * j] * xi[0] + dA[4 * j + 1] * xi[1];
      dx0[j][1] = dA[4 * j + 2] * xi[0] + dA[4 * j + 3] * xi[1];
      dx0[j][2] = 0;
      for (int i = 0; i < 3; i++) full[3 * i + j] -= wo * dx0[j][i];
    }
    if (P->slide == HYLC_SLIDE_NONE) continue;
    PetscReal t[3], v[3], s, nv;
    PetscInt  row;
    PetscCall(SlideRow(P, o, fam, sgn, &row, &s, t));
    v[0] = ms->A[0] * t[0] + ms->A[1] * t[1];
    v[1] = ms->A[2] * t[0] + ms->A[3] * t[1];
    v[2] = t[2];
    nv   = HylcNormalize3(v); /* v is tau now */
    for (int i = 0; i < 3; i++) ut[i] = y[i] - x0[i];
    for (int j = 0; j < 3; j++) {
      const PetscReal dv[3] = {dA[4 * j] * t[0] + dA[4 * j + 1] * t[1], dA[4 * j + 2] * t[0] + dA[4 * j + 3] * t[1], 0};
      const PetscReal tdv   = HylcDot3(v, dv);
      PetscReal       dtau[3];
      for (int i = 0; i < 3; i++) dtau[i] = (dv[i] - v[i] * tdv) / nv;
      full[3 * row + j] += s * wo * (HylcDot3(dtau, ut) - HylcDot3(v, dx0[j]));
    }
  }
  for (PetscInt k = 0; k < P->ncons; k++)
    for (int j = 0; j < 3; j++) dcdz[3 * k + j] = full[3 * P->crow[k] + j];
  PetscCall(PetscFree(full));
  PetscCall(PetscFree2(fam, sgn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* The kept constraint residuals at the state y for the strain of ms: translation rows
   sum_o w_o R_o^T (y_o - x0_o), slide rows sum_o s w_o tau_o . R_o^T (y_o - x0_o) with R_o, x0_o and tau_o
   (the reference tangent deformed by ms's A) of ms. At P's own strain this is A y - dL. */
PetscErrorCode HylcPeriodicConstraintResidualAt_Private(HylcPeriodic P, HylcMidsurface ms, const PetscReal *x0, const PetscReal y[], PetscReal c[])
{
  const PetscInt         N = P->N;
  PetscInt               nloops, m, *fam;
  PetscReal             *sgn, *full;
  const HylcMacroStrain *st;

  PetscFunctionBegin;
  PetscCall(ConstraintLayout(P, &nloops, &fam, &sgn, &m));
  PetscCall(PetscCalloc1(m, &full));
  PetscCall(HylcMidsurfaceGetStrain(ms, &st));
  for (PetscInt o = 0; o < N; o++) {
    const PetscInt  u  = P->D.prev[o];
    const PetscReal wo = 0.5 * (P->D.restLength[u] + P->D.restLength[o]);
    PetscReal       R[9], d[3], Rtd[3], t[3], tau[3], s;
    PetscInt        row;
    PetscCall(HylcMidsurfaceGetRotation(ms, P->xi + 3 * o, R));
    for (int i = 0; i < 3; i++) d[i] = y[4 * o + i] - x0[3 * o + i];
    MatT3(R, d, Rtd);
    for (int i = 0; i < 3; i++) full[i] += wo * Rtd[i];
    if (P->slide == HYLC_SLIDE_NONE) continue;
    PetscCall(SlideRow(P, o, fam, sgn, &row, &s, t));
    tau[0] = st->A[0] * t[0] + st->A[1] * t[1];
    tau[1] = st->A[2] * t[0] + st->A[3] * t[1];
    tau[2] = t[2];
    PetscCheck(HylcNormalize3(tau) > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Yarn folds back at vertex %" PetscInt_FMT ": no tangent for the slide constraint", o);
    full[row] += s * wo * HylcDot3(tau, Rtd);
  }
  for (PetscInt k = 0; k < P->ncons; k++) c[k] = full[P->crow[k]];
  PetscCall(PetscFree(full));
  PetscCall(PetscFree2(fam, sgn));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetConstraints - The constraints A y = dL of the set-up tile (borrowed; any output may be NULL).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameters:
+ m      - rows (independent; dependent ones dropped)
. A      - m x 4N, row-major
. dL     - m
- AAtinv - (A A^T)^-1, m x m

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetConstraints(HylcPeriodic P, PetscInt *m, const PetscReal **A, const PetscReal **dL, const PetscReal **AAtinv)
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  if (m) *m = P->ncons;
  if (A) *A = P->A;
  if (dL) *dL = P->dL;
  if (AAtinv) *AAtinv = P->AAtinv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicConstraintResidual - The constraint residual c = A y - dL.

  Not collective

  Input Parameters:
+ P - the periodic tile
- y - 4 per original vertex

  Output Parameter:
. c - one per constraint row

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicConstraintResidual(HylcPeriodic P, const PetscReal y[], PetscReal c[])
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < P->ncons; i++) {
    PetscReal s = -P->dL[i];
    for (PetscInt k = 0; k < 4 * P->N; k++) s += P->A[i * 4 * P->N + k] * y[k];
    c[i] = s;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
