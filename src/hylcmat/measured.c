/* hylcmat: measured cloth, the data-driven elastic model of Wang, O'Brien, Ramamoorthi (SIGGRAPH 2011) as
   the simulator its data were made for, ARCSim (Narain et al. 2012), evaluates it: the JSON reader and
   writer, the stiffness sample and its 30^3 lookup grid, the membrane energy of a face with its
   frozen-stiffness force and its own gradient, the bending of a hinge. Every convention, with its
   formula, is in docs/measured-cloth.md. Plain C99, no global state. */
#include "hylcmatimpl.h"
#include <hylc/private/json.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define NG    HYLCMAT_MEASURED_GRID
#define HM_PI 3.14159265358979323846

struct hylcmat_measured {
  double  density;       /* kg/m^2 */
  double  stretch[6][4]; /* the file's rows r0..r5 */
  double  bend[3][5];    /* rows: edges along u, at 45 degrees, along v; columns kappa = 0..40 1/m */
  double *grid;          /* khat at G00 = -0.25 + i/30, G11 = -0.25 + j/30, G01 = l/30: ((i NG + j) NG + l) 4 + c */
};

/* ---- the stiffness sample ----------------------------------------------------------------------- */
static void Sample(const double d[6][4], const double G[3], double k[4])
{
  const double a = 2 * G[0] + 1, b = 2 * G[2], c = 2 * G[1] + 1; /* C = 2G + I */
  const double l1 = 0.5 * ((a + c) + sqrt(4 * b * b + (a - c) * (a - c)));
  double       v0, v1;

  if (b != 0) {
    v0 = l1 - c;
    v1 = b;
  } else if (a >= c) {
    v0 = 1;
    v1 = 0;
  } else {
    v0 = 0;
    v1 = 1;
  }
  double sigma    = 6 * (sqrt(fmax(l1, 0)) - 1); /* level 1 at a principal stretch of 1/6 */
  sigma           = fmin(fmax(sigma, 0), 1 - 1e-6);
  double alpha    = 8 * fabs(atan2(v1, v0)) / HM_PI; /* 0, 22.5, 45, 67.5, 90 degrees -> 0..4 */
  alpha           = fmin(fmax(alpha, 0), 4 - 1e-6);
  const int    j  = (int)floor(alpha);
  const double wa = alpha - j;
  for (int q = 0; q < 4; q++) {
    const double lo = d[0][q], hi = (1 - wa) * d[j + 1][q] + wa * d[j + 2][q];
    k[q] = 2 * fmax((1 - sigma) * lo + sigma * hi, 0);
  }
}

static void BuildGrid(hylcmat_measured *mc)
{
  for (int i = 0; i < NG; i++)
    for (int j = 0; j < NG; j++)
      for (int l = 0; l < NG; l++) {
        const double G[3] = {-0.25 + i / (double)NG, -0.25 + j / (double)NG, l / (double)NG};
        Sample((const double(*)[4])mc->stretch, G, mc->grid + 4 * (((size_t)i * NG + j) * NG + l));
      }
}

void hylcmat_measured_sample(const hylcmat_measured *mc, const double G[3], double khat[4]) { Sample((const double(*)[4])mc->stretch, G, khat); }

/* a grid coordinate: the cell index, the weight and d(coordinate)/dG (0 where clamped) */
static void Coord(double x, int *i, double *w, double *dx)
{
  *dx = NG;
  if (!(x > 0)) x = 0, *dx = 0; /* also NaN */
  if (x > NG - 1 - 1e-5) x = NG - 1 - 1e-5, *dx = 0;
  int c = (int)floor(x);
  if (c < 0) c = 0;
  if (c > NG - 2) c = NG - 2;
  *i = c;
  *w = x - c;
}

void hylcmat_measured_stiffness(const hylcmat_measured *mc, const double G[3], double k[4], double dk[12])
{
  int    i[3];
  double w[3], dx[3];

  Coord((G[0] + 0.25) * NG, &i[0], &w[0], &dx[0]);
  Coord((G[1] + 0.25) * NG, &i[1], &w[1], &dx[1]);
  Coord(fabs(G[2]) * NG, &i[2], &w[2], &dx[2]);
  dx[2] *= G[2] > 0 ? 1 : G[2] < 0 ? -1 : 0;
  for (int q = 0; q < 4; q++) k[q] = 0;
  if (dk)
    for (int q = 0; q < 12; q++) dk[q] = 0;
  for (int c = 0; c < 8; c++) {
    const int     b[3] = {c & 1, c >> 1 & 1, c >> 2 & 1};
    const double *g    = mc->grid + 4 * (((size_t)(i[0] + b[0]) * NG + (i[1] + b[1])) * NG + (i[2] + b[2]));
    double        f[3], df[3];
    for (int a = 0; a < 3; a++) {
      f[a]  = b[a] ? w[a] : 1 - w[a];
      df[a] = (b[a] ? 1 : -1) * dx[a];
    }
    const double wt = f[0] * f[1] * f[2];
    for (int q = 0; q < 4; q++) k[q] += wt * g[q];
    if (dk)
      for (int q = 0; q < 4; q++) {
        dk[3 * q + 0] += df[0] * f[1] * f[2] * g[q];
        dk[3 * q + 1] += f[0] * df[1] * f[2] * g[q];
        dk[3 * q + 2] += f[0] * f[1] * df[2] * g[q];
      }
  }
}

void hylcmat_measured_membrane(const hylcmat_measured *mc, const double G[3], double *psi, double frozen[3], double energy[3], double kout[4])
{
  double       k[4], dk[12];
  const double q[4] = {G[0] * G[0], 2 * G[0] * G[1], G[1] * G[1], G[2] * G[2]};

  hylcmat_measured_stiffness(mc, G, k, energy ? dk : NULL);
  const double S[3] = {k[0] * G[0] + k[1] * G[1], k[1] * G[0] + k[2] * G[1], k[3] * G[2]};
  if (psi) *psi = 0.5 * (k[0] * q[0] + k[1] * q[1] + k[2] * q[2] + k[3] * q[3]);
  if (frozen)
    for (int a = 0; a < 3; a++) frozen[a] = S[a];
  if (energy)
    for (int a = 0; a < 3; a++) energy[a] = S[a] + 0.5 * (dk[a] * q[0] + dk[3 + a] * q[1] + dk[6 + a] * q[2] + dk[9 + a] * q[3]);
  if (kout)
    for (int c = 0; c < 4; c++) kout[c] = k[c];
}

/* ---- a face ------------------------------------------------------------------------------------- */
/* F = [x_u | x_v] of the triangle: Fu, Fv (3 each) */
static int Deformation(const hylcmat_shell_rest *r, const double x[9], double Fu[3], double Fv[3])
{
  const double *D = r->dinv;
  for (int c = 0; c < 3; c++) {
    const double d1 = x[3 + c] - x[c], d2 = x[6 + c] - x[c];
    Fu[c] = D[0] * d1 + D[2] * d2;
    Fv[c] = D[1] * d1 + D[3] * d2;
    if (!isfinite(Fu[c]) || !isfinite(Fv[c])) return HYLCMAT_ERR_NONFINITE;
  }
  return HYLCMAT_OK;
}

static void GreenOf(const double Fu[3], const double Fv[3], double G[3])
{
  G[0] = 0.5 * (Fu[0] * Fu[0] + Fu[1] * Fu[1] + Fu[2] * Fu[2] - 1);
  G[1] = 0.5 * (Fv[0] * Fv[0] + Fv[1] * Fv[1] + Fv[2] * Fv[2] - 1);
  G[2] = 0.5 * (Fu[0] * Fv[0] + Fu[1] * Fv[1] + Fu[2] * Fv[2]);
}

int hylcmat_measured_green(const hylcmat_shell_rest *r, const double x[9], double G[3])
{
  double Fu[3], Fv[3];
  if (!r || !x || !G) return HYLCMAT_ERR_ARG;
  G[0] = G[1] = G[2] = 0;
  HM_CALL(Deformation(r, x, Fu, Fv));
  GreenOf(Fu, Fv, G);
  return HYLCMAT_OK;
}

/* out (9) = s A dpsi/dx for dpsi/dG = D: P = dpsi/dF, columns D00 Fu + D01/2 Fv and D11 Fv + D01/2 Fu */
static void Chain(const hylcmat_shell_rest *r, const double Fu[3], const double Fv[3], const double D[3], double s, double out[9])
{
  const double *Di = r->dinv;
  for (int c = 0; c < 3; c++) {
    const double P0 = D[0] * Fu[c] + 0.5 * D[2] * Fv[c], P1 = D[1] * Fv[c] + 0.5 * D[2] * Fu[c];
    const double g1 = s * r->area * (P0 * Di[0] + P1 * Di[1]), g2 = s * r->area * (P0 * Di[2] + P1 * Di[3]);
    out[3 + c] = g1;
    out[6 + c] = g2;
    out[c]     = -(g1 + g2);
  }
}

int hylcmat_measured_face(const hylcmat_measured *mc, const hylcmat_shell_rest *r, const double x[9], double *E, double force[9], double grad[9], double Gout[3])
{
  double Fu[3], Fv[3], G[3], psi, Sf[3], Se[3];
  int    rc;

  if (E) *E = 0;
  if (force) memset(force, 0, 9 * sizeof(double));
  if (grad) memset(grad, 0, 9 * sizeof(double));
  if (Gout) Gout[0] = Gout[1] = Gout[2] = 0;
  if (!mc || !r || !x) return HYLCMAT_ERR_ARG;
  if ((rc = Deformation(r, x, Fu, Fv))) return rc;
  GreenOf(Fu, Fv, G);
  hylcmat_measured_membrane(mc, G, &psi, Sf, grad ? Se : NULL, NULL);
  if (E) *E = r->area * psi;
  if (force) Chain(r, Fu, Fv, Sf, -1, force);
  if (grad) Chain(r, Fu, Fv, Se, 1, grad);
  if (Gout)
    for (int a = 0; a < 3; a++) Gout[a] = G[a];
  return HYLCMAT_OK;
}

double hylcmat_measured_face_mass(const hylcmat_measured *mc, const hylcmat_shell_rest *r) { return mc && r ? mc->density * r->area : 0; }

/* ---- bending ------------------------------------------------------------------------------------ */
double hylcmat_measured_bending_sample(const hylcmat_measured *mc, double kappa, const double du[2], double *dkdkappa)
{
  double value = 0.1 * kappa, dvalue = 0.1; /* samples every 10 1/m */
  if (value > 4) value = 4, dvalue = 0;
  int vi = (int)value; /* truncation toward 0: a negative kappa extrapolates the first interval */
  if (vi < 0) vi = 0;
  if (vi > 3) vi = 3;
  const double wv   = value - vi;
  double       beta = 4 * atan2(du[1], du[0]) / HM_PI; /* the direction, folded into [0, 2] */
  if (beta < 0) beta = -beta;
  if (beta > 4) beta = 8 - beta;
  if (beta > 2) beta = 4 - beta;
  int bi = (int)beta;
  if (bi < 0) bi = 0;
  if (bi > 1) bi = 1;
  const double wb     = beta - bi;
  const double(*b)[5] = (const double(*)[5])mc->bend;
  const double lo = (1 - wb) * b[bi][vi] + wb * b[bi + 1][vi], hi = (1 - wb) * b[bi][vi + 1] + wb * b[bi + 1][vi + 1];
  const double k = (1 - wv) * lo + wv * hi;
  if (dkdkappa) *dkdkappa = k > 0 ? dvalue * (hi - lo) : 0;
  return fmax(k, 0);
}

static inline double Dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline void   Cross3(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

int hylcmat_measured_edge(const hylcmat_measured *mc, const double uv[8], const double x[12], double theta_rest, double *E, double force[12], hylcmat_measured_hinge *info)
{
  double e[3], ea[3], N0[3], N1[3], t0[3], t1[3], c[3];

  if (E) *E = 0;
  if (force) memset(force, 0, 12 * sizeof(double));
  if (info) memset(info, 0, sizeof(*info));
  if (!mc || !uv || !x) return HYLCMAT_ERR_ARG;
  for (int i = 0; i < 12; i++)
    if (!isfinite(x[i])) return HYLCMAT_ERR_NONFINITE;
  for (int i = 0; i < 8; i++)
    if (!isfinite(uv[i]) || !isfinite(theta_rest)) return HYLCMAT_ERR_ARG;
  /* material: the edge a -> b, the two faces' areas */
  const double du[2] = {uv[2] - uv[0], uv[3] - uv[1]};
  const double l     = hypot(du[0], du[1]);
  const double A0    = 0.5 * fabs(du[0] * (uv[5] - uv[1]) - du[1] * (uv[4] - uv[0]));
  const double A1    = 0.5 * fabs(du[0] * (uv[7] - uv[1]) - du[1] * (uv[6] - uv[0]));
  if (!(l > 0) || !(A0 > 0) || !(A1 > 0)) return HYLCMAT_ERR_DEGENERATE;
  /* deformed: N0 = (b - a) x (p0 - a), N1 = (a - b) x (p1 - b), e = a - b */
  for (int q = 0; q < 3; q++) {
    e[q]  = x[q] - x[3 + q];
    ea[q] = x[3 + q] - x[q];
    t0[q] = x[6 + q] - x[q];
    t1[q] = x[9 + q] - x[3 + q];
  }
  Cross3(ea, t0, N0);
  Cross3(e, t1, N1);
  const double le = sqrt(Dot3(e, e)), n0 = sqrt(Dot3(N0, N0)), n1 = sqrt(Dot3(N1, N1));
  if (!(le > 0) || !(n0 > 0) || !(n1 > 0)) return HYLCMAT_ERR_DEGENERATE;
  Cross3(N0, N1, c);
  const double theta = atan2(Dot3(e, c) / (le * n0 * n1), Dot3(N0, N1) / (n0 * n1));
  const double area = A0 + A1, kappa = theta * l / area, shape = l * l / (2 * area);
  const double k = hylcmat_measured_bending_sample(mc, kappa, du, NULL);
  const double d = theta - theta_rest;
  if (E) *E = k * shape * d * d / 4;
  if (force) { /* -dE/dtheta dtheta/dx: dtheta/dp = |e| N / |N|^2 for each wing p, the edge's ends by invariance */
    const double f = -k * shape * d / 2;
    double       w1[3];
    for (int q = 0; q < 3; q++) w1[q] = x[9 + q] - x[q];
    const double p0a = Dot3(t0, ea) / le, p1a = Dot3(w1, ea) / le; /* the wings along a -> b, from a */
    const double p0b = p0a - le, p1b = p1a - le;                   /* and from b */
    for (int q = 0; q < 3; q++) {
      const double g0 = N0[q] / (n0 * n0), g1 = N1[q] / (n1 * n1);
      force[6 + q] = f * le * g0;
      force[9 + q] = f * le * g1;
      force[q]     = f * (p0b * g0 + p1b * g1);
      force[3 + q] = -f * (p0a * g0 + p1a * g1);
    }
  }
  if (info) {
    info->theta  = theta;
    info->kappa  = kappa;
    info->length = l;
    info->area   = area;
    info->k      = k;
    info->shape  = shape;
  }
  return HYLCMAT_OK;
}

/* ---- the data: create, read, write --------------------------------------------------------------- */
static int Check(const double v[], int rows, int cols, const char what[], hm_err *E)
{
  char b[32];
  for (int i = 0; i < rows * cols; i++) HM_CHECK(isfinite(v[i]), E, HYLCMAT_ERR_FORMAT, "measured cloth: %s[%d][%d] must be finite, got %s", what, i / cols, i % cols, hylcmat_format_double(v[i], b));
  return HYLCMAT_OK;
}

int hylcmat_measured_create(double density, const double stretching[24], const double bending[15], hylcmat_measured **mc, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  char   b[32];

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_create: NULL result pointer");
  *mc = NULL;
  HM_CHECK(stretching && bending, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_create: NULL data");
  HM_CHECK(isfinite(density) && density >= 0, &E, HYLCMAT_ERR_FORMAT, "measured cloth: the density must be finite and >= 0 (kg/m^2), got %s", hylcmat_format_double(density, b));
  HM_CALL(Check(stretching, 6, 4, "stretching", &E));
  HM_CALL(Check(bending, 3, 5, "bending", &E));
  hylcmat_measured *m = calloc(1, sizeof(*m));
  if (m) m->grid = malloc(sizeof(double) * 4 * NG * NG * NG);
  if (!m || !m->grid) {
    free(m);
    return hm_fail(&E, HYLCMAT_ERR_MEMORY, "measured cloth: out of memory");
  }
  m->density = density;
  memcpy(m->stretch, stretching, sizeof(m->stretch));
  memcpy(m->bend, bending, sizeof(m->bend));
  BuildGrid(m);
  *mc = m;
  return HYLCMAT_OK;
}

void hylcmat_measured_free(hylcmat_measured *mc)
{
  if (!mc) return;
  free(mc->grid);
  free(mc);
}

void hylcmat_measured_data(const hylcmat_measured *mc, double stretching[24], double bending[15])
{
  if (stretching) memcpy(stretching, mc->stretch, sizeof(mc->stretch));
  if (bending) memcpy(bending, mc->bend, sizeof(mc->bend));
}

double hylcmat_measured_density(const hylcmat_measured *mc) { return mc->density; }

int hylcmat_measured_scale(hylcmat_measured *mc, double density_mult, double stretching_mult, double bending_mult, char *err, size_t errlen)
{
  hm_err       E        = {err, errlen};
  const double mult[3]  = {density_mult, stretching_mult, bending_mult};
  const char  *names[3] = {"density", "stretching", "bending"};
  char         b[32];

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_scale: NULL material");
  for (int i = 0; i < 3; i++) HM_CHECK(isfinite(mult[i]) && mult[i] > 0, &E, HYLCMAT_ERR_ARG, "measured cloth: the %s multiplier must be finite and > 0, got %s", names[i], hylcmat_format_double(mult[i], b));
  mc->density *= density_mult;
  for (int i = 0; i < 6; i++)
    for (int q = 0; q < 4; q++) mc->stretch[i][q] *= stretching_mult;
  for (int i = 0; i < 3; i++)
    for (int q = 0; q < 5; q++) mc->bend[i][q] *= bending_mult;
  BuildGrid(mc);
  return HYLCMAT_OK;
}

/* the reader: a document { "density": n, "stretching": [6 x [4 numbers]], "bending": [3 x [5 numbers]] } */
static int ReadRows(const char *name, const HylcJson *v, const char key[], int rows, int cols, double *out, hm_err *E)
{
  HM_CHECK(v->type == HYLC_JSON_ARRAY, E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected an array of %d rows of %d numbers, got %s", name, v->line, key, rows, cols, HylcJsonTypeName(v->type));
  HM_CHECK(v->n == rows, E, HYLCMAT_ERR_FORMAT, "%s:%d: %s: expected %d rows of %d numbers, got %d rows", name, v->line, key, rows, cols, v->n);
  for (int i = 0; i < rows; i++) {
    const HylcJson *r = &v->items[i];
    HM_CHECK(r->type == HYLC_JSON_ARRAY, E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: expected an array of %d numbers, got %s", name, r->line, key, i, cols, HylcJsonTypeName(r->type));
    HM_CHECK(r->n == cols, E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d]: expected %d numbers, got %d", name, r->line, key, i, cols, r->n);
    for (int j = 0; j < cols; j++) {
      HM_CHECK(r->items[j].type == HYLC_JSON_NUMBER, E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d][%d]: expected a number, got %s", name, r->items[j].line, key, i, j, HylcJsonTypeName(r->items[j].type));
      HM_CHECK(isfinite(r->items[j].num), E, HYLCMAT_ERR_FORMAT, "%s:%d: %s[%d][%d]: the number is out of the double range", name, r->items[j].line, key, i, j);
      out[i * cols + j] = r->items[j].num;
    }
  }
  return HYLCMAT_OK;
}

static int ReadDoc(const char *name, const HylcJson *root, hm_err *E, hylcmat_measured **mc)
{
  static const char *const keys[] = {"density", "stretching", "bending"};
  double                   st[24], be[15], rho;
  char                     b[32];

  HM_CHECK(root->type == HYLC_JSON_OBJECT, E, HYLCMAT_ERR_FORMAT, "%s:%d: the document: expected an object with \"density\", \"stretching\" and \"bending\", got %s", name, root->line, HylcJsonTypeName(root->type));
  for (int i = 0; i < root->n; i++) {
    int ok = 0;
    for (int j = 0; j < 3; j++) ok = ok || !strcmp(root->keys[i], keys[j]);
    HM_CHECK(ok, E, HYLCMAT_ERR_FORMAT, "%s:%d: unknown key \"%s\" (a measured-cloth file has \"density\", \"stretching\", \"bending\")", name, root->items[i].line, root->keys[i]);
  }
  for (int j = 0; j < 3; j++) HM_CHECK(HylcJsonMember(root, keys[j]), E, HYLCMAT_ERR_FORMAT, "%s:%d: missing key \"%s\"", name, root->line, keys[j]);
  const HylcJson *v = HylcJsonMember(root, "density");
  HM_CHECK(v->type == HYLC_JSON_NUMBER, E, HYLCMAT_ERR_FORMAT, "%s:%d: density: expected a number, got %s", name, v->line, HylcJsonTypeName(v->type));
  HM_CHECK(isfinite(v->num) && v->num >= 0, E, HYLCMAT_ERR_FORMAT, "%s:%d: density: the area density must be finite and >= 0 (kg/m^2), got %s", name, v->line, hylcmat_format_double(v->num, b));
  rho = v->num;
  HM_CALL(ReadRows(name, HylcJsonMember(root, "stretching"), "stretching", 6, 4, st, E));
  HM_CALL(ReadRows(name, HylcJsonMember(root, "bending"), "bending", 3, 5, be, E));
  return hylcmat_measured_create(rho, st, be, mc, E->buf, E->len);
}

int hylcmat_measured_load_memory(const char *name, const void *bytes, size_t len, hylcmat_measured **mc, char *err, size_t errlen)
{
  hm_err   E = {err, errlen};
  HylcJson root;
  int      r;

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_load_memory: NULL result pointer");
  *mc = NULL;
  if (!name) name = "(memory)";
  HM_CHECK(bytes || !len, &E, HYLCMAT_ERR_ARG, "%s: NULL bytes", name);
  memset(&root, 0, sizeof(root));
  r = HylcJsonParse(name, "a measured-cloth JSON file", bytes, len, &root, err, errlen);
  if (r) r = r == HYLC_JSON_ERR_MEMORY ? HYLCMAT_ERR_MEMORY : HYLCMAT_ERR_FORMAT;
  if (!r) r = ReadDoc(name, &root, &E, mc);
  HylcJsonFree(&root);
  return r;
}

int hylcmat_measured_load(const char *path, hylcmat_measured **mc, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  char  *bytes;
  size_t len;
  int    r;

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc, &E, HYLCMAT_ERR_ARG, "hylcmat_measured_load: NULL result pointer");
  *mc = NULL;
  HM_CALL(hm_read_file(path, "measured-cloth file", &bytes, &len, &E));
  r = hylcmat_measured_load_memory(path, bytes, len, mc, err, errlen);
  free(bytes);
  return r;
}

/* appends to a buffer snprintf-style: the length grows even when the buffer is full */
typedef struct {
  char  *buf;
  size_t cap, len;
} Out;

static void Put(Out *o, const char *text)
{
  const size_t n = strlen(text);
  if (o->len < o->cap) snprintf(o->buf + o->len, o->cap - o->len, "%s", text);
  o->len += n;
}

size_t hylcmat_measured_format(const hylcmat_measured *mc, char *buf, size_t buflen)
{
  Out  o = {buf, buf ? buflen : 0, 0};
  char b[32];

  if (buf && buflen) buf[0] = 0;
  if (!mc) return 0;
  Put(&o, "{\n    \"density\": ");
  Put(&o, hylcmat_format_double(mc->density, b));
  Put(&o, ",\n    \"stretching\": [\n");
  for (int i = 0; i < 6; i++) {
    Put(&o, "        [");
    for (int q = 0; q < 4; q++) {
      if (q) Put(&o, ", ");
      Put(&o, hylcmat_format_double(mc->stretch[i][q], b));
    }
    Put(&o, i < 5 ? "],\n" : "]\n");
  }
  Put(&o, "    ],\n    \"bending\": [\n");
  for (int i = 0; i < 3; i++) {
    Put(&o, "        [");
    for (int q = 0; q < 5; q++) {
      if (q) Put(&o, ", ");
      Put(&o, hylcmat_format_double(mc->bend[i][q], b));
    }
    Put(&o, i < 2 ? "],\n" : "]\n");
  }
  Put(&o, "    ]\n}\n");
  return o.len;
}

int hylcmat_measured_write(const hylcmat_measured *mc, const char *path, char *err, size_t errlen)
{
  hm_err E = {err, errlen};
  FILE  *fp;
  char   text[4096];

  if (err && errlen) err[0] = 0;
  HM_CHECK(mc && path && path[0], &E, HYLCMAT_ERR_ARG, "hylcmat_measured_write: NULL material or no file name");
  const size_t n = hylcmat_measured_format(mc, text, sizeof(text));
  HM_CHECK(n < sizeof(text), &E, HYLCMAT_ERR_MEMORY, "hylcmat_measured_write: the text is too long");
  fp = fopen(path, "w");
  if (!fp) return hm_fail(&E, HYLCMAT_ERR_OPEN, "Cannot write measured-cloth file '%s': %s", path, strerror(errno));
  const int bad = fwrite(text, 1, n, fp) != n;
  if (bad | ferror(fp) | fclose(fp)) return hm_fail(&E, HYLCMAT_ERR_READ, "Cannot write measured-cloth file '%s': %s", path, strerror(errno));
  return HYLCMAT_OK;
}
