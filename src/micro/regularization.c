/* HylcMicro: the regularization schedule of the Newton matrix K = M H M + alpha I, alpha = alpha^ ||M g||_inf
   (include/hylc/micro.h, HylcMicroSetRegularization*()): all of it in this file. The paper's decay of alpha^
   over the iterations; the adaptive schedule (trust-region logic after each line search); the hybrid one
   (the paper's until the gradient has fallen, adaptive after, the paper's again at negative curvature);
   alpha x 10 when K cannot be factored or gives no descent; and the fallback of a solve that did not
   converge to the paper's schedule. Called by the SNES callbacks (snes.c), the KKT preconditioner (kkt.c)
   and HylcMicroSolve() (micro.c). */
#include <hylc/private/microimpl.h>

/* the paper's alpha^ at iteration it: alphaStart (alphaEnd/alphaStart)^(min(it, alphaIts)/alphaIts) */
PetscReal HylcMicroPaperAlphaHat_Private(HylcMicro M, PetscInt it) { return M->par.alphaStart * PetscPowReal(M->par.alphaEnd / M->par.alphaStart, (PetscReal)PetscMin(it, M->par.alphaIts) / M->par.alphaIts); }

/* alpha of the Newton matrix formed at iteration it (of the whole solve) where ||M g||_inf = gmax: the
   schedule's alpha^ times gmax (at least PETSC_SMALL); at iteration 0 the schedule's state starts over */
PetscErrorCode HylcMicroRegularizationAlpha_Private(HylcMicro M, PetscInt it, PetscReal gmax)
{
  const PetscReal apap  = HylcMicroPaperAlphaHat_Private(M, it);
  const PetscInt  sched = M->par.alphaSched;

  PetscFunctionBegin;
  if (it == 0) { /* the start of the solve; a restart after a saddle escape continues the count (itBase), so
                    it keeps the schedule's state unless the saddle was the initial guess itself */
    M->st.reverted = PETSC_FALSE;
    M->st.gmax0    = gmax;
    M->st.ahat     = M->par.alphaStart;
    M->st.adapting = (PetscBool)(sched == HYLC_MICRO_ALPHA_ADAPTIVE);
  }
  if (sched == HYLC_MICRO_ALPHA_HYBRID && !M->st.adapting && !M->st.reverted && gmax <= M->par.alphaSwitch * M->st.gmax0) { /* the switch: adaptive from the paper's alpha^ */
    M->st.adapting = PETSC_TRUE;
    M->st.ahat     = apap;
    PetscCall(PetscInfo(M, "hybrid schedule: adaptive from iteration %" PetscInt_FMT " (||M g||_inf %g of its initial value), alpha^ %g\n", it, (double)(gmax / M->st.gmax0), (double)apap));
  }
  M->st.alpha = (M->st.adapting ? M->st.ahat : apap) * gmax; /* adaptive: alpha^ of the previous line search (HylcMicroRegularizationAdapt_Private) */
  if (!(M->st.alpha > 0)) M->st.alpha = PETSC_SMALL;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the adaptive schedule (trust-region logic on alpha^), after each line search, from the alpha^ the step
   was computed with (after any x 10 retries of the KKT solve, which are kept): a full step that was not cut
   by the step limit, needed no retry and whose energy decrease agrees with the quadratic model of the
   unregularized Hessian (ratio > 3/4) divides alpha^ by the factor; a step cut by the step limit (then the
   step limit is the trust region) lets alpha^ decay at least as the paper's schedule does; a poor agreement
   (ratio < 1/4) or a backtracked step multiplies it by the factor, a rejected line search by its square;
   always within [alphaMin, alphaMax] */
PetscErrorCode HylcMicroRegularizationAdapt_Private(HylcMicro M, PetscBool accepted, PetscBool clipped, PetscReal lambda, PetscReal actual, PetscReal pred)
{
  const PetscReal f = M->par.alphaFact;
  PetscReal       a;
  PetscInt        it;

  PetscFunctionBegin;
  if (!(M->st.gmax > 0)) PetscFunctionReturn(PETSC_SUCCESS); /* alpha was not scaled by ||M g||: keep alpha^ */
  a = M->st.alpha / M->st.gmax;
  if (!accepted)
    a *= f * f;
  else if (lambda < 1)
    a *= f;
  else {
    const PetscReal rho = pred > 0 ? actual / pred : 1; /* a decrease where the model predicts none is good */
    if (rho < 0.25)
      a *= f;
    else if (rho > 0.75 && !clipped && M->st.retries == M->st.retriesJac)
      a /= f;
  }
  if (accepted && clipped) { /* the paper's alpha^ of the next iteration as a ceiling */
    PetscCall(SNESGetIterationNumber(M->snes, &it));
    a = PetscMin(a, HylcMicroPaperAlphaHat_Private(M, M->st.itBase + it + 1));
  }
  M->st.ahat = PetscClipInterval(a, M->par.alphaMin, M->par.alphaMax);
  PetscCall(PetscInfo(M, "adaptive alpha^ %g -> %g (accepted %d, step limit %s, lambda %g, energy decrease %g, predicted %g)\n", (double)(M->st.alpha / M->st.gmax), (double)M->st.ahat, (int)accepted, clipped ? "active" : "inactive", (double)lambda,
                      (double)actual, (double)pred));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* more regularization: alpha x 10, refactor */
PetscErrorCode HylcMicroRegularizationIncrease_Private(HylcMicro M, PetscBool *ok)
{
  PetscFunctionBegin;
  PetscCall(MatShift(M->K, 9 * M->st.alpha));
  M->st.alpha *= 10;
  M->st.retries++;
  PetscCall(PetscInfo(M, "indefinite Newton matrix: alpha x 10 -> %g\n", (double)M->st.alpha));
  PetscCall(HylcMicroKKTFactor_Private(M, ok));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* after a failed factorization (*ok false): with the hybrid schedule after its switch, negative curvature
   on the constraints' tangent space means a saddle near: the paper's schedule, whose steps leave saddles
   along their negative curvature, for the rest of the solve (alpha raised to the paper's, refactored);
   otherwise nothing */
PetscErrorCode HylcMicroRegularizationRevert_Private(HylcMicro M, PetscBool *ok)
{
  PetscInt  it;
  PetscReal apap;

  PetscFunctionBegin;
  if (*ok || !M->st.adapting || M->st.projNeg <= 0 || M->par.alphaSched != HYLC_MICRO_ALPHA_HYBRID) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SNESGetIterationNumber(M->snes, &it));
  it += M->st.itBase;
  apap           = HylcMicroPaperAlphaHat_Private(M, it) * M->st.gmax;
  M->st.adapting = PETSC_FALSE;
  M->st.reverted = PETSC_TRUE;
  PetscCall(PetscInfo(M, "hybrid schedule: negative curvature at iteration %" PetscInt_FMT ", the paper's schedule from here (alpha %g -> %g)\n", it, (double)M->st.alpha, (double)PetscMax(M->st.alpha, apap)));
  if (apap > M->st.alpha) {
    PetscCall(MatShift(M->K, apap - M->st.alpha));
    M->st.alpha = apap;
  }
  PetscCall(HylcMicroKKTFactor_Private(M, ok));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* whether a solve that ended with status is repeated from the same start with the paper's schedule: the
   adaptive and hybrid schedules fall back (-micro_alpha_fallback) when they did not converge */
PetscBool HylcMicroRegularizationFallback_Private(HylcMicro M, HylcMicroStatus status) { return (PetscBool)(status != HYLC_MICRO_CONVERGED && M->par.alphaFallback && M->par.alphaSched != HYLC_MICRO_ALPHA_PAPER); }
