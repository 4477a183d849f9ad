#pragma once
/* Small HDF5 helpers shared by the samples writer (src/sampler/samples.c), the material writer
   (src/material/h5.c) and hylcmat's material reader (src/hylcmat/h5.c). Plain C99 and HDF5 only (hylcmat
   is built without PETSc). */
#include <hdf5.h>
#include <stdio.h>

/* the hylc HDF5 material format (docs/material.md) */
#define HYLC_MATERIAL_FORMAT         "hylc-material"
#define HYLC_MATERIAL_FORMAT_VERSION 1
/* the name of in-memory file images: HDF5's core driver refuses to open an image under a name that exists
   on disk, so it must not */
#define HYLC_H5_IMAGE_NAME "/nonexistent-hylc-directory/hylc-material-image.h5"

static inline herr_t HylcH5ErrorWalk_(unsigned n, const H5E_error2_t *e, void *ctx)
{
  (void)n;
  if (e->desc && e->desc[0]) snprintf((char *)ctx, 256, ", HDF5: %s", e->desc);
  return 0;
}

/* the innermost description on HDF5's error stack, as ", HDF5: <text>" (or "") */
static inline void HylcH5ErrorText(char buf[256])
{
  buf[0] = 0;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, HylcH5ErrorWalk_, buf);
}
