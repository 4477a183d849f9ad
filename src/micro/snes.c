/* HylcMicro: the SNES callbacks of the constrained, regularized Newton method (include/hylc/micro.h):
   the objective (energy), the residual M g_y, the regularized Jacobian K = M H M + alpha I, the line search
   (step limit, then backtracking to a strict decrease) and the convergence test on the projected gradient
   and the constraint residual; and the set-up of the SNES with its KSP and the KKT preconditioner. */
#include <hylc/private/microimpl.h>
#include <petsctime.h>

/* y = M y^ */
PetscErrorCode HylcMicroToY_Private(HylcMicro M, Vec X, PetscReal y[])
{
  const PetscScalar *x;

  PetscFunctionBegin;
  PetscCall(VecGetArrayRead(X, &x));
  for (PetscInt i = 0; i < M->ny; i++) y[i] = (i % 4 == 3) ? M->mu * PetscRealPart(x[i]) : PetscRealPart(x[i]);
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* energy at X: a degenerate state (zero-length or folded edge) or a non-finite energy gives +inf (a result
   of the trial step, not an error; every other failure is an error) */
PetscErrorCode HylcMicroSafeEnergy_Private(HylcMicro M, Vec X, PetscReal *E, PetscReal parts[4])
{
  PetscReal e[4] = {0, 0, 0, 0};
  PetscBool finite;

  PetscFunctionBegin;
  PetscCall(HylcMicroToY_Private(M, X, M->yw));
  PetscCall(HylcPeriodicSetState(M->P, M->yw));
  PetscCall(HylcPeriodicEvaluateFinite(M->P, HYLC_TERM_ALL, e, NULL, NULL, &finite));
  *E = finite ? e[0] + e[1] + e[2] + e[3] : PETSC_INFINITY;
  if (!PetscIsNormalReal(*E) && *E != 0) *E = PETSC_INFINITY;
  if (parts)
    for (int k = 0; k < 4; k++) parts[k] = e[k];
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormObjective(SNES snes, Vec X, PetscReal *E, void *ctx)
{
  PetscFunctionBegin;
  (void)snes;
  PetscCall(HylcMicroSafeEnergy_Private((HylcMicro)ctx, X, E, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* F = M g_y at X; also the energy and the unscaled Hessian (into K) for the Jacobian that follows */
static PetscErrorCode FormFunction(SNES snes, Vec X, Vec F, void *ctx)
{
  HylcMicro    M = (HylcMicro)ctx;
  PetscScalar *f;
  PetscBool    finite;

  PetscFunctionBegin;
  (void)snes;
  PetscCheck(!M->inject, PETSC_COMM_SELF, PETSC_ERR_LIB, "injected error (HYLC_INJECT_ERROR=%" PetscInt_FMT ")", M->injectAt);
  PetscCall(HylcMicroToY_Private(M, X, M->yw));
  PetscCall(HylcPeriodicSetState(M->P, M->yw));
  PetscCall(HylcPeriodicEvaluateFinite(M->P, HYLC_TERM_ALL, M->st.parts, M->gw, M->K, &finite));
  M->st.haveH = finite;
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < M->ny; i++) f[i] = !finite ? PETSC_INFINITY : ((i % 4 == 3) ? M->mu * M->gw[i] : M->gw[i]);
  PetscCall(VecRestoreArray(F, &f));
  M->st.E0 = !finite ? PETSC_INFINITY : M->st.parts[0] + M->st.parts[1] + M->st.parts[2] + M->st.parts[3];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* K = M H M + alpha I with alpha = alpha^_i ||M g||_inf; the constraint residual c = A y - dL */
static PetscErrorCode FormJacobian(SNES snes, Vec X, Mat J, Mat Jpre, void *ctx)
{
  HylcMicro M = (HylcMicro)ctx;
  PetscInt  it;
  PetscReal gmax = 0;

  PetscFunctionBegin;
  (void)J;
  (void)Jpre;
  PetscCall(SNESGetIterationNumber(snes, &it));
  it += M->st.itBase; /* the iteration of the whole solve (restarts after saddle escapes continue the schedule) */
  PetscCall(HylcMicroToY_Private(M, X, M->yw));
  if (!M->st.haveH) {
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicEvaluate(M->P, HYLC_TERM_ALL, M->st.parts, M->gw, M->K));
  }
  M->st.haveH = PETSC_FALSE;
  for (PetscInt i = 0; i < M->ny; i++) gmax = PetscMax(gmax, PetscAbsReal((i % 4 == 3) ? M->mu * M->gw[i] : M->gw[i]));
  M->st.gmax       = gmax;
  M->st.retriesJac = M->st.retries;
  PetscCall(HylcMicroRegularizationAlpha_Private(M, it, gmax));
  PetscCall(MatDiagonalScale(M->K, M->mvec, M->mvec));
  PetscCall(MatShift(M->K, M->st.alpha));
  PetscCall(MatSetOption(M->K, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(HylcPeriodicConstraintResidual(M->P, M->yw, M->kkt.c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the energy of an accepted iterate, appended to the history (HylcMicroGetEnergyHistory()) */
PetscErrorCode HylcMicroPushEnergy_Private(HylcMicro M, PetscReal E)
{
  PetscFunctionBegin;
  if (M->st.nhist == M->caphist) {
    PetscReal *h;
    M->caphist = M->caphist ? 2 * M->caphist : 256;
    PetscCall(PetscMalloc1(M->caphist, &h));
    PetscCall(PetscArraycpy(h, M->hist, M->st.nhist));
    PetscCall(PetscFree(M->hist));
    M->hist = h;
  }
  M->hist[M->st.nhist++] = E;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the step limit at the iterate X: the largest vertex displacement of a step, (p0 + p1 clamp(lambda_min, 0, 1)) r
   and, with -micro_step_clearance, at most that fraction of the clearance of X */
PetscErrorCode HylcMicroStepLimit_Private(HylcMicro M, Vec X, PetscReal *dmax)
{
  const HylcMacroStrain *ms;

  PetscFunctionBegin;
  PetscCall(HylcPeriodicGetMacroStrain(M->P, &ms));
  *dmax = (M->par.stepP0 + M->par.stepP1 * PetscClipInterval(ms->lambdaMin, 0, 1)) * M->r;
  if (M->par.stepClear > 0) { /* the clearance of the iterate: no two centerlines cross along the step */
    PetscReal clear;
    PetscCall(HylcMicroToY_Private(M, X, M->yw));
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicGetClearance(M->P, &clear));
    PetscCall(PetscInfo(M, "clearance %g r: step limit %g r%s\n", (double)(clear / M->r), (double)(PetscMin(*dmax, M->par.stepClear * clear) / M->r), M->par.stepClear * clear < *dmax ? " (clearance)" : ""));
    *dmax = PetscMin(*dmax, M->par.stepClear * clear);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the step limit, then backtracking until the energy strictly decreases; frames transported on acceptance */
static PetscErrorCode LineSearch(SNESLineSearch ls, void *ctx)
{
  HylcMicro          M = (HylcMicro)ctx;
  Vec                X, F, Y, W, G;
  PetscReal          dmax, d = 0, E, lambda = 1, ynorm, xnorm, fnorm;
  const PetscScalar *y;
  SNES               snes;
  PetscLogDouble     t0, t1;
  PetscBool          accepted = PETSC_FALSE, adaptive = M->st.adapting;
  PetscReal          lin = 0, quad = 0, Eold, Etrial = PETSC_INFINITY;

  PetscFunctionBegin;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogEventBegin(HYLC_MicroLineSearch, M, 0, 0, 0));
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  if (M->st.factorFailed) { /* no Newton step: the iterate stays and the solve ends */
    PetscReal knorm;
    PetscCall(MatNorm(M->K, NORM_FROBENIUS, &knorm));
    M->st.status    = PetscIsInfOrNanReal(knorm) ? HYLC_MICRO_NONFINITE : HYLC_MICRO_STALLED;
    M->st.statusSet = PETSC_TRUE;
    PetscCall(VecNorm(X, NORM_2, &xnorm));
    PetscCall(VecNorm(F, NORM_2, &fnorm));
    PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, 0));
    PetscCall(SNESLineSearchSetLambda(ls, 0));
    PetscCall(PetscLogEventEnd(HYLC_MicroLineSearch, M, 0, 0, 0));
    PetscCall(PetscTime(&t1));
    M->st.tLineSearch += t1 - t0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcMicroStepLimit_Private(M, X, &dmax));
  /* the largest vertex displacement of the linear step (ghosts are rotated copies: the same lengths) */
  PetscCall(VecGetArrayRead(Y, &y));
  for (PetscInt o = 0; o < M->ny / 4; o++) d = PetscMax(d, PetscSqrtReal(PetscSqr(PetscRealPart(y[4 * o])) + PetscSqr(PetscRealPart(y[4 * o + 1])) + PetscSqr(PetscRealPart(y[4 * o + 2]))));
  PetscCall(VecRestoreArrayRead(Y, &y));
  if (d > dmax) PetscCall(VecScale(Y, dmax / d));
  if (adaptive) { /* the model of the step -lambda Y: E0 - lambda (F.Y) + lambda^2/2 Y.(K - alpha I)Y */
    PetscScalar fy, yky, yy;
    PetscCall(VecDot(F, Y, &fy));
    PetscCall(MatMult(M->K, Y, G));
    PetscCall(VecDot(Y, G, &yky));
    PetscCall(VecDot(Y, Y, &yy));
    lin  = PetscRealPart(fy);
    quad = PetscRealPart(yky) - M->st.alpha * PetscRealPart(yy);
  }
  Eold = M->st.E0;
  for (PetscInt i = 0; i < M->par.lsMax; i++, lambda *= M->par.lsFactor) {
    PetscCall(VecWAXPY(W, -lambda, Y, X));
    PetscCall(HylcMicroSafeEnergy_Private(M, W, &E, NULL));
    if (E < M->st.E0) {
      accepted = PETSC_TRUE;
      Etrial   = E;
      break;
    }
  }
  if (accepted) {
    PetscCall(VecCopy(W, X));
    PetscCall(SNESComputeFunction(snes, X, F)); /* the state, E0, the gradient and the Hessian */
    PetscCall(HylcPeriodicUpdateFrames(M->P));
    M->st.stalls = 0;
    PetscCall(HylcMicroPushEnergy_Private(M, M->st.E0));
  } else {
    /* keep the iterate (alpha decays with the iteration count); the cached Hessian stays valid. If the
       step is a descent direction whose first-order decrease F.Y is below the rounding of the energy
       (1e3 eps |E0|), no trial can show a decrease: the iterate is converged as far as the energy can
       tell, and the convergence test ends the solve there (once the constraints hold), instead of
       stalling. That holds only for a step that is close to the Newton step: if alpha makes more than
       half of the model's curvature along Y (alpha |Y|^2 > Y.(K - alpha I)Y), the step is short because
       alpha is large (after the x 10 retries, or at the adaptive schedule's largest alpha^), not because
       the iterate is converged, and the rejection is a stall. (A direction that is not a descent
       direction, F.Y <= 0, is a stall too.) */
    PetscScalar fy;
    PetscCall(VecDot(F, Y, &fy));
    if (PetscRealPart(fy) > 0 && PetscRealPart(fy) <= 1e3 * PETSC_MACHINE_EPSILON * PetscAbsReal(M->st.E0)) {
      PetscScalar yky, yy;
      PetscCall(MatMult(M->K, Y, G));
      PetscCall(VecDot(Y, G, &yky));
      PetscCall(VecDot(Y, Y, &yy));
      if (M->st.alpha * PetscRealPart(yy) <= PetscRealPart(yky) - M->st.alpha * PetscRealPart(yy)) {
        M->st.resolved = PETSC_TRUE;
        PetscCall(PetscInfo(M, "rejected step with first-order decrease %g below the energy's rounding (E %g): converged to the energy's resolution\n", (double)PetscRealPart(fy), (double)M->st.E0));
      } else
        PetscCall(PetscInfo(M, "rejected step with first-order decrease %g below the energy's rounding (E %g), shortened by alpha (%g of the model's curvature along it): a stall\n", (double)PetscRealPart(fy), (double)M->st.E0,
                            (double)(M->st.alpha * PetscRealPart(yy) / PetscRealPart(yky))));
    }
    M->st.stalls++;
    M->st.stallsTotal++;
    PetscCall(HylcMicroToY_Private(M, X, M->yw));
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicEvaluate(M->P, HYLC_TERM_ALL, M->st.parts, M->gw, M->K));
    M->st.haveH = PETSC_TRUE;
    if (M->st.stalls >= M->par.maxStalls) {
      M->st.status    = HYLC_MICRO_STALLED;
      M->st.statusSet = PETSC_TRUE;
    }
  }
  if (adaptive) PetscCall(HylcMicroRegularizationAdapt_Private(M, accepted, (PetscBool)(d > dmax), lambda, accepted ? Eold - Etrial : 0, lambda * lin - 0.5 * lambda * lambda * quad));
  PetscCall(VecNorm(X, NORM_2, &xnorm));
  PetscCall(VecNorm(F, NORM_2, &fnorm));
  PetscCall(VecNorm(Y, NORM_2, &ynorm));
  PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, accepted ? lambda * ynorm : 0));
  PetscCall(SNESLineSearchSetLambda(ls, accepted ? lambda : 0));
  PetscCall(PetscLogEventEnd(HYLC_MicroLineSearch, M, 0, 0, 0));
  PetscCall(PetscTime(&t1));
  M->st.tLineSearch += t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* |z|^2 of the projected gradient z = g - A^T (A A^T)^-1 A g (unscaled) of the gradient g (S23-S25) */
static PetscReal ProjectedNorm2(HylcMicro M, const PetscReal g[])
{
  const PetscInt n = M->ny, m = M->m;
  PetscReal      z2 = 0;

  for (PetscInt i = 0; i < m; i++) {
    PetscReal s = 0;
    for (PetscInt k = 0; k < n; k++) s += M->kkt.A[i * n + k] * g[k];
    M->kkt.tmp[i] = s;
  }
  for (PetscInt i = 0; i < m; i++) {
    M->kkt.wl[i] = 0;
    for (PetscInt j = 0; j < m; j++) M->kkt.wl[i] += M->kkt.AAtinv[i * m + j] * M->kkt.tmp[j];
  }
  for (PetscInt k = 0; k < n; k++) {
    PetscReal zk = g[k];
    for (PetscInt i = 0; i < m; i++) zk -= M->kkt.A[i * n + k] * M->kkt.wl[i];
    z2 += zk * zk;
  }
  return z2;
}

/* |z| at the state y (the tile's state is left at y; frames untouched): the scale of the relative
   convergence test of a continued solve, taken at the cold initial guess, so that cold and continued
   solves stop at the same |z| */
PetscErrorCode HylcMicroProjectedGradientNorm_Private(HylcMicro M, const PetscReal y[], PetscReal *zn)
{
  PetscBool finite;

  PetscFunctionBegin;
  PetscCall(HylcPeriodicSetState(M->P, y));
  PetscCall(HylcPeriodicEvaluateFinite(M->P, HYLC_TERM_ALL, M->st.parts, M->gw, NULL, &finite));
  *zn = finite ? PetscSqrtReal(ProjectedNorm2(M, M->gw)) : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* S23-S25: the projected gradient z = g - A^T (A A^T)^-1 A g (unscaled) and the constraint residual. The
   relative test is against |z| at the cold initial guess, also for a continued solve (z0cold). */
static PetscErrorCode Converged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal gnorm, PetscReal f, SNESConvergedReason *reason, void *ctx)
{
  HylcMicro      M  = (HylcMicro)ctx;
  const PetscInt m  = M->m;
  PetscReal      z2 = 0, c2 = 0;
  PetscLogDouble now;
  PetscInt       maxit;
  Vec            X;

  PetscFunctionBegin;
  (void)xnorm;
  (void)gnorm;
  (void)f;
  *reason = SNES_CONVERGED_ITERATING;
  if (M->st.statusSet) { /* stalled line search */
    *reason = SNES_DIVERGED_LINE_SEARCH;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!PetscIsNormalReal(M->st.E0) && M->st.E0 != 0) {
    M->st.status    = HYLC_MICRO_NONFINITE;
    M->st.statusSet = PETSC_TRUE;
    *reason         = SNES_DIVERGED_FNORM_NAN;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  z2 = ProjectedNorm2(M, M->gw);
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(HylcMicroToY_Private(M, X, M->yw));
  PetscCall(HylcPeriodicConstraintResidual(M->P, M->yw, M->kkt.c));
  for (PetscInt i = 0; i < m; i++) c2 += M->kkt.c[i] * M->kkt.c[i];
  const PetscReal zn = PetscSqrtReal(z2), cn = PetscSqrtReal(c2);
  if (it == 0) M->st.z0 = !M->st.restart ? (M->st.continued ? M->st.z0cold : zn) : PetscMax(M->st.z0, zn); /* a restart: at least |z| after the escape (a saddle at the start has |z0| = 0) */
  M->st.lastz = M->st.z0 > 0 ? zn / M->st.z0 : 0;
  M->st.lastc = cn / M->r;
  if ((zn <= M->par.rtol * M->st.z0 || zn <= M->par.atol * M->ks) && cn < M->par.ctol * M->r) {
    *reason = SNES_CONVERGED_FNORM_RELATIVE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (M->st.resolved && cn < M->par.ctol * M->r) { /* the line search could not resolve the step's decrease */
    *reason = SNES_CONVERGED_FNORM_ABS;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscTime(&now));
  if (now - M->st.tStart > M->par.maxTime) {
    M->st.status    = HYLC_MICRO_MAX_TIME;
    M->st.statusSet = PETSC_TRUE;
    *reason         = SNES_DIVERGED_FUNCTION_COUNT; /* the wall-time budget */
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(SNESGetTolerances(snes, NULL, NULL, NULL, &maxit, NULL));
  if (it >= maxit) *reason = SNES_DIVERGED_MAX_IT;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the SNES with every default of the method, before any of its options are read (HylcMicroGetSNES()):
   Newton with the objective, residual and convergence test above, the iteration cap 2000, the shell line
   search, a KSPPREONLY whose PC is the KKT PCSHELL of kkt.c around the factorization PC; the options
   (-<prefix>micro_snes_*, -<prefix>micro_ksp_*, ...) are read by HylcMicroSetFromOptions() and override these */
PetscErrorCode HylcMicroCreateSNES_Private(HylcMicro M)
{
  KSP            ksp;
  PC             pc;
  SNESLineSearch ls;
  const char    *prefix;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)M, &prefix));
  PetscCall(SNESCreate(PETSC_COMM_SELF, &M->snes));
  PetscCall(SNESSetOptionsPrefix(M->snes, prefix));
  PetscCall(SNESAppendOptionsPrefix(M->snes, "micro_"));
  PetscCall(SNESSetType(M->snes, SNESNEWTONLS));
  PetscCall(SNESSetObjective(M->snes, FormObjective, M));
  PetscCall(SNESSetFunction(M->snes, NULL, FormFunction, M));
  PetscCall(SNESSetConvergenceTest(M->snes, Converged, M, NULL));
  PetscCall(SNESSetTolerances(M->snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2000, -1));
  PetscCall(SNESGetLineSearch(M->snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHSHELL));
  PetscCall(SNESLineSearchShellSetUserFunc(ls, LineSearch, M));
  PetscCall(SNESGetKSP(M->snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(HylcMicroSetKKT_Private(M, pc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the matrices, vectors and work arrays of the pattern, the Jacobian given to the SNES; once per pattern */
PetscErrorCode HylcMicroSetUpSNES_Private(HylcMicro M)
{
  SNES snes;
  KSP  ksp;
  PC   pc;

  PetscFunctionBegin;
  if (M->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_MicroSetUp, M, 0, 0, 0));
  PetscCall(HylcPeriodicGetSizes(M->P, &M->ny, NULL, NULL, &M->m));
  PetscCall(HylcPeriodicCreateMatrix(M->P, &M->K));
  PetscCall(MatSetBlockSize(M->K, 4)); /* 4 x 4 vertex blocks: the block size of the hylc factorization */
  PetscCall(MatCreateVecs(M->K, &M->X, NULL));
  PetscCall(VecDuplicate(M->X, &M->mvec));
  PetscCall(PetscMalloc2(M->ny, &M->yw, M->ny, &M->gw));
  PetscCall(HylcMicroResizeKKT_Private(M, M->m));
  PetscCall(HylcMicroGetSNES(M, &snes));
  PetscCall(SNESSetJacobian(snes, M->K, M->K, FormJacobian, M));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(HylcMicroSetUpKKT_Private(M, pc));
  M->setupcalled = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_MicroSetUp, M, 0, 0, 0));
  PetscCall(HylcMicroViewFromOptions(M, NULL, "-micro_view"));
  PetscFunctionReturn(PETSC_SUCCESS);
}
