/* Pure kernels of the macroscopic deformation: strain coordinates, I, A = sqrt(I), S, N (S12), the
   rotation field R(xi) (S10) with robust sinc-type functions, and the closed-form midsurface for
   singly curved II (docs/method.md §1.1-1.5, docs/macro.md). */
#include <hylc/macro.h>
#include <math.h>

/* ---- robust scalar functions ---------------------------------------------------------------- */

double HylcMacroSinc(double x)
{
  const double x2 = x * x;
  if (fabs(x) < 1e-4) return 1.0 - x2 / 6.0 * (1.0 - x2 / 20.0);
  return sin(x) / x;
}

double HylcMacroSinc2Half(double x)
{
  const double s = HylcMacroSinc(0.5 * x);
  return s * s;
}

/* Below |x| = 1 the direct forms lose about eps/x^2 to cancellation; the alternating series used
   there converge to full precision in at most 12 terms. */
#define HYLC_MACRO_SERIES_SWITCH 1.0
#define HYLC_MACRO_SERIES_TERMS  12

double HylcMacroG(double x)
{
  const double x2 = x * x;
  if (fabs(x) < HYLC_MACRO_SERIES_SWITCH) {
    double t = 1.0 / 6.0, s = 0;
    for (int k = 0; k < HYLC_MACRO_SERIES_TERMS; k++) {
      s += t;
      t *= -x2 / ((2 * k + 4) * (2 * k + 5));
    }
    return s;
  }
  return (1.0 - sin(x) / x) / x2;
}

double HylcMacroSincPrimeOverR(double r)
{
  const double r2 = r * r;
  if (fabs(r) < HYLC_MACRO_SERIES_SWITCH) {
    double t = -1.0 / 6.0, s = 0; /* t_k = (-1)^k r^(2k-2) / (2k+1)!, k >= 1 */
    for (int k = 1; k <= HYLC_MACRO_SERIES_TERMS; k++) {
      s += 2 * k * t;
      t *= -r2 / ((2 * k + 2) * (2 * k + 3));
    }
    return s;
  }
  return (cos(r) - sin(r) / r) / r2;
}

double HylcMacroSinc2HalfPrimeOverR(double r)
{
  const double r2 = r * r;
  if (fabs(r) < HYLC_MACRO_SERIES_SWITCH) {
    double t = -1.0 / 12.0, s = 0; /* t_k = 2 (-1)^(k+1) r^(2k-4) / (2k)!, k >= 2 */
    for (int k = 2; k < HYLC_MACRO_SERIES_TERMS + 2; k++) {
      s += (2 * k - 2) * t;
      t *= -r2 / ((2 * k + 1) * (2 * k + 2));
    }
    return s;
  }
  return 2.0 * (HylcMacroSinc(r) - HylcMacroSinc2Half(r)) / r2;
}

/* ---- strain coordinates --------------------------------------------------------------------- */

HylcMacroStrainError HylcMacroStrainValidate(const double z[6])
{
  for (int i = 0; i < 6; i++)
    if (!isfinite(z[i])) return HYLC_MACRO_STRAIN_NONFINITE;
  if (!(fabs(z[1]) < 1)) return HYLC_MACRO_STRAIN_SHEAR;
  if (!(1 + z[0] > 0)) return HYLC_MACRO_STRAIN_STRETCH_X;
  if (!(1 + z[2] > 0)) return HYLC_MACRO_STRAIN_STRETCH_Y;
  return HYLC_MACRO_STRAIN_OK;
}

const char *HylcMacroStrainErrorString(HylcMacroStrainError e)
{
  switch (e) {
  case HYLC_MACRO_STRAIN_OK:
    return "ok";
  case HYLC_MACRO_STRAIN_NONFINITE:
    return "a strain component is NaN or infinite";
  case HYLC_MACRO_STRAIN_SHEAR:
    return "|sa| >= 1 (sa is the cosine of the warp-weft angle)";
  case HYLC_MACRO_STRAIN_STRETCH_X:
    return "1 + sx <= 0";
  case HYLC_MACRO_STRAIN_STRETCH_Y:
    return "1 + sy <= 0";
  }
  return "unknown strain error";
}

void HylcMacroFirstForm(const double z[6], double I1[4])
{
  const double X = 1 + z[0], Y = 1 + z[2];
  I1[0] = X * X;
  I1[1] = z[1] * X * Y;
  I1[2] = I1[1];
  I1[3] = Y * Y;
}

void HylcMacroSqrtFirstForm(const double z[6], double A[4])
{
  const double X = 1 + z[0], Y = 1 + z[2];
  A[0] = X;
  A[1] = z[1] * Y;
  A[2] = 0;
  A[3] = sqrt((1 - z[1]) * (1 + z[1])) * Y;
}

void HylcMacroStretchMatrix(const double z[6], double S[6])
{
  double A[4];
  HylcMacroSqrtFirstForm(z, A);
  S[0] = A[0];
  S[1] = A[1];
  S[2] = A[2];
  S[3] = A[3];
  S[4] = 0;
  S[5] = 0;
}

double HylcMacroLambdaMin(const double z[6])
{
  double       I1[4];
  const double c = sqrt((1 - z[1]) * (1 + z[1])), X = 1 + z[0], Y = 1 + z[2];
  HylcMacroFirstForm(z, I1);
  const double det  = (c * X * Y) * (c * X * Y);
  const double half = 0.5 * (I1[0] + I1[3]), dif = 0.5 * (I1[0] - I1[3]);
  const double lmax = half + sqrt(dif * dif + I1[1] * I1[1]);
  return lmax > 0 ? det / lmax : 0;
}

void HylcMacroNormalDerivatives(const double z[6], double N[4])
{
  const double X = 1 + z[0], Y = 1 + z[2], c = sqrt((1 - z[1]) * (1 + z[1]));
  const double p = z[3], q = z[4], r = z[5];
  /* A^{-T} = [[1/X, 0], [-sa/(X c), 1/(c Y)]] */
  N[0] = -p / X;
  N[1] = -q / X;
  N[2] = z[1] * p / (X * c) - q / (c * Y);
  N[3] = z[1] * q / (X * c) - r / (c * Y);
}

HylcMacroCurvature HylcMacroClassifyII(const double II[3], double tol, double *H, double d[2])
{
  const double p = II[0], q = II[1], r = II[2];
  const double m = fmax(fabs(p), fmax(fabs(q), fabs(r)));
  if (tol <= 0) tol = 1e-12;
  if (m == 0) {
    if (H) *H = 0;
    if (d) d[0] = 1, d[1] = 0;
    return HYLC_MACRO_FLAT;
  }
  /* scale first: det can underflow or overflow for extreme curvatures */
  const double ps = p / m, qs = q / m, rs = r / m;
  if (fabs(ps * rs - qs * qs) > tol) return HYLC_MACRO_DOUBLY;
  double v[2];
  if (fabs(ps) >= fabs(rs))
    v[0] = ps, v[1] = qs;
  else
    v[0] = qs, v[1] = rs;
  const double nv = hypot(v[0], v[1]);
  v[0] /= nv;
  v[1] /= nv;
  if (fabs(v[1]) > fabs(v[0]) ? v[1] < 0 : v[0] < 0) v[0] = -v[0], v[1] = -v[1];
  if (H) *H = p + r;
  if (d) d[0] = v[0], d[1] = v[1];
  return HYLC_MACRO_SINGLY;
}

HylcMacroStrainError HylcMacroStrainSetUp(const double z[6], double tol, HylcMacroStrain *m)
{
  const HylcMacroStrainError e = HylcMacroStrainValidate(z);
  if (e != HYLC_MACRO_STRAIN_OK) return e;
  for (int i = 0; i < 6; i++) m->z[i] = z[i];
  HylcMacroFirstForm(z, m->I1);
  HylcMacroSqrtFirstForm(z, m->A);
  HylcMacroStretchMatrix(z, m->S);
  m->Ainv[0]   = 1 / m->A[0];
  m->Ainv[1]   = -m->A[1] / (m->A[0] * m->A[3]);
  m->Ainv[2]   = 0;
  m->Ainv[3]   = 1 / m->A[3];
  m->II[0]     = z[3];
  m->II[1]     = z[4];
  m->II[2]     = z[4];
  m->II[3]     = z[5];
  m->lambdaMin = HylcMacroLambdaMin(z);
  HylcMacroNormalDerivatives(z, m->N);
  m->curvature = HylcMacroClassifyII(z + 3, tol, &m->H, m->d);
  if (m->curvature == HYLC_MACRO_DOUBLY) {
    m->H    = 0;
    m->d[0] = 1, m->d[1] = 0;
  }
  m->dperp[0] = -m->d[1];
  m->dperp[1] = m->d[0];
  if (m->curvature == HYLC_MACRO_SINGLY) {
    m->ab[0] = m->N[0] * m->d[0] + m->N[1] * m->d[1];
    m->ab[1] = m->N[2] * m->d[0] + m->N[3] * m->d[1];
  } else
    m->ab[0] = m->ab[1] = 0;
  m->rho = hypot(m->ab[0], m->ab[1]);
  return HYLC_MACRO_STRAIN_OK;
}

/* ---- rotation field ------------------------------------------------------------------------- */

void HylcMacroRotationAB(double a, double b, double R[9], double D[9], double dRa[9], double dRb[9])
{
  const double r = hypot(a, b), c1 = HylcMacroSinc(r), c2 = HylcMacroSinc2Half(r);
  const double Dl[9] = {-0.5 * a * a * c2, -0.5 * a * b * c2, a * c1, -0.5 * a * b * c2, -0.5 * b * b * c2, b * c1, -a * c1, -b * c1, -0.5 * (a * a + b * b) * c2};

  if (D)
    for (int k = 0; k < 9; k++) D[k] = Dl[k];
  if (R) {
    for (int k = 0; k < 9; k++) R[k] = Dl[k];
    R[0] += 1;
    R[4] += 1;
    R[8] += 1;
  }
  if (dRa || dRb) {
    const double e1 = HylcMacroSincPrimeOverR(r), e2 = HylcMacroSinc2HalfPrimeOverR(r);
    if (dRa) {
      dRa[0] = -a * c2 - 0.5 * a * a * a * e2;
      dRa[1] = -0.5 * b * c2 - 0.5 * a * a * b * e2;
      dRa[2] = c1 + a * a * e1;
      dRa[3] = dRa[1];
      dRa[4] = -0.5 * a * b * b * e2;
      dRa[5] = a * b * e1;
      dRa[6] = -dRa[2];
      dRa[7] = -dRa[5];
      dRa[8] = -a * c1;
    }
    if (dRb) {
      dRb[0] = -0.5 * a * a * b * e2;
      dRb[1] = -0.5 * a * c2 - 0.5 * a * b * b * e2;
      dRb[2] = a * b * e1;
      dRb[3] = dRb[1];
      dRb[4] = -b * c2 - 0.5 * b * b * b * e2;
      dRb[5] = c1 + b * b * e1;
      dRb[6] = -dRb[2];
      dRb[7] = -dRb[5];
      dRb[8] = -b * c1;
    }
  }
}

void HylcMacroRotation(const double N[4], const double xi[2], double R[9], double D[9], double dR[18])
{
  const double a = N[0] * xi[0] + N[1] * xi[1], b = N[2] * xi[0] + N[3] * xi[1];
  if (!dR) {
    HylcMacroRotationAB(a, b, R, D, NULL, NULL);
    return;
  }
  double Ra[9], Rb[9];
  HylcMacroRotationAB(a, b, R, D, Ra, Rb);
  for (int al = 0; al < 2; al++)
    for (int k = 0; k < 9; k++) dR[9 * al + k] = Ra[k] * N[al] + Rb[k] * N[2 + al];
}

void HylcMacroNormal(const double N[4], const double xi[2], double n[3], double dn[6])
{
  double R[9], dR[18];
  HylcMacroRotation(N, xi, R, NULL, dn ? dR : NULL);
  for (int i = 0; i < 3; i++) n[i] = R[3 * i + 2];
  if (dn)
    for (int al = 0; al < 2; al++)
      for (int i = 0; i < 3; i++) dn[3 * al + i] = dR[9 * al + 3 * i + 2];
}

/* ---- closed-form midsurface ----------------------------------------------------------------- */

int HylcMacroClosedPhi(const HylcMacroStrain *m, const double xi[2], double phi[3], double n[3], double dphi[6])
{
  if (m->curvature == HYLC_MACRO_DOUBLY) return -1;
  const double s = m->d[0] * xi[0] + m->d[1] * xi[1], w = m->dperp[0] * xi[0] + m->dperp[1] * xi[1];
  double       v[2], u[2]; /* in-plane parts of S d and S dperp (third components are 0) */
  for (int i = 0; i < 2; i++) {
    v[i] = m->S[2 * i] * m->d[0] + m->S[2 * i + 1] * m->d[1];
    u[i] = m->S[2 * i] * m->dperp[0] + m->S[2 * i + 1] * m->dperp[1];
  }
  /* J(s) v = s v + s^2/2 c2 W'v + s^3 g W'^2 v with W'v = (0, 0, -p), W'^2 v = (-a' p, -b' p, 0) */
  const double p = m->ab[0] * v[0] + m->ab[1] * v[1], x = m->rho * s;
  const double c2 = HylcMacroSinc2Half(x), g = HylcMacroG(x), s3g = s * s * s * g;
  phi[0] = s * v[0] - s3g * m->ab[0] * p + w * u[0];
  phi[1] = s * v[1] - s3g * m->ab[1] * p + w * u[1];
  phi[2] = -0.5 * s * s * c2 * p;
  if (n || dphi) {
    double R[9];
    HylcMacroRotation(m->N, xi, R, NULL, NULL);
    if (n)
      for (int i = 0; i < 3; i++) n[i] = R[3 * i + 2];
    if (dphi)
      for (int i = 0; i < 3; i++)
        for (int al = 0; al < 2; al++) dphi[2 * i + al] = R[3 * i] * m->S[al] + R[3 * i + 1] * m->S[2 + al];
  }
  return 0;
}

int HylcMacroClosedPosition(const HylcMacroStrain *m, const double xi[2], double h, double x[3], double n[3])
{
  double nl[3];
  if (HylcMacroClosedPhi(m, xi, x, nl, NULL)) return -1;
  for (int i = 0; i < 3; i++) x[i] += h * nl[i];
  if (n)
    for (int i = 0; i < 3; i++) n[i] = nl[i];
  return 0;
}
