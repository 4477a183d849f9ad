/* Knit generators (stockinette, 1x1 rib): centrelines from src/pattern/knit.c, rest data from
   HylcPatternSetFromCurves(). */
#include <hylc/private/patternimpl.h>
#include <hylc/private/knit.h>
#include <stdlib.h>

/* a knit tile of type kt (the pattern's type names it in messages) */
static PetscErrorCode GenerateKnit(HylcPattern p, const HylcPatternGenParams *g, HylcKnitType kt)
{
  MPI_Comm        comm = PetscObjectComm((PetscObject)p);
  const char     *type = ((PetscObject)p)->type_name;
  const PetscBool rib  = (PetscBool)(kt == HYLC_KNIT_RIB);
  HylcKnitParams  kp;
  int             nyarns, *nverts = NULL;
  double         *pts = NULL, px, py;
  char            msg[256];
  PetscInt       *nv, *winding;

  PetscFunctionBegin;
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

PetscErrorCode HylcPatternGenerateStockinette_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(GenerateKnit(p, g, HYLC_KNIT_STOCKINETTE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternGenerateRib_Private(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(GenerateKnit(p, g, HYLC_KNIT_RIB));
  PetscFunctionReturn(PETSC_SUCCESS);
}
