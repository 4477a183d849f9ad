/* Benchmark: fitting a full 23,250-sample file (the C4 plan of the woven family: 5 x 150 + 9 x 50 x 50
   samples plus the zero sample; a synthetic smooth Psi) on one core, from reading the HDF5 samples file
   to the tables, and writing them (HDF5 and JSON). Prints the total and the per-stage breakdown (read,
   MLS + finite differences, marching + monotone projections + residualization, rest, write).
   Target (issue 7): under 5 s. */
#include <hylc/fit.h>
#include <hylc/samples.h>
#include <petsctime.h>
#include <unistd.h>
#include "../unit/fittest.h"

static PetscErrorCode EventTime(PetscLogEvent e, PetscLogDouble *t)
{
  PetscEventPerfInfo info;

  PetscFunctionBegin;
  PetscCall(PetscLogEventGetPerfInfo(PETSC_DETERMINE, e, &info));
  *t = info.time;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  PetscInt          n, *term;
  PetscReal        *z, *psi;
  HylcSampleRecord *recs;
  unsigned char    *done;
  char              dir[] = "/tmp/hylc-bench-fit.XXXXXX", path[64];
  HylcFit           fit;
  PetscLogDouble    t0, t1, t2, t3, tMLS, tMon, tRun;
  HylcMaterial      mat;
  char              h5[64], json[64];

  PetscFunctionBegin;
  PetscCall(PetscLogDefaultBegin());
  PetscCall(HylcInitializePackage());
  FitTestMakeData("woven", 150, 50, -1, &n, &z, &psi, &term);
  PetscCall(PetscCalloc2(n, &recs, n, &done));
  for (PetscInt k = 0; k < n; k++) {
    recs[k].index = k;
    recs[k].term  = (int)term[k];
    for (int i = 0; i < 6; i++) recs[k].z[i] = z[6 * k + i];
    recs[k].psi = psi[k];
    done[k]     = 1;
  }
  PetscCheck(mkdtemp(dir), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "mkdtemp");
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/s.h5", dir));
  PetscCall(HylcSamplesWriteHDF5(path, n, recs, done, NULL, NULL, "-bench"));

  PetscCall(HylcFitCreate(PETSC_COMM_SELF, &fit));
  PetscCall(PetscTime(&t0));
  PetscCall(HylcFitSetInput(fit, path));
  PetscCall(PetscOptionsSetValue(NULL, "-fit_density", "0.3"));
  PetscCall(HylcFitSetFromOptions(fit));
  PetscCall(HylcFitSetUp(fit));
  PetscCall(PetscTime(&t1));
  PetscCall(HylcFitCompute(fit));
  PetscCall(PetscTime(&t2));
  PetscCall(PetscSNPrintf(h5, sizeof(h5), "%s/model.h5", dir));
  PetscCall(PetscSNPrintf(json, sizeof(json), "%s/model.json", dir));
  PetscCall(HylcFitSetOutputs(fit, h5, json));
  PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &mat));
  PetscCall(HylcFitRun(fit, mat)); /* the tables are computed: fills the material, writes both files */
  PetscCall(PetscTime(&t3));
  PetscCall(EventTime(HYLC_FitMLS, &tMLS));
  PetscCall(EventTime(HYLC_FitMonotone, &tMon));
  PetscCall(EventTime(HYLC_FitRun, &tRun));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "fit of %d samples (woven C4 plan, synthetic Psi), one core: %.3f s (%.3f s with writing the model)\n", (int)n, t2 - t0, t3 - t0));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  read HDF5 + checks     %.3f s\n", t1 - t0));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  MLS + differences      %.3f s\n", tMLS));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  marching + monotone    %.4f s\n", tMon));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  rest (f0, statistics)  %.3f s\n", tRun - tMLS - tMon));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "  write HDF5 + JSON      %.3f s\n", t3 - t2));
  PetscCall(HylcMaterialDestroy(&mat));
  PetscCall(HylcFitDestroy(&fit));
  unlink(h5);
  unlink(json);
  unlink(path);
  rmdir(dir);
  PetscCall(PetscFree2(recs, done));
  free(z);
  free(psi);
  free(term);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(Run());
  PetscCall(PetscFinalize());
  return 0;
}
