/* Benchmark: fill-reducing orderings for PETSc's native sparse Cholesky (MATSOLVERPETSC) of the reduced
   Hessian of the paper's seven periodic tiles. For each pattern ($HYLC_REFDATA/patterns/hylc2020) and
   strain z = 0 and z = (0.2, 0, 0, 0, 0, 0): H_y at the initial guess (HylcPeriodic), K = H_y + alpha I
   with alpha = 1e-2 max|diag H_y|, raised tenfold until K is positive definite (inertia from MUMPS when
   available, else a successful native Cholesky with a small residual). Then for each ordering: the time of
   MatGetOrdering, of the symbolic factorization, the mean of the numeric factorization and of a solve,
   the nonzeros of the factor (upper triangle, diagonal included) and the fill ratio nz(U) / nz(triu K).
   Last row of each case: hylc's own supernodal Cholesky (HylcChol, include/hylc/chol.h), whose "nz" are the
   stored entries of its dense supernode panels (full 4 x 4 blocks, diagonal blocks in full). Then the solver
   types through MatGetFactor, each with its own ordering (inside "symb"): [hylc] (HylcChol as a PETSc solver
   type, src/linalg/matsolver.c), [cholmod] and [mumps] (skipped with a message when this PETSc lacks them;
   their nz are not reported by PETSc 3.18).
     -bench_reps <int>   numeric factorizations and solves averaged (default 20)
   Usage: bench_ordering [pattern ...] (default: all seven) */
#include <hylc/periodic.h>
#include <hylc/chol.h>
#include <petsctime.h>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <petsc/private/matimpl.h> /* F->ops->getinfo: does the factor count its entries? */
#pragma GCC diagnostic pop
#include "../unit/tilehessian.h"

static const char *const Orderings[] = {MATORDERINGNATURAL, MATORDERINGRCM, MATORDERINGND, MATORDERINGAMD, MATORDERINGMETISND};
#define NORD 5

/* is K positive definite? */
static PetscErrorCode IsSPD(Mat K, PetscBool *spd)
{
  PetscBool     mumps;
  Mat           F;
  MatFactorInfo info;

  PetscFunctionBegin;
  PetscCall(MatFactorInfoInitialize(&info));
  PetscCall(MatGetFactorAvailable(K, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &mumps));
  if (mumps) {
    PetscInt nneg, nzero, npos;
    PetscCall(MatGetFactor(K, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &F));
    PetscCall(MatMumpsSetIcntl(F, 24, 1)); /* null-pivot detection, needed for the inertia */
    PetscCall(MatCholeskyFactorSymbolic(F, K, NULL, &info));
    PetscCall(MatCholeskyFactorNumeric(F, K, &info));
    PetscCall(MatGetInertia(F, &nneg, &nzero, &npos));
    *spd = (PetscBool)(nneg == 0 && nzero == 0);
  } else {
    IS             row, col;
    MatFactorError err;
    Vec            x, b, r;
    PetscReal      nb, nr;
    PetscCall(MatGetOrdering(K, MATORDERINGNATURAL, &row, &col));
    PetscCall(MatGetFactor(K, MATSOLVERPETSC, MAT_FACTOR_CHOLESKY, &F));
    PetscCall(MatCholeskyFactorSymbolic(F, K, row, &info));
    PetscCall(MatCholeskyFactorNumeric(F, K, &info));
    PetscCall(MatFactorGetError(F, &err));
    PetscCall(MatCreateVecs(K, &x, &b));
    PetscCall(VecDuplicate(b, &r));
    PetscCall(VecSet(b, 1));
    PetscCall(MatSolve(F, b, x));
    PetscCall(MatMult(K, x, r));
    PetscCall(VecAXPY(r, -1, b));
    PetscCall(VecNorm(b, NORM_2, &nb));
    PetscCall(VecNorm(r, NORM_2, &nr));
    *spd = (PetscBool)(err == MAT_FACTOR_NOERROR && nr <= 1e-8 * nb);
    PetscCall(VecDestroy(&x));
    PetscCall(VecDestroy(&b));
    PetscCall(VecDestroy(&r));
    PetscCall(ISDestroy(&row));
    PetscCall(ISDestroy(&col));
  }
  PetscCall(MatDestroy(&F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* one solver type with one ordering (NULL: the solver type orders by itself) */
static PetscErrorCode BenchSolver(Mat K, MatSolverType stype, MatOrderingType type, PetscInt reps, PetscLogDouble *tt /* tOrder, tSym, tNum, tSolve */, PetscReal *nzF, PetscReal *res)
{
  Mat            F;
  IS             row, col;
  MatFactorInfo  info;
  MatInfo        minfo;
  Vec            x, b, r;
  PetscReal      nb, nr;
  PetscLogDouble t0, t1;

  PetscFunctionBegin;
  PetscCall(MatFactorInfoInitialize(&info));
  row = col = NULL;
  PetscCall(PetscTime(&t0));
  if (type) PetscCall(MatGetOrdering(K, type, &row, &col));
  PetscCall(PetscTime(&t1));
  tt[0] = t1 - t0;
  PetscCall(MatGetFactor(K, stype, MAT_FACTOR_CHOLESKY, &F));
  PetscCall(PetscTime(&t0));
  PetscCall(MatCholeskyFactorSymbolic(F, K, row, &info));
  PetscCall(PetscTime(&t1));
  tt[1] = t1 - t0;
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(MatCholeskyFactorNumeric(F, K, &info));
  PetscCall(PetscTime(&t1));
  tt[2] = (t1 - t0) / reps;
  PetscCall(MatCreateVecs(K, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(VecSet(b, 1));
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(MatSolve(F, b, x));
  PetscCall(PetscTime(&t1));
  tt[3] = (t1 - t0) / reps;
  PetscCall(MatMult(K, x, r));
  PetscCall(VecAXPY(r, -1, b));
  PetscCall(VecNorm(b, NORM_2, &nb));
  PetscCall(VecNorm(r, NORM_2, &nr));
  *res = nr / nb;
  *nzF = 0;
  if (F->ops->getinfo) { /* CHOLMOD and MUMPS in PETSc 3.18 do not count their factor's entries */
    PetscCall(MatGetInfo(F, MAT_LOCAL, &minfo));
    *nzF = minfo.nz_used;
  }
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&r));
  PetscCall(ISDestroy(&row));
  PetscCall(ISDestroy(&col));
  PetscCall(MatDestroy(&F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* hylc's own supernodal Cholesky (HylcChol, METIS on the vertex-block graph) on the same matrix */
static PetscErrorCode BenchHylcChol(Mat K, PetscInt reps, PetscLogDouble *tt, PetscReal *nzF, PetscReal *res)
{
  HylcChol           C;
  HylcCholInfo       info;
  PetscBool          ok;
  Vec                x, b, r;
  PetscReal          nb, nr;
  PetscLogDouble     t0, t1;
  PetscScalar       *xa;
  const PetscScalar *ba;

  PetscFunctionBegin;
  PetscCall(HylcCholCreate(&C));
  PetscCall(PetscTime(&t0));
  PetscCall(HylcCholFactor(C, K, 4, &ok)); /* symbolic (ordering included) + numeric */
  PetscCall(PetscTime(&t1));
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_PLIB, "HylcChol failed on a positive definite matrix");
  tt[0] = 0;
  tt[1] = t1 - t0;
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(HylcCholFactor(C, K, 4, &ok));
  PetscCall(PetscTime(&t1));
  tt[2] = (t1 - t0) / reps;
  tt[1] -= tt[2]; /* symbolic alone */
  PetscCall(MatCreateVecs(K, &x, &b));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(VecSet(b, 1));
  PetscCall(VecGetArrayRead(b, &ba));
  PetscCall(VecGetArray(x, &xa));
  PetscCall(PetscTime(&t0));
  for (PetscInt k = 0; k < reps; k++) PetscCall(HylcCholSolve(C, ba, xa));
  PetscCall(PetscTime(&t1));
  PetscCall(VecRestoreArray(x, &xa));
  PetscCall(VecRestoreArrayRead(b, &ba));
  tt[3] = (t1 - t0) / reps;
  PetscCall(MatMult(K, x, r));
  PetscCall(VecAXPY(r, -1, b));
  PetscCall(VecNorm(b, NORM_2, &nb));
  PetscCall(VecNorm(r, NORM_2, &nr));
  *res = nr / nb;
  PetscCall(HylcCholGetInfo(C, &info));
  *nzF = (PetscReal)info.nnzL;
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&r));
  PetscCall(HylcCholDestroy(&C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Bench(const char *dir, const char *name, const PetscReal z[6], PetscInt reps)
{
  char        path[PETSC_MAX_PATH_LEN];
  PetscBool   have, spd = PETSC_FALSE;
  HylcPattern p;
  Mat         H, K = NULL;
  Vec         d;
  PetscInt    n;
  PetscReal   dmax, alpha = 0, nzK;
  MatInfo     minfo;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.pyp", dir, name));
  PetscCall(PetscTestFile(path, 'r', &have));
  if (!have) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%-22s %s not found; skipped\n", name, path));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternLoad(p, path));
  PetscCall(HylcTestTileHessian(p, z, &H));
  PetscCall(MatGetSize(H, &n, NULL));
  PetscCall(MatCreateVecs(H, &d, NULL));
  PetscCall(MatGetDiagonal(H, d));
  PetscCall(VecNorm(d, NORM_INFINITY, &dmax));
  PetscCall(VecDestroy(&d));
  for (PetscReal f = 1e-2; f < 1e3 && !spd; f *= 10) {
    alpha = f * dmax;
    PetscCall(MatDestroy(&K));
    PetscCall(MatDuplicate(H, MAT_COPY_VALUES, &K));
    PetscCall(MatShift(K, alpha));
    PetscCall(MatSetBlockSize(K, 4)); /* vertex blocks: the block size of the solver type hylc */
    PetscCall(MatSetOption(K, MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(IsSPD(K, &spd));
  }
  PetscCheck(spd, PETSC_COMM_SELF, PETSC_ERR_NOT_CONVERGED, "%s: H_y + alpha I is not positive definite for alpha up to %g", name, (double)alpha);
  PetscCall(MatSetOption(K, MAT_SPD, PETSC_TRUE));
  PetscCall(MatGetInfo(K, MAT_LOCAL, &minfo));
  nzK = 0.5 * (minfo.nz_used + n);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s, z = (%g, %g, %g, %g, %g, %g): n = %d, nz(K) = %d, alpha = %.0e max|diag|\n", name, (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5], (int)n, (int)minfo.nz_used,
                        (double)(alpha / dmax)));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-9s %10s %6s %10s %10s %11s %10s %11s %9s\n", "ordering", "nz(U)", "fill", "order ms", "symb ms", "numeric ms", "solve ms", "ord+sym+num", "residual"));
  for (int k = 0; k < NORD; k++) {
    PetscLogDouble tt[4] = {0, 0, 0, 0};
    PetscReal      nzF = 0, res = 0;
    PetscCall(BenchSolver(K, MATSOLVERPETSC, Orderings[k], reps, tt, &nzF, &res));
    PetscCall(
        PetscPrintf(PETSC_COMM_SELF, "  %-9s %10.0f %6.2f %10.3f %10.3f %11.3f %10.3f %11.3f %9.1e\n", Orderings[k], (double)nzF, (double)(nzF / nzK), 1e3 * tt[0], 1e3 * tt[1], 1e3 * tt[2], 1e3 * tt[3], 1e3 * (tt[0] + tt[1] + tt[2]), (double)res));
  }
  {
    PetscLogDouble tt[4] = {0, 0, 0, 0};
    PetscReal      nzF = 0, res = 0;
    PetscCall(BenchHylcChol(K, reps, tt, &nzF, &res));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-9s %10.0f %6.2f %10s %10.3f %11.3f %10.3f %11.3f %9.1e   (HylcChol: stored panel entries; ordering inside symb)\n", "hylcchol", (double)nzF, (double)(nzF / nzK), "-", 1e3 * tt[1], 1e3 * tt[2],
                          1e3 * tt[3], 1e3 * (tt[1] + tt[2]), (double)res));
  }
  /* the same through MatGetFactor: HylcChol as the solver type hylc, and the external packages CHOLMOD
     and MUMPS, each with its own ordering (inside symb) */
  {
    const char *const solvers[] = {MATSOLVERHYLC, MATSOLVERCHOLMOD, MATSOLVERMUMPS};
    for (int k = 0; k < 3; k++) {
      PetscLogDouble tt[4] = {0, 0, 0, 0};
      PetscReal      nzF = 0, res = 0;
      PetscBool      avail;
      char           label[32];
      PetscCall(MatGetFactorAvailable(K, solvers[k], MAT_FACTOR_CHOLESKY, &avail));
      PetscCall(PetscSNPrintf(label, sizeof(label), "[%s]", solvers[k]));
      if (!avail) {
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-9s not available in this PETSc; skipped\n", label));
        continue;
      }
      PetscCall(BenchSolver(K, solvers[k], NULL, reps, tt, &nzF, &res));
      if (nzF > 0)
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-9s %10.0f %6.2f %10s %10.3f %11.3f %10.3f %11.3f %9.1e\n", label, (double)nzF, (double)(nzF / nzK), "-", 1e3 * tt[1], 1e3 * tt[2], 1e3 * tt[3], 1e3 * (tt[1] + tt[2]), (double)res));
      else
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-9s %10s %6s %10s %10.3f %11.3f %10.3f %11.3f %9.1e\n", label, "-", "-", "-", 1e3 * tt[1], 1e3 * tt[2], 1e3 * tt[3], 1e3 * (tt[1] + tt[2]), (double)res));
    }
  }
  PetscCall(MatDestroy(&K));
  PetscCall(MatDestroy(&H));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char            dir[PETSC_MAX_PATH_LEN];
  PetscBool       have;
  PetscInt        reps    = 20;
  const char     *names[] = {"stockinette", "stockinette_small", "cartridge_belt_rib", "slip_stitch_honeycomb", "basket", "satin", "satin_small"};
  const PetscReal z0[6] = {0, 0, 0, 0, 0, 0}, z1[6] = {0.2, 0, 0, 0, 0, 0};

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(HylcInitializePackage());
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-bench_reps", &reps, NULL));
  const char *env = getenv("HYLC_REFDATA");
  PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (!have)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "bench_ordering: %s not found; skipped\n", dir));
  else
    for (int i = 0; i < 7; i++) {
      PetscBool chosen = (PetscBool)(argc < 2);
      for (int a = 1; a < argc && !chosen; a++) PetscCall(PetscStrcmp(argv[a], names[i], &chosen));
      if (!chosen) continue;
      PetscCall(Bench(dir, names[i], z0, reps));
      PetscCall(Bench(dir, names[i], z1, reps));
    }
  PetscCall(PetscFinalize());
  return 0;
}
