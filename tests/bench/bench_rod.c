/* Benchmark of the rod element kernels: nanoseconds per element for stretching and bend-twist
   (energy only, energy + gradient, energy + gradient + Hessian) over a tile-sized batch of random
   elements.  Usage: bench_rod [elements] [sweeps] */
#include <hylc/geom.h>
#include <hylc/rod.h>
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

int main(int argc, char **argv)
{
  const int                    n = argc > 1 ? atoi(argv[1]) : 1500, sweeps = argc > 2 ? atoi(argv[2]) : 200;
  unsigned long long           st = 1;
  double                      *q = malloc(sizeof(double) * 11 * n), g[11], H[121], E[2], sink = 0;
  HylcRodBendTwistRef         *ref    = malloc(sizeof *ref * n);
  const HylcRodBendTwistParams par[2] = {{.B = 1, .beta = 0.8, .variant = HYLC_ROD_CURVATURE_AVERAGED}, {.B = 1, .beta = 0.8, .variant = HYLC_ROD_CURVATURE_PER_EDGE}};

  if (!q || !ref || n < 1 || sweeps < 1) return 1;
  /* a random polyline-like element per slot: edges of length ~1, turning angles up to ~1 rad */
  for (int k = 0; k < n; k++) {
    double *x = q + 11 * k, d1e[3], d1f[3];
    for (int i = 0; i < 11; i++) x[i] = 0.5 * (2 * Rand(&st) - 1);
    for (int i = 0; i < 3; i++) {
      x[4 + i] += 1.0 * (i == 0);
      x[8 + i] += 2.0 * (i == 0);
      d1e[i] = 2 * Rand(&st) - 1;
      d1f[i] = 2 * Rand(&st) - 1;
    }
    HylcRodBendTwistRefSetFrames(x, d1e, d1f, NAN, &ref[k]);
    ref[k].kappa0[0] = ref[k].kappa0[1] = 0.1;
    ref[k].tau0                         = 0.05;
    ref[k].lbar                         = 1.0;
  }

  printf("rod element kernels, %d elements x %d sweeps (ns per element)\n", n, sweeps);
  for (int mode = 0; mode < 3; mode++) {
    const char *name[3] = {"energy", "energy+gradient", "energy+gradient+Hessian"};
    double      t0      = Now();
    for (int s = 0; s < sweeps; s++)
      for (int k = 0; k < n; k++) {
        double Es;
        HylcRodStretch(q + 11 * k, 1.0, 1.0, 1.0, &Es, mode >= 1 ? g : NULL, mode >= 2 ? H : NULL);
        sink += Es + g[0] + H[7];
      }
    printf("  stretch     %-26s %8.1f\n", name[mode], 1e9 * (Now() - t0) / ((double)n * sweeps));
  }
  for (int v = 0; v < 2; v++)
    for (int mode = 0; mode < 3; mode++) {
      const char *name[3] = {"energy (plain path)", "energy+gradient", "energy+gradient+Hessian"};
      double      t0      = Now();
      for (int s = 0; s < sweeps; s++)
        for (int k = 0; k < n; k++) {
          if (mode == 0)
            HylcRodBendTwistEnergy(q + 11 * k, &ref[k], &par[v], 1.0, E);
          else
            HylcRodBendTwist(q + 11 * k, &ref[k], &par[v], 1.0, HYLC_ROD_BENDTWIST, E, g, mode == 2 ? H : NULL);
          sink += E[0] + E[1] + g[3] + H[60];
        }
      printf("  bend-twist  %-26s %8.1f   (%s curvature)\n", name[mode], 1e9 * (Now() - t0) / ((double)n * sweeps), v ? "per-edge" : "averaged");
    }
  if (sink == 12345.678) printf("%g\n", sink); /* keep the work alive */
  free(q);
  free(ref);
  return 0;
}
