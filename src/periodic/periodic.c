/* HylcPeriodic: lifecycle, options, setters, CheckStrain, GetTimes, View (include/hylc/periodic.h). */
#include <hylc/options.h>
#include "periodicimpl.h"

const char *const HylcSlideConstraints[] = {"none", "global", "per_yarn", "per_family", "HylcSlideConstraint", "HYLC_SLIDE_", NULL};

PetscClassId  HYLC_PERIODIC_CLASSID;
PetscLogEvent HYLC_PeriodicSetUp, HYLC_PeriodicEvaluate, HYLC_TileBroadphase, HYLC_TileContact, HYLC_TileAssemble, HYLC_TileEvaluate;

static PetscBool HylcPeriodicPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcPeriodicFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcPeriodicPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicInitializePackage - Registers the class id HylcPeriodic and its log events (PERIODIC_SetUp, PERIODIC_Evaluate, CONTACT_Broadphase, CONTACT_Energy, PERIODIC_Assemble, TILE_Evaluate). Called by
  HylcPeriodicCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcPeriodicInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcPeriodicPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcPeriodicPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcPeriodic", &HYLC_PERIODIC_CLASSID));
  PetscCall(PetscLogEventRegister("PERIODIC_SetUp", HYLC_PERIODIC_CLASSID, &HYLC_PeriodicSetUp));
  PetscCall(PetscLogEventRegister("PERIODIC_Evaluate", HYLC_PERIODIC_CLASSID, &HYLC_PeriodicEvaluate));
  PetscCall(PetscLogEventRegister("CONTACT_Broadphase", HYLC_PERIODIC_CLASSID, &HYLC_TileBroadphase));
  PetscCall(PetscLogEventRegister("CONTACT_Energy", HYLC_PERIODIC_CLASSID, &HYLC_TileContact));
  PetscCall(PetscLogEventRegister("PERIODIC_Assemble", HYLC_PERIODIC_CLASSID, &HYLC_TileAssemble));
  PetscCall(PetscLogEventRegister("TILE_Evaluate", HYLC_PERIODIC_CLASSID, &HYLC_TileEvaluate));
  PetscCall(PetscRegisterFinalize(HylcPeriodicFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicCreate - Creates a periodic tile: slide constraint global, contact-ghost margin 0.25, pair
  margin 1.05, constraint tolerance 1e-6, options prefix none (options -periodic_*). Give it a pattern
  with HylcPeriodicSetPattern() before HylcPeriodicSetUp().

  Collective

  Input Parameter:
. comm - the communicator (the tile lives on one rank: PETSC_COMM_SELF)

  Output Parameter:
. per - the new object

  Level: beginner

.seealso: HylcPeriodicSetPattern(), HylcPeriodicSetFromOptions(), HylcPeriodicSetUp(), HylcPeriodicDestroy()
@*/
PetscErrorCode HylcPeriodicCreate(MPI_Comm comm, HylcPeriodic *per)
{
  HylcPeriodic P;

  PetscFunctionBegin;
  PetscValidPointer(per, 2);
  *per = NULL;
  PetscCall(HylcPeriodicInitializePackage());
  PetscCall(PetscHeaderCreate(P, HYLC_PERIODIC_CLASSID, "HylcPeriodic", "Periodic yarn tile", "Periodic", comm, HylcPeriodicDestroy, HylcPeriodicView));
  P->slide        = HYLC_SLIDE_GLOBAL;
  P->marginFactor = 0; /* every copy in the neighbouring tiles */
  P->pairMargin   = 1.05;
  P->crtol        = 1e-6;
  PetscCall(HylcMidsurfaceCreate(comm, &P->ms));
  *per = P;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetPattern - Sets the tile's pattern (referenced, not copied) and yarn model (copied).
  Discards a previous set-up.

  Not collective

  Input Parameters:
+ P     - the periodic tile
. pat   - the pattern (set up)
- model - the yarn model

  Level: beginner

.seealso: HylcPeriodicCreate(), HylcPeriodicGetPattern()
@*/
PetscErrorCode HylcPeriodicSetPattern(HylcPeriodic P, HylcPattern pat, const HylcYarnModel *model)
{
  HylcPatternData D;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscValidHeaderSpecific(pat, HYLC_PATTERN_CLASSID, 2);
  PetscValidPointer(model, 3);
  PetscCall(HylcPatternGetData(pat, &D));
  PetscCheck(D.nv * (2 * SMAX + 1) * (2 * SMAX + 1) < PETSC_MAX_INT / 2, PetscObjectComm((PetscObject)P), PETSC_ERR_SUP, "Pattern too large for the ghost index");
  PetscCall(HylcPeriodicReset_Private(P));
  PetscCall(PetscObjectReference((PetscObject)pat));
  PetscCall(HylcPatternDestroy(&P->pat));
  P->pat   = pat;
  P->D     = D;
  P->model = *model;
  PetscCall(HylcYarnModelGetConstants(model, P->D.radius, &P->c));
  P->btpar.B       = P->c.B;
  P->btpar.beta    = P->c.beta;
  P->btpar.variant = model->curvature;
  P->N             = P->D.nv;
  P->viewed        = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetPattern - The tile's pattern (borrowed: do not destroy it), NULL before HylcPeriodicSetPattern().

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameter:
. pat - the pattern

  Level: intermediate

.seealso: HylcPeriodicSetPattern()
@*/
PetscErrorCode HylcPeriodicGetPattern(HylcPeriodic P, HylcPattern *pat)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscValidPointer(pat, 2);
  *pat = P->pat;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPeriodicReset_Private(HylcPeriodic P)
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
  PetscCall(PetscFree(P->crow));
  HylcBVHDestroy(&P->bvh);
  PetscCall(PetscFree(P->segx));
  HylcPairListFree(&P->cand);
  PetscCall(PetscFree2(P->pairs, P->pw));
  PetscCall(PetscFree2(P->cpairs, P->cw));
  P->ncand = P->capcand = 0;
  P->pairsValid         = PETSC_FALSE;
  PetscCall(PetscFree(P->coopos));
  PetscCall(PetscFree2(P->rowptr, P->colind));
  PetscCall(PetscFree2(P->coopairs, P->coopw));
  P->nfv = P->capfv = P->nfe = P->nchain = P->capfe = P->nbe = P->capbe = P->npairs = P->cappairs = P->ncoo = P->capcoo = P->coonpairs = 0;
  P->cooMat                                                                                                                            = NULL;
  P->setup                                                                                                                             = PETSC_FALSE;
  P->tEval = P->tContact = P->tAssemble = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicDestroy - Destroys a periodic tile (drops a reference; frees it with the last one).

  Collective

  Input Parameter:
. per - the object (may be NULL); set to NULL

  Level: beginner

.seealso: HylcPeriodicCreate()
@*/
PetscErrorCode HylcPeriodicDestroy(HylcPeriodic *per)
{
  PetscFunctionBegin;
  if (!*per) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*per, HYLC_PERIODIC_CLASSID, 1);
  if (--((PetscObject)(*per))->refct > 0) {
    *per = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcPeriodicReset_Private(*per));
  PetscCall(HylcMidsurfaceDestroy(&(*per)->ms));
  PetscCall(HylcMidsurfaceDestroy(&(*per)->msfd));
  PetscCall(HylcPatternDestroy(&(*per)->pat));
  PetscCall(PetscHeaderDestroy(per));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetOptionsPrefix - Sets the prefix of the tile's options (-<prefix>periodic_*) and of its
  midsurface's (-<prefix>macro_*).

  Not collective

  Input Parameters:
+ P      - the periodic tile
- prefix - the prefix (NULL: none)

  Level: intermediate

.seealso: HylcPeriodicSetFromOptions()
@*/
PetscErrorCode HylcPeriodicSetOptionsPrefix(HylcPeriodic P, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)P, prefix));
  PetscCall(HylcMidsurfaceSetOptionsPrefix(P->ms, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetFromOptions - Reads the tile's options (and the midsurface's). Only reads options: the
  work is done by HylcPeriodicSetUp().

  Not collective

  Input Parameter:
. P - the periodic tile

  Options Database Keys:
+ -periodic_slide <global>         - slide constraint: none, global (one row), per_yarn (one row per loop),
                                     per_family (one row per yarn family, invariant under mirrors and under
                                     the direction in which a file lists each yarn; docs/method.md) (HylcPeriodicSetSlideConstraint())
. -periodic_margin <0>             - contact ghosts: every copy of a tile edge in the neighbouring tiles (0), or only the copies within
                                     max(3 r, margin min(px, py)) of the tile on the deformed initial guess (HylcPeriodicSetContactMargin())
. -periodic_pair_margin <1.05>     - Hessian structure: keep the segment pairs closer than this many 2 r (HylcPeriodicSetPairMargin())
. -periodic_constraint_rtol <1e-6> - drop a constraint row within this relative distance of the span of the
                                     rows before it (linearly dependent: straight yarns; docs/method.md) (HylcPeriodicSetConstraintTolerance())
. -periodic_view                   - print the tile after each set-up (HylcPeriodicView())
- -macro_*                         - the midsurface (HylcMidsurfaceSetFromOptions())

  Level: beginner

.seealso: HylcPeriodicCreate(), HylcPeriodicSetUp()
@*/
PetscErrorCode HylcPeriodicSetFromOptions(HylcPeriodic P)
{
  PetscEnum sl = (PetscEnum)P->slide;
  PetscReal pairMargin, marginFactor, crtol;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  pairMargin   = P->pairMargin;
  marginFactor = P->marginFactor;
  crtol        = P->crtol;
  PetscObjectOptionsBegin((PetscObject)P);
  PetscCall(HylcOptionsEnum("-periodic_slide", "Slide constraint: none, global (one row), per_yarn (one row per yarn loop) or per_family (one row per yarn family, each yarn in its canonical direction)", "HylcPeriodicSetSlideConstraint",
                            HylcSlideConstraints, sl, &sl, NULL));
  PetscCall(HylcOptionsReal("-periodic_pair_margin", "Hessian structure: keep the segment pairs closer than this many 2 r (touching: 2 r), so that it changes rarely", "HylcPeriodicSetPairMargin", pairMargin, &pairMargin, NULL));
  PetscCall(HylcOptionsReal("-periodic_margin",
                            "Contact ghosts: 0 for every copy of a tile edge in the neighbouring tiles; > 0 for only the copies within max(3 r, margin * min(px, py)) of the tile on the deformed initial guess (misses contacts once yarns move more "
                            "than about (margin - 2 r) / 2)",
                            "HylcPeriodicSetContactMargin", marginFactor, &marginFactor, NULL));
  PetscCall(HylcOptionsReal("-periodic_constraint_rtol", "A constraint row whose distance to the span of the rows before it is at most this times its norm is dropped as linearly dependent (straight yarns: the slide row repeats the translation)",
                            "HylcPeriodicSetConstraintTolerance", crtol, &crtol, NULL));
  PetscCall(PetscOptionsName("-periodic_view", "Print the tile after each set-up", "HylcPeriodicView", NULL));
  PetscOptionsEnd();
  PetscCall(HylcPeriodicSetConstraintTolerance(P, crtol));
  PetscCall(HylcPeriodicSetSlideConstraint(P, (HylcSlideConstraint)sl));
  PetscCall(HylcPeriodicSetPairMargin(P, pairMargin));
  PetscCall(HylcPeriodicSetContactMargin(P, marginFactor));
  PetscCall(HylcMidsurfaceSetFromOptions(P->ms));
  P->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetStrain - Sets the macroscopic strain z = (sx, sa, sy, II00, II01, II11) (II in 1/m);
  the next HylcPeriodicSetUp() builds the tile for it.

  Not collective

  Input Parameters:
+ P - the periodic tile
- z - the strain

  Level: beginner

.seealso: HylcPeriodicCheckStrain(), HylcPeriodicSetUp()
@*/
PetscErrorCode HylcPeriodicSetStrain(HylcPeriodic P, const PetscReal z[6])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  const HylcMacroStrainError err = HylcMacroStrainValidate(z);
  PetscCheck(err == HYLC_MACRO_STRAIN_OK, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Invalid strain (%g, %g, %g, %g, %g, %g): %s", (double)z[0], (double)z[1], (double)z[2], (double)z[3], (double)z[4], (double)z[5], HylcMacroStrainErrorString(err));
  for (int k = 0; k < 6; k++) P->z[k] = z[k];
  P->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicCheckStrain - Refuses a strain z = (sx, sa, sy, II00, II01, II11) that does not give a valid,
  representable deformed tile, with a one-line PETSC_ERR_USER_INPUT error "<name>: <component> = <value>:
  <reason>". Beyond HylcPeriodicSetStrain()'s validity (finite, |sa| < 1, 1 + sx > 0, 1 + sy > 0) it bounds
  the stretch factors 1 + sx, 1 + sy by HYLC_PERIODIC_MAX_STRETCH and the angle the midsurface normal turns
  across one period, |N (px, 0)|, |N (0, py)|, |N (px, +-py)| with N = -A^-T II, by 2 pi (a tile bent
  further wraps onto itself). Subnormal components are valid. See docs/method.md.

  Not collective

  Input Parameters:
+ P    - the periodic tile
. z    - the strain
- name - what the strain came from, for the message (e.g. "-strain")

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicCheckStrain(HylcPeriodic P, const PetscReal z[6], const char name[])
{
  const char *const *comp = HylcStrainNames;
  double             zd[6], N[4];
  char               v[6][32]; /* C formatting: PETSc's printf appends '.' to integral %g values */

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
        const int k = PetscAbsReal(z[3]) >= PetscAbsReal(z[4]) && PetscAbsReal(z[3]) >= PetscAbsReal(z[5]) ? 3 : PetscAbsReal(z[4]) >= PetscAbsReal(z[5]) ? 4 : 5;
        char      msg[160];
        snprintf(msg, sizeof(msg), "the midsurface would turn by %.3g rad across one period (periods %g m, %g m)", ang, px, py);
        SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s = %s: %s; at most 2 pi (a tile bent further wraps onto itself)", name, comp[k], v[k], msg);
      }
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetSlideConstraint - Sets the slide constraint (option -periodic_slide).

  Not collective

  Input Parameters:
+ P - the periodic tile
- s - HYLC_SLIDE_NONE, HYLC_SLIDE_GLOBAL (one row), HYLC_SLIDE_PER_YARN (one row per loop) or
      HYLC_SLIDE_PER_FAMILY (one row per yarn family)

  Level: intermediate

.seealso: HylcPeriodicSetFromOptions()
@*/
PetscErrorCode HylcPeriodicSetSlideConstraint(HylcPeriodic P, HylcSlideConstraint s)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCheck(s >= HYLC_SLIDE_NONE && s <= HYLC_SLIDE_PER_FAMILY, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Unknown slide constraint %d", (int)s);
  P->slide = s;
  P->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetContactMargin - Sets the margin of the contact ghosts (option -periodic_margin). With 0,
  the default, every copy of a tile edge in the neighbouring tiles (one ring of 8, more when the stored
  vertices spread over more than a period) takes part in contact. With margin > 0, only the copies whose
  boxes come within max(3 r, margin min(px, py)) of the tile's box on the deformed initial guess do.

  Not collective

  Notes:
  A positive margin prunes the copies once, at set-up, so it is exact only while every vertex stays
  within about (max(3 r, margin min(px, py)) - 2 r) / 2 of its initial guess: beyond that a contact with a
  pruned copy is missing from the energy and yarns can pass through each other. With the former default
  0.25 this happened on 52 of the 1,051 samples of the stockinette's thinned plan (docs/performance.md);
  every copy costs 2-11 % more time per Newton iteration on the paper's patterns.

  Input Parameters:
+ P      - the periodic tile
- margin - the factor (>= 0; 0 for every copy)

  Level: advanced

.seealso: HylcPeriodicSetFromOptions()
@*/
PetscErrorCode HylcPeriodicSetContactMargin(HylcPeriodic P, PetscReal margin)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCheck(margin >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-periodic_margin must not be negative");
  P->marginFactor = margin;
  P->setup        = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetPairMargin - Sets the margin of the Hessian's contact structure (option
  -periodic_pair_margin): the segment pairs closer than margin x 2 r are kept in it (the pairs that touch
  are closer than 2 r), so that it changes rarely. It is rebuilt, and the factorization's symbolic phase
  redone, when a touching pair is not in it; a larger margin rebuilds less often but fills the factor more.

  Not collective

  Input Parameters:
+ P      - the periodic tile
- margin - the factor (>= 1, so that the structure holds every touching pair)

  Level: advanced

.seealso: HylcPeriodicSetFromOptions(), HylcPeriodicEvaluate()
@*/
PetscErrorCode HylcPeriodicSetPairMargin(HylcPeriodic P, PetscReal margin)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCheck(margin >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-periodic_pair_margin must be at least 1 (the structure must hold every touching pair)");
  P->pairMargin = margin;
  P->setup      = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicSetConstraintTolerance - Sets the relative tolerance of the constraint rows' dependence test
  (option -periodic_constraint_rtol): a row whose distance to the span of the rows before it is at most
  rtol times its norm is dropped as linearly dependent.

  Not collective

  Input Parameters:
+ P    - the periodic tile
- rtol - the tolerance, in (0, 1)

  Level: advanced

.seealso: HylcPeriodicSetFromOptions(), HylcPeriodicGetConstraints()
@*/
PetscErrorCode HylcPeriodicSetConstraintTolerance(HylcPeriodic P, PetscReal rtol)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCheck(rtol > 0 && rtol < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-periodic_constraint_rtol must be in (0, 1), got %g", (double)rtol);
  P->crtol = rtol;
  P->setup = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicGetTimes - Wall time (s) accumulated since the last set-up in evaluations (all), in contact
  (broadphase and pair kernels) and in assembling Hessians (any output may be NULL).

  Not collective

  Input Parameter:
. P - the periodic tile

  Output Parameters:
+ eval     - evaluations
. contact  - contact
- assemble - Hessian assembly

  Level: intermediate
@*/
PetscErrorCode HylcPeriodicGetTimes(HylcPeriodic P, PetscLogDouble *eval, PetscLogDouble *contact, PetscLogDouble *assemble)
{
  PetscFunctionBegin;
  if (eval) *eval = P->tEval;
  if (contact) *contact = P->tContact;
  if (assemble) *assemble = P->tAssemble;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicView - Prints the tile: its options, and after HylcPeriodicSetUp() the strain, the sizes of
  the extended pattern and the constraints. Option -periodic_view calls it after each set-up.

  Not collective

  Input Parameters:
+ P      - the periodic tile
- viewer - an ASCII viewer (NULL: stdout of the object's communicator)

  Level: beginner

.seealso: HylcPeriodicViewFromOptions()
@*/
PetscErrorCode HylcPeriodicView(HylcPeriodic P, PetscViewer viewer)
{
  PetscBool iascii;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  if (!viewer) PetscCall(PetscViewerASCIIGetStdout(PetscObjectComm((PetscObject)P), &viewer));
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &iascii));
  if (!iascii) PetscFunctionReturn(PETSC_SUCCESS);
  {
    const char *prefix = ((PetscObject)P)->prefix;
    PetscCall(PetscViewerASCIIPrintf(viewer, "HylcPeriodic Object%s%s%s: one rank\n", prefix ? " (" : "", prefix ? prefix : "", prefix ? ")" : ""));
  }
  PetscCall(PetscViewerASCIIPushTab(viewer));
  if (P->marginFactor > 0)
    PetscCall(PetscViewerASCIIPrintf(viewer, "slide constraint %s, contact ghosts within margin %g of the initial guess, pair margin %g, constraint rtol %g\n", HylcSlideConstraints[P->slide], (double)P->marginFactor, (double)P->pairMargin,
                                     (double)P->crtol));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "slide constraint %s, contact ghosts: every copy in the neighbouring tiles, pair margin %g, constraint rtol %g\n", HylcSlideConstraints[P->slide], (double)P->pairMargin, (double)P->crtol));
  if (P->setup)
    PetscCall(PetscViewerASCIIPrintf(viewer,
                                     "periodic tile: strain (%g, %g, %g, %g, %g, %g); %" PetscInt_FMT " original and %" PetscInt_FMT " ghost vertices, %" PetscInt_FMT " edges, %" PetscInt_FMT " bend-twist elements, %" PetscInt_FMT
                                     " constraints (slide %s; %" PetscInt_FMT " linearly dependent rows dropped)\n",
                                     (double)P->z[0], (double)P->z[1], (double)P->z[2], (double)P->z[3], (double)P->z[4], (double)P->z[5], P->N, P->nfv - P->N, P->nfe, P->nbe, P->ncons, HylcSlideConstraints[P->slide], P->ndropped));
  else
    PetscCall(PetscViewerASCIIPrintf(viewer, "%s\n", P->pat ? "not set up" : "no pattern"));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPeriodicViewFromOptions - Views the tile if the option name (e.g. -periodic_view) is set.

  Collective

  Input Parameters:
+ P    - the periodic tile
. obj  - an object whose prefix is used (NULL: the tile's)
- name - the option

  Level: intermediate

.seealso: HylcPeriodicView()
@*/
PetscErrorCode HylcPeriodicViewFromOptions(HylcPeriodic P, PetscObject obj, const char name[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(P, HYLC_PERIODIC_CLASSID, 1);
  PetscCall(PetscObjectViewFromOptions((PetscObject)P, obj, name));
  PetscFunctionReturn(PETSC_SUCCESS);
}
