#pragma once
/* Test support (tests/support, linked into the tests and benchmarks only, not part of libhylc): the
   reference implementation that the periodic assembly is checked against.

   HylcTile: the elastic energy of a periodic yarn tile whose periodic images are translated copies
   (x + s1 L1 + s2 L2 for lattice vectors L1, L2; at rest L1 = (px,0,0), L2 = (0,py,0)), with exact
   gradient and Hessian in the tile's own unknowns q = (x, y, z, theta_out) per vertex (4 per vertex).

   Every physical element is counted once: stretching per edge, bending and twisting per vertex, and
   contact per unordered segment pair (a, copy of b shifted by s) found by the AABB broadphase over the
   tile and its periodic copies and not excluded by the same-yarn rule. This is the energy of the
   co-rotated periodic problem at zero bending strain; the ghost-based assembly with fractional weights
   of the Newton solver must agree with it. The energy parts and masks are HYLC_TERM_* of hylc/yarn.h.

   Reference frames (d1 per edge, reference twist per vertex) are stored; HylcTileUpdateFrames()
   transports them in time to the current tangents (DER time-parallel transport, reference twist
   updated on the branch nearest its previous value). */
#include <hylc/pattern.h>
#include <hylc/yarn.h>
#include <petscmat.h>

typedef struct _n_HylcTile *HylcTile;

PETSC_EXTERN PetscErrorCode HylcTileCreate(HylcPattern, const HylcYarnModel *, HylcTile *);
PETSC_EXTERN PetscErrorCode HylcTileDestroy(HylcTile *);
PETSC_EXTERN PetscErrorCode HylcTileGetSize(HylcTile, PetscInt *);
PETSC_EXTERN PetscErrorCode HylcTileGetConstants(HylcTile, HylcYarnConstants *);
PETSC_EXTERN PetscErrorCode HylcTileSetLattice(HylcTile, const PetscReal[3], const PetscReal[3]);
PETSC_EXTERN PetscErrorCode HylcTileSetState(HylcTile, const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcTileGetState(HylcTile, PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcTileUpdateFrames(HylcTile);
PETSC_EXTERN PetscErrorCode HylcTileCreateMatrix(HylcTile, Mat *);
PETSC_EXTERN PetscErrorCode HylcTileEvaluate(HylcTile, int, PetscReal[4], PetscReal[], Mat);
PETSC_EXTERN PetscErrorCode HylcTileGetNumContactPairs(HylcTile, PetscInt *);
