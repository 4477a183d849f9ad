/* Benchmark of the contact kernels and the broadphase (include/hylc/contact.h).
   Prints ns per pair for the pair kernels and, for N random segments of realistic density, the time of
   the AABB hierarchy's build, refit and query against the O(N^2) brute force.
     build/bench/bench_contact [seconds per measurement, default 0.2] */
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double Now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static unsigned long long rng = 88172645463325252ULL;
static double             Rand(void)
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

static void RandUnit(double u[3])
{
  do {
    for (int k = 0; k < 3; k++) u[k] = 2 * Rand() - 1;
  } while (HylcNorm3(u) < 0.1 || HylcNorm3(u) > 1);
  HylcNormalize3(u);
}

/* nseg segments of length in [0.5, 1.5] r, centres uniform in a cube of side (20 nseg)^(1/3) r */
static void RandomSegments(int nseg, double r, double *x)
{
  const double L = cbrt(20.0 * nseg) * r;
  for (int i = 0; i < nseg; i++) {
    double u[3], c[3];
    RandUnit(u);
    for (int k = 0; k < 3; k++) c[k] = L * Rand();
    const double len = r * (0.5 + Rand());
    for (int k = 0; k < 3; k++) {
      x[6 * i + k]     = c[k] - 0.5 * len * u[k];
      x[6 * i + 3 + k] = c[k] + 0.5 * len * u[k];
    }
  }
}

static volatile double sink;

typedef enum { Q4_EGH, Q4_E, Q8_EGH, CP_EGH, Q4_REJECT } Kernel;

static double TimeKernel(Kernel kern, int npair, const double *x, double r, double tmin)
{
  double g[12] = {0}, H[144] = {0}, acc = 0;
  long   reps = 0;
  double t0   = Now(), t1;
  do {
    for (int p = 0; p < npair; p++) {
      const double *y = x + 12 * p;
      switch (kern) {
      case Q4_EGH:
      case Q4_REJECT:
        acc += HylcContactQuadrature(y, y + 3, y + 6, y + 9, r, r, 70, r, 4, 1, g, H);
        break;
      case Q4_E:
        acc += HylcContactQuadrature(y, y + 3, y + 6, y + 9, r, r, 70, r, 4, 1, NULL, NULL);
        break;
      case Q8_EGH:
        acc += HylcContactQuadrature(y, y + 3, y + 6, y + 9, r, r, 70, r, 8, 1, g, H);
        break;
      case CP_EGH:
        acc += HylcContactClosestPoint(y, y + 3, y + 6, y + 9, r, r, 70, r, 1, g, H, NULL, NULL, NULL);
        break;
      }
      acc += H[17] + g[5];
    }
    reps++;
    t1 = Now();
  } while (t1 - t0 < tmin);
  sink = acc;
  return 1e9 * (t1 - t0) / ((double)reps * npair);
}

/* Median of k timings of fn */
#define TIME_MEDIAN(k, out, stmt)                                \
  do {                                                           \
    double ts_[32];                                              \
    for (int it_ = 0; it_ < (k); it_++) {                        \
      const double t0_ = Now();                                  \
      stmt;                                                      \
      ts_[it_] = Now() - t0_;                                    \
    }                                                            \
    for (int a_ = 1; a_ < (k); a_++)                             \
      for (int b_ = a_; b_ > 0 && ts_[b_] < ts_[b_ - 1]; b_--) { \
        const double tt_ = ts_[b_];                              \
        ts_[b_]          = ts_[b_ - 1];                          \
        ts_[b_ - 1]      = tt_;                                  \
      }                                                          \
    out = ts_[(k) / 2];                                          \
  } while (0)

int main(int argc, char **argv)
{
  const double  tmin = argc > 1 ? atof(argv[1]) : 0.2, r = 0.5e-3;
  const double *xg, *wg;
  HylcGaussLegendre01(4, &xg, &wg);
  HylcGaussLegendre01(8, &xg, &wg);

  /* ---- pair kernels: pairs at distance 0.3 .. 0.95 (2r), segment lengths 0.5 .. 1.5 r */
  const int npair = 1000;
  double   *x     = (double *)malloc(12 * npair * sizeof(double));
  double   *xf    = (double *)malloc(12 * npair * sizeof(double));
  for (int p = 0; p < npair;) {
    double ua[3], ub[3], off[3], *y = x + 12 * p;
    RandUnit(ua);
    RandUnit(ub);
    RandUnit(off);
    const double la = r * (0.5 + Rand()), lb = r * (0.5 + Rand()), dist = 2 * r * Rand();
    for (int k = 0; k < 3; k++) {
      y[k]     = -0.5 * la * ua[k];
      y[3 + k] = 0.5 * la * ua[k];
      y[6 + k] = dist * off[k] - 0.5 * lb * ub[k];
      y[9 + k] = y[6 + k] + lb * ub[k];
    }
    const double d = HylcSegmentSegmentDistance(y, y + 3, y + 6, y + 9, NULL, NULL) / (2 * r);
    if (d > 0.3 && d < 0.95) {
      memcpy(xf + 12 * p, y, 12 * sizeof(double));
      for (int k = 0; k < 3; k++) xf[12 * p + 6 + k] += 3 * r, xf[12 * p + 9 + k] += 3 * r; /* far copy */
      p++;
    }
  }
  printf("contact pair kernels (%d pairs in contact, mean over repeated sweeps, %.2f s each)\n", npair, tmin);
  printf("  quadrature n=4, E+g+H       %8.1f ns/pair\n", TimeKernel(Q4_EGH, npair, x, r, tmin));
  printf("  quadrature n=4, E only      %8.1f ns/pair\n", TimeKernel(Q4_E, npair, x, r, tmin));
  printf("  quadrature n=8, E+g+H       %8.1f ns/pair\n", TimeKernel(Q8_EGH, npair, x, r, tmin));
  printf("  closest point, E+g+H        %8.1f ns/pair\n", TimeKernel(CP_EGH, npair, x, r, tmin));
  printf("  rejected pair (d >= 2r)     %8.1f ns/pair\n", TimeKernel(Q4_REJECT, npair, xf, r, tmin));
  free(x);
  free(xf);

  /* ---- broadphase */
  printf("\nbroadphase: N random segments, length 0.5-1.5 r, cube side (20 N)^(1/3) r, margin r; times in ms\n");
  printf("  %6s %8s %8s %8s %8s %8s %8s %10s %9s %9s\n", "N", "nb<2r", "cand", "build", "refit", "query", "ref+qry", "brute", "speedup", "w/ build");
  const int sizes[] = {500, 1500, 5000};
  for (int si = 0; si < 3; si++) {
    const int    nseg = sizes[si];
    double      *s    = (double *)malloc(6 * nseg * sizeof(double));
    HylcPairList tp = {0}, bp = {0};
    HylcBVH      bvh;
    RandomSegments(nseg, r, s);
    /* measured density: pairs closer than 2r per segment (counted on the brute-force candidates) */
    HylcBroadphaseBruteForce(nseg, s, NULL, r, NULL, &bp);
    size_t close = 0;
    for (size_t k = 0; k < bp.n; k++) {
      const int i = bp.idx[2 * k], j = bp.idx[2 * k + 1];
      close += HylcSegmentSegmentDistance(s + 6 * i, s + 6 * i + 3, s + 6 * j, s + 6 * j + 3, NULL, NULL) < 2 * r;
    }
    HylcBVHCreate(nseg, &bvh);
    double    tbuild, trefit, tquery, tbrute;
    const int k = 15;
    TIME_MEDIAN(k, tbuild, HylcBVHBuild(bvh, s, NULL, r));
    /* moved positions (as between Newton iterations), then refit and query */
    for (int i = 0; i < 6 * nseg; i++) s[i] += 0.05 * r * (2 * Rand() - 1);
    TIME_MEDIAN(k, trefit, HylcBVHRefit(bvh, s, NULL));
    TIME_MEDIAN(k, tquery, HylcBVHQuery(bvh, &tp));
    TIME_MEDIAN(nseg > 2000 ? 5 : k, tbrute, HylcBroadphaseBruteForce(nseg, s, NULL, r, NULL, &bp));
    HylcPairListSort(&tp);
    if (tp.n != bp.n || memcmp(tp.idx, bp.idx, 2 * tp.n * sizeof(int))) printf("  MISMATCH tree/brute force at N = %d\n", nseg);
    printf("  %6d %8.2f %8.2f %8.3f %8.3f %8.3f %8.3f %10.3f %8.1fx %8.1fx\n", nseg, 2.0 * close / nseg, 2.0 * tp.n / nseg, 1e3 * tbuild, 1e3 * trefit, 1e3 * tquery, 1e3 * (trefit + tquery), 1e3 * tbrute, tbrute / (trefit + tquery),
           tbrute / (tbuild + tquery));
    HylcBVHDestroy(&bvh);
    HylcPairListFree(&tp);
    HylcPairListFree(&bp);
    free(s);
  }
  printf("  (nb<2r: neighbours closer than 2r per segment; cand: candidate pairs per segment (box overlaps);\n"
         "   speedup = brute / (refit + query); w/ build = brute / (build + query))\n");
  return 0;
}
