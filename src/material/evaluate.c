/* HylcMaterialEvaluate: the evaluation of the material model is hylcmat's (src/hylcmat/eval.c: exact
   limits at equal eigenvalues of II, the long double fallback for extreme values; docs/material.md). */
#include <hylc/private/materialimpl.h>

/*@C
  HylcMaterialEvaluate - Psi(s) (J/m^2), and if grad (hess) is not NULL its gradient (Hessian, 6x6
  row-major, symmetric) with respect to s = (sx, sa, sy, II00, II01, II11). Exact at equal eigenvalues of
  II (docs/material.md). For finite strains every result is finite: a value beyond the double range is
  returned as +-PETSC_MAX_REAL (docs/material.md, "Range"); NaN or infinite strains propagate.
  Not collective; thread-safe; no allocation.
@*/
PetscErrorCode HylcMaterialEvaluate(HylcMaterial m, const PetscReal s[6], PetscReal *psi, PetscReal grad[6], PetscReal hess[36])
{
  int r;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  PetscValidRealPointer(s, 2);
  r = hylcmat_eval(m->hm, s, psi, grad, hess);
  PetscCheck(r != HYLCMAT_ERR_NAN, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Psi or a derivative is NaN at the finite strain (%g, %g, %g, %g, %g, %g)", (double)s[0], (double)s[1], (double)s[2], (double)s[3], (double)s[4], (double)s[5]);
  PetscCheck(!r, PETSC_COMM_SELF, HylcMaterialErrorCode_Private(r), "%s", hylcmat_strerror(r));
  PetscFunctionReturn(PETSC_SUCCESS);
}
