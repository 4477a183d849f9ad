/* HylcCalibrate: the envelope-theorem gradient of the objective, df/dlog p for p = E, Es, G, kc, against
   central differences of the objective (each a full re-solve of every sample), on a generated stockinette
   tile and a CSV target with 1D, 2D and off-axis rows.
   hylc-test: nprocs=1 */
#include <hylc/calibrate.h>
#include <stdlib.h>
#include <unistd.h>
#include "hylctest.h"

static const char csv[] = "sx,sa,sy,II00,II01,II11,psi\n"
                          "0,0,0,0,0,0,5.0\n"
                          "0.1,0,0,0,0,0,8.0\n"
                          "-0.05,0,0,0,0,0,6.1\n"
                          "0,0.2,0,0,0,0,7.0\n"
                          "0,0,0.08,0,0,0,6.9\n"
                          "0,0,0,60,0,0,6.6\n"
                          "0,0,0,0,0,-60,6.2\n"
                          "0.05,0.1,0,0,0,0,8.5\n"
                          "0,0,0,30,10,0,6.0\n";

int main(int argc, char **argv)
{
  char          path[] = "/tmp/hylc-calibrate-gradient-XXXXXX.csv";
  HylcCalibrate C;
  PetscReal     p[4] = {1.3e6, 0.8e6, 0.5e6, 60}, f, g[4], fp, fm, q[4];
  PetscInt      nf;
  const double  h = 1e-4;
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
  PetscCall(PetscOptionsSetValue(NULL, "-calibrate_target", path));
  PetscCall(PetscOptionsSetValue(NULL, "-calibrate_weight_zero", "0.5"));
  PetscCall(HylcTestOptionDefault("-micro_rtol", "1e-7"));
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateSetUp(C));
  PetscCall(HylcCalibrateEvaluate(C, p, &f, g, &nf));
  HYLC_CHECK(nf == 0, "%d samples did not converge", (int)nf);
  HYLC_CHECK(f > 1e-3, "objective %g should be clearly non-zero", (double)f);
  for (int j = 0; j < 4; j++) {
    double fd_;
    for (int k = 0; k < 4; k++) q[k] = p[k];
    q[j] = p[j] * exp(h);
    PetscCall(HylcCalibrateEvaluate(C, q, &fp, NULL, NULL));
    q[j] = p[j] * exp(-h);
    PetscCall(HylcCalibrateEvaluate(C, q, &fm, NULL, NULL));
    fd_ = (fp - fm) / (2 * h);
    if (getenv("HYLC_TEST_VERBOSE")) printf("%s: analytic %.10e central %.10e rel %.2e\n", HylcCalibrateParamNames[j], (double)g[j], fd_, fabs(fd_ - g[j]) / fabs(g[j]));
    HYLC_CHECK(fabs(g[j]) > 1e-6 * f, "gradient component %s = %g is too small to test", HylcCalibrateParamNames[j], (double)g[j]);
    HYLC_CHECK_REL(g[j], fd_, 1e-4);
  }
  PetscCall(HylcCalibrateDestroy(&C));
  unlink(path);
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
