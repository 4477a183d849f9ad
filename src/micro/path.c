/* HylcMicro: the homogeneous states of the standard fabric tests computed from the tile (include/hylc/micro.h,
   docs/fabric-fidelity.md): on a load path (include/hylcmat.h: uniaxial at any angle, equibiaxial, shear,
   bending) Psi is minimized over the path's free strains, each Psi a microscale equilibrium and its gradient the
   envelope-theorem stress. The table's states on the same paths are hylcmat_path_state(). */
#include <hylc/private/microimpl.h>
#include <hylc/private/newton2.h>
#include <hylcmat.h>
#include <petsctime.h>

/* a point of the minimization: free strains, strain, Psi, dPsi/dz, and the local fluctuation of its equilibrium */
typedef struct {
  PetscReal  p[3], z[6], J[24], psi, g[6];
  PetscReal *u;
  PetscBool  ok; /* every solve of the point converged */
} PathPoint;

/* one solve at z, continued from u (NULL: cold), cold again if that does not converge; counted in res */
static PetscErrorCode SolveAt(HylcMicro M, const PetscReal z[6], const PetscReal u[], HylcMicroPathResult *res, HylcMicroResult *r)
{
  PetscFunctionBegin;
  if (u) PetscCall(HylcMicroSetInitialFluctuation(M, u));
  PetscCall(HylcMicroSolve(M, z, r));
  res->solves++;
  res->microIterations += r->iterations;
  if (r->status != HYLC_MICRO_CONVERGED) {
    res->failedSolves++;
    if (u) {
      PetscCall(PetscInfo(M, "load path: the continued solve at (%g, %g, %g, %g, %g, %g) ended %s: solved again cold\n", (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5], HylcMicroStatuses[r->status]));
      PetscCall(HylcMicroSolve(M, z, r));
      res->solves++;
      res->microIterations += r->iterations;
      if (r->status != HYLC_MICRO_CONVERGED) res->failedSolves++;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the strain components a path's gradient needs: the in-plane ones and its curvature */
static int PathComps(const hylcmat_path *path) { return HYLC_STRAIN_PLANE_BITS | (path->kind == HYLCMAT_PATH_BENDING ? (path->angle ? 1 << 5 : 1 << 3) : 0); }

/* Psi and its gradient at the free strains pt->p, from the fluctuation u (NULL: cold); pt->u gets the
   fluctuation of the equilibrium. A strain the tile cannot take (|sa| >= 0.95, a stretch factor <= 0.05) is a
   failed point (psi = +inf), as is a solve that does not converge. */
static PetscErrorCode Evaluate(HylcMicro M, const hylcmat_path *path, PetscReal s, const PetscReal u[], PathPoint *pt, HylcMicroPathResult *res)
{
  HylcMicroResult r;

  PetscFunctionBegin;
  pt->ok  = PETSC_FALSE;
  pt->psi = PETSC_INFINITY;
  for (int j = 0; j < 6; j++) pt->g[j] = 0;
  if (hylcmat_path_strain(path, s, pt->p, pt->z, pt->J) || !(PetscAbsReal(pt->z[1]) < 0.95 && pt->z[0] > -0.95 && pt->z[2] > -0.95)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(SolveAt(M, pt->z, u, res, &r));
  pt->psi = r.psi;
  pt->ok  = (PetscBool)(r.status == HYLC_MICRO_CONVERGED);
  if (r.status == HYLC_MICRO_NONFINITE)
    PetscCall(PetscArrayzero(pt->u, M->ny)); /* no state to continue from: cold */
  else {
    PetscCall(HylcMicroGetState(M, M->yw));
    PetscCall(HylcMicroGetFluctuation(M, M->yw, pt->u));
  }
  if (!pt->ok) PetscFunctionReturn(PETSC_SUCCESS);
  if (M->par.uniGrad == HYLC_MICRO_UNIAXIAL_ENVELOPE) {
    PetscCall(HylcMicroGetStrainGradient(M, PathComps(path), pt->g));
    for (int j = 0; j < 6; j++)
      if (PetscIsInfOrNanReal(pt->g[j])) pt->g[j] = 0; /* a component the path does not move */
  } else {
    const int comps = PathComps(path);
    for (int j = 0; j < 6 && pt->ok; j++) {
      PetscReal       psi[2];
      const PetscReal h = j < 3 ? M->par.uniH : M->par.uniH * 100; /* 1/m: a curvature of the stretch's size over 1 cm */
      if (!(comps & (1 << j))) continue;
      for (int sgn = 0; sgn < 2; sgn++) {
        PetscReal zz[6];
        for (int k = 0; k < 6; k++) zz[k] = pt->z[k];
        zz[j] += sgn ? -h : h;
        PetscCall(SolveAt(M, zz, pt->u, res, &r));
        psi[sgn] = r.psi;
        if (r.status != HYLC_MICRO_CONVERGED) pt->ok = PETSC_FALSE;
      }
      pt->g[j] = (psi[0] - psi[1]) / (2 * h);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the reduced gradient J_p^T g (nf) and the path's force J_s^T g */
static void Reduced(int nf, const PathPoint *pt, PetscReal gp[3], PetscReal *force)
{
  *force = 0;
  for (int k = 0; k < 6; k++) *force += pt->J[k * (1 + nf)] * pt->g[k];
  for (int a = 0; a < 3; a++) {
    gp[a] = 0;
    for (int k = 0; k < 6 && a < nf; k++) gp[a] += pt->J[k * (1 + nf) + 1 + a] * pt->g[k];
  }
}

static void CopyPoint(PetscInt ny, const PathPoint *a, PathPoint *b)
{
  PetscReal *u = b->u;
  *b           = *a;
  b->u         = u;
  for (PetscInt i = 0; i < ny; i++) b->u[i] = a->u[i];
}

/* the work of HylcMicroSolvePath() */
static PetscErrorCode SolvePath(HylcMicro M, const hylcmat_path *path, PetscReal s, const PetscReal p0[], const PetscReal u0[], HylcMicroPathResult *res, PetscReal u[])
{
  const HylcMicroParams *par = &M->par;
  const int              nf  = hylcmat_path_nfree(path);
  PathPoint              cur, trial, pert;
  PetscReal              H[9], gp[3], d[3], force;
  PetscBool              haveH = PETSC_FALSE;
  PetscLogDouble         t0, t1;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidPointer(res, 6);
  PetscCheck(nf > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Load path kind %d: must be uniaxial (0), equibiaxial (1), shear (2) or bending (3)", path->kind);
  PetscCheck(path->kind != HYLCMAT_PATH_BENDING || path->angle == 0 || path->angle == 90, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Bending path: the axis angle %g must be 0 (II00) or 90 (II11)", (double)path->angle);
  PetscCheck(path->kind != HYLCMAT_PATH_UNIAXIAL || (path->angle >= 0 && path->angle <= 90), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Uniaxial path: the angle %g must be in [0, 90] degrees from the material x axis", (double)path->angle);
  PetscCheck((path->kind != HYLCMAT_PATH_UNIAXIAL && path->kind != HYLCMAT_PATH_EQUIBIAXIAL) || (s >= 0 && s < 1), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "%s path: the stretch %g is outside [0, 1): a tension test (a compressed strip buckles) within the sampled stretches", hylcmat_path_name(path->kind), (double)s);
  PetscCheck(path->kind != HYLCMAT_PATH_SHEAR || PetscAbsReal(s) < 0.95, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Shear path: sa = %g must be in (-0.95, 0.95)", (double)s);
  PetscCall(PetscTime(&t0));
  PetscCall(HylcMicroSetUp(M));
  PetscCall(PetscMemzero(res, sizeof(*res)));
  res->path = *path;
  res->s    = s;
  PetscCall(PetscMalloc3(M->ny, &cur.u, M->ny, &trial.u, M->ny, &pert.u));
  for (int a = 0; a < 3; a++) cur.p[a] = p0 && a < nf ? p0[a] : 0;
  PetscCall(Evaluate(M, path, s, u0, &cur, res));
  res->step = PETSC_INFINITY;
  for (PetscInt it = 0; cur.ok; it++) {
    Reduced(nf, &cur, gp, &force);
    if (haveH) { /* the step predicted with the last Hessian: done when it is small */
      HylcNewtonStepN(nf, H, gp, 1e-3, d);
      res->step = 0;
      for (int a = 0; a < nf; a++) res->step = PetscMax(res->step, PetscAbsReal(d[a]));
      if (res->step <= par->uniXtol) {
        res->converged = PETSC_TRUE;
        break;
      }
    }
    if (it >= par->uniMaxIt) break;
    /* the reduced Hessian by forward differences of the reduced gradient, continued from the point */
    for (int a = 0; a < nf && cur.ok; a++) {
      PetscReal gq[3], fq;
      for (int b = 0; b < 3; b++) pert.p[b] = cur.p[b];
      pert.p[a] += par->uniH;
      PetscCall(Evaluate(M, path, s, cur.u, &pert, res));
      if (!pert.ok) break;
      Reduced(nf, &pert, gq, &fq);
      for (int b = 0; b < nf; b++) H[nf * b + a] = (gq[b] - gp[b]) / par->uniH;
    }
    if (!pert.ok) break;
    for (int a = 0; a < nf; a++)
      for (int b = 0; b < a; b++) H[nf * a + b] = H[nf * b + a] = 0.5 * (H[nf * a + b] + H[nf * b + a]);
    haveH = PETSC_TRUE;
    HylcNewtonStepN(nf, H, gp, 1e-3, d);
    res->step = 0;
    for (int a = 0; a < nf; a++) res->step = PetscMax(res->step, PetscAbsReal(d[a]));
    if (res->step <= par->uniXtol) {
      res->converged = PETSC_TRUE;
      break;
    }
    if (res->step > par->uniMaxStep)
      for (int a = 0; a < nf; a++) d[a] *= par->uniMaxStep / res->step;
    /* backtracking on Psi */
    PetscBool accepted = PETSC_FALSE;
    PetscReal slope    = 0;
    for (int a = 0; a < nf; a++) slope += gp[a] * d[a];
    for (PetscReal t = 1; t > 1e-3 && !accepted; t *= 0.25) {
      for (int a = 0; a < 3; a++) trial.p[a] = cur.p[a] + (a < nf ? t * d[a] : 0);
      PetscCall(Evaluate(M, path, s, cur.u, &trial, res));
      accepted = (PetscBool)(trial.ok && trial.psi <= cur.psi + 1e-4 * t * PetscMin(slope, 0));
    }
    if (!accepted) { /* no decrease: Psi at its noise level? (the free gradient against the path's force, or the in-plane stress of a bent state) */
      PetscReal       gmax = 0;
      const PetscReal ref  = path->kind == HYLCMAT_PATH_BENDING ? PetscAbsReal(cur.g[0]) + PetscAbsReal(cur.g[1]) + PetscAbsReal(cur.g[2]) : PetscAbsReal(force);
      for (int a = 0; a < nf; a++) gmax = PetscMax(gmax, PetscAbsReal(gp[a]));
      if (gmax <= par->uniGtol * ref) res->converged = res->gradientStop = PETSC_TRUE;
      break;
    }
    CopyPoint(M->ny, &trial, &cur);
    res->iterations++;
  }
  Reduced(nf, &cur, gp, &force);
  for (int k = 0; k < 6; k++) res->z[k] = cur.z[k], res->grad[k] = cur.g[k];
  for (int a = 0; a < 3; a++) res->p[a] = cur.p[a], res->gfree[a] = a < nf ? gp[a] : 0;
  res->psi   = cur.psi;
  res->force = force;
  if (!cur.ok) res->converged = PETSC_FALSE;
  if (u) PetscCall(PetscArraycpy(u, cur.u, M->ny));
  PetscCall(PetscFree3(cur.u, trial.u, pert.u));
  PetscCall(PetscTime(&t1));
  res->time = t1 - t0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroSolvePath - The homogeneous state of the tile on a load path (include/hylcmat.h: uniaxial tension
  along any material direction, equibiaxial tension, shear, bending about either axis): the path's quantity s
  prescribed, Psi minimized over its free strains so that their stresses vanish (the free contraction of a
  strip, the free stretches of a shear test, the free in-plane strains of a bent strip). Returns the path's
  force d(min Psi)/ds (N/m; N for bending: the moment per unit width) and the state. Not collective.

  Input Parameters:
+ M    - the solver, with a pattern
. path - the load path (hylcmat_path: kind and angle)
. s    - the prescribed value (stretch, sa or curvature in 1/m)
. p0   - the starting free strains (hylcmat_path_nfree() of them; NULL: 0)
- u0   - the local fluctuation of an earlier equilibrium to continue from (NULL: cold)

  Output Parameters:
+ res - the result (res->converged says whether the minimization converged)
- u   - the local fluctuation of the state returned (may be NULL), to continue from

  Notes:
  The minimization is HylcMicroSolveUniaxial()'s, with as many free strains as the path has: Newton's method,
  the gradient by the envelope theorem (HylcMicroGetStrainGradient(), through the path's map
  hylcmat_path_strain()), the Hessian by forward differences of the reduced gradient (one continued solve per
  free strain and step), made positive definite, steps of at most maxStep and a backtracking line search on
  Psi; the same options (HylcMicroSetUniaxial(), HylcMicroSetUniaxialTolerances()) and stopping tests.

  Level: intermediate

.seealso: HylcMicroSolveUniaxial(), HylcMicroPathResultView(), hylcmat_path_state()
@*/
PetscErrorCode HylcMicroSolvePath(HylcMicro M, const hylcmat_path *path, PetscReal s, const PetscReal p0[], const PetscReal u0[], HylcMicroPathResult *res, PetscReal u[])
{
  PetscReal      rtol;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(M, HYLC_MICRO_CLASSID, 1);
  PetscValidPointer(path, 2);
  rtol        = M->par.rtol;
  M->par.rtol = M->par.uniRtol;
  ierr        = SolvePath(M, path, s, p0, u0, res, u);
  M->par.rtol = rtol; /* restored on an error too */
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMicroPathResultView - Prints a load path result in one line: the path, s, its force, the free strains,
  Psi, the largest free gradient, convergence and counts. Not collective.

  Input Parameters:
+ r      - the result of HylcMicroSolvePath()
- viewer - an ASCII viewer

  Level: intermediate

.seealso: HylcMicroSolvePath()
@*/
PetscErrorCode HylcMicroPathResultView(const HylcMicroPathResult *r, PetscViewer viewer)
{
  char      buf[640];
  PetscReal gmax = 0;
  const int nf   = hylcmat_path_nfree(&r->path);

  PetscFunctionBegin;
  for (int a = 0; a < nf; a++) gmax = PetscMax(gmax, PetscAbsReal(r->gfree[a]));
  /* C formatting: PETSc's printf appends '.' to integral %g values */
  snprintf(buf, sizeof(buf), "%s %g: s %.6g force %.9e %s z %.6e %.6e %.6e %.6e %.6e %.6e psi %.10e free gradient %.2e step %.1e %s; %d Newton steps, %d solves (%d not converged), %d micro iterations, %.2f s\n", hylcmat_path_name(r->path.kind),
           r->path.angle, (double)r->s, (double)r->force, r->path.kind == HYLCMAT_PATH_BENDING ? "N" : "N/m", (double)r->z[0], (double)r->z[1], (double)r->z[2], (double)r->z[3], (double)r->z[4], (double)r->z[5], (double)r->psi, (double)gmax,
           (double)r->step, r->converged ? (r->gradientStop ? "converged (gradient test)" : "converged") : "NOT CONVERGED", (int)r->iterations, (int)r->solves, (int)r->failedSolves, (int)r->microIterations, r->time);
  PetscCall(PetscViewerASCIIPrintf(viewer, "%s", buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}
