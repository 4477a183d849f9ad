/* The private HDF5 helper layer (include/hylc/private/h5util.h): plain C99 and HDF5, no PETSc, so that
   libhylc and libhylcmat (with HYLCMAT_WITH_HDF5) compile the same source. Every function returns
   HDF5's negative value on the first failing call; objects it opened are then left to the strong close
   of the file. */
#include <hylc/private/h5util.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void HylcH5QuietBegin(HylcH5Quiet *q)
{
  H5Eget_auto2(H5E_DEFAULT, &q->func, &q->data);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
}

void HylcH5QuietEnd(const HylcH5Quiet *q) { H5Eset_auto2(H5E_DEFAULT, q->func, q->data); }

static herr_t ErrorWalk(unsigned n, const H5E_error2_t *e, void *ctx)
{
  (void)n;
  if (e->desc && e->desc[0]) snprintf((char *)ctx, 256, ", HDF5: %s", e->desc);
  return 0;
}

void HylcH5ErrorText(char buf[256])
{
  buf[0] = 0;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, ErrorWalk, buf);
}

#define TRY(call)              \
  do {                         \
    if ((call) < 0) return -1; \
  } while (0)
#define TRYID(id, call)                 \
  do {                                  \
    if (((id) = (call)) < 0) return -1; \
  } while (0)

hid_t HylcH5StringType(void)
{
  hid_t t;

  TRYID(t, H5Tcopy(H5T_C_S1));
  TRY(H5Tset_size(t, H5T_VARIABLE));
  TRY(H5Tset_cset(t, H5T_CSET_UTF8));
  return t;
}

/* the string attribute (isattr) or dataset name of rank 0 (one string) or 1 (n strings) */
static herr_t WriteStrings(hid_t loc, const char name[], int isattr, int rank, hsize_t n, const char *const values[], const char description[])
{
  hid_t t, s, o;

  TRYID(t, HylcH5StringType());
  if (rank)
    TRYID(s, H5Screate_simple(1, &n, NULL));
  else
    TRYID(s, H5Screate(H5S_SCALAR));
  if (isattr) {
    TRYID(o, H5Acreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT));
    TRY(H5Awrite(o, t, values));
    TRY(H5Aclose(o));
  } else {
    TRYID(o, H5Dcreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (!rank || n) TRY(H5Dwrite(o, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, values));
    if (description) TRY(HylcH5WriteAttrString(o, "description", description));
    TRY(H5Dclose(o));
  }
  TRY(H5Sclose(s));
  TRY(H5Tclose(t));
  return 0;
}

herr_t HylcH5WriteAttrString(hid_t loc, const char name[], const char value[]) { return WriteStrings(loc, name, 1, 0, 1, &value, NULL); }

herr_t HylcH5WriteAttrStrings(hid_t loc, const char name[], int n, const char *const values[]) { return WriteStrings(loc, name, 1, 1, (hsize_t)n, values, NULL); }

herr_t HylcH5WriteStrings(hid_t loc, const char name[], int rank, hsize_t n, const char *const values[], const char description[]) { return WriteStrings(loc, name, 0, rank, n, values, description); }

/* the stored (little-endian) type of a native memory type */
static hid_t FileType(hid_t memtype) { return memtype == H5T_NATIVE_DOUBLE ? H5T_IEEE_F64LE : (memtype == H5T_NATIVE_LLONG ? H5T_STD_I64LE : H5T_STD_I32LE); }

herr_t HylcH5WriteAttrScalar(hid_t loc, const char name[], hid_t memtype, const void *value)
{
  hid_t s, a;

  TRYID(s, H5Screate(H5S_SCALAR));
  TRYID(a, H5Acreate2(loc, name, FileType(memtype), s, H5P_DEFAULT, H5P_DEFAULT));
  TRY(H5Awrite(a, memtype, value));
  TRY(H5Aclose(a));
  TRY(H5Sclose(s));
  return 0;
}

herr_t HylcH5WriteAttrDouble(hid_t loc, const char name[], double v) { return HylcH5WriteAttrScalar(loc, name, H5T_NATIVE_DOUBLE, &v); }

herr_t HylcH5WriteAttrLong(hid_t loc, const char name[], long long v) { return HylcH5WriteAttrScalar(loc, name, H5T_NATIVE_LLONG, &v); }

herr_t HylcH5WriteDataset(hid_t loc, const char name[], int rank, const hsize_t dims[], hid_t memtype, const void *buf, const char units[], const char description[])
{
  hid_t   s, d;
  hsize_t n = 1;

  if (rank)
    TRYID(s, H5Screate_simple(rank, dims, NULL));
  else
    TRYID(s, H5Screate(H5S_SCALAR));
  for (int i = 0; i < rank; i++) n *= dims[i];
  TRYID(d, H5Dcreate2(loc, name, FileType(memtype), s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (n) TRY(H5Dwrite(d, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf));
  if (units) TRY(HylcH5WriteAttrString(d, "units", units));
  if (description) TRY(HylcH5WriteAttrString(d, "description", description));
  TRY(H5Dclose(d));
  TRY(H5Sclose(s));
  return 0;
}

herr_t HylcH5ReadString(hid_t loc, const char name[], char **text)
{
  hid_t d, t, s;
  char *v = NULL;

  *text = NULL;
  TRYID(d, H5Dopen2(loc, name, H5P_DEFAULT));
  TRYID(t, HylcH5StringType());
  TRYID(s, H5Dget_space(d));
  TRY(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, &v));
  *text = malloc(strlen(v ? v : "") + 1);
  if (*text) strcpy(*text, v ? v : "");
#if H5_VERSION_GE(1, 12, 0)
  TRY(H5Treclaim(t, s, H5P_DEFAULT, &v));
#else
  TRY(H5Dvlen_reclaim(t, s, H5P_DEFAULT, &v));
#endif
  TRY(H5Sclose(s));
  TRY(H5Tclose(t));
  TRY(H5Dclose(d));
  return *text ? 0 : -1;
}

/* closes id keeping HDF5's error stack (every API call clears it) for HylcH5ErrorText() */
static void CloseKeepingErrors(hid_t id)
{
  hid_t stack = H5Eget_current_stack();

  H5Pclose(id);
  if (stack >= 0) H5Eset_current_stack(stack);
}

/* mode 0: a new file in memory; 1: open the image read-only; 2: open the file name read-only */
static hid_t Open(int mode, const char name[], size_t increment, const void *image, size_t len)
{
  hid_t fapl, file = -1;

  TRYID(fapl, H5Pcreate(H5P_FILE_ACCESS));
  if (H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) >= 0 && (mode == 2 || H5Pset_fapl_core(fapl, increment, 0) >= 0) && (mode != 1 || H5Pset_file_image(fapl, (void *)image, len) >= 0))
    file = mode ? H5Fopen(name, H5F_ACC_RDONLY, fapl) : H5Fcreate(name, H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
  CloseKeepingErrors(fapl);
  return file;
}

hid_t HylcH5ImageCreate(const char name[], size_t increment) { return Open(0, name, increment, NULL, 0); }

hid_t HylcH5ImageOpen(const char name[], const void *image, size_t len) { return Open(1, name, 1 << 16, image, len); }

hid_t HylcH5FileOpen(const char path[]) { return Open(2, path, 0, NULL, 0); }

ssize_t HylcH5ImageSize(hid_t file)
{
  if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) return -1;
  return H5Fget_file_image(file, NULL, 0);
}
