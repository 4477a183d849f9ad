/* The macroscale shell element (Algorithm C8): strains z of a triangle and its three edge neighbours,
   the energy A Psi(z), its exact gradient and Hessian by the chain rule (S43, S44), and the per-element
   projection of the Hessian to positive semidefinite. Conventions: method-spec section 10 (those of
   ARCSim-HYLC's compiled code), restated in include/hylcmat.h and docs/library.md.

   Variables. The in-plane strains depend on the material axes a = x_u, b = x_v (linear in x0, x1, x2:
   a = sum_i C0[i] x_i, b = sum_i C1[i] x_i). The bending strains are II = sum_k w_k t_k t_k^T with, for
   edge k from vertex a to b, c the triangle's third vertex and p the neighbour,
       w = -2 A_def theta / l = -kappa theta,   kappa = |e x f| / |e| (the height of c over the edge),
   a function of the three edge vectors e = x_b - x_a, f = x_c - x_a, g = x_p - x_a only, with
       theta = atan2(Y, X),   Y = -|e| e.(f x g),   X = (e.f)(e.g) - |e|^2 (f.g)
   (Y and X are (n x m).e and n.m times |e x f| |g x e| > 0). So Psi is a function of the six variables
   y = (sx, sa, sy, w0, w1, w2), z = L y with L = diag(I3, T), T[j][k] = (t0^2, t0 t1, t1^2)_k, and
       dE/dx = A sum_j Psi_yj dy_j/dx,   d2E/dx2 = A (J^T Psi_yy J + sum_j Psi_yj d2y_j/dx2).
   Per edge, w's derivatives with respect to (e, f, g) are formed in closed form:
       d2w = -(theta d2kappa + kappa d2theta + dkappa dtheta^T + dtheta dkappa^T),
       d2theta = (X d2Y - Y d2X) / r^2 - (dtheta drho^T + drho dtheta^T),  drho = (X dX + Y dY) / r^2,
   r^2 = X^2 + Y^2 = (|e x f| |g x e|)^2, and mapped to the vertices (x_a gets minus the sum).

   Projection: the translations of the vertices present are exact null vectors of H; a Householder
   reflection over the vertices splits them off, the remaining (3 n - 3)-dimensional block is
   eigen-decomposed (Householder tridiagonalization and implicit QL with Wilkinson shifts), eigenvalues
   below HYLCMAT_PSD_FLOOR are raised to it (H + sum (floor - lambda) v v^T), the translations get the
   floor, and the reflection is undone. This equals clamping the eigenvalues of the whole matrix. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

/* a triangle whose sine of an angle is below this is degenerate (deformed) */
#define DEG_SINE 1e-14

static inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void Cross(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
static inline void Sub(const double a[3], const double b[3], double c[3])
{
  c[0] = a[0] - b[0];
  c[1] = a[1] - b[1];
  c[2] = a[2] - b[2];
}

/* ---- rest data ---------------------------------------------------------------------------------- */
static int RestFromEdges(double e1u, double e1v, double e2u, double e2v, hylcmat_shell_rest *r)
{
  const double det = e1u * e2v - e1v * e2u, n1 = sqrt(e1u * e1u + e1v * e1v), n2 = sqrt(e2u * e2u + e2v * e2v);

  if (!isfinite(det) || !isfinite(n1) || !isfinite(n2)) return HYLCMAT_ERR_REST;
  if (!(det > 1e-13 * n1 * n2)) return HYLCMAT_ERR_REST; /* clockwise, zero area or degenerate */
  r->dinv[0] = e2v / det;
  r->dinv[1] = -e2u / det;
  r->dinv[2] = -e1v / det;
  r->dinv[3] = e1u / det;
  r->area    = 0.5 * det;
  for (int i = 0; i < 4; i++)
    if (!isfinite(r->dinv[i])) return HYLCMAT_ERR_REST;
  if (!(r->area > 0) || !isfinite(r->area)) return HYLCMAT_ERR_REST;
  return HYLCMAT_OK;
}

int hylcmat_shell_rest_uv(const double uv[6], hylcmat_shell_rest *r)
{
  if (!uv || !r) return HYLCMAT_ERR_ARG;
  for (int i = 0; i < 6; i++)
    if (!isfinite(uv[i])) return HYLCMAT_ERR_REST;
  return RestFromEdges(uv[2] - uv[0], uv[3] - uv[1], uv[4] - uv[0], uv[5] - uv[1], r);
}

int hylcmat_shell_rest_3d(const double X[9], double angle, hylcmat_shell_rest *r)
{
  double E1[3], E2[3], N[3], l1, nN, c, s, p, q;

  if (!X || !r) return HYLCMAT_ERR_ARG;
  for (int i = 0; i < 9; i++)
    if (!isfinite(X[i])) return HYLCMAT_ERR_REST;
  if (!isfinite(angle)) return HYLCMAT_ERR_REST;
  Sub(X + 3, X, E1);
  Sub(X + 6, X, E2);
  Cross(E1, E2, N);
  l1 = sqrt(Dot(E1, E1));
  nN = sqrt(Dot(N, N));
  if (!(l1 > 0) || !(nN > 1e-13 * l1 * sqrt(Dot(E2, E2))) || !isfinite(nN)) return HYLCMAT_ERR_REST;
  /* x2 in the frame (E1 / l1, n x E1 / l1): (E2.E1 / l1, |E1 x E2| / l1); then the material axes at
     the angle: u = (cos, sin) . y, v = (-sin, cos) . y */
  p = Dot(E1, E2) / l1;
  q = nN / l1;
  c = cos(angle);
  s = sin(angle);
  return RestFromEdges(c * l1, -s * l1, c * p + s * q, -s * p + c * q, r);
}

/* ---- one edge (hinge) ---------------------------------------------------------------------------- */
typedef struct {
  double e[3], f[3], g[3];
  double len, l2, l, fe, ge, fg, sig, fp[3], kap, V, X, Y, r2, th, w; /* len = |e|; the rest in units of len */
  double cfg[3], cge[3], N[3];                                        /* f x g, g x e, e x f */
  double dX[9], dY[9], dth[9], dkap[9], dw[9];
} Hinge;

/* values. The edge is computed in units of its length (e, f, g divided by |e| = len): theta is
   invariant, kappa and w = len w~ scale with it, so dw/dx = dw~/d(e, f, g)~ and d2w/dx2 = d2w~ / len;
   X, Y and r^2 stay of order 1 for any size of the stencil. Returns HYLCMAT_ERR_DEGENERATE if the
   neighbour face has zero area (the central triangle was checked by the caller). */
static int HingeValue(Hinge *h)
{
  double *e = h->e, *f = h->f, *g = h->g, g2, il;

  h->len = sqrt(Dot(e, e));
  if (!(h->len > 0) || !isfinite(h->len)) return h->len > 0 ? HYLCMAT_ERR_RANGE : HYLCMAT_ERR_DEGENERATE;
  il = 1 / h->len;
  for (int i = 0; i < 3; i++) e[i] *= il, f[i] *= il, g[i] *= il;
  h->l2  = Dot(e, e);
  h->l   = sqrt(h->l2);
  h->fe  = Dot(f, e);
  h->ge  = Dot(g, e);
  h->fg  = Dot(f, g);
  h->sig = h->fe / h->l2;
  for (int i = 0; i < 3; i++) h->fp[i] = f[i] - h->sig * e[i];
  h->kap = sqrt(Dot(h->fp, h->fp));
  Cross(f, g, h->cfg);
  h->V  = Dot(e, h->cfg);
  h->Y  = -h->l * h->V;
  h->X  = h->fe * h->ge - h->l2 * h->fg;
  h->r2 = h->X * h->X + h->Y * h->Y;
  g2    = Dot(g, g);
  if (!isfinite(h->r2) || !isfinite(g2)) return HYLCMAT_ERR_RANGE;
  /* r^2 = |e x f|^2 |g x e|^2 and |e x f| = kappa l: the neighbour's sine below DEG_SINE */
  if (!(h->r2 > DEG_SINE * DEG_SINE * h->kap * h->kap * h->l2 * h->l2 * g2)) return HYLCMAT_ERR_DEGENERATE;
  h->th = atan2(h->Y, h->X);
  h->w  = -h->len * h->kap * h->th;
  return HYLCMAT_OK;
}

/* gradients of X, Y, theta, kappa, w with respect to (e, f, g) */
static void HingeGrad(Hinge *h)
{
  const double *e = h->e, *f = h->f, *g = h->g, il = 1 / h->l, ir2 = 1 / h->r2, ik = 1 / h->kap;

  Cross(g, e, h->cge);
  Cross(e, f, h->N);
  for (int i = 0; i < 3; i++) {
    h->dY[i]       = -(h->V * e[i] * il + h->l * h->cfg[i]);
    h->dY[3 + i]   = -h->l * h->cge[i];
    h->dY[6 + i]   = -h->l * h->N[i];
    h->dX[i]       = h->ge * f[i] + h->fe * g[i] - 2 * h->fg * e[i];
    h->dX[3 + i]   = h->ge * e[i] - h->l2 * g[i];
    h->dX[6 + i]   = h->fe * e[i] - h->l2 * f[i];
    h->dkap[i]     = -h->sig * h->fp[i] * ik;
    h->dkap[3 + i] = h->fp[i] * ik;
    h->dkap[6 + i] = 0;
  }
  for (int i = 0; i < 9; i++) {
    h->dth[i] = (h->X * h->dY[i] - h->Y * h->dX[i]) * ir2;
    h->dw[i]  = -(h->th * h->dkap[i] + h->kap * h->dth[i]);
  }
}

/* adds s (a) to the 3 x 3 block B: B += s I */
static inline void AddI(double B[9], double s)
{
  B[0] += s;
  B[4] += s;
  B[8] += s;
}
/* B += s a b^T */
static inline void AddOuter(double B[9], double s, const double a[3], const double b[3])
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) B[3 * i + j] += s * a[i] * b[j];
}
/* B += s [a]_x (the cross-product matrix: [a]_x y = a x y) */
static inline void AddCrossMat(double B[9], double s, const double a[3])
{
  B[1] -= s * a[2];
  B[2] += s * a[1];
  B[3] += s * a[2];
  B[5] -= s * a[0];
  B[6] -= s * a[1];
  B[7] += s * a[0];
}

/* L (9 x 9, row-major, full) += wt d2w/d(e, f, g)^2 */
static void HingeHess(const Hinge *h, double wt, double L[81])
{
  const double *e = h->e, *f = h->f, *g = h->g;
  const double  il = 1 / h->l, ik = 1 / h->kap, ir2 = 1 / h->r2, l2 = h->l2, sig = h->sig;
  /* the blocks (ee, ef, eg, ff, fg, gg) of the sparse parts: d2w_s = -theta d2kappa - kappa (X d2Y - Y d2X) / r^2
     (d2kappa without its -dkappa dkappa^T / kappa part, added below with the outer products) */
  double ee[9], ef[9], eg[9], ff[9], fg[9], gg[9], eh[3];
  double cK = -h->th * ik, cY = -h->kap * h->X * ir2, cX = h->kap * h->Y * ir2;
  double drho[9], mu[9];

  memset(ee, 0, sizeof(ee));
  memset(ef, 0, sizeof(ef));
  memset(eg, 0, sizeof(eg));
  memset(ff, 0, sizeof(ff));
  memset(fg, 0, sizeof(fg));
  memset(gg, 0, sizeof(gg));
  for (int i = 0; i < 3; i++) eh[i] = e[i] * il;
  /* kappa: d2kappa = (Q2 - dkappa dkappa^T) / kappa with Q2 = d2(kappa^2) / 2:
     ff = I - eh eh^T; fe = -(e fp^T - sig e e^T) / l2 - sig I; ee = (-fp fp^T + sig (fp e^T + e fp^T) - sig^2 e e^T) / l2 + sig^2 I */
  AddI(ff, cK);
  AddOuter(ff, -cK, eh, eh);
  /* ef = fe^T = -(fp e^T - sig e e^T) / l2 - sig I */
  AddOuter(ef, -cK / l2, h->fp, e);
  AddOuter(ef, cK * sig / l2, e, e);
  AddI(ef, -cK * sig);
  AddOuter(ee, -cK / l2, h->fp, h->fp);
  AddOuter(ee, cK * sig / l2, h->fp, e);
  AddOuter(ee, cK * sig / l2, e, h->fp);
  AddOuter(ee, -cK * sig * sig / l2, e, e);
  AddI(ee, cK * sig * sig);
  /* Y = -l V: ee = -(V (I - eh eh^T) / l + eh cfg^T + cfg eh^T); ef = -eh cge^T + l [g]_x;
     eg = -eh N^T - l [f]_x; fg = l [e]_x */
  AddI(ee, -cY * h->V * il);
  AddOuter(ee, cY * h->V * il, eh, eh);
  AddOuter(ee, -cY, eh, h->cfg);
  AddOuter(ee, -cY, h->cfg, eh);
  AddOuter(ef, -cY, eh, h->cge);
  AddCrossMat(ef, cY * h->l, g);
  AddOuter(eg, -cY, eh, h->N);
  AddCrossMat(eg, -cY * h->l, f);
  AddCrossMat(fg, cY * h->l, e);
  /* X = (e.f)(e.g) - (e.e)(f.g): ee = f g^T + g f^T - 2 fg I; ef = g e^T + ge I - 2 e g^T;
     eg = f e^T + fe I - 2 e f^T; fg = e e^T - l2 I */
  AddOuter(ee, cX, f, g);
  AddOuter(ee, cX, g, f);
  AddI(ee, -2 * cX * h->fg);
  AddOuter(ef, cX, g, e);
  AddI(ef, cX * h->ge);
  AddOuter(ef, -2 * cX, e, g);
  AddOuter(eg, cX, f, e);
  AddI(eg, cX * h->fe);
  AddOuter(eg, -2 * cX, e, f);
  AddOuter(fg, cX, e, e);
  AddI(fg, -cX * l2);
  /* the outer products: -theta (-dkappa dkappa^T / kappa) + (dtheta mu^T + mu dtheta^T), with
     mu = kappa drho - dkappa */
  for (int i = 0; i < 9; i++) {
    drho[i] = (h->X * h->dX[i] + h->Y * h->dY[i]) * ir2;
    mu[i]   = h->kap * drho[i] - h->dkap[i];
  }
  {
    const double ck = h->th * ik;
    for (int i = 0; i < 9; i++)
      for (int j = 0; j < 9; j++) L[9 * i + j] += wt * (ck * h->dkap[i] * h->dkap[j] + h->dth[i] * mu[j] + mu[i] * h->dth[j]);
  }
  /* the blocks, symmetric: (r, c) and (c, r) */
  {
    const double *B[3][3] = {{ee, ef, eg}, {NULL, ff, fg}, {NULL, NULL, gg}};
    for (int r = 0; r < 3; r++)
      for (int c = r; c < 3; c++) {
        const double *b = B[r][c];
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) {
            if (r == c) {
              L[9 * (3 * r + i) + 3 * c + j] += wt * 0.5 * (b[3 * i + j] + b[3 * j + i]);
            } else {
              L[9 * (3 * r + i) + 3 * c + j] += wt * b[3 * i + j];
              L[9 * (3 * c + j) + 3 * r + i] += wt * b[3 * i + j];
            }
          }
      }
  }
}

/* ---- the element ---------------------------------------------------------------------------------- */
typedef struct {
  double a[3], b[3], al, be, ah[3], bh[3], sa; /* material axes, lengths, unit vectors, cosine */
  double C0[3], C1[3];                         /* a = sum C0[i] x_i, b = sum C1[i] x_i */
  double T[3][3];                              /* T[k] = (t0^2, t0 t1, t1^2) of edge k */
  int    nb;
  Hinge  h[3]; /* e, f, g in units of the edge length */
} Elem;

static const int EdgeA[3] = {0, 1, 2}, EdgeB[3] = {1, 2, 0}, EdgeC[3] = {2, 0, 1};

/* the strains z (6); HYLCMAT_ERR_NONFINITE / _DEGENERATE */
static int Strains(const hylcmat_shell_rest *r, const double x[18], int nb, Elem *el, double z[6])
{
  const double *D = r->dinv;
  double        d1[3], d2[3], N[3], t[3][2];

  for (int i = 0; i < 9; i++)
    if (!isfinite(x[i])) return HYLCMAT_ERR_NONFINITE;
  for (int k = 0; k < 3; k++)
    if (nb >> k & 1)
      for (int i = 0; i < 3; i++)
        if (!isfinite(x[9 + 3 * k + i])) return HYLCMAT_ERR_NONFINITE;
  el->nb = nb;
  Sub(x + 3, x, d1);
  Sub(x + 6, x, d2);
  el->C0[1] = D[0];
  el->C0[2] = D[2];
  el->C0[0] = -(D[0] + D[2]);
  el->C1[1] = D[1];
  el->C1[2] = D[3];
  el->C1[0] = -(D[1] + D[3]);
  for (int i = 0; i < 3; i++) {
    el->a[i] = D[0] * d1[i] + D[2] * d2[i];
    el->b[i] = D[1] * d1[i] + D[3] * d2[i];
  }
  el->al = sqrt(Dot(el->a, el->a));
  el->be = sqrt(Dot(el->b, el->b));
  Cross(d1, d2, N);
  {
    const double nN = sqrt(Dot(N, N)), n12 = sqrt(Dot(d1, d1) * Dot(d2, d2));
    if (!isfinite(el->al) || !isfinite(el->be) || !isfinite(nN) || !isfinite(n12)) return HYLCMAT_ERR_RANGE;
    if (!(nN > DEG_SINE * n12) || !(el->al > 0) || !(el->be > 0)) return HYLCMAT_ERR_DEGENERATE;
  }
  for (int i = 0; i < 3; i++) {
    el->ah[i] = el->a[i] / el->al;
    el->bh[i] = el->b[i] / el->be;
  }
  el->sa = Dot(el->ah, el->bh);
  z[0]   = el->al - 1;
  z[1]   = el->sa;
  z[2]   = el->be - 1;
  z[3] = z[4] = z[5] = 0;
  /* t_k: row 1 of Dm^-1 for edge (0,1), -(row 0 + row 1) for (1,2), row 0 for (2,0) */
  t[0][0] = D[2];
  t[0][1] = D[3];
  t[1][0] = -(D[0] + D[2]);
  t[1][1] = -(D[1] + D[3]);
  t[2][0] = D[0];
  t[2][1] = D[1];
  for (int k = 0; k < 3; k++) {
    el->T[k][0] = t[k][0] * t[k][0];
    el->T[k][1] = t[k][0] * t[k][1];
    el->T[k][2] = t[k][1] * t[k][1];
    if (!(nb >> k & 1)) continue;
    {
      Hinge        *h  = &el->h[k];
      const double *xa = x + 3 * EdgeA[k], *xb = x + 3 * EdgeB[k], *xc = x + 3 * EdgeC[k], *xp = x + 9 + 3 * k;
      Sub(xb, xa, h->e);
      Sub(xc, xa, h->f);
      Sub(xp, xa, h->g);
      HM_CALL(HingeValue(h));
      for (int j = 0; j < 3; j++) z[3 + j] += h->w * el->T[k][j];
    }
  }
  return HYLCMAT_OK;
}

/* B (3 x 3) into H (18 x 18) at vertex block (vi, vj), and B^T at (vj, vi) when vi != vj */
static inline void AddBlock(double *H, int vi, int vj, const double B[9])
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) H[18 * (3 * vi + i) + 3 * vj + j] += B[3 * i + j];
  if (vi != vj)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) H[18 * (3 * vj + j) + 3 * vi + i] += B[3 * i + j];
}

/* the 9 x 9 local Hessian L of an edge (variables e, f, g) into H at the vertices (a, b, c, p): e, f, g are
   x_b - x_a, x_c - x_a, x_p - x_a */
static void MapHinge(double *H, const double L[81], int va, int vb, int vc, int vp)
{
  const int v[3] = {vb, vc, vp};
  double    S[3][9], tot[9];

  memset(S, 0, sizeof(S));
  memset(tot, 0, sizeof(tot));
  for (int r = 0; r < 3; r++)
    for (int c = r; c < 3; c++) {
      double B[9];
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) B[3 * i + j] = L[9 * (3 * r + i) + 3 * c + j];
      AddBlock(H, v[r], v[c], B);
    }
  /* block (a, c) = -sum_r L[r][c]; (a, a) = sum of all */
  for (int c = 0; c < 3; c++)
    for (int r = 0; r < 3; r++)
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) S[c][3 * i + j] -= L[9 * (3 * r + i) + 3 * c + j];
  for (int c = 0; c < 3; c++) {
    AddBlock(H, va, v[c], S[c]);
    for (int i = 0; i < 9; i++) tot[i] -= S[c][i];
  }
  AddBlock(H, va, va, tot);
}

HM_INTERN int hm_psd_project(double H[324], int nb);

/* the element at level 0 (E), 1 (+ g), 2 (+ H) */
static int Element(const hylcmat *m, const hylcmat_shell_rest *r, const double x[18], int nb, int level, double *E, double g[18], double H[324], double zout[6])
{
  Elem         el;
  double       z[6], psi, dpsi[6], hpsi[36], py[6], Hy[36], A = r->area;
  const double T0 = 0;

  (void)T0;
  HM_CALL(Strains(r, x, nb, &el, z));
  if (zout) memcpy(zout, z, sizeof(z));
  HM_CALL(hylcmat_eval(m, z, &psi, level ? dpsi : NULL, level > 1 ? hpsi : NULL));
  *E = A * psi;
  if (!level) return HYLCMAT_OK;
  /* Psi_y = L^T Psi_z (times A) */
  for (int j = 0; j < 3; j++) py[j] = A * dpsi[j];
  for (int k = 0; k < 3; k++) py[3 + k] = A * (el.T[k][0] * dpsi[3] + el.T[k][1] * dpsi[4] + el.T[k][2] * dpsi[5]);
  /* gradient: in-plane through (a, b) */
  {
    double ga[3], gb[3];
    for (int i = 0; i < 3; i++) {
      ga[i] = py[0] * el.ah[i] + py[1] * (el.bh[i] - el.sa * el.ah[i]) / el.al;
      gb[i] = py[2] * el.bh[i] + py[1] * (el.ah[i] - el.sa * el.bh[i]) / el.be;
    }
    for (int v = 0; v < 3; v++)
      for (int i = 0; i < 3; i++) g[3 * v + i] = el.C0[v] * ga[i] + el.C1[v] * gb[i];
    for (int i = 9; i < 18; i++) g[i] = 0;
  }
  for (int k = 0; k < 3; k++) {
    Hinge *h = &el.h[k];
    if (!(nb >> k & 1)) continue;
    HingeGrad(h);
    {
      const int va = EdgeA[k], v[3] = {EdgeB[k], EdgeC[k], 3 + k};
      for (int c = 0; c < 3; c++)
        for (int i = 0; i < 3; i++) {
          g[3 * v[c] + i] += py[3 + k] * h->dw[3 * c + i];
          g[3 * va + i] -= py[3 + k] * h->dw[3 * c + i];
        }
    }
  }
  if (level < 2) return HYLCMAT_OK;
  /* Hessian. Psi_yy = L^T Psi_zz L (times A) */
  {
    double HL[36]; /* Psi_zz L */
    for (int i = 0; i < 6; i++) {
      for (int j = 0; j < 3; j++) HL[6 * i + j] = hpsi[6 * i + j];
      for (int k = 0; k < 3; k++) HL[6 * i + 3 + k] = el.T[k][0] * hpsi[6 * i + 3] + el.T[k][1] * hpsi[6 * i + 4] + el.T[k][2] * hpsi[6 * i + 5];
    }
    for (int j = 0; j < 6; j++) {
      for (int i = 0; i < 3; i++) Hy[6 * i + j] = A * HL[6 * i + j];
      for (int k = 0; k < 3; k++) Hy[6 * (3 + k) + j] = A * (el.T[k][0] * HL[6 * 3 + j] + el.T[k][1] * HL[6 * 4 + j] + el.T[k][2] * HL[6 * 5 + j]);
    }
  }
  memset(H, 0, sizeof(double) * 324);
  {
    /* J: rows y, as 3-vectors per vertex; Jc[r][v] for the central vertices v = 0, 1, 2, jn[k] = dw_k/dx_{3+k} */
    double Jc[6][3][3], jn[3][3];
    memset(Jc, 0, sizeof(Jc));
    for (int v = 0; v < 3; v++)
      for (int i = 0; i < 3; i++) {
        Jc[0][v][i] = el.C0[v] * el.ah[i];
        Jc[1][v][i] = el.C0[v] * (el.bh[i] - el.sa * el.ah[i]) / el.al + el.C1[v] * (el.ah[i] - el.sa * el.bh[i]) / el.be;
        Jc[2][v][i] = el.C1[v] * el.bh[i];
      }
    for (int k = 0; k < 3; k++) {
      const Hinge *h = &el.h[k];
      if (!(nb >> k & 1)) continue;
      {
        const int va = EdgeA[k], v[2] = {EdgeB[k], EdgeC[k]};
        for (int i = 0; i < 3; i++) {
          Jc[3 + k][v[0]][i] += h->dw[i];
          Jc[3 + k][v[1]][i] += h->dw[3 + i];
          Jc[3 + k][va][i] -= h->dw[i] + h->dw[3 + i] + h->dw[6 + i];
          jn[k][i] = h->dw[6 + i];
        }
      }
    }
    /* J^T Psi_yy J: central blocks */
    {
      double P[6][3][3]; /* Psi_yy Jc */
      for (int r2 = 0; r2 < 6; r2++)
        for (int v = 0; v < 3; v++)
          for (int i = 0; i < 3; i++) {
            double s = 0;
            for (int q = 0; q < 6; q++) s += Hy[6 * r2 + q] * Jc[q][v][i];
            P[r2][v][i] = s;
          }
      for (int vi = 0; vi < 3; vi++)
        for (int vj = vi; vj < 3; vj++) {
          double B[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
          for (int q = 0; q < 6; q++) AddOuter(B, 1, Jc[q][vi], P[q][vj]);
          if (vi == vj)
            for (int i = 0; i < 3; i++)
              for (int j = 0; j < 3; j++) H[18 * (3 * vi + i) + 3 * vj + j] += B[3 * i + j];
          else
            AddBlock(H, vi, vj, B);
        }
      /* central-neighbour and neighbour-neighbour blocks */
      for (int k = 0; k < 3; k++) {
        if (!(nb >> k & 1)) continue;
        for (int v = 0; v < 3; v++) {
          double B[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
          AddOuter(B, 1, P[3 + k][v], jn[k]);
          AddBlock(H, v, 3 + k, B);
        }
        for (int l = k; l < 3; l++) {
          double B[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
          if (!(nb >> l & 1)) continue;
          AddOuter(B, Hy[6 * (3 + k) + 3 + l], jn[k], jn[l]);
          AddBlock(H, 3 + k, 3 + l, B);
        }
      }
    }
  }
  /* + Psi_y d2y: in-plane, K in (a, b) */
  {
    const double ia = 1 / el.al, ib = 1 / el.be, sa = el.sa;
    double       Kaa[9], Kab[9], Kbb[9], gA[3], gB[3];
    memset(Kaa, 0, sizeof(Kaa));
    memset(Kab, 0, sizeof(Kab));
    memset(Kbb, 0, sizeof(Kbb));
    for (int i = 0; i < 3; i++) {
      gA[i] = (el.bh[i] - sa * el.ah[i]) * ia;
      gB[i] = (el.ah[i] - sa * el.bh[i]) * ib;
    }
    /* sx: (I - ah ah^T) / al; sy: (I - bh bh^T) / be */
    AddI(Kaa, py[0] * ia);
    AddOuter(Kaa, -py[0] * ia, el.ah, el.ah);
    AddI(Kbb, py[2] * ib);
    AddOuter(Kbb, -py[2] * ib, el.bh, el.bh);
    /* sa: aa = -(gA ah^T + ah gA^T) / al - sa (I - ah ah^T) / al^2, bb likewise,
       ab = (I - ah ah^T - bh bh^T + sa ah bh^T) / (al be) */
    AddOuter(Kaa, -py[1] * ia, gA, el.ah);
    AddOuter(Kaa, -py[1] * ia, el.ah, gA);
    AddI(Kaa, -py[1] * sa * ia * ia);
    AddOuter(Kaa, py[1] * sa * ia * ia, el.ah, el.ah);
    AddOuter(Kbb, -py[1] * ib, gB, el.bh);
    AddOuter(Kbb, -py[1] * ib, el.bh, gB);
    AddI(Kbb, -py[1] * sa * ib * ib);
    AddOuter(Kbb, py[1] * sa * ib * ib, el.bh, el.bh);
    AddI(Kab, py[1] * ia * ib);
    AddOuter(Kab, -py[1] * ia * ib, el.ah, el.ah);
    AddOuter(Kab, -py[1] * ia * ib, el.bh, el.bh);
    AddOuter(Kab, py[1] * sa * ia * ib, el.ah, el.bh);
    for (int vi = 0; vi < 3; vi++)
      for (int vj = vi; vj < 3; vj++) {
        double B[9];
        for (int q = 0; q < 9; q++) {
          const int i = q / 3, j = q % 3;
          B[q] = el.C0[vi] * el.C0[vj] * Kaa[q] + el.C1[vi] * el.C1[vj] * Kbb[q] + el.C0[vi] * el.C1[vj] * Kab[q] + el.C1[vi] * el.C0[vj] * Kab[3 * j + i];
        }
        if (vi == vj)
          for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) H[18 * (3 * vi + i) + 3 * vj + j] += 0.5 * (B[3 * i + j] + B[3 * j + i]);
        else
          AddBlock(H, vi, vj, B);
      }
  }
  /* bending */
  for (int k = 0; k < 3; k++) {
    double L[81];
    if (!(nb >> k & 1)) continue;
    memset(L, 0, sizeof(L));
    HingeHess(&el.h[k], py[3 + k] / el.h[k].len, L);
    MapHinge(H, L, EdgeA[k], EdgeB[k], EdgeC[k], 3 + k);
  }
  /* exact symmetry */
  for (int i = 0; i < 18; i++)
    for (int j = i + 1; j < 18; j++) {
      const double s = 0.5 * (H[18 * i + j] + H[18 * j + i]);
      H[18 * i + j] = H[18 * j + i] = s;
    }
  return HYLCMAT_OK;
}

int hylcmat_shell_strains(const hylcmat_shell_rest *r, const double x[18], int nbmask, double z[6], double J[108])
{
  Elem el;
  int  ret;

  if (!r || !x || !z) return HYLCMAT_ERR_ARG;
  ret = Strains(r, x, nbmask & 7, &el, z);
  if (ret) {
    for (int i = 0; i < 6; i++) z[i] = 0;
    if (J)
      for (int i = 0; i < 108; i++) J[i] = 0;
    return ret;
  }
  if (J) {
    const double ia = 1 / el.al, ib = 1 / el.be;
    memset(J, 0, sizeof(double) * 108);
    for (int v = 0; v < 3; v++)
      for (int i = 0; i < 3; i++) {
        J[3 * v + i]      = el.C0[v] * el.ah[i];
        J[18 + 3 * v + i] = el.C0[v] * (el.bh[i] - el.sa * el.ah[i]) * ia + el.C1[v] * (el.ah[i] - el.sa * el.bh[i]) * ib;
        J[36 + 3 * v + i] = el.C1[v] * el.bh[i];
      }
    for (int k = 0; k < 3; k++) {
      Hinge *h = &el.h[k];
      if (!(nbmask >> k & 1)) continue;
      HingeGrad(h);
      {
        const int va = EdgeA[k], v[3] = {EdgeB[k], EdgeC[k], 3 + k};
        for (int c = 0; c < 3; c++)
          for (int i = 0; i < 3; i++) {
            const double dw = h->dw[3 * c + i];
            for (int j = 0; j < 3; j++) {
              J[18 * (3 + j) + 3 * v[c] + i] += el.T[k][j] * dw;
              J[18 * (3 + j) + 3 * va + i] -= el.T[k][j] * dw;
            }
          }
      }
    }
  }
  return HYLCMAT_OK;
}

/* 0 if every entry of v (n) is finite */
static inline int NonFinite(const double *v, int n)
{
  double s = 0;
  for (int i = 0; i < n; i++) s += v[i] * 0;
  return s != 0 || isnan(s);
}

int hylcmat_shell_eval(const hylcmat *m, const hylcmat_shell_rest *r, const double x[18], int nbmask, int flags, double *E, double grad[18], double hess[324])
{
  const int level = hess ? 2 : (grad ? 1 : 0);
  double    e     = 0;
  int       ret;

  if (!m || !r || !x || !E || (hess && !grad)) {
    ret = HYLCMAT_ERR_ARG;
    goto fail;
  }
  ret = Element(m, r, x, nbmask & 7, level, &e, grad, hess, NULL);
  if (ret) goto fail;
  if (!isfinite(e) || (level > 0 && NonFinite(grad, 18)) || (level > 1 && NonFinite(hess, 324))) {
    ret = HYLCMAT_ERR_RANGE;
    goto fail;
  }
  if (level > 1 && (flags & HYLCMAT_SHELL_PSD)) {
    ret = hm_psd_project(hess, nbmask & 7);
    if (ret) goto fail;
  }
  *E = e;
  return HYLCMAT_OK;
fail:
  if (E) *E = 0;
  if (grad)
    for (int i = 0; i < 18; i++) grad[i] = 0;
  if (hess)
    for (int i = 0; i < 324; i++) hess[i] = 0;
  return ret;
}
