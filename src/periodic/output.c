/* HylcPeriodic: output: the state as a pattern, legacy VTK (include/hylc/periodic.h). */
#include "periodicimpl.h"

/*@C
  HylcPeriodicCreateStatePattern - The current state as a new pattern: positions and twists of the
  originals, the current reference directors and reference twists, the same rest data, and the periods
  of the deformed lattice ((1 + sx) px, (1 + sy) py). Only for strains whose periodic images are
  translations along x and y (sa = 0 and II = 0).

  Collective on PETSC_COMM_SELF

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. out - the new pattern

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicCreateStatePattern(HylcPeriodic P, HylcPattern *out)
{
  const PetscInt N = P->N;
  PetscReal     *X, *th, *D1, *RefT;

  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCheck(P->z[1] == 0 && P->z[3] == 0 && P->z[4] == 0 && P->z[5] == 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "A deformed tile is a .pyp pattern only without shear and bending (sa = II = 0); use VTK output instead");
  PetscCall(PetscMalloc4(3 * N, &X, N, &th, 3 * N, &D1, N, &RefT));
  for (PetscInt o = 0; o < N; o++) {
    PetscInt e, b = -1;
    for (int i = 0; i < 3; i++) X[3 * o + i] = P->y[4 * o + i];
    th[o] = P->y[4 * o + 3];
    PetscCall(PetscHMapIGet(P->emap, Key(N, o, 0, 0), &e));
    for (int i = 0; i < 3; i++) D1[3 * o + i] = P->ed1[3 * e + i];
    for (PetscInt k = 0; k < P->nbe && b < 0; k++)
      if (P->be[k].v[1] == o) b = k;
    RefT[o] = P->mref[b];
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, out));
  PetscCall(HylcPatternSetData(*out, N, (1 + P->z[0]) * P->D.px, (1 + P->z[2]) * P->D.py, P->D.radius, X, th, P->D.next, P->D.shift, P->D.restLength, P->D.restKappa, P->D.restTwist, D1, RefT));
  PetscCall(HylcPatternSetState(*out, HYLC_PATTERN_STATE_EQUILIBRIUM));
  PetscCall(PetscFree4(X, th, D1, RefT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicWriteVTK - Writes the current state repeated ntx x nty times (centred on the tile) as
  legacy-VTK polylines, one per yarn loop and copy; copies are placed by the co-rotated periodic map
  x = T x_o + d (bent tiles come out bent).

  Not collective

  Input Parameters:
+ P     - the periodic tile
. fname - the file
. ntx   - copies along x (>= 1)
- nty   - copies along y (>= 1)

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicWriteVTK(HylcPeriodic P, const char fname[], PetscInt ntx, PetscInt nty)
{
  PetscInt   nloops, npts = 0, nlines;
  PetscReal *xih, *x0, *xs;
  FILE      *fp;

  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCheck(ntx >= 1 && nty >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "VTK tiling must be at least 1x1");
  PetscCall(HylcPatternGetNumLoops(P->pat, &nloops));
  nlines = nloops * ntx * nty;
  npts   = (P->N + nloops) * ntx * nty;
  PetscCall(PetscMalloc3(3 * npts, &xih, 3 * npts, &x0, 3 * npts, &xs));
  /* reference positions of every point, then the map T x_o + d with T = R(xi_o + S) R(xi_o)^T */
  PetscInt q = 0;
  for (PetscInt i = 0; i < ntx; i++)
    for (PetscInt j = 0; j < nty; j++)
      for (PetscInt l = 0; l < nloops; l++) {
        const PetscInt *lv;
        PetscInt        n, s1 = i - ntx / 2, s2 = j - nty / 2;
        PetscCall(HylcPatternGetLoop(P->pat, l, &n, &lv, NULL));
        for (PetscInt k = 0; k <= n; k++, q++) {
          const PetscInt o = lv[k % n];
          xih[3 * q]       = P->xi[3 * o] + s1 * P->D.px;
          xih[3 * q + 1]   = P->xi[3 * o + 1] + s2 * P->D.py;
          xih[3 * q + 2]   = P->xi[3 * o + 2];
          s1 += P->D.shift[2 * o];
          s2 += P->D.shift[2 * o + 1];
        }
      }
  PetscCall(HylcMidsurfaceEvaluate(P->ms, npts, xih, xs, NULL));
  q = 0;
  for (PetscInt i = 0; i < ntx; i++)
    for (PetscInt j = 0; j < nty; j++)
      for (PetscInt l = 0; l < nloops; l++) {
        const PetscInt *lv;
        PetscInt        n;
        PetscCall(HylcPatternGetLoop(P->pat, l, &n, &lv, NULL));
        for (PetscInt k = 0; k <= n; k++, q++) {
          const PetscInt o = lv[k % n];
          PetscReal      Ro[9], Rs[9], T[9], xo0[3], Tx[3], Tu[3], u[3];
          PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, Ro));
          PetscCall(HylcMidsurfaceGetRotation(P->ms, xih + 3 * q, Rs));
          for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) T[3 * a + b] = Rs[3 * a] * Ro[3 * b] + Rs[3 * a + 1] * Ro[3 * b + 1] + Rs[3 * a + 2] * Ro[3 * b + 2];
          /* x = x0(xi + S) + T (x_o - x0(xi_o)) */
          for (int a = 0; a < 3; a++) xo0[a] = P->y0[4 * o + a];
          for (int a = 0; a < 3; a++) u[a] = P->y[4 * o + a] - xo0[a];
          Mat3(T, u, Tu);
          (void)Tx;
          for (int a = 0; a < 3; a++) x0[3 * q + a] = xs[3 * q + a] + Tu[a];
        }
      }
  fp = fopen(fname, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write VTK file '%s'", fname);
  fprintf(fp, "# vtk DataFile Version 3.0\nhylc deformed tile (%d x %d copies)\nASCII\nDATASET POLYDATA\n", (int)ntx, (int)nty);
  fprintf(fp, "FIELD FieldData 1\nradius 1 1 double\n%.10g\n", (double)P->c.r);
  fprintf(fp, "POINTS %d double\n", (int)npts);
  for (PetscInt k = 0; k < npts; k++) fprintf(fp, "%.10g %.10g %.10g\n", (double)x0[3 * k], (double)x0[3 * k + 1], (double)x0[3 * k + 2]);
  fprintf(fp, "LINES %d %d\n", (int)nlines, (int)(nlines + npts));
  q = 0;
  for (PetscInt c = 0; c < ntx * nty; c++)
    for (PetscInt l = 0; l < nloops; l++) {
      PetscInt n;
      PetscCall(HylcPatternGetLoop(P->pat, l, &n, NULL, NULL));
      fprintf(fp, "%d", (int)(n + 1));
      for (PetscInt k = 0; k <= n; k++, q++) fprintf(fp, " %d", (int)q);
      fprintf(fp, "\n");
    }
  fprintf(fp, "CELL_DATA %d\nSCALARS loop int 1\nLOOKUP_TABLE default\n", (int)nlines);
  for (PetscInt c = 0; c < ntx * nty; c++)
    for (PetscInt l = 0; l < nloops; l++) fprintf(fp, "%d\n", (int)l);
  const int bad = ferror(fp);
  PetscCheck(fclose(fp) == 0 && !bad, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write VTK file '%s'", fname);
  PetscCall(PetscFree3(xih, x0, xs));
  PetscFunctionReturn(PETSC_SUCCESS);
}
