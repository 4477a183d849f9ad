/* The options of every hylc program, by stage, so that each program can read the whole study's options
   file (config/satin.yaml gives -pattern_*, -yarn_*, -sampler_* and -fit_* options together): an option
   no one read is ignored when it belongs to a stage of another program only; any other unread option (a
   misspelt one, or one of this program's stages it did not read) is an error (HylcCheckOptionsUsed()).

   A new option of a stage is added to its group below; tests/regression/options_stages.sh checks that
   every hylc option a program lists in -help is known here and accepted by every other program. */
#include <hylc/private/sysimpl.h>
#include <string.h>
#include <strings.h>

enum {
  G_PATTERN   = 1 << 0,  /* HylcPatternSetFromOptions() */
  G_PATTOOL   = 1 << 1,  /* hylc-pattern's outputs */
  G_YARN      = 1 << 2,  /* HylcYarnModelSetFromOptions() */
  G_MICRO     = 1 << 3,  /* HylcMicroSetFromOptions(): the solver, its SNES/KSP/PC, the periodic tile, METIS */
  G_REFERENCE = 1 << 4,  /* the reference state (hylc-sample, hylc-calibrate) */
  G_PLAN      = 1 << 5,  /* the sampling plan's family and ranges (hylc-sample, hylc-calibrate) */
  G_SAMPLER   = 1 << 6,  /* the sampling job (hylc-sample) */
  G_SOLVE     = 1 << 7,  /* hylc-solve's strain and outputs */
  G_FIT       = 1 << 8,  /* HylcFitSetFromOptions() */
  G_EVAL      = 1 << 9,  /* hylc-eval and HylcMaterialSetFromOptions() */
  G_CALIBRATE = 1 << 10, /* HylcCalibrateSetFromOptions() */
  G_CLOTH     = 1 << 11  /* HylcClothSetFromOptions(): the cloth and its PETSc solvers */
};

/* an option name, or a prefix when it ends with '*' (the PETSc solvers a stage embeds) */
typedef struct {
  const char *name;
  unsigned    groups;
} HylcStageOption;

static const HylcStageOption HylcStageOptions[] = {
    /* pattern */
    {"pattern_consistent_periods", G_PATTERN},
    {"pattern_course", G_PATTERN},
    {"pattern_density", G_PATTERN},
    {"pattern_depth", G_PATTERN},
    {"pattern_exclude_arc", G_PATTERN},
    {"pattern_file", G_PATTERN},
    {"pattern_gap", G_PATTERN},
    {"pattern_radius", G_PATTERN},
    {"pattern_seglen", G_PATTERN},
    {"pattern_size", G_PATTERN},
    {"pattern_spacing", G_PATTERN},
    {"pattern_type", G_PATTERN},
    {"pattern_wale", G_PATTERN},
    {"pattern_output", G_PATTOOL},
    {"pattern_vtk", G_PATTOOL},
    {"pattern_vtk_tiles", G_PATTOOL},
    /* yarn model */
    {"yarn_E", G_YARN},
    {"yarn_Es", G_YARN},
    {"yarn_G", G_YARN},
    {"yarn_contact_points", G_YARN},
    {"yarn_contact_type", G_YARN},
    {"yarn_curvature", G_YARN},
    {"yarn_exclude_arc", G_YARN},
    {"yarn_kc", G_YARN},
    {"yarn_radius", G_YARN},
    /* microscale solver, its PETSc sub-solvers, the periodic tile, the macro midsurface, METIS */
    {"micro_alpha_end", G_MICRO},
    {"micro_alpha_factor", G_MICRO},
    {"micro_alpha_fallback", G_MICRO},
    {"micro_alpha_its", G_MICRO},
    {"micro_alpha_max", G_MICRO},
    {"micro_alpha_min", G_MICRO},
    {"micro_alpha_retries", G_MICRO},
    {"micro_alpha_schedule", G_MICRO},
    {"micro_alpha_start", G_MICRO},
    {"micro_alpha_switch", G_MICRO},
    {"micro_atol", G_MICRO},
    {"micro_ctol", G_MICRO},
    {"micro_factor_indefinite", G_MICRO},
    {"micro_factor_type", G_MICRO}, /* removed: an error naming its replacement where the solver is read */
    {"micro_ls_factor", G_MICRO},
    {"micro_ls_max", G_MICRO},
    {"micro_max_stalls", G_MICRO},
    {"micro_max_time", G_MICRO},
    {"micro_rtol", G_MICRO},
    {"micro_saddle_escapes", G_MICRO},
    {"micro_saddle_test", G_MICRO},
    {"micro_saddle_tol", G_MICRO},
    {"micro_step_clearance", G_MICRO},
    {"micro_step_p0", G_MICRO},
    {"micro_step_p1", G_MICRO},
    {"micro_twist_scale", G_MICRO},
    {"micro_uniaxial_fd_step", G_MICRO},
    {"micro_uniaxial_gradient", G_MICRO},
    {"micro_uniaxial_gtol", G_MICRO},
    {"micro_uniaxial_max_it", G_MICRO},
    {"micro_uniaxial_max_step", G_MICRO},
    {"micro_uniaxial_rtol", G_MICRO},
    {"micro_uniaxial_xtol", G_MICRO},
    {"micro_view", G_MICRO},
    {"micro_snes_*", G_MICRO},
    {"micro_ksp_*", G_MICRO},
    {"micro_pc_*", G_MICRO},
    {"micro_factor_pc_*", G_MICRO},
    {"micro_factor_mat_*", G_MICRO},
    {"periodic_constraint_rtol", G_MICRO},
    {"periodic_margin", G_MICRO},
    {"periodic_pair_margin", G_MICRO},
    {"periodic_slide", G_MICRO},
    {"periodic_view", G_MICRO},
    {"macro_grid", G_MICRO},
    {"macro_interp", G_MICRO},
    {"macro_normal", G_MICRO},
    {"macro_phi", G_MICRO},
    {"hylc_metis_compress", G_MICRO},
    {"hylc_metis_nseps", G_MICRO},
    {"hylc_metis_seed", G_MICRO},
    {"hylc_metis_ufactor", G_MICRO},
    /* reference state */
    {"reference_bounds", G_REFERENCE},
    {"reference_etol", G_REFERENCE},
    {"reference_kind", G_REFERENCE},
    {"reference_max_evals", G_REFERENCE},
    {"reference_max_rounds", G_REFERENCE},
    {"reference_minimum", G_REFERENCE},
    {"reference_output", G_REFERENCE},
    {"reference_stress_free", G_REFERENCE},
    {"reference_tension", G_REFERENCE},
    {"reference_xtol", G_REFERENCE},
    /* sampling plan and job */
    {"sampler_family", G_PLAN},
    {"sampler_range_sx", G_PLAN},
    {"sampler_spacing", G_PLAN},
    {"sampler_graded_h0", G_PLAN},
    {"sampler_graded_growth", G_PLAN},
    {"sampler_graded_hmax", G_PLAN},
    {"sampler_graded_sub", G_PLAN},
    {"sampler_range_sa", G_PLAN},
    {"sampler_range_sy", G_PLAN},
    {"sampler_range_II00", G_PLAN},
    {"sampler_range_II11", G_PLAN},
    {"sampler_batch", G_SAMPLER},
    {"sampler_both_rtol", G_SAMPLER},
    {"sampler_stress", G_SAMPLER},
    {"sampler_density", G_SAMPLER},
    {"sampler_export_raw", G_SAMPLER},
    {"sampler_n1", G_SAMPLER},
    {"sampler_n2", G_SAMPLER},
    {"sampler_output", G_SAMPLER},
    {"sampler_overwrite", G_SAMPLER},
    {"sampler_progress", G_SAMPLER},
    {"sampler_reference", G_SAMPLER},
    {"sampler_resume", G_SAMPLER},
    {"sampler_start", G_SAMPLER},
    {"sampler_terms", G_SAMPLER},
    {"sampler_view", G_SAMPLER},
    /* one solve */
    {"strain", G_SOLVE | G_EVAL},
    {"solve_output", G_SOLVE},
    {"solve_uniaxial", G_SOLVE},
    {"solve_uniaxial_csv", G_SOLVE},
    {"solve_path", G_SOLVE},
    {"solve_path_angle", G_SOLVE},
    {"solve_path_values", G_SOLVE},
    {"solve_path_csv", G_SOLVE},
    {"solve_uniaxial_strains", G_SOLVE},
    {"solve_vtk", G_SOLVE},
    {"solve_vtk_tiles", G_SOLVE},
    /* fit */
    {"fit_compat", G_FIT},
    {"fit_density", G_FIT},
    {"fit_end_slope", G_FIT},
    {"fit_family", G_FIT},
    {"fit_fd_eps", G_FIT},
    {"fit_flat_tol", G_FIT},
    {"fit_input", G_FIT},
    {"fit_json", G_FIT},
    {"fit_knots", G_FIT},
    {"fit_method", G_FIT},
    {"fit_fabric_floor", G_FIT},
    {"fit_fabric_ridge", G_FIT},
    {"fit_fabric_reg", G_FIT},
    {"fit_fabric_passes", G_FIT},
    {"fit_knots1d", G_FIT},
    {"fit_knots1d_factor", G_FIT},
    {"fit_knots2d_bend_factor", G_FIT},
    {"fit_knots2d_bend_stretch", G_FIT},
    {"fit_knots2d_bend_symmetric", G_FIT},
    {"fit_knots2d_factor", G_FIT},
    {"fit_knots2d_poisson", G_FIT},
    {"fit_knots2d_stretch", G_FIT},
    {"fit_knots2d_symmetric", G_FIT},
    {"fit_knots_kernel_samples", G_FIT},
    {"fit_knots_kernel_spacing", G_FIT},
    {"fit_knots_refine", G_FIT},
    {"fit_min_samples_1d", G_FIT},
    {"fit_min_samples_2d", G_FIT},
    {"fit_mls_grow", G_FIT},
    {"fit_mls_kernel", G_FIT},
    {"fit_mls_truncation", G_FIT},
    {"fit_monotone_rule", G_FIT},
    {"fit_output", G_FIT},
    {"fit_quasiconvex", G_FIT},
    {"fit_raw_n1", G_FIT},
    {"fit_raw_n2", G_FIT},
    {"fit_reg", G_FIT},
    {"fit_symmetrize_sa", G_FIT},
    {"fit_terms", G_FIT},
    {"fit_yarn_density", G_FIT},
    {"fit_zero_compression", G_FIT},
    {"fit_zero_compression_strict", G_FIT},
    /* evaluation of a material table */
    {"material", G_EVAL},
    {"material_file", G_EVAL},
    {"material_view", G_EVAL},
    {"derivatives", G_EVAL},
    {"eval_hdf5", G_EVAL},
    {"eval_input", G_EVAL},
    {"eval_json", G_EVAL},
    {"eval_output", G_EVAL},
    {"eval_uniaxial", G_EVAL},
    {"eval_uniaxial_csv", G_EVAL},
    {"eval_path", G_EVAL},
    {"eval_path_angle", G_EVAL},
    {"eval_path_values", G_EVAL},
    {"eval_path_csv", G_EVAL},
    {"eval_uniaxial_strains", G_EVAL},
    {"eval_sheet", G_EVAL},
    {"eval_sheet_curvatures", G_EVAL},
    {"eval_sheet_energy", G_EVAL},
    {"eval_sheet_json", G_EVAL},
    {"eval_sheet_strains", G_EVAL},
    {"eval_measured_json", G_EVAL},
    {"measured", G_EVAL},
    /* calibration */
    {"calibrate_bounds_E", G_CALIBRATE},
    {"calibrate_bounds_Es", G_CALIBRATE},
    {"calibrate_bounds_G", G_CALIBRATE},
    {"calibrate_bounds_kc", G_CALIBRATE},
    {"calibrate_dump", G_CALIBRATE},
    {"calibrate_fatol", G_CALIBRATE},
    {"calibrate_flat_tol", G_CALIBRATE},
    {"calibrate_ftol", G_CALIBRATE},
    {"calibrate_lambda", G_CALIBRATE},
    {"calibrate_max_it", G_CALIBRATE},
    {"calibrate_max_reject", G_CALIBRATE}, /* removed: an error naming its replacement (TAO) */
    {"calibrate_tao_*", G_CALIBRATE},
    {"calibrate_max_samples", G_CALIBRATE},
    {"calibrate_n", G_CALIBRATE},
    {"calibrate_n2", G_CALIBRATE},
    {"calibrate_output", G_CALIBRATE},
    {"calibrate_params", G_CALIBRATE},
    {"calibrate_reference", G_CALIBRATE},
    {"calibrate_start", G_CALIBRATE},
    {"calibrate_stationary", G_CALIBRATE},
    {"calibrate_stationary_h", G_CALIBRATE},
    {"calibrate_stationary_jacobian", G_CALIBRATE},
    {"calibrate_stride", G_CALIBRATE},
    {"calibrate_target", G_CALIBRATE},
    {"calibrate_target_type", G_CALIBRATE},
    {"calibrate_terms", G_CALIBRATE},
    {"calibrate_tie", G_CALIBRATE},
    {"calibrate_view", G_CALIBRATE},
    {"calibrate_weight_zero", G_CALIBRATE},
    {"calibrate_weights", G_CALIBRATE},
    {"calibrate_xtol", G_CALIBRATE},
    /* the cloth (hylc-cloth) and its embedded solvers */
    {"cloth_angle", G_CLOTH},
    {"cloth_atol", G_CLOTH},
    {"cloth_dynamic", G_CLOTH},
    {"cloth_dt", G_CLOTH},
    {"cloth_dt_max", G_CLOTH},
    {"cloth_damping", G_CLOTH},
    {"cloth_tmax", G_CLOTH},
    {"cloth_rest_tol", G_CLOTH},
    {"cloth_rest_rtol", G_CLOTH},
    {"cloth_vtk_dt", G_CLOTH},
    {"cloth_barrier_distance", G_CLOTH},
    {"cloth_barrier_stiffness", G_CLOTH},
    {"cloth_cantilever_angle", G_CLOTH},
    {"cloth_cantilever_n", G_CLOTH},
    {"cloth_cantilever_width", G_CLOTH},
    {"cloth_direction", G_CLOTH},
    {"cloth_drape_diameter", G_CLOTH},
    {"cloth_drape_disc", G_CLOTH},
    {"cloth_face", G_CLOTH},
    {"cloth_gravity", G_CLOTH},
    {"cloth_h", G_CLOTH},
    {"cloth_hessian", G_CLOTH},
    {"cloth_length", G_CLOTH},
    {"cloth_linesearch_monitor", G_CLOTH},
    {"cloth_load_steps", G_CLOTH},
    {"cloth_material", G_CLOTH},
    {"cloth_max_it", G_CLOTH},
    {"cloth_mesh_file", G_CLOTH},
    {"cloth_mesh_scale", G_CLOTH},
    {"cloth_monitor", G_CLOTH},
    {"cloth_output", G_CLOTH},
    {"cloth_planar", G_CLOTH},
    {"cloth_plot", G_CLOTH},
    {"cloth_plot_script", G_CLOTH},
    {"cloth_rim_radius", G_CLOTH},
    {"cloth_rtol", G_CLOTH},
    {"cloth_scene_clamp", G_CLOTH},
    {"cloth_scene_corners", G_CLOTH},
    {"cloth_solver", G_CLOTH},
    {"cloth_strain_max", G_CLOTH},
    {"cloth_strain_steps", G_CLOTH},
    {"cloth_test", G_CLOTH},
    {"cloth_view", G_CLOTH},
    {"cloth_vtk", G_CLOTH},
    {"cloth_width", G_CLOTH},
    {"cloth_snes_*", G_CLOTH},
    {"cloth_ksp_*", G_CLOTH},
    {"cloth_pc_*", G_CLOTH},
    {"cloth_tao_*", G_CLOTH},
};

/* the stages each program reads */
static const struct {
  const char *program;
  unsigned    groups;
} HylcPrograms[] = {
    {"hylc-pattern", G_PATTERN | G_PATTOOL},
    {"hylc-solve", G_PATTERN | G_YARN | G_MICRO | G_SOLVE},
    {"hylc-sample", G_PATTERN | G_YARN | G_MICRO | G_REFERENCE | G_PLAN | G_SAMPLER},
    {"hylc-fit", G_FIT},
    {"hylc-eval", G_EVAL},
    {"hylc-calibrate", G_PATTERN | G_YARN | G_MICRO | G_REFERENCE | G_PLAN | G_CALIBRATE},
    {"hylc-cloth", G_CLOTH},
};

static char HylcProgram[64] = "";

/*@C
  HylcSetProgramName - Records the name of the running program (the last component of argv[0]; called by
  HylcInitialize()), which decides the stages whose options it reads (HylcOptionIsOtherStage()). Not
  collective.

  Input Parameter:
. name - the program's path or name; NULL or "" for none

  Level: developer
@*/
PetscErrorCode HylcSetProgramName(const char name[])
{
  const char *base = name ? strrchr(name, '/') : NULL;

  PetscFunctionBegin;
  PetscCall(PetscStrncpy(HylcProgram, base ? base + 1 : name ? name : "", sizeof(HylcProgram)));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the groups of the option name (without its dash), 0 if no stage reads it */
static unsigned HylcOptionGroups(const char name[])
{
  unsigned g = 0;

  for (size_t i = 0; i < sizeof(HylcStageOptions) / sizeof(HylcStageOptions[0]); i++) {
    const char  *e = HylcStageOptions[i].name;
    const size_t n = strlen(e);
    if (e[n - 1] == '*' ? !strncasecmp(name, e, n - 1) && name[n - 1] : !strcasecmp(name, e)) g |= HylcStageOptions[i].groups;
  }
  return g;
}

/*@C
  HylcOptionIsOtherStage - Whether an option belongs to the stages of other hylc programs only: an
  option of the whole study's options file that this program may ignore. A misspelt option, or one of
  this program's own stages, is not. A program not among hylc's (a test, an example) has no stages of its
  own: every hylc option is another stage's. Not collective.

  Input Parameter:
. name - the option name, with or without its leading dash (case is ignored, as PETSc does)

  Output Parameter:
. other - PETSC_TRUE if only other programs read it

  Level: developer

.seealso: HylcCheckOptionsUsed(), HylcSetProgramName()
@*/
PetscErrorCode HylcOptionIsOtherStage(const char name[], PetscBool *other)
{
  unsigned own = 0, g;

  PetscFunctionBegin;
  PetscCheck(other, PETSC_COMM_SELF, PETSC_ERR_ARG_NULL, "other: a NULL pointer");
  *other = PETSC_FALSE;
  if (!name) PetscFunctionReturn(PETSC_SUCCESS);
  while (*name == '-') name++;
  g = HylcOptionGroups(name);
  for (size_t i = 0; i < sizeof(HylcPrograms) / sizeof(HylcPrograms[0]); i++)
    if (!strcmp(HylcProgram, HylcPrograms[i].program)) own = HylcPrograms[i].groups;
  *other = (PetscBool)(g && !(g & own));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int HylcOptionIsHylc_Private(const char name[])
{
  for (size_t i = 0; i < sizeof(HylcStageOptions) / sizeof(HylcStageOptions[0]); i++) {
    const char  *e = HylcStageOptions[i].name;
    const size_t n = strlen(e);
    if (e[n - 1] != '*' && !strcasecmp(name, e)) return 1;
  }
  return 0;
}
