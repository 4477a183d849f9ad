#pragma once
/* Private definition of HylcMicro: only src/micro may include this. The object is split by job:
     src/micro/micro.c  the object: create/destroy, prefix, pattern, set-up, solve, results;
     src/micro/opts.c   the parameters: setters, SetFromOptions, View;
     src/micro/kkt.c    the KKT preconditioner (S22): a PCSHELL around PCCHOLESKY and its Schur complement;
     src/micro/snes.c   the SNES callbacks: objective, residual, Jacobian, line search, convergence test;
     src/micro/regularization.c the schedule of alpha (paper, adaptive, hybrid, x 10 retries, fallback);
     src/micro/saddle.c the second-order test of a converged state and the escape from saddle points. */
#include <hylc/micro.h>
#include <petsc/private/petscimpl.h>

typedef struct {
  PetscReal alphaStart, alphaEnd; /* alpha^ schedule: alphaStart (alphaEnd/alphaStart)^(min(i, alphaIts)/alphaIts) */
  PetscInt  alphaIts, maxRetries;
  PetscReal twistScale;     /* mu; <= 0: 1/r */
  PetscReal stepP0, stepP1; /* d_max = (p0 + p1 clamp(lambda_min(I), 0, 1)) r */
  PetscReal lsFactor;
  PetscInt  lsMax, maxStalls;
  PetscReal rtol, atol, ctol, maxTime;
  PetscBool indefinite;         /* accept a factorization of an indefinite K (the descent test still applies) */
  PetscInt  alphaSched;         /* HylcMicroAlphaSchedule: paper (the decay above) or adaptive */
  PetscReal alphaFact;          /* adaptive: alpha^ / factor after a good step, x factor after a poor one */
  PetscReal alphaMin, alphaMax; /* adaptive: the bounds of alpha^ */
  PetscReal stepClear;          /* step limit also <= stepClear x the clearance (0: off) */
  PetscReal alphaSwitch;        /* hybrid: adaptive once ||M g||_inf <= alphaSwitch ||M g_0||_inf */
  PetscBool alphaFallback;      /* adaptive, hybrid: a solve that does not converge is repeated with the paper schedule */
  PetscBool saddleTest;         /* second-order test of a converged state */
  PetscInt  saddleMax;          /* escapes from saddle points per solve */
  PetscReal saddleTol;          /* negative curvature below -saddleTol max|diag(M H M)| makes a saddle */
  PetscInt  uniGrad;            /* HylcMicroUniaxialGradient of HylcMicroSolveUniaxial() */
  PetscReal uniXtol;            /* uniaxial: converged when the predicted Newton step in the lateral strains is at most this */
  PetscInt  uniMaxIt;           /* uniaxial: Newton steps */
  PetscReal uniH;               /* uniaxial: difference step (strain) of the lateral Hessian (and of the fd gradient) */
  PetscReal uniMaxStep;         /* uniaxial: largest change of a lateral strain per Newton step */
  PetscReal uniRtol;            /* uniaxial: -micro_rtol of its solves (the gradients' accuracy) */
  PetscReal uniGtol;            /* uniaxial: converged also when a line search fails with |lateral gradient| <= gtol |T| */
} HylcMicroParams;

struct _HylcMicroOps {
  PetscErrorCode (*view)(HylcMicro, PetscViewer);
};

/* the factorization of K and the KKT data (S22) of the current pattern and strain (kkt.c) */
typedef struct {
  PC               inner;   /* PCCHOLESKY of K (prefix <prefix>micro_factor_; solver type hylc by default) */
  PetscBool        cholmod; /* the solver type is CHOLMOD (its not-positive-definite error is a failed factorization) */
  Mat              Bd, Zd;  /* dense n x m: the Schur right-hand sides M A^T and Z = K^-1 M A^T (on Bw, Z) */
  PetscReal       *Bw;
  const PetscReal *A, *dL, *AAtinv; /* the tile's constraints (borrowed) */
  PetscReal       *c, *Z, *S, *Sinv, *wl, *tmp;
} HylcMicroKKT;

/* the state of one solve: zeroed at its start by HylcMicroResetSolveState_Private() (status converged, no
   energy yet); everything the method changes while it runs */
typedef struct {
  /* the regularization (regularization.c) */
  PetscReal alpha;
  PetscReal gmax;       /* ||M g||_inf of the iterate the Newton matrix was formed at */
  PetscReal ahat;       /* adaptive schedule: alpha^ of the next Newton matrix */
  PetscReal gmax0;      /* ||M g||_inf at the first iteration of the solve */
  PetscBool adapting;   /* alpha^ follows the adaptive logic in this iteration (adaptive, or hybrid after its switch) */
  PetscBool reverted;   /* hybrid: negative curvature after the switch sent this solve back to the paper's schedule */
  PetscInt  projNeg;    /* negative eigenvalues of K on the constraints' tangent space (when counted) */
  PetscInt  retriesJac; /* retries before this Newton matrix was formed */
  /* the iteration */
  PetscBool       haveH; /* K holds the unscaled H_y of the state in X */
  PetscReal       E0;    /* energy of the current iterate */
  PetscReal       parts[4];
  PetscReal       z0;     /* |z| at the first iteration, or at the cold initial guess for a continued solve */
  PetscReal       z0cold; /* |z| at the cold initial guess y0 (continued solves: the scale of the relative test) */
  PetscReal       lastz, lastc;
  PetscInt        stalls, stallsTotal, retries;
  PetscLogDouble  tStart, tFactor, tLineSearch;
  HylcMicroStatus status;
  PetscBool       statusSet;
  PetscBool       resolved;     /* a rejected step whose first-order decrease is below the energy's rounding: converged as far as E can tell */
  PetscBool       factorFailed; /* the Newton matrix could not be factored after every alpha increase */
  PetscInt        itBase;       /* Newton iterations of this solve before the current SNESSolve (restarts after saddle escapes) */
  PetscBool       restart;      /* the current SNESSolve continues the solve after a saddle escape */
  PetscInt        escapes;      /* saddle escapes of this solve */
  PetscInt        nhist;        /* energies in the history (hist) */
  PetscBool       continued;    /* this solve started from a state given by HylcMicroSetInitialState() */
} HylcMicroSolveState;

/* HylcMicro: the parameters (par: what the setters and options set), the pattern's matrices and vectors,
   the factorization (kkt) and the state of one solve (st) */
struct _p_HylcMicro {
  PETSCHEADER(struct _HylcMicroOps);
  HylcMicroParams     par;
  HylcPattern         pat;
  HylcYarnModel       model;
  HylcPeriodic        P;           /* created by HylcMicroGetPeriodic(); given the pattern by HylcMicroSetPattern() */
  PetscBool           setupcalled; /* the matrices, vectors and KKT buffers of the current pattern are built */
  PetscInt            ny, m;       /* unknowns, constraint rows */
  PetscReal           mu, r, ks;   /* twist scale, yarn radius, stretching stiffness k_s */
  SNES                snes;        /* created and configured by HylcMicroGetSNES(); reset (SNESReset) for a new pattern */
  Mat                 K;
  Vec                 X, mvec;
  PetscReal          *yw, *gw; /* work: unscaled unknowns and gradient */
  PetscInt            caphist;
  PetscReal          *hist; /* the energy history of the last solve (st.nhist values) */
  HylcMicroKKT        kkt;
  HylcMicroSolveState st;
  /* inputs of the next solve */
  PetscReal *uinit;    /* HylcMicroSetInitialState(): the fluctuation u~ = y - y0 (twists included) of a state */
  PetscInt   nuinit;   /* its length (the tile's ny when it was set) */
  PetscBool  haveInit; /* the next solve starts from y0 + uinit (used once) */
  PetscBool  inject;   /* this solve raises the injected error (HYLC_INJECT_ERROR) */
  PetscInt   injectAt; /* the value of HYLC_INJECT_ERROR of this solve (for the message) */
};

/* the object's options prefix ("" if none), for messages: "-%smicro_alpha_start" */
static inline const char *HylcMicroPrefix_Private(HylcMicro M) { return ((PetscObject)M)->prefix ? ((PetscObject)M)->prefix : ""; }

/* micro.c */
PETSC_INTERN PetscErrorCode HylcMicroResetSolveState_Private(HylcMicro);
/* kkt.c */
PETSC_INTERN PetscErrorCode HylcMicroKKTFactor_Private(HylcMicro, PetscBool *);
PETSC_INTERN PetscErrorCode HylcMicroKKTSolve_Private(HylcMicro, Vec, Vec);
PETSC_INTERN PetscErrorCode HylcMicroSetKKT_Private(HylcMicro, PC);
PETSC_INTERN PetscErrorCode HylcMicroSetUpKKT_Private(HylcMicro, PC);
PETSC_INTERN PetscErrorCode HylcMicroResizeKKT_Private(HylcMicro, PetscInt);
PETSC_INTERN PetscErrorCode HylcMicroDestroyKKT_Private(HylcMicro);
/* snes.c */
PETSC_INTERN PetscErrorCode HylcMicroCreateSNES_Private(HylcMicro);
PETSC_INTERN PetscErrorCode HylcMicroSetUpSNES_Private(HylcMicro);
PETSC_INTERN PetscErrorCode HylcMicroToY_Private(HylcMicro, Vec, PetscReal[]);
PETSC_INTERN PetscErrorCode HylcMicroSafeEnergy_Private(HylcMicro, Vec, PetscReal *, PetscReal[4]);
PETSC_INTERN PetscErrorCode HylcMicroProjectedGradientNorm_Private(HylcMicro, const PetscReal[], PetscReal *);
PETSC_INTERN PetscErrorCode HylcMicroStepLimit_Private(HylcMicro, Vec, PetscReal *);
PETSC_INTERN PetscErrorCode HylcMicroPushEnergy_Private(HylcMicro, PetscReal);
/* regularization.c: the schedule of alpha */
PETSC_INTERN PetscReal      HylcMicroPaperAlphaHat_Private(HylcMicro, PetscInt);
PETSC_INTERN PetscErrorCode HylcMicroRegularizationAlpha_Private(HylcMicro, PetscInt, PetscReal);
PETSC_INTERN PetscErrorCode HylcMicroRegularizationAdapt_Private(HylcMicro, PetscBool, PetscBool, PetscReal, PetscReal, PetscReal);
PETSC_INTERN PetscErrorCode HylcMicroRegularizationIncrease_Private(HylcMicro, PetscBool *);
PETSC_INTERN PetscErrorCode HylcMicroRegularizationRevert_Private(HylcMicro, PetscBool *);
PETSC_INTERN PetscBool      HylcMicroRegularizationFallback_Private(HylcMicro, HylcMicroStatus);
/* saddle.c */
PETSC_INTERN PetscErrorCode HylcMicroSaddle_Private(HylcMicro, PetscBool, PetscInt *, PetscBool *);
