/* HylcMicro: constrained, regularized Newton on SNES (see include/hylc/micro.h). */
#include <hylc/micro.h>
#include <hylc/geom.h>
#include <hylc/chol.h>
#include <petsctime.h>

/* "failed" names the reserved value 5 (no longer produced: errors inside a solve are errors), so that the
   status_names of files and the journals of older runs keep their meaning */
const char *const HylcMicroStatuses[] = {"converged", "iteration_cap", "time_cap", "stalled", "nonfinite", "failed", "HylcMicroStatus", "HYLC_MICRO_", NULL};

/* fault injection for tests (docs/method.md): HYLC_INJECT_ERROR=N makes the N-th HylcMicroSolve() of the
   process raise PETSC_ERR_LIB from inside the SNES function evaluation */
static PetscInt injectAt = -1, solveCount = 0; /* injectAt: -1 unread, 0 off */

typedef struct {
  /* parameters */
  PetscReal alphaStart, alphaEnd; /* alpha^ schedule: alphaStart (alphaEnd/alphaStart)^(min(i, alphaIts)/alphaIts) */
  PetscInt  alphaIts, maxRetries;
  PetscReal twistScale;     /* mu; <= 0: 1/r */
  PetscReal stepP0, stepP1; /* d_max = (p0 + p1 clamp(lambda_min(I), 0, 1)) r */
  PetscReal lsFactor;
  PetscInt  lsMax, maxStalls;
  PetscReal rtol, atol, ctol, maxTime;
  PetscBool petscFactor; /* factor K with a PETSc PC (prefix micro_factor_) instead of HylcChol */
  PetscBool indefinite;  /* accept a factorization of an indefinite K (the descent test still applies) */
} MicroParams;

struct _n_HylcMicro {
  MPI_Comm      comm;
  MicroParams   par;
  HylcPattern   pat;
  HylcYarnModel model;
  HylcPeriodic  P;
  PetscInt      ny, m;     /* unknowns, constraint rows */
  PetscReal     mu, r, ks; /* twist scale, yarn radius, stretching stiffness k_s */
  SNES          snes;
  Mat           K;
  Vec           X, mvec;
  PetscReal    *yw, *gw; /* work: unscaled unknowns and gradient */
  PC            inner;   /* PETSc factorization (-micro_factor_type petsc) */
  HylcChol      chol;    /* hylc's supernodal Cholesky (default) */
  /* KKT data */
  const PetscReal *A, *dL, *AAtinv;
  PetscReal       *c, *Z, *S, *Sinv, *wl, *tmp;
  PetscReal        alpha;
  /* state of a solve */
  PetscBool       haveH; /* K holds the unscaled H_y of the state in X */
  PetscReal       E0;    /* energy of the current iterate */
  PetscReal       parts[4];
  PetscReal       z0; /* |z| at the first iteration */
  PetscReal       lastz, lastc;
  PetscInt        stalls, stallsTotal, retries;
  PetscLogDouble  tStart, tFactor, tLineSearch;
  HylcMicroStatus status;
  PetscBool       statusSet;
  PetscBool       factorFailed; /* the Newton matrix could not be factored after every alpha increase */
  PetscBool       inject;       /* this solve raises the injected error (HYLC_INJECT_ERROR) */
  PetscInt        nhist, caphist;
  PetscReal      *hist;
  PetscBool       setFromOptionsCalled;
};

static PetscErrorCode MicroParamsDefault(MicroParams *p)
{
  PetscFunctionBegin;
  p->alphaStart  = 5000;
  p->alphaEnd    = 5;
  p->alphaIts    = 400;
  p->maxRetries  = 12;
  p->twistScale  = 0;
  p->stepP0      = 0.05;
  p->stepP1      = 0.15;
  p->lsFactor    = 0.1;
  p->lsMax       = 11;
  p->maxStalls   = 5;
  p->rtol        = 1e-5;
  p->atol        = 1e-10;
  p->ctol        = 1e-4;
  p->maxTime     = 60;
  p->petscFactor = PETSC_FALSE;
  p->indefinite  = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroCreate(MPI_Comm comm, HylcMicro *micro)
{
  HylcMicro M;

  PetscFunctionBegin;
  PetscCall(HylcInitializePackage());
  PetscCall(PetscNew(&M));
  M->comm = comm;
  PetscCall(MicroParamsDefault(&M->par));
  *micro = M;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MicroFreeSolver(HylcMicro M)
{
  PetscFunctionBegin;
  PetscCall(SNESDestroy(&M->snes));
  PetscCall(MatDestroy(&M->K));
  PetscCall(VecDestroy(&M->X));
  PetscCall(VecDestroy(&M->mvec));
  PetscCall(PetscFree2(M->yw, M->gw));
  PetscCall(PCDestroy(&M->inner));
  PetscCall(HylcCholDestroy(&M->chol));
  PetscCall(PetscFree6(M->c, M->Z, M->S, M->Sinv, M->wl, M->tmp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroDestroy(HylcMicro *micro)
{
  PetscFunctionBegin;
  if (!*micro) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MicroFreeSolver(*micro));
  PetscCall(HylcPeriodicDestroy(&(*micro)->P));
  PetscCall(HylcPatternDestroy(&(*micro)->pat));
  PetscCall(PetscFree((*micro)->hist));
  PetscCall(PetscFree(*micro));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroSetPattern(HylcMicro M, HylcPattern pat, const HylcYarnModel *model)
{
  PetscFunctionBegin;
  PetscCall(PetscObjectReference((PetscObject)pat));
  PetscCall(HylcPatternDestroy(&M->pat));
  PetscCall(HylcPeriodicDestroy(&M->P));
  PetscCall(MicroFreeSolver(M));
  M->pat   = pat;
  M->model = *model;
  PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &M->P));
  PetscCall(HylcPeriodicSetPattern(M->P, pat, model));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetFromOptions - Options of the Newton solver (prefix -micro_), and of the periodic tile
  (-periodic_*, -macro_*). The SNES, its KSP and the inner factorization have the prefixes micro_ and
  micro_factor_: -micro_snes_max_it (iteration cap, default 2000), -micro_snes_monitor,
  -micro_factor_pc_factor_mat_ordering_type, ...
+ -micro_alpha_start <5000>, -micro_alpha_end <5>, -micro_alpha_its <400> - the alpha^ schedule
. -micro_alpha_retries <12>      - alpha x 10 retries when K is indefinite
. -micro_twist_scale <1/r>       - mu, the scale of the twist unknowns (0: 1/r)
. -micro_step_p0 <0.05>, -micro_step_p1 <0.15> - step limit (p0 + p1 clamp(lambda_min(I),0,1)) r
. -micro_ls_factor <0.1>, -micro_ls_max <11> - backtracking factor and number of trials
. -micro_factor_type <hylc>      - hylc: the supernodal Cholesky of include/hylc/chol.h; petsc: PCCHOLESKY
                                   with the options -micro_factor_pc_* (ordering metisnd by default)
. -micro_factor_indefinite <true> - accept the factorization of an indefinite K (signed Cholesky L S L^T, as
                                   PETSc's and Eigen's LDL^T do) when the step is a descent direction of
                                   positive curvature; false: alpha x 10 at any negative pivot
. -micro_max_stalls <5>          - consecutive failed line searches before giving up
. -micro_rtol <1e-5>             - |z| < rtol |z0|
. -micro_atol <1e-10>            - or |z| < atol k_s
. -micro_ctol <1e-4>             - |A y - dL| < ctol r
- -micro_max_time <60>           - wall-time cap per solve (s)
@*/
PetscErrorCode HylcMicroSetFromOptions(HylcMicro M)
{
  MicroParams *p = &M->par;

  PetscFunctionBegin;
  PetscOptionsBegin(M->comm, NULL, "Microscale Newton solver", "HylcMicro");
  PetscCall(PetscOptionsReal("-micro_alpha_start", "Regularization schedule: alpha^ at iteration 0", "HylcMicro", p->alphaStart, &p->alphaStart, NULL));
  PetscCall(PetscOptionsReal("-micro_alpha_end", "Regularization schedule: alpha^ from iteration alpha_its on", "HylcMicro", p->alphaEnd, &p->alphaEnd, NULL));
  PetscCall(PetscOptionsInt("-micro_alpha_its", "Regularization schedule: iterations of the geometric decay", "HylcMicro", p->alphaIts, &p->alphaIts, NULL));
  PetscCall(PetscOptionsInt("-micro_alpha_retries", "Retries with alpha x 10 when the Newton matrix is indefinite", "HylcMicro", p->maxRetries, &p->maxRetries, NULL));
  PetscCall(PetscOptionsReal("-micro_twist_scale", "Scale mu of the twist unknowns (0 = 1/r)", "HylcMicro", p->twistScale, &p->twistScale, NULL));
  PetscCall(PetscOptionsReal("-micro_step_p0", "Step limit d_max = (p0 + p1 clamp(lambda_min(I),0,1)) r: p0", "HylcMicro", p->stepP0, &p->stepP0, NULL));
  PetscCall(PetscOptionsReal("-micro_step_p1", "Step limit: p1", "HylcMicro", p->stepP1, &p->stepP1, NULL));
  PetscCall(PetscOptionsReal("-micro_ls_factor", "Backtracking factor of the line search", "HylcMicro", p->lsFactor, &p->lsFactor, NULL));
  PetscCall(PetscOptionsInt("-micro_ls_max", "Line-search trials per iteration", "HylcMicro", p->lsMax, &p->lsMax, NULL));
  PetscCall(PetscOptionsInt("-micro_max_stalls", "Consecutive line searches without decrease before the solve stops (status stalled)", "HylcMicro", p->maxStalls, &p->maxStalls, NULL));
  PetscCall(PetscOptionsReal("-micro_rtol", "Convergence: projected gradient |z| < rtol |z0|", "HylcMicro", p->rtol, &p->rtol, NULL));
  PetscCall(PetscOptionsReal("-micro_atol", "Convergence also when |z| < atol k_s (k_s = Es pi r^2, a force): for tiles already at rest", "HylcMicro", p->atol, &p->atol, NULL));
  PetscCall(PetscOptionsReal("-micro_ctol", "Convergence: constraint residual |A y - dL| < ctol r", "HylcMicro", p->ctol, &p->ctol, NULL));
  {
    const char *types[] = {"hylc", "petsc"};
    PetscInt    t       = p->petscFactor ? 1 : 0;
    PetscCall(PetscOptionsEList("-micro_factor_type", "Factorization of the Newton matrix: hylc (supernodal Cholesky on vertex blocks) or petsc (PCCHOLESKY, options -micro_factor_pc_*)", "HylcMicro", types, 2, types[t], &t, NULL));
    PetscCheck(!M->snes || (t == 1) == p->petscFactor, M->comm, PETSC_ERR_ARG_WRONGSTATE, "-micro_factor_type cannot change after the solver is set up");
    p->petscFactor = (PetscBool)(t == 1);
  }
  PetscCall(PetscOptionsBool("-micro_factor_indefinite", "Accept the factorization of an indefinite Newton matrix if the step descends with positive curvature (false: alpha x 10 at any negative pivot; hylc factorization only)", "HylcMicro", p->indefinite, &p->indefinite, NULL));
  if (M->chol) PetscCall(HylcCholSetIndefinite(M->chol, p->indefinite));
  PetscCall(PetscOptionsReal("-micro_max_time", "Wall-time cap per solve (s); status time_cap", "HylcMicro", p->maxTime, &p->maxTime, NULL));
  PetscOptionsEnd();
  PetscCheck(p->alphaStart > 0 && p->alphaEnd > 0 && p->alphaIts >= 1, M->comm, PETSC_ERR_USER_INPUT, "-micro_alpha_start, -micro_alpha_end must be positive and -micro_alpha_its at least 1");
  PetscCheck(p->lsFactor > 0 && p->lsFactor < 1 && p->lsMax >= 1, M->comm, PETSC_ERR_USER_INPUT, "-micro_ls_factor must be in (0, 1) and -micro_ls_max at least 1");
  PetscCheck(p->rtol > 0 && p->ctol > 0 && p->maxTime > 0 && p->stepP0 > 0 && p->stepP1 >= 0, M->comm, PETSC_ERR_USER_INPUT, "-micro_rtol, -micro_ctol, -micro_max_time, -micro_step_p0 must be positive, -micro_step_p1 non-negative");
  if (M->P) PetscCall(HylcPeriodicSetFromOptions(M->P));
  M->setFromOptionsCalled = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* y = M y^ */
static PetscErrorCode ToY(HylcMicro M, Vec X, PetscReal y[])
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
static PetscErrorCode SafeEnergy(HylcMicro M, Vec X, PetscReal *E, PetscReal parts[4])
{
  PetscReal e[4] = {0, 0, 0, 0};
  PetscBool finite;

  PetscFunctionBegin;
  PetscCall(ToY(M, X, M->yw));
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
  PetscCall(SafeEnergy((HylcMicro)ctx, X, E, NULL));
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
  PetscCheck(!M->inject, PETSC_COMM_SELF, PETSC_ERR_LIB, "injected error (HYLC_INJECT_ERROR=%" PetscInt_FMT ")", injectAt);
  PetscCall(ToY(M, X, M->yw));
  PetscCall(HylcPeriodicSetState(M->P, M->yw));
  PetscCall(HylcPeriodicEvaluateFinite(M->P, HYLC_TERM_ALL, M->parts, M->gw, M->K, &finite));
  M->haveH = finite;
  PetscCall(VecGetArray(F, &f));
  for (PetscInt i = 0; i < M->ny; i++) f[i] = !finite ? PETSC_INFINITY : ((i % 4 == 3) ? M->mu * M->gw[i] : M->gw[i]);
  PetscCall(VecRestoreArray(F, &f));
  M->E0 = !finite ? PETSC_INFINITY : M->parts[0] + M->parts[1] + M->parts[2] + M->parts[3];
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
  PetscCall(ToY(M, X, M->yw));
  if (!M->haveH) {
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicEvaluate(M->P, HYLC_TERM_ALL, M->parts, M->gw, M->K));
  }
  M->haveH = PETSC_FALSE;
  for (PetscInt i = 0; i < M->ny; i++) gmax = PetscMax(gmax, PetscAbsReal((i % 4 == 3) ? M->mu * M->gw[i] : M->gw[i]));
  const PetscReal t = (PetscReal)PetscMin(it, M->par.alphaIts) / M->par.alphaIts;
  M->alpha          = M->par.alphaStart * PetscPowReal(M->par.alphaEnd / M->par.alphaStart, t) * gmax;
  if (!(M->alpha > 0)) M->alpha = PETSC_SMALL;
  PetscCall(MatDiagonalScale(M->K, M->mvec, M->mvec));
  PetscCall(MatShift(M->K, M->alpha));
  PetscCall(MatSetOption(M->K, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(HylcPeriodicConstraintResidual(M->P, M->yw, M->c));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* x = K^-1 b with the current factorization */
static PetscErrorCode FactorApply(HylcMicro M, Vec b, Vec x)
{
  const PetscScalar *ba;
  PetscScalar       *xa;

  PetscFunctionBegin;
  if (!M->chol) {
    PetscCall(PCApply(M->inner, b, x));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecGetArrayRead(b, &ba));
  PetscCall(VecGetArray(x, &xa));
  PetscCall(HylcCholSolve(M->chol, ba, xa));
  PetscCall(VecRestoreArray(x, &xa));
  PetscCall(VecRestoreArrayRead(b, &ba));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* factor K and form the Schur complement data Z = K^-1 M A^T and S^-1 = (A M Z)^-1 */
static PetscErrorCode KKTFactor(HylcMicro M, PetscBool *ok)
{
  const PetscInt n = M->ny, m = M->m;
  PCFailedReason reason;
  Vec            b, x;
  PetscScalar   *a;
  PetscLogDouble t0, t1;

  PetscFunctionBegin;
  PetscCall(PetscTime(&t0));
  if (M->chol)
    PetscCall(HylcCholFactor(M->chol, M->K, 4, ok));
  else {
    /* a zero pivot is reported by PETSc's factorizations as a failed reason, not an error (the matrix's
       erroriffailure is false): that is the regularization's job; any error is an error */
    PetscCall(PCSetOperators(M->inner, M->K, M->K));
    PetscCall(PCSetUp(M->inner));
    PetscCall(PCGetFailedReason(M->inner, &reason));
    *ok = (PetscBool)(reason == PC_NOERROR);
    if (!*ok) PetscCall(PetscInfo(NULL, "PETSc factorization of the Newton matrix failed: %s\n", PCFailedReasons[reason]));
  }
  if (*ok && M->chol) { /* Z = K^-1 M A^T: all m right-hand sides in one pass over the factor */
    for (PetscInt i = 0; i < m; i++)
      for (PetscInt k = 0; k < n; k++) M->Z[i * n + k] = M->A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0);
    PetscCall(HylcCholSolveMany(M->chol, m, M->Z, M->Z));
  } else if (*ok) {
    PetscCall(MatCreateVecs(M->K, &x, &b));
    for (PetscInt i = 0; i < m; i++) {
      PetscCall(VecGetArray(b, &a));
      for (PetscInt k = 0; k < n; k++) a[k] = M->A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0);
      PetscCall(VecRestoreArray(b, &a));
      PetscCall(FactorApply(M, b, x));
      PetscCall(VecGetArray(x, &a));
      for (PetscInt k = 0; k < n; k++) M->Z[i * n + k] = PetscRealPart(a[k]);
      PetscCall(VecRestoreArray(x, &a));
    }
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&b));
  }
  if (*ok) {
    for (PetscInt i = 0; i < m; i++)
      for (PetscInt j = 0; j < m; j++) {
        PetscReal s = 0;
        for (PetscInt k = 0; k < n; k++) s += M->A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0) * M->Z[j * n + k];
        M->S[i * m + j] = s;
      }
    *ok = (PetscBool)(HylcDenseInverse((int)m, M->S, M->Sinv, 0.0) == 0);
  }
  PetscCall(PetscTime(&t1));
  M->tFactor += t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* more regularization: alpha x 10, refactor */
static PetscErrorCode KKTIncreaseAlpha(HylcMicro M, PetscBool *ok)
{
  PetscFunctionBegin;
  PetscCall(MatShift(M->K, 9 * M->alpha));
  M->alpha *= 10;
  M->retries++;
  PetscCall(PetscInfo(NULL, "indefinite Newton matrix: alpha x 10 -> %g\n", (double)M->alpha));
  PetscCall(KKTFactor(M, ok));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KKTSetUp(PC pc)
{
  HylcMicro M;
  PetscBool ok;

  PetscFunctionBegin;
  PetscCall(PCShellGetContext(pc, &M));
  PetscCall(KKTFactor(M, &ok));
  for (PetscInt k = 0; !ok && k < M->par.maxRetries; k++) PetscCall(KKTIncreaseAlpha(M, &ok));
  /* no step: the line search ends the solve (status stalled, or nonfinite for a non-finite matrix) */
  if (!ok) M->factorFailed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* x = -w_y, the KKT solution (S22) for b = M g: x = K^-1 b + Z S^-1 (c - A M K^-1 b) (SNES steps X - x) */
static PetscErrorCode KKTSolve(HylcMicro M, Vec b, Vec x)
{
  const PetscInt n = M->ny, m = M->m;
  PetscScalar   *xa;

  PetscFunctionBegin;
  PetscCall(FactorApply(M, b, x));
  PetscCall(VecGetArray(x, &xa));
  for (PetscInt i = 0; i < m; i++) {
    PetscReal s = M->c[i];
    for (PetscInt k = 0; k < n; k++) s -= M->A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0) * PetscRealPart(xa[k]);
    M->tmp[i] = s;
  }
  for (PetscInt i = 0; i < m; i++) {
    M->wl[i] = 0;
    for (PetscInt j = 0; j < m; j++) M->wl[i] += M->Sinv[i * m + j] * M->tmp[j];
  }
  for (PetscInt k = 0; k < n; k++) {
    PetscReal s = 0;
    for (PetscInt i = 0; i < m; i++) s += M->Z[i * n + k] * M->wl[i];
    xa[k] += s;
  }
  PetscCall(VecRestoreArray(x, &xa));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KKTApply(PC pc, Vec b, Vec x)
{
  HylcMicro   M;
  PetscScalar descent, curv;
  Vec         Kx;

  PetscFunctionBegin;
  PetscCall(PCShellGetContext(pc, &M));
  if (M->factorFailed) {
    PetscCall(VecSet(x, 0));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecDuplicate(x, &Kx));
  for (PetscInt k = 0;; k++) {
    PetscBool ok;
    PetscCall(KKTSolve(M, b, x));
    /* a descent direction of positive curvature; otherwise K is too indefinite: regularize more */
    PetscCall(VecDot(b, x, &descent));
    PetscCall(MatMult(M->K, x, Kx));
    PetscCall(VecDot(x, Kx, &curv));
    if ((PetscRealPart(descent) > 0 && PetscRealPart(curv) > 0) || k >= M->par.maxRetries) break;
    PetscCall(KKTIncreaseAlpha(M, &ok));
    if (!ok) {
      M->factorFailed = PETSC_TRUE;
      PetscCall(VecSet(x, 0));
      break;
    }
  }
  PetscCall(VecDestroy(&Kx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the step limit, then backtracking until the energy strictly decreases; frames transported on acceptance */
static PetscErrorCode LineSearch(SNESLineSearch ls, void *ctx)
{
  HylcMicro              M = (HylcMicro)ctx;
  Vec                    X, F, Y, W, G;
  PetscReal              dmax, d = 0, E, lambda = 1, ynorm, xnorm, fnorm;
  const PetscScalar     *y;
  SNES                   snes;
  PetscLogDouble         t0, t1;
  const HylcMacroStrain *ms;
  PetscBool              accepted = PETSC_FALSE;

  PetscFunctionBegin;
  PetscCall(PetscTime(&t0));
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  if (M->factorFailed) { /* no Newton step: the iterate stays and the solve ends */
    PetscReal knorm;
    PetscCall(MatNorm(M->K, NORM_FROBENIUS, &knorm));
    M->status    = PetscIsInfOrNanReal(knorm) ? HYLC_MICRO_NONFINITE : HYLC_MICRO_STALLED;
    M->statusSet = PETSC_TRUE;
    PetscCall(VecNorm(X, NORM_2, &xnorm));
    PetscCall(VecNorm(F, NORM_2, &fnorm));
    PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, 0));
    PetscCall(SNESLineSearchSetLambda(ls, 0));
    PetscCall(PetscTime(&t1));
    M->tLineSearch += t1 - t0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcPeriodicGetMacroStrain(M->P, &ms));
  dmax = (M->par.stepP0 + M->par.stepP1 * PetscClipInterval(ms->lambdaMin, 0, 1)) * M->r;
  /* the largest vertex displacement of the linear step (ghosts are rotated copies: the same lengths) */
  PetscCall(VecGetArrayRead(Y, &y));
  for (PetscInt o = 0; o < M->ny / 4; o++) d = PetscMax(d, PetscSqrtReal(PetscSqr(PetscRealPart(y[4 * o])) + PetscSqr(PetscRealPart(y[4 * o + 1])) + PetscSqr(PetscRealPart(y[4 * o + 2]))));
  PetscCall(VecRestoreArrayRead(Y, &y));
  if (d > dmax) PetscCall(VecScale(Y, dmax / d));
  for (PetscInt i = 0; i < M->par.lsMax; i++, lambda *= M->par.lsFactor) {
    PetscCall(VecWAXPY(W, -lambda, Y, X));
    PetscCall(SafeEnergy(M, W, &E, NULL));
    if (E < M->E0) {
      accepted = PETSC_TRUE;
      break;
    }
  }
  if (accepted) {
    PetscCall(VecCopy(W, X));
    PetscCall(SNESComputeFunction(snes, X, F)); /* the state, E0, the gradient and the Hessian */
    PetscCall(HylcPeriodicUpdateFrames(M->P));
    M->stalls = 0;
    if (M->nhist == M->caphist) {
      PetscReal *h;
      M->caphist = M->caphist ? 2 * M->caphist : 256;
      PetscCall(PetscMalloc1(M->caphist, &h));
      PetscCall(PetscArraycpy(h, M->hist, M->nhist));
      PetscCall(PetscFree(M->hist));
      M->hist = h;
    }
    M->hist[M->nhist++] = M->E0;
  } else {
    /* keep the iterate (alpha decays with the iteration count); the cached Hessian stays valid */
    M->stalls++;
    M->stallsTotal++;
    PetscCall(ToY(M, X, M->yw));
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicEvaluate(M->P, HYLC_TERM_ALL, M->parts, M->gw, M->K));
    M->haveH = PETSC_TRUE;
    if (M->stalls >= M->par.maxStalls) {
      M->status    = HYLC_MICRO_STALLED;
      M->statusSet = PETSC_TRUE;
    }
  }
  PetscCall(VecNorm(X, NORM_2, &xnorm));
  PetscCall(VecNorm(F, NORM_2, &fnorm));
  PetscCall(VecNorm(Y, NORM_2, &ynorm));
  PetscCall(SNESLineSearchSetNorms(ls, xnorm, fnorm, accepted ? lambda * ynorm : 0));
  PetscCall(SNESLineSearchSetLambda(ls, accepted ? lambda : 0));
  PetscCall(PetscTime(&t1));
  M->tLineSearch += t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* S23-S25: the projected gradient z = g - A^T (A A^T)^-1 A g (unscaled) and the constraint residual */
static PetscErrorCode Converged(SNES snes, PetscInt it, PetscReal xnorm, PetscReal gnorm, PetscReal f, SNESConvergedReason *reason, void *ctx)
{
  HylcMicro      M = (HylcMicro)ctx;
  const PetscInt n = M->ny, m = M->m;
  PetscReal      z2 = 0, c2 = 0;
  PetscLogDouble now;
  PetscInt       maxit;
  Vec            X;

  PetscFunctionBegin;
  (void)xnorm;
  (void)gnorm;
  (void)f;
  *reason = SNES_CONVERGED_ITERATING;
  if (M->statusSet) { /* stalled line search */
    *reason = SNES_DIVERGED_LINE_SEARCH;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!PetscIsNormalReal(M->E0) && M->E0 != 0) {
    M->status    = HYLC_MICRO_NONFINITE;
    M->statusSet = PETSC_TRUE;
    *reason      = SNES_DIVERGED_FNORM_NAN;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt i = 0; i < m; i++) {
    PetscReal s = 0;
    for (PetscInt k = 0; k < n; k++) s += M->A[i * n + k] * M->gw[k];
    M->tmp[i] = s;
  }
  for (PetscInt i = 0; i < m; i++) {
    M->wl[i] = 0;
    for (PetscInt j = 0; j < m; j++) M->wl[i] += M->AAtinv[i * m + j] * M->tmp[j];
  }
  for (PetscInt k = 0; k < n; k++) {
    PetscReal zk = M->gw[k];
    for (PetscInt i = 0; i < m; i++) zk -= M->A[i * n + k] * M->wl[i];
    z2 += zk * zk;
  }
  PetscCall(SNESGetSolution(snes, &X));
  PetscCall(ToY(M, X, M->yw));
  PetscCall(HylcPeriodicConstraintResidual(M->P, M->yw, M->c));
  for (PetscInt i = 0; i < m; i++) c2 += M->c[i] * M->c[i];
  const PetscReal zn = PetscSqrtReal(z2), cn = PetscSqrtReal(c2);
  if (it == 0) M->z0 = zn;
  M->lastz = M->z0 > 0 ? zn / M->z0 : 0;
  M->lastc = cn / M->r;
  if ((zn <= M->par.rtol * M->z0 || zn <= M->par.atol * M->ks) && cn < M->par.ctol * M->r) {
    *reason = SNES_CONVERGED_FNORM_RELATIVE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscTime(&now));
  if (now - M->tStart > M->par.maxTime) {
    M->status    = HYLC_MICRO_MAX_TIME;
    M->statusSet = PETSC_TRUE;
    *reason      = SNES_DIVERGED_FUNCTION_COUNT; /* the wall-time budget */
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(SNESGetTolerances(snes, NULL, NULL, NULL, &maxit, NULL));
  if (it >= maxit) *reason = SNES_DIVERGED_MAX_IT;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the SNES, its KSP (preonly + the KKT PCSHELL) and the inner factorization; created once per pattern */
static PetscErrorCode MicroSetUpSolver(HylcMicro M)
{
  KSP            ksp;
  PC             pc;
  SNESLineSearch ls;

  PetscFunctionBegin;
  if (M->snes) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(HylcPeriodicGetSizes(M->P, &M->ny, NULL, NULL, &M->m));
  PetscCall(HylcPeriodicCreateMatrix(M->P, &M->K));
  PetscCall(MatCreateVecs(M->K, &M->X, NULL));
  PetscCall(VecDuplicate(M->X, &M->mvec));
  PetscCall(PetscMalloc2(M->ny, &M->yw, M->ny, &M->gw));
  PetscCall(PetscMalloc6(M->m, &M->c, M->m * M->ny, &M->Z, M->m * M->m, &M->S, M->m * M->m, &M->Sinv, M->m, &M->wl, M->m, &M->tmp));
  if (M->par.petscFactor) {
    PetscCall(PCCreate(PETSC_COMM_SELF, &M->inner));
    PetscCall(PCSetType(M->inner, PCCHOLESKY));
    PetscCall(PCFactorSetMatOrderingType(M->inner, HylcDefaultOrdering()));
    PetscCall(PCSetOptionsPrefix(M->inner, "micro_factor_"));
    PetscCall(PCSetFromOptions(M->inner));
  } else {
    PetscCall(HylcCholCreate(&M->chol));
    PetscCall(HylcCholSetIndefinite(M->chol, M->par.indefinite));
  }
  PetscCall(SNESCreate(PETSC_COMM_SELF, &M->snes));
  PetscCall(SNESSetOptionsPrefix(M->snes, "micro_"));
  PetscCall(SNESSetType(M->snes, SNESNEWTONLS));
  PetscCall(SNESSetObjective(M->snes, FormObjective, M));
  PetscCall(SNESSetFunction(M->snes, NULL, FormFunction, M));
  PetscCall(SNESSetJacobian(M->snes, M->K, M->K, FormJacobian, M));
  PetscCall(SNESSetConvergenceTest(M->snes, Converged, M, NULL));
  PetscCall(SNESSetTolerances(M->snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2000, -1));
  PetscCall(SNESGetLineSearch(M->snes, &ls));
  PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHSHELL));
  PetscCall(SNESLineSearchShellSetUserFunc(ls, LineSearch, M));
  PetscCall(SNESGetKSP(M->snes, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, M));
  PetscCall(PCShellSetSetUp(pc, KKTSetUp));
  PetscCall(PCShellSetApply(pc, KKTApply));
  PetscCall(PCShellSetName(pc, M->chol ? "hylc KKT (S22): Schur complement around HylcChol, a supernodal Cholesky (-micro_factor_type)" : "hylc KKT (S22): Schur complement around a PETSc Cholesky factorization (-micro_factor_pc_*)"));
  PetscCall(SNESSetFromOptions(M->snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSolve - Solves for the equilibrium of the tile under the strain z (Algorithms C2, C3) from the
  initial guess u~ = 0. Not collective (PETSC_COMM_SELF). The result's status says whether it converged;
  a non-converged sample is not an error.
@*/
PetscErrorCode HylcMicroSolve(HylcMicro M, const PetscReal z[6], HylcMicroResult *res)
{
  PetscLogDouble      t1, tEval, tContact, tAssemble;
  PetscScalar        *x;
  SNESConvergedReason reason;
  PetscInt            its;
  HylcYarnConstants   c;
  PetscReal           area;
  PetscInt            m;

  PetscFunctionBegin;
  PetscCheck(M->P, M->comm, PETSC_ERR_ARG_WRONGSTATE, "Call HylcMicroSetPattern() first");
  if (injectAt < 0) { /* read once per process */
    const char *env = getenv("HYLC_INJECT_ERROR");
    char       *end = NULL;
    long        n   = env ? strtol(env, &end, 10) : 0;
    PetscCheck(!env || (end != env && !*end && n >= 0 && n < PETSC_MAX_INT), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "HYLC_INJECT_ERROR=%s: expected a non-negative integer (the 1-based number of the solve that raises an injected error)", env);
    injectAt = (PetscInt)n;
  }
  M->inject = (PetscBool)(injectAt > 0 && ++solveCount == injectAt);
  PetscCall(PetscMemzero(res, sizeof(*res)));
  for (int k = 0; k < 6; k++) res->z[k] = z[k];
  PetscCall(PetscLogEventBegin(HYLC_MicroSolve, 0, 0, 0, 0));
  PetscCall(PetscTime(&M->tStart));
  PetscCall(HylcPeriodicSetStrain(M->P, z));
  PetscCall(HylcPeriodicSetUp(M->P));
  PetscCall(HylcPeriodicGetConstants(M->P, &c));
  PetscCall(HylcPeriodicGetConstraints(M->P, &m, &M->A, &M->dL, &M->AAtinv));
  if (M->snes && m != M->m) { /* the number of independent constraint rows may depend on the strain */
    PetscCall(PetscFree6(M->c, M->Z, M->S, M->Sinv, M->wl, M->tmp));
    M->m = m;
    PetscCall(PetscMalloc6(M->m, &M->c, M->m * M->ny, &M->Z, M->m * M->m, &M->S, M->m * M->m, &M->Sinv, M->m, &M->wl, M->m, &M->tmp));
  }
  M->r  = c.r;
  M->ks = c.ks;
  M->mu = M->par.twistScale > 0 ? M->par.twistScale : 1.0 / c.r;
  PetscCall(MicroSetUpSolver(M));
  {
    PetscScalar *mv;
    PetscCall(VecGetArray(M->mvec, &mv));
    for (PetscInt i = 0; i < M->ny; i++) mv[i] = (i % 4 == 3) ? M->mu : 1.0;
    PetscCall(VecRestoreArray(M->mvec, &mv));
  }
  /* initial guess: y^ = M^-1 y0 */
  PetscCall(HylcPeriodicGetInitialState(M->P, M->yw));
  PetscCall(VecGetArray(M->X, &x));
  for (PetscInt i = 0; i < M->ny; i++) x[i] = (i % 4 == 3) ? M->yw[i] / M->mu : M->yw[i];
  PetscCall(VecRestoreArray(M->X, &x));
  M->haveH  = PETSC_FALSE;
  M->stalls = M->stallsTotal = M->retries = 0;
  M->statusSet = M->factorFailed = PETSC_FALSE;
  M->status                      = HYLC_MICRO_CONVERGED;
  M->tFactor = M->tLineSearch = 0;
  M->nhist                    = 0;
  M->E0                       = PETSC_INFINITY;
  /* an error inside the solve (a bug, no memory, a bad option) is an error: only the outcomes of the
     method are statuses (a failed factorization and a degenerate trial state are outcomes, handled above) */
  PetscCall(SNESSolve(M->snes, NULL, M->X));
  PetscCall(SNESGetConvergedReason(M->snes, &reason));
  PetscCall(SNESGetIterationNumber(M->snes, &its));
  if (reason > 0)
    res->status = HYLC_MICRO_CONVERGED;
  else if (M->statusSet)
    res->status = M->status;
  else if (reason == SNES_DIVERGED_MAX_IT)
    res->status = HYLC_MICRO_MAX_IT;
  else if (reason == SNES_DIVERGED_FNORM_NAN || reason == SNES_DIVERGED_FUNCTION_DOMAIN)
    res->status = HYLC_MICRO_NONFINITE;
  else
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_PLIB, "The Newton solve ended with the unexpected SNES reason %s", SNESConvergedReasons[reason]);
  /* the final state and its energy */
  PetscCall(SafeEnergy(M, M->X, &res->energy, res->parts));
  if (!PetscIsNormalReal(res->energy) && res->energy != 0) res->status = HYLC_MICRO_NONFINITE;
  PetscCall(HylcPeriodicGetArea(M->P, &area));
  res->psi        = res->energy / area;
  res->iterations = its;
  res->retries    = M->retries;
  res->stalls     = M->stallsTotal;
  res->residual   = M->lastz;
  res->cresidual  = M->lastc;
  PetscCall(PetscTime(&t1));
  res->time = t1 - M->tStart;
  PetscCall(HylcPeriodicGetTimes(M->P, &tEval, &tContact, &tAssemble));
  res->tAssembly   = tEval - tContact;
  res->tContact    = tContact;
  res->tFactor     = M->tFactor;
  res->tLineSearch = M->tLineSearch;
  PetscCall(PetscLogEventEnd(HYLC_MicroSolve, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroGetPeriodic(HylcMicro M, HylcPeriodic *P)
{
  PetscFunctionBegin;
  *P = M->P;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the unscaled unknowns y of the last solve */
PetscErrorCode HylcMicroGetState(HylcMicro M, PetscReal y[])
{
  PetscFunctionBegin;
  PetscCall(ToY(M, M->X, y));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* energies of the accepted iterates of the last solve */
PetscErrorCode HylcMicroGetEnergyHistory(HylcMicro M, PetscInt *n, const PetscReal **E)
{
  PetscFunctionBegin;
  *n = M->nhist;
  *E = M->hist;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroResultView(const HylcMicroResult *r, PetscViewer viewer)
{
  char buf[512];

  PetscFunctionBegin;
  /* C formatting: PETSc's printf appends '.' to integral %g values */
  snprintf(buf, sizeof(buf), "strain: %.9g %.9g %.9g %.9g %.9g %.9g\npsi: %.10e\nenergy_parts: %.10e %.10e %.10e %.10e\n", (double)r->z[0], (double)r->z[1], (double)r->z[2], (double)r->z[3], (double)r->z[4], (double)r->z[5], (double)r->psi, (double)r->parts[0], (double)r->parts[1], (double)r->parts[2], (double)r->parts[3]);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscCall(PetscViewerASCIIPrintf(viewer, "status: %s\n", HylcMicroStatuses[r->status]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "iterations: %" PetscInt_FMT "\n", r->iterations));
  snprintf(buf, sizeof(buf), "residual: %.3e (projected gradient, relative), constraints %.3e r\nregularization retries: %d, stalled line searches: %d\ntime: %.4f s (assembly %.4f, contact %.4f, factorization %.4f, line search %.4f)\n", (double)r->residual, (double)r->cresidual, (int)r->retries, (int)r->stalls, r->time, r->tAssembly, r->tContact, r->tFactor, r->tLineSearch);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetUp - Creates the SNES, its KSP and the factorization (reading their options) ahead of the
  first solve, so that every option has been read once this returns. Not collective.
@*/
PetscErrorCode HylcMicroSetUp(HylcMicro M)
{
  const PetscReal z[6] = {0, 0, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCheck(M->P, M->comm, PETSC_ERR_ARG_WRONGSTATE, "Call HylcMicroSetPattern() first");
  if (M->snes) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(HylcPeriodicSetStrain(M->P, z));
  PetscCall(HylcPeriodicSetUp(M->P));
  PetscCall(MicroSetUpSolver(M));
  PetscFunctionReturn(PETSC_SUCCESS);
}
