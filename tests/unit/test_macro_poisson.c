/* HylcMidsurface: the Poisson phi converges to the closed form at second order (grids 24, 48, 96;
   bilinear and bicubic interpolation; II00 only with shear, and a rotated direction d), polar normals
   converge to R(xi) e3, doubly curved II (auto -> poisson, phi(0) = 0, n . phi_,alpha small), the
   sign convention through the object, options and error handling.
   HYLC_TEST_VERBOSE=1 prints the errors and orders. */
#include <hylc/macro.h>
#include <stdlib.h>
#include "hylctest.h"

static PetscBool verbose = PETSC_FALSE;

/* max |x_poisson - x_closed| and max |n_poisson - n_closed| over random points of the box */
static PetscErrorCode PoissonError(const PetscReal z[6], const PetscReal lo[2], const PetscReal hi[2], PetscInt grid, HylcMidsurfaceInterp interp, HylcMidsurfaceNormal normal, PetscReal *ephi, PetscReal *en, PetscInt *its)
{
  HylcMidsurface         ms;
  const HylcMacroStrain *m;
  const PetscInt         np = 400;
  PetscReal             *xih, *x, *n;
  unsigned long long     st = 777;

  PetscFunctionBegin;
  PetscCall(HylcMidsurfaceCreate(PETSC_COMM_SELF, &ms));
  PetscCall(HylcMidsurfaceSetStrain(ms, z));
  PetscCall(HylcMidsurfaceSetBox(ms, lo, hi));
  PetscCall(HylcMidsurfaceSetType(ms, HYLC_MIDSURFACE_POISSON));
  PetscCall(HylcMidsurfaceSetGridSize(ms, grid));
  PetscCall(HylcMidsurfaceSetInterpolation(ms, interp));
  PetscCall(HylcMidsurfaceSetNormalType(ms, normal));
  PetscCall(HylcMidsurfaceSetUp(ms));
  PetscCall(HylcMidsurfaceGetSolveInfo(ms, NULL, its));
  PetscCall(HylcMidsurfaceGetStrain(ms, &m));
  PetscCall(PetscMalloc3(3 * np, &xih, 3 * np, &x, 3 * np, &n));
  for (PetscInt p = 0; p < np; p++) {
    xih[3 * p]     = lo[0] + (hi[0] - lo[0]) * HylcTestRand(&st);
    xih[3 * p + 1] = lo[1] + (hi[1] - lo[1]) * HylcTestRand(&st);
    xih[3 * p + 2] = 0;
  }
  PetscCall(HylcMidsurfaceEvaluate(ms, np, xih, x, n));
  *ephi = *en = 0;
  for (PetscInt p = 0; p < np; p++) {
    double xi[2] = {xih[3 * p], xih[3 * p + 1]}, phi[3], nc[3];
    HylcMacroClosedPhi(m, xi, phi, nc, NULL);
    for (int i = 0; i < 3; i++) {
      *ephi = PetscMax(*ephi, PetscAbsReal(x[3 * p + i] - phi[i]));
      *en   = PetscMax(*en, PetscAbsReal(n[3 * p + i] - nc[i]));
    }
  }
  PetscCall(PetscFree3(xih, x, n));
  PetscCall(HylcMidsurfaceDestroy(&ms));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestConvergence(void)
{
  const PetscReal th = 0.5, H = 1.1;
  const PetscReal cases[2][6] = {{0.1, 0.3, -0.1, 0.8, 0, 0}, {-0.1, -0.2, 0.2, H * cos(th) * cos(th), H * cos(th) * sin(th), H * sin(th) * sin(th)}};
  const PetscReal lo[2] = {-1.0, -0.6}, hi[2] = {1.2, 0.9};
  const PetscInt  grids[3] = {24, 48, 96};

  PetscFunctionBegin;
  for (int c = 0; c < 2; c++)
    for (int ip = 0; ip < 2; ip++) {
      PetscReal ephi[3], en[3], enp[3];
      PetscInt  its[3], itsp;
      for (int g = 0; g < 3; g++) {
        PetscCall(PoissonError(cases[c], lo, hi, grids[g], (HylcMidsurfaceInterp)ip, HYLC_MIDSURFACE_NORMAL_ROTATION, &ephi[g], &en[g], &its[g]));
        PetscCall(PoissonError(cases[c], lo, hi, grids[g], (HylcMidsurfaceInterp)ip, HYLC_MIDSURFACE_NORMAL_POLAR, &ephi[g], &enp[g], &itsp));
        HYLC_CHECK(en[g] <= 1e-15, "case %d: rotation normals of the Poisson midsurface are R(xi) e3 (err %g)", c, (double)en[g]);
      }
      const PetscReal o1 = PetscLog2Real(ephi[0] / ephi[1]), o2 = PetscLog2Real(ephi[1] / ephi[2]);
      const PetscReal p1 = PetscLog2Real(enp[0] / enp[1]), p2 = PetscLog2Real(enp[1] / enp[2]);
      HYLC_CHECK(o1 >= 1.8 && o2 >= 1.8, "case %d %s: phi orders %.2f %.2f (errors %.3e %.3e %.3e)", c, HylcMidsurfaceInterps[ip], (double)o1, (double)o2, (double)ephi[0], (double)ephi[1], (double)ephi[2]);
      HYLC_CHECK(ephi[2] <= 2e-4, "case %d %s: phi error on the 96 grid %.3e", c, HylcMidsurfaceInterps[ip], (double)ephi[2]);
      HYLC_CHECK(p1 >= 1.5 && p2 >= 1.5 && enp[2] <= 1e-3, "case %d %s: polar normal orders %.2f %.2f (errors %.3e %.3e %.3e)", c, HylcMidsurfaceInterps[ip], (double)p1, (double)p2, (double)enp[0], (double)enp[1], (double)enp[2]);
      if (verbose)
        PetscCall(PetscPrintf(PETSC_COMM_SELF, "case %d %-8s phi err %.3e %.3e %.3e orders %.2f %.2f | polar n err %.3e %.3e %.3e orders %.2f %.2f | KSP its (3 comps) %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", c,
                              HylcMidsurfaceInterps[ip], (double)ephi[0], (double)ephi[1], (double)ephi[2], (double)o1, (double)o2, (double)enp[0], (double)enp[1], (double)enp[2], (double)p1, (double)p2, its[0], its[1], its[2]));
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestDoubly(void)
{
  HylcMidsurface     ms;
  const PetscReal    z[6] = {0.05, 0.2, -0.05, 0.3, 0.1, -0.25};
  HylcMidsurfaceType type;
  PetscReal          x0[3], n0[3], worst[2] = {0, 0};
  unsigned long long st = 4242;

  PetscFunctionBegin;
  PetscCall(HylcMidsurfaceCreate(PETSC_COMM_SELF, &ms));
  PetscCall(HylcMidsurfaceSetStrain(ms, z));
  PetscCall(HylcMidsurfaceSetInterpolation(ms, HYLC_MIDSURFACE_INTERP_BICUBIC));
  PetscCall(HylcMidsurfaceSetUp(ms));
  PetscCall(HylcMidsurfaceGetType(ms, &type));
  HYLC_CHECK(type == HYLC_MIDSURFACE_POISSON, "auto resolves to poisson for doubly curved II");
  PetscCall(HylcMidsurfaceEvaluate(ms, 1, (PetscReal[3]){0, 0, 0}, x0, n0));
  for (int i = 0; i < 3; i++) HYLC_CHECK(PetscAbsReal(x0[i]) <= 1e-14, "phi(0) = 0 (component %d: %g)", i, (double)x0[i]);
  for (int nt = 0; nt < 2; nt++) {
    PetscCall(HylcMidsurfaceSetNormalType(ms, (HylcMidsurfaceNormal)nt));
    for (int t = 0; t < 100; t++) {
      const PetscReal xi[2] = {-0.9 + 1.8 * HylcTestRand(&st), -0.9 + 1.8 * HylcTestRand(&st)}, e = 1e-4;
      PetscReal       pts[9] = {xi[0], xi[1], 0, xi[0] + e, xi[1], 0, xi[0], xi[1] + e, 0}, x[9], n[9], R[9];
      PetscCall(HylcMidsurfaceEvaluate(ms, 3, pts, x, n));
      PetscCall(HylcMidsurfaceGetRotation(ms, xi, R));
      for (int i = 0; i < 3; i++) HYLC_CHECK_CLOSE(n[i], R[3 * i + 2], 1e-15);
      HYLC_CHECK_CLOSE(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-14);
      for (int al = 0; al < 2; al++) {
        PetscReal d = 0;
        for (int i = 0; i < 3; i++) d += n[i] * (x[3 * (al + 1) + i] - x[i]) / e;
        worst[nt] = PetscMax(worst[nt], PetscAbsReal(d));
      }
    }
  }
  /* polar normals are perpendicular to the Poisson surface up to the discretization error; the (S10) normals
     only up to the doubly-curved approximation error O(|II|^2) */
  HYLC_CHECK(worst[1] <= 2e-3, "doubly curved: polar normals |n . phi_,alpha| = %.3e", (double)worst[1]);
  HYLC_CHECK(worst[0] <= 0.05, "doubly curved: rotation normals |n . phi_,alpha| = %.3e", (double)worst[0]);
  if (verbose) PetscCall(PetscPrintf(PETSC_COMM_SELF, "doubly curved II (0.3, 0.1, -0.25), grid 96 bicubic: max |n . phi_,alpha|: rotation %.3e, polar %.3e\n", (double)worst[0], (double)worst[1]));
  PetscCall(HylcMidsurfaceDestroy(&ms));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestObject(void)
{
  HylcMidsurface     ms;
  HylcMidsurfaceType type;
  PetscInt           grid, its;
  PetscErrorCode     ierr;

  PetscFunctionBegin;
  /* sign convention: II00 = 0.5 > 0 bends toward +n, phi3 ~ 0.25 xi1^2 */
  PetscCall(HylcMidsurfaceCreate(PETSC_COMM_SELF, &ms));
  PetscCall(HylcMidsurfaceSetStrain(ms, (PetscReal[6]){0, 0, 0, 0.5, 0, 0}));
  {
    PetscReal x[6], n[6];
    PetscCall(HylcMidsurfaceEvaluate(ms, 2, (PetscReal[6]){0.01, 0, 0, 0.01, 0, 0.2}, x, n));
    HYLC_CHECK(x[2] > 0, "II00 > 0 bends toward +n");
    HYLC_CHECK_REL(x[2], 0.25 * 0.01 * 0.01, 1e-4);
    for (int i = 0; i < 3; i++) HYLC_CHECK_CLOSE(x[3 + i], x[i] + 0.2 * n[i], 1e-15);
  }
  PetscCall(HylcMidsurfaceGetType(ms, &type));
  HYLC_CHECK(type == HYLC_MIDSURFACE_CLOSED, "auto resolves to closed for singly curved II");
  /* options */
  PetscCall(PetscOptionsSetValue(NULL, "-t_macro_phi", "poisson"));
  PetscCall(PetscOptionsSetValue(NULL, "-t_macro_grid", "32"));
  PetscCall(PetscOptionsSetValue(NULL, "-t_macro_interp", "bicubic"));
  PetscCall(PetscOptionsSetValue(NULL, "-t_macro_normal", "polar"));
  PetscCall(PetscOptionsSetValue(NULL, "-t_macro_ksp_rtol", "1e-10"));
  PetscCall(HylcMidsurfaceSetOptionsPrefix(ms, "t_"));
  PetscCall(HylcMidsurfaceSetFromOptions(ms));
  PetscCall(HylcMidsurfaceSetUp(ms));
  PetscCall(HylcMidsurfaceGetType(ms, &type));
  PetscCall(HylcMidsurfaceGetSolveInfo(ms, &grid, &its));
  HYLC_CHECK(type == HYLC_MIDSURFACE_POISSON && grid == 32 && its > 0, "options: type %d grid %d its %d", (int)type, (int)grid, (int)its);
  {
    PetscInt  nleft;
    PetscBool used;
    PetscCall(PetscOptionsUsed(NULL, "t_macro_ksp_rtol", &used)); /* name without the dash */
    HYLC_CHECK(used, "-t_macro_ksp_rtol reached the KSP");
    PetscCall(PetscOptionsAllUsed(NULL, &nleft));
    HYLC_CHECK(nleft == 0, "%d options left unused", (int)nleft);
  }
  PetscCall(PetscOptionsClearValue(NULL, "-t_macro_phi"));
  PetscCall(PetscOptionsClearValue(NULL, "-t_macro_grid"));
  PetscCall(PetscOptionsClearValue(NULL, "-t_macro_interp"));
  PetscCall(PetscOptionsClearValue(NULL, "-t_macro_normal"));
  PetscCall(PetscOptionsClearValue(NULL, "-t_macro_ksp_rtol"));
  if (verbose) PetscCall(HylcMidsurfaceView(ms, PETSC_VIEWER_STDOUT_SELF));

  /* errors in user input */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcMidsurfaceSetStrain(ms, (PetscReal[6]){0, 1.0, 0, 0, 0, 0});
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "|sa| = 1 is rejected (%d)", (int)ierr);
  ierr = HylcMidsurfaceSetStrain(ms, (PetscReal[6]){-1.5, 0, 0, 0, 0, 0});
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "1 + sx < 0 is rejected (%d)", (int)ierr);
  ierr = HylcMidsurfaceSetGridSize(ms, 4);
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "grid 4 is rejected (%d)", (int)ierr);
  PetscCall(PetscPopErrorHandler());
  PetscCall(HylcMidsurfaceSetStrain(ms, (PetscReal[6]){0, 0, 0, 1, 0, 1}));
  PetscCall(HylcMidsurfaceSetType(ms, HYLC_MIDSURFACE_CLOSED));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcMidsurfaceSetUp(ms);
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "closed with doubly curved II is rejected (%d)", (int)ierr);
  PetscCall(PetscPopErrorHandler());
  PetscCall(HylcMidsurfaceDestroy(&ms));
  HYLC_CHECK(ms == NULL, "Destroy sets the handle to NULL");
  PetscCall(HylcMidsurfaceDestroy(&ms));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  verbose = getenv("HYLC_TEST_VERBOSE") ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(TestObject());
  PetscCall(TestConvergence());
  PetscCall(TestDoubly());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
