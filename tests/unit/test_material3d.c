/* hylc's 3D terms (include/hylcmat.h, hylcmat_term3d: (sx,sa,sy) and each in-plane pair with II00 and with II11) in the evaluator:
   - a table with every kind of term, the 3D ones with random node data, evaluated at strains away from the knots
     (II01 != 0, II00 = II11 and II = 0 among them): the gradient against central differences of Psi (to 1e-6 of
     its scale), the Hessian against central differences of the gradient (to 1e-5; not at II = 0, where the
     bending coordinate sits on a knot and the C1 splines' second derivatives jump);
   - at II01 = 0 the (sx, sy, II00) term contributes its tricubic at (sx, sy, II00) where II00 >= II11 and at
     (sx, sy, II11)'s x-bending value where II00 < II11 (the eigen-split's convention), checked against a
     direct tensor-product evaluation;
   - the setter refuses a triple that is not a term, bad knots and non-finite data, naming them;
   - the 3D terms through a HylcMaterial (HylcMaterialSet3D) into the HDF5 format (version 2, group /3D) and back
     give the same Psi and gradient bit for bit; the ARCSim-HYLC JSON leaves them out (its format has none).
   hylc-test: nprocs=1 */
#include <hylc/material.h>
#include <hylcmat.h>
#include <petscsys.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "hylctest.h"

static double Rnd(unsigned *s)
{
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xffff) / 65535.0 * 2 - 1;
}

/* 1D cubic Hermite basis at x on [t0, t1]: a0, a1 (values), b0, b1 (slopes) */
static void H1(double t0, double t1, double x, double a[2], double b[2])
{
  const double h = t1 - t0, s = (x - t0) / h;
  a[0] = 2 * s * s * s - 3 * s * s + 1, a[1] = -2 * s * s * s + 3 * s * s;
  b[0] = (s * s * s - 2 * s * s + s) * h, b[1] = (s * s * s - s * s) * h;
}

/* the tricubic of a 3D term at (u, v, w) inside its knots, directly */
static double Direct3(const hylcmat_term3d *t, double u, double v, double w)
{
  int    i = 0, j = 0, k = 0;
  double au[2], bu[2], av[2], bv[2], aw[2], bw[2], f = 0;
  while (i + 2 < t->nu && u >= t->tu[i + 1]) i++;
  while (j + 2 < t->nv && v >= t->tv[j + 1]) j++;
  while (k + 2 < t->nw && w >= t->tw[k + 1]) k++;
  H1(t->tu[i], t->tu[i + 1], u, au, bu);
  H1(t->tv[j], t->tv[j + 1], v, av, bv);
  H1(t->tw[k], t->tw[k + 1], w, aw, bw);
  for (int c = 0; c < 2; c++)
    for (int b = 0; b < 2; b++)
      for (int a = 0; a < 2; a++) {
        const int n = ((k + c) * t->nv + j + b) * t->nu + i + a;
        f += au[a] * av[b] * aw[c] * t->p[n] + bu[a] * av[b] * aw[c] * t->mu[n] + au[a] * bv[b] * aw[c] * t->mv[n] + au[a] * av[b] * bw[c] * t->mw[n];
        f += bu[a] * bv[b] * aw[c] * t->muv[n] + bu[a] * av[b] * bw[c] * t->muw[n] + au[a] * bv[b] * bw[c] * t->mvw[n] + bu[a] * bv[b] * bw[c] * t->muvw[n];
      }
  return f;
}

int main(int argc, char **argv)
{
  hylcmat  *m;
  char      err[512];
  unsigned  seed  = 7;
  double    tk[5] = {-1, -0.4, 0, 0.3, 1}, data[11][125];
  const int n = 5, N = 125;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  HYLC_CHECK(!hylcmat_create(&m), "create");
  {
    const double scale[5] = {1, 0.75, 1, 170, 170};
    HYLC_CHECK(!hylcmat_set_strain_scale(m, scale, err, sizeof(err)), "%s", err);
  }
  /* 1D and 2D terms so that the 3D ones add to something */
  for (int k = 0; k < 5; k++) {
    double p[5], mm[5];
    for (int i = 0; i < n; i++) p[i] = 0.3 * tk[i] * tk[i] + 0.05 * Rnd(&seed), mm[i] = 0.6 * tk[i] + 0.05 * Rnd(&seed);
    hylcmat_term1d t = {k, n, HYLCMAT_EXT_LINEAR, tk, p, mm};
    HYLC_CHECK(!hylcmat_set_term1d(m, &t, err, sizeof(err)), "%s", err);
  }
  for (int q = 0; q < 9; q++) {
    double p[25], mu[25], mv[25], muv[25];
    int    k0, k1;
    hylcmat_pair(q, &k0, &k1);
    for (int i = 0; i < 25; i++) p[i] = 0.02 * Rnd(&seed), mu[i] = 0.02 * Rnd(&seed), mv[i] = 0.02 * Rnd(&seed), muv[i] = 0.02 * Rnd(&seed);
    hylcmat_term2d t = {k0, k1, n, n, HYLCMAT_EXT_LINEAR, tk, tk, p, mu, mv, muv};
    HYLC_CHECK(!hylcmat_set_term2d(m, &t, err, sizeof(err)), "%s", err);
  }
  for (int r = 0; r < HYLCMAT_N3D; r++) {
    int k0, k1, k2;
    hylcmat_triple(r, &k0, &k1, &k2);
    for (int a = 0; a < 8; a++)
      for (int i = 0; i < N; i++) data[a][i] = 0.03 * Rnd(&seed);
    hylcmat_term3d t = {k0, k1, k2, n, n, n, HYLCMAT_EXT_LINEAR, tk, tk, tk, data[0], data[1], data[2], data[3], data[4], data[5], data[6], data[7]};
    HYLC_CHECK(!hylcmat_set_term3d(m, &t, err, sizeof(err)), "%s", err);
  }
  /* derivatives against central differences */
  {
    const double pts[][6] = {
        {0.1, 0.2, -0.15, 30, 10, -20}, {-0.2, -0.1, 0.25, 12, 0, 12}, {0.05, 0.02, 0.08, 0, 0, 0}, {0.35, 0.4, 0.1, -60, 25, 40}, {-0.1, 0.3, -0.2, 80, 0, -5}, {0.2, -0.25, 0.15, 7, -3, 7},
    };
    for (size_t c = 0; c < sizeof(pts) / sizeof(pts[0]); c++) {
      double psi, g[6], H[36], gs = 0, Hs = 0, eg = 0, eH = 0;
      HYLC_CHECK(!hylcmat_eval(m, pts[c], &psi, g, H), "eval");
      for (int i = 0; i < 6; i++) gs = fmax(gs, fabs(g[i]) * (i >= 3 ? 100 : 1));
      for (int i = 0; i < 36; i++) Hs = fmax(Hs, fabs(H[i]) * (i / 6 >= 3 ? 100 : 1) * (i % 6 >= 3 ? 100 : 1));
      for (int i = 0; i < 6; i++) {
        const double h = i >= 3 ? 1e-5 : 1e-6;
        double       zp[6], zm[6], pp, pm, gp[6], gm[6];
        memcpy(zp, pts[c], sizeof(zp));
        memcpy(zm, pts[c], sizeof(zm));
        zp[i] += h, zm[i] -= h;
        HYLC_CHECK(!hylcmat_eval(m, zp, &pp, gp, NULL) && !hylcmat_eval(m, zm, &pm, gm, NULL), "eval");
        eg = fmax(eg, fabs((pp - pm) / (2 * h) - g[i]) * (i >= 3 ? 100 : 1));
        for (int j = 0; j < 6; j++) eH = fmax(eH, fabs((gp[j] - gm[j]) / (2 * h) - H[6 * i + j]) * (i >= 3 ? 100 : 1) * (j >= 3 ? 100 : 1));
      }
      if (getenv("HYLC_TEST_VERBOSE")) printf("point %d: gradient error %.3g of %.3g, Hessian error %.3g of %.3g\n", (int)c, eg, gs, eH, Hs);
      HYLC_CHECK(eg <= 1e-6 * gs, "point %d: the gradient differs from central differences by %.3g (scale %.3g)", (int)c, eg, gs);
      /* at II = 0 the bending coordinate sits on a knot, where the splines' second derivatives jump (they are C1):
         only the gradient is compared there */
      if (pts[c][3] != 0 || pts[c][4] != 0 || pts[c][5] != 0) HYLC_CHECK(eH <= 1e-5 * Hs, "point %d: the Hessian differs from central differences of the gradient by %.3g (scale %.3g)", (int)c, eH, Hs);
    }
  }
  /* the (sx, sy, II00) term's part at II01 = 0 against the direct tricubic: Psi with minus Psi without it */
  {
    hylcmat_term3d t;
    hylcmat       *m2;
    const double   z[6] = {0.12, 0, -0.07, 45, 0, 10}, sc = 170;
    double         a, b;
    HYLC_CHECK(hylcmat_term3d_get(m, 0, 2, 3, &t), "get (0,2,3)");
    HYLC_CHECK(!hylcmat_create(&m2), "create");
    {
      const double scale[5] = {1, 0.75, 1, 170, 170};
      HYLC_CHECK(!hylcmat_set_strain_scale(m2, scale, err, sizeof(err)), "%s", err);
      HYLC_CHECK(!hylcmat_set_term3d(m2, &t, err, sizeof(err)), "%s", err);
    }
    HYLC_CHECK(!hylcmat_eval(m2, z, &a, NULL, NULL), "eval");
    b = Direct3(&t, z[0], z[2], z[3] / sc);
    HYLC_CHECK(fabs(a - b) <= 1e-14 * fmax(1, fabs(b)), "(sx, sy, II00) at II00 = 45 > II11: %.17g, the tricubic %.17g", a, b);
    {
      const double zs[6] = {0.12, 0, -0.07, 10, 0, 45}; /* II00 < II11: the x-bending function at the smaller eigenvalue */
      HYLC_CHECK(!hylcmat_eval(m2, zs, &a, NULL, NULL), "eval");
      b = Direct3(&t, zs[0], zs[2], zs[3] / sc);
      HYLC_CHECK(fabs(a - b) <= 1e-14 * fmax(1, fabs(b)), "(sx, sy, II00) at II00 = 10 < II11 = 45: %.17g, the tricubic at II00 %.17g", a, b);
    }
    /* constant beyond the knots (the fabric fit's extension of a 3D term: a correction known only inside its
       sampled box): outside in sx and sy it is the tricubic at the nearest face; linear would differ */
    {
      const double zo[6] = {1.8, 0, 1.4, 45, 0, 10};
      hylcmat     *m3;
      double       lin;
      HYLC_CHECK(!hylcmat_eval(m2, zo, &lin, NULL, NULL), "eval");
      t.ext = HYLCMAT_EXT_CONSTANT;
      HYLC_CHECK(!hylcmat_create(&m3), "create");
      {
        const double scale[5] = {1, 0.75, 1, 170, 170};
        HYLC_CHECK(!hylcmat_set_strain_scale(m3, scale, err, sizeof(err)), "%s", err);
        HYLC_CHECK(!hylcmat_set_term3d(m3, &t, err, sizeof(err)), "%s", err);
      }
      HYLC_CHECK(!hylcmat_eval(m3, zo, &a, NULL, NULL), "eval");
      b = Direct3(&t, 1, 1, zo[3] / sc);
      HYLC_CHECK(fabs(a - b) <= 1e-14 * fmax(1, fabs(b)), "constant extension at sx 1.8, sy 1.4: %.17g, the tricubic at the box's corner %.17g", a, b);
      HYLC_CHECK(fabs(lin - b) > 1e-6, "the linear extension equals the constant one (%.17g): the check cannot fail", lin);
      hylcmat_free(m3);
    }
    hylcmat_free(m2);
  }
  /* refusals */
  {
    hylcmat_term3d t;
    int            r;
    HYLC_CHECK(hylcmat_term3d_get(m, 0, 1, 2, &t), "get (0,1,2)");
    t.k1 = 3;
    t.k2 = 4;
    r    = hylcmat_set_term3d(m, &t, err, sizeof(err));
    HYLC_CHECK(r == HYLCMAT_ERR_FORMAT && strstr(err, "not a term"), "(0,3,4): %d '%s'", r, err);
    HYLC_CHECK(hylcmat_term3d_get(m, 0, 1, 2, &t), "get (0,1,2)");
    {
      double bad[5] = {-1, 0, 0, 0.5, 1};
      t.tv          = bad;
      r             = hylcmat_set_term3d(m, &t, err, sizeof(err));
      HYLC_CHECK(r == HYLCMAT_ERR_FORMAT && strstr(err, "tv"), "knots not increasing: %d '%s'", r, err);
    }
    HYLC_CHECK(hylcmat_term3d_get(m, 0, 1, 2, &t), "get (0,1,2)");
    {
      double d[125];
      memcpy(d, t.muvw, sizeof(d));
      d[17]  = NAN;
      t.muvw = d;
      r      = hylcmat_set_term3d(m, &t, err, sizeof(err));
      HYLC_CHECK(r == HYLCMAT_ERR_FORMAT && strstr(err, "muvw"), "NaN in muvw: %d '%s'", r, err);
    }
  }
  /* the HDF5 round trip (and the JSON without the 3D terms) */
  {
    HylcMaterial M;
    hylcmat     *back, *js;
    char         dir[]    = "/tmp/hylc-m3d-XXXXXX", h5[256], json[256];
    const double scale[5] = {1, 0.75, 1, 170, 170};
    HYLC_CHECK(mkdtemp(dir) != NULL, "mkdtemp");
    snprintf(h5, sizeof(h5), "%s/m.h5", dir);
    snprintf(json, sizeof(json), "%s/m.json", dir);
    PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &M));
    PetscCall(HylcMaterialSetStrainScale(M, scale));
    PetscCall(HylcMaterialSetConstant(M, 0.01));
    for (int r = 0; r < HYLCMAT_N3D; r++) {
      hylcmat_term3d t;
      int            k0, k1, k2;
      hylcmat_triple(r, &k0, &k1, &k2);
      HYLC_CHECK(hylcmat_term3d_get(m, k0, k1, k2, &t), "get %d", r);
      PetscCall(HylcMaterialSet3D(M, &t));
    }
    PetscCall(HylcMaterialWriteHDF5(M, h5, NULL));
    PetscCall(HylcMaterialWriteJSON(M, json));
    HYLC_CHECK(!hylcmat_load(h5, &back, err, sizeof(err)), "load %s: %s", h5, err);
    HYLC_CHECK(!hylcmat_load(json, &js, err, sizeof(err)), "load %s: %s", json, err);
    if (back && js) {
      const double z[3][6] = {{0.1, 0.2, -0.15, 30, 10, -20}, {0.2, -0.25, 0.15, 7, -3, 7}, {-0.3, 0.1, 0.2, -40, 0, 60}};
      for (int c = 0; c < 3; c++) {
        double a, b, ga[6], gb[6], pa;
        PetscCall(HylcMaterialEvaluate(M, z[c], &pa, NULL, NULL));
        HYLC_CHECK(!hylcmat_eval(back, z[c], &a, ga, NULL) && !hylcmat_eval(js, z[c], &b, gb, NULL), "eval");
        HYLC_CHECK(a == pa, "point %d: Psi %.17g after the HDF5 round trip, %.17g before", c, a, pa);
        HYLC_CHECK(b == 0.01 && pa != 0.01, "point %d: the JSON table gives %.17g (its constant 0.01 only: no 3D terms), the full one %.17g", c, b, pa);
      }
      for (int r = 0; r < HYLCMAT_N3D; r++) {
        hylcmat_term3d t;
        int            k0, k1, k2;
        hylcmat_triple(r, &k0, &k1, &k2);
        HYLC_CHECK(hylcmat_term3d_get(back, k0, k1, k2, &t), "the HDF5 table lost 3D term %s", hylcmat_term3d_name(r));
        HYLC_CHECK(!hylcmat_term3d_get(js, k0, k1, k2, &t), "the JSON table has 3D term %s", hylcmat_term3d_name(r));
      }
    }
    hylcmat_free(back);
    hylcmat_free(js);
    PetscCall(HylcMaterialDestroy(&M));
    unlink(h5);
    unlink(json);
    rmdir(dir);
  }
  hylcmat_free(m);
  PetscCall(PetscFinalize());
  return hylc_test_failures ? 1 : 0;
}
