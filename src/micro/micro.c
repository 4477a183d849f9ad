/* HylcMicro, the object: create/destroy, prefix, pattern, set-up, solve and results (include/hylc/micro.h).
   The parameters and options are in opts.c, the KKT preconditioner in kkt.c, the SNES callbacks in snes.c. */
#include <hylc/private/microimpl.h>
#include <hylc/chol.h>
#include <petsctime.h>

/* "failed" names the reserved value 5 (no longer produced: errors inside a solve are errors), so that the
   status_names of files and the journals of older runs keep their meaning */
const char *const HylcMicroStatuses[] = {"converged", "iteration_cap", "time_cap", "stalled", "nonfinite", "failed", "HylcMicroStatus", "HYLC_MICRO_", NULL};

/* fault injection for tests (docs/method.md): HYLC_INJECT_ERROR=N makes the N-th HylcMicroSolve() of the
   process raise PETSC_ERR_LIB from inside the SNES function evaluation */
static PetscInt injectAt = -1, solveCount = 0; /* injectAt: -1 unread, 0 off */

PetscClassId  HYLC_MICRO_CLASSID;
PetscLogEvent HYLC_MicroSetUp, HYLC_MicroSolve, HYLC_MicroFactor, HYLC_MicroSaddle, HYLC_MicroLineSearch;

static PetscBool HylcMicroPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcMicroFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcMicroPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroInitializePackage - Registers the class id HylcMicro and its log events (MICRO_SetUp, MICRO_Solve, MICRO_Factor, MICRO_Saddle, MICRO_LineSearch). Called by
  HylcMicroCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcMicroInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcMicroPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcMicroPackageInitialized = PETSC_TRUE;
  PetscCall(HylcSysInitializePackage()); /* the default ordering of the factorization, metisnd */
  PetscCall(PetscClassIdRegister("HylcMicro", &HYLC_MICRO_CLASSID));
  PetscCall(PetscLogEventRegister("MICRO_SetUp", HYLC_MICRO_CLASSID, &HYLC_MicroSetUp));
  PetscCall(PetscLogEventRegister("MICRO_Solve", HYLC_MICRO_CLASSID, &HYLC_MicroSolve));
  PetscCall(PetscLogEventRegister("MICRO_Factor", HYLC_MICRO_CLASSID, &HYLC_MicroFactor));
  PetscCall(PetscLogEventRegister("MICRO_Saddle", HYLC_MICRO_CLASSID, &HYLC_MicroSaddle));
  PetscCall(PetscLogEventRegister("MICRO_LineSearch", HYLC_MICRO_CLASSID, &HYLC_MicroLineSearch));
  PetscCall(PetscRegisterFinalize(HylcMicroFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void ParamsDefault(HylcMicroParams *p)
{
  p->alphaStart    = 5000;
  p->alphaEnd      = 5;
  p->alphaIts      = 400;
  p->maxRetries    = 12;
  p->alphaSched    = HYLC_MICRO_ALPHA_ADAPTIVE;
  p->alphaFact     = 4;
  p->alphaMin      = 1e-2;
  p->alphaMax      = 1e10;
  p->alphaSwitch   = 1e-2;
  p->alphaFallback = PETSC_TRUE;
  p->twistScale    = 0;
  p->stepP0        = 0.05;
  p->stepP1        = 0.15;
  p->lsFactor      = 0.1;
  p->lsMax         = 11;
  p->maxStalls     = 5;
  p->rtol          = 1e-5;
  p->atol          = 1e-10;
  p->ctol          = 1e-4;
  p->maxTime       = 60;
  p->indefinite    = PETSC_TRUE;
  p->saddleTest    = PETSC_TRUE;
  p->saddleMax     = 5;
  p->saddleTol     = 1e-6;
  p->uniGrad       = HYLC_MICRO_UNIAXIAL_ENVELOPE;
  p->uniXtol       = 1e-5;
  p->uniMaxIt      = 30;
  p->uniH          = 1e-4;
  p->uniMaxStep    = 0.05;
  p->uniRtol       = 1e-8;
  p->uniGtol       = 1e-4;
}

/*@C
  HylcMicroCreate - Creates a microscale solver with the default parameters and no options prefix (its
  options are -micro_*). Its sub-objects, the periodic tile (HylcMicroGetPeriodic()), the SNES (HylcMicroGetSNES())
  and the factorization PC (HylcMicroGetFactorPC()), are created on first use. Not collective (each rank
  solves its samples alone; use PETSC_COMM_SELF).

  Input Parameter:
. comm - the communicator (PETSC_COMM_SELF)

  Output Parameter:
. micro - the solver

  Level: beginner

.seealso: HylcMicroSetPattern(), HylcMicroSetFromOptions(), HylcMicroSetUp(), HylcMicroSolve(), HylcMicroDestroy()
@*/
PetscErrorCode HylcMicroCreate(MPI_Comm comm, HylcMicro *micro)
{
  HylcMicro M;

  PetscFunctionBegin;
  PetscValidPointer(micro, 2);
  PetscCall(HylcMicroInitializePackage());
  PetscCall(PetscHeaderCreate(M, HYLC_MICRO_CLASSID, "HylcMicro", "Microscale Newton solver", "Micro", comm, HylcMicroDestroy, HylcMicroView));
  ParamsDefault(&M->par);
  PetscCall(PetscObjectChangeTypeName((PetscObject)M, "regularized_newton"));
  *micro = M;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the solver built for one pattern (the SNES and the inner factorization PC stay, reset) */
static PetscErrorCode FreeSolver(HylcMicro M)
{
  PetscFunctionBegin;
  if (M->setupcalled) PetscCall(SNESReset(M->snes));
  M->setupcalled = PETSC_FALSE;
  PetscCall(MatDestroy(&M->K));
  PetscCall(VecDestroy(&M->X));
  PetscCall(VecDestroy(&M->mvec));
  PetscCall(PetscFree2(M->yw, M->gw));
  PetscCall(PetscFree(M->uinit));
  M->nuinit   = 0;
  M->haveInit = PETSC_FALSE;
  if (M->kkt.inner) PetscCall(PCReset(M->kkt.inner));
  PetscCall(HylcMicroDestroyKKT_Private(M));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroDestroy - Destroys a microscale solver. Not collective.

  Input Parameter:
. micro - the solver (may be NULL); set to NULL

  Level: beginner

.seealso: HylcMicroCreate()
@*/
PetscErrorCode HylcMicroDestroy(HylcMicro *micro)
{
  PetscFunctionBegin;
  if (!*micro) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*micro, HYLC_MICRO_CLASSID, 1);
  if (--((PetscObject)(*micro))->refct > 0) {
    *micro = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(FreeSolver(*micro));
  PetscCall(SNESDestroy(&(*micro)->snes));
  PetscCall(PCDestroy(&(*micro)->kkt.inner));
  PetscCall(HylcPeriodicDestroy(&(*micro)->P));
  PetscCall(HylcPatternDestroy(&(*micro)->pat));
  PetscCall(PetscFree((*micro)->hist));
  PetscCall(PetscHeaderDestroy(micro));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetOptionsPrefix - Sets the prefix of the solver's options (default none: -micro_*, as every
  stage spells its keys with its module name) and of its sub-objects: the periodic tile (-<prefix>periodic_*,
  -<prefix>macro_*), the SNES (-<prefix>micro_snes_*, -<prefix>micro_ksp_*) and the factorization PC
  (-<prefix>micro_factor_pc_*). Not collective.

  Input Parameters:
+ M      - the solver
- prefix - the prefix (without the leading dash; NULL: none)

  Level: intermediate

.seealso: HylcMicroSetFromOptions(), HylcMicroGetFactorPC()
@*/
PetscErrorCode HylcMicroSetOptionsPrefix(HylcMicro M, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)M, prefix));
  if (M->snes) {
    PetscCall(SNESSetOptionsPrefix(M->snes, prefix));
    PetscCall(SNESAppendOptionsPrefix(M->snes, "micro_"));
  }
  if (M->kkt.inner) {
    PetscCall(PCSetOptionsPrefix(M->kkt.inner, prefix));
    PetscCall(PCAppendOptionsPrefix(M->kkt.inner, "micro_factor_"));
  }
  if (M->P) PetscCall(HylcPeriodicSetOptionsPrefix(M->P, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetFactorPC - Gets the PCCHOLESKY that factors the Newton matrix K inside the KKT
  preconditioner, creating it on first use (solver type hylc, ordering metisnd, options prefix
  "<prefix>micro_factor_", e.g. -micro_factor_pc_factor_mat_solver_type). Not collective.

  Input Parameter:
. M - the solver

  Output Parameter:
. pc - the factorization (owned by M)

  Level: advanced

.seealso: HylcMicroSetUp(), MATSOLVERHYLC
@*/
PetscErrorCode HylcMicroGetFactorPC(HylcMicro M, PC *pc)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidPointer(pc, 2);
  if (!M->kkt.inner) {
    PetscCall(HylcCholRegisterSolverType()); /* the default solver type, linalg's */
    PetscCall(PCCreate(PETSC_COMM_SELF, &M->kkt.inner));
    PetscCall(PetscObjectIncrementTabLevel((PetscObject)M->kkt.inner, (PetscObject)M, 1));
    PetscCall(PCSetType(M->kkt.inner, PCCHOLESKY));
    PetscCall(PCFactorSetMatOrderingType(M->kkt.inner, HylcDefaultOrdering()));
    PetscCall(PCFactorSetMatSolverType(M->kkt.inner, MATSOLVERHYLC));
    PetscCall(PCSetOptionsPrefix(M->kkt.inner, ((PetscObject)M)->prefix));
    PetscCall(PCAppendOptionsPrefix(M->kkt.inner, "micro_factor_"));
  }
  *pc = M->kkt.inner;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetSNES - Gets the SNES of the Newton method, creating it on first use with the method's
  defaults: type newtonls, the energy as objective, the residual M g_y, the projected-gradient convergence
  test, at most 2000 iterations, the shell line search (step limit and backtracking), a KSPPREONLY whose PC
  is the KKT PCSHELL around the factorization PC (HylcMicroGetFactorPC()). Its options prefix is the
  solver's followed by micro_ (-micro_snes_*, -micro_ksp_*); HylcMicroSetFromOptions() calls SNESSetFromOptions() on it, so
  options override these defaults. The Jacobian and the vectors are given at HylcMicroSetUp(); a new
  pattern resets it (SNESReset()). Not collective.

  Input Parameter:
. M - the solver

  Output Parameter:
. snes - the SNES (owned by M)

  Notes:
  Replacing the objective, function, convergence test, line search or preconditioner breaks the method;
  tolerances, monitors and viewers are the SNES's to change.

  Level: advanced

.seealso: HylcMicroSetFromOptions(), HylcMicroGetFactorPC(), HylcMicroSetUp()
@*/
PetscErrorCode HylcMicroGetSNES(HylcMicro M, SNES *snes)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidPointer(snes, 2);
  if (!M->snes) PetscCall(HylcMicroCreateSNES_Private(M));
  *snes = M->snes;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetPattern - Sets the tile to solve: a pattern and the yarn model, given to the solver's
  periodic tile (HylcMicroGetPeriodic(), created on first use and kept with its options); the Newton
  solver's matrices are rebuilt at the next set-up. Not collective.

  Input Parameters:
+ M     - the solver
. pat   - the pattern (referenced)
- model - the yarn model (copied)

  Level: beginner

.seealso: HylcMicroGetPeriodic(), HylcMicroSetUp()
@*/
PetscErrorCode HylcMicroSetPattern(HylcMicro M, HylcPattern pat, const HylcYarnModel *model)
{
  HylcPeriodic P;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidHeaderSpecific(pat, HYLC_PATTERN_CLASSID, 2);
  PetscValidPointer(model, 3);
  PetscCall(PetscObjectReference((PetscObject)pat));
  PetscCall(HylcPatternDestroy(&M->pat));
  PetscCall(FreeSolver(M));
  M->pat   = pat;
  M->model = *model;
  PetscCall(HylcMicroGetPeriodic(M, &P));
  PetscCall(HylcPeriodicSetPattern(P, pat, model));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetUp - Builds the Newton matrix, the vectors and the KKT buffers of the pattern and gives them
  to the SNES (HylcMicroGetSNES()) ahead of the first solve; the tile is set up at zero strain. Reads no
  options (HylcMicroSetFromOptions() does). Views the solver with -micro_view. Not collective.

  Input Parameter:
. M - the solver, with a pattern (HylcMicroSetPattern())

  Level: beginner

.seealso: HylcMicroSetFromOptions(), HylcMicroSolve()
@*/
PetscErrorCode HylcMicroSetUp(HylcMicro M)
{
  const PetscReal z[6] = {0, 0, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(M->pat, PetscObjectComm((PetscObject)M), PETSC_ERR_ARG_WRONGSTATE, "Call HylcMicroSetPattern() first");
  if (M->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(HylcPeriodicSetStrain(M->P, z));
  PetscCall(HylcPeriodicSetUp(M->P));
  PetscCall(HylcMicroSetUpSNES_Private(M));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the state of one solve at its start: nothing counted, no energy yet, converged until the method says
   otherwise (the one place the per-solve state is reset; include/hylc/private/microimpl.h) */
PetscErrorCode HylcMicroResetSolveState_Private(HylcMicro M)
{
  PetscFunctionBegin;
  PetscCall(PetscMemzero(&M->st, sizeof(M->st)));
  M->st.status = HYLC_MICRO_CONVERGED;
  M->st.E0     = PETSC_INFINITY;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* one solve of HylcMicroSolve() with the current parameters: from the cold guess, or from the state of
   HylcMicroSetInitialState() if one is pending */
static PetscErrorCode SolveOnce(HylcMicro M, const PetscReal z[6], HylcMicroResult *res)
{
  PetscLogDouble      t1, tEval, tContact, tAssemble;
  PetscScalar        *x;
  SNESConvergedReason reason;
  PetscInt            its;
  HylcYarnConstants   c;
  PetscReal           area;
  PetscInt            m;

  PetscFunctionBegin;
  PetscCall(PetscMemzero(res, sizeof(*res)));
  for (int k = 0; k < 6; k++) res->z[k] = z[k];
  PetscCall(HylcMicroResetSolveState_Private(M));
  PetscCall(PetscTime(&M->st.tStart));
  PetscCall(HylcPeriodicSetStrain(M->P, z));
  PetscCall(HylcPeriodicSetUp(M->P));
  PetscCall(HylcPeriodicGetConstants(M->P, &c));
  PetscCall(HylcPeriodicGetConstraints(M->P, &m, &M->kkt.A, &M->kkt.dL, &M->kkt.AAtinv));
  if (M->setupcalled && m != M->m) PetscCall(HylcMicroResizeKKT_Private(M, m)); /* the number of independent constraint rows may depend on the strain */
  M->r  = c.r;
  M->ks = c.ks;
  M->mu = M->par.twistScale > 0 ? M->par.twistScale : 1.0 / c.r;
  PetscCall(HylcMicroSetUpSNES_Private(M));
  {
    PetscScalar *mv;
    PetscCall(VecGetArray(M->mvec, &mv));
    for (PetscInt i = 0; i < M->ny; i++) mv[i] = (i % 4 == 3) ? M->mu : 1.0;
    PetscCall(VecRestoreArray(M->mvec, &mv));
  }
  /* initial guess: y^ = M^-1 y0, or, continued, y0 + u~ of the state given by HylcMicroSetInitialState() with
     the reference frames transported from the rest frames of this strain to it */
  PetscCall(HylcPeriodicGetInitialState(M->P, M->yw));
  if (M->haveInit) {
    M->haveInit = PETSC_FALSE;
    PetscCheck(M->nuinit == M->ny, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "HylcMicroSetInitialState: the state has %" PetscInt_FMT " unknowns, the tile %" PetscInt_FMT, M->nuinit, M->ny);
    PetscCall(HylcMicroProjectedGradientNorm_Private(M, M->yw, &M->st.z0cold)); /* the cold start's |z0| */
    PetscCall(HylcPeriodicFluctuationFromLocal(M->P, M->uinit, M->yw));
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicUpdateFrames(M->P));
    M->st.continued = PETSC_TRUE;
  }
  PetscCall(VecGetArray(M->X, &x));
  for (PetscInt i = 0; i < M->ny; i++) x[i] = (i % 4 == 3) ? M->yw[i] / M->mu : M->yw[i];
  PetscCall(VecRestoreArray(M->X, &x));
  /* an error inside the solve (a bug, no memory, a bad option) is an error: only the outcomes of the
     method are statuses (a failed factorization and a degenerate trial state are outcomes, handled above) */
  PetscCall(SNESSolve(M->snes, NULL, M->X));
  PetscCall(SNESGetConvergedReason(M->snes, &reason));
  PetscCall(SNESGetIterationNumber(M->snes, &its));
  /* the second-order test of a converged state; a saddle point is left along negative curvature and the
     Newton iteration resumes, up to saddleMax times (saddle.c) */
  res->negcurv = -1;
  while (reason > 0 && M->par.saddleTest) {
    PetscInt  neg;
    PetscBool escaped;
    PetscCall(HylcMicroSaddle_Private(M, (PetscBool)(M->st.escapes < M->par.saddleMax), &neg, &escaped));
    res->negcurv = neg;
    if (!escaped) break;
    M->st.escapes++;
    M->st.itBase += its;
    M->st.restart  = PETSC_TRUE;
    M->st.stalls   = 0;
    M->st.resolved = PETSC_FALSE;
    PetscCall(SNESSolve(M->snes, NULL, M->X));
    PetscCall(SNESGetConvergedReason(M->snes, &reason));
    PetscCall(SNESGetIterationNumber(M->snes, &its));
  }
  if (reason <= 0) res->negcurv = -1; /* not converged after an escape: not tested */
  its += M->st.itBase;
  M->st.restart = PETSC_FALSE;
  res->escapes  = M->st.escapes;
  if (reason > 0)
    res->status = HYLC_MICRO_CONVERGED;
  else if (M->st.statusSet)
    res->status = M->st.status;
  else if (reason == SNES_DIVERGED_MAX_IT)
    res->status = HYLC_MICRO_MAX_IT;
  else if (reason == SNES_DIVERGED_FNORM_NAN || reason == SNES_DIVERGED_FUNCTION_DOMAIN)
    res->status = HYLC_MICRO_NONFINITE;
  else
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_PLIB, "The Newton solve ended with the unexpected SNES reason %s", SNESConvergedReasons[reason]);
  /* the final state and its energy */
  PetscCall(HylcMicroSafeEnergy_Private(M, M->X, &res->energy, res->parts));
  if (!PetscIsNormalReal(res->energy) && res->energy != 0) res->status = HYLC_MICRO_NONFINITE;
  PetscCall(HylcPeriodicGetArea(M->P, &area));
  res->psi        = res->energy / area;
  res->iterations = its;
  res->retries    = M->st.retries;
  res->stalls     = M->st.stallsTotal;
  res->residual   = M->st.lastz;
  res->cresidual  = M->st.lastc;
  PetscCall(PetscTime(&t1));
  res->time = t1 - M->st.tStart;
  PetscCall(HylcPeriodicGetTimes(M->P, &tEval, &tContact, &tAssemble));
  res->tAssembly   = tEval - tContact;
  res->tContact    = tContact;
  res->tFactor     = M->st.tFactor;
  res->tLineSearch = M->st.tLineSearch;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSolve - Solves for the equilibrium of the tile under the strain z (Algorithms C2, C3) from the
  initial guess u~ = 0 (or from the state of HylcMicroSetInitialState(), once), setting the solver up first if needed. Not collective (PETSC_COMM_SELF).

  Input Parameters:
+ M - the solver, with a pattern
- z - the strain (sx, sa, sy, II00, II01, II11; II in 1/m)

  Output Parameter:
. res - the result: psi, energies, status, iterations, residuals and times

  Notes:
  The result's status says whether it converged; a non-converged sample is not an error. With the adaptive
  or hybrid schedule, a solve that does not converge is repeated from the same start with the paper's
  schedule (HylcMicroSetRegularizationFallback(); res->fallback says so). An error inside
  the solve (a bug, no memory, a bad option) is an error of this function.

  Level: beginner

.seealso: HylcMicroSetUp(), HylcMicroGetState(), HylcMicroResultView()
@*/
PetscErrorCode HylcMicroSolve(HylcMicro M, const PetscReal z[6], HylcMicroResult *res)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(M->pat, PetscObjectComm((PetscObject)M), PETSC_ERR_ARG_WRONGSTATE, "Call HylcMicroSetPattern() first");
  if (injectAt < 0) { /* read once per process */
    const char *env = getenv("HYLC_INJECT_ERROR");
    char       *end = NULL;
    long        n   = env ? strtol(env, &end, 10) : 0;
    PetscCheck(!env || (end != env && !*end && n >= 0 && n < PETSC_MAX_INT), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "HYLC_INJECT_ERROR=%s: expected a non-negative integer (the 1-based number of the solve that raises an injected error)", env);
    injectAt = (PetscInt)n;
  }
  M->inject   = (PetscBool)(injectAt > 0 && ++solveCount == injectAt);
  M->injectAt = injectAt;
  PetscCall(PetscLogEventBegin(HYLC_MicroSolve, M, 0, 0, 0));
  PetscCall(SolveOnce(M, z, res));
  if (HylcMicroRegularizationFallback_Private(M, res->status)) {
    /* the adaptive or hybrid schedule failed: the same start with the paper schedule (its steps are shorter
       while the gradient is large), the sums of both solves' counts and times reported */
    const HylcMicroResult first = *res;
    const PetscInt        sched = M->par.alphaSched;
    PetscErrorCode        ierr;
    PetscCall(PetscInfo(M, "the %s schedule ended %s after %" PetscInt_FMT " iterations: solved again from the same start with the paper schedule\n", HylcMicroAlphaSchedules[sched], HylcMicroStatuses[first.status], first.iterations));
    M->haveInit       = M->st.continued; /* the state of HylcMicroSetInitialState() is kept in uinit */
    M->par.alphaSched = HYLC_MICRO_ALPHA_PAPER;
    ierr              = SolveOnce(M, z, res);
    M->par.alphaSched = sched;
    PetscCall(ierr);
    res->fallback = PETSC_TRUE;
    res->iterations += first.iterations;
    res->retries += first.retries;
    res->stalls += first.stalls;
    res->time += first.time;
    res->tAssembly += first.tAssembly;
    res->tContact += first.tContact;
    res->tFactor += first.tFactor;
    res->tLineSearch += first.tLineSearch;
  }
  PetscCall(PetscLogEventEnd(HYLC_MicroSolve, M, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetPeriodic - Gets the periodic tile of the solver, creating it on first use with the solver's
  prefix (options -<prefix>periodic_*, -<prefix>macro_*, read by HylcMicroSetFromOptions()); HylcMicroSetPattern() gives it the pattern.
  Not collective.

  Input Parameter:
. M - the solver

  Output Parameter:
. P - the tile (owned by M)

  Level: intermediate

.seealso: HylcMicroSetPattern(), HylcMicroGetSNES()
@*/
PetscErrorCode HylcMicroGetPeriodic(HylcMicro M, HylcPeriodic *P)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidPointer(P, 2);
  if (!M->P) {
    PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &M->P));
    PetscCall(HylcPeriodicSetOptionsPrefix(M->P, ((PetscObject)M)->prefix));
  }
  *P = M->P;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetState - Gets the unscaled unknowns y of the last solve. Not collective.

  Input Parameter:
. M - the solver, after HylcMicroSolve()

  Output Parameter:
. y - the unknowns (an array of the tile's size, HylcPeriodicGetSizes())

  Level: intermediate

.seealso: HylcMicroSolve()
@*/
PetscErrorCode HylcMicroGetState(HylcMicro M, PetscReal y[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(M->X, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "HylcMicroGetState: no solve yet");
  PetscCall(HylcMicroToY_Private(M, M->X, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetInitialState - Makes the next HylcMicroSolve() (only the next one) start from a given state
  instead of u~ = 0 (continuation along a path of strains). Not collective.

  Input Parameters:
+ M - the solver, after a HylcMicroSolve() (its tile is set up at the strain of that solve)
- y - a state of the tile at the strain of the last solve, e.g. from HylcMicroGetState(); NULL cancels

  Notes:
  What is carried over is the fluctuation u~ = y - y0(z_last), positions and twists (y0: the initial guess
  of HylcPeriodicGetInitialState() at the last solve's strain, taken now), in the local coordinates of the
  macroscopic deformation (HylcPeriodicFluctuationToLocal(): per vertex, R(xi)^T u~ with its in-plane part
  mapped by A^-1): the next solve, at strain z, starts from y0(z) + R_z(xi) [A_z (A^-1 w_xy); w_z]. In the
  plane this deforms the whole last state by A_z A^-1, so yarn pieces in contact stay in contact; adding
  u~ as it is would move them apart or through each other by (A_z - A) times their rest distance. The
  reference frames are not
  carried: the tile's frames are rebuilt at z from the rest frames by one parallel transport to the
  starting state (HylcPeriodicUpdateFrames()). The frames of the last solve cannot be reused as they are,
  because the set of full edges (ghosts, contact copies) is rebuilt for each strain. The reference frame is
  a gauge: the twists are kept, so the starting material frames differ from the predecessor's by the
  holonomy between the two transport paths (small for nearby states); the Newton method corrects that like
  any other part of the initial guess, and the equilibrium reached does not depend on the gauge.

  Level: intermediate

.seealso: HylcMicroSolve(), HylcMicroGetState(), HylcMicroGetContinued()
@*/
PetscErrorCode HylcMicroSetInitialState(HylcMicro M, const PetscReal y[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (!y) {
    M->haveInit = PETSC_FALSE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(M->X && M->P && M->setupcalled, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "HylcMicroSetInitialState: no solve yet (the state must be one of the tile at the strain of the last solve)");
  if (M->nuinit != M->ny) {
    PetscCall(PetscFree(M->uinit));
    PetscCall(PetscMalloc1(M->ny, &M->uinit));
    M->nuinit = M->ny;
  }
  for (PetscInt i = 0; i < M->ny; i++) PetscCheck(!PetscIsInfOrNanReal(y[i]), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "HylcMicroSetInitialState: unknown %" PetscInt_FMT " of the state is not finite (%g)", i, (double)y[i]);
  PetscCall(HylcPeriodicFluctuationToLocal(M->P, y, M->uinit));
  M->haveInit = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetFluctuation - The local coordinates of the fluctuation of a state of the tile at the strain of
  the last solve (HylcPeriodicFluctuationToLocal()): what HylcMicroSetInitialState() carries over. Taken
  right after a solve, it can be given to HylcMicroSetInitialFluctuation() later, after solves at other
  strains (the sampler's -sampler_start both solves each sample cold before it continues from its
  predecessor). Not collective.

  Input Parameters:
+ M - the solver, after a HylcMicroSolve() (its tile is set up at the strain of that solve)
- y - a state of the tile at that strain (HylcMicroGetState())

  Output Parameter:
. u - the local fluctuation (the tile's size, HylcPeriodicGetSizes(); may not be y)

  Level: advanced

.seealso: HylcMicroSetInitialFluctuation(), HylcMicroSetInitialState()
@*/
PetscErrorCode HylcMicroGetFluctuation(HylcMicro M, const PetscReal y[], PetscReal u[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(M->X && M->P && M->setupcalled, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "HylcMicroGetFluctuation: no solve yet (the state must be one of the tile at the strain of the last solve)");
  PetscCall(HylcPeriodicFluctuationToLocal(M->P, y, u));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetInitialFluctuation - Makes the next HylcMicroSolve() (only the next one) start from y0(z) plus
  a fluctuation in local coordinates (HylcMicroGetFluctuation()); HylcMicroSetInitialState(M, y) is this
  with the fluctuation of y at the strain of the last solve. Not collective.

  Input Parameters:
+ M - the solver, after a HylcMicroSolve() (for the tile's size)
- u - the local fluctuation, finite; NULL cancels

  Level: advanced

.seealso: HylcMicroGetFluctuation(), HylcMicroSetInitialState()
@*/
PetscErrorCode HylcMicroSetInitialFluctuation(HylcMicro M, const PetscReal u[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (!u) {
    M->haveInit = PETSC_FALSE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCheck(M->X && M->P && M->setupcalled, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "HylcMicroSetInitialFluctuation: no solve yet (the tile's size is not known)");
  if (M->nuinit != M->ny) {
    PetscCall(PetscFree(M->uinit));
    PetscCall(PetscMalloc1(M->ny, &M->uinit));
    M->nuinit = M->ny;
  }
  for (PetscInt i = 0; i < M->ny; i++) PetscCheck(!PetscIsInfOrNanReal(u[i]), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "HylcMicroSetInitialFluctuation: unknown %" PetscInt_FMT " of the fluctuation is not finite (%g)", i, (double)u[i]);
  PetscCall(PetscArraycpy(M->uinit, u, M->ny));
  M->haveInit = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the order of outcomes: converged, then not converged, then non-finite */
static int OutcomeRank(const HylcMicroResult *r) { return r->status == HYLC_MICRO_CONVERGED ? 0 : r->status == HYLC_MICRO_NONFINITE ? 2 : 1; }

/*@C
  HylcMicroSolveContinued - One step of a continuation: solves at z from the fluctuation u of an earlier
  equilibrium (HylcMicroGetFluctuation()), and, if that does not converge, again cold (u~ = 0); the better of
  the two is kept (converged, then not converged, then non-finite; the cold one on a tie). With u NULL it is
  HylcMicroSolve() from u~ = 0. Not collective.

  Input Parameters:
+ M - the solver, after a first HylcMicroSolve() if u is given
. z - the strain
- u - the local fluctuation to start from, or NULL

  Output Parameters:
+ res     - the kept result; its iterations and time are the sums of both solves when it was retried
. y       - the kept result's state (the tile's size; may be NULL)
- retried - whether the continued solve was retried cold (may be NULL)

  Level: intermediate

.seealso: HylcMicroSolve(), HylcMicroGetFluctuation(), HylcMicroSetInitialFluctuation()
@*/
PetscErrorCode HylcMicroSolveContinued(HylcMicro M, const PetscReal z[6], const PetscReal u[], HylcMicroResult *res, PetscReal y[], PetscBool *retried)
{
  HylcMicroResult rc;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (retried) *retried = PETSC_FALSE;
  if (u) PetscCall(HylcMicroSetInitialFluctuation(M, u));
  PetscCall(HylcMicroSolve(M, z, res));
  if (y) PetscCall(HylcMicroGetState(M, y));
  if (!u || res->status == HYLC_MICRO_CONVERGED) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(HylcMicroSolve(M, z, &rc));
  if (retried) *retried = PETSC_TRUE;
  rc.iterations += res->iterations;
  rc.time += res->time;
  if (OutcomeRank(&rc) <= OutcomeRank(res)) {
    *res = rc;
    if (y) PetscCall(HylcMicroGetState(M, y));
  } else {
    res->iterations = rc.iterations;
    res->time       = rc.time;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetContinued - Whether the last solve started from a state given by HylcMicroSetInitialState().
  Not collective.

  Input Parameter:
. M - the solver

  Output Parameter:
. continued - PETSC_TRUE if it did, PETSC_FALSE if it started from u~ = 0

  Level: intermediate

.seealso: HylcMicroSetInitialState()
@*/
PetscErrorCode HylcMicroGetContinued(HylcMicro M, PetscBool *continued)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidBoolPointer(continued, 2);
  *continued = M->st.continued;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetEnergyHistory - Gets the energies of the accepted iterates of the last solve. Not collective.

  Input Parameter:
. M - the solver

  Output Parameters:
+ n - the number of accepted iterates
- E - their energies (J; owned by M, valid until the next solve)

  Level: developer

.seealso: HylcMicroSolve()
@*/
PetscErrorCode HylcMicroGetEnergyHistory(HylcMicro M, PetscInt *n, const PetscReal **E)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  *n = M->st.nhist;
  *E = M->hist;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroResultView - Prints a result: strain, psi, energy parts, status, iterations, residuals, times.
  Not collective.

  Input Parameters:
+ r      - the result of HylcMicroSolve()
- viewer - an ASCII viewer

  Level: beginner

.seealso: HylcMicroSolve(), HylcMicroView()
@*/
PetscErrorCode HylcMicroResultView(const HylcMicroResult *r, PetscViewer viewer)
{
  char buf[512];

  PetscFunctionBegin;
  /* C formatting: PETSc's printf appends '.' to integral %g values */
  snprintf(buf, sizeof(buf), "strain: %.9g %.9g %.9g %.9g %.9g %.9g\npsi: %.10e\nenergy_parts: %.10e %.10e %.10e %.10e\n", (double)r->z[0], (double)r->z[1], (double)r->z[2], (double)r->z[3], (double)r->z[4], (double)r->z[5], (double)r->psi,
           (double)r->parts[0], (double)r->parts[1], (double)r->parts[2], (double)r->parts[3]);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscCall(PetscViewerASCIIPrintf(viewer, "status: %s\n", HylcMicroStatuses[r->status]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "iterations: %" PetscInt_FMT "\n", r->iterations));
  if (r->fallback) PetscCall(PetscViewerASCIIPrintf(viewer, "fallback: the adaptive or hybrid schedule did not converge; solved again from the same start with the paper schedule (iterations, retries, stalls and times are the sums of both)\n"));
  if (r->negcurv >= 0)
    PetscCall(PetscViewerASCIIPrintf(viewer, "second-order test: %" PetscInt_FMT " negative eigenvalues on the tangent space at the end (%s), %" PetscInt_FMT " saddle escapes\n", r->negcurv, r->negcurv ? "a saddle point" : "a minimum", r->escapes));
  snprintf(buf, sizeof(buf), "residual: %.3e (projected gradient, relative), constraints %.3e r\nregularization retries: %d, stalled line searches: %d\ntime: %.4f s (assembly %.4f, contact %.4f, factorization %.4f, line search %.4f)\n",
           (double)r->residual, (double)r->cresidual, (int)r->retries, (int)r->stalls, r->time, r->tAssembly, r->tContact, r->tFactor, r->tLineSearch);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}
