/* The cloth's energy, gradient and Hessian: the C8 shell elements of the owned triangles (hylcmat),
   gravity, the contact barrier of the supports and, in the dynamic mode, the inertia of the backward
   Euler step (the incremental potential). Prescribed coordinates have zero gradient and identity rows
   and columns in the Hessian.

   E = sum_t A_t Psi(z_t) + sum_v m_v (-g . x_v) + sum_v a_v kappa b(d_s(x_v))
       [+ sum_v m_v (|x_v - x_n - dt v_n|^2 / (2 dt^2) + c |x_v - x_n|^2 / (2 dt))]
   with m_v = rho_A a_v (a_v the lumped rest area), b the barrier of kernels.c and d_s the signed
   distance to each support. */
#include <hylc/private/clothimpl.h>

/* the local coordinates of every element's stencil */
static PetscErrorCode Stencils(HylcCloth c, Vec X)
{
  const PetscScalar *xl;

  PetscFunctionBegin;
  PetscCall(VecScatterBegin(c->scatter, X, c->Xloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c->scatter, X, c->Xloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(c->Xloc, &xl));
  for (PetscInt e = 0; e < c->ne; e++)
    for (int k = 0; k < 6; k++) {
      PetscInt l = c->stencil[6 * e + k];
      for (int d = 0; d < 3; d++) c->xs[18 * e + 3 * k + d] = l >= 0 ? xl[3 * l + d] : 0;
    }
  PetscCall(VecRestoreArrayRead(c->Xloc, &xl));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* an element error: a degenerate or non-finite deformed state is a state the solver must avoid (the
   energy is +inf there), anything else is an error naming the triangle */
static PetscErrorCode ElementError(HylcCloth c, int rc, PetscBool *infeasible)
{
  PetscFunctionBegin;
  *infeasible = PETSC_FALSE;
  if (!rc) PetscFunctionReturn(PETSC_SUCCESS);
  if (rc == HYLCMAT_ERR_DEGENERATE || rc == HYLCMAT_ERR_NONFINITE || rc == HYLCMAT_ERR_RANGE) {
    *infeasible = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  for (PetscInt e = 0; e < c->ne; e++) {
    double E;
    int    r = hylcmat_shell_eval(c->hm, &c->rest[e], c->xs + 18 * e, c->mask[e], 0, &E, NULL, NULL);
    PetscCheck(!r, PETSC_COMM_SELF, PETSC_ERR_LIB, "shell element of triangle %" PetscInt_FMT ": %s", c->elem[e], hylcmat_strerror(r));
  }
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "shell elements: %s", hylcmat_strerror(rc));
}

/* the vertex terms of an owned vertex: energy, gradient (3), Hessian (3x3; projected: the barrier's
   curvature term, negative semidefinite, dropped) */
static PetscReal VertexTerms(HylcCloth c, PetscInt i, const PetscScalar *x, const PetscScalar *xn, const PetscScalar *vn, PetscReal g[3], PetscReal H[9], PetscBool project)
{
  PetscInt  v = c->iperm[c->vstart + i];
  PetscReal a = c->vmass[v], m = c->rhoA * a, E = 0;

  if (g)
    for (int d = 0; d < 3; d++) g[d] = 0;
  if (H)
    for (int d = 0; d < 9; d++) H[d] = 0;
  for (int d = 0; d < 3; d++) {
    E -= m * c->gscale * c->g[d] * x[3 * i + d];
    if (g) g[d] -= m * c->gscale * c->g[d];
  }
  for (PetscInt s = 0; s < c->nsupport; s++) {
    double p[3] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]}, dg[3], dh[9], b1, b2, dist, b;
    dist        = HylcClothSupportDistance_Private(&c->support[s], p, dg, dh);
    if (dist >= c->barrierDist) continue;
    b = HylcClothBarrier_Private(dist, c->barrierDist, &b1, &b2);
    E += a * c->kappaB * b;
    if (g)
      for (int d = 0; d < 3; d++) g[d] += a * c->kappaB * b1 * dg[d];
    if (H)
      for (int d = 0; d < 3; d++)
        for (int e = 0; e < 3; e++) H[3 * d + e] += a * c->kappaB * (b2 * dg[d] * dg[e] + (project ? 0 : b1 * dh[3 * d + e]));
  }
  if (c->dynamic) {
    PetscReal ia = 1 / c->dtcur;
    for (int d = 0; d < 3; d++) {
      PetscReal r = x[3 * i + d] - xn[3 * i + d] - c->dtcur * vn[3 * i + d], q = x[3 * i + d] - xn[3 * i + d];
      E += 0.5 * m * ia * ia * r * r + 0.5 * m * c->damping * ia * q * q;
      if (g) g[d] += m * ia * ia * r + m * c->damping * ia * q;
      if (H) H[4 * d] += m * ia * (ia + c->damping);
    }
  }
  return E;
}

/*
  E (+inf for a state the element or the barrier refuses: a flat or non-finite triangle, a vertex on or
  behind a support) and, if G, the gradient with zeros at the prescribed coordinates. Collective.
*/
PetscErrorCode HylcClothEnergy_Private(HylcCloth c, Vec X, PetscReal *E, Vec G)
{
  int                rc;
  PetscBool          bad;
  PetscReal          El = 0;
  const PetscScalar *x, *xn = NULL, *vn = NULL;
  PetscScalar       *gl = NULL, *gg = NULL;
  PetscInt           nown = c->vend - c->vstart;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_ClothAssemble, c, 0, 0, 0));
  PetscCall(Stencils(c, X));
  rc = hylcmat_shell_eval_batch(c->hm, (size_t)c->ne, c->rest, c->xs, c->mask, 0, c->Es, G ? c->gs : NULL, NULL);
  PetscCall(ElementError(c, rc, &bad));
  if (!bad)
    for (PetscInt e = 0; e < c->ne; e++) El += c->Es[e];
  else
    El = PETSC_INFINITY;
  if (G) {
    PetscCall(VecZeroEntries(c->Xloc));
    PetscCall(VecGetArray(c->Xloc, &gl));
    if (!bad)
      for (PetscInt e = 0; e < c->ne; e++)
        for (int k = 0; k < 6; k++) {
          PetscInt l = c->stencil[6 * e + k];
          if (l < 0) continue;
          for (int d = 0; d < 3; d++) gl[3 * l + d] += c->gs[18 * e + 3 * k + d];
        }
    PetscCall(VecRestoreArray(c->Xloc, &gl));
    PetscCall(VecZeroEntries(G));
    PetscCall(VecScatterBegin(c->scatter, c->Xloc, G, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(c->scatter, c->Xloc, G, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecGetArray(G, &gg));
  }
  PetscCall(VecGetArrayRead(X, &x));
  if (c->dynamic) {
    PetscCall(VecGetArrayRead(c->xn, &xn));
    PetscCall(VecGetArrayRead(c->vn, &vn));
  }
  for (PetscInt i = 0; i < nown; i++) {
    PetscReal gv[3];
    El += VertexTerms(c, i, x, xn, vn, gv, NULL, PETSC_FALSE);
    if (gg)
      for (int d = 0; d < 3; d++) gg[3 * i + d] = c->fixed[3 * i + d] ? 0 : gg[3 * i + d] + gv[d];
  }
  if (c->dynamic) {
    PetscCall(VecRestoreArrayRead(c->xn, &xn));
    PetscCall(VecRestoreArrayRead(c->vn, &vn));
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  if (G) PetscCall(VecRestoreArray(G, &gg));
  if (PetscIsInfOrNanReal(El)) El = PETSC_INFINITY;
  PetscCall(MPIU_Allreduce(&El, E, 1, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)c)));
  if (HylcClothInfeasible(*E)) *E = PETSC_INFINITY; /* the same value on any number of ranks */
  PetscCall(PetscLogEventEnd(HYLC_ClothAssemble, c, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The Hessian at X into H (the COO pattern of HylcClothBuild_Private): every element Hessian exact or
  projected to PSD (hylcmat's HYLCMAT_SHELL_PSD), the vertex terms, identity rows and columns at the
  prescribed coordinates. Collective.
*/
PetscErrorCode HylcClothHessian_Private(HylcCloth c, Vec X, PetscBool project, Mat H)
{
  int                rc;
  PetscBool          bad;
  PetscCount         q = 0;
  const PetscScalar *x, *xn = NULL, *vn = NULL;
  PetscInt           nown = c->vend - c->vstart, *fl;
  PetscScalar       *fa;

  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_ClothAssemble, c, 0, 0, 0));
  PetscCall(Stencils(c, X));
  rc = hylcmat_shell_eval_batch(c->hm, (size_t)c->ne, c->rest, c->xs, c->mask, project ? HYLCMAT_SHELL_PSD : 0, c->Es, c->gs, c->Hs);
  PetscCall(ElementError(c, rc, &bad));
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Hessian requested at a state with a degenerate triangle");
  /* the fixed flags of the local vertices (ghosts included) through the scatter */
  PetscCall(VecGetArray(c->Xloc, &fa));
  {
    Vec          F;
    PetscScalar *f;
    PetscCall(VecDuplicate(X, &F));
    PetscCall(VecGetArray(F, &f));
    for (PetscInt i = 0; i < 3 * nown; i++) f[i] = c->fixed[i];
    PetscCall(VecRestoreArray(F, &f));
    PetscCall(VecRestoreArray(c->Xloc, &fa));
    PetscCall(VecScatterBegin(c->scatter, F, c->Xloc, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(c->scatter, F, c->Xloc, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecDestroy(&F));
    PetscCall(VecGetArray(c->Xloc, &fa));
  }
  PetscCall(PetscMalloc1(3 * PetscMax(c->nloc, 1), &fl));
  for (PetscInt i = 0; i < 3 * c->nloc; i++) fl[i] = fa[i] != 0;
  PetscCall(VecRestoreArray(c->Xloc, &fa));
  for (PetscInt e = 0; e < c->ne; e++) {
    const PetscReal *He = c->Hs + 324 * e;
    for (int a = 0; a < 6; a++) {
      PetscInt la = c->stencil[6 * e + a];
      if (la < 0) continue;
      for (int i = 0; i < 3; i++)
        for (int b = 0; b < 6; b++) {
          PetscInt lb = c->stencil[6 * e + b];
          if (lb < 0) continue;
          for (int j = 0; j < 3; j++) c->coo[q++] = (fl[3 * la + i] || fl[3 * lb + j]) ? 0 : He[(3 * a + i) * 18 + 3 * b + j];
        }
    }
  }
  PetscCall(PetscFree(fl));
  PetscCall(VecGetArrayRead(X, &x));
  if (c->dynamic) {
    PetscCall(VecGetArrayRead(c->xn, &xn));
    PetscCall(VecGetArrayRead(c->vn, &vn));
  }
  for (PetscInt i = 0; i < nown; i++) {
    PetscReal Hv[9];
    (void)VertexTerms(c, i, x, xn, vn, NULL, Hv, project);
    for (int d = 0; d < 3; d++)
      for (int e = 0; e < 3; e++) {
        PetscBool fd = c->fixed[3 * i + d] ? PETSC_TRUE : PETSC_FALSE, fe = c->fixed[3 * i + e] ? PETSC_TRUE : PETSC_FALSE;
        c->coo[q++] = (fd || fe) ? (d == e ? 1.0 : 0.0) : Hv[3 * d + e];
      }
  }
  if (c->dynamic) {
    PetscCall(VecRestoreArrayRead(c->xn, &xn));
    PetscCall(VecRestoreArrayRead(c->vn, &vn));
  }
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(MatSetValuesCOO(H, c->coo, INSERT_VALUES));
  PetscCall(PetscLogEventEnd(HYLC_ClothAssemble, c, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Whether the straight path X0 -> X1 keeps every vertex clear of every support: the signed distance is
  convex along the path (a convex support), so a vertex is clear when it stays positive at its minimum,
  which a golden-section search brackets (with the 1-Lipschitz bound closing the gap). Collective.
*/
PetscErrorCode HylcClothFeasible_Private(HylcCloth c, Vec X0, Vec X1, PetscBool *ok)
{
  const PetscScalar *a, *b;
  PetscInt           nown = c->vend - c->vstart;
  PetscBool          good = PETSC_TRUE;

  PetscFunctionBegin;
  if (!c->nsupport) {
    *ok = PETSC_TRUE;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(VecGetArrayRead(X0, &a));
  PetscCall(VecGetArrayRead(X1, &b));
  for (PetscInt i = 0; i < nown && good; i++) {
    double p0[3] = {a[3 * i], a[3 * i + 1], a[3 * i + 2]}, p1[3] = {b[3 * i], b[3 * i + 1], b[3 * i + 2]}, dl;
    dl = PetscSqrtReal((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]) + (p1[2] - p0[2]) * (p1[2] - p0[2]));
    for (PetscInt s = 0; s < c->nsupport && good; s++) {
      const HylcClothSupport *sp = &c->support[s];
      double                  d0 = HylcClothSupportDistance_Private(sp, p0, NULL, NULL), d1 = HylcClothSupportDistance_Private(sp, p1, NULL, NULL);
      if (d1 <= 0 || d0 <= 0) {
        good = PETSC_FALSE;
        break;
      }
      if (sp->kind == 0 || d0 - dl > 0 || d1 - dl > 0) continue; /* linear, or too far to reach it */
      {
        double lo = 0, hi = 1, g = 0.5 * (PetscSqrtReal(5.0) - 1), m1, m2, f1, f2, p[3];
        for (int it = 0; it < 200; it++) {
          m1 = hi - g * (hi - lo);
          m2 = lo + g * (hi - lo);
          for (int d = 0; d < 3; d++) p[d] = p0[d] + m1 * (p1[d] - p0[d]);
          f1 = HylcClothSupportDistance_Private(sp, p, NULL, NULL);
          for (int d = 0; d < 3; d++) p[d] = p0[d] + m2 * (p1[d] - p0[d]);
          f2 = HylcClothSupportDistance_Private(sp, p, NULL, NULL);
          if (f1 <= 0 || f2 <= 0) {
            good = PETSC_FALSE;
            break;
          }
          if (PetscMin(f1, f2) - (hi - lo) * dl > 0) break; /* the minimum is positive */
          if (f1 < f2)
            hi = m2;
          else
            lo = m1;
        }
      }
    }
  }
  PetscCall(VecRestoreArrayRead(X0, &a));
  PetscCall(VecRestoreArrayRead(X1, &b));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &good, 1, MPIU_BOOL, MPI_LAND, PetscObjectComm((PetscObject)c)));
  *ok = good;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The force the clamp exerts on the cloth, summed over its vertices: the gradient of the elastic and
  vertex terms at the clamped coordinates (all three components, whatever is fixed). Collective.
*/
PetscErrorCode HylcClothReaction_Private(HylcCloth c, Vec X, PetscInt k, PetscReal F[3])
{
  PetscInt *fixedSave, nown = c->vend - c->vstart;
  Vec       G;
  PetscReal E, Fl[3] = {0, 0, 0};

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(3 * nown, &fixedSave));
  PetscCall(PetscArraycpy(fixedSave, c->fixed, 3 * nown));
  for (PetscInt i = 0; i < 3 * nown; i++) c->fixed[i] = 0;
  PetscCall(VecDuplicate(X, &G));
  PetscCall(HylcClothEnergy_Private(c, X, &E, G));
  PetscCall(PetscArraycpy(c->fixed, fixedSave, 3 * nown));
  PetscCall(PetscFree(fixedSave));
  {
    const PetscScalar    *g;
    const HylcClothClamp *cl = &c->clamp[k];
    PetscCall(VecGetArrayRead(G, &g));
    for (PetscInt j = 0; j < cl->n; j++) {
      PetscInt gi = c->perm[cl->v[j]];
      if (gi < c->vstart || gi >= c->vend) continue;
      for (int d = 0; d < 3; d++) Fl[d] += g[3 * (gi - c->vstart) + d];
    }
    PetscCall(VecRestoreArrayRead(G, &g));
  }
  PetscCall(VecDestroy(&G));
  PetscCall(MPIU_Allreduce(Fl, F, 3, MPIU_REAL, MPIU_SUM, PetscObjectComm((PetscObject)c)));
  /* at equilibrium the clamp's force on the cloth balances the cloth's: F = +dE/dx_clamp */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the positions X gathered on every rank in the original numbering into c->xgather (nv x 3) */
PetscErrorCode HylcClothGather_Private(HylcCloth c, Vec X)
{
  Vec                all;
  VecScatter         sc;
  const PetscScalar *a;

  PetscFunctionBegin;
  if (!c->xgather) PetscCall(PetscMalloc1(3 * c->nv, &c->xgather));
  PetscCall(VecScatterCreateToAll(X, &sc, &all));
  PetscCall(VecScatterBegin(sc, X, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, X, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(all, &a));
  for (PetscInt g = 0; g < c->nv; g++)
    for (int d = 0; d < 3; d++) c->xgather[3 * c->iperm[g] + d] = a[3 * g + d];
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecDestroy(&all));
  PetscCall(VecScatterDestroy(&sc));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the strains (nt x 6, original triangle order) at the gathered positions c->xgather, on every rank */
PetscErrorCode HylcClothStrains_Private(HylcCloth c, Vec X, PetscReal *z)
{
  hylcmat_mesh *hmesh;
  char          err[512];
  int           rc, *tri;

  PetscFunctionBegin;
  PetscCall(HylcClothGather_Private(c, X));
  PetscCall(PetscMalloc1(3 * c->nt, &tri));
  for (PetscInt i = 0; i < 3 * c->nt; i++) tri[i] = (int)c->tri[i];
  rc = hylcmat_mesh_create_uv((int)c->nv, (int)c->nt, tri, c->uv, &hmesh, err, sizeof err);
  PetscCall(PetscFree(tri));
  PetscCheck(!rc, PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", err);
  rc = hylcmat_mesh_strains(hmesh, c->xgather, z, err, sizeof err);
  hylcmat_mesh_free(hmesh);
  PetscCheck(!rc, PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", err);
  PetscFunctionReturn(PETSC_SUCCESS);
}
