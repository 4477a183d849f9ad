/* HylcCalibrate -calibrate_stationary (issue 30): the stationarity's residuals dPsi/ds_k at the base
   strain and their Gauss-Newton Jacobian (each energy term's part of the gradient at the fixed state of
   the tile) against central differences of the gradient over full re-solves (reported: they differ a lot), on a generated stockinette
   taken as its own reference state (not an equilibrium of its periods: a non-zero gradient at 0) and a CSV
   target; then a calibration with a large weight ends with a smaller |dPsi/ds| at 0 than one without, with
   either Jacobian (fd, the default: below a tenth).
   hylc-test: nprocs=1 */
#include <hylc/calibrate.h>
#include <stdlib.h>
#include <unistd.h>
#include "hylctest.h"

static const char csv[] = "sx,sa,sy,II00,II01,II11,psi\n"
                          "0,0,0,0,0,0,5.0\n"
                          "0.1,0,0,0,0,0,8.0\n"
                          "0.05,0,0,0,0,0,6.0\n"
                          "-0.05,0,0,0,0,0,6.1\n"
                          "0,0.2,0,0,0,0,7.0\n"
                          "0,0,0.08,0,0,0,6.9\n"
                          "0,0,0,60,0,0,6.6\n";

/* a calibration of E, Es, kc (G tied) with stationarity weight w: |dPsi/dsx| + |dPsi/dsy| at 0 after it */
static PetscErrorCode Calibrate(const char w[], const char jac[], const char maxit[], PetscReal *after, PetscReal *scale)
{
  HylcCalibrate C;
  PetscReal     S[2], a[2];

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(NULL, "-calibrate_stationary", w));
  PetscCall(PetscOptionsSetValue(NULL, "-calibrate_stationary_jacobian", jac));
  PetscCall(PetscOptionsSetValue(NULL, "-calibrate_max_it", maxit));
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateSolve(C));
  PetscCall(HylcCalibrateGetStationarity(C, S, NULL, a));
  *after = PetscAbsReal(a[0] / S[0]) + PetscAbsReal(a[1] / S[1]);
  *scale = S[0];
  PetscCall(HylcCalibrateDestroy(&C));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char          path[] = "/tmp/hylc-calibrate-stationary-XXXXXX.csv";
  HylcCalibrate C;
  PetscReal     p[4] = {1e6, 1e6, 4e5, 50}, ds[2], J[8], q[4], dp[2], dm[2], row[2] = {0, 0}, err = 0, a0, a1, a2, S;
  const double  h       = 1e-4;
  const int     verbose = getenv("HYLC_TEST_VERBOSE") != NULL;
  int           fd;
  FILE         *fp_;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  fd = mkstemps(path, 4);
  HYLC_CHECK(fd >= 0, "mkstemps");
  fp_ = fdopen(fd, "w");
  fputs(csv, fp_);
  fclose(fp_);
  PetscCall(HylcTestOptionDefault("-pattern_type", "stockinette"));
  PetscCall(HylcTestOptionDefault("-calibrate_reference", "none"));
  PetscCall(HylcTestOptionDefault("-micro_rtol", "1e-8"));
  PetscCall(HylcTestOptionDefault("-yarn_E", "1e6"));
  PetscCall(HylcTestOptionDefault("-yarn_Es", "1e6"));
  PetscCall(HylcTestOptionDefault("-yarn_kc", "50"));
  PetscCall(PetscOptionsSetValue(NULL, "-calibrate_target", path));

  /* the Jacobian columns against central differences in log p (each a full re-solve of the base sample) */
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateSetUp(C));
  PetscCall(HylcCalibrateEvaluateStationarity(C, p, ds, J));
  if (verbose) printf("dPsi/dsx %.10e dPsi/dsy %.10e N/m\n", (double)ds[0], (double)ds[1]);
  HYLC_CHECK(PetscAbsReal(ds[0]) > 1e-3 && PetscAbsReal(ds[1]) > 1e-3, "the generated tile should not be stationary at 0: %g %g", (double)ds[0], (double)ds[1]);
  for (int j = 0; j < 4; j++) {
    for (int k = 0; k < 4; k++) q[k] = p[k];
    q[j] = p[j] * exp(h);
    PetscCall(HylcCalibrateEvaluateStationarity(C, q, dp, NULL));
    q[j] = p[j] * exp(-h);
    PetscCall(HylcCalibrateEvaluateStationarity(C, q, dm, NULL));
    for (int k = 0; k < 2; k++) {
      const double fd_ = (dp[k] - dm[k]) / (2 * h);
      row[k] += fd_;
      err = PetscMax(err, fabs(fd_ - J[2 * j + k]) / fabs(ds[k]));
      if (verbose) printf("%-2s d/dlog p of dPsi/ds%s: Gauss-Newton %+.6e central %+.6e (difference %.2e of |dPsi/ds|)\n", HylcCalibrateParamNames[j], k ? "y" : "x", (double)J[2 * j + k], fd_, fabs(fd_ - J[2 * j + k]) / fabs(ds[k]));
    }
  }
  /* Psi is homogeneous of degree 1 in (E, Es, G, kc) jointly with the same equilibrium: both Jacobians' rows
     sum to the gradient, the Gauss-Newton one exactly (the terms add up), the true one to the differences' error */
  for (int k = 0; k < 2; k++) {
    PetscReal gn = 0;
    for (int j = 0; j < 4; j++) gn += J[2 * j + k];
    HYLC_CHECK_REL(gn, ds[k], 1e-10);
    HYLC_CHECK_REL(row[k], ds[k], 1e-4);
  }
  /* the Gauss-Newton columns leave out the equilibrium's change with p: measured off by up to 2.65 |dPsi/ds|
     here, kc's with the wrong sign (docs/calibrate.md); only reported */
  printf("stationarity Jacobian: Gauss-Newton vs central differences differ by up to %.3g of |dPsi/ds|\n", (double)err);
  PetscCall(HylcCalibrateDestroy(&C));

  /* a large weight makes the calibrated tile closer to stationary than no weight */
  PetscCall(Calibrate("0", "fd", "8", &a0, &S));
  PetscCall(Calibrate("100", "fd", "8", &a1, &S));
  PetscCall(Calibrate("100", "gn", "3", &a2, &S)); /* its 4th iteration's line search fails after ~90 evaluations */
  printf("|dPsi/dsx|/S_x + |dPsi/dsy|/S_y after the calibration: %.4e without, %.4e with weight 100 (fd Jacobian), %.4e (gn Jacobian); S_x %.4g N/m\n", (double)a0, (double)a1, (double)a2, (double)S);
  HYLC_CHECK(a1 < 0.1 * a0, "with -calibrate_stationary 100 the gradient at 0 (%g) should be well below that without (%g)", (double)a1, (double)a0);
  HYLC_CHECK(a2 < a0, "with -calibrate_stationary 100 and the gn Jacobian the gradient at 0 (%g) should be below that without (%g)", (double)a2, (double)a0);
  unlink(path);
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
