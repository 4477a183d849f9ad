/* HylcFitRun: the fitted tables into a HylcMaterial, and the output files. (The only part of the fit
   that needs the material; the pipeline itself is HylcFitCompute.) */
#include <hylc/private/fitimpl.h>

/*@C
  HylcFitRun - Runs the fit (HylcFitCompute) and fills the material: constant f0, strain scale, area
  density and every fitted term (terms of the material that were not fitted are left as they are).
  Then writes -fit_output (HDF5; the options database as provenance) and -fit_json when set.
  Collective on the material's communicator (the files are written by its rank 0).
@*/
PetscErrorCode HylcFitRun(HylcFit fit, HylcMaterial mat)
{
  PetscReal scale[5];

  PetscFunctionBegin;
  PetscValidHeaderSpecific(fit, HYLC_FIT_CLASSID, 1);
  PetscValidPointer(mat, 2);
  PetscCall(HylcFitCompute(fit));
  PetscCall(HylcFitGetStrainScale(fit, scale));
  PetscCall(HylcMaterialSetStrainScale(mat, scale));
  PetscCall(HylcMaterialSetConstant(mat, fit->f0));
  PetscCall(HylcMaterialSetDensity(mat, fit->rhoA));
  for (int c = 0; c < 5; c++)
    if (fit->has[1 + c]) PetscCall(HylcMaterialSet1D(mat, &fit->s1[c]));
  for (int t = 6; t < HYLC_PLAN_NTERM; t++)
    if (fit->has[t]) PetscCall(HylcMaterialSet2D(mat, &fit->s2[t - 6]));
  for (int t = HYLC_PLAN_NTERM; t < HYLC_PLAN_NTERM3; t++)
    if (fit->has[t]) PetscCall(HylcMaterialSet3D(mat, &fit->s3[t - HYLC_PLAN_NTERM]));
  if (fit->output[0]) PetscCall(HylcMaterialWriteHDF5(mat, fit->output, NULL));
  if (fit->json[0]) {
    char left[128] = "";
    PetscCall(HylcMaterialWriteJSON(mat, fit->json));
    for (int t = HYLC_PLAN_NTERM; t < HYLC_PLAN_NTERM3; t++)
      if (fit->has[t]) {
        PetscCall(PetscStrlcat(left, left[0] ? ", " : "", sizeof(left)));
        PetscCall(PetscStrlcat(left, HylcPlanTermName(t), sizeof(left)));
      }
    if (left[0])
      PetscCall(PetscPrintf(PetscObjectComm((PetscObject)mat), "[fit] %s keeps the paper's terms (ARCSim-HYLC's format); it leaves out the 3D terms %s, which the HDF5 table%s%s holds (docs/material.md, \"Three-strain terms\")\n", fit->json, left,
                            fit->output[0] ? " " : "", fit->output));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
