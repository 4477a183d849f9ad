#pragma once
/* Internals of src/sys shared between its files. */
#include <hylc/sys.h>

/* -help sorted, hylc's options first (src/sys/help.c): HylcInitialize() captures PETSc's help printer
   before PetscInitialize(), HylcMainFinalize() prints it */
PETSC_INTERN void HylcHelpCapture(int, char **);
PETSC_INTERN void HylcHelpFlush(void);
/* whether the option name (without its dash) is one of hylc's stages' own, by its exact name (not a
   PETSc solver's option under a hylc prefix; src/sys/programs.c) */
PETSC_INTERN int HylcOptionIsHylc_Private(const char[]);
