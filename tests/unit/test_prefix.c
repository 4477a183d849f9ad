/* Options prefixes of the stage objects: a sampler with the prefix a_ and a calibration with the prefix c_
   read every option of theirs and of their sub-objects after the prefix (-a_sampler_*, -a_pattern_*,
   -a_yarn_*, -a_reference_*, -a_micro_*, -a_periodic_*; the same with c_, and the plan's -c_sampler_family)
   and run: the sampler writes its samples file, the calibration reads it as its target and fits kc. No
   option without a prefix is set, so an option read without its object's prefix is a default, which the
   checks tell apart; HylcCheckOptionsUsed() in each SetUp refuses any prefixed option left unread.
   Runs in the current directory.
   hylc-test: nprocs=2 */
#include <hylc/sampler.h>
#include <hylc/calibrate.h>
#include <string.h>
#include "hylctest.h"

/* does the view of obj contain text? (viewed into a file on rank 0, read back) */
static PetscErrorCode ViewContains(PetscObject obj, const char name[], const char text[], PetscBool *has)
{
  PetscViewer v;
  char        buf[16384], path[256];
  size_t      n;
  FILE       *fp;
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s.%d.txt", name, (int)rank)); /* one file per rank */
  PetscCall(PetscViewerASCIIOpen(PETSC_COMM_SELF, path, &v));
  PetscCall(PetscObjectView(obj, v));
  PetscCall(PetscViewerDestroy(&v));
  fp = fopen(path, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot read %s", path);
  n      = fread(buf, 1, sizeof(buf) - 1, fp);
  buf[n] = 0;
  fclose(fp);
  remove(path);
  *has = strstr(buf, text) ? PETSC_TRUE : PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetOptions(const char *const kv[][2], PetscBool set)
{
  PetscFunctionBegin;
  for (int i = 0; kv[i][0]; i++) {
    if (set)
      PetscCall(PetscOptionsSetValue(NULL, kv[i][0], kv[i][1]));
    else
      PetscCall(PetscOptionsClearValue(NULL, kv[i][0]));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestSampler(void)
{
  const char *const opts[][2] = {{"-a_pattern_type", "plain"},
                                 {"-a_yarn_kc", "50"},
                                 {"-a_sampler_terms", "zero,sx"},
                                 {"-a_sampler_n1", "3"},
                                 {"-a_sampler_family", "woven"},
                                 {"-a_sampler_output", "prefix_a.h5"},
                                 {"-a_sampler_overwrite", NULL},
                                 {"-a_sampler_progress", "1000"},
                                 {"-a_sampler_reference", "relax"},
                                 {"-a_reference_max_evals", "6"},
                                 {"-a_reference_output", "prefix_a.pyp"},
                                 {"-a_micro_max_time", "58"},
                                 {"-a_periodic_pair_margin", "1.07"},
                                 {NULL, NULL}};
  HylcSampler       S;
  HylcPattern       pat;
  HylcMicro         micro;
  HylcPeriodic      P;
  HylcPatternType   type;
  PetscBool         same, has;
  PetscMPIInt       rank;
  long              n;
  HylcSampleRecord *recs;
  unsigned char    *done;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  PetscCall(SetOptions(opts, PETSC_TRUE));
  PetscCall(HylcSamplerCreate(PETSC_COMM_WORLD, &S));
  PetscCall(HylcSamplerSetOptionsPrefix(S, "a_"));
  PetscCall(HylcSamplerSetFromOptions(S));
  PetscCall(HylcSamplerGetPattern(S, &pat));
  PetscCall(HylcPatternGetType(pat, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNPLAIN, &same));
  HYLC_CHECK(same, "-a_pattern_type plain: the sampler's pattern is %s", type);
  PetscCall(HylcSamplerGetMicro(S, &micro));
  PetscCall(ViewContains((PetscObject)micro, "prefix_a_micro", "wall-time cap 58 s", &has));
  HYLC_CHECK(has, "-a_micro_max_time 58 was not read by the sampler's solver");
  PetscCall(HylcMicroGetPeriodic(micro, &P));
  PetscCall(ViewContains((PetscObject)P, "prefix_a_periodic", "pair margin 1.07", &has));
  HYLC_CHECK(has, "-a_periodic_pair_margin 1.07 was not read by the solver's tile");
  PetscCall(HylcSamplerSetUp(S)); /* refuses any -a_ option not read */
  PetscCall(HylcSamplerRun(S));
  PetscCall(HylcSamplerDestroy(&S));
  PetscCall(SetOptions(opts, PETSC_FALSE));
  if (!rank) {
    FILE *fp = fopen("prefix_a.pyp", "r");
    HYLC_CHECK(fp, "-a_reference_output prefix_a.pyp was not written");
    if (fp) fclose(fp);
    PetscCall(HylcSamplesReadHDF5("prefix_a.h5", &n, &recs, &done, NULL));
    HYLC_CHECK(n == 4, "-a_sampler_terms zero,sx -a_sampler_n1 3: %ld samples, expected 4", n);
    for (long k = 0; k < n; k++) HYLC_CHECK(done[k] && recs[k].status == 0, "sample %ld: done %d, status %d", k, (int)done[k], recs[k].status);
    PetscCall(PetscFree(recs));
    PetscCall(PetscFree(done));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestCalibrate(void)
{
  const char *const opts[][2] = {{"-c_pattern_file", "prefix_a.pyp"},
                                 {"-c_yarn_kc", "35"},
                                 {"-c_calibrate_target", "prefix_a.h5"},
                                 {"-c_calibrate_params", "kc"},
                                 {"-c_calibrate_max_it", "3"},
                                 {"-c_calibrate_reference", "none"},
                                 {"-c_sampler_family", "woven"},
                                 {"-c_reference_max_evals", "6"},
                                 {"-c_micro_max_time", "59"},
                                 {"-c_periodic_pair_margin", "1.08"},
                                 {NULL, NULL}};
  HylcCalibrate     C;
  HylcMicro         micro;
  HylcPeriodic      P;
  PetscReal         p0[HYLC_CALIBRATE_NPARAM], p1[HYLC_CALIBRATE_NPARAM], f0, f1;
  PetscInt          its, m;
  PetscBool         has;

  PetscFunctionBegin;
  PetscCall(SetOptions(opts, PETSC_TRUE));
  PetscCall(HylcCalibrateCreate(PETSC_COMM_WORLD, &C));
  PetscCall(HylcCalibrateSetOptionsPrefix(C, "c_"));
  PetscCall(HylcCalibrateSetFromOptions(C));
  PetscCall(HylcCalibrateGetMicro(C, &micro));
  PetscCall(ViewContains((PetscObject)micro, "prefix_c_micro", "wall-time cap 59 s", &has));
  HYLC_CHECK(has, "-c_micro_max_time 59 was not read by the calibration's solver");
  PetscCall(HylcMicroGetPeriodic(micro, &P));
  PetscCall(ViewContains((PetscObject)P, "prefix_c_periodic", "pair margin 1.08", &has));
  HYLC_CHECK(has, "-c_periodic_pair_margin 1.08 was not read by the solver's tile");
  PetscCall(HylcCalibrateSetUp(C)); /* refuses any -c_ option not read */
  PetscCall(HylcCalibrateGetSize(C, &m));
  HYLC_CHECK(m == 4, "the target prefix_a.h5 gave %" PetscInt_FMT " samples, expected 4", m);
  PetscCall(HylcCalibrateSolve(C));
  PetscCall(HylcCalibrateGetParameters(C, p0, p1));
  PetscCall(HylcCalibrateGetObjective(C, &f0, &f1, &its));
  HYLC_CHECK_CLOSE(p0[3], 35, 1e-12); /* -c_yarn_kc */
  HYLC_CHECK(f1 < 0.1 * f0 && PetscAbsReal(p1[3] / 50 - 1) < 0.05, "kc from 35 to %g (target 50), objective %g -> %g", (double)p1[3], (double)f0, (double)f1);
  PetscCall(HylcCalibrateDestroy(&C));
  PetscCall(SetOptions(opts, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestSampler());
  PetscCall(TestCalibrate());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
