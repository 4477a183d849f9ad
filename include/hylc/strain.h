#ifndef HYLC_STRAIN_H
#define HYLC_STRAIN_H
/* The one vocabulary of the homogenized strains and of the energy's terms (src/sys/strain.c), used by every
   stage (periodic, plan, samples, fit, material, calibrate, tables) and by hylcmat. Plain C99, no PETSc:
   libhylcmat compiles the same definitions.

   Strain components (index s): z = (sx, sa, sy, II00, II01, II11), the 6-vector of every strain in memory and
   in files; a table's seventh column is the energy psi.
   Coordinates (index k or c): the five components that are sampled and fitted, 0 = sx, 1 = sa, 2 = sy,
   3 = II00, 4 = II11 (II01 never is); coordinate k is strain component HylcCoordStrain[k]. The 1D terms of
   the energy are named and numbered as the coordinates.
   Pairs (index q): the nine 2D terms (k0, k1), k0 < k1, in the order of the material tables:
   (sx,sa) (sx,sy) (sx,II00) (sx,II11) (sa,sy) (sa,II00) (sa,II11) (sy,II00) (sy,II11), named "k0name-k1name".

   A new strain term is added here first; docs/architecture.md lists what else it touches. */

#define HYLC_NSTRAIN           6  /* components of z */
#define HYLC_NCOORD            5  /* coordinates = 1D terms */
#define HYLC_NPAIR             9  /* pairs = 2D terms */
#define HYLC_NTRIPLE           7  /* triples = 3D terms, hylc's extension of the paper's model: (sx,sa,sy), and each in-plane pair with each bending coordinate */
#define HYLC_STRAIN_ALL_BITS   63 /* bit s set for every strain component s (component masks) */
#define HYLC_STRAIN_PLANE_BITS 7  /* sx, sa, sy */
#define HYLC_STRAIN_NO_POISSON 64 /* with a component mask: leave NaN a component whose derivative needs a doubly curved (Poisson) midsurface at a flat or singly curved strain */

/* each name spelled once: the arrays below and the pairs' names are made of these */
#define HYLC_NAME_SX   "sx"
#define HYLC_NAME_SA   "sa"
#define HYLC_NAME_SY   "sy"
#define HYLC_NAME_II00 "II00"
#define HYLC_NAME_II01 "II01"
#define HYLC_NAME_II11 "II11"
#define HYLC_NAME_PSI  "psi"

#ifdef __cplusplus
extern "C" {
#endif
/* the six strain components, then the energy psi (the columns of a strain table) */
extern const char *const HylcStrainNames[HYLC_NSTRAIN + 1];
/* the coordinates = the 1D terms */
extern const char *const HylcCoordNames[HYLC_NCOORD];
/* position of coordinate k in z: 0, 1, 2, 3, 5 */
extern const int HylcCoordStrain[HYLC_NCOORD];
/* the pairs = the 2D terms: their coordinates (k0 < k1) and names */
extern const int         HylcPairCoords[HYLC_NPAIR][2];
extern const char *const HylcPairNames[HYLC_NPAIR];
/* the load paths of include/hylcmat.h (uniaxial, equibiaxial, shear, bending), as a PETSc enum list (the kind's
   name, then the type's name, the prefix and NULL) */
extern const char *const HylcPathNames[7];
/* index of the pair (k0, k1) (k0 < k1), or -1 */
int HylcPairIndex(int k0, int k1);
/* the triples = the 3D terms (hylc's extension): their coordinates (k0 < k1 < k2) and names ("sx-sa-sy", ...) */
extern const int         HylcTripleCoords[HYLC_NTRIPLE][3];
extern const char *const HylcTripleNames[HYLC_NTRIPLE];
/* index of the triple (k0, k1, k2), or -1 */
int HylcTripleIndex(int k0, int k1, int k2);
#ifdef __cplusplus
}
#endif
#endif
