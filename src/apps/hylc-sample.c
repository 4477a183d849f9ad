static const char help[] = "hylc-sample: the sampling job of Algorithm C4 -- microscale solves of a periodic yarn tile over\n"
                           "the sampled strains, distributed over MPI ranks, written to HDF5.\n\n"
                           "  mpirun -n 4 hylc-sample -options_file config/satin.yaml -sampler_output satin.h5\n"
                           "  mpirun -n 4 hylc-sample -options_file config/satin.yaml -sampler_output satin.h5 -sampler_resume\n"
                           "  hylc-sample -pattern_type plain -sampler_terms zero,sx -sampler_n1 10   (a quick run)\n\n";

#include <hylc/sampler.h>

/* the work of hylc-sample on S (created and destroyed by Run, also on an error) */
static PetscErrorCode Sample(HylcSampler S)
{
  PetscBool help_only;

  PetscFunctionBeginUser;
  PetscCall(HylcSamplerSetFromOptions(S));
  PetscCall(PetscOptionsHasHelp(NULL, &help_only));
  if (!help_only) { /* -help: every option has been listed; do no work */
    PetscCall(HylcSamplerSetUp(S));
    PetscCall(HylcSamplerRun(S));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcSampler    S;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcSamplerCreate(PETSC_COMM_WORLD, &S));
  ierr = Sample(S);
  PetscCall(HylcSamplerDestroy(&S)); /* also on an error: nothing leaks */
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
