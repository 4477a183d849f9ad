/* The hylc HDF5 material format (docs/material.md): built and parsed as in-memory file images (HDF5's core
   driver), so that every rank parses the same bytes (collective errors) and rank 0 writes the file with
   plain, atomic stdio. */
#include <hylc/private/materialimpl.h>
#include <hdf5.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define MATERIAL_FORMAT         "hylc-material"
#define MATERIAL_FORMAT_VERSION 1
/* the name of the in-memory files: HDF5's core driver refuses to open an image under a name that
   exists on disk, so it must not */
#define IMAGE_NAME "/nonexistent-hylc-directory/hylc-material-image.h5"

/* the file the current HDF5 call works on, for messages */
static const char *H5File = "?";

static herr_t ErrorWalk(unsigned n, const H5E_error2_t *e, void *ctx)
{
  (void)n;
  if (e->desc && e->desc[0]) snprintf((char *)ctx, 256, ", HDF5: %s", e->desc);
  return 0;
}

static void ErrorText(char buf[256])
{
  buf[0] = 0;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, ErrorWalk, buf);
}

/* CallH5(call): a negative return of a raw HDF5 call becomes a PETSc error naming the call and the file */
#define CallH5(...)                                                                                         \
  do {                                                                                                      \
    if ((__VA_ARGS__) < 0) {                                                                                \
      char h5msg_[256];                                                                                     \
      ErrorText(h5msg_);                                                                                    \
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 call %s failed on %s%s", #__VA_ARGS__, H5File, h5msg_); \
    }                                                                                                       \
  } while (0)
#define CallH5Id(id, ...) \
  do {                    \
    (id) = (__VA_ARGS__); \
    CallH5(id);           \
  } while (0)

/* ------------------------------------------------------------------------------------------------ */
/* Writing                                                                                            */
/* ------------------------------------------------------------------------------------------------ */

static PetscErrorCode AttrString(hid_t loc, const char name[], const char value[])
{
  hid_t t, s, a;

  PetscFunctionBegin;
  CallH5Id(t, H5Tcopy(H5T_C_S1));
  CallH5(H5Tset_size(t, H5T_VARIABLE));
  CallH5(H5Tset_cset(t, H5T_CSET_UTF8));
  CallH5Id(s, H5Screate(H5S_SCALAR));
  CallH5Id(a, H5Acreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT));
  CallH5(H5Awrite(a, t, &value));
  CallH5(H5Aclose(a));
  CallH5(H5Sclose(s));
  CallH5(H5Tclose(t));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AttrLong(hid_t loc, const char name[], long long v)
{
  hid_t s, a;

  PetscFunctionBegin;
  CallH5Id(s, H5Screate(H5S_SCALAR));
  CallH5Id(a, H5Acreate2(loc, name, H5T_STD_I64LE, s, H5P_DEFAULT, H5P_DEFAULT));
  CallH5(H5Awrite(a, H5T_NATIVE_LLONG, &v));
  CallH5(H5Aclose(a));
  CallH5(H5Sclose(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a dataset of doubles (or int32 if ints) of rank 0 (dims NULL), 1 or 2, with units and description */
static PetscErrorCode Dataset(hid_t loc, const char name[], int rank, const hsize_t dims[], const double *dv, const int *iv, const char units[], const char description[])
{
  hid_t s, d;

  PetscFunctionBegin;
  if (rank)
    CallH5Id(s, H5Screate_simple(rank, dims, NULL));
  else
    CallH5Id(s, H5Screate(H5S_SCALAR));
  CallH5Id(d, H5Dcreate2(loc, name, iv ? H5T_STD_I32LE : H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  CallH5(H5Dwrite(d, iv ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, iv ? (const void *)iv : (const void *)dv));
  PetscCall(AttrString(d, "units", units));
  PetscCall(AttrString(d, "description", description));
  CallH5(H5Dclose(d));
  CallH5(H5Sclose(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char *const ExtNames[] = {"linear", "constant", "zero"};

static PetscErrorCode WriteContents(hid_t file, HylcMaterial m, const char optionsText[])
{
  char              date[64], petscv[128], h5v[64], desc[512];
  time_t            now = time(NULL);
  struct tm         tm;
  unsigned          maj, min, rel;
  char             *allopts = NULL;
  hid_t             g1, g2, g;
  hsize_t           dim5 = 5;
  double            scale[5];
  int               shift[5];
  const char *const coordinate[5] = {"sx (stretch along x)", "sa (shear: cosine of the angle between the deformed material axes)", "sy (stretch along y)", "x-bending curvature (eigenvalue of II)", "y-bending curvature (eigenvalue of II)"};

  PetscFunctionBegin;
  gmtime_r(&now, &tm);
  strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", &tm);
  PetscCall(PetscGetVersion(petscv, sizeof(petscv)));
  CallH5(H5get_libversion(&maj, &min, &rel));
  snprintf(h5v, sizeof(h5v), "%u.%u.%u", maj, min, rel);
  if (!optionsText) PetscCall(PetscOptionsGetAll(NULL, &allopts));
  PetscCall(AttrString(file, "format", MATERIAL_FORMAT));
  PetscCall(AttrLong(file, "format_version", MATERIAL_FORMAT_VERSION));
  PetscCall(AttrString(file, "description", "Homogenized yarn-level cloth material: Psi(s) = constant + 1D terms f_k(s_k / sigma_k) + 2D terms f_k0k1(s_k0 / sigma_k0, s_k1 / sigma_k1), cubic/bicubic Hermite splines in normalized strains, bending terms split over the eigenvalues of II (docs/material.md). Equivalent to the ARCSim-HYLC JSON."));
  PetscCall(AttrString(file, "hylc_version", HYLC_VERSION_STRING));
  PetscCall(AttrString(file, "petsc_version", petscv));
  PetscCall(AttrString(file, "hdf5_version", h5v));
  PetscCall(AttrString(file, "creation_date", date));
  PetscCall(AttrString(file, "source", m->source));
  PetscCall(AttrString(file, "options", optionsText ? optionsText : (allopts ? allopts : "")));
  PetscCall(PetscFree(allopts));

  for (int k = 0; k < 5; k++) {
    scale[k] = (double)m->scale[k];
    shift[k] = (int)m->shift[k];
  }
  {
    double v = (double)m->density;
    PetscCall(Dataset(file, "density", 0, NULL, &v, NULL, "kg/m^2", "area density rho_A of the cloth (mass per reference area)"));
    v = (double)m->C0;
    PetscCall(Dataset(file, "constant", 0, NULL, &v, NULL, "J/m^2", "constant term C0 of Psi (Psi of the zero-strain sample)"));
  }
  PetscCall(Dataset(file, "strain_scale", 1, &dim5, scale, NULL, "1, 1, 1, 1/m, 1/m", "normalization sigma_k of the coordinates sx, sa, sy, x-bending, y-bending: the spline abscissae are s_k / sigma_k"));
  PetscCall(Dataset(file, "strain_shift", 1, &dim5, NULL, shift, "1", "the JSON's informational 'strain shift' (1,0,1,0,0: sx and sy are 0-centred stretches); not used by the evaluator"));

  CallH5Id(g1, H5Gcreate2(file, "1D", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  PetscCall(AttrString(g1, "description", "one-dimensional terms f_k(x), x = s_k / sigma_k, one group per term present: cubic Hermite spline with knots t, values p, slopes m = df/dx"));
  for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) {
    const HylcSpline1D *s = &m->t1[k];
    hsize_t             n;
    if (!m->has1[k]) continue;
    n = (hsize_t)s->n;
    CallH5Id(g, H5Gcreate2(g1, HylcMaterialTermNames1D[k], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    snprintf(desc, sizeof(desc), "f_%d(x) of the coordinate %s, x = s / %.17g", (int)k, coordinate[k], scale[k]);
    PetscCall(AttrString(g, "description", desc));
    PetscCall(AttrLong(g, "k", (long long)k));
    PetscCall(AttrLong(g, "ext", (long long)s->ext));
    PetscCall(AttrString(g, "extrapolation", ExtNames[s->ext]));
    PetscCall(Dataset(g, "t", 1, &n, s->t, NULL, "1", "knots (normalized strain), strictly increasing"));
    PetscCall(Dataset(g, "p", 1, &n, s->p, NULL, "J/m^2", "values at the knots"));
    PetscCall(Dataset(g, "m", 1, &n, s->m, NULL, "J/m^2", "slopes df/dx at the knots (per unit normalized strain)"));
    CallH5(H5Gclose(g));
  }
  CallH5(H5Gclose(g1));

  CallH5Id(g2, H5Gcreate2(file, "2D", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  PetscCall(AttrString(g2, "description", "two-dimensional terms f_k0k1(u, v), u = s_k0 / sigma_k0, v = s_k1 / sigma_k1, one group per term present: bicubic Hermite spline with knots tu, tv and node arrays of shape (len(tv), len(tu)): p[iv, iu] is the value at (tu[iu], tv[iv])"));
  for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) {
    const HylcSpline2D *s = &m->t2[q];
    hsize_t             nu, nv, dims[2];
    if (!m->has2[q]) continue;
    nu      = (hsize_t)s->nu;
    nv      = (hsize_t)s->nv;
    dims[0] = nv;
    dims[1] = nu;
    CallH5Id(g, H5Gcreate2(g2, HylcMaterialTermNames2D[q], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    snprintf(desc, sizeof(desc), "f_%d%d(u, v) of the coordinates u = %s / %.17g and v = %s / %.17g", (int)s->k0, (int)s->k1, coordinate[s->k0], scale[s->k0], coordinate[s->k1], scale[s->k1]);
    PetscCall(AttrString(g, "description", desc));
    PetscCall(AttrLong(g, "k0", (long long)s->k0));
    PetscCall(AttrLong(g, "k1", (long long)s->k1));
    PetscCall(AttrLong(g, "ext", (long long)s->ext));
    PetscCall(AttrString(g, "extrapolation", ExtNames[s->ext]));
    PetscCall(Dataset(g, "tu", 1, &nu, s->tu, NULL, "1", "knots of u (normalized strain k0), strictly increasing"));
    PetscCall(Dataset(g, "tv", 1, &nv, s->tv, NULL, "1", "knots of v (normalized strain k1), strictly increasing"));
    PetscCall(Dataset(g, "p", 2, dims, s->p, NULL, "J/m^2", "values at the nodes, p[iv, iu] at (tu[iu], tv[iv])"));
    PetscCall(Dataset(g, "mu", 2, dims, s->mu, NULL, "J/m^2", "df/du at the nodes"));
    PetscCall(Dataset(g, "mv", 2, dims, s->mv, NULL, "J/m^2", "df/dv at the nodes"));
    PetscCall(Dataset(g, "muv", 2, dims, s->muv, NULL, "J/m^2", "d2f/dudv at the nodes"));
    CallH5(H5Gclose(g));
  }
  CallH5(H5Gclose(g2));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialFormatHDF5_Private(HylcMaterial m, const char optionsText[], void **image, size_t *len)
{
  hid_t          fapl, file;
  ssize_t        size = -1;
  H5E_auto2_t    efunc;
  void          *edata;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  *image = NULL;
  *len   = 0;
  H5File = "the in-memory HDF5 image";
  H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl >= 0 && (H5Pset_fapl_core(fapl, 1 << 16, 0) < 0 || H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0)) {
    H5Pclose(fapl);
    fapl = -1;
  }
  file = fapl >= 0 ? H5Fcreate(IMAGE_NAME, H5F_ACC_TRUNC, H5P_DEFAULT, fapl) : -1;
  if (file < 0) {
    char msg[256];
    ErrorText(msg);
    if (fapl >= 0) H5Pclose(fapl);
    H5Eset_auto2(H5E_DEFAULT, efunc, edata);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot create an in-memory HDF5 file%s", msg);
  }
  ierr = WriteContents(file, m, optionsText);
  if (!ierr && H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0) size = H5Fget_file_image(file, NULL, 0);
  if (!ierr && size > 0) {
    ierr = PetscMalloc(size, image);
    if (!ierr && H5Fget_file_image(file, *image, (size_t)size) != size) size = -1;
  }
  H5Fclose(file);
  H5Pclose(fapl);
  H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  if (!ierr && size <= 0) {
    PetscCall(PetscFree(*image));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot get the image of the in-memory HDF5 file");
  }
  if (ierr) PetscCall(PetscFree(*image));
  PetscCall(ierr);
  *len = (size_t)size;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ------------------------------------------------------------------------------------------------ */
/* Reading                                                                                            */
/* ------------------------------------------------------------------------------------------------ */

static PetscErrorCode Exists(const HylcMaterialDoc *d, hid_t loc, const char path[], const char name[], PetscBool required, PetscBool *has)
{
  htri_t e;

  PetscFunctionBegin;
  CallH5Id(e, H5Lexists(loc, name, H5P_DEFAULT));
  PetscCheck(e > 0 || !required, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: %s%s is missing", d->name, path, name);
  if (has) *has = (PetscBool)(e > 0);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a string attribute (variable or fixed length) into buf */
static PetscErrorCode ReadAttrString(const HylcMaterialDoc *d, hid_t loc, const char path[], const char name[], char buf[], size_t size)
{
  hid_t  a, t, mt;
  htri_t vlen;

  PetscFunctionBegin;
  buf[0] = 0;
  CallH5Id(a, H5Aopen(loc, name, H5P_DEFAULT));
  CallH5Id(t, H5Aget_type(a));
  PetscCheck(H5Tget_class(t) == H5T_STRING, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: attribute %s@%s is not a string", d->name, path, name);
  CallH5Id(vlen, H5Tis_variable_str(t));
  CallH5Id(mt, H5Tcopy(H5T_C_S1));
  CallH5(H5Tset_cset(mt, H5Tget_cset(t)));
  if (vlen) {
    char *s = NULL;
    CallH5(H5Tset_size(mt, H5T_VARIABLE));
    CallH5(H5Aread(a, mt, &s));
    if (s) {
      snprintf(buf, size, "%s", s);
      H5free_memory(s);
    }
  } else {
    size_t n = H5Tget_size(t);
    char  *s;
    PetscCall(PetscCalloc1(n + 1, &s));
    CallH5(H5Tset_size(mt, n + 1));
    CallH5(H5Aread(a, mt, s));
    snprintf(buf, size, "%s", s);
    PetscCall(PetscFree(s));
  }
  CallH5(H5Tclose(mt));
  CallH5(H5Tclose(t));
  CallH5(H5Aclose(a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadAttrLong(const HylcMaterialDoc *d, hid_t loc, const char path[], const char name[], long long *v)
{
  hid_t  a, s;
  htri_t e;

  PetscFunctionBegin;
  CallH5Id(e, H5Aexists(loc, name));
  PetscCheck(e > 0, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: attribute %s@%s is missing", d->name, path, name);
  CallH5Id(a, H5Aopen(loc, name, H5P_DEFAULT));
  CallH5Id(s, H5Aget_space(a));
  PetscCheck(H5Sget_simple_extent_npoints(s) == 1, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: attribute %s@%s must be a scalar", d->name, path, name);
  CallH5(H5Aread(a, H5T_NATIVE_LLONG, v));
  CallH5(H5Sclose(s));
  CallH5(H5Aclose(a));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a dataset of the given rank with its dimensions (dims[0] outermost); the data as doubles (or ints) in
   freshly allocated *out */
static PetscErrorCode ReadData(const HylcMaterialDoc *d, hid_t loc, const char path[], const char name[], int rank, hsize_t dims[], PetscReal **out, PetscInt *iout)
{
  hid_t   ds, sp;
  int     r;
  hsize_t dd[2] = {1, 1}, n = 1;

  PetscFunctionBegin;
  PetscCall(Exists(d, loc, path, name, PETSC_TRUE, NULL));
  CallH5Id(ds, H5Dopen2(loc, name, H5P_DEFAULT));
  CallH5Id(sp, H5Dget_space(ds));
  CallH5Id(r, H5Sget_simple_extent_ndims(sp));
  PetscCheck(r == rank, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: dataset %s%s has rank %d, expected %d", d->name, path, name, r, rank);
  if (r) CallH5(H5Sget_simple_extent_dims(sp, dd, NULL));
  for (int i = 0; i < r; i++) {
    n *= dd[i];
    if (dims[i]) PetscCheck(dd[i] == dims[i], d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: dataset %s%s has dimension %d of size %llu, expected %llu", d->name, path, name, i, (unsigned long long)dd[i], (unsigned long long)dims[i]);
    dims[i] = dd[i];
  }
  PetscCheck(n < (1u << 28), d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: dataset %s%s is too large", d->name, path, name);
  if (out) {
    double *buf;
    PetscCall(PetscMalloc1(n + 1, &buf));
    CallH5(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf));
    PetscCall(PetscMalloc1(n + 1, out));
    for (hsize_t i = 0; i < n; i++) (*out)[i] = (PetscReal)buf[i];
    PetscCall(PetscFree(buf));
  } else {
    int *buf;
    PetscCall(PetscMalloc1(n + 1, &buf));
    CallH5(H5Dread(ds, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf));
    for (hsize_t i = 0; i < n; i++) iout[i] = (PetscInt)buf[i];
    PetscCall(PetscFree(buf));
  }
  CallH5(H5Sclose(sp));
  CallH5(H5Dclose(ds));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadScalar(const HylcMaterialDoc *d, hid_t loc, const char name[], PetscReal *v)
{
  PetscReal *buf;

  PetscFunctionBegin;
  PetscCall(ReadData(d, loc, "/", name, 0, NULL, &buf, NULL));
  *v = buf[0];
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* every member of group g must be one of the names[] */
static PetscErrorCode CheckMembers(const HylcMaterialDoc *d, hid_t g, const char path[], int nnames, const char *const names[])
{
  H5G_info_t info;

  PetscFunctionBegin;
  CallH5(H5Gget_info(g, &info));
  for (hsize_t i = 0; i < info.nlinks; i++) {
    char      name[256] = "";
    PetscBool ok        = PETSC_FALSE;
    CallH5(H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof(name), H5P_DEFAULT));
    for (int j = 0; j < nnames; j++) ok = (PetscBool)(ok || !strcmp(name, names[j]));
    PetscCheck(ok, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: unknown member %s%s", d->name, path, name);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadExt(const HylcMaterialDoc *d, hid_t g, const char path[], HylcSplineExt *ext)
{
  long long e;

  PetscFunctionBegin;
  PetscCall(ReadAttrLong(d, g, path, "ext", &e));
  PetscCheck(e >= 0 && e <= 2, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: %s@ext = %lld is not 0 (linear), 1 (constant) or 2 (zero)", d->name, path, e);
  *ext = (HylcSplineExt)e;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadContents(HylcMaterialDoc *d, hid_t file)
{
  char                     fmt[64];
  long long                version, v;
  hsize_t                  dim5 = 5;
  PetscReal               *buf;
  PetscBool                has;
  hid_t                    g1, g2, g;
  static const char *const top[] = {"density", "constant", "strain_scale", "strain_shift", "1D", "2D"};

  PetscFunctionBegin;
  {
    htri_t e;
    CallH5Id(e, H5Aexists(file, "format"));
    PetscCheck(e > 0, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: an HDF5 file without the root attribute 'format': not a hylc material file", d->name);
  }
  PetscCall(ReadAttrString(d, file, "/", "format", fmt, sizeof(fmt)));
  PetscCheck(!strcmp(fmt, MATERIAL_FORMAT), d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: an HDF5 file of format '%s', not a hylc material file ('%s')", d->name, fmt, MATERIAL_FORMAT);
  PetscCall(ReadAttrLong(d, file, "/", "format_version", &version));
  PetscCheck(version >= 1 && version <= MATERIAL_FORMAT_VERSION, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: material format version %lld is not supported (this hylc reads version %d)", d->name, version, MATERIAL_FORMAT_VERSION);
  PetscCall(CheckMembers(d, file, "/", 6, top));
  PetscCall(ReadScalar(d, file, "density", &d->density));
  PetscCall(ReadScalar(d, file, "constant", &d->C0));
  PetscCall(ReadData(d, file, "/", "strain_scale", 1, &dim5, &buf, NULL));
  for (int k = 0; k < 5; k++) d->scale[k] = buf[k];
  PetscCall(PetscFree(buf));
  PetscCall(Exists(d, file, "/", "strain_shift", PETSC_FALSE, &has));
  if (has) PetscCall(ReadData(d, file, "/", "strain_shift", 1, &dim5, NULL, d->shift));

  PetscCall(Exists(d, file, "/", "1D", PETSC_FALSE, &has));
  if (has) {
    CallH5Id(g1, H5Gopen2(file, "1D", H5P_DEFAULT));
    PetscCall(CheckMembers(d, g1, "/1D/", HYLC_MATERIAL_N1D, HylcMaterialTermNames1D));
    for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) {
      HylcSpline1D *s = &d->s1[d->n1];
      char          path[64];
      hsize_t       n = 0;
      PetscCall(Exists(d, g1, "/1D/", HylcMaterialTermNames1D[k], PETSC_FALSE, &has));
      if (!has) continue;
      snprintf(path, sizeof(path), "/1D/%s/", HylcMaterialTermNames1D[k]);
      CallH5Id(g, H5Gopen2(g1, HylcMaterialTermNames1D[k], H5P_DEFAULT));
      PetscCall(ReadAttrLong(d, g, path, "k", &v));
      PetscCheck(v == k, d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: %s@k = %lld, expected %d", d->name, path, v, (int)k);
      s->k = k;
      PetscCall(ReadExt(d, g, path, &s->ext));
      d->n1++;
      PetscCall(ReadData(d, g, path, "t", 1, &n, &s->t, NULL));
      s->n = (PetscInt)n;
      PetscCall(ReadData(d, g, path, "p", 1, &n, &s->p, NULL));
      PetscCall(ReadData(d, g, path, "m", 1, &n, &s->m, NULL));
      CallH5(H5Gclose(g));
    }
    CallH5(H5Gclose(g1));
  }
  PetscCall(Exists(d, file, "/", "2D", PETSC_FALSE, &has));
  if (has) {
    CallH5Id(g2, H5Gopen2(file, "2D", H5P_DEFAULT));
    PetscCall(CheckMembers(d, g2, "/2D/", HYLC_MATERIAL_N2D, HylcMaterialTermNames2D));
    for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) {
      HylcSpline2D *s = &d->s2[d->n2];
      char          path[64];
      hsize_t       nu = 0, nv = 0, dims[2];
      long long     k1;
      PetscCall(Exists(d, g2, "/2D/", HylcMaterialTermNames2D[q], PETSC_FALSE, &has));
      if (!has) continue;
      snprintf(path, sizeof(path), "/2D/%s/", HylcMaterialTermNames2D[q]);
      CallH5Id(g, H5Gopen2(g2, HylcMaterialTermNames2D[q], H5P_DEFAULT));
      PetscCall(ReadAttrLong(d, g, path, "k0", &v));
      PetscCall(ReadAttrLong(d, g, path, "k1", &k1));
      PetscCheck(v == HylcMaterialPairs[q][0] && k1 == HylcMaterialPairs[q][1], d->comm, PETSC_ERR_FILE_UNEXPECTED, "%s: %s has (k0, k1) = (%lld, %lld), expected (%d, %d)", d->name, path, v, k1, (int)HylcMaterialPairs[q][0], (int)HylcMaterialPairs[q][1]);
      s->k0 = HylcMaterialPairs[q][0];
      s->k1 = HylcMaterialPairs[q][1];
      PetscCall(ReadExt(d, g, path, &s->ext));
      d->n2++;
      PetscCall(ReadData(d, g, path, "tu", 1, &nu, &s->tu, NULL));
      PetscCall(ReadData(d, g, path, "tv", 1, &nv, &s->tv, NULL));
      s->nu   = (PetscInt)nu;
      s->nv   = (PetscInt)nv;
      dims[0] = nv;
      dims[1] = nu;
      PetscCall(ReadData(d, g, path, "p", 2, dims, &s->p, NULL));
      PetscCall(ReadData(d, g, path, "mu", 2, dims, &s->mu, NULL));
      PetscCall(ReadData(d, g, path, "mv", 2, dims, &s->mv, NULL));
      PetscCall(ReadData(d, g, path, "muv", 2, dims, &s->muv, NULL));
      CallH5(H5Gclose(g));
    }
    CallH5(H5Gclose(g2));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialParseHDF5_Private(HylcMaterial m, const char name[], const void *image, size_t len)
{
  hid_t           fapl, file;
  H5E_auto2_t     efunc;
  void           *edata;
  HylcMaterialDoc d;
  PetscErrorCode  ierr;

  PetscFunctionBegin;
  HylcMaterialDocInit(&d, m, name);
  H5File = name;
  H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl >= 0 && (H5Pset_fapl_core(fapl, 1 << 16, 0) < 0 || H5Pset_file_image(fapl, (void *)image, len) < 0 || H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0)) {
    H5Pclose(fapl);
    fapl = -1;
  }
  file = fapl >= 0 ? H5Fopen(IMAGE_NAME, H5F_ACC_RDONLY, fapl) : -1;
  if (file < 0) {
    char msg[256];
    ErrorText(msg);
    if (fapl >= 0) H5Pclose(fapl);
    H5Eset_auto2(H5E_DEFAULT, efunc, edata);
    SETERRQ(d.comm, PETSC_ERR_FILE_READ, "%s: cannot open as HDF5 (damaged or truncated file?)%s", name, msg);
  }
  ierr = ReadContents(&d, file);
  H5Fclose(file);
  H5Pclose(fapl);
  H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  H5File = "?";
  if (ierr) HylcMaterialDocFree(&d);
  PetscCall(ierr);
  PetscCall(HylcMaterialDocInstall(m, &d));
  PetscFunctionReturn(PETSC_SUCCESS);
}
