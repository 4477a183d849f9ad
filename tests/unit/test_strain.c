/* The one vocabulary of strains and terms (include/hylc/strain.h): the names every stage uses (the plan's
   terms, the material's and hylcmat's term names, the table reader's columns, the pairs' coordinates and
   their index) are those of the documented file formats, in their order, and agree with each other. */
#include <hylc/strain.h>
#include <hylc/plan.h>
#include <hylc/material.h>
#include <hylc/table.h>
#include <hylcmat.h>
#include <string.h>
#include "hylctest.h"

/* the names of docs/output-format.md and docs/material.md, written out here on purpose */
static const char *const Terms[22]  = {"zero",    "sx",      "sa",      "sy",      "II00",     "II11",       "sx-sa",      "sx-sy",      "sx-II00",    "sx-II11",    "sa-sy",
                                       "sa-II00", "sa-II11", "sy-II00", "sy-II11", "sx-sa-sy", "sx-sa-II00", "sx-sa-II11", "sx-sy-II00", "sx-sy-II11", "sa-sy-II00", "sa-sy-II11"};
static const char *const Columns[7] = {"sx", "sa", "sy", "II00", "II01", "II11", "psi"};

int main(void)
{
  char name[32];

  HYLC_CHECK(HYLC_PLAN_NTERM == 15 && HYLC_PLAN_NTERM3 == 22 && HYLCMAT_N3D == HYLC_NTRIPLE && HYLC_PLAN_NCOORD == 5 && HYLC_MATERIAL_N1D == 5 && HYLC_MATERIAL_N2D == 9 && HYLCMAT_N1D == HYLC_NCOORD && HYLCMAT_N2D == HYLC_NPAIR, "sizes");
  for (int t = 0; t < 22; t++) HYLC_CHECK(!strcmp(HylcPlanTermName(t), Terms[t]), "plan term %d: %s, expected %s", t, HylcPlanTermName(t), Terms[t]);
  HYLC_CHECK(!strcmp(HylcPlanTermName(22), "unknown") && !strcmp(HylcPlanTermName(-1), "unknown"), "plan term out of range");
  for (int r = 0; r < HYLC_NTRIPLE; r++) { /* the triples: in-plane pair or (sx, sa, sy), then a coordinate, in order, named by their coordinates */
    int k0, k1, k2, c[3];
    hylcmat_triple(r, &k0, &k1, &k2);
    HylcPlanTriple(HYLC_PLAN_NTERM + r, c);
    snprintf(name, sizeof(name), "%s-%s-%s", HylcCoordNames[k0], HylcCoordNames[k1], HylcCoordNames[k2]);
    HYLC_CHECK(k0 < k1 && k1 < k2 && k1 < 3 && c[0] == k0 && c[1] == k1 && c[2] == k2, "triple %d: (%d, %d, %d)", r, k0, k1, k2);
    HYLC_CHECK(!strcmp(HylcTripleNames[r], name) && !strcmp(hylcmat_term3d_name(r), name) && !strcmp(Terms[HYLC_PLAN_NTERM + r], name), "triple %d named %s, expected %s", r, HylcTripleNames[r], name);
    HYLC_CHECK(HylcTripleIndex(k0, k1, k2) == r && HylcPlanTermDim(HYLC_PLAN_NTERM + r) == 3, "index of triple %d", r);
  }
  for (int s = 0; s < 7; s++) HYLC_CHECK(!strcmp(HylcTableStrainNames[s], Columns[s]), "table column %d: %s, expected %s", s, HylcTableStrainNames[s], Columns[s]);
  for (int k = 0; k < HYLC_NCOORD; k++) {
    HYLC_CHECK(!strcmp(HylcCoordNames[k], Terms[1 + k]), "coordinate %d: %s", k, HylcCoordNames[k]);
    HYLC_CHECK(!strcmp(HylcMaterialTermNames1D[k], Terms[1 + k]) && !strcmp(hylcmat_term1d_name(k), Terms[1 + k]), "1D term %d of the material or hylcmat", k);
    HYLC_CHECK(HylcPlanStrainIndex(k) == HylcCoordStrain[k] && !strcmp(HylcStrainNames[HylcCoordStrain[k]], HylcCoordNames[k]), "coordinate %d at strain position %d", k, HylcCoordStrain[k]);
  }
  for (int q = 0; q < HYLC_NPAIR; q++) {
    int k0 = HylcPairCoords[q][0], k1 = HylcPairCoords[q][1], c0, c1;
    HYLC_CHECK(k0 >= 0 && k0 < k1 && k1 < HYLC_NCOORD, "pair %d: (%d, %d)", q, k0, k1);
    HYLC_CHECK(q == 0 || HylcPairCoords[q - 1][0] < k0 || (HylcPairCoords[q - 1][0] == k0 && HylcPairCoords[q - 1][1] < k1), "pairs out of order at %d", q);
    snprintf(name, sizeof(name), "%s-%s", HylcCoordNames[k0], HylcCoordNames[k1]);
    HYLC_CHECK(!strcmp(HylcPairNames[q], name) && !strcmp(HylcPairNames[q], Terms[6 + q]), "pair %d named %s, expected %s", q, HylcPairNames[q], name);
    HYLC_CHECK(!strcmp(HylcMaterialTermNames2D[q], name) && !strcmp(hylcmat_term2d_name(q), name), "2D term %d of the material or hylcmat", q);
    HYLC_CHECK(HylcPairIndex(k0, k1) == q && HylcMaterialPairIndex(k0, k1) == q && hylcmat_pair_index(k0, k1) == q, "index of pair (%d, %d)", k0, k1);
    HylcPlanPair(6 + q, &c0, &c1);
    HYLC_CHECK(c0 == k0 && c1 == k1, "plan pair %d: (%d, %d)", 6 + q, c0, c1);
    hylcmat_pair(q, &c0, &c1);
    HYLC_CHECK(c0 == k0 && c1 == k1, "hylcmat pair %d: (%d, %d)", q, c0, c1);
  }
  HYLC_CHECK(HylcPairIndex(1, 0) == -1 && HylcPairIndex(3, 4) == -1 && HylcPairIndex(0, 0) == -1, "not a pair");
  return HYLC_TEST_RESULT();
}
