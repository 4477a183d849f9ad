/* Benchmark of the material evaluator (HylcMaterialEvaluate) on one core: evaluations per second of Psi,
   Psi + gradient and Psi + gradient + Hessian over random strains in the sampled range of a table (the
   in-plane strains within the knots of the 1D terms, the II components up to the bending scales), for
   stock1.json and basket1.json from $HYLC_REFDATA/materials, or a synthetic table when those are absent.
   Also the rate at strains with equal eigenvalues of II (II00 = II11, II01 = 0; in particular II = 0),
   where the piecewise-polynomial form of the divided differences is used.
   Usage: bench_eval [strains] [sweeps] */
#include <hylc/material.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double Now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double Rand(unsigned long long *s)
{
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return (double)((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

/* a synthetic table of the paper's shape: 11 knots per 1D term, 9 x 9 per 2D term, random C1 data */
static PetscErrorCode Synthetic(HylcMaterial m)
{
  double             t[11], p[11], mm[11], tu[9], P[81], U[81], V[81], W[81];
  const double       sc[5] = {0.8, 0.75, 0.8, 200, 230};
  unsigned long long st    = 3;

  PetscFunctionBegin;
  PetscCall(HylcMaterialSetStrainScale(m, sc));
  PetscCall(HylcMaterialSetConstant(m, 0.05));
  for (int i = 0; i < 11; i++) t[i] = -0.95 + 0.19 * i;
  for (int i = 0; i < 9; i++) tu[i] = -0.72 + 0.18 * i;
  for (int k = 0; k < 5; k++) {
    HylcSpline1D s = {k, 11, t, p, mm, HYLC_EXT_LINEAR};
    for (int i = 0; i < 11; i++) {
      p[i]  = t[i] * t[i] + 0.1 * Rand(&st);
      mm[i] = 2 * t[i] + 0.1 * Rand(&st);
    }
    PetscCall(HylcMaterialSet1D(m, &s));
  }
  for (int q = 0; q < HYLC_MATERIAL_N2D; q++) {
    HylcSpline2D s = {HylcMaterialPairs[q][0], HylcMaterialPairs[q][1], 9, 9, tu, tu, P, U, V, W, HYLC_EXT_LINEAR};
    for (int i = 0; i < 81; i++) {
      P[i] = 0.01 * Rand(&st);
      U[i] = 0.01 * Rand(&st);
      V[i] = 0.01 * Rand(&st);
      W[i] = 0.01 * Rand(&st);
    }
    PetscCall(HylcMaterialSet2D(m, &s));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Bench(HylcMaterial m, const char *name, int n, int sweeps)
{
  unsigned long long  st = 11;
  double             *S, sc[5], sink = 0, g[6], H[36];
  const HylcSpline1D *s1;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(6 * n, &S));
  PetscCall(HylcMaterialGetStrainScale(m, sc));
  for (int k = 0; k < n; k++) {
    for (int c = 0; c < 3; c++) {
      double lo = -1, hi = 1;
      PetscCall(HylcMaterialGet1D(m, c, &s1));
      if (s1) lo = s1->t[0], hi = s1->t[s1->n - 1];
      S[6 * k + c] = sc[c] * (lo + (hi - lo) * Rand(&st));
    }
    S[6 * k + 3] = sc[3] * (2 * Rand(&st) - 1);
    S[6 * k + 4] = 0.5 * sc[3] * (2 * Rand(&st) - 1);
    S[6 * k + 5] = sc[4] * (2 * Rand(&st) - 1);
  }
  for (int equal = 0; equal < 2; equal++) {
    if (equal) /* II00 = II11, II01 = 0; every fourth strain II = 0 */
      for (int k = 0; k < n; k++) {
        S[6 * k + 5] = S[6 * k + 3] = (k % 4 == 0) ? 0 : S[6 * k + 3];
        S[6 * k + 4]                = 0;
      }
    for (int mode = 0; mode < 3; mode++) {
      const char *what[3] = {"Psi", "Psi + gradient", "Psi + gradient + Hessian"};
      double      t0      = Now(), dt;
      for (int sw = 0; sw < sweeps; sw++)
        for (int k = 0; k < n; k++) {
          double E;
          PetscCall(HylcMaterialEvaluate(m, S + 6 * k, &E, mode ? g : NULL, mode > 1 ? H : NULL));
          sink += E + (mode ? g[k % 6] : 0) + (mode > 1 ? H[k % 36] : 0);
        }
      dt = Now() - t0;
      printf("  %-12s %-28s %-22s %10.3g /s  %7.0f ns\n", name, what[mode], equal ? "equal eigenvalues" : "random strains", (double)n * sweeps / dt, 1e9 * dt / ((double)n * sweeps));
    }
  }
  if (sink == 12345.678) printf("%g\n", sink);
  PetscCall(PetscFree(S));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  HylcMaterial m;
  const char  *env = getenv("HYLC_REFDATA"), *tables[2] = {"stock1", "basket1"};
  int          n, sweeps, found = 0;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  n      = argc > 1 && argv[1][0] != '-' ? atoi(argv[1]) : 100000;
  sweeps = argc > 2 && argv[2][0] != '-' ? atoi(argv[2]) : 10;
  PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &m));
  printf("material evaluation on one core, %d strains x %d sweeps (evaluations per second, ns per evaluation)\n", n, sweeps);
  for (int f = 0; f < 2; f++) {
    char      path[PETSC_MAX_PATH_LEN];
    PetscBool have;
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/materials/%s.json", env ? env : "../shared/refdata", tables[f]));
    PetscCall(PetscTestFile(path, 'r', &have));
    if (!have) continue;
    PetscCall(HylcMaterialLoad(m, path));
    PetscCall(Bench(m, tables[f], n, sweeps));
    found++;
  }
  if (!found) {
    printf("  (the paper's tables were not found under %s/materials: a synthetic table of the same shape)\n", env ? env : "../shared/refdata");
    PetscCall(Synthetic(m));
    PetscCall(Bench(m, "synthetic", n, sweeps));
  }
  PetscCall(HylcMaterialDestroy(&m));
  PetscCall(PetscFinalize());
  return 0;
}
