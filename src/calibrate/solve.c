/* HylcCalibrate: evaluation of the samples over the ranks, the objective with its envelope-theorem
   Jacobian, its minimisation in log parameters by TAO (held flat directions, hylc's stopping tests), and
   the outputs (docs/calibrate.md). */
#include "calibrateimpl.h"
#include <petsctime.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

/* energy part matching parameter j: E bend (1), Es stretch (0), G twist (2), kc contact (3) */
static const int PartOf[HYLC_CALIBRATE_NPARAM] = {1, 0, 2, 3};

/* the gradient dPsi/dsx, dPsi/dsy at the micro solver's current equilibrium and its Gauss-Newton columns,
   dlogp[2 q + k] = p_q d/dp_q of dPsi/ds_k at the fixed state (parameter q's energy term) */
PetscErrorCode HylcCalibrateStrainGradient_Private(HylcCalibrate C, PetscReal ds[2], PetscReal dlogp[])
{
  PetscReal g[6], dp[24];

  PetscFunctionBegin;
  PetscCall(HylcMicroGetStrainGradientParts(C->micro, HYLC_STRAIN_PLANE_BITS, g, dp));
  ds[0] = g[0];
  ds[1] = g[2];
  for (int q = 0; q < HYLC_CALIBRATE_NPARAM; q++) {
    dlogp[2 * q]     = dp[6 * PartOf[q]];
    dlogp[2 * q + 1] = dp[6 * PartOf[q] + 2];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the coordinate of a 1D term t (1..5) in z: sx, sa, sy, II00, II11 */
static const int CoordOf1D[6] = {-1, 0, 1, 2, 3, 5};

PetscErrorCode HylcCalibrateBuildUnits_Private(HylcCalibrate C)
{
  PetscInt nu = 0, pos = 0;

  PetscFunctionBegin;
  PetscCall(PetscFree2(C->ustart, C->uorder));
  PetscCall(PetscMalloc2(C->m + 1, &C->ustart, C->m + 1, &C->uorder));
  /* the half-lines of the 1D terms (samples at zero strain go with the positive side), each ordered by the
     distance from zero (insertion sort, stable: equal distances keep the target's order) */
  if (C->continued)
    for (PetscInt t = 1; t <= 5; t++)
      for (int side = 0; side < 2; side++) {
        const PetscInt first = pos, c = CoordOf1D[t];
        for (PetscInt i = 1; i < C->m; i++) {
          if (C->term[i] != t || (side == 0) != (C->z[6 * i + c] >= 0)) continue;
          PetscInt j = pos++;
          for (; j > first && PetscAbsReal(C->z[6 * C->uorder[j - 1] + c]) > PetscAbsReal(C->z[6 * i + c]); j--) C->uorder[j] = C->uorder[j - 1];
          C->uorder[j] = i;
        }
        if (pos > first) C->ustart[nu++] = first;
      }
  /* every other sample (the base strain, 2D terms, rows off the axes; all of them when cold) alone */
  for (PetscInt i = 0; i < C->m; i++) {
    if (C->continued && i > 0 && C->term[i] >= 1 && C->term[i] <= 5) continue;
    C->ustart[nu++]  = pos;
    C->uorder[pos++] = i;
  }
  PetscCheck(pos == C->m, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The units of the calibration cover %" PetscInt_FMT " of %" PetscInt_FMT " samples", pos, C->m);
  C->ustart[nu] = pos;
  C->nunits     = nu;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcCalibrateSolveSamples_Private(HylcCalibrate C, const PetscReal p[], PetscReal rec[])
{
  MPI_Comm      comm  = PetscObjectComm((PetscObject)C);
  HylcYarnModel model = C->model;
  PetscInt      nloc = 0, j = 0, ny = 0;
  PetscReal    *buf, *all, *y = NULL, *u = NULL;
  PetscMPIInt  *counts, *displs;
  const int     NB = HYLC_CALIB_NRECORD + 1; /* a record and its sample index */

  PetscFunctionBegin;
  model.E  = p[0];
  model.Es = p[1];
  model.G  = p[2];
  model.kc = p[3];
  PetscCall(PetscLogEventBegin(HYLC_CalibrateEvaluate, C, 0, 0, 0));
  PetscCall(HylcMicroSetPattern(C->micro, C->pat, &model));
  PetscCall(HylcMicroSetUp(C->micro));
  for (PetscInt b = C->rank; b < C->nunits; b += C->size) nloc += C->ustart[b + 1] - C->ustart[b];
  PetscCall(PetscMalloc1(nloc * NB + 1, &buf));
  /* static cyclic split of the units (continuation: a 1D term's half-line, from zero outward, each sample
     from its predecessor's equilibrium, retried cold if that does not converge; cold: one sample each), each
     unit's first sample from the reference state: a result does not depend on which rank solves it */
  for (PetscInt b = C->rank; b < C->nunits; b += C->size) {
    PetscBool prevOk = PETSC_FALSE;
    for (PetscInt q = C->ustart[b]; q < C->ustart[b + 1]; q++, j++) {
      const PetscInt  k = C->uorder[q];
      HylcMicroResult res;
      HylcPeriodic    P;
      PetscReal       area, *o = buf + j * NB;
      PetscCall(HylcMicroSolveContinued(C->micro, C->z + 6 * k, prevOk ? u : NULL, &res, y, NULL));
      PetscCall(HylcMicroGetPeriodic(C->micro, &P));
      if (!y && C->continued) { /* the tile's size is known after the first solve */
        PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, NULL));
        PetscCall(PetscMalloc2(ny, &y, ny, &u));
        PetscCall(HylcMicroGetState(C->micro, y));
      }
      prevOk = (PetscBool)(C->continued && res.status == HYLC_MICRO_CONVERGED);
      if (prevOk) PetscCall(HylcMicroGetFluctuation(C->micro, y, u));
      PetscCall(HylcPeriodicGetArea(P, &area));
      o[0] = res.psi;
      for (int r = 0; r < HYLC_CALIBRATE_NPARAM; r++) o[1 + r] = res.parts[PartOf[r]] / area; /* dPsi/dlog p_r */
      o[5] = (PetscReal)res.status;
      o[6] = (PetscReal)res.iterations;
      for (int r = HYLC_CALIB_REC_DS; r < HYLC_CALIB_NRECORD; r++) o[r] = 0;
      if (k == 0 && C->hasGrad && res.status == HYLC_MICRO_CONVERGED) /* the gradient at the base strain, split by parameter */
        PetscCall(HylcCalibrateStrainGradient_Private(C, o + HYLC_CALIB_REC_DS, o + HYLC_CALIB_REC_DSP));
      o[HYLC_CALIB_NRECORD] = (PetscReal)k;
    }
  }
  /* -calibrate_stationary_jacobian fd: the stationarity's Jacobian columns (the parameters not fixed) by
     central differences in log p, each a cold re-solve of the base sample: they include the change of the
     equilibrium with p that the Gauss-Newton columns above leave out */
  if (C->wstat > 0 && C->statFD) {
    PetscReal *ob = NULL;
    for (PetscInt i = 0; i < nloc; i++)
      if (buf[i * NB + HYLC_CALIB_NRECORD] == 0) ob = buf + i * NB;
    if (ob && ob[5] == 0) {
      for (int q = 0; q < HYLC_CALIBRATE_NPARAM; q++) {
        PetscReal       g[2][6];
        HylcMicroResult res;
        PetscBool       ok = PETSC_TRUE;
        if (C->role[q] == HYLC_CALIBRATE_FIXED) continue;
        for (int sg = 0; sg < 2; sg++) {
          HylcYarnModel mq = model;
          PetscReal    *pq = q == 0 ? &mq.E : q == 1 ? &mq.Es : q == 2 ? &mq.G : &mq.kc;
          *pq *= PetscExpReal(sg ? -C->statH : C->statH);
          PetscCall(HylcMicroSetPattern(C->micro, C->pat, &mq));
          PetscCall(HylcMicroSetUp(C->micro));
          PetscCall(HylcMicroSolveContinued(C->micro, C->z, NULL, &res, NULL, NULL));
          if (res.status != HYLC_MICRO_CONVERGED) {
            ok = PETSC_FALSE;
            break;
          }
          PetscCall(HylcMicroGetStrainGradient(C->micro, HYLC_STRAIN_PLANE_BITS, g[sg]));
        }
        if (ok)
          for (int k = 0; k < 2; k++) ob[HYLC_CALIB_REC_DSP + 2 * q + k] = (g[0][2 * k] - g[1][2 * k]) / (2 * C->statH);
        else
          PetscCall(PetscInfo(C, "the base sample with %s x exp(+-%g) did not converge: its stationarity column is the Gauss-Newton one\n", HylcCalibrateParamNames[q], (double)C->statH));
      }
    }
  }
  PetscCall(PetscFree2(y, u));
  PetscCall(PetscLogEventEnd(HYLC_CalibrateEvaluate, C, 0, 0, 0));
  PetscCall(PetscLogEventBegin(HYLC_CalibrateGather, C, 0, 0, 0));
  PetscCall(PetscMalloc3(C->size, &counts, C->size, &displs, C->m * NB + 1, &all));
  for (PetscMPIInt r = 0, off = 0; r < C->size; r++) {
    PetscInt nr = 0;
    for (PetscInt b = r; b < C->nunits; b += C->size) nr += C->ustart[b + 1] - C->ustart[b];
    counts[r] = (PetscMPIInt)(nr * NB);
    displs[r] = off;
    off += counts[r];
  }
  PetscCallMPI(MPI_Allgatherv(buf, (PetscMPIInt)(nloc * NB), MPIU_REAL, all, counts, displs, MPIU_REAL, comm));
  for (PetscInt i = 0; i < C->m; i++) {
    const PetscReal *o = all + i * NB;
    const PetscInt   k = (PetscInt)o[HYLC_CALIB_NRECORD];
    PetscCheck(k >= 0 && k < C->m, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Gathered record of sample %" PetscInt_FMT " outside the %" PetscInt_FMT " samples", k, C->m);
    PetscCall(PetscArraycpy(rec + k * HYLC_CALIB_NRECORD, o, HYLC_CALIB_NRECORD));
  }
  PetscCall(PetscFree3(counts, displs, all));
  PetscCall(PetscFree(buf));
  PetscCall(PetscLogEventEnd(HYLC_CalibrateGather, C, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* r[0] = sqrt(w0) (Psi(z_b) - Psi_T(z_b)) / |Psi_T(z_b)|,
   r[i] = sqrt(w_t / n_t) ((Psi_i - Psi_b) - (T_i - T_b)) / R_t for the other samples (0 if not converged);
   J[i][q] = dr_i / dlog p_q (no ties); f = sum r^2 (infinite if the base sample did not converge) */
PetscErrorCode HylcCalibrateResiduals_Private(HylcCalibrate C, const PetscReal rec[], PetscReal r[], PetscReal J[], PetscReal *f, PetscInt *nfailed)
{
  const PetscInt   NR = HYLC_CALIB_NRECORD, NP = HYLC_CALIBRATE_NPARAM;
  const PetscReal *b  = rec;
  PetscReal        s  = 0, scale0;
  PetscInt         nf = 0;

  PetscFunctionBegin;
  scale0 = PetscAbsReal(C->tpsi[0]);
  if (scale0 == 0)
    for (PetscInt t = 1; t < HYLC_CALIB_NTERM; t++) scale0 = PetscMax(scale0, C->range[t]);
  for (PetscInt i = 0; i < C->m; i++) {
    const PetscReal *o = rec + i * NR;
    if (o[5] != 0 || (i && b[5] != 0)) {
      r[i] = 0;
      for (PetscInt q = 0; q < NP; q++) J[i * NP + q] = 0;
      nf++;
      continue;
    }
    if (!i) {
      const PetscReal c = PetscSqrtReal(C->wzero) / scale0;
      r[0]              = c * (o[0] - C->tpsi[0]);
      for (PetscInt q = 0; q < NP; q++) J[q] = c * o[1 + q];
    } else {
      const PetscInt  t = C->term[i];
      const PetscReal c = PetscSqrtReal(C->w[t] / C->nt[t]) / C->range[t];
      r[i]              = c * ((o[0] - b[0]) - (C->tpsi[i] - C->tpsi[0]));
      for (PetscInt q = 0; q < NP; q++) J[i * NP + q] = c * (o[1 + q] - b[1 + q]);
    }
    s += r[i] * r[i];
  }
  /* the stationarity at the base strain: sqrt(w) dPsi/ds_k(z_b) / S_k, its Jacobian from the records: the
     energy terms' parts at the fixed state of the tile (gn: the change of the equilibrium with p left out)
     or central differences over re-solves (fd) */
  for (PetscInt k = 0; k < C->nres - C->m; k++) {
    const PetscInt  i = C->m + k;
    const PetscReal c = PetscSqrtReal(C->wstat) / C->sscale[k];
    r[i]              = b[5] != 0 ? 0 : c * b[HYLC_CALIB_REC_DS + k];
    for (PetscInt q = 0; q < NP; q++) J[i * NP + q] = b[5] != 0 ? 0 : c * b[HYLC_CALIB_REC_DSP + 2 * q + k];
    s += r[i] * r[i];
  }
  *f = b[5] != 0 ? PETSC_INFINITY : s;
  if (nfailed) *nfailed = nf;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateEvaluate - The objective f at explicit parameter values p = (E, Es, G, kc) (no ties applied)
  and its gradient grad[j] = df / dlog p_j by the envelope theorem; one solve per sample, the samples
  spread over the ranks. After HylcCalibrateSetUp().

  Collective

  Input Parameters:
+ C - the calibration
- p - the 4 parameter values (> 0)

  Output Parameters:
+ f       - the objective
. grad    - the gradient in log parameters (may be NULL)
- nfailed - samples left out because they did not converge (may be NULL)

  Level: intermediate
@*/
PetscErrorCode HylcCalibrateEvaluate(HylcCalibrate C, const PetscReal p[], PetscReal *f, PetscReal grad[], PetscInt *nfailed)
{
  PetscReal *rec, *r, *J;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCheck(C->setupcalled, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_WRONGSTATE, "Call HylcCalibrateSetUp() first");
  for (int q = 0; q < HYLC_CALIBRATE_NPARAM; q++) PetscCheck(p[q] > 0, PetscObjectComm((PetscObject)C), PETSC_ERR_ARG_OUTOFRANGE, "Parameter %s = %g must be positive", HylcCalibrateParamNames[q], (double)p[q]);
  PetscCall(PetscMalloc3(C->m * HYLC_CALIB_NRECORD, &rec, C->nres, &r, C->nres * HYLC_CALIBRATE_NPARAM, &J));
  PetscCall(HylcCalibrateSolveSamples_Private(C, p, rec));
  PetscCall(HylcCalibrateResiduals_Private(C, rec, r, J, f, nfailed));
  if (grad)
    for (int q = 0; q < HYLC_CALIBRATE_NPARAM; q++) {
      grad[q] = 0;
      for (PetscInt i = 0; i < C->nres; i++) grad[q] += 2 * r[i] * J[i * HYLC_CALIBRATE_NPARAM + q];
    }
  PetscCall(PetscFree3(rec, r, J));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the full parameter vector from the log values of the active parameters: tied ones follow E */
static void Expand(HylcCalibrate C, const PetscReal x[], PetscReal p[])
{
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) p[j] = C->role[j] == HYLC_CALIBRATE_FIXED ? C->p0[j] : PetscExpReal(x[j]); /* fixed: exactly the initial value */
  for (int j = 1; j < HYLC_CALIBRATE_NPARAM; j++)
    if (C->role[j] == HYLC_CALIBRATE_TIED) p[j] = C->p0[j] * (p[0] / C->p0[0]);
}

/* eigenvalues (ascending) and eigenvectors (columns of V) of a symmetric n x n matrix, n <= 4 (Jacobi) */
static void SymEig(int n, const PetscReal A0[], PetscReal ev[], PetscReal V[])
{
  PetscReal A[16];
  for (int i = 0; i < n * n; i++) A[i] = A0[i];
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) V[i * n + j] = i == j;
  for (int sweep = 0; sweep < 60; sweep++) {
    PetscReal off = 0;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++) off += A[i * n + j] * A[i * n + j];
    if (off < 1e-300) break;
    for (int pp = 0; pp < n; pp++)
      for (int q = pp + 1; q < n; q++) {
        if (A[pp * n + q] == 0) continue;
        const PetscReal th = 0.5 * PetscAtan2Real(2 * A[pp * n + q], A[q * n + q] - A[pp * n + pp]);
        const PetscReal c = PetscCosReal(th), s = PetscSinReal(th);
        for (int k = 0; k < n; k++) { /* A = A G */
          const PetscReal akp = A[k * n + pp], akq = A[k * n + q];
          A[k * n + pp] = c * akp - s * akq;
          A[k * n + q]  = s * akp + c * akq;
        }
        for (int k = 0; k < n; k++) { /* A = G^T A */
          const PetscReal apk = A[pp * n + k], aqk = A[q * n + k];
          A[pp * n + k] = c * apk - s * aqk;
          A[q * n + k]  = s * apk + c * aqk;
        }
        for (int k = 0; k < n; k++) {
          const PetscReal vkp = V[k * n + pp], vkq = V[k * n + q];
          V[k * n + pp] = c * vkp - s * vkq;
          V[k * n + q]  = s * vkp + c * vkq;
        }
      }
  }
  for (int i = 0; i < n; i++) ev[i] = A[i * n + i];
  for (int i = 0; i < n; i++) /* sort ascending */
    for (int j = i + 1; j < n; j++)
      if (ev[j] < ev[i]) {
        PetscReal t = ev[i];
        ev[i]       = ev[j];
        ev[j]       = t;
        for (int k = 0; k < n; k++) {
          t            = V[k * n + i];
          V[k * n + i] = V[k * n + j];
          V[k * n + j] = t;
        }
      }
}

/* columns of the active parameters (E's column also carries the tied parameters) */
static void ActiveJacobian(HylcCalibrate C, const PetscReal J[], const int act[], int na, PetscReal Jc[])
{
  for (PetscInt i = 0; i < C->nres; i++)
    for (int a = 0; a < na; a++) {
      const int j = act[a];
      PetscReal v = J[i * HYLC_CALIBRATE_NPARAM + j];
      if (j == 0)
        for (int q = 1; q < HYLC_CALIBRATE_NPARAM; q++)
          if (C->role[q] == HYLC_CALIBRATE_TIED) v += J[i * HYLC_CALIBRATE_NPARAM + q];
      Jc[i * na + a] = v;
    }
}

/* the line of iteration it (step < 0: none, the initial point) */
static PetscErrorCode PrintLine(HylcCalibrate C, PetscInt it, PetscReal f, const PetscReal p[], PetscReal step, PetscInt nfailed, PetscLogDouble dt)
{
  char buf[512];
  int  len;

  PetscFunctionBegin;
  if (f < PETSC_INFINITY)
    len = snprintf(buf, sizeof(buf), "[calibrate] it %3d  f %.6e", (int)it, (double)f);
  else
    len = snprintf(buf, sizeof(buf), "[calibrate] it %3d  f inf (the base sample did not converge)", (int)it);
  len += snprintf(buf + len, sizeof(buf) - len, "  E %.6g  Es %.6g  G %.6g  kc %.6g", (double)p[0], (double)p[1], (double)p[2], (double)p[3]);
  if (step >= 0) len += snprintf(buf + len, sizeof(buf) - len, "  step %.2e", (double)step);
  if (nfailed && f < PETSC_INFINITY) len += snprintf(buf + len, sizeof(buf) - len, "  (%d samples not converged, left out)", (int)nfailed);
  snprintf(buf + len, sizeof(buf) - len, "  %.1f s\n", dt);
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)C), "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the state of one HylcCalibrateSolve(): TAO's variables are the log values of the free parameters */
typedef struct {
  HylcCalibrate  C;
  int            act[HYLC_CALIBRATE_NPARAM], na; /* the free parameters, in the order of TAO's variables */
  PetscReal     *rec, *r, *J, *Jc;               /* the evaluation at xc: records, residuals, Jacobian (m x 4), active columns */
  PetscReal      xc[HYLC_CALIBRATE_NPARAM], f;   /* its point (log values of all four) and objective */
  PetscInt       nfailed;
  PetscBool      cached;
  PetscLogDouble dt;                                  /* the time of that evaluation */
  PetscReal      xprev[HYLC_CALIBRATE_NPARAM], fprev; /* the previous iterate */
  Vec            XL, XU;                              /* TAO's bounds: those of a held parameter collapse to its value */
  const char    *reason;                              /* the test of hylc that stopped TAO */
} CalibTao;

/* r, J and f at TAO's point X, solved unless X is the point of the last evaluation (TAO asks for the
   residual and the Jacobian of a point separately: one solve of the samples serves both) */
static PetscErrorCode EvalAt(CalibTao *c, Vec X)
{
  HylcCalibrate      C = c->C;
  const PetscScalar *x;
  PetscReal          lx[HYLC_CALIBRATE_NPARAM], p[HYLC_CALIBRATE_NPARAM];
  PetscBool          same = c->cached;
  PetscLogDouble     t0, t1;

  PetscFunctionBegin;
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) lx[j] = PetscLogReal(C->p0[j]);
  PetscCall(VecGetArrayRead(X, &x));
  for (int a = 0; a < c->na; a++) lx[c->act[a]] = PetscRealPart(x[a]);
  PetscCall(VecRestoreArrayRead(X, &x));
  for (int a = 0; a < c->na; a++) same = (PetscBool)(same && lx[c->act[a]] == c->xc[c->act[a]]);
  if (same) PetscFunctionReturn(PETSC_SUCCESS);
  Expand(C, lx, p);
  PetscCall(PetscTime(&t0));
  PetscCall(HylcCalibrateSolveSamples_Private(C, p, c->rec));
  PetscCall(HylcCalibrateResiduals_Private(C, c->rec, c->r, c->J, &c->f, &c->nfailed));
  PetscCall(PetscTime(&t1));
  C->nevals++;
  c->dt = t1 - t0;
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) c->xc[j] = lx[j];
  c->cached = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* TAO's residual: the normalised residuals; all infinite where the base sample did not converge (f = inf,
   which TAO's line search rejects) */
static PetscErrorCode FormResidual(Tao tao, Vec X, Vec F, void *ctx)
{
  CalibTao    *c = (CalibTao *)ctx;
  PetscScalar *f;

  PetscFunctionBegin;
  (void)tao;
  PetscCall(EvalAt(c, X));
  PetscCall(VecGetArrayWrite(F, &f));
  for (PetscInt i = 0; i < c->C->nres; i++) f[i] = c->f < PETSC_INFINITY ? c->r[i] : PETSC_INFINITY;
  PetscCall(VecRestoreArrayWrite(F, &f));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* TAO's Jacobian (dense, m x na): the free parameters' columns (E's with the tied ones'), zero for a held
   parameter, so that it does not move (its bounds are collapsed as well) */
static PetscErrorCode FormJacobian(Tao tao, Vec X, Mat Jm, Mat Jpre, void *ctx)
{
  CalibTao     *c = (CalibTao *)ctx;
  HylcCalibrate C = c->C;
  PetscScalar  *v;
  PetscInt      lda;

  PetscFunctionBegin;
  (void)tao;
  (void)Jpre;
  PetscCall(EvalAt(c, X));
  ActiveJacobian(C, c->J, c->act, c->na, c->Jc);
  PetscCall(MatDenseGetLDA(Jm, &lda));
  PetscCall(MatDenseGetArrayWrite(Jm, &v));
  for (int a = 0; a < c->na; a++)
    for (PetscInt i = 0; i < C->nres; i++) v[i + a * lda] = C->held[c->act[a]] ? 0 : c->Jc[i * c->na + a];
  PetscCall(MatDenseRestoreArrayWrite(Jm, &v));
  PetscCall(MatAssemblyBegin(Jm, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(Jm, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* objective and gradient for TAO types that are not least-squares ones (-calibrate_tao_type blmvm, ...):
   (1/2) |r|^2, as TAOBRGN's, and J^T r */
static PetscErrorCode FormObjectiveGradient(Tao tao, Vec X, PetscReal *f, Vec G, void *ctx)
{
  CalibTao     *c = (CalibTao *)ctx;
  HylcCalibrate C = c->C;
  PetscScalar  *g;

  PetscFunctionBegin;
  (void)tao;
  PetscCall(EvalAt(c, X));
  ActiveJacobian(C, c->J, c->act, c->na, c->Jc);
  *f = 0.5 * c->f;
  PetscCall(VecGetArrayWrite(G, &g));
  for (int a = 0; a < c->na; a++) {
    g[a] = 0;
    if (!C->held[c->act[a]])
      for (PetscInt i = 0; i < C->nres; i++) g[a] += c->Jc[i * c->na + a] * c->r[i];
  }
  PetscCall(VecRestoreArrayWrite(G, &g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* holds the free parameters along flat directions of the Jacobian at the current point (singular value
   below -calibrate_flat_tol: the one with the largest component in it), at their current values;
   *left: some free parameter is not held */
static PetscErrorCode HoldFlat(CalibTao *c, PetscBool *left)
{
  HylcCalibrate C = c->C;

  PetscFunctionBegin;
  *left = PETSC_TRUE;
  for (;;) {
    int       act[HYLC_CALIBRATE_NPARAM], na = 0, worst = 0, j;
    PetscReal A[16], ev[4], V[16];

    for (int a = 0; a < c->na; a++)
      if (!C->held[c->act[a]]) act[na++] = c->act[a];
    if (!na) {
      *left = PETSC_FALSE;
      break;
    }
    ActiveJacobian(C, c->J, act, na, c->Jc);
    for (int a = 0; a < na; a++)
      for (int b = 0; b < na; b++) {
        A[a * na + b] = 0;
        for (PetscInt i = 0; i < C->nres; i++) A[a * na + b] += c->Jc[i * na + a] * c->Jc[i * na + b];
      }
    SymEig(na, A, ev, V);
    if (PetscSqrtReal(PetscMax(ev[0], 0)) >= C->flatTol) break;
    for (int a = 1; a < na; a++)
      if (PetscAbsReal(V[a * na + 0]) > PetscAbsReal(V[worst * na + 0])) worst = a;
    j          = act[worst];
    C->held[j] = PETSC_TRUE;
    for (int a = 0; a < c->na; a++) /* TAO keeps it where it is */
      if (c->act[a] == j) {
        PetscCall(VecSetValue(c->XL, a, c->xc[j], INSERT_VALUES));
        PetscCall(VecSetValue(c->XU, a, c->xc[j], INSERT_VALUES));
      }
    PetscCall(VecAssemblyBegin(c->XL));
    PetscCall(VecAssemblyEnd(c->XL));
    PetscCall(VecAssemblyBegin(c->XU));
    PetscCall(VecAssemblyEnd(c->XU));
    PetscCall(PetscPrintf(PetscObjectComm((PetscObject)C), "[calibrate] %s is not determined by the data (singular value %.2e of the Jacobian < -calibrate_flat_tol %g): held at %g\n", HylcCalibrateParamNames[j],
                          (double)PetscSqrtReal(PetscMax(ev[0], 0)), (double)C->flatTol, (double)PetscExpReal(c->xc[j])));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* TAO's convergence test, called after each iteration (and at the start) by the TAO that iterates (TAOBRGN's
   subsolver): TAO's own tests (-calibrate_tao_gatol, ..., the iteration and evaluation limits), then the
   iteration's line, hylc's tests (-calibrate_fatol, -calibrate_xtol, -calibrate_ftol) and the flat
   directions of the Jacobian at the new point, held before the next step */
static PetscErrorCode ConvergenceTest(Tao tao, void *ctx)
{
  CalibTao          *c = (CalibTao *)ctx;
  HylcCalibrate      C = c->C;
  PetscInt           it;
  Vec                X;
  PetscReal          p[HYLC_CALIBRATE_NPARAM], step = 0;
  TaoConvergedReason reason;
  const char        *why = NULL;

  PetscFunctionBegin;
  PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  PetscCall(TaoGetIterationNumber(tao, &it));
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(EvalAt(c, X)); /* the point TAO accepted: normally its last evaluation */
  PetscCall(TaoGetConvergedReason(tao, &reason));
  for (int a = 0; a < c->na; a++) step = PetscMax(step, PetscAbsReal(c->xc[c->act[a]] - c->xprev[c->act[a]]));
  if (it > 0) {
    Expand(C, c->xc, p);
    PetscCall(PrintLine(C, it, c->f, p, step, c->nfailed, c->dt));
  }
  C->its = it;
  if (reason == TAO_CONTINUE_ITERATING) {
    PetscBool left;
    if (c->f <= C->fatol)
      why = "objective below -calibrate_fatol";
    else if (it > 0 && step > 0 && step < C->xtol) /* step 0: a trust-region method's rejected step */
      why = "step below -calibrate_xtol";
    else if (it > 0 && step > 0 && c->fprev - c->f < C->ftol * c->fprev)
      why = "relative decrease below -calibrate_ftol";
    else {
      PetscCall(HoldFlat(c, &left));
      if (!left) why = "no parameter left to fit";
    }
    if (why) {
      c->reason = why;
      PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_USER));
    }
  }
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) c->xprev[j] = c->xc[j];
  c->fprev = c->f;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteYAML(HylcCalibrate C)
{
  char        tmp[PETSC_MAX_PATH_LEN + 32];
  FILE       *fp;
  time_t      now = time(NULL);
  char        stamp[64];
  const char *roles[3] = {"free", "tied to E", "fixed"};

  PetscFunctionBegin;
  if (C->rank || !C->output[0]) PetscFunctionReturn(PETSC_SUCCESS);
  strftime(stamp, sizeof(stamp), "%Y-%m-%d %H:%M UTC", gmtime(&now));
  PetscCall(HylcFileOpenTemp(C->output, tmp, sizeof(tmp), &fp));
  fprintf(fp, "# yarn parameters calibrated by hylc-calibrate %s (%s); docs/calibrate.md\n", HYLC_VERSION_STRING, stamp);
  fprintf(fp, "# pattern: %s%s\n", C->patLabel, C->refComputed ? " (its reference state computed with the initial parameters, kept fixed)" : "");
  fprintf(fp, "# target: %s (%s), %d samples\n", C->target, HylcCalibTargetTypes[C->targetResolved], (int)C->m);
  fprintf(fp, "# objective: %.6e -> %.6e in %d iterations\n", (double)C->f0, (double)C->f1, (int)C->its);
  if (C->hasGrad && C->sscale[0] > 0 && C->sscale[1] > 0)
    fprintf(fp, "# stationarity at the base strain (-calibrate_stationary %g): dPsi/dsx / S_x %+.4f -> %+.4f, dPsi/dsy / S_y %+.4f -> %+.4f (S the target's dPsi/ds at 5 %%: %.6g, %.6g N/m)\n", (double)C->wstat,
            (double)(C->rec0[HYLC_CALIB_REC_DS] / C->sscale[0]), (double)(C->rec1[HYLC_CALIB_REC_DS] / C->sscale[0]), (double)(C->rec0[HYLC_CALIB_REC_DS + 1] / C->sscale[1]), (double)(C->rec1[HYLC_CALIB_REC_DS + 1] / C->sscale[1]),
            (double)C->sscale[0], (double)C->sscale[1]);
  for (int j = 0; j < HYLC_CALIBRATE_NPARAM; j++) fprintf(fp, "# %-2s %-9s initial %.9g%s%s\n", HylcCalibrateParamNames[j], roles[C->role[j]], (double)C->p0[j], C->held[j] ? " HELD (not determined by the data)" : "", C->bound[j] ? " AT BOUND" : "");
  fprintf(fp, "# use after the pattern's options: -options_file config/<p>.yaml -options_file %s\n", C->output);
  fprintf(fp, "yarn_E:  %.9g   # bending Young's modulus (Pa)\n", (double)C->p[0]);
  fprintf(fp, "yarn_Es: %.9g   # stretching modulus (Pa)\n", (double)C->p[1]);
  fprintf(fp, "yarn_G:  %.9g   # shear modulus (Pa)\n", (double)C->p[2]);
  fprintf(fp, "yarn_kc: %.9g   # contact stiffness (N/m)\n", (double)C->p[3]);
  PetscCall(HylcFileCommitTemp(&fp, tmp, C->output));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "[calibrate] wrote %s\n", C->output));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteDump(HylcCalibrate C)
{
  char  tmp[PETSC_MAX_PATH_LEN + 32];
  FILE *fp;

  PetscFunctionBegin;
  if (C->rank || !C->dump[0]) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(HylcFileOpenTemp(C->dump, tmp, sizeof(tmp), &fp));
  fprintf(fp, "index,term,sx,sa,sy,II00,II01,II11,target,initial,calibrated,status_initial,status_calibrated\n");
  for (PetscInt i = 0; i < C->m; i++) {
    const PetscReal *z = C->z + 6 * i;
    fprintf(fp, "%d,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d\n", (int)i, HylcCalibrateTermName_Private(C->term[i]), z[0], z[1], z[2], z[3], z[4], z[5], (double)C->tpsi[i], (double)C->rec0[i * HYLC_CALIB_NRECORD],
            (double)C->rec1[i * HYLC_CALIB_NRECORD], (int)C->rec0[i * HYLC_CALIB_NRECORD + 5], (int)C->rec1[i * HYLC_CALIB_NRECORD + 5]);
  }
  PetscCall(HylcFileCommitTemp(&fp, tmp, C->dump));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "[calibrate] wrote %s\n", C->dump));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCalibrateSolve - Minimises the objective over the log values of the free parameters, within their
  bounds, with the calibration's TAO (HylcCalibrateGetTao(): TAOBRGN with Levenberg-Marquardt damping unless
  -calibrate_tao_type says otherwise; docs/calibrate.md): one solve per sample per point TAO evaluates, the
  Jacobian with it (envelope theorem). Prints a line per iteration, holds parameters along flat
  directions, flags parameters at a bound, and writes -calibrate_output and -calibrate_dump. Calls
  HylcCalibrateSetUp() first if needed.

  Collective

  Input Parameter:
. C - the calibration

  Level: beginner

.seealso: HylcCalibrateGetTao(), HylcCalibrateSetTolerances(), HylcCalibrateSetMaxIterations()
@*/
PetscErrorCode HylcCalibrateSolve(HylcCalibrate C)
{
  MPI_Comm           comm = PetscObjectComm((PetscObject)C);
  const PetscInt     NP   = HYLC_CALIBRATE_NPARAM;
  PetscInt           m;
  CalibTao           c;
  Tao                tao, inner;
  Vec                X, F;
  Mat                Jm;
  PetscBool          isbrgn;
  PetscReal          p[HYLC_CALIBRATE_NPARAM];
  PetscLogDouble     t1, ts;
  TaoConvergedReason treason;
  char               reason[128];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(C, HYLC_CALIBRATE_CLASSID, 1);
  PetscCall(HylcCalibrateSetUp(C));
  m = C->m;                                       /* known after the set-up */
  if (C->taoUsed) PetscCall(TaoDestroy(&C->tao)); /* a TAO is set up for one problem size: a fresh one */
  PetscCall(HylcCalibrateTaoSetFromOptions_Private(C));
  PetscCall(HylcCalibrateGetTao(C, &tao));
  PetscCall(PetscLogEventBegin(HYLC_CalibrateSolve, C, 0, 0, 0));
  PetscCall(PetscTime(&ts));
  PetscCall(PetscMemzero(&c, sizeof(c)));
  c.C       = C;
  C->nevals = 0;
  for (int j = 0; j < NP; j++) {
    C->held[j] = C->bound[j] = PETSC_FALSE;
    if (C->role[j] == HYLC_CALIBRATE_FREE) c.act[c.na++] = j;
  }
  PetscCall(PetscMalloc4(m * HYLC_CALIB_NRECORD, &c.rec, C->nres, &c.r, C->nres * NP, &c.J, C->nres * NP, &c.Jc));
  {
    char line[256] = "";
    for (int j = 0; j < NP; j++) {
      PetscCall(PetscStrlcat(line, j ? ", " : "", sizeof(line)));
      PetscCall(PetscStrlcat(line, HylcCalibrateParamNames[j], sizeof(line)));
      PetscCall(PetscStrlcat(line, C->role[j] == HYLC_CALIBRATE_FREE ? " free" : C->role[j] == HYLC_CALIBRATE_TIED ? " tied to E" : " fixed", sizeof(line)));
    }
    PetscCall(PetscPrintf(comm, "[calibrate] %" PetscInt_FMT " samples (target %s, %s) on %d ranks; %s; TAO %s\n", m, C->target, HylcCalibTargetTypes[C->targetResolved], (int)C->size, line, ((PetscObject)tao)->type_name));
  }
  if (C->z[0] != 0 || C->z[1] != 0 || C->z[2] != 0 || C->z[3] != 0 || C->z[4] != 0 || C->z[5] != 0)
    PetscCall(PetscPrintf(comm, "[calibrate] the target has no zero strain: base strain z_b = (%g, %g, %g, %g, %g, %g), the row nearest to it; dPsi = Psi(z) - Psi(z_b)\n", (double)C->z[0], (double)C->z[1], (double)C->z[2], (double)C->z[3],
                          (double)C->z[4], (double)C->z[5]));

  /* TAO's problem: the log values of the free parameters within the log bounds (every rank the same) */
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, c.na, &X));
  PetscCall(VecDuplicate(X, &c.XL));
  PetscCall(VecDuplicate(X, &c.XU));
  for (int a = 0; a < c.na; a++) {
    const int j = c.act[a];
    PetscCall(VecSetValue(X, a, PetscLogReal(C->p0[j]), INSERT_VALUES));
    PetscCall(VecSetValue(c.XL, a, PetscLogReal(C->lo[j]), INSERT_VALUES));
    PetscCall(VecSetValue(c.XU, a, PetscLogReal(C->hi[j]), INSERT_VALUES));
  }
  PetscCall(VecAssemblyBegin(X));
  PetscCall(VecAssemblyEnd(X));
  PetscCall(VecAssemblyBegin(c.XL));
  PetscCall(VecAssemblyEnd(c.XL));
  PetscCall(VecAssemblyBegin(c.XU));
  PetscCall(VecAssemblyEnd(c.XU));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, C->nres, &F));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, C->nres, c.na, NULL, &Jm));
  PetscCall(TaoSetSolution(tao, X));
  PetscCall(TaoSetVariableBounds(tao, c.XL, c.XU));
  PetscCall(TaoSetResidualRoutine(tao, F, FormResidual, &c));
  PetscCall(TaoSetJacobianResidualRoutine(tao, Jm, Jm, FormJacobian, &c));
  PetscCall(TaoSetObjectiveAndGradient(tao, NULL, FormObjectiveGradient, &c));
  PetscCall(PetscObjectTypeCompare((PetscObject)tao, TAOBRGN, &isbrgn));
  inner = tao;
  if (isbrgn) PetscCall(TaoBRGNGetSubsolver(tao, &inner)); /* it iterates, with its own convergence test */
  PetscCall(TaoSetConvergenceTest(inner, ConvergenceTest, &c));

  /* the initial point: its evaluation (TAO's first, from the cache) and line */
  PetscCall(EvalAt(&c, X));
  PetscCheck(c.f < PETSC_INFINITY, comm, PETSC_ERR_NOT_CONVERGED, "The base sample (strain %g %g %g %g %g %g) did not converge with the initial parameters; check -yarn_* and -micro_*", (double)C->z[0], (double)C->z[1], (double)C->z[2],
             (double)C->z[3], (double)C->z[4], (double)C->z[5]);
  PetscCall(PetscArraycpy(C->rec0, c.rec, m * HYLC_CALIB_NRECORD));
  C->f0  = c.f;
  C->its = 0;
  Expand(C, c.xc, p);
  PetscCall(PrintLine(C, 0, c.f, p, -1, c.nfailed, c.dt));
  for (int j = 0; j < NP; j++) c.xprev[j] = c.xc[j];
  c.fprev = c.f;

  C->taoUsed = PETSC_TRUE;
  PetscCall(TaoSolve(tao));
  PetscCall(TaoGetConvergedReason(tao, &treason));
  if (treason == TAO_CONVERGED_USER && c.reason)
    PetscCall(PetscStrncpy(reason, c.reason, sizeof(reason)));
  else if (treason == TAO_DIVERGED_MAXITS)
    PetscCall(PetscStrncpy(reason, "iteration limit (-calibrate_max_it)", sizeof(reason)));
  else if (treason == TAO_CONVERGED_GATOL || treason == TAO_CONVERGED_GRTOL || treason == TAO_CONVERGED_GTTOL)
    PetscCall(PetscSNPrintf(reason, sizeof(reason), "TAO's gradient test (%s; -calibrate_tao_gatol, -calibrate_tao_grtol, -calibrate_tao_gttol)", TaoConvergedReasons[treason]));
  else
    PetscCall(PetscSNPrintf(reason, sizeof(reason), "TAO %s", TaoConvergedReasons[treason]));

  /* the final point (TAO's solution; normally the last evaluation) */
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(EvalAt(&c, X));
  Expand(C, c.xc, C->p);
  for (int a = 0; a < c.na; a++) {
    const int j = c.act[a];
    if (!C->held[j]) C->bound[j] = (PetscBool)((c.xc[j] <= PetscLogReal(C->lo[j]) + 1e-9) || (c.xc[j] >= PetscLogReal(C->hi[j]) - 1e-9));
  }
  C->f1 = c.f;
  PetscCall(PetscArraycpy(C->rec1, c.rec, m * HYLC_CALIB_NRECORD));
  PetscCall(PetscTime(&t1));
  C->tsolve = t1 - ts;
  C->solved = PETSC_TRUE;
  PetscCall(PetscPrintf(comm, "[calibrate] stopped: %s (%" PetscInt_FMT " evaluations)\n", reason, C->nevals));
  for (int j = 0; j < NP; j++)
    if (C->bound[j]) PetscCall(PetscPrintf(comm, "[calibrate] warning: %s = %g ends at a bound of -calibrate_bounds_%s [%g, %g]\n", HylcCalibrateParamNames[j], (double)C->p[j], HylcCalibrateParamNames[j], (double)C->lo[j], (double)C->hi[j]));
  if (c.nfailed) {
    PetscInt shown = 0;
    PetscCall(PetscPrintf(comm, "[calibrate] %" PetscInt_FMT " samples did not converge with the final parameters and were left out:\n", c.nfailed));
    for (PetscInt i = 0; i < m && shown < 10; i++) {
      const PetscReal *o = c.rec + i * HYLC_CALIB_NRECORD, *z = C->z + 6 * i;
      if (o[5] == 0) continue;
      shown++;
      PetscCall(PetscPrintf(comm, "  sample %" PetscInt_FMT " (%s) strain %g %g %g %g %g %g: %s after %d iterations\n", i, HylcCalibrateTermName_Private(C->term[i]), (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5],
                            HylcMicroStatuses[(int)o[5]], (int)o[6]));
    }
  }
  PetscCall(WriteYAML(C));
  PetscCall(WriteDump(C));
  PetscCall(VecDestroy(&X));
  PetscCall(VecDestroy(&F));
  PetscCall(VecDestroy(&c.XL));
  PetscCall(VecDestroy(&c.XU));
  PetscCall(MatDestroy(&Jm));
  PetscCall(PetscFree4(c.rec, c.r, c.J, c.Jc));
  PetscCall(PetscLogEventEnd(HYLC_CalibrateSolve, C, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
