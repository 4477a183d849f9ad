/* The sampling plan of Algorithm C4: sizes (1 + 5 x 150 + 9 x 50 x 50 = 23,251 with the zero sample),
   SampleRange end points and spacing, the order of samples, term selection. */
#include <hylc/plan.h>
#include "hylctest.h"

int main(void)
{
  HylcPlan p;
  double   Z[150], z[6];
  int      term;

  HYLC_CHECK(HylcPlanDefaults("stockinette", 1.0, &p) == 0, "defaults");
  HYLC_CHECK(HylcPlanSize(&p) == 1 + 5 * 150 + 9 * 2500, "plan size %ld", HylcPlanSize(&p));
  HYLC_CHECK(HylcPlanDefaults("knitwear", 1.0, &p) == -1, "unknown family accepted");
  HylcPlanDefaults("stockinette", 1.0, &p);

  /* sx: end points exact, monotone, denser toward compression */
  HYLC_CHECK(HylcSampleRange(0, -0.5, 0.8, 150, Z) == 0, "sx range");
  HYLC_CHECK(Z[0] == -0.5 && Z[149] == 0.8, "sx end points %g %g", Z[0], Z[149]);
  for (int k = 1; k < 150; k++) HYLC_CHECK(Z[k] > Z[k - 1], "sx not increasing at %d", k);
  HYLC_CHECK(Z[1] - Z[0] < Z[149] - Z[148], "sx spacing should grow toward extension: %g vs %g", Z[1] - Z[0], Z[149] - Z[148]);
  /* (Z + 1)^(1/10) is uniform */
  for (int k = 1; k < 149; k++) HYLC_CHECK_CLOSE(pow(Z[k + 1] + 1, 0.1) - pow(Z[k] + 1, 0.1), pow(Z[1] + 1, 0.1) - pow(Z[0] + 1, 0.1), 1e-12);
  /* sa: symmetric, dense near 0 */
  HYLC_CHECK(HylcSampleRange(1, -0.75, 0.75, 150, Z) == 0, "sa range");
  for (int k = 0; k < 150; k++) HYLC_CHECK_CLOSE(Z[k], -Z[149 - k], 1e-15);
  HYLC_CHECK_CLOSE(Z[0], -0.75, 1e-15);
  HYLC_CHECK(fabs(Z[75] - Z[74]) < fabs(Z[1] - Z[0]), "sa spacing should be finer near 0");
  HYLC_CHECK(HylcSampleRange(0, -1.2, 0.5, 10, Z) == -1, "sx below -1 accepted");
  HYLC_CHECK(HylcSampleRange(1, 0.5, -0.5, 10, Z) == -1, "zmin > zmax accepted");

  /* order: zero sample, the 1D terms, then the 2D terms (first coordinate outer) */
  HYLC_CHECK(HylcPlanSample(&p, 0, z, &term) == 0 && term == 0 && z[0] == 0 && z[3] == 0, "zero sample");
  HylcPlanSample(&p, 1, z, &term);
  HYLC_CHECK(term == 1 && z[0] == -0.5 && z[1] == 0, "first sx sample: term %d, z0 %g", term, z[0]);
  HylcPlanSample(&p, 1 + 4 * 150 + 149, z, &term);
  HYLC_CHECK(term == 5 && z[5] == 230 && z[3] == 0 && z[4] == 0, "last II11 sample: term %d, z5 %g", term, z[5]);
  HylcPlanSample(&p, 1 + 5 * 150 + 2500 + 51, z, &term); /* (sx, sy) term, i = 1, j = 1 */
  HYLC_CHECK(term == 7 && z[0] != 0 && z[2] != 0 && z[1] == 0, "2D (sx, sy) sample: term %d", term);
  HYLC_CHECK(HylcPlanSample(&p, HylcPlanSize(&p), z, &term) == -1, "sample past the end accepted");
  /* every sample lies in its ranges, and II01 is never set */
  for (long k = 0; k < HylcPlanSize(&p); k++) {
    HylcPlanSample(&p, k, z, &term);
    HYLC_CHECK(z[4] == 0, "II01 set at sample %ld", k);
    HYLC_CHECK(z[0] >= -0.5 - 1e-12 && z[0] <= 0.8 + 1e-12 && fabs(z[1]) <= 0.75 + 1e-12, "sample %ld out of range", k);
  }
  /* term selection: only the 1D terms */
  p.terms = 0x3e;
  HYLC_CHECK(HylcPlanSize(&p) == 750, "1D-only plan size %ld", HylcPlanSize(&p));
  HylcPlanSample(&p, 0, z, &term);
  HYLC_CHECK(term == 1, "first sample of a 1D-only plan: term %d", term);
  /* the units of continuation (HylcPlanUnits): every sample exactly once; within a unit one term, one
     varying coordinate, and |z| of it growing outward from the first sample; 1 + 2 per 1D term + 2 n2 per
     2D term units for the stockinette ranges (every axis has samples on both sides of zero) */
  HylcPlanDefaults("stockinette", 1.0, &p);
  p.n1 = 30;
  p.n2 = 10;
  {
    const long N = HylcPlanSize(&p), nu = HylcPlanUnits(&p, NULL, NULL);
    long       start[256], order[1200];
    int        seen[1200] = {0};
    HYLC_CHECK(N == 1051 && nu == 1 + 5 * 2 + 9 * 2 * 10, "thinned plan: %ld samples, %ld units", N, nu);
    HYLC_CHECK(HylcPlanUnits(&p, start, order) == nu && start[0] == 0 && start[nu] == N, "unit offsets");
    for (long i = 0; i < N; i++) seen[order[i]]++;
    for (long k = 0; k < N; k++) HYLC_CHECK(seen[k] == 1, "sample %ld is in %d units", k, seen[k]);
    for (long u = 0; u < nu; u++) {
      double z0[6], z1[6];
      int    t0, t1;
      HylcPlanSample(&p, order[start[u]], z0, &t0);
      for (long i = start[u] + 1; i < start[u + 1]; i++) {
        HylcPlanSample(&p, order[i - 1], z0, &t0);
        HylcPlanSample(&p, order[i], z1, &t1);
        HYLC_CHECK(t0 == t1, "unit %ld mixes terms %d and %d", u, t0, t1);
        int nvary = 0;
        for (int c = 0; c < 6; c++)
          if (z0[c] != z1[c]) {
            nvary++;
            HYLC_CHECK(fabs(z1[c]) > fabs(z0[c]), "unit %ld: sample %ld is not farther from zero than its predecessor (%g after %g)", u, order[i], z1[c], z0[c]);
          }
        HYLC_CHECK(nvary == 1, "unit %ld: %d coordinates vary between consecutive samples", u, nvary);
      }
    }
  }
  /* II ranges scale with 1/r */
  HylcPlanDefaults("woven", 10.0, &p);
  HYLC_CHECK(p.max1[3] == 1700 && p.min1[4] == -1700, "II range for r = 0.1 mm: %g %g", p.max1[3], p.min1[4]);
  return HYLC_TEST_RESULT();
}
