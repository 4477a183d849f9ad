/* The dynamic mode of HylcCloth (-cloth_dynamic, docs/fabric.md): the cloth released under gravity and
   brought to rest by implicit time stepping, for the states that no static path reaches (a drape whose
   load path buckles, a knit strip that curls).

   Backward Euler with mass-proportional damping c, the step from (x_n, v_n) of length dt minimizing the
   incremental potential
       Phi(x) = E(x) + sum_v m_v (|x_v - x_n - dt v_n|^2 / (2 dt^2) + c |x_v - x_n|^2 / (2 dt)),
   whose stationarity is m (x - x_n - dt v_n) / dt^2 + c m (x - x_n) / dt + grad E = 0: the backward Euler
   step of m a = -grad E - c m v with v_{n+1} = (x_{n+1} - x_n) / dt. E is the static energy (elements,
   gravity, the supports' barrier: energy.c adds the inertia terms while c->dynamic is set), so every step
   is solved by the static solver (solve.c: Newton on the PSD-projected or exact Hessian with the energy
   line search that keeps the cloth clear of the supports) and sees a Hessian with m (1/dt^2 + c/dt) added
   to its diagonal: each step is a well-posed minimization even where the static one is not.

   Why not PETSc's TS: a TS step solves its residual with an SNES that has no objective, so it cannot
   refuse a step through a support or into an inverted triangle by the energy, and the supports'
   frictionless contact is a barrier that only the line search on Phi keeps finite. The incremental
   potential is the form of backward Euler that keeps both.

   A step's Newton solve has the static tolerances (-cloth_rtol, -cloth_max_it). Measured on the paper's
   stock1 drape at h = 1 cm (1,590 triangles): with them the cloth came to rest at t = 1.03 s in 237
   steps (4.9 min); with a looser 1e-6 per step and at most 12 iterations it still moved at 1.2 m/s at
   t = 1.22 s after 25 min (the curled edges chatter), so the steps are solved as tightly as the static
   problem. The step length adapts: halved when a step's Newton solve fails, grown by 1.5 (up to
   -cloth_dt_max) after a step that took at most 6 iterations. When the largest vertex speed falls below
   -cloth_rest_tol, the static solver polishes the state to an equilibrium (no inertia, at most 12
   iterations). If it does not converge (a nearly neutral mode creeps: a fold that is still forming), the
   state before the polish is at rest when its static residual (the gradient norm of E over the force
   scale, the norm with the clamps' reactions) is at most -cloth_rest_rtol; otherwise the dynamics goes on
   for at least 5 steps before the next polish. With -cloth_vtk_dt > 0 the state is written as a VTK frame
   (<output>_dynamics_NNNN.vtk, frame NNNN at t >= NNNN * vtk_dt, the step that first passes it) for
   ParaView's animation. */
#include <hylc/private/clothimpl.h>

const char *const HylcClothDynamicsTypes[] = {"off", "auto", "on", "HylcClothDynamics", "HYLC_CLOTH_DYNAMICS_", NULL};

PetscErrorCode HylcClothDynamicReset_Private(HylcCloth c)
{
  PetscFunctionBegin;
  PetscCall(VecDestroy(&c->xn));
  PetscCall(VecDestroy(&c->vn));
  c->dynamic = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the largest vertex speed |v| (m/s) over the owned vertices, and the kinetic energy (J) */
static PetscErrorCode Speed(HylcCloth c, Vec V, PetscReal *vmax, PetscReal *ekin)
{
  const PetscScalar *v;
  PetscReal          r[2] = {0, 0};

  PetscFunctionBegin;
  PetscCall(VecGetArrayRead(V, &v));
  for (PetscInt i = 0; i < c->vend - c->vstart; i++) {
    PetscReal s2 = v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2];
    r[0]         = PetscMax(r[0], s2);
    r[1] += 0.5 * c->rhoA * c->vmass[c->iperm[c->vstart + i]] * s2;
  }
  PetscCall(VecRestoreArrayRead(V, &v));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &r[0], 1, MPIU_REAL, MPIU_MAX, CLOTH_COMM_PRIVATE(c)));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &r[1], 1, MPIU_REAL, MPIU_SUM, CLOTH_COMM_PRIVATE(c)));
  *vmax = PetscSqrtReal(r[0]);
  *ekin = r[1];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  From the state c->x at rest, at the current load and gravity scale: backward Euler steps until the
  cloth is at rest and the static solver confirms an equilibrium there (rest = PETSC_TRUE), or until
  -cloth_tmax of simulated time or a time step below 1/4096 of -cloth_dt (rest = PETSC_FALSE, c->x the
  last state). Collective.
*/
PetscErrorCode HylcClothSettle_Private(HylcCloth c, PetscBool *rest)
{
  MPI_Comm  comm = CLOTH_COMM_PRIVATE(c);
  PetscReal dt = c->dt, dtmin = c->dt / 4096, vmax = PETSC_MAX_REAL, ekin = 0;
  PetscInt  its0 = c->newtonIts, wait = 0, frame = 0; /* wait: steps before the next polish after a failed one; frame: the last VTK frame */
  Vec       xsave;

  PetscFunctionBegin;
  *rest = PETSC_FALSE;
  if (!c->xn) PetscCall(VecDuplicate(c->x, &c->xn));
  if (!c->vn) PetscCall(VecDuplicate(c->x, &c->vn));
  PetscCall(VecDuplicate(c->x, &xsave));
  PetscCall(VecZeroEntries(c->vn));
  PetscCall(HylcClothApplyClamps_Private(c, c->x));
  c->time         = 0;
  c->restResidual = -1;
  while (c->time < c->tmax) {
    PetscBool ok;
    PetscReal E;
    PetscCall(PetscLogEventBegin(HYLC_ClothStep, c, 0, 0, 0));
    PetscCall(VecCopy(c->x, c->xn));
    c->dynamic = PETSC_TRUE;
    c->dtcur   = dt;
    /* the start of Newton: x_n + dt v_n, or x_n where that is infeasible */
    PetscCall(VecAXPY(c->x, dt, c->vn));
    PetscCall(HylcClothApplyClamps_Private(c, c->x));
    {
      PetscBool clear = PETSC_TRUE;
      if (c->nsupport) PetscCall(HylcClothFeasible_Private(c, c->xn, c->x, &clear));
      if (clear) PetscCall(HylcClothEnergy_Private(c, c->x, &E, NULL));
      if (!clear || HylcClothInfeasible(E)) PetscCall(VecCopy(c->xn, c->x));
    }
    PetscCall(HylcClothSolveStatic_Private(c, &ok));
    c->dynamic = PETSC_FALSE;
    if (!ok) {
      PetscCall(VecCopy(c->xn, c->x));
      c->timeStepFails++;
      PetscCall(PetscLogEventEnd(HYLC_ClothStep, c, 0, 0, 0));
      if (c->monitor) PetscCall(PetscPrintf(comm, "  time step %g s at t = %g s: not converged in %" PetscInt_FMT " iterations (reason %" PetscInt_FMT "), halved\n", (double)dt, (double)c->time, c->lastIts, c->lastReason));
      dt /= 2;
      if (dt < dtmin) {
        PetscCall(PetscPrintf(comm, "  dynamics: the time step fell below %g s at t = %g s (-cloth_dt %g s; try a smaller -cloth_dt, more -cloth_damping or a finer -cloth_h)\n", (double)dtmin, (double)c->time, (double)c->dt));
        break;
      }
      continue;
    }
    /* accepted: v_{n+1} = (x_{n+1} - x_n) / dt */
    PetscCall(VecWAXPY(c->vn, -1.0, c->xn, c->x));
    PetscCall(VecScale(c->vn, 1 / dt));
    c->time += dt;
    c->timeSteps++;
    PetscCall(Speed(c, c->vn, &vmax, &ekin));
    PetscCall(PetscLogEventEnd(HYLC_ClothStep, c, 0, 0, 0));
    if (c->vtkDt > 0 && c->time >= (frame + 1) * c->vtkDt * (1 - 1e-12)) { /* an animation frame (ParaView reads the numbered series) */
      char suffix[64], path[PETSC_MAX_PATH_LEN + 64];
      frame = (PetscInt)PetscFloorReal(c->time / c->vtkDt * (1 + 1e-12));
      PetscCall(PetscSNPrintf(suffix, sizeof(suffix), "dynamics_%04" PetscInt_FMT ".vtk", frame));
      PetscCall(HylcClothOutputName_Private(c, suffix, path, sizeof(path)));
      PetscCall(HylcClothWriteVTK_Private(c, path));
    }
    if (c->monitor) PetscCall(PetscPrintf(comm, "  t = %-10.6g s  dt %-9.3g s  Newton %2" PetscInt_FMT "  largest speed %-10.4g m/s  kinetic energy %.4g J\n", (double)c->time, (double)dt, c->lastIts, (double)vmax, (double)ekin));
    if (wait > 0) wait--;
    if (vmax < c->restTol && !wait) { /* slow enough: the static equilibrium near it, or a residual small enough */
      PetscBool eq;
      PetscReal Fref, r;
      PetscInt  maxit = c->maxit;
      Vec       G;
      PetscCall(VecDuplicate(c->x, &G));
      PetscCall(HylcClothEnergy_Private(c, c->x, &E, G));
      PetscCall(VecNorm(G, NORM_2, &r));
      PetscCall(VecDestroy(&G));
      PetscCall(HylcClothForceScale_Private(c, c->x, &Fref));
      r /= Fref > 0 ? Fref : 1;
      PetscCall(VecCopy(c->x, xsave));
      c->maxit = PetscMin(c->maxit, 12); /* from a state at rest Newton converges in a few iterations or creeps */
      PetscCall(HylcClothSolveStatic_Private(c, &eq));
      c->maxit = maxit;
      c->polishes++;
      if (c->monitor) PetscCall(PetscPrintf(comm, "  slow at t = %g s (static residual %.3g of the force scale): the static solve %s in %" PetscInt_FMT " iterations\n", (double)c->time, (double)r, eq ? "converged" : "did not converge", c->lastIts));
      if (eq) {
        c->restResidual = 0;
        *rest           = PETSC_TRUE;
        break;
      }
      PetscCall(VecCopy(xsave, c->x));
      wait = 5;
      if (r <= c->restRtol) { /* at rest, not polished: a nearly neutral mode creeps (folds, a slow buckle) */
        c->restResidual = r;
        *rest           = PETSC_TRUE;
        break;
      }
    }
    if (c->lastIts <= 6) dt = PetscMin(1.5 * dt, c->dtMax);
  }
  PetscCall(PetscInfo(c, "dynamics: %" PetscInt_FMT " time steps (%" PetscInt_FMT " halved), t = %g s, largest speed %g m/s, %" PetscInt_FMT " Newton iterations\n", c->timeSteps, c->timeStepFails, (double)c->time, (double)vmax, c->newtonIts - its0));
  PetscCall(VecDestroy(&xsave));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The equilibrium under full gravity (the clamps where they are) from the current state at gravity scale c->gscale, by
  -cloth_dynamic: the static load path in at least nsteps steps (OFF), that and, where it fails, the
  dynamics from its last equilibrium (AUTO), or the dynamics from the rest mesh (ON). converged: an
  equilibrium was reached. Collective.
*/
PetscErrorCode HylcClothEquilibrium_Private(HylcCloth c, PetscInt nsteps, PetscBool *converged)
{
  MPI_Comm comm = CLOTH_COMM_PRIVATE(c);
  PetscInt steps0, fails0;

  PetscFunctionBegin;
  *converged = PETSC_FALSE;
  if (c->dynamics != HYLC_CLOTH_DYNAMICS_ON) {
    PetscCall(HylcClothLoadPath_Private(c, c->load, 1, nsteps, converged));
    if (*converged || c->dynamics == HYLC_CLOTH_DYNAMICS_OFF) PetscFunctionReturn(PETSC_SUCCESS);
    PetscCall(PetscPrintf(comm, "  the static load path stops at gravity scale %.4g: released under full gravity, backward Euler to rest (-cloth_dynamic auto)\n", (double)c->gscale));
  } else
    PetscCall(VecCopy(c->x0, c->x));
  c->gscale = 1;
  steps0    = c->timeSteps;
  fails0    = c->timeStepFails;
  PetscCall(HylcClothSettle_Private(c, converged));
  if (*converged && c->restResidual > 0)
    PetscCall(PetscPrintf(comm, "  dynamics: %" PetscInt_FMT " time steps (%" PetscInt_FMT " repeated with half the step) to t = %.4g s, at rest (static residual %.2g of the force scale, not polished)\n", c->timeSteps - steps0,
                          c->timeStepFails - fails0, (double)c->time, (double)c->restResidual));
  else
    PetscCall(PetscPrintf(comm, "  dynamics: %" PetscInt_FMT " time steps (%" PetscInt_FMT " repeated with half the step) to t = %.4g s, %s\n", c->timeSteps - steps0, c->timeStepFails - fails0, (double)c->time,
                          *converged ? "at rest in a static equilibrium" : "not at rest"));
  PetscFunctionReturn(PETSC_SUCCESS);
}
