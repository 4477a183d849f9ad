/* Equilibria of the cloth: minimizing the energy (energy.c) with PETSc's solvers.

   NEWTON (default): SNES newtonls, F = the gradient, J = the Hessian (projected, exact, or auto: exact
   whenever its signed Cholesky factorization has no negative pivot), a direct solve (-cloth_ksp_type
   preonly, HylcClothDefaultKSP_Private: hylc's Cholesky, on several ranks on every rank; MUMPS as an
   option), and a shell line search on the energy: the step X - lambda Y
   is halved until the path is clear of every support (HylcClothFeasible_Private) and the energy
   decreases by the Armijo condition (or, within rounding of the energy, the gradient norm decreases).
   A direction that is not a descent direction (the exact Hessian at an unstable state) is replaced by
   the projected Newton direction.

   TRUST: TAO's trust-region Newton (TAONTR) with the same objective, gradient and Hessian, Steihaug CG
   (-cloth_tao_ksp_type stcg) preconditioned by the Cholesky factorization of the Hessian; a trial point
   that the supports or the elements refuse has the objective +inf, and TAO shrinks the region.

   Options of the embedded solvers carry the cloth's prefix: -cloth_snes_monitor, -cloth_ksp_view,
   -cloth_tao_monitor, ... */
#include <hylc/private/clothimpl.h>
#include <petscmat.h>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <petsc/private/matimpl.h>
#pragma GCC diagnostic pop
#include <hylc/chol.h>

/* the number of negative pivots of the last factorization (MatGetInertia: hylc's and MUMPS' Cholesky,
   also inside PCREDUNDANT), or -1 when the preconditioner does not tell */
static PetscErrorCode NegativePivots(KSP ksp, PetscInt *nneg)
{
  PC        pc;
  Mat       F;
  PetscBool isfactor;
  PetscInt  nzero, npos;

  PetscFunctionBegin;
  *nneg = -1;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCREDUNDANT, &isfactor));
  if (isfactor) { /* the same sequential factorization on every rank (HylcClothDefaultKSP_Private) */
    KSP inner;
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(NegativePivots(inner, nneg));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCCHOLESKY, &isfactor));
  if (!isfactor) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCFactorGetMatrix(pc, &F));
  if (!F || !F->ops->getinertia) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(MatGetInertia(F, nneg, &nzero, &npos));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Backtracking along X - lambda Y from lambda = 1: W the new point, G the gradient there. F is the
  gradient at X and E0 the energy there. ok = PETSC_FALSE when no lambda >= 2^-40 is accepted.
*/
PetscErrorCode HylcClothBacktrack_Private(HylcCloth c, Vec X, PetscReal E0, Vec F, Vec Y, Vec W, Vec G, PetscReal *lambda, PetscBool *ok)
{
  PetscReal slope, lam = 1, E, f0, f1;

  PetscFunctionBegin;
  PetscCall(VecDot(F, Y, &slope));
  slope = -slope; /* d/dlambda E(X - lambda Y) at 0 */
  PetscCall(VecNorm(F, NORM_2, &f0));
  *ok = PETSC_FALSE;
  for (int it = 0; it < 40; it++, lam *= 0.5) {
    PetscBool clear;
    PetscCall(VecWAXPY(W, -lam, Y, X));
    PetscCall(HylcClothFeasible_Private(c, X, W, &clear));
    if (!clear) continue;
    PetscCall(HylcClothEnergy_Private(c, W, &E, G));
    if (HylcClothInfeasible(E)) continue;
    if (E <= E0 + 1e-4 * lam * slope) {
      *ok = PETSC_TRUE;
      break;
    }
    /* within the rounding of the energy, a decrease of the gradient norm decides */
    if (E - E0 <= 64 * PETSC_MACHINE_EPSILON * (PetscAbsReal(E0) + c->Escale)) {
      PetscCall(VecNorm(G, NORM_2, &f1));
      if (f1 < f0) {
        *ok = PETSC_TRUE;
        break;
      }
    }
  }
  *lambda = lam;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the SNES's line search: see the top of the file */
static PetscErrorCode LineSearchEnergy(SNESLineSearch ls, void *ctx)
{
  HylcCloth c = (HylcCloth)ctx;
  SNES      snes;
  KSP       ksp;
  Vec       X, F, Y, W, G;
  PetscReal E0, slope, lambda;
  PetscBool ok;
  PetscInt  nneg;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_ClothLineSearch, c, 0, 0, 0));
  PetscCall(SNESLineSearchGetSNES(ls, &snes));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(SNESLineSearchGetVecs(ls, &X, &F, &Y, &W, &G));
  PetscCall(VecDot(F, Y, &slope));
  PetscCall(NegativePivots(ksp, &nneg));
  c->nnegPivots = nneg;
  if (c->lastExact && (nneg > 0 || slope <= 0)) {
    /* the exact Hessian is indefinite here: the projected Newton direction */
    PetscCall(HylcClothHessian_Private(c, X, PETSC_TRUE, c->H));
    PetscCall(KSPSetOperators(ksp, c->H, c->H));
    PetscCall(HylcClothFactor_Private(ksp));
    PetscCall(KSPSolve(ksp, F, Y));
    c->lastExact = PETSC_FALSE;
    c->hessExact--;
    c->hessProj++;
    PetscCall(VecDot(F, Y, &slope));
  }
  if (slope <= 0) PetscCall(VecCopy(F, Y)); /* never expected with a PSD matrix: steepest descent */
  PetscCall(HylcClothEnergy_Private(c, X, &E0, NULL));
  PetscCall(HylcClothBacktrack_Private(c, X, E0, F, Y, W, G, &lambda, &ok));
  if (!ok) {
    c->lsFails++;
    if (c->lsMonitor) PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c), "    line search failed: %s Hessian (negative pivots %" PetscInt_FMT "), E %.12g, slope %g\n", c->lastExact ? "exact" : "projected", nneg, (double)E0, (double)slope));
    PetscCall(SNESLineSearchSetReason(ls, SNES_LINESEARCH_FAILED_REDUCT));
    PetscCall(PetscLogEventEnd(HYLC_ClothLineSearch, c, 0, 0, 0));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (c->lsMonitor) {
    PetscReal E1;
    PetscCall(HylcClothEnergy_Private(c, W, &E1, NULL));
    PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c), "    line search: lambda %g, %s Hessian (negative pivots %" PetscInt_FMT "), E %.12g -> %.12g\n", (double)lambda, c->lastExact ? "exact" : "projected", nneg, (double)E0, (double)E1));
  }
  PetscCall(VecCopy(W, X));
  PetscCall(VecCopy(G, F));
  PetscCall(SNESLineSearchSetLambda(ls, lambda));
  PetscCall(SNESLineSearchComputeNorms(ls));
  PetscCall(PetscLogEventEnd(HYLC_ClothLineSearch, c, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormGradient(SNES snes, Vec X, Vec F, void *ctx)
{
  HylcCloth c = (HylcCloth)ctx;
  PetscReal E;

  PetscFunctionBegin;
  (void)snes;
  PetscCall(HylcClothEnergy_Private(c, X, &E, F));
  PetscCheck(!HylcClothInfeasible(E), PetscObjectComm((PetscObject)c), PETSC_ERR_NOT_CONVERGED, "the cloth's state is infeasible (a degenerate triangle or a vertex through a support) at the start of a solve");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormObjective(SNES snes, Vec X, PetscReal *E, void *ctx)
{
  PetscFunctionBegin;
  (void)snes;
  PetscCall(HylcClothEnergy_Private((HylcCloth)ctx, X, E, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcClothFormHessian_Private(HylcCloth c, Vec X, Mat H)
{
  PetscFunctionBegin;
  c->lastExact = c->hessian != HYLC_CLOTH_HESSIAN_PROJECTED ? PETSC_TRUE : PETSC_FALSE;
  if (c->lastExact)
    c->hessExact++;
  else
    c->hessProj++;
  PetscCall(HylcClothHessian_Private(c, X, c->lastExact ? PETSC_FALSE : PETSC_TRUE, H));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* MUMPS counts the negative pivots of the whole matrix only with ICNTL(13) = 1 (no ScaLAPACK on the
   root node): set on its factor before the first factorization (the user's -mat_mumps_icntl_13 is read
   afterwards and wins) */
PetscErrorCode HylcClothMumpsInertia_Private(KSP ksp)
{
  PC            pc;
  Mat           F;
  PetscBool     isch, ismumps, pset;
  MatSolverType st;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCCHOLESKY, &isch));
  if (!isch) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCFactorGetMatSolverType(pc, &st));
  PetscCall(PetscStrcmp(st, MATSOLVERMUMPS, &ismumps));
  PetscCall(PCGetOperatorsSet(pc, NULL, &pset));
  if (!ismumps || !pset) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PCFactorSetUpMatSolverType(pc));
  PetscCall(PCFactorGetMatrix(pc, &F));
  PetscCall(MatMumpsSetIcntl(F, 13, 1));
  PetscCall(MatMumpsSetIcntl(F, 24, 1)); /* MatGetInertia counts the null pivots too: their detection */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Factorizes the operators of ksp now (KSPSetUp), with MUMPS' settings above set first; a MUMPS
  factorization that runs out of its workspace (INFOG(1) = -9, MAT_FACTOR_OUTMEMORY: the analysis'
  estimate exceeded) is redone from a new analysis with ICNTL(14), the workspace margin in %, doubled (at
  most 4 times). A failed factor cannot be left for the next factorization: PETSc 3.18's MUMPS interface
  returns at once from every later numerical factorization of the same analysis (INFOG(1) < 0 is kept),
  so every Newton step of every load step would fail, whatever the matrix. The KSPSolve that follows
  finds the operators unchanged and does not factorize again. Collective.
*/
PetscErrorCode HylcClothFactor_Private(KSP ksp)
{
  PC             pc;
  Mat            A, P, F;
  MatFactorError err     = MAT_FACTOR_NOERROR;
  PetscBool      ismumps = PETSC_FALSE;
  MatSolverType  st;

  PetscFunctionBegin;
  PetscCall(KSPGetPC(ksp, &pc));
  for (int attempt = 0;; attempt++) {
    PetscInt w = 0;
    PetscCall(HylcClothMumpsInertia_Private(ksp));
    PetscCall(KSPSetUp(ksp));
    PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCCHOLESKY, &ismumps));
    if (ismumps) {
      PetscCall(PCFactorGetMatSolverType(pc, &st));
      PetscCall(PetscStrcmp(st, MATSOLVERMUMPS, &ismumps));
    }
    if (!ismumps) break;
    PetscCall(PCFactorGetMatrix(pc, &F));
    PetscCall(MatFactorGetError(F, &err));
    if (err != MAT_FACTOR_OUTMEMORY || attempt == 4) break;
    PetscCall(MatMumpsGetIcntl(F, 14, &w));
    w = 2 * PetscMax(w, 20);
    PetscCall(PetscInfo(ksp, "MUMPS' workspace exceeded (INFOG(1) = -9): a new analysis with ICNTL(14) = %" PetscInt_FMT "\n", w));
    PetscCall(PCGetOperators(pc, &A, &P));
    PetscCall(PetscObjectReference((PetscObject)A));
    PetscCall(PetscObjectReference((PetscObject)P));
    PetscCall(PCReset(pc)); /* the factor dropped: a new MUMPS instance and analysis */
    PetscCall(KSPSetOperators(ksp, A, P));
    PetscCall(MatDestroy(&A));
    PetscCall(MatDestroy(&P));
    PetscCall(PCFactorSetUpMatSolverType(pc));
    PetscCall(PCFactorGetMatrix(pc, &F));
    PetscCall(MatMumpsSetIcntl(F, 14, w));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode FormJacobian(SNES snes, Vec X, Mat J, Mat P, void *ctx)
{
  KSP ksp;

  PetscFunctionBegin;
  (void)P;
  PetscCall(HylcClothFormHessian_Private((HylcCloth)ctx, X, J));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(KSPSetOperators(ksp, J, J)); /* as SNES does next: factorized here */
  PetscCall(HylcClothFactor_Private(ksp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the direct solver of the Newton systems: a signed Cholesky factorization that counts the negative
   pivots, hylc's supernodal one (MATSOLVERHYLC, METIS ordering). On several ranks every rank factors the
   whole matrix (PCREDUNDANT, one subcommunicator per rank, -cloth_redundant_* options): measured on the
   20,724-triangle drape (2026-11-27, docs/performance.md), MUMPS' LDL^T on 2 ranks took 133 s of
   factorization in 78 Newton iterations with this machine's reference BLAS, HylcChol on one rank 19 s.
   MUMPS stays an option away: -cloth_pc_type cholesky -cloth_pc_factor_mat_solver_type mumps. */
PetscErrorCode HylcClothDefaultKSP_Private(KSP ksp, PetscBool preonly)
{
  PC          pc;
  PetscMPIInt size;

  PetscFunctionBegin;
  if (preonly) PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)ksp), &size));
  if (size > 1) {
    KSP inner;
    PetscCall(PCSetType(pc, PCREDUNDANT));
    PetscCall(PCRedundantSetNumber(pc, size));
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(KSPSetType(inner, KSPPREONLY));
    PetscCall(KSPGetPC(inner, &pc));
  }
  PetscCall(PCSetType(pc, PCCHOLESKY));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERHYLC));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TaoFG(Tao tao, Vec X, PetscReal *E, Vec G, void *ctx)
{
  HylcCloth c  = (HylcCloth)ctx;
  PetscBool ok = PETSC_TRUE;

  PetscFunctionBegin;
  (void)tao;
  if (c->nsupport) PetscCall(HylcClothFeasible_Private(c, c->xprev, X, &ok));
  if (!ok) {
    *E = PETSC_INFINITY;
    PetscCall(VecZeroEntries(G));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcClothEnergy_Private(c, X, E, G));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TaoH(Tao tao, Vec X, Mat H, Mat P, void *ctx)
{
  PetscFunctionBegin;
  (void)tao;
  (void)P;
  PetscCall(HylcClothFormHessian_Private((HylcCloth)ctx, X, H));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TaoUpdate(Tao tao, PetscInt it, void *ctx)
{
  HylcCloth c = (HylcCloth)ctx;
  Vec       X;

  PetscFunctionBegin;
  (void)it;
  PetscCall(TaoGetSolution(tao, &X));
  PetscCall(VecCopy(X, c->xprev));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Reads the options of the embedded solvers (-cloth_snes_*, -cloth_ksp_*, -cloth_pc_*, -cloth_tao_*,
...) so that -help lists them and the check of unused options
  accepts them: the solvers themselves are made per mesh, with the same prefixes. Collective.
*/
PetscErrorCode HylcClothSolverOptions_Private(HylcCloth c)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)c);
  const char *prefix;
  SNES        snes;
  Tao         tao;
  KSP         ksp;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)c, &prefix));
  PetscCall(SNESCreate(comm, &snes));
  PetscCall(SNESSetOptionsPrefix(snes, prefix));
  PetscCall(SNESAppendOptionsPrefix(snes, "cloth_"));
  PetscCall(SNESSetType(snes, SNESNEWTONLS));
  PetscCall(SNESGetKSP(snes, &ksp));
  PetscCall(HylcClothDefaultKSP_Private(ksp, PETSC_TRUE));
  PetscCall(SNESSetFromOptions(snes));
  PetscCall(SNESDestroy(&snes));
  PetscCall(TaoCreate(comm, &tao));
  PetscCall(TaoSetOptionsPrefix(tao, prefix));
  PetscCall(TaoAppendOptionsPrefix(tao, "cloth_"));
  PetscCall(TaoSetType(tao, TAONTR));
  PetscCall(TaoSetFromOptions(tao));
  PetscCall(TaoDestroy(&tao));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcClothSolverReset_Private(HylcCloth c)
{
  PetscFunctionBegin;
  PetscCall(SNESDestroy(&c->snes));
  PetscCall(TaoDestroy(&c->tao));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SolverSetUp(HylcCloth c)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)c);
  const char *prefix;

  PetscFunctionBegin;
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)c, &prefix));
  if (c->solver == HYLC_CLOTH_SOLVER_NEWTON && !c->snes) {
    SNESLineSearch ls;
    KSP            ksp;
    Vec            r;
    PetscCall(SNESCreate(comm, &c->snes));
    PetscCall(SNESSetOptionsPrefix(c->snes, prefix));
    PetscCall(SNESAppendOptionsPrefix(c->snes, "cloth_"));
    PetscCall(VecDuplicate(c->x, &r));
    PetscCall(SNESSetFunction(c->snes, r, FormGradient, c));
    PetscCall(VecDestroy(&r));
    PetscCall(SNESSetJacobian(c->snes, c->H, c->H, FormJacobian, c));
    PetscCall(SNESSetObjective(c->snes, FormObjective, c));
    PetscCall(SNESSetType(c->snes, SNESNEWTONLS));
    PetscCall(SNESGetLineSearch(c->snes, &ls));
    PetscCall(SNESLineSearchSetType(ls, SNESLINESEARCHSHELL));
    PetscCall(SNESLineSearchShellSetUserFunc(ls, LineSearchEnergy, c));
    PetscCall(SNESGetKSP(c->snes, &ksp));
    PetscCall(HylcClothDefaultKSP_Private(ksp, PETSC_TRUE));
    PetscCall(SNESSetTolerances(c->snes, c->atolUsed, c->rtol, 0.0, c->maxit, 100000));
    PetscCall(SNESSetFromOptions(c->snes));
  }
  if (c->solver == HYLC_CLOTH_SOLVER_TRUST && !c->tao) {
    KSP ksp;
    PetscCall(TaoCreate(comm, &c->tao));
    PetscCall(TaoSetOptionsPrefix(c->tao, prefix));
    PetscCall(TaoAppendOptionsPrefix(c->tao, "cloth_"));
    PetscCall(TaoSetType(c->tao, TAONTR));
    PetscCall(TaoSetSolution(c->tao, c->x));
    PetscCall(TaoSetObjectiveAndGradient(c->tao, NULL, TaoFG, c));
    PetscCall(TaoSetHessian(c->tao, c->H, c->H, TaoH, c));
    PetscCall(TaoSetUpdate(c->tao, TaoUpdate, c));
    PetscCall(TaoGetKSP(c->tao, &ksp));
    if (ksp) {
      PetscCall(KSPSetType(ksp, KSPSTCG));
      PetscCall(HylcClothDefaultKSP_Private(ksp, PETSC_FALSE));
    }
    PetscCall(TaoSetTolerances(c->tao, c->atolUsed, c->rtol, 0));
    PetscCall(TaoSetMaximumIterations(c->tao, c->maxit));
    PetscCall(TaoSetFromOptions(c->tao));
    if (!c->xprev) PetscCall(VecDuplicate(c->x, &c->xprev));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the norm of the gradient with the prescribed coordinates' entries kept (the clamps' reactions): the
   force scale of the tolerances */
PetscErrorCode HylcClothForceScale_Private(HylcCloth c, Vec X, PetscReal *F)
{
  PetscInt *fixedSave, nown = c->vend - c->vstart;
  Vec       G;
  PetscReal E;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(3 * nown, &fixedSave));
  PetscCall(PetscArraycpy(fixedSave, c->fixed, 3 * nown));
  for (PetscInt i = 0; i < 3 * nown; i++) c->fixed[i] = 0;
  PetscCall(VecDuplicate(X, &G));
  PetscCall(HylcClothEnergy_Private(c, X, &E, G));
  PetscCall(PetscArraycpy(c->fixed, fixedSave, 3 * nown));
  PetscCall(PetscFree(fixedSave));
  PetscCall(VecNorm(G, NORM_2, F));
  PetscCall(VecDestroy(&G));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Minimizes the energy from c->x (the clamps' coordinates set from the load parameter first). converged:
  the solver's own test passed. The iterations are added to c->newtonIts. Collective.
*/
PetscErrorCode HylcClothSolveStatic_Private(HylcCloth c, PetscBool *converged)
{
  PetscInt  its = 0;
  PetscReal Fref, atol;

  PetscFunctionBegin;
  PetscCall(SolverSetUp(c));
  PetscCall(HylcClothApplyClamps_Private(c, c->x));
  PetscCall(PetscLogEventBegin(HYLC_ClothSolve, c, 0, 0, 0));
  /* converged: the gradient norm (free coordinates) below rtol times the force scale (the gradient with
     the clamps' reactions), at least atol */
  PetscCall(HylcClothForceScale_Private(c, c->x, &Fref));
  atol = PetscMax(c->rtol * Fref, c->atolUsed);
  if (c->snes) PetscCall(SNESSetTolerances(c->snes, atol, 0.0, 0.0, c->maxit, 100000));
  if (c->tao) PetscCall(TaoSetTolerances(c->tao, atol, 0.0, 0.0));
  if (c->solver == HYLC_CLOTH_SOLVER_NEWTON) {
    SNESConvergedReason reason;
    PetscCall(SNESSolve(c->snes, NULL, c->x));
    PetscCall(SNESGetConvergedReason(c->snes, &reason));
    PetscCall(SNESGetIterationNumber(c->snes, &its));
    *converged = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
    if (reason == SNES_DIVERGED_LINE_SEARCH) { /* no decrease within rounding: converged if the gradient is nearly small enough */
      PetscReal fn;
      PetscCall(SNESGetFunctionNorm(c->snes, &fn));
      if (fn <= 100 * atol) *converged = PETSC_TRUE;
    }
    c->lastReason = (PetscInt)reason;
  } else {
    TaoConvergedReason reason;
    PetscCall(VecCopy(c->x, c->xprev));
    PetscCall(TaoSetSolution(c->tao, c->x));
    PetscCall(TaoSolve(c->tao));
    PetscCall(TaoGetConvergedReason(c->tao, &reason));
    PetscCall(TaoGetIterationNumber(c->tao, &its));
    *converged    = reason > 0 ? PETSC_TRUE : PETSC_FALSE;
    c->lastReason = (PetscInt)reason;
  }
  c->newtonIts += its;
  c->lastIts = its;
  PetscCall(PetscLogEventEnd(HYLC_ClothSolve, c, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The tangent predictor of a load step: from the equilibrium c->x at (load, gscale), the clamps move
  by (t1 - load) times their motion and gravity changes by (g1 - gscale): the linearized response
  K dx = -(K_fc dc + dgrad) with the projected Hessian K, so that the first Newton iterate does not
  crush the triangles next to a moving clamp. Collective.
*/
static PetscErrorCode TangentPredictor(HylcCloth c, PetscReal t1, PetscReal g1)
{
  PetscInt    *fixedSave, nown = c->vend - c->vstart;
  Vec          D, R, dx;
  PetscScalar *d, *r;
  KSP          ksp;

  PetscFunctionBegin;
  PetscCall(SolverSetUp(c));
  PetscCall(VecDuplicate(c->x, &D));
  PetscCall(VecDuplicate(c->x, &R));
  PetscCall(VecDuplicate(c->x, &dx));
  PetscCall(HylcClothApplyClamps_Private(c, c->x)); /* the fixed flags */
  PetscCall(PetscMalloc1(3 * nown, &fixedSave));
  PetscCall(PetscArraycpy(fixedSave, c->fixed, 3 * nown));
  PetscCall(VecGetArray(D, &d));
  for (PetscInt i = 0; i < 3 * nown; i++) d[i] = c->fixed[i] ? (t1 - c->load) * c->xprescribed[i] : 0;
  PetscCall(VecRestoreArray(D, &d));
  for (PetscInt i = 0; i < 3 * nown; i++) c->fixed[i] = 0;
  PetscCall(HylcClothHessian_Private(c, c->x, PETSC_TRUE, c->H));
  PetscCall(PetscArraycpy(c->fixed, fixedSave, 3 * nown));
  PetscCall(MatMult(c->H, D, R));
  PetscCall(VecGetArray(R, &r));
  for (PetscInt i = 0; i < nown; i++) {
    PetscReal m = c->rhoA * c->vmass[c->iperm[c->vstart + i]];
    for (int k = 0; k < 3; k++) r[3 * i + k] = fixedSave[3 * i + k] ? 0 : r[3 * i + k] - (g1 - c->gscale) * m * c->g[k];
  }
  PetscCall(VecRestoreArray(R, &r));
  PetscCall(PetscFree(fixedSave));
  PetscCall(HylcClothHessian_Private(c, c->x, PETSC_TRUE, c->H));
  if (c->solver == HYLC_CLOTH_SOLVER_NEWTON)
    PetscCall(SNESGetKSP(c->snes, &ksp));
  else
    PetscCall(TaoGetKSP(c->tao, &ksp));
  PetscCall(KSPSetOperators(ksp, c->H, c->H));
  PetscCall(HylcClothFactor_Private(ksp)); /* MUMPS' settings before its first analysis */
  PetscCall(KSPSolve(ksp, R, dx));
  {
    /* a linear response larger than a tenth of the specimen (a cantilever's first load step: linear
       theory deflects it by more than its length) is only a direction: scaled down to that */
    PetscReal          mx = 0, cap = 0.1 * PetscSqrtReal(c->area), sc = 1;
    const PetscScalar *a;
    PetscCall(VecGetArrayRead(dx, &a));
    for (PetscInt i = 0; i < nown; i++) mx = PetscMax(mx, PetscSqrtReal(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2]));
    PetscCall(VecRestoreArrayRead(dx, &a));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &mx, 1, MPIU_REAL, MPIU_MAX, PetscObjectComm((PetscObject)c)));
    if (mx > cap) sc = cap / mx;
    PetscCall(VecAXPY(c->x, 1.0, D));
    PetscCall(VecAXPY(c->x, -sc, dx));
  }
  PetscCall(VecDestroy(&D));
  PetscCall(VecDestroy(&R));
  PetscCall(VecDestroy(&dx));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Load stepping from the current state (at load c->load, gravity scale c->gscale) to load t1 and
  gravity scale g1 in at least c->loadSteps steps, each step's start predicted by extrapolating the last
  two; a step that does not converge is halved (down to 1/1024 of the first). converged: the final
  state is an equilibrium. Collective.
*/
PetscErrorCode HylcClothLoadPath_Private(HylcCloth c, PetscReal t1, PetscReal g1, PetscInt nsteps, PetscBool *converged)
{
  PetscReal t0 = c->load, gs0 = c->gscale, s = 0, ds = 1.0 / PetscMax(nsteps, 1), dsmin = ds / 1024;
  Vec       xa, xb; /* the last two converged states (for the predictor) */
  PetscBool havePrev = PETSC_FALSE;
  PetscReal sprev    = 0;

  PetscFunctionBegin;
  *converged = PETSC_TRUE;
  PetscCall(VecDuplicate(c->x, &xa));
  PetscCall(VecDuplicate(c->x, &xb));
  PetscCall(VecCopy(c->x, xa));
  while (s < 1 - 1e-14) {
    PetscReal sn = PetscMin(1.0, s + ds);
    PetscBool ok;
    c->load   = t0 + sn * (t1 - t0);
    c->gscale = gs0 + sn * (g1 - gs0);
    if (havePrev) { /* linear predictor from the last two converged states */
      PetscCall(VecCopy(xa, c->x));
      PetscCall(VecAXPBY(c->x, -(sn - s) / (s - sprev), 1.0 + (sn - s) / (s - sprev), xb));
    } else { /* the first step: the tangent predictor from the last equilibrium */
      PetscReal tn = c->load, gn = c->gscale;
      PetscCall(VecCopy(xa, c->x));
      c->load   = t0 + s * (t1 - t0);
      c->gscale = gs0 + s * (g1 - gs0);
      PetscCall(TangentPredictor(c, tn, gn));
      c->load   = tn;
      c->gscale = gn;
    }
    {
      PetscReal E;
      PetscCall(HylcClothApplyClamps_Private(c, c->x));
      PetscCall(HylcClothEnergy_Private(c, c->x, &E, NULL));
      if (HylcClothInfeasible(E)) { /* the prediction is infeasible: start from the last state */
        PetscCall(VecCopy(xa, c->x));
        PetscCall(HylcClothApplyClamps_Private(c, c->x));
        PetscCall(HylcClothEnergy_Private(c, c->x, &E, NULL));
      }
      PetscCheck(!HylcClothInfeasible(E), PetscObjectComm((PetscObject)c), PETSC_ERR_NOT_CONVERGED, "load step to %g: the clamps' motion makes a triangle degenerate or a vertex cross a support; use more -cloth_load_steps", (double)sn);
    }
    PetscCall(HylcClothSolveStatic_Private(c, &ok));
    if (c->monitor) PetscCall(PetscPrintf(PetscObjectComm((PetscObject)c), "  load step %.6g: %s in %" PetscInt_FMT " iterations\n", (double)sn, ok ? "converged" : "not converged", c->lastIts));
    if (!ok) {
      if (ds / 2 < dsmin) {
        *converged = PETSC_FALSE;
        break;
      }
      ds /= 2;
      continue;
    }
    c->loadStepsDone++;
    /* accept: the last two states for the predictor */
    PetscCall(VecCopy(xa, xb));
    sprev    = s;
    havePrev = PETSC_TRUE;
    PetscCall(VecCopy(c->x, xa));
    s  = sn;
    ds = PetscMin(ds * 1.5, 1.0 / PetscMax(nsteps, 1));
  }
  if (!*converged) { /* leave the last equilibrium */
    PetscCall(VecCopy(xa, c->x));
    c->load   = t0 + s * (t1 - t0);
    c->gscale = gs0 + s * (g1 - gs0);
  }
  PetscCall(VecDestroy(&xa));
  PetscCall(VecDestroy(&xb));
  PetscFunctionReturn(PETSC_SUCCESS);
}
