/* HylcPattern: object lifecycle, options, accessors and yarn-loop extraction. */
#include <hylc/options.h>
#include <hylc/private/patternimpl.h>

PetscClassId  HYLC_PATTERN_CLASSID;
PetscLogEvent HYLC_PatternLoad, HYLC_PatternWrite, HYLC_PatternGenerate, HYLC_PatternDistance;

static PetscBool HylcPatternPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcPatternFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcPatternPackageInitialized = PETSC_FALSE;
  PetscCall(HylcPatternRegistryDestroy_Private());
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternInitializePackage - Registers the class id HylcPattern, its log events (PATTERN_Load,
  PATTERN_Write, PATTERN_Generate, PATTERN_Distance) and the built-in pattern sources (HylcPatternRegisterAll()). Called by
  HylcPatternCreate() and by HylcInitializePackage(); idempotent.

  Not collective

  Level: developer

.seealso: HylcInitializePackage()
@*/
PetscErrorCode HylcPatternInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcPatternPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcPatternPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcPattern", &HYLC_PATTERN_CLASSID));
  PetscCall(PetscLogEventRegister("PATTERN_Load", HYLC_PATTERN_CLASSID, &HYLC_PatternLoad));
  PetscCall(PetscLogEventRegister("PATTERN_Write", HYLC_PATTERN_CLASSID, &HYLC_PatternWrite));
  PetscCall(PetscLogEventRegister("PATTERN_Generate", HYLC_PATTERN_CLASSID, &HYLC_PatternGenerate));
  PetscCall(PetscLogEventRegister("PATTERN_Distance", HYLC_PATTERN_CLASSID, &HYLC_PatternDistance));
  PetscCall(HylcPatternRegisterAll());
  PetscCall(PetscRegisterFinalize(HylcPatternFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGenParamsDefault - The default parameters of the generators: radius 1 mm, every other value 0
  (the generator's own default).

  Not collective

  Output Parameter:
. g - the parameters

  Level: intermediate

.seealso: HylcPatternSetGenParams()
@*/
PetscErrorCode HylcPatternGenParamsDefault(HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscCall(PetscMemzero(g, sizeof(*g)));
  g->radius = 1e-3;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternCreate - Creates an empty periodic yarn pattern.
  Collective.  Fill it with HylcPatternLoad(), HylcPatternGenerate(), or HylcPatternSetFromOptions() +
  HylcPatternSetUp().
@*/
PetscErrorCode HylcPatternCreate(MPI_Comm comm, HylcPattern *pat)
{
  HylcPattern p;

  PetscFunctionBegin;
  PetscValidPointer(pat, 2);
  PetscCall(HylcPatternInitializePackage());
  PetscCall(PetscHeaderCreate(p, HYLC_PATTERN_CLASSID, "HylcPattern", "Periodic yarn pattern", "Pattern", comm, HylcPatternDestroy, HylcPatternView));
  PetscCall(HylcPatternGenParamsDefault(&p->gen));
  p->viewDensity    = 0; /* the shared default, HylcDefaultYarnDensity(r): what hylc-fit and the JSON use */
  p->viewExcludeArc = 3.0;
  PetscCall(PetscObjectChangeTypeName((PetscObject)p, HYLCPATTERNSTOCKINETTE));
  *pat = p;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternReset_Private(HylcPattern p)
{
  PetscFunctionBegin;
  PetscCall(PetscFree7(p->X, p->theta, p->restLength, p->restKappa, p->restTwist, p->refD1, p->refTwist));
  PetscCall(PetscFree3(p->next, p->prev, p->shift));
  PetscCall(PetscFree6(p->loopStart, p->loopVerts, p->winding, p->vertLoop, p->vertPos, p->vertCum));
  PetscCall(PetscFree2(p->loopArc, p->loopLen));
  p->nv      = 0;
  p->nloops  = 0;
  p->hasdata = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcPatternAllocate_Private(HylcPattern p, PetscInt nv)
{
  PetscFunctionBegin;
  PetscCall(HylcPatternReset_Private(p));
  p->nv = nv;
  PetscCall(PetscCalloc7(3 * nv, &p->X, nv, &p->theta, nv, &p->restLength, 2 * nv, &p->restKappa, nv, &p->restTwist, 3 * nv, &p->refD1, nv, &p->refTwist));
  PetscCall(PetscCalloc3(nv, &p->next, nv, &p->prev, 2 * nv, &p->shift));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternDestroy - Destroys a pattern. Accepts NULL; sets the handle to NULL. Collective.
@*/
PetscErrorCode HylcPatternDestroy(HylcPattern *p)
{
  PetscFunctionBegin;
  if (!*p) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidHeaderSpecific(*p, HYLC_PATTERN_CLASSID, 1);
  if (--((PetscObject)(*p))->refct > 0) {
    *p = NULL;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcPatternReset_Private(*p));
  PetscCall(PetscHeaderDestroy(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetOptionsPrefix - Sets the prefix of the pattern's options (-<prefix>pattern_*).

  Not collective

  Input Parameters:
+ p      - the pattern
- prefix - the prefix (NULL: none)

  Level: intermediate

.seealso: HylcPatternSetFromOptions()
@*/
PetscErrorCode HylcPatternSetOptionsPrefix(HylcPattern p, const char prefix[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(PetscObjectSetOptionsPrefix((PetscObject)p, prefix));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetType - Sets the pattern's source: "file" or a registered generator (HylcPatternRegister());
  HylcPatternSetUp() then loads or generates the data.

  Collective

  Input Parameters:
+ p    - the pattern
- type - the name (an unknown one is refused, naming the registered ones)

  Options Database Key:
. -pattern_type <file> - the same (-help lists the registered names)

  Level: beginner

.seealso: HylcPatternGetType(), HylcPatternRegister(), HylcPatternSetFileName()
@*/
PetscErrorCode HylcPatternSetType(HylcPattern p, HylcPatternType type)
{
  HylcPatternGenerator source;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(HylcPatternFindSource_Private(type, &source));
  if (!source) {
    char names[1024];
    PetscCall(HylcPatternSourceNames_Private(", ", PETSC_FALSE, names, sizeof(names)));
    SETERRQ(PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "Unknown pattern type '%s'; use one of %s", type, names);
  }
  PetscCall(PetscObjectChangeTypeName((PetscObject)p, type));
  p->setupcalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetType - The pattern's source: "file" or the name of a registered generator.

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameter:
. type - the name (owned by the pattern; NULL if none was set)

  Level: beginner

.seealso: HylcPatternSetType()
@*/
PetscErrorCode HylcPatternGetType(HylcPattern p, HylcPatternType *type)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  *type = ((PetscObject)p)->type_name;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetFileName - Sets the .pyp file the pattern loads and its type to "file".

  Collective

  Input Parameters:
+ p    - the pattern
- file - the path

  Options Database Key:
. -pattern_file <file.pyp> - the same

  Level: beginner

.seealso: HylcPatternGetFileName(), HylcPatternSetType()
@*/
PetscErrorCode HylcPatternSetFileName(HylcPattern p, const char file[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(PetscStrncpy(p->filename, file, sizeof(p->filename)));
  PetscCall(HylcPatternSetType(p, HYLCPATTERNFILE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetFileName - The .pyp file the pattern loads (type "file"; HylcPatternSetFileName() or
  -pattern_file), or "" if none was given.

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameter:
. file - the path (owned by the pattern)

  Level: intermediate

.seealso: HylcPatternSetFileName(), HylcPatternGetType()
@*/
PetscErrorCode HylcPatternGetFileName(HylcPattern p, const char *file[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscValidPointer(file, 2);
  *file = p->filename;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetGenParams - Sets the parameters of the generators (radius, lengths, tile size, ...); a
  pattern already set up is generated again by the next HylcPatternSetUp().

  Not collective

  Input Parameters:
+ p - the pattern
- g - the parameters (copied; HylcPatternGenParamsDefault() for the defaults)

  Level: intermediate

.seealso: HylcPatternGetGenParams(), HylcPatternGenerate()
@*/
PetscErrorCode HylcPatternSetGenParams(HylcPattern p, const HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  p->gen         = *g;
  p->setupcalled = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetGenParams - The parameters of the generators as set or read from the options.

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameter:
. g - a copy of the parameters

  Level: intermediate

.seealso: HylcPatternSetGenParams()
@*/
PetscErrorCode HylcPatternGetGenParams(HylcPattern p, HylcPatternGenParams *g)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  *g = p->gen;
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define HYLC_STR_(x) #x
#define HYLC_STR(x)  HYLC_STR_(x)

/* A real option given on the command line or in a file: finite, and > 0 (positive) or >= 0. */
static PetscErrorCode CheckReal(HylcPattern p, const char name[], PetscBool set, PetscReal v, PetscBool positive)
{
  const char *prefix   = ((PetscObject)p)->prefix;
  char        raw[256] = "", key[128];

  PetscFunctionBegin;
  if (!set) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscSNPrintf(key, sizeof(key), "-%s%s", prefix ? prefix : "", name + 1));
  PetscCall(PetscOptionsGetString(((PetscObject)p)->options, NULL, key, raw, sizeof(raw), NULL));
  PetscCheck(PetscIsNormalReal(v) || v == 0, PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "Option %s %s: not a finite number", key, raw);
  PetscCheck(positive ? v > 0 : v >= 0, PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "Option %s %s: must be %s", key, raw, positive ? "positive" : "positive, or 0 for the default");
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -pattern_size: exactly two integers, each in [1, HYLC_PATTERN_MAX_SIZE] */
static PetscErrorCode CheckSize(HylcPattern p, const char name[], PetscInt n, const PetscInt size[2])
{
  MPI_Comm    comm     = PetscObjectComm((PetscObject)p);
  const char *prefix   = ((PetscObject)p)->prefix;
  char        raw[256] = "", key[128];
  PetscInt    nraw     = 1;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(key, sizeof(key), "-%s%s", prefix ? prefix : "", name + 1));
  PetscCall(PetscOptionsGetString(((PetscObject)p)->options, NULL, key, raw, sizeof(raw), NULL));
  for (const char *c = raw; *c; c++) nraw += (*c == ',');
  PetscCheck(n == 2 && nraw == 2, comm, PETSC_ERR_USER_INPUT, "Option %s %s: needs two integers nx,ny", key, raw);
  PetscCheck(size[0] >= 1 && size[1] >= 1 && size[0] <= HYLC_PATTERN_MAX_SIZE && size[1] <= HYLC_PATTERN_MAX_SIZE, comm, PETSC_ERR_USER_INPUT, "Option %s %s: sizes must be integers from 1 to %d", key, raw, HYLC_PATTERN_MAX_SIZE);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetFromOptions - Reads the pattern options. Collective.

  Options (prefix "-pattern_" unless the object has another prefix):
+ -pattern_file <f.pyp>            - load this .pyp file (sets the type to "file")
. -pattern_type <stockinette>      - file, or a registered generator: plain, basket, twill, satin, stockinette, rib, ... (HylcPatternRegister())
. -pattern_radius <1e-3>           - generators: yarn radius (m)
. -pattern_spacing <4r>            - wovens: distance between neighbouring parallel yarns (m)
. -pattern_gap <0.1>               - wovens: clearance at crossings relative to 2r
. -pattern_wale, -pattern_course, -pattern_depth - knits: stitch width, course height, loop depth (m)
. -pattern_seglen <r>              - generators: target edge length (m)
. -pattern_size <nx,ny>            - generators: tile size in threads or stitches
. -pattern_consistent_periods      - loader: use the periods implied by the periodic edges' rest lengths
. -pattern_density <0>             - volumetric yarn density used by the summary (kg/m^3); 0: 0.12 kg/m^2 / r, the rule of hylc-fit and the tables
- -pattern_exclude_arc <3>         - summary: same-yarn pairs closer than this rest arc (units of r) are not contacts
@*/
PetscErrorCode HylcPatternSetFromOptions(HylcPattern p)
{
  char                 file[PETSC_MAX_PATH_LEN] = "", type[64];
  PetscBool            flg, fflg, tflg, set[9] = {PETSC_FALSE}, sizeset = PETSC_FALSE, both, isfile;
  PetscInt             n = 2, nsize = 0;
  HylcPatternGenerator source;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(HylcPatternInitializePackage()); /* the registry of -pattern_type */
  PetscObjectOptionsBegin((PetscObject)p);
  PetscCall(PetscStrncpy(type, ((PetscObject)p)->type_name, sizeof(type)));
  PetscCall(HylcOptionsString("-pattern_file", "Periodic yarn pattern file (.pyp) to load", "HylcPatternLoad", p->filename, file, sizeof(file), &fflg));
  if (fflg)
    PetscCall(HylcPatternSetFileName(p, file));
  else if (p->filename[0])
    PetscCall(PetscStrncpy(type, HYLCPATTERNFILE, sizeof(type)));
  PetscCall(HylcOptionsFList("-pattern_type", "Pattern source: a file or a generator (HylcPatternRegister())", "HylcPatternSetType", HylcPatternList, type, type, sizeof(type), &tflg));
  PetscCall(HylcOptionsReal("-pattern_radius", "Generators: yarn radius (m), > 0", "HylcPatternGenerate", p->gen.radius, &p->gen.radius, &set[0]));
  PetscCall(HylcOptionsReal("-pattern_spacing", "Wovens: distance between neighbouring parallel yarns (m); 0 = 4 r", "HylcPatternGenerate", p->gen.spacing, &p->gen.spacing, &set[1]));
  PetscCall(HylcOptionsReal("-pattern_gap", "Wovens: clearance at crossings relative to 2r; 0 = 0.1", "HylcPatternGenerate", p->gen.gap, &p->gen.gap, &set[2]));
  PetscCall(HylcOptionsReal("-pattern_wale", "Knits: stitch width along x (m); 0 = default", "HylcPatternGenerate", p->gen.wale, &p->gen.wale, &set[3]));
  PetscCall(HylcOptionsReal("-pattern_course", "Knits: course height along y (m); 0 = default", "HylcPatternGenerate", p->gen.course, &p->gen.course, &set[4]));
  PetscCall(HylcOptionsReal("-pattern_depth", "Knits: z amplitude of the loops (m); 0 = default", "HylcPatternGenerate", p->gen.depth, &p->gen.depth, &set[5]));
  PetscCall(HylcOptionsReal("-pattern_seglen", "Generators: target edge length (m); 0 = r", "HylcPatternGenerate", p->gen.seglen, &p->gen.seglen, &set[6]));
  n = 2;
  PetscCall(HylcOptionsIntArray("-pattern_size", "Generators: tile size nx,ny (each 1 to " HYLC_STR(HYLC_PATTERN_MAX_SIZE) ") in threads (wovens) or wales,courses (knits); default the smallest repeat", "HylcPatternGenerate", p->gen.size, &n, &flg));
  nsize   = n;
  sizeset = flg;
  PetscCall(HylcOptionsReal("-pattern_density", "Volumetric yarn density for the summary's area density (kg/m^3); 0 = 0.12 kg/m^2 / r (120 kg/m^3 at r = 1 mm), the rule of hylc-fit, hylc-sample's raw export and the paper's tables",
                            "HylcPatternGetAreaDensity", p->viewDensity, &p->viewDensity, &set[7]));
  PetscCall(HylcOptionsReal("-pattern_exclude_arc", "Summary: same-yarn segment pairs closer than this rest arc length (units of r) are not contacts", "HylcPatternMinSegmentDistance", p->viewExcludeArc, &p->viewExcludeArc, &set[8]));
  PetscCall(PetscOptionsBool("-pattern_consistent_periods", "Loader: replace the stored periods by the ones the rest lengths of the periodic edges imply (basket.pyp, docs/method.md §2.1b)", "HylcPatternLoad", p->consistentPeriods,
                             &p->consistentPeriods, NULL));
  PetscCall(PetscObjectProcessOptionsHandlers((PetscObject)p, PetscOptionsObject));
  PetscOptionsEnd();
  /* checked after PetscOptionsEnd(), so that an error leaves nothing allocated behind */
  if (tflg) {
    PetscCall(HylcPatternFindSource_Private(type, &source));
    if (!source) {
      const char *prefix = ((PetscObject)p)->prefix;
      char        names[1024];
      PetscCall(HylcPatternSourceNames_Private(" ", PETSC_TRUE, names, sizeof(names)));
      SETERRQ(PetscObjectComm((PetscObject)p), PETSC_ERR_USER, "Unknown option %s for -%spattern_type. Available options: %s", type, prefix ? prefix : "", names);
    }
    PetscCall(HylcPatternSetType(p, type));
  }
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  both = (PetscBool)(fflg && tflg && !isfile);
  PetscCheck(!both, PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "Both -pattern_file %s and -pattern_type %s were given; use one", file, type);
  PetscCall(CheckReal(p, "-pattern_radius", set[0], p->gen.radius, PETSC_TRUE));
  PetscCall(CheckReal(p, "-pattern_spacing", set[1], p->gen.spacing, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_gap", set[2], p->gen.gap, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_wale", set[3], p->gen.wale, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_course", set[4], p->gen.course, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_depth", set[5], p->gen.depth, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_seglen", set[6], p->gen.seglen, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_density", set[7], p->viewDensity, PETSC_FALSE));
  PetscCall(CheckReal(p, "-pattern_exclude_arc", set[8], p->viewExcludeArc, PETSC_FALSE));
  if (sizeset) PetscCall(CheckSize(p, "-pattern_size", nsize, p->gen.size));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetUp - Loads or generates the pattern selected by its type. Collective.
@*/
PetscErrorCode HylcPatternSetUp(HylcPattern p)
{
  PetscBool isfile;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  if (p->setupcalled && p->hasdata) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCall(PetscStrcmp(((PetscObject)p)->type_name, HYLCPATTERNFILE, &isfile));
  if (isfile) { /* the registered source "file" (registry.c) */
    HylcPatternGenerator load;
    PetscCall(HylcPatternFindSource_Private(HYLCPATTERNFILE, &load));
    PetscCall((*load)(p, &p->gen));
  } else {
    char type[64];
    PetscCall(PetscStrncpy(type, ((PetscObject)p)->type_name, sizeof(type)));
    PetscCall(HylcPatternGenerate(p, type, &p->gen));
  }
  p->setupcalled = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Extracts the loops (cycles of next[]) and checks the connectivity: every vertex has exactly one
   outgoing and one incoming edge. */
PetscErrorCode HylcPatternBuildLoops_Private(HylcPattern p)
{
  PetscInt  nv = p->nv, nl = 0, k = 0;
  PetscInt *seen;
  MPI_Comm  comm = PetscObjectComm((PetscObject)p);

  PetscFunctionBegin;
  PetscCall(PetscFree6(p->loopStart, p->loopVerts, p->winding, p->vertLoop, p->vertPos, p->vertCum));
  PetscCall(PetscFree2(p->loopArc, p->loopLen));
  PetscCall(PetscCalloc1(nv, &seen));
  for (PetscInt v = 0; v < nv; v++) {
    PetscCheck(p->next[v] >= 0 && p->next[v] < nv, comm, PETSC_ERR_USER_INPUT, "Edge leaving vertex %" PetscInt_FMT " ends at vertex %" PetscInt_FMT ", outside [0, %" PetscInt_FMT ")", v, p->next[v], nv);
    seen[p->next[v]]++;
  }
  for (PetscInt v = 0; v < nv; v++) PetscCheck(seen[v] == 1, comm, PETSC_ERR_USER_INPUT, "Vertex %" PetscInt_FMT " has %" PetscInt_FMT " incoming edges; every vertex needs exactly one", v, seen[v]);
  for (PetscInt v = 0; v < nv; v++) p->prev[p->next[v]] = v;
  PetscCall(PetscArrayzero(seen, nv));
  for (PetscInt v = 0; v < nv; v++)
    if (!seen[v]) {
      nl++;
      for (PetscInt w = v; !seen[w]; w = p->next[w]) seen[w] = 1;
    }
  p->nloops = nl;
  PetscCall(PetscMalloc6(nl + 1, &p->loopStart, nv, &p->loopVerts, 2 * nl, &p->winding, nv, &p->vertLoop, nv, &p->vertPos, 2 * nv, &p->vertCum));
  PetscCall(PetscMalloc2(nv + nl, &p->loopArc, nl, &p->loopLen));
  PetscCall(PetscArrayzero(seen, nv));
  nl = 0;
  for (PetscInt v = 0; v < nv; v++) {
    if (seen[v]) continue;
    p->loopStart[nl]       = k;
    p->winding[2 * nl + 0] = p->winding[2 * nl + 1] = 0;
    for (PetscInt w = v; !seen[w]; w = p->next[w]) {
      seen[w]               = 1;
      p->vertLoop[w]        = nl;
      p->vertPos[w]         = k - p->loopStart[nl];
      p->loopVerts[k++]     = w;
      p->vertCum[2 * w]     = p->winding[2 * nl + 0];
      p->vertCum[2 * w + 1] = p->winding[2 * nl + 1];
      p->winding[2 * nl + 0] += p->shift[2 * w + 0];
      p->winding[2 * nl + 1] += p->shift[2 * w + 1];
    }
    nl++;
  }
  p->loopStart[nl] = k;
  /* cumulative rest arc: loopArc[loopStart[l] + l + j] = rest length from the loop start to its j-th vertex */
  for (PetscInt l = 0; l < nl; l++) {
    PetscReal *arc = p->loopArc + p->loopStart[l] + l;
    PetscInt   n   = p->loopStart[l + 1] - p->loopStart[l];
    arc[0]         = 0;
    for (PetscInt j = 0; j < n; j++) arc[j + 1] = arc[j] + p->restLength[p->loopVerts[p->loopStart[l] + j]];
    p->loopLen[l] = arc[n];
  }
  PetscCall(PetscFree(seen));
  p->hasdata = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetData - The pattern's data: vertices, periods, radius, rest data, reference frames and the
  connectivity (borrowed pointers, valid until the pattern changes).

  Not collective

  Input Parameter:
. p - the pattern, with data (HylcPatternSetUp(), HylcPatternLoad() or HylcPatternGenerate())

  Output Parameter:
. d - the data

  Level: intermediate

.seealso: HylcPatternSetData(), HylcPatternGetNumVertices()
@*/
PetscErrorCode HylcPatternGetData(HylcPattern p, HylcPatternData *d)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(p->hasdata, PetscObjectComm((PetscObject)p), PETSC_ERR_ARG_WRONGSTATE, "Pattern has no data yet: call HylcPatternSetUp(), HylcPatternLoad() or HylcPatternGenerate() first");
  d->nv         = p->nv;
  d->px         = p->px;
  d->py         = p->py;
  d->radius     = p->radius;
  d->X          = p->X;
  d->theta      = p->theta;
  d->restLength = p->restLength;
  d->restKappa  = p->restKappa;
  d->restTwist  = p->restTwist;
  d->refD1      = p->refD1;
  d->refTwist   = p->refTwist;
  d->next       = p->next;
  d->prev       = p->prev;
  d->shift      = p->shift;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetNumVertices - The number of vertices of the tile.

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameter:
. nv - the number (0 before the data are set)

  Level: beginner

.seealso: HylcPatternGetData()
@*/
PetscErrorCode HylcPatternGetNumVertices(HylcPattern p, PetscInt *nv)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  *nv = p->nv;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetPeriods - The tile's periods along x and y (m).

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameters:
+ px - the period along x (may be NULL)
- py - the period along y (may be NULL)

  Level: beginner

.seealso: HylcPatternGetData()
@*/
PetscErrorCode HylcPatternGetPeriods(HylcPattern p, PetscReal *px, PetscReal *py)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  if (px) *px = p->px;
  if (py) *py = p->py;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetRadius - The yarn radius of the pattern (m).

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameter:
. r - the radius

  Level: beginner

.seealso: HylcPatternGetData(), HylcYarnModelGetConstants()
@*/
PetscErrorCode HylcPatternGetRadius(HylcPattern p, PetscReal *r)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  *r = p->radius;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetNumLoops - The number of yarn loops of the tile (the cycles of next[]).

  Not collective

  Input Parameter:
. p - the pattern

  Output Parameter:
. nl - the number

  Level: intermediate

.seealso: HylcPatternGetVertexLoop()
@*/
PetscErrorCode HylcPatternGetNumLoops(HylcPattern p, PetscInt *nl)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  *nl = p->nloops;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetLoop - Vertices of yarn loop l in yarn order, and its winding (sum of edge shifts).
  Not collective. Any output may be NULL.
@*/
PetscErrorCode HylcPatternGetLoop(HylcPattern p, PetscInt l, PetscInt *n, const PetscInt **verts, PetscInt winding[2])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(l >= 0 && l < p->nloops, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Loop %" PetscInt_FMT " out of range [0, %" PetscInt_FMT ")", l, p->nloops);
  if (n) *n = p->loopStart[l + 1] - p->loopStart[l];
  if (verts) *verts = p->loopVerts + p->loopStart[l];
  if (winding) {
    winding[0] = p->winding[2 * l];
    winding[1] = p->winding[2 * l + 1];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternGetVertexLoop - The loop a vertex belongs to and its position along it.

  Not collective

  Input Parameters:
+ p - the pattern
- v - the vertex, 0 to nv - 1

  Output Parameters:
+ loop - the loop (may be NULL)
- pos  - the position of v in the loop (may be NULL)

  Level: intermediate

.seealso: HylcPatternGetNumLoops()
@*/
PetscErrorCode HylcPatternGetVertexLoop(HylcPattern p, PetscInt v, PetscInt *loop, PetscInt *pos)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(v >= 0 && v < p->nv, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Vertex %" PetscInt_FMT " out of range [0, %" PetscInt_FMT ")", v, p->nv);
  if (loop) *loop = p->vertLoop[v];
  if (pos) *pos = p->vertPos[v];
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternDuplicate - Makes an independent copy of a pattern's data. Collective.
@*/
PetscErrorCode HylcPatternDuplicate(HylcPattern p, HylcPattern *newp)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(HylcPatternCreate(PetscObjectComm((PetscObject)p), newp));
  (*newp)->gen            = p->gen;
  (*newp)->viewDensity    = p->viewDensity;
  (*newp)->viewExcludeArc = p->viewExcludeArc;
  (*newp)->state          = p->state;
  PetscCall(PetscStrncpy((*newp)->filename, p->filename, sizeof(p->filename)));
  PetscCall(PetscObjectChangeTypeName((PetscObject)*newp, ((PetscObject)p)->type_name));
  if (p->hasdata) {
    PetscCall(HylcPatternSetData(*newp, p->nv, p->px, p->py, p->radius, p->X, p->theta, p->next, p->shift, p->restLength, p->restKappa, p->restTwist, p->refD1, p->refTwist));
    (*newp)->setupcalled = PETSC_TRUE;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetData - Sets all data of a pattern from arrays (copied), indexed as in pattern.h:
  edges are given by next[v] and shift[2v] of the edge leaving each vertex. Validates connectivity,
  but not geometry (the .pyp reader does that). Collective; the same data on every rank.
@*/
PetscErrorCode HylcPatternSetData(HylcPattern p, PetscInt nv, PetscReal px, PetscReal py, PetscReal r, const PetscReal X[], const PetscReal theta[], const PetscInt next[], const PetscInt shift[], const PetscReal restLength[],
                                  const PetscReal restKappa[], const PetscReal restTwist[], const PetscReal refD1[], const PetscReal refTwist[])
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(nv > 0, PetscObjectComm((PetscObject)p), PETSC_ERR_USER_INPUT, "A pattern needs at least one vertex, got %" PetscInt_FMT, nv);
  PetscCall(HylcPatternAllocate_Private(p, nv));
  p->px     = px;
  p->py     = py;
  p->radius = r;
  PetscCall(PetscArraycpy(p->X, X, 3 * nv));
  PetscCall(PetscArraycpy(p->theta, theta, nv));
  PetscCall(PetscArraycpy(p->next, next, nv));
  PetscCall(PetscArraycpy(p->shift, shift, 2 * nv));
  PetscCall(PetscArraycpy(p->restLength, restLength, nv));
  PetscCall(PetscArraycpy(p->restKappa, restKappa, 2 * nv));
  PetscCall(PetscArraycpy(p->restTwist, restTwist, nv));
  PetscCall(PetscArraycpy(p->refD1, refD1, 3 * nv));
  PetscCall(PetscArraycpy(p->refTwist, refTwist, nv));
  PetscCall(HylcPatternBuildLoops_Private(p));
  p->setupcalled = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternCreateSupercell - The nx x ny supercell of a pattern: nx*ny copies of the tile, periods
  (nx px, ny py), vertex (v, copy i, j) numbered (j nx + i) N + v at X_v + (i px, j py, 0), with the same
  rest data and directors. Its energy at a periodic state is nx*ny times the tile's. Collective.
@*/
PetscErrorCode HylcPatternCreateSupercell(HylcPattern p, PetscInt nx, PetscInt ny, HylcPattern *sp)
{
  const PetscInt N = p->nv, M = N * nx * ny;
  PetscReal     *X, *th, *RL, *RK, *RT, *D1, *RefT;
  PetscInt      *next, *shift;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(nx >= 1 && ny >= 1, PetscObjectComm((PetscObject)p), PETSC_ERR_ARG_OUTOFRANGE, "Supercell size must be at least 1x1");
  PetscCall(PetscMalloc7(3 * M, &X, M, &th, M, &RL, 2 * M, &RK, M, &RT, 3 * M, &D1, M, &RefT));
  PetscCall(PetscMalloc2(M, &next, 2 * M, &shift));
  for (PetscInt j = 0; j < ny; j++)
    for (PetscInt i = 0; i < nx; i++)
      for (PetscInt v = 0; v < N; v++) {
        const PetscInt k = (j * nx + i) * N + v, w = p->next[v];
        /* the head of the edge lies in copy (i + dx, j + dy), wrapped into the supercell */
        const PetscInt ci = i + p->shift[2 * v], cj = j + p->shift[2 * v + 1];
        const PetscInt wi = ((ci % nx) + nx) % nx, wj = ((cj % ny) + ny) % ny;
        X[3 * k]         = p->X[3 * v] + i * p->px;
        X[3 * k + 1]     = p->X[3 * v + 1] + j * p->py;
        X[3 * k + 2]     = p->X[3 * v + 2];
        th[k]            = p->theta[v];
        RL[k]            = p->restLength[v];
        RK[2 * k]        = p->restKappa[2 * v];
        RK[2 * k + 1]    = p->restKappa[2 * v + 1];
        RT[k]            = p->restTwist[v];
        RefT[k]          = p->refTwist[v];
        next[k]          = (wj * nx + wi) * N + w;
        shift[2 * k]     = (ci - wi) / nx;
        shift[2 * k + 1] = (cj - wj) / ny;
        for (int d = 0; d < 3; d++) D1[3 * k + d] = p->refD1[3 * v + d];
      }
  PetscCall(HylcPatternCreate(PetscObjectComm((PetscObject)p), sp));
  PetscCall(HylcPatternSetData(*sp, M, nx * p->px, ny * p->py, p->radius, X, th, next, shift, RL, RK, RT, D1, RefT));
  (*sp)->state = p->state;
  PetscCall(PetscFree7(X, th, RL, RK, RT, D1, RefT));
  PetscCall(PetscFree2(next, shift));
  PetscFunctionReturn(PETSC_SUCCESS);
}

const char *const HylcPatternStates[] = {"unrecorded", "reference", "generated", "equilibrium", "HylcPatternState", "HYLC_PATTERN_STATE_", NULL};

/*@C
  HylcPatternGetState - What the tile is: a reference state, a generator's tile, a solved tile under a
  strain, or a file without the record (include/hylc/pattern.h). Not collective.

  Input Parameter:
. p - the pattern

  Output Parameter:
. state - the state

  Level: intermediate

.seealso: HylcPatternSetState(), HylcReferenceStateNeeded()
@*/
PetscErrorCode HylcPatternGetState(HylcPattern p, HylcPatternState *state)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  *state = p->state;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternSetState - Sets what the tile is (written to .pyp files by HylcPatternWrite()). Not
  collective.

  Input Parameters:
+ p     - the pattern
- state - the state

  Level: intermediate

.seealso: HylcPatternGetState()
@*/
PetscErrorCode HylcPatternSetState(HylcPattern p, HylcPatternState state)
{
  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(state >= HYLC_PATTERN_STATE_UNRECORDED && state <= HYLC_PATTERN_STATE_EQUILIBRIUM, PetscObjectComm((PetscObject)p), PETSC_ERR_ARG_OUTOFRANGE, "Unknown pattern state %d", (int)state);
  p->state = state;
  PetscFunctionReturn(PETSC_SUCCESS);
}
