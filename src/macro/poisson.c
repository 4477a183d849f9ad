/* The Poisson midsurface (docs/method.md §1.4, (16), (17)): on a DMDA node grid, solve
   lap phi_k = div (R S)_k with the pure Neumann condition N . grad phi = N . (R S), for k = 1..3, with one
   symmetric positive semi-definite matrix (5-point Laplacian, ghost-node Neumann rows), CG with the
   constant null space removed, then shift so that the interpolated phi(0) = 0. */
#include <hylc/private/macroimpl.h>

PetscErrorCode HylcMidsurfacePoissonReset_Private(HylcMidsurface ms)
{
  PetscFunctionBegin;
  PetscCall(KSPDestroy(&ms->ksp));
  PetscCall(MatDestroy(&ms->A));
  PetscCall(DMDestroy(&ms->da));
  PetscCall(PetscFree(ms->phi));
  PetscCall(PetscFree(ms->grad));
  ms->its = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* G = R(xi) S, 3x2 row-major */
static void FieldRS(const HylcMacroStrain *m, const PetscReal xi[2], PetscReal G[6])
{
  double R[9];
  HylcMacroRotation(m->N, xi, R, NULL, NULL);
  for (int i = 0; i < 3; i++)
    for (int al = 0; al < 2; al++) G[2 * i + al] = R[3 * i] * m->S[al] + R[3 * i + 1] * m->S[2 + al];
}

/* Catmull-Rom weights for the nodes -1, 0, 1, 2 at parameter t */
static void CubicWeights(PetscReal t, PetscReal w[4])
{
  const PetscReal t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t3 + 2 * t2 - t);
  w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
  w[2] = 0.5 * (-3 * t3 + 4 * t2 + t);
  w[3] = 0.5 * (t3 - t2);
}

void HylcMidsurfaceInterpolate_Private(HylcMidsurface ms, const PetscReal *field, PetscInt nc, const PetscReal xi[2], PetscReal out[])
{
  PetscInt  base[2], np;
  PetscReal w[2][4];

  for (PetscInt c = 0; c < nc; c++) out[c] = 0;
  np = ms->interp == HYLC_MIDSURFACE_INTERP_BICUBIC ? 4 : 2;
  for (int d = 0; d < 2; d++) {
    const PetscReal u = (xi[d] - ms->origin[d]) / ms->h[d];
    /* cell index, clamped so the stencil stays on the grid (outside: polynomial extrapolation) */
    PetscInt i = (PetscInt)PetscFloorReal(u), lo = np == 4 ? 1 : 0, hi = np == 4 ? ms->M[d] - 3 : ms->M[d] - 2;
    i                 = PetscMax(lo, PetscMin(hi, i));
    const PetscReal t = u - i;
    if (np == 4) {
      CubicWeights(t, w[d]);
      base[d] = i - 1;
    } else {
      w[d][0] = 1 - t;
      w[d][1] = t;
      base[d] = i;
    }
  }
  for (PetscInt b = 0; b < np; b++)
    for (PetscInt a = 0; a < np; a++) {
      const PetscReal  wt = w[0][a] * w[1][b];
      const PetscReal *f  = field + nc * ((base[1] + b) * ms->M[0] + base[0] + a);
      for (PetscInt c = 0; c < nc; c++) out[c] += wt * f[c];
    }
}

static PetscErrorCode AssembleMatrix(HylcMidsurface ms)
{
  const PetscInt  M0 = ms->M[0], M1 = ms->M[1];
  const PetscReal hx = ms->h[0], hy = ms->h[1];

  PetscFunctionBegin;
  PetscCall(DMCreateMatrix(ms->da, &ms->A));
  for (PetscInt j = 0; j < M1; j++)
    for (PetscInt i = 0; i < M0; i++) {
      MatStencil      row = {.i = i, .j = j}, col[5];
      PetscScalar     v[5];
      PetscInt        nc = 0;
      const PetscBool bx = (PetscBool)(i == 0 || i == M0 - 1), by = (PetscBool)(j == 0 || j == M1 - 1);
      /* row scale s = wx wy hx hy (wx = 1/2 on x boundaries, likewise wy), and the sign flips -lap to SPD */
      const PetscReal s = (bx ? 0.5 : 1.0) * (by ? 0.5 : 1.0) * hx * hy;
      /* x part: interior (phi_{i-1} - 2 phi_i + phi_{i+1})/hx^2; boundary 2 (phi_nb - phi_i)/hx^2 (ghost node) */
      const PetscReal cx = (bx ? 2.0 : 1.0) * s / (hx * hx), cy = (by ? 2.0 : 1.0) * s / (hy * hy);
      PetscReal       diag = 0;
      if (i > 0) col[nc] = (MatStencil){.i = i - 1, .j = j}, v[nc++] = -cx, diag += cx;
      if (i < M0 - 1) col[nc] = (MatStencil){.i = i + 1, .j = j}, v[nc++] = -cx, diag += cx;
      if (j > 0) col[nc] = (MatStencil){.i = i, .j = j - 1}, v[nc++] = -cy, diag += cy;
      if (j < M1 - 1) col[nc] = (MatStencil){.i = i, .j = j + 1}, v[nc++] = -cy, diag += cy;
      col[nc] = row, v[nc++] = diag;
      PetscCall(MatSetValuesStencil(ms->A, 1, &row, nc, col, v, INSERT_VALUES));
    }
  PetscCall(MatAssemblyBegin(ms->A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(ms->A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(ms->A, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* right-hand sides of the three components: -s (div_h G + Neumann ghost terms) */
static PetscErrorCode AssembleRHS(HylcMidsurface ms, Vec b[3])
{
  const PetscInt  M0 = ms->M[0], M1 = ms->M[1];
  const PetscReal hx = ms->h[0], hy = ms->h[1];
  PetscScalar   **bb[3];

  PetscFunctionBegin;
  for (int k = 0; k < 3; k++) PetscCall(DMDAVecGetArray(ms->da, b[k], &bb[k]));
  for (PetscInt j = 0; j < M1; j++)
    for (PetscInt i = 0; i < M0; i++) {
      const PetscReal xi[2] = {ms->origin[0] + i * hx, ms->origin[1] + j * hy};
      const PetscReal xe[2] = {xi[0] + hx, xi[1]}, xw[2] = {xi[0] - hx, xi[1]};
      const PetscReal xn[2] = {xi[0], xi[1] + hy}, xs[2] = {xi[0], xi[1] - hy};
      const PetscBool bx = (PetscBool)(i == 0 || i == M0 - 1), by = (PetscBool)(j == 0 || j == M1 - 1);
      const PetscReal s = (bx ? 0.5 : 1.0) * (by ? 0.5 : 1.0) * hx * hy;
      PetscReal       G[6], Ge[6], Gw[6], Gn[6], Gs[6];
      FieldRS(&ms->strain, xi, G);
      FieldRS(&ms->strain, xe, Ge);
      FieldRS(&ms->strain, xw, Gw);
      FieldRS(&ms->strain, xn, Gn);
      FieldRS(&ms->strain, xs, Gs);
      for (int k = 0; k < 3; k++) {
        PetscReal f = (Ge[2 * k] - Gw[2 * k]) / (2 * hx) + (Gn[2 * k + 1] - Gs[2 * k + 1]) / (2 * hy);
        /* ghost node phi_{-1} = phi_1 - 2 hx G_x at i = 0, phi_{M} = phi_{M-2} + 2 hx G_x at i = M-1 */
        if (i == 0) f += 2 * G[2 * k] / hx;
        if (i == M0 - 1) f -= 2 * G[2 * k] / hx;
        if (j == 0) f += 2 * G[2 * k + 1] / hy;
        if (j == M1 - 1) f -= 2 * G[2 * k + 1] / hy;
        bb[k][j][i] = -s * f;
      }
    }
  for (int k = 0; k < 3; k++) PetscCall(DMDAVecRestoreArray(ms->da, b[k], &bb[k]));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* FD gradient of phi at the nodes: central inside, second-order one-sided on the boundary */
static PetscErrorCode ComputeGradient(HylcMidsurface ms)
{
  const PetscInt M0 = ms->M[0], M1 = ms->M[1];

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(6 * M0 * M1, &ms->grad));
  for (PetscInt j = 0; j < M1; j++)
    for (PetscInt i = 0; i < M0; i++) {
      const PetscInt id[2] = {i, j}, Md[2] = {M0, M1}, stride[2] = {1, M0}, node = j * M0 + i;
      for (int al = 0; al < 2; al++) {
        const PetscInt  st = stride[al], c = id[al];
        const PetscReal h = ms->h[al];
        for (int k = 0; k < 3; k++) {
          const PetscReal *p = ms->phi + k;
          PetscReal        d;
          if (c == 0)
            d = (-3 * p[3 * node] + 4 * p[3 * (node + st)] - p[3 * (node + 2 * st)]) / (2 * h);
          else if (c == Md[al] - 1)
            d = (3 * p[3 * node] - 4 * p[3 * (node - st)] + p[3 * (node - 2 * st)]) / (2 * h);
          else
            d = (p[3 * (node + st)] - p[3 * (node - st)]) / (2 * h);
          ms->grad[6 * node + 2 * k + al] = d;
        }
      }
    }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMidsurfacePoissonSetUp_Private(HylcMidsurface ms)
{
  MPI_Comm     comm = PetscObjectComm((PetscObject)ms);
  MatNullSpace nsp;
  Vec          b[3], x;
  PetscReal    lo[2], hi[2];
  const char  *prefix;
  char         kspprefix[256];
  PC           pc;

  PetscFunctionBegin;
  PetscCall(HylcMidsurfacePoissonReset_Private(ms));
  /* grid: the box with xi = 0 in it, plus 2 cells on every side */
  for (int d = 0; d < 2; d++) {
    lo[d]         = PetscMin(ms->lo[d], 0);
    hi[d]         = PetscMax(ms->hi[d], 0);
    ms->M[d]      = ms->grid;
    ms->h[d]      = (hi[d] - lo[d]) / (ms->grid - 5);
    ms->origin[d] = lo[d] - 2 * ms->h[d];
    PetscCheck(ms->h[d] > 0, comm, PETSC_ERR_USER_INPUT, "HylcMidsurface: the box [%g, %g] x [%g, %g] has zero width", (double)ms->lo[0], (double)ms->hi[0], (double)ms->lo[1], (double)ms->hi[1]);
  }
  PetscCall(PetscLogEventBegin(HYLC_MacroPoisson, ms, 0, 0, 0));
  PetscCall(DMDACreate2d(comm, DM_BOUNDARY_NONE, DM_BOUNDARY_NONE, DMDA_STENCIL_STAR, ms->M[0], ms->M[1], PETSC_DECIDE, PETSC_DECIDE, 1, 1, NULL, NULL, &ms->da));
  PetscCall(DMSetUp(ms->da));
  PetscCall(AssembleMatrix(ms));
  PetscCall(MatNullSpaceCreate(comm, PETSC_TRUE, 0, NULL, &nsp));
  PetscCall(MatSetNullSpace(ms->A, nsp));

  PetscCall(KSPCreate(comm, &ms->ksp));
  PetscCall(PetscObjectIncrementTabLevel((PetscObject)ms->ksp, (PetscObject)ms, 1));
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)ms, &prefix));
  PetscCall(PetscSNPrintf(kspprefix, sizeof(kspprefix), "%smacro_", prefix ? prefix : ""));
  PetscCall(KSPSetOptionsPrefix(ms->ksp, kspprefix));
  PetscCall(KSPSetOperators(ms->ksp, ms->A, ms->A));
  PetscCall(KSPSetType(ms->ksp, KSPCG));
  PetscCall(KSPGetPC(ms->ksp, &pc));
  PetscCall(PCSetType(pc, PCICC));
  PetscCall(PCFactorSetShiftType(pc, MAT_SHIFT_POSITIVE_DEFINITE));
  PetscCall(KSPSetTolerances(ms->ksp, 1e-12, 1e-300, PETSC_DEFAULT, 10000));
  PetscCall(KSPSetFromOptions(ms->ksp));

  for (int k = 0; k < 3; k++) PetscCall(DMCreateGlobalVector(ms->da, &b[k]));
  PetscCall(DMCreateGlobalVector(ms->da, &x));
  PetscCall(AssembleRHS(ms, b));
  PetscCall(PetscMalloc1(3 * ms->M[0] * ms->M[1], &ms->phi));
  for (int k = 0; k < 3; k++) {
    KSPConvergedReason reason;
    PetscInt           its;
    const PetscScalar *xa;
    /* the discrete flux balance holds only to O(h^2): project the rhs onto the range */
    PetscCall(MatNullSpaceRemove(nsp, b[k]));
    PetscCall(VecZeroEntries(x));
    PetscCall(KSPSolve(ms->ksp, b[k], x));
    PetscCall(KSPGetConvergedReason(ms->ksp, &reason));
    PetscCall(KSPGetIterationNumber(ms->ksp, &its));
    PetscCheck(reason > 0, comm, PETSC_ERR_NOT_CONVERGED, "HylcMidsurface: the Poisson solve of component %d did not converge (%s after %" PetscInt_FMT " iterations); see -macro_ksp_*", k, KSPConvergedReasons[reason], its);
    ms->its += its;
    PetscCall(VecGetArrayRead(x, &xa));
    for (PetscInt n = 0; n < ms->M[0] * ms->M[1]; n++) ms->phi[3 * n + k] = PetscRealPart(xa[n]);
    PetscCall(VecRestoreArrayRead(x, &xa));
  }
  /* phi(0) = 0 for the interpolant */
  {
    const PetscReal zero[2] = {0, 0};
    PetscReal       p0[3];
    HylcMidsurfaceInterpolate_Private(ms, ms->phi, 3, zero, p0);
    for (PetscInt n = 0; n < ms->M[0] * ms->M[1]; n++)
      for (int k = 0; k < 3; k++) ms->phi[3 * n + k] -= p0[k];
  }
  PetscCall(ComputeGradient(ms));
  for (int k = 0; k < 3; k++) PetscCall(VecDestroy(&b[k]));
  PetscCall(VecDestroy(&x));
  PetscCall(MatNullSpaceDestroy(&nsp));
  PetscCall(PetscLogEventEnd(HYLC_MacroPoisson, ms, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int HylcMacroPolarRotation(const double S[6], const double F[6], double R[9])
{
  /* M' = F A^T (3x2), Q = M' (M'^T M')^{-1/2}, R = [q1 q2 q1 x q2] */
  double Mp[6], C[3], Q[6];
  for (int i = 0; i < 3; i++)
    for (int be = 0; be < 2; be++) Mp[2 * i + be] = F[2 * i] * S[2 * be] + F[2 * i + 1] * S[2 * be + 1]; /* sum_al F_{i al} A_{be al} */
  C[0] = C[1] = C[2] = 0;                                                                                /* C = M'^T M' = [[C0, C1], [C1, C2]] */
  for (int i = 0; i < 3; i++) {
    C[0] += Mp[2 * i] * Mp[2 * i];
    C[1] += Mp[2 * i] * Mp[2 * i + 1];
    C[2] += Mp[2 * i + 1] * Mp[2 * i + 1];
  }
  const double det = C[0] * C[2] - C[1] * C[1];
  if (!(det > 0)) return -1;
  /* sqrt(C) = (C + sqrt(det) I) / sqrt(tr C + 2 sqrt(det)); Q = M' sqrt(C)^{-1} */
  const double sd = sqrt(det), t = sqrt(C[0] + C[2] + 2 * sd);
  const double P[3] = {(C[0] + sd) / t, C[1] / t, (C[2] + sd) / t}, dp = P[0] * P[2] - P[1] * P[1];
  const double Pi[3] = {P[2] / dp, -P[1] / dp, P[0] / dp};
  for (int i = 0; i < 3; i++) {
    Q[2 * i]     = Mp[2 * i] * Pi[0] + Mp[2 * i + 1] * Pi[1];
    Q[2 * i + 1] = Mp[2 * i] * Pi[1] + Mp[2 * i + 1] * Pi[2];
  }
  for (int i = 0; i < 3; i++) {
    R[3 * i]     = Q[2 * i];
    R[3 * i + 1] = Q[2 * i + 1];
  }
  R[2] = Q[2] * Q[5] - Q[4] * Q[3];
  R[5] = Q[4] * Q[1] - Q[0] * Q[5];
  R[8] = Q[0] * Q[3] - Q[2] * Q[1];
  return 0;
}
