/* Material files and contents:
   - Python repr() of doubles (what json.dumps writes);
   - every JSON table in $HYLC_REFDATA/materials loads, evaluates finite, and load + WriteJSON reproduces it byte
     for byte, also through HDF5 (JSON -> HDF5 -> material -> JSON); skipped with a note when absent;
   - a material with absent terms and non-default extrapolation round-trips through both formats;
   - malformed JSON and HDF5 and invalid contents are refused with messages naming the file, line and key
     path (checked here through PetscErrorMessage; the program-level messages in eval_tool.sh). */
#include <hylc/material.h>
#include <hylc/private/materialimpl.h>
#include <dirent.h>
#include <hdf5.h>
#include <stdlib.h>
#include <string.h>
#include "hylctest.h"

static PetscErrorCode ReadAll(const char path[], char **text, size_t *len)
{
  FILE *fp = fopen(path, "rb");
  long  n;

  PetscFunctionBegin;
  *text = NULL;
  *len  = 0;
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot open %s", path);
  fseek(fp, 0, SEEK_END);
  n = ftell(fp);
  rewind(fp);
  PetscCall(PetscMalloc1(n + 1, text));
  *len          = fread(*text, 1, (size_t)n, fp);
  (*text)[*len] = 0;
  fclose(fp);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscBool SameFiles(const char a[], const char b[])
{
  char     *ta, *tb;
  size_t    la, lb;
  PetscBool same;

  if (ReadAll(a, &ta, &la) || ReadAll(b, &tb, &lb)) return PETSC_FALSE;
  same = (PetscBool)(la == lb && !memcmp(ta, tb, la));
  if (!same)
    for (size_t i = 0; i < PetscMin(la, lb); i++)
      if (ta[i] != tb[i]) {
        fprintf(stderr, "%s and %s differ first at byte %zu\n", a, b, i);
        break;
      }
  PetscFree(ta);
  PetscFree(tb);
  return same;
}

static void CheckRepr(double x, const char *want)
{
  char b[32];
  HYLC_CHECK(!strcmp(HylcFormatDoubleRepr(x, b), want), "repr(%.17g) = %s, expected %s", x, b, want);
}

/* the error of f(...) must be code and its message must contain want */
#define CHECK_ERROR(call, code, want)                                                                                  \
  do {                                                                                                                 \
    PetscErrorCode ierr_;                                                                                              \
    const char    *text_;                                                                                              \
    char          *spec_ = NULL;                                                                                       \
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));                                                   \
    ierr_ = (call);                                                                                                    \
    PetscCall(PetscPopErrorHandler());                                                                                 \
    PetscErrorMessage(ierr_, &text_, &spec_);                                                                          \
    HYLC_CHECK(ierr_ == (code), "%s: error %d, expected %d (%s)", #call, (int)ierr_, (int)(code), spec_ ? spec_ : ""); \
    HYLC_CHECK(spec_ &&strstr(spec_, want), "%s: message '%s' lacks '%s'", #call, spec_ ? spec_ : "", want);           \
  } while (0)

static PetscErrorCode TestRefdata(HylcMaterial m, const char dir[])
{
  DIR           *d = opendir(dir);
  struct dirent *e;
  int            n = 0;

  PetscFunctionBegin;
  PetscCheck(d, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot list %s", dir);
  while ((e = readdir(d))) {
    char               path[PETSC_MAX_PATH_LEN], name[256];
    size_t             l  = strlen(e->d_name);
    unsigned long long st = 5;
    double             sc[5];
    if (l < 6 || strcmp(e->d_name + l - 5, ".json")) continue;
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, e->d_name));
    PetscCall(PetscStrncpy(name, e->d_name, sizeof(name)));
    PetscCall(HylcMaterialLoad(m, path));
    PetscCall(HylcMaterialWriteJSON(m, "copy.json"));
    HYLC_CHECK(SameFiles(path, "copy.json"), "%s: load + WriteJSON does not reproduce the file", name);
    PetscCall(HylcMaterialWriteHDF5(m, "copy.h5", "-test options"));
    PetscCall(HylcMaterialReset(m));
    PetscCall(HylcMaterialLoad(m, "copy.h5"));
    PetscCall(HylcMaterialWriteJSON(m, "copy2.json"));
    HYLC_CHECK(SameFiles(path, "copy2.json"), "%s: JSON -> HDF5 -> JSON does not reproduce the file", name);
    /* 5 1D and 9 2D terms; finite values in and beyond the range */
    for (int k = 0; k < 5; k++) {
      const HylcSpline1D *s;
      PetscCall(HylcMaterialGet1D(m, k, &s));
      HYLC_CHECK(s && s->n == 11, "%s: 1D term %d", name, k);
    }
    for (int q = 0; q < 9; q++) {
      const HylcSpline2D *s;
      PetscCall(HylcMaterialGet2D(m, HylcMaterialPairs[q][0], HylcMaterialPairs[q][1], &s));
      HYLC_CHECK(s != NULL, "%s: 2D term %d", name, q);
    }
    PetscCall(HylcMaterialGetStrainScale(m, sc));
    for (int it = 0; it < 200; it++) {
      double s[6], E, g[6], H[36];
      for (int k = 0; k < 6; k++) s[k] = 3 * (HylcTestRand(&st) - 0.5) * sc[k < 5 ? (k == 4 ? 3 : k) : 4];
      if (it % 3 == 0) s[3] = s[4] = s[5] = 0;
      PetscCall(HylcMaterialEvaluate(m, s, &E, g, H));
      HYLC_CHECK(isfinite(E), "%s: Psi not finite", name);
      for (int i = 0; i < 6; i++) HYLC_CHECK(isfinite(g[i]), "%s: gradient not finite", name);
      for (int i = 0; i < 36; i++) HYLC_CHECK(isfinite(H[i]), "%s: Hessian not finite", name);
    }
    n++;
  }
  closedir(d);
  HYLC_CHECK(n >= 9, "only %d JSON materials in %s", n, dir);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a small material: some terms absent, non-default extrapolation, awkward numbers */
static PetscErrorCode Small(HylcMaterial m)
{
  double       t[3] = {-0.5, 0.0, 0.7}, p[3] = {1e-5, -0.0, 200.0}, mm[3] = {0.1, 3.7599491320428058e-06, -1e22};
  double       tu[2] = {-1, 1}, tv[3] = {0, 0.25, 1.5}, P[6] = {0, 1, 2, 3, 4, 5}, U[6] = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5}, V[6] = {1, 1, 1, 1, 1, 1}, W[6] = {0, 0, 0, 0, 0, 0};
  double       scale[5] = {0.8, 0.75, 0.8, 200, 230};
  PetscInt     shift[5] = {1, 0, 1, 0, 0};
  HylcSpline1D s1       = {3, 3, t, p, mm, HYLC_EXT_CONSTANT};
  HylcSpline2D s2       = {1, 4, 2, 3, tu, tv, P, U, V, W, HYLC_EXT_ZERO};
  HylcSpline1D s0       = {0, 3, t, p, mm, HYLC_EXT_LINEAR};

  PetscFunctionBegin;
  PetscCall(HylcMaterialReset(m));
  PetscCall(HylcMaterialSetDensity(m, 0.33182390968));
  PetscCall(HylcMaterialSetStrainScale(m, scale));
  PetscCall(HylcMaterialSetStrainShift(m, shift));
  PetscCall(HylcMaterialSetConstant(m, 0.05526709407619351));
  PetscCall(HylcMaterialSet1D(m, &s1));
  PetscCall(HylcMaterialSet1D(m, &s0));
  PetscCall(HylcMaterialSet2D(m, &s2));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestRoundTrip(HylcMaterial m)
{
  char  *text;
  size_t len;
  double sc[5], E0, E1, s[6] = {0.1, -0.2, 0.3, 40, -12, 300};

  PetscFunctionBegin;
  PetscCall(Small(m));
  PetscCall(HylcMaterialEvaluate(m, s, &E0, NULL, NULL));
  PetscCall(HylcMaterialWriteJSON(m, "small.json"));
  PetscCall(ReadAll("small.json", &text, &len));
  HYLC_CHECK(strstr(text, "\"ext\": 1") && strstr(text, "\"ext\": 2") && !strstr(text, "\"ext\": 0"), "ext written only when not linear");
  HYLC_CHECK(strstr(text, "        \"p\": [\n          1e-05,\n          -0.0,\n          200.0\n        ],") != NULL, "layout of a 1D term:\n%s", text);
  HYLC_CHECK(strstr(text, "-1e+22") && strstr(text, "3.7599491320428058e-06"), "exponent formats");
  HYLC_CHECK(text[len - 1] == '}' && text[len - 2] == '\n', "no final newline");
  PetscCall(PetscFree(text));
  PetscCall(HylcMaterialReset(m));
  PetscCall(HylcMaterialLoad(m, "small.json"));
  PetscCall(HylcMaterialWriteJSON(m, "small2.json"));
  HYLC_CHECK(SameFiles("small.json", "small2.json"), "JSON round trip of the small material");
  PetscCall(HylcMaterialWriteHDF5(m, "small.h5", NULL));
  PetscCall(HylcMaterialReset(m));
  PetscCall(HylcMaterialLoad(m, "small.h5"));
  PetscCall(HylcMaterialWriteJSON(m, "small3.json"));
  HYLC_CHECK(SameFiles("small.json", "small3.json"), "HDF5 round trip of the small material");
  PetscCall(HylcMaterialEvaluate(m, s, &E1, NULL, NULL));
  HYLC_CHECK(E0 == E1, "Psi after the round trips %.17g, before %.17g", E1, E0);
  {
    const HylcSpline1D *a;
    const HylcSpline2D *b;
    PetscCall(HylcMaterialGet1D(m, 1, &a));
    HYLC_CHECK(a == NULL, "absent 1D term present after the round trip");
    PetscCall(HylcMaterialGet1D(m, 3, &a));
    HYLC_CHECK(a && a->ext == HYLC_EXT_CONSTANT && a->n == 3 && signbit(a->p[1]), "1D term after the round trip");
    PetscCall(HylcMaterialGet2D(m, 1, 4, &b));
    HYLC_CHECK(b && b->ext == HYLC_EXT_ZERO && b->nu == 2 && b->nv == 3 && b->p[4] == 4, "2D term after the round trip");
    PetscCall(HylcMaterialGet2D(m, 0, 1, &b));
    HYLC_CHECK(b == NULL, "absent 2D term present after the round trip");
  }
  PetscCall(HylcMaterialGetStrainScale(m, sc));
  HYLC_CHECK(sc[4] == 230, "strain scale");
  /* an empty material writes and reads */
  PetscCall(HylcMaterialReset(m));
  PetscCall(HylcMaterialWriteJSON(m, "empty.json"));
  PetscCall(ReadAll("empty.json", &text, &len));
  HYLC_CHECK(strstr(text, "\"1D\": [],\n    \"2D\": []\n  }\n}") != NULL, "empty term lists:\n%s", text);
  PetscCall(PetscFree(text));
  PetscCall(HylcMaterialLoad(m, "empty.json"));
  PetscCall(HylcMaterialEvaluate(m, s, &E1, NULL, NULL));
  HYLC_CHECK(E1 == 0, "Psi of the empty material %g", E1);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char Good[] = "{\n"
                           "  \"density\": 0.3,\n"
                           "  \"strain scale\": [1.0, 1.0, 1.0, 100.0, 100.0],\n"
                           "  \"coeffs\": {\n"
                           "    \"const\": 0.5,\n"
                           "    \"1D\": [{\"k\": 3, \"t\": [-1.0, 0.0, 1.0], \"p\": [1, 0, 1], \"m\": [-1, 0, 1]}],\n"
                           "    \"2D\": [{\"k0\": 0, \"k1\": 3, \"tu\": [0, 1], \"tv\": [0, 1], \"p\": [0, 0, 0, 1], \"mu\": [0, 0, 0, 0], \"mv\": [0, 0, 0, 0], \"muv\": [0, 0, 0, 0], \"ext\": 1}]\n"
                           "  }\n"
                           "}\n";

/* Good with the first occurrence of from replaced by to */
static PetscErrorCode Variant(const char from[], const char to[], char out[4096])
{
  const char *at = strstr(Good, from);

  PetscFunctionBegin;
  PetscCheck(at, PETSC_COMM_SELF, PETSC_ERR_PLIB, "test bug: '%s' not in the base text", from);
  snprintf(out, 4096, "%.*s%s%s", (int)(at - Good), Good, to, at + strlen(from));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestErrors(HylcMaterial m)
{
  char t[4096];

  PetscFunctionBegin;
  PetscCall(HylcMaterialLoadFromString(m, "good.json", Good));
  {
    const HylcSpline2D *b;
    PetscCall(HylcMaterialGet2D(m, 0, 3, &b));
    HYLC_CHECK(b && b->ext == HYLC_EXT_CONSTANT, "good.json: 2D term");
  }
  /* syntax */
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", ""), PETSC_ERR_USER_INPUT, "e.json: empty file");
  PetscCall(Variant("0.5,", "0.5", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:6: expected ',' or '}'");
  PetscCall(Variant("[1, 0, 1]", "[1, 0, 1,]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:6: trailing comma");
  PetscCall(Variant("0.3", "NaN", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:2: expected a value, found 'NaN");
  PetscCall(Variant("0.3", "1e999", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:2: number 1e999 is out of the range");
  PetscCall(Variant("0.3", "01", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:2: expected ',' or '}'");
  PetscCall(Variant("0.3", "1.", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:2: malformed number");
  PetscCall(Variant("\"density\"", "\"density", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:2: control character");
  PetscCall(Variant("\"density\"", "\"d\\qensity\"", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "invalid escape '\\q'");
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", "{\"density\": 1}\n{}"), PETSC_ERR_USER_INPUT, "e.json:2: unexpected text after the end");
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", "{\"density\": 1, \"density\": 2}"), PETSC_ERR_USER_INPUT, "e.json:1: duplicate key \"density\"");
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", "{\"density\": [[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]}"), PETSC_ERR_USER_INPUT,
              "nesting deeper");
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", "{\"density\": \"\\u12\"}"), PETSC_ERR_USER_INPUT, "invalid \\u escape");
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", "[1, 2"), PETSC_ERR_USER_INPUT, "e.json:1: end of file inside the array opened at line 1");
  /* schema */
  PetscCall(Variant("\"const\"", "\"cnst\"", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:5: coeffs: unknown key \"cnst\"");
  PetscCall(Variant("  \"density\": 0.3,\n", "", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:1: missing key \"density\"");
  PetscCall(Variant("\"p\": [1, 0, 1]", "\"p\": [1, 0]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:6: coeffs.1D[0].p: expected 3 numbers (one per knot), got 2");
  PetscCall(Variant("\"muv\": [0, 0, 0, 0]", "\"muv\": [0, 0, 0]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:7: coeffs.2D[0].muv: expected 4 numbers (len(tu) * len(tv) = 2 * 2), got 3");
  PetscCall(Variant("[-1.0, 0.0, 1.0]", "[-1.0, 1.0, 0.0]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:6: coeffs.1D[0].t[2]: knots must be strictly increasing");
  PetscCall(Variant("\"k\": 3", "\"k\": 5", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "coeffs.1D[0].k: expected an integer in 0..4");
  PetscCall(Variant("\"k\": 3", "\"k\": 2.5", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "coeffs.1D[0].k: expected an integer in 0..4");
  PetscCall(Variant("\"k1\": 3", "\"k1\": 2, \"k0\": 1", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "duplicate key \"k0\"");
  PetscCall(Variant("\"k0\": 0, \"k1\": 3", "\"k0\": 2, \"k1\": 1", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "coeffs.2D[0]: (k0, k1) = (2, 1) is not a term of the model");
  PetscCall(Variant("\"ext\": 1", "\"ext\": 3", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "coeffs.2D[0].ext: expected an integer in 0..2");
  PetscCall(Variant("[1.0, 1.0, 1.0, 100.0, 100.0]", "[1.0, 1.0, 0.0, 100.0, 100.0]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:3: strain scale[2]: must be positive");
  PetscCall(Variant("[1.0, 1.0, 1.0, 100.0, 100.0]", "[1.0, 1.0, 100.0, 100.0]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:3: strain scale: expected 5 numbers");
  PetscCall(Variant("[1, 0, 1]", "[1, \"0\", 1]", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "coeffs.1D[0].p[1]: expected a number, got a string");
  PetscCall(Variant("[{\"k\": 3,", "[{\"k\": 3, \"t\": [0, 1], \"p\": [0, 0], \"m\": [0, 0]}, {\"k\": 3,", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "coeffs.1D[1]: a second term with k = 3");
  PetscCall(Variant("0.3", "-0.3", t));
  CHECK_ERROR(HylcMaterialLoadFromString(m, "e.json", t), PETSC_ERR_USER_INPUT, "e.json:2: density: the area density must be in [0, 1e+06] kg/m^2, got -0.3");
  /* a failed load leaves the material unchanged */
  {
    const HylcSpline2D *b;
    PetscCall(HylcMaterialGet2D(m, 0, 3, &b));
    HYLC_CHECK(b != NULL, "a failed load changed the material");
  }
  /* files */
  CHECK_ERROR(HylcMaterialLoad(m, "no/such/file.json"), PETSC_ERR_FILE_OPEN, "Cannot open material file 'no/such/file.json'");
  {
    FILE *fp = fopen("trunc.h5", "wb");
    fwrite("\211HDF\r\n\032\n\0\0\0\0", 1, 12, fp);
    fclose(fp);
    CHECK_ERROR(HylcMaterialLoad(m, "trunc.h5"), PETSC_ERR_FILE_READ, "trunc.h5: cannot open as HDF5");
  }
  {
    hid_t f = H5Fcreate("other.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    H5Fclose(f);
    CHECK_ERROR(HylcMaterialLoad(m, "other.h5"), PETSC_ERR_FILE_UNEXPECTED, "other.h5: an HDF5 file without the root attribute 'format'");
  }
  CHECK_ERROR(HylcMaterialWriteJSON(m, "no/such/dir/out.json"), PETSC_ERR_FILE_WRITE, "Cannot write the JSON material file 'no/such/dir/out.json'");
  /* contents */
  {
    double       t3[3] = {0, 1, 1}, p3[3] = {0, 0, 0}, nan3[3] = {0, NAN, 0}, scale[5] = {1, 1, 1, 1, 0};
    HylcSpline1D s = {2, 3, t3, p3, p3, HYLC_EXT_LINEAR};
    CHECK_ERROR(HylcMaterialSet1D(m, &s), PETSC_ERR_USER_INPUT, "1D term sy (k = 2): knots t must be strictly increasing, but t[2] = 1 <= t[1] = 1");
    t3[2] = 2;
    s.p   = nan3;
    CHECK_ERROR(HylcMaterialSet1D(m, &s), PETSC_ERR_USER_INPUT, "1D term sy (k = 2): p[1] = nan is not finite");
    s.p = p3;
    s.n = 1;
    CHECK_ERROR(HylcMaterialSet1D(m, &s), PETSC_ERR_USER_INPUT, "needs at least 2 knots");
    s.n = 3;
    s.k = 5;
    CHECK_ERROR(HylcMaterialSet1D(m, &s), PETSC_ERR_USER_INPUT, "k = 5 is out of range");
    s.k   = 0;
    s.ext = (HylcSplineExt)7;
    CHECK_ERROR(HylcMaterialSet1D(m, &s), PETSC_ERR_USER_INPUT, "extrapolation mode 7");
    {
      HylcSpline2D s2 = {3, 4, 3, 3, t3, t3, p3, p3, p3, p3, HYLC_EXT_LINEAR};
      CHECK_ERROR(HylcMaterialSet2D(m, &s2), PETSC_ERR_USER_INPUT, "(k0, k1) = (3, 4) is not a term of the model");
    }
    CHECK_ERROR(HylcMaterialSetStrainScale(m, scale), PETSC_ERR_USER_INPUT, "Strain scale 4 (II11) must be finite and positive");
    CHECK_ERROR(HylcMaterialSetDensity(m, -1), PETSC_ERR_USER_INPUT, "density must be finite and in [0, 1e+06] kg/m^2, got -1");
    CHECK_ERROR(HylcMaterialSetConstant(m, INFINITY), PETSC_ERR_USER_INPUT, "constant must be finite");
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  HylcMaterial m;
  char         dir[PETSC_MAX_PATH_LEN];
  PetscBool    have;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  CheckRepr(0.0, "0.0");
  CheckRepr(-0.0, "-0.0");
  CheckRepr(1e-5, "1e-05");
  CheckRepr(1.5e-5, "1.5e-05");
  CheckRepr(1e-4, "0.0001");
  CheckRepr(0.00011, "0.00011");
  CheckRepr(200.0, "200.0");
  CheckRepr(-0.8, "-0.8");
  CheckRepr(0.1 + 0.2, "0.30000000000000004");
  CheckRepr(3.7599491320428058e-06, "3.7599491320428058e-06");
  CheckRepr(1e16, "1e+16");
  CheckRepr(9999999999999998.0, "9999999999999998.0");
  CheckRepr(123456789012345680.0, "1.2345678901234568e+17");
  CheckRepr(5e-324, "5e-324");
  CheckRepr(1.7976931348623157e308, "1.7976931348623157e+308");
  CheckRepr(-1e22, "-1e+22");
  CheckRepr(0.6174999999999999, "0.6174999999999999");
  CheckRepr(2.0 / 3.0, "0.6666666666666666");
  CheckRepr(1152921504606846976.0, "1.152921504606847e+18"); /* 2^60 */
  CheckRepr(9007199254740993.0, "9007199254740992.0");       /* 2^53 + 1 rounds to 2^53 */

  PetscCall(HylcMaterialCreate(PETSC_COMM_SELF, &m));
  PetscCall(TestRoundTrip(m));
  PetscCall(TestErrors(m));
  {
    const char *env = getenv("HYLC_REFDATA");
    PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/materials", env ? env : "../shared/refdata"));
  }
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (have)
    PetscCall(TestRefdata(m, dir));
  else
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "note: %s not found: the round trips of the paper's tables were skipped\n", dir));
  PetscCall(HylcMaterialDestroy(&m));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
