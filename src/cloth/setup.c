/* The cloth's parallel layout: METIS partition of the (replicated) mesh, the owned triangles and their
   stencils, the vertex numbering of the global vectors, the scatter to the local (owned + ghost)
   coordinates, the COO pattern of the Hessian, and the constraints (clamps, pins, planar).

   Partition: METIS_PartMeshDual (triangles sharing an edge are adjacent) on rank 0, broadcast; a rank
   owns the triangles METIS gives it and the vertices of its node partition, renumbered so that each rank
   owns a contiguous block (rank order, then the original order). One rank: the identity. */
#include <hylc/private/clothimpl.h>
#include <metis.h>

PetscErrorCode HylcClothLayoutReset_Private(HylcCloth c)
{
  PetscFunctionBegin;
  PetscCall(PetscFree2(c->perm, c->iperm));
  PetscCall(PetscFree(c->vranges));
  PetscCall(PetscFree(c->elem));
  PetscCall(PetscFree(c->loc2glob));
  PetscCall(PetscFree(c->stencil));
  PetscCall(PetscFree(c->mask));
  PetscCall(PetscFree(c->rest));
  PetscCall(PetscFree4(c->xs, c->Es, c->gs, c->Hs));
  PetscCall(PetscFree2(c->fixed, c->xprescribed));
  PetscCall(PetscFree(c->coo));
  PetscCall(VecDestroy(&c->Xloc));
  PetscCall(VecScatterDestroy(&c->scatter));
  PetscCall(MatDestroy(&c->H));
  PetscCall(VecDestroy(&c->x));
  PetscCall(VecDestroy(&c->x0));
  PetscCall(VecDestroy(&c->xprev));
  PetscCall(HylcClothDynamicReset_Private(c));
  PetscCall(PetscFree(c->xgather));
  c->ne = c->nloc = 0;
  c->ncoo         = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcClothClampsReset_Private(HylcCloth c)
{
  PetscFunctionBegin;
  for (PetscInt k = 0; k < c->nclamp; k++) PetscCall(PetscFree(c->clamp[k].v));
  c->nclamp = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  A clamp: the vertices v (original numbering) move rigidly by load * disp (onlyz: only their z is held).
  A vertex index outside the mesh is an error naming it.
*/
PetscErrorCode HylcClothAddClamp_Private(HylcCloth c, PetscInt n, const PetscInt v[], const PetscReal disp[3], PetscBool onlyz)
{
  HylcClothClamp *k;

  PetscFunctionBegin;
  PetscCheck(c->nclamp < HYLC_CLOTH_MAX_CLAMPS, PetscObjectComm((PetscObject)c), PETSC_ERR_SUP, "at most %d clamps", HYLC_CLOTH_MAX_CLAMPS);
  PetscCheck(n > 0, PetscObjectComm((PetscObject)c), PETSC_ERR_USER_INPUT, "clamp %" PetscInt_FMT ": no vertex of the mesh lies in it (outside the mesh)", c->nclamp);
  for (PetscInt i = 0; i < n; i++)
    PetscCheck(v[i] >= 0 && v[i] < c->nv, PetscObjectComm((PetscObject)c), PETSC_ERR_USER_INPUT, "clamp %" PetscInt_FMT ": vertex %" PetscInt_FMT " is outside the mesh (%" PetscInt_FMT " vertices)", c->nclamp, v[i], c->nv);
  k = &c->clamp[c->nclamp++];
  PetscCall(PetscMalloc1(n, &k->v));
  PetscCall(PetscArraycpy(k->v, v, n));
  k->n = n;
  for (int i = 0; i < 3; i++) k->disp[i] = disp ? disp[i] : 0;
  k->onlyz = onlyz;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the fixed flags of the owned coordinates and their displacement per unit load, from the clamps and
   the planar constraint */
static PetscErrorCode Constraints(HylcCloth c)
{
  PetscInt nown = c->vend - c->vstart;

  PetscFunctionBegin;
  for (PetscInt i = 0; i < 3 * nown; i++) {
    c->fixed[i]       = 0;
    c->xprescribed[i] = 0;
  }
  if (c->planar)
    for (PetscInt i = 0; i < nown; i++) c->fixed[3 * i + 2] = 1;
  for (PetscInt k = 0; k < c->nclamp; k++) {
    const HylcClothClamp *cl = &c->clamp[k];
    for (PetscInt j = 0; j < cl->n; j++) {
      PetscInt g = c->perm[cl->v[j]];
      if (g < c->vstart || g >= c->vend) continue;
      for (int d = cl->onlyz ? 2 : 0; d < 3; d++) {
        c->fixed[3 * (g - c->vstart) + d]       = 1;
        c->xprescribed[3 * (g - c->vstart) + d] = cl->disp[d];
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* sets the prescribed coordinates of X: rest + load * displacement */
PetscErrorCode HylcClothApplyClamps_Private(HylcCloth c, Vec X)
{
  PetscScalar       *x;
  const PetscScalar *x0;
  PetscInt           nown = c->vend - c->vstart;

  PetscFunctionBegin;
  PetscCall(Constraints(c));
  PetscCall(VecGetArray(X, &x));
  PetscCall(VecGetArrayRead(c->x0, &x0));
  for (PetscInt i = 0; i < 3 * nown; i++)
    if (c->fixed[i]) x[i] = x0[i] + c->load * c->xprescribed[i];
  PetscCall(VecRestoreArrayRead(c->x0, &x0));
  PetscCall(VecRestoreArray(X, &x));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* METIS on rank 0: element and node parts */
static PetscErrorCode Partition(HylcCloth c, PetscInt *epart, PetscInt *npart)
{
  MPI_Comm comm = PetscObjectComm((PetscObject)c);

  PetscFunctionBegin;
  if (c->size == 1) {
    for (PetscInt t = 0; t < c->nt; t++) epart[t] = 0;
    for (PetscInt v = 0; v < c->nv; v++) npart[v] = 0;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!c->rank) {
    idx_t ne = (idx_t)c->nt, nn = (idx_t)c->nv, ncommon = 2, nparts = (idx_t)c->size, objval, *eptr, *eind, *ep, *np, opt[METIS_NOPTIONS];
    int   st;
    PetscCall(PetscMalloc4(ne + 1, &eptr, 3 * ne, &eind, ne, &ep, nn, &np));
    for (idx_t t = 0; t <= ne; t++) eptr[t] = 3 * t;
    for (idx_t t = 0; t < 3 * ne; t++) eind[t] = (idx_t)c->tri[t];
    METIS_SetDefaultOptions(opt);
    opt[METIS_OPTION_NUMBERING] = 0;
    opt[METIS_OPTION_SEED]      = 1;
    st                          = METIS_PartMeshDual(&ne, &nn, eptr, eind, NULL, NULL, &ncommon, &nparts, NULL, opt, &objval, ep, np);
    PetscCheck(st == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartMeshDual failed (%d)", st);
    for (idx_t t = 0; t < ne; t++) epart[t] = ep[t];
    for (idx_t v = 0; v < nn; v++) npart[v] = np[v];
    PetscCall(PetscFree4(eptr, eind, ep, np));
  }
  PetscCallMPI(MPI_Bcast(epart, c->nt, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(npart, c->nv, MPIU_INT, 0, comm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Builds the layout from the mesh (c->nv, nt, tri, uv): partition, stencils, scatter, Hessian pattern,
  vectors; x = x0 = the rest positions. The mesh's adjacency is checked here (hylcmat_mesh_create_uv):
  a non-manifold edge or a triangle of zero area is an error naming it. Collective.
*/
PetscErrorCode HylcClothBuild_Private(HylcCloth c)
{
  MPI_Comm      comm  = PetscObjectComm((PetscObject)c);
  hylcmat_mesh *hmesh = NULL;
  char          err[512];
  int           rc;
  PetscInt     *epart, *npart, *cnt, nown, *stglob;
  PetscInt     *rows, *cols;

  PetscFunctionBegin;
  PetscCall(HylcClothLayoutReset_Private(c));
  PetscCallMPI(MPI_Comm_rank(comm, &c->rank));
  PetscCallMPI(MPI_Comm_size(comm, &c->size));
  {
    int *tri;
    PetscCall(PetscMalloc1(3 * c->nt, &tri));
    for (PetscInt i = 0; i < 3 * c->nt; i++) tri[i] = (int)c->tri[i];
    rc = hylcmat_mesh_create_uv((int)c->nv, (int)c->nt, tri, c->uv, &hmesh, err, sizeof err);
    PetscCall(PetscFree(tri));
  }
  PetscCheck(!rc, comm, PETSC_ERR_USER_INPUT, "%s%s%s", c->meshFile[0] ? c->meshFile : "", c->meshFile[0] ? ": " : "", err);
  /* every vertex must belong to a triangle (a lone vertex would be a free, massless point) */
  {
    PetscInt *used;
    PetscCall(PetscCalloc1(c->nv, &used));
    for (PetscInt i = 0; i < 3 * c->nt; i++) used[c->tri[i]] = 1;
    for (PetscInt v = 0; v < c->nv; v++)
      if (!used[v]) {
        PetscCall(PetscFree(used));
        hylcmat_mesh_free(hmesh);
        SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s%svertex %" PetscInt_FMT " belongs to no triangle", c->meshFile[0] ? c->meshFile : "mesh", ": ", v + (c->meshFile[0] ? 1 : 0));
      }
    PetscCall(PetscFree(used));
  }
  PetscCall(PetscMalloc2(c->nt, &epart, c->nv, &npart));
  PetscCall(Partition(c, epart, npart));
  /* numbering: by part, then original index */
  PetscCall(PetscMalloc2(c->nv, &c->perm, c->nv, &c->iperm));
  PetscCall(PetscCalloc1(c->size + 1, &c->vranges));
  PetscCall(PetscCalloc1(c->size + 1, &cnt));
  for (PetscInt v = 0; v < c->nv; v++) c->vranges[npart[v] + 1]++;
  for (PetscMPIInt r = 0; r < c->size; r++) c->vranges[r + 1] += c->vranges[r];
  for (PetscInt v = 0; v < c->nv; v++) {
    PetscInt g  = c->vranges[npart[v]] + cnt[npart[v]]++;
    c->perm[v]  = g;
    c->iperm[g] = v;
  }
  PetscCall(PetscFree(cnt));
  c->vstart = c->vranges[c->rank];
  c->vend   = c->vranges[c->rank + 1];
  nown      = c->vend - c->vstart;
  /* owned elements, their stencils in the new numbering */
  c->ne = 0;
  for (PetscInt t = 0; t < c->nt; t++)
    if (epart[t] == c->rank) c->ne++;
  PetscCall(PetscMalloc1(c->ne, &c->elem));
  PetscCall(PetscMalloc1(6 * c->ne, &c->stencil));
  PetscCall(PetscMalloc1(c->ne, &c->mask));
  PetscCall(PetscMalloc1(c->ne, &c->rest));
  PetscCall(PetscMalloc1(6 * c->ne, &stglob));
  {
    PetscInt e = 0;
    for (PetscInt t = 0; t < c->nt; t++) {
      int v[6];
      if (epart[t] != c->rank) continue;
      c->elem[e] = t;
      rc         = hylcmat_mesh_element(hmesh, (int)t, v, &c->rest[e]);
      PetscCheck(!rc, comm, PETSC_ERR_LIB, "hylcmat_mesh_element(%" PetscInt_FMT "): %s", t, hylcmat_strerror(rc));
      c->mask[e] = 0;
      for (int k = 0; k < 6; k++) {
        stglob[6 * e + k] = v[k] >= 0 ? c->perm[v[k]] : -1;
        if (k >= 3 && v[k] >= 0) c->mask[e] |= 1 << (k - 3);
      }
      e++;
    }
  }
  hylcmat_mesh_free(hmesh);
  PetscCall(PetscFree2(epart, npart));
  /* local vertices: the sorted stencil vertices */
  {
    PetscInt *all, n = 0;
    PetscCall(PetscMalloc1(6 * c->ne, &all));
    for (PetscInt i = 0; i < 6 * c->ne; i++)
      if (stglob[i] >= 0) all[n++] = stglob[i];
    PetscCall(PetscSortRemoveDupsInt(&n, all));
    c->nloc = n;
    PetscCall(PetscMalloc1(PetscMax(n, 1), &c->loc2glob));
    PetscCall(PetscArraycpy(c->loc2glob, all, n));
    PetscCall(PetscFree(all));
    for (PetscInt i = 0; i < 6 * c->ne; i++) {
      PetscInt loc = -1;
      if (stglob[i] >= 0) PetscCall(PetscFindInt(stglob[i], c->nloc, c->loc2glob, &loc));
      c->stencil[i] = loc;
    }
  }
  PetscCall(PetscMalloc4(18 * c->ne, &c->xs, c->ne, &c->Es, 18 * c->ne, &c->gs, 324 * c->ne, &c->Hs));
  /* vectors and the scatter */
  PetscCall(VecCreateMPI(comm, 3 * nown, 3 * c->nv, &c->x));
  PetscCall(VecSetBlockSize(c->x, 3));
  PetscCall(VecDuplicate(c->x, &c->x0));
  {
    PetscScalar *x0;
    PetscCall(VecGetArray(c->x0, &x0));
    for (PetscInt i = 0; i < nown; i++)
      for (int d = 0; d < 3; d++) x0[3 * i + d] = c->X[3 * c->iperm[c->vstart + i] + d];
    PetscCall(VecRestoreArray(c->x0, &x0));
  }
  PetscCall(VecCopy(c->x0, c->x));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 3 * c->nloc, &c->Xloc));
  {
    IS is;
    PetscCall(ISCreateBlock(PETSC_COMM_SELF, 3, c->nloc, c->loc2glob, PETSC_COPY_VALUES, &is));
    PetscCall(VecScatterCreate(c->x, is, c->Xloc, NULL, &c->scatter));
    PetscCall(ISDestroy(&is));
  }
  PetscCall(PetscMalloc2(3 * nown, &c->fixed, 3 * nown, &c->xprescribed));
  PetscCall(Constraints(c));
  /* the COO pattern: each element's present vertices, all pairs, 3x3 blocks; then a 3x3 block per owned
     vertex (contact, inertia, the identity of fixed coordinates) */
  c->ncoo = 0;
  for (PetscInt e = 0; e < c->ne; e++) {
    PetscInt p = 3;
    for (int k = 0; k < 3; k++)
      if (c->mask[e] & (1 << k)) p++;
    c->ncoo += 9 * p * p;
  }
  c->ncoo += 9 * nown;
  PetscCall(PetscMalloc2(c->ncoo, &rows, c->ncoo, &cols));
  {
    PetscCount q = 0;
    for (PetscInt e = 0; e < c->ne; e++)
      for (int a = 0; a < 6; a++) {
        if (a >= 3 && !(c->mask[e] & (1 << (a - 3)))) continue;
        for (int i = 0; i < 3; i++)
          for (int b = 0; b < 6; b++) {
            if (b >= 3 && !(c->mask[e] & (1 << (b - 3)))) continue;
            for (int j = 0; j < 3; j++) {
              rows[q]   = 3 * stglob[6 * e + a] + i;
              cols[q++] = 3 * stglob[6 * e + b] + j;
            }
          }
      }
    for (PetscInt v = 0; v < nown; v++)
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
          rows[q]   = 3 * (c->vstart + v) + i;
          cols[q++] = 3 * (c->vstart + v) + j;
        }
  }
  PetscCall(PetscFree(stglob));
  PetscCall(MatCreate(comm, &c->H));
  PetscCall(MatSetSizes(c->H, 3 * nown, 3 * nown, 3 * c->nv, 3 * c->nv));
  PetscCall(MatSetType(c->H, MATAIJ));
  PetscCall(MatSetBlockSize(c->H, 3));
  PetscCall(MatSetPreallocationCOO(c->H, c->ncoo, rows, cols));
  PetscCall(PetscFree2(rows, cols));
  PetscCall(PetscMalloc1(c->ncoo, &c->coo));
  PetscCall(MatSetOption(c->H, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(c->H, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  PetscFunctionReturn(PETSC_SUCCESS);
}
