/* The ordering "metisnd" (METIS_NodeND, registered by HylcSysInitializePackage()):
   - it returns a valid permutation, equal for rows and columns, for a 2D 5-point Laplacian, a structurally
     unsymmetric matrix, a matrix with disconnected blocks, a diagonal, a 1x1 and an empty matrix, and the
     reduced Hessian H_y of a bent stockinette tile (HylcPeriodic) shifted to K = H_y + |H_y|_inf I (SPD
     by Gershgorin; its rows come in inodes of 4, which the ordering must keep together for PETSc's inode
     LU to be correct);
   - PETSc's native Cholesky (MATSOLVERPETSC) and LU with it solve K x = b to a relative residual of
     1e-10, directly (MatGetFactor + MatGetOrdering) and through KSPPREONLY + PCCHOLESKY with
     -pc_factor_mat_ordering_type metisnd;
   - on the Laplacian its factor is much sparser than the natural ordering's;
   - its options are read (-hylc_metis_nseps, -hylc_metis_seed) and a bad value is a user-input error. */
#include <hylc/periodic.h>
#include <petscksp.h>
#include "hylctest.h"
#include "tilehessian.h"

/* checks that the ordering of A is a permutation, the same for rows and columns */
static PetscErrorCode CheckOrdering(Mat A, const char *what, IS *rowOut, IS *colOut)
{
  IS              row, col;
  PetscInt        n, nr, nc;
  const PetscInt *r, *c;
  PetscBool      *seen;

  PetscFunctionBegin;
  PetscCall(MatGetSize(A, &n, NULL));
  PetscCall(MatGetOrdering(A, MATORDERINGMETISND, &row, &col));
  PetscCall(ISGetLocalSize(row, &nr));
  PetscCall(ISGetLocalSize(col, &nc));
  HYLC_CHECK(nr == n && nc == n, "%s: permutation sizes %d, %d for a matrix of size %d", what, (int)nr, (int)nc, (int)n);
  if (nr == n && nc == n) {
    PetscCall(ISGetIndices(row, &r));
    PetscCall(ISGetIndices(col, &c));
    PetscCall(PetscCalloc1(n + 1, &seen));
    PetscInt bad = 0, diff = 0;
    for (PetscInt i = 0; i < n; i++) {
      if (r[i] < 0 || r[i] >= n || seen[r[i]])
        bad++;
      else
        seen[r[i]] = PETSC_TRUE;
      if (r[i] != c[i]) diff++;
    }
    HYLC_CHECK(bad == 0, "%s: %d invalid or repeated entries in the row permutation", what, (int)bad);
    HYLC_CHECK(diff == 0, "%s: row and column permutations differ in %d places", what, (int)diff);
    PetscCall(PetscFree(seen));
    PetscCall(ISRestoreIndices(row, &r));
    PetscCall(ISRestoreIndices(col, &c));
  }
  if (rowOut)
    *rowOut = row;
  else
    PetscCall(ISDestroy(&row));
  if (colOut)
    *colOut = col;
  else
    PetscCall(ISDestroy(&col));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* |A x - b| / |b| for a random b and x = F^-1 b */
static PetscErrorCode Residual(Mat A, Mat F, PetscReal *res)
{
  Vec         x, b, r;
  PetscRandom rnd;
  PetscReal   nb, nr;

  PetscFunctionBegin;
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  PetscCall(PetscRandomSetSeed(rnd, 17));
  PetscCall(PetscRandomSeed(rnd));
  PetscCall(VecSetRandom(b, rnd));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MatSolve(F, b, x));
  PetscCall(MatMult(A, x, r));
  PetscCall(VecAXPY(r, -1, b));
  PetscCall(VecNorm(b, NORM_2, &nb));
  PetscCall(VecNorm(r, NORM_2, &nr));
  *res = nb > 0 ? nr / nb : nr;
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* factors A (Cholesky if chol, else LU) with the ordering `type`; returns the relative residual of a
   solve and the nonzeros of the factor */
static PetscErrorCode FactorSolve(Mat A, MatOrderingType type, PetscBool chol, PetscReal *res, PetscReal *nz)
{
  Mat           F;
  IS            row, col;
  MatFactorInfo info;
  MatInfo       minfo;

  PetscFunctionBegin;
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatGetOrdering(A, type, &row, &col));
  PetscCall(MatGetFactor(A, MATSOLVERPETSC, chol ? MAT_FACTOR_CHOLESKY : MAT_FACTOR_LU, &F));
  if (chol) {
    PetscCall(MatCholeskyFactorSymbolic(F, A, row, &info));
    PetscCall(MatCholeskyFactorNumeric(F, A, &info));
  } else {
    PetscCall(MatLUFactorSymbolic(F, A, row, col, &info));
    PetscCall(MatLUFactorNumeric(F, A, &info));
  }
  PetscCall(Residual(A, F, res));
  PetscCall(MatGetInfo(F, MAT_LOCAL, &minfo));
  *nz = minfo.nz_used;
  PetscCall(ISDestroy(&row));
  PetscCall(ISDestroy(&col));
  PetscCall(MatDestroy(&F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ordering checks, Cholesky (if spd) and LU with metisnd, and the same solve through a KSP */
static PetscErrorCode CheckMatrix(Mat A, const char *what, PetscBool spd)
{
  PetscReal res, nz;
  PetscInt  n;

  PetscFunctionBegin;
  PetscCall(MatGetSize(A, &n, NULL));
  PetscCall(CheckOrdering(A, what, NULL, NULL));
  if (n == 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(FactorSolve(A, MATORDERINGMETISND, PETSC_FALSE, &res, &nz));
  HYLC_CHECK(res <= 1e-10, "%s: LU with metisnd: relative residual %g", what, (double)res);
  if (!spd) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(FactorSolve(A, MATORDERINGMETISND, PETSC_TRUE, &res, &nz));
  HYLC_CHECK(res <= 1e-10, "%s: Cholesky with metisnd: relative residual %g", what, (double)res);
  /* through KSP / PC options */
  {
    KSP       ksp;
    PC        pc;
    Vec       x, b, r;
    PetscReal nb, nr;
    Mat       F;
    MatInfo   minfo;
    PetscCall(KSPCreate(PETSC_COMM_SELF, &ksp));
    PetscCall(KSPSetOptionsPrefix(ksp, "tm_"));
    PetscCall(KSPSetOperators(ksp, A, A));
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PetscOptionsSetValue(NULL, "-tm_pc_factor_mat_ordering_type", "metisnd"));
    PetscCall(KSPSetFromOptions(ksp));
    PetscCall(PetscOptionsClearValue(NULL, "-tm_pc_factor_mat_ordering_type"));
    PetscCall(MatCreateVecs(A, &x, &b));
    PetscCall(VecDuplicate(b, &r));
    PetscCall(VecSet(b, 1));
    PetscCall(KSPSolve(ksp, b, x));
    PetscCall(PCFactorGetMatrix(pc, &F));
    PetscCall(MatGetInfo(F, MAT_LOCAL, &minfo));
    HYLC_CHECK(minfo.nz_used == nz, "%s: the PC's factor has %g nonzeros, the factor with metisnd %g", what, minfo.nz_used, nz);
    PetscCall(MatMult(A, x, r));
    PetscCall(VecAXPY(r, -1, b));
    PetscCall(VecNorm(b, NORM_2, &nb));
    PetscCall(VecNorm(r, NORM_2, &nr));
    HYLC_CHECK(nr <= 1e-10 * nb, "%s: KSP with PCCHOLESKY and metisnd: relative residual %g", what, (double)(nr / nb));
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&b));
    PetscCall(VecDestroy(&r));
    PetscCall(KSPDestroy(&ksp));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* 5-point Laplacian on an m x m grid (Dirichlet), SPD; with skew != 0 an unsymmetric convection term and
   a structurally unsymmetric coupling i -> i + m + 1 */
static PetscErrorCode Laplacian(PetscInt m, PetscReal skew, Mat *A)
{
  PetscFunctionBegin;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, m * m, m * m, 6, NULL, A));
  for (PetscInt i = 0; i < m; i++)
    for (PetscInt j = 0; j < m; j++) {
      const PetscInt r = i * m + j;
      PetscCall(MatSetValue(*A, r, r, 4, INSERT_VALUES));
      if (i > 0) PetscCall(MatSetValue(*A, r, r - m, -1 - skew, INSERT_VALUES));
      if (i < m - 1) PetscCall(MatSetValue(*A, r, r + m, -1 + skew, INSERT_VALUES));
      if (j > 0) PetscCall(MatSetValue(*A, r, r - 1, -1 - skew, INSERT_VALUES));
      if (j < m - 1) PetscCall(MatSetValue(*A, r, r + 1, -1 + skew, INSERT_VALUES));
      if (skew != 0 && r + m + 1 < m * m) PetscCall(MatSetValue(*A, r, r + m + 1, skew, INSERT_VALUES));
    }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestLaplacian(void)
{
  Mat       A;
  PetscReal res, nzMetis, nzNatural;

  PetscFunctionBegin;
  PetscCall(Laplacian(30, 0, &A));
  PetscCall(MatSetOption(A, MAT_SPD, PETSC_TRUE));
  PetscCall(CheckMatrix(A, "Laplacian 30x30", PETSC_TRUE));
  PetscCall(FactorSolve(A, MATORDERINGMETISND, PETSC_TRUE, &res, &nzMetis));
  PetscCall(FactorSolve(A, MATORDERINGNATURAL, PETSC_TRUE, &res, &nzNatural));
  /* natural (banded) fill is about n^1.5 = 27000; nested dissection's is O(n log n) */
  HYLC_CHECK(nzMetis < 0.6 * nzNatural, "Laplacian: Cholesky factor with metisnd has %g nonzeros, with natural %g", nzMetis, nzNatural);
  /* options are read: other separators and seed still give a valid permutation; a bad value is an error */
  PetscCall(PetscOptionsSetValue(NULL, "-hylc_metis_nseps", "3"));
  PetscCall(PetscOptionsSetValue(NULL, "-hylc_metis_seed", "7"));
  PetscCall(CheckOrdering(A, "Laplacian, nseps 3, seed 7", NULL, NULL));
  PetscCall(PetscOptionsSetValue(NULL, "-hylc_metis_nseps", "0"));
  {
    IS             row = NULL, col = NULL;
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = MatGetOrdering(A, MATORDERINGMETISND, &row, &col);
    PetscCall(PetscPopErrorHandler());
    HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "-hylc_metis_nseps 0 gave error code %d", (int)ierr);
    PetscCall(ISDestroy(&row));
    PetscCall(ISDestroy(&col));
  }
  PetscCall(PetscOptionsClearValue(NULL, "-hylc_metis_nseps"));
  PetscCall(PetscOptionsClearValue(NULL, "-hylc_metis_seed"));
  PetscCall(MatDestroy(&A));

  PetscCall(Laplacian(17, 0.3, &A));
  PetscCall(CheckMatrix(A, "unsymmetric 17x17 grid", PETSC_FALSE));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a diagonal matrix of size n (n = 0: empty, n = 1: 1x1), and a block-diagonal one with 3 tridiagonal blocks */
static PetscErrorCode TestSmall(void)
{
  Mat A;

  PetscFunctionBegin;
  for (PetscInt n = 0; n <= 5; n += (n < 1 ? 1 : 4)) {
    char what[64];
    PetscCall(PetscSNPrintf(what, sizeof(what), "diagonal %dx%d", (int)n, (int)n));
    PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 1, NULL, &A));
    for (PetscInt i = 0; i < n; i++) PetscCall(MatSetValue(A, i, i, 2.0 + i, INSERT_VALUES));
    PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
    PetscCall(CheckMatrix(A, what, PETSC_TRUE));
    PetscCall(MatDestroy(&A));
  }
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, 30, 30, 3, NULL, &A));
  for (PetscInt i = 0; i < 30; i++) {
    PetscCall(MatSetValue(A, i, i, 4, INSERT_VALUES));
    if (i % 10) PetscCall(MatSetValue(A, i, i - 1, -1, INSERT_VALUES));
    if ((i + 1) % 10) PetscCall(MatSetValue(A, i, i + 1, -1, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscCall(CheckMatrix(A, "3 disconnected blocks", PETSC_TRUE));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* K = H_y + |H_y|_inf I of a bent stockinette tile */
static PetscErrorCode TestPeriodicHessian(void)
{
  HylcPatternGenParams g;
  HylcPattern          p;
  Mat                  H;
  PetscInt             n;
  PetscReal            hinf;
  PetscBool            sym;
  const PetscReal      z[6] = {0.05, 0.1, -0.05, 120, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNSTOCKINETTE, &g));
  PetscCall(HylcTestTileHessian(p, z, &H));
  PetscCall(MatGetSize(H, &n, NULL));
  PetscCall(MatNorm(H, NORM_INFINITY, &hinf));
  PetscCall(MatIsSymmetric(H, 1e-10 * hinf, &sym));
  HYLC_CHECK(sym, "stockinette H_y is not symmetric");
  PetscCall(MatShift(H, hinf)); /* Gershgorin: every eigenvalue of H_y is >= -|H_y|_inf */
  PetscCall(MatSetOption(H, MAT_SPD, PETSC_TRUE));
  HYLC_CHECK(n > 100, "stockinette tile has only %d unknowns", (int)n);
  PetscCall(CheckMatrix(H, "stockinette K = H_y + |H_y|_inf I", PETSC_TRUE));
  PetscCall(MatDestroy(&H));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(HylcInitializePackage());
  PetscCall(TestSmall());
  PetscCall(TestLaplacian());
  PetscCall(TestPeriodicHessian());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
