/* Plain C kernels of the fitting pipeline (include/hylc/fit.h): symlog, MLS, knots, boundary rules,
   residualization and the zero-compression rule (docs/method.md §9, §9.1). */
#include <hylc/fit.h>
#include <math.h>

PetscReal HylcSymlog(PetscReal x) { return x > 0 ? log1p(x) : x < 0 ? -log1p(-x) : 0; }
PetscReal HylcSymexp(PetscReal y) { return y > 0 ? expm1(y) : y < 0 ? -expm1(-y) : 0; }

/* Solves the n x n system A x = b (row-major, n <= 8) by Gaussian elimination with partial pivoting, in
   place (b becomes x). Returns -1 when a pivot is below 1e-13 of the largest entry of A. */
static int DenseSolve(int n, double A[], double b[])
{
  double amax = 0;
  for (int i = 0; i < n * n; i++) amax = fmax(amax, fabs(A[i]));
  if (!(amax > 0)) return -1;
  for (int c = 0; c < n; c++) {
    int piv = c;
    for (int r = c + 1; r < n; r++)
      if (fabs(A[r * n + c]) > fabs(A[piv * n + c])) piv = r;
    if (!(fabs(A[piv * n + c]) > 1e-13 * amax)) return -1;
    if (piv != c) {
      for (int k = 0; k < n; k++) {
        const double t = A[c * n + k];
        A[c * n + k]   = A[piv * n + k];
        A[piv * n + k] = t;
      }
      const double t = b[c];
      b[c]           = b[piv];
      b[piv]         = t;
    }
    for (int r = c + 1; r < n; r++) {
      const double f = A[r * n + c] / A[c * n + c];
      if (f == 0) continue;
      for (int k = c; k < n; k++) A[r * n + k] -= f * A[c * n + k];
      b[r] -= f * b[c];
    }
  }
  for (int c = n - 1; c >= 0; c--) {
    double s = b[c];
    for (int k = c + 1; k < n; k++) s -= A[c * n + k] * b[k];
    b[c] = s / A[c * n + c];
  }
  return 0;
}

int HylcMLS1D(PetscInt n, const PetscReal x[], const PetscReal f[], PetscReal kernel, PetscReal truncation, PetscReal xq, PetscReal *value)
{
  const double s = kernel / truncation, c = -0.5 / (s * s);
  double       A[9] = {0}, b[3] = {0};
  int          cnt = 0;

  for (PetscInt i = 0; i < n; i++) {
    const double d = x[i] - xq;
    if (!(fabs(d) < kernel)) continue;
    const double w = exp(c * d * d), xi = x[i], B[3] = {1, xi, xi * xi};
    cnt++;
    for (int a = 0; a < 3; a++) {
      const double wa = w * B[a];
      for (int e = a; e < 3; e++) A[a * 3 + e] += wa * B[e];
      b[a] += wa * f[i];
    }
  }
  if (cnt < 3) return -1;
  for (int a = 0; a < 3; a++)
    for (int e = 0; e < a; e++) A[a * 3 + e] = A[e * 3 + a];
  if (DenseSolve(3, A, b)) return -1;
  *value = b[0] + xq * (b[1] + xq * b[2]);
  return cnt;
}

int HylcMLS2D(PetscInt n, const PetscReal x[], const PetscReal y[], const PetscReal f[], PetscReal kx, PetscReal ky, PetscReal truncation, PetscReal xq, PetscReal yq, PetscReal *value)
{
  const double sx = kx / truncation, sy = ky / truncation, cx = -0.5 / (sx * sx), cy = -0.5 / (sy * sy);
  double       A[64] = {0}, b[8] = {0};
  int          cnt = 0;

  for (PetscInt i = 0; i < n; i++) {
    const double dx = x[i] - xq, dy = y[i] - yq;
    if (!(fabs(dx) < kx) || !(fabs(dy) < ky)) continue;
    const double w = exp(cx * dx * dx + cy * dy * dy), u = x[i], v = y[i];
    const double B[8] = {1, v, v * v, u, u * v, u * v * v, u * u, u * u * v};
    cnt++;
    for (int a = 0; a < 8; a++) {
      const double wa = w * B[a];
      for (int e = a; e < 8; e++) A[a * 8 + e] += wa * B[e];
      b[a] += wa * f[i];
    }
  }
  if (cnt < 8) return -1;
  for (int a = 0; a < 8; a++)
    for (int e = 0; e < a; e++) A[a * 8 + e] = A[e * 8 + a];
  if (DenseSolve(8, A, b)) return -1;
  const double u = xq, v = yq;
  *value = b[0] + v * (b[1] + v * b[2]) + u * (b[3] + v * (b[4] + v * b[5])) + u * u * (b[6] + v * b[7]);
  return cnt;
}

int HylcFitKnots1D(PetscReal min, PetscReal max, PetscReal factor, PetscInt n, PetscReal t[])
{
  int k = 0;
  if (n < 2 || !(min < max) || !(factor > 0)) return -1;
  const double a = factor * min, b = factor * max, h = (b - a) / (n - 1);
  for (PetscInt i = 0; i < n; i++) t[i] = i * h + a; /* as numpy's linspace: i step + start, exact end */
  t[n - 1] = b;
  for (PetscInt i = 1; i < n; i++)
    if (fabs(t[i]) < fabs(t[k])) k = (int)i;
  const double s = t[k];
  for (PetscInt i = 0; i < n; i++) t[i] -= s;
  return k;
}

int HylcFitKnots1DRefined(PetscReal min, PetscReal max, PetscReal factor, PetscInt n, PetscInt levels, PetscReal t[], PetscInt *nt)
{
  PetscReal u[1024];
  PetscInt  m = 0;
  if (levels < 0 || levels > 20 || n > 1024) return -1;
  const int k = HylcFitKnots1D(min, max, factor, n, u);
  if (k < 0) return -1;
  /* the paper's knots left of 0, the refinement of the first interval on that side, 0, and to the right */
  for (PetscInt i = 0; i < k; i++) t[m++] = u[i];
  if (k > 0)
    for (PetscInt j = 1; j <= levels; j++) t[m++] = u[k - 1] * ldexp(1.0, -(int)j);
  const int i0 = (int)m;
  t[m++]       = 0;
  if (k + 1 < n)
    for (PetscInt j = levels; j >= 1; j--) t[m++] = u[k + 1] * ldexp(1.0, -(int)j);
  for (PetscInt i = k + 1; i < n; i++) t[m++] = u[i];
  *nt = m;
  return i0;
}

int HylcFitKnots2D(PetscReal min, PetscReal max, PetscReal factor, PetscInt nl, PetscInt nr, PetscReal t[], PetscInt *nt)
{
  PetscInt m = 0;
  if (nl < 1 || nr < 1 || !(min <= max) || !(factor > 0)) return -1;
  const double a = factor * min, b = factor * max;
  if (a < 0 && nl > 1)
    for (PetscInt i = 0; i < nl - 1; i++) t[m++] = i * ((0 - a) / (nl - 1)) + a;
  const int i0 = (int)m;
  t[m++]       = 0;
  if (b > 0 && nr > 1)
    for (PetscInt i = 1; i < nr; i++) t[m++] = i == nr - 1 ? b : i * (b / (nr - 1));
  *nt = m;
  return m >= 2 ? i0 : -1;
}

void HylcFitClampBoundary2D(PetscInt nu, PetscInt nv, PetscReal eps, PetscReal mu[], PetscReal mv[])
{
  for (PetscInt j = 0; j < nv; j++) {
    mu[j * nu]          = PetscMin(mu[j * nu], -eps);
    mu[j * nu + nu - 1] = PetscMax(mu[j * nu + nu - 1], eps);
  }
  for (PetscInt i = 0; i < nu; i++) {
    mv[i]                 = PetscMin(mv[i], -eps);
    mv[(nv - 1) * nu + i] = PetscMax(mv[(nv - 1) * nu + i], eps);
  }
}

void HylcFitZeroBoundaryMixed2D(PetscInt nu, PetscInt nv, PetscReal muv[])
{
  for (PetscInt j = 0; j < nv; j++) muv[j * nu] = muv[j * nu + nu - 1] = 0;
  for (PetscInt i = 0; i < nu; i++) muv[i] = muv[(nv - 1) * nu + i] = 0;
}

void HylcFitResidualize2D(PetscInt nu, PetscInt nv, PetscInt i0, PetscInt j0, PetscReal p[], PetscReal mu[], PetscReal mv[], PetscReal muv[])
{
  (void)muv;
  const double p00 = p[j0 * nu + i0];
  for (PetscInt j = 0; j < nv; j++)
    for (PetscInt i = 0; i < nu; i++) {
      if (i == i0 || j == j0) continue;
      const PetscInt k = j * nu + i;
      p[k] -= p[j0 * nu + i] + p[j * nu + i0] - p00;
      mu[k] -= mu[j0 * nu + i];
      mv[k] -= mv[j * nu + i0];
    }
  for (PetscInt j = 0; j < nv; j++) p[j * nu + i0] = mu[j * nu + i0] = mv[j * nu + i0] = 0;
  for (PetscInt i = 0; i < nu; i++) p[j0 * nu + i] = mu[j0 * nu + i] = mv[j0 * nu + i] = 0;
}

void HylcFitZeroCompression2D(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], PetscBool zu, PetscBool zv, PetscBool strict, PetscReal p[], PetscReal mu[], PetscReal mv[], PetscReal muv[])
{
  for (PetscInt j = 0; j < nv; j++)
    for (PetscInt i = 0; i < nu; i++) {
      const PetscInt k = j * nu + i;
      if ((zu && tu[i] < 0) || (zv && tv[j] < 0)) p[k] = mu[k] = mv[k] = muv[k] = 0;
    }
  if (!strict) return;
  /* the first knot line at or beyond 0 borders the zeroed cells: muv there would leave a non-zero
     bicubic inside the last compressed cell */
  if (zu)
    for (PetscInt i = 1; i < nu; i++)
      if (tu[i] >= 0 && tu[i - 1] < 0)
        for (PetscInt j = 0; j < nv; j++) muv[j * nu + i] = 0;
  if (zv)
    for (PetscInt j = 1; j < nv; j++)
      if (tv[j] >= 0 && tv[j - 1] < 0)
        for (PetscInt i = 0; i < nu; i++) muv[j * nu + i] = 0;
}
