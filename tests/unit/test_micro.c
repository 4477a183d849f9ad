/* HylcMicro, the Newton solver:
   - a straight periodic yarn (default slide constraint: its dependent row is dropped, 3 rows remain)
     stretched by sx converges to 1/2 ks eps^2 L / A (relative 1e-8), and Psi(0.2) / Psi(0.1) = 4;
   - bent by II00 = kappa it converges to 1/2 B kappa^2 L / A within the discretization error;
   - the energy never increases between accepted iterates;
   - a solve gives bitwise the same result alone and after other solves with the same solver;
   - continuation (HylcMicroSetInitialState): z2 from the equilibrium of a nearby z1 reaches the cold Psi to
     1e-9 relative in fewer iterations, and the state is used once;
   - on the paper's patterns (when present): z = 0 converges on all seven;
   - mirror equivariance: the mirror image (x -> -x) of a pattern sheared by sa has the energy of the
     pattern sheared by -sa (the paper's basket and satin, a generated twill), to 1e-9; so Psi(sa) = Psi(-sa)
     holds exactly as far as a pattern is mirror symmetric (the stored basket and satin are not, by 3-8 %:
     docs/method.md);
   - representation: storing vertices one or two periods away (the same periodic object) changes nothing;
   - the object: prefix, setters, view, the removed -micro_factor_type, the factorization PC's solver type;
   - -micro_alpha_schedule adaptive: the paper schedule's psi (1e-8) where the equilibrium is unique, with no
     more iterations; its bad values refused;
   - the second-order test: a straight yarn compressed past the Euler load is a saddle, left by the escape
     for a buckled state of lower energy; below the load a minimum, unchanged. */
#include <hylc/micro.h>
#include <unistd.h>
#include <hylc/chol.h>
#include <petscblaslapack.h>
#include "hylctest.h"

static PetscErrorCode StraightYarn(PetscInt N, HylcPattern *p)
{
  const PetscReal px = 8e-3, py = 20e-3, r = 1e-3;
  PetscReal       pts[3 * 64];
  PetscInt        nv[1] = {N}, w[2] = {1, 0};

  PetscFunctionBegin;
  for (PetscInt k = 0; k < N; k++) {
    pts[3 * k]     = -0.5 * px + (k + 0.5) * px / N;
    pts[3 * k + 1] = 0;
    pts[3 * k + 2] = 0;
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, p));
  PetscCall(HylcPatternSetFromCurves(*p, px, py, r, 1, nv, w, pts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SolveStraight(PetscInt N, const PetscReal z[6], HylcMicroResult *res, HylcYarnConstants *c, PetscReal *area)
{
  HylcPattern   p;
  HylcMicro     M;
  HylcYarnModel m;
  HylcPeriodic  P;

  PetscFunctionBegin;
  PetscCall(StraightYarn(N, &p));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroGetPeriodic(M, &P));
  /* the default slide constraint: its row repeats the translation row of a straight yarn and is dropped */
  PetscCall(HylcMicroSolve(M, z, res));
  {
    PetscInt nc;
    PetscCall(HylcPeriodicGetConstraints(P, &nc, NULL, NULL, NULL));
    HYLC_CHECK(nc == 3, "straight yarn, default slide constraint: %d independent constraint rows, expected 3", (int)nc);
  }
  PetscCall(HylcPeriodicGetConstants(P, c));
  PetscCall(HylcPeriodicGetArea(P, area));
  /* monotone energy */
  {
    PetscInt         n;
    const PetscReal *E;
    PetscCall(HylcMicroGetEnergyHistory(M, &n, &E));
    for (PetscInt i = 1; i < n; i++) HYLC_CHECK(E[i] < E[i - 1], "energy increased at accepted iterate %d: %g -> %g", (int)i, (double)E[i - 1], (double)E[i]);
  }
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the option name=value is refused by HylcMicroSetFromOptions() with PETSC_ERR_USER_INPUT (the option is
   cleared again) */
static PetscErrorCode CheckOptionRefused(HylcMicro M, const char name[], const char value[])
{
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscOptionsSetValue(NULL, name, value));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcMicroSetFromOptions(M);
  PetscCall(PetscPopErrorHandler());
  PetscCall(PetscOptionsClearValue(NULL, name));
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "%s %s: error %d, expected PETSC_ERR_USER_INPUT", name, value, (int)ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestAnalytic(void)
{
  HylcMicroResult   res;
  HylcYarnConstants c;
  PetscReal         area;

  PetscFunctionBegin;
  for (int k = 0; k < 2; k++) {
    const PetscReal eps = k ? -0.05 : 0.15, z[6] = {eps, 0, 0, 0, 0, 0};
    PetscCall(SolveStraight(16, z, &res, &c, &area));
    const PetscReal exact = 0.5 * c.ks * eps * eps * 8e-3 / area;
    HYLC_CHECK(res.status == HYLC_MICRO_CONVERGED, "stretched yarn: status %s", HylcMicroStatuses[res.status]);
    HYLC_CHECK(PetscAbsReal(res.psi - exact) <= 1e-8 * exact, "stretched yarn eps = %g: psi %.12g vs %.12g", (double)eps, (double)res.psi, (double)exact);
  }
  /* Psi(0.2) / Psi(0.1) = 4 (Psi = 1/2 k_s eps^2 L / A) with the default options */
  {
    HylcMicroResult r1, r2;
    const PetscReal z1[6] = {0.1, 0, 0, 0, 0, 0}, z2[6] = {0.2, 0, 0, 0, 0, 0};
    PetscCall(SolveStraight(16, z1, &r1, &c, &area));
    PetscCall(SolveStraight(16, z2, &r2, &c, &area));
    HYLC_CHECK(r1.status == HYLC_MICRO_CONVERGED && r2.status == HYLC_MICRO_CONVERGED, "stretched yarn: statuses %s, %s", HylcMicroStatuses[r1.status], HylcMicroStatuses[r2.status]);
    HYLC_CHECK(PetscAbsReal(r2.psi / r1.psi - 4) <= 1e-7, "stretched yarn: Psi(0.2) / Psi(0.1) = %.12g, expected 4", (double)(r2.psi / r1.psi));
  }
  /* bent: the error shrinks at second order with the edge length */
  PetscReal err[2];
  for (int k = 0; k < 2; k++) {
    const PetscReal kappa = 150, z[6] = {0, 0, 0, kappa, 0, 0};
    PetscCall(SolveStraight(k ? 32 : 16, z, &res, &c, &area));
    const PetscReal exact = 0.5 * c.B * kappa * kappa * 8e-3 / area;
    HYLC_CHECK(res.status == HYLC_MICRO_CONVERGED, "bent yarn: status %s", HylcMicroStatuses[res.status]);
    err[k] = PetscAbsReal(res.psi - exact) / exact;
  }
  HYLC_CHECK(err[1] < 2e-3 && err[0] / err[1] > 3.5, "bent yarn: relative errors %g (16 edges), %g (32 edges)", (double)err[0], (double)err[1]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the same sample alone and after other samples with the same solver: bitwise identical */
static PetscErrorCode TestReproducible(void)
{
  HylcPattern          p;
  HylcPatternGenParams g;
  HylcYarnModel        m;
  HylcMicro            A, B;
  HylcMicroResult      ra, rb, tmp;
  const PetscReal      z[6] = {0.1, 0.1, -0.05, 60, 0, 0}, z1[6] = {-0.1, 0, 0.2, 0, 0, -80}, z2[6] = {0, 0.3, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNTWILL, &g));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &A));
  PetscCall(HylcMicroSetPattern(A, p, &m));
  PetscCall(HylcMicroSolve(A, z, &ra));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &B));
  PetscCall(HylcMicroSetPattern(B, p, &m));
  PetscCall(HylcMicroSolve(B, z1, &tmp));
  PetscCall(HylcMicroSolve(B, z2, &tmp));
  PetscCall(HylcMicroSolve(B, z, &rb));
  HYLC_CHECK(ra.status == HYLC_MICRO_CONVERGED, "twill sample: status %s", HylcMicroStatuses[ra.status]);
  HYLC_CHECK(ra.psi == rb.psi && ra.iterations == rb.iterations, "alone %.17g (%d its) vs in a batch %.17g (%d its)", (double)ra.psi, (int)ra.iterations, (double)rb.psi, (int)rb.iterations);
  for (int k = 0; k < 4; k++) HYLC_CHECK(ra.parts[k] == rb.parts[k], "energy part %d differs: %.17g vs %.17g", k, (double)ra.parts[k], (double)rb.parts[k]);
  PetscCall(HylcMicroDestroy(&A));
  PetscCall(HylcMicroDestroy(&B));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* continuation: z2 solved from the equilibrium of a nearby z1 (HylcMicroSetInitialState) reaches the Psi of
   a cold solve of z2 to 1e-9 relative, in fewer iterations; the initial state is used once */
static PetscErrorCode TestContinuation(void)
{
  HylcPattern          p;
  HylcPatternGenParams g;
  HylcYarnModel        m;
  HylcMicro            M;
  HylcMicroResult      r1, rc, rw, r3;
  PetscInt             ny;
  PetscReal           *y;
  PetscBool            cont;
  const PetscReal      z1[6] = {0.1, 0.05, 0, 0, 0, 0}, z2[6] = {0.12, 0.06, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNTWILL, &g));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroSolve(M, z2, &rc)); /* cold */
  PetscCall(HylcMicroGetContinued(M, &cont));
  HYLC_CHECK(!cont, "a solve without an initial state says it was continued");
  PetscCall(HylcMicroSolve(M, z1, &r1));
  {
    HylcPeriodic P;
    PetscCall(HylcMicroGetPeriodic(M, &P));
    PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, NULL));
  }
  PetscCall(PetscMalloc1(ny, &y));
  PetscCall(HylcMicroGetState(M, y));
  PetscCall(HylcMicroSetInitialState(M, y));
  PetscCall(HylcMicroSolve(M, z2, &rw)); /* continued from z1 */
  PetscCall(HylcMicroGetContinued(M, &cont));
  HYLC_CHECK(cont, "the solve after HylcMicroSetInitialState says it was not continued");
  HYLC_CHECK(rc.status == HYLC_MICRO_CONVERGED && r1.status == HYLC_MICRO_CONVERGED && rw.status == HYLC_MICRO_CONVERGED, "continuation: statuses cold %s, z1 %s, continued %s", HylcMicroStatuses[rc.status], HylcMicroStatuses[r1.status],
             HylcMicroStatuses[rw.status]);
  HYLC_CHECK(PetscAbsReal(rw.psi - rc.psi) <= 1e-9 * PetscAbsReal(rc.psi), "continued Psi %.12e vs cold %.12e (relative %.2e > 1e-9)", (double)rw.psi, (double)rc.psi, (double)(PetscAbsReal(rw.psi - rc.psi) / PetscAbsReal(rc.psi)));
  HYLC_CHECK(rw.iterations < rc.iterations, "continued solve: %d iterations, cold %d (expected fewer)", (int)rw.iterations, (int)rc.iterations);
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "continuation: cold %d iterations, continued %d; Psi %.12e vs %.12e\n", (int)rc.iterations, (int)rw.iterations, (double)rc.psi, (double)rw.psi));
  /* used once: the next solve is cold again and bitwise the cold one */
  PetscCall(HylcMicroSolve(M, z2, &r3));
  PetscCall(HylcMicroGetContinued(M, &cont));
  HYLC_CHECK(!cont && r3.psi == rc.psi && r3.iterations == rc.iterations, "the initial state was used twice: %.17g (%d its) vs cold %.17g (%d its)", (double)r3.psi, (int)r3.iterations, (double)rc.psi, (int)rc.iterations);
  PetscCall(PetscFree(y));
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a mirror-symmetric weave: psi(sa) = psi(-sa) to the stopping tolerance */
static PetscErrorCode TestShearSymmetry(void)
{
  HylcPattern          p;
  HylcPatternGenParams g;
  HylcYarnModel        m;
  HylcMicro            M;
  HylcMicroResult      rp, rm;
  const PetscReal      zp[6] = {0.05, 0.3, 0, 0, 0, 0}, zm[6] = {0.05, -0.3, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNPLAIN, &g));
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50; /* contact carries the shear */
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroSolve(M, zp, &rp));
  PetscCall(HylcMicroSolve(M, zm, &rm));
  HYLC_CHECK(rp.status == HYLC_MICRO_CONVERGED && rm.status == HYLC_MICRO_CONVERGED, "plain weave sheared: status %s, %s", HylcMicroStatuses[rp.status], HylcMicroStatuses[rm.status]);
  HYLC_CHECK(rp.parts[3] > 0, "plain weave sheared: no contact");
  HYLC_CHECK(PetscAbsReal(rp.psi - rm.psi) <= 1e-6 * rp.psi, "plain weave: psi(sa = 0.3) = %.12g, psi(sa = -0.3) = %.12g", (double)rp.psi, (double)rm.psi);
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the image of p under the mirror x -> -x: positions and directors mirrored, the material angles and
   twists negated, the second curvature component negated (the frame stays right-handed: d2 -> -M d2) */
static PetscErrorCode MirrorX(HylcPattern p, HylcPattern *q)
{
  HylcPatternData d;
  PetscInt        n;
  PetscReal      *X, *th, *RK, *RT, *D1, *RefT;
  PetscInt       *sh;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetData(p, &d));
  n = d.nv;
  PetscCall(PetscMalloc6(3 * n, &X, n, &th, 2 * n, &RK, n, &RT, 3 * n, &D1, n, &RefT));
  PetscCall(PetscMalloc1(2 * n, &sh));
  for (PetscInt v = 0; v < n; v++) {
    X[3 * v] = -d.X[3 * v], X[3 * v + 1] = d.X[3 * v + 1], X[3 * v + 2] = d.X[3 * v + 2];
    D1[3 * v] = -d.refD1[3 * v], D1[3 * v + 1] = d.refD1[3 * v + 1], D1[3 * v + 2] = d.refD1[3 * v + 2];
    th[v] = -d.theta[v], RT[v] = -d.restTwist[v], RefT[v] = -d.refTwist[v];
    RK[2 * v] = d.restKappa[2 * v], RK[2 * v + 1] = -d.restKappa[2 * v + 1];
    sh[2 * v] = -d.shift[2 * v], sh[2 * v + 1] = d.shift[2 * v + 1];
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, q));
  PetscCall(HylcPatternSetData(*q, n, d.px, d.py, d.radius, X, th, d.next, sh, d.restLength, RK, RT, D1, RefT));
  PetscCall(PetscFree6(X, th, RK, RT, D1, RefT));
  PetscCall(PetscFree(sh));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the same periodic object with every third vertex stored one or two periods away */
static PetscErrorCode Rewrap(HylcPattern p, HylcPattern *q)
{
  HylcPatternData d;
  PetscReal      *X;
  PetscInt       *sh;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetData(p, &d));
  PetscCall(PetscMalloc2(3 * d.nv, &X, 2 * d.nv, &sh));
  PetscCall(PetscArraycpy(X, d.X, 3 * d.nv));
  PetscCall(PetscArraycpy(sh, d.shift, 2 * d.nv));
  for (PetscInt v = 0; v < d.nv; v += 3) {
    const PetscInt l[2] = {v % 2 ? 1 : -2, v % 6 ? 0 : 1}, u = d.prev[v];
    X[3 * v] += l[0] * d.px, X[3 * v + 1] += l[1] * d.py;
    sh[2 * v] += l[0], sh[2 * v + 1] += l[1]; /* the edge leaving v: X[next] + shift p - X[v] unchanged */
    sh[2 * u] -= l[0], sh[2 * u + 1] -= l[1]; /* the edge entering v */
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, q));
  PetscCall(HylcPatternSetData(*q, d.nv, d.px, d.py, d.radius, X, d.theta, d.next, sh, d.restLength, d.restKappa, d.restTwist, d.refD1, d.refTwist));
  PetscCall(PetscFree2(X, sh));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* psi of the mirror image at +sa against psi of p at -sa; psi of the rewrapped copy against p */
static PetscErrorCode CheckMirrorAndWrap(const char *name, HylcPattern p, const HylcYarnModel *m, PetscReal sa, HylcSlideConstraint slide)
{
  HylcPattern     q, w;
  HylcMicro       M, Q, W;
  HylcMicroResult rm, rq, rp, rw;
  const PetscReal zp[6] = {0.02, sa, 0, 0, 0, 0}, zm[6] = {0.02, -sa, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(MirrorX(p, &q));
  PetscCall(Rewrap(p, &w));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &Q));
  PetscCall(HylcMicroSetPattern(Q, q, m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &W));
  PetscCall(HylcMicroSetPattern(W, w, m));
  {
    HylcMicro all[3] = {M, Q, W};
    for (int k = 0; k < 3; k++) {
      HylcPeriodic P;
      PetscCall(HylcMicroGetPeriodic(all[k], &P));
      PetscCall(HylcPeriodicSetSlideConstraint(P, slide));
    }
  }
  PetscCall(HylcMicroSolve(M, zm, &rm));
  PetscCall(HylcMicroSolve(Q, zp, &rq));
  PetscCall(HylcMicroSolve(M, zp, &rp));
  PetscCall(HylcMicroSolve(W, zp, &rw));
  HYLC_CHECK(rm.status == HYLC_MICRO_CONVERGED && rq.status == HYLC_MICRO_CONVERGED && rp.status == HYLC_MICRO_CONVERGED && rw.status == HYLC_MICRO_CONVERGED, "%s: status %s %s %s %s", name, HylcMicroStatuses[rm.status], HylcMicroStatuses[rq.status],
             HylcMicroStatuses[rp.status], HylcMicroStatuses[rw.status]);
  HYLC_CHECK(PetscAbsReal(rq.psi - rm.psi) <= 1e-9 * rm.psi, "%s: mirror image at sa = %g: psi %.12g, the pattern at sa = %g: psi %.12g", name, (double)sa, (double)rq.psi, (double)-sa, (double)rm.psi);
  HYLC_CHECK(PetscAbsReal(rw.psi - rp.psi) <= 1e-9 * rp.psi, "%s: vertices stored a period away: psi %.12g instead of %.12g", name, (double)rw.psi, (double)rp.psi);
  if (getenv("HYLC_REPORT"))
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: psi(+%g) = %.10g, psi(-%g) = %.10g, mirror image at +%g: %.10g, rewrapped: %.10g\n", name, (double)sa, (double)rp.psi, (double)sa, (double)rm.psi, (double)sa, (double)rq.psi, (double)rw.psi));
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcMicroDestroy(&Q));
  PetscCall(HylcMicroDestroy(&W));
  PetscCall(HylcPatternDestroy(&q));
  PetscCall(HylcPatternDestroy(&w));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestMirrorTwill(void)
{
  HylcPattern          p;
  HylcPatternGenParams g;
  HylcYarnModel        m;

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNTWILL, &g));
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50;
  PetscCall(CheckMirrorAndWrap("generated twill", p, &m, 0.3, HYLC_SLIDE_GLOBAL));
  /* per_family: 3 + 2 constraint rows on a woven (warp and weft), 3 + 1 on a knit */
  for (int k = 0; k < 2; k++) {
    HylcPattern  q;
    HylcPeriodic P;
    PetscInt     mc;
    PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &q));
    PetscCall(HylcPatternGenerate(q, k ? HYLCPATTERNSTOCKINETTE : HYLCPATTERNTWILL, &g));
    PetscCall(HylcPeriodicCreate(PETSC_COMM_SELF, &P));
    PetscCall(HylcPeriodicSetPattern(P, q, &m));
    PetscCall(HylcPeriodicSetSlideConstraint(P, HYLC_SLIDE_PER_FAMILY));
    PetscCall(HylcPeriodicSetUp(P));
    PetscCall(HylcPeriodicGetSizes(P, NULL, NULL, NULL, &mc));
    HYLC_CHECK(mc == (k ? 4 : 5), "%s: %d constraint rows with -periodic_slide per_family", k ? "stockinette" : "twill", (int)mc);
    PetscCall(HylcPeriodicDestroy(&P));
    PetscCall(HylcPatternDestroy(&q));
  }
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode LoadConfigured(const char *root, const char *dir, const char *name, HylcPattern *p, HylcYarnModel *m)
{
  char         path[PETSC_MAX_PATH_LEN];
  PetscOptions opt;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/config/%s.yaml", root, name));
  PetscCall(PetscOptionsCreate(&opt));
  PetscCall(PetscOptionsInsertFile(PETSC_COMM_SELF, opt, path, PETSC_TRUE));
  PetscCall(PetscOptionsPush(opt));
  PetscCall(HylcYarnModelDefault(m));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, m));
  PetscCall(PetscOptionsPop());
  PetscCall(PetscOptionsDestroy(&opt));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s.pyp", dir, name));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, p));
  PetscCall(HylcPatternLoad(*p, path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestPaperPatterns(const char *root, const char *dir)
{
  const char *names[] = {"basket", "satin", "stockinette", "cartridge_belt_rib", "slip_stitch_honeycomb", "satin_small", "stockinette_small"};

  PetscFunctionBegin;
  for (size_t k = 0; k < sizeof(names) / sizeof(names[0]); k++) {
    HylcPattern     p;
    HylcYarnModel   m;
    HylcMicro       M;
    HylcMicroResult r0, rp, rm;
    const PetscReal z0[6] = {0, 0, 0, 0, 0, 0}, zp[6] = {0, 0.3, 0, 0, 0, 0}, zm[6] = {0, -0.3, 0, 0, 0, 0};
    PetscCall(LoadConfigured(root, dir, names[k], &p, &m));
    PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
    PetscCall(HylcMicroSetPattern(M, p, &m));
    PetscCall(HylcMicroSolve(M, z0, &r0));
    HYLC_CHECK(r0.status == HYLC_MICRO_CONVERGED, "%s at z = 0: status %s after %d iterations", names[k], HylcMicroStatuses[r0.status], (int)r0.iterations);
    if (getenv("HYLC_REPORT")) PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: psi(0) = %.6g J/m^2, %d iterations, %.3f s\n", names[k], (double)r0.psi, (int)r0.iterations, r0.time));
    if (k < 2) { /* basket and satin: symmetric under sa -> -sa */
      PetscCall(HylcMicroSolve(M, zp, &rp));
      PetscCall(HylcMicroSolve(M, zm, &rm));
      HYLC_CHECK(rp.status == HYLC_MICRO_CONVERGED && rm.status == HYLC_MICRO_CONVERGED, "%s sa = +-0.3: status %s, %s", names[k], HylcMicroStatuses[rp.status], HylcMicroStatuses[rm.status]);
      /* Psi(sa) - Psi(-sa) is measured, not asserted: the stored basket and satin are not mirror symmetric
         (3-8 %, docs/method.md). Asserted: the solver is mirror equivariant on them */
      if (getenv("HYLC_REPORT")) PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s: psi(+0.3) = %.10g, psi(-0.3) = %.10g\n", names[k], (double)rp.psi, (double)rm.psi));
      PetscCall(CheckMirrorAndWrap(names[k], p, &m, 0.3, HYLC_SLIDE_GLOBAL));
    }
    PetscCall(HylcMicroDestroy(&M));
    PetscCall(HylcPatternDestroy(&p));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* is text in the file? */
static PetscBool FileHas(const char *path, const char *text)
{
  char      line[1024];
  PetscBool has = PETSC_FALSE;
  FILE     *f   = fopen(path, "r");
  if (!f) return PETSC_FALSE;
  while (!has && fgets(line, sizeof(line), f)) has = (PetscBool)(strstr(line, text) != NULL);
  fclose(f);
  return has;
}

/* views obj (PetscObjectView) into a new temporary file made from the template path (...XXXXXX), whose
   name is left in path; the caller removes it */
static PetscErrorCode ViewToTempFile(PetscObject obj, char path[])
{
  PetscViewer v;
  int         fd = mkstemp(path);

  PetscFunctionBegin;
  PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "mkstemp(%s) failed", path);
  close(fd);
  PetscCall(PetscViewerASCIIOpen(PETSC_COMM_SELF, path, &v));
  PetscCall(PetscObjectView(obj, v));
  PetscCall(PetscViewerDestroy(&v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the object: no default prefix (keys -micro_*), setters (and their refusal of bad values), a changed prefix reaches
   the options, HylcMicroView prints what was set, the removed -<prefix>factor_type is an error naming its
   replacement, and the factorization PC chosen through HylcMicroGetFactorPC gives the same psi (1e-9) */
static PetscErrorCode TestObject(void)
{
  HylcMicro       M;
  HylcPattern     p;
  HylcYarnModel   m;
  HylcMicroResult r1, r2;
  PC              pc;
  const char     *prefix;
  PetscBool       eq;
  PetscErrorCode  ierr;
  char            path[] = "/tmp/hylc_test_micro_viewXXXXXX";
  const PetscReal z[6]   = {0.1, 0, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(StraightYarn(16, &p));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)M, &prefix));
  HYLC_CHECK(!prefix, "default prefix %s, expected none (the keys are -micro_*)", prefix);
  /* bad values are refused with PETSC_ERR_USER_INPUT */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcMicroSetTolerances(M, -1, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT);
  PetscCall(PetscPopErrorHandler());
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "HylcMicroSetTolerances(rtol = -1): error %d, expected PETSC_ERR_USER_INPUT", (int)ierr);
  PetscCall(HylcMicroSetTolerances(M, 1e-5, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT)); /* restore */
  /* a changed prefix: its options are read, the setters' values are viewed */
  PetscCall(HylcMicroSetOptionsPrefix(M, "other_"));
  PetscCall(PetscObjectGetOptionsPrefix((PetscObject)M, &prefix));
  PetscCall(PetscStrcmp(prefix, "other_", &eq));
  HYLC_CHECK(eq, "prefix %s, expected other_", prefix);
  PetscCall(PetscOptionsSetValue(NULL, "-other_micro_ls_max", "17"));
  PetscCall(PetscOptionsSetValue(NULL, "-other_periodic_pair_margin", "1.06"));
  PetscCall(HylcMicroSetStepLimit(M, 0.07, PETSC_DEFAULT));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroSetFromOptions(M));
  PetscCall(HylcMicroSetUp(M));
  PetscCall(ViewToTempFile((PetscObject)M, path));
  HYLC_CHECK(FileHas(path, "17 trials") && FileHas(path, "step limit (0.07 +") && FileHas(path, "(other_)") && FileHas(path, "solver type hylc (-other_micro_factor_pc_factor_mat_solver_type)") && FileHas(path, "(other_micro_factor_)"),
             "HylcMicroView (%s) lacks the prefix, a setter's or an option's value", path);
  remove(path);
  {
    HylcPeriodic P;
    SNES         snes;
    PetscCall(HylcMicroGetPeriodic(M, &P));
    PetscCall(PetscObjectGetOptionsPrefix((PetscObject)P, &prefix));
    PetscCall(PetscStrcmp(prefix, "other_", &eq));
    HYLC_CHECK(eq, "the tile's prefix %s, expected other_ (the solver's)", prefix);
    PetscCall(HylcMicroGetSNES(M, &snes));
    PetscCall(PetscObjectGetOptionsPrefix((PetscObject)snes, &prefix));
    PetscCall(PetscStrcmp(prefix, "other_micro_", &eq));
    HYLC_CHECK(eq, "the SNES's prefix %s, expected other_micro_", prefix);
    char path2[] = "/tmp/hylc_test_micro_viewXXXXXX";
    PetscCall(ViewToTempFile((PetscObject)P, path2));
    HYLC_CHECK(FileHas(path2, "pair margin 1.06") && FileHas(path2, "(other_)"), "-other_periodic_pair_margin 1.06 was not read by the tile, or its prefix is not other_ (%s)", path2);
    remove(path2);
  }
  PetscCall(PetscOptionsClearValue(NULL, "-other_micro_ls_max"));
  PetscCall(PetscOptionsClearValue(NULL, "-other_periodic_pair_margin"));
  PetscCall(HylcMicroSolve(M, z, &r1));
  /* the removed -factor_type */
  PetscCall(CheckOptionRefused(M, "-other_micro_factor_type", "petsc"));
  PetscCall(HylcMicroDestroy(&M));
  /* PETSc's Cholesky chosen through the getter */
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroGetFactorPC(M, &pc));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERPETSC));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroSetStepLimit(M, 0.07, PETSC_DEFAULT));
  PetscCall(HylcMicroSetLineSearch(M, PETSC_DEFAULT, 17, PETSC_DEFAULT));
  PetscCall(HylcMicroSolve(M, z, &r2));
  HYLC_CHECK(r1.status == HYLC_MICRO_CONVERGED && r2.status == HYLC_MICRO_CONVERGED, "straight yarn: not converged");
  HYLC_CHECK_REL(r1.psi, r2.psi, 1e-9);
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -micro_alpha_schedule adaptive against the paper's schedule on a generated plain weave (kc = 50) at strains
   with one equilibrium: the same psi to 1e-8 relative (both solved to rtol 1e-10, so that the comparison is
   of equilibria, not of where each schedule stops) and, with the default tolerances, no more iterations;
   and the option's bad values are refused with PETSC_ERR_USER_INPUT; HylcMicroView names the schedule */
static PetscErrorCode TestAdaptive(void)
{
  HylcPattern                  p;
  HylcPatternGenParams         g;
  HylcYarnModel                m;
  HylcMicro                    M;
  HylcMicroResult              r[3];
  PetscErrorCode               ierr;
  char                         path[]   = "/tmp/hylc_test_micro_adaptXXXXXX";
  const PetscReal              zs[4][6] = {{0.1, 0, 0, 0, 0, 0}, {0, 0, 0.15, 0, 0, 0}, {0.05, 0.2, 0, 0, 0, 0}, {0, 0, 0, 60, 0, 0}};
  const char *const            bad[][2] = {{"-micro_alpha_schedule", "fast"}, {"-micro_alpha_factor", "1"}, {"-micro_alpha_min", "0"}, {"-micro_alpha_max", "1e-3"}, {"-micro_alpha_switch", "0"}, {"-micro_step_clearance", "0.5"}};
  const char *const            sname[3] = {"paper", "adaptive", "hybrid"};
  const HylcMicroAlphaSchedule sched[3] = {HYLC_MICRO_ALPHA_PAPER, HYLC_MICRO_ALPHA_ADAPTIVE, HYLC_MICRO_ALPHA_HYBRID};

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
  PetscCall(HylcPatternGenerate(p, HYLCPATTERNPLAIN, &g));
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50;
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscReal psi1 = 0; /* the paper's Psi at strain 1, rtol 1e-10 */
  PetscCall(HylcMicroSetRegularizationSwitch(M, 0.1));
  for (int k = 0; k < 4; k++) {
    PetscInt its[3];
    for (int a = 0; a < 3; a++) { /* the default tolerances: iterations */
      PetscCall(HylcMicroSetRegularizationSchedule(M, sched[a], PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      PetscCall(HylcMicroSetTolerances(M, 1e-5, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      PetscCall(HylcMicroSolve(M, zs[k], &r[a]));
      its[a] = r[a].iterations;
      HYLC_CHECK(r[a].status == HYLC_MICRO_CONVERGED, "plain weave, strain %d, %s: status %s", k, sname[a], HylcMicroStatuses[r[a].status]);
    }
    HYLC_CHECK(its[1] <= its[0] && its[2] <= its[0], "plain weave, strain %d: adaptive %d, hybrid %d iterations, paper %d", k, (int)its[1], (int)its[2], (int)its[0]);
    for (int a = 0; a < 3; a++) { /* tight: the equilibrium */
      PetscCall(HylcMicroSetRegularizationSchedule(M, sched[a], PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      PetscCall(HylcMicroSetTolerances(M, 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      PetscCall(HylcMicroSolve(M, zs[k], &r[a]));
      HYLC_CHECK(r[a].status == HYLC_MICRO_CONVERGED, "plain weave, strain %d, %s, rtol 1e-10: status %s", k, sname[a], HylcMicroStatuses[r[a].status]);
    }
    if (k == 1) psi1 = r[0].psi;
    for (int a = 1; a < 3; a++)
      HYLC_CHECK(PetscAbsReal(r[a].psi - r[0].psi) <= 1e-8 * PetscAbsReal(r[0].psi), "plain weave, strain %d: psi %s %.12g, paper %.12g (%d, %d iterations, rtol 1e-10; default rtol: %d, %d)", k, sname[a], (double)r[a].psi, (double)r[0].psi,
                 (int)r[a].iterations, (int)r[0].iterations, (int)its[a], (int)its[0]);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "adaptive, hybrid: strain %d: iterations %d, %d (paper %d), rtol 1e-10: %d, %d (%d), psi rel. diff %.1e, %.1e\n", k, (int)its[1], (int)its[2], (int)its[0], (int)r[1].iterations, (int)r[2].iterations,
                          (int)r[0].iterations, (double)(PetscAbsReal(r[1].psi - r[0].psi) / r[0].psi), (double)(PetscAbsReal(r[2].psi - r[0].psi) / r[0].psi)));
  }
  { /* the clearance step limit: the same equilibrium (rtol 1e-10) */
    HylcMicroResult rc;
    PetscCall(HylcMicroSetRegularizationSchedule(M, HYLC_MICRO_ALPHA_PAPER, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    PetscCall(HylcMicroSetStepLimit(M, 0.5, 0));
    PetscCall(HylcMicroSetStepClearance(M, 0.1));
    PetscCall(HylcMicroSolve(M, zs[1], &rc));
    HYLC_CHECK(rc.status == HYLC_MICRO_CONVERGED && PetscAbsReal(rc.psi - psi1) <= 1e-8 * PetscAbsReal(psi1), "plain weave, clearance step limit 0.1: status %s, psi %.12g, paper %.12g", HylcMicroStatuses[rc.status], (double)rc.psi, (double)psi1);
    PetscCall(HylcMicroSetStepClearance(M, 0));
    PetscCall(HylcMicroSetStepLimit(M, 0.05, 0.15));
  }
  { /* the fallback: an adaptive schedule held at alpha^ = 1e10 makes steps too short to converge in 20
       iterations; the solve is repeated with the paper schedule, which converges to its Psi (rtol 1e-10);
       without the fallback the status is the iteration cap */
    HylcMicroResult rf;
    SNES            snes;
    PetscInt        maxit;
    PetscCall(HylcMicroGetSNES(M, &snes));
    PetscCall(SNESGetTolerances(snes, NULL, NULL, NULL, &maxit, NULL));
    PetscCall(SNESSetTolerances(snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 20, PETSC_DEFAULT));
    PetscCall(HylcMicroSetRegularizationSchedule(M, HYLC_MICRO_ALPHA_ADAPTIVE, PETSC_DEFAULT, 1e10, 1e10));
    PetscCall(HylcMicroSolve(M, zs[1], &rf));
    HYLC_CHECK(rf.status == HYLC_MICRO_CONVERGED && rf.fallback && rf.iterations > 20 && PetscAbsReal(rf.psi - psi1) <= 1e-8 * PetscAbsReal(psi1),
               "plain weave, adaptive at alpha^ 1e10, 20 iterations: status %s, fallback %d, %d iterations, psi %.12g, paper %.12g", HylcMicroStatuses[rf.status], (int)rf.fallback, (int)rf.iterations, (double)rf.psi, (double)psi1);
    PetscCall(HylcMicroSetRegularizationFallback(M, PETSC_FALSE));
    PetscCall(HylcMicroSolve(M, zs[1], &rf));
    HYLC_CHECK(rf.status == HYLC_MICRO_MAX_IT && !rf.fallback && rf.iterations == 20, "plain weave, adaptive at alpha^ 1e10, 20 iterations, no fallback: status %s, fallback %d, %d iterations", HylcMicroStatuses[rf.status], (int)rf.fallback,
               (int)rf.iterations);
    PetscCall(HylcMicroSetRegularizationFallback(M, PETSC_TRUE));
    PetscCall(HylcMicroSetRegularizationSchedule(M, HYLC_MICRO_ALPHA_PAPER, PETSC_DEFAULT, 1e-2, 1e10));
    PetscCall(SNESSetTolerances(snes, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, maxit, PETSC_DEFAULT));
  }
  PetscCall(HylcMicroSetRegularizationSchedule(M, HYLC_MICRO_ALPHA_HYBRID, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  /* the view names the schedule */
  PetscCall(ViewToTempFile((PetscObject)M, path));
  HYLC_CHECK(FileHas(path, "regularization: hybrid, the paper schedule alpha^ 5000 -> 5 over 400 iterations"), "HylcMicroView (%s) does not show the hybrid schedule", path);
  remove(path);
  /* bad values */
  for (size_t b = 0; b < sizeof(bad) / sizeof(bad[0]); b++) {
    PetscCall(CheckOptionRefused(M, bad[b][0], bad[b][1]));
    PetscCall(HylcMicroSetRegularizationSchedule(M, HYLC_MICRO_ALPHA_PAPER, 4, 1e-2, 1e10)); /* restore */
    PetscCall(HylcMicroSetRegularizationSwitch(M, 1e-2));
    PetscCall(HylcMicroSetStepClearance(M, 0));
  }
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcMicroSetRegularizationSchedule(M, (HylcMicroAlphaSchedule)7, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT);
  PetscCall(PetscPopErrorHandler());
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "HylcMicroSetRegularizationSchedule(7): error %d, expected PETSC_ERR_USER_INPUT", (int)ierr);
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the eigenvalues below -tol max|diag(M H M)| of M H M restricted to the tangent space of the constraints
   (B^T v = 0, B = M A^T), at the state of M's last solve: dense, from an orthonormal basis of the tangent
   space (QR of B) and LAPACK syev; M = 1 per position, 1/r per twist (the default twist scale) */
static PetscErrorCode DenseProjectedNegative(HylcMicro M, PetscReal tol, PetscInt *neg)
{
  HylcPeriodic       P;
  HylcYarnConstants  c;
  PetscInt           n, m;
  const PetscReal   *A;
  PetscReal         *y, *g, *Q, *T, *W, *work, *tau, parts[4], dmax = 0;
  const PetscScalar *h;
  Mat                H, D;
  PetscBLASInt       bn, bm, bk, lwork, info;

  PetscFunctionBegin;
  PetscCall(HylcMicroGetPeriodic(M, &P));
  PetscCall(HylcPeriodicGetSizes(P, &n, NULL, NULL, NULL));
  PetscCall(HylcPeriodicGetConstraints(P, &m, &A, NULL, NULL));
  PetscCall(HylcPeriodicGetConstants(P, &c));
  PetscCall(PetscMalloc7(n, &y, n, &g, n * n, &Q, n * n, &T, n, &W, 64 * n, &work, n, &tau));
  PetscCall(HylcMicroGetState(M, y));
  PetscCall(HylcPeriodicSetState(P, y));
  PetscCall(HylcPeriodicCreateMatrix(P, &H));
  PetscCall(HylcPeriodicEvaluate(P, HYLC_TERM_ALL, parts, g, H));
  PetscCall(MatConvert(H, MATSEQDENSE, MAT_INITIAL_MATRIX, &D));
  PetscCall(MatDenseGetArrayRead(D, &h));
  /* Q: the columns of B, then the full orthogonal factor of its QR; its last n - m columns span the tangent space */
  PetscCall(PetscArrayzero(Q, n * n));
  for (PetscInt i = 0; i < m; i++)
    for (PetscInt k = 0; k < n; k++) Q[i * n + k] = A[i * n + k] * ((k % 4 == 3) ? 1.0 / c.r : 1.0);
  PetscCall(PetscBLASIntCast(n, &bn));
  PetscCall(PetscBLASIntCast(m, &bm));
  lwork = 64 * bn;
  PetscCallBLAS("LAPACKgeqrf", LAPACKgeqrf_(&bn, &bm, Q, &bn, tau, work, &lwork, &info));
  HYLC_CHECK(info == 0, "geqrf: info %d", (int)info);
  PetscCallBLAS("LAPACKorgqr", LAPACKorgqr_(&bn, &bn, &bm, Q, &bn, tau, work, &lwork, &info));
  HYLC_CHECK(info == 0, "orgqr: info %d", (int)info);
  /* T = (M H M) Z, then W = Z^T T (k x k, in Q's storage no longer needed... kept apart in T's tail) */
  const PetscInt k = n - m;
  PetscReal     *R;
  PetscCall(PetscMalloc1(k * k, &R));
  for (PetscInt j = 0; j < k; j++)
    for (PetscInt a = 0; a < n; a++) {
      PetscReal s = 0;
      for (PetscInt b = 0; b < n; b++) s += h[b * n + a] * ((a % 4 == 3) ? 1.0 / c.r : 1.0) * ((b % 4 == 3) ? 1.0 / c.r : 1.0) * Q[(m + j) * n + b];
      T[j * n + a] = s;
    }
  for (PetscInt a = 0; a < n; a++) dmax = PetscMax(dmax, PetscAbsReal(h[a * n + a] * ((a % 4 == 3) ? 1.0 / (c.r * c.r) : 1.0)));
  for (PetscInt i = 0; i < k; i++)
    for (PetscInt j = 0; j < k; j++) {
      PetscReal s = 0;
      for (PetscInt a = 0; a < n; a++) s += Q[(m + i) * n + a] * T[j * n + a];
      R[j * k + i] = s;
    }
  PetscCall(PetscBLASIntCast(k, &bk));
  PetscCallBLAS("LAPACKsyev", LAPACKsyev_("N", "U", &bk, R, &bk, W, work, &lwork, &info));
  HYLC_CHECK(info == 0, "syev: info %d", (int)info);
  *neg = 0;
  for (PetscInt i = 0; i < k; i++) *neg += W[i] < -tol * dmax;
  PetscCall(MatDenseRestoreArrayRead(D, &h));
  PetscCall(MatDestroy(&D));
  PetscCall(MatDestroy(&H));
  PetscCall(PetscFree(R));
  PetscCall(PetscFree7(y, g, Q, T, W, work, tau));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the second-order test and the escape from saddle points (HylcMicroSetSaddleEscape): a straight periodic
   yarn compressed by eps is an equilibrium, and the cold start (the affine, straight state) is it; past the
   Euler load it is a saddle point. For the discrete rod, whose curvature is measured per rest length, the
   load is at eps_c = (2 pi / L)^2 B / (k_s (1 + eps)) (L the rest period): the test finds negative curvature
   there and, with escapes, the solve ends in a buckled state of lower energy (post-buckling theory: about
   (2 q - q^2) of the straight state's, q = eps_c / |eps|) whose Hessian has none; below the load the
   straight state is a minimum (no escape, the same Psi) */
static PetscErrorCode TestSaddle(void)
{
  HylcPattern       p;
  HylcYarnModel     m;
  HylcMicro         M;
  HylcPeriodic      P;
  HylcYarnConstants c;
  HylcMicroResult   r;
  PetscReal         area, epsc, L = 8e-3;
  PetscErrorCode    ierr;

  PetscFunctionBegin;
  PetscCall(StraightYarn(16, &p));
  PetscCall(HylcYarnModelDefault(&m));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  PetscCall(HylcMicroGetPeriodic(M, &P));
  {
    const PetscReal z0[6] = {0, 0, 0, 0, 0, 0};
    PetscCall(HylcMicroSolve(M, z0, &r)); /* the default: tested, a minimum */
    HYLC_CHECK(r.negcurv == 0 && r.escapes == 0, "straight yarn at rest, default second-order test: negcurv %d, escapes %d", (int)r.negcurv, (int)r.escapes);
    PetscCall(HylcMicroSetSaddleEscape(M, PETSC_FALSE, 0, PETSC_DEFAULT));
    PetscCall(HylcMicroSolve(M, z0, &r));
    HYLC_CHECK(r.negcurv == -1 && r.escapes == 0, "straight yarn, no second-order test: negcurv %d, escapes %d", (int)r.negcurv, (int)r.escapes);
  }
  PetscCall(HylcPeriodicGetConstants(P, &c));
  PetscCall(HylcPeriodicGetArea(P, &area));
  for (int k = 0; k < 2; k++) {
    const PetscReal eps = k ? -0.3 : -0.05, z[6] = {eps, 0, 0, 0, 0, 0};
    const PetscReal straight = 0.5 * c.ks * eps * eps * L / area;
    epsc                     = PetscSqr(2 * PETSC_PI / L) * c.B / (c.ks * (1 + eps));
    HYLC_CHECK(k ? -eps > 1.25 * epsc : -eps < 0.5 * epsc, "straight yarn: eps %g against the Euler strain %g: the test needs another eps", (double)eps, (double)epsc);
    /* the test alone: the straight state, and its negative curvature past the Euler load */
    PetscCall(HylcMicroSetSaddleEscape(M, PETSC_TRUE, 0, PETSC_DEFAULT));
    PetscCall(HylcMicroSolve(M, z, &r));
    HYLC_CHECK(r.status == HYLC_MICRO_CONVERGED && PetscAbsReal(r.psi - straight) <= 1e-8 * straight, "compressed yarn eps %g, test only: status %s, psi %.12g, straight %.12g", (double)eps, HylcMicroStatuses[r.status], (double)r.psi,
               (double)straight);
    HYLC_CHECK(k ? r.negcurv > 0 : r.negcurv == 0, "compressed yarn eps %g (Euler strain %g), test only: %d negative eigenvalues", (double)eps, (double)epsc, (int)r.negcurv);
    HYLC_CHECK(r.escapes == 0, "compressed yarn eps %g, test only: %d escapes", (double)eps, (int)r.escapes);
    {
      PetscInt nd;
      PetscCall(DenseProjectedNegative(M, 1e-6, &nd));
      HYLC_CHECK(nd == r.negcurv, "compressed yarn eps %g: the test counts %d negative eigenvalues, a dense eigensolver %d", (double)eps, (int)r.negcurv, (int)nd);
    }
    /* with escapes: a minimum, below the straight state past the load */
    PetscCall(HylcMicroSetSaddleEscape(M, PETSC_TRUE, 5, PETSC_DEFAULT));
    PetscCall(HylcMicroSolve(M, z, &r));
    HYLC_CHECK(r.status == HYLC_MICRO_CONVERGED && r.negcurv == 0, "compressed yarn eps %g, escapes: status %s, %d negative eigenvalues at the end", (double)eps, HylcMicroStatuses[r.status], (int)r.negcurv);
    if (k)
      HYLC_CHECK(r.escapes >= 1 && r.psi < 0.95 * straight, "compressed yarn eps %g past the Euler load: %d escapes, psi %g, straight %g", (double)eps, (int)r.escapes, (double)r.psi, (double)straight);
    else
      HYLC_CHECK(r.escapes == 0 && PetscAbsReal(r.psi - straight) <= 1e-8 * straight, "compressed yarn eps %g below the Euler load: %d escapes, psi %.12g, straight %.12g", (double)eps, (int)r.escapes, (double)r.psi, (double)straight);
    {
      PetscInt         n;
      const PetscReal *E;
      PetscCall(HylcMicroGetEnergyHistory(M, &n, &E));
      for (PetscInt i = 1; i < n; i++) HYLC_CHECK(E[i] < E[i - 1], "compressed yarn eps %g, escapes: energy increased at accepted iterate %d: %g -> %g", (double)eps, (int)i, (double)E[i - 1], (double)E[i]);
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "saddle: eps %g (Euler %g): psi %g, straight %g (post-buckling estimate %g), %d escapes, %d iterations\n", (double)eps, (double)epsc, (double)r.psi, (double)straight,
                          (double)(k ? straight * (2 * epsc / -eps - PetscSqr(epsc / eps)) : straight), (int)r.escapes, (int)r.iterations));
  }
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  /* the count against a dense eigensolver on generated knits, cold, adaptive, test only: it is the inertia of
     the factor of K plus the positive eigenvalues of the Schur complement S = B^T K^-1 B, minus m */
  {
    const char *const    types[2] = {HYLCPATTERNSTOCKINETTE, HYLCPATTERNRIB};
    const PetscReal      zs[][6]  = {{0, 0, 0.1, 0, 0, 0}, {0, 0, 0.25, 0, 0, 0}, {0.2, 0, 0, 0, 0, 0}, {-0.3, 0, 0, 0, 0, 0}, {0, 0, -0.3, 0, 0, 0}, {0, 0.2, 0, 0, 0, 0}};
    HylcPatternGenParams g;
    PetscInt             saddles = 0;
    for (int t = 0; t < 2; t++) {
      PetscCall(HylcPatternGenParamsDefault(&g));
      PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &p));
      PetscCall(HylcPatternGenerate(p, types[t], &g));
      PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
      PetscCall(HylcMicroSetPattern(M, p, &m));
      PetscCall(HylcMicroSetRegularizationSchedule(M, HYLC_MICRO_ALPHA_ADAPTIVE, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      PetscCall(HylcMicroSetSaddleEscape(M, PETSC_TRUE, 0, PETSC_DEFAULT));
      for (size_t k = 0; k < sizeof(zs) / sizeof(zs[0]); k++) {
        PetscInt nd;
        PetscCall(HylcMicroSolve(M, zs[k], &r));
        if (r.status != HYLC_MICRO_CONVERGED) continue;
        PetscCall(DenseProjectedNegative(M, 1e-6, &nd));
        HYLC_CHECK(nd == r.negcurv, "%s, strain %d: the test counts %d negative eigenvalues, a dense eigensolver %d", types[t], (int)k, (int)r.negcurv, (int)nd);
        saddles += nd > 0;
      }
      PetscCall(HylcMicroDestroy(&M));
      PetscCall(HylcPatternDestroy(&p));
    }
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "saddle: the second-order test agrees with a dense eigensolver on 12 generated-knit samples, %d of them saddles\n", (int)saddles));
  }
  PetscCall(StraightYarn(16, &p));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroSetPattern(M, p, &m));
  /* bad values */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcMicroSetSaddleEscape(M, PETSC_TRUE, -1, PETSC_DEFAULT);
  PetscCall(PetscPopErrorHandler());
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT, "HylcMicroSetSaddleEscape(-1 escapes): error %d, expected PETSC_ERR_USER_INPUT", (int)ierr);
  PetscCall(CheckOptionRefused(M, "-micro_saddle_tol", "0"));
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the lazy sub-objects: created on first use with the method's defaults (iteration cap 2000, solver type
   hylc); HylcMicroSetFromOptions needs no pattern and its options override the defaults (-micro_snes_max_it,
   -micro_factor_pc_factor_mat_solver_type, -periodic_margin); a new pattern keeps the tile, its options
   and the SNES (SNESReset), and a solver given a second pattern of another size solves it bitwise as a
   fresh solver does */
static PetscErrorCode TestLazy(void)
{
  HylcMicro       M, F;
  HylcPeriodic    P0, P1, P2;
  SNES            s0, s1;
  PC              pc;
  PetscInt        maxit;
  MatSolverType   type;
  PetscBool       eq;
  HylcPattern     a, b;
  HylcYarnModel   m;
  HylcMicroResult ra, rb, rf;
  char            path[] = "/tmp/hylc_test_micro_lazyXXXXXX";
  const PetscReal z[6]   = {0.05, 0.1, 0, 0, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &M));
  PetscCall(HylcMicroGetSNES(M, &s0));
  PetscCall(SNESGetTolerances(s0, NULL, NULL, NULL, &maxit, NULL));
  HYLC_CHECK(maxit == 2000, "default iteration cap %d, expected 2000", (int)maxit);
  PetscCall(HylcMicroGetFactorPC(M, &pc));
  PetscCall(PCFactorGetMatSolverType(pc, &type));
  PetscCall(PetscStrcmp(type, MATSOLVERHYLC, &eq));
  HYLC_CHECK(eq, "default solver type %s, expected hylc", type ? type : "(null)");
  PetscCall(HylcMicroSetRegularizationFallback(M, PETSC_FALSE)); /* the iteration cap is what is counted below */
  PetscCall(PetscOptionsSetValue(NULL, "-micro_snes_max_it", "2"));
  PetscCall(PetscOptionsSetValue(NULL, "-micro_factor_pc_factor_mat_solver_type", "petsc"));
  PetscCall(PetscOptionsSetValue(NULL, "-periodic_margin", "0.375"));
  PetscCall(HylcMicroSetFromOptions(M)); /* no pattern yet */
  PetscCall(PetscOptionsClearValue(NULL, "-micro_snes_max_it"));
  PetscCall(PetscOptionsClearValue(NULL, "-micro_factor_pc_factor_mat_solver_type"));
  PetscCall(PetscOptionsClearValue(NULL, "-periodic_margin"));
  PetscCall(HylcMicroGetSNES(M, &s1));
  PetscCall(SNESGetTolerances(s1, NULL, NULL, NULL, &maxit, NULL));
  HYLC_CHECK(s1 == s0 && maxit == 2, "-micro_snes_max_it 2: iteration cap %d (same SNES: %d)", (int)maxit, (int)(s1 == s0));
  PetscCall(PCFactorGetMatSolverType(pc, &type));
  PetscCall(PetscStrcmp(type, MATSOLVERPETSC, &eq));
  HYLC_CHECK(eq, "-micro_factor_pc_factor_mat_solver_type petsc: solver type %s", type ? type : "(null)");
  PetscCall(HylcMicroGetPeriodic(M, &P0));
  /* two patterns of different sizes: the tile and the SNES stay, with their options */
  PetscCall(StraightYarn(16, &a));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &b));
  {
    HylcPatternGenParams g;
    PetscCall(HylcPatternGenParamsDefault(&g));
    PetscCall(HylcPatternGenerate(b, HYLCPATTERNPLAIN, &g));
  }
  PetscCall(HylcYarnModelDefault(&m));
  m.kc = 50;
  PetscCall(HylcMicroSetPattern(M, a, &m));
  PetscCall(HylcMicroSolve(M, z, &ra));
  PetscCall(HylcMicroSetPattern(M, b, &m));
  PetscCall(HylcMicroGetPeriodic(M, &P1));
  PetscCall(HylcMicroSetUp(M));
  PetscCall(HylcMicroSolve(M, z, &rb));
  PetscCall(HylcMicroGetPeriodic(M, &P2));
  PetscCall(HylcMicroGetSNES(M, &s1));
  HYLC_CHECK(P0 == P1 && P1 == P2 && s1 == s0, "a new pattern replaced the tile or the SNES");
  PetscCall(ViewToTempFile((PetscObject)P2, path));
  HYLC_CHECK(FileHas(path, "contact ghosts within margin 0.375"), "-periodic_margin 0.375 read before the patterns was lost (%s)", path);
  remove(path);
  /* a fresh solver with the same settings, given only the second pattern */
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &F));
  PetscCall(HylcMicroGetSNES(F, &s1));
  PetscCall(SNESSetTolerances(s1, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2, PETSC_DEFAULT));
  PetscCall(HylcMicroGetFactorPC(F, &pc));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERPETSC));
  PetscCall(HylcMicroGetPeriodic(F, &P1));
  PetscCall(HylcMicroSetRegularizationFallback(F, PETSC_FALSE));
  PetscCall(HylcPeriodicSetContactMargin(P1, 0.375));
  PetscCall(HylcMicroSetPattern(F, b, &m));
  PetscCall(HylcMicroSolve(F, z, &rf));
  HYLC_CHECK(ra.status == HYLC_MICRO_CONVERGED && rb.iterations == 2 && rb.status == HYLC_MICRO_MAX_IT, "with -micro_snes_max_it 2: straight yarn %d iterations (%s), plain weave %d iterations (%s)", (int)ra.iterations, HylcMicroStatuses[ra.status],
             (int)rb.iterations, HylcMicroStatuses[rb.status]);
  HYLC_CHECK(rb.psi == rf.psi && rb.iterations == rf.iterations && rb.retries == rf.retries, "second pattern: psi %.17g (%d its) vs a fresh solver %.17g (%d its)", (double)rb.psi, (int)rb.iterations, (double)rf.psi, (int)rf.iterations);
  PetscCall(HylcMicroDestroy(&F));
  PetscCall(HylcMicroDestroy(&M));
  PetscCall(HylcPatternDestroy(&a));
  PetscCall(HylcPatternDestroy(&b));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char        dir[PETSC_MAX_PATH_LEN];
  PetscBool   have;
  const char *env = getenv("HYLC_REFDATA"), *root = getenv("HYLC_ROOT");

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestObject());
  PetscCall(TestLazy());
  PetscCall(TestAnalytic());
  PetscCall(TestReproducible());
  PetscCall(TestContinuation());
  PetscCall(TestShearSymmetry());
  PetscCall(TestMirrorTwill());
  PetscCall(TestAdaptive());
  PetscCall(TestSaddle());
  PetscCall(PetscSNPrintf(dir, sizeof(dir), "%s/patterns/hylc2020", env ? env : "../shared/refdata"));
  PetscCall(PetscTestDirectory(dir, 'r', &have));
  if (have)
    PetscCall(TestPaperPatterns(root ? root : ".", dir));
  else
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "note: %s not found: the paper-pattern checks were skipped\n", dir));
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
