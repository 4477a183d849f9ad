/* The cloth's outputs: file names from -cloth_output, VTK files (legacy ASCII polydata, for ParaView)
   and the PNG plots of examples/plot_cloth.py. Rank 0 writes; every file goes to a temporary name first
   and is renamed when complete (HylcFileOpenTemp / HylcFileCommitTemp). */
#include <hylc/private/clothimpl.h>
#include <unistd.h>
#include <libgen.h>
#include <stdarg.h>

/* prefix_suffix; "" when there is no output prefix */
PetscErrorCode HylcClothOutputName_Private(HylcCloth c, const char suffix[], char path[], size_t len)
{
  PetscFunctionBegin;
  path[0] = 0;
  if (!c->output[0]) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(path, len, "%s_%s", c->output, suffix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The current state as VTK polydata: points (current positions), triangles, point data "displacement"
  and cell data "strain" (sx sa sy), "curvature" (II00 II01 II11, 1/m) and "material_u" (the deformed
  material x axis, unit). Collective (gathers); rank 0 writes.
*/
PetscErrorCode HylcClothWriteVTK_Private(HylcCloth c, const char path[])
{
  PetscReal *z;
  FILE      *fp = NULL;
  char       tmp[PETSC_MAX_PATH_LEN + 64];

  PetscFunctionBegin;
  if (!path[0] || !c->vtk) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_ClothOutput, c, 0, 0, 0));
  PetscCall(PetscMalloc1(6 * c->nt, &z));
  PetscCall(HylcClothStrains_Private(c, c->x, z));
  if (!c->rank) {
    const PetscReal *x = c->xgather;
    PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
    fprintf(fp, "# vtk DataFile Version 3.0\nhylc-cloth %s\nASCII\nDATASET POLYDATA\nPOINTS %" PetscInt_FMT " double\n", HylcClothTests[c->test], c->nv);
    for (PetscInt v = 0; v < c->nv; v++) fprintf(fp, "%.10g %.10g %.10g\n", (double)x[3 * v], (double)x[3 * v + 1], (double)x[3 * v + 2]);
    fprintf(fp, "POLYGONS %" PetscInt_FMT " %" PetscInt_FMT "\n", c->nt, 4 * c->nt);
    for (PetscInt t = 0; t < c->nt; t++) fprintf(fp, "3 %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", c->tri[3 * t], c->tri[3 * t + 1], c->tri[3 * t + 2]);
    fprintf(fp, "POINT_DATA %" PetscInt_FMT "\nVECTORS displacement double\n", c->nv);
    for (PetscInt v = 0; v < c->nv; v++) fprintf(fp, "%.8g %.8g %.8g\n", (double)(x[3 * v] - c->X[3 * v]), (double)(x[3 * v + 1] - c->X[3 * v + 1]), (double)(x[3 * v + 2] - c->X[3 * v + 2]));
    fprintf(fp, "CELL_DATA %" PetscInt_FMT "\nVECTORS strain double\n", c->nt);
    for (PetscInt t = 0; t < c->nt; t++) fprintf(fp, "%.8g %.8g %.8g\n", (double)z[6 * t], (double)z[6 * t + 1], (double)z[6 * t + 2]);
    fprintf(fp, "VECTORS curvature double\n");
    for (PetscInt t = 0; t < c->nt; t++) fprintf(fp, "%.8g %.8g %.8g\n", (double)z[6 * t + 3], (double)z[6 * t + 4], (double)z[6 * t + 5]);
    fprintf(fp, "VECTORS material_u double\n");
    for (PetscInt t = 0; t < c->nt; t++) {
      /* x_u = F e_u: solve the corner differences in material coordinates */
      const PetscInt  *v = c->tri + 3 * t;
      const PetscReal *u = c->uv + 6 * t;
      PetscReal        a = u[2] - u[0], b = u[4] - u[0], cc = u[3] - u[1], d = u[5] - u[1], det = a * d - b * cc, xu[3], n = 0;
      for (int k = 0; k < 3; k++) {
        PetscReal e1 = x[3 * v[1] + k] - x[3 * v[0] + k], e2 = x[3 * v[2] + k] - x[3 * v[0] + k];
        xu[k] = (e1 * d - e2 * cc) / det;
        n += xu[k] * xu[k];
      }
      n = PetscSqrtReal(n);
      fprintf(fp, "%.8g %.8g %.8g\n", (double)(xu[0] / n), (double)(xu[1] / n), (double)(xu[2] / n));
    }
    PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  }
  PetscCall(PetscFree(z));
  PetscCall(PetscLogEventEnd(HYLC_ClothOutput, c, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the plotting script: -cloth_plot_script, or examples/plot_cloth.py of the checkout the program was
   built in (build/bin/../../examples), or the installed PREFIX/share/hylc/plot_cloth.py */
static PetscErrorCode PlotScript(HylcCloth c, char path[], size_t len)
{
  char    exe[PETSC_MAX_PATH_LEN], *dir;
  ssize_t n;

  PetscFunctionBegin;
  path[0] = 0;
  if (c->plotScript[0]) {
    PetscCall(PetscStrncpy(path, c->plotScript, len));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);
  if (n <= 0) PetscFunctionReturn(PETSC_SUCCESS);
  exe[n] = 0;
  dir    = dirname(exe);
  PetscCall(PetscSNPrintf(path, len, "%s/../../examples/plot_cloth.py", dir));
  if (access(path, R_OK)) PetscCall(PetscSNPrintf(path, len, "%s/../share/hylc/plot_cloth.py", dir));
  if (access(path, R_OK)) path[0] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Runs the plotting script on rank 0: python3 plot_cloth.py kind csv (it writes csv with .png for .csv,
  and for "drape" a top view of the VTK file named by the CSV). A missing python3/matplotlib or script
  is reported on one line and the run goes on (the CSV and VTK are the results). Collective.
*/
PetscErrorCode HylcClothPlot_Private(HylcCloth c, const char kind[], const char csv[])
{
  char        script[PETSC_MAX_PATH_LEN], cmd[4 * PETSC_MAX_PATH_LEN], line[1024];
  const char *py = access("/usr/bin/python3", X_OK) ? "python3" : "/usr/bin/python3";
  FILE       *fp;
  int         st = 0;

  PetscFunctionBegin;
  if (!c->plot || !csv[0]) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscLogEventBegin(HYLC_ClothOutput, c, 0, 0, 0));
  PetscCall(PlotScript(c, script, sizeof(script)));
  if (!script[0]) {
    PetscCall(PetscPrintf(CLOTH_COMM_PRIVATE(c), "plot: examples/plot_cloth.py not found (give -cloth_plot_script, or -cloth_plot 0)\n"));
    PetscCall(PetscLogEventEnd(HYLC_ClothOutput, c, 0, 0, 0));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscSNPrintf(cmd, sizeof(cmd), "%s '%s' %s '%s' 2>&1; echo \"plot-status $?\"", py, script, kind, csv));
  if (!c->rank) {
    fp = popen(cmd, "r");
    if (fp) {
      while (fgets(line, sizeof(line), fp)) {
        if (!strncmp(line, "plot-status ", 12))
          st = atoi(line + 12);
        else if (c->monitor || strstr(line, "rror"))
          printf("plot: %s", line);
      }
      pclose(fp);
    } else
      st = -1;
    if (st) printf("plot: %s %s failed (status %d): no PNG (python3 with matplotlib needed)\n", script, kind, st);
    fflush(stdout);
  }
  PetscCall(PetscLogEventEnd(HYLC_ClothOutput, c, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcClothTextAppend_Private(HylcClothText *t, const char fmt[], ...)
{
  va_list ap;
  int     n;

  PetscFunctionBegin;
  for (;;) {
    size_t room = t->cap - t->len;
    va_start(ap, fmt);
    n = vsnprintf(t->s ? t->s + t->len : NULL, t->s ? room : 0, fmt, ap);
    va_end(ap);
    PetscCheck(n >= 0, PETSC_COMM_SELF, PETSC_ERR_SYS, "vsnprintf failed");
    if (t->s && (size_t)n < room) break;
    t->cap = 2 * (t->cap + (size_t)n + 256);
    PetscCall(PetscRealloc(t->cap, &t->s));
  }
  t->len += (size_t)n;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* writes the text to path on rank 0 (nothing for an empty path) and frees it. Collective. */
PetscErrorCode HylcClothTextWrite_Private(HylcCloth c, HylcClothText *t, const char path[])
{
  PetscFunctionBegin;
  if (path && path[0] && !c->rank) {
    FILE *fp;
    char  tmp[PETSC_MAX_PATH_LEN + 64];
    PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
    if (t->len && fwrite(t->s, 1, t->len, fp) != t->len) {
      HylcFileAbortTemp(&fp, tmp);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "cannot write %s", path);
    }
    PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  }
  PetscCall(PetscFree(t->s));
  t->len = t->cap = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}
