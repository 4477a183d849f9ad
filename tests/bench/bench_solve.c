/* Benchmark: microscale solves on the paper's seven patterns with their config/<name>.yaml parameters,
   at z = 0, sx = +-0.3, sy = 0.3, sa = 0.5, II00 = +-0.8 sigma, II11 = +-0.8 sigma (sigma: docs/method.md §8).
   Prints per sample: Newton iterations, status, CPU seconds (clock()), and the shares of the wall time in
   assembly (energy, gradient and Hessian evaluations without contact), contact (broadphase and contact
   kernels), factorization (Cholesky and the Schur-complement solves) and line search (including its
   energy evaluations, so the shares overlap). Paper (Table S1, 128 threads): 2.2-5.7 CPU-s per stockinette sample,
   25-28 per rib sample. Usage: bench_solve [name ...] (default: all seven). */
#include <hylc/micro.h>
#include <petsctime.h>
#include <time.h>

typedef struct {
  const char *name;
  PetscReal   sx, sy;           /* sigma of II00, II11 (1/m) */
  PetscReal   paper1D, paper2D; /* implied CPU-s per sample, Table S1 */
} Case;

static const Case cases[] = {
    {"basket", 170, 170, 11, 6.3},
    {"satin", 170, 170, 8.5, 9.2},
    {"stockinette", 200, 230, 2.2, 5.7},
    {"cartridge_belt_rib", 100, 80, 28, 25},
    {"slip_stitch_honeycomb", 120, 120, 13, 19},
    {"satin_small", 1700, 1700, 7.9, 8.6},
    {"stockinette_small", 2000, 2300, 4.8, 4.8},
};

static PetscErrorCode Run(const char *root, const char *dir, const Case *c)
{
  char            path[PETSC_MAX_PATH_LEN];
  PetscOptions    opt;
  HylcYarnModel   m;
  HylcPattern     p;
  HylcMicro       M;
  const PetscReal zs[9][6] = {
      {0, 0, 0, 0, 0, 0}, {0.3, 0, 0, 0, 0, 0}, {-0.3, 0, 0, 0, 0, 0}, {0, 0, 0.3, 0, 0, 0}, {0, 0.5, 0, 0, 0, 0}, {0, 0, 0, 0.8 * c->sx, 0, 0}, {0, 0, 0, -0.8 * c->sx, 0, 0}, {0, 0, 0, 0, 0, 0.8 * c->sy}, {0, 0, 0, 0, 0, -0.8 * c->sy},
  };
  const char    *label[9] = {"z = 0", "sx = +0.3", "sx = -0.3", "sy = +0.3", "sa = +0.5", "II00 = +0.8 s", "II00 = -0.8 s", "II11 = +0.8 s", "II11 = -0.8 s"};
  PetscLogDouble total = 0, worst = 0;
  PetscInt       nconv = 0;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/config/%s.yaml", root, c->name));
  PetscCall(PetscOptionsCreate(&opt));
  PetscCall(PetscOptionsInsertFile(PETSC_COMM_SELF, opt, path, PETSC_TRUE));
  PetscCall(PetscOptionsPush(opt));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, &m));
  PetscCall(PetscOptionsPop());
  PetscCall(PetscOptionsDestroy(&opt));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.pyp", dir, c->name));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternLoad(p, path));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroSetFromOptions(M));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "\n%s (paper: %.1f CPU-s per 1D sample, %.1f per 2D sample)\n", c->name, (double)c->paper1D, (double)c->paper2D));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-14s %5s %-13s %9s %8s %8s %8s %8s  %s\n", "sample", "its", "status", "CPU-s", "assembly", "contact", "factor", "lsearch", "psi (J/m^2)"));
  for (int k = 0; k < 9; k++) {
    HylcMicroResult r;
    const clock_t   c0 = clock();
    PetscCall(HylcMicroSolve(M, zs[k], &r));
    const clock_t        c1  = clock();
    const PetscLogDouble cpu = (PetscLogDouble)(c1 - c0) / CLOCKS_PER_SEC, w = r.time > 0 ? r.time : 1;
    total += cpu;
    worst = PetscMax(worst, cpu);
    nconv += r.status == HYLC_MICRO_CONVERGED;
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %-14s %5d %-13s %9.3f %7.0f%% %7.0f%% %7.0f%% %7.0f%%  %.10e\n", label[k], (int)r.iterations, HylcMicroStatuses[r.status], cpu, 100 * r.tAssembly / w, 100 * r.tContact / w, 100 * r.tFactor / w,
                          100 * r.tLineSearch / w, (double)r.psi));
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  %s: %d/9 converged, mean %.3f CPU-s, worst %.3f CPU-s per sample; speed-up over the paper's %.1f CPU-s (best case of Table S1): %.1fx on average, %.1fx worst\n", c->name, (int)nconv, total / 9, worst,
                        (double)PetscMin(c->paper1D, c->paper2D), PetscMin(c->paper1D, c->paper2D) / (total / 9), PetscMin(c->paper1D, c->paper2D) / worst));
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char        dir[PETSC_MAX_PATH_LEN], root[PETSC_MAX_PATH_LEN] = ".";
  PetscBool   have;
  const char *env = getenv("HYLC_REFDATA");

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  if (getenv("HYLC_ROOT")) PetscCall(PetscStrncpy(root, getenv("HYLC_ROOT"), sizeof(root)));
  PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (!have)
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "bench_solve: %s not found; skipped\n", dir));
  else
    for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
      PetscBool sel = (PetscBool)(argc < 2);
      for (int a = 1; a < argc; a++) {
        PetscBool eq;
        PetscCall(PetscStrcmp(argv[a], cases[k].name, &eq));
        sel = (PetscBool)(sel || eq);
      }
      if (sel) PetscCall(Run(root, dir, &cases[k]));
    }
  PetscCall(PetscFinalize());
  return 0;
}
