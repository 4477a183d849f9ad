/* Plain C kernels of the cloth stage (include/hylc/cloth.h): the free curl of a table, the elastica of a
   cantilever under its own weight, the contact barrier and the distance to a support. */
#include <hylc/private/clothimpl.h>
#include <hylc/private/newton2.h>
#include <math.h>

/* Psi over two free strains z[i[0]], z[i[1]] of z0 (the others fixed) */
typedef struct {
  const hylcmat *m;
  double         z0[6];
  int            i[2];
} Pair;

static int PairEval(const Pair *p, const double y[2], double *psi, double g[2], double H[4])
{
  double z[6], gr[6], he[36];
  int    rc;

  for (int k = 0; k < 6; k++) z[k] = p->z0[k];
  z[p->i[0]] = y[0];
  z[p->i[1]] = y[1];
  rc         = hylcmat_eval(p->m, z, psi, g ? gr : NULL, H ? he : NULL);
  if (rc) return rc;
  if (g) {
    g[0] = gr[p->i[0]];
    g[1] = gr[p->i[1]];
  }
  if (H) {
    H[0] = he[p->i[0] * 6 + p->i[0]];
    H[1] = he[p->i[0] * 6 + p->i[1]];
    H[2] = he[p->i[1] * 6 + p->i[0]];
    H[3] = he[p->i[1] * 6 + p->i[1]];
  }
  return 0;
}

/* damped Newton on the two free strains from y, the 2x2 Hessian's eigenvalues raised to a floor (a
   descent direction always); at a stationary point with negative curvature, a step along it */
static int PairNewton(const Pair *p, double y[2], double *fout, int *conv)
{
  double f, g[2], H[4];
  int    rc, it;

  *conv = 0;
  if ((rc = PairEval(p, y, &f, g, H))) return rc;
  for (it = 0; it < 300; it++) {
    double d[2], gnorm = fabs(g[0]) + fabs(g[1]), t = 1, slope, l1, l2, v1[2], v2[2], fl;
    HylcSymEig2(H, &l1, &l2, v1, v2);
    fl = 1e-8 * (fabs(l1) + 1e-12);
    if (gnorm < 1e-13 * (1 + fabs(f))) {
      if (l2 >= 0) {
        *conv = 1;
        break;
      }
      /* a saddle: step along the negative curvature, to the lower side */
      {
        double best = f, yb[2] = {y[0], y[1]};
        for (int sg = -1; sg <= 1; sg += 2)
          for (double h = 1e-4; h < 1; h *= 2) {
            double yt[2] = {y[0] + sg * h * v2[0], y[1] + sg * h * v2[1]}, ft;
            if ((rc = PairEval(p, yt, &ft, NULL, NULL))) return rc;
            if (ft < best) {
              best  = ft;
              yb[0] = yt[0];
              yb[1] = yt[1];
            } else if (ft > best)
              break;
          }
        if (best >= f) {
          *conv = 1; /* flat to rounding */
          break;
        }
        y[0] = yb[0];
        y[1] = yb[1];
        if ((rc = PairEval(p, y, &f, g, H))) return rc;
        continue;
      }
    }
    HylcEigSolve2(fmax(l1, fl), fmax(l2, fl), v1, v2, g, d);
    slope = g[0] * d[0] + g[1] * d[1];
    for (;;) {
      double yt[2] = {y[0] + t * d[0], y[1] + t * d[1]}, ft;
      if ((rc = PairEval(p, yt, &ft, NULL, NULL))) return rc;
      if (ft <= f + 1e-4 * t * slope || t < 1e-12) {
        if (t >= 1e-12) {
          y[0] = yt[0];
          y[1] = yt[1];
        }
        break;
      }
      t *= 0.5;
    }
    if (t < 1e-12) { /* no decrease within rounding: stationary */
      *conv = gnorm < 1e-8 * (1 + fabs(f));
      break;
    }
    if ((rc = PairEval(p, y, &f, g, H))) return rc;
  }
  *fout = f;
  return 0;
}

int HylcClothTableCurl(const hylcmat *m, double *II00, double *II11, double *psi)
{
  Pair   p    = {m, {0, 0, 0, 0, 0, 0}, {3, 5}};
  double y[2] = {0, 0}, f, best = INFINITY;
  int    rc, conv;

  /* the bending terms need not be convex either: the best start of a coarse grid (1/m) */
  for (int i = -20; i <= 20; i++)
    for (int j = -20; j <= 20; j++) {
      double yt[2] = {25.0 * i, 25.0 * j}, ft;
      if ((rc = PairEval(&p, yt, &ft, NULL, NULL))) return rc;
      if (ft < best) {
        best = ft;
        y[0] = yt[0];
        y[1] = yt[1];
      }
    }
  if ((rc = PairNewton(&p, y, &f, &conv))) return rc;
  *II00 = y[0];
  *II11 = y[1];
  if (psi) *psi = f;
  return conv ? 0 : -1;
}

int HylcClothTableMoment(void *vctx, double kappa, double *M, double *dMdk)
{
  const HylcClothMomentCtx *ctx  = (const HylcClothMomentCtx *)vctx;
  double                    z[6] = {0, 0, 0, 0, 0, 0}, psi, g[6], H[36], sgn = ctx->faceDown ? 1.0 : -1.0;
  int                       k = ctx->dir ? 5 : 3, rc;

  z[k] = sgn * kappa;
  rc   = hylcmat_eval(ctx->m, z, &psi, g, H);
  if (rc) return rc;
  *M = sgn * g[k];
  if (dMdk) *dMdk = H[k * 6 + k];
  return 0;
}

/* kappa >= 0 with M(kappa) = target (M increasing): a bracket grown from the guess *kappa (the value
   at a nearby point of the strip), then Newton's method safeguarded by bisection. -1 if M stays below
   the target (the table's bending term flat beyond its knots) */
static int InverseMoment(HylcClothMomentFn M, void *ctx, double target, double *kappa)
{
  double lo = 0, hi, Mlo, Mhi, k, Mk, dM;
  int    rc;

  if ((rc = M(ctx, 0, &Mlo, NULL))) return rc;
  if (target <= Mlo) {
    *kappa = 0;
    return 0;
  }
  hi = *kappa > 0 ? *kappa : 1;
  for (;;) {
    if ((rc = M(ctx, hi, &Mhi, NULL))) return rc;
    if (Mhi >= target) break;
    lo  = hi;
    Mlo = Mhi;
    hi *= 2;
    if (hi > 1e8) return -1;
  }
  if (lo == 0 && *kappa > 0) { /* the guess was above: tighten the bracket from below */
    for (double t = 0.5 * hi; t > 1e-3 * hi; t *= 0.5) {
      if ((rc = M(ctx, t, &Mk, NULL))) return rc;
      if (Mk >= target) {
        hi = t;
        continue;
      }
      lo = t;
      break;
    }
  }
  k = 0.5 * (lo + hi);
  if (*kappa > lo && *kappa < hi) k = *kappa;
  for (int it = 0; it < 200; it++) {
    double kn;
    if ((rc = M(ctx, k, &Mk, &dM))) return rc;
    if (Mk > target)
      hi = k;
    else
      lo = k;
    kn = dM > 0 ? k - (Mk - target) / dM : 0.5 * (lo + hi);
    if (!(kn > lo && kn < hi)) kn = 0.5 * (lo + hi);
    if (fabs(kn - k) <= 1e-14 * (1 + fabs(k)) || hi - lo <= 1e-14 * (1 + hi)) {
      *kappa = kn;
      return 0;
    }
    k = kn;
  }
  *kappa = k;
  return 0;
}

/* integrates theta' = kappa(M), M' = -w (l - s) cos(theta), x' = cos, y' = -sin from the root with M(0)
   = M0; returns M(l) (the tip moment, 0 for the right M0) and the tip */
static int Shoot(HylcClothMomentFn Mf, void *ctx, double w, double l, int n, double M0, double *Ml, double *xt, double *yt)
{
  double h = l / n, th = 0, M = M0, x = 0, y = 0, kg = 0;
  int    rc;

  for (int i = 0; i < n; i++) {
    double s = i * h, k[4][4], st[4] = {th, M, x, y};
    for (int q = 0; q < 4; q++) {
      double ss = s + (q == 0 ? 0 : q == 3 ? h : 0.5 * h), a = q == 0 ? 0 : q == 3 ? 1 : 0.5, tq, Mq, kap = kg;
      tq = st[0] + (q ? a * h * k[q - 1][0] : 0);
      Mq = st[1] + (q ? a * h * k[q - 1][1] : 0);
      if ((rc = InverseMoment(Mf, ctx, Mq, &kap))) return rc;
      kg      = kap;
      k[q][0] = kap;
      k[q][1] = -w * (l - ss) * cos(tq);
      k[q][2] = cos(tq);
      k[q][3] = -sin(tq);
    }
    th += h / 6 * (k[0][0] + 2 * k[1][0] + 2 * k[2][0] + k[3][0]);
    M += h / 6 * (k[0][1] + 2 * k[1][1] + 2 * k[2][1] + k[3][1]);
    x += h / 6 * (k[0][2] + 2 * k[1][2] + 2 * k[2][2] + k[3][2]);
    y += h / 6 * (k[0][3] + 2 * k[1][3] + 2 * k[2][3] + k[3][3]);
  }
  *Ml = M;
  *xt = x;
  *yt = y;
  return 0;
}

/* the root of f on [a, b] with f(a) < 0 <= f(b) by the Illinois method; f returns a hylcmat error
   (> 0, passed on), 0, or -1 for a point outside f's domain, which lies beyond the root (treated as
   f > 0 with a bisection step). Stops when the bracket is below rtol * b or |f| <= ftol. */
typedef int (*RootFn)(void *ctx, double t, double *f);
static int Illinois(RootFn f, void *ctx, double a, double fa, double b, double rtol, double ftol, double *root)
{
  double fb;
  int    rc, side = 0, bad;

  rc = f(ctx, b, &fb);
  if (rc > 0) return rc;
  bad = rc < 0;
  for (int it = 0; it < 300; it++) {
    double t, ft;
    if (bad)
      t = 0.5 * (a + b);
    else
      t = (a * fb - b * fa) / (fb - fa);
    if (!(t > a && t < b)) t = 0.5 * (a + b);
    rc = f(ctx, t, &ft);
    if (rc > 0) return rc;
    if (rc < 0) { /* beyond the domain: the root is below */
      b   = t;
      bad = 1;
    } else if (ft >= 0) {
      b   = t;
      fb  = ft;
      bad = 0;
      if (side == 1) fa *= 0.5;
      side = 1;
    } else {
      a  = t;
      fa = ft;
      if (side == -1 && !bad) fb *= 0.5;
      side = -1;
    }
    if (b - a <= rtol * b || (rc == 0 && fabs(ft) <= ftol)) {
      *root = rc == 0 ? t : a;
      return 0;
    }
  }
  *root = 0.5 * (a + b);
  return 0;
}

typedef struct {
  HylcClothMomentFn Mf;
  void             *ctx;
  double            w, l, angle, x, y;
  int               n;
} Elastica;

static int TipMoment(void *vctx, double M0, double *f)
{
  Elastica *e = (Elastica *)vctx;
  return Shoot(e->Mf, e->ctx, e->w, e->l, e->n, M0, f, &e->x, &e->y);
}

int HylcClothElasticaTip(HylcClothMomentFn Mf, void *ctx, double w, double l, int n, double *xtip, double *ytip)
{
  /* the root moment lies between 0 (the tip moment then -w l^2 / 2 cos.. < 0) and that of the straight
     strip, w l^2 / 2 (the tip moment then >= 0) */
  Elastica e = {Mf, ctx, w, l, 0, 0, 0, n};
  double   f0, M0;
  int      rc;

  if ((rc = TipMoment(&e, 0, &f0))) return rc;
  if (f0 >= 0) return -1;
  if ((rc = Illinois(TipMoment, &e, 0, f0, 0.5 * w * l * l * 1.000001, 1e-15, 1e-15 * w * l * l, &M0))) return rc;
  if ((rc = TipMoment(&e, M0, &f0))) return rc;
  if (fabs(f0) > 1e-9 * w * l * l) return -1; /* the table's range ends before the root moment */
  *xtip = e.x;
  *ytip = e.y;
  return 0;
}

static int ChordAngle(void *vctx, double l, double *f)
{
  Elastica *e = (Elastica *)vctx;
  double    x, y;
  int       rc = HylcClothElasticaTip(e->Mf, e->ctx, e->w, l, e->n, &x, &y);
  if (rc) return rc;
  *f = atan2(-y, x) - e->angle;
  return 0;
}

int HylcClothElasticaOverhang(HylcClothMomentFn Mf, void *ctx, double w, double angle, int n, double *lout)
{
  Elastica e  = {Mf, ctx, w, 0, angle, 0, 0, n};
  double   lo = 1e-4, hi = 1e-2, flo, fhi, l;
  int      rc;

  /* the chord angle grows with l: a bracket, then the Illinois method. An overhang whose root moment
     the table's bending term does not reach (flat beyond its knots) counts as too long; the overhang
     found must have its tip within the table */
  if ((rc = ChordAngle(&e, lo, &flo))) return rc < 0 ? -1 : rc;
  if (flo >= 0) return -1;
  for (;;) {
    rc = ChordAngle(&e, hi, &fhi);
    if (rc > 0) return rc;
    if (rc < 0 || fhi >= 0) break;
    lo  = hi;
    flo = fhi;
    hi *= 2;
    if (hi > 100) return -1;
  }
  if ((rc = Illinois(ChordAngle, &e, lo, flo, hi, 1e-13, 1e-13 * angle, &l))) return rc;
  if ((rc = ChordAngle(&e, l, &fhi))) return -1;
  if (fabs(fhi) > 1e-8 * angle) return -1; /* the table's range ends before the angle */
  *lout = l;
  return 0;
}

/* the barrier b(g) = -(g - gh)^2 ln(g / gh) for 0 < g < gh (0 beyond, +inf at g <= 0): C2 at gh */
double HylcClothBarrier_Private(double g, double gh, double *d1, double *d2)
{
  double r, lg;

  if (g >= gh) {
    if (d1) *d1 = 0;
    if (d2) *d2 = 0;
    return 0;
  }
  if (g <= 0) {
    if (d1) *d1 = 0;
    if (d2) *d2 = 0;
    return INFINITY;
  }
  r  = g - gh;
  lg = log(g / gh);
  if (d1) *d1 = -2 * r * lg - r * r / g;
  if (d2) *d2 = -2 * lg - 4 * r / g + r * r / (g * g);
  return -r * r * lg;
}

/* signed distance of p to the support with its gradient and Hessian (either may be NULL) */
double HylcClothSupportDistance_Private(const HylcClothSupport *s, const double p[3], double grad[3], double hess[9])
{
  if (grad)
    for (int i = 0; i < 3; i++) grad[i] = 0;
  if (hess)
    for (int i = 0; i < 9; i++) hess[i] = 0;
  if (s->kind == 0) {
    if (grad) grad[2] = 1;
    return p[2] - s->z0;
  } else {
    /* distance to the solid cylinder C0 = {r <= R - rho, z <= z0 - rho}, minus rho */
    double Rin = s->R - s->rho, zc = s->z0 - s->rho, dx = p[0] - s->cx, dy = p[1] - s->cy, r = sqrt(dx * dx + dy * dy), h = p[2] - zc;
    double er[3] = {r > 0 ? dx / r : 1, r > 0 ? dy / r : 0, 0};
    if (r <= Rin) {
      if (h <= 0) { /* inside C0 (deep penetration): the distance to its top face, negative */
        if (grad) grad[2] = 1;
        return h - s->rho;
      }
      if (grad) grad[2] = 1;
      return h - s->rho;
    } else if (h <= 0) { /* beside the pedestal */
      if (grad)
        for (int i = 0; i < 2; i++) grad[i] = er[i];
      if (hess)
        for (int i = 0; i < 2; i++)
          for (int j = 0; j < 2; j++) hess[i * 3 + j] = ((i == j) - er[i] * er[j]) / r;
      return r - Rin - s->rho;
    } else { /* the rounded rim */
      double q = r - Rin, d = sqrt(q * q + h * h), n[3] = {q / d * er[0], q / d * er[1], h / d};
      if (grad)
        for (int i = 0; i < 3; i++) grad[i] = n[i];
      if (hess) {
        double ez[3] = {0, 0, 1};
        for (int i = 0; i < 3; i++)
          for (int j = 0; j < 3; j++) hess[i * 3 + j] = (er[i] * er[j] + ez[i] * ez[j] - n[i] * n[j]) / d + (i < 2 && j < 2 ? q / (d * r) * ((i == j) - er[i] * er[j]) : 0);
      }
      return d - s->rho;
    }
  }
}
