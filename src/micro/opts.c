/* HylcMicro: the parameters, their setters and options (HylcMicroSetFromOptions reads options and builds
   nothing), and the viewer. */
#include <hylc/options.h>
#include <hylc/private/microimpl.h>

/*@C
  HylcMicroSetRegularization - Sets the regularization alpha = alpha^_i ||M g||_inf of the Newton matrix
  K = M H M + alpha I: the schedule alpha^_i = start (end/start)^(min(i, its)/its) and the number of
  alpha x 10 retries when K is indefinite. Not collective.

  Input Parameters:
+ M       - the solver
. start   - alpha^ at iteration 0 (default 5000; PETSC_DEFAULT keeps the value)
. end     - alpha^ from iteration its on (default 5)
. its     - iterations of the geometric decay (default 400)
- retries - alpha x 10 retries for an indefinite K (default 12)

  Options Database Keys:
+ -micro_alpha_start <5000> - start
. -micro_alpha_end <5> - end
. -micro_alpha_its <400> - its
- -micro_alpha_retries <12> - retries

  Level: intermediate

.seealso: HylcMicroSetFromOptions(), HylcMicroSetIndefinite()
@*/
PetscErrorCode HylcMicroSetRegularization(HylcMicro M, PetscReal start, PetscReal end, PetscInt its, PetscInt retries)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (start != (PetscReal)PETSC_DEFAULT) M->par.alphaStart = start;
  if (end != (PetscReal)PETSC_DEFAULT) M->par.alphaEnd = end;
  if (its != PETSC_DEFAULT) M->par.alphaIts = its;
  if (retries != PETSC_DEFAULT) M->par.maxRetries = retries;
  PetscCheck(M->par.alphaStart > 0 && M->par.alphaEnd > 0 && M->par.alphaIts >= 1 && M->par.maxRetries >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-%smicro_alpha_start %g, -%smicro_alpha_end %g must be positive, -%smicro_alpha_its %" PetscInt_FMT " at least 1 and -%smicro_alpha_retries %" PetscInt_FMT " non-negative", HylcMicroPrefix_Private(M), (double)M->par.alphaStart,
             HylcMicroPrefix_Private(M), (double)M->par.alphaEnd, HylcMicroPrefix_Private(M), M->par.alphaIts, HylcMicroPrefix_Private(M), M->par.maxRetries);
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const HylcMicroAlphaSchedules[] = {"paper", "adaptive", "hybrid", "HylcMicroAlphaSchedule", "HYLC_MICRO_ALPHA_", NULL};

/*@C
  HylcMicroSetRegularizationSchedule - Sets how alpha^ of alpha = alpha^ ||M g||_inf evolves: paper (the
  paper's procedure), the geometric decay of HylcMicroSetRegularization() over the iteration count; or
  adaptive (the default), a trust-region-like rule: alpha^ starts at the start value of HylcMicroSetRegularization() and, after each line search, is the
  alpha^ the step was computed with (after any x 10 retries) divided by factor if the full step was accepted
  and the actual energy decrease is more than 3/4 of the decrease predicted by the quadratic model of the
  unregularized Hessian, multiplied by factor if it is less than 1/4 or the step was backtracked, by
  factor^2 if the line search found no decrease; a step cut by the step limit lets alpha^ decay at least as
  the paper's schedule; always clamped to [min, max]. The adaptive schedule refuses a K that is indefinite on
  the tangent space of the constraints (the x 10 retries raise alpha^), since with a small alpha^ the steps
  would otherwise converge to saddle points; or hybrid, the paper's schedule until ||M g||_inf falls below
  the switch of HylcMicroSetRegularizationSwitch() times its initial value, then adaptive, back to the
  paper's for good at negative curvature. The convergence test is the same. Not collective.

  Input Parameters:
+ M        - the solver
. schedule - HYLC_MICRO_ALPHA_PAPER, HYLC_MICRO_ALPHA_ADAPTIVE or HYLC_MICRO_ALPHA_HYBRID
. factor   - adaptive: the factor, > 1 (default 4; PETSC_DEFAULT keeps the value)
. min      - adaptive: the smallest alpha^, > 0 (default 1e-2)
- max      - adaptive: the largest alpha^, >= min (default 1e10)

  Options Database Keys:
+ -micro_alpha_schedule <adaptive> - adaptive, paper (the paper's procedure) or hybrid
. -micro_alpha_factor <4> - factor
. -micro_alpha_min <1e-2> - min
- -micro_alpha_max <1e10> - max

  Level: intermediate

.seealso: HylcMicroSetRegularization(), HylcMicroSetFromOptions()
@*/
PetscErrorCode HylcMicroSetRegularizationSchedule(HylcMicro M, HylcMicroAlphaSchedule schedule, PetscReal factor, PetscReal min, PetscReal max)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(schedule == HYLC_MICRO_ALPHA_PAPER || schedule == HYLC_MICRO_ALPHA_ADAPTIVE || schedule == HYLC_MICRO_ALPHA_HYBRID, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_alpha_schedule %d: must be paper, adaptive or hybrid",
             HylcMicroPrefix_Private(M), (int)schedule);
  M->par.alphaSched = schedule;
  if (factor != (PetscReal)PETSC_DEFAULT) M->par.alphaFact = factor;
  if (min != (PetscReal)PETSC_DEFAULT) M->par.alphaMin = min;
  if (max != (PetscReal)PETSC_DEFAULT) M->par.alphaMax = max;
  PetscCheck(M->par.alphaFact > 1 && PetscIsNormalReal(M->par.alphaFact), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_alpha_factor %g: must be finite and greater than 1", HylcMicroPrefix_Private(M), (double)M->par.alphaFact);
  PetscCheck(M->par.alphaMin > 0 && M->par.alphaMax >= M->par.alphaMin && PetscIsNormalReal(M->par.alphaMax), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-%smicro_alpha_min %g must be positive and -%smicro_alpha_max %g finite and at least -%smicro_alpha_min", HylcMicroPrefix_Private(M), (double)M->par.alphaMin, HylcMicroPrefix_Private(M), (double)M->par.alphaMax,
             HylcMicroPrefix_Private(M));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@
  HylcMicroSetRegularizationSwitch - The switch of the hybrid regularization schedule
  (HYLC_MICRO_ALPHA_HYBRID): alpha^ follows the paper's decay while the scaled gradient is large, which
  keeps the early steps short and the solve on the branch the paper's schedule reaches, and follows the
  adaptive logic of HylcMicroSetRegularizationSchedule() from the first iteration whose ||M g||_inf is at
  most sw times its value at iteration 0, starting from the paper's alpha^ of that iteration. Not collective.

  Input Parameters:
+ M  - the solver
- sw - the switch, in (0, 1] (default 1e-2; PETSC_DEFAULT keeps the value)

  Options Database Key:
. -micro_alpha_switch <1e-2> - sw

  Level: intermediate

.seealso: HylcMicroSetRegularizationSchedule(), HylcMicroSetRegularization()
@*/
PetscErrorCode HylcMicroSetRegularizationSwitch(HylcMicro M, PetscReal sw)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (sw != (PetscReal)PETSC_DEFAULT) M->par.alphaSwitch = sw;
  PetscCheck(M->par.alphaSwitch > 0 && M->par.alphaSwitch <= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_alpha_switch %g: must be in (0, 1]", HylcMicroPrefix_Private(M), (double)M->par.alphaSwitch);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@
  HylcMicroSetRegularizationFallback - Whether a solve with the adaptive or the hybrid schedule
  (HylcMicroSetRegularizationSchedule()) that does not converge is repeated, from the same start, with the
  paper's schedule. The adaptive schedule can stall where the paper's converges: a cold start deep in
  compression (the rib at s_x < -0.5) forces the yarns into each other, and the steps of a small alpha^ meet the
  pole of the contact penalty. The result is then the repeat's (HylcMicroResult.fallback is set; the
  iterations, retries, stalls and times are the sums of both solves). Not collective.

  Input Parameters:
+ M  - the solver
- fb - PETSC_TRUE (default) to repeat, PETSC_FALSE to report the first solve's status

  Options Database Key:
. -micro_alpha_fallback <true> - fb

  Level: intermediate

.seealso: HylcMicroSetRegularizationSchedule(), HylcMicroSolve()
@*/
PetscErrorCode HylcMicroSetRegularizationFallback(HylcMicro M, PetscBool fb)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  M->par.alphaFallback = fb;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetTwistScale - Sets mu, the scale of the twist unknowns (y = M y^, M = 1 per position, mu per
  twist). Not collective.

  Input Parameters:
+ M  - the solver
- mu - the scale; 0 (default) means 1/r for the yarn radius r

  Options Database Key:
. -micro_twist_scale <0> - mu

  Level: advanced

.seealso: HylcMicroSetFromOptions()
@*/
PetscErrorCode HylcMicroSetTwistScale(HylcMicro M, PetscReal mu)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(mu >= 0 && PetscIsNormalReal(mu + 1), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_twist_scale %g: must be finite and non-negative (0: 1/r)", HylcMicroPrefix_Private(M), (double)mu);
  M->par.twistScale = mu;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetStepLimit - Sets the step limit d_max = (p0 + p1 clamp(lambda_min(I), 0, 1)) r of the largest
  vertex displacement of a Newton step (S2.2). Not collective.

  Input Parameters:
+ M  - the solver
. p0 - default 0.05 (PETSC_DEFAULT keeps the value)
- p1 - default 0.15

  Options Database Keys:
+ -micro_step_p0 <0.05> - p0
- -micro_step_p1 <0.15> - p1

  Level: advanced

.seealso: HylcMicroSetLineSearch()
@*/
PetscErrorCode HylcMicroSetStepLimit(HylcMicro M, PetscReal p0, PetscReal p1)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (p0 != (PetscReal)PETSC_DEFAULT) M->par.stepP0 = p0;
  if (p1 != (PetscReal)PETSC_DEFAULT) M->par.stepP1 = p1;
  PetscCheck(M->par.stepP0 > 0 && M->par.stepP1 >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_step_p0 %g must be positive, -%smicro_step_p1 %g non-negative", HylcMicroPrefix_Private(M), (double)M->par.stepP0, HylcMicroPrefix_Private(M),
             (double)M->par.stepP1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@
  HylcMicroSetStepClearance - Ties the step limit to the contact geometry: with rho > 0 the largest vertex
  displacement of a Newton step is also at most rho times the clearance of the current iterate, the
  smallest distance between two yarn centerlines that may touch (HylcPeriodicGetClearance()). With
  rho < 1/2 no two centerlines cross along the step, so a step cannot pull one yarn through another
  across the contact barrier, whatever the regularization (docs/method.md, "Newton solver"). Not collective.

  Input Parameters:
+ M   - the solver
- rho - the fraction, in [0, 1/2) (default 0: no clearance limit; PETSC_DEFAULT keeps the value)

  Options Database Key:
. -micro_step_clearance <0> - rho

  Level: intermediate

.seealso: HylcMicroSetStepLimit(), HylcPeriodicGetClearance()
@*/
PetscErrorCode HylcMicroSetStepClearance(HylcMicro M, PetscReal rho)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (rho != (PetscReal)PETSC_DEFAULT) M->par.stepClear = rho;
  PetscCheck(M->par.stepClear >= 0 && M->par.stepClear < 0.5, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_step_clearance %g: must be in [0, 0.5)", HylcMicroPrefix_Private(M), (double)M->par.stepClear);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetLineSearch - Sets the backtracking line search: the step is multiplied by factor until the
  energy strictly decreases, at most trials times; after maxStalls consecutive line searches without
  decrease the solve stops (status stalled). Not collective.

  Input Parameters:
+ M         - the solver
. factor    - backtracking factor in (0, 1) (default 0.1; PETSC_DEFAULT keeps the value)
. trials    - trials per iteration (default 11)
- maxStalls - consecutive failed line searches before giving up (default 5)

  Options Database Keys:
+ -micro_ls_factor <0.1> - factor
. -micro_ls_max <11> - trials
- -micro_max_stalls <5> - maxStalls

  Level: advanced

.seealso: HylcMicroSetStepLimit()
@*/
PetscErrorCode HylcMicroSetLineSearch(HylcMicro M, PetscReal factor, PetscInt trials, PetscInt maxStalls)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (factor != (PetscReal)PETSC_DEFAULT) M->par.lsFactor = factor;
  if (trials != PETSC_DEFAULT) M->par.lsMax = trials;
  if (maxStalls != PETSC_DEFAULT) M->par.maxStalls = maxStalls;
  PetscCheck(M->par.lsFactor > 0 && M->par.lsFactor < 1 && M->par.lsMax >= 1 && M->par.maxStalls >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-%smicro_ls_factor %g must be in (0, 1), -%smicro_ls_max %" PetscInt_FMT " and -%smicro_max_stalls %" PetscInt_FMT " at least 1", HylcMicroPrefix_Private(M), (double)M->par.lsFactor, HylcMicroPrefix_Private(M), M->par.lsMax,
             HylcMicroPrefix_Private(M), M->par.maxStalls);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetTolerances - Sets the convergence test and the wall-time cap: converged when the projected
  gradient |z| < rtol |z0| or |z| < atol k_s, and the constraint residual |A y - dL| < ctol r. Not collective.

  Input Parameters:
+ M       - the solver
. rtol    - default 1e-5 (PETSC_DEFAULT keeps the value)
. atol    - default 1e-10 (k_s = Es pi r^2, a force: for tiles already at rest)
. ctol    - default 1e-4
- maxTime - wall-time cap per solve in seconds (default 60; status time_cap)

  Options Database Keys:
+ -micro_rtol <1e-5> - rtol
. -micro_atol <1e-10> - atol
. -micro_ctol <1e-4> - ctol
- -micro_max_time <60> - maxTime

  Level: beginner

.seealso: HylcMicroSetFromOptions()
@*/
PetscErrorCode HylcMicroSetTolerances(HylcMicro M, PetscReal rtol, PetscReal atol, PetscReal ctol, PetscReal maxTime)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (rtol != (PetscReal)PETSC_DEFAULT) M->par.rtol = rtol;
  if (atol != (PetscReal)PETSC_DEFAULT) M->par.atol = atol;
  if (ctol != (PetscReal)PETSC_DEFAULT) M->par.ctol = ctol;
  if (maxTime != (PetscReal)PETSC_DEFAULT) M->par.maxTime = maxTime;
  PetscCheck(M->par.rtol > 0 && M->par.ctol > 0 && M->par.maxTime > 0 && M->par.atol >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_rtol %g, -%smicro_ctol %g, -%smicro_max_time %g must be positive, -%smicro_atol %g non-negative",
             HylcMicroPrefix_Private(M), (double)M->par.rtol, HylcMicroPrefix_Private(M), (double)M->par.ctol, HylcMicroPrefix_Private(M), (double)M->par.maxTime, HylcMicroPrefix_Private(M), (double)M->par.atol);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetIndefinite - Accept the factorization of an indefinite Newton matrix when the step is a
  descent direction of positive curvature (true, default; the factorizations are signed, as LDL^T), or
  increase alpha x 10 whenever K has a negative eigenvalue (false; counted with MatGetInertia() for the
  solver types hylc, petsc and mumps; cholmod fails on any indefinite K). Not collective.

  Input Parameters:
+ M   - the solver
- flg - PETSC_TRUE to accept indefinite factorizations

  Options Database Key:
. -micro_factor_indefinite <true> - flg

  Level: advanced

.seealso: HylcMicroSetRegularization(), HylcMicroGetFactorPC()
@*/
PetscErrorCode HylcMicroSetIndefinite(HylcMicro M, PetscBool flg)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  M->par.indefinite = flg;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetSaddleEscape - Sets the second-order test of a converged state: the Hessian restricted to the
  tangent space of the constraints, shifted by tol x the largest diagonal entry of M H M, is factored and
  its negative eigenvalues counted (HylcMicroResult.negcurv). A state with some is a saddle point, not a
  minimum; it is left by a step along the direction of most negative curvature and the Newton iteration
  resumes, at most maxEscapes times per solve (HylcMicroResult.escapes). Not collective.

  Input Parameters:
+ M          - the solver
. test       - PETSC_TRUE to test converged states (default; implied by maxEscapes > 0)
. maxEscapes - escapes per solve (default 5; 0: test only; PETSC_DEFAULT keeps the value)
- tol        - relative threshold of negative curvature (default 1e-6; PETSC_DEFAULT keeps the value)

  Options Database Keys:
+ -micro_saddle_test <true> - test
. -micro_saddle_escapes <5> - maxEscapes
- -micro_saddle_tol <1e-6> - tol

  Notes:
  The count needs a solver type that counts negative pivots (hylc, petsc, mumps); cholmod, which fails on an
  indefinite K, proves a minimum (negcurv 0) when K is positive definite and otherwise leaves the count
  unknown (negcurv -1, no escape). The test costs one factorization per solve; the Newton iterations after the escapes cost
  more (about +38 % on the stockinette's thinned plan with the paper's schedule, where 31 % of the cold
  solves ended at saddle points). Turn both off with -micro_saddle_escapes 0 -micro_saddle_test false.
  docs/method.md, "Saddle points".

  Level: intermediate

.seealso: HylcMicroSetRegularizationSchedule(), HylcMicroSolve()
@*/
PetscErrorCode HylcMicroSetSaddleEscape(HylcMicro M, PetscBool test, PetscInt maxEscapes, PetscReal tol)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (maxEscapes != PETSC_DEFAULT) M->par.saddleMax = maxEscapes;
  if (tol != (PetscReal)PETSC_DEFAULT) M->par.saddleTol = tol;
  PetscCheck(M->par.saddleMax >= 0 && M->par.saddleTol > 0 && M->par.saddleTol < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_saddle_escapes %" PetscInt_FMT " must be non-negative, -%smicro_saddle_tol %g in (0, 1)", HylcMicroPrefix_Private(M),
             M->par.saddleMax, HylcMicroPrefix_Private(M), (double)M->par.saddleTol);
  M->par.saddleTest = (PetscBool)(test || M->par.saddleMax > 0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const HylcMicroUniaxialGradients[] = {"envelope", "fd", "HylcMicroUniaxialGradient", "HYLC_MICRO_UNIAXIAL_", NULL};

/*@C
  HylcMicroSetUniaxial - Sets how HylcMicroSolveUniaxial() minimizes Psi over the two free (lateral) strains:
  a Newton method whose gradient is that of gradient, whose Hessian is the forward difference of the lateral
  gradient with step h, with steps of at most maxStep in each strain and a backtracking line search on Psi.
  Not collective.

  Input Parameters:
+ M        - the solver
. gradient - HYLC_MICRO_UNIAXIAL_ENVELOPE (default: the envelope theorem at each equilibrium,
             HylcMicroGetStrainGradient()) or HYLC_MICRO_UNIAXIAL_FD (central differences of Psi with step
             h over continued solves)
. xtol     - converged when the Newton step to the minimizer predicted at the state is at most xtol in each
             lateral strain (default 1e-5; PETSC_DEFAULT keeps the value)
. maxIt    - Newton steps (default 30)
. h        - difference step, a strain (default 1e-4)
- maxStep  - largest change of a lateral strain per Newton step (default 0.05)

  Options Database Keys:
+ -micro_uniaxial_gradient <envelope> - envelope or fd
. -micro_uniaxial_xtol <1e-5> - xtol
. -micro_uniaxial_max_it <30> - maxIt
. -micro_uniaxial_fd_step <1e-4> - h
- -micro_uniaxial_max_step <0.05> - maxStep

  Level: intermediate

.seealso: HylcMicroSolveUniaxial(), HylcMicroGetStrainGradient()
@*/
PetscErrorCode HylcMicroSetUniaxial(HylcMicro M, HylcMicroUniaxialGradient gradient, PetscReal xtol, PetscInt maxIt, PetscReal h, PetscReal maxStep)
{
  const char *p;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  p = HylcMicroPrefix_Private(M);
  PetscCheck(gradient == HYLC_MICRO_UNIAXIAL_ENVELOPE || gradient == HYLC_MICRO_UNIAXIAL_FD, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_gradient %d: must be envelope or fd", p, (int)gradient);
  M->par.uniGrad = gradient;
  if (xtol != (PetscReal)PETSC_DEFAULT) {
    PetscCheck(xtol > 0 && xtol < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_xtol %g: must be in (0, 1)", p, (double)xtol);
    M->par.uniXtol = xtol;
  }
  if (maxIt != PETSC_DEFAULT) {
    PetscCheck(maxIt >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_max_it %" PetscInt_FMT ": must be at least 1", p, maxIt);
    M->par.uniMaxIt = maxIt;
  }
  if (h != (PetscReal)PETSC_DEFAULT) {
    PetscCheck(h > 0 && h <= 0.01, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_fd_step %g: must be in (0, 0.01]", p, (double)h);
    M->par.uniH = h;
  }
  if (maxStep != (PetscReal)PETSC_DEFAULT) {
    PetscCheck(maxStep > 0 && maxStep <= 0.5, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_max_step %g: must be in (0, 0.5]", p, (double)maxStep);
    M->par.uniMaxStep = maxStep;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetUniaxialTolerances - Sets the accuracy of HylcMicroSolveUniaxial(): the relative tolerance of its
  microscale solves (-micro_rtol while it runs; the lateral minimization needs gradients well below the
  lateral stresses it drives to zero) and the gradient test that ends it when a line search finds no decrease
  (Psi is then at its noise level: nearby equilibria of the tile differ by about 1e-7 relative). Not collective.

  Input Parameters:
+ M    - the solver
. rtol - -micro_rtol of the uniaxial solves (default 1e-8; PETSC_DEFAULT keeps the value)
- gtol - converged after a failed line search if the lateral gradient is at most gtol |T| (default 1e-4)

  Options Database Keys:
+ -micro_uniaxial_rtol <1e-8> - rtol
- -micro_uniaxial_gtol <1e-4> - gtol

  Level: intermediate

.seealso: HylcMicroSolveUniaxial(), HylcMicroSetUniaxial(), HylcMicroSetTolerances()
@*/
PetscErrorCode HylcMicroSetUniaxialTolerances(HylcMicro M, PetscReal rtol, PetscReal gtol)
{
  const char *p;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  p = HylcMicroPrefix_Private(M);
  if (rtol != (PetscReal)PETSC_DEFAULT) {
    PetscCheck(rtol > 0 && rtol < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_rtol %g: must be in (0, 1)", p, (double)rtol);
    M->par.uniRtol = rtol;
  }
  if (gtol != (PetscReal)PETSC_DEFAULT) {
    PetscCheck(gtol >= 0 && gtol < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_uniaxial_gtol %g: must be in [0, 1)", p, (double)gtol);
    M->par.uniGtol = gtol;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSetFromOptions - Reads the options of the Newton solver (-micro_*, after the solver's prefix if
  it has one) and, as SLEPc's EPSSetFromOptions() calls STSetFromOptions(), those of its sub-objects,
  created on first use with their defaults: the periodic tile (HylcMicroGetPeriodic(): -periodic_*,
  -macro_*), the factorization PC (HylcMicroGetFactorPC(), prefix micro_factor_:
  -micro_factor_pc_factor_mat_solver_type hylc|petsc|cholmod|mumps, -micro_factor_pc_factor_mat_ordering_type,
  ...) and the SNES with its KSP (HylcMicroGetSNES(), prefix micro_: -micro_snes_max_it (iteration cap,
  default 2000), -micro_snes_monitor, ...). It needs no pattern and builds nothing. Not collective.

  Input Parameter:
. M - the solver

  Options Database Keys:
+ -micro_alpha_start, -micro_alpha_end, -micro_alpha_its, -micro_alpha_retries - HylcMicroSetRegularization()
. -micro_alpha_schedule adaptive|paper|hybrid, -micro_alpha_factor, -micro_alpha_min, -micro_alpha_max - HylcMicroSetRegularizationSchedule()
. -micro_twist_scale - HylcMicroSetTwistScale()
. -micro_step_p0, -micro_step_p1 - HylcMicroSetStepLimit()
. -micro_ls_factor, -micro_ls_max, -micro_max_stalls - HylcMicroSetLineSearch()
. -micro_rtol, -micro_atol, -micro_ctol, -micro_max_time - HylcMicroSetTolerances()
. -micro_factor_indefinite - HylcMicroSetIndefinite()
. -micro_saddle_test, -micro_saddle_escapes, -micro_saddle_tol - HylcMicroSetSaddleEscape()
. -micro_uniaxial_gradient, -micro_uniaxial_xtol, -micro_uniaxial_max_it, -micro_uniaxial_fd_step, -micro_uniaxial_max_step - HylcMicroSetUniaxial()
. -micro_uniaxial_rtol, -micro_uniaxial_gtol - HylcMicroSetUniaxialTolerances()
. -micro_view - HylcMicroView() at set-up
. -periodic_*, -macro_* - HylcPeriodicSetFromOptions() of HylcMicroGetPeriodic()
. -micro_factor_pc_* - PCSetFromOptions() of HylcMicroGetFactorPC()
- -micro_snes_*, -micro_ksp_* - SNESSetFromOptions() of HylcMicroGetSNES()

  Notes:
  -micro_factor_type (hylc|petsc) was removed: it is an error naming its replacement,
  -micro_factor_pc_factor_mat_solver_type (hylc, the default, or petsc, cholmod, mumps).

  Level: beginner

.seealso: HylcMicroSetUp(), HylcMicroView(), HylcMicroGetSNES(), HylcMicroGetPeriodic(), HylcMicroGetFactorPC()
@*/
PetscErrorCode HylcMicroSetFromOptions(HylcMicro M)
{
  HylcMicroParams p = M->par;
  PetscBool       flg, schedSet;
  char            sched[64];
  HylcPeriodic    P;
  PC              inner;
  SNES            snes;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCall(PetscOptionsHasName(((PetscObject)M)->options, ((PetscObject)M)->prefix, "-micro_factor_type", &flg));
  PetscCheck(!flg, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-%smicro_factor_type was removed: choose the factorization with -%smicro_factor_pc_factor_mat_solver_type hylc|petsc|cholmod|mumps (hylc is the default; petsc is the former -%smicro_factor_type petsc)", HylcMicroPrefix_Private(M),
             HylcMicroPrefix_Private(M), HylcMicroPrefix_Private(M));
  PetscObjectOptionsBegin((PetscObject)M);
  PetscCall(HylcOptionsReal("-micro_alpha_start", "Regularization schedule: alpha^ at iteration 0", "HylcMicroSetRegularization", p.alphaStart, &p.alphaStart, NULL));
  PetscCall(HylcOptionsReal("-micro_alpha_end", "Regularization schedule: alpha^ from iteration alpha_its on", "HylcMicroSetRegularization", p.alphaEnd, &p.alphaEnd, NULL));
  PetscCall(HylcOptionsInt("-micro_alpha_its", "Regularization schedule: iterations of the geometric decay", "HylcMicroSetRegularization", p.alphaIts, &p.alphaIts, NULL));
  PetscCall(HylcOptionsInt("-micro_alpha_retries", "Retries with alpha x 10 when the Newton matrix is indefinite", "HylcMicroSetRegularization", p.maxRetries, &p.maxRetries, NULL));
  PetscCall(PetscStrncpy(sched, HylcMicroAlphaSchedules[p.alphaSched], sizeof(sched)));
  PetscCall(HylcOptionsString("-micro_alpha_schedule",
                              "Regularization schedule of alpha^: adaptive (trust-region-like: down after good steps, up after poor or rejected ones; the default), paper (the paper's decay over alpha_its iterations) or hybrid (paper until ||M "
                              "g||_inf <= alpha_switch x its initial value, then adaptive)",
                              "HylcMicroSetRegularizationSchedule", sched, sched, sizeof(sched), &schedSet));
  PetscCall(HylcOptionsReal("-micro_alpha_factor", "Adaptive regularization: alpha^ / factor after a good step, x factor after a poor one", "HylcMicroSetRegularizationSchedule", p.alphaFact, &p.alphaFact, NULL));
  PetscCall(HylcOptionsReal("-micro_alpha_min", "Adaptive regularization: smallest alpha^", "HylcMicroSetRegularizationSchedule", p.alphaMin, &p.alphaMin, NULL));
  PetscCall(HylcOptionsReal("-micro_alpha_max", "Adaptive regularization: largest alpha^", "HylcMicroSetRegularizationSchedule", p.alphaMax, &p.alphaMax, NULL));
  PetscCall(HylcOptionsReal("-micro_alpha_switch", "Hybrid regularization: adaptive once ||M g||_inf <= alpha_switch x its value at the first iteration", "HylcMicroSetRegularizationSwitch", p.alphaSwitch, &p.alphaSwitch, NULL));
  PetscCall(PetscOptionsBool("-micro_alpha_fallback", "Adaptive and hybrid regularization: a solve that does not converge is repeated from the same start with the paper schedule", "HylcMicroSetRegularizationFallback", p.alphaFallback,
                             &p.alphaFallback, NULL));
  PetscCall(HylcOptionsReal("-micro_twist_scale", "Scale mu of the twist unknowns, 0 = 1/r", "HylcMicroSetTwistScale", p.twistScale, &p.twistScale, NULL));
  PetscCall(HylcOptionsReal("-micro_step_p0", "Step limit d_max = (p0 + p1 clamp(lambda_min(I),0,1)) r: p0", "HylcMicroSetStepLimit", p.stepP0, &p.stepP0, NULL));
  PetscCall(HylcOptionsReal("-micro_step_p1", "Step limit: p1", "HylcMicroSetStepLimit", p.stepP1, &p.stepP1, NULL));
  PetscCall(HylcOptionsReal("-micro_step_clearance", "Step limit also at most this fraction (< 1/2) of the smallest distance between yarn centerlines that may touch, so that no step crosses two yarns; 0 = off", "HylcMicroSetStepClearance",
                            p.stepClear, &p.stepClear, NULL));
  PetscCall(HylcOptionsReal("-micro_ls_factor", "Backtracking factor of the line search", "HylcMicroSetLineSearch", p.lsFactor, &p.lsFactor, NULL));
  PetscCall(HylcOptionsInt("-micro_ls_max", "Line-search trials per iteration", "HylcMicroSetLineSearch", p.lsMax, &p.lsMax, NULL));
  PetscCall(HylcOptionsInt("-micro_max_stalls", "Consecutive line searches without decrease before the solve stops, status stalled", "HylcMicroSetLineSearch", p.maxStalls, &p.maxStalls, NULL));
  PetscCall(HylcOptionsReal("-micro_rtol", "Convergence: projected gradient |z| < rtol |z0|", "HylcMicroSetTolerances", p.rtol, &p.rtol, NULL));
  PetscCall(HylcOptionsReal("-micro_atol", "Convergence also when |z| < atol k_s (k_s = Es pi r^2, a force): for tiles already at rest", "HylcMicroSetTolerances", p.atol, &p.atol, NULL));
  PetscCall(HylcOptionsReal("-micro_ctol", "Convergence: constraint residual |A y - dL| < ctol r", "HylcMicroSetTolerances", p.ctol, &p.ctol, NULL));
  PetscCall(HylcOptionsReal("-micro_max_time", "Wall-time cap per solve (s); status time_cap", "HylcMicroSetTolerances", p.maxTime, &p.maxTime, NULL));
  PetscCall(PetscOptionsBool("-micro_factor_indefinite", "Accept the factorization of an indefinite Newton matrix if the step descends with positive curvature; false: alpha x 10 at any negative eigenvalue", "HylcMicroSetIndefinite", p.indefinite,
                             &p.indefinite, NULL));
  PetscCall(PetscOptionsBool("-micro_saddle_test", "Second-order test of converged states: count the negative eigenvalues of the Hessian on the constraints' tangent space (implied by -micro_saddle_escapes > 0)", "HylcMicroSetSaddleEscape",
                             p.saddleTest, &p.saddleTest, NULL));
  PetscCall(
      HylcOptionsInt("-micro_saddle_escapes", "Second-order test: escapes from saddle points (negative curvature on the constraints' tangent space) along negative curvature, per solve", "HylcMicroSetSaddleEscape", p.saddleMax, &p.saddleMax, NULL));
  PetscCall(HylcOptionsReal("-micro_saddle_tol", "Second-order test: curvature below -saddle_tol x max|diag(M H M)| is negative", "HylcMicroSetSaddleEscape", p.saddleTol, &p.saddleTol, NULL));
  PetscCall(HylcOptionsEnum("-micro_uniaxial_gradient", "Uniaxial state (HylcMicroSolveUniaxial): dPsi/dz by the envelope theorem at each equilibrium, or by central differences of Psi (fd, 6 more solves per point)", "HylcMicroSetUniaxial",
                            HylcMicroUniaxialGradients, (PetscEnum)p.uniGrad, (PetscEnum *)&p.uniGrad, NULL));
  PetscCall(HylcOptionsReal("-micro_uniaxial_xtol", "Uniaxial state: converged when the predicted Newton step in the lateral strains is at most this (strain, dimensionless)", "HylcMicroSetUniaxial", p.uniXtol, &p.uniXtol, NULL));
  PetscCall(HylcOptionsInt("-micro_uniaxial_max_it", "Uniaxial state: Newton steps in the lateral strains", "HylcMicroSetUniaxial", p.uniMaxIt, &p.uniMaxIt, NULL));
  PetscCall(HylcOptionsReal("-micro_uniaxial_fd_step", "Uniaxial state: difference step of the lateral Hessian and of the fd gradient (strain, dimensionless)", "HylcMicroSetUniaxial", p.uniH, &p.uniH, NULL));
  PetscCall(HylcOptionsReal("-micro_uniaxial_max_step", "Uniaxial state: largest change of a lateral strain per Newton step (strain, dimensionless)", "HylcMicroSetUniaxial", p.uniMaxStep, &p.uniMaxStep, NULL));
  PetscCall(HylcOptionsReal("-micro_uniaxial_rtol", "Uniaxial state: -micro_rtol of its microscale solves (relative, dimensionless)", "HylcMicroSetUniaxialTolerances", p.uniRtol, &p.uniRtol, NULL));
  PetscCall(HylcOptionsReal("-micro_uniaxial_gtol", "Uniaxial state: converged after a line search without decrease if |lateral gradient| <= gtol |T| (dimensionless)", "HylcMicroSetUniaxialTolerances", p.uniGtol, &p.uniGtol, NULL));
  PetscCall(PetscOptionsName("-micro_view", "Print the solver at set-up", "HylcMicroView", &flg));
  PetscOptionsEnd();
  if (schedSet) { /* checked after PetscOptionsEnd(), which must run */
    PetscBool paper, adaptive, hybrid;
    PetscCall(PetscStrcmp(sched, "paper", &paper));
    PetscCall(PetscStrcmp(sched, "adaptive", &adaptive));
    PetscCall(PetscStrcmp(sched, "hybrid", &hybrid));
    PetscCheck(paper || adaptive || hybrid, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-%smicro_alpha_schedule %s: must be paper, adaptive or hybrid", HylcMicroPrefix_Private(M), sched);
    p.alphaSched = adaptive ? HYLC_MICRO_ALPHA_ADAPTIVE : hybrid ? HYLC_MICRO_ALPHA_HYBRID : HYLC_MICRO_ALPHA_PAPER;
  }
  PetscCall(HylcMicroSetRegularization(M, p.alphaStart, p.alphaEnd, p.alphaIts, p.maxRetries));
  PetscCall(HylcMicroSetRegularizationSchedule(M, (HylcMicroAlphaSchedule)p.alphaSched, p.alphaFact, p.alphaMin, p.alphaMax));
  PetscCall(HylcMicroSetRegularizationSwitch(M, p.alphaSwitch));
  PetscCall(HylcMicroSetRegularizationFallback(M, p.alphaFallback));
  PetscCall(HylcMicroSetTwistScale(M, p.twistScale));
  PetscCall(HylcMicroSetStepLimit(M, p.stepP0, p.stepP1));
  PetscCall(HylcMicroSetStepClearance(M, p.stepClear));
  PetscCall(HylcMicroSetLineSearch(M, p.lsFactor, p.lsMax, p.maxStalls));
  PetscCall(HylcMicroSetTolerances(M, p.rtol, p.atol, p.ctol, p.maxTime));
  PetscCall(HylcMicroSetIndefinite(M, p.indefinite));
  PetscCall(HylcMicroSetSaddleEscape(M, p.saddleTest, p.saddleMax, p.saddleTol));
  PetscCall(HylcMicroSetUniaxial(M, (HylcMicroUniaxialGradient)p.uniGrad, p.uniXtol, p.uniMaxIt, p.uniH, p.uniMaxStep));
  PetscCall(HylcMicroSetUniaxialTolerances(M, p.uniRtol, p.uniGtol));
  /* the sub-objects, created with their defaults first so that the options override them */
  PetscCall(HylcMicroGetPeriodic(M, &P));
  PetscCall(HylcPeriodicSetFromOptions(P));
  PetscCall(HylcMicroGetFactorPC(M, &inner));
  PetscCall(PCSetFromOptions(inner));
  PetscCall(HylcMetisSetFromOptions(PetscObjectComm((PetscObject)M))); /* the ordering of its factorizations */
  PetscCall(HylcMicroGetSNES(M, &snes));
  PetscCall(SNESSetFromOptions(snes));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroView - Prints the solver: its parameters, the sizes of the tile's system and, once set up, the
  factorization of the Newton matrix. Not collective.

  Input Parameters:
+ M      - the solver
- viewer - an ASCII viewer (NULL: stdout of PETSC_COMM_SELF)

  Options Database Key:
. -micro_view - view at set-up (HylcMicroSetUp(), or the first HylcMicroSolve())

  Level: beginner

.seealso: HylcMicroViewFromOptions(), HylcMicroResultView()
@*/
PetscErrorCode HylcMicroView(HylcMicro M, PetscViewer viewer)
{
  const HylcMicroParams *p = &M->par;
  PetscBool              ascii;
  char                   buf[512];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PETSC_COMM_SELF, &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (!ascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscObjectPrintClassNamePrefixType((PetscObject)M, viewer));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  /* C formatting: PETSc's printf appends '.' to integral %g values */
  if (p->alphaSched == HYLC_MICRO_ALPHA_ADAPTIVE)
    snprintf(buf, sizeof(buf), "regularization: adaptive, alpha^ from %g, / %g after good steps, x %g after poor ones, within [%g, %g], up to %d retries x 10; factorization of an indefinite K %s\n", (double)p->alphaStart, (double)p->alphaFact,
             (double)p->alphaFact, (double)p->alphaMin, (double)p->alphaMax, (int)p->maxRetries, "refused");
  else if (p->alphaSched == HYLC_MICRO_ALPHA_HYBRID)
    snprintf(buf, sizeof(buf),
             "regularization: hybrid, the paper schedule alpha^ %g -> %g over %d iterations (factorization of an indefinite K %s) until ||M g||_inf <= %g x its initial value, then adaptive (/ %g after good steps, x %g after poor ones, within [%g, "
             "%g], indefinite K refused); up to %d retries x 10\n",
             (double)p->alphaStart, (double)p->alphaEnd, (int)p->alphaIts, p->indefinite ? "accepted" : "refused", (double)p->alphaSwitch, (double)p->alphaFact, (double)p->alphaFact, (double)p->alphaMin, (double)p->alphaMax, (int)p->maxRetries);
  else
    snprintf(buf, sizeof(buf), "regularization: paper schedule, alpha^ %g -> %g over %d iterations, up to %d retries x 10; factorization of an indefinite K %s\n", (double)p->alphaStart, (double)p->alphaEnd, (int)p->alphaIts, (int)p->maxRetries,
             p->indefinite ? "accepted" : "refused");
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  if (p->alphaSched != HYLC_MICRO_ALPHA_PAPER)
    PetscCall(PetscViewerASCIIPrintf(viewer, "a solve that does not converge is %s\n", p->alphaFallback ? "repeated from the same start with the paper schedule" : "not repeated (-micro_alpha_fallback false)"));
  if (p->stepClear > 0)
    snprintf(buf, sizeof(buf), "twist scale mu: %s; step limit min((%g + %g clamp(lambda_min, 0, 1)) r, %g x clearance); line search x %g, %d trials, stop after %d stalls\n", p->twistScale > 0 ? "set" : "1/r", (double)p->stepP0, (double)p->stepP1,
             (double)p->stepClear, (double)p->lsFactor, (int)p->lsMax, (int)p->maxStalls);
  else
    snprintf(buf, sizeof(buf), "twist scale mu: %s; step limit (%g + %g clamp(lambda_min, 0, 1)) r; line search x %g, %d trials, stop after %d stalls\n", p->twistScale > 0 ? "set" : "1/r", (double)p->stepP0, (double)p->stepP1, (double)p->lsFactor,
             (int)p->lsMax, (int)p->maxStalls);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  snprintf(buf, sizeof(buf), "convergence: |z| < %g |z0| or |z| < %g k_s, |A y - dL| < %g r; wall-time cap %g s\n", (double)p->rtol, (double)p->atol, (double)p->ctol, (double)p->maxTime);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  if (p->saddleTest)
    snprintf(buf, sizeof(buf), "second-order test: curvature below -%g max|diag(M H M)| on the tangent space; up to %d saddle escapes per solve\n", (double)p->saddleTol, (int)p->saddleMax);
  else
    snprintf(buf, sizeof(buf), "second-order test: off (converged states may be saddle points)\n");
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  snprintf(buf, sizeof(buf), "uniaxial state: gradient %s, Newton in the lateral strains to a predicted step <= %g (or |lateral gradient| <= %g |T| when a line search fails), at most %d steps of <= %g, difference step %g, solves with rtol %g\n",
           HylcMicroUniaxialGradients[p->uniGrad], (double)p->uniXtol, (double)p->uniGtol, (int)p->uniMaxIt, (double)p->uniMaxStep, (double)p->uniH, (double)p->uniRtol);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  if (!M->pat)
    PetscCall(PetscViewerASCIIPrintf(viewer, "no pattern set\n"));
  else if (!M->setupcalled)
    PetscCall(PetscViewerASCIIPrintf(viewer, "pattern set, not set up\n"));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "unknowns: %" PetscInt_FMT " (%" PetscInt_FMT " vertices), constraint rows: %" PetscInt_FMT "\n", M->ny, M->ny / 4, M->m));
  if (M->kkt.inner) {
    MatSolverType type;
    PetscCall(PCFactorGetMatSolverType(M->kkt.inner, &type));
    PetscCall(PetscViewerASCIIPrintf(viewer, "factorization of K: PCCHOLESKY, solver type %s (-%smicro_factor_pc_factor_mat_solver_type)\n", type ? type : "(default)", HylcMicroPrefix_Private(M)));
    if (M->setupcalled) PetscCall(PCView(M->kkt.inner, viewer));
  }
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroViewFromOptions - Views the solver if the option name (e.g. "-micro_view", read after the
  solver's prefix) is set. Not collective.

  Input Parameters:
+ M    - the solver
. obj  - an optional object whose prefix is used instead
- name - the option name

  Level: intermediate

.seealso: HylcMicroView()
@*/
PetscErrorCode HylcMicroViewFromOptions(HylcMicro M, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)M, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
