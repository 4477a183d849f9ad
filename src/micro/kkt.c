/* HylcMicro: the KKT preconditioner (S22), a PCSHELL that solves the constrained Newton system by a Schur
   complement around an ordinary PCCHOLESKY of K (prefix <micro_>factor_). The solver type of that
   factorization is PETSc's choice (-micro_factor_pc_factor_mat_solver_type hylc|petsc|cholmod|mumps,
   default hylc: HylcChol, include/hylc/chol.h); the ordering is METIS nested dissection (metisnd) for the
   solver types that use the PC's ordering. Indefiniteness is detected the same way for every solver type:
   a failed factorization (PCGetFailedReason), negative pivots counted by MatGetInertia() when indefinite
   matrices are refused (-micro_factor_indefinite false), and the descent and curvature test of the step. */
#include <hylc/private/microimpl.h>
#include <hylc/chol.h>
#include <hylc/geom.h>
#include <petsctime.h>

/* the constraint-row buffers and the dense n x m right-hand sides of the Schur complement */
PetscErrorCode HylcMicroResizeKKT_Private(HylcMicro M, PetscInt m)
{
  PetscFunctionBegin;
  PetscCall(HylcMicroDestroyKKT_Private(M));
  M->m = m;
  PetscCall(PetscMalloc6(M->m, &M->c, M->m * M->ny, &M->Z, M->m * M->m, &M->S, M->m * M->m, &M->Sinv, M->m, &M->wl, M->m, &M->tmp));
  PetscCall(PetscMalloc1(M->m * M->ny, &M->Bw));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, M->ny, M->m, M->Bw, &M->Bd));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, M->ny, M->m, M->Z, &M->Zd));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroDestroyKKT_Private(HylcMicro M)
{
  PetscFunctionBegin;
  PetscCall(MatDestroy(&M->Bd));
  PetscCall(MatDestroy(&M->Zd));
  PetscCall(PetscFree(M->Bw));
  PetscCall(PetscFree6(M->c, M->Z, M->S, M->Sinv, M->wl, M->tmp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* is the factor positive definite? (only asked when indefinite matrices are refused) */
static PetscErrorCode FactorPositive(HylcMicro M, PetscBool *pos)
{
  Mat           F;
  MatSolverType type;
  PetscBool     inertia, mumps;
  PetscInt      nneg = 0, nzero = 0;

  PetscFunctionBegin;
  *pos = PETSC_TRUE;
  PetscCall(PCFactorGetMatrix(M->inner, &F));
  PetscCall(MatFactorGetSolverType(F, &type));
  /* the solver types with MatGetInertia for a Cholesky factor of SeqAIJ; CHOLMOD fails on an indefinite K */
  {
    const char *const withInertia[] = {MATSOLVERHYLC, MATSOLVERPETSC, MATSOLVERMUMPS};
    inertia                         = PETSC_FALSE;
    for (int k = 0; k < 3 && !inertia; k++) PetscCall(PetscStrcmp(type, withInertia[k], &inertia));
  }
  if (!inertia) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscStrcmp(type, MATSOLVERMUMPS, &mumps));
  if (mumps) { /* MatGetInertia needs ICNTL(24) = 1 with MUMPS; INFOG(12), the negative pivots, does not */
#if defined(PETSC_HAVE_MUMPS)
    PetscCall(MatMumpsGetInfog(F, 12, &nneg));
#endif
  } else
    PetscCall(MatGetInertia(F, &nneg, &nzero, NULL));
  *pos = (PetscBool)(nneg == 0 && nzero == 0);
  if (!*pos) PetscCall(PetscInfo(M, "Newton matrix indefinite (%" PetscInt_FMT " negative, %" PetscInt_FMT " zero pivots) and -micro_factor_indefinite false or -micro_alpha_schedule adaptive\n", nneg, nzero));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* factor K and form the Schur complement data Z = K^-1 M A^T and S^-1 = (A M Z)^-1 */
static PetscErrorCode KKTFactor(HylcMicro M, PetscBool *ok)
{
  const PetscInt n = M->ny, m = M->m;
  PCFailedReason reason;
  PetscLogDouble t0, t1;

  PetscFunctionBegin;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogEventBegin(HYLC_MicroFactor, M, 0, 0, 0));
  /* a zero pivot is reported by the factorizations as a failed reason, not an error (the matrix's
     erroriffailure is false): that is the regularization's job; any error is an error */
  PetscCall(PCSetOperators(M->inner, M->K, M->K));
  if (!M->cholmod) {
    PetscCall(PCSetUp(M->inner));
    PetscCall(PCGetFailedReason(M->inner, &reason));
  } else {
    /* PETSc 3.18's CHOLMOD interface raises PETSC_ERR_MAT_CH_ZRPVT for a matrix that is not positive
       definite, whatever the error-if-failure flag: that error is a failed factorization here */
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = PCSetUp(M->inner);
    PetscCall(PetscPopErrorHandler());
    if (ierr == PETSC_ERR_MAT_CH_ZRPVT)
      reason = PC_FACTOR_NUMERIC_ZEROPIVOT;
    else {
      PetscCall(ierr);
      PetscCall(PCGetFailedReason(M->inner, &reason));
    }
  }
  *ok = (PetscBool)(reason == PC_NOERROR);
  if (!*ok) PetscCall(PetscInfo(M, "factorization of the Newton matrix failed: %s\n", PCFailedReasons[reason]));
  /* the adaptive schedule refuses an indefinite K whatever -micro_factor_indefinite says: its alpha^ is
     lowered until the quadratic model has negative curvature, and such steps end in saddle points */
  if (*ok && (!M->par.indefinite || M->par.alphaSched == HYLC_MICRO_ALPHA_ADAPTIVE)) PetscCall(FactorPositive(M, ok));
  if (*ok) { /* Z = K^-1 M A^T: all m right-hand sides in one MatMatSolve */
    Mat F;
    for (PetscInt i = 0; i < m; i++)
      for (PetscInt k = 0; k < n; k++) M->Bw[i * n + k] = M->A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0);
    PetscCall(PCFactorGetMatrix(M->inner, &F));
    if (m > 0) PetscCall(MatMatSolve(F, M->Bd, M->Zd));
    for (PetscInt i = 0; i < m; i++)
      for (PetscInt j = 0; j < m; j++) {
        PetscReal s = 0;
        for (PetscInt k = 0; k < n; k++) s += M->A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0) * M->Z[j * n + k];
        M->S[i * m + j] = s;
      }
    *ok = (PetscBool)(HylcDenseInverse((int)m, M->S, M->Sinv, 0.0) == 0);
  }
  PetscCall(PetscLogEventEnd(HYLC_MicroFactor, M, 0, 0, 0));
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
  PetscCall(PetscInfo(M, "indefinite Newton matrix: alpha x 10 -> %g\n", (double)M->alpha));
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
  PetscCall(PCApply(M->inner, b, x));
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

/* the KKT PCSHELL pc of the SNES's KSP around the inner PCCHOLESKY (HylcMicroGetFactorPC()): set when the
   SNES is created, before any option is read */
PetscErrorCode HylcMicroSetKKT_Private(HylcMicro M, PC pc)
{
  PC inner;

  PetscFunctionBegin;
  PetscCall(HylcMicroGetFactorPC(M, &inner));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, M));
  PetscCall(PCShellSetSetUp(pc, KKTSetUp));
  PetscCall(PCShellSetApply(pc, KKTApply));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* at set-up, once the options are read: the factorization's solver type (CHOLMOD's errors are handled
   apart) and the name of the KKT shell, which shows it */
PetscErrorCode HylcMicroSetUpKKT_Private(HylcMicro M, PC pc)
{
  MatSolverType type;
  char          name[256];

  PetscFunctionBegin;
  PetscCall(PCFactorGetMatSolverType(M->inner, &type));
  PetscCall(PetscStrcmp(type, MATSOLVERCHOLMOD, &M->cholmod));
  PetscCall(PetscSNPrintf(name, sizeof(name), "hylc KKT (S22): Schur complement around PCCHOLESKY, solver type %s (-%sfactor_pc_factor_mat_solver_type)", type ? type : "default", ((PetscObject)M)->prefix ? ((PetscObject)M)->prefix : ""));
  PetscCall(PCShellSetName(pc, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
