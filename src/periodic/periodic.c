/* HylcPeriodic: ghost extension, elimination, constraints and reduced assembly (include/hylc/periodic.h). */
#include <hylc/periodic.h>
#include <hylc/contact.h>
#include <hylc/geom.h>
#include <hylc/rod.h>
#include <petsc/private/hashmapi.h>
#include <petsctime.h>

const char *const HylcSlideConstraints[] = {"none", "global", "per_yarn", "per_family", "HylcSlideConstraint", "HYLC_SLIDE_", NULL};

#define SMAX 8 /* |lattice shift| bound of ghosts */

typedef struct {
  PetscInt  e, f; /* incoming and outgoing full edges */
  PetscInt  v[3]; /* full vertices prev, centre, next */
  PetscReal w;    /* fractional weight */
} BendElem;

struct _n_HylcPeriodic {
  char                   prefix[64];
  HylcPattern            pat;
  HylcPatternData        D;
  HylcYarnModel          model;
  HylcYarnConstants      c;
  HylcRodBendTwistParams btpar;
  HylcMidsurface         ms;
  PetscReal              z[6];
  HylcSlideConstraint    slide;
  PetscReal              marginFactor; /* contact-ghost margin: max(3 r, factor min(px, py)) */
  PetscBool              setup;
  PetscInt               N;  /* original vertices */
  PetscReal             *xi; /* reference (xi1, xi2, h) of the originals, recentred */
  /* full vertices: original o, shift s; the first N are the originals */
  PetscInt   nfv, capfv, *fo, *fs;
  PetscReal *T, *d;      /* per full vertex: T (9), d (3) */
  PetscBool *rigidId;    /* T == I exactly */
  PetscHMapI vmap, emap; /* (o, s) -> full vertex / full edge */
  /* full edges: source full vertex (edge leaving o(src) in copy s(src)) and head */
  PetscInt       nfe, capfe, *esrc, *ehead;
  PetscReal     *et, *ed1, *et0, *ed10; /* frames per full edge (and saved copy) */
  PetscReal     *sw;                    /* stretch weight per full edge (0: contact-only edge) */
  unsigned char *eghost;                /* edge has no original vertex */
  /* bend/twist elements */
  PetscInt   nbe, capbe;
  BendElem  *be;
  PetscReal *mref, *mref0;
  /* state */
  PetscReal *y, *y0, *x; /* y and the initial guess y0: 4 N; x: 3 per full vertex */
  /* constraints */
  PetscInt   ncons, ndropped; /* independent constraint rows kept, linearly dependent rows dropped */
  PetscReal  crtol;           /* relative tolerance of the dependence test (-periodic_constraint_rtol) */
  PetscReal *A, *dL, *AAtinv;
  /* contact */
  HylcBVH      bvh;
  double      *segx;
  HylcPairList cand;
  PetscInt     npairs, cappairs, *pairs; /* pairs that can touch (boxes inflated by r overlap): full edges i, j */
  PetscInt     ncand, capcand, *cpairs;  /* candidates for the Hessian's structure (boxes inflated by pairMargin r) */
  PetscReal   *cw;
  PetscReal    pairMargin;
  PetscReal   *pw; /* pair weights */
  /* COO */
  PetscInt     ncoo, capcoo, *coopos; /* element-entry values coov and where each goes in the CSR values */
  PetscScalar *coov;
  PetscInt    *rowptr, *colind, nnz; /* the CSR structure of H_y: 4x4 blocks of coupled vertices */
  PetscInt     coonpairs, *coopairs; /* the pairs of the current COO structure, a superset of the touching ones */
  PetscReal   *coopw;
  Mat          cooMat;
  /* accumulated wall times (s): evaluations with a Hessian, contact (broadphase + pairs), assembly */
  PetscLogDouble tEval, tContact, tAssemble;
};

static inline PetscInt Key(PetscInt N, PetscInt o, PetscInt s1, PetscInt s2) { return o + N * ((s1 + SMAX) + (2 * SMAX + 1) * (s2 + SMAX)); }

PetscErrorCode HylcPeriodicCreate(HylcPattern pat, const HylcYarnModel *model, HylcPeriodic *per)
{
  HylcPeriodic P;

  PetscFunctionBegin;
  PetscCall(PetscNew(&P));
  PetscCall(PetscObjectReference((PetscObject)pat));
  P->pat          = pat;
  P->model        = *model;
  P->slide        = HYLC_SLIDE_GLOBAL;
  P->marginFactor = 0.25;
  P->pairMargin   = 1.05;
  P->crtol        = 1e-6;
  PetscCall(HylcPatternGetData(pat, &P->D));
  PetscCall(HylcYarnModelGetConstants(model, P->D.radius, &P->c));
  P->btpar.B       = P->c.B;
  P->btpar.beta    = P->c.beta;
  P->btpar.variant = model->curvature;
  P->N             = P->D.nv;
  PetscCheck(P->N * (2 * SMAX + 1) * (2 * SMAX + 1) < PETSC_MAX_INT / 2, PETSC_COMM_SELF, PETSC_ERR_SUP, "Pattern too large for the ghost index");
  PetscCall(HylcMidsurfaceCreate(PETSC_COMM_SELF, &P->ms));
  *per = P;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode PeriodicReset(HylcPeriodic P)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(P->xi));
  PetscCall(PetscFree2(P->fo, P->fs));
  PetscCall(PetscFree3(P->T, P->d, P->rigidId));
  if (P->vmap) PetscCall(PetscHMapIDestroy(&P->vmap));
  if (P->emap) PetscCall(PetscHMapIDestroy(&P->emap));
  PetscCall(PetscFree4(P->esrc, P->ehead, P->sw, P->eghost));
  PetscCall(PetscFree4(P->et, P->ed1, P->et0, P->ed10));
  PetscCall(PetscFree(P->be));
  PetscCall(PetscFree2(P->mref, P->mref0));
  PetscCall(PetscFree3(P->y, P->y0, P->x));
  PetscCall(PetscFree3(P->A, P->dL, P->AAtinv));
  HylcBVHDestroy(&P->bvh);
  PetscCall(PetscFree(P->segx));
  HylcPairListFree(&P->cand);
  PetscCall(PetscFree2(P->pairs, P->pw));
  PetscCall(PetscFree2(P->cpairs, P->cw));
  P->ncand = P->capcand = 0;
  PetscCall(PetscFree2(P->coopos, P->coov));
  PetscCall(PetscFree2(P->rowptr, P->colind));
  PetscCall(PetscFree2(P->coopairs, P->coopw));
  P->nfv = P->capfv = P->nfe = P->capfe = P->nbe = P->capbe = P->npairs = P->cappairs = P->ncoo = P->capcoo = P->coonpairs = 0;
  P->cooMat                                                                                                                = NULL;
  P->setup                                                                                                                 = PETSC_FALSE;
  P->tEval = P->tContact = P->tAssemble = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicDestroy(HylcPeriodic *per)
{
  PetscFunctionBegin;
  if (!*per) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PeriodicReset(*per));
  PetscCall(HylcMidsurfaceDestroy(&(*per)->ms));
  PetscCall(HylcPatternDestroy(&(*per)->pat));
  PetscCall(PetscFree(*per));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicSetOptionsPrefix(HylcPeriodic P, const char prefix[])
{
  PetscFunctionBegin;
  PetscCall(PetscStrncpy(P->prefix, prefix ? prefix : "", sizeof(P->prefix)));
  PetscCall(HylcMidsurfaceSetOptionsPrefix(P->ms, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetFromOptions - Options:
+ -periodic_slide <global>       - slide constraint: none, global (one row), per_yarn (one row per loop),
                                   per_family (one row per yarn family, invariant under mirrors and under
                                   the direction in which a file lists each yarn; docs/method.md)
. -periodic_margin <0.25>        - contact ghosts: copies of edges within max(3 r, margin min(px, py)) of the tile
. -periodic_constraint_rtol <1e-6> - drop a constraint row within this relative distance of the span of the
                                   rows before it (linearly dependent: straight yarns; docs/method.md)
- -macro_*                        - the midsurface (HylcMidsurfaceSetFromOptions())
@*/
PetscErrorCode HylcPeriodicSetFromOptions(HylcPeriodic P)
{
  PetscEnum sl = (PetscEnum)P->slide;

  PetscFunctionBegin;
  PetscOptionsBegin(PETSC_COMM_SELF, P->prefix[0] ? P->prefix : NULL, "Periodic tile options", "HylcPeriodic");
  PetscCall(PetscOptionsEnum("-periodic_slide", "Slide constraint: none, global (one row), per_yarn (one row per yarn loop) or per_family (one row per yarn family, each yarn in its canonical direction)", "HylcPeriodicSetSlideConstraint", HylcSlideConstraints, sl, &sl, NULL));
  PetscCall(PetscOptionsReal("-periodic_pair_margin", "Hessian structure: keep segment pairs whose boxes inflated by this many r overlap, so that it changes rarely", "HylcPeriodicEvaluate", P->pairMargin, &P->pairMargin, NULL));
  PetscCall(PetscOptionsReal("-periodic_margin", "Contact ghosts: copies of edges within max(3 r, margin * min(px, py)) of the tile", "HylcPeriodicSetUp", P->marginFactor, &P->marginFactor, NULL));
  PetscCall(PetscOptionsReal("-periodic_constraint_rtol", "A constraint row whose distance to the span of the rows before it is at most this times its norm is dropped as linearly dependent (straight yarns: the slide row repeats the translation)", "HylcPeriodicSetUp", P->crtol, &P->crtol, NULL));
  PetscOptionsEnd();
  PetscCheck(P->crtol > 0 && P->crtol < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-periodic_constraint_rtol must be in (0, 1), got %g", (double)P->crtol);
  P->setup = PETSC_FALSE;
  P->slide = (HylcSlideConstraint)sl;
  PetscCheck(P->pairMargin >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-periodic_pair_margin must be at least 1 (boxes inflated by r find every touching pair)");
  PetscCheck(P->marginFactor >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-periodic_margin must not be negative");
  PetscCall(HylcMidsurfaceSetFromOptions(P->ms));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicSetStrain(HylcPeriodic P, const PetscReal z[6])
{
  PetscFunctionBegin;
  const HylcMacroStrainError err = HylcMacroStrainValidate(z);
  PetscCheck(err == HYLC_MACRO_STRAIN_OK, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Invalid strain (%g, %g, %g, %g, %g, %g): %s", (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5], HylcMacroStrainErrorString(err));
  for (int k = 0; k < 6; k++) P->z[k] = z[k];
  P->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicCheckStrain - Refuses a strain z = (sx, sa, sy, II00, II01, II11) that does not give a valid,
  representable deformed tile, with a one-line PETSC_ERR_USER_INPUT error "<name>: <component> = <value>:
  <reason>" (name: e.g. the option, "-strain"). Beyond HylcPeriodicSetStrain()'s validity (finite, |sa| < 1,
  1 + sx > 0, 1 + sy > 0) it bounds the stretch factors 1 + sx, 1 + sy by HYLC_PERIODIC_MAX_STRETCH and the
  angle the midsurface normal turns across one period, |N (px, 0)|, |N (0, py)|, |N (px, +-py)| with
  N = -A^-T II, by 2 pi (a tile bent further wraps onto itself; at extreme II the midsurface collapses to
  a point). Subnormal components are valid. Not collective. See docs/method.md.
@*/
PetscErrorCode HylcPeriodicCheckStrain(HylcPeriodic P, const PetscReal z[6], const char name[])
{
  static const char *const comp[6] = {"sx", "sa", "sy", "II00", "II01", "II11"};
  double                   zd[6], N[4];
  char                     v[6][32]; /* C formatting: PETSc's printf appends '.' to integral %g values */

  PetscFunctionBegin;
  for (int k = 0; k < 6; k++) {
    PetscCheck(!PetscIsInfOrNanReal(z[k]), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s is not finite", name, comp[k]);
    zd[k] = (double)z[k];
  }
  for (int k = 0; k < 6; k++) snprintf(v[k], sizeof(v[k]), "%.15g", zd[k]);
  PetscCheck(PetscAbsReal(z[1]) < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: sa = %s: |sa| must be below 1 (sa is the cosine of the angle between the deformed warp and weft directions)", name, v[1]);
  for (int k = 0; k < 3; k += 2) {
    PetscCheck(1 + z[k] > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s = %s: the stretch factor 1 + %s must be positive", name, comp[k], v[k], comp[k]);
    PetscCheck(1 + z[k] <= HYLC_PERIODIC_MAX_STRETCH, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s = %s: the stretch factor 1 + %s must be at most 1e3", name, comp[k], v[k], comp[k]);
  }
  HylcMacroNormalDerivatives(zd, N);
  {
    const double px = P->D.px, py = P->D.py, c4[4][2] = {{px, 0}, {0, py}, {px, py}, {px, -py}};
    for (int i = 0; i < 4; i++) {
      const double a = N[0] * c4[i][0] + N[1] * c4[i][1], b = N[2] * c4[i][0] + N[3] * c4[i][1], ang = PetscSqrtReal(a * a + b * b);
      if (!(ang <= 2 * PETSC_PI)) {
        const int k = PetscAbsReal(z[3]) >= PetscAbsReal(z[4]) && PetscAbsReal(z[3]) >= PetscAbsReal(z[5]) ? 3 : PetscAbsReal(z[4]) >= PetscAbsReal(z[5]) ? 4
                                                                                                                                                          : 5;
        char      msg[160];
        snprintf(msg, sizeof(msg), "the midsurface would turn by %.3g rad across one period (periods %g m, %g m)", ang, px, py);
        SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s = %s: %s; at most 2 pi (a tile bent further wraps onto itself)", name, comp[k], v[k], msg);
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicSetSlideConstraint(HylcPeriodic P, HylcSlideConstraint s)
{
  PetscFunctionBegin;
  P->slide = s;
  P->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the full vertex (o, s), created as a ghost if new */
static PetscErrorCode FullVertex(HylcPeriodic P, PetscInt o, PetscInt s1, PetscInt s2, PetscInt *k)
{
  PetscFunctionBegin;
  PetscCheck(PetscAbsInt(s1) <= SMAX && PetscAbsInt(s2) <= SMAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "Ghost shift (%d, %d) beyond %d periods", (int)s1, (int)s2, SMAX);
  const PetscInt key = Key(P->N, o, s1, s2);
  PetscCall(PetscHMapIGet(P->vmap, key, k));
  if (*k >= 0) PetscFunctionReturn(PETSC_SUCCESS);
  if (P->nfv == P->capfv) {
    PetscInt *fo, *fs;
    P->capfv = P->capfv ? 2 * P->capfv : 2 * P->N + 16;
    PetscCall(PetscMalloc2(P->capfv, &fo, 2 * P->capfv, &fs));
    PetscCall(PetscArraycpy(fo, P->fo, P->nfv));
    PetscCall(PetscArraycpy(fs, P->fs, 2 * P->nfv));
    PetscCall(PetscFree2(P->fo, P->fs));
    P->fo = fo;
    P->fs = fs;
  }
  *k                = P->nfv++;
  P->fo[*k]         = o;
  P->fs[2 * *k]     = s1;
  P->fs[2 * *k + 1] = s2;
  PetscCall(PetscHMapISet(P->vmap, key, *k));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the full edge leaving o in copy s (created with its vertices if new); stretch weight added separately */
static PetscErrorCode FullEdge(HylcPeriodic P, PetscInt o, PetscInt s1, PetscInt s2, PetscInt *e)
{
  PetscFunctionBegin;
  const PetscInt key = Key(P->N, o, s1, s2);
  PetscCall(PetscHMapIGet(P->emap, key, e));
  if (*e >= 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscInt k0, k1;
  PetscCall(FullVertex(P, o, s1, s2, &k0));
  PetscCall(FullVertex(P, P->D.next[o], s1 + P->D.shift[2 * o], s2 + P->D.shift[2 * o + 1], &k1));
  if (P->nfe == P->capfe) {
    PetscInt      *es, *eh;
    PetscReal     *sw;
    unsigned char *eg;
    P->capfe = P->capfe ? 2 * P->capfe : 2 * P->N + 16;
    PetscCall(PetscMalloc4(P->capfe, &es, P->capfe, &eh, P->capfe, &sw, P->capfe, &eg));
    PetscCall(PetscArraycpy(es, P->esrc, P->nfe));
    PetscCall(PetscArraycpy(eh, P->ehead, P->nfe));
    PetscCall(PetscArraycpy(sw, P->sw, P->nfe));
    PetscCall(PetscArraycpy(eg, P->eghost, P->nfe));
    PetscCall(PetscFree4(P->esrc, P->ehead, P->sw, P->eghost));
    P->esrc   = es;
    P->ehead  = eh;
    P->sw     = sw;
    P->eghost = eg;
  }
  *e            = P->nfe++;
  P->esrc[*e]   = k0;
  P->ehead[*e]  = k1;
  P->sw[*e]     = 0;
  P->eghost[*e] = (unsigned char)(k0 >= P->N && k1 >= P->N);
  PetscCall(PetscHMapISet(P->emap, key, *e));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* bend/twist element centred on o in copy s (deduplicated by its centre) */
static PetscErrorCode AddBend(HylcPeriodic P, PetscHMapI bmap, PetscInt o, PetscInt s1, PetscInt s2)
{
  PetscInt b;

  PetscFunctionBegin;
  const PetscInt key = Key(P->N, o, s1, s2);
  PetscCall(PetscHMapIGet(bmap, key, &b));
  if (b >= 0) PetscFunctionReturn(PETSC_SUCCESS);
  const PetscInt u = P->D.prev[o];
  PetscInt       e, f;
  PetscCall(FullEdge(P, u, s1 - P->D.shift[2 * u], s2 - P->D.shift[2 * u + 1], &e));
  PetscCall(FullEdge(P, o, s1, s2, &f));
  if (P->nbe == P->capbe) {
    BendElem *nb;
    P->capbe = P->capbe ? 2 * P->capbe : 2 * P->N + 16;
    PetscCall(PetscMalloc1(P->capbe, &nb));
    PetscCall(PetscArraycpy(nb, P->be, P->nbe));
    PetscCall(PetscFree(P->be));
    P->be = nb;
  }
  BendElem *E = P->be + P->nbe;
  E->e        = e;
  E->f        = f;
  E->v[0]     = P->esrc[e];
  E->v[1]     = P->esrc[f];
  E->v[2]     = P->ehead[f];
  E->w        = ((E->v[0] < P->N) + (E->v[1] < P->N) + (E->v[2] < P->N)) / 3.0;
  PetscCall(PetscHMapISet(bmap, key, P->nbe++));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* reference position (xi1, xi2, h) of full vertex k */
static inline void RefPos(const HylcPeriodic P, PetscInt k, PetscReal xih[3])
{
  const PetscInt o = P->fo[k];
  xih[0]           = P->xi[3 * o] + P->fs[2 * k] * P->D.px;
  xih[1]           = P->xi[3 * o + 1] + P->fs[2 * k + 1] * P->D.py;
  xih[2]           = P->xi[3 * o + 2];
}

static inline void MatT3(const PetscReal M[9], const PetscReal v[3], PetscReal out[3])
{
  for (int i = 0; i < 3; i++) out[i] = M[i] * v[0] + M[3 + i] * v[1] + M[6 + i] * v[2];
}
static inline void Mat3(const PetscReal M[9], const PetscReal v[3], PetscReal out[3])
{
  for (int i = 0; i < 3; i++) out[i] = M[3 * i] * v[0] + M[3 * i + 1] * v[1] + M[3 * i + 2] * v[2];
}

/* per_family: the family (row) and the sign of each loop. A loop's canonical direction is its winding
   divided by the gcd of its components, made lexicographically positive (sign -1 if that reverses it);
   loops of equal canonical direction form a family; loops that close inside the tile (zero winding) form
   their own family with their stored direction. */
static PetscErrorCode SlideFamilies(HylcPattern pat, PetscInt nloops, PetscInt fam[], PetscReal sgn[], PetscInt *nfam)
{
  PetscInt *dir;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(2 * nloops, &dir));
  *nfam = 0;
  for (PetscInt l = 0; l < nloops; l++) {
    PetscInt w[2], a, b, g;
    PetscCall(HylcPatternGetLoop(pat, l, NULL, NULL, w));
    a = PetscAbsInt(w[0]), b = PetscAbsInt(w[1]);
    while (b) {
      const PetscInt t = a % b;
      a = b, b = t;
    }
    g      = a ? a : 1;
    sgn[l] = (w[0] < 0 || (w[0] == 0 && w[1] < 0)) ? -1.0 : 1.0;
    w[0] = (PetscInt)sgn[l] * w[0] / g, w[1] = (PetscInt)sgn[l] * w[1] / g;
    fam[l] = -1;
    for (PetscInt f = 0; f < *nfam; f++)
      if (dir[2 * f] == w[0] && dir[2 * f + 1] == w[1]) fam[l] = f;
    if (fam[l] < 0) {
      dir[2 * *nfam] = w[0], dir[2 * *nfam + 1] = w[1];
      fam[l] = (*nfam)++;
    }
  }
  PetscCall(PetscFree(dir));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Reduces the m constraint rows of A (and dL) to an independent set, in order: modified Gram-Schmidt with
   one reorthogonalization on the rows of A (not on A A^T, which would square the condition); row i is
   dropped when its distance to the span of the rows kept before it is at most crtol |a_i|. The translation
   rows come first and are independent, so a slide row that repeats them (straight yarns; parallel straight
   yarns under per_yarn) is the one dropped. Dropping a dependent row does not change the feasible set: at
   the initial guess every row vanishes, and a dependent row is a combination of the kept ones. When no row
   is dropped, A and dL are untouched (bitwise). */
static PetscErrorCode ReduceConstraints(HylcPeriodic P, PetscInt *m)
{
  const PetscInt n = 4 * P->N, m0 = *m;
  PetscReal     *Q, *r;
  PetscInt       nq = 0, kept = 0;

  PetscFunctionBegin;
  PetscCall(PetscMalloc2(m0 * n, &Q, n, &r));
  for (PetscInt i = 0; i < m0; i++) {
    const PetscReal *a  = P->A + i * n;
    PetscReal        a2 = 0, r2 = 0, scale = 0;
    for (PetscInt k = 0; k < n; k++) scale = PetscMax(scale, PetscAbsReal(a[k]));
    PetscCheck(scale > 0 && !PetscIsInfOrNanReal(scale) && !PetscIsInfOrNanReal(P->dL[i]), PETSC_COMM_SELF, PETSC_ERR_FP, "Constraint row %" PetscInt_FMT " is zero or not finite (|a| max %g, dL %g): is the strain representable?", i, (double)scale, (double)P->dL[i]);
    for (PetscInt k = 0; k < n; k++) {
      r[k] = a[k] / scale; /* scaled: no overflow or underflow in the squares */
      a2 += r[k] * r[k];
    }
    for (int pass = 0; pass < 2; pass++)
      for (PetscInt q = 0; q < nq; q++) {
        PetscReal d = 0;
        for (PetscInt k = 0; k < n; k++) d += Q[q * n + k] * r[k];
        for (PetscInt k = 0; k < n; k++) r[k] -= d * Q[q * n + k];
      }
    for (PetscInt k = 0; k < n; k++) r2 += r[k] * r[k];
    if (r2 <= P->crtol * P->crtol * a2) {
      PetscCall(PetscInfo(NULL, "constraint row %" PetscInt_FMT " dropped: linearly dependent on the rows before it (relative distance %g <= %g)\n", i, (double)PetscSqrtReal(r2 / a2), (double)P->crtol));
      continue;
    }
    const PetscReal rn = PetscSqrtReal(r2);
    for (PetscInt k = 0; k < n; k++) Q[nq * n + k] = r[k] / rn;
    nq++;
    if (kept != i) {
      PetscCall(PetscArraycpy(P->A + kept * n, a, n));
      P->dL[kept] = P->dL[i];
    }
    kept++;
  }
  PetscCall(PetscFree2(Q, r));
  P->ndropped = m0 - kept;
  P->ncons = *m = kept;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode SetUpConstraints(HylcPeriodic P, const PetscReal *x0)
{
  const PetscInt         N = P->N;
  PetscInt               nloops, m, nfam = 0, *fam;
  PetscReal             *sgn;
  const HylcMacroStrain *ms;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetNumLoops(P->pat, &nloops));
  PetscCall(PetscMalloc2(nloops, &fam, nloops, &sgn));
  if (P->slide == HYLC_SLIDE_PER_FAMILY) PetscCall(SlideFamilies(P->pat, nloops, fam, sgn, &nfam));
  m        = 3 + (P->slide == HYLC_SLIDE_PER_YARN ? nloops : P->slide == HYLC_SLIDE_PER_FAMILY ? nfam
                                                         : P->slide == HYLC_SLIDE_GLOBAL       ? 1
                                                                                               : 0);
  P->ncons = m;
  PetscCall(PetscCalloc3(m * 4 * N, &P->A, m, &P->dL, m * m, &P->AAtinv));
  PetscCall(HylcMidsurfaceGetStrain(P->ms, &ms));
  for (PetscInt o = 0; o < N; o++) {
    const PetscInt  u = P->D.prev[o], w = P->D.next[o];
    const PetscReal wo = 0.5 * (P->D.restLength[u] + P->D.restLength[o]); /* rest Voronoi length */
    PetscReal       R[9], Rtx[3], tau[3], te[3], tf[3], Rtau[3];
    PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, R));
    MatT3(R, x0 + 3 * o, Rtx);
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) P->A[i * 4 * N + 4 * o + j] = wo * R[3 * j + i]; /* rows of R^T */
      P->dL[i] += wo * Rtx[i];
    }
    if (P->slide == HYLC_SLIDE_NONE) continue;
    /* reference unit tangent at o in (xi1, xi2, h), deformed in-plane by S3 = [[A, 0], [0, 1]] */
    for (int i = 0; i < 3; i++) {
      te[i] = P->xi[3 * o + i] - P->xi[3 * u + i];
      tf[i] = P->xi[3 * w + i] - P->xi[3 * o + i];
    }
    te[0] += P->D.shift[2 * u] * P->D.px;
    te[1] += P->D.shift[2 * u + 1] * P->D.py;
    tf[0] += P->D.shift[2 * o] * P->D.px;
    tf[1] += P->D.shift[2 * o + 1] * P->D.py;
    HylcNormalize3(te);
    HylcNormalize3(tf);
    const PetscReal t0 = te[0] + tf[0], t1 = te[1] + tf[1];
    tau[0] = ms->A[0] * t0 + ms->A[1] * t1;
    tau[1] = ms->A[2] * t0 + ms->A[3] * t1;
    tau[2] = te[2] + tf[2];
    PetscCheck(HylcNormalize3(tau) > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Yarn folds back at vertex %" PetscInt_FMT ": no tangent for the slide constraint", o);
    Mat3(R, tau, Rtau);
    PetscInt  row = 3, l;
    PetscReal s   = 1;
    PetscCall(HylcPatternGetVertexLoop(P->pat, o, &l, NULL));
    if (P->slide == HYLC_SLIDE_PER_YARN) row += l;
    if (P->slide == HYLC_SLIDE_PER_FAMILY) row += fam[l], s = sgn[l];
    for (int j = 0; j < 3; j++) P->A[row * 4 * N + 4 * o + j] = s * wo * Rtau[j];
    P->dL[row] += s * wo * HylcDot3(tau, Rtx);
  }
  PetscCall(PetscFree2(fam, sgn));
  PetscCall(ReduceConstraints(P, &m));
  /* (A A^T)^-1 of the small SPD matrix */
  {
    PetscReal *M, *I1;
    PetscCall(PetscCalloc2(m * m, &M, m * m, &I1));
    for (PetscInt i = 0; i < m; i++) {
      I1[i * m + i] = 1;
      for (PetscInt j = 0; j < m; j++)
        for (PetscInt k = 0; k < 4 * N; k++) M[i * m + j] += P->A[i * 4 * N + k] * P->A[j * 4 * N + k];
    }
    /* the kept rows are independent to crtol (sin of the angle to the span of the others): the pivots of
       A A^T are at least about crtol^2 times its diagonal */
    const int err = HylcDenseInverse((int)m, M, I1, 1e-2 * P->crtol * P->crtol);
    PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The reduced constraint rows are numerically dependent (row %d) although they passed the dependence test with -periodic_constraint_rtol %g", -1 - err, (double)P->crtol);
    PetscCall(PetscArraycpy(P->AAtinv, I1, m * m));
    PetscCall(PetscFree2(M, I1));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetUp - Builds the midsurface, the extended pattern, the elimination maps, the projected
  reference frames, the initial state (x = phi + h n, u~ = 0) and the constraints. Not collective.
@*/
PetscErrorCode HylcPeriodicSetUp(HylcPeriodic P)
{
  const PetscInt N = P->N;
  PetscReal      lo[2], hi[2], *x0;
  PetscHMapI     bmap;

  PetscFunctionBegin;
  if (P->setup) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PeriodicReset(P));
  PetscCall(PetscLogEventBegin(HYLC_PeriodicSetUp, 0, 0, 0, 0));
  /* reference coordinates, recentred so that the mean of (xi1, xi2, h) is 0 (C1 step 16) */
  PetscCall(PetscMalloc1(3 * N, &P->xi));
  {
    PetscReal mean[3] = {0, 0, 0};
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) mean[i] += P->D.X[3 * o + i] / N;
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) P->xi[3 * o + i] = P->D.X[3 * o + i] - mean[i];
  }
  /* extended pattern: originals first, then every element touching an original */
  PetscCall(PetscHMapICreate(&P->vmap));
  PetscCall(PetscHMapICreate(&P->emap));
  PetscCall(PetscHMapICreate(&bmap));
  for (PetscInt o = 0; o < N; o++) {
    PetscInt k;
    PetscCall(FullVertex(P, o, 0, 0, &k));
  }
  for (PetscInt o = 0; o < N; o++) {
    const PetscInt u = P->D.prev[o], w = P->D.next[o];
    PetscInt       e;
    PetscCall(FullEdge(P, o, 0, 0, &e));
    PetscCall(FullEdge(P, u, -P->D.shift[2 * u], -P->D.shift[2 * u + 1], &e));
    PetscCall(AddBend(P, bmap, o, 0, 0));
    PetscCall(AddBend(P, bmap, u, -P->D.shift[2 * u], -P->D.shift[2 * u + 1]));
    PetscCall(AddBend(P, bmap, w, P->D.shift[2 * o], P->D.shift[2 * o + 1]));
  }
  PetscCall(PetscHMapIDestroy(&bmap));
  /* stretch weights of the chain edges */
  for (PetscInt e = 0; e < P->nfe; e++) P->sw[e] = ((P->esrc[e] < N) + (P->ehead[e] < N)) / 2.0;

  /* midsurface over the reference box of the extended pattern (contact ghosts stay within one period) */
  lo[0] = lo[1] = PETSC_MAX_REAL;
  hi[0] = hi[1] = PETSC_MIN_REAL;
  for (PetscInt o = 0; o < N; o++)
    for (int i = 0; i < 2; i++) {
      lo[i] = PetscMin(lo[i], P->xi[3 * o + i]);
      hi[i] = PetscMax(hi[i], P->xi[3 * o + i]);
    }
  lo[0] -= 1.5 * P->D.px;
  hi[0] += 1.5 * P->D.px;
  lo[1] -= 1.5 * P->D.py;
  hi[1] += 1.5 * P->D.py;
  PetscCall(HylcMidsurfaceSetStrain(P->ms, P->z));
  PetscCall(HylcMidsurfaceSetBox(P->ms, lo, hi));
  PetscCall(HylcMidsurfaceSetUp(P->ms));

  /* contact ghosts: copies of tile edges in the neighbouring tiles within the margin, measured on the
     deformed initial guess. Usually the 8 neighbours; more rings when the stored vertices spread over more
     than a period (a file may store any periodic copy of a vertex) */
  {
    const PetscReal margin = PetscMax(3 * P->c.r, P->marginFactor * PetscMin(P->D.px, P->D.py));
    PetscReal       blo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, bhi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL};
    PetscReal      *xih, *xo, xmin[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, xmax[2] = {PETSC_MIN_REAL, PETSC_MIN_REAL};
    PetscInt        k1, k2;
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 2; i++) {
        xmin[i] = PetscMin(xmin[i], P->xi[3 * o + i]);
        xmax[i] = PetscMax(xmax[i], P->xi[3 * o + i]);
      }
    k1                     = 1 + (PetscInt)PetscMax(0, PetscCeilReal((xmax[0] - xmin[0]) / P->D.px - 1.05));
    k2                     = 1 + (PetscInt)PetscMax(0, PetscCeilReal((xmax[1] - xmin[1]) / P->D.py - 1.05));
    const PetscInt ncopies = (2 * k1 + 1) * (2 * k2 + 1);
    PetscCall(PetscMalloc2(3 * N * ncopies * 2, &xih, 3 * N * ncopies * 2, &xo));
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) xih[3 * o + i] = P->xi[3 * o + i];
    PetscCall(HylcMidsurfaceEvaluate(P->ms, N, xih, xo, NULL));
    for (PetscInt o = 0; o < N; o++)
      for (int i = 0; i < 3; i++) {
        blo[i] = PetscMin(blo[i], xo[3 * o + i]);
        bhi[i] = PetscMax(bhi[i], xo[3 * o + i]);
      }
    PetscInt q = 0;
    for (PetscInt s1 = -k1; s1 <= k1; s1++)
      for (PetscInt s2 = -k2; s2 <= k2; s2++) {
        if (!s1 && !s2) continue;
        for (PetscInt o = 0; o < N; o++, q++) {
          const PetscInt w = P->D.next[o];
          xih[6 * q + 0]   = P->xi[3 * o] + s1 * P->D.px;
          xih[6 * q + 1]   = P->xi[3 * o + 1] + s2 * P->D.py;
          xih[6 * q + 2]   = P->xi[3 * o + 2];
          xih[6 * q + 3]   = P->xi[3 * w] + (s1 + P->D.shift[2 * o]) * P->D.px;
          xih[6 * q + 4]   = P->xi[3 * w + 1] + (s2 + P->D.shift[2 * o + 1]) * P->D.py;
          xih[6 * q + 5]   = P->xi[3 * w + 2];
        }
      }
    PetscCall(HylcMidsurfaceEvaluate(P->ms, 2 * q, xih, xo, NULL));
    q = 0;
    for (PetscInt s1 = -k1; s1 <= k1; s1++)
      for (PetscInt s2 = -k2; s2 <= k2; s2++) {
        if (!s1 && !s2) continue;
        for (PetscInt o = 0; o < N; o++, q++) {
          PetscBool near = PETSC_TRUE;
          for (int i = 0; i < 3; i++) {
            const PetscReal a = PetscMin(xo[6 * q + i], xo[6 * q + 3 + i]), b = PetscMax(xo[6 * q + i], xo[6 * q + 3 + i]);
            if (a > bhi[i] + margin || b < blo[i] - margin) near = PETSC_FALSE;
          }
          if (near) {
            PetscInt e;
            PetscCall(FullEdge(P, o, s1, s2, &e));
          }
        }
      }
    PetscCall(PetscFree2(xih, xo));
  }

  /* elimination maps and the initial state */
  PetscCall(PetscMalloc3(9 * P->nfv, &P->T, 3 * P->nfv, &P->d, P->nfv, &P->rigidId));
  PetscCall(PetscMalloc3(4 * N, &P->y, 4 * N, &P->y0, 3 * P->nfv, &P->x));
  PetscCall(PetscMalloc1(3 * P->nfv, &x0));
  {
    PetscReal *xih;
    PetscCall(PetscMalloc1(3 * P->nfv, &xih));
    for (PetscInt k = 0; k < P->nfv; k++) RefPos(P, k, xih + 3 * k);
    PetscCall(HylcMidsurfaceEvaluate(P->ms, P->nfv, xih, x0, NULL));
    for (PetscInt k = 0; k < P->nfv; k++) {
      const PetscInt o = P->fo[k];
      PetscReal     *T = P->T + 9 * k, Ro[9], Rk[9], Tx[3];
      if (k < N) {
        for (int i = 0; i < 9; i++) T[i] = (i % 4 == 0);
        for (int i = 0; i < 3; i++) P->d[3 * k + i] = 0;
        P->rigidId[k] = PETSC_TRUE;
        continue;
      }
      PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, Ro));
      PetscCall(HylcMidsurfaceGetRotation(P->ms, xih + 3 * k, Rk));
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) T[3 * i + j] = Rk[3 * i] * Ro[3 * j] + Rk[3 * i + 1] * Ro[3 * j + 1] + Rk[3 * i + 2] * Ro[3 * j + 2];
      P->rigidId[k] = PETSC_TRUE;
      for (int i = 0; i < 9; i++)
        if (T[i] != (PetscReal)(i % 4 == 0)) P->rigidId[k] = PETSC_FALSE;
      Mat3(T, x0 + 3 * o, Tx);
      for (int i = 0; i < 3; i++) P->d[3 * k + i] = x0[3 * k + i] - Tx[i];
    }
    /* projected reference frames (24): d1 <- normalize((I - t t^T) R(xi_v) d1_pattern) */
    PetscCall(PetscMalloc4(3 * P->nfe, &P->et, 3 * P->nfe, &P->ed1, 3 * P->nfe, &P->et0, 3 * P->nfe, &P->ed10));
    for (PetscInt e = 0; e < P->nfe; e++) {
      const PetscInt k0 = P->esrc[e], k1 = P->ehead[e];
      PetscReal      R[9];
      HylcSub3(x0 + 3 * k1, x0 + 3 * k0, P->et + 3 * e);
      PetscCheck(HylcNormalize3(P->et + 3 * e) > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Zero-length edge in the deformed initial guess");
      PetscCall(HylcMidsurfaceGetRotation(P->ms, xih + 3 * k0, R));
      Mat3(R, P->D.refD1 + 3 * P->fo[k0], P->ed1 + 3 * e);
      PetscCheck(HylcOrthonormalizeDirector(P->et + 3 * e, P->ed1 + 3 * e) > 1e-3, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Projected reference director of edge %" PetscInt_FMT " is parallel to its edge", P->fo[k0]);
    }
    PetscCall(PetscFree(xih));
  }
  PetscCall(PetscMalloc2(P->nbe, &P->mref, P->nbe, &P->mref0));
  for (PetscInt b = 0; b < P->nbe; b++) {
    const BendElem *E = P->be + b;
    P->mref[b]        = HylcAngleNear(HylcReferenceTwist(P->et + 3 * E->e, P->ed1 + 3 * E->e, P->et + 3 * E->f, P->ed1 + 3 * E->f), P->D.refTwist[P->fo[E->v[1]]]);
  }
  for (PetscInt o = 0; o < N; o++) {
    for (int i = 0; i < 3; i++) P->y[4 * o + i] = x0[3 * o + i];
    P->y[4 * o + 3] = P->D.theta[o];
  }
  PetscCall(PetscArraycpy(P->y0, P->y, 4 * N));
  PetscCall(SetUpConstraints(P, x0));
  PetscCall(PetscFree(x0));
  PetscCall(PetscMalloc1(6 * P->nfe, &P->segx));
  P->setup = PETSC_TRUE;
  PetscCall(HylcPeriodicSetState(P, P->y));
  PetscCall(PetscLogEventEnd(HYLC_PeriodicSetUp, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetSizes(HylcPeriodic P, PetscInt *ny, PetscInt *nfull, PetscInt *nedges, PetscInt *ncons)
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  if (ny) *ny = 4 * P->N;
  if (nfull) *nfull = P->nfv;
  if (nedges) *nedges = P->nfe;
  if (ncons) *ncons = P->ncons;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetArea(HylcPeriodic P, PetscReal *A)
{
  PetscFunctionBegin;
  *A = P->D.px * P->D.py;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetConstants(HylcPeriodic P, HylcYarnConstants *c)
{
  PetscFunctionBegin;
  *c = P->c;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetMacroStrain(HylcPeriodic P, const HylcMacroStrain **m)
{
  PetscFunctionBegin;
  PetscCall(HylcMidsurfaceGetStrain(P->ms, m));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetInitialState(HylcPeriodic P, PetscReal y[])
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(PetscArraycpy(y, P->y0, 4 * P->N));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetState - Sets y and computes the full positions q = C y + d. Not collective.
@*/
PetscErrorCode HylcPeriodicSetState(HylcPeriodic P, const PetscReal y[])
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  if (y != P->y) PetscCall(PetscArraycpy(P->y, y, 4 * P->N));
  for (PetscInt k = 0; k < P->nfv; k++) {
    const PetscInt   o  = P->fo[k];
    const PetscReal *xo = P->y + 4 * o;
    if (P->rigidId[k])
      for (int i = 0; i < 3; i++) P->x[3 * k + i] = xo[i] + P->d[3 * k + i];
    else {
      Mat3(P->T + 9 * k, xo, P->x + 3 * k);
      for (int i = 0; i < 3; i++) P->x[3 * k + i] += P->d[3 * k + i];
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetFullPositions(HylcPeriodic P, PetscInt *n, const PetscReal **x, const PetscInt **orig, const PetscInt **shift)
{
  PetscFunctionBegin;
  if (n) *n = P->nfv;
  if (x) *x = P->x;
  if (orig) *orig = P->fo;
  if (shift) *shift = P->fs;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetConstraints(HylcPeriodic P, PetscInt *m, const PetscReal **A, const PetscReal **dL, const PetscReal **AAtinv)
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  if (m) *m = P->ncons;
  if (A) *A = P->A;
  if (dL) *dL = P->dL;
  if (AAtinv) *AAtinv = P->AAtinv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* c = A y - dL */
PetscErrorCode HylcPeriodicConstraintResidual(HylcPeriodic P, const PetscReal y[], PetscReal c[])
{
  PetscFunctionBegin;
  for (PetscInt i = 0; i < P->ncons; i++) {
    PetscReal s = -P->dL[i];
    for (PetscInt k = 0; k < 4 * P->N; k++) s += P->A[i * 4 * P->N + k] * y[k];
    c[i] = s;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicUpdateFrames - Time-parallel transport of every full edge's reference director to its
  current tangent, and reference twists updated on the nearest branch. Not collective.
@*/
PetscErrorCode HylcPeriodicUpdateFrames(HylcPeriodic P)
{
  PetscFunctionBegin;
  for (PetscInt e = 0; e < P->nfe; e++) {
    PetscReal tn[3];
    HylcSub3(P->x + 3 * P->ehead[e], P->x + 3 * P->esrc[e], tn);
    PetscCheck(HylcNormalize3(tn) > 0, PETSC_COMM_SELF, PETSC_ERR_FP, "Zero-length edge");
    HylcParallelTransport(P->et + 3 * e, tn, P->ed1 + 3 * e, P->ed1 + 3 * e);
    HylcOrthonormalizeDirector(tn, P->ed1 + 3 * e);
    for (int i = 0; i < 3; i++) P->et[3 * e + i] = tn[i];
  }
  for (PetscInt b = 0; b < P->nbe; b++) {
    const BendElem *E = P->be + b;
    P->mref[b]        = HylcAngleNear(HylcReferenceTwist(P->et + 3 * E->e, P->ed1 + 3 * E->e, P->et + 3 * E->f, P->ed1 + 3 * E->f), P->mref[b]);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicSaveFrames(HylcPeriodic P)
{
  PetscFunctionBegin;
  PetscCall(PetscArraycpy(P->et0, P->et, 3 * P->nfe));
  PetscCall(PetscArraycpy(P->ed10, P->ed1, 3 * P->nfe));
  PetscCall(PetscArraycpy(P->mref0, P->mref, P->nbe));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicRestoreFrames(HylcPeriodic P)
{
  PetscFunctionBegin;
  PetscCall(PetscArraycpy(P->et, P->et0, 3 * P->nfe));
  PetscCall(PetscArraycpy(P->ed1, P->ed10, 3 * P->nfe));
  PetscCall(PetscArraycpy(P->mref, P->mref0, P->nbe));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* contact pairs among the full edges: broadphase with boxes inflated by pairMargin r (candidates for
   the Hessian's structure), zero-weight pairs pruned, same-yarn pairs excluded; the pairs that can touch
   are those whose boxes inflated by r overlap */
static PetscErrorCode PushPair(PetscInt *n, PetscInt *cap, PetscInt **pairs, PetscReal **w, PetscInt i, PetscInt j, PetscReal wt)
{
  PetscFunctionBegin;
  if (*n == *cap) {
    PetscInt  *np;
    PetscReal *nw;
    *cap = *cap ? 2 * *cap : 256;
    PetscCall(PetscMalloc2(2 * *cap, &np, *cap, &nw));
    PetscCall(PetscArraycpy(np, *pairs, 2 * *n));
    PetscCall(PetscArraycpy(nw, *w, *n));
    PetscCall(PetscFree2(*pairs, *w));
    *pairs = np;
    *w     = nw;
  }
  (*pairs)[2 * *n]     = i;
  (*pairs)[2 * *n + 1] = j;
  (*w)[(*n)++]         = wt;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static inline PetscBool BoxesOverlap(const double *a, const double *b, PetscReal m)
{
  for (int d = 0; d < 3; d++) {
    const double alo = PetscMin(a[d], a[3 + d]) - m, ahi = PetscMax(a[d], a[3 + d]) + m;
    const double blo = PetscMin(b[d], b[3 + d]) - m, bhi = PetscMax(b[d], b[3 + d]) + m;
    if (alo > bhi || blo > ahi) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

static PetscErrorCode FindPairs(HylcPeriodic P)
{
  PetscFunctionBegin;
  PetscCall(PetscLogEventBegin(HYLC_TileBroadphase, 0, 0, 0, 0));
  for (PetscInt e = 0; e < P->nfe; e++)
    for (int i = 0; i < 3; i++) {
      P->segx[6 * e + i]     = P->x[3 * P->esrc[e] + i];
      P->segx[6 * e + 3 + i] = P->x[3 * P->ehead[e] + i];
    }
  if (!P->bvh) {
    PetscCheck(!HylcBVHCreate((int)P->nfe, &P->bvh), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot create the broadphase");
    PetscCheck(!HylcBVHBuild(P->bvh, P->segx, NULL, P->pairMargin * P->c.r), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot build the broadphase");
    PetscCheck(!HylcBVHSetGhost(P->bvh, P->eghost), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot set ghost flags");
  } else
    PetscCheck(!HylcBVHRefit(P->bvh, P->segx, NULL), PETSC_COMM_SELF, PETSC_ERR_MEM, "Cannot refit the broadphase");
  PetscCheck(!HylcBVHQuery(P->bvh, &P->cand), PETSC_COMM_SELF, PETSC_ERR_MEM, "Broadphase query failed");
  HylcPairListSort(&P->cand);
  P->npairs = P->ncand = 0;
  for (size_t c = 0; c < P->cand.n; c++) {
    const PetscInt i = P->cand.idx[2 * c], j = P->cand.idx[2 * c + 1];
    const PetscInt ki = P->esrc[i], kj = P->esrc[j];
    const PetscInt s[2] = {P->fs[2 * kj] - P->fs[2 * ki], P->fs[2 * kj + 1] - P->fs[2 * ki + 1]};
    PetscBool      excl;
    PetscCall(HylcPatternIsExcludedPair(P->pat, P->model.excludeArc, P->fo[ki], P->fo[kj], s, &excl));
    if (excl) continue;
    const PetscInt nor = (P->esrc[i] < P->N) + (P->ehead[i] < P->N) + (P->esrc[j] < P->N) + (P->ehead[j] < P->N);
    if (!nor) continue;
    PetscCall(PushPair(&P->ncand, &P->capcand, &P->cpairs, &P->cw, i, j, nor / 4.0));
    if (BoxesOverlap(P->segx + 6 * i, P->segx + 6 * j, P->c.r)) PetscCall(PushPair(&P->npairs, &P->cappairs, &P->pairs, &P->pw, i, j, nor / 4.0));
  }
  PetscCall(PetscLogEventEnd(HYLC_TileBroadphase, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicGetNumContactPairs(HylcPeriodic P, PetscInt *n)
{
  PetscFunctionBegin;
  PetscCall(FindPairs(P));
  *n = P->npairs;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* local element layout: a list of "slots", each a full vertex position (3 dofs) or a twist (1 dof) */
typedef struct {
  PetscInt n;       /* number of local dofs */
  PetscInt vert[4]; /* full vertex of each position slot (-1 none) */
  PetscInt pos[4];  /* local offset of each position slot */
  PetscInt npos;
  PetscInt twist[2]; /* local offset of twist dofs and their original vertex */
  PetscInt two[2];
  PetscInt ntw;
} Layout;

static void LayoutDofs(const HylcPeriodic P, const Layout *L, PetscInt idx[])
{
  for (PetscInt a = 0; a < L->npos; a++)
    for (int i = 0; i < 3; i++) idx[L->pos[a] + i] = 4 * P->fo[L->vert[a]] + i;
  for (PetscInt a = 0; a < L->ntw; a++) idx[L->twist[a]] = 4 * L->two[a] + 3;
}

/* g_loc <- B^T g_loc and H_loc <- B^T H_loc B for the rotation blocks T of the position slots */
static void Reduce(const HylcPeriodic P, const Layout *L, double g[], double H[])
{
  const PetscInt n = L->n;
  for (PetscInt a = 0; a < L->npos; a++) {
    const PetscInt k = L->vert[a], o = L->pos[a];
    if (P->rigidId[k]) continue;
    const PetscReal *T = P->T + 9 * k;
    if (g) {
      PetscReal t[3];
      MatT3(T, g + o, t);
      for (int i = 0; i < 3; i++) g[o + i] = t[i];
    }
    if (H) {
      /* rows: H[o+i, :] <- sum_m T[m, i] H[o+m, :]; columns likewise */
      for (PetscInt c = 0; c < n; c++) {
        PetscReal t[3];
        for (int i = 0; i < 3; i++) t[i] = T[i] * H[(o + 0) * n + c] + T[3 + i] * H[(o + 1) * n + c] + T[6 + i] * H[(o + 2) * n + c];
        for (int i = 0; i < 3; i++) H[(o + i) * n + c] = t[i];
      }
      for (PetscInt r = 0; r < n; r++) {
        PetscReal t[3];
        for (int i = 0; i < 3; i++) t[i] = H[r * n + o] * T[i] + H[r * n + o + 1] * T[3 + i] + H[r * n + o + 2] * T[6 + i];
        for (int i = 0; i < 3; i++) H[r * n + o + i] = t[i];
      }
    }
  }
}

static void StretchLayout(const HylcPeriodic P, PetscInt e, Layout *L)
{
  L->n       = 6;
  L->npos    = 2;
  L->vert[0] = P->esrc[e];
  L->vert[1] = P->ehead[e];
  L->pos[0]  = 0;
  L->pos[1]  = 3;
  L->ntw     = 0;
}
static void BendLayout(const HylcPeriodic P, const BendElem *E, Layout *L)
{
  L->n        = 11;
  L->npos     = 3;
  L->vert[0]  = E->v[0];
  L->vert[1]  = E->v[1];
  L->vert[2]  = E->v[2];
  L->pos[0]   = 0;
  L->pos[1]   = 4;
  L->pos[2]   = 8;
  L->ntw      = 2;
  L->twist[0] = 3;
  L->twist[1] = 7;
  L->two[0]   = P->fo[E->v[0]];
  L->two[1]   = P->fo[E->v[1]];
}
static void ContactLayout(const HylcPeriodic P, PetscInt i, PetscInt j, Layout *L)
{
  L->n       = 12;
  L->npos    = 4;
  L->vert[0] = P->esrc[i];
  L->vert[1] = P->ehead[i];
  L->vert[2] = P->esrc[j];
  L->vert[3] = P->ehead[j];
  for (int a = 0; a < 4; a++) L->pos[a] = 3 * a;
  L->ntw = 0;
}

PetscErrorCode HylcPeriodicCreateMatrix(HylcPeriodic P, Mat *H)
{
  PetscFunctionBegin;
  PetscCall(MatCreate(PETSC_COMM_SELF, H));
  PetscCall(MatSetSizes(*H, 4 * P->N, 4 * P->N, 4 * P->N, 4 * P->N));
  PetscCall(MatSetType(*H, MATSEQAIJ));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* is every touching pair in the COO structure? (both lists sorted lexicographically) */
static PetscBool PairsCovered(const HylcPeriodic P)
{
  PetscInt a = 0;
  for (PetscInt p = 0; p < P->npairs; p++) {
    const PetscInt i = P->pairs[2 * p], j = P->pairs[2 * p + 1];
    while (a < P->coonpairs && (P->coopairs[2 * a] < i || (P->coopairs[2 * a] == i && P->coopairs[2 * a + 1] < j))) a++;
    if (a == P->coonpairs || P->coopairs[2 * a] != i || P->coopairs[2 * a + 1] != j) return PETSC_FALSE;
  }
  return PETSC_TRUE;
}

/* Visits the elements in the order of the assembled values: stretch elements, bend-twist elements, then
   the pairs of the structure; returns the global dofs of element k in idx and its size in n. */
static PetscInt NumStructElements(const HylcPeriodic P) { return P->nfe + P->nbe + P->coonpairs; }
static void     StructElementDofs(const HylcPeriodic P, PetscInt k, PetscInt idx[12], PetscInt *n)
{
  Layout L;
  if (k < P->nfe) {
    StretchLayout(P, k, &L);
    if (P->sw[k] == 0) L.n = 0; /* no original vertex: not assembled */
  } else if (k < P->nfe + P->nbe)
    BendLayout(P, P->be + (k - P->nfe), &L);
  else {
    const PetscInt p = k - P->nfe - P->nbe;
    ContactLayout(P, P->coopairs[2 * p], P->coopairs[2 * p + 1], &L);
  }
  if (L.n) LayoutDofs(P, &L, idx);
  *n = L.n;
}

/* The structure of H_y: stencils plus a superset of the touching contact pairs, as 4x4 blocks of coupled
   vertices in a CSR matrix, and the position in its value array of every element-matrix entry. It is
   rebuilt only when a touching pair falls outside it; the matrix's nonzero pattern, hence the symbolic
   factorization, is then reused. (This replaces MatSetPreallocationCOO, whose sort of all element entries
   cost as much as ten evaluations.) The rows are built one vertex at a time from the elements incident to
   it, so every lookup of a neighbour block is O(1). */
static PetscErrorCode SetCOO(HylcPeriodic P, Mat H)
{
  const PetscInt  N = P->N;
  PetscInt       *doff, *dof, *koff, *sel, *istart, *inc, *start, *nbr, *mark, *where, *vpos, maxdeg = 0;
  unsigned short *mask;

  PetscFunctionBegin;
  if (H == P->cooMat && PairsCovered(P)) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscFree2(P->coopairs, P->coopw));
  PetscCall(PetscMalloc2(2 * P->ncand + 1, &P->coopairs, P->ncand + 1, &P->coopw));
  PetscCall(PetscArraycpy(P->coopairs, P->cpairs, 2 * P->ncand));
  PetscCall(PetscArraycpy(P->coopw, P->cw, P->ncand));
  P->coonpairs        = P->ncand;
  const PetscInt nent = P->nfe * 36 + P->nbe * 121 + P->coonpairs * 144, nel = NumStructElements(P);
  if (nent > P->capcoo) {
    PetscCall(PetscFree2(P->coopos, P->coov));
    P->capcoo = nent + nent / 4;
    PetscCall(PetscMalloc2(P->capcoo, &P->coopos, P->capcoo, &P->coov));
  }
  /* the dofs of every element (dof[doff[e] + p], p < n), and the offset koff[e] of its first entry in the
     element order of coopos: entry (p, q) of element e is coopos[koff[e] + p n + q] */
  PetscCall(PetscMalloc3(nel + 1, &doff, 12 * nel + 1, &dof, nel + 1, &koff));
  doff[0] = koff[0] = 0;
  for (PetscInt e = 0; e < nel; e++) {
    PetscInt n;
    StructElementDofs(P, e, dof + doff[e], &n);
    doff[e + 1] = doff[e] + n;
    koff[e + 1] = koff[e] + n * n;
  }
  const PetscInt ndof = doff[nel], ncoo = koff[nel];
  /* incidence: the element dof slots s (index into dof) of every vertex a, inc[istart[a] .. istart[a+1]),
     and the element sel[s] of each slot */
  PetscCall(PetscMalloc2(ndof + 1, &sel, ndof + 1, &inc));
  PetscCall(PetscCalloc2(N + 1, &istart, N + 1, &start));
  for (PetscInt e = 0; e < nel; e++)
    for (PetscInt s = doff[e]; s < doff[e + 1]; s++) {
      sel[s] = e;
      istart[dof[s] / 4 + 1]++;
    }
  for (PetscInt a = 0; a < N; a++) istart[a + 1] += istart[a];
  for (PetscInt s = 0; s < ndof; s++) inc[istart[dof[s] / 4]++] = s;
  for (PetscInt a = N; a > 0; a--) istart[a] = istart[a - 1];
  istart[0] = 0;
  /* vertex adjacency, the sorted neighbours nbr[start[a] .. start[a+1]) of each vertex (distinct via the
     marker mark[b] == a; where[b] is b's position in the row being built), and which of the 16 entries of
     each vertex block are used (positions do not couple with twists in stretch and contact elements): a
     16-bit mask per block. A row has at most its incident entries as neighbours, hence the bound ncoo. */
  PetscCall(PetscMalloc4(ncoo + 1, &nbr, ncoo + 1, &mask, N, &mark, N, &where));
  for (PetscInt b = 0; b < N; b++) mark[b] = -1;
  for (PetscInt a = 0; a < N; a++) {
    PetscInt *row = nbr + start[a], m = 0;
    for (PetscInt t = istart[a]; t < istart[a + 1]; t++) {
      const PetscInt e = sel[inc[t]];
      for (PetscInt s = doff[e]; s < doff[e + 1]; s++) {
        const PetscInt b = dof[s] / 4;
        if (mark[b] != a) {
          mark[b]  = a;
          row[m++] = b;
        }
      }
    }
    PetscCall(PetscSortInt(m, row));
    start[a + 1] = start[a] + m;
    maxdeg       = PetscMax(maxdeg, m);
    for (PetscInt q = 0; q < m; q++) {
      where[row[q]]      = q;
      mask[start[a] + q] = 0;
    }
    for (PetscInt t = istart[a]; t < istart[a + 1]; t++) {
      const PetscInt sp = inc[t], e = sel[sp], i = dof[sp] % 4; /* the slot sp is row 4a + i of element e */
      for (PetscInt s = doff[e]; s < doff[e + 1]; s++) mask[start[a] + where[dof[s] / 4]] |= (unsigned short)(1u << (4 * i + dof[s] % 4));
    }
  }
  /* CSR of the scalar rows: row 4a + i has, for every neighbour block, the columns its mask uses, entry
     (i, j) of the row's block q at the position vpos[16q + 4i + j] of the CSR values; then where each
     element entry of row vertex a goes */
  PetscCall(PetscFree2(P->rowptr, P->colind));
  PetscInt nnz = 0;
  for (PetscInt q = 0; q < start[N]; q++) nnz += __builtin_popcount(mask[q]);
  PetscCall(PetscMalloc2(4 * N + 1, &P->rowptr, nnz + 1, &P->colind));
  PetscCall(PetscMalloc1(16 * maxdeg + 1, &vpos));
  P->rowptr[0] = 0;
  for (PetscInt a = 0; a < N; a++) {
    const PetscInt        deg = start[a + 1] - start[a], *row = nbr + start[a];
    const unsigned short *rmask = mask + start[a];
    for (PetscInt i = 0; i < 4; i++) {
      const PetscInt r = 4 * a + i;
      PetscInt       c = P->rowptr[r];
      for (PetscInt q = 0; q < deg; q++) {
        for (PetscInt j = 0; j < 4; j++)
          if (rmask[q] & (1u << (4 * i + j))) {
            vpos[16 * q + 4 * i + j] = c;
            P->colind[c++]           = 4 * row[q] + j;
          }
      }
      P->rowptr[r + 1] = c;
    }
    for (PetscInt q = 0; q < deg; q++) where[row[q]] = q;
    for (PetscInt t = istart[a]; t < istart[a + 1]; t++) {
      const PetscInt sp = inc[t], e = sel[sp], n = doff[e + 1] - doff[e], i = dof[sp] % 4;
      PetscInt       k = koff[e] + (sp - doff[e]) * n;
      for (PetscInt s = doff[e]; s < doff[e + 1]; s++, k++) P->coopos[k] = vpos[16 * where[dof[s] / 4] + 4 * i + dof[s] % 4];
    }
  }
  P->nnz  = nnz;
  P->ncoo = ncoo;
  PetscCall(PetscFree(vpos));
  PetscCall(PetscFree4(nbr, mask, mark, where));
  PetscCall(PetscFree2(istart, start));
  PetscCall(PetscFree2(sel, inc));
  PetscCall(PetscFree3(doff, dof, koff));
  PetscCall(MatSeqAIJSetPreallocationCSR(H, P->rowptr, P->colind, NULL));
  P->cooMat = H;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* accumulate a reduced element gradient and Hessian */
static inline void Scatter(const HylcPeriodic P, const Layout *L, double ge[], double He[], PetscReal gy[], PetscScalar *hv)
{
  PetscInt idx[12];
  Reduce(P, L, gy ? ge : NULL, hv ? He : NULL);
  if (gy) {
    LayoutDofs(P, L, idx);
    for (PetscInt i = 0; i < L->n; i++) gy[idx[i]] += ge[i];
  }
  if (hv)
    for (PetscInt i = 0; i < L->n * L->n; i++) hv[i] = He[i];
}

/* the evaluation; a degenerate element or a non-finite energy is no error: *bad = 1 (zero-length edge at
   original vertex *badv), 2 (degenerate bending element at *badv) or 3 (non-finite energy), parts = +inf */
static PetscErrorCode PeriodicEvaluate(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], Mat H, int *bad, PetscInt *badv)
{
  PetscReal    E[4] = {0, 0, 0, 0};
  double       x[12], ge[12], He[144];
  Layout       L;
  PetscScalar *hv;
  PetscInt     k = 0;

  PetscFunctionBegin;
  *bad  = 0;
  *badv = -1;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscLogDouble t0, t1, tc0, tc1;
  PetscCall(PetscLogEventBegin(HYLC_PeriodicEvaluate, 0, 0, 0, 0));
  PetscCall(PetscTime(&t0));
  if (gy) PetscCall(PetscArrayzero(gy, 4 * P->N));
  if (mask & HYLC_TERM_CONTACT)
    PetscCall(FindPairs(P));
  else
    P->npairs = 0;
  if (H) PetscCall(SetCOO(P, H));
  hv = H ? P->coov : NULL;
  for (PetscInt e = 0; e < P->nfe; e++) {
    if (P->sw[e] == 0) continue;
    StretchLayout(P, e, &L);
    for (int i = 0; i < 3; i++) {
      x[i]     = P->x[3 * P->esrc[e] + i];
      x[3 + i] = P->x[3 * P->ehead[e] + i];
    }
    if (mask & HYLC_TERM_STRETCH) {
      double en;
      if (HylcRodStretch(x, P->D.restLength[P->fo[P->esrc[e]]], P->c.ks, P->sw[e], &en, gy ? ge : NULL, H ? He : NULL)) {
        *bad  = 1;
        *badv = P->fo[P->esrc[e]];
        break;
      }
      E[0] += en;
      Scatter(P, &L, ge, He, gy, hv ? hv + k : NULL);
    } else if (hv)
      for (int i = 0; i < 36; i++) hv[k + i] = 0;
    k += 36;
  }
  const int bt = ((mask & HYLC_TERM_BEND) ? HYLC_ROD_BEND : 0) | ((mask & HYLC_TERM_TWIST) ? HYLC_ROD_TWIST : 0);
  for (PetscInt b = 0; b < P->nbe && !*bad; b++) {
    const BendElem     *B  = P->be + b;
    const PetscInt      oc = P->fo[B->v[1]], ou = P->fo[B->v[0]];
    HylcRodBendTwistRef ref;
    double              en[2];
    BendLayout(P, B, &L);
    for (int i = 0; i < 3; i++) {
      x[i]       = P->x[3 * B->v[0] + i];
      x[4 + i]   = P->x[3 * B->v[1] + i];
      x[8 + i]   = P->x[3 * B->v[2] + i];
      ref.te[i]  = P->et[3 * B->e + i];
      ref.d1e[i] = P->ed1[3 * B->e + i];
      ref.tf[i]  = P->et[3 * B->f + i];
      ref.d1f[i] = P->ed1[3 * B->f + i];
    }
    x[3]          = P->y[4 * ou + 3];
    x[7]          = P->y[4 * oc + 3];
    ref.mref      = P->mref[b];
    ref.kappa0[0] = ref.kappa0[2] = P->D.restKappa[2 * oc];
    ref.kappa0[1] = ref.kappa0[3] = P->D.restKappa[2 * oc + 1];
    ref.tau0                      = P->D.restTwist[oc];
    ref.lbar                      = 0.5 * (P->D.restLength[ou] + P->D.restLength[oc]);
    if (bt) {
      const int err = (gy || H) ? HylcRodBendTwist(x, &ref, &P->btpar, B->w, bt, en, gy ? ge : NULL, H ? He : NULL) : HylcRodBendTwistEnergy(x, &ref, &P->btpar, B->w, en);
      if (err) {
        *bad  = 2;
        *badv = oc;
        break;
      }
      if (mask & HYLC_TERM_BEND) E[1] += en[0];
      if (mask & HYLC_TERM_TWIST) E[2] += en[1];
      Scatter(P, &L, ge, He, gy, hv ? hv + k : NULL);
    } else if (hv)
      for (int i = 0; i < 121; i++) hv[k + i] = 0;
    k += 121;
  }
  PetscCall(PetscLogEventBegin(HYLC_TileContact, 0, 0, 0, 0));
  PetscCall(PetscTime(&tc0));
  const PetscInt   np = *bad ? 0 : H ? P->coonpairs
                                     : P->npairs; /* with a Hessian: every pair of its structure (the others give 0) */
  const PetscInt  *pl = H ? P->coopairs : P->pairs;
  const PetscReal *pw = H ? P->coopw : P->pw;
  for (PetscInt p = 0; p < np; p++) {
    const PetscInt i = pl[2 * p], j = pl[2 * p + 1];
    double         en;
    ContactLayout(P, i, j, &L);
    for (int a = 0; a < 4; a++)
      for (int c = 0; c < 3; c++) x[3 * a + c] = P->x[3 * L.vert[a] + c];
    const PetscReal la = P->D.restLength[P->fo[P->esrc[i]]], lb = P->D.restLength[P->fo[P->esrc[j]]];
    if (P->model.contactType == HYLC_CONTACT_QUADRATURE)
      en = HylcContactQuadrature(x, x + 3, x + 6, x + 9, la, lb, P->c.kc, P->c.r, (int)P->model.contactPoints, pw[p], gy ? ge : NULL, H ? He : NULL);
    else
      en = HylcContactClosestPoint(x, x + 3, x + 6, x + 9, la, lb, P->c.kc, P->c.r, pw[p], gy ? ge : NULL, H ? He : NULL, NULL, NULL, NULL);
    E[3] += en;
    Scatter(P, &L, ge, He, gy, hv ? hv + k : NULL);
    k += 144;
  }
  PetscCall(PetscTime(&tc1));
  P->tContact += tc1 - tc0;
  PetscCall(PetscLogEventEnd(HYLC_TileContact, 0, 0, 0, 0));
  if (H && !*bad) {
    PetscCall(PetscLogEventBegin(HYLC_TileAssemble, 0, 0, 0, 0));
    PetscCall(PetscTime(&tc0));
    PetscScalar *v;
    PetscCall(MatSeqAIJGetArray(H, &v));
    PetscCall(PetscArrayzero(v, P->nnz));
    for (PetscInt q = 0; q < P->ncoo; q++) v[P->coopos[q]] += P->coov[q];
    PetscCall(MatSeqAIJRestoreArray(H, &v));
    PetscCall(PetscTime(&tc1));
    P->tAssemble += tc1 - tc0;
    PetscCall(PetscLogEventEnd(HYLC_TileAssemble, 0, 0, 0, 0));
  }
  PetscCall(PetscTime(&t1));
  P->tEval += t1 - t0;
  if (!*bad && !(PetscIsNormalReal(E[0] + E[1] + E[2] + E[3]) || E[0] + E[1] + E[2] + E[3] == 0)) *bad = 3;
  for (int i = 0; i < 4; i++) parts[i] = *bad == 1 || *bad == 2 ? PETSC_INFINITY : E[i];
  PetscCall(PetscLogEventEnd(HYLC_PeriodicEvaluate, 0, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicEvaluate - Energy of the current state (parts: stretch, bend, twist, contact, for the terms
  in mask), and optionally the reduced gradient g_y (4 per original vertex, overwritten) and reduced
  Hessian H_y (from HylcPeriodicCreateMatrix(), overwritten). A degenerate geometry or a non-finite energy is a PETSC_ERR_FP error
  (see HylcPeriodicEvaluateFinite()). Not collective.
@*/
PetscErrorCode HylcPeriodicEvaluate(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], Mat H)
{
  int      bad;
  PetscInt v;

  PetscFunctionBegin;
  PetscCall(PeriodicEvaluate(P, mask, parts, gy, H, &bad, &v));
  PetscCheck(bad != 1, PETSC_COMM_SELF, PETSC_ERR_FP, "Zero-length edge at vertex %" PetscInt_FMT, v);
  PetscCheck(bad != 2, PETSC_COMM_SELF, PETSC_ERR_FP, "Bending element at vertex %" PetscInt_FMT " is degenerate", v);
  PetscCheck(bad != 3, PETSC_COMM_SELF, PETSC_ERR_FP, "Energy is not finite: stretch %g, bend %g, twist %g, contact %g", (double)parts[0], (double)parts[1], (double)parts[2], (double)parts[3]);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicEvaluateFinite - HylcPeriodicEvaluate() for a solver's trial states: a degenerate geometry
  (a zero-length edge, a degenerate bending element) or a non-finite energy is a result, not an error:
  *finite = PETSC_FALSE and the energy counts as +inf (gy and H are then undefined). Any other failure
  is an error. Not collective.
@*/
PetscErrorCode HylcPeriodicEvaluateFinite(HylcPeriodic P, int mask, PetscReal parts[4], PetscReal gy[], Mat H, PetscBool *finite)
{
  int      bad;
  PetscInt v;

  PetscFunctionBegin;
  PetscCall(PeriodicEvaluate(P, mask, parts, gy, H, &bad, &v));
  *finite = (PetscBool)!bad;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetTimes - Wall time (s) accumulated since the last set-up in evaluations (all), in contact
  (broadphase and pair kernels) and in assembling Hessians. Not collective.
@*/
PetscErrorCode HylcPeriodicGetTimes(HylcPeriodic P, PetscLogDouble *eval, PetscLogDouble *contact, PetscLogDouble *assemble)
{
  PetscFunctionBegin;
  if (eval) *eval = P->tEval;
  if (contact) *contact = P->tContact;
  if (assemble) *assemble = P->tAssemble;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicView(HylcPeriodic P, PetscViewer viewer)
{
  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCall(PetscViewerASCIIPrintf(viewer, "periodic tile: strain (%g, %g, %g, %g, %g, %g); %" PetscInt_FMT " original and %" PetscInt_FMT " ghost vertices, %" PetscInt_FMT " edges, %" PetscInt_FMT " bend-twist elements, %" PetscInt_FMT " constraints (slide %s; %" PetscInt_FMT " linearly dependent rows dropped)\n", (double)P->z[0], (double)P->z[1], (double)P->z[2], (double)P->z[3], (double)P->z[4], (double)P->z[5], P->N, P->nfv - P->N, P->nfe, P->nbe, P->ncons, HylcSlideConstraints[P->slide], P->ndropped));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicCreateStatePattern - The current state as a new pattern: positions and twists of the
  originals, the current reference directors and reference twists, the same rest data, and the periods
  of the deformed lattice ((1 + sx) px, (1 + sy) py). Only for strains whose periodic images are
  translations along x and y (sa = 0 and II = 0). Collective on PETSC_COMM_SELF.
@*/
PetscErrorCode HylcPeriodicCreateStatePattern(HylcPeriodic P, HylcPattern *out)
{
  const PetscInt N = P->N;
  PetscReal     *X, *th, *D1, *RefT;

  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCheck(P->z[1] == 0 && P->z[3] == 0 && P->z[4] == 0 && P->z[5] == 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "A deformed tile is a .pyp pattern only without shear and bending (sa = II = 0); use VTK output instead");
  PetscCall(PetscMalloc4(3 * N, &X, N, &th, 3 * N, &D1, N, &RefT));
  for (PetscInt o = 0; o < N; o++) {
    PetscInt e, b = -1;
    for (int i = 0; i < 3; i++) X[3 * o + i] = P->y[4 * o + i];
    th[o] = P->y[4 * o + 3];
    PetscCall(PetscHMapIGet(P->emap, Key(N, o, 0, 0), &e));
    for (int i = 0; i < 3; i++) D1[3 * o + i] = P->ed1[3 * e + i];
    for (PetscInt k = 0; k < P->nbe && b < 0; k++)
      if (P->be[k].v[1] == o) b = k;
    RefT[o] = P->mref[b];
  }
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, out));
  PetscCall(HylcPatternSetData(*out, N, (1 + P->z[0]) * P->D.px, (1 + P->z[2]) * P->D.py, P->D.radius, X, th, P->D.next, P->D.shift, P->D.restLength, P->D.restKappa, P->D.restTwist, D1, RefT));
  PetscCall(PetscFree4(X, th, D1, RefT));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicWriteVTK - Writes the current state repeated ntx x nty times (centred on the tile) as
  legacy-VTK polylines, one per yarn loop and copy; copies are placed by the co-rotated periodic map
  x = T x_o + d (bent tiles come out bent). Not collective.
@*/
PetscErrorCode HylcPeriodicWriteVTK(HylcPeriodic P, const char fname[], PetscInt ntx, PetscInt nty)
{
  PetscInt   nloops, npts = 0, nlines;
  PetscReal *xih, *x0, *xs;
  FILE      *fp;

  PetscFunctionBegin;
  PetscCheck(P->setup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcPeriodicSetUp() first");
  PetscCheck(ntx >= 1 && nty >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "VTK tiling must be at least 1x1");
  PetscCall(HylcPatternGetNumLoops(P->pat, &nloops));
  nlines = nloops * ntx * nty;
  npts   = (P->N + nloops) * ntx * nty;
  PetscCall(PetscMalloc3(3 * npts, &xih, 3 * npts, &x0, 3 * npts, &xs));
  /* reference positions of every point, then the map T x_o + d with T = R(xi_o + S) R(xi_o)^T */
  PetscInt q = 0;
  for (PetscInt i = 0; i < ntx; i++)
    for (PetscInt j = 0; j < nty; j++)
      for (PetscInt l = 0; l < nloops; l++) {
        const PetscInt *lv;
        PetscInt        n, s1 = i - ntx / 2, s2 = j - nty / 2;
        PetscCall(HylcPatternGetLoop(P->pat, l, &n, &lv, NULL));
        for (PetscInt k = 0; k <= n; k++, q++) {
          const PetscInt o = lv[k % n];
          xih[3 * q]       = P->xi[3 * o] + s1 * P->D.px;
          xih[3 * q + 1]   = P->xi[3 * o + 1] + s2 * P->D.py;
          xih[3 * q + 2]   = P->xi[3 * o + 2];
          s1 += P->D.shift[2 * o];
          s2 += P->D.shift[2 * o + 1];
        }
      }
  PetscCall(HylcMidsurfaceEvaluate(P->ms, npts, xih, xs, NULL));
  q = 0;
  for (PetscInt i = 0; i < ntx; i++)
    for (PetscInt j = 0; j < nty; j++)
      for (PetscInt l = 0; l < nloops; l++) {
        const PetscInt *lv;
        PetscInt        n;
        PetscCall(HylcPatternGetLoop(P->pat, l, &n, &lv, NULL));
        for (PetscInt k = 0; k <= n; k++, q++) {
          const PetscInt o = lv[k % n];
          PetscReal      Ro[9], Rs[9], T[9], xo0[3], Tx[3], Tu[3], u[3];
          PetscCall(HylcMidsurfaceGetRotation(P->ms, P->xi + 3 * o, Ro));
          PetscCall(HylcMidsurfaceGetRotation(P->ms, xih + 3 * q, Rs));
          for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) T[3 * a + b] = Rs[3 * a] * Ro[3 * b] + Rs[3 * a + 1] * Ro[3 * b + 1] + Rs[3 * a + 2] * Ro[3 * b + 2];
          /* x = x0(xi + S) + T (x_o - x0(xi_o)) */
          for (int a = 0; a < 3; a++) xo0[a] = P->y0[4 * o + a];
          for (int a = 0; a < 3; a++) u[a] = P->y[4 * o + a] - xo0[a];
          Mat3(T, u, Tu);
          (void)Tx;
          for (int a = 0; a < 3; a++) x0[3 * q + a] = xs[3 * q + a] + Tu[a];
        }
      }
  fp = fopen(fname, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write VTK file '%s'", fname);
  fprintf(fp, "# vtk DataFile Version 3.0\nhylc deformed tile (%d x %d copies)\nASCII\nDATASET POLYDATA\n", (int)ntx, (int)nty);
  fprintf(fp, "FIELD FieldData 1\nradius 1 1 double\n%.10g\n", (double)P->c.r);
  fprintf(fp, "POINTS %d double\n", (int)npts);
  for (PetscInt k = 0; k < npts; k++) fprintf(fp, "%.10g %.10g %.10g\n", (double)x0[3 * k], (double)x0[3 * k + 1], (double)x0[3 * k + 2]);
  fprintf(fp, "LINES %d %d\n", (int)nlines, (int)(nlines + npts));
  q = 0;
  for (PetscInt c = 0; c < ntx * nty; c++)
    for (PetscInt l = 0; l < nloops; l++) {
      PetscInt n;
      PetscCall(HylcPatternGetLoop(P->pat, l, &n, NULL, NULL));
      fprintf(fp, "%d", (int)(n + 1));
      for (PetscInt k = 0; k <= n; k++, q++) fprintf(fp, " %d", (int)q);
      fprintf(fp, "\n");
    }
  fprintf(fp, "CELL_DATA %d\nSCALARS loop int 1\nLOOKUP_TABLE default\n", (int)nlines);
  for (PetscInt c = 0; c < ntx * nty; c++)
    for (PetscInt l = 0; l < nloops; l++) fprintf(fp, "%d\n", (int)l);
  const int bad = ferror(fp);
  PetscCheck(fclose(fp) == 0 && !bad, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write VTK file '%s'", fname);
  PetscCall(PetscFree3(xih, x0, xs));
  PetscFunctionReturn(PETSC_SUCCESS);
}
