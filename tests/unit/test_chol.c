/* HylcChol, the supernodal block Cholesky (src/linalg/chol.c), and the solver type hylc (matsolver.c):
   - random sparse SPD matrices with block sizes 1 to 5, METIS and natural orderings: the solution of
     A x = b has a relative residual <= 1e-12 and agrees with PETSc's own Cholesky;
   - the factor of a matrix with a known dense factor (block tridiagonal) is exact to rounding;
   - an indefinite matrix is reported (ok = false) by default; with indefinite matrices accepted, its
     inertia equals MUMPS's and the solve has a small residual (block sizes 4 and 3);
   - the symbolic phase reruns only when the nonzero pattern changes;
   - HylcCholSolveMany gives bitwise the results of HylcCholSolve, also in place;
   - the Newton matrices H_y + alpha BI of the paper's tiles ($HYLC_REFDATA, skipped when absent);
   - through PCCHOLESKY with the solver type hylc: PCApply and MatMatSolve bitwise equal to HylcChol,
     MatGetInertia, and a zero pivot as a failed factorization.
   hylc-test: nprocs=1 */
#include <hylc/chol.h>
#include <hylc/periodic.h>
#include <petscpc.h>
#include "hylctest.h"
#include "tilehessian.h"

/* a random symmetric matrix of nb blocks of size bs: block-sparse (each block pair coupled with
   probability p, within a band of blocks plus a few long links), made diagonally dominant by shift */
static PetscErrorCode RandomSPD(PetscInt nb, PetscInt bs, PetscReal p, PetscReal shift, unsigned long long *seed, Mat *A)
{
  const PetscInt n = nb * bs;
  PetscReal     *rowsum;

  PetscFunctionBegin;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, PETSC_DEFAULT, NULL, A));
  PetscCall(MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(PetscCalloc1(n, &rowsum));
  for (PetscInt BI = 0; BI < nb; BI++)
    for (PetscInt BJ = 0; BJ <= BI; BJ++) {
      const PetscBool band = (PetscBool)(BI - BJ <= 2);
      if (BI != BJ && !(band ? HylcTestRand(seed) < 0.8 : HylcTestRand(seed) < p)) continue;
      for (PetscInt i = 0; i < bs; i++)
        for (PetscInt j = 0; j < bs; j++) {
          const PetscInt r = BI * bs + i, c = BJ * bs + j;
          if (r < c) continue;
          if (BI == BJ && HylcTestRand(seed) < 0.2 && r != c) continue; /* some zeros inside blocks */
          const PetscScalar v = 2 * HylcTestRand(seed) - 1;
          PetscCall(MatSetValue(*A, r, c, v, ADD_VALUES));
          if (r != c) PetscCall(MatSetValue(*A, c, r, v, ADD_VALUES));
          rowsum[r] += PetscAbsScalar(v);
          if (r != c) rowsum[c] += PetscAbsScalar(v);
        }
    }
  for (PetscInt r = 0; r < n; r++) PetscCall(MatSetValue(*A, r, r, rowsum[r] + shift, ADD_VALUES));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscFree(rowsum));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* factor, solve A x = b for a random b; check the residual and the agreement with PETSc's Cholesky */
static PetscErrorCode CheckSolve(Mat A, PetscInt bs, HylcCholOrdering ord, PetscBool relax, const char *label, unsigned long long *seed)
{
  HylcChol           C;
  PetscBool          spd;
  PetscInt           n;
  Vec                b, x, r, xp;
  PetscScalar       *xa;
  const PetscScalar *ba;
  PetscReal          nb, nr, nd, nx;
  Mat                F;
  IS                 rp, cp;
  MatFactorInfo      info;

  PetscFunctionBegin;
  PetscCall(MatGetSize(A, &n, NULL));
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(VecDuplicate(b, &xp));
  PetscCall(VecGetArray(b, &xa));
  for (PetscInt i = 0; i < n; i++) xa[i] = 2 * HylcTestRand(seed) - 1;
  PetscCall(VecRestoreArray(b, &xa));
  PetscCall(HylcCholCreate(&C));
  PetscCall(HylcCholSetOrdering(C, ord));
  PetscCall(HylcCholSetRelaxed(C, relax));
  PetscCall(HylcCholFactor(C, A, bs, &spd));
  HYLC_CHECK(spd, "%s: SPD matrix reported indefinite", label);
  PetscCall(VecGetArrayRead(b, &ba));
  PetscCall(VecGetArray(x, &xa));
  PetscCall(HylcCholSolve(C, ba, xa));
  PetscCall(VecRestoreArray(x, &xa));
  PetscCall(VecRestoreArrayRead(b, &ba));
  PetscCall(MatMult(A, x, r));
  PetscCall(VecAXPY(r, -1, b));
  PetscCall(VecNorm(b, NORM_2, &nb));
  PetscCall(VecNorm(r, NORM_2, &nr));
  HYLC_CHECK(nr <= 1e-12 * nb, "%s: relative residual %g", label, (double)(nr / nb));
  /* PETSc's Cholesky, natural ordering */
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatGetOrdering(A, MATORDERINGNATURAL, &rp, &cp));
  PetscCall(MatGetFactor(A, MATSOLVERPETSC, MAT_FACTOR_CHOLESKY, &F));
  PetscCall(MatCholeskyFactorSymbolic(F, A, rp, &info));
  PetscCall(MatCholeskyFactorNumeric(F, A, &info));
  PetscCall(MatSolve(F, b, xp));
  PetscCall(VecAXPY(xp, -1, x));
  PetscCall(VecNorm(xp, NORM_2, &nd));
  PetscCall(VecNorm(x, NORM_2, &nx));
  HYLC_CHECK(nd <= 1e-10 * nx, "%s: differs from PETSc's Cholesky by %g (relative)", label, (double)(nd / nx));
  PetscCall(MatDestroy(&F));
  PetscCall(ISDestroy(&rp));
  PetscCall(ISDestroy(&cp));
  PetscCall(HylcCholDestroy(&C));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&r));
  PetscCall(VecDestroy(&xp));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestRandom(void)
{
  unsigned long long seed   = 0x9e3779b97f4a7c15ULL;
  const PetscInt     bss[5] = {1, 3, 4, 2, 5}, nbs[4] = {1, 7, 60, 250};

  PetscFunctionBegin;
  for (int a = 0; a < 5; a++)
    for (int k = 0; k < 4; k++)
      for (int o = 0; o < 3; o++) {
        Mat  A;
        char label[64];
        PetscCall(RandomSPD(nbs[k], bss[a], 0.02, 0.5, &seed, &A));
        PetscCall(PetscSNPrintf(label, sizeof(label), "random bs %d nb %d %s%s", (int)bss[a], (int)nbs[k], o == 1 ? "natural" : "metis", o == 2 ? " fundamental supernodes" : ""));
        PetscCall(CheckSolve(A, bss[a], o == 1 ? HYLC_CHOL_ORDERING_NATURAL : HYLC_CHOL_ORDERING_METIS, (PetscBool)(o != 2), label, &seed));
        PetscCall(MatDestroy(&A));
      }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* A = L L^T with L lower bidiagonal (diagonal 2, subdiagonal 1): A is tridiagonal [1 2 ...; 2 5 2; ...]
   with A_00 = 4; the natural-order factor is L, so the solution of A x = A 1 is 1 to rounding */
static PetscErrorCode TestKnownFactor(void)
{
  const PetscInt n = 40;
  Mat            A;
  HylcChol       C;
  PetscBool      spd;
  PetscScalar    b[40], x[40];

  PetscFunctionBegin;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 3, NULL, &A));
  for (PetscInt i = 0; i < n; i++) {
    PetscCall(MatSetValue(A, i, i, i == 0 ? 4.0 : 5.0, INSERT_VALUES));
    if (i > 0) PetscCall(MatSetValue(A, i, i - 1, 2.0, INSERT_VALUES));
    if (i < n - 1) PetscCall(MatSetValue(A, i, i + 1, 2.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  for (PetscInt i = 0; i < n; i++) b[i] = (i == 0 ? 6.0 : i == n - 1 ? 7.0 : 9.0);
  PetscCall(HylcCholCreate(&C));
  for (int o = 0; o < 2; o++) {
    PetscCall(HylcCholSetOrdering(C, o ? HYLC_CHOL_ORDERING_NATURAL : HYLC_CHOL_ORDERING_METIS));
    for (PetscInt bs = 1; bs <= 4; bs *= 2) {
      PetscCall(HylcCholFactor(C, A, bs, &spd));
      HYLC_CHECK(spd, "tridiagonal: reported indefinite");
      PetscCall(HylcCholSolve(C, b, x));
      for (PetscInt i = 0; i < n; i++) HYLC_CHECK_CLOSE(x[i], 1.0, 1e-13);
    }
  }
  PetscCall(HylcCholDestroy(&C));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* indefinite: reported; shifted: factors. Symbolic reruns only on a new nonzero pattern. */
static PetscErrorCode TestIndefiniteAndReuse(void)
{
  unsigned long long seed = 12345;
  Mat                A, B;
  HylcChol           C;
  PetscBool          spd;
  HylcCholInfo       info;

  PetscFunctionBegin;
  PetscCall(RandomSPD(50, 4, 0.05, 0.1, &seed, &A));
  PetscCall(HylcCholCreate(&C));
  PetscCall(MatShift(A, -1e3)); /* every diagonal entry negative */
  PetscCall(HylcCholFactor(C, A, 4, &spd));
  HYLC_CHECK(!spd, "a negative definite matrix was reported positive definite");
  PetscCall(MatShift(A, 1e3));
  PetscCall(HylcCholFactor(C, A, 4, &spd));
  HYLC_CHECK(spd, "the shifted-back matrix was reported indefinite");
  {
    /* one negative eigenvalue only: A - (lambda_min + 1) e e^T style, via a large negative entry */
    PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &B));
    PetscCall(MatSetValue(B, 100, 100, -1.0, INSERT_VALUES));
    PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
    PetscCall(HylcCholFactor(C, B, 4, &spd));
    HYLC_CHECK(!spd, "a matrix with a negative diagonal entry was reported positive definite");
    PetscCall(MatDestroy(&B));
  }
  PetscCall(HylcCholFactor(C, A, 4, &spd));
  PetscCall(HylcCholGetInfo(C, &info));
  const PetscInt nsym = info.nsymbolic;
  PetscCall(MatScale(A, 2.0)); /* values only */
  PetscCall(HylcCholFactor(C, A, 4, &spd));
  PetscCall(HylcCholGetInfo(C, &info));
  HYLC_CHECK(info.nsymbolic == nsym && spd, "symbolic phase rerun for new values (%d -> %d)", (int)nsym, (int)info.nsymbolic);
  PetscCall(MatSetValue(A, 0, 199, 1e-3, INSERT_VALUES)); /* a new nonzero (and its mirror) */
  PetscCall(MatSetValue(A, 199, 0, 1e-3, INSERT_VALUES));
  PetscCall(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  PetscCall(HylcCholFactor(C, A, 4, &spd));
  PetscCall(HylcCholGetInfo(C, &info));
  HYLC_CHECK(info.nsymbolic == nsym + 1 && spd, "no symbolic phase for a new pattern (%d -> %d)", (int)nsym, (int)info.nsymbolic);
  /* many right-hand sides: bitwise equal to one at a time, also in place (m = 4 is a specialised kernel,
     11 more than one chunk of columns) */
  for (PetscInt m = 2; m <= 11; m += m == 5 ? 6 : 1) {
    const PetscInt n = 200;
    PetscScalar    b[2200], x1[2200], x2[2200];
    for (PetscInt i = 0; i < n * m; i++) b[i] = PetscSinReal(0.37 * i + 1);
    for (PetscInt j = 0; j < m; j++) PetscCall(HylcCholSolve(C, b + j * n, x1 + j * n));
    PetscCall(HylcCholSolveMany(C, m, b, x2));
    PetscCall(HylcCholSolveMany(C, m, b, b));
    PetscInt bad = 0;
    for (PetscInt i = 0; i < n * m; i++) bad += (x1[i] != x2[i]) + (b[i] != x2[i]);
    HYLC_CHECK(bad == 0, "HylcCholSolveMany with %d right-hand sides differs from HylcCholSolve in %d entries", (int)m, (int)bad);
  }
  PetscCall(HylcCholDestroy(&C));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* signed factorization of indefinite matrices: inertia against LAPACK's eigenvalues, and the solve */
static PetscErrorCode TestInertia(void)
{
  unsigned long long seed      = 4242;
  const PetscReal    shifts[3] = {-8.0, -12.0, -16.0};

  PetscFunctionBegin;
  for (int a = 0; a < 2; a++) /* bs 4, then 3 */
    for (int k = 0; k < 3; k++)
      for (int o = 0; o < 2; o++) {
        const PetscInt nb = 40, bs = a ? 3 : 4, n = nb * bs;
        Mat            A;
        HylcChol       C;
        PetscBool      ok;
        PetscInt       nneg, npos, lneg = 0;
        PetscScalar    b[160], x[160], r[160];
        PetscBool      mumps;
        /* diagonal dominance margin 0.5, shifted down: a few eigenvalues become negative */
        PetscCall(RandomSPD(nb, bs, 0.05, 0.5, &seed, &A));
        PetscCall(MatShift(A, shifts[k]));
        PetscCall(MatGetFactorAvailable(A, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &mumps));
        if (!mumps) {
          printf("MUMPS not available: inertia test skipped\n");
          PetscCall(MatDestroy(&A));
          PetscFunctionReturn(PETSC_SUCCESS);
        } else {
          Mat           F;
          MatFactorInfo info;
          PetscInt      zn, zp;
          PetscCall(MatFactorInfoInitialize(&info));
          PetscCall(MatGetFactor(A, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &F));
          PetscCall(MatMumpsSetIcntl(F, 24, 1));
          PetscCall(MatCholeskyFactorSymbolic(F, A, NULL, &info));
          PetscCall(MatCholeskyFactorNumeric(F, A, &info));
          PetscCall(MatGetInertia(F, &lneg, &zn, &zp));
          HYLC_CHECK(zn == 0, "test matrix singular");
          PetscCall(MatDestroy(&F));
        }
        PetscCall(HylcCholCreate(&C));
        PetscCall(HylcCholSetOrdering(C, o ? HYLC_CHOL_ORDERING_NATURAL : HYLC_CHOL_ORDERING_METIS));
        PetscCall(HylcCholFactor(C, A, bs, &ok));
        HYLC_CHECK(!ok || lneg == 0, "shift %g: %d negative eigenvalues but reported positive definite", (double)shifts[k], (int)lneg);
        PetscCall(HylcCholSetIndefinite(C, PETSC_TRUE));
        PetscCall(HylcCholFactor(C, A, bs, &ok));
        HYLC_CHECK(ok, "shift %g: signed factorization failed", (double)shifts[k]);
        if (ok) {
          PetscCall(HylcCholGetInertia(C, &nneg, &npos));
          HYLC_CHECK(nneg == lneg && npos == n - lneg, "shift %g: inertia (%d, %d), MUMPS %d negative", (double)shifts[k], (int)nneg, (int)npos, (int)lneg);
          HYLC_CHECK(lneg > 0, "shift %g: the test matrix should be indefinite", (double)shifts[k]);
          for (PetscInt i = 0; i < n; i++) b[i] = PetscCosReal(1.3 * i);
          PetscCall(HylcCholSolve(C, b, x));
          PetscReal rn = 0, bn2 = 0;
          for (PetscInt i = 0; i < n; i++) {
            r[i] = -b[i];
            for (PetscInt j = 0; j < n; j++) {
              PetscScalar v;
              PetscCall(MatGetValue(A, i, j, &v));
              r[i] += v * x[j];
            }
            rn += r[i] * r[i], bn2 += b[i] * b[i];
          }
          HYLC_CHECK(PetscSqrtReal(rn) <= 1e-10 * PetscSqrtReal(bn2), "shift %g: indefinite solve residual %g", (double)shifts[k], (double)PetscSqrtReal(rn / bn2));
        }
        PetscCall(HylcCholDestroy(&C));
        PetscCall(MatDestroy(&A));
      }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the reduced Hessians of the paper's tiles, shifted to be positive definite */
static PetscErrorCode TestPaperTiles(void)
{
  const char        *names[] = {"stockinette", "cartridge_belt_rib", "satin_small"};
  const char        *env     = getenv("HYLC_REFDATA");
  unsigned long long seed    = 7;

  PetscFunctionBegin;
  for (int t = 0; t < 3; t++) {
    char            path[PETSC_MAX_PATH_LEN];
    PetscBool       have;
    HylcPattern     p;
    Mat             H;
    const PetscReal z[6] = {0.1, 0.05, -0.05, 0, 0, 0};
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/patterns/hylc2020/%s.pyp", env ? env : "../shared/refdata", names[t]));
    PetscCall(PetscTestFile(path, 'r', &have));
    if (!have) {
      printf("%s not found: paper tiles skipped\n", path);
      continue;
    }
    PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
    PetscCall(HylcPatternLoad(p, path));
    PetscCall(HylcTestTileHessian(p, z, &H));
    {
      Vec       d;
      PetscReal dmax;
      PetscCall(MatCreateVecs(H, &d, NULL));
      PetscCall(MatGetDiagonal(H, d));
      PetscCall(VecNorm(d, NORM_INFINITY, &dmax));
      PetscCall(MatShift(H, dmax));
      PetscCall(VecDestroy(&d));
    }
    PetscCall(CheckSolve(H, 4, HYLC_CHOL_ORDERING_METIS, PETSC_TRUE, names[t], &seed));
    PetscCall(CheckSolve(H, 4, HYLC_CHOL_ORDERING_METIS, PETSC_FALSE, names[t], &seed));
    PetscCall(MatDestroy(&H));
    PetscCall(HylcPatternDestroy(&p));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* HylcChol as the PETSc solver type "hylc": PCCHOLESKY with -pc_factor_mat_solver_type hylc gives bitwise
   the results of HylcChol (PCApply, MatMatSolve against HylcCholSolveMany), MatGetInertia equals
   HylcCholGetInertia, and a zero pivot is a failed factorization (PC_FACTOR_NUMERIC_ZEROPIVOT), not an error */
static PetscErrorCode TestSolverType(void)
{
  unsigned long long seed = 11;
  const PetscInt     nb = 40, bs = 4, n = nb * bs, m = 5;
  Mat                A, F, B, X;
  PC                 pc;
  HylcChol           C;
  Vec                b, x;
  PetscScalar       *ba, *xa, *bm, *x1;
  const PetscScalar *xr;
  PetscBool          ok, same = PETSC_TRUE;
  MatSolverType      type;
  PCFailedReason     reason;
  PetscInt           nneg, nzero, npos, cneg, cpos;

  PetscFunctionBegin;
  PetscCall(RandomSPD(nb, bs, 0.05, 0.5, &seed, &A));
  PetscCall(MatSetBlockSize(A, bs));
  PetscCall(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(PCCreate(PETSC_COMM_SELF, &pc));
  PetscCall(PCSetType(pc, PCCHOLESKY));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERHYLC));
  PetscCall(PCSetOperators(pc, A, A));
  PetscCall(PCSetUp(pc));
  PetscCall(PCFactorGetMatrix(pc, &F));
  PetscCall(MatFactorGetSolverType(F, &type));
  PetscCall(PetscStrcmp(type, MATSOLVERHYLC, &ok));
  HYLC_CHECK(ok, "MatFactorGetSolverType: %s, expected hylc", type);
  PetscCall(HylcCholCreate(&C));
  PetscCall(HylcCholFactor(C, A, bs, &ok));
  HYLC_CHECK(ok, "HylcChol failed on an SPD matrix");
  /* one right-hand side */
  PetscCall(MatCreateVecs(A, &x, &b));
  PetscCall(VecGetArray(b, &ba));
  for (PetscInt i = 0; i < n; i++) ba[i] = 2 * HylcTestRand(&seed) - 1;
  PetscCall(PetscMalloc2(n * m, &bm, n * m, &x1));
  PetscCall(HylcCholSolve(C, ba, x1));
  PetscCall(VecRestoreArray(b, &ba));
  PetscCall(PCApply(pc, b, x));
  PetscCall(VecGetArrayRead(x, &xr));
  for (PetscInt i = 0; i < n; i++) same = (PetscBool)(same && xr[i] == x1[i]);
  PetscCall(VecRestoreArrayRead(x, &xr));
  HYLC_CHECK(same, "PCApply with the solver type hylc differs from HylcCholSolve");
  /* m right-hand sides in one MatMatSolve */
  for (PetscInt i = 0; i < n * m; i++) bm[i] = 2 * HylcTestRand(&seed) - 1;
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, n, m, bm, &B));
  PetscCall(MatCreateSeqDense(PETSC_COMM_SELF, n, m, NULL, &X));
  PetscCall(MatMatSolve(F, B, X));
  PetscCall(HylcCholSolveMany(C, m, bm, x1));
  PetscCall(MatDenseGetArray(X, &xa));
  same = PETSC_TRUE;
  for (PetscInt i = 0; i < n * m; i++) same = (PetscBool)(same && xa[i] == x1[i]);
  PetscCall(MatDenseRestoreArray(X, &xa));
  HYLC_CHECK(same, "MatMatSolve with the solver type hylc differs from HylcCholSolveMany");
  /* inertia of an indefinite matrix: A - 3 I */
  PetscCall(MatShift(A, -3.0));
  PetscCall(PCSetUp(pc));
  PetscCall(PCGetFailedReason(pc, &reason));
  HYLC_CHECK(reason == PC_NOERROR, "indefinite matrix: factorization failed (%s)", PCFailedReasons[reason]);
  PetscCall(MatGetInertia(F, &nneg, &nzero, &npos));
  PetscCall(HylcCholSetIndefinite(C, PETSC_TRUE));
  PetscCall(HylcCholFactor(C, A, bs, &ok));
  PetscCall(HylcCholGetInertia(C, &cneg, &cpos));
  HYLC_CHECK(ok && nneg == cneg && npos == cpos && nzero == 0 && nneg > 0, "inertia: MatGetInertia (%d, %d, %d), HylcChol (%d, %d)", (int)nneg, (int)nzero, (int)npos, (int)cneg, (int)cpos);
  /* a zero pivot: a failed factorization, not an error */
  {
    const PetscInt row = 7;
    PetscCall(MatZeroRowsColumns(A, 1, &row, 0.0, NULL, NULL));
    PetscCall(PCSetUp(pc));
    PetscCall(PCGetFailedReason(pc, &reason));
    HYLC_CHECK(reason == PC_FACTOR_NUMERIC_ZEROPIVOT, "zero pivot: failed reason %s, expected FACTOR_NUMERIC_ZEROPIVOT", PCFailedReasons[reason]);
  }
  PetscCall(PetscFree2(bm, x1));
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&X));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(HylcCholDestroy(&C));
  PetscCall(PCDestroy(&pc));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(HylcInitializePackage());
  PetscCall(TestKnownFactor());
  PetscCall(TestRandom());
  PetscCall(TestIndefiniteAndReuse());
  PetscCall(TestInertia());
  PetscCall(TestPaperTiles());
  PetscCall(TestSolverType());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
