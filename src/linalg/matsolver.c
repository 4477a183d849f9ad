/* HylcChol as the PETSc solver type "hylc" (MATSOLVERHYLC, include/hylc/chol.h): the factor matrix that
   MatGetFactor(A, "hylc", MAT_FACTOR_CHOLESKY, &F) returns for a MATSEQAIJ matrix A. PCCHOLESKY drives it
   through the usual operations:
     MatCholeskyFactorSymbolic  -> HylcCholFactorSymbolic (its own METIS ordering of the block graph)
     MatCholeskyFactorNumeric   -> HylcCholFactor (numeric phase; a failed pivot sets the factor error)
     MatSolve                   -> HylcCholSolve
     MatMatSolve                -> HylcCholSolveMany (every column of a dense right-hand side in one pass)
     MatGetInertia              -> HylcCholGetInertia (no zero eigenvalues: a zero pivot fails)
     MatGetInfo, MatView, MatFactorGetSolverType, MatDestroy. */
#include <hylc/chol.h>
/* PETSc's private Mat header (the factor's operation table); its inline helpers have unused parameters */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <petsc/private/matimpl.h>
#pragma GCC diagnostic pop

typedef struct {
  HylcChol chol;
  PetscInt bs;
} Mat_Hylc;

static PetscErrorCode MatFactorGetSolverType_Hylc(Mat F, MatSolverType *type)
{
  PetscFunctionBegin;
  (void)F;
  *type = MATSOLVERHYLC;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatSolve_Hylc(Mat F, Vec b, Vec x)
{
  Mat_Hylc          *h = (Mat_Hylc *)F->data;
  const PetscScalar *ba;
  PetscScalar       *xa;

  PetscFunctionBegin;
  PetscCall(VecGetArrayRead(b, &ba));
  PetscCall(VecGetArrayWrite(x, &xa));
  PetscCall(HylcCholSolve(h->chol, ba, xa));
  PetscCall(VecRestoreArrayWrite(x, &xa));
  PetscCall(VecRestoreArrayRead(b, &ba));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* X = A^-1 B for dense B, X: one pass over the factor for all columns when both are stored contiguously */
static PetscErrorCode MatMatSolve_Hylc(Mat F, Mat B, Mat X)
{
  Mat_Hylc          *h = (Mat_Hylc *)F->data;
  const PetscScalar *ba;
  PetscScalar       *xa;
  PetscInt           n, nrhs, ldb, ldx;
  PetscBool          dense;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompareAny((PetscObject)B, &dense, MATSEQDENSE, MATDENSE, ""));
  PetscCheck(dense, PETSC_COMM_SELF, PETSC_ERR_SUP, "MatMatSolve with the hylc factor: the right-hand side must be MATSEQDENSE");
  PetscCall(PetscObjectTypeCompareAny((PetscObject)X, &dense, MATSEQDENSE, MATDENSE, ""));
  PetscCheck(dense, PETSC_COMM_SELF, PETSC_ERR_SUP, "MatMatSolve with the hylc factor: the solution must be MATSEQDENSE");
  PetscCall(MatGetSize(B, &n, &nrhs));
  PetscCall(MatDenseGetLDA(B, &ldb));
  PetscCall(MatDenseGetLDA(X, &ldx));
  PetscCall(MatDenseGetArrayRead(B, &ba));
  PetscCall(MatDenseGetArrayWrite(X, &xa));
  if (ldb == n && ldx == n)
    PetscCall(HylcCholSolveMany(h->chol, nrhs, ba, xa));
  else
    for (PetscInt j = 0; j < nrhs; j++) PetscCall(HylcCholSolve(h->chol, ba + (size_t)j * ldb, xa + (size_t)j * ldx));
  PetscCall(MatDenseRestoreArrayWrite(X, &xa));
  PetscCall(MatDenseRestoreArrayRead(B, &ba));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatGetInertia_Hylc(Mat F, PetscInt *nneg, PetscInt *nzero, PetscInt *npos)
{
  Mat_Hylc *h = (Mat_Hylc *)F->data;

  PetscFunctionBegin;
  PetscCall(HylcCholGetInertia(h->chol, nneg, npos));
  if (nzero) *nzero = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatCholeskyFactorNumeric_Hylc(Mat F, Mat A, const MatFactorInfo *info)
{
  Mat_Hylc *h = (Mat_Hylc *)F->data;
  PetscBool ok;

  PetscFunctionBegin;
  (void)info;
  F->factorerrortype = MAT_FACTOR_NOERROR;
  PetscCall(HylcCholFactor(h->chol, A, h->bs, &ok));
  if (!ok) {
    PetscCheck(!A->erroriffailure, PETSC_COMM_SELF, PETSC_ERR_MAT_CH_ZRPVT, "HylcChol: zero, tiny or non-finite pivot");
    PetscCall(PetscInfo(F, "HylcChol: zero, tiny or non-finite pivot\n"));
    F->factorerrortype = MAT_FACTOR_NUMERIC_ZEROPIVOT;
  }
  F->assembled    = PETSC_TRUE;
  F->preallocated = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* perm is ignored (canuseordering is false): HylcChol orders the block graph itself */
static PetscErrorCode MatCholeskyFactorSymbolic_Hylc(Mat F, Mat A, IS perm, const MatFactorInfo *info)
{
  Mat_Hylc *h = (Mat_Hylc *)F->data;
  PetscInt  bs;

  PetscFunctionBegin;
  (void)perm;
  (void)info;
  PetscCall(MatGetBlockSize(A, &bs));
  h->bs = bs >= 1 ? bs : 1;
  PetscCall(HylcCholFactorSymbolic(h->chol, A, h->bs));
  F->ops->choleskyfactornumeric = MatCholeskyFactorNumeric_Hylc;
  F->ops->solve                 = MatSolve_Hylc;
  F->ops->matsolve              = MatMatSolve_Hylc;
  F->ops->getinertia            = MatGetInertia_Hylc;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatGetInfo_Hylc(Mat F, MatInfoType flag, MatInfo *info)
{
  Mat_Hylc    *h = (Mat_Hylc *)F->data;
  HylcCholInfo ci;

  PetscFunctionBegin;
  (void)flag;
  PetscCall(PetscMemzero(info, sizeof(*info)));
  PetscCall(HylcCholGetInfo(h->chol, &ci));
  info->block_size   = (PetscLogDouble)h->bs;
  info->nz_allocated = (PetscLogDouble)ci.nnzL;
  info->nz_used      = (PetscLogDouble)ci.nnzL;
  info->memory       = (PetscLogDouble)ci.nnzL * sizeof(PetscReal);
  info->assemblies   = (PetscLogDouble)ci.nnumeric;
  /* against the lower triangle of A (the dense panels also store the upper half of their diagonal blocks) */
  info->fill_ratio_needed = ci.nnzA > 0 ? (PetscLogDouble)ci.nnzL / (0.5 * (ci.nnzA + ci.n)) : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatView_Hylc(Mat F, PetscViewer viewer)
{
  Mat_Hylc         *h = (Mat_Hylc *)F->data;
  PetscBool         ascii;
  PetscViewerFormat format;

  PetscFunctionBegin;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscViewerGetFormat(viewer, &format));
  if (format == PETSC_VIEWER_ASCII_INFO || format == PETSC_VIEWER_ASCII_INFO_DETAIL) PetscCall(HylcCholView(h->chol, viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode MatDestroy_Hylc(Mat F)
{
  Mat_Hylc *h = (Mat_Hylc *)F->data;

  PetscFunctionBegin;
  PetscCall(HylcCholDestroy(&h->chol));
  PetscCall(PetscFree(F->data));
  PetscCall(PetscObjectComposeFunction((PetscObject)F, "MatFactorGetSolverType_C", NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  MatGetFactor_SeqAIJ_Hylc - The factor matrix of the solver type "hylc" (MATSOLVERHYLC) for a MATSEQAIJ
  matrix; called by MatGetFactor(), registered by HylcCholRegisterSolverType(). Not collective (sequential).

  Input Parameters:
+ A     - the MATSEQAIJ matrix (symmetric structure and values; block size from MatGetBlockSize())
- ftype - MAT_FACTOR_CHOLESKY (the only type supported)

  Output Parameter:
. F - the factor matrix, ready for MatCholeskyFactorSymbolic()
@*/
PetscErrorCode MatGetFactor_SeqAIJ_Hylc(Mat A, MatFactorType ftype, Mat *F)
{
  Mat       B;
  Mat_Hylc *h;
  PetscInt  m, n;

  PetscFunctionBegin;
  PetscCheck(ftype == MAT_FACTOR_CHOLESKY, PETSC_COMM_SELF, PETSC_ERR_SUP, "The hylc solver type only does Cholesky factorizations, not %s", MatFactorTypes[ftype]);
  PetscCall(MatGetSize(A, &m, &n));
  PetscCheck(m == n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "The hylc solver type needs a square matrix, not %" PetscInt_FMT " x %" PetscInt_FMT, m, n);
  PetscCall(MatCreate(PetscObjectComm((PetscObject)A), &B));
  PetscCall(MatSetSizes(B, m, n, m, n));
  PetscCall(PetscStrallocpy(MATSOLVERHYLC, &((PetscObject)B)->type_name));
  PetscCall(MatSetUp(B));
  PetscCall(PetscNew(&h));
  PetscCall(HylcCholCreate(&h->chol));
  PetscCall(HylcCholSetIndefinite(h->chol, PETSC_TRUE));
  h->bs   = 1;
  B->data = h;

  B->ops->choleskyfactorsymbolic = MatCholeskyFactorSymbolic_Hylc;
  B->ops->getinfo                = MatGetInfo_Hylc;
  B->ops->view                   = MatView_Hylc;
  B->ops->destroy                = MatDestroy_Hylc;
  PetscCall(PetscObjectComposeFunction((PetscObject)B, "MatFactorGetSolverType_C", MatFactorGetSolverType_Hylc));
  B->factortype     = MAT_FACTOR_CHOLESKY;
  B->canuseordering = PETSC_FALSE;
  B->assembled      = PETSC_TRUE;
  B->preallocated   = PETSC_TRUE;
  PetscCall(PetscFree(B->solvertype));
  PetscCall(PetscStrallocpy(MATSOLVERHYLC, &B->solvertype));
  *F = B;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscBool HylcCholSolverTypeRegistered = PETSC_FALSE;

static PetscErrorCode HylcCholFinalizeSolverType(void)
{
  PetscFunctionBegin;
  HylcCholSolverTypeRegistered = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcCholRegisterSolverType - Registers the solver type "hylc" (MATSOLVERHYLC) for MATSEQAIJ and
  MAT_FACTOR_CHOLESKY with MatSolverTypeRegister(), after PETSc's own solver types (which stay the
  defaults). Called by HylcCholInitializePackage() and by a stage before it names the type
  (HylcMicroGetFactorPC()); idempotent.

  Not collective

  Level: developer

.seealso: MatGetFactor_SeqAIJ_Hylc(), HylcCholInitializePackage()
@*/
PetscErrorCode HylcCholRegisterSolverType(void)
{
  PetscFunctionBegin;
  if (HylcCholSolverTypeRegistered) PetscFunctionReturn(PETSC_SUCCESS);
  HylcCholSolverTypeRegistered = PETSC_TRUE;
  PetscCall(MatInitializePackage()); /* PETSc's own solver types first: they stay the defaults */
  PetscCall(MatSolverTypeRegister(MATSOLVERHYLC, MATSEQAIJ, MAT_FACTOR_CHOLESKY, MatGetFactor_SeqAIJ_Hylc));
  PetscCall(PetscRegisterFinalize(HylcCholFinalizeSolverType));
  PetscFunctionReturn(PETSC_SUCCESS);
}
