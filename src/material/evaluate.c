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

/*@C
  HylcMaterialUniaxial - The homogeneous uniaxial tension state of the material (hylcmat_uniaxial(),
  docs/fabric-uniaxial.md): the stretch s along the material x axis (dir 0: sx = s) or y axis (dir 1:
  sy = s), bending zero, Psi minimized over the two free strains (sa and the other stretch), and
  T = dPsi/ds there, the force per unit width of a strip in its homogeneous central zone. Not collective;
  thread-safe; no allocation.

  Input Parameters:
+ m     - the material
. dir   - 0 (x; HYLC_UNIAXIAL_X of include/hylc/micro.h) or 1 (y)
. s     - the stretch, in [0, 1) and within the table's range of the stretch's 1D term
- guess - the starting lateral strains ((sa, sy) for x, (sa, sx) for y), e.g. those of a nearby s on a loading
          path; NULL: the lowest point of a grid of the lateral strains (hylcmat_uniaxial())

  Output Parameters:
+ T         - dPsi/ds (N/m; may be NULL)
. lateral   - the lateral strains of the state ((sa, sy) for x, (sa, sx) for y; may be NULL)
. psi       - Psi there (J/m^2; may be NULL)
- converged - whether the minimization converged (may be NULL: then not converging is an error,
              PETSC_ERR_NOT_CONVERGED; otherwise the outputs are the last iterate's)

  Notes:
  A bad direction or stretch is an error (PETSC_ERR_ARG_OUTOFRANGE) whose message names the value and the
  allowed range.

  Level: intermediate

.seealso: HylcMaterialEvaluate(), HylcMicroSolveUniaxial()
@*/
PetscErrorCode HylcMaterialUniaxial(HylcMaterial m, PetscInt dir, PetscReal s, const PetscReal guess[2], PetscReal *T, PetscReal lateral[2], PetscReal *psi, PetscBool *converged)
{
  hylcmat_uniaxial_state st;
  char                   err[512];
  int                    r;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  r = hylcmat_uniaxial(m->hm, (int)dir, (double)s, guess, &st, err, sizeof(err));
  if (converged) *converged = (PetscBool)(r == HYLCMAT_OK);
  if (r == HYLCMAT_ERR_NOCONV && converged) r = HYLCMAT_OK;
  PetscCheck(!r, PETSC_COMM_SELF, HylcMaterialErrorCode_Private(r), "%s", err[0] ? err : hylcmat_strerror(r));
  if (T) *T = st.T;
  if (lateral) lateral[0] = st.lateral[0], lateral[1] = st.lateral[1];
  if (psi) *psi = st.psi;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMaterialPathState - The homogeneous state of the table on a load path (hylcmat_path_state(), include/hylcmat.h:
  uniaxial tension at any angle, equibiaxial tension, shear, bending), the path's value s prescribed and Psi
  minimized over its free strains. Not collective; no allocation.

  Input Parameters:
+ m     - the material
. path  - the load path
. s     - the prescribed value (stretch, sa, or curvature in 1/m)
- guess - the starting free strains (those of a nearby s along a loading path), or NULL for the lowest point of
          a grid of them

  Output Parameters:
+ res       - the state (the path's force d(min Psi)/ds, the free strains, the strain, Psi, the gradient)
- converged - whether the minimization converged (may be NULL: then not converging is an error)

  Notes:
  A bad path or value is an error (PETSC_ERR_ARG_OUTOFRANGE) whose message names it.

  Level: intermediate

.seealso: HylcMaterialUniaxial(), HylcMicroSolvePath()
@*/
PetscErrorCode HylcMaterialPathState(HylcMaterial m, const hylcmat_path *path, PetscReal s, const PetscReal guess[], hylcmat_path_result *res, PetscBool *converged)
{
  char err[512];
  int  r;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(m, HYLC_MATERIAL_CLASSID, 1);
  r = hylcmat_path_state(m->hm, path, (double)s, guess, res, err, sizeof(err));
  if (converged) *converged = (PetscBool)(r == HYLCMAT_OK);
  if (r == HYLCMAT_ERR_NOCONV && converged) r = HYLCMAT_OK;
  PetscCheck(!r, PETSC_COMM_SELF, HylcMaterialErrorCode_Private(r), "%s", err[0] ? err : hylcmat_strerror(r));
  PetscFunctionReturn(PETSC_SUCCESS);
}
