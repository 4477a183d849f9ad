/* A mesh of shell elements (include/hylcmat.h): the stencils (each triangle's neighbours across its
   edges, from the edges sorted by their vertices), the rest data, and the sparsity of the Hessian
   (vertex blocks of 3 x 3: vertex u couples to every vertex of every stencil u belongs to), computed
   once; then the whole-mesh strains, energy, gradient and Hessian values. Plain C99. */
#include "hylcmatimpl.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct hylcmat_mesh {
  int                 nv, nt;
  int                *st;   /* nt x 6 stencil vertices (-1: no neighbour) */
  int                *nb;   /* nt: the neighbour mask */
  hylcmat_shell_rest *rest; /* nt */
  double              area;
  /* Hessian: vertex u's coupled vertices adj[adjptr[u] .. adjptr[u+1]) sorted; its 3 rows start at
     base[u] + d 3 deg(u); pos[36 t + 6 i + j] = index of st[t][j] in st[t][i]'s list (-1: missing) */
  int64_t *adjptr, *base, nnz;
  int     *adj;
  int     *pos;
};

typedef struct {
  int lo, hi, t, k; /* edge vertices (lo < hi), triangle, edge index */
} Edge;

static int CmpEdge(const void *a, const void *b)
{
  const Edge *x = (const Edge *)a, *y = (const Edge *)b;
  if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
  if (x->hi != y->hi) return x->hi < y->hi ? -1 : 1;
  return x->t < y->t ? -1 : (x->t > y->t);
}

static int CmpInt(const void *a, const void *b)
{
  const int x = *(const int *)a, y = *(const int *)b;
  return x < y ? -1 : (x > y);
}

void hylcmat_mesh_free(hylcmat_mesh *mesh)
{
  if (!mesh) return;
  free(mesh->st);
  free(mesh->nb);
  free(mesh->rest);
  free(mesh->adjptr);
  free(mesh->base);
  free(mesh->adj);
  free(mesh->pos);
  free(mesh);
}

/* the stencils; E names the triangle or edge of an error */
static int Adjacency(hylcmat_mesh *M, const int *tri, hm_err *E)
{
  const int nt = M->nt;
  Edge     *ed = (Edge *)malloc(sizeof(Edge) * 3 * (size_t)nt);

  if (!ed) return hm_fail(E, HYLCMAT_ERR_MEMORY, "mesh: out of memory (%d triangles)", nt);
  for (int t = 0; t < nt; t++)
    for (int k = 0; k < 3; k++) {
      const int a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3];
      Edge     *e = &ed[3 * t + k];
      e->lo       = a < b ? a : b;
      e->hi       = a < b ? b : a;
      e->t        = t;
      e->k        = k;
    }
  qsort(ed, 3 * (size_t)nt, sizeof(Edge), CmpEdge);
  for (size_t i = 0; i < 3 * (size_t)nt;) {
    size_t j = i + 1;
    while (j < 3 * (size_t)nt && ed[j].lo == ed[i].lo && ed[j].hi == ed[i].hi) j++;
    if (j - i > 2) {
      const int r = hm_fail(E, HYLCMAT_ERR_MESH, "mesh: edge (%d, %d) is shared by %d triangles (%d, %d, %d%s): a non-manifold edge", ed[i].lo, ed[i].hi, (int)(j - i), ed[i].t, ed[i + 1].t, ed[i + 2].t, j - i > 3 ? ", ..." : "");
      free(ed);
      return r;
    }
    if (j - i == 2) {
      const Edge *p = &ed[i], *q = &ed[i + 1];
      const int   pa = tri[3 * p->t + p->k], qa = tri[3 * q->t + q->k];
      if (p->t == q->t) {
        const int r = hm_fail(E, HYLCMAT_ERR_MESH, "mesh: triangle %d has edge (%d, %d) twice", p->t, p->lo, p->hi);
        free(ed);
        return r;
      }
      if (pa == qa) {
        const int r = hm_fail(E, HYLCMAT_ERR_MESH, "mesh: triangles %d and %d run through their common edge (%d, %d) in the same direction: their orientations (counter-clockwise in material coordinates) disagree", p->t, q->t, pa,
                              tri[3 * p->t + (p->k + 1) % 3]);
        free(ed);
        return r;
      }
      M->st[6 * p->t + 3 + p->k] = tri[3 * q->t + (q->k + 2) % 3];
      M->st[6 * q->t + 3 + q->k] = tri[3 * p->t + (p->k + 2) % 3];
      M->nb[p->t] |= 1 << p->k;
      M->nb[q->t] |= 1 << q->k;
    }
    i = j;
  }
  free(ed);
  return HYLCMAT_OK;
}

/* the Hessian's sparsity from the stencils */
static int Pattern(hylcmat_mesh *M, hm_err *E)
{
  const int nv = M->nv, nt = M->nt;
  int64_t  *incp = NULL;
  int      *inc = NULL, *buf = NULL, *cnt = NULL;
  int64_t   nadj = 0, off = 0;
  int       ret = HYLCMAT_OK, maxbuf = 0;

  incp      = (int64_t *)calloc((size_t)nv + 1, sizeof(int64_t));
  cnt       = (int *)calloc((size_t)nv, sizeof(int));
  M->adjptr = (int64_t *)calloc((size_t)nv + 1, sizeof(int64_t));
  M->base   = (int64_t *)calloc((size_t)nv + 1, sizeof(int64_t));
  M->pos    = (int *)malloc(sizeof(int) * 36 * (size_t)nt);
  if (!incp || !cnt || !M->adjptr || !M->base || !M->pos) goto oom;
  /* incidence: the stencils each vertex belongs to */
  for (int t = 0; t < nt; t++)
    for (int i = 0; i < 6; i++)
      if (M->st[6 * t + i] >= 0) incp[M->st[6 * t + i] + 1]++;
  for (int v = 0; v < nv; v++) incp[v + 1] += incp[v];
  inc = (int *)malloc(sizeof(int) * (size_t)(incp[nv] ? incp[nv] : 1));
  if (!inc) goto oom;
  for (int t = 0; t < nt; t++)
    for (int i = 0; i < 6; i++) {
      const int v = M->st[6 * t + i];
      if (v >= 0) inc[incp[v] + cnt[v]++] = t;
    }
  for (int v = 0; v < nv; v++)
    if (6 * (incp[v + 1] - incp[v]) > maxbuf) maxbuf = (int)(6 * (incp[v + 1] - incp[v]));
  buf = (int *)malloc(sizeof(int) * (size_t)(maxbuf ? maxbuf : 1));
  if (!buf) goto oom;
  /* pass 1 counts, pass 2 fills */
  for (int pass = 0; pass < 2; pass++) {
    nadj = 0;
    for (int v = 0; v < nv; v++) {
      int n = 0;
      for (int64_t q = incp[v]; q < incp[v + 1]; q++)
        for (int i = 0; i < 6; i++)
          if (M->st[6 * inc[q] + i] >= 0) buf[n++] = M->st[6 * inc[q] + i];
      qsort(buf, (size_t)n, sizeof(int), CmpInt);
      for (int i = 0; i < n; i++)
        if (i == 0 || buf[i] != buf[i - 1]) {
          if (pass) M->adj[nadj] = buf[i];
          nadj++;
        }
      if (!pass) M->adjptr[v + 1] = nadj;
    }
    if (!pass) {
      M->adj = (int *)malloc(sizeof(int) * (size_t)(nadj ? nadj : 1));
      if (!M->adj) goto oom;
    }
  }
  for (int v = 0; v < nv; v++) {
    M->base[v] = off;
    off += 9 * (M->adjptr[v + 1] - M->adjptr[v]);
  }
  M->base[nv] = off;
  M->nnz      = off;
  if (3 * (int64_t)nv > 2147483647 || off > ((int64_t)1 << 62)) {
    ret = hm_fail(E, HYLCMAT_ERR_ARG, "mesh: too large (%d vertices)", nv);
    goto done;
  }
  for (int t = 0; t < nt; t++)
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++) {
        const int vi = M->st[6 * t + i], vj = M->st[6 * t + j];
        int       p = -1;
        if (vi >= 0 && vj >= 0) {
          const int *a  = M->adj + M->adjptr[vi];
          int        lo = 0, hi = (int)(M->adjptr[vi + 1] - M->adjptr[vi]) - 1;
          while (lo <= hi) {
            const int mid = (lo + hi) / 2;
            if (a[mid] == vj) {
              p = mid;
              break;
            }
            if (a[mid] < vj)
              lo = mid + 1;
            else
              hi = mid - 1;
          }
        }
        M->pos[36 * t + 6 * i + j] = p;
      }
  goto done;
oom:
  ret = hm_fail(E, HYLCMAT_ERR_MEMORY, "mesh: out of memory (%d vertices, %d triangles)", nv, nt);
done:
  free(incp);
  free(inc);
  free(cnt);
  free(buf);
  return ret;
}

/* X: rest positions (nv x 3) with angle (nt or NULL), or uv (nt x 6) */
static int Create(int nv, int nt, const int *tri, const double *X, const double *angle, const double *uv, hylcmat_mesh **mesh, char *err, size_t errlen)
{
  hm_err        E = {err, errlen};
  hylcmat_mesh *M;
  int           ret;

  if (err && errlen) err[0] = 0;
  HM_CHECK(mesh, &E, HYLCMAT_ERR_ARG, "mesh: NULL output");
  *mesh = NULL;
  HM_CHECK(tri && (X || uv), &E, HYLCMAT_ERR_ARG, "mesh: NULL triangles or rest coordinates");
  HM_CHECK(nv >= 3 && nt >= 1, &E, HYLCMAT_ERR_ARG, "mesh: %d vertices and %d triangles (at least 3 and 1 needed)", nv, nt);
  HM_CHECK(nv <= 715827882 && nt <= 357913941, &E, HYLCMAT_ERR_ARG, "mesh: too large (%d vertices, %d triangles)", nv, nt);
  for (int t = 0; t < nt; t++)
    for (int k = 0; k < 3; k++) {
      const int v = tri[3 * t + k];
      HM_CHECK(v >= 0 && v < nv, &E, HYLCMAT_ERR_MESH, "mesh: triangle %d: vertex index %d out of range (%d vertices)", t, v, nv);
      HM_CHECK(v != tri[3 * t + (k + 1) % 3], &E, HYLCMAT_ERR_MESH, "mesh: triangle %d has vertex %d twice", t, v);
    }
  M = (hylcmat_mesh *)calloc(1, sizeof(*M));
  HM_CHECK(M, &E, HYLCMAT_ERR_MEMORY, "mesh: out of memory");
  M->nv   = nv;
  M->nt   = nt;
  M->st   = (int *)malloc(sizeof(int) * 6 * (size_t)nt);
  M->nb   = (int *)calloc((size_t)nt, sizeof(int));
  M->rest = (hylcmat_shell_rest *)malloc(sizeof(hylcmat_shell_rest) * (size_t)nt);
  if (!M->st || !M->nb || !M->rest) {
    hylcmat_mesh_free(M);
    return hm_fail(&E, HYLCMAT_ERR_MEMORY, "mesh: out of memory (%d triangles)", nt);
  }
  for (int t = 0; t < nt; t++) {
    double tx[9];
    for (int k = 0; k < 3; k++) M->st[6 * t + k] = tri[3 * t + k];
    M->st[6 * t + 3] = M->st[6 * t + 4] = M->st[6 * t + 5] = -1;
    if (uv) {
      ret = hylcmat_shell_rest_uv(uv + 6 * (size_t)t, &M->rest[t]);
      if (ret) {
        const double *u   = uv + 6 * (size_t)t;
        const double  det = (u[2] - u[0]) * (u[5] - u[1]) - (u[3] - u[1]) * (u[4] - u[0]);
        hylcmat_mesh_free(M);
        if (!isfinite(det)) return hm_fail(&E, ret, "mesh: triangle %d: non-finite material coordinates", t);
        if (det < 0) return hm_fail(&E, ret, "mesh: triangle %d (vertices %d %d %d): inverted rest triangle (clockwise in material coordinates, 2 A = %.6g)", t, tri[3 * t], tri[3 * t + 1], tri[3 * t + 2], det);
        if (det > 0)
          return hm_fail(&E, ret, "mesh: triangle %d (vertices %d %d %d): degenerate rest triangle in material coordinates (2 A = %.6g: an angle's sine below 1e-13, or an edge or 2 A outside 1.5e-154 .. 1.3e154)", t, tri[3 * t], tri[3 * t + 1],
                         tri[3 * t + 2], det);
        return hm_fail(&E, ret, "mesh: triangle %d (vertices %d %d %d): zero-area rest triangle in material coordinates (2 A = %.6g)", t, tri[3 * t], tri[3 * t + 1], tri[3 * t + 2], det);
      }
    } else {
      for (int k = 0; k < 3; k++)
        for (int i = 0; i < 3; i++) tx[3 * k + i] = X[3 * (size_t)tri[3 * t + k] + i];
      ret = hylcmat_shell_rest_3d(tx, angle ? angle[t] : 0, &M->rest[t]);
      if (ret) {
        int finite = angle ? isfinite(angle[t]) : 1;
        for (int i = 0; i < 9; i++) finite = finite && isfinite(tx[i]);
        hylcmat_mesh_free(M);
        if (!finite) return hm_fail(&E, ret, "mesh: triangle %d (vertices %d %d %d): non-finite rest position or material angle", t, tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]);
        return hm_fail(&E, ret, "mesh: triangle %d (vertices %d %d %d): zero-area rest triangle", t, tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]);
      }
    }
    M->area += M->rest[t].area;
  }
  ret = Adjacency(M, tri, &E);
  if (!ret) ret = Pattern(M, &E);
  if (ret) {
    hylcmat_mesh_free(M);
    return ret;
  }
  *mesh = M;
  return HYLCMAT_OK;
}

int hylcmat_mesh_create(int nv, int nt, const int *tri, const double *X, const double *angle, hylcmat_mesh **mesh, char *err, size_t errlen)
{
  if (!X) {
    hm_err E = {err, errlen};
    if (mesh) *mesh = NULL;
    return hm_fail(&E, HYLCMAT_ERR_ARG, "mesh: NULL rest positions");
  }
  return Create(nv, nt, tri, X, angle, NULL, mesh, err, errlen);
}

int hylcmat_mesh_create_uv(int nv, int nt, const int *tri, const double *uv, hylcmat_mesh **mesh, char *err, size_t errlen)
{
  if (!uv) {
    hm_err E = {err, errlen};
    if (mesh) *mesh = NULL;
    return hm_fail(&E, HYLCMAT_ERR_ARG, "mesh: NULL material coordinates");
  }
  return Create(nv, nt, tri, NULL, NULL, uv, mesh, err, errlen);
}

int hylcmat_mesh_nv(const hylcmat_mesh *mesh) { return mesh ? mesh->nv : 0; }

int hylcmat_mesh_nt(const hylcmat_mesh *mesh) { return mesh ? mesh->nt : 0; }

double hylcmat_mesh_area(const hylcmat_mesh *mesh) { return mesh ? mesh->area : 0; }

int hylcmat_mesh_element(const hylcmat_mesh *mesh, int t, int v[6], hylcmat_shell_rest *r)
{
  if (!mesh || t < 0 || t >= mesh->nt) return HYLCMAT_ERR_ARG;
  if (v)
    for (int i = 0; i < 6; i++) v[i] = mesh->st[6 * (size_t)t + i];
  if (r) *r = mesh->rest[t];
  return HYLCMAT_OK;
}

int64_t hylcmat_mesh_hessian_nnz(const hylcmat_mesh *mesh) { return mesh ? mesh->nnz : 0; }

void hylcmat_mesh_hessian_csr(const hylcmat_mesh *mesh, int64_t *rowptr, int *colind)
{
  if (!mesh) return;
  for (int v = 0; v < mesh->nv; v++) {
    const int64_t deg = mesh->adjptr[v + 1] - mesh->adjptr[v];
    for (int d = 0; d < 3; d++) {
      const int64_t start = mesh->base[v] + 3 * d * deg;
      if (rowptr) rowptr[3 * v + d] = start;
      if (colind)
        for (int64_t q = 0; q < deg; q++)
          for (int e = 0; e < 3; e++) colind[start + 3 * q + e] = 3 * mesh->adj[mesh->adjptr[v] + q] + e;
    }
  }
  if (rowptr) rowptr[3 * mesh->nv] = mesh->nnz;
}

void hylcmat_mesh_hessian_coo(const hylcmat_mesh *mesh, int *rows, int *cols)
{
  if (!mesh) return;
  hylcmat_mesh_hessian_csr(mesh, NULL, cols);
  if (rows)
    for (int v = 0; v < mesh->nv; v++) {
      const int64_t deg = mesh->adjptr[v + 1] - mesh->adjptr[v];
      for (int d = 0; d < 3; d++)
        for (int64_t q = 0; q < 3 * deg; q++) rows[mesh->base[v] + 3 * d * deg + q] = 3 * v + d;
    }
}

/* the stencil coordinates of triangle t (missing neighbours: 0) */
static inline void Gather(const hylcmat_mesh *M, int t, const double *x, double xs[18])
{
  for (int i = 0; i < 6; i++) {
    const int v = M->st[6 * (size_t)t + i];
    for (int c = 0; c < 3; c++) xs[3 * i + c] = v >= 0 ? x[3 * (size_t)v + c] : 0;
  }
}

/* 1 if every entry of v is finite */
static int AllFinite(const double *v, int64_t n)
{
  double s = 0;
  for (int64_t i = 0; i < n; i++) s += v[i] * 0;
  return s == 0;
}

static int ElementError(const hylcmat_mesh *M, int t, int ret, hm_err *E)
{
  const int *s = M->st + 6 * (size_t)t;
  return hm_fail(E, ret, "mesh: triangle %d (vertices %d %d %d, neighbours %d %d %d): %s", t, s[0], s[1], s[2], s[3], s[4], s[5], hylcmat_strerror(ret));
}

int hylcmat_mesh_strains(const hylcmat_mesh *mesh, const double *x, double *z, char *err, size_t errlen)
{
  hm_err E = {err, errlen};

  if (err && errlen) err[0] = 0;
  HM_CHECK(mesh && x && z, &E, HYLCMAT_ERR_ARG, "mesh strains: NULL argument");
  for (int t = 0; t < mesh->nt; t++) {
    double    xs[18];
    const int nb = mesh->nb[t];
    int       ret;
    Gather(mesh, t, x, xs);
    ret = hylcmat_shell_strains(&mesh->rest[t], xs, nb, z + 6 * (size_t)t, NULL);
    if (ret) {
      memset(z, 0, sizeof(double) * 6 * (size_t)mesh->nt);
      return ElementError(mesh, t, ret, &E);
    }
  }
  return HYLCMAT_OK;
}

HM_INTERN int hm_psd_project_many(int m, double *const H[], const int nb[]);

/* the group of the batched projection (hylcmat_shell_eval_batch) */
#define GROUP 4

int hylcmat_mesh_eval(const hylcmat_mesh *mesh, const hylcmat *m, const double *x, int flags, double *E, double *grad, double *hval, char *err, size_t errlen)
{
  hm_err    Er  = {err, errlen};
  double    tot = 0, xs[GROUP][18], e[GROUP], g[GROUP][18], H[GROUP][324];
  const int psd = hval && (flags & HYLCMAT_SHELL_PSD);

  if (err && errlen) err[0] = 0;
  if (E) *E = 0;
  HM_CHECK(mesh && m && x && E && (!hval || grad), &Er, HYLCMAT_ERR_ARG, "mesh eval: NULL argument (or a Hessian without the gradient)");
  if (grad) memset(grad, 0, sizeof(double) * 3 * (size_t)mesh->nv);
  if (hval) memset(hval, 0, sizeof(double) * (size_t)mesh->nnz);
  /* groups of GROUP triangles: each element without the projection, then (PSD) the group's projections
     together, then the assembly */
  for (int t0 = 0; t0 < mesh->nt; t0 += GROUP) {
    const int t1  = t0 + GROUP < mesh->nt ? t0 + GROUP : mesh->nt;
    int       ret = HYLCMAT_OK, bad = -1;
    for (int t = t0; t < t1 && !ret; t++) {
      Gather(mesh, t, x, xs[t - t0]);
      ret = hylcmat_shell_eval(m, &mesh->rest[t], xs[t - t0], mesh->nb[t], flags & ~HYLCMAT_SHELL_PSD, &e[t - t0], grad ? g[t - t0] : NULL, hval ? H[t - t0] : NULL);
      if (ret) bad = t;
    }
    if (!ret && psd) {
      double *Hs[GROUP];
      int     nbs[GROUP];
      for (int t = t0; t < t1; t++) Hs[t - t0] = H[t - t0], nbs[t - t0] = mesh->nb[t];
      if (hm_psd_project_many(t1 - t0, Hs, nbs)) /* beyond the double range: each on its own, to name the triangle */
        for (int t = t0; t < t1 && !ret; t++) {
          ret = hylcmat_shell_eval(m, &mesh->rest[t], xs[t - t0], mesh->nb[t], flags, &e[t - t0], g[t - t0], H[t - t0]);
          if (ret) bad = t;
        }
    }
    if (ret) {
      if (grad) memset(grad, 0, sizeof(double) * 3 * (size_t)mesh->nv);
      if (hval) memset(hval, 0, sizeof(double) * (size_t)mesh->nnz);
      return ElementError(mesh, bad, ret, &Er);
    }
    for (int t = t0; t < t1; t++) {
      const int *s = mesh->st + 6 * (size_t)t;
      tot += e[t - t0];
      if (grad)
        for (int i = 0; i < 6; i++)
          if (s[i] >= 0)
            for (int c = 0; c < 3; c++) grad[3 * (size_t)s[i] + c] += g[t - t0][3 * i + c];
      if (hval) {
        const int *pos = mesh->pos + 36 * (size_t)t;
        for (int i = 0; i < 6; i++) {
          int64_t row;
          int     deg3;
          if (s[i] < 0) continue;
          row  = mesh->base[s[i]];
          deg3 = 3 * (int)(mesh->adjptr[s[i] + 1] - mesh->adjptr[s[i]]);
          for (int j = 0; j < 6; j++) {
            const int p = pos[6 * i + j];
            if (p < 0) continue;
            for (int a = 0; a < 3; a++) {
              double       *dst = hval + row + a * deg3 + 3 * p;
              const double *src = H[t - t0] + 18 * (3 * i + a) + 3 * j;
              dst[0] += src[0];
              dst[1] += src[1];
              dst[2] += src[2];
            }
          }
        }
      }
    }
  }
  if (!isfinite(tot) || (grad && !AllFinite(grad, 3 * (int64_t)mesh->nv)) || (hval && !AllFinite(hval, mesh->nnz))) {
    if (grad) memset(grad, 0, sizeof(double) * 3 * (size_t)mesh->nv);
    if (hval) memset(hval, 0, sizeof(double) * (size_t)mesh->nnz);
    return hm_fail(&Er, HYLCMAT_ERR_RANGE, "mesh eval: the total energy, gradient or Hessian is beyond the double range");
  }
  *E = tot;
  return HYLCMAT_OK;
}
