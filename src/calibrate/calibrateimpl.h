#pragma once
/* Private definition of HylcCalibrate (src/calibrate/ only). */
#include <hylc/calibrate.h>
#include <petsc/private/petscimpl.h>
#include <petsctao.h>

#define HYLC_CALIB_NTERM   (HYLC_PLAN_NTERM + 1) /* the plan's 15 terms and "other" (rows of a file off the plan's axes) */
#define HYLC_CALIB_OTHER   HYLC_PLAN_NTERM
#define HYLC_CALIB_NRECORD 17 /* per sample and evaluation: psi, dpsi/dlog p (4), status, iterations, then (the base sample only) the gradient below */
#define HYLC_CALIB_REC_DS  7  /* dPsi/dsx, dPsi/dsy at the base strain (N/m; II = 0 only, else 0) */
#define HYLC_CALIB_REC_DSP 9  /* [9 + 2 q + k]: p_q d/dp_q of dPsi/ds_k at the fixed state (q = E, Es, G, kc; k = x, y) */

typedef enum {
  HYLC_CALIB_TARGET_AUTO    = 0,
  HYLC_CALIB_TARGET_TABLE   = 1,
  HYLC_CALIB_TARGET_SAMPLES = 2,
  HYLC_CALIB_TARGET_RAW     = 3,
  HYLC_CALIB_TARGET_CSV     = 4
} HylcCalibTargetType;
PETSC_INTERN const char *const HylcCalibTargetTypes[];

struct _HylcCalibrateOps {
  PetscErrorCode (*view)(HylcCalibrate, PetscViewer);
};

struct _p_HylcCalibrate {
  PETSCHEADER(struct _HylcCalibrateOps);
  PetscMPIInt rank, size;
  /* files */
  char                target[PETSC_MAX_PATH_LEN], output[PETSC_MAX_PATH_LEN], dump[PETSC_MAX_PATH_LEN], refout[PETSC_MAX_PATH_LEN];
  HylcCalibTargetType targetType; /* as given (auto) and as resolved in SetUp */
  HylcCalibTargetType targetResolved;
  /* the tile */
  HylcPattern         pat; /* created by HylcCalibrateGetPattern(), set up by HylcCalibrateSetUp() */
  char                patLabel[PETSC_MAX_PATH_LEN + 64];
  HylcYarnModel       model; /* the initial model as read from -yarn_* */
  HylcMicro           micro; /* this rank's solver (PETSC_COMM_SELF), created by HylcCalibrateGetMicro() */
  HylcReferenceParams refpar;
  HylcReferenceMode   refmode;
  PetscBool           refComputed;
  /* parameters */
  HylcCalibrateRole role[HYLC_CALIBRATE_NPARAM];
  PetscReal         p0[HYLC_CALIBRATE_NPARAM], p[HYLC_CALIBRATE_NPARAM];    /* initial (resolved), current */
  PetscReal         blo[HYLC_CALIBRATE_NPARAM], bhi[HYLC_CALIBRATE_NPARAM]; /* bounds as given (-1: relative to the initial value) */
  PetscReal         lo[HYLC_CALIBRATE_NPARAM], hi[HYLC_CALIBRATE_NPARAM];   /* bounds resolved by HylcCalibrateSetUp() */
  PetscBool         held[HYLC_CALIBRATE_NPARAM];                            /* free but not determined by the data: held */
  PetscBool         bound[HYLC_CALIBRATE_NPARAM];                           /* free and ending at a bound */
  /* sampling of a table target */
  HylcPlanRanges ranges;
  HylcPlan       plan;          /* ranges resolved for the yarn radius by HylcCalibrateSetUp() */
  PetscInt       n1, n2, terms; /* samples per 1D term, per 2D axis; bit t: term t */
  /* thinning of a file target */
  PetscInt stride, maxSamples;
  /* objective */
  PetscReal wzero, w[HYLC_CALIB_NTERM];
  PetscReal wstat;    /* -calibrate_stationary: weight of (dPsi/ds_k(z_b) / S_k)^2, k = x, y (0: off) */
  PetscReal sscale[2]; /* S_k: the target's dPsi/ds_k at s_k = 5 % (a table), or 2 dPsi_T / s of its row nearest 5 % (N/m; 0: none) */
  PetscBool statFD;    /* -calibrate_stationary_jacobian fd: its Jacobian by central differences (re-solves of the base sample), else gn */
  PetscReal statH;     /* the step in log p of those differences */
  PetscBool hasGrad;   /* the base strain is in-plane: the gradient there is computed */
  PetscInt  nres;      /* residuals: m, and 2 with the stationarity */
  /* the optimizer: TAO (options prefix calibrate_), created by HylcCalibrateGetTao(), and the options it
     is given before TaoSetFromOptions() (the -calibrate_tao_* options override them) and the tests hylc
     adds to TAO's (held flat directions, -calibrate_xtol, -calibrate_ftol, -calibrate_fatol) */
  Tao       tao;
  PetscBool taoUsed; /* TaoSolve() ran on it: HylcCalibrateSolve() replaces it by a fresh one */
  PetscInt  maxIt;
  PetscReal lambda, xtol, ftol, fatol, flatTol;
  /* the samples: 0 is the base strain z_b */
  HylcCalibrateStart start;    /* -calibrate_start */
  PetscBool  targetContinued;  /* a samples target with continued samples (read by HylcCalibrateReadTarget_Private) */
  PetscBool  continued;        /* the start resolved in HylcCalibrateSetUp(): the units below solved by continuation */
  PetscInt   nunits, *ustart;  /* units of work: samples uorder[ustart[u] .. ustart[u+1]) (m + 1 entries) */
  PetscInt  *uorder;           /* m: the samples, unit by unit, each unit from the zero strain outward */
  PetscInt   m;
  PetscReal *z, *tpsi; /* 6m, m: strains and the target energy */
  PetscInt  *term;     /* m */
  PetscInt   nt[HYLC_CALIB_NTERM];
  PetscReal  range[HYLC_CALIB_NTERM];
  PetscInt   nrows, nskipped; /* file rows read, rows not used (not converged in a samples file, or thinned) */
  /* results */
  PetscReal     *rec0, *rec1; /* m x HYLC_CALIB_NRECORD: the initial and the final evaluation */
  PetscReal      f0, f1;
  PetscInt       its, nevals;
  PetscBool      solverSetUp, setupcalled, solved;
  PetscLogDouble tsolve;
};

/* calibrate.c: frees the samples and results, marks the object not set up */
PETSC_INTERN PetscErrorCode HylcCalibrateResetSamples_Private(HylcCalibrate);
/* calibrate.c: the pattern set up, the initial values and bounds resolved, the plan resolved, the solver set up */
PETSC_INTERN PetscErrorCode HylcCalibrateSetUpSolver_Private(HylcCalibrate);
/* opts.c: the optimizer's options (hylc's as TAO's defaults, then -calibrate_tao_*) */
PETSC_INTERN PetscErrorCode HylcCalibrateTaoSetFromOptions_Private(HylcCalibrate);
/* target.c: reads the target and fills z, target, term, nt, range (collective) */
PETSC_INTERN PetscErrorCode HylcCalibrateReadTarget_Private(HylcCalibrate);
/* solve.c: the units of work of the samples (continuation: the half-lines of the 1D terms; otherwise or
   for the other samples, one sample each) */
PETSC_INTERN PetscErrorCode HylcCalibrateBuildUnits_Private(HylcCalibrate);
/* target.c: the rows of a file target (rank 0) */
typedef struct {
  PetscInt   n, cap;
  PetscReal *z, *psi; /* 6n, n */
  PetscInt  *term;    /* the plan's term (HYLC_CALIB_OTHER: off the plan's axes) */
  PetscInt  *line;    /* the row's line in a text file (1-based), its row in a samples file (0-based) */
  PetscBool  continued; /* a samples file with continued samples (/samples/start 1 or 2): -calibrate_start auto */
  PetscReal  sscale[2]; /* S_x, S_y of -calibrate_stationary from every usable row (before the thinning; 0: none) */
} HylcCalibRows;
PETSC_INTERN PetscErrorCode HylcCalibRowsDestroy_Private(HylcCalibRows *);
/* target.c: rank 0's part of reading a CSV, raw data.txt or samples file target: rows read, checked (values,
   strains against the tile P unless NULL), the base row and the rows kept in S (not collective) */
PETSC_INTERN PetscErrorCode HylcCalibrateReadFileTarget_Private(const char path[], HylcCalibTargetType kind, PetscReal radius, PetscInt stride, PetscInt maxSamples, HylcPeriodic P, HylcCalibRows *S, PetscInt *nrows, PetscInt *nskipped);
/* term name (the plan's names and "other") */
PETSC_INTERN const char *HylcCalibrateTermName_Private(PetscInt t);
/* solve.c: one evaluation at explicit p (no ties): the records (m x HYLC_CALIB_NRECORD) on every rank */
PETSC_INTERN PetscErrorCode HylcCalibrateSolveSamples_Private(HylcCalibrate, const PetscReal p[], PetscReal rec[]);
PETSC_INTERN PetscErrorCode HylcCalibrateStrainGradient_Private(HylcCalibrate, PetscReal ds[2], PetscReal dlogp[]);
/* solve.c: residuals r (nres: entry 0 the base term, 1..m-1 the samples, m and m+1 the stationarity's) and
   Jacobian J (nres x 4, row-major) from records */
PETSC_INTERN PetscErrorCode HylcCalibrateResiduals_Private(HylcCalibrate, const PetscReal rec[], PetscReal r[], PetscReal J[], PetscReal *f, PetscInt *nfailed);
