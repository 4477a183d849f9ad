/* libFuzzer harness: the .obj reader of hylc-cloth's scene (src/cloth/mesh.c, HylcClothMeshReadOBJ_Private).
   The input is written to <tmp>/mesh.obj; a first line "#fuzz S" sets the scale (any number: the reader
   must refuse what is not a finite positive factor). A mesh the reader accepts must be what it promises
   (every index in range, every vertex in a face, every coordinate finite and within 1e6 m): anything else
   aborts, a finding. It then gets its material coordinates (HylcClothMeshMaterial_Private) and, if they
   are valid and it has at most 256 triangles, its layout (HylcClothBuild_Private: the adjacency of
   hylcmat_mesh, the vectors, the Hessian pattern). An error return is fine; a crash, a sanitizer report, a leak or a hang is a finding. */
#include "fuzzcommon.h"
#include <hylc/private/clothimpl.h>
#include <math.h>
#include <stdio.h>
#include <unistd.h>

static char dir[64], objPath[128];

static void RemoveDir(void)
{
  unlink(objPath);
  rmdir(dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
  HylcCloth c;
  HylcFuzzInit(argc, argv);
  snprintf(dir, sizeof(dir), "%s", "/tmp/hylc-fuzz-obj.XXXXXX");
  if (!mkdtemp(dir)) abort();
  snprintf(objPath, sizeof(objPath), "%s/mesh.obj", dir);
  atexit(RemoveDir);
  if (HylcClothCreate(PETSC_COMM_SELF, &c) || HylcClothDestroy(&c)) abort();
  HylcFuzzInitEnd();
  return 0;
}

/* what the reader promises of a mesh it accepts */
static void CheckMesh(HylcCloth c)
{
  char *used;
  if (c->nv < 3 || c->nt < 1 || !c->X || !c->tri) abort();
  used = (char *)calloc((size_t)c->nv, 1);
  if (!used) abort();
  for (PetscInt i = 0; i < 3 * c->nt; i++) {
    if (c->tri[i] < 0 || c->tri[i] >= c->nv) abort();
    used[c->tri[i]] = 1;
  }
  for (PetscInt v = 0; v < c->nv; v++)
    if (!used[v]) abort();
  free(used);
  for (PetscInt i = 0; i < 3 * c->nv; i++)
    if (!(fabs((double)c->X[i]) <= 1e6)) abort();
  if (c->uv)
    for (PetscInt i = 0; i < 6 * c->nt; i++)
      if (!(fabs((double)c->uv[i]) <= 1e6)) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  HylcCloth c;
  double    scale = 1;
  FILE     *fp    = fopen(objPath, "wb");

  if (!fp || fwrite(data, 1, size, fp) != size || fclose(fp)) abort();
  if (size > 6 && !memcmp(data, "#fuzz ", 6)) {
    char head[64] = "";
    memcpy(head, data, size < sizeof(head) - 1 ? size : sizeof(head) - 1);
    if (sscanf(head + 6, "%lf", &scale) != 1) scale = 1;
  }
  if (HylcClothCreate(PETSC_COMM_SELF, &c)) abort();
  if (!HylcClothMeshReadOBJ_Private(c, objPath, (PetscReal)scale)) {
    CheckMesh(c);
    /* the layout's code paths do not depend on the mesh's size: built for the small ones only (its Hessian
       pattern dominates the time of a large one) */
    if (!HylcClothMeshMaterial_Private(c, 0.3, (PetscBool)(size % 2)) && c->nt <= 256) (void)HylcClothBuild_Private(c);
  }
  if (HylcClothDestroy(&c)) abort();
  return 0;
}
