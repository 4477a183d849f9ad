/* The body of the material evaluator, included twice by evaluate.c: once in double (R = double, the
   fast path) and once in long double (R = long double, the fallback for strains or tables whose
   intermediate quantities leave the double range; see evaluate.c). Every name is F(name), so the two
   copies do not clash. Knots and node data are read as double and widened to R. Plain C99. */

/* divided-difference quantities of one constituent h in table units (a = A / sigma, s = S / sigma):
   P, Q and their derivatives in a; W1 = dQ/dw, W2 = d2Q/dadw, W3 = d2Q/dw2 (w = s^2). */
typedef struct {
  R P, Q, Pa, Qa, Paa, Qaa, W1, W2, W3;
} F(Quot);

/* the bending part accumulated in physical units: P-type and Q-type quantities (see Add) */
typedef struct {
  R P, PA, PAA, Pw, PAw, Pww;
  R Q, QA, QAA, Qw, QAw, Qww;
} F(Bend);

/* the Hermite basis with nd derivatives: the spline is sum_c a[0][c] p[i+c] + b[0][c] m[i+c]; a[d],
   b[d] are the d-th derivatives */
typedef struct {
  int i;
  R   a[3][2], b[3][2];
} F(Basis);

static inline void F(ShiftPoly)(const R c[4], R e, R out[4])
{
  out[0] = c[0] + e * (c[1] + e * (c[2] + e * c[3]));
  out[1] = c[1] + e * (2 * c[2] + 3 * e * c[3]);
  out[2] = c[2] + 3 * e * c[3];
  out[3] = c[3];
}

/* The interval of x among the knots t[0..n-1]: -1 left of t[0] (and for NaN), n-1 from t[n-1] on,
   otherwise the i with t[i] <= x < t[i+1]. The first guess from the mean knot spacing
   (ih = (n-1) / (t[n-1] - t[0])) is used only when it is a valid index and lands on or next to the
   interval; otherwise a binary search on the knots (never a cast of a non-finite number). */
static inline int F(Loc)(int n, const double t[], double ih, R x)
{
  int lo = 0, hi = n - 1;
  R   g;

  if (!(x >= t[0])) return -1;
  if (x >= t[n - 1]) return n - 1;
  g = (x - t[0]) * ih;
  if (g >= 0 && g < (R)(n - 1)) {
    const int i = (int)g; /* 0 <= i <= n - 2 */
    if (x >= t[i]) {
      if (x < t[i + 1]) return i;
      if (i + 2 <= n - 1 && x < t[i + 2]) return i + 1;
    } else if (i >= 1 && x >= t[i - 1])
      return i - 1;
  }
  while (hi - lo > 1) { /* t[lo] <= x < t[hi] */
    const int mid = lo + (hi - lo) / 2;
    if (x >= t[mid])
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

/* the piece polynomial i (HylcHermite1DPiece) about its own origin k: sum c[r] (x - k)^r; node data
   P[j - j0], M[j - j0] */
static inline void F(PieceOwn)(int n, const double t[], const R P[], const R M[], int j0, int ext, int i, R *k, R c[4])
{
  if (i < 0 || i >= n - 1) {
    const int e = i < 0 ? 0 : n - 1;
    *k          = t[e];
    c[0]        = ext == HYLCMAT_EXT_ZERO ? 0 : P[e - j0];
    c[1]        = ext == HYLCMAT_EXT_LINEAR ? M[e - j0] : 0;
    c[2] = c[3] = 0;
  } else {
    /* one division (the others as products with its reciprocal: the same to rounding) */
    const R ih = 1 / ((R)t[i + 1] - (R)t[i]), m0 = M[i - j0], m1 = M[i + 1 - j0], d = (P[i + 1 - j0] - P[i - j0]) * ih;
    *k   = t[i];
    c[0] = P[i - j0];
    c[1] = m0;
    c[2] = (3 * d - 2 * m0 - m1) * ih;
    c[3] = (m0 + m1 - 2 * d) * (ih * ih);
  }
}

static void F(Piece)(int n, const double t[], const R P[], const R M[], int j0, int ext, int i, R x0, R c[4])
{
  R k, own[4];

  F(PieceOwn)
  (n, t, P, M, j0, ext, i, &k, own);
  F(ShiftPoly)
  (own, x0 - k, c);
}

/* HylcHermite1DKnotJump on node data P, M */
static void F(KnotJump)(int n, const double t[], const R P[], const R M[], int j0, int ext, int k, R J[4])
{
  R L[4], Rt[4];

  F(Piece)
  (n, t, P, M, j0, ext, k - 1, t[k], L);
  F(Piece)
  (n, t, P, M, j0, ext, k, t[k], Rt);
  J[2] = Rt[2] - L[2];
  J[3] = Rt[3] - L[3];
  J[0] = J[1] = 0;
  if (k == 0) {
    J[0] = ext == HYLCMAT_EXT_ZERO ? P[-j0] : 0;
    J[1] = ext == HYLCMAT_EXT_LINEAR ? 0 : M[-j0];
  }
  if (k == n - 1) {
    J[0] = ext == HYLCMAT_EXT_ZERO ? -P[n - 1 - j0] : 0;
    J[1] = ext == HYLCMAT_EXT_LINEAR ? 0 : -M[n - 1 - j0];
  }
}

/* the piece form: x- = a - s in piece L, x+ = a + s in piece Rp (Rp - L <= 1); node data P, M from j0;
   nd = number of a-derivatives wanted (0: P, Q; 1: + Pa, Qa, W1; 2: all), the others are set to 0 */
static HM_ALWAYS_INLINE void F(QuotPieces)(int n, const double t[], const R P[], const R M[], int j0, int ext, int L, int Rp, R a, R s, int nd, F(Quot) * q)
{
  R       l[4], d[4] = {0, 0, 0, 0};
  const R w = s * s;

  if (Rp == L + 1 && L >= 0 && Rp < n - 1) {
    /* an interior knot k = Rp between a - s and a + s: both pieces' own coefficients once; the jump at k
       is J = (0, 0, cR2 - (cL2 + 3 cL3 h), cR3 - cL3) (the left piece moved to t[k]), shifted to a */
    R       cL[4], cR[4], kL, kR, J2, J3, dk;
    const R h = (R)t[Rp] - (R)t[L];
    F(PieceOwn)
    (n, t, P, M, j0, ext, L, &kL, cL);
    F(PieceOwn)
    (n, t, P, M, j0, ext, Rp, &kR, cR);
    F(ShiftPoly)
    (cL, a - kL, l);
    J2   = cR[2] - (cL[2] + 3 * cL[3] * h);
    J3   = cR[3] - cL[3];
    dk   = a - kR;
    d[0] = dk * dk * (J2 + J3 * dk);
    d[1] = dk * (2 * J2 + 3 * J3 * dk);
    d[2] = J2 + 3 * J3 * dk;
    d[3] = J3;
  } else {
    F(Piece)
    (n, t, P, M, j0, ext, L, a, l);
  }
  q->P   = l[0] + l[2] * w;
  q->Q   = l[1] + l[3] * w;
  q->Pa  = nd > 0 ? l[1] + 3 * l[3] * w : 0;
  q->Qa  = nd > 0 ? 2 * l[2] : 0;
  q->Paa = nd > 1 ? 2 * l[2] : 0;
  q->Qaa = nd > 1 ? 6 * l[3] : 0;
  q->W1  = nd > 0 ? l[3] : 0;
  q->W2  = 0;
  q->W3  = 0;
  if (Rp == L) return;
  if (!(Rp == L + 1 && L >= 0 && Rp < n - 1))
    for (int k = L + 1; k <= Rp; k++) { /* h_R - h_L: the sum of the jumps at the knots between */
      R J[4], e[4];
      F(KnotJump)
      (n, t, P, M, j0, ext, k, J);
      F(ShiftPoly)
      (J, a - t[k], e);
      for (int r = 0; r < 4; r++) d[r] += e[r];
    }
  {
    /* the quotients by s, s^3, s^5 as products with 1/s (the same to rounding; s >= S_TINY here) */
    const R s3 = w * s, is = 1 / s, is3 = is * is * is;
    q->P += 0.5 * (d[0] + d[1] * s + d[2] * w + d[3] * s3);
    q->Q += 0.5 * (d[0] * is + d[1] + d[2] * s + d[3] * w);
    if (nd < 1) return;
    q->Pa += 0.5 * (d[1] + 2 * d[2] * s + 3 * d[3] * w);
    q->Qa += 0.5 * (d[1] * is + 2 * d[2] + 3 * d[3] * s);
    q->W1 += 0.5 * d[3] + 0.25 * (d[2] * w - d[0]) * is3;
    if (nd < 2) return;
    q->Paa += d[2] + 3 * d[3] * s;
    q->Qaa += d[2] * is + 3 * d[3];
    q->W2 = 0.25 * (3 * d[3] * w - d[1]) * is3;
    q->W3 = 0.125 * (3 * d[0] - d[2] * w) * (is3 * is * is);
  }
}

/* the direct form from h, h', h'' at a + s (hp) and a - s (hm); nd = number of a-derivatives wanted */
static inline void F(QuotDirect)(R s, const R hp[3], const R hm[3], int nd, F(Quot) * q)
{
  const R w = s * s, i2s = 0.5 / s;

  q->P  = 0.5 * (hp[0] + hm[0]);
  q->Q  = (hp[0] - hm[0]) * i2s;
  q->Pa = q->Qa = q->Paa = q->Qaa = q->W1 = q->W2 = q->W3 = 0;
  if (nd < 1) return;
  q->Pa = 0.5 * (hp[1] + hm[1]);
  q->Qa = (hp[1] - hm[1]) * i2s;
  q->W1 = (q->Pa - q->Q) / (2 * w);
  if (nd < 2) return;
  q->Paa = 0.5 * (hp[2] + hm[2]);
  q->Qaa = (hp[2] - hm[2]) * i2s;
  q->W2  = (q->Paa - q->Qa) / (2 * w);
  q->W3  = (q->Qaa - 6 * q->W1) / (4 * w);
}

static HM_ALWAYS_INLINE void F(BasisAt)(int n, const double t[], double ih, int ext, R x, int nd, F(Basis) * B)
{
  const int loc = F(Loc)(n, t, ih, x);

  for (int d = 0; d <= nd; d++) B->a[d][0] = B->a[d][1] = B->b[d][0] = B->b[d][1] = 0;
  if (loc < 0 || loc >= n - 1) {
    const int c = loc < 0 ? 0 : 1;
    B->i        = loc < 0 ? 0 : n - 2;
    if (ext != HYLCMAT_EXT_ZERO) B->a[0][c] = 1;
    if (ext == HYLCMAT_EXT_LINEAR) {
      B->b[0][c] = x - t[loc < 0 ? 0 : n - 1];
      if (nd > 0) B->b[1][c] = 1;
    }
  } else {
    const R h = (R)t[loc + 1] - (R)t[loc], s = (x - t[loc]) / h, s2 = s * s, s3 = s2 * s;
    B->i       = loc;
    B->a[0][0] = 2 * s3 - 3 * s2 + 1;
    B->a[0][1] = -2 * s3 + 3 * s2;
    B->b[0][0] = (s3 - 2 * s2 + s) * h;
    B->b[0][1] = (s3 - s2) * h;
    if (nd > 0) {
      B->a[1][0] = (6 * s2 - 6 * s) / h;
      B->a[1][1] = -B->a[1][0];
      B->b[1][0] = 3 * s2 - 4 * s + 1;
      B->b[1][1] = 3 * s2 - 2 * s;
    }
    if (nd > 1) {
      B->a[2][0] = (12 * s - 6) / (h * h);
      B->a[2][1] = -B->a[2][0];
      B->b[2][0] = (6 * s - 4) / h;
      B->b[2][1] = (6 * s - 2) / h;
    }
  }
}

/* f[d] = d-th derivative of a 1D spline at x, d <= nd */
static HM_ALWAYS_INLINE void F(Eval1D)(const hylcmat_term1d *sp, double ih, R x, int nd, R f[3])
{
  F(Basis)
  B;
  const double *p, *m;

  F(BasisAt)
  (sp->n, sp->t, ih, sp->ext, x, nd, &B);
  p = sp->p + B.i;
  m = sp->m + B.i;
  for (int d = 0; d <= nd; d++) f[d] = B.a[d][0] * p[0] + B.a[d][1] * p[1] + B.b[d][0] * m[0] + B.b[d][1] * m[1];
}

/* the node values P[o][.] and v-slopes M[o][.] of the restriction v -> d^o f(u, v)/du^o (o <= nd), for
   the v-nodes j0..j1 (at most 3), from the u-basis Bu */
static HM_ALWAYS_INLINE void F(SliceV)(const hylcmat_term2d *sp, const F(Basis) * Bu, int j0, int j1, int nd, R P[3][3], R M[3][3])
{
  for (int j = j0; j <= j1; j++) {
    const int     k = j * sp->nu + Bu->i;
    const double *p = sp->p + k, *mu = sp->mu + k, *mv = sp->mv + k, *muv = sp->muv + k;
    for (int o = 0; o <= nd; o++) {
      P[o][j - j0] = Bu->a[o][0] * p[0] + Bu->a[o][1] * p[1] + Bu->b[o][0] * mu[0] + Bu->b[o][1] * mu[1];
      M[o][j - j0] = Bu->a[o][0] * mv[0] + Bu->a[o][1] * mv[1] + Bu->b[o][0] * muv[0] + Bu->b[o][1] * muv[1];
    }
  }
}

/* f[o][r] = d^(o+r) f / du^o dv^r of a 2D spline at (u, v), o + r <= nd, from the u-basis Bu (nd derivatives) */
static HM_ALWAYS_INLINE void F(Eval2D)(const hylcmat_term2d *sp, const F(Basis) * Bu, double ihv, R v, int nd, R f[3][3])
{
  F(Basis)
  Bv;
  R P[3][3], M[3][3];

  F(BasisAt)
  (sp->nv, sp->tv, ihv, sp->ext, v, nd, &Bv);
  F(SliceV)
  (sp, Bu, Bv.i, Bv.i + 1, nd, P, M);
  for (int o = 0; o <= nd; o++)
    for (int r = 0; r <= nd - o; r++) f[o][r] = Bv.a[r][0] * P[o][0] + Bv.a[r][1] * P[o][1] + Bv.b[r][0] * M[o][0] + Bv.b[r][1] * M[o][1];
}

/* a 1D bending constituent h(x) = f_k(x) at x = a +- s */
static HM_ALWAYS_INLINE void F(Quot1D)(const hylcmat_term1d *sp, double sw, double ih, R a, R s, int level, F(Quot) * q)
{
  R hp[3] = {0, 0, 0}, hm[3] = {0, 0, 0};

  if (s < sw) {
    const R   ss = s < S_TINY ? 0 : s;
    const int L = F(Loc)(sp->n, sp->t, ih, a - ss), Rp = F(Loc)(sp->n, sp->t, ih, a + ss);
    if (Rp - L <= 1) {
      const int j0 = HM_MAX(L, 0), j1 = HM_MIN(Rp + 1, sp->n - 1);
      R         P[3], M[3];
      for (int j = j0; j <= j1; j++) {
        P[j - j0] = sp->p[j];
        M[j - j0] = sp->m[j];
      }
      F(QuotPieces)
      (sp->n, sp->t, P, M, j0, sp->ext, L, Rp, a, ss, level, q);
      return;
    }
  }
  F(Eval1D)
  (sp, ih, a + s, level, hp);
  F(Eval1D)
  (sp, ih, a - s, level, hm);
  F(QuotDirect)
  (s, hp, hm, level, q);
}

/* a 2D bending constituent h(x) = f_ik(u, x) at x = a +- s, and (level >= 1) its u-derivatives: q[0] for
   h, q[1] for dh/du (level - 1 a-derivatives), q[2] for d2h/du2 (level 2, none); Bu: the u-basis */
static HM_ALWAYS_INLINE void F(Quot2D)(const hylcmat_term2d *sp, double sw, double ihv, const F(Basis) * Bu, R a, R s, int level, F(Quot) q[3])
{
  R fp[3][3], fm[3][3];

  if (s < sw) {
    const R   ss = s < S_TINY ? 0 : s;
    const int L = F(Loc)(sp->nv, sp->tv, ihv, a - ss), Rp = F(Loc)(sp->nv, sp->tv, ihv, a + ss);
    if (Rp - L <= 1) {
      const int j0 = HM_MAX(L, 0), j1 = HM_MIN(Rp + 1, sp->nv - 1);
      R         P[3][3], M[3][3];
      F(SliceV)
      (sp, Bu, j0, j1, level, P, M);
      for (int o = 0; o <= level; o++) F(QuotPieces)
      (sp->nv, sp->tv, P[o], M[o], j0, sp->ext, L, Rp, a, ss, level - o, &q[o]);
      return;
    }
  }
  F(Eval2D)
  (sp, Bu, ihv, a + s, level, fp);
  F(Eval2D)
  (sp, Bu, ihv, a - s, level, fm);
  for (int o = 0; o <= level; o++) {
    const R hp[3] = {fp[o][0], o < level ? fp[o][1] : 0, o + 1 < level ? fp[o][2] : 0};
    const R hm[3] = {fm[o][0], o < level ? fm[o][1] : 0, o + 1 < level ? fm[o][2] : 0};
    F(QuotDirect)
    (s, hp, hm, level - o, &q[o]);
  }
}

/* the derivative orders (ou, ov) of the restrictions of a 3D term along w, by total order: a level-nd evaluation
   uses the first 1, 3 or 6 */
static const int F(D3)[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};

/* the node values P[o][.] and w-slopes M[o][.] of the restriction w -> d^(ou+ov) f(u, v, w)/du^ou dv^ov of a 3D
   term ((ou, ov) = D3[o], total order <= nd) for the w-nodes j0..j1 (at most 3), from the u- and v-bases */
static HM_ALWAYS_INLINE void F(SliceW3)(const hylcmat_term3d *sp, const F(Basis) * Bu, const F(Basis) * Bv, int j0, int j1, int nd, R P[6][3], R M[6][3])
{
  const int no = nd == 0 ? 1 : nd == 1 ? 3 : 6;
  for (int j = j0; j <= j1; j++)
    for (int o = 0; o < no; o++) {
      const int ou = F(D3)[o][0], ov = F(D3)[o][1];
      R         pv = 0, pw = 0;
      for (int f = 0; f < 2; f++)
        for (int e = 0; e < 2; e++) {
          const int k  = (j * sp->nv + Bv->i + f) * sp->nu + Bu->i + e;
          const R   au = Bu->a[ou][e], bu = Bu->b[ou][e], av = Bv->a[ov][f], bv = Bv->b[ov][f];
          pv += au * av * sp->p[k] + bu * av * sp->mu[k] + au * bv * sp->mv[k] + bu * bv * sp->muv[k];
          pw += au * av * sp->mw[k] + bu * av * sp->muw[k] + au * bv * sp->mvw[k] + bu * bv * sp->muvw[k];
        }
      P[o][j - j0] = pv;
      M[o][j - j0] = pw;
    }
}

/* f[o][r] = d^r/dw^r of the restriction o (F(D3)) of a 3D term at w, orders up to nd in total */
static HM_ALWAYS_INLINE void F(Eval3DW)(const hylcmat_term3d *sp, const F(Basis) * Bu, const F(Basis) * Bv, double ihw, R w, int nd, R f[6][3])
{
  F(Basis)
  Bw;
  R         P[6][3], M[6][3];
  const int no = nd == 0 ? 1 : nd == 1 ? 3 : 6;

  F(BasisAt)
  (sp->nw, sp->tw, ihw, sp->ext, w, nd, &Bw);
  F(SliceW3)
  (sp, Bu, Bv, Bw.i, Bw.i + 1, nd, P, M);
  for (int o = 0; o < no; o++)
    for (int r = 0; r <= nd - F(D3)[o][0] - F(D3)[o][1]; r++) f[o][r] = Bw.a[r][0] * P[o][0] + Bw.a[r][1] * P[o][1] + Bw.b[r][0] * M[o][0] + Bw.b[r][1] * M[o][1];
}

/* a 3D bending constituent h(x) = f(u, v, x) at x = a +- s and its (u, v)-derivatives q[o] (o as F(D3), each
   with level minus its order a-derivatives), as F(Quot2D) */
static HM_ALWAYS_INLINE void F(Quot3D)(const hylcmat_term3d *sp, double sw, double ihw, const F(Basis) * Bu, const F(Basis) * Bv, R a, R s, int level, F(Quot) q[6])
{
  const int no = level == 0 ? 1 : level == 1 ? 3 : 6;
  R         fp[6][3], fm[6][3];

  if (s < sw) {
    const R   ss = s < S_TINY ? 0 : s;
    const int L = F(Loc)(sp->nw, sp->tw, ihw, a - ss), Rp = F(Loc)(sp->nw, sp->tw, ihw, a + ss);
    if (Rp - L <= 1) {
      const int j0 = HM_MAX(L, 0), j1 = HM_MIN(Rp + 1, sp->nw - 1);
      R         P[6][3], M[6][3];
      F(SliceW3)
      (sp, Bu, Bv, j0, j1, level, P, M);
      for (int o = 0; o < no; o++) F(QuotPieces)
      (sp->nw, sp->tw, P[o], M[o], j0, sp->ext, L, Rp, a, ss, level - F(D3)[o][0] - F(D3)[o][1], &q[o]);
      return;
    }
  }
  F(Eval3DW)
  (sp, Bu, Bv, ihw, a + s, level, fp);
  F(Eval3DW)
  (sp, Bu, Bv, ihw, a - s, level, fm);
  for (int o = 0; o < no; o++) {
    const int lev   = level - F(D3)[o][0] - F(D3)[o][1];
    const R   hp[3] = {fp[o][0], lev > 0 ? fp[o][1] : 0, lev > 1 ? fp[o][2] : 0};
    const R   hm[3] = {fm[o][0], lev > 0 ? fm[o][1] : 0, lev > 1 ? fm[o][2] : 0};
    F(QuotDirect)
    (s, hp, hm, lev, &q[o]);
  }
}

/* adds a constituent in table units to T in physical units: sg = +1 (x-bending f) or -1 (y-bending g),
   is = 1/sigma of its bending coordinate, f = the factor of its u-derivative order (1, 1/sigma_i, 1/sigma_i^2).
   The P-type part P, P_A, P_AA, P_w = Q_a/2, P_Aw = Q_aa/2, P_ww = W2/2 is the same for f and g; the
   Q-type part Q, Q_A, Q_AA, Q_w, Q_Aw, Q_ww carries the sign. */
static inline void F(Add)(F(Bend) * T, const F(Quot) * q, R sg, R is, R f, int nd)
{
  const R is2 = is * is, is3 = is2 * is, fs = f * sg;

  T->P += f * q->P;
  T->Q += fs * q->Q * is;
  if (nd < 1) return;
  T->PA += f * q->Pa * is;
  T->Pw += f * 0.5 * q->Qa * is2;
  T->QA += fs * q->Qa * is2;
  T->Qw += fs * q->W1 * is3;
  if (nd < 2) return;
  {
    const R is4 = is2 * is2, is5 = is4 * is;
    T->PAA += f * q->Paa * is2;
    T->PAw += f * 0.5 * q->Qaa * is3;
    T->Pww += f * 0.5 * q->W2 * is4;
    T->QAA += fs * q->Qaa * is3;
    T->QAw += fs * q->W2 * is4;
    T->Qww += fs * q->W3 * is5;
  }
}

/* S = sqrt(B^2 + C^2) without overflow or underflow of the squares (the plain form in the range where
   it is exact to rounding, so ordinary strains give the same bits as before) */
static inline R F(Hypot)(R B, R C)
{
  const R b = B < 0 ? -B : B, c = C < 0 ? -C : C, mx = b > c ? b : c;

  if (mx == 0) return 0;
  if (mx > 1e-150 && mx < 1e150) return SQRT(B * B + C * C);
  {
    const R x = B / mx, y = C / mx;
    return mx * SQRT(x * x + y * y);
  }
}

/* Psi, and (level >= 1) its gradient g, (level 2) its Hessian hess (6x6, row-major) at s, in R; inlined
   into one copy per level (F(Evaluate) below), so the loops over derivative orders are fixed */
static HM_ALWAYS_INLINE void F(EvaluateLevel)(const hylcmat *m, const double s[6], int level, R *psi, R grad[6], R hess[36])
{
  const R is[5] = {1 / (R)m->scale[0], 1 / (R)m->scale[1], 1 / (R)m->scale[2], 1 / (R)m->scale[3], 1 / (R)m->scale[4]};
  const R X[3]  = {s[0] * is[0], s[1] * is[1], s[2] * is[2]};
  /* halves first: (s3 + s5) / 2 overflows for strains near the largest double */
  const R A = 0.5 * (R)s[3] + 0.5 * (R)s[5], B = 0.5 * (R)s[3] - 0.5 * (R)s[5], C = s[4], S = F(Hypot)(B, C);
  R       E = m->C0, g[6] = {0, 0, 0, 0, 0, 0}, H[6][6];
  F(Bend)
  T0, Tu[3], Tuu[3], Tm[3]; /* Tm[i + j - 1]: the mixed (i, j) in-plane derivative of the 3D bending terms */
  F(Basis)
  Bq[HYLCMAT_N2D]; /* the pairs' u-bases (a pair with m->ushare[q] >= 0 uses that one's) */

  /* zeroed as far as the level uses them (Add touches P, Q at nd = 0, + PA, Pw, QA, Qw at nd = 1) */
  if (level > 1) {
    memset(&T0, 0, sizeof(T0));
    memset(Tu, 0, sizeof(Tu));
    memset(H, 0, sizeof(H));
    memset(Tuu, 0, sizeof(Tuu));
    memset(Tm, 0, sizeof(Tm));
  } else {
    T0.P = T0.Q = T0.PA = T0.Pw = T0.QA = T0.Qw = 0;
    for (int i = 0; i < 3; i++) Tu[i].P = Tu[i].Q = 0;
  }
  /* in-plane: 1D terms and the pairs (0,1) (0,2) (1,2) */
  for (int k = 0; k < 3; k++) {
    R f[3];
    if (!m->has1[k]) continue;
    F(Eval1D)
    (&m->t1[k], m->ih1[k], X[k], level, f);
    E += f[0];
    if (level) g[k] += f[1] * is[k];
    if (level > 1) H[k][k] += f[2] * is[k] * is[k];
  }
  for (int q = 0; q < HYLCMAT_N2D; q++) {
    const int             i = HylcmatPairs[q][0], j = HylcmatPairs[q][1];
    const hylcmat_term2d *sp = &m->t2[q];
    const F(Basis) * Bu;
    R f[3][3];
    if (j > 2 || !m->has2[q]) continue;
    if (m->ushare[q] >= 0)
      Bu = &Bq[m->ushare[q]];
    else {
      F(BasisAt)
      (sp->nu, sp->tu, m->ihu[q], sp->ext, X[i], level, &Bq[q]);
      Bu = &Bq[q];
    }
    F(Eval2D)
    (sp, Bu, m->ihv[q], X[j], level, f);
    E += f[0][0];
    if (level) {
      g[i] += f[1][0] * is[i];
      g[j] += f[0][1] * is[j];
    }
    if (level > 1) {
      H[i][i] += f[2][0] * is[i] * is[i];
      H[i][j] += f[1][1] * is[i] * is[j];
      H[j][j] += f[0][2] * is[j] * is[j];
    }
  }
  /* bending: the 1D terms 3 (f, x) and 4 (g, y), and the pairs (i, 3), (i, 4) */
  for (int k = 3; k < 5; k++) {
    F(Quot)
    q;
    if (!m->has1[k]) continue;
    F(Quot1D)
    (&m->t1[k], m->sw1[k], m->ih1[k], A * is[k], S * is[k], level, &q);
    F(Add)
    (&T0, &q, k == 3 ? 1 : -1, is[k], 1, level);
  }
  for (int r = 0; r < HYLCMAT_N2D; r++) {
    const int i = HylcmatPairs[r][0], k = HylcmatPairs[r][1];
    F(Quot)
    q[3];
    const F(Basis) * Bu;
    if (k < 3 || !m->has2[r]) continue;
    if (m->ushare[r] >= 0)
      Bu = &Bq[m->ushare[r]];
    else {
      F(BasisAt)
      (m->t2[r].nu, m->t2[r].tu, m->ihu[r], m->t2[r].ext, X[i], level, &Bq[r]);
      Bu = &Bq[r];
    }
    F(Quot2D)
    (&m->t2[r], m->sw2[r], m->ihv[r], Bu, A * is[k], S * is[k], level, q);
    F(Add)
    (&T0, &q[0], k == 3 ? 1 : -1, is[k], 1, level);
    if (level) F(Add)
    (&Tu[i], &q[1], k == 3 ? 1 : -1, is[k], is[i], level - 1);
    if (level > 1) F(Add)
    (&Tuu[i], &q[2], k == 3 ? 1 : -1, is[k], is[i] * is[i], 0);
  }
  /* hylc's 3D terms: (sx, sa, sy) in-plane, the in-plane pairs with II00 and with II11 through the eigen-split */
  for (int r = 0; r < HYLCMAT_N3D; r++) {
    const hylcmat_term3d *sp = &m->t3[r];
    const int             i = HylcTripleCoords[r][0], j = HylcTripleCoords[r][1], k = HylcTripleCoords[r][2];
    F(Basis)
    Bu, Bv;
    if (!m->has3[r]) continue;
    F(BasisAt)
    (sp->nu, sp->tu, m->ihu3[r], sp->ext, X[i], level, &Bu);
    F(BasisAt)
    (sp->nv, sp->tv, m->ihv3[r], sp->ext, X[j], level, &Bv);
    if (k < 3) {
      R f[6][3];
      F(Eval3DW)
      (sp, &Bu, &Bv, m->ihw3[r], X[k], level, f);
      E += f[0][0];
      if (level) {
        g[i] += f[1][0] * is[i];
        g[j] += f[2][0] * is[j];
        g[k] += f[0][1] * is[k];
      }
      if (level > 1) {
        H[i][i] += f[3][0] * is[i] * is[i];
        H[i][j] += f[4][0] * is[i] * is[j];
        H[j][j] += f[5][0] * is[j] * is[j];
        H[i][k] += f[1][1] * is[i] * is[k];
        H[j][k] += f[2][1] * is[j] * is[k];
        H[k][k] += f[0][2] * is[k] * is[k];
      }
    } else {
      const int kb = k == 3 ? 3 : 4; /* the bending coordinate's index among the scales */
      const R   sg = k == 3 ? 1 : -1;
      F(Quot)
      q[6];
      F(Quot3D)
      (sp, m->sw3[r], m->ihw3[r], &Bu, &Bv, A * is[kb], S * is[kb], level, q);
      F(Add)
      (&T0, &q[0], sg, is[kb], 1, level);
      if (level) {
        F(Add)
        (&Tu[i], &q[1], sg, is[kb], is[i], level - 1);
        F(Add)
        (&Tu[j], &q[2], sg, is[kb], is[j], level - 1);
      }
      if (level > 1) {
        F(Add)
        (&Tuu[i], &q[3], sg, is[kb], is[i] * is[i], 0);
        F(Add)
        (&Tm[i + j - 1], &q[4], sg, is[kb], is[i] * is[j], 0);
        F(Add)
        (&Tuu[j], &q[5], sg, is[kb], is[j] * is[j], 0);
      }
    }
  }
  E += T0.P + B * T0.Q;
  if (level) {
    const R EA = T0.PA + B * T0.QA, EB = 2 * B * T0.Pw + T0.Q + 2 * B * B * T0.Qw, EC = 2 * C * T0.Pw + 2 * B * C * T0.Qw;
    g[3] += 0.5 * (EA + EB);
    g[5] += 0.5 * (EA - EB);
    g[4] += EC;
    for (int i = 0; i < 3; i++) g[i] += Tu[i].P + B * Tu[i].Q;
  }
  if (level > 1) {
    const R B2 = B * B, EAA = T0.PAA + B * T0.QAA, EAB = 2 * B * T0.PAw + T0.QA + 2 * B2 * T0.QAw, EAC = 2 * C * (T0.PAw + B * T0.QAw);
    const R EBB = 2 * T0.Pw + 4 * B2 * T0.Pww + 6 * B * T0.Qw + 4 * B2 * B * T0.Qww;
    const R EBC = C * (4 * B * T0.Pww + 2 * T0.Qw + 4 * B2 * T0.Qww);
    const R ECC = 2 * T0.Pw + 4 * C * C * T0.Pww + 2 * B * T0.Qw + 4 * B * C * C * T0.Qww;
    H[3][3] += 0.25 * (EAA + 2 * EAB + EBB);
    H[3][5] += 0.25 * (EAA - EBB);
    H[5][5] += 0.25 * (EAA - 2 * EAB + EBB);
    H[3][4] += 0.5 * (EAC + EBC);
    H[4][5] += 0.5 * (EAC - EBC);
    H[4][4] += ECC;
    for (int i = 0; i < 3; i++) {
      const F(Bend) *t = &Tu[i];
      const R EuA = t->PA + B * t->QA, EuB = 2 * B * t->Pw + t->Q + 2 * B2 * t->Qw, EuC = 2 * C * (t->Pw + B * t->Qw);
      H[i][3] += 0.5 * (EuA + EuB);
      H[i][5] += 0.5 * (EuA - EuB);
      H[i][4] += EuC;
      H[i][i] += Tuu[i].P + B * Tuu[i].Q;
    }
    for (int i = 0; i < 2; i++)
      for (int j = i + 1; j < 3; j++) H[i][j] += Tm[i + j - 1].P + B * Tm[i + j - 1].Q;
    for (int i = 0; i < 6; i++)
      for (int j = 0; j < 6; j++) hess[6 * i + j] = i <= j ? H[i][j] : H[j][i];
  }
  *psi = E;
  if (level)
    for (int i = 0; i < 6; i++) grad[i] = g[i];
}

static void F(Evaluate0)(const hylcmat *m, const double s[6], R *psi, R grad[6], R hess[36]) { F(EvaluateLevel)(m, s, 0, psi, grad, hess); }
static void F(Evaluate1)(const hylcmat *m, const double s[6], R *psi, R grad[6], R hess[36]) { F(EvaluateLevel)(m, s, 1, psi, grad, hess); }
static void F(Evaluate2)(const hylcmat *m, const double s[6], R *psi, R grad[6], R hess[36]) { F(EvaluateLevel)(m, s, 2, psi, grad, hess); }

static void F(Evaluate)(const hylcmat *m, const double s[6], int level, R *psi, R grad[6], R hess[36])
{
  if (level == 0)
    F(Evaluate0)(m, s, psi, grad, hess);
  else if (level == 1)
    F(Evaluate1)(m, s, psi, grad, hess);
  else
    F(Evaluate2)(m, s, psi, grad, hess);
}
