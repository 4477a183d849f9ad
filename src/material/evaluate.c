/* Evaluation of the material model: Psi(s), its gradient and Hessian with respect to the six strains
   s = (sx, sa, sy, II00, II01, II11), with exact limits at equal eigenvalues of II.

   The bending terms (docs/material.md, "Evaluation"): with A = (II00 + II11)/2, B = (II00 - II11)/2,
   C = II01, S = sqrt(B^2 + C^2), the eigenvalues A +- S and c^2 = 1/2 + B/(2S), every bending
   contribution c^2 [f(A+S) + g(A-S)] + (1 - c^2) [f(A-S) + g(A+S)] of an x-bending function f and a
   y-bending function g equals  P + B Q  with, for each constituent h (= f or g, with Q's sign + for f
   and - for g),
     P(A, w) = [h(A+S) + h(A-S)] / 2,   Q(A, w) = [h(A+S) - h(A-S)] / (2S),   w = S^2,
   both smooth in (A, w) where h is. Derivatives with respect to (A, B, C) follow from those of P and Q
   with respect to A and w (w_B = 2B, w_C = 2C), and all of them are formed without cancellation:
   - near S = 0 (S below ~half the knot spacing) from the local cubic pieces of h about A: one piece
     gives polynomials in w; a knot between A - S and A + S adds the jump polynomial of h at that knot
     (C1: starts at second order), so every quotient by a power of S is exact;
   - otherwise from h, h', h'' at A +- S directly.
   Everything is computed in table units (x = lambda / sigma) and scaled at the end.

   Range: the computation runs in double; when a result comes out non-finite for finite strains (a
   strain near the largest double, a table whose coefficients overflow an intermediate quantity), it is
   repeated in long double (x86: 15-bit exponent, so no intermediate of a table the loader accepts can
   overflow, docs/material.md) and each non-finite result is replaced by its long double value rounded
   to double, a magnitude beyond the largest double becoming +-PETSC_MAX_REAL (saturated). The finite
   results of the double pass are kept, so Psi does not depend on whether derivatives were asked for.
   Ordinary strains never take the fallback. */
#include <hylc/private/materialimpl.h>
#include <math.h>
#include <float.h>
#include <string.h>

/* below this half split (table units) the piece form uses s = 0: the one-sided (right) limit */
#define S_TINY 1e-50

#define R       double
#define F(name) name##_d
#define SQRT    sqrt
#include "evaluate_body.h"
#undef R
#undef F
#undef SQRT

#define R       long double
#define F(name) name##_l
#define SQRT    sqrtl
#include "evaluate_body.h"
#undef R
#undef F
#undef SQRT

/* a long double result as a double, saturated at +-PETSC_MAX_REAL */
static inline PetscReal Saturate(long double v)
{
  if (v > (long double)PETSC_MAX_REAL) return PETSC_MAX_REAL;
  if (v < -(long double)PETSC_MAX_REAL) return -PETSC_MAX_REAL;
  return (PetscReal)v;
}

/*@C
  HylcMaterialEvaluate - Psi(s) (J/m^2), and if grad (hess) is not NULL its gradient (Hessian, 6x6
  row-major, symmetric) with respect to s = (sx, sa, sy, II00, II01, II11). Exact at equal eigenvalues of
  II (docs/material.md). For finite strains every result is finite: a value beyond the double range is
  returned as +-PETSC_MAX_REAL (docs/material.md, "Range"); NaN or infinite strains propagate.
  Not collective; thread-safe; no allocation.
@*/
PetscErrorCode HylcMaterialEvaluate(HylcMaterial m, const PetscReal s[6], PetscReal *psi, PetscReal grad[6], PetscReal hess[36])
{
  const int level = hess ? 2 : (grad ? 1 : 0);
  PetscReal E, g[6] = {0, 0, 0, 0, 0, 0}, H[36];
  PetscBool finite = PETSC_TRUE, inputFinite = PETSC_TRUE;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidRealPointer(s, 2);
  Evaluate_d(m, s, level, &E, g, H);
  if (!isfinite(E)) finite = PETSC_FALSE;
  for (int i = 0; i < 6 && level; i++)
    if (!isfinite(g[i])) finite = PETSC_FALSE;
  for (int i = 0; i < 36 && level > 1; i++)
    if (!isfinite(H[i])) finite = PETSC_FALSE;
  for (int i = 0; i < 6; i++)
    if (!isfinite(s[i])) inputFinite = PETSC_FALSE;
  if (!finite && inputFinite) { /* the long double fallback, for the results that are not finite */
    long double El, gl[6] = {0, 0, 0, 0, 0, 0}, Hl[36];
    Evaluate_l(m, s, level, &El, gl, Hl);
    PetscCheck(!isnan(El), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Psi is NaN at the finite strain (%g, %g, %g, %g, %g, %g)", (double)s[0], (double)s[1], (double)s[2], (double)s[3], (double)s[4], (double)s[5]);
    if (!isfinite(E)) E = Saturate(El);
    for (int i = 0; i < 6 && level; i++) {
      PetscCheck(!isnan(gl[i]), PETSC_COMM_SELF, PETSC_ERR_PLIB, "grad Psi is NaN at a finite strain");
      if (!isfinite(g[i])) g[i] = Saturate(gl[i]);
    }
    for (int i = 0; i < 36 && level > 1; i++) {
      PetscCheck(!isnan(Hl[i]), PETSC_COMM_SELF, PETSC_ERR_PLIB, "The Hessian of Psi is NaN at a finite strain");
      if (!isfinite(H[i])) H[i] = Saturate(Hl[i]);
    }
  }
  if (psi) *psi = E;
  if (grad)
    for (PetscInt i = 0; i < 6; i++) grad[i] = g[i];
  if (hess)
    for (PetscInt i = 0; i < 36; i++) hess[i] = H[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}
