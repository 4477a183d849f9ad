/* The vocabulary of strains and terms (include/hylc/strain.h): the only definition of their names, indices
   and pairs. Plain C99; compiled into libhylc and libhylcmat. */
#include <hylc/strain.h>
#include <stddef.h>

const char *const HylcStrainNames[HYLC_NSTRAIN + 1] = {HYLC_NAME_SX, HYLC_NAME_SA, HYLC_NAME_SY, HYLC_NAME_II00, HYLC_NAME_II01, HYLC_NAME_II11, HYLC_NAME_PSI};

const char *const HylcCoordNames[HYLC_NCOORD] = {HYLC_NAME_SX, HYLC_NAME_SA, HYLC_NAME_SY, HYLC_NAME_II00, HYLC_NAME_II11};

const int HylcCoordStrain[HYLC_NCOORD] = {0, 1, 2, 3, 5};

const int HylcPairCoords[HYLC_NPAIR][2] = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}};

const char *const HylcPairNames[HYLC_NPAIR] = {HYLC_NAME_SX "-" HYLC_NAME_SA,   HYLC_NAME_SX "-" HYLC_NAME_SY,   HYLC_NAME_SX "-" HYLC_NAME_II00, HYLC_NAME_SX "-" HYLC_NAME_II11, HYLC_NAME_SA "-" HYLC_NAME_SY,
                                               HYLC_NAME_SA "-" HYLC_NAME_II00, HYLC_NAME_SA "-" HYLC_NAME_II11, HYLC_NAME_SY "-" HYLC_NAME_II00, HYLC_NAME_SY "-" HYLC_NAME_II11};

int HylcPairIndex(int k0, int k1)
{
  for (int q = 0; q < HYLC_NPAIR; q++)
    if (HylcPairCoords[q][0] == k0 && HylcPairCoords[q][1] == k1) return q;
  return -1;
}

/* the load paths of include/hylcmat.h, with the two trailing entries of PETSc's enum lists */
const char *const HylcPathNames[7] = {"uniaxial", "equibiaxial", "shear", "bending", "HylcPath", "HYLCMAT_PATH_", NULL};

#define HYLC_TRIPLE_NAME(a, b, c) HYLC_NAME_##a "-" HYLC_NAME_##b "-" HYLC_NAME_##c
const int         HylcTripleCoords[HYLC_NTRIPLE][3] = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {0, 2, 3}, {0, 2, 4}, {1, 2, 3}, {1, 2, 4}};
const char *const HylcTripleNames[HYLC_NTRIPLE]     = {HYLC_TRIPLE_NAME(SX, SA, SY),   HYLC_TRIPLE_NAME(SX, SA, II00), HYLC_TRIPLE_NAME(SX, SA, II11), HYLC_TRIPLE_NAME(SX, SY, II00),
                                                       HYLC_TRIPLE_NAME(SX, SY, II11), HYLC_TRIPLE_NAME(SA, SY, II00), HYLC_TRIPLE_NAME(SA, SY, II11)};

int HylcTripleIndex(int k0, int k1, int k2)
{
  for (int r = 0; r < HYLC_NTRIPLE; r++)
    if (HylcTripleCoords[r][0] == k0 && HylcTripleCoords[r][1] == k1 && HylcTripleCoords[r][2] == k2) return r;
  return -1;
}
