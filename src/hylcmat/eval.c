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
   to double, a magnitude beyond the largest double becoming +-DBL_MAX (saturated). The finite
   results of the double pass are kept, so Psi does not depend on whether derivatives were asked for.
   Ordinary strains never take the fallback. */
#include "hylcmatimpl.h"
#include <float.h>
#include <math.h>
#include <string.h>

/* the evaluator's inner functions inlined into one copy per derivative level */
#if defined(__GNUC__)
#  define HM_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#  define HM_ALWAYS_INLINE inline
#endif

#define HM_MAX(a, b) ((a) < (b) ? (b) : (a))
#define HM_MIN(a, b) ((b) < (a) ? (b) : (a))

/* below this half split (table units) the piece form uses s = 0: the one-sided (right) limit */
#define S_TINY 1e-50

#define R       double
#define F(name) name##_d
#define SQRT    sqrt
#include "eval_body.h"
#undef R
#undef F
#undef SQRT

#define R       long double
#define F(name) name##_l
#define SQRT    sqrtl
#include "eval_body.h"
#undef R
#undef F
#undef SQRT

/* a long double result as a double, saturated at +-DBL_MAX */
static inline double Saturate(long double v)
{
  if (v > (long double)DBL_MAX) return DBL_MAX;
  if (v < -(long double)DBL_MAX) return -DBL_MAX;
  return (double)v;
}

int hylcmat_eval(const hylcmat *m, const double s[6], double *psi, double grad[6], double hess[36])
{
  const int level = hess ? 2 : (grad ? 1 : 0);
  double    E, g[6] = {0, 0, 0, 0, 0, 0}, H[36];
  int       finite = 1, inputFinite = 1;

  if (!m || !s) return HYLCMAT_ERR_ARG;
  Evaluate_d(m, s, level, &E, g, H);
  if (!isfinite(E)) finite = 0;
  for (int i = 0; i < 6 && level; i++)
    if (!isfinite(g[i])) finite = 0;
  for (int i = 0; i < 36 && level > 1; i++)
    if (!isfinite(H[i])) finite = 0;
  for (int i = 0; i < 6; i++)
    if (!isfinite(s[i])) inputFinite = 0;
  if (!finite && inputFinite) { /* the long double fallback, for the results that are not finite */
    long double El, gl[6] = {0, 0, 0, 0, 0, 0}, Hl[36];
    Evaluate_l(m, s, level, &El, gl, Hl);
    if (isnan(El)) return HYLCMAT_ERR_NAN;
    if (!isfinite(E)) E = Saturate(El);
    for (int i = 0; i < 6 && level; i++) {
      if (isnan(gl[i])) return HYLCMAT_ERR_NAN;
      if (!isfinite(g[i])) g[i] = Saturate(gl[i]);
    }
    for (int i = 0; i < 36 && level > 1; i++) {
      if (isnan(Hl[i])) return HYLCMAT_ERR_NAN;
      if (!isfinite(H[i])) H[i] = Saturate(Hl[i]);
    }
  }
  if (psi) *psi = E;
  if (grad)
    for (int i = 0; i < 6; i++) grad[i] = g[i];
  if (hess)
    for (int i = 0; i < 36; i++) hess[i] = H[i];
  return HYLCMAT_OK;
}

int hylcmat_eval_batch(const hylcmat *m, size_t n, const double *strains, double *psi, double *grad, double *hess)
{
  int first = HYLCMAT_OK;

  if (!m || (n && !strains)) return HYLCMAT_ERR_ARG;
  for (size_t i = 0; i < n; i++) {
    double    e;
    const int r = hylcmat_eval(m, strains + 6 * i, &e, grad ? grad + 6 * i : NULL, hess ? hess + 36 * i : NULL);
    if (psi) psi[i] = e;
    if (r && !first) first = r;
  }
  return first;
}
