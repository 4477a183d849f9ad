#include <hylc/geom.h>
#include <petscsys.h>
#include <petscblaslapack.h>
#include <stdlib.h>

int HylcParallelTransport(const double a[3], const double b[3], const double v[3], double out[3])
{
  const double c = HylcDot3(a, b);
  double       k[3], kxv[3], w[3];

  if (c <= -1.0 + 1e-12) { /* antiparallel: rotate by pi about any axis perpendicular to a */
    double ax[3];
    HylcAnyPerpendicular(a, ax);
    HylcRotateAxisAngle(v, ax, M_PI, out);
    return -1;
  }
  HylcCross3(a, b, k);
  HylcCross3(k, v, kxv);
  const double f = HylcDot3(k, v) / (1.0 + c);
  for (int i = 0; i < 3; i++) w[i] = c * v[i] + kxv[i] + f * k[i];
  for (int i = 0; i < 3; i++) out[i] = w[i];
  return 0;
}

double HylcSignedAngle(const double u[3], const double v[3], const double t[3])
{
  double w[3];
  HylcCross3(u, v, w);
  return atan2(HylcDot3(w, t), HylcDot3(u, v));
}

void HylcRotateAxisAngle(const double v[3], const double t[3], double phi, double out[3])
{
  const double c = cos(phi), s = sin(phi), td = HylcDot3(t, v);
  double       txv[3];
  HylcCross3(t, v, txv);
  for (int i = 0; i < 3; i++) out[i] = c * v[i] + s * txv[i] + (1.0 - c) * td * t[i];
}

double HylcOrthonormalizeDirector(const double t[3], double d1[3])
{
  const double n0 = HylcNorm3(d1);
  if (!(n0 > 0)) return 0.0;
  HylcAxpy3(-HylcDot3(t, d1), t, d1);
  const double n1 = HylcNorm3(d1);
  if (!(n1 > 0)) return 0.0;
  HylcScale3(1.0 / n1, d1);
  return n1 / n0;
}

void HylcAnyPerpendicular(const double t[3], double d[3])
{
  /* cross with the coordinate axis least aligned with t */
  const double ax = fabs(t[0]), ay = fabs(t[1]), az = fabs(t[2]);
  double       e[3] = {0, 0, 0};
  if (ax <= ay && ax <= az)
    e[0] = 1;
  else if (ay <= az)
    e[1] = 1;
  else
    e[2] = 1;
  HylcCross3(t, e, d);
  HylcNormalize3(d);
}

double HylcCurvatureBinormal(const double te[3], const double tf[3], double kb[3])
{
  const double chi = 1.0 + HylcDot3(te, tf);
  HylcCross3(te, tf, kb);
  HylcScale3(2.0 / (chi > 1e-12 ? chi : 1e-12), kb);
  return chi;
}

void HylcMaterialCurvature(const double kb[3], const double m1e[3], const double m2e[3], const double m1f[3], const double m2f[3], double kappa[2])
{
  double m1[3], m2[3];
  for (int i = 0; i < 3; i++) {
    m1[i] = 0.5 * (m1e[i] + m1f[i]);
    m2[i] = 0.5 * (m2e[i] + m2f[i]);
  }
  kappa[0] = HylcDot3(kb, m2);
  kappa[1] = -HylcDot3(kb, m1);
}

void HylcMaterialFrame(const double d1[3], const double d2[3], double theta, double m1[3], double m2[3])
{
  const double c = cos(theta), s = sin(theta);
  for (int i = 0; i < 3; i++) {
    const double a = d1[i], b = d2[i];
    m1[i] = c * a + s * b;
    m2[i] = -s * a + c * b;
  }
}

double HylcReferenceTwist(const double te[3], const double d1e[3], const double tf[3], const double d1f[3])
{
  double p[3];
  HylcParallelTransport(te, tf, d1e, p);
  return HylcSignedAngle(p, d1f, tf);
}

static inline double Clamp01(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }

double HylcSegmentSegmentDistance(const double p0[3], const double p1[3], const double q0[3], const double q1[3], double *sout, double *tout)
{
  double       d1[3], d2[3], r[3], s, t;
  const double eps = 1e-14;
  HylcSub3(p1, p0, d1);
  HylcSub3(q1, q0, d2);
  HylcSub3(p0, q0, r);
  const double a = HylcDot3(d1, d1), e = HylcDot3(d2, d2), f = HylcDot3(d2, r);

  if (a <= eps * eps && e <= eps * eps) {
    s = t = 0;
  } else if (a <= eps * eps) {
    s = 0;
    t = Clamp01(f / e);
  } else {
    const double c = HylcDot3(d1, r);
    if (e <= eps * eps) {
      t = 0;
      s = Clamp01(-c / a);
    } else {
      const double b = HylcDot3(d1, d2), denom = a * e - b * b;
      /* (nearly) parallel: denom relative to a e is tiny; pick s = 0 and solve for t */
      s = denom > 1e-12 * a * e ? Clamp01((b * f - c * e) / denom) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = Clamp01(-c / a);
      } else if (t > 1) {
        t = 1;
        s = Clamp01((b - c) / a);
      }
    }
  }
  double cp[3], cq[3], v[3];
  for (int i = 0; i < 3; i++) {
    cp[i] = p0[i] + s * d1[i];
    cq[i] = q0[i] + t * d2[i];
  }
  HylcSub3(cp, cq, v);
  if (sout) *sout = s;
  if (tout) *tout = t;
  return HylcNorm3(v);
}

int HylcDenseInverse(int m, double *A, double *Ainv, double tol)
{
  const PetscBLASInt n = (PetscBLASInt)m, lwork = (PetscBLASInt)(m * m);
  PetscBLASInt       info = 0, *ipiv;
  double             dmax = 0;
  int                r;

  if (m <= 0) return 0;
  if (!(ipiv = malloc(sizeof(PetscBLASInt) * (size_t)m))) return -1 - m;
  /* Ainv = A in LAPACK's column-major order, so that the row pivots are those of A */
  for (int i = 0; i < m; i++) {
    dmax = fmax(dmax, fabs(A[i * m + i]));
    for (int j = 0; j < m; j++) Ainv[j * m + i] = A[i * m + j];
  }
  LAPACKgetrf_(&n, &n, Ainv, &n, ipiv, &info);
  r = info < 0 ? -1 : 0;
  for (int c = 0; c < m && !r; c++) /* the first pivot below tol (also NaN) */
    if (!(fabs(Ainv[c * m + c]) > tol * dmax)) r = -1 - c;
  if (!r) {
    LAPACKgetri_(&n, Ainv, &n, ipiv, A, &lwork, &info); /* A is the work array */
    if (info) r = info > 0 ? -(int)info : -1;           /* info > 0: pivot info - 1 is zero */
  }
  free(ipiv);
  if (r) return r;
  for (int i = 0; i < m; i++) /* back to row-major */
    for (int j = i + 1; j < m; j++) {
      const double t  = Ainv[i * m + j];
      Ainv[i * m + j] = Ainv[j * m + i];
      Ainv[j * m + i] = t;
    }
  return 0;
}
