/* Cubic and bicubic Hermite spline evaluation (include/hylc/spline.h). */
#include <hylc/spline.h>

PetscInt HylcSplineLocate(PetscInt n, const PetscReal t[], PetscReal x)
{
  PetscInt lo = 0, hi = n - 1;

  if (!(x >= t[0])) return -1; /* also NaN: treated as left extrapolation, propagates through the basis */
  if (x >= t[n - 1]) return n - 1;
  while (hi - lo > 1) { /* invariant: t[lo] <= x < t[hi] */
    const PetscInt mid = (lo + hi) / 2;
    if (x >= t[mid])
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

PetscInt HylcHermiteBasis(PetscInt n, const PetscReal t[], HylcSplineExt ext, PetscReal x, PetscReal a[2], PetscReal b[2], PetscReal da[2], PetscReal db[2], PetscReal dda[2], PetscReal ddb[2])
{
  const PetscInt loc  = HylcSplineLocate(n, t, x);
  PetscReal      A[2] = {0, 0}, B[2] = {0, 0}, dA[2] = {0, 0}, dB[2] = {0, 0}, ddA[2] = {0, 0}, ddB[2] = {0, 0};
  PetscInt       i;

  if (loc < 0 || loc >= n - 1) {
    const PetscInt c = loc < 0 ? 0 : 1; /* which end of the first/last interval */
    const PetscInt e = loc < 0 ? 0 : n - 1;

    i = loc < 0 ? 0 : n - 2;
    switch (ext) {
    case HYLC_EXT_LINEAR:
      A[c]  = 1;
      B[c]  = x - t[e];
      dB[c] = 1;
      break;
    case HYLC_EXT_CONSTANT:
      A[c] = 1;
      break;
    case HYLC_EXT_ZERO:
      break;
    }
  } else {
    const PetscReal h = t[loc + 1] - t[loc], s = (x - t[loc]) / h, s2 = s * s, s3 = s2 * s;

    i      = loc;
    A[0]   = 2 * s3 - 3 * s2 + 1;
    A[1]   = -2 * s3 + 3 * s2;
    B[0]   = (s3 - 2 * s2 + s) * h;
    B[1]   = (s3 - s2) * h;
    dA[0]  = (6 * s2 - 6 * s) / h;
    dA[1]  = -dA[0];
    dB[0]  = 3 * s2 - 4 * s + 1;
    dB[1]  = 3 * s2 - 2 * s;
    ddA[0] = (12 * s - 6) / (h * h);
    ddA[1] = -ddA[0];
    ddB[0] = (6 * s - 4) / h;
    ddB[1] = (6 * s - 2) / h;
  }
  for (PetscInt c = 0; c < 2; c++) {
    a[c] = A[c];
    b[c] = B[c];
    if (da) da[c] = dA[c];
    if (db) db[c] = dB[c];
    if (dda) dda[c] = ddA[c];
    if (ddb) ddb[c] = ddB[c];
  }
  return i;
}

PetscReal HylcHermite1DEval(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], HylcSplineExt ext, PetscReal x, PetscReal *d1, PetscReal *d2)
{
  PetscReal      a[2], b[2], da[2], db[2], dda[2], ddb[2];
  const PetscInt i = HylcHermiteBasis(n, t, ext, x, a, b, da, db, dda, ddb);

  if (d1) *d1 = da[0] * p[i] + da[1] * p[i + 1] + db[0] * m[i] + db[1] * m[i + 1];
  if (d2) *d2 = dda[0] * p[i] + dda[1] * p[i + 1] + ddb[0] * m[i] + ddb[1] * m[i + 1];
  return a[0] * p[i] + a[1] * p[i + 1] + b[0] * m[i] + b[1] * m[i + 1];
}

PetscReal HylcSpline1DEval(const HylcSpline1D *s, PetscReal x, PetscReal *d1, PetscReal *d2) { return HylcHermite1DEval(s->n, s->t, s->p, s->m, s->ext, x, d1, d2); }

PetscReal HylcHermite2DEval(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal tv[], const PetscReal p[], const PetscReal mu[], const PetscReal mv[], const PetscReal muv[], HylcSplineExt ext, PetscReal u, PetscReal v, PetscReal g[2],
                            PetscReal H[3])
{
  PetscReal      au[2], bu[2], dau[2], dbu[2], ddau[2], ddbu[2];
  PetscReal      av[2], bv[2], dav[2], dbv[2], ddav[2], ddbv[2];
  const PetscInt i = HylcHermiteBasis(nu, tu, ext, u, au, bu, dau, dbu, ddau, ddbu);
  const PetscInt j = HylcHermiteBasis(nv, tv, ext, v, av, bv, dav, dbv, ddav, ddbv);
  PetscReal      f = 0, fu = 0, fv = 0, fuu = 0, fuv = 0, fvv = 0;

  for (PetscInt cj = 0; cj < 2; cj++) {
    for (PetscInt ci = 0; ci < 2; ci++) {
      const PetscInt  k = (j + cj) * nu + (i + ci);
      const PetscReal P = p[k], U = mu[k], V = mv[k], W = muv[k];

      f += au[ci] * av[cj] * P + bu[ci] * av[cj] * U + au[ci] * bv[cj] * V + bu[ci] * bv[cj] * W;
      if (g || H) {
        fu += dau[ci] * av[cj] * P + dbu[ci] * av[cj] * U + dau[ci] * bv[cj] * V + dbu[ci] * bv[cj] * W;
        fv += au[ci] * dav[cj] * P + bu[ci] * dav[cj] * U + au[ci] * dbv[cj] * V + bu[ci] * dbv[cj] * W;
      }
      if (H) {
        fuu += ddau[ci] * av[cj] * P + ddbu[ci] * av[cj] * U + ddau[ci] * bv[cj] * V + ddbu[ci] * bv[cj] * W;
        fuv += dau[ci] * dav[cj] * P + dbu[ci] * dav[cj] * U + dau[ci] * dbv[cj] * V + dbu[ci] * dbv[cj] * W;
        fvv += au[ci] * ddav[cj] * P + bu[ci] * ddav[cj] * U + au[ci] * ddbv[cj] * V + bu[ci] * ddbv[cj] * W;
      }
    }
  }
  if (g) {
    g[0] = fu;
    g[1] = fv;
  }
  if (H) {
    H[0] = fuu;
    H[1] = fuv;
    H[2] = fvv;
  }
  return f;
}

PetscReal HylcSpline2DEval(const HylcSpline2D *s, PetscReal u, PetscReal v, PetscReal g[2], PetscReal H[3]) { return HylcHermite2DEval(s->nu, s->nv, s->tu, s->tv, s->p, s->mu, s->mv, s->muv, s->ext, u, v, g, H); }

/* the piece polynomial about its own origin k: sum c[r] (x - k)^r */
static void PieceOwn(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], PetscInt j0, HylcSplineExt ext, PetscInt i, PetscReal *k, PetscReal c[4])
{
  if (i < 0 || i >= n - 1) {
    const PetscInt e = i < 0 ? 0 : n - 1;
    *k               = t[e];
    c[0]             = ext == HYLC_EXT_ZERO ? 0 : p[e - j0];
    c[1]             = ext == HYLC_EXT_LINEAR ? m[e - j0] : 0;
    c[2] = c[3] = 0;
  } else {
    const PetscReal h = t[i + 1] - t[i], m0 = m[i - j0], m1 = m[i + 1 - j0], d = (p[i + 1 - j0] - p[i - j0]) / h;
    *k   = t[i];
    c[0] = p[i - j0];
    c[1] = m0;
    c[2] = (3 * d - 2 * m0 - m1) / h;
    c[3] = (m0 + m1 - 2 * d) / (h * h);
  }
}

/* re-expands sum c[r] (x - k)^r about x0 */
static void Shift(const PetscReal c[4], PetscReal e, PetscReal out[4])
{
  out[0] = c[0] + e * (c[1] + e * (c[2] + e * c[3]));
  out[1] = c[1] + e * (2 * c[2] + 3 * e * c[3]);
  out[2] = c[2] + 3 * e * c[3];
  out[3] = c[3];
}

void HylcHermite1DPiece(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], PetscInt j0, HylcSplineExt ext, PetscInt i, PetscReal x0, PetscReal c[4])
{
  PetscReal k, own[4];

  PieceOwn(n, t, p, m, j0, ext, i, &k, own);
  Shift(own, x0 - k, c);
}

void HylcHermite1DKnotJump(PetscInt n, const PetscReal t[], const PetscReal p[], const PetscReal m[], PetscInt j0, HylcSplineExt ext, PetscInt k, PetscReal J[4])
{
  PetscReal L[4], R[4];

  HylcHermite1DPiece(n, t, p, m, j0, ext, k - 1, t[k], L);
  HylcHermite1DPiece(n, t, p, m, j0, ext, k, t[k], R);
  J[2] = R[2] - L[2];
  J[3] = R[3] - L[3];
  J[0] = J[1] = 0;
  if (k == 0) { /* the first interval minus the extrapolation on the left, at t[0] */
    J[0] = ext == HYLC_EXT_ZERO ? p[-j0] : 0;
    J[1] = ext == HYLC_EXT_LINEAR ? 0 : m[-j0];
  }
  if (k == n - 1) { /* the extrapolation on the right minus the last interval, at t[n-1] */
    J[0] = ext == HYLC_EXT_ZERO ? -p[n - 1 - j0] : 0;
    J[1] = ext == HYLC_EXT_LINEAR ? 0 : -m[n - 1 - j0];
  }
}

void HylcHermite2DSliceV(PetscInt nu, PetscInt nv, const PetscReal tu[], const PetscReal p[], const PetscReal mu[], const PetscReal mv[], const PetscReal muv[], HylcSplineExt ext, PetscReal u, PetscInt j0, PetscInt j1, PetscReal P[], PetscReal M[],
                         PetscReal Pu[], PetscReal Mu[], PetscReal Puu[], PetscReal Muu[])
{
  PetscReal      a[2], b[2], da[2], db[2], dda[2], ddb[2];
  const PetscInt i = HylcHermiteBasis(nu, tu, ext, u, a, b, da, db, dda, ddb);

  (void)nv;
  for (PetscInt j = j0; j <= j1; j++) {
    const PetscInt k = j * nu + i;
    P[j - j0]        = a[0] * p[k] + a[1] * p[k + 1] + b[0] * mu[k] + b[1] * mu[k + 1];
    M[j - j0]        = a[0] * mv[k] + a[1] * mv[k + 1] + b[0] * muv[k] + b[1] * muv[k + 1];
    if (Pu) Pu[j - j0] = da[0] * p[k] + da[1] * p[k + 1] + db[0] * mu[k] + db[1] * mu[k + 1];
    if (Mu) Mu[j - j0] = da[0] * mv[k] + da[1] * mv[k + 1] + db[0] * muv[k] + db[1] * muv[k + 1];
    if (Puu) Puu[j - j0] = dda[0] * p[k] + dda[1] * p[k + 1] + ddb[0] * mu[k] + ddb[1] * mu[k + 1];
    if (Muu) Muu[j - j0] = dda[0] * mv[k] + dda[1] * mv[k + 1] + ddb[0] * muv[k] + ddb[1] * muv[k + 1];
  }
}
