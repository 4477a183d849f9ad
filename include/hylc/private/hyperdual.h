#pragma once
/* Forward-mode second-order ("hyper-dual") numbers over a fixed, small number of variables: a value,
   its gradient and its symmetric Hessian (upper triangle packed row by row).  Used by the element
   kernels (src/rod/) to get exact Hessians without hand-derived closed forms.

   HYLC_HD_DEFINE(P, T, N) defines the type T with N variables and the inline operations P##Const,
   P##Var, P##Add, P##Sub, P##Scale, P##AddConst, P##Axpy, P##Mul, P##Recip, P##Sqrt, P##Chain1 and
   P##Atan2.  Two instances are defined here: Hd3 (3 variables) and Hd6 (6 variables).

   Packed index of (i, j), i <= j:  i*N - i*(i-1)/2 + (j - i). */
#include <math.h>

#define HYLC_HD_DEFINE(P, T, N) \
  typedef struct { \
    double v, g[N], h[(N) * ((N) + 1) / 2]; \
  } T; \
  enum { P##_NH = (N) * ((N) + 1) / 2 }; \
  static inline T P##Const(double c) \
  { \
    T r = {0}; \
    r.v = c; \
    return r; \
  } \
  /* independent variable number i with value x */ \
  static inline T P##Var(double x, int i) \
  { \
    T r = {0}; \
    r.v    = x; \
    r.g[i] = 1.0; \
    return r; \
  } \
  static inline T P##Add(T a, T b) \
  { \
    a.v += b.v; \
    for (int i = 0; i < (N); i++) a.g[i] += b.g[i]; \
    for (int k = 0; k < P##_NH; k++) a.h[k] += b.h[k]; \
    return a; \
  } \
  static inline T P##Sub(T a, T b) \
  { \
    a.v -= b.v; \
    for (int i = 0; i < (N); i++) a.g[i] -= b.g[i]; \
    for (int k = 0; k < P##_NH; k++) a.h[k] -= b.h[k]; \
    return a; \
  } \
  static inline T P##Scale(double s, T a) \
  { \
    a.v *= s; \
    for (int i = 0; i < (N); i++) a.g[i] *= s; \
    for (int k = 0; k < P##_NH; k++) a.h[k] *= s; \
    return a; \
  } \
  static inline T P##AddConst(T a, double c) \
  { \
    a.v += c; \
    return a; \
  } \
  /* y + s x */ \
  static inline T P##Axpy(double s, T x, T y) \
  { \
    y.v += s * x.v; \
    for (int i = 0; i < (N); i++) y.g[i] += s * x.g[i]; \
    for (int k = 0; k < P##_NH; k++) y.h[k] += s * x.h[k]; \
    return y; \
  } \
  static inline T P##Mul(T a, T b) \
  { \
    T r; \
    r.v = a.v * b.v; \
    for (int i = 0; i < (N); i++) r.g[i] = a.v * b.g[i] + b.v * a.g[i]; \
    for (int i = 0, k = 0; i < (N); i++) \
      for (int j = i; j < (N); j++, k++) r.h[k] = a.v * b.h[k] + b.v * a.h[k] + a.g[i] * b.g[j] + a.g[j] * b.g[i]; \
    return r; \
  } \
  /* f(a) given f(a.v), f'(a.v), f''(a.v) */ \
  static inline T P##Chain1(T a, double f0, double f1, double f2) \
  { \
    T r; \
    r.v = f0; \
    for (int i = 0; i < (N); i++) r.g[i] = f1 * a.g[i]; \
    for (int i = 0, k = 0; i < (N); i++) \
      for (int j = i; j < (N); j++, k++) r.h[k] = f1 * a.h[k] + f2 * a.g[i] * a.g[j]; \
    return r; \
  } \
  static inline T P##Recip(T a) \
  { \
    const double ia = 1.0 / a.v; \
    return P##Chain1(a, ia, -ia * ia, 2.0 * ia * ia * ia); \
  } \
  static inline T P##Sqrt(T a) \
  { \
    const double s = sqrt(a.v); \
    return P##Chain1(a, s, 0.5 / s, -0.25 / (s * a.v)); \
  } \
  /* atan2(y, x) (principal value; add a constant for another branch) */ \
  static inline T P##Atan2(T y, T x) \
  { \
    T            r; \
    const double r2 = x.v * x.v + y.v * y.v, ir2 = 1.0 / r2, ir4 = ir2 * ir2; \
    const double fx = -y.v * ir2, fy = x.v * ir2; \
    const double fxx = 2.0 * x.v * y.v * ir4, fyy = -fxx, fxy = (y.v * y.v - x.v * x.v) * ir4; \
    r.v = atan2(y.v, x.v); \
    for (int i = 0; i < (N); i++) r.g[i] = fx * x.g[i] + fy * y.g[i]; \
    for (int i = 0, k = 0; i < (N); i++) \
      for (int j = i; j < (N); j++, k++) \
        r.h[k] = fx * x.h[k] + fy * y.h[k] + fxx * x.g[i] * x.g[j] + fyy * y.g[i] * y.g[j] + fxy * (x.g[i] * y.g[j] + y.g[i] * x.g[j]); \
    return r; \
  }

HYLC_HD_DEFINE(Hd3, Hd3, 3)
HYLC_HD_DEFINE(Hd6, Hd6, 6)

/* Dot product of two 3-vectors of Hd3 numbers, u over variables 0..2 and v over a disjoint set of 3
   variables, as an Hd6 over (u's variables, v's variables). */
static inline Hd6 Hd6MixedDot3(const Hd3 u[3], const Hd3 v[3])
{
  Hd6 r = {0};
  for (int c = 0; c < 3; c++) {
    const Hd3 a = u[c], b = v[c];
    r.v += a.v * b.v;
    for (int i = 0; i < 3; i++) {
      r.g[i] += b.v * a.g[i];
      r.g[3 + i] += a.v * b.g[i];
    }
    /* packed Hd6 rows 0..2: (i, j) for j = i..5; block uu has H(a) b.v, block uv has a.g (x) b.g */
    for (int i = 0, k = 0, kk = 0; i < 3; i++) {
      for (int j = i; j < 3; j++, k++, kk++) r.h[kk] += b.v * a.h[k];
      for (int j = 0; j < 3; j++, kk++) r.h[kk] += a.g[i] * b.g[j];
    }
    /* rows 3..5 start at packed index 15: block vv = a.v H(b) */
    for (int k = 0; k < 6; k++) r.h[15 + k] += a.v * b.h[k];
  }
  return r;
}

/* Unpack the Hessian of an Hd6 into a full 6x6 row-major array. */
static inline void Hd6HessFull(const Hd6 *a, double H[36])
{
  for (int i = 0, k = 0; i < 6; i++)
    for (int j = i; j < 6; j++, k++) H[i * 6 + j] = H[j * 6 + i] = a->h[k];
}
