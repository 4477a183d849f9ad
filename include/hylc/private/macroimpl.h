#pragma once
/* Private definition of HylcMidsurface: only src/ may include this. */
#include <hylc/macro.h>
#include <petsc/private/petscimpl.h>
#include <petscdmda.h>
#include <petscksp.h>

struct _HylcMidsurfaceOps {
  PetscErrorCode (*view)(HylcMidsurface, PetscViewer);
};

struct _p_HylcMidsurface {
  PETSCHEADER(struct _HylcMidsurfaceOps);
  /* settings */
  HylcMidsurfaceType   type;     /* requested */
  HylcMidsurfaceType   resolved; /* closed or poisson, after SetUp */
  HylcMidsurfaceInterp interp;
  HylcMidsurfaceNormal normal;
  PetscInt             grid; /* nodes per direction */
  PetscReal            lo[2], hi[2];
  PetscBool            hasStrain, setupcalled;
  HylcMacroStrain      strain;
  /* Poisson grid: node (i, j) at origin + (i h0, j h1), i < M[0], j < M[1] */
  DM         da;
  Mat        A;
  KSP        ksp;
  PetscInt   M[2];
  PetscReal  origin[2], h[2];
  PetscReal *phi;  /* 3 per node, node index j M[0] + i */
  PetscReal *grad; /* 6 per node: FD gradient dphi_i/dxi_alpha at [2 i + alpha] (polar normals) */
  PetscInt   its;  /* KSP iterations, summed over the three components */
};

/* Poisson grid: build and solve (poisson.c). */
PETSC_INTERN PetscErrorCode HylcMidsurfacePoissonSetUp_Private(HylcMidsurface);
PETSC_INTERN PetscErrorCode HylcMidsurfacePoissonReset_Private(HylcMidsurface);
/* Interpolates ncomp components per node of field at xi. Not collective. */
PETSC_INTERN void HylcMidsurfaceInterpolate_Private(HylcMidsurface, const PetscReal *, PetscInt, const PetscReal[2], PetscReal[]);
/* Rotation minimizing |R S - F| over SO(3) for a 3x2 F (polar decomposition of F A^T). Returns -1 if F is
   rank deficient. */
PETSC_INTERN int HylcMacroPolarRotation(const double S[6], const double F[6], double R[9]);
