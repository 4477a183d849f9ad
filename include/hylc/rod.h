#pragma once
/* Discrete Elastic Rods element kernels (method spec section 3): stretching per edge, bending and
   twisting per interior vertex.  Pure numerical functions on plain double arrays, free of PETSc
   objects and thread-safe.  Every kernel takes a fractional weight w that multiplies E, g and H.
   Conventions (dof order, frames, reference-twist branch, units) are documented in docs/rod.md. */

/* ---- constants of a circular cross-section of radius r ---- */
/* k_s = E_s pi r^2 */
static inline double HylcRodStretchStiffness(double Es, double r) { return Es * 3.14159265358979323846 * r * r; }
/* B = E pi r^4 / 4 */
static inline double HylcRodBendStiffness(double E, double r) { return E * 3.14159265358979323846 * r * r * r * r / 4.0; }
/* beta = G J = G pi r^4 / 2 */
static inline double HylcRodTwistStiffness(double G, double r) { return G * 3.14159265358979323846 * r * r * r * r / 2.0; }

/* ---- stretching: one edge, 6 dofs x = (x_j, x_{j+1}) ----
   E = w 1/2 ks lbar (l/lbar - 1)^2,  l = |x_{j+1} - x_j|.
   HylcRodStretch: E (may be NULL), gradient g[6] (may be NULL) and row-major Hessian H[36] (may be
   NULL) are overwritten.  Returns 0, or -1 for a zero-length edge (then E = HUGE_VAL, g = H = 0).
   The Hessian is exact, hence indefinite for a compressed edge (l < lbar). */
int    HylcRodStretch(const double x[6], double lbar, double ks, double w, double *E, double g[6], double H[36]);
double HylcRodStretchEnergy(const double x[6], double lbar, double ks, double w);

/* ---- bending and twisting: one interior vertex i, 11 dofs ----
   q = (x_{i-1}[3], theta^e, x_i[3], theta^f, x_{i+1}[3]) where e = x_i - x_{i-1} is the incoming edge,
   f = x_{i+1} - x_i the outgoing edge and theta^e, theta^f their twist angles.

   The reference frame of an edge at q is the stored director parallel-transported from the stored
   tangent to the current tangent t(q): d1(q) = P_{t_stored}^{t(q)} d1_stored, d2 = t x d1.  The reference
   twist m(q) is the signed angle about t^f from P_{t^e}^{t^f} d1^e(q) to d1^f(q), on the 2 pi branch
   nearest the stored value mref.  Material frames m1 = cos(theta) d1 + sin(theta) d2,
   m2 = -sin(theta) d1 + cos(theta) d2; curvature binormal kb = 2 t^e x t^f / (1 + t^e . t^f).

   Averaged variant (default, matches the .pyp RK data): kappa = (kb . mbar2, -kb . mbar1), mbar = mean of
   the two edges' material frames,  E_bend = w B/(2 lbar) |kappa - kappa0|^2.
   Per-edge variant: kappa^(j) = (kb . m2^j, -kb . m1^j) for j = e, f, rest (kappa0[0..1] for e,
   kappa0[2..3] for f),  E_bend = w B/(4 lbar) sum_j |kappa^(j) - kappa0^(j)|^2.
   Twist: tau = m + theta^f - theta^e,  E_twist = w beta/(2 lbar) (tau - tau0)^2.
   kappa and tau are integrated (dimensionless) quantities; lbar = (lbar_e + lbar_f)/2. */
typedef enum { HYLC_ROD_CURVATURE_AVERAGED = 0, HYLC_ROD_CURVATURE_PER_EDGE = 1 } HylcRodCurvatureVariant;

/* which terms enter g and H (the energies of both terms are always reported) */
enum { HYLC_ROD_BEND = 1, HYLC_ROD_TWIST = 2, HYLC_ROD_BENDTWIST = 3 };

typedef struct {
  double te[3], d1e[3]; /* incoming edge: stored unit tangent and reference director (made orthonormal internally) */
  double tf[3], d1f[3]; /* outgoing edge: the same */
  double mref;          /* stored reference twist (selects the 2 pi branch) */
  double kappa0[4];     /* rest curvature: averaged (kappa0[0], kappa0[1]); per-edge all four */
  double tau0;          /* rest twist */
  double lbar;          /* rest Voronoi length (lbar_e + lbar_f)/2 */
} HylcRodBendTwistRef;

typedef struct {
  double                  B;       /* bending stiffness E pi r^4/4 */
  double                  beta;    /* twisting stiffness G pi r^4/2 */
  HylcRodCurvatureVariant variant; /* curvature convention */
} HylcRodBendTwistParams;

/* Energy, gradient and exact Hessian of one bend-twist element.
   E[2] = (bending, twisting) energies (may be NULL); g[11] and row-major H[121] (each may be NULL) are
   overwritten with the derivatives of the terms selected by 'terms' (HYLC_ROD_BEND | HYLC_ROD_TWIST).
   Returns 0; -1 if the element is degenerate (zero-length edge, edges folded back on each other, or an
   edge tangent reversed with respect to its stored tangent), in which case E = HUGE_VAL, g = H = 0. */
int HylcRodBendTwist(const double q[11], const HylcRodBendTwistRef *ref, const HylcRodBendTwistParams *par, double w, int terms, double E[2], double g[11], double H[121]);

/* Energies only (plain arithmetic, for line searches): E[2] = (bending, twisting). Returns 0 or -1 as above. */
int HylcRodBendTwistEnergy(const double q[11], const HylcRodBendTwistRef *ref, const HylcRodBendTwistParams *par, double w, double E[2]);

/* Strains of the element at q: averaged curvature kappa[2], per-edge curvatures kappa_edges[4]
   (kappa^(e), kappa^(f)), twist tau and reference twist m (each output may be NULL).  Used to set rest
   values from a configuration.  Returns 0 or -1 as above. */
int HylcRodBendTwistStrains(const double q[11], const HylcRodBendTwistRef *ref, double kappa[2], double kappa_edges[4], double *tau, double *m);

/* Fills ref's frame data for the configuration q: te, tf from q, the given reference directors d1e,
   d1f (orthonormalized against the tangents) and the reference twist computed from them (principal
   branch when mref_near is NaN, else the branch nearest mref_near).  Rest values and lbar are not touched. */
void HylcRodBendTwistRefSetFrames(const double q[11], const double d1e[3], const double d1f[3], double mref_near, HylcRodBendTwistRef *ref);

/* phi + 2 pi n with the integer n that brings it nearest to 'near' */
double HylcAngleNear(double phi, double near);
