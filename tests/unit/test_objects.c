/* The stage objects HylcPeriodic, HylcSampler and HylcCalibrate as PETSc objects: SetFromOptions only reads
   options (called twice: nothing leaks, the sub-objects stay the same), lazy getters, reference counts,
   setters that check their value, and -periodic_view / -sampler_view printing (to files, read back).
   Runs a one-sample job of a small generated plain weave in the current directory.
   hylc-test: nprocs=1 */
#include <hylc/sampler.h>
#include <hylc/calibrate.h>
#include <hylc/sys.h>
#include <string.h>
#include "hylctest.h"

/* does file path contain text? */
static PetscBool FileContains(const char path[], const char text[])
{
  char   buf[8192];
  size_t n;
  FILE  *fp = fopen(path, "r");
  if (!fp) return PETSC_FALSE;
  n = fread(buf, 1, sizeof(buf) - 1, fp);
  fclose(fp);
  buf[n] = 0;
  return strstr(buf, text) ? PETSC_TRUE : PETSC_FALSE;
}

/* a setter refusing a bad value with the given error code */
#define EXPECT_ERROR(call, code)                                                          \
  do {                                                                                    \
    PetscErrorCode e_;                                                                    \
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));                      \
    e_ = (call);                                                                          \
    PetscCall(PetscPopErrorHandler());                                                    \
    HYLC_CHECK(e_ == (code), "%s returned %d, expected %d", #call, (int)e_, (int)(code)); \
  } while (0)

static PetscErrorCode TestPeriodic(void)
{
  HylcPattern   pat, got;
  HylcPeriodic  P, Q;
  HylcYarnModel model;
  PetscInt      ny, m;
  PetscClassId  id;
  PetscViewer   v;

  PetscFunctionBegin;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &pat));
  PetscCall(HylcPatternSetType(pat, HYLCPATTERNPLAIN));
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcYarnModelDefault(&model));
  PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
  PetscCall(PetscObjectGetClassId((PetscObject)P, &id));
  HYLC_CHECK(id == HYLC_PERIODIC_CLASSID, "class id %d, expected HYLC_PERIODIC_CLASSID %d", (int)id, (int)HYLC_PERIODIC_CLASSID);
  PetscCall(HylcPeriodicGetPattern(P, &got));
  HYLC_CHECK(!got, "a new tile has no pattern");
  EXPECT_ERROR(HylcPeriodicSetUp(P), PETSC_ERR_ARG_WRONGSTATE);
  PetscCall(HylcPeriodicSetFromOptions(P));
  PetscCall(HylcPeriodicSetFromOptions(P));
  PetscCall(HylcPeriodicSetPattern(P, pat, &model));
  PetscCall(HylcPeriodicSetPattern(P, pat, &model)); /* a second time: the old reference dropped */
  PetscCall(HylcPeriodicGetPattern(P, &got));
  HYLC_CHECK(got == pat, "HylcPeriodicGetPattern returns the pattern set");
  EXPECT_ERROR(HylcPeriodicSetPairMargin(P, 0.5), PETSC_ERR_USER_INPUT);
  EXPECT_ERROR(HylcPeriodicSetContactMargin(P, -1), PETSC_ERR_USER_INPUT);
  EXPECT_ERROR(HylcPeriodicSetConstraintTolerance(P, 1), PETSC_ERR_USER_INPUT);
  PetscCall(HylcPeriodicSetSlideConstraint(P, HYLC_SLIDE_NONE));
  PetscCall(HylcPeriodicSetUp(P)); /* prints to periodic_view.txt (-periodic_view) */
  PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, &m));
  HYLC_CHECK(m == 3, "slide none: %d constraint rows, expected 3 (translation)", (int)m);
  /* a second reference: the first destroy only drops it */
  Q = P;
  PetscCall(PetscObjectReference((PetscObject)Q));
  PetscCall(HylcPeriodicDestroy(&Q));
  HYLC_CHECK(!Q, "Destroy sets the handle to NULL");
  PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, NULL));
  PetscCall(PetscViewerASCIIOpen(PETSC_COMM_SELF, "periodic_view_direct.txt", &v));
  PetscCall(HylcPeriodicView(P, v));
  PetscCall(PetscViewerDestroy(&v));
  HYLC_CHECK(FileContains("periodic_view_direct.txt", "slide none"), "HylcPeriodicView names the slide constraint");
  PetscCall(HylcPeriodicDestroy(&P));
  PetscCall(HylcPeriodicDestroy(&P)); /* NULL: no-op */
  PetscCall(HylcPatternDestroy(&pat));
  HYLC_CHECK(FileContains("periodic_view.txt", "HylcPeriodic Object"), "-periodic_view printed the tile");
  HYLC_CHECK(FileContains("periodic_view.txt", "slide constraint none"), "-periodic_view printed the slide constraint set");
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestSampler(void)
{
  HylcSampler     S;
  HylcPattern     p1, p2;
  HylcMicro       m1, m2;
  const HylcPlan *plan;
  PetscClassId    id;

  PetscFunctionBegin;
  PetscCall(HylcSamplerCreate(PETSC_COMM_WORLD, &S));
  PetscCall(PetscObjectGetClassId((PetscObject)S, &id));
  HYLC_CHECK(id == HYLC_SAMPLER_CLASSID, "class id %d, expected HYLC_SAMPLER_CLASSID %d", (int)id, (int)HYLC_SAMPLER_CLASSID);
  PetscCall(HylcSamplerSetFromOptions(S));
  PetscCall(HylcSamplerGetPattern(S, &p1));
  PetscCall(HylcSamplerGetMicro(S, &m1));
  PetscCall(HylcSamplerSetFromOptions(S)); /* only reads options: no second pattern or solver */
  PetscCall(HylcSamplerGetPattern(S, &p2));
  PetscCall(HylcSamplerGetMicro(S, &m2));
  HYLC_CHECK(p1 == p2 && m1 == m2, "a second SetFromOptions keeps the pattern and the solver");
  EXPECT_ERROR(HylcSamplerGetPlan(S, &plan), PETSC_ERR_ARG_WRONGSTATE); /* ranges need the radius */
  EXPECT_ERROR(HylcSamplerSetBatchSize(S, 0), PETSC_ERR_USER_INPUT);
  EXPECT_ERROR(HylcSamplerSetSampleCounts(S, 0, 5), PETSC_ERR_USER_INPUT);
  PetscCall(HylcSamplerSetUp(S)); /* prints sampler_view.txt (-sampler_view) */
  PetscCall(HylcSamplerGetPlan(S, &plan));
  HYLC_CHECK(HylcPlanSize(plan) == 1, "plan of -sampler_terms zero: %ld samples, expected 1", HylcPlanSize(plan));
  EXPECT_ERROR(HylcSamplerSetOutput(S, "other.h5"), PETSC_ERR_ARG_WRONGSTATE);
  PetscCall(HylcSamplerRun(S));
  PetscCall(HylcSamplerDestroy(&S));
  HYLC_CHECK(!S, "Destroy sets the handle to NULL");
  HYLC_CHECK(FileContains("sampler_view.txt", "HylcSampler Object"), "-sampler_view printed the sampler");
  HYLC_CHECK(FileContains("sampler_view.txt", "terms zero: 1 samples"), "-sampler_view printed the plan");
  HYLC_CHECK(FileContains("objects.h5", "HDF"), "the job wrote its output");
  /* an unused sampler: created, read twice, destroyed without a set-up */
  PetscCall(HylcSamplerCreate(PETSC_COMM_WORLD, &S));
  PetscCall(HylcSamplerSetFromOptions(S));
  PetscCall(HylcSamplerSetFromOptions(S));
  PetscCall(HylcSamplerDestroy(&S));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestCalibrate(void)
{
  HylcCalibrate C;
  HylcPattern   p1, p2;
  HylcMicro     m1, m2;

  PetscFunctionBegin;
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateGetPattern(C, &p1));
  PetscCall(HylcCalibrateGetMicro(C, &m1));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateGetPattern(C, &p2));
  PetscCall(HylcCalibrateGetMicro(C, &m2));
  HYLC_CHECK(p1 == p2 && m1 == m2, "a second SetFromOptions keeps the pattern and the solver");
  EXPECT_ERROR(HylcCalibrateSetThinning(C, 0, 0), PETSC_ERR_USER_INPUT);
  EXPECT_ERROR(HylcCalibrateSetTermWeight(C, "sz", 1), PETSC_ERR_USER_INPUT);
  EXPECT_ERROR(HylcCalibrateSetTargetType(C, "xml"), PETSC_ERR_USER_INPUT);
  PetscCall(HylcCalibrateSetTermWeight(C, "sx-sa", 2));
  PetscCall(HylcCalibrateDestroy(&C));
  HYLC_CHECK(!C, "Destroy sets the handle to NULL");
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsSetValue(NULL, "-pattern_type", "plain"));
  PetscCall(PetscOptionsSetValue(NULL, "-sampler_terms", "zero"));
  PetscCall(PetscOptionsSetValue(NULL, "-sampler_reference", "none"));
  PetscCall(PetscOptionsSetValue(NULL, "-sampler_output", "objects.h5"));
  PetscCall(PetscOptionsSetValue(NULL, "-sampler_overwrite", NULL));
  PetscCall(PetscOptionsSetValue(NULL, "-sampler_progress", "1000"));
  PetscCall(PetscOptionsSetValue(NULL, "-sampler_view", "ascii:sampler_view.txt"));
  PetscCall(PetscOptionsSetValue(NULL, "-periodic_view", "ascii:periodic_view.txt"));
  PetscCall(TestPeriodic());
  PetscCall(TestSampler());
  PetscCall(TestCalibrate());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
