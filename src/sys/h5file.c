/* Atomic HDF5 output of plain datasets (include/hylc/sys.h): the shared HDF5 helpers
   (include/hylc/private/h5util.h) build the file in memory, the file helpers (src/sys/file.c) write it. */
#include <hylc/sys.h>
#include <hylc/private/h5util.h>

/* what the HDF5 calls work on, for HylcCallHDF5's messages */
#define HylcH5Where "the in-memory HDF5 image"

static PetscErrorCode WriteDatasets(hid_t file, int n, const HylcFileH5Doubles ds[])
{
  PetscFunctionBegin;
  for (int i = 0; i < n; i++) {
    hsize_t dims[3];
    if (!ds[i].v) continue;
    PetscCheck(ds[i].rank >= 1 && ds[i].rank <= 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Dataset %s: rank %d must be 1, 2 or 3", ds[i].name, ds[i].rank);
    for (int r = 0; r < ds[i].rank; r++) dims[r] = (hsize_t)ds[i].dims[r];
    HylcCallHDF5(HylcH5WriteDataset(file, ds[i].name, ds[i].rank, dims, H5T_NATIVE_DOUBLE, ds[i].v, NULL, NULL));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcFileWriteHDF5 - Writes datasets of doubles as a new HDF5 file, atomically: the file is built in memory
  (HDF5's core driver), written to a unique temporary beside path, fsynced and renamed onto path
  (HylcFileOpenTemp(), HylcFileCommitTemp()); on any failure path is left as it was. HDF5 prints nothing;
  its message goes into the error. Not collective.

  Input Parameters:
+ path - the file
. what - what the file is, for messages (e.g. "-eval_output")
. n    - the number of datasets
- ds   - the datasets (name, rank 1..3, dims, values; those with NULL values are skipped), stored as IEEE
         64-bit little-endian

  Level: developer

.seealso: HylcFileOpenTemp(), HylcFileCommitTemp()
@*/
PetscErrorCode HylcFileWriteHDF5(const char path[], const char what[], int n, const HylcFileH5Doubles ds[])
{
  hid_t          file;
  HylcH5Quiet    quiet;
  ssize_t        size  = -1;
  void          *image = NULL;
  FILE          *fp    = NULL;
  char           tmp[PETSC_MAX_PATH_LEN + 16], msg[256] = "";
  PetscErrorCode ierr;

  PetscFunctionBegin;
  HylcH5QuietBegin(&quiet);
  file = HylcH5ImageCreate(HYLC_H5_IMAGE_NAME, 1 << 16);
  if (file < 0) {
    HylcH5ErrorText(msg);
    HylcH5QuietEnd(&quiet);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot create %s %s in memory%s", what, path, msg);
  }
  ierr = WriteDatasets(file, n, ds);
  if (!ierr) {
    size = HylcH5ImageSize(file);
    if (size > 0) {
      ierr = PetscMalloc((size_t)size, &image);
      if (!ierr && H5Fget_file_image(file, image, (size_t)size) != size) size = -1;
    }
    if (!ierr && size <= 0) HylcH5ErrorText(msg);
  }
  H5Fclose(file); /* strong close: also every object an error left open */
  HylcH5QuietEnd(&quiet);
  if (ierr || size <= 0) PetscCall(PetscFree(image));
  PetscCall(ierr);
  PetscCheck(size > 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot build %s %s%s", what, path, msg);
  ierr = HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp);
  if (!ierr) {
    if (fwrite(image, 1, (size_t)size, fp) != (size_t)size) { /* the error (ENOSPC, EFBIG) stays on the stream: CommitTemp reports it */
    }
    ierr = HylcFileCommitTemp(&fp, tmp, path);
  }
  PetscCall(PetscFree(image));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}
