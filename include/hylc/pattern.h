#pragma once
/* HylcPattern: a periodic yarn tile (closed periodic yarn loops with rest data), the object every
   pipeline stage consumes.  See docs/patterns.md for the .pyp format and the generators.

   Data layout (N vertices = N edges; every vertex has exactly one outgoing and one incoming edge):
     X[3v]          reference position of vertex v (m)
     theta[v]       twist of the edge leaving v (rad)
     next[v]        head vertex of the edge leaving v
     prev[v]        tail vertex of the edge entering v
     shift[2v]      lattice offset (dx, dy) of that edge's head: the edge runs from X[v] to
                    X[next[v]] + (dx px, dy py, 0)
     restLength[v]  rest length of the edge leaving v (m)
     restKappa[2v]  rest material curvature (kappa1, kappa2) at v (dimensionless, integrated)
     restTwist[v]   rest twist at v (rad)
     refD1[3v]      reference director d1 of the edge leaving v (unit, perpendicular to the edge)
     refTwist[v]    reference twist at v (rad)
   Yarn loops are the cycles of next[]; loop l lists its vertices in yarn order starting at its
   smallest vertex index, and its winding is the sum of the shifts along it. */
#include <hylc/sys.h>
#include <petscviewer.h>

typedef struct _p_HylcPattern *HylcPattern;

/* Registration: the class id and log events of this stage (HylcPatternInitializePackage(), called by HylcPatternCreate()). */
PETSC_EXTERN PetscClassId   HYLC_PATTERN_CLASSID;
PETSC_EXTERN PetscLogEvent  HYLC_PatternLoad, HYLC_PatternWrite, HYLC_PatternGenerate, HYLC_PatternDistance;
PETSC_EXTERN PetscErrorCode HylcPatternInitializePackage(void);

/* Pattern sources: a .pyp file or one of the registered generators (HylcPatternRegister()). */
typedef const char *HylcPatternType;
#define HYLCPATTERNFILE        "file"
#define HYLCPATTERNPLAIN       "plain"
#define HYLCPATTERNBASKET      "basket"
#define HYLCPATTERNTWILL       "twill"
#define HYLCPATTERNSATIN       "satin"
#define HYLCPATTERNSTOCKINETTE "stockinette"
#define HYLCPATTERNRIB         "rib"

/* Parameters of the procedural generators (lengths in metres; 0 or negative = default). */
typedef struct {
  PetscReal radius;  /* yarn radius r (default 1e-3 m) */
  PetscReal spacing; /* wovens: distance between neighbouring parallel yarns (default 4 r) */
  PetscReal wale;    /* knits: stitch width along x (default: see docs/patterns.md) */
  PetscReal course;  /* knits: course height along y (default: see docs/patterns.md) */
  PetscReal depth;   /* knits: z amplitude of the loops (default: see docs/patterns.md) */
  PetscReal gap;     /* wovens: clearance at crossings relative to 2r (default 0.1: centrelines 2.2 r apart) */
  PetscReal seglen;  /* target edge length (default r) */
  PetscInt  size[2]; /* tile size in threads (wovens: x-yarns, y-yarns) or stitches (knits: wales, courses);
                        0 = the smallest repeat of the pattern */
} HylcPatternGenParams;

/* A generator: fills the pattern's data (HylcPatternSetFromCurves() or HylcPatternSetData()) from the
   parameters; the pattern's type is already its registered name (HylcPatternGetType()). Collective. */
typedef PetscErrorCode (*HylcPatternGenerator)(HylcPattern, const HylcPatternGenParams *);

/* The registry of pattern sources (src/pattern/registry.c): "file" (HylcPatternSetFileName()) and the
   generators, each added by one HylcPatternRegister() call; -pattern_type lists them (PetscOptionsFList).
   HylcPatternRegisterAll() adds the built-in ones (file, plain, basket, twill, satin, stockinette, rib)
   and is called by HylcPatternInitializePackage(). Not collective. */
PETSC_EXTERN PetscFunctionList HylcPatternList;
PETSC_EXTERN PetscErrorCode    HylcPatternRegister(const char[], HylcPatternGenerator);
PETSC_EXTERN PetscErrorCode    HylcPatternRegisterAll(void);

/* The data arrays of a pattern (read-only views; see the layout above). */
typedef struct {
  PetscInt         nv;
  PetscReal        px, py, radius;
  const PetscReal *X, *theta, *restLength, *restKappa, *restTwist, *refD1, *refTwist;
  const PetscInt  *next, *prev, *shift;
} HylcPatternData;

PETSC_EXTERN PetscErrorCode HylcPatternCreate(MPI_Comm, HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcPatternDestroy(HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcPatternSetOptionsPrefix(HylcPattern, const char[]);
PETSC_EXTERN PetscErrorCode HylcPatternSetFromOptions(HylcPattern);
PETSC_EXTERN PetscErrorCode HylcPatternSetUp(HylcPattern);
PETSC_EXTERN PetscErrorCode HylcPatternView(HylcPattern, PetscViewer);
PETSC_EXTERN PetscErrorCode HylcPatternViewFromOptions(HylcPattern, PetscObject, const char[]);

/* Source selection, used by HylcPatternSetUp(). */
PETSC_EXTERN PetscErrorCode HylcPatternSetType(HylcPattern, HylcPatternType);
PETSC_EXTERN PetscErrorCode HylcPatternGetType(HylcPattern, HylcPatternType *);

/* What the tile is (issue 33), recorded in the .pyp files hylc writes ("hylc state: <name>" in the comment
   of the *pattern header, which every reader skips): REFERENCE, a reference state (Algorithm C1's, or a
   pattern taken as one); GENERATED, a generator's tile (not relaxed); EQUILIBRIUM, a solved tile under a
   strain (hylc-solve -solve_output); UNRECORDED, a file without the record (the paper's .pyp files), taken
   as its own reference state as before. A job in the auto reference mode computes the reference state of
   every pattern but a REFERENCE or UNRECORDED one (HylcReferenceStateNeeded()). */
typedef enum { HYLC_PATTERN_STATE_UNRECORDED = 0, HYLC_PATTERN_STATE_REFERENCE = 1, HYLC_PATTERN_STATE_GENERATED = 2, HYLC_PATTERN_STATE_EQUILIBRIUM = 3 } HylcPatternState;
PETSC_EXTERN const char *const HylcPatternStates[];
PETSC_EXTERN PetscErrorCode    HylcPatternGetState(HylcPattern, HylcPatternState *);
PETSC_EXTERN PetscErrorCode    HylcPatternSetState(HylcPattern, HylcPatternState);
PETSC_EXTERN PetscErrorCode    HylcPatternSetFileName(HylcPattern, const char[]);
PETSC_EXTERN PetscErrorCode    HylcPatternGetFileName(HylcPattern, const char *[]);
PETSC_EXTERN PetscErrorCode    HylcPatternSetGenParams(HylcPattern, const HylcPatternGenParams *);
PETSC_EXTERN PetscErrorCode    HylcPatternGetGenParams(HylcPattern, HylcPatternGenParams *);
PETSC_EXTERN PetscErrorCode    HylcPatternGenParamsDefault(HylcPatternGenParams *);

/* Direct construction. Collective. */
PETSC_EXTERN PetscErrorCode HylcPatternLoad(HylcPattern, const char[]);
PETSC_EXTERN PetscErrorCode HylcPatternLoadFromString(HylcPattern, const char[], const char[]);
PETSC_EXTERN PetscErrorCode HylcPatternGenerate(HylcPattern, HylcPatternType, const HylcPatternGenParams *);
PETSC_EXTERN PetscErrorCode HylcPatternSetData(HylcPattern, PetscInt, PetscReal, PetscReal, PetscReal, const PetscReal[], const PetscReal[], const PetscInt[], const PetscInt[], const PetscReal[], const PetscReal[], const PetscReal[],
                                               const PetscReal[], const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPatternSetFromCurves(HylcPattern, PetscReal, PetscReal, PetscReal, PetscInt, const PetscInt[], const PetscInt[], const PetscReal[]);
PETSC_EXTERN PetscErrorCode HylcPatternDuplicate(HylcPattern, HylcPattern *);
PETSC_EXTERN PetscErrorCode HylcPatternSetRestFromGeometry(HylcPattern);
PETSC_EXTERN PetscErrorCode HylcPatternScaleRest(HylcPattern, PetscReal, PetscReal);
PETSC_EXTERN PetscErrorCode HylcPatternRecentre(HylcPattern);
PETSC_EXTERN PetscErrorCode HylcPatternCreateSupercell(HylcPattern, PetscInt, PetscInt, HylcPattern *);

/* Output. Collective; rank 0 writes. */
PETSC_EXTERN PetscErrorCode HylcPatternWrite(HylcPattern, const char[]);
PETSC_EXTERN PetscErrorCode HylcPatternWriteVTK(HylcPattern, const char[], PetscInt, PetscInt);

/* Access. Not collective. */
PETSC_EXTERN PetscErrorCode HylcPatternGetData(HylcPattern, HylcPatternData *);
PETSC_EXTERN PetscErrorCode HylcPatternGetNumVertices(HylcPattern, PetscInt *);
PETSC_EXTERN PetscErrorCode HylcPatternGetPeriods(HylcPattern, PetscReal *, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcPatternGetRadius(HylcPattern, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcPatternGetNumLoops(HylcPattern, PetscInt *);
PETSC_EXTERN PetscErrorCode HylcPatternGetLoop(HylcPattern, PetscInt, PetscInt *, const PetscInt **, PetscInt[2]);
PETSC_EXTERN PetscErrorCode HylcPatternGetVertexLoop(HylcPattern, PetscInt, PetscInt *, PetscInt *);

/* Analysis. Not collective. */
PETSC_EXTERN PetscErrorCode HylcPatternGetYarnLength(HylcPattern, PetscReal *, PetscReal *);
PETSC_EXTERN PetscErrorCode HylcPatternGetAreaDensity(HylcPattern, PetscReal, PetscReal *);
/* The default volumetric yarn density (kg/m^3) of a yarn of radius r (m): 0.12 kg/m^2 / r, which
   reproduces the area densities of the paper's tables for basket, satin, stockinette and honeycomb
   (docs/fit.md). Used by hylc-sample (info.txt) and hylc-fit when no density is given. */
static inline PetscReal     HylcDefaultYarnDensity(PetscReal r) { return 0.12 / r; }
PETSC_EXTERN PetscErrorCode HylcPatternIsExcludedPair(HylcPattern, PetscReal, PetscInt, PetscInt, const PetscInt[2], PetscBool *);
PETSC_EXTERN PetscErrorCode HylcPatternMinSegmentDistance(HylcPattern, PetscReal, PetscReal *, PetscInt[4]);
