/* The macroscale shell element (Algorithm C8): strains z of a triangle and its three edge neighbours,
   the energy A Psi(z), its exact gradient and Hessian by the chain rule (S43, S44), and the per-element
   projection of the Hessian to positive semidefinite. Conventions: docs/method.md §10 (those of
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

   Projection (src/hylcmat/psd.c): the translations of the vertices present are exact null vectors of
   H; a Householder reflection over the vertices splits them off, the remaining (3 n - 3)-dimensional
   block is eigen-decomposed (Householder tridiagonalization and implicit QR with Wilkinson shifts),
   eigenvalues below HYLCMAT_PSD_FLOOR are raised to it (H + sum (floor - lambda) u u^T), and the
   translations get the floor: the same as clamping the eigenvalues of the whole matrix. The Hessian is
   built in its upper block triangle and mirrored once, so it is exactly symmetric. */
#include "hylcmatimpl.h"
#include <math.h>
#include <string.h>

/* a triangle whose sine of an angle is below this is degenerate (deformed) */
#define DEG_SINE 1e-14

static inline double Dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline void   Cross(const double a[3], const double b[3], double c[3])
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
/* the element squares edge lengths and twice the area (2 A = |e1 x e2|): a rest triangle whose edges or
   2 A lie outside [REST_MIN, REST_MAX] would be degenerate (squares below the normal doubles: a
   subnormal area) or out of range (squares beyond the double range) at its own rest state */
#define REST_MIN 1.4916681462400413e-154 /* sqrt(DBL_MIN) */
#define REST_MAX 1.3407807929942596e+154 /* sqrt(DBL_MAX) */

static int RestFromEdges(double e1u, double e1v, double e2u, double e2v, hylcmat_shell_rest *r)
{
  const double det = e1u * e2v - e1v * e2u, n1 = hypot(e1u, e1v), n2 = hypot(e2u, e2v);

  if (!isfinite(det) || !isfinite(n1) || !isfinite(n2)) return HYLCMAT_ERR_REST;
  if (!(det >= REST_MIN && det <= REST_MAX && n1 >= REST_MIN && n1 <= REST_MAX && n2 >= REST_MIN && n2 <= REST_MAX)) return HYLCMAT_ERR_REST; /* clockwise, zero, subnormal or huge */
  if (!(det / n1 / n2 > 1e-13)) return HYLCMAT_ERR_REST;                                                                                      /* degenerate: the sine of the angle at vertex 0 */
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

/* dw alone (energy + gradient: the same operations as HingeGrad, the intermediate gradients in
   locals, not stored) */
static void HingeGradW(const Hinge *h, double dw[9])
{
  const double *e = h->e, *f = h->f, *g = h->g, il = 1 / h->l, ir2 = 1 / h->r2, ik = 1 / h->kap;
  double        cge[3], N[3];

  Cross(g, e, cge);
  Cross(e, f, N);
  for (int i = 0; i < 3; i++) {
    const double dY0 = -(h->V * e[i] * il + h->l * h->cfg[i]), dY1 = -h->l * cge[i], dY2 = -h->l * N[i];
    const double dX0 = h->ge * f[i] + h->fe * g[i] - 2 * h->fg * e[i], dX1 = h->ge * e[i] - h->l2 * g[i], dX2 = h->fe * e[i] - h->l2 * f[i];
    const double dk0 = -h->sig * h->fp[i] * ik, dk1 = h->fp[i] * ik;
    const double dt0 = (h->X * dY0 - h->Y * dX0) * ir2, dt1 = (h->X * dY1 - h->Y * dX1) * ir2, dt2 = (h->X * dY2 - h->Y * dX2) * ir2;
    dw[i]     = -(h->th * dk0 + h->kap * dt0);
    dw[3 + i] = -(h->th * dk1 + h->kap * dt1);
    dw[6 + i] = -(h->th * 0 + h->kap * dt2);
  }
}

/* B += s I */
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
/* entry (i, j) of the cross-product matrix [a]_x ([a]_x y = a x y) */
static inline double CrossMat(const double a[3], int i, int j) { return i == j ? 0 : (j == (i + 1) % 3 ? -a[3 - i - j] : a[3 - i - j]); }

/* The blocks B[0..5] = ee, ef, eg, ff, fg, gg (3 x 3, row-major; the diagonal blocks exactly
   symmetric) of wt d2w~/d(e, f, g)^2 (units of the edge: the caller divides wt by its length):
     d2w = -theta d2kappa - kappa (X d2Y - Y d2X) / r^2 + dtheta mu^T + mu dtheta^T,  mu = kappa drho - dkappa,
   with d2kappa = (Q2 - dkappa dkappa^T) / kappa, Q2 = d2(kappa^2) / 2:
     Q2: ff = I - eh eh^T; ef = -(fp e^T - sig e e^T) / l2 - sig I; ee = (-fp fp^T + sig (fp e^T + e fp^T) - sig^2 e e^T) / l2 + sig^2 I;
     d2Y: ee = -(V (I - eh eh^T) / l + eh cfg^T + cfg eh^T); ef = -eh cge^T + l [g]_x; eg = -eh N^T - l [f]_x; fg = l [e]_x;
     d2X: ee = f g^T + g f^T - 2 fg I; ef = g e^T + ge I - 2 e g^T; eg = f e^T + fe I - 2 e f^T; fg = e e^T - l2 I
   (cfg = f x g, cge = g x e, N = e x f, eh = e / l, fp = f - sig e). */
static void HingeHess(const Hinge *h, double wt, double B[6][9])
{
  const double *e = h->e, *f = h->f, *g = h->g, *fp = h->fp;
  const double  il = 1 / h->l, ik = 1 / h->kap, ir2 = 1 / h->r2, il2 = 1 / h->l2, sig = h->sig, V = h->V, l = h->l;
  const double  cK = -h->th * ik * wt, cY = -h->kap * h->X * ir2 * wt, cX = h->kap * h->Y * ir2 * wt, ck = h->th * ik * wt;
  double        A[9], M[9], eh[3], Gx[9], Fx[9], Ex[9];

  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) Gx[3 * i + j] = CrossMat(g, i, j), Fx[3 * i + j] = CrossMat(f, i, j), Ex[3 * i + j] = CrossMat(e, i, j);
  for (int i = 0; i < 9; i++) {
    A[i] = wt * h->dth[i];
    M[i] = h->kap * (h->X * h->dX[i] + h->Y * h->dY[i]) * ir2 - h->dkap[i];
  }
  for (int i = 0; i < 3; i++) eh[i] = e[i] * il;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      const double d = i == j ? 1 : 0;
      if (j >= i) {
        B[0][3 * i + j] = cK * ((-fp[i] * fp[j] + sig * (fp[i] * e[j] + e[i] * fp[j]) - sig * sig * e[i] * e[j]) * il2 + sig * sig * d) - cY * (V * il * (d - eh[i] * eh[j]) + eh[i] * h->cfg[j] + h->cfg[i] * eh[j]) +
                          cX * (f[i] * g[j] + g[i] * f[j] - 2 * h->fg * d) + ck * h->dkap[i] * h->dkap[j] + A[i] * M[j] + M[i] * A[j];
        B[3][3 * i + j] = cK * (d - eh[i] * eh[j]) + ck * h->dkap[3 + i] * h->dkap[3 + j] + A[3 + i] * M[3 + j] + M[3 + i] * A[3 + j];
        B[5][3 * i + j] = A[6 + i] * M[6 + j] + M[6 + i] * A[6 + j];
      }
      B[1][3 * i + j] =
          cK * ((sig * e[i] * e[j] - fp[i] * e[j]) * il2 - sig * d) + cY * (l * Gx[3 * i + j] - eh[i] * h->cge[j]) + cX * (g[i] * e[j] + h->ge * d - 2 * e[i] * g[j]) + ck * h->dkap[i] * h->dkap[3 + j] + A[i] * M[3 + j] + M[i] * A[3 + j];
      B[2][3 * i + j] = -cY * (eh[i] * h->N[j] + l * Fx[3 * i + j]) + cX * (f[i] * e[j] + h->fe * d - 2 * e[i] * f[j]) + A[i] * M[6 + j] + M[i] * A[6 + j];
      B[4][3 * i + j] = cY * l * Ex[3 * i + j] + cX * (e[i] * e[j] - h->l2 * d) + A[3 + i] * M[6 + j] + M[3 + i] * A[6 + j];
    }
  for (int q = 0; q < 6; q += 3)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < i; j++) B[q][3 * i + j] = B[q][3 * j + i];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < i; j++) B[5][3 * i + j] = B[5][3 * j + i];
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

  {
    double t = 0; /* x * 0 is NaN exactly when x is not finite */
    for (int i = 0; i < 9; i++) t += x[i] * 0;
    for (int k = 0; k < 3; k++)
      if (nb >> k & 1) t += x[9 + 3 * k] * 0 + x[10 + 3 * k] * 0 + x[11 + 3 * k] * 0;
    if (t != 0 || isnan(t)) return HYLCMAT_ERR_NONFINITE;
  }
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

/* B (3 x 3) into the upper block triangle of H (18 x 18): at (vi, vj) if vi <= vj, else B^T at (vj, vi) */
static inline void AddBlock(double *H, int vi, int vj, const double B[9])
{
  if (vi <= vj)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) H[18 * (3 * vi + i) + 3 * vj + j] += B[3 * i + j];
  else
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) H[18 * (3 * vj + j) + 3 * vi + i] += B[3 * i + j];
}

/* the blocks of an edge's local Hessian (variables e, f, g = x_b - x_a, x_c - x_a, x_p - x_a) into H at
   the vertices (a, b, c, p): (b, b) = ee, (b, c) = ef, ..., (a, c) = -sum_r L[r][c], (a, a) = sum of all */
static void MapHinge(double *H, double B[6][9], int va, int vb, int vc, int vp)
{
  double S[3][9], T[9];

  AddBlock(H, vb, vb, B[0]);
  AddBlock(H, vb, vc, B[1]);
  AddBlock(H, vb, vp, B[2]);
  AddBlock(H, vc, vc, B[3]);
  AddBlock(H, vc, vp, B[4]);
  AddBlock(H, vp, vp, B[5]);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      const int q = 3 * i + j, t = 3 * j + i;
      S[0][q] = -(B[0][q] + B[1][t] + B[2][t]); /* ee + fe + ge */
      S[1][q] = -(B[1][q] + B[3][q] + B[4][t]); /* ef + ff + gf */
      S[2][q] = -(B[2][q] + B[4][q] + B[5][q]); /* eg + fg + gg */
    }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) T[3 * i + j] = -(S[0][3 * i + j] + S[1][3 * i + j] + S[2][3 * i + j]);
  AddBlock(H, va, vb, S[0]);
  AddBlock(H, va, vc, S[1]);
  AddBlock(H, va, vp, S[2]);
  /* (a, a): symmetric exactly */
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++) T[3 * i + j] = T[3 * j + i] = 0.5 * (T[3 * i + j] + T[3 * j + i]);
  AddBlock(H, va, va, T);
}

HM_INTERN int hm_psd_project(double H[324], int nb);
HM_INTERN int hm_psd_project_many(int m, double *const H[], const int nb[]);

/* the element at level 0 (E), 1 (+ g), 2 (+ H) */
static int Element(const hylcmat *m, const hylcmat_shell_rest *r, const double x[18], int nb, int level, double *E, double g[18], double H[324], double zout[6])
{
  Elem   el;
  double z[6], psi, dpsi[6], hpsi[36], py[6], Hy[36], A = r->area;

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
    double       ga[3], gb[3];
    const double qa = py[1] / el.al, qb = py[1] / el.be; /* (two divisions instead of six: the same to rounding) */
    for (int i = 0; i < 3; i++) {
      ga[i] = py[0] * el.ah[i] + qa * (el.bh[i] - el.sa * el.ah[i]);
      gb[i] = py[2] * el.bh[i] + qb * (el.ah[i] - el.sa * el.bh[i]);
    }
    for (int v = 0; v < 3; v++)
      for (int i = 0; i < 3; i++) g[3 * v + i] = el.C0[v] * ga[i] + el.C1[v] * gb[i];
    for (int i = 9; i < 18; i++) g[i] = 0;
  }
  for (int k = 0; k < 3; k++) {
    Hinge *h = &el.h[k];
    if (!(nb >> k & 1)) continue;
    if (level > 1)
      HingeGrad(h);
    else
      HingeGradW(h, h->dw);
    {
      double *ga = g + 3 * EdgeA[k], *gb = g + 3 * EdgeB[k], *gc = g + 3 * EdgeC[k], *gp = g + 9 + 3 * k;
      for (int i = 0; i < 3; i++) {
        const double de = py[3 + k] * h->dw[i], df = py[3 + k] * h->dw[3 + i], dg = py[3 + k] * h->dw[6 + i];
        gb[i] += de;
        gc[i] += df;
        gp[i] = dg;
        ga[i] -= de + df + dg;
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
    double Jc[6][3][3], jn[3][3], P[6][3][3];
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
      for (int i = 0; i < 3; i++) {
        Jc[3 + k][EdgeB[k]][i] += h->dw[i];
        Jc[3 + k][EdgeC[k]][i] += h->dw[3 + i];
        Jc[3 + k][EdgeA[k]][i] -= h->dw[i] + h->dw[3 + i] + h->dw[6 + i];
        jn[k][i] = h->dw[6 + i];
      }
    }
    /* J^T Psi_yy J, upper blocks: P = Psi_yy Jc */
    for (int r2 = 0; r2 < 6; r2++)
      for (int v = 0; v < 3; v++)
        for (int i = 0; i < 3; i++) {
          double t = 0;
          for (int q = 0; q < 6; q++) t += Hy[6 * r2 + q] * Jc[q][v][i];
          P[r2][v][i] = t;
        }
    for (int vi = 0; vi < 3; vi++)
      for (int vj = vi; vj < 3; vj++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) {
            double t = 0;
            for (int q = 0; q < 6; q++) t += Jc[q][vi][i] * P[q][vj][j];
            H[18 * (3 * vi + i) + 3 * vj + j] = t;
          }
    for (int k = 0; k < 3; k++) {
      if (!(nb >> k & 1)) continue;
      for (int v = 0; v < 3; v++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) H[18 * (3 * v + i) + 9 + 3 * k + j] = P[3 + k][v][i] * jn[k][j];
      for (int l = k; l < 3; l++) {
        if (!(nb >> l & 1)) continue;
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) H[18 * (9 + 3 * k + i) + 9 + 3 * l + j] = Hy[6 * (3 + k) + 3 + l] * jn[k][i] * jn[l][j];
      }
    }
  }
  /* + Psi_y d2y: in-plane, K in (a, b) */
  {
    const double ia = 1 / el.al, ib = 1 / el.be, sa = el.sa;
    double       Kaa[9], Kab[9], Kbb[9], gA[3], gB[3];
    for (int i = 0; i < 3; i++) {
      gA[i] = (el.bh[i] - sa * el.ah[i]) * ia;
      gB[i] = (el.ah[i] - sa * el.bh[i]) * ib;
    }
    /* sx: (I - ah ah^T) / al; sy: (I - bh bh^T) / be; sa: aa = -(gA ah^T + ah gA^T) / al - sa (I - ah ah^T) / al^2,
       bb likewise, ab = (I - ah ah^T - bh bh^T + sa ah bh^T) / (al be) */
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        const double d = i == j ? 1 : 0, aa = d - el.ah[i] * el.ah[j], bb = d - el.bh[i] * el.bh[j];
        Kaa[3 * i + j] = py[0] * ia * aa - py[1] * (ia * (gA[i] * el.ah[j] + el.ah[i] * gA[j]) + sa * ia * ia * aa);
        Kbb[3 * i + j] = py[2] * ib * bb - py[1] * (ib * (gB[i] * el.bh[j] + el.bh[i] * gB[j]) + sa * ib * ib * bb);
        Kab[3 * i + j] = py[1] * ia * ib * (aa - el.bh[i] * el.bh[j] + sa * el.ah[i] * el.bh[j]);
      }
    for (int vi = 0; vi < 3; vi++)
      for (int vj = vi; vj < 3; vj++) {
        const double c00 = el.C0[vi] * el.C0[vj], c11 = el.C1[vi] * el.C1[vj], c01 = el.C0[vi] * el.C1[vj], c10 = el.C1[vi] * el.C0[vj];
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) H[18 * (3 * vi + i) + 3 * vj + j] += c00 * Kaa[3 * i + j] + c11 * Kbb[3 * i + j] + c01 * Kab[3 * i + j] + c10 * Kab[3 * j + i];
      }
  }
  /* bending */
  for (int k = 0; k < 3; k++) {
    double B[6][9];
    if (!(nb >> k & 1)) continue;
    HingeHess(&el.h[k], py[3 + k] / el.h[k].len, B);
    MapHinge(H, B, EdgeA[k], EdgeB[k], EdgeC[k], 3 + k);
  }
  /* the lower triangle from the upper one (exactly symmetric); every entry finite? */
  {
    double fin = 0;
    for (int i = 0; i < 18; i++) {
      fin += H[19 * i] * 0;
      for (int j = i + 1; j < 18; j++) {
        H[18 * j + i] = H[18 * i + j];
        fin += H[18 * i + j] * 0;
      }
    }
    if (fin != 0 || isnan(fin)) return HYLCMAT_ERR_RANGE;
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
  if (!isfinite(e) || (level > 0 && NonFinite(grad, 18))) { /* (the Hessian was checked by Element) */
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

/* the group size of the batched projection: up to this many eigen-decompositions together (their QR
   iterations in pairs) */
#define PSD_GROUP 4

int hylcmat_shell_eval_batch(const hylcmat *m, size_t n, const hylcmat_shell_rest *r, const double *x, const int *nbmask, int flags, double *E, double *grad, double *hess)
{
  int first = HYLCMAT_OK;

  if (!m || (n && (!r || !x || !nbmask || !E)) || (hess && !grad)) return HYLCMAT_ERR_ARG;
  for (size_t i0 = 0; i0 < n; i0 += PSD_GROUP) {
    const size_t i1 = i0 + PSD_GROUP < n ? i0 + PSD_GROUP : n;
    double      *Hs[PSD_GROUP];
    int          nbs[PSD_GROUP], g = 0;
    size_t       which[PSD_GROUP];
    for (size_t i = i0; i < i1; i++) {
      const int ret = hylcmat_shell_eval(m, &r[i], x + 18 * i, nbmask[i], flags & ~HYLCMAT_SHELL_PSD, &E[i], grad ? grad + 18 * i : NULL, hess ? hess + 324 * i : NULL);
      if (ret) {
        if (!first) first = ret;
      } else if (hess && (flags & HYLCMAT_SHELL_PSD)) {
        Hs[g] = hess + 324 * i, nbs[g] = nbmask[i] & 7, which[g++] = i;
      }
    }
    if (g && hm_psd_project_many(g, Hs, nbs)) /* a projection beyond the double range: each on its own, to find the one */
      for (int k = 0; k < g; k++) {
        const size_t i   = which[k];
        const int    ret = hylcmat_shell_eval(m, &r[i], x + 18 * i, nbmask[i], flags, &E[i], grad + 18 * i, hess + 324 * i);
        if (ret && !first) first = ret;
      }
  }
  return first;
}
