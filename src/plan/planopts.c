/* The sampling plan's options, shared by hylc-sample and hylc-calibrate (one spelling, one check). */
#include <hylc/options.h>
#include <hylc/plan.h>
#include <string.h>

const char *const HylcPlanFamilies[] = {"woven", "stockinette", "honeycomb", "rib", "HylcPlanFamily", "", NULL};

/*@C
  HylcPlanRangesFromOptions - Reads the plan's ranges inside a PetscOptionsBegin/End block (only reads them;
  HylcPlanRangesApply() turns them into ranges for a yarn radius): -sampler_family (the defaults of
  docs/method.md §8, II scaled by 1 mm / r) and -sampler_range_<c> min,max for c = sx, sa, sy, II00, II11
  (the 2D ranges follow the 1D ones in proportion). -help shows the family's defaults for r = 1 mm.

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
    for (int t = 6; t < HYLC_PLAN_NTERM; t++) { /* 2D ranges follow the 1D ones in proportion */
      int ci, cj;
      HylcPlanPair(t, &ci, &cj);
      for (int a = 0; a < 2; a++)
        if ((a ? cj : ci) == c) {
          if (mn0 != 0) p.min2[t - 6][a] *= p.min1[c] / mn0;
          if (mx0 != 0) p.max2[t - 6][a] *= p.max1[c] / mx0;
        }
    }
  }
  for (int c = 0; c < HYLC_PLAN_NCOORD; c++) {
    double Z[1];
    PetscCheck(!HylcSampleRange(c, p.min1[c], p.max1[c], 1, Z), comm, PETSC_ERR_USER_INPUT, "-sampler_range_%s %g,%g is not a valid range (sx, sy > -1; the others must contain 0)", cn[c], p.min1[c], p.max1[c]);
  }
  p.n1    = plan->n1;
  p.n2    = plan->n2;
  p.terms = plan->terms;
  *plan   = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPlanTermsFromString - Parses a list of the plan's terms: "all", "1d" (zero and the five 1D terms) or a
  comma list of term names (HylcPlanTermName). Collective.

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
  PetscBool all, d1;

  PetscFunctionBegin;
  PetscCall(PetscStrcmp(list, "all", &all));
  PetscCall(PetscStrcmp(list, "1d", &d1));
  if (all || d1) {
    *terms = all ? (1 << HYLC_PLAN_NTERM) - 1 : (1 << 6) - 1;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscStrncpy(buf, list, sizeof(buf)));
  *terms = 0;
  for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
    int found = -1;
    for (int t = 0; t < HYLC_PLAN_NTERM; t++) {
      PetscBool eq;
      PetscCall(PetscStrcmp(tok, HylcPlanTermName(t), &eq));
      if (eq) found = t;
    }
    PetscCheck(found >= 0, comm, PETSC_ERR_USER_INPUT, "%s: unknown term '%s' (use zero, sx, sa, sy, II00, II11, sx-sa, sx-sy, sx-II00, sx-II11, sa-sy, sa-II00, sa-II11, sy-II00, sy-II11, 1d or all)", opt, tok);
    *terms |= 1 << found;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}
