/* Unit tests of the procedural knit generators (include/hylc/private/knit.h):
   sampling and periodicity, interlocking topology, and clearance between yarns.
   Silent on success; set HYLC_KNIT_REPORT=1 to print the measured figures. */
#include <hylc/geom.h>
#include <hylc/private/knit.h>
#include <stdlib.h>
#include <string.h>
#include "hylctest.h"

typedef struct {
  int     nyarns, *nverts, nw, m; /* m: vertices per stitch */
  double *pts, px, py, r, w, c;
  long   *off; /* first vertex of each yarn */
} Tile;

static int MakeTile(HylcKnitType type, const HylcKnitParams *p, Tile *t)
{
  char msg[256];
  memset(t, 0, sizeof(*t));
  int ierr = HylcKnitSample(type, p, &t->nyarns, &t->nverts, &t->pts, &t->px, &t->py, msg, sizeof msg);
  HYLC_CHECK(ierr == 0, "HylcKnitSample failed: %s", msg);
  if (ierr) return 1;
  t->nw     = p->nwales;
  t->r      = p->r;
  t->w      = t->px / p->nwales;
  t->c      = t->py / p->ncourses;
  t->m      = t->nverts[0] / p->nwales;
  t->off    = malloc((size_t)(t->nyarns + 1) * sizeof(long));
  t->off[0] = 0;
  for (int k = 0; k < t->nyarns; k++) t->off[k + 1] = t->off[k] + t->nverts[k];
  return 0;
}

static void FreeTile(Tile *t)
{
  free(t->nverts);
  free(t->pts);
  free(t->off);
}

/* Vertex v (any integer, unwrapped: v >= n continues with +px) of yarn k, shifted by (sx px, sy py). */
static void Vert(const Tile *t, int k, long v, int sx, int sy, double x[3])
{
  const long n = t->nverts[k];
  long       q = v % n, wrap = v / n;
  if (q < 0) {
    q += n;
    wrap -= 1;
  }
  const double *y = t->pts + 3 * (t->off[k] + q);
  x[0]            = y[0] + (wrap + sx) * t->px;
  x[1]            = y[1] + sy * t->py;
  x[2]            = y[2];
}

/* Counts, checks and edge lengths (every edge, including the periodic closing one, within +-30% of seglen). */
static void CheckSampling(const Tile *t, const HylcKnitParams *p, double seglen, const char *name)
{
  HYLC_CHECK(t->nyarns == p->ncourses, "%s: nyarns %d", name, t->nyarns);
  HYLC_CHECK(t->m % 2 == 0 && t->m >= HYLC_KNIT_MIN_VERTS_PER_STITCH, "%s: %d vertices per stitch", name, t->m);
  double mean[3] = {0, 0, 0}, emin = INFINITY, emax = 0;
  long   ntot = 0;
  for (int k = 0; k < t->nyarns; k++) {
    HYLC_CHECK(t->nverts[k] == t->m * t->nw, "%s: yarn %d has %d vertices", name, k, t->nverts[k]);
    for (long v = 0; v < t->nverts[k]; v++) {
      double a[3], b[3], e[3];
      Vert(t, k, v, 0, 0, a);
      Vert(t, k, v + 1, 0, 0, b);
      HylcSub3(b, a, e);
      const double l = HylcNorm3(e);
      if (l < emin) emin = l;
      if (l > emax) emax = l;
      for (int q = 0; q < 3; q++) mean[q] += a[q];
      ntot++;
    }
  }
  HYLC_CHECK(emin >= 0.7 * seglen && emax <= 1.3 * seglen, "%s: edge lengths [%g, %g] vs seglen %g", name, emin, emax, seglen);
  for (int q = 0; q < 3; q++) HYLC_CHECK(fabs(mean[q] / ntot) < 1e-9 * t->px, "%s: mean[%d] = %g", name, q, mean[q] / ntot);
  if (getenv("HYLC_KNIT_REPORT"))
    printf("%s: px %.4g py %.4g (units r: %.3f x %.3f), %d verts/stitch, edge/seglen in [%.3f, %.3f], stitch length %.3f r\n", name, t->px, t->py, t->px / t->r, t->py / t->r, t->m, emin / seglen, emax / seglen, t->m * (emin + emax) / 2 / t->r);
}

/* Stitch i of a yarn repeats stitch 0 shifted by i*wale (stockinette) or z-mirrored on odd i (rib). */
static void CheckStitchPeriodicity(const Tile *t, int rib, const char *name)
{
  double err = 0;
  for (int k = 0; k < t->nyarns; k++)
    for (int i = 0; i < t->nw; i++)
      for (int q = 0; q < t->m; q++) {
        double a[3], b[3];
        Vert(t, k, q, 0, 0, a);
        Vert(t, k, (long)i * t->m + q, 0, 0, b);
        const double zs = (rib && (i % 2)) ? -1.0 : 1.0;
        err             = fmax(err, fabs(b[0] - a[0] - i * t->w) + fabs(b[1] - a[1]) + fabs(b[2] - zs * a[2]));
      }
  HYLC_CHECK(err < 1e-9 * t->px, "%s: stitch periodicity error %g", name, err);
}

/* Signed crossings, in the xy projection, of the closed polygon R (nr vertices) with the open polyline A
   (na vertices). over: sum of crossing signs where A passes above R (larger z), under: where R is above.
   Crossing sign: sign of (t_over x t_under).z. If the ends of A lie outside the projection of R and can be
   joined far away without crossing it, over == under == linking number of R with the closed-up A. */
static void Crossings(const double *R, int nr, const double *A, int na, int *over, int *under)
{
  *over = *under = 0;
  for (int a = 0; a < nr; a++) {
    const double *p0 = R + 3 * a, *p1 = R + 3 * ((a + 1) % nr);
    for (int b = 0; b + 1 < na; b++) {
      const double *q0 = A + 3 * b, *q1 = A + 3 * (b + 1);
      const double  d1x = p1[0] - p0[0], d1y = p1[1] - p0[1], d2x = q1[0] - q0[0], d2y = q1[1] - q0[1];
      const double  den = d1x * d2y - d1y * d2x;
      if (den == 0) continue;
      const double ex = q0[0] - p0[0], ey = q0[1] - p0[1];
      const double s = (ex * d2y - ey * d2x) / den, u = (ex * d1y - ey * d1x) / den;
      if (s < 0 || s >= 1 || u < 0 || u >= 1) continue;
      const double zr = p0[2] + s * (p1[2] - p0[2]), za = q0[2] + u * (q1[2] - q0[2]);
      if (za > zr)
        *over += (d2x * d1y - d2y * d1x) > 0 ? 1 : -1; /* A over R: t_A x t_R */
      else
        *under += den > 0 ? 1 : -1; /* R over A: t_R x t_A */
    }
  }
}

/* Linking of stitch i of course j (closed by the straight segment between its two sinker centres) with
   the left (half = 0) or right (half = 1) half of stitch i2 of the yarn dc courses above. Checks that the
   over and under counts agree and returns the linking number. */
static int StitchPassage(const Tile *t, int j, int i, int dc, int i2, int half, const char *name)
{
  const int nc = t->nyarns, m = t->m;
  double   *R = malloc(3 * (size_t)(m + 1) * sizeof(double)), *A = malloc(3 * (size_t)(m / 2 + 1) * sizeof(double));
  for (int q = 0; q <= m; q++) Vert(t, j, (long)i * m + q, 0, 0, R + 3 * q);
  const int jn = (j + dc) % nc, sy = (j + dc) / nc;
  for (int q = 0; q <= m / 2; q++) Vert(t, jn, (long)i2 * m + half * (m / 2) + q, 0, sy, A + 3 * q);
  int over, under;
  Crossings(R, m + 1, A, m / 2 + 1, &over, &under);
  HYLC_CHECK(over == under, "%s: course %d stitch %d vs course +%d stitch %d half %d: over %d != under %d", name, j, i, dc, i2, half, over, under);
  free(R);
  free(A);
  return over;
}

/* Every stitch of every course is interlocked with the course above: its left half passes through the
   stitch below with linking number sigma_i = +-1 and its right half with -sigma_i; sigma is the same for all
   stitches of a stockinette and alternates between wales of a rib. Non-neighbouring stitches and the
   course two above are not linked. */
static void CheckTopology(const Tile *t, int rib, const char *name)
{
  const int ref = StitchPassage(t, 0, 0, 1, 0, 0, name);
  HYLC_CHECK(ref == 1 || ref == -1, "%s: stitch (0,0) linking %d, expected +-1", name, ref);
  for (int j = 0; j < t->nyarns; j++)
    for (int i = 0; i < t->nw; i++) {
      const int expect = (rib && (i % 2)) ? -ref : ref;
      const int left = StitchPassage(t, j, i, 1, i, 0, name), right = StitchPassage(t, j, i, 1, i, 1, name);
      HYLC_CHECK(left == expect && right == -expect, "%s: course %d stitch %d: linking %d/%d, expected %d/%d", name, j, i, left, right, expect, -expect);
      if (t->nw > 2) {
        const int in = (i + 1) % t->nw;
        HYLC_CHECK(StitchPassage(t, j, i, 1, in, 0, name) == 0, "%s: course %d stitch %d linked with stitch %d above", name, j, i, in);
      }
      HYLC_CHECK(StitchPassage(t, j, i, 2, i, 0, name) == 0 && StitchPassage(t, j, i, 2, i, 1, name) == 0, "%s: course %d stitch %d linked with course +2", name, j, i);
    }
}

/* Minimum centreline distance between segments of different yarns (including periodic images) and between
   segments of the same yarn more than 4r apart along the arc; over image shifts -1..1 in x and y. */
static void MinDistances(const Tile *t, double *dother, double *dself)
{
  *dother = *dself = INFINITY;
  for (int a = 0; a < t->nyarns; a++) {
    const long na = t->nverts[a];
    double    *sa = malloc((size_t)(na + 1) * sizeof(double)); /* arc length at vertex v (0..na) */
    sa[0]         = 0;
    for (long v = 0; v < na; v++) {
      double x0[3], x1[3], e[3];
      Vert(t, a, v, 0, 0, x0);
      Vert(t, a, v + 1, 0, 0, x1);
      HylcSub3(x1, x0, e);
      sa[v + 1] = sa[v] + HylcNorm3(e);
    }
    const double La = sa[na];
    for (int b = a; b < t->nyarns; b++)
      for (int sx = -1; sx <= 1; sx++)
        for (int sy = -1; sy <= 1; sy++) {
          const int same = (a == b && sy == 0);
          for (long u = 0; u < na; u++)
            for (long v = 0; v < t->nverts[b]; v++) {
              if (same) { /* arc gap between segment u and segment v of the unwrapped yarn shifted by sx laps */
                const double su0 = sa[u], su1 = sa[u + 1], sv0 = sa[v] + sx * La, sv1 = sa[v + 1] + sx * La;
                const double gap = sv0 >= su1 ? sv0 - su1 : (su0 >= sv1 ? su0 - sv1 : -1);
                if (gap <= 4 * t->r) continue;
              }
              double p0[3], p1[3], q0[3], q1[3], s, tt;
              Vert(t, a, u, 0, 0, p0);
              Vert(t, a, u + 1, 0, 0, p1);
              Vert(t, b, v, sx, sy, q0);
              Vert(t, b, v + 1, sx, sy, q1);
              const double d = HylcSegmentSegmentDistance(p0, p1, q0, q1, &s, &tt);
              if (same)
                *dself = fmin(*dself, d);
              else
                *dother = fmin(*dother, d);
            }
        }
    free(sa);
  }
  *dother /= t->r;
  *dself /= t->r;
}

/* Full check of one tile; floor: required minimum distance in units of r (both kinds). */
static void CheckTile(HylcKnitType type, HylcKnitParams p, double floor_r, const char *name)
{
  Tile      t;
  const int rib = type == HYLC_KNIT_RIB;
  if (MakeTile(type, &p, &t)) return;
  CheckSampling(&t, &p, p.seglen > 0 ? p.seglen : p.r, name);
  CheckStitchPeriodicity(&t, rib, name);
  CheckTopology(&t, rib, name);
  double dother, dself;
  MinDistances(&t, &dother, &dself);
  HYLC_CHECK(dother >= floor_r && dself >= floor_r, "%s: min distance between yarns %.3f r, within a yarn (> 4r of arc) %.3f r; floor %.2f r", name, dother, dself, floor_r);
  if (getenv("HYLC_KNIT_REPORT")) printf("%s: min distance between yarns %.3f r, within a yarn %.3f r\n", name, dother, dself);
  FreeTile(&t);
}

static void CheckRejected(HylcKnitType type, HylcKnitParams p, const char *name)
{
  int     ny = -7, *nv = NULL;
  double *x = NULL, px = 0, py = 0;
  char    msg[128] = "";
  int     ierr     = HylcKnitSample(type, &p, &ny, &nv, &x, &px, &py, msg, sizeof msg);
  HYLC_CHECK(ierr != 0 && msg[0] != 0, "%s: invalid parameters accepted (ierr %d)", name, ierr);
  HYLC_CHECK(ny == -7 && !nv && !x, "%s: outputs touched on error", name);
  if (!ierr) {
    free(nv);
    free(x);
  }
}

int main(void)
{
  const double   r = 1e-3;
  HylcKnitParams d = {.r = r, .nwales = 2, .ncourses = 2};

  /* defaults (the paper's stockinette layout: 2 stitches x 2 courses) */
  CheckTile(HYLC_KNIT_STOCKINETTE, d, 1.6, "stockinette 2x2");
  CheckTile(HYLC_KNIT_RIB, d, 1.35, "rib 2x2");
  {
    HylcKnitParams p = d;
    p.nwales = p.ncourses = 1;
    CheckTile(HYLC_KNIT_STOCKINETTE, p, 1.6, "stockinette 1x1");
    p.nwales = 3, p.ncourses = 3;
    CheckTile(HYLC_KNIT_STOCKINETTE, p, 1.6, "stockinette 3x3");
    p.nwales = 4, p.ncourses = 1;
    CheckTile(HYLC_KNIT_RIB, p, 1.35, "rib 4x1");
    p.nwales = 4, p.ncourses = 3;
    CheckTile(HYLC_KNIT_RIB, p, 1.35, "rib 4x3");
  }
  /* other proportions and sampling densities, other radius */
  {
    HylcKnitParams p = {.r = 0.1e-3, .wale = 0.9e-3, .course = 0.45e-3, .depth = 0.15e-3, .seglen = 0.05e-3, .nwales = 2, .ncourses = 2};
    CheckTile(HYLC_KNIT_STOCKINETTE, p, 1.0, "stockinette r=0.1mm wide fine");
    CheckTile(HYLC_KNIT_RIB, p, 1.0, "rib r=0.1mm wide fine");
    HylcKnitParams q = d;
    q.seglen         = 2.5 * r;
    CheckTile(HYLC_KNIT_STOCKINETTE, q, 1.0, "stockinette coarse");
    CheckTile(HYLC_KNIT_RIB, q, 1.0, "rib coarse");
  }

  /* invalid parameters */
  {
    HylcKnitParams p = d;
    p.nwales         = 3;
    CheckRejected(HYLC_KNIT_RIB, p, "rib with odd nwales");
    p   = d;
    p.r = 0;
    CheckRejected(HYLC_KNIT_STOCKINETTE, p, "r = 0");
    p   = d;
    p.r = NAN;
    CheckRejected(HYLC_KNIT_STOCKINETTE, p, "r = nan");
    p        = d;
    p.nwales = 0;
    CheckRejected(HYLC_KNIT_STOCKINETTE, p, "nwales = 0");
    p          = d;
    p.ncourses = 0;
    CheckRejected(HYLC_KNIT_STOCKINETTE, p, "ncourses = 0");
    p        = d;
    p.seglen = 10 * r;
    CheckRejected(HYLC_KNIT_STOCKINETTE, p, "seglen too large");
    p      = d;
    p.wale = INFINITY;
    CheckRejected(HYLC_KNIT_STOCKINETTE, p, "wale = inf");
    CheckRejected((HylcKnitType)7, d, "unknown type");
  }
  return HYLC_TEST_RESULT();
}
