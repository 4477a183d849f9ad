#pragma once
/* HYLC_TARGET_CLONES before a function definition: with GCC on x86-64, an extra clone of the function
   compiled for x86-64-v3 (AVX2, FMA), chosen at load time on processors that have it; elsewhere nothing.
   Used on the Cholesky panels and solves (src/linalg/chol.c): about 2x there on this project's machines
   (docs/performance.md). (Tried on the bend-twist element: 1.5x on the kernel, no measurable change of a
   whole solve, so not used there.) No FMA: -std=c11 keeps floating-point contraction off (tried on
   the Cholesky kernels, 2026-11-24: no faster factorization, slower triangular solves; on the packed
   update kernels of 2026-11-27 about 15 % faster, not taken: the factor would differ between the clones
   and from the AVX-512 copy of src/linalg/chol.c), and GCC does not
   reassociate sums without -ffast-math, so both clones perform the same operations in the same order.
   Plain C, no PETSc. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__has_attribute)
#  if __has_attribute(target_clones)
#    define HYLC_TARGET_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#  endif
#endif
#if !defined(HYLC_TARGET_CLONES)
#  define HYLC_TARGET_CLONES
#endif
