/* The cloth's rest mesh: the specimens' generated meshes (a strip, a disc) and .obj files, and the
   material coordinates of every triangle corner.

   The generated meshes are an equilateral-type lattice: rows of vertices parallel to x, every other row
   shifted by half a spacing, so that the edges run in three directions 60 degrees apart and no diagonal
   is preferred. On such a lattice (and on its affine images) the dihedral-angle II of the C8 element
   converges at order 2 triangle by triangle; on a criss-cross mesh (squares cut by both diagonals) it
   does not (rms error 71 % of 1/rho on a cylinder of radius rho, at every resolution: docs/fabric.md),
   which rules that pattern out for this element. */
#include <hylc/private/clothimpl.h>
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

PetscErrorCode HylcClothMeshReset_Private(HylcCloth c)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(c->tri));
  PetscCall(PetscFree(c->X));
  PetscCall(PetscFree(c->uv));
  PetscCall(PetscFree(c->vmass));
  c->nv = c->nt = 0;
  c->meshbuilt  = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rows of the lattice merged into triangles, counter-clockwise seen from +z */
static void MergeRows(const PetscInt *A, PetscInt na, const PetscInt *B, PetscInt nb, const PetscReal *X, PetscInt *tri, PetscInt *nt)
{
  PetscInt ia = 0, ib = 0;

  while (ia < na - 1 || ib < nb - 1) {
    PetscBool advA;
    if (ib == nb - 1)
      advA = PETSC_TRUE;
    else if (ia == na - 1)
      advA = PETSC_FALSE;
    else
      advA = X[3 * A[ia + 1]] <= X[3 * B[ib + 1]] - 1e-12 * PetscAbsReal(X[3 * B[ib + 1]]) ? PETSC_TRUE : PETSC_FALSE;
    if (advA) {
      tri[3 * *nt + 0] = A[ia];
      tri[3 * *nt + 1] = A[ia + 1];
      tri[3 * *nt + 2] = B[ib];
      ia++;
    } else {
      tri[3 * *nt + 0] = A[ia];
      tri[3 * *nt + 1] = B[ib + 1];
      tri[3 * *nt + 2] = B[ib];
      ib++;
    }
    (*nt)++;
  }
}

/* lumped area per vertex and the total area */
static PetscErrorCode Areas(HylcCloth c)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(c->vmass));
  PetscCall(PetscCalloc1(c->nv, &c->vmass));
  c->area = 0;
  for (PetscInt t = 0; t < c->nt; t++) {
    const PetscReal *u = c->uv + 6 * t, A = 0.5 * ((u[2] - u[0]) * (u[5] - u[1]) - (u[4] - u[0]) * (u[3] - u[1]));
    c->area += A;
    for (int k = 0; k < 3; k++) c->vmass[c->tri[3 * t + k]] += A / 3;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The strip [x0, x0 + L] x [0, W] in the plane z = 0: ny rows of height W / ny, nx spacings of L / nx
  along them (an affine image of the equilateral lattice); the shifted rows get extra vertices at both
  ends so that the ends x = x0 and x = x0 + L are straight.
*/
PetscErrorCode HylcClothMeshStripN_Private(HylcCloth c, PetscReal x0, PetscReal L, PetscReal W, PetscInt nx, PetscInt ny)
{
  PetscInt  nv = 0, nt = 0, *row, *rowlen;
  PetscReal hy = W / ny, dx = L / nx;

  PetscFunctionBegin;
  PetscCall(HylcClothMeshReset_Private(c));
  PetscCall(PetscMalloc1(3 * ((ny + 1) * (nx + 2)), &c->X));
  PetscCall(PetscMalloc2((ny + 1) * (nx + 2), &row, ny + 1, &rowlen));
  for (PetscInt j = 0; j <= ny; j++) {
    PetscInt n = 0;
    if (j % 2 == 0)
      for (PetscInt i = 0; i <= nx; i++) {
        c->X[3 * nv + 0]        = x0 + i * dx;
        c->X[3 * nv + 1]        = j * hy;
        c->X[3 * nv + 2]        = 0;
        row[j * (nx + 2) + n++] = nv++;
      }
    else
      for (PetscInt i = -1; i <= nx; i++) {
        c->X[3 * nv + 0]        = i < 0 ? x0 : i == nx ? x0 + L : x0 + (i + 0.5) * dx;
        c->X[3 * nv + 1]        = j * hy;
        c->X[3 * nv + 2]        = 0;
        row[j * (nx + 2) + n++] = nv++;
      }
    rowlen[j] = n;
  }
  PetscCall(PetscMalloc1(3 * 2 * ny * (nx + 2), &c->tri));
  for (PetscInt j = 0; j < ny; j++) MergeRows(row + j * (nx + 2), rowlen[j], row + (j + 1) * (nx + 2), rowlen[j + 1], c->X, c->tri, &nt);
  PetscCall(PetscFree2(row, rowlen));
  c->nv = nv;
  c->nt = nt;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The strip [x0, x0 + L] x [0, W] with the lattice's rows across it (parallel to y): nx row spacings of
  L / nx along x, ny spacings of W / ny along each row (the transpose of HylcClothMeshStripN_Private).
  Every row is a straight line x = const of vertices and edges, so an end held along a row (a clamp, a
  free end) is a line of the mesh; with rows along the strip no edge runs across it and a clamp line
  x = const is a zigzag.
*/
PetscErrorCode HylcClothMeshStripAcross_Private(HylcCloth c, PetscReal x0, PetscReal L, PetscReal W, PetscInt nx, PetscInt ny)
{
  PetscFunctionBegin;
  PetscCall(HylcClothMeshStripN_Private(c, 0, W, L, ny, nx));
  for (PetscInt i = 0; i < c->nv; i++) { /* (u, v) -> (x0 + v, u): a reflection, so the orientation flips */
    PetscReal u = c->X[3 * i], v = c->X[3 * i + 1];
    c->X[3 * i]     = x0 + v;
    c->X[3 * i + 1] = u;
  }
  for (PetscInt t = 0; t < c->nt; t++) { /* counter-clockwise seen from +z again */
    PetscInt a        = c->tri[3 * t + 1];
    c->tri[3 * t + 1] = c->tri[3 * t + 2];
    c->tri[3 * t + 2] = a;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the strip with rows about h sqrt(3) / 2 apart and the spacing along them as close to h as the length
   allows: nearly equilateral triangles */
PetscErrorCode HylcClothMeshStrip_Private(HylcCloth c, PetscReal x0, PetscReal L, PetscReal W, PetscReal h)
{
  PetscInt  ny = PetscMax(1, (PetscInt)PetscFloorReal(W / (h * PetscSqrtReal(3.0) / 2) + 0.5)), nx;
  PetscReal dx = 2 * (W / ny) / PetscSqrtReal(3.0);

  PetscFunctionBegin;
  nx = PetscMax(1, (PetscInt)PetscFloorReal(L / dx + 0.5));
  PetscCall(HylcClothMeshStripN_Private(c, x0, L, W, nx, ny));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  A disc of radius R centred at the origin, z = 0: the lattice of spacing h clipped to the triangles whose
  vertices lie within R + 0.3 h, then the vertices within 0.3 h of the circles of radius R and Rsnap
  moved radially onto them (a move of at most 0.3 h keeps every lattice triangle valid).
*/
PetscErrorCode HylcClothMeshDisc_Private(HylcCloth c, PetscReal R, PetscReal Rsnap, PetscReal h)
{
  PetscReal  hy = h * PetscSqrtReal(3.0) / 2, lim = R + 0.3 * h;
  PetscInt   nr = (PetscInt)PetscCeilReal(lim / hy) + 1, nc = (PetscInt)PetscCeilReal(lim / h) + 2, nrow = 2 * nr + 1, ncol = 2 * nc + 2;
  PetscInt  *id, *tri, nt = 0, nv = 0, *A, *B, na, nb, *keep;
  PetscReal *X;

  PetscFunctionBegin;
  PetscCall(HylcClothMeshReset_Private(c));
  PetscCall(PetscMalloc3(nrow * ncol, &id, 3 * nrow * ncol, &X, 6 * nrow * ncol, &tri));
  /* all lattice points of the square; rows j = -nr..nr, odd rows shifted by h / 2 */
  for (PetscInt j = 0; j < nrow; j++)
    for (PetscInt i = 0; i < ncol; i++) {
      PetscInt jj               = j - nr;
      X[3 * (j * ncol + i) + 0] = (i - nc) * h + ((jj % 2 + 2) % 2 ? 0.5 * h : 0);
      X[3 * (j * ncol + i) + 1] = jj * hy;
      X[3 * (j * ncol + i) + 2] = 0;
    }
  PetscCall(PetscMalloc2(ncol, &A, ncol, &B));
  for (PetscInt j = 0; j + 1 < nrow; j++) {
    for (PetscInt i = 0; i < ncol; i++) {
      A[i] = j * ncol + i;
      B[i] = (j + 1) * ncol + i;
    }
    na = nb = ncol;
    /* rows of equal length, offset by half: merge, then drop the end triangles that overhang */
    MergeRows(A, na, B, nb, X, tri, &nt);
  }
  PetscCall(PetscFree2(A, B));
  PetscCall(PetscCalloc1(nrow * ncol, &keep));
  {
    PetscInt m = 0;
    for (PetscInt t = 0; t < nt; t++) {
      PetscBool in = PETSC_TRUE;
      for (int k = 0; k < 3; k++) {
        const PetscReal *p = X + 3 * tri[3 * t + k];
        if (PetscSqrtReal(p[0] * p[0] + p[1] * p[1]) > lim) in = PETSC_FALSE;
      }
      if (!in) continue;
      for (int k = 0; k < 3; k++) {
        tri[3 * m + k]       = tri[3 * t + k];
        keep[tri[3 * t + k]] = 1;
      }
      m++;
    }
    nt = m;
  }
  for (PetscInt i = 0; i < nrow * ncol; i++) id[i] = keep[i] ? nv++ : -1;
  PetscCall(PetscMalloc1(3 * nv, &c->X));
  PetscCall(PetscMalloc1(3 * nt, &c->tri));
  for (PetscInt i = 0; i < nrow * ncol; i++) {
    PetscReal *p = X + 3 * i, r;
    if (id[i] < 0) continue;
    r = PetscSqrtReal(p[0] * p[0] + p[1] * p[1]);
    if (r > R - 0.3 * h && r > 0)
      p[0] *= R / r, p[1] *= R / r;
    else if (Rsnap > 0 && PetscAbsReal(r - Rsnap) < 0.3 * h && r > 0)
      p[0] *= Rsnap / r, p[1] *= Rsnap / r;
    for (int k = 0; k < 3; k++) c->X[3 * id[i] + k] = p[k];
  }
  for (PetscInt t = 0; t < 3 * nt; t++) c->tri[t] = id[tri[t]];
  PetscCall(PetscFree(keep));
  PetscCall(PetscFree3(id, X, tri));
  c->nv = nv;
  c->nt = nt;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* next token of an .obj face item "v", "v/vt", "v//vn", "v/vt/vn": the v and vt indices (1-based, or
   negative relative ones; 0 for absent vt) */
static int ParseFaceItem(const char *s, long *v, long *vt)
{
  char *end;

  *vt = 0;
  *v  = strtol(s, &end, 10);
  if (end == s) return -1;
  if (*end == '/') {
    const char *q = end + 1;
    if (*q != '/') {
      *vt = strtol(q, &end, 10);
      if (end == q) return -1;
    } else
      end = (char *)q;
    if (*end == '/') {
      strtol(end + 1, &end, 10);
    }
  }
  return (*end == 0 || isspace((unsigned char)*end)) ? 0 : -1;
}

/*
  Reads a triangle mesh from a Wavefront .obj file (rank 0 reads, every rank gets the mesh): v lines
  (positions, m after multiplying by scale), optional vt lines (material coordinates of the corners, m
  after scale), f lines with 3 items (polygons with more are refused); every other line is ignored.
  Errors name the file and line.
*/
PetscErrorCode HylcClothMeshReadOBJ_Private(HylcCloth c, const char path[], PetscReal scale)
{
  MPI_Comm    comm    = PetscObjectComm((PetscObject)c);
  PetscInt    dims[3] = {0, 0, 0}; /* nv, nvt, nt */
  PetscReal  *X = NULL, *VT = NULL;
  PetscInt   *F                             = NULL; /* nt x 6: v0 v1 v2 vt0 vt1 vt2 (vt -1: none) */
  char        msg[PETSC_MAX_PATH_LEN + 256] = "";
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCall(HylcClothMeshReset_Private(c));
  PetscCall(HylcFileCheckInput(comm, path, "-cloth_mesh_file"));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    FILE    *fp = fopen(path, "r");
    char     line[4096];
    long     ln     = 0;
    PetscInt cap[3] = {1024, 1024, 1024};
    PetscCall(PetscMalloc3(3 * cap[0], &X, 2 * cap[1], &VT, 6 * cap[2], &F));
    if (!fp) PetscCall(PetscSNPrintf(msg, sizeof(msg), "cannot open %s", path));
    while (fp && !msg[0] && fgets(line, sizeof(line), fp)) {
      char *s = line;
      ln++;
      while (isspace((unsigned char)*s)) s++;
      if (s[0] == 'v' && isspace((unsigned char)s[1])) {
        double a, b, d;
        if (sscanf(s + 1, "%lf %lf %lf", &a, &b, &d) != 3 || !isfinite(a) || !isfinite(b) || !isfinite(d)) {
          PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: a vertex needs three finite coordinates", path, ln));
          break;
        }
        if (dims[0] == cap[0]) {
          PetscReal *n;
          PetscCall(PetscMalloc1(6 * cap[0], &n));
          PetscCall(PetscArraycpy(n, X, 3 * cap[0]));
          PetscCall(PetscFree(X));
          X = n;
          cap[0] *= 2;
        }
        X[3 * dims[0] + 0] = scale * a;
        X[3 * dims[0] + 1] = scale * b;
        X[3 * dims[0] + 2] = scale * d;
        dims[0]++;
      } else if (s[0] == 'v' && s[1] == 't' && isspace((unsigned char)s[2])) {
        double a, b;
        if (sscanf(s + 2, "%lf %lf", &a, &b) != 2 || !isfinite(a) || !isfinite(b)) {
          PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: a texture coordinate needs two finite numbers", path, ln));
          break;
        }
        if (dims[1] == cap[1]) {
          PetscReal *n;
          PetscCall(PetscMalloc1(4 * cap[1], &n));
          PetscCall(PetscArraycpy(n, VT, 2 * cap[1]));
          PetscCall(PetscFree(VT));
          VT = n;
          cap[1] *= 2;
        }
        VT[2 * dims[1] + 0] = scale * a;
        VT[2 * dims[1] + 1] = scale * b;
        dims[1]++;
      } else if (s[0] == 'f' && isspace((unsigned char)s[1])) {
        long  v[3], vt[3];
        int   n = 0;
        char *p = s + 1;
        for (;;) {
          while (isspace((unsigned char)*p)) p++;
          if (!*p) break;
          if (n == 3) {
            PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: a face with more than 3 vertices (triangulate the mesh)", path, ln));
            break;
          }
          if (ParseFaceItem(p, &v[n], &vt[n])) {
            PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: cannot read face item %d", path, ln, n + 1));
            break;
          }
          while (*p && !isspace((unsigned char)*p)) p++;
          n++;
        }
        if (msg[0]) break;
        if (n != 3) {
          PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: a face needs 3 vertices, has %d", path, ln, n));
          break;
        }
        if (dims[2] == cap[2]) {
          PetscInt *nf;
          PetscCall(PetscMalloc1(12 * cap[2], &nf));
          PetscCall(PetscArraycpy(nf, F, 6 * cap[2]));
          PetscCall(PetscFree(F));
          F = nf;
          cap[2] *= 2;
        }
        for (int k = 0; k < 3; k++) {
          long vi = v[k] < 0 ? dims[0] + v[k] : v[k] - 1, ti = vt[k] < 0 ? dims[1] + vt[k] : vt[k] - 1;
          if (vi < 0 || vi >= dims[0]) {
            PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: vertex index %ld out of range (%" PetscInt_FMT " vertices so far)", path, ln, v[k], dims[0]));
            break;
          }
          if (vt[k] && (ti < 0 || ti >= dims[1])) {
            PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s:%ld: texture index %ld out of range", path, ln, vt[k]));
            break;
          }
          F[6 * dims[2] + k]     = (PetscInt)vi;
          F[6 * dims[2] + 3 + k] = vt[k] ? (PetscInt)ti : -1;
        }
        dims[2]++;
      }
    }
    if (fp) fclose(fp);
    if (!msg[0] && !dims[2]) PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s: no triangles (f lines)", path));
  }
  PetscCallMPI(MPI_Bcast(msg, sizeof(msg), MPI_CHAR, 0, comm));
  if (msg[0]) {
    PetscCall(PetscFree3(X, VT, F));
    SETERRQ(comm, PETSC_ERR_FILE_UNEXPECTED, "%s", msg);
  }
  PetscCallMPI(MPI_Bcast(dims, 3, MPIU_INT, 0, comm));
  if (rank) PetscCall(PetscMalloc3(3 * dims[0], &X, 2 * PetscMax(dims[1], 1), &VT, 6 * dims[2], &F));
  PetscCallMPI(MPI_Bcast(X, 3 * dims[0], MPIU_REAL, 0, comm));
  if (dims[1]) PetscCallMPI(MPI_Bcast(VT, 2 * dims[1], MPIU_REAL, 0, comm));
  PetscCallMPI(MPI_Bcast(F, 6 * dims[2], MPIU_INT, 0, comm));
  c->nv = dims[0];
  c->nt = dims[2];
  PetscCall(PetscMalloc1(3 * c->nv, &c->X));
  PetscCall(PetscArraycpy(c->X, X, 3 * c->nv));
  PetscCall(PetscMalloc1(3 * c->nt, &c->tri));
  for (PetscInt t = 0; t < c->nt; t++)
    for (int k = 0; k < 3; k++) c->tri[3 * t + k] = F[6 * t + k];
  /* material coordinates from vt when every corner has one */
  {
    PetscBool all = dims[1] > 0 ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt t = 0; t < c->nt && all; t++)
      for (int k = 0; k < 3; k++)
        if (F[6 * t + 3 + k] < 0) all = PETSC_FALSE;
    if (all) {
      PetscCall(PetscMalloc1(6 * c->nt, &c->uv));
      for (PetscInt t = 0; t < c->nt; t++)
        for (int k = 0; k < 3; k++) {
          c->uv[6 * t + 2 * k + 0] = VT[2 * F[6 * t + 3 + k] + 0];
          c->uv[6 * t + 2 * k + 1] = VT[2 * F[6 * t + 3 + k] + 1];
        }
    }
  }
  PetscCall(PetscFree3(X, VT, F));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Material coordinates of every corner: for a planar rest mesh (z = 0), u along the direction at angle
  theta to x, v at theta + 90 degrees (n = +z), or mirrored (v -> -v, triangles reversed: n = -z) for
  the face down. A mesh read with texture coordinates keeps them (faceDown mirrors them likewise). A
  3D rest mesh without them: per triangle, u along the projection of the direction at angle theta to x
  onto its plane (hylcmat_mesh's rest_3d convention through the local frame), v = n x u.
  Then the lumped areas; a triangle that is not counter-clockwise in (u, v) is an error.
*/
PetscErrorCode HylcClothMeshMaterial_Private(HylcCloth c, PetscReal theta, PetscBool faceDown)
{
  PetscReal ct = PetscCosReal(theta), st = PetscSinReal(theta);
  PetscBool haveUV = c->uv ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBegin;
  if (!haveUV) PetscCall(PetscMalloc1(6 * c->nt, &c->uv));
  for (PetscInt t = 0; t < c->nt; t++) {
    PetscInt *v = c->tri + 3 * t;
    PetscReal u[6];
    if (haveUV) {
      for (int k = 0; k < 3; k++) {
        PetscReal a = c->uv[6 * t + 2 * k], b = c->uv[6 * t + 2 * k + 1];
        u[2 * k]     = ct * a + st * b;
        u[2 * k + 1] = -st * a + ct * b;
      }
    } else {
      /* a local frame of the triangle: e1 along the projection of (cos theta, sin theta, 0), e2 = n x e1 */
      const PetscReal *p0 = c->X + 3 * v[0], *p1 = c->X + 3 * v[1], *p2 = c->X + 3 * v[2];
      PetscReal        a[3], b[3], n[3], d[3] = {ct, st, 0}, e1[3], e2[3], nn, dn;
      for (int i = 0; i < 3; i++) a[i] = p1[i] - p0[i], b[i] = p2[i] - p0[i];
      n[0] = a[1] * b[2] - a[2] * b[1];
      n[1] = a[2] * b[0] - a[0] * b[2];
      n[2] = a[0] * b[1] - a[1] * b[0];
      nn   = PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      PetscCheck(nn > 0, PetscObjectComm((PetscObject)c), PETSC_ERR_USER_INPUT, "mesh: triangle %" PetscInt_FMT " (vertices %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT ") has zero area", t, v[0], v[1], v[2]);
      for (int i = 0; i < 3; i++) n[i] /= nn;
      dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
      for (int i = 0; i < 3; i++) e1[i] = d[i] - dn * n[i];
      dn = PetscSqrtReal(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
      if (dn < 1e-8) { /* the direction is normal to the triangle: use its first edge */
        for (int i = 0; i < 3; i++) e1[i] = a[i];
        dn = PetscSqrtReal(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      }
      for (int i = 0; i < 3; i++) e1[i] /= dn;
      e2[0] = n[1] * e1[2] - n[2] * e1[1];
      e2[1] = n[2] * e1[0] - n[0] * e1[2];
      e2[2] = n[0] * e1[1] - n[1] * e1[0];
      for (int k = 0; k < 3; k++) {
        const PetscReal *p = c->X + 3 * v[k];
        u[2 * k]           = (p[0] - p0[0]) * e1[0] + (p[1] - p0[1]) * e1[1] + (p[2] - p0[2]) * e1[2];
        u[2 * k + 1]       = (p[0] - p0[0]) * e2[0] + (p[1] - p0[1]) * e2[1] + (p[2] - p0[2]) * e2[2];
      }
      /* for a planar mesh in z = 0 facing +z, shift to global material coordinates (seams do not matter) */
      if (PetscAbsReal(p0[2]) == 0 && PetscAbsReal(n[2] - 1) < 1e-12) {
        PetscReal o[2] = {ct * p0[0] + st * p0[1], -st * p0[0] + ct * p0[1]};
        for (int k = 0; k < 3; k++) u[2 * k] += o[0], u[2 * k + 1] += o[1];
      }
    }
    if (faceDown) { /* mirror v and reverse the triangle: n flips */
      PetscInt  tv = v[1];
      PetscReal tu[2];
      v[1]  = v[2];
      v[2]  = tv;
      tu[0] = u[2];
      tu[1] = u[3];
      u[2]  = u[4];
      u[3]  = u[5];
      u[4]  = tu[0];
      u[5]  = tu[1];
      for (int k = 0; k < 3; k++) u[2 * k + 1] = -u[2 * k + 1];
    }
    for (int k = 0; k < 6; k++) c->uv[6 * t + k] = u[k];
    {
      PetscReal A = 0.5 * ((u[2] - u[0]) * (u[5] - u[1]) - (u[4] - u[0]) * (u[3] - u[1]));
      PetscCheck(A > 0, PetscObjectComm((PetscObject)c), PETSC_ERR_USER_INPUT, "mesh: triangle %" PetscInt_FMT " (vertices %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT ") is %s in its material coordinates", t, v[0], v[1], v[2],
                 A == 0 ? "degenerate" : "clockwise");
    }
  }
  PetscCall(Areas(c));
  c->meshbuilt = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}
