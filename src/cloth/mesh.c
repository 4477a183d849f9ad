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
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

/* ---- the .obj reader ------------------------------------------------------------------------------ */

/* limits of an .obj mesh: the count of v, vt and f lines (six times it fits a PetscInt and an MPI count),
   and the largest coordinate in m after -cloth_mesh_scale (a cloth of 1000 km is a wrong scale; beyond
   about 1e150 m the areas and energies overflow) */
#define OBJ_MAX_COUNT (PETSC_MAX_INT / 16)
#define OBJ_MAX_COORD 1e6

/* the file's contents on rank 0 */
typedef struct {
  PetscInt   n[3], cap[3]; /* v, vt, f lines read, and the room for them */
  PetscReal *X, *VT;       /* 3 per vertex, 2 per texture coordinate (m) */
  PetscInt  *F;            /* 6 per face: v0 v1 v2 vt0 vt1 vt2 (0-based; vt -1: none) */
  long      *vline, *fline;
} OBJData;

static PetscErrorCode OBJDataFree(OBJData *d)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(d->X));
  PetscCall(PetscFree(d->VT));
  PetscCall(PetscFree(d->F));
  PetscCall(PetscFree(d->vline));
  PetscCall(PetscFree(d->fline));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* *p (n entries of elem bytes) moved into a new block of room for cap entries: each array its own block,
   freed by PetscFree() alone */
static PetscErrorCode OBJGrow(void *p, size_t elem, PetscInt n, PetscInt cap)
{
  void **a = (void **)p, *q;

  PetscFunctionBegin;
  PetscCall(PetscMalloc((size_t)cap * elem, &q));
  if (n) PetscCall(PetscMemcpy(q, *a, (size_t)n * elem));
  PetscCall(PetscFree(*a));
  *a = q;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* room for one more entry of kind k (0 v, 1 vt, 2 f); *full when the file has too many */
static PetscErrorCode OBJRoom(OBJData *d, int k, PetscBool *full)
{
  PetscInt cap;

  PetscFunctionBegin;
  *full = (PetscBool)(d->n[k] >= OBJ_MAX_COUNT);
  if (*full || d->n[k] < d->cap[k]) PetscFunctionReturn(PETSC_SUCCESS);
  cap = d->cap[k] ? PetscMin(2 * d->cap[k], OBJ_MAX_COUNT) : 1024;
  if (k == 0) {
    PetscCall(OBJGrow(&d->X, 3 * sizeof(PetscReal), d->n[0], cap));
    PetscCall(OBJGrow(&d->vline, sizeof(long), d->n[0], cap));
  } else if (k == 1) {
    PetscCall(OBJGrow(&d->VT, 2 * sizeof(PetscReal), d->n[1], cap));
  } else {
    PetscCall(OBJGrow(&d->F, 6 * sizeof(PetscInt), d->n[2], cap));
    PetscCall(OBJGrow(&d->fline, sizeof(long), d->n[2], cap));
  }
  d->cap[k] = cap;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the n numbers at the start of s into v, then only further numbers (a vertex's w or r g b, a texture
   coordinate's w, which are ignored): 0, or -1 if s has fewer numbers or other text */
static int OBJNumbers(const char *s, int n, double v[])
{
  for (int i = 0;; i++) {
    char  *end;
    double x;
    while (isspace((unsigned char)*s)) s++;
    if (!*s) return i >= n ? 0 : -1;
    x = strtod(s, &end);
    if (end == s || (*end && !isspace((unsigned char)*end))) return -1;
    if (i < n) v[i] = x;
    s = end;
  }
}

/* an index of a face item: a decimal integer, non-zero (1-based, or negative: relative to the end) */
static int OBJIndex(const char *s, const char **end, long *i)
{
  char *e;

  if (!isdigit((unsigned char)*s) && !((*s == '-' || *s == '+') && isdigit((unsigned char)s[1]))) return -1;
  errno = 0;
  *i    = strtol(s, &e, 10);
  if (errno == ERANGE) *i = *i < 0 ? LONG_MIN : LONG_MAX; /* out of range below, as it is */
  *end = e;
  return 0;
}

/* a face item "v", "v/vt", "v//vn", "v/vt/vn" ending at a blank or the end: the v index and the vt index
   (*hasvt 0 if none); -1 if it is anything else */
static int OBJFaceItem(const char *s, long *v, long *vt, int *hasvt)
{
  const char *e;
  long        vn;

  *hasvt = 0;
  if (OBJIndex(s, &e, v)) return -1;
  if (*e == '/') {
    s = e + 1;
    if (*s != '/') {
      if (OBJIndex(s, &e, vt)) return -1;
      *hasvt = 1;
    } else
      e = s;
    if (*e == '/' && OBJIndex(e + 1, &e, &vn)) return -1;
  }
  return (*e == 0 || isspace((unsigned char)*e)) ? 0 : -1;
}

/* a 0-based index from an .obj index i (1-based, or negative: -1 the last so far) among n; -1 if none */
static PetscInt OBJResolve(long i, PetscInt n)
{
  if (i > 0 && i <= n) return (PetscInt)(i - 1);
  if (i < 0 && i >= -(long)n) return (PetscInt)(n + i);
  return -1;
}

/* the root of a vertex in the union-find forest p (path halving) */
static PetscInt OBJRoot(PetscInt *p, PetscInt v)
{
  while (p[v] != v) v = p[v] = p[p[v]];
  return v;
}

/* reads the file on rank 0 into d; a user error (the file, its line and what is wrong) is written to msg */
static PetscErrorCode OBJRead(const char path[], PetscReal scale, OBJData *d, char msg[], size_t len)
{
  FILE     *fp   = fopen(path, "r");
  char     *line = NULL;
  size_t    room = 0;
  ssize_t   got;
  long      ln = 0;
  PetscBool full;

  PetscFunctionBegin;
  if (!fp) {
    (void)snprintf(msg, len, "cannot open %s: %s", path, strerror(errno));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (!(scale > 0 && isfinite(scale))) (void)snprintf(msg, len, "%s: the scale %g of its coordinates (-cloth_mesh_scale) is not a finite positive factor", path, (double)scale);
  /* whole lines, of any length */
  while (!msg[0] && (got = getline(&line, &room, fp)) >= 0) {
    char *s = line, *hash;
    ln++;
    if ((size_t)got != strlen(line)) {
      (void)snprintf(msg, len, "%s:%ld: a NUL byte (not a text file)", path, ln);
      break;
    }
    if ((hash = strchr(s, '#'))) *hash = 0; /* a comment, to the end of the line */
    while (isspace((unsigned char)*s)) s++;
    if (s[0] == 'v' && isspace((unsigned char)s[1])) {
      double a[3];
      if (OBJNumbers(s + 1, 3, a)) {
        (void)snprintf(msg, len, "%s:%ld: a vertex needs three coordinates (numbers)", path, ln);
        break;
      }
      for (int k = 0; k < 3 && !msg[0]; k++)
        if (!(PetscAbsReal(scale * a[k]) <= OBJ_MAX_COORD)) (void)snprintf(msg, len, "%s:%ld: coordinate %g m (after -cloth_mesh_scale %g) is not finite or beyond %g m", path, ln, (double)(scale * a[k]), (double)scale, OBJ_MAX_COORD);
      if (msg[0]) break;
      PetscCall(OBJRoom(d, 0, &full));
      if (full) {
        (void)snprintf(msg, len, "%s:%ld: more than %" PetscInt_FMT " vertices", path, ln, OBJ_MAX_COUNT);
        break;
      }
      for (int k = 0; k < 3; k++) d->X[3 * d->n[0] + k] = scale * a[k];
      d->vline[d->n[0]++] = ln;
    } else if (s[0] == 'v' && s[1] == 't' && isspace((unsigned char)s[2])) {
      double a[2];
      if (OBJNumbers(s + 2, 2, a)) {
        (void)snprintf(msg, len, "%s:%ld: a texture coordinate needs two numbers", path, ln);
        break;
      }
      for (int k = 0; k < 2 && !msg[0]; k++)
        if (!(PetscAbsReal(scale * a[k]) <= OBJ_MAX_COORD)) (void)snprintf(msg, len, "%s:%ld: texture coordinate %g m (after -cloth_mesh_scale %g) is not finite or beyond %g m", path, ln, (double)(scale * a[k]), (double)scale, OBJ_MAX_COORD);
      if (msg[0]) break;
      PetscCall(OBJRoom(d, 1, &full));
      if (full) {
        (void)snprintf(msg, len, "%s:%ld: more than %" PetscInt_FMT " texture coordinates", path, ln, OBJ_MAX_COUNT);
        break;
      }
      for (int k = 0; k < 2; k++) d->VT[2 * d->n[1] + k] = scale * a[k];
      d->n[1]++;
    } else if (s[0] == 'f' && isspace((unsigned char)s[1])) {
      long     v[3], vt[3];
      int      hasvt[3], n = 0;
      PetscInt fv[6];
      char    *p = s + 1;
      for (;;) {
        while (isspace((unsigned char)*p)) p++;
        if (!*p) break;
        if (n == 3) {
          (void)snprintf(msg, len, "%s:%ld: a face with more than 3 vertices (triangulate the mesh)", path, ln);
          break;
        }
        if (OBJFaceItem(p, &v[n], &vt[n], &hasvt[n])) {
          (void)snprintf(msg, len, "%s:%ld: cannot read face item %d (v, v/vt, v//vn or v/vt/vn)", path, ln, n + 1);
          break;
        }
        while (*p && !isspace((unsigned char)*p)) p++;
        n++;
      }
      if (msg[0]) break;
      if (n != 3) {
        (void)snprintf(msg, len, "%s:%ld: a face needs 3 vertices, has %d", path, ln, n);
        break;
      }
      for (int k = 0; k < 3 && !msg[0]; k++) {
        fv[k]     = OBJResolve(v[k], d->n[0]);
        fv[3 + k] = hasvt[k] ? OBJResolve(vt[k], d->n[1]) : -1;
        if (fv[k] < 0)
          (void)snprintf(msg, len, "%s:%ld: vertex index %ld out of range (%" PetscInt_FMT " vertices so far)", path, ln, v[k], d->n[0]);
        else if (hasvt[k] && fv[3 + k] < 0)
          (void)snprintf(msg, len, "%s:%ld: texture index %ld out of range (%" PetscInt_FMT " texture coordinates so far)", path, ln, vt[k], d->n[1]);
      }
      if (!msg[0] && (fv[0] == fv[1] || fv[1] == fv[2] || fv[2] == fv[0])) (void)snprintf(msg, len, "%s:%ld: a face with a vertex twice", path, ln);
      if (msg[0]) break;
      PetscCall(OBJRoom(d, 2, &full));
      if (full) {
        (void)snprintf(msg, len, "%s:%ld: more than %" PetscInt_FMT " faces", path, ln, OBJ_MAX_COUNT);
        break;
      }
      PetscCall(PetscArraycpy(d->F + 6 * d->n[2], fv, 6));
      d->fline[d->n[2]++] = ln;
    }
  }
  if (!msg[0] && ferror(fp)) (void)snprintf(msg, len, "%s:%ld: read error", path, ln + 1);
  free(line);
  fclose(fp);
  if (!msg[0] && !d->n[2]) (void)snprintf(msg, len, "%s: no triangles (f lines)", path);
  if (msg[0]) PetscFunctionReturn(PETSC_SUCCESS);
  /* every face of non-zero area; every vertex in a face (a lone vertex would be a free, massless point);
     one piece (a piece apart would be held by nothing the scene holds the other by, or float away) */
  {
    PetscInt *p, first = -1, pieces = 0;
    PetscCall(PetscMalloc1(d->n[0], &p));
    for (PetscInt i = 0; i < d->n[0]; i++) p[i] = -1;
    for (PetscInt t = 0; t < d->n[2] && !msg[0]; t++) {
      const PetscInt  *f  = d->F + 6 * t;
      const PetscReal *x0 = d->X + 3 * f[0], *x1 = d->X + 3 * f[1], *x2 = d->X + 3 * f[2];
      PetscReal        a[3], b[3], n[3];
      for (int k = 0; k < 3; k++) a[k] = x1[k] - x0[k], b[k] = x2[k] - x0[k];
      n[0] = a[1] * b[2] - a[2] * b[1];
      n[1] = a[2] * b[0] - a[0] * b[2];
      n[2] = a[0] * b[1] - a[1] * b[0];
      if (!(PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) >= DBL_MIN)) {
        (void)snprintf(msg, len, "%s:%ld: a triangle of zero area (its vertices on one line)", path, d->fline[t]);
        break;
      }
      for (int k = 0; k < 3; k++)
        if (p[f[k]] < 0) p[f[k]] = f[k];
      for (int k = 1; k < 3; k++) p[OBJRoot(p, f[k])] = OBJRoot(p, f[0]);
    }
    for (PetscInt i = 0; i < d->n[0] && !msg[0]; i++)
      if (p[i] < 0) (void)snprintf(msg, len, "%s:%ld: vertex %" PetscInt_FMT " belongs to no triangle", path, d->vline[i], i + 1);
    for (PetscInt i = 0; i < d->n[0] && !msg[0]; i++)
      if (OBJRoot(p, i) == i) pieces++;
    if (!msg[0] && pieces > 1) {
      const PetscInt r0 = OBJRoot(p, d->F[0]);
      for (PetscInt t = 1; t < d->n[2] && first < 0; t++)
        if (OBJRoot(p, d->F[6 * t]) != r0) first = t;
      (void)snprintf(msg, len, "%s: the mesh is in %" PetscInt_FMT " pieces (the faces of lines %ld and %ld are not connected through shared vertices): a scene is one piece of cloth", path, pieces, d->fline[0], d->fline[first]);
    }
    PetscCall(PetscFree(p));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Reads a triangle mesh from a Wavefront .obj file (rank 0 reads, every rank gets the mesh): v lines
  (positions, m after multiplying by scale; further numbers, w or a colour, are ignored), optional vt
  lines (material coordinates of the corners, m after scale), f lines with 3 items v, v/vt, v//vn or
  v/vt/vn (1-based or negative indices; polygons with more are refused); a # starts a comment, lines may
  be of any length, every other line (vn, o, g, s, usemtl, ...) is ignored. Refused, naming the file and
  line: a malformed line, a coordinate that is not finite or beyond 1e6 m after scale, an index out of
  range, a face with a vertex twice or of zero area, a vertex in no face, a mesh in more than one piece.
*/
PetscErrorCode HylcClothMeshReadOBJ_Private(HylcCloth c, const char path[], PetscReal scale)
{
  MPI_Comm    comm                          = PetscObjectComm((PetscObject)c);
  OBJData     d                             = {{0, 0, 0}, {0, 0, 0}, NULL, NULL, NULL, NULL, NULL};
  char        msg[PETSC_MAX_PATH_LEN + 512] = "";
  PetscMPIInt rank;

  PetscFunctionBegin;
  PetscCall(HylcClothMeshReset_Private(c));
  PetscCall(HylcFileCheckInput(comm, path, "-cloth_mesh_file"));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) PetscCall(OBJRead(path, scale, &d, msg, sizeof(msg)));
  PetscCallMPI(MPI_Bcast(msg, sizeof(msg), MPI_CHAR, 0, comm));
  if (msg[0]) {
    PetscCall(OBJDataFree(&d));
    SETERRQ(comm, PETSC_ERR_FILE_UNEXPECTED, "%s", msg);
  }
  PetscCallMPI(MPI_Bcast(d.n, 3, MPIU_INT, 0, comm));
  if (rank) {
    PetscCall(PetscMalloc1(3 * d.n[0], &d.X));
    PetscCall(PetscMalloc1(2 * d.n[1], &d.VT));
    PetscCall(PetscMalloc1(6 * d.n[2], &d.F));
  }
  PetscCallMPI(MPI_Bcast(d.X, (PetscMPIInt)(3 * d.n[0]), MPIU_REAL, 0, comm));
  if (d.n[1]) PetscCallMPI(MPI_Bcast(d.VT, (PetscMPIInt)(2 * d.n[1]), MPIU_REAL, 0, comm));
  PetscCallMPI(MPI_Bcast(d.F, (PetscMPIInt)(6 * d.n[2]), MPIU_INT, 0, comm));
  c->nv = d.n[0];
  c->nt = d.n[2];
  PetscCall(PetscMalloc1(3 * c->nv, &c->X));
  PetscCall(PetscArraycpy(c->X, d.X, 3 * c->nv));
  PetscCall(PetscMalloc1(3 * c->nt, &c->tri));
  for (PetscInt t = 0; t < c->nt; t++)
    for (int k = 0; k < 3; k++) c->tri[3 * t + k] = d.F[6 * t + k];
  /* material coordinates from vt when every corner has one */
  {
    PetscBool all = d.n[1] > 0 ? PETSC_TRUE : PETSC_FALSE;
    for (PetscInt t = 0; t < c->nt && all; t++)
      for (int k = 0; k < 3; k++)
        if (d.F[6 * t + 3 + k] < 0) all = PETSC_FALSE;
    if (all) {
      PetscCall(PetscMalloc1(6 * c->nt, &c->uv));
      for (PetscInt t = 0; t < c->nt; t++)
        for (int k = 0; k < 3; k++) {
          c->uv[6 * t + 2 * k + 0] = d.VT[2 * d.F[6 * t + 3 + k] + 0];
          c->uv[6 * t + 2 * k + 1] = d.VT[2 * d.F[6 * t + 3 + k] + 1];
        }
    }
  }
  PetscCall(OBJDataFree(&d));
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
