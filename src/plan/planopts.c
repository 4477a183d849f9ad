/* The sampling plan's options, shared by hylc-sample and hylc-calibrate (one spelling, one check). */
#include <hylc/options.h>
#include <hylc/plan.h>
#include <string.h>

const char *const HylcPlanFamilies[] = {"woven", "stockinette", "honeycomb", "rib", "HylcPlanFamily", "", NULL};
const char *const HylcPlanSpacings[] = {"paper", "graded", "HylcPlanSpacing", "HYLC_PLAN_SPACING_", NULL};

/*@C
  HylcPlanRangesFromOptions - Reads the plan's ranges and spacing inside a PetscOptionsBegin/End block (only
  reads them; HylcPlanRangesApply() turns them into ranges for a yarn radius): -sampler_family (the defaults
  of docs/method.md §8, II scaled by 1 mm / r), -sampler_range_<c> min,max for c = sx, sa, sy, II00, II11 (the
  2D ranges follow the 1D ones in proportion), -sampler_spacing paper|graded and the graded spacing's
  -sampler_graded_h0, -sampler_graded_growth, -sampler_graded_hmax, -sampler_graded_sub. -help shows the
  family's defaults for r = 1 mm.

  Collective

  Input Parameters:
+ PetscOptionsObject - the options block
. comm   - communicator for errors
- man    - the manual page named in -help (the setter of the calling object)

  Output Parameter:
. ranges - the family and the ranges given

  Level: developer

.seealso: HylcPlanRangesApply(), HylcSamplerSetPlanRanges(), HylcCalibrateSetPlanRanges()
@*/
PetscErrorCode HylcPlanRangesFromOptions(PetscOptionItems *PetscOptionsObject, MPI_Comm comm, const char man[], HylcPlanRanges *ranges)
{
  const char *const *cn  = HylcCoordNames;
  PetscEnum          fam = (PetscEnum)ranges->family;
  HylcPlan           p;

  PetscFunctionBegin;
  PetscCall(HylcOptionsEnum("-sampler_family", "Default sampling ranges of docs/method.md §8 (II scaled by 1 mm / r)", man, HylcPlanFamilies, fam, &fam, NULL));
  ranges->family = (PetscInt)fam;
  PetscCheck(!HylcPlanDefaults(HylcPlanFamilies[fam], 1, &p), comm, PETSC_ERR_USER_INPUT, "Unknown sampling family");
  for (int c = 0; c < HYLC_PLAN_NCOORD; c++) {
    PetscReal v[2] = {ranges->set[c] ? ranges->min[c] : p.min1[c], ranges->set[c] ? ranges->max[c] : p.max1[c]};
    PetscInt  n    = 2;
    PetscBool set;
    char      opt[64];
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-sampler_range_%s", cn[c]));
    PetscCall(HylcOptionsRealArray(opt, "1D sampling range min,max of this strain (II in 1/m; default the family's, II for r = 1 mm scaled by 1 mm / r); the 2D ranges scale with it", man, v, &n, &set));
    if (set) {
      PetscCheck(n == 2 && v[0] <= v[1], comm, PETSC_ERR_USER_INPUT, "%s needs two values min,max with min <= max", opt);
      ranges->set[c] = PETSC_TRUE;
      ranges->min[c] = v[0];
      ranges->max[c] = v[1];
    }
  }
  {
    PetscEnum sp = (PetscEnum)ranges->spacing;
    PetscReal h0[5], growth = ranges->growth > 0 ? ranges->growth : p.growth, hmax = ranges->hmax > 0 ? ranges->hmax : p.hmax;
    PetscInt  n = HYLC_PLAN_NCOORD, sub = ranges->sub > 0 ? ranges->sub : p.sub;
    PetscBool set;
    for (int c = 0; c < HYLC_PLAN_NCOORD; c++) h0[c] = ranges->h0set ? ranges->h0[c] : p.h0[c];
    PetscCall(HylcOptionsEnum("-sampler_spacing",
                              "How an axis is sampled: graded (knots dense near 0, spacing -sampler_graded_h0 growing by -sampler_graded_growth, each interval cut -sampler_graded_sub times: the fabric fit's knots) or paper (Algorithm C4's "
                              "-sampler_n1 samples per 1D term, -sampler_n2 per 2D axis; giving either selects paper spacing unless this is given)",
                              man, HylcPlanSpacings, sp, &sp, &set));
    ranges->spacing = (PetscInt)sp;
    if (set) ranges->spacingSet = PETSC_TRUE;
    PetscCall(HylcOptionsRealArray("-sampler_graded_h0", "graded spacing: the knot spacing at 0 of sx, sa, sy, II00, II11 (1 and 1/m; default 0.01 and 2.5 1/m at r = 1 mm, scaled by 1 mm / r)", man, h0, &n, &set));
    if (set) {
      PetscCheck(n == HYLC_PLAN_NCOORD, comm, PETSC_ERR_USER_INPUT, "-sampler_graded_h0 needs %d values (sx, sa, sy, II00, II11), got %d", HYLC_PLAN_NCOORD, (int)n);
      for (int c = 0; c < HYLC_PLAN_NCOORD; c++) PetscCheck(h0[c] > 0, comm, PETSC_ERR_USER_INPUT, "-sampler_graded_h0: %s spacing %g must be positive", cn[c], (double)h0[c]);
      ranges->h0set = PETSC_TRUE;
      for (int c = 0; c < HYLC_PLAN_NCOORD; c++) ranges->h0[c] = h0[c];
    }
    PetscCall(HylcOptionsReal("-sampler_graded_growth", "graded spacing: ratio of consecutive knot spacings away from 0 (>= 1)", man, growth, &growth, &set));
    if (set) {
      PetscCheck(growth >= 1 && growth <= 10, comm, PETSC_ERR_USER_INPUT, "-sampler_graded_growth %g: must be in [1, 10]", (double)growth);
      ranges->growth = growth;
    }
    PetscCall(HylcOptionsReal("-sampler_graded_hmax", "graded spacing: the largest knot spacing, a fraction of the axis's range (0, 1]", man, hmax, &hmax, &set));
    if (set) {
      PetscCheck(hmax > 0 && hmax <= 1, comm, PETSC_ERR_USER_INPUT, "-sampler_graded_hmax %g: must be in (0, 1]", (double)hmax);
      ranges->hmax = hmax;
    }
    PetscCall(HylcOptionsInt("-sampler_graded_sub", "graded spacing: samples per knot interval (1: the knots only; 2: knots and midpoints)", man, sub, &sub, &set));
    if (set) {
      PetscCheck(sub >= 1 && sub <= 16, comm, PETSC_ERR_USER_INPUT, "-sampler_graded_sub %d: must be in 1..16", (int)sub);
      ranges->sub = sub;
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPlanRangesApply - The plan's ranges for a yarn radius: the family's defaults (II scaled by 1 mm / r),
  the 1D ranges given replacing them, the 2D ranges following the 1D ones in proportion; checks them.

  Not collective

  Input Parameters:
+ comm   - communicator for errors
. ranges - from HylcPlanRangesFromOptions() (or filled by hand)
- radius - the yarn radius (m)

  Output Parameter:
. plan   - ranges set; n1, n2 and terms are left as they were

  Level: developer

.seealso: HylcPlanRangesFromOptions()
@*/
PetscErrorCode HylcPlanRangesApply(MPI_Comm comm, const HylcPlanRanges *ranges, PetscReal radius, HylcPlan *plan)
{
  const char *const *cn = HylcCoordNames;
  HylcPlan           p  = *plan;

  PetscFunctionBegin;
  PetscCheck(ranges->family >= 0 && ranges->family < 4 && !HylcPlanDefaults(HylcPlanFamilies[ranges->family], 1e-3 / radius, &p), comm, PETSC_ERR_USER_INPUT, "Unknown sampling family");
  for (int c = 0; c < HYLC_PLAN_NCOORD; c++) {
    const double mn0 = p.min1[c], mx0 = p.max1[c];
    if (ranges->set[c]) {
      p.min1[c] = ranges->min[c];
      p.max1[c] = ranges->max[c];
    }
    for (int t = 6; t < HYLC_PLAN_NTERM3; t++) /* 2D and 3D ranges follow the 1D ones in proportion */
      for (int a = 0; a < HylcPlanTermDim(t); a++)
        if (HylcPlanAxisCoord(t, a) == c) {
          double *mn = t < HYLC_PLAN_NTERM ? &p.min2[t - 6][a] : &p.min3[t - HYLC_PLAN_NTERM][a];
          double *mx = t < HYLC_PLAN_NTERM ? &p.max2[t - 6][a] : &p.max3[t - HYLC_PLAN_NTERM][a];
          if (mn0 != 0) *mn *= p.min1[c] / mn0;
          if (mx0 != 0) *mx *= p.max1[c] / mx0;
        }
  }
  for (int c = 0; c < HYLC_PLAN_NCOORD; c++) {
    double Z[1];
    PetscCheck(!HylcSampleRange(c, p.min1[c], p.max1[c], 1, Z), comm, PETSC_ERR_USER_INPUT, "-sampler_range_%s %g,%g is not a valid range (sx, sy > -1; the others must contain 0)", cn[c], p.min1[c], p.max1[c]);
  }
  p.spacing = (int)ranges->spacing;
  if (ranges->h0set)
    for (int c = 0; c < HYLC_PLAN_NCOORD; c++) p.h0[c] = ranges->h0[c];
  if (ranges->growth > 0) p.growth = ranges->growth;
  if (ranges->hmax > 0) p.hmax = ranges->hmax;
  if (ranges->sub > 0) p.sub = (int)ranges->sub;
  if (p.spacing == HYLC_PLAN_SPACING_GRADED)
    for (int t = 1; t < HYLC_PLAN_NTERM3; t++)
      for (int a = 0; a < HylcPlanTermDim(t); a++) {
        double    Z[HYLC_PLAN_MAXAXIS];
        const int n = HylcPlanAxis(&p, t, a, Z);
        PetscCheck(n > 0, comm, PETSC_ERR_USER_INPUT, "-sampler_spacing graded: axis %d of term %s has more than %d samples (-sampler_graded_h0 %g too small for its range, or -sampler_graded_sub too large)", a, HylcPlanTermName(t), HYLC_PLAN_MAXAXIS,
                   p.h0[HylcPlanAxisCoord(t, a)]);
      }
  p.n1    = plan->n1;
  p.n2    = plan->n2;
  p.terms = plan->terms;
  *plan   = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPlanTermsFromString - Parses a list of the plan's terms: "all", "paper" (the paper's terms: zero, the 1D
  and the 2D ones, without hylc's 3D terms), "1d" (zero and the five 1D terms) or a comma list of term names
  (HylcPlanTermName). Collective.

  Input Parameters:
+ comm - communicator for errors
. opt  - the option the list came from (for messages)
- list - the list

  Output Parameter:
. terms - bit t set for term t

  Level: developer
@*/
PetscErrorCode HylcPlanTermsFromString(MPI_Comm comm, const char opt[], const char list[], int *terms)
{
  char      buf[512], *tok, *save = NULL;
  PetscBool all, d1, paper;

  PetscFunctionBegin;
  PetscCall(PetscStrcmp(list, "all", &all));
  PetscCall(PetscStrcmp(list, "1d", &d1));
  PetscCall(PetscStrcmp(list, "paper", &paper));
  if (all || d1 || paper) {
    *terms = all ? HYLC_PLAN_ALL_TERMS : paper ? HYLC_PLAN_PAPER_TERMS : (1 << 6) - 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscStrncpy(buf, list, sizeof(buf)));
  *terms = 0;
  for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
    int found = -1;
    for (int t = 0; t < HYLC_PLAN_NTERM3; t++) {
      PetscBool eq;
      PetscCall(PetscStrcmp(tok, HylcPlanTermName(t), &eq));
      if (eq) found = t;
    }
    PetscCheck(found >= 0, comm, PETSC_ERR_USER_INPUT,
               "%s: unknown term '%s' (use zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, sx-sa-sy, sx-sa-II00, sx-sa-II11, sx-sy-II00, sx-sy-II11, sa-sy-II00, sa-sy-II11, 1d, paper or all)",
               opt, tok);
    *terms |= 1 << found;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
