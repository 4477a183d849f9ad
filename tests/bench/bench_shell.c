/* The shell element of Algorithm C8 (hylcmat_shell_eval, hylcmat_mesh_eval) on one core, the paper's
   stock1 table ($HYLC_REFDATA/materials/stock1.json; skipped without it):
   - per triangle: 40 random interior stencils (in-plane strains up to ~20 %, curvatures up to 0.3 of the
     table's bending scale, random rigid motions), evaluated over and over: triangles per second for the
     energy; energy + gradient; + Hessian; + PSD projection;
   - whole mesh: a 224 x 224 grid of a 1 m square (100,352 triangles, 50,625 vertices) stretched and
     waved (curvatures up to ~10 1/m), hylcmat_mesh_eval at the same four levels (assembly included).
   Rates from the process CPU time, the best of 5 repetitions (the wall time of that one in brackets:
   other work may share the core, and the best repetition is the one it disturbed least).
   Targets (issue 31): energy + gradient >= 1e6 triangles/s, + Hessian >= 3e5/s, + projection >= 1e5/s. */
#include <hylcmat.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double Cpu(void)
{
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double Wall(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static unsigned long long Seed = 20260731;
static double             Uni(void) /* [-1, 1) */
{
  Seed = Seed * 6364136223846793005ULL + 1442695040888963407ULL;
  return 2.0 * (double)(Seed >> 11) / 9007199254740992.0 - 1;
}

/* a random interior stencil */
static void Stencil(double kappa, hylcmat_shell_rest *r, double x[18])
{
  const double L = 0.01 * (1 + 0.3 * Uni());
  double       u[6][2], y[18], Q[9], q[4], nq = 0;
  const double F[4] = {1.05 + 0.1 * Uni(), 0.1 * Uni(), 0.1 * Uni(), 1.05 + 0.1 * Uni()}, K[3] = {kappa * Uni(), 0.5 * kappa * Uni(), kappa * Uni()};

  u[0][0] = 0, u[0][1] = 0;
  u[1][0] = L * (1 + 0.2 * Uni()), u[1][1] = 0.2 * L * Uni();
  u[2][0] = L * (0.4 + 0.2 * Uni()), u[2][1] = L * (1 + 0.2 * Uni());
  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 2; i++) u[3 + k][i] = u[k][i] + u[(k + 1) % 3][i] - u[(k + 2) % 3][i] + 0.2 * L * Uni();
  {
    const double uv[6] = {u[0][0], u[0][1], u[1][0], u[1][1], u[2][0], u[2][1]};
    hylcmat_shell_rest_uv(uv, r);
  }
  for (int v = 0; v < 6; v++) {
    const double p = u[v][0], s = u[v][1];
    y[3 * v]     = F[0] * p + F[1] * s;
    y[3 * v + 1] = F[2] * p + F[3] * s;
    y[3 * v + 2] = 0.5 * (K[0] * p * p + 2 * K[1] * p * s + K[2] * s * s);
  }
  for (int i = 0; i < 4; i++) q[i] = Uni(), nq += q[i] * q[i];
  nq = sqrt(nq);
  for (int i = 0; i < 4; i++) q[i] /= nq;
  {
    const double w = q[0], a = q[1], b = q[2], c = q[3];
    const double R[9] = {1 - 2 * (b * b + c * c), 2 * (a * b - w * c), 2 * (a * c + w * b), 2 * (a * b + w * c), 1 - 2 * (a * a + c * c), 2 * (b * c - w * a), 2 * (a * c - w * b), 2 * (b * c + w * a), 1 - 2 * (a * a + b * b)};
    memcpy(Q, R, sizeof(R));
  }
  for (int v = 0; v < 6; v++)
    for (int i = 0; i < 3; i++) x[3 * v + i] = Q[3 * i] * y[3 * v] + Q[3 * i + 1] * y[3 * v + 1] + Q[3 * i + 2] * y[3 * v + 2] + 0.3 * i;
}

static const char *Verdict(double rate, double target) { return target <= 0 ? "" : (rate >= target ? "  (target >= %.0e: met)" : "  (target >= %.0e: NOT met)"); }

int main(void)
{
  const char *env = getenv("HYLC_REFDATA");
  char        path[4096], err[512];
  hylcmat    *m;
  enum { NS = 40 };
  hylcmat_shell_rest r[NS];
  double             X[NS][18], sc[5], sink = 0;
  const char        *names[4]   = {"energy", "energy + gradient", "+ Hessian", "+ PSD projection"};
  const double       targets[4] = {0, 1e6, 3e5, 1e5};

  snprintf(path, sizeof(path), "%s/materials/stock1.json", env ? env : "../shared/refdata");
  if (hylcmat_load(path, &m, err, sizeof(err))) {
    printf("bench_shell: skipped (%s)\n", err);
    return 0;
  }
  hylcmat_strain_scale(m, sc);
  for (int s = 0; s < NS; s++) Stencil(0.3 * sc[3], &r[s], X[s]);
  printf("shell element (Algorithm C8) on stock1.json, one core; rates from CPU time (wall time in brackets)\n");
  printf("per triangle, %d random interior stencils evaluated repeatedly:\n", NS);
  for (int lev = 0; lev < 4; lev++) {
    const long reps = lev < 2 ? 5000 : (lev == 2 ? 1600 : 400);
    double     best = 0, bestw = 0;
    for (int rep = 0; rep < 5; rep++) {
      double E, g[18], H[324], c0 = Cpu(), w0 = Wall(), c, w;
      for (long k = 0; k < reps; k++)
        for (int s = 0; s < NS; s++) {
          const int ret = hylcmat_shell_eval(m, &r[s], X[s], 7, lev == 3 ? HYLCMAT_SHELL_PSD : 0, &E, lev ? g : NULL, lev > 1 ? H : NULL);
          if (ret) {
            printf("error %d\n", ret);
            return 1;
          }
          sink += E;
        }
      c = Cpu() - c0;
      w = Wall() - w0;
      if (reps * NS / c > best) best = reps * NS / c, bestw = reps * NS / w;
    }
    printf("  %-18s %10.3g triangles/s (%.3g)", names[lev], best, bestw);
    printf(Verdict(best, targets[lev]), targets[lev]);
    printf("\n");
  }
  /* the same stencils through hylcmat_shell_eval_batch (the QR iterations of two elements interleaved) */
  {
    hylcmat_shell_rest rb[NS];
    int                nb[NS];
    double            *xb = malloc(sizeof(double) * 18 * NS), *Eb = malloc(sizeof(double) * NS), *gb = malloc(sizeof(double) * 18 * NS), *Hb = malloc(sizeof(double) * 324 * NS);
    for (int s = 0; s < NS; s++) {
      rb[s] = r[s], nb[s] = 7;
      for (int i = 0; i < 18; i++) xb[18 * s + i] = X[s][i];
    }
    printf("per triangle, the same stencils through hylcmat_shell_eval_batch (%d per call):\n", NS);
    for (int lev = 2; lev < 4; lev++) {
      const long reps = lev == 2 ? 1600 : 400;
      double     best = 0, bestw = 0;
      for (int rep = 0; rep < 5; rep++) {
        double c0 = Cpu(), w0 = Wall(), c, w;
        for (long k = 0; k < reps; k++) {
          if (hylcmat_shell_eval_batch(m, NS, rb, xb, nb, lev == 3 ? HYLCMAT_SHELL_PSD : 0, Eb, gb, Hb)) {
            printf("error\n");
            return 1;
          }
          sink += Eb[0];
        }
        c = Cpu() - c0;
        w = Wall() - w0;
        if (reps * NS / c > best) best = reps * NS / c, bestw = reps * NS / w;
      }
      printf("  %-18s %10.3g triangles/s (%.3g)", names[lev], best, bestw);
      printf(Verdict(best, targets[lev]), targets[lev]);
      printf("\n");
    }
    free(xb), free(Eb), free(gb), free(Hb);
  }
  /* the whole mesh */
  {
    const int     n = 224, nv = (n + 1) * (n + 1), nt = 2 * n * n;
    int          *tri = malloc(sizeof(int) * 3 * nt);
    double       *uv = malloc(sizeof(double) * 6 * nt), *x = malloc(sizeof(double) * 3 * nv), *g = malloc(sizeof(double) * 3 * nv), *h, E;
    hylcmat_mesh *M;
    double        c0 = Cpu(), w0 = Wall();
    for (int i = 0, t = 0; i < n; i++)
      for (int j = 0; j < n; j++, t += 2) {
        const int p = i * (n + 1) + j, q = (i + 1) * (n + 1) + j, rr = q + 1, s = p + 1;
        const int T[6] = {p, q, rr, p, rr, s};
        memcpy(tri + 3 * t, T, sizeof(T));
      }
    for (int t = 0; t < nt; t++)
      for (int k = 0; k < 3; k++) {
        const int v           = tri[3 * t + k];
        uv[6 * t + 2 * k]     = (double)(v / (n + 1)) / n;
        uv[6 * t + 2 * k + 1] = (double)(v % (n + 1)) / n;
      }
    if (hylcmat_mesh_create_uv(nv, nt, tri, uv, &M, err, sizeof(err))) {
      printf("mesh: %s\n", err);
      return 1;
    }
    printf("whole mesh, %d triangles, %d vertices, %lld Hessian entries (mesh set-up %.2f s):\n", nt, nv, (long long)hylcmat_mesh_hessian_nnz(M), Cpu() - c0 + 0 * w0);
    h = malloc(sizeof(double) * hylcmat_mesh_hessian_nnz(M));
    for (int v = 0; v < nv; v++) {
      const double u = (double)(v / (n + 1)) / n, s = (double)(v % (n + 1)) / n;
      x[3 * v]     = u * (1.05 + 0.02 * sin(7 * s));
      x[3 * v + 1] = s;
      x[3 * v + 2] = 0.01 * sin(2 * M_PI * u / 0.2) * cos(2 * M_PI * s / 0.3);
    }
    for (int lev = 0; lev < 4; lev++) {
      double best = 0, bestw = 0;
      for (int rep = 0; rep < (lev < 2 ? 5 : 3); rep++) {
        double c, w;
        int    ret;
        c0  = Cpu();
        w0  = Wall();
        ret = hylcmat_mesh_eval(M, m, x, lev == 3 ? HYLCMAT_SHELL_PSD : 0, &E, lev ? g : NULL, lev > 1 ? h : NULL, err, sizeof(err));
        c   = Cpu() - c0;
        w   = Wall() - w0;
        if (ret) {
          printf("mesh eval: %s\n", err);
          return 1;
        }
        sink += E;
        if (nt / c > best) best = nt / c, bestw = nt / w;
      }
      printf("  %-18s %10.3g triangles/s (%.3g)", names[lev], best, bestw);
      printf(Verdict(best, targets[lev]), targets[lev]);
      printf("\n");
    }
    hylcmat_mesh_free(M);
    free(tri), free(uv), free(x), free(g), free(h);
  }
  if (!isfinite(sink)) printf("(non-finite sum)\n");
  hylcmat_free(m);
  return 0;
}
