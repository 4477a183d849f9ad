#pragma once
/* Procedural yarn centrelines of periodic weft-knit tiles (stockinette, 1x1 rib).
   Plain C (no PETSc types). The curve model, the defaults and measured clearances are documented in
   docs/knit-generators.md.

   Conventions: every yarn is one course running along +x that closes after one tile width
   (winding (1,0)); course j lies at y ~ j*course; +z is the technical face (the side where the legs of
   knit stitches lie). Each yarn starts at a sinker centre (the point between two stitches), its first
   stitch is a knit stitch, and every stitch has the same even number of vertices, so stitch i of a yarn
   is the vertex range [i*m, (i+1)*m) with m = nverts[k]/nwales and vertex i*m + m/2 is the centre of
   that stitch's needle-loop head.

   The generated tile may contain small overlaps between yarns (centreline distances a bit below 2r);
   they are removed later by the contact-aware reference-state relaxation. */
#include <stddef.h>

typedef struct {
  double r;        /* yarn radius (m); required, > 0 */
  double wale;     /* stitch width along x (m); <= 0: default HYLC_KNIT_DEFAULT_WALE * r */
  double course;   /* course height along y (m); <= 0: default HYLC_KNIT_DEFAULT_COURSE * r */
  double depth;    /* z amplitude (m): centrelines span about [-depth, depth]; <= 0: HYLC_KNIT_DEFAULT_DEPTH * r */
  double seglen;   /* target edge length (m); <= 0: default r */
  int    nwales;   /* stitches per course in the tile (>= 1; rib needs an even number) */
  int    ncourses; /* courses in the tile (>= 1) */
} HylcKnitParams;

typedef enum { HYLC_KNIT_STOCKINETTE, HYLC_KNIT_RIB } HylcKnitType;

/* Defaults, in units of r (proportions of the relaxed stockinette of Sperl et al. 2020:
   7.53 r per stitch, 3.97 r per course, z within about +-1.3 r). */
#define HYLC_KNIT_DEFAULT_WALE   7.5
#define HYLC_KNIT_DEFAULT_COURSE 4.0
#define HYLC_KNIT_DEFAULT_DEPTH  1.3

/* Fixed shape constants of the stitch curve (see docs/knit-generators.md):
   x = wale (T/2pi + LEAN sin 2T), y = -LOOP course cos T, z = -depth S(T) cos 2T,
   S = 1 (stockinette) or tanh(SHARP sin(T/2))/tanh(SHARP) (rib). */
#define HYLC_KNIT_LEAN  0.24
#define HYLC_KNIT_LOOP  0.84
#define HYLC_KNIT_SHARP 6.0

/* Minimum number of vertices per stitch (the stitch is rejected as too coarse below it). */
#define HYLC_KNIT_MIN_VERTS_PER_STITCH 8

/* Samples the yarn centrelines of a periodic knit tile. On success returns 0 and sets
   *nyarns (= ncourses), *nverts (malloc'd array of nyarns counts), *pts (malloc'd, concatenated
   3*sum(nverts) coordinates of the UNWRAPPED polylines: yarn k's vertices in order along the yarn; the
   yarn continues past its last vertex with its first vertex shifted by (px, 0, 0)), *px = nwales*wale,
   *py = ncourses*course. Vertices are at (approximately) uniform arc length with the same number of
   vertices per stitch (the even integer nearest to stitch length / seglen). Points are centred so the
   tile's mean vertex position is 0. Returns non-zero and writes a message into errmsg (size errlen; may
   be NULL) on invalid parameters or allocation failure; the outputs are then untouched.
   The caller frees *nverts and *pts with free(). */
int HylcKnitSample(HylcKnitType type, const HylcKnitParams *p, int *nyarns, int **nverts, double **pts, double *px, double *py, char *errmsg, size_t errlen);
