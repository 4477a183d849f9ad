/* HylcPattern viewers: text summary and legacy-VTK polylines. */
#include <hylc/private/patternimpl.h>

/*@C
  HylcPatternView - Prints a summary: sizes, periods, radius, each loop's vertex count and winding, yarn
  length, area density and the minimum distance between non-excluded segments in units of r.
  Collective.  Options used by the summary: -pattern_density, -pattern_exclude_arc.
@*/
PetscErrorCode HylcPatternView(HylcPattern p, PetscViewer viewer)
{
  PetscBool iascii;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)p), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  PetscReal L = 0, R = 0, rhoA = 0, dmin = PETSC_INFINITY;
  PetscInt  pair[4] = {-1, -1, 0, 0};
  if (p->hasdata) { /* everything that can fail before the first line of output */
    PetscCall(HylcPatternGetYarnLength(p, &L, &R));
    PetscCall(HylcPatternGetAreaDensity(p, p->viewDensity, &rhoA));
    PetscCall(HylcPatternMinSegmentDistance(p, p->viewExcludeArc, &dmin, pair));
  }
  PetscCall(PetscObjectPrintClassNamePrefixType((PetscObject)p, viewer));
  PetscCall(PetscViewerASCIIPushTab(viewer));
  if (p->filename[0]) PetscCall(PetscViewerASCIIPrintf(viewer, "file: %s\n", p->filename));
  if (p->hasdata)
    PetscCall(PetscViewerASCIIPrintf(viewer, "state: %s\n",
                                     p->state == HYLC_PATTERN_STATE_UNRECORDED  ? "not recorded in the file (taken as its own reference state)"
                                     : p->state == HYLC_PATTERN_STATE_GENERATED ? "generated (not a reference state)"
                                                                                : HylcPatternStates[p->state]));
  if (!p->hasdata) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "(no data: not set up)\n"));
    PetscCall(PetscViewerASCIIPopTab(viewer));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscViewerASCIIPrintf(viewer, "vertices: %" PetscInt_FMT "\n", p->nv));
  PetscCall(PetscViewerASCIIPrintf(viewer, "loops: %" PetscInt_FMT "\n", p->nloops));
  PetscCall(PetscViewerASCIIPrintf(viewer, "periods: %.9g %.9g\n", (double)p->px, (double)p->py));
  PetscCall(PetscViewerASCIIPrintf(viewer, "radius: %.9g\n", (double)p->radius));
  for (PetscInt l = 0; l < p->nloops; l++)
    PetscCall(PetscViewerASCIIPrintf(viewer, "loop %" PetscInt_FMT ": %" PetscInt_FMT " vertices, winding (%" PetscInt_FMT ", %" PetscInt_FMT "), rest length %.6g m\n", l, p->loopStart[l + 1] - p->loopStart[l], p->winding[2 * l],
                                     p->winding[2 * l + 1], (double)p->loopLen[l]));
  PetscCall(PetscViewerASCIIPrintf(viewer, "yarn length: %.6g m (rest %.6g m)\n", (double)L, (double)R));
  PetscCall(PetscViewerASCIIPrintf(viewer, "area density: %.6g kg/m^2 (volumetric density %.6g kg/m^3%s)\n", (double)rhoA, (double)(p->viewDensity > 0 ? p->viewDensity : HylcDefaultYarnDensity(p->radius)),
                                   p->viewDensity > 0 ? ", -pattern_density" : ": 0.12 kg/m^2 / r, as hylc-fit and the tables"));
  if (dmin < PETSC_INFINITY)
    PetscCall(PetscViewerASCIIPrintf(viewer, "min distance: %.4f r (segments %" PetscInt_FMT " and %" PetscInt_FMT " shifted by (%" PetscInt_FMT ", %" PetscInt_FMT "); same-yarn pairs within %.6g r of rest arc excluded)\n",
                                     (double)(dmin / p->radius), pair[0], pair[1], pair[2], pair[3], (double)p->viewExcludeArc));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "min distance: > 20 r (no segment pair within 20 r)\n"));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternViewFromOptions - Views the pattern if the option name is given (PetscObjectViewFromOptions()).

  Collective

  Input Parameters:
+ p    - the pattern
. obj  - an object whose prefix is used (NULL: the pattern's)
- name - the option, e.g. "-pattern_view"

  Level: intermediate

.seealso: HylcPatternView()
@*/
PetscErrorCode HylcPatternViewFromOptions(HylcPattern p, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)p, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternWriteVTK - Writes the tile repeated ntx x nty times as legacy-VTK polylines (one polyline
  per yarn loop and tile copy, closed onto the next copy), with cell data "loop" and point data "twist"
  (theta) and field data "radius", for ParaView (use a Tube filter with the radius). Collective; rank 0
  writes.
@*/
PetscErrorCode HylcPatternWriteVTK(HylcPattern p, const char fname[], PetscInt ntx, PetscInt nty)
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)p);
  PetscMPIInt    rank;
  PetscErrorCode code                      = 0;
  char           msg[HYLC_PATTERN_MSG_LEN] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(p->hasdata, comm, PETSC_ERR_ARG_WRONGSTATE, "Pattern has no data to write");
  PetscCheck(ntx >= 1 && nty >= 1, comm, PETSC_ERR_USER_INPUT, "VTK tiling must be at least 1x1, got %" PetscInt_FMT "x%" PetscInt_FMT, ntx, nty);
  PetscCheck((double)ntx * (double)nty * (double)(p->nv + p->nloops) <= 1e8, comm, PETSC_ERR_USER_INPUT, "VTK tiling %" PetscInt_FMT "x%" PetscInt_FMT " of a %" PetscInt_FMT "-vertex tile gives %.3g points, more than 1e8", ntx, nty, p->nv,
             (double)ntx * (double)nty * (double)(p->nv + p->nloops));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    FILE          *fp     = NULL;
    const PetscInt ncopy  = ntx * nty;
    const PetscInt npts   = ncopy * (p->nv + p->nloops);
    const PetscInt nlines = ncopy * p->nloops;
    char           tmp[PETSC_MAX_PATH_LEN + 16];
    /* a unique temporary renamed onto fname once complete: a full disk leaves no partial file */
    PetscCall(PetscPushErrorHandler(HylcPatternKeepMessage_Private, msg));
    code = HylcFileOpenTemp(fname, tmp, sizeof(tmp), &fp);
    if (!code) {
      fprintf(fp, "# vtk DataFile Version 3.0\nhylc yarn pattern (%d x %d tiles)\nASCII\nDATASET POLYDATA\n", (int)ntx, (int)nty);
      fprintf(fp, "FIELD FieldData 1\nradius 1 1 double\n%.10g\n", (double)p->radius);
      fprintf(fp, "POINTS %d double\n", (int)npts);
      for (PetscInt i = 0; i < ntx; i++)
        for (PetscInt j = 0; j < nty; j++)
          for (PetscInt l = 0; l < p->nloops; l++) {
            const PetscInt *lv = p->loopVerts + p->loopStart[l], n = p->loopStart[l + 1] - p->loopStart[l];
            PetscInt        sx = i, sy = j; /* accumulated lattice shift of the unwrapped yarn */
            for (PetscInt k = 0; k <= n; k++) {
              const PetscInt v = lv[k % n];
              fprintf(fp, "%.10g %.10g %.10g\n", (double)(p->X[3 * v] + sx * p->px), (double)(p->X[3 * v + 1] + sy * p->py), (double)p->X[3 * v + 2]);
              sx += p->shift[2 * v];
              sy += p->shift[2 * v + 1];
            }
          }
      fprintf(fp, "LINES %d %d\n", (int)nlines, (int)(nlines + npts));
      PetscInt off = 0;
      for (PetscInt c = 0; c < ncopy; c++)
        for (PetscInt l = 0; l < p->nloops; l++) {
          const PetscInt n = p->loopStart[l + 1] - p->loopStart[l];
          fprintf(fp, "%d", (int)(n + 1));
          for (PetscInt k = 0; k <= n; k++) fprintf(fp, " %d", (int)(off + k));
          fprintf(fp, "\n");
          off += n + 1;
        }
      fprintf(fp, "CELL_DATA %d\nSCALARS loop int 1\nLOOKUP_TABLE default\n", (int)nlines);
      for (PetscInt c = 0; c < ncopy; c++)
        for (PetscInt l = 0; l < p->nloops; l++) fprintf(fp, "%d\n", (int)l);
      fprintf(fp, "POINT_DATA %d\nSCALARS twist double 1\nLOOKUP_TABLE default\n", (int)npts);
      for (PetscInt c = 0; c < ncopy; c++)
        for (PetscInt l = 0; l < p->nloops; l++) {
          const PetscInt *lv = p->loopVerts + p->loopStart[l], n = p->loopStart[l + 1] - p->loopStart[l];
          for (PetscInt k = 0; k <= n; k++) fprintf(fp, "%.10g\n", (double)p->theta[lv[k % n]]);
        }
      code = HylcFileCommitTemp(&fp, tmp, fname);
    }
    PetscCall(PetscPopErrorHandler());
  }
  PetscCall(HylcPatternRaiseFromRank0_Private(comm, code, msg));
  PetscFunctionReturn(PETSC_SUCCESS);
}
