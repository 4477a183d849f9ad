/* Private definitions of hylcmat (src/hylcmat/ only): the table and the error helpers. Plain C99. */
#ifndef HYLCMATIMPL_H
#define HYLCMATIMPL_H
#include <hylcmat.h>
#include <hylc/strain.h>

/* internal symbols are not exported from the shared libraries */
#if defined(__GNUC__)
#  define HM_INTERN __attribute__((visibility("hidden")))
#else
#  define HM_INTERN
#endif

struct hylcmat {
  double         density;  /* area density rho_A (kg/m^2) */
  double         scale[5]; /* strain scale sigma_0..4 */
  int            shift[5]; /* the JSON's informational strain shift */
  double         C0;       /* constant (J/m^2) */
  int            has1[HYLCMAT_N1D], has2[HYLCMAT_N2D];
  hylcmat_term1d t1[HYLCMAT_N1D]; /* term k at index k; arrays owned (malloc) */
  hylcmat_term2d t2[HYLCMAT_N2D]; /* pair at its index in HylcmatPairs */
  int            has3[HYLCMAT_N3D];
  hylcmat_term3d t3[HYLCMAT_N3D]; /* triple at its index in HylcTripleCoords */
  double         sw3[HYLCMAT_N3D], ihu3[HYLCMAT_N3D], ihv3[HYLCMAT_N3D], ihw3[HYLCMAT_N3D];
  /* evaluator: below sw (table units) the bending divided differences of a term use the
     piecewise-polynomial form (docs/material.md); ih = (n - 1) / (t[n-1] - t[0]) of each knot vector
     is the first guess of the interval search */
  double sw1[HYLCMAT_N1D], sw2[HYLCMAT_N2D];
  double ih1[HYLCMAT_N1D], ihu[HYLCMAT_N2D], ihv[HYLCMAT_N2D];
  /* ushare[q] = an earlier pair q' < q of the same u-coordinate and the same u-knots and extension
     (its u-basis is the same: the evaluator reuses it), or -1 (src/hylcmat/core.c: UShare) */
  int ushare[HYLCMAT_N2D];
};

/* the terms' names and pairs: the shared vocabulary (include/hylc/strain.h, src/sys/strain.c) */
#define HylcmatPairs   HylcPairCoords
#define HylcmatNames1D HylcCoordNames
#define HylcmatNames2D HylcPairNames

/* where a message goes: the caller's buffer (may be NULL) */
typedef struct {
  char  *buf;
  size_t len;
} hm_err;

/* formats the message into e (if any) and returns code */
HM_INTERN int hm_fail(hm_err *e, int code, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#define HM_CHECK(cond, e, code, ...)                       \
  do {                                                     \
    if (!(cond)) return hm_fail((e), (code), __VA_ARGS__); \
  } while (0)
#define HM_CALL(x)           \
  do {                       \
    const int hm_r_ = (x);   \
    if (hm_r_) return hm_r_; \
  } while (0)

/* the largest area density a table may hold (kg/m^2; include/hylcmat.h, docs/material.md): far beyond
   any cloth's (a 1e300 made the cloth's weight-based tolerances overflow) */
#define HM_MAX_DENSITY 1e6

/* The contents of a material file as read by the JSON and HDF5 parsers, before they are installed
   through the validating setters (hm_doc_install). */
typedef struct {
  const char    *name; /* file name, for messages */
  hm_err        *E;
  double         density, scale[5], C0;
  int            shift[5];
  int            n1, n2, n3; /* terms read so far */
  hylcmat_term1d s1[HYLCMAT_N1D];
  hylcmat_term2d s2[HYLCMAT_N2D];
  hylcmat_term3d s3[HYLCMAT_N3D];
} hm_doc;

HM_INTERN void hm_doc_init(hm_doc *d, const char *name, hm_err *E);
HM_INTERN void hm_doc_free(hm_doc *d);
/* a new table with the document's contents (validated), then frees the document */
HM_INTERN int hm_doc_install(hm_doc *d, hylcmat **m);

/* reads the whole file path (a what, for messages: "material file") into a new NUL-terminated buffer
   *bytes (len bytes without the NUL); errors OPEN (missing, a directory, not a regular file), READ,
   FORMAT (1 GiB or more), MEMORY with a message naming the file */
HM_INTERN int hm_read_file(const char *path, const char *what, char **bytes, size_t *len, hm_err *E);

HM_INTERN int hm_parse_json(const char *name, const char *text, size_t len, hm_err *E, hylcmat **m);
#ifdef HYLCMAT_WITH_HDF5
HM_INTERN int hm_parse_hdf5(const char *name, const void *image, size_t len, hm_err *E, hylcmat **m);
#endif
#endif
