/* Stretching element of Discrete Elastic Rods: E = w 1/2 ks lbar (l/lbar - 1)^2 on one edge. */
#include <hylc/rod.h>
#include <hylc/geom.h>
#include <stddef.h>

int HylcRodStretch(const double x[6], double lbar, double ks, double w, double *E, double g[6], double H[36])
{
  double       e[3];
  const double il0 = 1.0 / lbar;

  HylcSub3(x + 3, x, e);
  const double l = HylcNorm3(e);
  if (!(l > 0)) {
    if (E) *E = HUGE_VAL;
    if (g)
      for (int i = 0; i < 6; i++) g[i] = 0;
    if (H)
      for (int i = 0; i < 36; i++) H[i] = 0;
    return -1;
  }
  const double strain = l * il0 - 1.0, wk = w * ks;
  if (E) *E = 0.5 * wk * lbar * strain * strain;
  if (g) {
    /* dE/de = w ks (l/lbar - 1) t; x_j gets -, x_{j+1} gets + */
    const double s = wk * strain / l;
    for (int i = 0; i < 3; i++) {
      g[i]     = -s * e[i];
      g[3 + i] = s * e[i];
    }
  }
  if (H) {
    /* d2E/de2 = w ks [(1/lbar - 1/l) I + (1/l) t t^T];  H = [He -He; -He He] */
    const double il = 1.0 / l, a = wk * (il0 - il), b = wk * il * il * il;
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        const double h         = (i == j ? a : 0.0) + b * e[i] * e[j];
        H[i * 6 + j]           = h;
        H[(i + 3) * 6 + j + 3] = h;
        H[i * 6 + j + 3]       = -h;
        H[(i + 3) * 6 + j]     = -h;
      }
    }
  }
  return 0;
}

double HylcRodStretchEnergy(const double x[6], double lbar, double ks, double w)
{
  double E;
  HylcRodStretch(x, lbar, ks, w, &E, NULL, NULL);
  return E;
}
