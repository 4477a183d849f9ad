/* Macro kernels: A = sqrt(I) upper triangular with A^T A = I, strain validation, lambda_min, N = -A^{-T} II,
   the robust scalar functions against long double references, R(xi) orthonormal and equal to exp(W)
   (long double Taylor reference), R - I accurate for tiny strains, dR/dxi against finite differences,
   and the closed-form midsurface: grad phi = R S by finite differences, n . phi_,alpha = 0,
   n_,alpha = R N_{:,alpha}, the exact cylinder and the sign convention (II00 > 0 bends toward +n).
   HYLC_TEST_VERBOSE=1 prints the measured errors. */
#include <hylc/macro.h>
#include <stdlib.h>
#include "hylctest.h"

static double Uniform(unsigned long long *st, double lo, double hi) { return lo + (hi - lo) * HylcTestRand(st); }

static void RandomStrain(unsigned long long *st, double bend, double z[6])
{
  z[0] = Uniform(st, -0.5, 1.0);
  z[1] = Uniform(st, -0.9, 0.9);
  z[2] = Uniform(st, -0.5, 1.0);
  z[3] = Uniform(st, -bend, bend);
  z[4] = Uniform(st, -bend, bend);
  z[5] = Uniform(st, -bend, bend);
}

/* exp(W(a, b)) in long double: scaling and squaring with a 30-term Taylor series */
static void ExpWLong(long double a, long double b, long double E[9])
{
  long double W[9] = {0, 0, a, 0, 0, b, -a, -b, 0}, T[9], P[9];
  int         k    = 0;
  long double r    = sqrtl(a * a + b * b);
  while (r > 0.25L) r *= 0.5L, k++;
  for (int i = 0; i < 9; i++) W[i] = ldexpl(W[i], -k);
  for (int i = 0; i < 9; i++) E[i] = (i % 4 == 0) ? 1 : 0, T[i] = E[i];
  for (int n = 1; n <= 30; n++) {
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        long double s = 0;
        for (int l = 0; l < 3; l++) s += T[3 * i + l] * W[3 * l + j];
        P[3 * i + j] = s / n;
      }
    for (int i = 0; i < 9; i++) T[i] = P[i], E[i] += P[i];
  }
  for (int q = 0; q < k; q++) {
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        long double s = 0;
        for (int l = 0; l < 3; l++) s += E[3 * i + l] * E[3 * l + j];
        P[3 * i + j] = s;
      }
    for (int i = 0; i < 9; i++) E[i] = P[i];
  }
}

static void TestStrain(unsigned long long *st)
{
  double errAtA = 0;
  for (int t = 0; t < 1000; t++) {
    double z[6], I1[4], A[4], S[6], N[4];
    RandomStrain(st, 3.0, z);
    HYLC_CHECK(HylcMacroStrainValidate(z) == HYLC_MACRO_STRAIN_OK, "z valid");
    HylcMacroFirstForm(z, I1);
    HylcMacroSqrtFirstForm(z, A);
    HylcMacroStretchMatrix(z, S);
    HylcMacroNormalDerivatives(z, N);
    HYLC_CHECK(A[2] == 0, "A upper triangular");
    HYLC_CHECK(A[0] > 0 && A[3] > 0, "A has a positive diagonal");
    for (int i = 0; i < 2; i++)
      for (int j = 0; j < 2; j++) {
        const double AtA = A[i] * A[j] + A[2 + i] * A[2 + j];
        errAtA           = fmax(errAtA, fabs(AtA - I1[2 * i + j]) / fmax(fabs(I1[0]), fabs(I1[3])));
        HYLC_CHECK(S[2 * i + j] == A[2 * i + j], "S = [A; 0]");
      }
    HYLC_CHECK(S[4] == 0 && S[5] == 0, "S third row 0");
    /* lambda_min against the textbook formula */
    const double tr = I1[0] + I1[3], det = I1[0] * I1[3] - I1[1] * I1[2];
    const double lm = 0.5 * (tr - sqrt(tr * tr - 4 * det));
    HYLC_CHECK_CLOSE(HylcMacroLambdaMin(z), lm, 1e-12 * tr);
    /* A^T N = -II */
    const double II[4] = {z[3], z[4], z[4], z[5]};
    for (int al = 0; al < 2; al++)
      for (int be = 0; be < 2; be++) HYLC_CHECK_CLOSE(A[al] * N[be] + A[2 + al] * N[2 + be], -II[2 * al + be], 1e-13);
  }
  HYLC_CHECK(errAtA <= 1e-14, "max |A^T A - I| / |I| = %.3e", errAtA);
  if (getenv("HYLC_TEST_VERBOSE")) printf("strain: max |A^T A - I|/|I| = %.3e\n", errAtA);

  /* lambda_min is accurate for nearly degenerate shear */
  {
    const double z[6] = {0, 1 - 1e-12, 0, 0, 0, 0};
    HYLC_CHECK_REL(HylcMacroLambdaMin(z), 1 - z[1], 1e-12); /* eigenvalues 1 +- sa */
  }
  /* validation */
  const double               bad[5][6] = {{0, 1, 0, 0, 0, 0}, {0, -1.5, 0, 0, 0, 0}, {-1, 0, 0, 0, 0, 0}, {0, 0, -1.2, 0, 0, 0}, {0, 0, 0, NAN, 0, 0}};
  const HylcMacroStrainError want[5]   = {HYLC_MACRO_STRAIN_SHEAR, HYLC_MACRO_STRAIN_SHEAR, HYLC_MACRO_STRAIN_STRETCH_X, HYLC_MACRO_STRAIN_STRETCH_Y, HYLC_MACRO_STRAIN_NONFINITE};
  for (int k = 0; k < 5; k++) {
    HylcMacroStrain m;
    HYLC_CHECK(HylcMacroStrainValidate(bad[k]) == want[k], "bad strain %d", k);
    HYLC_CHECK(HylcMacroStrainSetUp(bad[k], 0, &m) == want[k], "bad strain %d (setup)", k);
    HYLC_CHECK(HylcMacroStrainErrorString(want[k])[0] != 0, "message");
  }
  /* classification */
  {
    double       H, d[2];
    const double flat[3] = {0, 0, 0}, x[3] = {2, 0, 0}, y[3] = {0, 0, -3}, dbl[3] = {1, 0, 1};
    const double th = 0.7, rot[3] = {1.5 * cos(th) * cos(th), 1.5 * cos(th) * sin(th), 1.5 * sin(th) * sin(th)};
    HYLC_CHECK(HylcMacroClassifyII(flat, 0, &H, d) == HYLC_MACRO_FLAT, "flat");
    HYLC_CHECK(HylcMacroClassifyII(x, 0, &H, d) == HYLC_MACRO_SINGLY && H == 2 && d[0] == 1 && d[1] == 0, "II00 only: H %g d %g %g", H, d[0], d[1]);
    HYLC_CHECK(HylcMacroClassifyII(y, 0, &H, d) == HYLC_MACRO_SINGLY && H == -3 && d[0] == 0 && d[1] == 1, "II11 only: H %g d %g %g", H, d[0], d[1]);
    HYLC_CHECK(HylcMacroClassifyII(dbl, 0, &H, d) == HYLC_MACRO_DOUBLY, "doubly");
    HYLC_CHECK(HylcMacroClassifyII(rot, 0, &H, d) == HYLC_MACRO_SINGLY, "rotated");
    HYLC_CHECK_CLOSE(H, 1.5, 1e-15);
    HYLC_CHECK_CLOSE(d[0], cos(th), 1e-15);
    HYLC_CHECK_CLOSE(d[1], sin(th), 1e-15);
  }
}

static void TestScalars(void)
{
  const double xs[]  = {0, 1e-300, 1e-13, 1e-9, 1e-5, 9.99e-5, 1e-4, 1.01e-4, 1e-3, 0.1, 0.5, 0.999, 1.0, 1.001, 2, 3.14, 7.5, 30};
  double       worst = 0;
  for (size_t k = 0; k < sizeof(xs) / sizeof(xs[0]); k++) {
    const long double x = xs[k], x2 = x * x;
    long double       sinc, s2, g, e1, e2;
    if (x < 2) {                /* long double Taylor series, 30 terms */
      long double t = 1, c = 1; /* t = x^(2k) */
      sinc = s2 = g = e1 = e2 = 0;
      for (int k = 0; k < 30; k++) {
        long double f1 = 1, f2 = 1; /* (2k+1)!, (2k+2)! */
        for (int j = 2; j <= 2 * k + 1; j++) f1 *= j;
        f2 = f1 * (2 * k + 2);
        sinc += c * t / f1;                                                /* sum (-1)^k x^2k / (2k+1)! */
        s2 += 2 * c * t / f2;                                              /* 2 (1 - cos x)/x^2 = sum 2 (-1)^k x^2k / (2k+2)! */
        g += c * t / (f1 * (2 * k + 2) * (2 * k + 3));                     /* sum (-1)^k x^2k / (2k+3)! */
        e1 += -c * (2 * k + 2) * t / (f2 * (2 * k + 3));                   /* sum_{k>=1} (-1)^k 2k x^(2k-2) / (2k+1)!, shifted */
        e2 += -2 * c * (2 * k + 2) * t / (f2 * (2 * k + 3) * (2 * k + 4)); /* sum_{k>=2} 2 (-1)^(k+1) (2k-2) x^(2k-4) / (2k)!, shifted */
        t *= x2;
        c = -c;
      }
    } else {
      sinc = sinl(x) / x;
      s2   = 2 * (1 - cosl(x)) / x2;
      g    = (1 - sinc) / x2;
      e1   = (cosl(x) - sinc) / x2;
      e2   = 2 * (sinc - s2) / x2;
    }
    const double      got[5] = {HylcMacroSinc(xs[k]), HylcMacroSinc2Half(xs[k]), HylcMacroG(xs[k]), HylcMacroSincPrimeOverR(xs[k]), HylcMacroSinc2HalfPrimeOverR(xs[k])};
    const long double ref[5] = {sinc, s2, g, e1, e2};
    for (int f = 0; f < 5; f++) {
      const double rel = (double)fabsl((got[f] - ref[f]) / ref[f]);
      worst            = fmax(worst, rel);
      HYLC_CHECK(rel <= 1e-14, "function %d at x = %g: %.17g vs %.17Lg (rel %.2e)", f, xs[k], got[f], ref[f], rel);
    }
  }
  if (getenv("HYLC_TEST_VERBOSE")) printf("scalars: worst relative error %.3e\n", worst);
}

static void TestRotation(unsigned long long *st)
{
  double orth = 0, expErr = 0, dErr = 0, dScale = 0;
  for (int t = 0; t < 2000; t++) {
    double       z[6], N[4], R[9], D[9], dR[18];
    const double bend = (t % 3 == 0) ? 0.1 : (t % 3 == 1 ? 2.0 : 8.0); /* up to several full turns */
    RandomStrain(st, bend, z);
    HylcMacroNormalDerivatives(z, N);
    const double xi[2] = {Uniform(st, -1.5, 1.5), Uniform(st, -1.5, 1.5)};
    HylcMacroRotation(N, xi, R, D, dR);
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        double s = 0;
        for (int l = 0; l < 3; l++) s += R[3 * l + i] * R[3 * l + j];
        orth = fmax(orth, fabs(s - (i == j)));
      }
    const double det = R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) + R[2] * (R[3] * R[7] - R[4] * R[6]);
    HYLC_CHECK_CLOSE(det, 1.0, 1e-14);
    for (int k = 0; k < 9; k++) HYLC_CHECK(D[k] == R[k] - (k % 4 == 0) || fabs(D[k] - (R[k] - (k % 4 == 0))) <= 4e-16, "D = R - I");
    /* exp(W) in long double */
    const double a = N[0] * xi[0] + N[1] * xi[1], b = N[2] * xi[0] + N[3] * xi[1];
    if (hypot(a, b) < 40) {
      long double E[9];
      ExpWLong(a, b, E);
      for (int k = 0; k < 9; k++) expErr = fmax(expErr, (double)fabsl(R[k] - E[k]));
    }
    /* dR/dxi against central differences */
    for (int al = 0; al < 2; al++) {
      const double h     = 1e-6;
      double       xp[2] = {xi[0], xi[1]}, xm[2] = {xi[0], xi[1]}, Rp[9], Rm[9];
      xp[al] += h;
      xm[al] -= h;
      HylcMacroRotation(N, xp, Rp, NULL, NULL);
      HylcMacroRotation(N, xm, Rm, NULL, NULL);
      const double nN = fabs(N[al]) + fabs(N[2 + al]);
      for (int k = 0; k < 9; k++) dErr = fmax(dErr, fabs((Rp[k] - Rm[k]) / (2 * h) - dR[9 * al + k]) / fmax(nN, 1e-300));
      dScale = fmax(dScale, nN);
    }
  }
  HYLC_CHECK(orth <= 1e-14, "max |R^T R - I| = %.3e", orth);
  HYLC_CHECK(expErr <= 1e-14, "max |R - exp(W)| = %.3e", expErr);
  HYLC_CHECK(dErr <= 1e-7, "max |dR/dxi - FD| / |N| = %.3e", dErr);
  if (getenv("HYLC_TEST_VERBOSE")) printf("rotation: max |R^T R - I| = %.3e, max |R - exp W| = %.3e, dR/dxi FD rel err %.3e\n", orth, expErr, dErr);

  /* R -> I for tiny strains without loss of precision: R - I against long double */
  double       tinyErr  = 0;
  const double scales[] = {1e-5, 1e-9, 1e-13, 1e-100, 1e-200};
  for (size_t sc = 0; sc < sizeof(scales) / sizeof(scales[0]); sc++) {
    for (int t = 0; t < 200; t++) {
      double z[6], N[4], D[9], dR[18];
      RandomStrain(st, 1.0, z);
      for (int k = 3; k < 6; k++) z[k] *= scales[sc];
      HylcMacroNormalDerivatives(z, N);
      const double xi[2] = {Uniform(st, -1, 1), Uniform(st, -1, 1)};
      HylcMacroRotation(N, xi, NULL, D, dR);
      const long double a = N[0] * xi[0] + N[1] * xi[1], b = N[2] * xi[0] + N[3] * xi[1]; /* the same a, b */
      const long double r = sqrtl(a * a + b * b), h = r / 2;
      const long double c1 = r < 1e-6L ? 1 - r * r / 6 : sinl(r) / r, sh = h < 1e-6L ? 1 - h * h / 6 : sinl(h) / h, c2 = sh * sh;
      const long double ref[9] = {-a * a * c2 / 2, -a * b * c2 / 2, a * c1, -a * b * c2 / 2, -b * b * c2 / 2, b * c1, -a * c1, -b * c1, -r * r * c2 / 2};
      for (int k = 0; k < 9; k++) {
        if (ref[k] == 0) continue;
        if (fabsl(ref[k]) < 1e-290L) continue; /* subnormal range */
        tinyErr = fmax(tinyErr, (double)fabsl((D[k] - ref[k]) / ref[k]));
      }
      /* off-diagonals of R itself carry the rotation at full precision */
    }
  }
  HYLC_CHECK(tinyErr <= 8e-16, "max relative error of R - I for tiny strains = %.3e", tinyErr);
  if (getenv("HYLC_TEST_VERBOSE")) printf("rotation: tiny strains (1e-5..1e-200) max rel err of R - I = %.3e\n", tinyErr);
  (void)dScale;
}

/* grad phi = R S (FD), n . phi_,alpha = 0, n_,alpha = R N_{:,alpha} for one singly curved strain */
static void CheckClosed(const char *what, const double z[6], unsigned long long *st, double *worstFD, double *worstOrth, double *worstDn, double *worstDnFD)
{
  HylcMacroStrain m;
  HYLC_CHECK(HylcMacroStrainSetUp(z, 0, &m) == HYLC_MACRO_STRAIN_OK, "%s: setup", what);
  HYLC_CHECK(m.curvature != HYLC_MACRO_DOUBLY, "%s: singly curved", what);
  double phi0[3];
  HYLC_CHECK(HylcMacroClosedPhi(&m, (double[2]){0, 0}, phi0, NULL, NULL) == 0, "%s", what);
  for (int i = 0; i < 3; i++) HYLC_CHECK(phi0[i] == 0, "%s: phi(0) = 0", what);
  for (int t = 0; t < 200; t++) {
    const double xi[2] = {Uniform(st, -2, 2), Uniform(st, -2, 2)};
    double       phi[3], n[3], dphi[6], R[9], dn[6], nn[3];
    HylcMacroClosedPhi(&m, xi, phi, n, dphi);
    HylcMacroRotation(m.N, xi, R, NULL, NULL);
    HylcMacroNormal(m.N, xi, nn, dn);
    for (int i = 0; i < 3; i++) HYLC_CHECK(n[i] == nn[i], "%s: n", what);
    for (int al = 0; al < 2; al++) {
      const double h     = 1e-5;
      double       xp[2] = {xi[0], xi[1]}, xm[2] = {xi[0], xi[1]}, pp[3], pm[3], np[3], nm[3];
      xp[al] += h;
      xm[al] -= h;
      HylcMacroClosedPhi(&m, xp, pp, np, NULL);
      HylcMacroClosedPhi(&m, xm, pm, nm, NULL);
      double colnorm = 0, dot = 0;
      for (int i = 0; i < 3; i++) {
        const double RS = R[3 * i] * m.S[al] + R[3 * i + 1] * m.S[2 + al];
        colnorm += RS * RS;
      }
      colnorm = sqrt(colnorm);
      for (int i = 0; i < 3; i++) {
        const double RS = R[3 * i] * m.S[al] + R[3 * i + 1] * m.S[2 + al];
        const double fd = (pp[i] - pm[i]) / (2 * h);
        *worstFD        = fmax(*worstFD, fabs(fd - RS) / colnorm);
        HYLC_CHECK(fabs(dphi[2 * i + al] - RS) <= 1e-14 * colnorm, "%s: dphi output", what);
        dot += n[i] * fd;
        /* n_,alpha = R (N_{0 alpha}, N_{1 alpha}, 0) */
        const double RN = R[3 * i] * m.N[al] + R[3 * i + 1] * m.N[2 + al];
        const double sc = fabs(m.N[al]) + fabs(m.N[2 + al]) + 1e-300;
        *worstDn        = fmax(*worstDn, fabs(dn[3 * al + i] - RN) / sc);
        *worstDnFD      = fmax(*worstDnFD, fabs((np[i] - nm[i]) / (2 * h) - RN) / sc);
      }
      *worstOrth = fmax(*worstOrth, fabs(dot) / colnorm);
    }
    /* x = phi + h n */
    double x[3], xn[3];
    HylcMacroClosedPosition(&m, xi, 0.3, x, xn);
    for (int i = 0; i < 3; i++) HYLC_CHECK_CLOSE(x[i], phi[i] + 0.3 * n[i], 1e-15);
  }
}

static void TestClosed(unsigned long long *st)
{
  double       fd = 0, orth = 0, dn = 0, dnfd = 0;
  const double th = 0.4, H = 1.3;
  const double cases[][6] = {
      {0.1, 0.0, -0.1, 1.2, 0, 0},                                                           /* II00 only */
      {0.1, 0.4, -0.1, -1.7, 0, 0},                                                          /* II00 only, sheared */
      {-0.2, -0.5, 0.3, 0, 0, 2.1},                                                          /* II11 only, sheared */
      {0.05, 0.3, 0.2, H * cos(th) * cos(th), H * cos(th) * sin(th), H * sin(th) * sin(th)}, /* rotated d */
      {0.0, 0.0, 0.0, 1e-9, 0, 0},                                                           /* tiny bending */
      {0.3, 0.2, -0.1, 0, 0, 0},                                                             /* flat */
  };
  for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
    char name[32];
    snprintf(name, sizeof(name), "closed case %d", (int)k);
    CheckClosed(name, cases[k], st, &fd, &orth, &dn, &dnfd);
  }
  HYLC_CHECK(fd <= 1e-8, "closed form: max |FD grad phi - R S| / |R S| = %.3e", fd);
  HYLC_CHECK(orth <= 1e-8, "closed form: max |n . phi_,alpha| = %.3e", orth);
  HYLC_CHECK(dn <= 1e-14, "closed form: max |dn/dxi_alpha - R N_alpha| / |N_alpha| = %.3e", dn);
  HYLC_CHECK(dnfd <= 1e-8, "closed form: max |FD n_,alpha - R N_alpha| / |N_alpha| = %.3e", dnfd);
  if (getenv("HYLC_TEST_VERBOSE")) printf("closed form: grad phi FD rel err %.3e, |n.phi_a| %.3e, n_,a vs R N: analytic %.3e, FD %.3e\n", fd, orth, dn, dnfd);

  /* exact cylinder: z = (0,0,0,H,0,0): phi = (sin(H s)/H, xi2, (1 - cos(H s))/H), n = (-sin, 0, cos) */
  {
    const double    z[6] = {0, 0, 0, 2.0, 0, 0};
    HylcMacroStrain m;
    HylcMacroStrainSetUp(z, 0, &m);
    for (int t = 0; t < 50; t++) {
      const double xi[2] = {Uniform(st, -4, 4), Uniform(st, -1, 1)};
      double       phi[3], n[3];
      HylcMacroClosedPhi(&m, xi, phi, n, NULL);
      HYLC_CHECK_CLOSE(phi[0], sin(2 * xi[0]) / 2, 1e-15);
      HYLC_CHECK_CLOSE(phi[1], xi[1], 1e-15);
      HYLC_CHECK_CLOSE(phi[2], (1 - cos(2 * xi[0])) / 2, 1e-15);
      HYLC_CHECK_CLOSE(n[0], -sin(2 * xi[0]), 1e-15);
      HYLC_CHECK_CLOSE(n[1], 0, 1e-15);
      HYLC_CHECK_CLOSE(n[2], cos(2 * xi[0]), 1e-15);
    }
  }
  /* sign convention: II00 = H > 0 bends toward +n: phi3 ~ H xi1^2 / 2 > 0; the same with shear and stretch */
  {
    const double zs[2][6] = {{0, 0, 0, 0.5, 0, 0}, {0.2, 0.5, -0.1, 0.5, 0, 0}};
    for (int k = 0; k < 2; k++) {
      HylcMacroStrain m;
      HylcMacroStrainSetUp(zs[k], 0, &m);
      const double X = 1 + zs[k][0], xi[2] = {1e-3, 0};
      double       phi[3], n[3];
      HylcMacroClosedPhi(&m, xi, phi, n, NULL);
      HYLC_CHECK(phi[2] > 0, "II00 > 0 bends toward +n (phi3 = %g)", phi[2]);
      /* II00 = n . phi_,11 = H, so phi3 ~ H xi1^2 / 2 independently of the in-plane strain */
      HYLC_CHECK_REL(phi[2], 0.5 * 0.5 * xi[0] * xi[0], 1e-5);
      HYLC_CHECK(n[0] < 0 && n[2] > 0, "n tilts back toward -x");
      (void)X;
    }
  }
  /* II00 = n . phi_,11 on a random sheared cylinder (second FD) */
  {
    const double    z[6] = {0.1, 0.4, -0.1, -1.7, 0, 0};
    HylcMacroStrain m;
    HylcMacroStrainSetUp(z, 0, &m);
    const double xi[2] = {0.3, -0.2}, h = 1e-4;
    double       p0[3], pp[3], pm[3], n[3];
    HylcMacroClosedPhi(&m, xi, p0, n, NULL);
    HylcMacroClosedPhi(&m, (double[2]){xi[0] + h, xi[1]}, pp, NULL, NULL);
    HylcMacroClosedPhi(&m, (double[2]){xi[0] - h, xi[1]}, pm, NULL, NULL);
    double II00 = 0;
    for (int i = 0; i < 3; i++) II00 += n[i] * (pp[i] - 2 * p0[i] + pm[i]) / (h * h);
    HYLC_CHECK_REL(II00, -1.7, 1e-6);
  }
}

int main(void)
{
  unsigned long long st = 20200701;
  TestStrain(&st);
  TestScalars();
  TestRotation(&st);
  TestClosed(&st);
  return HYLC_TEST_RESULT();
}
