#pragma once
/* HylcChol: a supernodal sparse Cholesky factorization A = P^T L L^T P for the Newton matrices of the
   microscale solve (src/linalg/chol.c).

   The matrices are symmetric positive definite (after the regularization alpha I), of order 4 N for N
   yarn vertices, with a structure of 4 x 4 vertex blocks that changes rarely. HylcChol works on that
   block structure: a METIS nested-dissection ordering of the vertex graph, the elimination tree and the
   column structures of L on vertices, fundamental supernodes, and dense column-major supernode panels.
   Compared with PETSc's native Cholesky of the same SeqAIJ matrix (MATSOLVERPETSC), the symbolic phase
   is on a graph 16 times smaller, and the numeric phase runs dense 4 x 4 block kernels; see
   docs/performance.md for the figures.

   Usage:
     HylcCholCreate(&chol);
     HylcCholFactor(chol, A, 4, &ok);    symbolic phase when A's nonzero pattern changed, then numeric
     HylcCholSolve(chol, b, x);          x = A^-1 b
     HylcCholDestroy(&chol);
   A is a SeqAIJ matrix with a symmetric nonzero pattern and symmetric values; only the entries on and
   below the diagonal of the permuted matrix are read. Not collective. */
#include <hylc/sys.h>
#include <petscmat.h>

typedef struct _n_HylcChol *HylcChol;

/* Registration: the class id and log events of this stage (HylcCholInitializePackage(), called by
   HylcCholCreate()), and the solver type below (HylcCholRegisterSolverType()). */
PETSC_EXTERN PetscClassId   HYLC_CHOL_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_CholSymbolic, HYLC_CholNumeric, HYLC_CholSolve;
PETSC_EXTERN PetscErrorCode HylcCholInitializePackage(void);

typedef enum {
  HYLC_CHOL_ORDERING_METIS,  /* METIS_NodeND of the block graph (default) */
  HYLC_CHOL_ORDERING_NATURAL /* the order of A (tests) */
} HylcCholOrdering;

typedef struct {
  PetscInt       n, bs;               /* order and block size */
  PetscInt       nsuper;              /* supernodes */
  PetscCount     nnzL;                /* stored entries of L (dense supernode panels, diagonal blocks in full) */
  PetscCount     nnzA;                /* entries of A (both triangles) at the symbolic phase */
  PetscLogDouble flops;               /* floating-point operations of one numeric factorization */
  PetscInt       nsymbolic, nnumeric; /* phases run since creation */
} HylcCholInfo;

PETSC_EXTERN PetscErrorCode HylcCholCreate(HylcChol *);
PETSC_EXTERN PetscErrorCode HylcCholDestroy(HylcChol *);
PETSC_EXTERN PetscErrorCode HylcCholSetOrdering(HylcChol, HylcCholOrdering);
/* Relaxed supernodes (merged along the elimination tree at the price of a few explicit zeros); default
   false (measured: no gain on the paper's tiles, whose vertex blocks are already 4 columns wide). */
PETSC_EXTERN PetscErrorCode HylcCholSetRelaxed(HylcChol, PetscBool);
/* Factors A (block size bs, which must divide its order) as A = P^T L S L^T P, S = diag(+-1) the signs of
   the pivots: the Cholesky factorization when A is positive definite. *ok is PETSC_FALSE, and the factor
   unusable, when a pivot is zero or tiny (|d| <= 1e-14 |A_kk|), not finite, or negative while indefinite
   matrices are refused (the default: then *ok says whether A is positive definite). */
PETSC_EXTERN PetscErrorCode HylcCholFactor(HylcChol, Mat A, PetscInt bs, PetscBool *ok);
/* The symbolic phase alone (ordering, elimination tree, supernodes); HylcCholFactor() then runs only the
   numeric phase while A's nonzero pattern stays the same. */
PETSC_EXTERN PetscErrorCode HylcCholFactorSymbolic(HylcChol, Mat A, PetscInt bs);
/* Accept indefinite matrices (negative pivots; no pivoting, so only for matrices whose leading principal
   minors do not vanish, as regularized Hessians). Default PETSC_FALSE. */
PETSC_EXTERN PetscErrorCode HylcCholSetIndefinite(HylcChol, PetscBool);
/* The inertia of the last factored matrix (Sylvester): negative and positive eigenvalues. */
PETSC_EXTERN PetscErrorCode HylcCholGetInertia(HylcChol, PetscInt *nneg, PetscInt *npos);
/* x = A^-1 b with the last successful factorization; x may equal b. */
PETSC_EXTERN PetscErrorCode HylcCholSolve(HylcChol, const PetscScalar b[], PetscScalar x[]);
/* the same for nrhs right-hand sides stored one after the other (b[j n + i]); x may equal b */
PETSC_EXTERN PetscErrorCode HylcCholSolveMany(HylcChol, PetscInt nrhs, const PetscScalar b[], PetscScalar x[]);
PETSC_EXTERN PetscErrorCode HylcCholGetInfo(HylcChol, HylcCholInfo *);
PETSC_EXTERN PetscErrorCode HylcCholView(HylcChol, PetscViewer);

/* HylcChol as a PETSc solver type (src/linalg/matsolver.c), registered by HylcCholRegisterSolverType() for
   MATSEQAIJ and MAT_FACTOR_CHOLESKY: PCFactorSetMatSolverType(pc, MATSOLVERHYLC) or
   -pc_factor_mat_solver_type hylc (in hylc: -micro_factor_pc_factor_mat_solver_type hylc, the default).
   The factor implements MatCholeskyFactorSymbolic/Numeric, MatSolve, MatMatSolve (all columns of a dense
   right-hand side in one pass over L), MatGetInertia, MatGetInfo and MatView. It orders on its own (METIS
   nested dissection of the block graph; MatFactorGetCanUseOrdering() is false, so the PC's ordering is
   not used), takes the block size from A (MatGetBlockSize; 1 if unset) and accepts indefinite matrices
   (signed factorization, MatGetInertia() counts the negative pivots). A zero, tiny or non-finite pivot is
   a failed factorization (MAT_FACTOR_NUMERIC_ZEROPIVOT, or an error when A's error-if-failure is set). */
#define MATSOLVERHYLC "hylc"
PETSC_EXTERN PetscErrorCode MatGetFactor_SeqAIJ_Hylc(Mat, MatFactorType, Mat *);
/* Registers MATSOLVERHYLC with PETSc (after PETSc's own solver types, which stay the defaults); idempotent.
   Called by HylcCholInitializePackage() and, before it names the type, by every user of it
   (HylcMicroGetFactorPC()): a stage that names another stage's type in a PETSc registry registers that
   type through the owner's function, as PETSc's MatInitializePackage() registers the external solver
   types. Not collective. */
PETSC_EXTERN PetscErrorCode HylcCholRegisterSolverType(void);
