/* HylcMicro: the KKT preconditioner (S22), a PCSHELL that solves the constrained Newton system by a Schur
   complement around an ordinary PCCHOLESKY of K (prefix <prefix>micro_factor_). The solver type of that
   factorization is PETSc's choice (-micro_factor_pc_factor_mat_solver_type hylc|petsc|cholmod|mumps,
   default hylc: HylcChol, include/hylc/chol.h); the ordering is METIS nested dissection (metisnd) for the
   solver types that use the PC's ordering. Indefiniteness is detected the same way for every solver type:
   a failed factorization (PCGetFailedReason), negative pivots counted by MatGetInertia() when indefinite
   matrices are refused (-micro_factor_indefinite false), and the descent and curvature test of the step. */
#include <hylc/private/microimpl.h>
#include <hylc/chol.h>
#include <hylc/geom.h>
#include <petsctime.h>
#include <petscblaslapack.h>

/* the constraint-row buffers and the dense n x m right-hand sides of the Schur complement */
PetscErrorCode HylcMicroResizeKKT_Private(HylcMicro M, PetscInt m)
{
  PetscFunctionBegin;
  PetscCall(HylcMicroDestroyKKT_Private(M));
  M->m = m;
  PetscCall(PetscMalloc6(M->m, &M->kkt.c, M->m * M->ny, &M->kkt.Z, M->m * M->m, &M->kkt.S, M->m * M->m, &M->kkt.Sinv, M->m, &M->kkt.wl, M->m, &M->kkt.tmp));
  PetscCall(PetscMalloc1(M->m * M->ny, &M->kkt.Bw));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, M->ny, M->m, M->kkt.Bw, &M->kkt.Bd));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, M->ny, M->m, M->kkt.Z, &M->kkt.Zd));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMicroDestroyKKT_Private(HylcMicro M)
{
  PetscFunctionBegin;
  PetscCall(MatDestroy(&M->kkt.Bd));
  PetscCall(MatDestroy(&M->kkt.Zd));
  PetscCall(PetscFree(M->kkt.Bw));
  PetscCall(PetscFree6(M->kkt.c, M->kkt.Z, M->kkt.S, M->kkt.Sinv, M->kkt.wl, M->kkt.tmp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the inertia of the factor: *have false for a solver type without MatGetInertia (CHOLMOD, which fails on
   an indefinite K instead) */
static PetscErrorCode FactorInertia(HylcMicro M, PetscBool *have, PetscInt *nneg, PetscInt *nzero)
{
  Mat           F;
  MatSolverType type;
  PetscBool     inertia, mumps;

  PetscFunctionBegin;
  *nneg = *nzero = 0;
  PetscCall(PCFactorGetMatrix(M->kkt.inner, &F));
  PetscCall(MatFactorGetSolverType(F, &type));
  /* the solver types with MatGetInertia for a Cholesky factor of SeqAIJ; CHOLMOD fails on an indefinite K */
  {
    const char *const withInertia[] = {MATSOLVERHYLC, MATSOLVERPETSC, MATSOLVERMUMPS};
    inertia                         = PETSC_FALSE;
    for (int k = 0; k < 3 && !inertia; k++) PetscCall(PetscStrcmp(type, withInertia[k], &inertia));
  }
  *have = inertia;
  if (!inertia) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscStrcmp(type, MATSOLVERMUMPS, &mumps));
  if (mumps) { /* MatGetInertia needs ICNTL(24) = 1 with MUMPS; INFOG(12), the negative pivots, does not */
#if defined(PETSC_HAVE_MUMPS)
    PetscCall(MatMumpsGetInfog(F, 12, nneg));
#endif
  } else
    PetscCall(MatGetInertia(F, nneg, nzero, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the number of positive eigenvalues of the m x m Schur complement S = B^T K^-1 B (B = M A^T) */
static PetscErrorCode SchurPositive(HylcMicro M, PetscInt *npos)
{
  PetscBLASInt n, lwork, info;
  PetscReal   *a, *w, *work;

  PetscFunctionBegin;
  *npos = 0;
  if (M->m == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscBLASIntCast(M->m, &n));
  lwork = 8 * n;
  PetscCall(PetscMalloc3(M->m * M->m, &a, M->m, &w, lwork, &work));
  for (PetscInt i = 0; i < M->m * M->m; i++) a[i] = 0.5 * (M->kkt.S[i] + M->kkt.S[(i % M->m) * M->m + i / M->m]);
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("N", "U", &n, a, &n, w, work, &lwork, &info));
  PetscCheck(info == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "LAPACK syev of the %" PetscInt_FMT " x %" PetscInt_FMT " Schur complement failed: info %d", M->m, M->m, (int)info);
  for (PetscInt i = 0; i < M->m; i++) *npos += w[i] > 0;
  PetscCall(PetscFree3(a, w, work));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* factor K and form the Schur complement data Z = K^-1 M A^T and S^-1 = (A M Z)^-1 */
PetscErrorCode HylcMicroKKTFactor_Private(HylcMicro M, PetscBool *ok)
{
  const PetscInt n = M->ny, m = M->m;
  PCFailedReason reason;
  PetscLogDouble t0, t1;

  PetscFunctionBegin;
  PetscCall(PetscTime(&t0));
  PetscCall(PetscLogEventBegin(HYLC_MicroFactor, M, 0, 0, 0));
  /* a zero pivot is reported by the factorizations as a failed reason, not an error (the matrix's
     erroriffailure is false): that is the regularization's job; any error is an error */
  PetscCall(PCSetOperators(M->kkt.inner, M->K, M->K));
  if (!M->kkt.cholmod) {
    PetscCall(PCSetUp(M->kkt.inner));
    PetscCall(PCGetFailedReason(M->kkt.inner, &reason));
  } else {
    /* PETSc 3.18's CHOLMOD interface raises PETSC_ERR_MAT_CH_ZRPVT for a matrix that is not positive
       definite, whatever the error-if-failure flag: that error is a failed factorization here */
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = PCSetUp(M->kkt.inner);
    PetscCall(PetscPopErrorHandler());
    if (ierr == PETSC_ERR_MAT_CH_ZRPVT)
      reason = PC_FACTOR_NUMERIC_ZEROPIVOT;
    else {
      PetscCall(ierr);
      PetscCall(PCGetFailedReason(M->kkt.inner, &reason));
    }
  }
  *ok = (PetscBool)(reason == PC_NOERROR);
  if (!*ok) PetscCall(PetscInfo(M, "factorization of the Newton matrix failed: %s\n", PCFailedReasons[reason]));
  /* -micro_factor_indefinite false refuses any negative or zero pivot of K; the adaptive schedule (and the
     hybrid one after its switch) refuses a K that is indefinite on the tangent space of the constraints,
     whatever -micro_factor_indefinite says: its alpha^ is lowered until the quadratic model has negative
     curvature, and such steps end in saddle points. By Haynsworth's inertia additivity, with B = M A^T of
     full column rank m and S = B^T K^-1 B, the projected matrix Z^T K Z has #neg(K) + #pos(S) - m
     negative eigenvalues. */
  M->st.projNeg  = 0;
  PetscInt  nneg = 0, nzero = 0;
  PetscBool have = PETSC_FALSE;
  if (*ok && (!M->par.indefinite || M->st.adapting)) {
    PetscCall(FactorInertia(M, &have, &nneg, &nzero));
    if (have && (nzero > 0 || (nneg > 0 && !M->st.adapting))) {
      *ok = PETSC_FALSE;
      PetscCall(PetscInfo(M, "Newton matrix indefinite (%" PetscInt_FMT " negative, %" PetscInt_FMT " zero pivots) and -micro_factor_indefinite false\n", nneg, nzero));
    }
  }
  if (*ok) { /* Z = K^-1 M A^T: all m right-hand sides in one MatMatSolve */
    Mat F;
    for (PetscInt i = 0; i < m; i++)
      for (PetscInt k = 0; k < n; k++) M->kkt.Bw[i * n + k] = M->kkt.A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0);
    PetscCall(PCFactorGetMatrix(M->kkt.inner, &F));
    if (m > 0) PetscCall(MatMatSolve(F, M->kkt.Bd, M->kkt.Zd));
    for (PetscInt i = 0; i < m; i++)
      for (PetscInt j = 0; j < m; j++) {
        PetscReal s = 0;
        for (PetscInt k = 0; k < n; k++) s += M->kkt.A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0) * M->kkt.Z[j * n + k];
        M->kkt.S[i * m + j] = s;
      }
    /* adapting: the inertia on the tangent space of the constraints, from S before HylcDenseInverse()
       overwrites it (its work array) */
    PetscInt npos = 0;
    if (have && nneg > 0) PetscCall(SchurPositive(M, &npos));
    *ok = (PetscBool)(HylcDenseInverse((int)m, M->kkt.S, M->kkt.Sinv, 0.0) == 0);
    if (*ok && have && nneg > 0) {
      M->st.projNeg = nneg + npos - m;
      if (M->st.projNeg > 0) {
        *ok = PETSC_FALSE;
        PetscCall(PetscInfo(M, "Newton matrix indefinite on the constraints' tangent space (%" PetscInt_FMT " negative eigenvalues; %" PetscInt_FMT " negative pivots of K)\n", M->st.projNeg, nneg));
      }
    }
  }
  PetscCall(PetscLogEventEnd(HYLC_MicroFactor, M, 0, 0, 0));
  PetscCall(PetscTime(&t1));
  M->st.tFactor += t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode KKTSetUp(PC pc)
{
  HylcMicro M;
  PetscBool ok;

  PetscFunctionBegin;
  PetscCall(PCShellGetContext(pc, &M));
  PetscCall(HylcMicroKKTFactor_Private(M, &ok));
  if (!ok) PetscCall(HylcMicroRegularizationRevert_Private(M, &ok));
  for (PetscInt k = 0; !ok && k < M->par.maxRetries; k++) PetscCall(HylcMicroRegularizationIncrease_Private(M, &ok));
  /* no step: the line search ends the solve (status stalled, or nonfinite for a non-finite matrix) */
  if (!ok) M->st.factorFailed = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* x = -w_y, the KKT solution (S22) for b = M g: x = K^-1 b + Z S^-1 (c - A M K^-1 b) (SNES steps X - x) */
PetscErrorCode HylcMicroKKTSolve_Private(HylcMicro M, Vec b, Vec x)
{
  const PetscInt n = M->ny, m = M->m;
  PetscScalar   *xa;

  PetscFunctionBegin;
  PetscCall(PCApply(M->kkt.inner, b, x));
  PetscCall(VecGetArray(x, &xa));
  for (PetscInt i = 0; i < m; i++) {
    PetscReal s = M->kkt.c[i];
    for (PetscInt k = 0; k < n; k++) s -= M->kkt.A[i * n + k] * ((k % 4 == 3) ? M->mu : 1.0) * PetscRealPart(xa[k]);
    M->kkt.tmp[i] = s;
  }
  for (PetscInt i = 0; i < m; i++) {
    M->kkt.wl[i] = 0;
    for (PetscInt j = 0; j < m; j++) M->kkt.wl[i] += M->kkt.Sinv[i * m + j] * M->kkt.tmp[j];
  }
  for (PetscInt k = 0; k < n; k++) {
    PetscReal s = 0;
    for (PetscInt i = 0; i < m; i++) s += M->kkt.Z[i * n + k] * M->kkt.wl[i];
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
  if (M->st.factorFailed) {
    PetscCall(VecSet(x, 0));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecDuplicate(x, &Kx));
  for (PetscInt k = 0;; k++) {
    PetscBool ok;
    PetscCall(HylcMicroKKTSolve_Private(M, b, x));
    /* a descent direction of positive curvature; otherwise K is too indefinite: regularize more */
    PetscCall(VecDot(b, x, &descent));
    PetscCall(MatMult(M->K, x, Kx));
    PetscCall(VecDot(x, Kx, &curv));
    if ((PetscRealPart(descent) > 0 && PetscRealPart(curv) > 0) || k >= M->par.maxRetries) break;
    PetscCall(HylcMicroRegularizationIncrease_Private(M, &ok));
    if (!ok) {
      M->st.factorFailed = PETSC_TRUE;
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
  PetscCall(PCFactorGetMatSolverType(M->kkt.inner, &type));
  PetscCall(PetscStrcmp(type, MATSOLVERCHOLMOD, &M->kkt.cholmod));
  PetscCall(PetscSNPrintf(name, sizeof(name), "hylc KKT (S22): Schur complement around PCCHOLESKY, solver type %s (-%smicro_factor_pc_factor_mat_solver_type)", type ? type : "default", ((PetscObject)M)->prefix ? ((PetscObject)M)->prefix : ""));
  PetscCall(PCShellSetName(pc, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
