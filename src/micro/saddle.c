/* HylcMicro: the second-order test of a converged state and the escape from saddle points (docs/method.md,
   "Saddle points").

   The Newton iteration stops where the projected gradient vanishes: at a local minimum, or at a saddle
   point, where the Hessian restricted to the tangent space of the constraints has a negative eigenvalue.
   A cold start is often symmetric (the affine deformation of a symmetric tile), the gradient keeps that
   symmetry, and the iterates stay on the symmetric states, whose energy they minimize: they end at a saddle
   of the full problem (a compressed yarn kept straight, a loop kept centred), an equilibrium no real cloth
   rests in, with a higher energy than the minima next to it. The test: with K = M H M + sigma I,
   sigma = tol max|diag(M H M)|, the number of negative eigenvalues of K on the tangent space (the inertia
   of its factorization and of the Schur complement, as the adaptive schedule counts them). A saddle is left
   along a direction of negative curvature: sigma is raised x 10 until K is positive definite on the tangent
   space, inverse iteration with that factor (the KKT solve with a zero constraint residual, which keeps the
   iterate in the tangent space) gives the eigenvector of the smallest eigenvalue, and a step along it,
   signed to descend, of the largest vertex displacement the step limit allows, is halved until the energy
   decreases by at least a quarter of its quadratic model. The Newton iteration then resumes. */
#include <hylc/private/microimpl.h>

/* a fixed pseudo-random start vector in [-1/2, 1/2) (the same on every rank and in every run) */
static PetscErrorCode StartVector(Vec v)
{
  PetscScalar *a;
  PetscInt     n;
  uint64_t     s = 0x9E3779B97F4A7C15ULL;

  PetscFunctionBegin;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt i = 0; i < n; i++) {
    s    = s * 6364136223846793005ULL + 1442695040888963407ULL;
    a[i] = (PetscReal)(s >> 11) / 9007199254740992.0 - 0.5;
  }
  PetscCall(VecRestoreArray(v, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the largest vertex displacement of a step v of the scaled unknowns */
static PetscErrorCode MaxDisplacement(HylcMicro M, Vec v, PetscReal *d)
{
  const PetscScalar *a;

  PetscFunctionBegin;
  *d = 0;
  PetscCall(VecGetArrayRead(v, &a));
  for (PetscInt o = 0; o < M->ny / 4; o++) *d = PetscMax(*d, PetscSqrtReal(PetscSqr(PetscRealPart(a[4 * o])) + PetscSqr(PetscRealPart(a[4 * o + 1])) + PetscSqr(PetscRealPart(a[4 * o + 2]))));
  PetscCall(VecRestoreArrayRead(v, &a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the direction of most negative curvature of M H M on the tangent space, by inverse iteration with the
   factor of K = M H M + sigma I (positive definite there) in M->kkt.inner; on return *q is its curvature
   v^T M H M v (|v| = 1) */
static PetscErrorCode NegativeCurvature(HylcMicro M, PetscReal sigma, Vec v, PetscReal *q)
{
  Vec         w, kv;
  PetscReal   nrm, qold = 0;
  PetscScalar vkv;

  PetscFunctionBegin;
  PetscCall(VecDuplicate(v, &w));
  PetscCall(VecDuplicate(v, &kv));
  PetscCall(PetscArrayzero(M->kkt.c, M->m)); /* solutions in the tangent space A M v = 0 */
  PetscCall(StartVector(v));
  *q = 0;
  for (PetscInt k = 0; k < 100; k++) {
    PetscCall(HylcMicroKKTSolve_Private(M, v, w));
    PetscCall(VecNorm(w, NORM_2, &nrm));
    if (!(nrm > 0)) break;
    PetscCall(VecAXPBY(v, 1.0 / nrm, 0.0, w));
    PetscCall(MatMult(M->K, v, kv));
    PetscCall(VecDot(v, kv, &vkv));
    *q = PetscRealPart(vkv) - sigma;
    if (k >= 4 && PetscAbsReal(*q - qold) <= 1e-3 * PetscAbsReal(*q)) break;
    qold = *q;
  }
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&kv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the second-order test at the converged iterate M->X: *neg negative eigenvalues of M H M below
   -tol max|diag| on the tangent space (-1: not known: a failed factorization, which is how a solver type
   without inertia (cholmod) reports an indefinite K); with escape, a saddle is left by a step along
   negative curvature (*escaped) */
PetscErrorCode HylcMicroSaddle_Private(HylcMicro M, PetscBool escape, PetscInt *neg, PetscBool *escaped)
{
  const PetscBool adapting = M->st.adapting;
  const PetscReal alpha    = M->st.alpha;
  Vec             v = NULL, w = NULL;
  PetscReal       dmax, sigma, q = 0, E0, dlim, dv, gv = 0;
  PetscBool       ok;

  PetscFunctionBegin;
  *neg     = -1;
  *escaped = PETSC_FALSE;
  PetscCall(PetscLogEventBegin(HYLC_MicroSaddle, M, 0, 0, 0));
  PetscCall(VecDuplicate(M->X, &v));
  /* H and g at X (the converged iterate's are in K and gw unless the Jacobian was formed since) */
  PetscCall(HylcMicroToY_Private(M, M->X, M->yw));
  if (!M->st.haveH) {
    PetscCall(HylcPeriodicSetState(M->P, M->yw));
    PetscCall(HylcPeriodicEvaluate(M->P, HYLC_TERM_ALL, M->st.parts, M->gw, M->K));
  }
  M->st.haveH = PETSC_FALSE; /* K is scaled and shifted below */
  E0          = M->st.parts[0] + M->st.parts[1] + M->st.parts[2] + M->st.parts[3];
  PetscCall(MatDiagonalScale(M->K, M->mvec, M->mvec));
  PetscCall(MatGetDiagonal(M->K, v));
  PetscCall(VecNorm(v, NORM_INFINITY, &dmax));
  sigma = M->par.saddleTol * dmax;
  PetscCall(MatShift(M->K, sigma));
  PetscCall(MatSetOption(M->K, MAT_SYMMETRIC, PETSC_TRUE));
  M->st.alpha    = sigma;
  M->st.adapting = PETSC_TRUE; /* the factorization counts the negative eigenvalues on the tangent space */
  PetscCall(HylcMicroKKTFactor_Private(M, &ok));
  if (ok)
    *neg = 0;
  else if (M->st.projNeg > 0)
    *neg = M->st.projNeg;
  PetscCall(PetscInfo(M, "second-order test (sigma %g = %g x max|diag(M H M)|): %" PetscInt_FMT " negative eigenvalues on the tangent space\n", (double)sigma, (double)M->par.saddleTol, *neg));
  if (*neg > 0 && escape) {
    PetscReal s = sigma;
    for (PetscInt k = 0; !ok && k < M->par.maxRetries; k++) { /* the shift that makes K positive definite there */
      PetscCall(MatShift(M->K, 9 * s));
      s *= 10;
      M->st.alpha = s;
      PetscCall(HylcMicroKKTFactor_Private(M, &ok));
    }
    if (ok) PetscCall(NegativeCurvature(M, s, v, &q));
    if (ok && q < -sigma) {
      const PetscScalar *va;
      PetscReal          t, E = PETSC_INFINITY;
      /* descend: v . M g <= 0 */
      PetscCall(VecGetArrayRead(v, &va));
      for (PetscInt i = 0; i < M->ny; i++) gv += PetscRealPart(va[i]) * ((i % 4 == 3) ? M->mu * M->gw[i] : M->gw[i]);
      PetscCall(VecRestoreArrayRead(v, &va));
      if (gv > 0) {
        PetscCall(VecScale(v, -1));
        gv = -gv;
      }
      PetscCall(MaxDisplacement(M, v, &dv));
      PetscCall(HylcMicroStepLimit_Private(M, M->X, &dlim));
      t = dv > 0 ? dlim / dv : 0;
      PetscCall(VecDuplicate(M->X, &w));
      for (PetscInt i = 0; i < 30 && t > 0; i++, t *= 0.5) {
        const PetscReal pred = -t * gv - 0.5 * t * t * q; /* the model's decrease, > 0 */
        PetscCall(VecWAXPY(w, t, v, M->X));
        PetscCall(HylcMicroSafeEnergy_Private(M, w, &E, NULL));
        if (E < E0 && E0 - E >= 0.25 * pred) {
          PetscCall(VecCopy(w, M->X));
          PetscCall(HylcMicroToY_Private(M, M->X, M->yw));
          PetscCall(HylcPeriodicSetState(M->P, M->yw));
          PetscCall(HylcPeriodicUpdateFrames(M->P));
          PetscCall(HylcMicroPushEnergy_Private(M, E));
          M->st.E0 = E;
          *escaped = PETSC_TRUE;
          PetscCall(PetscInfo(M, "saddle escape: curvature %g (shift %g), step %g r, energy %.12g -> %.12g\n", (double)q, (double)s, (double)(t * dv / M->r), (double)E0, (double)E));
          break;
        }
      }
      if (!*escaped) PetscCall(PetscInfo(M, "saddle escape: no decrease along the direction of curvature %g\n", (double)q));
    } else
      PetscCall(PetscInfo(M, "saddle escape: no direction of negative curvature found (factored: %d, curvature %g)\n", (int)ok, (double)q));
  }
  M->st.adapting = adapting;
  M->st.alpha    = alpha;
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&w));
  PetscCall(PetscLogEventEnd(HYLC_MicroSaddle, M, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
