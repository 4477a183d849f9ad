/* The reference state of Algorithm C1 (include/hylc/reference.h). */
#include <hylc/options.h>
#include <hylc/reference.h>

const char *const        HylcReferenceModes[] = {"auto", "compute", "none", "relax", "HylcReferenceMode", "HYLC_REFERENCE_", NULL};
static const char *const Kinds[]              = {"auto", "knit", "woven", "HylcReferenceKind", "", NULL};

/*@C
  HylcReferenceParamsDefault - The default parameters of the reference state (Algorithm C1): the
  stress-free relaxation to E < 1e-10 J in at most 30 rounds, the tension factors of the pattern's kind
  (auto), the in-plane minimum over sx, sy in [-0.4, 0.2] (Nelder-Mead, 1e-4, at most 80 solves), no options
  prefix.

  Not collective

  Output Parameter:
. p - the parameters

  Level: intermediate

.seealso: HylcReferenceParamsSetFromOptions(), HylcReferenceStateCompute()
@*/
PetscErrorCode HylcReferenceParamsDefault(HylcReferenceParams *p)
{
  PetscFunctionBegin;
  p->etol       = 1e-10;
  p->maxRounds  = 30;
  p->kind       = 0;
  p->stressFree = PETSC_TRUE;
  p->tension    = PETSC_TRUE;
  p->minimum    = PETSC_TRUE;
  p->lo         = -0.4;
  p->hi         = 0.2;
  p->xtol       = 1e-4;
  p->maxEvals   = 80;
  p->prefix[0]  = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcReferenceParamsSetFromOptions - Reads the options of the reference state after the given options
  prefix, which the parameters keep for the solvers HylcReferenceStateCompute() creates (-<prefix>micro_*).

  Collective

  Input Parameters:
+ comm   - the communicator the options are read on
- prefix - the options prefix (NULL: none), at most 255 characters

  Input/Output Parameter:
. p - the parameters: their values are the defaults of the options, replaced by those given

  Options Database Keys:
+ -reference_etol <1e-10> - stress-free relaxation: stop when the energy is below this (J)
. -reference_max_rounds <30> - stress-free relaxation: at most this many rounds (>= 1)
. -reference_kind <auto> - tension factors: auto, knit or woven
. -reference_stress_free <true> - reset the rest values to the geometry and relax
. -reference_tension <true> - apply the tension factors
. -reference_minimum <true> - find the in-plane minimum over the periods
. -reference_bounds <-0.4,0.2> - bounds lo,hi of sx and sy in the minimum (-1 < lo < 0 < hi)
. -reference_xtol <1e-4> - Nelder-Mead simplex size tolerance (strain, >= 0)
- -reference_max_evals <80> - at most this many solves in the minimum (>= 3: the first simplex)

  Level: intermediate

.seealso: HylcReferenceParamsDefault(), HylcReferenceStateCompute()
@*/
PetscErrorCode HylcReferenceParamsSetFromOptions(MPI_Comm comm, const char prefix[], HylcReferenceParams *p)
{
  PetscEnum kind = (PetscEnum)p->kind;
  PetscReal b[2] = {p->lo, p->hi};
  PetscInt  nb   = 2;
  PetscBool set;
  size_t    len;

  PetscFunctionBegin;
  PetscCall(PetscStrlen(prefix, &len));
  PetscCheck(len < sizeof(p->prefix), comm, PETSC_ERR_ARG_SIZ, "Options prefix %s is longer than %d characters", prefix, (int)sizeof(p->prefix) - 1);
  PetscCall(PetscStrncpy(p->prefix, prefix ? prefix : "", sizeof(p->prefix)));
  PetscOptionsBegin(comm, prefix, "Reference state (Algorithm C1)", "HylcReferenceState");
  PetscCall(HylcOptionsReal("-reference_etol", "Stress-free relaxation: stop when the energy is below this (J)", "HylcReferenceStateCompute", p->etol, &p->etol, NULL));
  PetscCall(HylcOptionsInt("-reference_max_rounds", "Stress-free relaxation: at most this many reset-and-relax rounds (>= 1)", "HylcReferenceStateCompute", p->maxRounds, &p->maxRounds, NULL));
  PetscCall(HylcOptionsEnum("-reference_kind", "Tension factors: knit (rest lengths x 0.9, curvatures x 0.8) or woven (curvatures x 0.9); auto: knit if every yarn runs along x", "HylcReferenceStateCompute", Kinds, kind, &kind, NULL));
  PetscCall(PetscOptionsBool("-reference_stress_free", "Reset the rest values to the geometry and relax (false keeps the pattern's rest data)", "HylcReferenceStateCompute", p->stressFree, &p->stressFree, NULL));
  PetscCall(PetscOptionsBool("-reference_tension", "Apply the tension factors", "HylcReferenceStateCompute", p->tension, &p->tension, NULL));
  PetscCall(PetscOptionsBool("-reference_minimum", "Find the in-plane minimum of the energy over the periods", "HylcReferenceStateCompute", p->minimum, &p->minimum, NULL));
  PetscCall(HylcOptionsRealArray("-reference_bounds", "Bounds lo,hi of sx and sy in the in-plane minimum", "HylcReferenceStateCompute", b, &nb, &set));
  PetscCall(HylcOptionsReal("-reference_xtol", "In-plane minimum: Nelder-Mead simplex size tolerance (strain, >= 0)", "HylcReferenceStateCompute", p->xtol, &p->xtol, NULL));
  PetscCall(HylcOptionsInt("-reference_max_evals", "In-plane minimum: at most this many solves (>= 3: the first simplex)", "HylcReferenceStateCompute", p->maxEvals, &p->maxEvals, NULL));
  PetscOptionsEnd();
  PetscCheck(!set || (nb == 2 && b[0] < 0 && b[1] > 0 && b[0] > -1), comm, PETSC_ERR_USER_INPUT, "-%sreference_bounds needs lo,hi with -1 < lo < 0 < hi", p->prefix);
  PetscCheck(p->maxRounds >= 1, comm, PETSC_ERR_USER_INPUT, "-%sreference_max_rounds %" PetscInt_FMT ": at least 1 round of the stress-free relaxation (-%sreference_stress_free false skips it)", p->prefix, p->maxRounds, p->prefix);
  PetscCheck(p->maxEvals >= 3, comm, PETSC_ERR_USER_INPUT, "-%sreference_max_evals %" PetscInt_FMT ": at least 3 solves (the first simplex of the in-plane minimum; -%sreference_minimum false skips it)", p->prefix, p->maxEvals, p->prefix);
  PetscCheck(p->xtol >= 0, comm, PETSC_ERR_USER_INPUT, "-%sreference_xtol %.6g: a simplex size, >= 0 (0: stop at -%sreference_max_evals only)", p->prefix, (double)p->xtol, p->prefix);
  p->lo   = b[0];
  p->hi   = b[1];
  p->kind = (PetscInt)kind;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* E of the equilibrium at in-plane strain (sx, sy); +inf when the solve does not converge */
static PetscErrorCode EnergyAt(HylcMicro M, PetscReal sx, PetscReal sy, PetscReal *E, PetscInt *nsolves)
{
  const PetscReal z[6] = {sx, 0, sy, 0, 0, 0};
  HylcMicroResult r;

  PetscFunctionBegin;
  PetscCall(HylcMicroSolve(M, z, &r));
  (*nsolves)++;
  *E = r.status == HYLC_MICRO_CONVERGED ? r.energy : PETSC_INFINITY;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Nelder-Mead over (sx, sy) in the box [lo, hi]^2 (points outside are +inf) */
static PetscErrorCode InPlaneMinimum(HylcMicro M, const HylcReferenceParams *par, PetscViewer v, PetscReal best[2], PetscReal *Ebest)
{
  PetscReal x[3][2] = {{0, 0}, {0.02, 0}, {0, 0.02}}, f[3];
  PetscInt  n       = 0;

  PetscFunctionBegin;
  for (int i = 0; i < 3; i++) PetscCall(EnergyAt(M, x[i][0], x[i][1], &f[i], &n));
  while (n < par->maxEvals) {
    /* order: f[0] <= f[1] <= f[2] */
    for (int i = 0; i < 3; i++)
      for (int j = i + 1; j < 3; j++)
        if (f[j] < f[i]) {
          PetscReal t = f[i];
          f[i]        = f[j];
          f[j]        = t;
          for (int d = 0; d < 2; d++) {
            t       = x[i][d];
            x[i][d] = x[j][d];
            x[j][d] = t;
          }
        }
    const PetscReal size = PetscMax(PetscAbsReal(x[1][0] - x[0][0]) + PetscAbsReal(x[1][1] - x[0][1]), PetscAbsReal(x[2][0] - x[0][0]) + PetscAbsReal(x[2][1] - x[0][1]));
    if (size < par->xtol) break;
    PetscReal c[2], xr[2], fr;
    for (int d = 0; d < 2; d++) c[d] = 0.5 * (x[0][d] + x[1][d]);
    for (int d = 0; d < 2; d++) xr[d] = c[d] + (c[d] - x[2][d]);
    if (xr[0] < par->lo || xr[0] > par->hi || xr[1] < par->lo || xr[1] > par->hi)
      fr = PETSC_INFINITY;
    else
      PetscCall(EnergyAt(M, xr[0], xr[1], &fr, &n));
    if (fr < f[0]) { /* expand */
      PetscReal xe[2], fe;
      for (int d = 0; d < 2; d++) xe[d] = c[d] + 2 * (c[d] - x[2][d]);
      if (xe[0] < par->lo || xe[0] > par->hi || xe[1] < par->lo || xe[1] > par->hi)
        fe = PETSC_INFINITY;
      else
        PetscCall(EnergyAt(M, xe[0], xe[1], &fe, &n));
      if (fe < fr) {
        x[2][0] = xe[0], x[2][1] = xe[1], f[2] = fe;
      } else {
        x[2][0] = xr[0], x[2][1] = xr[1], f[2] = fr;
      }
    } else if (fr < f[1]) {
      x[2][0] = xr[0], x[2][1] = xr[1], f[2] = fr;
    } else { /* contract toward the worst point, else shrink toward the best */
      PetscReal xc[2], fc;
      for (int d = 0; d < 2; d++) xc[d] = c[d] + 0.5 * (x[2][d] - c[d]);
      PetscCall(EnergyAt(M, xc[0], xc[1], &fc, &n));
      if (fc < f[2]) {
        x[2][0] = xc[0], x[2][1] = xc[1], f[2] = fc;
      } else
        for (int i = 1; i < 3; i++) {
          for (int d = 0; d < 2; d++) x[i][d] = x[0][d] + 0.5 * (x[i][d] - x[0][d]);
          PetscCall(EnergyAt(M, x[i][0], x[i][1], &f[i], &n));
        }
    }
  }
  PetscInt ib = 0;
  for (int i = 1; i < 3; i++)
    if (f[i] < f[ib]) ib = i;
  best[0] = x[ib][0];
  best[1] = x[ib][1];
  *Ebest  = f[ib];
  if (v) PetscCall(PetscViewerASCIIPrintf(v, "[reference] in-plane minimum at sx = %.6f, sy = %.6f (E = %.6e J, %d solves)\n", (double)best[0], (double)best[1], (double)*Ebest, (int)n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the equilibrium of pattern p at in-plane strain (sx, sy) as a new pattern */
static PetscErrorCode Relaxed(HylcPattern p, const HylcYarnModel *model, const HylcReferenceParams *par, PetscReal sx, PetscReal sy, HylcPattern *out, PetscReal *E, HylcMicroStatus *status)
{
  HylcMicro       M;
  HylcMicroResult r;
  HylcPeriodic    P;
  const PetscReal z[6] = {sx, 0, sy, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  if (par->prefix[0]) PetscCall(HylcMicroSetOptionsPrefix(M, par->prefix));
  PetscCall(HylcMicroSetPattern(M, p, model));
  PetscCall(HylcMicroSetFromOptions(M));
  PetscCall(HylcMicroSolve(M, z, &r));
  PetscCall(HylcMicroGetPeriodic(M, &P));
  PetscCall(HylcPeriodicCreateStatePattern(P, out));
  *E      = r.energy;
  *status = r.status;
  PetscCall(HylcMicroDestroy(&M));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcReferenceStateCompute - Algorithm C1 on a copy of the pattern; the result is a new pattern.
@*/
PetscErrorCode HylcReferenceStateCompute(HylcPattern in, const HylcYarnModel *model, const HylcReferenceParams *par, PetscViewer v, HylcPattern *out)
{
  HylcPattern     p, q;
  PetscReal       E = PETSC_INFINITY;
  HylcMicroStatus st;
  PetscInt        round, nloops;
  PetscBool       knit = PETSC_TRUE;

  PetscFunctionBegin;
  PetscCall(HylcPatternDuplicate(in, &p));
  /* 1. stress free: rest values := current values, relax, repeat */
  PetscReal Eprev = PETSC_INFINITY;
  PetscBool stuck = PETSC_FALSE;
  for (round = 0; par->stressFree && round < par->maxRounds; round++) {
    PetscCall(HylcPatternSetRestFromGeometry(p));
    PetscCall(Relaxed(p, model, par, 0, 0, &q, &E, &st));
    PetscCall(HylcPatternDestroy(&p));
    p = q;
    if (v) PetscCall(PetscViewerASCIIPrintf(v, "[reference] stress-free round %d: E = %.6e J (%s)\n", (int)round, (double)E, HylcMicroStatuses[st]));
    if (E < par->etol) break;
    /* contact that cannot be resolved at these periods: the energy stops falling */
    if (E > 0.98 * Eprev) {
      stuck = PETSC_TRUE;
      break;
    }
    Eprev = E;
  }
  if (par->stressFree && E >= par->etol && v)
    PetscCall(PetscViewerASCIIPrintf(v, "[reference] warning: no stress-free state at these periods (E = %.3e J %s); the remaining contact is relaxed by the in-plane minimum\n", (double)E, stuck ? "stopped falling" : "after the last round"));
  if (par->stressFree)
    PetscCall(HylcPatternSetRestFromGeometry(p));
  else if (v)
    PetscCall(PetscViewerASCIIPrintf(v, "[reference] the pattern's rest data kept (no stress-free relaxation)\n"));
  /* 2. tension */
  PetscCall(HylcPatternGetNumLoops(p, &nloops));
  for (PetscInt l = 0; l < nloops; l++) {
    PetscInt w[2];
    PetscCall(HylcPatternGetLoop(p, l, NULL, NULL, w));
    if (w[1] != 0) knit = PETSC_FALSE;
  }
  if (par->kind) knit = (PetscBool)(par->kind == 1);
  if (par->tension) {
    PetscCall(HylcPatternScaleRest(p, knit ? 0.9 : 1.0, knit ? 0.8 : 0.9));
    if (v) PetscCall(PetscViewerASCIIPrintf(v, "[reference] tension for a %s: rest lengths x %g, rest curvatures x %g\n", knit ? "knit" : "woven", knit ? 0.9 : 1.0, knit ? 0.8 : 0.9));
  }
  /* 3. the in-plane minimum over the periods, and the equilibrium there as the new reference */
  PetscReal best[2] = {0, 0}, Eb;
  if (par->minimum) {
    HylcMicro M;
    PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
    if (par->prefix[0]) PetscCall(HylcMicroSetOptionsPrefix(M, par->prefix));
    PetscCall(HylcMicroSetPattern(M, p, model));
    PetscCall(HylcMicroSetFromOptions(M));
    PetscCall(InPlaneMinimum(M, par, v, best, &Eb));
    PetscCall(HylcMicroDestroy(&M));
  }
  PetscCall(Relaxed(p, model, par, best[0], best[1], &q, &E, &st));
  PetscCheck(st == HYLC_MICRO_CONVERGED, PetscObjectComm((PetscObject)in), PETSC_ERR_NOT_CONVERGED, "The equilibrium at the in-plane minimum did not converge (%s)", HylcMicroStatuses[st]);
  PetscCall(HylcPatternDestroy(&p));
  /* 4. recentre */
  PetscCall(HylcPatternRecentre(q));
  PetscCall(HylcPatternSetState(q, HYLC_PATTERN_STATE_REFERENCE));
  if (v) PetscCall(PetscViewerASCIIPrintf(v, "[reference] reference state: periods scaled by (%.6f, %.6f), E = %.6e J\n", (double)(1 + best[0]), (double)(1 + best[1]), (double)E));
  *out = q;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcReferenceStateNeeded - Whether a job's reference mode computes a reference state for this pattern:
  compute and relax always, none never, auto unless the pattern is a file that records being a reference state
  (hylc's own, computed for a yarn: used as given; auto is Algorithm C1 for a generated pattern or a file that is
  not a reference state, relax for a file that records nothing, as the paper's stored tiles;
  HylcReferenceStateForMode()). Not collective.

  Input Parameters:
+ in   - the pattern, set up
- mode - the mode

  Output Parameter:
. needed - PETSC_TRUE if HylcReferenceStateForMode() computes one

  Level: intermediate

.seealso: HylcReferenceStateForMode(), HylcPatternGetState()
@*/
PetscErrorCode HylcReferenceStateNeeded(HylcPattern in, HylcReferenceMode mode, PetscBool *needed)
{
  HylcPatternState state;
  HylcPatternType  type;
  PetscBool        isfile;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetState(in, &state));
  PetscCall(HylcPatternGetType(in, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  *needed = (PetscBool)(mode != HYLC_REFERENCE_NONE && !(mode == HYLC_REFERENCE_AUTO && isfile && state == HYLC_PATTERN_STATE_REFERENCE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcReferenceStateForMode - The reference state a job's -sampler_reference or -calibrate_reference mode
  asks for: compute (Algorithm C1), relax (the pattern's rest data kept, no tension: only the in-plane minimum
  over the periods and the recentring, so that the stored tile under the configured yarn becomes a minimum of
  the model: at rest at z = 0, dPsi/dsx = dPsi/dsy = 0), auto (relax for a pattern file that records nothing,
  as the paper's stored tiles; a file that records being a reference state, hylc's own, as given; C1 for a
  generated pattern and any other file), or none (the pattern as given: the paper's procedure, which samples its stored tiles as they
  are, not at rest under the configured yarn). *out is NULL when the mode asks for none.

  Collective

  Input Parameters:
+ in    - the pattern, set up
. mode  - the mode
. model - the yarn model
. par   - the parameters of C1 (relax overrides stress-free, tension and minimum)
- v     - viewer for progress lines (may be NULL)

  Output Parameter:
. out - the reference state, a new pattern, or NULL

  Level: intermediate

.seealso: HylcReferenceStateCompute()
@*/
PetscErrorCode HylcReferenceStateForMode(HylcPattern in, HylcReferenceMode mode, const HylcYarnModel *model, const HylcReferenceParams *par, PetscViewer v, HylcPattern *out)
{
  HylcPatternType     type;
  PetscBool           isfile, needed;
  HylcReferenceParams p = *par;

  PetscFunctionBegin;
  *out = NULL;
  PetscCall(HylcPatternGetType(in, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  PetscCall(HylcReferenceStateNeeded(in, mode, &needed));
  {
    HylcPatternState state;
    PetscCall(HylcPatternGetState(in, &state));
    if (mode == HYLC_REFERENCE_AUTO && isfile && state == HYLC_PATTERN_STATE_UNRECORDED) {
      if (v)
        PetscCall(PetscViewerASCIIPrintf(
            v,
            "[reference] the pattern file is a stored reference state (it records nothing, as the paper's files): relaxed to the in-plane minimum under the configured yarn (auto; -sampler_reference none keeps it as given, the paper's procedure)\n"));
      mode = HYLC_REFERENCE_RELAX;
    } else if (mode == HYLC_REFERENCE_AUTO && isfile && state == HYLC_PATTERN_STATE_REFERENCE) {
      if (v) PetscCall(PetscViewerASCIIPrintf(v, "[reference] the pattern file records a reference state: used as given (auto; -sampler_reference relax makes it a minimum under the configured yarn)\n"));
    } else if (v && mode == HYLC_REFERENCE_AUTO && isfile)
      PetscCall(PetscViewerASCIIPrintf(v, "[reference] the pattern file is not a reference state (%s): computing it (Algorithm C1)\n", HylcPatternStates[state]));
    else if (v && mode == HYLC_REFERENCE_AUTO)
      PetscCall(PetscViewerASCIIPrintf(v, "[reference] a generated pattern: computing its reference state (Algorithm C1)\n"));
  }
  if (!needed) PetscFunctionReturn(PETSC_SUCCESS);
  if (mode == HYLC_REFERENCE_RELAX) {
    p.stressFree = PETSC_FALSE;
    p.tension    = PETSC_FALSE;
    p.minimum    = PETSC_TRUE;
    if (v) PetscCall(PetscViewerASCIIPrintf(v, "[reference] relax: the in-plane minimum of the pattern as given, under the configured yarn\n"));
  }
  PetscCall(HylcReferenceStateCompute(in, model, &p, v, out));
  PetscFunctionReturn(PETSC_SUCCESS);
}
