#pragma once
/* Forward-mode second-order ("hyper-dual") numbers over a fixed, small number of variables: a value,
   its gradient and its symmetric Hessian (upper triangle packed row by row).  Used by the element
   kernels (src/rod/) to get exact Hessians without hand-derived closed forms.

   HYLC_HD_DEFINE(P, T, N) defines the type T with N variables and inline operations that write their
   result through the first pointer argument.  Every operation computes the Hessian part first, then the
   gradient, then the value, so the result may alias any operand.
     P##Var(r, x, i)             independent variable i with value x
     P##Lin(r, a, x, b, y)       r = a x + b y        (a, b doubles)
     P##Axpy(y, a, x)            y += a x
     P##Scale(x, a)              x *= a
     P##Mul(r, x, y)             r = x y
     P##Chain1(r, x, f, f', f'') r = f(x) from the value and two derivatives of f at x.v
     P##Recip(r, x), P##Atan2(r, y, x)
   Two instances are defined here: Hd3 (3 variables) and Hd6 (6 variables).
   Packed index of (i, j), i <= j:  i*N - i*(i-1)/2 + (j - i). */
#include <math.h>
#include <string.h>

#define HYLC_HD_DEFINE(P, T, N)                                                                                                                                                     \
  typedef struct {                                                                                                                                                                  \
    double v, g[N], h[(N) * ((N) + 1) / 2];                                                                                                                                         \
  } T;                                                                                                                                                                              \
  enum { P##_NH = (N) * ((N) + 1) / 2 };                                                                                                                                            \
  static inline void P##Var(T *r, double x, int i)                                                                                                                                  \
  {                                                                                                                                                                                 \
    memset(r, 0, sizeof(T));                                                                                                                                                        \
    r->v    = x;                                                                                                                                                                    \
    r->g[i] = 1.0;                                                                                                                                                                  \
  }                                                                                                                                                                                 \
  static inline void P##Lin(T *r, double a, const T *x, double b, const T *y)                                                                                                       \
  {                                                                                                                                                                                 \
    for (int k = 0; k < P##_NH; k++) r->h[k] = a * x->h[k] + b * y->h[k];                                                                                                           \
    for (int i = 0; i < (N); i++) r->g[i] = a * x->g[i] + b * y->g[i];                                                                                                              \
    r->v = a * x->v + b * y->v;                                                                                                                                                     \
  }                                                                                                                                                                                 \
  static inline void P##Axpy(T *y, double a, const T *x)                                                                                                                            \
  {                                                                                                                                                                                 \
    for (int k = 0; k < P##_NH; k++) y->h[k] += a * x->h[k];                                                                                                                        \
    for (int i = 0; i < (N); i++) y->g[i] += a * x->g[i];                                                                                                                           \
    y->v += a * x->v;                                                                                                                                                               \
  }                                                                                                                                                                                 \
  static inline void P##Scale(T *x, double a)                                                                                                                                       \
  {                                                                                                                                                                                 \
    for (int k = 0; k < P##_NH; k++) x->h[k] *= a;                                                                                                                                  \
    for (int i = 0; i < (N); i++) x->g[i] *= a;                                                                                                                                     \
    x->v *= a;                                                                                                                                                                      \
  }                                                                                                                                                                                 \
  static inline void P##Mul(T *r, const T *x, const T *y)                                                                                                                           \
  {                                                                                                                                                                                 \
    const double xv = x->v, yv = y->v;                                                                                                                                              \
    for (int i = 0, k = 0; i < (N); i++)                                                                                                                                            \
      for (int j = i; j < (N); j++, k++) r->h[k] = xv * y->h[k] + yv * x->h[k] + x->g[i] * y->g[j] + x->g[j] * y->g[i];                                                             \
    for (int i = 0; i < (N); i++) r->g[i] = xv * y->g[i] + yv * x->g[i];                                                                                                            \
    r->v = xv * yv;                                                                                                                                                                 \
  }                                                                                                                                                                                 \
  static inline void P##Chain1(T *r, const T *x, double f0, double f1, double f2)                                                                                                   \
  {                                                                                                                                                                                 \
    for (int i = 0, k = 0; i < (N); i++)                                                                                                                                            \
      for (int j = i; j < (N); j++, k++) r->h[k] = f1 * x->h[k] + f2 * x->g[i] * x->g[j];                                                                                           \
    for (int i = 0; i < (N); i++) r->g[i] = f1 * x->g[i];                                                                                                                           \
    r->v = f0;                                                                                                                                                                      \
  }                                                                                                                                                                                 \
  static inline void P##Recip(T *r, const T *x)                                                                                                                                     \
  {                                                                                                                                                                                 \
    const double ix = 1.0 / x->v;                                                                                                                                                   \
    P##Chain1(r, x, ix, -ix *ix, 2.0 * ix * ix * ix);                                                                                                                               \
  }                                                                                                                                                                                 \
  /* atan2(y, x), principal value (add a constant for another branch) */                                                                                                            \
  static inline void P##Atan2(T *r, const T *y, const T *x)                                                                                                                         \
  {                                                                                                                                                                                 \
    const double xv = x->v, yv = y->v, ir2 = 1.0 / (xv * xv + yv * yv), ir4 = ir2 * ir2;                                                                                            \
    const double fx = -yv * ir2, fy = xv * ir2;                                                                                                                                     \
    const double fxx = 2.0 * xv * yv * ir4, fyy = -fxx, fxy = (yv * yv - xv * xv) * ir4;                                                                                            \
    for (int i = 0, k = 0; i < (N); i++)                                                                                                                                            \
      for (int j = i; j < (N); j++, k++) r->h[k] = fx * x->h[k] + fy * y->h[k] + fxx * x->g[i] * x->g[j] + fyy * y->g[i] * y->g[j] + fxy * (x->g[i] * y->g[j] + y->g[i] * x->g[j]); \
    for (int i = 0; i < (N); i++) r->g[i] = fx * x->g[i] + fy * y->g[i];                                                                                                            \
    r->v = atan2(yv, xv);                                                                                                                                                           \
  }

HYLC_HD_DEFINE(Hd3, Hd3, 3)
HYLC_HD_DEFINE(Hd6, Hd6, 6)

/* r = u . v for 3-vectors of Hd3 numbers, u over variables 0..2 and v over a disjoint set of 3
   variables, as an Hd6 over (u's variables, v's variables). */
static inline void Hd6MixedDot3(Hd6 *r, const Hd3 u[3], const Hd3 v[3])
{
  memset(r, 0, sizeof *r);
  for (int c = 0; c < 3; c++) {
    const Hd3 *a = &u[c], *b = &v[c];
    r->v += a->v * b->v;
    for (int i = 0; i < 3; i++) {
      r->g[i] += b->v * a->g[i];
      r->g[3 + i] += a->v * b->g[i];
    }
    /* packed Hd6 rows 0..2: (i, j) for j = i..5; block uu is H(a) b.v, block uv is a.g (x) b.g */
    for (int i = 0, k = 0, kk = 0; i < 3; i++) {
      for (int j = i; j < 3; j++, k++, kk++) r->h[kk] += b->v * a->h[k];
      for (int j = 0; j < 3; j++, kk++) r->h[kk] += a->g[i] * b->g[j];
    }
    /* rows 3..5 start at packed index 15: block vv = a.v H(b) */
    for (int k = 0; k < 6; k++) r->h[15 + k] += a->v * b->h[k];
  }
}
