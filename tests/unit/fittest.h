#pragma once
/* Synthetic samples for the fit tests: a known smooth quasiconvex Psi on the sampling plan of
   Algorithm C4 (include/hylc/plan.h). */
#include <hylc/plan.h>
#include <petscsys.h>
#include <stdlib.h>

static const double FitTestV[5] = {1.0, 0.75, 1.0, 170, 170}; /* woven 1D limits = the strain scale */

static inline double FitTestPos3(double x) { return x > 0 ? x * x * x : 0; }

/* convex terms per coordinate (a curled bending minimum at II00 / 170 = 0.3), a Poisson-like coupling
   of (sx, sy) and mild couplings that vanish in compression */
static inline double FitTestPsi(const double z[6])
{
  const double sx = z[0] / FitTestV[0], sa = z[1] / FitTestV[1], sy = z[2] / FitTestV[2], bx = z[3] / FitTestV[3], by = z[5] / FitTestV[4];
  double       f = 0.1;
  f += 0.3 * sx * sx + 0.05 * sx * sx * sx + 0.25 * sy * sy + 0.03 * sy * sy * sy;
  f += 0.2 * sa * sa + 0.03 * sa * sa * sa * sa;
  f += 0.04 * ((bx - 0.3) * (bx - 0.3) - 0.09) + 0.03 * by * by;
  f += -0.03 * sx * sy;
  f += 0.1 * FitTestPos3(sx) * sa * sa + 0.05 * sa * sa * FitTestPos3(sy) + 0.02 * FitTestPos3(sx) * bx * bx + 0.03 * sa * sa * by * by + 0.01 * sa * sa * bx * bx;
  return f;
}

/* the plan of 'family' (woven: the limits above) with n1 1D samples and n2^2 2D samples, without term
   dropTerm (if > 0); arrays allocated with malloc */
static inline void FitTestMakeData(const char *family, int n1, int n2, int dropTerm, PetscInt *n, PetscReal **z, PetscReal **psi, PetscInt **term)
{
  HylcPlan plan;
  HylcPlanDefaults(family, 1.0, &plan);
  plan.n1 = n1;
  plan.n2 = n2;
  if (dropTerm > 0) plan.terms &= ~(1 << dropTerm);
  const long N = HylcPlanSize(&plan);
  *z           = (PetscReal *)malloc(sizeof(PetscReal) * 6 * N);
  *psi         = (PetscReal *)malloc(sizeof(PetscReal) * N);
  *term        = (PetscInt *)malloc(sizeof(PetscInt) * N);
  for (long k = 0; k < N; k++) {
    double zz[6];
    int    t;
    HylcPlanSample(&plan, k, zz, &t);
    for (int i = 0; i < 6; i++) (*z)[6 * k + i] = zz[i];
    (*psi)[k]  = FitTestPsi(zz);
    (*term)[k] = t;
  }
  *n = (PetscInt)N;
}
