/* HylcMaterialEvaluate at extreme finite strains (issue 12, probe 4.1 and 4.10): every finite strain
   gives finite Psi, gradient and Hessian, for
   1. built-in tables at the edges of what the loader accepts: knots -1e308, 0, 1e308 (finite spacing),
      a spacing of 1e-300 (1/h finite, h^2 underflows), node values of 1e300, strain scales of 1e-300
      and 1e300, each extrapolation mode;
   2. every paper table in $HYLC_REFDATA/materials (skipped with a note when absent);
   at strains of 0, +-1e-320, +-1e-300, +-1e-10, +-0.3, +-1e3, +-1e155, +-1e300, +-1e308 and the largest
   double in each component, all components together (same and alternating signs), and 1000 random
   mixes of these magnitudes. Also: Psi does not depend on the level (with or without derivatives), the
   Hessian is symmetric, an exactly known far value (linear and bilinear extrapolation) is right or
   saturated at +-PETSC_MAX_REAL with the right sign, and the loader refuses a spacing whose inverse
   overflows (the probe's t = [0, 5e-324]). */
#include <hylc/material.h>
#include <petscsys.h>
#include <dirent.h>
#include <float.h>
#include <string.h>
#include "hylctest.h"

static const double Mag[] = {0, 1e-320, 1e-300, 1e-10, 0.3, 1e3, 1e155, 1e300, 1e308, DBL_MAX};
#define NMAG ((int)(sizeof(Mag) / sizeof(Mag[0])))

static PetscErrorCode CheckAt(HylcMaterial m, const char name[], const double s[6], long *nsat)
{
  double E, E0, E1, g[6], g1[6], H[36];
  int    bad = 0;

  PetscFunctionBegin;
  PetscCall(HylcMaterialEvaluate(m, s, &E, g, H));
  PetscCall(HylcMaterialEvaluate(m, s, &E0, NULL, NULL));
  PetscCall(HylcMaterialEvaluate(m, s, &E1, g1, NULL));
  bad = !isfinite(E);
  for (int i = 0; i < 6; i++) bad = bad || !isfinite(g[i]);
  for (int i = 0; i < 36; i++) bad = bad || !isfinite(H[i]);
  HYLC_CHECK(!bad, "%s: non-finite result at s = (%g, %g, %g, %g, %g, %g): psi %g, grad %g %g %g %g %g %g, H00 %g H33 %g H44 %g H55 %g", name, s[0], s[1], s[2], s[3], s[4], s[5], E, g[0], g[1], g[2], g[3], g[4], g[5], H[0], H[21], H[28], H[35]);
  HYLC_CHECK(E0 == E && E1 == E, "%s: Psi depends on the level at s = (%g, %g, %g, %g, %g, %g): %.17g %.17g %.17g", name, s[0], s[1], s[2], s[3], s[4], s[5], E0, E1, E);
  for (int i = 0; i < 6; i++) HYLC_CHECK(g1[i] == g[i], "%s: gradient %d depends on the level at s = (%g, %g, %g, %g, %g, %g)", name, i, s[0], s[1], s[2], s[3], s[4], s[5]);
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < i; j++) HYLC_CHECK(H[6 * i + j] == H[6 * j + i], "%s: Hessian not symmetric at (%d, %d)", name, i, j);
  if (fabs(E) == DBL_MAX) (*nsat)++;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the sweep over the strains of the header */
static PetscErrorCode Sweep(HylcMaterial m, const char name[])
{
  unsigned long long rng = 12345;
  double             s[6];
  long               nsat = 0, n = 0;

  PetscFunctionBegin;
  for (int k = 0; k < 6; k++)
    for (int a = 0; a < NMAG; a++)
      for (int sg = -1; sg <= 1; sg += 2) {
        for (int i = 0; i < 6; i++) s[i] = 0;
        s[k] = sg * Mag[a];
        PetscCall(CheckAt(m, name, s, &nsat));
        n++;
      }
  for (int a = 0; a < NMAG; a++)
    for (int pat = 0; pat < 4; pat++) {
      for (int i = 0; i < 6; i++) s[i] = Mag[a] * (pat == 0 ? 1 : pat == 1 ? -1 : pat == 2 ? (i % 2 ? -1 : 1) : (i % 3 ? 1 : -1));
      PetscCall(CheckAt(m, name, s, &nsat));
      n++;
    }
  for (int r = 0; r < 1000; r++) {
    for (int i = 0; i < 6; i++) {
      const int    a  = (int)(HylcTestRand(&rng) * NMAG);
      const double sg = HylcTestRand(&rng) < 0.5 ? -1 : 1;
      s[i]            = sg * Mag[a] * (HylcTestRand(&rng) < 0.3 ? 0.5 + 0.5 * HylcTestRand(&rng) : 1); /* finite: at most the magnitude */
    }
    PetscCall(CheckAt(m, name, s, &nsat));
    n++;
  }
  HYLC_CHECK(nsat < n, "%s: every Psi saturated", name);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a 1D term k with knots t (n), values p and slopes m */
static PetscErrorCode Set1(HylcMaterial mat, PetscInt k, PetscInt n, const double t[], const double p[], const double m[], HylcSplineExt ext)
{
  HylcSpline1D s;

  PetscFunctionBegin;
  s.k   = k;
  s.n   = n;
  s.t   = (PetscReal *)t;
  s.p   = (PetscReal *)p;
  s.m   = (PetscReal *)m;
  s.ext = ext;
  PetscCall(HylcMaterialSet1D(mat, &s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a 2D term (k0, k1) on 3 x 3 knots tu, tv with node data from one seed */
static PetscErrorCode Set2(HylcMaterial mat, PetscInt k0, PetscInt k1, const double tu[3], const double tv[3], double amp, HylcSplineExt ext, unsigned long long *rng)
{
  HylcSpline2D s;
  double       p[9], mu[9], mv[9], muv[9];

  PetscFunctionBegin;
  for (int i = 0; i < 9; i++) {
    p[i]   = amp * (2 * HylcTestRand(rng) - 1);
    mu[i]  = amp * (2 * HylcTestRand(rng) - 1);
    mv[i]  = amp * (2 * HylcTestRand(rng) - 1);
    muv[i] = amp * (2 * HylcTestRand(rng) - 1);
  }
  s.k0  = k0;
  s.k1  = k1;
  s.nu  = 3;
  s.nv  = 3;
  s.tu  = (PetscReal *)tu;
  s.tv  = (PetscReal *)tv;
  s.p   = p;
  s.mu  = mu;
  s.mv  = mv;
  s.muv = muv;
  s.ext = ext;
  PetscCall(HylcMaterialSet2D(mat, &s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* every term of the model on the given knots (the same for each axis), amplitude amp, one mode */
static PetscErrorCode BuildAll(HylcMaterial mat, const double t[3], double amp, double scale, HylcSplineExt ext, unsigned long long *rng)
{
  double sc[5] = {scale, scale, scale, scale, scale};

  PetscFunctionBegin;
  PetscCall(HylcMaterialReset(mat));
  PetscCall(HylcMaterialSetStrainScale(mat, sc));
  for (PetscInt k = 0; k < 5; k++) {
    double p[3], m[3];
    for (int i = 0; i < 3; i++) {
      p[i] = amp * (2 * HylcTestRand(rng) - 1);
      m[i] = amp * (2 * HylcTestRand(rng) - 1);
    }
    PetscCall(Set1(mat, k, 3, t, p, m, ext));
  }
  for (PetscInt q = 0; q < 9; q++) PetscCall(Set2(mat, HylcMaterialPairs[q][0], HylcMaterialPairs[q][1], t, t, amp, ext, rng));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  HylcMaterial       mat;
  unsigned long long rng        = 777;
  const double       knots[][3] = {{-1e308, 0, 1e308}, {0, 1e-300, 2e-300}, {-1, 0, 1}, {-1e-300, 0, 1e-300}};
  const double       amps[]     = {1, 1e300};
  const double       scales[]   = {1, 1e-300, 1e300, 170};
  char               name[128];

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &mat));

  /* 1. built-in extreme tables */
  for (size_t a = 0; a < sizeof(knots) / sizeof(knots[0]); a++)
    for (size_t b = 0; b < sizeof(amps) / sizeof(amps[0]); b++)
      for (size_t c = 0; c < sizeof(scales) / sizeof(scales[0]); c++)
        for (int e = 0; e < 3; e++) {
          snprintf(name, sizeof(name), "knots (%g, %g, %g), amplitude %g, scale %g, ext %d", knots[a][0], knots[a][1], knots[a][2], amps[b], scales[c], e);
          PetscCall(BuildAll(mat, knots[a], amps[b], scales[c], (HylcSplineExt)e, &rng));
          PetscCall(Sweep(mat, name));
        }

  /* exact far values: f_sx = 2 + 3 (x - 1) right of [0, 1] (linear), and the bilinear corner of f_sx-sy */
  {
    const double t[2] = {0, 1}, p[2] = {0, 2}, m1[2] = {0, 3};
    const double tu[3] = {-1, 0, 1}, zero[9] = {0}, muv[9] = {0, 0, 0, 0, 0, 0, 0, 0, -1};
    HylcSpline2D s2 = {0, 2, 3, 3, (PetscReal *)tu, (PetscReal *)tu, (PetscReal *)zero, (PetscReal *)zero, (PetscReal *)zero, (PetscReal *)muv, HYLC_EXT_LINEAR};
    double       E, g[6], H[36], st[6] = {1e300, 0, 0, 0, 0, 0};

    PetscCall(HylcMaterialReset(mat));
    PetscCall(Set1(mat, 0, 2, t, p, m1, HYLC_EXT_LINEAR));
    PetscCall(HylcMaterialEvaluate(mat, st, &E, g, H));
    HYLC_CHECK_REL(E, 3e300, 1e-15);
    HYLC_CHECK(g[0] == 3 && H[0] == 0, "far gradient %g, Hessian %g (expected 3, 0)", g[0], H[0]);
    st[0] = 1e308;
    PetscCall(HylcMaterialEvaluate(mat, st, &E, g, H));
    HYLC_CHECK(E == DBL_MAX && g[0] == 3, "Psi(1e308) = %g (expected the largest double: 3e308 saturated), grad %g", E, g[0]);
    st[0] = -1e308; /* left of t[0]: p = 0, m = 0 */
    PetscCall(HylcMaterialEvaluate(mat, st, &E, g, H));
    HYLC_CHECK(E == 0 && g[0] == 0, "Psi(-1e308) = %g, grad %g (expected 0, 0)", E, g[0]);
    PetscCall(HylcMaterialReset(mat));
    PetscCall(HylcMaterialSet2D(mat, &s2));
    st[0] = 1e200;
    st[2] = 1e200; /* muv du dv = -(1e200 - 1)^2: beyond the double range, negative */
    PetscCall(HylcMaterialEvaluate(mat, st, &E, g, H));
    HYLC_CHECK(E == -DBL_MAX, "bilinear corner: Psi = %g (expected -largest double)", E);
    HYLC_CHECK_REL(g[0], -1e200, 1e-12);
    HYLC_CHECK(H[2] == -1 && H[12] == -1, "bilinear corner: H02 = %g (expected -1)", H[2]);
  }

  /* the loader refuses a spacing whose inverse overflows (issue 12, probe 4.1) */
  {
    const double   t[2] = {0, 5e-324}, p[2] = {0, 1}, m[2] = {0, 0};
    HylcSpline1D   s = {0, 2, (PetscReal *)t, (PetscReal *)p, (PetscReal *)m, HYLC_EXT_LINEAR};
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = HylcMaterialSet1D(mat, &s);
    PetscCall(PetscPopErrorHandler());
    HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "t = [0, 5e-324] accepted (error %d)", (int)ierr);
  }

  /* 2. the paper's tables */
  {
    const char *env = getenv("HYLC_REFDATA");
    char        dir[PETSC_MAX_PATH_LEN];
    DIR        *d;
    int         nfiles = 0;
    snprintf(dir, sizeof(dir), "%s/materials", env ? env : "");
    d = env ? opendir(dir) : NULL;
    if (!d)
      printf("note: no $HYLC_REFDATA/materials: paper tables not swept\n");
    else {
      struct dirent *e;
      while ((e = readdir(d))) {
        const size_t l = strlen(e->d_name);
        char         path[2 * PETSC_MAX_PATH_LEN];
        if (l < 6 || strcmp(e->d_name + l - 5, ".json")) continue;
        snprintf(path, sizeof(path), "%s/%s", dir, e->d_name);
        PetscCall(HylcMaterialLoad(mat, path));
        PetscCall(Sweep(mat, e->d_name));
        nfiles++;
      }
      closedir(d);
      HYLC_CHECK(nfiles > 0, "no .json in %s", dir);
    }
  }
  PetscCall(HylcMaterialDestroy(&mat));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
