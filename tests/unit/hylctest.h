#pragma once
/* Minimal helpers for hylc's C unit tests.
   A unit test is a program in tests/unit/ that exits 0 when every check passed and non-zero otherwise;
   it stays silent on success and prints each failed check (file:line and the values) to stderr.
   The runner (tests/run.sh) runs it under mpirun with the number of ranks given by a line
   "   hylc-test: nprocs=N" in a comment of the source (default 1). */
#include <math.h>
#include <stdio.h>

static int hylc_test_failures = 0;

#define HYLC_CHECK(cond, ...)                                                  \
  do {                                                                         \
    if (!(cond)) {                                                             \
      hylc_test_failures++;                                                    \
      fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                                            \
      fprintf(stderr, "\n");                                                   \
    }                                                                          \
  } while (0)

/* |a - b| <= tol * max(1, |b|)  (relative for large values, absolute below 1) */
#define HYLC_CHECK_CLOSE(a, b, tol)                                                                                                                     \
  do {                                                                                                                                                  \
    const double hylc_a_ = (a), hylc_b_ = (b), hylc_t_ = (tol);                                                                                         \
    const double hylc_s_ = fabs(hylc_b_) > 1 ? fabs(hylc_b_) : 1.0;                                                                                     \
    HYLC_CHECK(fabs(hylc_a_ - hylc_b_) <= hylc_t_ * hylc_s_ && isfinite(hylc_a_), "%s = %.17g, %s = %.17g, tol %g", #a, hylc_a_, #b, hylc_b_, hylc_t_); \
  } while (0)

/* |a - b| <= tol * |b| (pure relative), with a finite a */
#define HYLC_CHECK_REL(a, b, tol)                                                                                                                                 \
  do {                                                                                                                                                            \
    const double hylc_a_ = (a), hylc_b_ = (b), hylc_t_ = (tol);                                                                                                   \
    HYLC_CHECK(fabs(hylc_a_ - hylc_b_) <= hylc_t_ * fabs(hylc_b_) && isfinite(hylc_a_), "%s = %.17g, %s = %.17g, rel tol %g", #a, hylc_a_, #b, hylc_b_, hylc_t_); \
  } while (0)

/* Deterministic uniform random numbers in [0,1) for tests (xorshift64*). */
static inline double HylcTestRand(unsigned long long *state)
{
  unsigned long long x = *state;
  x ^= x >> 12;
  x ^= x << 25;
  x ^= x >> 27;
  *state = x;
  return (double)((x * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

#define HYLC_TEST_RESULT() (hylc_test_failures ? 1 : 0)

#ifdef PETSCSYS_H
#  include <hylc/sys.h> /* PETSC_SUCCESS on PETSc < 3.19 */
/* an option's value unless the command line gives it (include PETSc before this header) */
static inline PetscErrorCode HylcTestOptionDefault(const char name[], const char value[])
{
  PetscBool set;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, name, &set));
  if (!set) PetscCall(PetscOptionsSetValue(NULL, name, value));
  PetscFunctionReturn(PETSC_SUCCESS);
}
#endif
