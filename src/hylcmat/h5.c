/* The hylc HDF5 material format (docs/material.md), reading side: parses an in-memory file image
   (HDF5's core driver). Compiled only with HYLCMAT_WITH_HDF5; the writer is in src/material/h5.c.
   The HDF5 library itself is not thread-safe unless built so: do not load HDF5 tables from several
   threads at once. */
#ifdef HYLCMAT_WITH_HDF5
#  include "hylcmatimpl.h"
#  include <hylc/private/h5util.h>
#  include <stdio.h>
#  include <stdlib.h>
#  include <string.h>

/* CallH5(call): a negative return of a raw HDF5 call becomes an error naming the call and the file (d) */
#  define H5Fail_(call)     return hm_fail(d->E, HYLCMAT_ERR_HDF5, "HDF5 call %s failed on %s%s", call, d->name, hylc_h5msg_)
#  define CallH5(...)       HYLC_H5_CHECK_(H5Fail_(#  __VA_ARGS__), __VA_ARGS__)
#  define CallH5Id(id, ...) HYLC_H5_CHECK_ID_(H5Fail_(#  __VA_ARGS__), id, __VA_ARGS__)

static int Exists(const hm_doc *d, hid_t loc, const char path[], const char name[], int required, int *has)
{
  htri_t e;

  CallH5Id(e, H5Lexists(loc, name, H5P_DEFAULT));
  HM_CHECK(e > 0 || !required, d->E, HYLCMAT_ERR_CONTENT, "%s: %s%s is missing", d->name, path, name);
  if (has) *has = (int)(e > 0);
  return HYLCMAT_OK;
}

/* a string attribute (variable or fixed length) into buf */
static int ReadAttrString(const hm_doc *d, hid_t loc, const char path[], const char name[], char buf[], size_t size)
{
  hid_t  a, t, mt;
  htri_t vlen;

  buf[0] = 0;
  CallH5Id(a, H5Aopen(loc, name, H5P_DEFAULT));
  CallH5Id(t, H5Aget_type(a));
  HM_CHECK(H5Tget_class(t) == H5T_STRING, d->E, HYLCMAT_ERR_CONTENT, "%s: attribute %s@%s is not a string", d->name, path, name);
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
    char  *s = calloc(n + 1, 1);
    HM_CHECK(s, d->E, HYLCMAT_ERR_MEMORY, "%s: attribute %s@%s: out of memory", d->name, path, name);
    CallH5(H5Tset_size(mt, n + 1));
    CallH5(H5Aread(a, mt, s));
    snprintf(buf, size, "%s", s);
    free(s);
  }
  CallH5(H5Tclose(mt));
  CallH5(H5Tclose(t));
  CallH5(H5Aclose(a));
  return HYLCMAT_OK;
}

/* what an HDF5 type class holds, for messages */
static const char *ClassName(H5T_class_t c)
{
  switch (c) {
  case H5T_INTEGER:
    return "integers";
  case H5T_FLOAT:
    return "floating-point numbers";
  case H5T_STRING:
    return "strings";
  case H5T_COMPOUND:
    return "compound records";
  case H5T_ENUM:
    return "enumerated values";
  case H5T_ARRAY:
    return "arrays";
  case H5T_VLEN:
    return "variable-length sequences";
  case H5T_REFERENCE:
    return "references";
  default:
    return "data of another class";
  }
}

static int ReadAttrLong(const hm_doc *d, hid_t loc, const char path[], const char name[], long long *v)
{
  hid_t  a, s;
  htri_t e;

  CallH5Id(e, H5Aexists(loc, name));
  HM_CHECK(e > 0, d->E, HYLCMAT_ERR_CONTENT, "%s: attribute %s@%s is missing", d->name, path, name);
  CallH5Id(a, H5Aopen(loc, name, H5P_DEFAULT));
  {
    hid_t       t;
    H5T_class_t c;
    CallH5Id(t, H5Aget_type(a));
    c = H5Tget_class(t);
    CallH5(H5Tclose(t));
    HM_CHECK(c == H5T_INTEGER, d->E, HYLCMAT_ERR_CONTENT, "%s: attribute %s@%s holds %s, expected an integer", d->name, path, name, ClassName(c));
  }
  CallH5Id(s, H5Aget_space(a));
  HM_CHECK(H5Sget_simple_extent_npoints(s) == 1, d->E, HYLCMAT_ERR_CONTENT, "%s: attribute %s@%s must be a scalar", d->name, path, name);
  CallH5(H5Aread(a, H5T_NATIVE_LLONG, v));
  CallH5(H5Sclose(s));
  CallH5(H5Aclose(a));
  return HYLCMAT_OK;
}

/* a dataset of the given rank with its dimensions (dims[0] outermost); the data as doubles (or ints) in
   freshly allocated *out */
static int ReadData(const hm_doc *d, hid_t loc, const char path[], const char name[], int rank, hsize_t dims[], double **out, int *iout)
{
  hid_t   ds, sp;
  int     r;
  hsize_t dd[3] = {1, 1, 1}, n = 1;

  HM_CALL(Exists(d, loc, path, name, 1, NULL));
  CallH5Id(ds, H5Dopen2(loc, name, H5P_DEFAULT));
  {
    hid_t       t;
    H5T_class_t c;
    CallH5Id(t, H5Dget_type(ds));
    c = H5Tget_class(t);
    CallH5(H5Tclose(t));
    HM_CHECK(c == H5T_FLOAT || c == H5T_INTEGER, d->E, HYLCMAT_ERR_CONTENT, "%s: dataset %s%s holds %s, expected numbers", d->name, path, name, ClassName(c));
  }
  CallH5Id(sp, H5Dget_space(ds));
  CallH5Id(r, H5Sget_simple_extent_ndims(sp));
  HM_CHECK(r == rank, d->E, HYLCMAT_ERR_CONTENT, "%s: dataset %s%s has rank %d, expected %d", d->name, path, name, r, rank);
  if (r) CallH5(H5Sget_simple_extent_dims(sp, dd, NULL));
  for (int i = 0; i < r; i++) {
    n *= dd[i];
    if (dims[i]) HM_CHECK(dd[i] == dims[i], d->E, HYLCMAT_ERR_CONTENT, "%s: dataset %s%s has dimension %d of size %llu, expected %llu", d->name, path, name, i, (unsigned long long)dd[i], (unsigned long long)dims[i]);
    dims[i] = dd[i];
  }
  HM_CHECK(n < (1u << 28), d->E, HYLCMAT_ERR_CONTENT, "%s: dataset %s%s is too large", d->name, path, name);
  if (out) {
    *out = malloc(sizeof(double) * (size_t)(n + 1)); /* owned by the caller from here on, also on an error */
    HM_CHECK(*out, d->E, HYLCMAT_ERR_MEMORY, "%s: dataset %s%s: out of memory", d->name, path, name);
    CallH5(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, *out));
  } else {
    int buf[8];
    HM_CHECK(n <= 8, d->E, HYLCMAT_ERR_CONTENT, "%s: dataset %s%s is too large", d->name, path, name);
    CallH5(H5Dread(ds, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf));
    for (hsize_t i = 0; i < n; i++) iout[i] = (int)buf[i];
  }
  CallH5(H5Sclose(sp));
  CallH5(H5Dclose(ds));
  return HYLCMAT_OK;
}

static int ReadScalar(const hm_doc *d, hid_t loc, const char name[], double *v)
{
  double *buf = NULL;
  int     r   = ReadData(d, loc, "/", name, 0, NULL, &buf, NULL);

  if (!r) *v = buf[0];
  free(buf);
  return r;
}

/* every member of group g must be one of the names[] */
static int CheckMembers(const hm_doc *d, hid_t g, const char path[], int nnames, const char *const names[])
{
  H5G_info_t info;

  CallH5(H5Gget_info(g, &info));
  for (hsize_t i = 0; i < info.nlinks; i++) {
    char name[256] = "";
    int  ok        = 0;
    CallH5(H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof(name), H5P_DEFAULT));
    for (int j = 0; j < nnames; j++) ok = (int)(ok || !strcmp(name, names[j]));
    HM_CHECK(ok, d->E, HYLCMAT_ERR_CONTENT, "%s: unknown member %s%s", d->name, path, name);
  }
  return HYLCMAT_OK;
}

/* the group name of parent (at path dir) if present (*has): opened in *g, its path in path[64]; with
   nnames > 0, every member must be one of names[] */
static int OpenGroup(const hm_doc *d, hid_t parent, const char dir[], const char name[], int nnames, const char *const names[], char path[64], hid_t *g, int *has)
{
  HM_CALL(Exists(d, parent, dir, name, 0, has));
  if (!*has) return HYLCMAT_OK;
  snprintf(path, 64, "%s%s/", dir, name);
  CallH5Id(*g, H5Gopen2(parent, name, H5P_DEFAULT));
  if (nnames) HM_CALL(CheckMembers(d, *g, path, nnames, names));
  return HYLCMAT_OK;
}

static int ReadExt(const hm_doc *d, hid_t g, const char path[], int *ext)
{
  long long e;

  HM_CALL(ReadAttrLong(d, g, path, "ext", &e));
  HM_CHECK(e >= 0 && e <= 2, d->E, HYLCMAT_ERR_CONTENT, "%s: %s@ext = %lld is not 0 (linear), 1 (constant) or 2 (zero)", d->name, path, e);
  *ext = (int)e;
  return HYLCMAT_OK;
}

/* the 3D terms (format version 2): group /3D/<u-v-w> with attributes k0, k1, k2, ext, knots tu, tv, tw and
   the node arrays p, mu, mv, mw, muv, muw, mvw, muvw of shape (nw, nv, nu) */
static int Read3D(hm_doc *d, hid_t file)
{
  char                     gpath[64];
  int                      has;
  hid_t                    g3, g;
  static const char *const arrays[] = {"p", "mu", "mv", "mw", "muv", "muw", "mvw", "muvw"};

  HM_CALL(OpenGroup(d, file, "/", "3D", HYLCMAT_N3D, HylcTripleNames, gpath, &g3, &has));
  if (!has) return HYLCMAT_OK;
  for (int r = 0; r < HYLCMAT_N3D; r++) {
    hylcmat_term3d *s = &d->s3[d->n3];
    char            path[64];
    hsize_t         nu = 0, nv = 0, nw = 0, dims[3];
    long long       k[3];
    const double  **out[8] = {&s->p, &s->mu, &s->mv, &s->mw, &s->muv, &s->muw, &s->mvw, &s->muvw};
    HM_CALL(OpenGroup(d, g3, gpath, HylcTripleNames[r], 0, NULL, path, &g, &has));
    if (!has) continue;
    HM_CALL(ReadAttrLong(d, g, path, "k0", &k[0]));
    HM_CALL(ReadAttrLong(d, g, path, "k1", &k[1]));
    HM_CALL(ReadAttrLong(d, g, path, "k2", &k[2]));
    HM_CHECK(k[0] == HylcTripleCoords[r][0] && k[1] == HylcTripleCoords[r][1] && k[2] == HylcTripleCoords[r][2], d->E, HYLCMAT_ERR_CONTENT, "%s: %s has (k0, k1, k2) = (%lld, %lld, %lld), expected (%d, %d, %d)", d->name, path, k[0], k[1], k[2],
             (int)HylcTripleCoords[r][0], (int)HylcTripleCoords[r][1], (int)HylcTripleCoords[r][2]);
    s->k0 = HylcTripleCoords[r][0];
    s->k1 = HylcTripleCoords[r][1];
    s->k2 = HylcTripleCoords[r][2];
    HM_CALL(ReadExt(d, g, path, &s->ext));
    d->n3++;
    HM_CALL(ReadData(d, g, path, "tu", 1, &nu, (double **)&s->tu, NULL));
    HM_CALL(ReadData(d, g, path, "tv", 1, &nv, (double **)&s->tv, NULL));
    HM_CALL(ReadData(d, g, path, "tw", 1, &nw, (double **)&s->tw, NULL));
    s->nu = (int)nu;
    s->nv = (int)nv;
    s->nw = (int)nw;
    for (int a = 0; a < 8; a++) {
      dims[0] = nw;
      dims[1] = nv;
      dims[2] = nu;
      HM_CALL(ReadData(d, g, path, arrays[a], 3, dims, (double **)out[a], NULL));
    }
    CallH5(H5Gclose(g));
  }
  CallH5(H5Gclose(g3));
  return HYLCMAT_OK;
}

static int ReadContents(hm_doc *d, hid_t file)
{
  char                     fmt[64], gpath[64];
  long long                version, v;
  hsize_t                  dim5 = 5;
  double                  *buf;
  int                      has;
  hid_t                    g1, g2, g;
  static const char *const top[] = {"density", "constant", "strain_scale", "strain_shift", "1D", "2D", "3D"};

  {
    htri_t e;
    CallH5Id(e, H5Aexists(file, "format"));
    HM_CHECK(e > 0, d->E, HYLCMAT_ERR_CONTENT, "%s: an HDF5 file without the root attribute 'format': not a hylc material file", d->name);
  }
  HM_CALL(ReadAttrString(d, file, "/", "format", fmt, sizeof(fmt)));
  HM_CHECK(!strcmp(fmt, HYLC_MATERIAL_FORMAT), d->E, HYLCMAT_ERR_CONTENT, "%s: an HDF5 file of format '%s', not a hylc material file ('%s')", d->name, fmt, HYLC_MATERIAL_FORMAT);
  HM_CALL(ReadAttrLong(d, file, "/", "format_version", &version));
  HM_CHECK(version >= 1 && version <= HYLC_MATERIAL_FORMAT_VERSION, d->E, HYLCMAT_ERR_CONTENT, "%s: material format version %lld is not supported (this hylc reads version %d)", d->name, version, HYLC_MATERIAL_FORMAT_VERSION);
  HM_CALL(CheckMembers(d, file, "/", version >= 2 ? 7 : 6, top));
  HM_CALL(ReadScalar(d, file, "density", &d->density));
  HM_CALL(ReadScalar(d, file, "constant", &d->C0));
  buf = NULL;
  {
    const int r = ReadData(d, file, "/", "strain_scale", 1, &dim5, &buf, NULL);
    if (!r)
      for (int k = 0; k < 5; k++) d->scale[k] = buf[k];
    free(buf);
    HM_CALL(r);
  }
  HM_CALL(Exists(d, file, "/", "strain_shift", 0, &has));
  if (has) HM_CALL(ReadData(d, file, "/", "strain_shift", 1, &dim5, NULL, d->shift));

  HM_CALL(OpenGroup(d, file, "/", "1D", HYLCMAT_N1D, HylcmatNames1D, gpath, &g1, &has));
  if (has) {
    for (int k = 0; k < HYLCMAT_N1D; k++) {
      hylcmat_term1d *s = &d->s1[d->n1];
      char            path[64];
      hsize_t         n = 0;
      HM_CALL(OpenGroup(d, g1, gpath, HylcmatNames1D[k], 0, NULL, path, &g, &has));
      if (!has) continue;
      HM_CALL(ReadAttrLong(d, g, path, "k", &v));
      HM_CHECK(v == k, d->E, HYLCMAT_ERR_CONTENT, "%s: %s@k = %lld, expected %d", d->name, path, v, (int)k);
      s->k = k;
      HM_CALL(ReadExt(d, g, path, &s->ext));
      d->n1++;
      HM_CALL(ReadData(d, g, path, "t", 1, &n, (double **)&s->t, NULL));
      s->n = (int)n;
      HM_CALL(ReadData(d, g, path, "p", 1, &n, (double **)&s->p, NULL));
      HM_CALL(ReadData(d, g, path, "m", 1, &n, (double **)&s->m, NULL));
      CallH5(H5Gclose(g));
    }
    CallH5(H5Gclose(g1));
  }
  HM_CALL(OpenGroup(d, file, "/", "2D", HYLCMAT_N2D, HylcmatNames2D, gpath, &g2, &has));
  if (has) {
    for (int q = 0; q < HYLCMAT_N2D; q++) {
      hylcmat_term2d *s = &d->s2[d->n2];
      char            path[64];
      hsize_t         nu = 0, nv = 0, dims[2];
      long long       k1;
      HM_CALL(OpenGroup(d, g2, gpath, HylcmatNames2D[q], 0, NULL, path, &g, &has));
      if (!has) continue;
      HM_CALL(ReadAttrLong(d, g, path, "k0", &v));
      HM_CALL(ReadAttrLong(d, g, path, "k1", &k1));
      HM_CHECK(v == HylcmatPairs[q][0] && k1 == HylcmatPairs[q][1], d->E, HYLCMAT_ERR_CONTENT, "%s: %s has (k0, k1) = (%lld, %lld), expected (%d, %d)", d->name, path, v, k1, (int)HylcmatPairs[q][0], (int)HylcmatPairs[q][1]);
      s->k0 = HylcmatPairs[q][0];
      s->k1 = HylcmatPairs[q][1];
      HM_CALL(ReadExt(d, g, path, &s->ext));
      d->n2++;
      HM_CALL(ReadData(d, g, path, "tu", 1, &nu, (double **)&s->tu, NULL));
      HM_CALL(ReadData(d, g, path, "tv", 1, &nv, (double **)&s->tv, NULL));
      s->nu   = (int)nu;
      s->nv   = (int)nv;
      dims[0] = nv;
      dims[1] = nu;
      HM_CALL(ReadData(d, g, path, "p", 2, dims, (double **)&s->p, NULL));
      HM_CALL(ReadData(d, g, path, "mu", 2, dims, (double **)&s->mu, NULL));
      HM_CALL(ReadData(d, g, path, "mv", 2, dims, (double **)&s->mv, NULL));
      HM_CALL(ReadData(d, g, path, "muv", 2, dims, (double **)&s->muv, NULL));
      CallH5(H5Gclose(g));
    }
    CallH5(H5Gclose(g2));
  }
  if (version >= 2) HM_CALL(Read3D(d, file));
  return HYLCMAT_OK;
}

int hm_parse_hdf5(const char *name, const void *image, size_t len, hm_err *E, hylcmat **m)
{
  hid_t       file;
  HylcH5Quiet quiet;
  hm_doc      d;
  int         ierr;

  hm_doc_init(&d, name, E);
  HylcH5QuietBegin(&quiet);
  file = HylcH5ImageOpen(HYLC_H5_IMAGE_NAME, image, len);
  if (file < 0) {
    char msg[256];
    HylcH5ErrorText(msg);
    HylcH5QuietEnd(&quiet);
    return hm_fail(E, HYLCMAT_ERR_READ, "%s: cannot open as HDF5 (damaged or truncated file?)%s", name, msg);
  }
  ierr = ReadContents(&d, file);
  H5Fclose(file);
  HylcH5QuietEnd(&quiet);
  if (ierr) {
    hm_doc_free(&d);
    return ierr;
  }
  return hm_doc_install(&d, m);
}
#else
typedef int hylcmat_no_hdf5; /* ISO C: a translation unit is not empty */
#endif
