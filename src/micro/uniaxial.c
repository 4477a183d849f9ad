/* HylcMicro: the strain gradient of the equilibrium energy (envelope theorem) and the homogeneous uniaxial
   tension state of the tile (include/hylc/micro.h, docs/fabric-uniaxial.md). */
#include <hylc/private/microimpl.h>
#include <hylc/private/newton2.h>
#include <petsctime.h>

const char *const HylcUniaxialDirections[] = {"x", "y", "HylcUniaxialDirection", "HYLC_UNIAXIAL_", NULL};

/* dPsi/dz_j (the components comps) of the energy terms of mask at the state of the last solve, with the
   multipliers of those terms' gradient: linear in the terms, so the terms' results add up to all terms' */
static PetscErrorCode StrainGradientOfTerms(HylcMicro M, int mask, int comps, PetscReal dpsi[6])
{
  PetscInt         m;
  const PetscReal *A, *AAtinv;
  PetscReal        parts[4], dEdz[6], *dcdz, *Ag, area;

  PetscFunctionBegin;
  PetscCall(HylcPeriodicGetConstraints(M->P, &m, &A, NULL, &AAtinv));
  PetscCall(PetscMalloc2(6 * m, &dcdz, 2 * m, &Ag));
  PetscCall(HylcPeriodicEvaluateStrainDerivative(M->P, mask, comps, parts, M->gw, dEdz, dcdz));
  for (PetscInt i = 0; i < m; i++) {
    PetscReal t = 0;
    for (PetscInt k = 0; k < M->ny; k++) t += A[i * M->ny + k] * M->gw[k];
    Ag[i] = t;
  }
  for (PetscInt i = 0; i < m; i++) { /* lambda = -(A A^T)^-1 A g */
    PetscReal t = 0;
    for (PetscInt k = 0; k < m; k++) t -= AAtinv[i * m + k] * Ag[k];
    Ag[m + i] = t;
  }
  PetscCall(HylcPeriodicGetArea(M->P, &area));
  for (int j = 0; j < 6; j++) {
    PetscReal t = dEdz[j];
    if (!(comps & (1 << j))) {
      dpsi[j] = (PetscReal)NAN;
      continue;
    }
    for (PetscInt i = 0; i < m; i++) t += Ag[m + i] * dcdz[6 * i + j];
    dpsi[j] = t / area;
  }
  PetscCall(PetscFree2(dcdz, Ag));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the state of the last solve set in the tile */
static PetscErrorCode StrainGradientSetState(HylcMicro M, int comps, const char caller[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscCheck(M->X && M->P && M->setupcalled, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "%s: no solve yet", caller);
  PetscCheck((comps & HYLC_STRAIN_ALL_BITS) && !(comps & ~(HYLC_STRAIN_ALL_BITS | HYLC_STRAIN_NO_POISSON)), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: component mask %d: bits 0..5 (at least one) and HYLC_STRAIN_NO_POISSON only", caller, comps);
  PetscCall(HylcMicroToY_Private(M, M->X, M->yw));
  PetscCall(HylcPeriodicSetState(M->P, M->yw));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetStrainGradient - The stress of the last solve's equilibrium: the gradient of the equilibrium
  energy density Psi with respect to the strain z = (sx, sa, sy, II00, II01, II11), by the envelope theorem:
  at an equilibrium of E(y; z) under the constraints c(y; z) = A y - dL = 0,
  dPsi/dz_j = (dE/dz_j + lambda . dc/dz_j) / area with the partial derivatives at fixed y
  (HylcPeriodicEvaluateStrainDerivative()) and the multipliers lambda = -(A A^T)^-1 A g_y of the state's
  gradient. No solve. Not collective.

  Input Parameters:
+ M     - the solver, after a HylcMicroSolve()
- comps - the components wanted: bit j for z_j (HYLC_STRAIN_ALL_BITS for all six, HYLC_STRAIN_PLANE_BITS for
          sx, sa, sy), or'ed with HYLC_STRAIN_NO_POISSON to leave NaN a curvature component that would need a
          Poisson midsurface (HylcPeriodicEvaluateStrainDerivative())

  Output Parameter:
. dpsi - dPsi/dz_j (N/m for sx, sa, sy; N for the curvatures, i.e. J/m^2 per 1/m); NaN where not asked for

  Notes:
  The result is exact at an exact equilibrium; at a converged one its error is of the order of the
  remaining gradient (the solve's tolerance, -micro_rtol). It is meaningless at a state that did not
  converge. The in-plane components at II = 0 are exact; the others use central differences of the periodic
  map (HylcPeriodicEvaluateStrainDerivative()) on its closed form, except a curvature across the axis of a
  bent strain (II11 at II00 != 0) and the curvatures of a doubly curved strain, which need Poisson midsurfaces.
  tests/unit/test_uniaxial.c checks every component against central differences of Psi.

  Level: intermediate

.seealso: HylcMicroSolve(), HylcMicroSolveUniaxial(), HylcPeriodicEvaluateStrainDerivative()
@*/
PetscErrorCode HylcMicroGetStrainGradient(HylcMicro M, int comps, PetscReal dpsi[6])
{
  PetscFunctionBegin;
  PetscCall(StrainGradientSetState(M, comps, "HylcMicroGetStrainGradient"));
  PetscCall(StrainGradientOfTerms(M, HYLC_TERM_ALL, comps, dpsi));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroGetStrainGradientParts - HylcMicroGetStrainGradient() split by energy term: the gradient of
  each term (stretch, bend, twist, contact) at the state of the last solve, with the constraint multipliers
  of that term's own gradient. The terms add up to the gradient. Each term is linear in its modulus
  (E_s, E, G, k_c), so dparts[6 k + j] is p_k d/dp_k of dPsi/dz_j at the fixed state of the tile: the
  change of the gradient with a parameter without the change of the equilibrium (hylc-calibrate's
  -calibrate_stationary uses it as a Gauss-Newton Jacobian). No solve. Not collective.

  Input Parameters:
+ M     - the solver, after a HylcMicroSolve()
- comps - the components wanted (as HylcMicroGetStrainGradient())

  Output Parameters:
+ dpsi   - dPsi/dz_j (NaN where not asked for)
- dparts - 24 values, dparts[6 k + j]: term k (0 stretch, 1 bend, 2 twist, 3 contact), strain component j

  Level: advanced

.seealso: HylcMicroGetStrainGradient()
@*/
PetscErrorCode HylcMicroGetStrainGradientParts(HylcMicro M, int comps, PetscReal dpsi[6], PetscReal dparts[24])
{
  static const int masks[4] = {HYLC_TERM_STRETCH, HYLC_TERM_BEND, HYLC_TERM_TWIST, HYLC_TERM_CONTACT};

  PetscFunctionBegin;
  PetscCall(StrainGradientSetState(M, comps, "HylcMicroGetStrainGradientParts"));
  for (int j = 0; j < 6; j++) dpsi[j] = 0;
  for (int k = 0; k < 4; k++) {
    PetscCall(StrainGradientOfTerms(M, masks[k], comps, dparts + 6 * k));
    for (int j = 0; j < 6; j++) dpsi[j] += dparts[6 * k + j];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSolveUniaxial - The homogeneous uniaxial tension state of the tile: the stretch s prescribed along
  the material x axis (sx = s) or y axis (sy = s), bending zero, and Psi minimized over the two free strains
  (sa and the other stretch), so that the lateral stresses vanish (free contraction). Returns T = dPsi/ds,
  the force per unit width of a strip in its homogeneous central zone (N/m), and the lateral strains. Not
  collective.

  Input Parameters:
+ M    - the solver, with a pattern
. dir  - HYLC_UNIAXIAL_X or HYLC_UNIAXIAL_Y
. s    - the stretch, in [0, 1)
. lat0 - the starting lateral strains (sa, sy) for x, (sa, sx) for y (NULL: 0, 0)
- u0   - the local fluctuation of an earlier equilibrium to continue from (HylcMicroGetFluctuation(), or the
         u of an earlier call; NULL: cold)

  Output Parameters:
+ res - the result (res->converged says whether the minimization converged)
- u   - the local fluctuation of the state returned (the tile's size; may be NULL), to continue from

  Notes:
  HylcMicroSolvePath() on the uniaxial path along x or y. Each Psi is a microscale equilibrium (HylcMicroSolve(),
  continued from the last accepted point, cold again if that does not converge). The minimization is a Newton method in the two lateral strains p: the
  gradient by HylcMicroGetStrainGradient() (or central differences, HylcMicroSetUniaxial()), the Hessian by
  forward differences of the lateral gradient (two more solves per step, continued from the point), made
  positive definite, steps of at most maxStep per strain and a backtracking line search on Psi (Armijo,
  1e-4). It stops when the Newton step predicted at the current point is at most xtol in each strain, or
  when a line search finds no decrease while the lateral gradient is at most gtol |T| (Psi at its noise
  level; res->gradientStop). A point whose solve does not converge is rejected by the line search; if the
  first one fails, or every trial of a line search at a larger gradient, the result is returned with
  res->converged false. The solves use the relative tolerance of HylcMicroSetUniaxialTolerances() (1e-8)
  instead of -micro_rtol. Options: HylcMicroSetUniaxial(), HylcMicroSetUniaxialTolerances().

  Level: intermediate

.seealso: HylcMicroSetUniaxial(), HylcMicroGetStrainGradient(), HylcMicroUniaxialResultView()
@*/
PetscErrorCode HylcMicroSolveUniaxial(HylcMicro M, HylcUniaxialDirection dir, PetscReal s, const PetscReal lat0[2], const PetscReal u0[], HylcMicroUniaxialResult *res, PetscReal u[])
{
  hylcmat_path        path = {HYLCMAT_PATH_UNIAXIAL, dir == HYLC_UNIAXIAL_Y ? 90 : 0};
  HylcMicroPathResult r;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidPointer(res, 6);
  PetscCheck(dir == HYLC_UNIAXIAL_X || dir == HYLC_UNIAXIAL_Y, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Uniaxial direction %d: must be x (0) or y (1)", (int)dir);
  PetscCheck(s >= 0 && s < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Uniaxial stretch %g is outside [0, 1): a uniaxial state is a tension test (a compressed strip buckles) within the sampled stretches", (double)s);
  PetscCheck(!lat0 || (!PetscIsInfOrNanReal(lat0[0]) && !PetscIsInfOrNanReal(lat0[1]) && PetscAbsReal(lat0[0]) < 0.95 && lat0[1] > -0.95 && lat0[1] < 1e3), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "Uniaxial starting lateral strains (%g, %g): need |sa| < 0.95 and a stretch in (-0.95, 1e3)", lat0 ? (double)lat0[0] : 0.0, lat0 ? (double)lat0[1] : 0.0);
  PetscCall(HylcMicroSolvePath(M, &path, s, lat0, u0, &r, u));
  PetscCall(PetscMemzero(res, sizeof(*res)));
  res->dir = dir;
  res->s   = s;
  for (int k = 0; k < 6; k++) res->z[k] = r.z[k];
  for (int j = 0; j < 3; j++) res->grad[j] = r.grad[j];
  res->lateral[0]      = r.p[0];
  res->lateral[1]      = r.p[1];
  res->psi             = r.psi;
  res->T               = r.force;
  res->step            = r.step;
  res->converged       = r.converged;
  res->gradientStop    = r.gradientStop;
  res->iterations      = r.iterations;
  res->solves          = r.solves;
  res->microIterations = r.microIterations;
  res->failedSolves    = r.failedSolves;
  res->time            = r.time;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroUniaxialResultView - Prints a uniaxial result in one line: direction, stretch, T, the lateral
  strains, Psi, the lateral gradient, convergence and counts. Not collective.

  Input Parameters:
+ r      - the result of HylcMicroSolveUniaxial()
- viewer - an ASCII viewer

  Level: intermediate

.seealso: HylcMicroSolveUniaxial()
@*/
PetscErrorCode HylcMicroUniaxialResultView(const HylcMicroUniaxialResult *r, PetscViewer viewer)
{
  char            buf[512];
  const PetscReal gl[2] = {r->grad[1], r->grad[r->dir == HYLC_UNIAXIAL_X ? 2 : 0]};

  PetscFunctionBegin;
  /* C formatting: PETSc's printf appends '.' to integral %g values */
  snprintf(buf, sizeof(buf), "uniaxial %s: s %.6g T %.9e N/m sa %.6e %s %.6e psi %.10e lateral gradient %.2e %.2e N/m step %.1e %s; %d Newton steps, %d solves (%d not converged), %d micro iterations, %.2f s\n", HylcUniaxialDirections[r->dir],
           (double)r->s, (double)r->T, (double)r->lateral[0], r->dir == HYLC_UNIAXIAL_X ? "sy" : "sx", (double)r->lateral[1], (double)r->psi, (double)gl[0], (double)gl[1], (double)r->step,
           r->converged ? (r->gradientStop ? "converged (gradient test)" : "converged") : "NOT CONVERGED", (int)r->iterations, (int)r->solves, (int)r->failedSolves, (int)r->microIterations, r->time);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}
