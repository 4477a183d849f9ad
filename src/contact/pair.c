/* Contact kernels for one segment pair: Gauss-Legendre quadrature of Kaldor's double integral and the
   closest-point variant with its exact Hessian. See include/hylc/contact.h and docs/contact.md. */
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <string.h>

/* ---------------------------------------------------------------- Gauss-Legendre rules on [0, 1] */

static double gl_nodes[HYLC_GAUSS_MAX + 1][HYLC_GAUSS_MAX];
static double gl_weights[HYLC_GAUSS_MAX + 1][HYLC_GAUSS_MAX];
static int    gl_ready[HYLC_GAUSS_MAX + 1];

/* Legendre P_n(x) and its derivative by the three-term recurrence (|x| < 1). */
static void Legendre(int n, double x, double *p, double *dp)
{
  double pm1 = 1.0, pk = x; /* P_0, P_1 */
  if (n == 0) {
    *p  = 1.0;
    *dp = 0.0;
    return;
  }
  for (int k = 1; k < n; k++) { /* (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1} */
    const double pk1 = ((2 * k + 1) * x * pk - k * pm1) / (k + 1);
    pm1              = pk;
    pk               = pk1;
  }
  *p  = pk;
  *dp = n * (x * pk - pm1) / (x * x - 1.0);
}

static void GaussLegendreCompute(int n, double *nodes, double *weights)
{
  /* roots of P_n on [-1, 1] are symmetric; find the m = ceil(n/2) non-negative ones by Newton from the
     Tricomi-type guess cos(pi (i - 1/4) / (n + 1/2)), i = 1..m (largest root first) */
  const int m = (n + 1) / 2;
  for (int i = 1; i <= m; i++) {
    double x = cos(M_PI * (i - 0.25) / (n + 0.5)), p, dp;
    for (int it = 0; it < 100; it++) {
      Legendre(n, x, &p, &dp);
      const double dx = p / dp;
      x -= dx;
      if (fabs(dx) <= 1e-16 * (fabs(x) > 1e-3 ? fabs(x) : 1e-3)) break;
    }
    if (n % 2 == 1 && i == m) x = 0.0; /* the middle root is exactly 0 */
    Legendre(n, x, &p, &dp);
    const double wgt = 2.0 / ((1.0 - x * x) * dp * dp);
    /* map to [0, 1]: sigma = (1 + x)/2, weight halved; ascending order */
    nodes[n - i]   = 0.5 * (1.0 + x);
    nodes[i - 1]   = 0.5 * (1.0 - x);
    weights[n - i] = 0.5 * wgt;
    weights[i - 1] = 0.5 * wgt;
  }
}

int HylcGaussLegendre01(int n, const double **nodes, const double **weights)
{
  if (n < 1 || n > HYLC_GAUSS_MAX) {
    if (nodes) *nodes = NULL;
    if (weights) *weights = NULL;
    return -1;
  }
  if (!gl_ready[n]) {
    GaussLegendreCompute(n, gl_nodes[n], gl_weights[n]);
    gl_ready[n] = 1;
  }
  if (nodes) *nodes = gl_nodes[n];
  if (weights) *weights = gl_weights[n];
  return 0;
}

/* ---------------------------------------------------------------- penalty */

void HylcContactPenalty(double delta, double *f, double *df, double *d2f)
{
  if (!(delta < 1.0)) {
    if (f) *f = 0;
    if (df) *df = 0;
    if (d2f) *d2f = 0;
    return;
  }
  /* cancellation-free forms: f = ((1 - delta^2)/delta)^2, f' = -2 (1 - delta^2)(1 + delta^2)/delta^3 */
  const double id = 1.0 / delta, om = (1.0 - delta) * (1.0 + delta), u = om * id;
  if (f) *f = u * u;
  if (df) *df = -2.0 * u * (1.0 + delta * delta) * id * id;
  if (d2f) *d2f = 6.0 * id * id * id * id + 2.0;
}

/* ---------------------------------------------------------------- helpers */

/* Symmetric 3x3 stored as (xx, yy, zz, xy, xz, yz). */
static inline void SymAxpy(double a, const double S[6], double T[6])
{
  for (int k = 0; k < 6; k++) T[k] += a * S[k];
}

/* H[block (I,J)] += alpha * S (3x3 symmetric), and the transposed block (J,I) when I != J. */
static inline void AddBlockSym(double H[144], int I, int J, double alpha, const double S[6])
{
  const double M[3][3] = {{S[0], S[3], S[4]}, {S[3], S[1], S[5]}, {S[4], S[5], S[2]}};
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      H[(3 * I + i) * 12 + 3 * J + j] += alpha * M[i][j];
      if (I != J) H[(3 * J + j) * 12 + 3 * I + i] += alpha * M[i][j];
    }
}

/* ---------------------------------------------------------------- quadrature variant */

double HylcContactQuadrature(const double a0[3], const double a1[3], const double b0[3], const double b1[3], double la, double lb, double kc, double r, int n, double w, double g[12], double H[144])
{
  const double *sg, *wg;
  double        ea[3], eb[3];

  if (g) memset(g, 0, 12 * sizeof(double));
  if (H) memset(H, 0, 144 * sizeof(double));
  if (HylcGaussLegendre01(n, &sg, &wg)) return NAN;
  const double dseg = HylcSegmentSegmentDistance(a0, a1, b0, b1, NULL, NULL);
  if (!(dseg < 2.0 * r)) return 0.0; /* no quadrature pair can be within 2 r */

  HylcSub3(a1, a0, ea);
  HylcSub3(b1, b0, eb);
  const double i2r = 0.5 / r, r4sq = 4.0 * r * r, i4r2 = i2r * i2r, r2 = 2.0 * r;
  /* points q_h of segment b, computed once */
  double q[HYLC_GAUSS_MAX][3];
  for (int h = 0; h < n; h++)
    for (int k = 0; k < 3; k++) q[h][k] = b0[k] + sg[h] * eb[k];

  /* Sums over all quadrature pairs, with ww = w_g w_h, s = s_g, t = s_h and the per-term gradient gv and
     Hessian Hv of f(|v|/2r) with respect to v = p_g - q_h:
       G0 = sum ww gv, Gs = sum ww s gv, Gt = sum ww t gv
       T0 = sum ww Hv, U1 = sum ww s Hv, U2 = sum ww s^2 Hv, T1 = sum ww t Hv, T2 = sum ww t^2 Hv,
       M = sum ww s t Hv
     The 12-vector and 12x12 blocks follow from v = (1-s) a0 + s a1 - (1-t) b0 - t b1. */
  double    E = 0, G0[3] = {0, 0, 0}, Gs[3] = {0, 0, 0}, Gt[3] = {0, 0, 0};
  double    T0[6] = {0}, U1[6] = {0}, U2[6] = {0}, T1[6] = {0}, T2[6] = {0}, M[6] = {0};
  const int wantg = g != NULL, wantH = H != NULL;

  for (int gi = 0; gi < n; gi++) {
    const double s = sg[gi];
    double       p[3], Eg = 0, g0[3] = {0, 0, 0}, gt[3] = {0, 0, 0}, S0[6] = {0}, S1[6] = {0}, S2[6] = {0};
    for (int k = 0; k < 3; k++) p[k] = a0[k] + s * ea[k];
    for (int h = 0; h < n; h++) {
      double       v[3];
      const double t = sg[h];
      HylcSub3(p, q[h], v);
      const double d2 = HylcDot3(v, v);
      if (!(d2 < r4sq)) continue;
      /* one division per term: with id = 1/|v|, delta = |v|/(2r), 1/delta = 2r id, and
         f = ((1 - delta^2)/delta)^2, f' = -2 (1 - delta^2)(1 + delta^2)/delta^3 (see HylcContactPenalty) */
      const double ww = wg[h]; /* w_g is applied per row below */
      const double id = 1.0 / sqrt(d2), p2 = d2 * i4r2, idel = r2 * id, u = (1.0 - p2) * idel;
      Eg += ww * u * u;
      if (!wantg && !wantH) continue;
      const double idel2 = idel * idel, fp = -2.0 * u * (1.0 + p2) * idel2;
      /* gradient wrt v: f'/(2r) v/|v| */
      const double be = fp * i2r * id, cg = ww * be;
      for (int k = 0; k < 3; k++) {
        g0[k] += cg * v[k];
        gt[k] += cg * t * v[k];
      }
      if (!wantH) continue;
      /* Hessian wrt v: beta I + (alpha - beta) v v^T / |v|^2, alpha = f''/(4r^2), beta = f'/(2r |v|) */
      const double al = (6.0 * idel2 * idel2 + 2.0) * i4r2, c = ww * (al - be) * id * id, wb = ww * be;
      const double Hv[6] = {wb + c * v[0] * v[0], wb + c * v[1] * v[1], wb + c * v[2] * v[2], c * v[0] * v[1], c * v[0] * v[2], c * v[1] * v[2]};
      SymAxpy(1.0, Hv, S0);
      SymAxpy(t, Hv, S1);
      SymAxpy(t * t, Hv, S2);
    }
    const double wgi = wg[gi];
    E += wgi * Eg;
    for (int k = 0; k < 3; k++) {
      G0[k] += wgi * g0[k];
      Gs[k] += wgi * s * g0[k];
      Gt[k] += wgi * gt[k];
    }
    if (wantH) {
      SymAxpy(wgi, S0, T0);
      SymAxpy(wgi * s, S0, U1);
      SymAxpy(wgi * s * s, S0, U2);
      SymAxpy(wgi, S1, T1);
      SymAxpy(wgi, S2, T2);
      SymAxpy(wgi * s, S1, M);
    }
  }

  const double K = w * kc * la * lb;
  if (g) {
    for (int k = 0; k < 3; k++) {
      g[0 + k] = K * (G0[k] - Gs[k]);
      g[3 + k] = K * Gs[k];
      g[6 + k] = -K * (G0[k] - Gt[k]);
      g[9 + k] = -K * Gt[k];
    }
  }
  if (H) {
    double B[6];
    /* a-a blocks */
    for (int k = 0; k < 6; k++) B[k] = T0[k] - 2 * U1[k] + U2[k];
    AddBlockSym(H, 0, 0, K, B);
    for (int k = 0; k < 6; k++) B[k] = U1[k] - U2[k];
    AddBlockSym(H, 0, 1, K, B);
    AddBlockSym(H, 1, 1, K, U2);
    /* b-b blocks */
    for (int k = 0; k < 6; k++) B[k] = T0[k] - 2 * T1[k] + T2[k];
    AddBlockSym(H, 2, 2, K, B);
    for (int k = 0; k < 6; k++) B[k] = T1[k] - T2[k];
    AddBlockSym(H, 2, 3, K, B);
    AddBlockSym(H, 3, 3, K, T2);
    /* a-b blocks: -sum (c_a c_b) Hv */
    for (int k = 0; k < 6; k++) B[k] = T0[k] - U1[k] - T1[k] + M[k];
    AddBlockSym(H, 0, 2, -K, B);
    for (int k = 0; k < 6; k++) B[k] = T1[k] - M[k];
    AddBlockSym(H, 0, 3, -K, B);
    for (int k = 0; k < 6; k++) B[k] = U1[k] - M[k];
    AddBlockSym(H, 1, 2, -K, B);
    AddBlockSym(H, 1, 3, -K, M);
  }
  return K * E;
}

/* ---------------------------------------------------------------- closest-point variant */

double HylcContactClosestPoint(const double a0[3], const double a1[3], const double b0[3], const double b1[3], double la, double lb, double kc, double r, double w, double g[12], double H[144], double *sout, double *tout, double *dist)
{
  double s, t, ea[3], eb[3], v[3];

  if (g) memset(g, 0, 12 * sizeof(double));
  if (H) memset(H, 0, 144 * sizeof(double));
  const double d = HylcSegmentSegmentDistance(a0, a1, b0, b1, &s, &t);
  if (sout) *sout = s;
  if (tout) *tout = t;
  if (dist) *dist = d;
  if (!(d < 2.0 * r)) return 0.0;

  const double K = w * kc * la * lb, i2r = 0.5 / r;
  if (!(d > 0)) return K * INFINITY; /* touching axes: pole of f, derivatives undefined */
  HylcSub3(a1, a0, ea);
  HylcSub3(b1, b0, eb);
  for (int k = 0; k < 3; k++) v[k] = a0[k] + s * ea[k] - b0[k] - t * eb[k];
  double f, fp, fpp;
  HylcContactPenalty(d * i2r, &f, &fp, &fpp);
  const double nh[3] = {v[0] / d, v[1] / d, v[2] / d};
  const double c[4]  = {1.0 - s, s, -(1.0 - t), -t}; /* J = [c_0 I, c_1 I, c_2 I, c_3 I] */

  if (g) {
    const double cg = K * fp * i2r;
    for (int I = 0; I < 4; I++)
      for (int k = 0; k < 3; k++) g[3 * I + k] = cg * c[I] * nh[k];
  }
  if (H) {
    /* H = K [ (f''/(4r^2) - f'/(2r d)) (c c^T (x) n n^T) + f'/(2r d) (c c^T (x) I - G_xu Guu^-1 G_ux) ] */
    const double al = K * (fpp * i2r * i2r - fp * i2r / d), be = K * fp * i2r / d;
    for (int I = 0; I < 4; I++)
      for (int J = 0; J < 4; J++)
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) H[(3 * I + i) * 12 + 3 * J + j] = c[I] * c[J] * (al * nh[i] * nh[j] + (i == j ? be : 0.0));

    /* unclamped parameters and their mixed derivatives G_xu (12 each) */
    double    Gx[2][12], Guu[2][2];
    int       nu    = 0, which[2];
    const int sfree = s > 0.0 && s<1.0, tfree = t> 0.0 && t < 1.0;
    if (sfree) which[nu++] = 0;
    if (tfree) which[nu++] = 1;
    for (int u = 0; u < nu; u++) {
      double *G = Gx[u];
      if (which[u] == 0) { /* G_xs = J_s^T v + J^T ea, J_s = [-I, I, 0, 0] */
        for (int k = 0; k < 3; k++) {
          G[0 + k] = -v[k] + c[0] * ea[k];
          G[3 + k] = v[k] + c[1] * ea[k];
          G[6 + k] = c[2] * ea[k];
          G[9 + k] = c[3] * ea[k];
        }
      } else { /* G_xt = J_t^T v - J^T eb, J_t = [0, 0, I, -I] */
        for (int k = 0; k < 3; k++) {
          G[0 + k] = -c[0] * eb[k];
          G[3 + k] = -c[1] * eb[k];
          G[6 + k] = v[k] - c[2] * eb[k];
          G[9 + k] = -v[k] - c[3] * eb[k];
        }
      }
    }
    const double aa = HylcDot3(ea, ea), bb = HylcDot3(eb, eb), ab = HylcDot3(ea, eb);
    double       Ginv[2][2] = {{0, 0}, {0, 0}};
    if (nu == 1) {
      Ginv[0][0] = 1.0 / (which[0] == 0 ? aa : bb);
    } else if (nu == 2) {
      Guu[0][0]        = aa;
      Guu[1][1]        = bb;
      Guu[0][1]        = -ab;
      Guu[1][0]        = -ab;
      const double det = Guu[0][0] * Guu[1][1] - Guu[0][1] * Guu[1][0];
      Ginv[0][0]       = Guu[1][1] / det;
      Ginv[1][1]       = Guu[0][0] / det;
      Ginv[0][1]       = -Guu[0][1] / det;
      Ginv[1][0]       = -Guu[1][0] / det;
    }
    for (int u = 0; u < nu; u++)
      for (int uu = 0; uu < nu; uu++) {
        const double cu = -be * Ginv[u][uu];
        if (cu == 0.0) continue;
        for (int i = 0; i < 12; i++)
          for (int j = 0; j < 12; j++) H[i * 12 + j] += cu * Gx[u][i] * Gx[uu][j];
      }
  }
  return K * f;
}
