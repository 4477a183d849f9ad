#include <hylc/sys.h>
#include <hylc/chol.h>

PetscClassId  HYLC_PATTERN_CLASSID;
PetscLogEvent HYLC_PatternLoad, HYLC_PatternWrite, HYLC_PatternGenerate, HYLC_PatternDistance;
PetscLogEvent HYLC_TileEvaluate, HYLC_TileBroadphase, HYLC_TileContact, HYLC_TileAssemble;
PetscLogEvent HYLC_PeriodicSetUp, HYLC_PeriodicEvaluate, HYLC_SamplerRun;
PetscClassId  HYLC_MICRO_CLASSID, HYLC_CHOL_CLASSID;
PetscLogEvent HYLC_MicroSolve, HYLC_MicroSetUp, HYLC_MicroFactor, HYLC_MicroLineSearch, HYLC_MicroSaddle;
PetscLogEvent HYLC_CholSymbolic, HYLC_CholNumeric, HYLC_CholSolve;
PetscClassId  HYLC_PERIODIC_CLASSID, HYLC_SAMPLER_CLASSID;

const char   *HylcDefaultOrdering(void) { return MATORDERINGMETISND; }
PetscClassId  HYLC_MIDSURFACE_CLASSID;
PetscLogEvent HYLC_MacroSetUp, HYLC_MacroPoisson, HYLC_MacroEvaluate;
PetscClassId  HYLC_MATERIAL_CLASSID, HYLC_FIT_CLASSID;
PetscLogEvent HYLC_MaterialLoad, HYLC_MaterialWrite, HYLC_FitRun, HYLC_FitTerm, HYLC_FitMLS, HYLC_FitMonotone;
PetscClassId  HYLC_CALIBRATE_CLASSID;
PetscLogEvent HYLC_CalibrateSetUp, HYLC_CalibrateSolve, HYLC_CalibrateEvaluate, HYLC_CalibrateGather;

PETSC_INTERN PetscErrorCode HylcMetisRegister(void);

static PetscBool HylcPackageInitialized = PETSC_FALSE;

static PetscErrorCode HylcFinalizePackage(void)
{
  PetscFunctionBegin;
  HylcPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcInitializePackage(void)
{
  PetscFunctionBegin;
  if (HylcPackageInitialized) PetscFunctionReturn(PETSC_SUCCESS);
  HylcPackageInitialized = PETSC_TRUE;
  PetscCall(PetscClassIdRegister("HylcPattern", &HYLC_PATTERN_CLASSID));
  PetscCall(PetscLogEventRegister("PATTERN_Load", HYLC_PATTERN_CLASSID, &HYLC_PatternLoad));
  PetscCall(PetscLogEventRegister("PATTERN_Write", HYLC_PATTERN_CLASSID, &HYLC_PatternWrite));
  PetscCall(PetscLogEventRegister("PATTERN_Generate", HYLC_PATTERN_CLASSID, &HYLC_PatternGenerate));
  PetscCall(PetscLogEventRegister("PATTERN_Distance", HYLC_PATTERN_CLASSID, &HYLC_PatternDistance));
  PetscCall(PetscClassIdRegister("HylcPeriodic", &HYLC_PERIODIC_CLASSID));
  PetscCall(PetscLogEventRegister("PERIODIC_SetUp", HYLC_PERIODIC_CLASSID, &HYLC_PeriodicSetUp));
  PetscCall(PetscLogEventRegister("PERIODIC_Evaluate", HYLC_PERIODIC_CLASSID, &HYLC_PeriodicEvaluate));
  /* the contact pairs and the assembly inside PERIODIC_Evaluate; TILE_Evaluate is the test-support tile (tests/support/tile.c) */
  PetscCall(PetscLogEventRegister("CONTACT_Broadphase", HYLC_PERIODIC_CLASSID, &HYLC_TileBroadphase));
  PetscCall(PetscLogEventRegister("CONTACT_Energy", HYLC_PERIODIC_CLASSID, &HYLC_TileContact));
  PetscCall(PetscLogEventRegister("PERIODIC_Assemble", HYLC_PERIODIC_CLASSID, &HYLC_TileAssemble));
  PetscCall(PetscLogEventRegister("TILE_Evaluate", HYLC_PERIODIC_CLASSID, &HYLC_TileEvaluate));
  PetscCall(PetscClassIdRegister("HylcSampler", &HYLC_SAMPLER_CLASSID));
  PetscCall(PetscLogEventRegister("SAMPLER_Run", HYLC_SAMPLER_CLASSID, &HYLC_SamplerRun));
  PetscCall(PetscClassIdRegister("HylcMicro", &HYLC_MICRO_CLASSID));
  PetscCall(PetscLogEventRegister("MICRO_SetUp", HYLC_MICRO_CLASSID, &HYLC_MicroSetUp));
  PetscCall(PetscLogEventRegister("MICRO_Solve", HYLC_MICRO_CLASSID, &HYLC_MicroSolve));
  PetscCall(PetscLogEventRegister("MICRO_Factor", HYLC_MICRO_CLASSID, &HYLC_MicroFactor));
  PetscCall(PetscLogEventRegister("MICRO_Saddle", HYLC_MICRO_CLASSID, &HYLC_MicroSaddle));
  PetscCall(PetscLogEventRegister("MICRO_LineSearch", HYLC_MICRO_CLASSID, &HYLC_MicroLineSearch));
  PetscCall(PetscClassIdRegister("HylcChol", &HYLC_CHOL_CLASSID));
  PetscCall(PetscLogEventRegister("CHOL_Symbolic", HYLC_CHOL_CLASSID, &HYLC_CholSymbolic));
  PetscCall(PetscLogEventRegister("CHOL_Numeric", HYLC_CHOL_CLASSID, &HYLC_CholNumeric));
  PetscCall(PetscLogEventRegister("CHOL_Solve", HYLC_CHOL_CLASSID, &HYLC_CholSolve));
  /* HylcChol as a PETSc solver type: -pc_factor_mat_solver_type hylc (include/hylc/chol.h) */
  PetscCall(MatInitializePackage()); /* PETSc's own solver types first: they stay the defaults */
  PetscCall(MatSolverTypeRegister(MATSOLVERHYLC, MATSEQAIJ, MAT_FACTOR_CHOLESKY, MatGetFactor_SeqAIJ_Hylc));
  PetscCall(PetscClassIdRegister("HylcMidsurface", &HYLC_MIDSURFACE_CLASSID));
  PetscCall(PetscLogEventRegister("MACRO_SetUp", HYLC_MIDSURFACE_CLASSID, &HYLC_MacroSetUp));
  PetscCall(PetscLogEventRegister("MACRO_Poisson", HYLC_MIDSURFACE_CLASSID, &HYLC_MacroPoisson));
  PetscCall(PetscLogEventRegister("MACRO_Evaluate", HYLC_MIDSURFACE_CLASSID, &HYLC_MacroEvaluate));
  PetscCall(PetscClassIdRegister("HylcMaterial", &HYLC_MATERIAL_CLASSID));
  PetscCall(PetscLogEventRegister("MATERIAL_Load", HYLC_MATERIAL_CLASSID, &HYLC_MaterialLoad));
  PetscCall(PetscLogEventRegister("MATERIAL_Write", HYLC_MATERIAL_CLASSID, &HYLC_MaterialWrite));
  PetscCall(PetscClassIdRegister("HylcFit", &HYLC_FIT_CLASSID));
  PetscCall(PetscLogEventRegister("FIT_Run", HYLC_FIT_CLASSID, &HYLC_FitRun));
  PetscCall(PetscLogEventRegister("FIT_Term", HYLC_FIT_CLASSID, &HYLC_FitTerm));
  PetscCall(PetscLogEventRegister("FIT_MLS", HYLC_FIT_CLASSID, &HYLC_FitMLS));
  PetscCall(PetscLogEventRegister("FIT_Monotone", HYLC_FIT_CLASSID, &HYLC_FitMonotone));
  PetscCall(PetscClassIdRegister("HylcCalibrate", &HYLC_CALIBRATE_CLASSID));
  PetscCall(PetscLogEventRegister("CALIB_SetUp", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateSetUp));
  PetscCall(PetscLogEventRegister("CALIB_Solve", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateSolve));
  PetscCall(PetscLogEventRegister("CALIB_Evaluate", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateEvaluate));
  PetscCall(PetscLogEventRegister("CALIB_Gather", HYLC_CALIBRATE_CLASSID, &HYLC_CalibrateGather));
  PetscCall(HylcMetisRegister());
  PetscCall(PetscRegisterFinalize(HylcFinalizePackage));
  PetscFunctionReturn(PETSC_SUCCESS);
}
