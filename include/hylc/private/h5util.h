#pragma once
/* The one private HDF5 helper layer (src/sys/h5util.c) of the samples writer (src/samples/h5samples.c),
   the material writer (src/material/h5.c) and hylcmat's material reader (src/hylcmat/h5.c). The
   functions are plain C99 and HDF5 only (hylcmat is built without PETSc): each returns HDF5's negative
   value on failure and leaves HDF5's error stack for HylcH5ErrorText(). The error-wrapping macros turn
   such a failure into the caller's error: HYLC_H5_CHECK_ for any convention (hylcmat), HylcCallHDF5 for
   PETSc. src/sys/h5util.c is compiled into libhylc and into libhylcmat built with HYLCMAT_WITH_HDF5. */
#include <hdf5.h>
#include <stddef.h>

/* the hylc HDF5 material format (docs/material.md) */
#define HYLC_MATERIAL_FORMAT         "hylc-material"
#define HYLC_MATERIAL_FORMAT_VERSION 2 /* 2: the 3D terms (group /3D); a table without them is written as version 1 */
/* the name of in-memory file images: HDF5's core driver refuses to open an image under a name that exists
   on disk, so it must not */
#define HYLC_H5_IMAGE_NAME "/nonexistent-hylc-directory/hylc-material-image.h5"

#if defined(__GNUC__)
#  define HYLC_H5_INTERN __attribute__((visibility("hidden")))
#else
#  define HYLC_H5_INTERN
#endif

/* HDF5's automatic error printing, switched off between Begin and End (the errors go into messages) */
typedef struct {
  H5E_auto2_t func;
  void       *data;
} HylcH5Quiet;
HYLC_H5_INTERN void HylcH5QuietBegin(HylcH5Quiet *);
HYLC_H5_INTERN void HylcH5QuietEnd(const HylcH5Quiet *);
/* the innermost description on HDF5's error stack, as ", HDF5: <text>" (or "") */
HYLC_H5_INTERN void HylcH5ErrorText(char buf[256]);

/* a variable-length UTF-8 string type (close it with H5Tclose) */
HYLC_H5_INTERN hid_t HylcH5StringType(void);
/* attributes: a UTF-8 string, a list of n strings, a scalar number (memtype H5T_NATIVE_DOUBLE, stored as
   IEEE f64; H5T_NATIVE_LLONG, i64; H5T_NATIVE_INT, i32) */
HYLC_H5_INTERN herr_t HylcH5WriteAttrString(hid_t loc, const char name[], const char value[]);
HYLC_H5_INTERN herr_t HylcH5WriteAttrStrings(hid_t loc, const char name[], int n, const char *const values[]);
HYLC_H5_INTERN herr_t HylcH5WriteAttrScalar(hid_t loc, const char name[], hid_t memtype, const void *value);
HYLC_H5_INTERN herr_t HylcH5WriteAttrDouble(hid_t loc, const char name[], double v);
HYLC_H5_INTERN herr_t HylcH5WriteAttrLong(hid_t loc, const char name[], long long v);
/* a numeric dataset of rank 0 (scalar, dims unused), 1 or 2 from buf (memtype as for the attributes),
   with the string attributes units and description when not NULL */
HYLC_H5_INTERN herr_t HylcH5WriteDataset(hid_t loc, const char name[], int rank, const hsize_t dims[], hid_t memtype, const void *buf, const char units[], const char description[]);
/* a string dataset: rank 0, the one string values[0]; rank 1, the n strings values[]; with a description */
HYLC_H5_INTERN herr_t HylcH5WriteStrings(hid_t loc, const char name[], int rank, hsize_t n, const char *const values[], const char description[]);
/* the scalar string dataset name as a malloc'd copy in *text ("" if it holds NULL) */
HYLC_H5_INTERN herr_t HylcH5ReadString(hid_t loc, const char name[], char **text);

/* a new file in memory (the core driver, no backing store, strong close: closing the file closes every
   object left open) under name, growing by increment bytes */
HYLC_H5_INTERN hid_t HylcH5ImageCreate(const char name[], size_t increment);
/* the file image (len bytes at image, not copied: keep it until the file is closed), read-only */
HYLC_H5_INTERN hid_t HylcH5ImageOpen(const char name[], const void *image, size_t len);
/* the file path on disk, read-only, strong close */
HYLC_H5_INTERN hid_t HylcH5FileOpen(const char path[]);
/* flushes the in-memory file and returns the size of its image (<= 0 on failure); then
   H5Fget_file_image(file, buf, size) copies it */
HYLC_H5_INTERN ssize_t HylcH5ImageSize(hid_t file);

/* HYLC_H5_CHECK_(onfail, call): if the raw HDF5 call returns a negative value, runs the statement onfail
   with HDF5's description in the string hylc_h5msg_; HYLC_H5_CHECK_ID_(onfail, id, call) also stores the
   returned hid_t in id. The wrappers stringify the call themselves (#__VA_ARGS__, unexpanded). */
#define HYLC_H5_CHECK_(onfail, ...) \
  do {                              \
    if ((__VA_ARGS__) < 0) {        \
      char hylc_h5msg_[256];        \
      HylcH5ErrorText(hylc_h5msg_); \
      onfail;                       \
    }                               \
  } while (0)
#define HYLC_H5_CHECK_ID_(onfail, id, ...) \
  do {                                     \
    (id) = (__VA_ARGS__);                  \
    HYLC_H5_CHECK_(onfail, id);            \
  } while (0)

/* PETSc: HylcCallHDF5(call) makes a failing HDF5 call a PETSc error naming the call, the file (the
   expression HylcH5Where, a string the including file defines) and HDF5's description; HylcCallHDF5Id(id,
   call) also stores the returned hid_t. Expanded only in PETSc code (hylcmat does not use them). */
#define HylcH5PetscFail_(call)  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 call %s failed on %s%s", call, HylcH5Where, hylc_h5msg_)
#define HylcCallHDF5(...)       HYLC_H5_CHECK_(HylcH5PetscFail_(#__VA_ARGS__), __VA_ARGS__)
#define HylcCallHDF5Id(id, ...) HYLC_H5_CHECK_ID_(HylcH5PetscFail_(#__VA_ARGS__), id, __VA_ARGS__)
