/* shell_element: the macroscale shell element of Algorithm C8 with hylcmat (include/hylcmat.h; libc +
   libm only), as a cloth simulator uses it: a mesh object built once (stencils, rest data, Hessian
   sparsity), then per frame the total energy, its gradient and the Hessian (CSR), optionally with each
   element Hessian projected to positive semidefinite; and one element on its own.

     cc -std=c99 shell_element.c $(pkg-config --cflags --libs hylcmat) -o shell_element
     ./shell_element stock1.json

   The mesh is a 4 x 4 grid of a 4 cm square (material coordinates u, v in m), bent into a cylinder of
   radius 2 cm around the v axis and stretched 5 % along it. docs/library.md has the conventions. */
#include <hylcmat.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { N = 4, NV = (N + 1) * (N + 1), NT = 2 * N * N };

int main(int argc, char **argv)
{
  hylcmat      *mat;
  hylcmat_mesh *mesh;
  char          err[512];
  int           tri[3 * NT], rc;
  double        X[3 * NV], x[3 * NV], grad[3 * NV], E, Ep, gn = 0;
  const double  side = 0.04, rho = 0.02;

  if (argc < 2) {
    fprintf(stderr, "usage: %s material.json\n", argv[0]);
    return 2;
  }
  if (hylcmat_load(argv[1], &mat, err, sizeof(err))) {
    fprintf(stderr, "shell_element: error: %s\n", err);
    return 1;
  }
  /* rest positions in the plane z = 0, triangles counter-clockwise seen from +z: n = +z at rest */
  for (int i = 0; i <= N; i++)
    for (int j = 0; j <= N; j++) {
      double *p = X + 3 * (i * (N + 1) + j);
      p[0] = side * i / N, p[1] = side * j / N, p[2] = 0;
    }
  for (int i = 0, t = 0; i < N; i++)
    for (int j = 0; j < N; j++, t += 2) {
      const int a = i * (N + 1) + j, b = (i + 1) * (N + 1) + j, c = b + 1, d = a + 1;
      const int T[6] = {a, b, c, a, c, d};
      for (int k = 0; k < 6; k++) tri[3 * t + k] = T[k];
    }
  /* material angle 0: u along each triangle's first edge x1 - x0, which is +x here for every triangle */
  if (hylcmat_mesh_create(NV, NT, tri, X, NULL, &mesh, err, sizeof(err))) {
    fprintf(stderr, "shell_element: error: %s\n", err);
    hylcmat_free(mat);
    return 1;
  }
  /* deformed: a cylinder around an axis along v on the +z side (bending toward n: II00 = +1/rho) */
  for (int v = 0; v < NV; v++) {
    const double s = X[3 * v] - 0.5 * side;
    x[3 * v]       = rho * sin(s / rho);
    x[3 * v + 1]   = 1.05 * X[3 * v + 1];
    x[3 * v + 2]   = rho * (1 - cos(s / rho));
  }
  {
    const int64_t nnz    = hylcmat_mesh_hessian_nnz(mesh);
    int64_t      *rowptr = malloc(sizeof(int64_t) * (3 * NV + 1));
    int          *colind = malloc(sizeof(int) * nnz);
    double       *hval   = malloc(sizeof(double) * nnz), z[6 * NT];
    hylcmat_mesh_hessian_csr(mesh, rowptr, colind);
    rc = hylcmat_mesh_eval(mesh, mat, x, HYLCMAT_SHELL_PSD, &E, grad, hval, err, sizeof(err));
    if (!rc) rc = hylcmat_mesh_eval(mesh, mat, X, 0, &Ep, NULL, NULL, err, sizeof(err));
    if (!rc) rc = hylcmat_mesh_strains(mesh, x, z, err, sizeof(err));
    if (rc)
      fprintf(stderr, "shell_element: error: %s\n", err);
    else {
      for (int i = 0; i < 3 * NV; i++) gn += grad[i] * grad[i];
      printf("mesh: %d vertices, %d triangles, rest area %g m^2, Hessian %d x %d with %lld entries\n", NV, NT, hylcmat_mesh_area(mesh), 3 * NV, 3 * NV, (long long)nnz);
      printf("flat at rest: E = %.10g J (= Psi(0) x area); bent: E = %.10g J, |dE/dx| = %.6g N\n", Ep, E, sqrt(gn));
      printf("an interior triangle's strains (sx, sa, sy, II00, II01, II11): %.4f %.4f %.4f %.2f %.2f %.2f (1/rho = %g)\n", z[6 * 12], z[6 * 12 + 1], z[6 * 12 + 2], z[6 * 12 + 3], z[6 * 12 + 4], z[6 * 12 + 5], 1 / rho);
      for (int64_t q = rowptr[36]; q < rowptr[37]; q++) /* row 36: vertex 12, x */
        if (colind[q] == 36) printf("projected Hessian: row 36 (vertex 12, x) has %lld entries, H[36][36] = %.6g N/m\n", (long long)(rowptr[37] - rowptr[36]), hval[q]);
    }
    free(rowptr), free(colind), free(hval);
  }
  /* one element on its own: triangle 12's stencil */
  if (!rc) {
    int                v[6], nb = 0;
    hylcmat_shell_rest r;
    double             xs[18], e, g[18], H[324];
    hylcmat_mesh_element(mesh, 12, v, &r);
    for (int i = 0; i < 6; i++)
      for (int c = 0; c < 3; c++) xs[3 * i + c] = v[i] >= 0 ? x[3 * v[i] + c] : 0;
    for (int k = 0; k < 3; k++) nb |= (v[3 + k] >= 0) << k;
    rc = hylcmat_shell_eval(mat, &r, xs, nb, 0, &e, g, H);
    if (rc)
      fprintf(stderr, "shell_element: error: %s\n", hylcmat_strerror(rc));
    else
      printf("triangle 12 alone: stencil %d %d %d | %d %d %d, rest area %g m^2, E = %.10g J, dE/dx0 = (%.4g %.4g %.4g)\n", v[0], v[1], v[2], v[3], v[4], v[5], r.area, e, g[0], g[1], g[2]);
  }
  hylcmat_mesh_free(mesh);
  hylcmat_free(mat);
  return rc ? 1 : 0;
}
