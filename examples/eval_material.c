/* eval_material: how a cloth simulator uses hylcmat (include/hylcmat.h; libc + libm only).
   Loads a material table once, then evaluates Psi, its gradient and its Hessian at a batch of strains
   s = (sx, sa, sy, II00, II01, II11), as a simulator does per element and per frame.

     cc eval_material.c $(pkg-config --cflags --libs hylcmat) -o eval_material
     ./eval_material stock1.json                 # a few strains, Psi and dPsi/ds
     ./eval_material stock1.json 0.1,0,0,0,0,0   # one strain: Psi, gradient, Hessian (%.17g) */
#include <hylcmat.h>
#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
  hylcmat *mat;
  char     err[512];
  int      r;

  if (argc < 2) {
    fprintf(stderr, "usage: %s material.json [sx,sa,sy,II00,II01,II11]\n", argv[0]);
    return 2;
  }
  r = hylcmat_load(argv[1], &mat, err, sizeof(err));
  if (r) {
    fprintf(stderr, "eval_material: error: %s\n", err);
    return 1;
  }
  if (argc > 2) { /* one strain, everything */
    double s[6], psi, grad[6], hess[36];
    if (sscanf(argv[2], "%lf,%lf,%lf,%lf,%lf,%lf", &s[0], &s[1], &s[2], &s[3], &s[4], &s[5]) != 6) {
      fprintf(stderr, "eval_material: error: '%s' is not six comma-separated numbers\n", argv[2]);
      hylcmat_free(mat);
      return 2;
    }
    r = hylcmat_eval(mat, s, &psi, grad, hess);
    if (r) {
      fprintf(stderr, "eval_material: error: %s\n", hylcmat_strerror(r));
      hylcmat_free(mat);
      return 1;
    }
    printf("psi: %.17g\ngrad:", psi);
    for (int i = 0; i < 6; i++) printf(" %.17g", grad[i]);
    printf("\nhessian:\n");
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++) printf("%.17g%s", hess[6 * i + j], j < 5 ? " " : "\n");
  } else { /* a batch: stretch, shear, and bending with equal curvatures (II00 = II11, II01 = 0) */
    enum { N = 4 };
    const double strains[N * 6] = {0.1, 0, 0, 0, 0, 0, 0, 0.2, 0, 0, 0, 0, 0.05, 0, -0.02, 30, 0, 30, 0, 0, 0, 20, 5, -10};
    double       psi[N], grad[N * 6];
    r = hylcmat_eval_batch(mat, N, strains, psi, grad, NULL); /* no Hessian: NULL */
    for (int k = 0; k < N && !r; k++) {
      printf("s = (%g, %g, %g, %g, %g, %g): psi = %.10g J/m^2, dpsi/ds =", strains[6 * k], strains[6 * k + 1], strains[6 * k + 2], strains[6 * k + 3], strains[6 * k + 4], strains[6 * k + 5], psi[k]);
      for (int i = 0; i < 6; i++) printf(" %.6g", grad[6 * k + i]);
      printf("\n");
    }
    if (r) fprintf(stderr, "eval_material: error: %s\n", hylcmat_strerror(r));
  }
  hylcmat_free(mat);
  return r ? 1 : 0;
}
