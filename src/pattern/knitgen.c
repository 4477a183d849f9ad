/* Knit generators (stockinette, 1x1 rib): centrelines from src/pattern/knit.c, rest data from
   HylcPatternSetFromCurves(). */
#include <hylc/private/patternimpl.h>
#include <hylc/private/knit.h>
#include <stdlib.h>

PetscErrorCode HylcPatternGenerateKnit_Private(HylcPattern p, HylcPatternType type, const HylcPatternGenParams *g)
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)p);
  HylcKnitParams kp;
  HylcKnitType   kt;
  PetscBool      rib;
  int            nyarns, *nverts = NULL;
  double        *pts = NULL, px, py;
  char           msg[256];
  PetscInt      *nv, *winding;

  PetscFunctionBegin;
  PetscCall(PetscStrcmp(type, HYLCPATTERNRIB, &rib));
  kt          = rib ? HYLC_KNIT_RIB : HYLC_KNIT_STOCKINETTE;
  kp.r        = g->radius;
  kp.wale     = g->wale;
  kp.course   = g->course;
  kp.depth    = g->depth;
  kp.seglen   = g->seglen;
  kp.nwales   = (int)(g->size[0] > 0 ? g->size[0] : (rib ? 2 : 1));
  kp.ncourses = (int)(g->size[1] > 0 ? g->size[1] : 2);
  PetscCheck(HylcKnitSample(kt, &kp, &nyarns, &nverts, &pts, &px, &py, msg, sizeof(msg)) == 0, comm, PETSC_ERR_USER_INPUT, "Cannot generate %s (-pattern_size %d,%d): %s", type, kp.nwales, kp.ncourses, msg);
  PetscCall(PetscMalloc2(nyarns, &nv, 2 * nyarns, &winding));
  for (int k = 0; k < nyarns; k++) {
    nv[k]              = nverts[k];
    winding[2 * k]     = 1;
    winding[2 * k + 1] = 0;
  }
  PetscCall(HylcPatternSetFromCurves(p, px, py, g->radius, nyarns, nv, winding, pts));
  PetscCall(PetscFree2(nv, winding));
  free(nverts);
  free(pts);
  PetscFunctionReturn(PETSC_SUCCESS);
}
