/* The measured-cloth side of HylcMaterial (docs/measured-cloth.md): a table's strip at any angle and the
   table written as measured cloth; the work is hylcmat's (src/hylcmat/tension.c, measured_fit.c). */
#include <hylc/private/materialimpl.h>

/*@C
  HylcMaterialTension - The homogeneous strip state of the material cut at angle phi to its material x
  axis and stretched by s along its length (hylcmat_tension()): bending zero, Psi minimized over the two
  lateral unknowns (the lateral stretch and the shear between the deformed length and width), and
  T = dPsi/ds, the force per unit reference width. phi = 0 and pi/2 are HylcMaterialUniaxial()'s states,
  pi/4 the bias test. Not collective; thread-safe; no allocation.

  Input Parameters:
+ m     - the material
. phi   - the strip's angle (radians, from material x toward y)
. s     - the stretch along the strip, in [0, 1)
- guess - the starting (1 + lateral strain, shear), e.g. those of a nearby s on a loading path; NULL: the
          lowest point of a grid

  Output Parameters:
+ T         - the force per unit reference width (N/m; may be NULL)
. lateral   - the engineering strain across the strip and the shear, the cosine of the deformed angle
              between the length and the width (may be NULL)
- converged - whether the minimization converged (may be NULL: then not converging is an error,
              PETSC_ERR_NOT_CONVERGED)

  Level: intermediate

.seealso: HylcMaterialUniaxial(), HylcMaterialWriteMeasured()
@*/
PetscErrorCode HylcMaterialTension(HylcMaterial m, PetscReal phi, PetscReal s, const PetscReal guess[2], PetscReal *T, PetscReal lateral[2], PetscBool *converged)
{
  hylcmat_tension_state st;
  char                  err[512];
  int                   r;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  r = hylcmat_tension(m->hm, (double)phi, (double)s, guess, &st, err, sizeof(err));
  if (converged) *converged = (PetscBool)(r == HYLCMAT_OK);
  if (r == HYLCMAT_ERR_NOCONV && converged) r = HYLCMAT_OK;
  PetscCheck(!r, PETSC_COMM_SELF, HylcMaterialErrorCode_Private(r), "%s", err[0] ? err : hylcmat_strerror(r));
  if (T) *T = st.T;
  if (lateral) lateral[0] = st.lateral, lateral[1] = st.shear;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialWriteMeasured - Writes the material as a measured-cloth JSON (the data-driven format of
  Wang, O'Brien, Ramamoorthi 2011 that ARCSim reads): the least-squares data of hylcmat_measured_fit()
  (docs/measured-cloth.md, "Export"). Collective; rank 0 writes (atomically, as the other writers).

  Input Parameters:
+ m    - the material
- path - the output file

  Output Parameter:
. fit - (may be NULL; 5 values) the RMS and the largest (2 to 10 %) relative strip tension error of the
        export, its RMS relative bending moment error, the table's largest in-plane dPsi/ds at rest (N/m)
        and its largest dPsi/dII at rest (N): what the format cannot hold

  Level: intermediate

.seealso: HylcMaterialTension(), HylcMaterialWriteJSON()
@*/
PetscErrorCode HylcMaterialWriteMeasured(HylcMaterial m, const char path[], PetscReal fit[5])
{
  hylcmat_measured *mc;
  double            f[5];
  char              err[512], text[4096];
  int               r;
  size_t            n;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  r = hylcmat_measured_fit(m->hm, &mc, f, err, sizeof(err));
  PetscCheck(!r, PETSC_COMM_SELF, HylcMaterialErrorCode_Private(r), "%s", err[0] ? err : hylcmat_strerror(r));
  n = hylcmat_measured_format(mc, text, sizeof(text));
  hylcmat_measured_free(mc);
  PetscCheck(n < sizeof(text), PETSC_COMM_SELF, PETSC_ERR_PLIB, "The measured-cloth text is too long (%zu bytes)", n);
  PetscCall(HylcMaterialWriteBytes_Private(m, path, "measured-cloth", text, n));
  if (fit)
    for (int i = 0; i < 5; i++) fit[i] = f[i];
  PetscFunctionReturn(PETSC_SUCCESS);
}
