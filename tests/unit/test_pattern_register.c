/* A pattern generator registered from outside the library (HylcPatternRegister()): -pattern_type accepts
   it and -help lists it, HylcPatternGenerate() and HylcPatternSetUp() call it with the pattern's type set
   to its name, and the messages for an unknown type name it among the available ones.
   hylc-test: nprocs=1 */
#include <hylc/pattern.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "hylctest.h"

/* "wave": one yarn along x, a sine in z of amplitude r, nx periods of 8 r (size[0]), 16 vertices per period;
   the tile is 8 r nx by 4 r */
static PetscErrorCode GenerateWave(HylcPattern p, const HylcPatternGenParams *g)
{
  const PetscReal r  = g->radius;
  const PetscInt  nx = g->size[0] > 0 ? g->size[0] : 1, n = 16 * nx, winding[2] = {1, 0};
  const PetscReal px = 8 * r * nx, py = 4 * r;
  PetscReal      *pts;
  HylcPatternType type;
  PetscBool       named;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetType(p, &type));
  PetscCall(PetscStrcmp(type, "wave", &named));
  HYLC_CHECK(named, "the generator sees the type '%s', expected 'wave'", type);
  PetscCall(PetscMalloc1(3 * n, &pts));
  for (PetscInt v = 0; v < n; v++) {
    const PetscReal x = (v + 0.5) * px / n - 0.5 * px;
    pts[3 * v]        = x;
    pts[3 * v + 1]    = 0;
    pts[3 * v + 2]    = r * PetscSinReal(2 * PETSC_PI * x / (8 * r));
  }
  PetscCall(HylcPatternSetFromCurves(p, px, py, r, 1, &n, winding, pts));
  PetscCall(PetscFree(pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the -help output of HylcPatternSetFromOptions() (PETSc prints the list of a PetscOptionsFList() to stdout
   itself), captured in a file and read back */
static PetscErrorCode HelpOf(HylcPattern p, char text[], size_t len)
{
  const char path[] = "test_pattern_register.help.txt";
  int        saved, fd;
  size_t     n;
  FILE      *fp;

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, "-help", NULL));
  fflush(stdout);
  saved = dup(1);
  fd    = open(path, O_CREAT | O_TRUNC | O_WRONLY, 0644);
  PetscCheck(saved >= 0 && fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot redirect stdout to %s", path);
  dup2(fd, 1);
  close(fd);
  PetscCall(HylcPatternSetFromOptions(p));
  fflush(stdout);
  dup2(saved, 1);
  close(saved);
  PetscCall(PetscOptionsClearValue(NULL, "-help"));
  fp = fopen(path, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot read %s", path);
  n       = fread(text, 1, len - 1, fp);
  text[n] = 0;
  fclose(fp);
  remove(path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the message of an error raised by call, and its code */
static PetscErrorCode ErrorOf(PetscErrorCode (*call)(HylcPattern), HylcPattern p, PetscErrorCode *code, char msg[], size_t len)
{
  const char *text = NULL;

  PetscFunctionBegin;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  *code = call(p);
  PetscCall(PetscPopErrorHandler());
  msg[0] = 0;
  if (*code) {
    PetscCall(PetscErrorMessage(*code, NULL, (char **)&text));
    PetscCall(PetscStrncpy(msg, text ? text : "", len));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetTypeWoolly(HylcPattern p) { return HylcPatternSetType(p, "woolly"); }

int main(int argc, char **argv)
{
  HylcPattern          p;
  HylcPatternGenParams g;
  PetscInt             nv, nl;
  PetscReal            px, py;
  HylcPatternType      type;
  PetscErrorCode       code;
  PetscBool            same;
  char                 msg[1024], *line, helpText[1 << 15];

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(HylcPatternRegister("wave", GenerateWave));

  /* -pattern_type wave through the options, with -help: the list shows the new generator */
  PetscCall(PetscOptionsSetValue(NULL, "-pattern_type", "wave"));
  PetscCall(PetscOptionsSetValue(NULL, "-pattern_size", "2,1"));
  PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &p));
  PetscCall(HelpOf(p, helpText, sizeof(helpText)));
  line = strstr(helpText, "-pattern_type");
  HYLC_CHECK(line, "-help has no -pattern_type line:\n%s", helpText);
  if (line) {
    char *end = strstr(line, "(HylcPatternSetType)");
    HYLC_CHECK(end, "-help's -pattern_type entry does not end in (HylcPatternSetType):\n%s", line);
    if (end) *end = 0;
    HYLC_CHECK(strstr(line, " wave"), "-help's -pattern_type entry does not list wave: %s", line);
    HYLC_CHECK(strstr(line, "file") && strstr(line, "plain") && strstr(line, "satin") && strstr(line, "rib"), "-help's -pattern_type entry lacks a built-in source: %s", line);
  }
  PetscCall(HylcPatternGetType(p, &type));
  PetscCall(PetscStrcmp(type, "wave", &same));
  HYLC_CHECK(same, "-pattern_type wave gave the type '%s'", type);
  PetscCall(HylcPatternSetUp(p));
  PetscCall(HylcPatternGetNumVertices(p, &nv));
  PetscCall(HylcPatternGetNumLoops(p, &nl));
  PetscCall(HylcPatternGetPeriods(p, &px, &py));
  HYLC_CHECK(nv == 32 && nl == 1, "the wave of size 2,1 has %" PetscInt_FMT " vertices in %" PetscInt_FMT " loops, expected 32 in 1", nv, nl);
  HYLC_CHECK_CLOSE(px, 16e-3, 1e-14);
  HYLC_CHECK_CLOSE(py, 4e-3, 1e-14);

  /* an unknown type names the registered ones, the new one included */
  PetscCall(ErrorOf(SetTypeWoolly, p, &code, msg, sizeof(msg)));
  HYLC_CHECK(code == PETSC_ERR_USER_INPUT && strstr(msg, "Unknown pattern type 'woolly'") && strstr(msg, "stockinette, rib, wave"), "HylcPatternSetType(woolly): code %d, message '%s'", (int)code, msg);
  PetscCall(PetscOptionsSetValue(NULL, "-pattern_type", "woolly"));
  PetscCall(ErrorOf(HylcPatternSetFromOptions, p, &code, msg, sizeof(msg)));
  HYLC_CHECK(code == PETSC_ERR_USER && strstr(msg, "Unknown option woolly for -pattern_type. Available options: file plain basket twill satin stockinette rib wave"), "-pattern_type woolly: code %d, message '%s'", (int)code, msg);
  PetscCall(PetscOptionsClearValue(NULL, "-pattern_type"));
  PetscCall(PetscOptionsClearValue(NULL, "-pattern_size"));
  PetscCall(HylcPatternDestroy(&p));

  /* HylcPatternGenerate() by name, with its parameter checks */
  PetscCall(HylcPatternCreate(PETSC_COMM_WORLD, &p));
  PetscCall(HylcPatternGenParamsDefault(&g));
  g.radius = 2e-3;
  PetscCall(HylcPatternGenerate(p, "wave", &g));
  PetscCall(HylcPatternGetNumVertices(p, &nv));
  PetscCall(HylcPatternGetPeriods(p, &px, &py));
  HYLC_CHECK(nv == 16, "the wave of size 1 has %" PetscInt_FMT " vertices, expected 16", nv);
  HYLC_CHECK_CLOSE(px, 16e-3, 1e-14);
  PetscCall(HylcPatternDestroy(&p));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
