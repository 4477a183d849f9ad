/* hylcmat_eval_batch on one core: Psi + grad (and + Hessian) per second for 10^6 random strains of the
   paper's stock1 table ($HYLC_REFDATA/materials/stock1.json; skipped without it). */
#include <hylcmat.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double Now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(void)
{
  const char  *env = getenv("HYLC_REFDATA");
  char         path[4096], err[512];
  hylcmat     *m;
  const size_t n      = 1000000;
  const double amp[6] = {0.2, 0.3, 0.2, 50, 30, 50};
  double      *s, *psi, *grad, *hess;
  unsigned     seed = 12345;

  snprintf(path, sizeof(path), "%s/materials/stock1.json", env ? env : "../shared/refdata");
  if (hylcmat_load(path, &m, err, sizeof(err))) {
    printf("hylcmat_eval_batch: skipped (%s)\n", err);
    return 0;
  }
  s    = malloc(sizeof(double) * 6 * n);
  psi  = malloc(sizeof(double) * n);
  grad = malloc(sizeof(double) * 6 * n);
  hess = malloc(sizeof(double) * 36 * 100000);
  for (size_t i = 0; i < 6 * n; i++) {
    seed = seed * 1103515245u + 12345u;
    s[i] = amp[i % 6] * (2.0 * ((seed >> 8) & 0xffffff) / 16777216.0 - 1.0);
  }
  {
    double t = Now(), rate, rate2;
    hylcmat_eval_batch(m, n, s, psi, grad, NULL);
    rate = (double)n / (Now() - t);
    t    = Now();
    hylcmat_eval_batch(m, 100000, s, psi, grad, hess);
    rate2 = 1e5 / (Now() - t);
    printf("hylcmat_eval_batch (C) on stock1.json, one core: %.3g Psi+grad per second, %.3g Psi+grad+Hessian per second\n", rate, rate2);
  }
  free(s);
  free(psi);
  free(grad);
  free(hess);
  hylcmat_free(m);
  return 0;
}
