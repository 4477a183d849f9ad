/* The hylc HDF5 material format (docs/material.md), writing side: built as an in-memory file image (HDF5's
   core driver), which rank 0 writes with plain, atomic stdio. The reader is hylcmat's (src/hylcmat/h5.c,
   built with HYLCMAT_WITH_HDF5 into libhylc). */
#include <hylc/private/materialimpl.h>
#include <hylc/private/h5util.h>
#include <hylc/strain.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* what the HDF5 calls work on, for HylcCallHDF5's messages */
#define HylcH5Where "the in-memory HDF5 image"

/* a dataset of doubles (dv) or int32 (iv) of rank 0 (dims NULL), 1, 2 or 3, with units and description */
static PetscErrorCode Dataset(hid_t loc, const char name[], int rank, const hsize_t dims[], const double *dv, const int *iv, const char units[], const char description[])
{
  PetscFunctionBegin;
  HylcCallHDF5(HylcH5WriteDataset(loc, name, rank, dims, iv ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, iv ? (const void *)iv : (const void *)dv, units, description));
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
  hid_t             g1, g2, g3, g;
  hsize_t           dim5 = 5;
  int               n3   = 0;
  double            scale[5];
  int               shift[5];
  const char *const coordinate[5] = {"sx (stretch along x)", "sa (shear: cosine of the angle between the deformed material axes)", "sy (stretch along y)", "x-bending curvature (eigenvalue of II)", "y-bending curvature (eigenvalue of II)"};

  PetscFunctionBegin;
  gmtime_r(&now, &tm);
  strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", &tm);
  PetscCall(PetscGetVersion(petscv, sizeof(petscv)));
  HylcCallHDF5(H5get_libversion(&maj, &min, &rel));
  snprintf(h5v, sizeof(h5v), "%u.%u.%u", maj, min, rel);
  if (!optionsText) PetscCall(PetscOptionsGetAll(NULL, &allopts));
  HylcCallHDF5(HylcH5WriteAttrString(file, "format", HYLC_MATERIAL_FORMAT));
  for (int r = 0; r < HYLCMAT_N3D; r++) {
    hylcmat_term3d t;
    if (hylcmat_term3d_get(m->hm, HylcTripleCoords[r][0], HylcTripleCoords[r][1], HylcTripleCoords[r][2], &t)) n3++;
  }
  /* a table without 3D terms stays readable by a hylc that reads version 1 */
  HylcCallHDF5(HylcH5WriteAttrLong(file, "format_version", n3 ? HYLC_MATERIAL_FORMAT_VERSION : 1));
  HylcCallHDF5(
      HylcH5WriteAttrString(file, "description",
                            "Homogenized yarn-level cloth material: Psi(s) = constant + 1D terms f_k(s_k / sigma_k) + 2D terms f_k0k1(s_k0 / sigma_k0, s_k1 / sigma_k1), cubic/bicubic Hermite splines in normalized strains, bending terms "
                            "split over the eigenvalues of II (docs/material.md); with format_version 2, 3D terms f_k0k1k2 (hylc's extension, tricubic Hermite, not in the ARCSim-HYLC JSON). Without them equivalent to the ARCSim-HYLC JSON."));
  HylcCallHDF5(HylcH5WriteAttrString(file, "hylc_version", HYLC_VERSION_STRING));
  HylcCallHDF5(HylcH5WriteAttrString(file, "petsc_version", petscv));
  HylcCallHDF5(HylcH5WriteAttrString(file, "hdf5_version", h5v));
  HylcCallHDF5(HylcH5WriteAttrString(file, "creation_date", date));
  HylcCallHDF5(HylcH5WriteAttrString(file, "source", m->source));
  HylcCallHDF5(HylcH5WriteAttrString(file, "options", optionsText ? optionsText : (allopts ? allopts : "")));
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

  HylcCallHDF5Id(g1, H5Gcreate2(file, "1D", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(g1, "description", "one-dimensional terms f_k(x), x = s_k / sigma_k, one group per term present: cubic Hermite spline with knots t, values p, slopes m = df/dx"));
  for (PetscInt k = 0; k < HYLC_MATERIAL_N1D; k++) {
    const HylcSpline1D *s = &m->t1[k];
    hsize_t             n;
    if (!m->has1[k]) continue;
    n = (hsize_t)s->n;
    HylcCallHDF5Id(g, H5Gcreate2(g1, HylcMaterialTermNames1D[k], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    snprintf(desc, sizeof(desc), "f_%d(x) of the coordinate %s, x = s / %.17g", (int)k, coordinate[k], scale[k]);
    HylcCallHDF5(HylcH5WriteAttrString(g, "description", desc));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "k", (long long)k));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "ext", (long long)s->ext));
    HylcCallHDF5(HylcH5WriteAttrString(g, "extrapolation", ExtNames[s->ext]));
    PetscCall(Dataset(g, "t", 1, &n, s->t, NULL, "1", "knots (normalized strain), strictly increasing"));
    PetscCall(Dataset(g, "p", 1, &n, s->p, NULL, "J/m^2", "values at the knots"));
    PetscCall(Dataset(g, "m", 1, &n, s->m, NULL, "J/m^2", "slopes df/dx at the knots (per unit normalized strain)"));
    HylcCallHDF5(H5Gclose(g));
  }
  HylcCallHDF5(H5Gclose(g1));

  HylcCallHDF5Id(g2, H5Gcreate2(file, "2D", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(
      g2, "description",
      "two-dimensional terms f_k0k1(u, v), u = s_k0 / sigma_k0, v = s_k1 / sigma_k1, one group per term present: bicubic Hermite spline with knots tu, tv and node arrays of shape (len(tv), len(tu)): p[iv, iu] is the value at (tu[iu], tv[iv])"));
  for (PetscInt q = 0; q < HYLC_MATERIAL_N2D; q++) {
    const HylcSpline2D *s = &m->t2[q];
    hsize_t             nu, nv, dims[2];
    if (!m->has2[q]) continue;
    nu      = (hsize_t)s->nu;
    nv      = (hsize_t)s->nv;
    dims[0] = nv;
    dims[1] = nu;
    HylcCallHDF5Id(g, H5Gcreate2(g2, HylcMaterialTermNames2D[q], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    snprintf(desc, sizeof(desc), "f_%d%d(u, v) of the coordinates u = %s / %.17g and v = %s / %.17g", (int)s->k0, (int)s->k1, coordinate[s->k0], scale[s->k0], coordinate[s->k1], scale[s->k1]);
    HylcCallHDF5(HylcH5WriteAttrString(g, "description", desc));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "k0", (long long)s->k0));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "k1", (long long)s->k1));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "ext", (long long)s->ext));
    HylcCallHDF5(HylcH5WriteAttrString(g, "extrapolation", ExtNames[s->ext]));
    PetscCall(Dataset(g, "tu", 1, &nu, s->tu, NULL, "1", "knots of u (normalized strain k0), strictly increasing"));
    PetscCall(Dataset(g, "tv", 1, &nv, s->tv, NULL, "1", "knots of v (normalized strain k1), strictly increasing"));
    PetscCall(Dataset(g, "p", 2, dims, s->p, NULL, "J/m^2", "values at the nodes, p[iv, iu] at (tu[iu], tv[iv])"));
    PetscCall(Dataset(g, "mu", 2, dims, s->mu, NULL, "J/m^2", "df/du at the nodes"));
    PetscCall(Dataset(g, "mv", 2, dims, s->mv, NULL, "J/m^2", "df/dv at the nodes"));
    PetscCall(Dataset(g, "muv", 2, dims, s->muv, NULL, "J/m^2", "d2f/dudv at the nodes"));
    HylcCallHDF5(H5Gclose(g));
  }
  HylcCallHDF5(H5Gclose(g2));
  if (!n3) PetscFunctionReturn(PETSC_SUCCESS);

  HylcCallHDF5Id(g3, H5Gcreate2(file, "3D", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(g3, "description",
                                     "three-dimensional terms f_k0k1k2(u, v, w) (hylc's extension of the paper's model), u, v, w the normalized strains k0, k1, k2, one group per term present: tricubic Hermite spline with knots tu, tv, tw and "
                                     "node arrays of shape (len(tw), len(tv), len(tu)): p[iw, iv, iu] is the value at (tu[iu], tv[iv], tw[iw]); a bending coordinate enters through the eigenvalues of II as in the 2D terms"));
  for (int r = 0; r < HYLCMAT_N3D; r++) {
    hylcmat_term3d t;
    hsize_t        nu, nv, nw, dims[3];
    if (!hylcmat_term3d_get(m->hm, HylcTripleCoords[r][0], HylcTripleCoords[r][1], HylcTripleCoords[r][2], &t)) continue;
    nu      = (hsize_t)t.nu;
    nv      = (hsize_t)t.nv;
    nw      = (hsize_t)t.nw;
    dims[0] = nw;
    dims[1] = nv;
    dims[2] = nu;
    HylcCallHDF5Id(g, H5Gcreate2(g3, HylcTripleNames[r], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    snprintf(desc, sizeof(desc), "f_%d%d%d(u, v, w) of u = %s / %.17g, v = %s / %.17g, w = %s / %.17g", t.k0, t.k1, t.k2, coordinate[t.k0], scale[t.k0], coordinate[t.k1], scale[t.k1], coordinate[t.k2], scale[t.k2]);
    HylcCallHDF5(HylcH5WriteAttrString(g, "description", desc));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "k0", (long long)t.k0));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "k1", (long long)t.k1));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "k2", (long long)t.k2));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "ext", (long long)t.ext));
    HylcCallHDF5(HylcH5WriteAttrString(g, "extrapolation", ExtNames[t.ext]));
    PetscCall(Dataset(g, "tu", 1, &nu, t.tu, NULL, "1", "knots of u (normalized strain k0), strictly increasing"));
    PetscCall(Dataset(g, "tv", 1, &nv, t.tv, NULL, "1", "knots of v (normalized strain k1), strictly increasing"));
    PetscCall(Dataset(g, "tw", 1, &nw, t.tw, NULL, "1", "knots of w (normalized strain k2), strictly increasing"));
    PetscCall(Dataset(g, "p", 3, dims, t.p, NULL, "J/m^2", "values at the nodes, p[iw, iv, iu] at (tu[iu], tv[iv], tw[iw])"));
    PetscCall(Dataset(g, "mu", 3, dims, t.mu, NULL, "J/m^2", "df/du at the nodes"));
    PetscCall(Dataset(g, "mv", 3, dims, t.mv, NULL, "J/m^2", "df/dv at the nodes"));
    PetscCall(Dataset(g, "mw", 3, dims, t.mw, NULL, "J/m^2", "df/dw at the nodes"));
    PetscCall(Dataset(g, "muv", 3, dims, t.muv, NULL, "J/m^2", "d2f/dudv at the nodes"));
    PetscCall(Dataset(g, "muw", 3, dims, t.muw, NULL, "J/m^2", "d2f/dudw at the nodes"));
    PetscCall(Dataset(g, "mvw", 3, dims, t.mvw, NULL, "J/m^2", "d2f/dvdw at the nodes"));
    PetscCall(Dataset(g, "muvw", 3, dims, t.muvw, NULL, "J/m^2", "d3f/dudvdw at the nodes"));
    HylcCallHDF5(H5Gclose(g));
  }
  HylcCallHDF5(H5Gclose(g3));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcMaterialFormatHDF5_Private(HylcMaterial m, const char optionsText[], void **image, size_t *len)
{
  hid_t          file;
  ssize_t        size = -1;
  HylcH5Quiet    quiet;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  *image = NULL;
  *len   = 0;
  HylcH5QuietBegin(&quiet);
  file = HylcH5ImageCreate(HYLC_H5_IMAGE_NAME, 1 << 16);
  if (file < 0) {
    char msg[256];
    HylcH5ErrorText(msg);
    HylcH5QuietEnd(&quiet);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot create an in-memory HDF5 file%s", msg);
  }
  ierr = WriteContents(file, m, optionsText);
  if (!ierr) size = HylcH5ImageSize(file);
  if (!ierr && size > 0) {
    ierr = PetscMalloc(size, image);
    if (!ierr && H5Fget_file_image(file, *image, (size_t)size) != size) size = -1;
  }
  H5Fclose(file);
  HylcH5QuietEnd(&quiet);
  if (!ierr && size <= 0) {
    PetscCall(PetscFree(*image));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot get the image of the in-memory HDF5 file");
  }
  if (ierr) PetscCall(PetscFree(*image));
  PetscCall(ierr);
  *len = (size_t)size;
  PetscFunctionReturn(PETSC_SUCCESS);
}
