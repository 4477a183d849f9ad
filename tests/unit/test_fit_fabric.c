/* The fabric method of hylc-fit (-fit_method fabric, src/fit/fabric.c): a known table, built on the graded
   knots of the sampling plan (include/hylc/plan.h), sampled at the plan's points with its values and its exact
   gradient (the stresses a sampling run records), is recovered exactly by the fit: every node value and slope of
   every 1D term to 1e-7 and of every 2D term to 3e-6 of the term's largest (the least-squares problem is
   consistent, so rounding is the only error), including the slopes of the 2D residuals across the axes (the
   lateral couplings the paper's fit sets to 0) and terms that are odd in sa, and the 2D mixed slopes muv to
   1e-4 of the largest (they are taken from the differences of the fitted slopes, exact for the quadratic
   slopes of this truth: src/fit/fabric.c); the 3D terms (hylc's extension) from the samples of their grids, every
   node value and slope to 1e-6 of the largest, the mixed derivatives to 3e-5 (the truth uvw (1 + 0.3u + 0.2v - 0.1w) is quadratic in each
   variable, so the differences of slopes that give the mixed derivatives are exact), through HylcFitRun into a
   material (HylcMaterialGet3D). Also: auto picks fabric when every row has its stress and paper
   otherwise, and -fit_compat authors with -fit_method fabric is refused. */
#include <hylc/fit.h>
#include <hylc/material.h>
#include <hylc/plan.h>
#include <hylc/strain.h>
#include "hylctest.h"
#include <math.h>
#include <string.h>

/* the truth: per coordinate a convex 1D function with its minimum at 0, per pair a residual vanishing on the
   axes with non-zero slopes across them; normalised units u = z / scale */
static double F1(int c, double u, double *d)
{
  const double a = 0.3 + 0.1 * c, b = 2.0 + c, s = c == 1 ? 0.2 : 0; /* sa: an odd cubic part */
  *d = 2 * a * u + 4 * b * u * u * u + 3 * s * u * u * (u > 0 ? 1 : -1);
  return a * u * u + b * u * u * u * u + s * fabs(u) * u * u;
}
static double G2(int q, double u, double v, double *gu, double *gv, double *guv)
{
  const double c = 0.05 * (q + 1), d = 0.02 * (q % 3 - 1), e = 0.03;
  *gu  = c * v + 2 * d * u * v + e * v * v;
  *gv  = c * u + d * u * u + 2 * e * u * v;
  *guv = c + 2 * d * u + 2 * e * v;
  return c * u * v + d * u * u * v + e * u * v * v;
}

/* the 3D truth of triple r and its derivatives D[q] (bit 0 d/du, bit 1 d/dv, bit 2 d/dw) */
static void G3(int r, double u, double v, double w, double D[8])
{
  const double c = 0.04 * (r + 1), a = 0.3, b = 0.2, e = -0.1;
  D[0] = c * u * v * w * (1 + a * u + b * v + e * w);
  D[1] = c * v * w * (1 + 2 * a * u + b * v + e * w);
  D[2] = c * u * w * (1 + a * u + 2 * b * v + e * w);
  D[4] = c * u * v * (1 + a * u + b * v + 2 * e * w);
  D[3] = c * w * (1 + 2 * a * u + 2 * b * v + e * w);
  D[5] = c * v * (1 + 2 * a * u + b * v + 2 * e * w);
  D[6] = c * u * (1 + a * u + 2 * b * v + 2 * e * w);
  D[7] = c * (1 + 2 * a * u + 2 * b * v + 2 * e * w);
}

int main(int argc, char **argv)
{
  HylcPlan   plan;
  PetscInt   n, *term;
  PetscReal *z, *psi, *stress, scale[6] = {1, 0.75, 1, 170, 1, 170};
  double     K[9][2][HYLC_PLAN_MAXAXIS], K1[5][HYLC_PLAN_MAXAXIS];
  int        nK[9][2], nK1[5];

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  HYLC_CHECK(!HylcPlanDefaults("woven", 1, &plan), "plan defaults");
  plan.spacing = HYLC_PLAN_SPACING_GRADED;
  plan.terms   = HYLC_PLAN_ALL_TERMS;
  for (int c = 0; c < 5; c++) nK1[c] = HylcPlanAxisKnots(&plan, 1 + c, 0, K1[c]);
  for (int q = 0; q < 9; q++)
    for (int a = 0; a < 2; a++) nK[q][a] = HylcPlanAxisKnots(&plan, 6 + q, a, K[q][a]);
  n = HylcPlanSize(&plan);
  PetscCall(PetscMalloc4(6 * n, &z, n, &psi, 6 * n, &stress, n, &term));
  /* the truth table: Hermite splines through the functions' values and slopes at the knots, evaluated with
     the splines themselves (so the truth is exactly representable) */
  {
    HylcSpline1D s1[5];
    HylcSpline2D s2[9];
    PetscReal    f0 = 0.0123;
    for (int c = 0; c < 5; c++) {
      s1[c].k = c, s1[c].n = nK1[c], s1[c].ext = HYLC_EXT_LINEAR;
      PetscCall(PetscMalloc3(nK1[c], &s1[c].t, nK1[c], &s1[c].p, nK1[c], &s1[c].m));
      for (int i = 0; i < nK1[c]; i++) {
        double d;
        s1[c].t[i] = K1[c][i] / scale[HylcPlanStrainIndex(c)];
        s1[c].p[i] = F1(c, s1[c].t[i], &d);
        s1[c].m[i] = d;
      }
    }
    for (int q = 0; q < 9; q++) {
      const int nu = nK[q][0], nv = nK[q][1], ci = HylcPairCoords[q][0], cj = HylcPairCoords[q][1];
      s2[q].k0 = ci, s2[q].k1 = cj, s2[q].nu = nu, s2[q].nv = nv, s2[q].ext = HYLC_EXT_LINEAR;
      PetscCall(PetscMalloc6(nu, &s2[q].tu, nv, &s2[q].tv, nu * nv, &s2[q].p, nu * nv, &s2[q].mu, nu * nv, &s2[q].mv, nu * nv, &s2[q].muv));
      for (int i = 0; i < nu; i++) s2[q].tu[i] = K[q][0][i] / scale[HylcPlanStrainIndex(ci)];
      for (int j = 0; j < nv; j++) s2[q].tv[j] = K[q][1][j] / scale[HylcPlanStrainIndex(cj)];
      for (int j = 0; j < nv; j++)
        for (int i = 0; i < nu; i++) {
          const int k = j * nu + i;
          s2[q].p[k]  = G2(q, s2[q].tu[i], s2[q].tv[j], &s2[q].mu[k], &s2[q].mv[k], &s2[q].muv[k]);
        }
    }
    for (PetscInt k = 0; k < n; k++) {
      int t;
      HYLC_CHECK(!HylcPlanSample(&plan, k, z + 6 * k, &t), "plan sample %d", (int)k);
      term[k] = t;
      psi[k]  = f0;
      for (int s = 0; s < 6; s++) stress[6 * k + s] = 0;
      for (int c = 0; c < 5; c++) {
        const int s = HylcPlanStrainIndex(c);
        PetscReal d;
        psi[k] += HylcSpline1DEval(&s1[c], z[6 * k + s] / scale[s], &d, NULL);
        stress[6 * k + s] += d / scale[s];
      }
      for (int q = 0; q < 9; q++) {
        const int si = HylcPlanStrainIndex(s2[q].k0), sj = HylcPlanStrainIndex(s2[q].k1);
        PetscReal g[2];
        psi[k] += HylcSpline2DEval(&s2[q], z[6 * k + si] / scale[si], z[6 * k + sj] / scale[sj], g, NULL);
        stress[6 * k + si] += g[0] / scale[si];
        stress[6 * k + sj] += g[1] / scale[sj];
      }
      for (int r = 0; r < HYLC_NTRIPLE; r++) {
        int    s[3];
        double D[8];
        for (int a = 0; a < 3; a++) s[a] = HylcPlanStrainIndex(HylcTripleCoords[r][a]);
        G3(r, z[6 * k + s[0]] / scale[s[0]], z[6 * k + s[1]] / scale[s[1]], z[6 * k + s[2]] / scale[s[2]], D);
        psi[k] += D[0];
        stress[6 * k + s[0]] += D[1] / scale[s[0]];
        stress[6 * k + s[1]] += D[2] / scale[s[1]];
        stress[6 * k + s[2]] += D[4] / scale[s[2]];
      }
    }
    /* the fit */
    {
      HylcFit       fit;
      HylcFitMethod method;
      PetscCall(PetscOptionsInsertString(NULL, "-fit_quasiconvex false"));
      PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
      PetscCall(HylcFitSetFromOptions(fit));
      PetscCall(HylcFitSetData(fit, n, z, psi, term, 0.3));
      PetscCall(HylcFitSetStress(fit, stress));
      PetscCall(HylcFitCompute(fit));
      PetscCall(HylcFitGetMethod(fit, &method));
      HYLC_CHECK(method == HYLC_FIT_METHOD_FABRIC, "auto chose %s with every stress given", HylcFitMethods[method]);
      for (int c = 0; c < 5; c++) {
        const HylcSpline1D *f;
        double              big = 0, err = 0;
        PetscCall(HylcFitGet1D(fit, c, &f));
        HYLC_CHECK(f->n == s1[c].n, "1D %s: %d knots, truth %d", HylcCoordNames[c], (int)f->n, (int)s1[c].n);
        for (int i = 0; i < f->n; i++) big = PetscMax(big, PetscMax(fabs(s1[c].p[i]), fabs(s1[c].m[i] * (i + 1 < f->n ? s1[c].t[i + 1] - s1[c].t[i] : 1))));
        for (int i = 0; i < f->n && f->n == s1[c].n; i++) {
          const double h = i + 1 < f->n ? s1[c].t[i + 1] - s1[c].t[i] : s1[c].t[i] - s1[c].t[i - 1];
          err            = PetscMax(err, PetscMax(fabs(f->t[i] - s1[c].t[i]), PetscMax(fabs(f->p[i] - s1[c].p[i]), fabs(f->m[i] - s1[c].m[i]) * h)));
        }
        if (getenv("HYLC_TEST_VERBOSE")) printf("1D %s: largest node error %.3g of %.3g\n", HylcCoordNames[c], err, big);
        HYLC_CHECK(err <= 1e-7 * big, "1D %s: node error %.3g of the term's largest %.3g", HylcCoordNames[c], err, big);
      }
      for (int q = 0; q < 9; q++) {
        const HylcSpline2D *g;
        double              big = 0, err = 0, cross = 0, ew[4] = {0, 0, 0, 0}, bigmuv = 0;
        PetscCall(HylcFitGet2D(fit, s2[q].k0, s2[q].k1, &g));
        HYLC_CHECK(g->nu == s2[q].nu && g->nv == s2[q].nv, "2D %s: %d x %d knots, truth %d x %d", HylcPairNames[q], (int)g->nu, (int)g->nv, (int)s2[q].nu, (int)s2[q].nv);
        for (int k = 0; k < g->nu * g->nv && g->nu == s2[q].nu && g->nv == s2[q].nv; k++) {
          const double tv[4] = {s2[q].p[k], s2[q].mu[k], s2[q].mv[k], s2[q].muv[k]}, fv[4] = {g->p[k], g->mu[k], g->mv[k], g->muv[k]};
          for (int w = 0; w < 4; w++) {
            ew[w] = PetscMax(ew[w], fabs(fv[w] - tv[w]));
            if (w == 3) {
              bigmuv = PetscMax(bigmuv, fabs(tv[w]));
              continue;
            }
            big = PetscMax(big, fabs(tv[w]));
            err = PetscMax(err, fabs(fv[w] - tv[w]));
          }
        }
        /* the residual's slope across its v = 0 axis, which the truth has */
        for (int i = 0; i < g->nu; i++)
          if (g->tv[0] < 0) { /* the v = 0 row */
            for (int j = 0; j < g->nv; j++)
              if (g->tv[j] == 0) cross = PetscMax(cross, fabs(g->mv[j * g->nu + i]));
          }
        if (getenv("HYLC_TEST_VERBOSE")) printf("2D %s: largest node error %.3g of %.3g (p %.3g, mu %.3g, mv %.3g, muv %.3g; slope across v = 0 up to %.3g)\n", HylcPairNames[q], err, big, ew[0], ew[1], ew[2], ew[3], cross);
        HYLC_CHECK(err <= 3e-6 * big, "2D %s: node error %.3g of the term's largest %.3g (p, mu, mv)", HylcPairNames[q], err, big);
        HYLC_CHECK(ew[3] <= 1e-4 * bigmuv, "2D %s: muv error %.3g of the largest %.3g", HylcPairNames[q], ew[3], bigmuv);
        HYLC_CHECK(cross > 1e-3 * big, "2D %s: the slope across v = 0 (%.3g) should be the truth's, not 0", HylcPairNames[q], cross);
      }
      {
        HylcMaterial mat;
        PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &mat));
        PetscCall(HylcFitRun(fit, mat));
        for (int r = 0; r < HYLC_NTRIPLE; r++) {
          hylcmat_term3d t;
          PetscBool      has;
          double         err = 0, big = 0, eq[8] = {0, 0, 0, 0, 0, 0, 0, 0};
          PetscCall(HylcMaterialGet3D(mat, HylcTripleCoords[r][0], HylcTripleCoords[r][1], HylcTripleCoords[r][2], &t, &has));
          HYLC_CHECK(has, "3D %s: not fitted", HylcTripleNames[r]);
          if (!has) continue;
          HYLC_CHECK(t.ext == HYLCMAT_EXT_CONSTANT, "3D %s: extension %d beyond the sampled box, not constant", HylcTripleNames[r], t.ext);
          for (int iw = 0; iw < t.nw; iw++)
            for (int iv = 0; iv < t.nv; iv++)
              for (int iu = 0; iu < t.nu; iu++) {
                const int     node = (iw * t.nv + iv) * t.nu + iu;
                const double *F[8] = {t.p, t.mu, t.mv, t.muv, t.mw, t.muw, t.mvw, t.muvw};
                double        D[8];
                G3(r, t.tu[iu], t.tv[iv], t.tw[iw], D);
                for (int q = 0; q < 8; q++) big = PetscMax(big, fabs(D[q])), err = PetscMax(err, fabs(F[q][node] - D[q])), eq[q] = PetscMax(eq[q], fabs(F[q][node] - D[q]));
              }
          if (getenv("HYLC_TEST_VERBOSE"))
            printf("3D %s: %d x %d x %d knots, largest node error %.3g of %.3g (p %.2g mu %.2g mv %.2g muv %.2g mw %.2g muw %.2g mvw %.2g muvw %.2g)\n", HylcTripleNames[r], t.nu, t.nv, t.nw, err, big, eq[0], eq[1], eq[2], eq[3], eq[4], eq[5], eq[6],
                   eq[7]);
          HYLC_CHECK(PetscMax(PetscMax(eq[0], eq[1]), PetscMax(eq[2], eq[4])) <= 1e-6 * big, "3D %s: value or slope error %.3g of the largest %.3g", HylcTripleNames[r], PetscMax(PetscMax(eq[0], eq[1]), PetscMax(eq[2], eq[4])), big);
          HYLC_CHECK(err <= 3e-5 * big, "3D %s: node error %.3g of the largest %.3g", HylcTripleNames[r], err, big);
        }
        PetscCall(HylcMaterialDestroy(&mat));
      }
      PetscCall(HylcFitDestroy(&fit));
    }
    /* without stresses auto is the paper's method; authors with fabric is refused */
    {
      HylcFit        fit;
      HylcFitMethod  method;
      PetscErrorCode ierr;
      PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
      PetscCall(HylcFitSetData(fit, n, z, psi, term, 0.3));
      PetscCall(HylcFitCompute(fit));
      PetscCall(HylcFitGetMethod(fit, &method));
      HYLC_CHECK(method == HYLC_FIT_METHOD_PAPER, "auto chose %s without stresses", HylcFitMethods[method]);
      PetscCall(HylcFitDestroy(&fit));
      PetscCall(PetscOptionsClear(NULL));
      PetscCall(PetscOptionsInsertString(NULL, "-fit_compat authors -fit_method fabric"));
      PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
      PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
      ierr = HylcFitSetFromOptions(fit);
      PetscCall(PetscPopErrorHandler());
      HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "-fit_compat authors -fit_method fabric: %d, expected a user input error", (int)ierr);
      PetscCall(HylcFitDestroy(&fit));
      PetscCall(PetscOptionsClear(NULL));
    }
    for (int c = 0; c < 5; c++) PetscCall(PetscFree3(s1[c].t, s1[c].p, s1[c].m));
    for (int q = 0; q < 9; q++) PetscCall(PetscFree6(s2[q].tu, s2[q].tv, s2[q].p, s2[q].mu, s2[q].mv, s2[q].muv));
  }
  PetscCall(PetscFree4(z, psi, stress, term));
  PetscCall(PetscFinalize());
  return hylc_test_failures ? 1 : 0;
}
