/* The fitting pipeline (HylcFitCompute) on synthetic samples of a known smooth quasiconvex Psi, taken
   on the sampling plan of Algorithm C4 (include/hylc/plan.h; 150 1D samples, 50 x 50 2D grids: the full 23,251-sample plan):
   - the model (S26) reproduces Psi to 1 % at every sample with the woven settings, in paper and authors
     compat modes (worst 0.83 %, at the range ends where the splines extrapolate beyond the 0.95 / 0.9
     knot spans); with the stockinette settings to 2 % inside the knots;
   - f0 is the zero sample's Psi, the strain scale the max |strain| of the data, the knots as in §9.1;
   - 2D residual terms vanish on the axes, are zero at compressed nodes (and on the whole compressed
     half-plane with -fit_zero_compression_strict) except for (sx, sy), have muv = 0 on the boundary;
   - extrapolation is linear and increasing outward;
   - a requested term without samples is left out; bad data give clear errors. */
#include <hylc/fit.h>
#include <hylc/plan.h>
#include "hylctest.h"
#include "fittest.h"
#include <string.h>

#define V                                       FitTestV
#define MakeData(n1, n2, drop, n, z, psi, term) FitTestMakeData("woven", n1, n2, drop, n, z, psi, term)

/* fits the data with the given options; checks accuracy and the structural properties */
static PetscErrorCode Check(const char *label, const char *options, PetscBool strict, double tol, PetscBool inside)
{
  HylcFit    fit;
  PetscInt   n;
  PetscReal *z, *psi, f0, scale[5], worst = 0;
  PetscInt  *term;

  PetscFunctionBeginUser;
  MakeData(150, 50, -1, &n, &z, &psi, &term);
  PetscCall(PetscOptionsClear(NULL));
  PetscCall(PetscOptionsInsertString(NULL, options));
  PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
  PetscCall(HylcFitSetFromOptions(fit));
  PetscCall(HylcFitSetData(fit, n, z, psi, term, 0.3));
  PetscCall(HylcFitCompute(fit));
  PetscCall(HylcFitGetConstant(fit, &f0));
  HYLC_CHECK(f0 == psi[0], "%s: f0 %g is not the zero sample's %g", label, f0, psi[0]);
  PetscCall(HylcFitGetStrainScale(fit, scale));
  for (int c = 0; c < 5; c++) HYLC_CHECK(scale[c] == V[c], "%s: strain scale %d: %g, expected %g", label, c, scale[c], V[c]);
  /* the material filled by HylcFitRun evaluates to the same model (S26) */
  {
    HylcMaterial mat;
    PetscReal    sc[5], c0, rho;
    PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &mat));
    PetscCall(HylcFitRun(fit, mat));
    PetscCall(HylcMaterialGetStrainScale(mat, sc));
    PetscCall(HylcMaterialGetConstant(mat, &c0));
    PetscCall(HylcMaterialGetDensity(mat, &rho));
    HYLC_CHECK(c0 == f0 && rho == 0.3 && sc[3] == V[3], "%s: material constants", label);
    for (PetscInt k = 0; k < n; k++) {
      PetscReal a, b;
      PetscCall(HylcFitEvaluateAxes(fit, z + 6 * k, &a));
      PetscCall(HylcMaterialEvaluate(mat, z + 6 * k, &b, NULL, NULL));
      HYLC_CHECK(fabs(a - b) <= 1e-12 * fabs(a), "%s: sample %d: HylcMaterialEvaluate %.17g, the fit's model %.17g", label, (int)k, b, a);
      if (fabs(a - b) > 1e-12 * fabs(a)) break;
    }
    PetscCall(HylcMaterialDestroy(&mat));
  }
  /* accuracy at every sample */
  for (PetscInt k = 0; k < n; k++) {
    PetscReal f;
    if (inside && term[k] >= 6) { /* only where the 2D term interpolates (inside its knots) */
      const HylcSpline2D *s;
      int                 ci, cj;
      HylcPlanPair((int)term[k], &ci, &cj);
      PetscCall(HylcFitGet2D(fit, ci, cj, &s));
      const double u = z[6 * k + HylcPlanStrainIndex(ci)] / V[ci], v = z[6 * k + HylcPlanStrainIndex(cj)] / V[cj];
      if (u < s->tu[0] || u > s->tu[s->nu - 1] || v < s->tv[0] || v > s->tv[s->nv - 1]) continue;
    }
    PetscCall(HylcFitEvaluateAxes(fit, z + 6 * k, &f));
    const double rel = fabs(f - psi[k]) / psi[k];
    if (rel > worst) worst = rel;
    if (getenv("HYLC_TEST_VERBOSE") && rel > 0.5 * tol) printf("  %s %g %g %g %g %g: %.3f %%\n", HylcPlanTermName((int)term[k]), z[6 * k], z[6 * k + 1], z[6 * k + 2], z[6 * k + 3], z[6 * k + 5], 100 * rel);
    HYLC_CHECK(rel < tol, "%s: sample %d (term %s, z = %g %g %g %g %g): model %.6g, Psi %.6g (%.2f %%)", label, (int)k, HylcPlanTermName((int)term[k]), z[6 * k], z[6 * k + 1], z[6 * k + 2], z[6 * k + 3], z[6 * k + 5], f, psi[k], 100 * rel);
    if (rel >= tol && !getenv("HYLC_TEST_VERBOSE")) break;
  }
  if (getenv("HYLC_TEST_VERBOSE")) printf("%s: worst relative error %.3g %%\n", label, 100 * worst);
  /* 1D terms: the zero knot, residual at 0, linear increasing extrapolation */
  for (int k = 0; k < 5; k++) {
    const HylcSpline1D *s;
    PetscCall(HylcFitGet1D(fit, k, &s));
    HYLC_CHECK(s && s->n == (strstr(options, "paper") || strstr(options, "authors") ? 11 : 17), "%s: 1D term %d: %d knots", label, k, s ? (int)s->n : -1);
    if (!s) continue;
    int zero = -1;
    for (int i = 0; i < s->n; i++)
      if (s->t[i] == 0) zero = i;
    HYLC_CHECK(zero >= 0 && s->p[zero] == 0, "%s: 1D term %d: no zero knot or f(0) != 0", label, k);
    HYLC_CHECK(s->m[0] <= -1e-8 && s->m[s->n - 1] >= 1e-8, "%s: 1D term %d end slopes %g %g", label, k, s->m[0], s->m[s->n - 1]);
    const double a = s->t[0], b = s->t[s->n - 1];
    for (int q = 1; q <= 5; q++) {
      double d1;
      HYLC_CHECK(HylcSpline1DEval(s, a - 0.1 * q, &d1, NULL) > HylcSpline1DEval(s, a - 0.1 * (q - 1), NULL, NULL) && d1 == s->m[0], "%s: 1D term %d left extrapolation", label, k);
      HYLC_CHECK(HylcSpline1DEval(s, b + 0.1 * q, &d1, NULL) > HylcSpline1DEval(s, b + 0.1 * (q - 1), NULL, NULL) && d1 == s->m[s->n - 1], "%s: 1D term %d right extrapolation", label, k);
    }
  }
  /* 2D terms */
  for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
    const HylcSpline2D *s;
    int                 ci, cj;
    HylcPlanPair(t, &ci, &cj);
    PetscCall(HylcFitGet2D(fit, ci, cj, &s));
    HYLC_CHECK(s != NULL, "%s: 2D term %s missing", label, HylcPlanTermName(t));
    if (!s) continue;
    const PetscInt nu = s->nu, nv = s->nv;
    const double   u0 = s->tu[0], u1 = s->tu[nu - 1], v0 = s->tv[0], v1 = s->tv[nv - 1];
    for (PetscInt i = 0; i < nu; i++) HYLC_CHECK(s->muv[i] == 0 && s->muv[(nv - 1) * nu + i] == 0, "%s: %s muv on the boundary", label, HylcPlanTermName(t));
    for (PetscInt j = 0; j < nv; j++) HYLC_CHECK(s->muv[j * nu] == 0 && s->muv[j * nu + nu - 1] == 0, "%s: %s muv on the boundary", label, HylcPlanTermName(t));
    for (int q = 0; q <= 100; q++) {
      const double x = u0 - 0.2 + (u1 - u0 + 0.4) * q / 100, y = v0 - 0.2 + (v1 - v0 + 0.4) * q / 100;
      HYLC_CHECK(HylcSpline2DEval(s, x, 0, NULL, NULL) == 0 && HylcSpline2DEval(s, 0, y, NULL, NULL) == 0, "%s: %s not zero on the axes (%g, %g)", label, HylcPlanTermName(t), x, y);
    }
    /* compression */
    const PetscBool zu = (PetscBool)(t != 7 && (ci == 0 || ci == 2)), zv = (PetscBool)(t != 7 && (cj == 0 || cj == 2));
    for (PetscInt j = 0; j < nv; j++)
      for (PetscInt i = 0; i < nu; i++)
        if ((zu && s->tu[i] < 0) || (zv && s->tv[j] < 0))
          HYLC_CHECK(s->p[j * nu + i] == 0 && s->mu[j * nu + i] == 0 && s->mv[j * nu + i] == 0 && s->muv[j * nu + i] == 0, "%s: %s compressed node (%d, %d) not zero", label, HylcPlanTermName(t), (int)i, (int)j);
    if (zu || zv)
      for (int a = 0; a <= 30; a++)
        for (int b = 0; b <= 30; b++) {
          const double x = zu ? u0 - 0.1 + (0.1 - u0) * a / 30 - 1e-9 : u0 - 0.1 + (u1 - u0 + 0.2) * a / 30;
          const double y = zv ? v0 - 0.1 + (0.1 - v0) * b / 30 - 1e-9 : v0 - 0.1 + (v1 - v0 + 0.2) * b / 30;
          if ((zu && x >= 0) || (zv && y >= 0)) continue;
          const PetscReal f = HylcSpline2DEval(s, x, y, NULL, NULL);
          if (strict || (zu && x <= s->tu[0]) || (zv && y <= s->tv[0])) HYLC_CHECK(f == 0, "%s: %s non-zero in compression at (%g, %g): %g", label, HylcPlanTermName(t), x, y, f);
        }
    if (t == 7) { /* the Poisson pair keeps its compression quadrant */
      double mx = 0;
      for (PetscInt k = 0; k < nu * nv; k++) mx = fmax(mx, fabs(s->p[k]));
      HYLC_CHECK(mx > 0, "%s: sx-sy residual is all zero", label);
    }
    /* linear extrapolation: second derivatives vanish outward */
    for (int q = 0; q <= 10; q++) {
      const double x = u0 + (u1 - u0) * q / 10, y = v0 + (v1 - v0) * q / 10;
      double       H[3];
      HylcSpline2DEval(s, x, v1 + 0.3, NULL, H);
      HYLC_CHECK(fabs(H[2]) < 1e-12, "%s: %s not linear beyond v = %g: f_vv %g", label, HylcPlanTermName(t), v1, H[2]);
      HylcSpline2DEval(s, u0 - 0.3, y, NULL, H);
      HYLC_CHECK(fabs(H[0]) < 1e-12, "%s: %s not linear before u = %g: f_uu %g", label, HylcPlanTermName(t), u0, H[0]);
    }
  }
  /* the total model increases outward beyond the sampled 1D ranges */
  for (int c = 0; c < 5; c++)
    for (int side = -1; side <= 1; side += 2) {
      double zz[6] = {0}, prev = -1;
      for (int q = 0; q <= 8; q++) {
        PetscReal f;
        zz[HylcPlanStrainIndex(c)] = side * V[c] * (1 + 0.1 * q) * (side < 0 && (c == 0 || c == 2) ? 0.6 : 1);
        PetscCall(HylcFitEvaluateAxes(fit, zz, &f));
        if (q) HYLC_CHECK(f > prev, "%s: model does not increase outward along %s (side %d) at %g", label, HylcPlanTermName(1 + c), side, zz[HylcPlanStrainIndex(c)]);
        prev = f;
      }
    }
  PetscCall(HylcFitDestroy(&fit));
  free(z);
  free(psi);
  free(term);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* error cases: the message must name the problem */
static PetscErrorCode ExpectError(const char *label, PetscInt n, const PetscReal *z, const PetscReal *psi, const PetscInt *term, const char *options, const char *want)
{
  HylcFit        fit;
  PetscErrorCode ierr;
  const char    *msg = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(NULL));
  PetscCall(PetscOptionsInsertString(NULL, options));
  PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
  PetscCall(HylcFitSetFromOptions(fit));
  PetscCall(HylcFitSetData(fit, n, z, psi, term, 0.3));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcFitCompute(fit);
  PetscCall(PetscPopErrorHandler());
  HYLC_CHECK(ierr != 0, "%s: accepted", label);
  if (ierr) {
    PetscErrorMessage(ierr, NULL, (char **)&msg);
    HYLC_CHECK(msg && strstr(msg, want), "%s: message '%s' lacks '%s'", label, msg ? msg : "", want);
  }
  PetscCall(HylcFitDestroy(&fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a fit of the data with the given options, computed */
static PetscErrorCode FitWith(const char *options, PetscInt n, const PetscReal *z, const PetscReal *psi, const PetscInt *term, HylcFit *fit)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsClear(NULL));
  PetscCall(PetscOptionsInsertString(NULL, options));
  PetscCall(HylcFitCreate(PETSC_COMM_SELF, fit));
  PetscCall(HylcFitSetFromOptions(*fit));
  PetscCall(HylcFitSetData(*fit, n, z, psi, term, 0.3));
  PetscCall(HylcFitCompute(*fit));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  PetscFunctionBeginUser;
  PetscCall(Check("woven/refined", "", PETSC_FALSE, 0.01, PETSC_FALSE));
  PetscCall(Check("woven/paper", "-fit_knots paper", PETSC_FALSE, 0.01, PETSC_FALSE));
  PetscCall(Check("woven/authors/strict", "-fit_compat authors -fit_zero_compression_strict", PETSC_TRUE, 0.01, PETSC_FALSE));
  /* the stockinette's 2D bending knots cover 0.3 of the data range, and beyond them the residual is
     extrapolated linearly (the paper's choice, not meant to be accurate there): checked inside; and
     its reg = 1e-2 lifts the flat curled bending minimum by design (1.25 % here) */
  PetscCall(Check("stockinette", "-fit_family stockinette", PETSC_FALSE, 0.02, PETSC_TRUE));
  /* -fit_compat authors changes the 2D tables (the bending minimum of II00 is off the axis), not the 1D ones
     of the paper's knot layout (which it implies) */
  {
    HylcFit    a, b;
    PetscInt   n, *term, differ = 0;
    PetscReal *z, *psi;
    MakeData(150, 20, -1, &n, &z, &psi, &term);
    PetscCall(FitWith("-fit_knots paper", n, z, psi, term, &a));
    PetscCall(FitWith("-fit_compat authors", n, z, psi, term, &b));
    for (int k = 0; k < 5; k++) {
      const HylcSpline1D *sa, *sb;
      PetscCall(HylcFitGet1D(a, k, &sa));
      PetscCall(HylcFitGet1D(b, k, &sb));
      for (int i = 0; i < sa->n; i++) HYLC_CHECK(sa->p[i] == sb->p[i] && sa->m[i] == sb->m[i], "compat changes 1D term %d", k);
    }
    for (int t = 6; t < HYLC_PLAN_NTERM; t++) {
      const HylcSpline2D *sa, *sb;
      int                 ci, cj;
      HylcPlanPair(t, &ci, &cj);
      PetscCall(HylcFitGet2D(a, ci, cj, &sa));
      PetscCall(HylcFitGet2D(b, ci, cj, &sb));
      for (int i = 0; i < sa->nu * sa->nv; i++) differ += sa->p[i] != sb->p[i] || sa->mu[i] != sb->mu[i] || sa->mv[i] != sb->mv[i] || sa->muv[i] != sb->muv[i];
    }
    HYLC_CHECK(differ > 0, "-fit_compat authors gives the same 2D tables");
    PetscCall(HylcFitDestroy(&a));
    PetscCall(HylcFitDestroy(&b));
    free(z);
    free(psi);
    free(term);
  }
  /* -fit_knots refined against paper (issue 30): the paper's knots keep the paper layout's values of
     Psi - f0 (each knot taken relative to 0 by its own kernel), so away from 0 the two fits agree, and
     the range-normalised RMS of no 1D term is materially worse than the paper layout's (measured: equal
     to 6 digits on sx, sa, sy, 10 % lower on II00, 1.7 % higher on the pure quadratic II11, 8.881e-6 ->
     9.034e-6 J/m^2 of a 0.03 range: the narrow kernels' bias differs from the wide one's; before the
     shift the paper's knots were off by the two kernels' difference at 0, up to 7.5e-6 here) */
  {
    HylcFit    a, b;
    PetscInt   n, *term;
    PetscReal *z, *psi;
    MakeData(150, 20, -1, &n, &z, &psi, &term);
    PetscCall(FitWith("-fit_knots paper", n, z, psi, term, &a));
    PetscCall(FitWith("", n, z, psi, term, &b));
    for (int k = 0; k < 5; k++) {
      const HylcSpline1D *sa, *sb;
      PetscInt            ia = -1, ib = -1, cnt, checked = 0;
      PetscReal           ra, rb, pmax = 0;
      PetscCall(HylcFitGet1D(a, k, &sa));
      PetscCall(HylcFitGet1D(b, k, &sb));
      for (int i = 0; i < sa->n; i++) {
        if (sa->t[i] == 0) ia = i;
        pmax = PetscMax(pmax, PetscAbsReal(sa->p[i]));
      }
      for (int i = 0; i < sb->n; i++)
        if (sb->t[i] == 0) ib = i;
      HYLC_CHECK(ia >= 0 && ib >= 0 && sb->n == sa->n + 6, "1D term %d: knots %d and %d, zero at %d and %d", k, (int)sa->n, (int)sb->n, (int)ia, (int)ib);
      if (ia < 0 || ib < 0 || sb->n != sa->n + 6) continue;
      for (int i = 0; i < sa->n; i++) { /* the paper's knots beyond the first interval on each side */
        const int j = i < ia ? i : i + 6;
        if (PetscAbsInt(i - ia) < 2) continue;
        HYLC_CHECK(sb->t[j] == sa->t[i] && PetscAbsReal(sb->p[j] - sa->p[i]) <= 1e-12 * pmax, "1D term %d knot %g: refined p %.17g, paper %.17g", k, sa->t[i], sb->p[j], sa->p[i]);
        checked++;
      }
      HYLC_CHECK(checked == sa->n - 3, "1D term %d: %d knots compared", k, (int)checked);
      PetscCall(HylcFitGetTermStats(a, 1 + k, &cnt, &ra, NULL));
      PetscCall(HylcFitGetTermStats(b, 1 + k, &cnt, &rb, NULL));
      if (getenv("HYLC_TEST_VERBOSE")) printf("1D term %d: RMS paper %.6g, refined %.6g\n", k, ra, rb);
      HYLC_CHECK(rb <= ra * 1.02, "1D term %d: refined RMS %g worse than the paper layout's %g", k, rb, ra);
    }
    PetscCall(HylcFitDestroy(&a));
    PetscCall(HylcFitDestroy(&b));
    free(z);
    free(psi);
    free(term);
  }
  /* knots of the stockinette bending pairs: 5 x 5 */
  {
    HylcFit             fit;
    PetscInt            n, *term;
    PetscReal          *z, *psi;
    const HylcSpline2D *s;
    MakeData(150, 20, 9 /* sx-II11 */, &n, &z, &psi, &term);
    PetscCall(PetscOptionsClear(NULL));
    PetscCall(PetscOptionsInsertString(NULL, "-fit_family stockinette"));
    PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
    PetscCall(HylcFitSetFromOptions(fit));
    PetscCall(HylcFitSetData(fit, n, z, psi, term, 0.3));
    PetscCall(HylcFitCompute(fit));
    PetscCall(HylcFitGet2D(fit, 1, 3, &s));
    HYLC_CHECK(s && s->nu == 5 && s->nv == 5 && fabs(s->tu[0] + 0.3 * 0.8) < 1e-12, "stockinette sa-II00 knots");
    PetscCall(HylcFitGet2D(fit, 0, 1, &s));
    HYLC_CHECK(s && s->nu == 8 && s->nv == 9, "stockinette sx-sa knots %d x %d", s ? (int)s->nu : 0, s ? (int)s->nv : 0);
    PetscCall(HylcFitGet2D(fit, 0, 2, &s));
    HYLC_CHECK(s && s->nu == 10 && s->nv == 10, "sx-sy knots");
    PetscCall(HylcFitGet2D(fit, 0, 4, &s));
    HYLC_CHECK(s == NULL, "sx-II11 without samples was fitted");
    PetscInt cnt;
    PetscCall(HylcFitGetTermStats(fit, 9, &cnt, NULL, NULL));
    HYLC_CHECK(cnt == 0, "stats of a missing term");
    PetscCall(HylcFitDestroy(&fit));
    /* errors: NaN strain, too few samples, II01 != 0 */
    z[6 * 5 + 0] = NAN;
    PetscCall(ExpectError("NaN", n, z, psi, term, "", "non-finite"));
    z[6 * 5 + 0] = 0.1;
    z[6 * 5 + 4] = 0.2;
    PetscCall(ExpectError("II01", n, z, psi, term, "", "II01"));
    z[6 * 5 + 4] = 0;
    PetscCall(ExpectError("few", n, z, psi, term, "-fit_min_samples_1d 200", "only 150 usable samples"));
    PetscCall(ExpectError("sparse", n, z, psi, term, "-fit_mls_kernel 0.005 -fit_mls_grow 1", "singular"));
    free(z);
    free(psi);
    free(term);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(Run());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
