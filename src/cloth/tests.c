/* The virtual standard tests of HylcCloth (docs/fabric.md): strip tensile, the table's homogeneous
   uniaxial curve, and the helpers they share (the specimen strip, the central zone, clamps by region). */
#include <hylc/private/clothimpl.h>
#include <math.h>

/* the vertices of the rest mesh inside the box [x0, x1] x [y0, y1] (any z) */
PetscErrorCode HylcClothVerticesInBox_Private(HylcCloth c, PetscReal x0, PetscReal x1, PetscReal y0, PetscReal y1, PetscInt *n, PetscInt **v)
{
  PetscFunctionBegin;
  *n = 0;
  PetscCall(PetscMalloc1(c->nv, v));
  for (PetscInt i = 0; i < c->nv; i++) {
    const PetscReal *p = c->X + 3 * i;
    if (p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1) (*v)[(*n)++] = i;
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a strip specimen [x0, x0 + L] x [0, W], material x at angle (degrees) to the length, face down or up;
   the clamps are reset */
PetscErrorCode HylcClothStrip_Private(HylcCloth c, PetscReal x0, PetscReal L, PetscReal W, PetscReal h, PetscReal angle, PetscBool faceDown)
{
  PetscFunctionBegin;
  PetscCall(HylcClothSolverReset_Private(c));
  PetscCall(HylcClothClampsReset_Private(c));
  PetscCall(HylcClothMeshStrip_Private(c, x0, L, W, h));
  PetscCall(HylcClothMeshMaterial_Private(c, angle * PETSC_PI / 180, faceDown));
  c->nsupport = 0;
  c->load     = 0;
  c->gscale   = 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* lays out the mesh over the ranks and sets the tolerances that depend on its size; x = rest */
PetscErrorCode HylcClothPrepare_Private(HylcCloth c)
{
  PetscReal W = c->rhoA * c->gravity * c->area;

  PetscFunctionBegin;
  PetscCall(HylcClothBuild_Private(c));
  c->Escale = PetscMax(W * PetscSqrtReal(c->area), hylcmat_constant(c->hm) * c->area);
  if (c->atol < 0)
    c->atolUsed = PetscMax(1e-14 * W, 1e-16);
  else
    c->atolUsed = c->atol;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* area-weighted mean strains of the triangles whose rest centroids lie in the box */
PetscErrorCode HylcClothZoneMean_Private(HylcCloth c, const PetscReal *z, PetscReal x0, PetscReal x1, PetscReal y0, PetscReal y1, PetscReal mean[6])
{
  PetscReal A = 0;

  PetscFunctionBegin;
  for (int k = 0; k < 6; k++) mean[k] = 0;
  for (PetscInt t = 0; t < c->nt; t++) {
    const PetscInt  *v  = c->tri + 3 * t;
    PetscReal        cx = (c->X[3 * v[0]] + c->X[3 * v[1]] + c->X[3 * v[2]]) / 3, cy = (c->X[3 * v[0] + 1] + c->X[3 * v[1] + 1] + c->X[3 * v[2] + 1]) / 3;
    const PetscReal *u = c->uv + 6 * t;
    PetscReal        a = 0.5 * ((u[2] - u[0]) * (u[5] - u[1]) - (u[4] - u[0]) * (u[3] - u[1]));
    if (cx < x0 || cx > x1 || cy < y0 || cy > y1) continue;
    for (int k = 0; k < 6; k++) mean[k] += a * z[6 * t + k];
    A += a;
  }
  PetscCheck(A > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the central zone holds no triangle");
  for (int k = 0; k < 6; k++) mean[k] /= A;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* y(x) at x by linear interpolation in the table (xs increasing) */
/* a figure of the summary, or "not reached" where the curve ends before its strain (no NaN printed) */
static const char *Fig(char buf[48], PetscReal v, const char unit[])
{
  if (PetscIsInfOrNanReal(v)) return "not reached";
  snprintf(buf, 48, "%.6g%s%s", (double)v, unit[0] ? " " : "", unit);
  return buf;
}

static PetscReal Interp(PetscInt n, const PetscReal *xs, const PetscReal *ys, PetscReal x)
{
  if (n < 2 || x < xs[0] - 1e-12 || x > xs[n - 1] + 1e-12) return (PetscReal)NAN; /* no extrapolation */
  for (PetscInt i = 0; i + 1 < n; i++)
    if (x <= xs[i + 1] || i + 2 == n) return ys[i] + (ys[i + 1] - ys[i]) * (x - xs[i]) / (xs[i + 1] - xs[i]);
  return ys[n - 1];
}

/* the derivative dy/dx at x from the table (central difference of the neighbouring points) */
static PetscReal Slope(PetscInt n, const PetscReal *xs, const PetscReal *ys, PetscReal x)
{
  PetscReal h = n > 1 ? xs[1] - xs[0] : 1;
  return (Interp(n, xs, ys, x + h) - Interp(n, xs, ys, x - h)) / (2 * h);
}

static PetscErrorCode DirectionList(HylcCloth c, PetscInt *n, PetscInt dirs[2])
{
  PetscFunctionBegin;
  *n = 0;
  if (c->direction != HYLC_CLOTH_DIR_Y) dirs[(*n)++] = 0;
  if (c->direction != HYLC_CLOTH_DIR_X) dirs[(*n)++] = 1;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Strip tensile (ISO 13934-1, docs/fabric.md): a strip of -cloth_length (gauge, 0.2 m) by -cloth_width
  (0.05 m), material x along its length (direction x) or across it (y), gripped over the full width at
  both ends; the right grip moves to each nominal strain. Per step: T = the grip's force / width (N/m),
  the central zone's strains (middle fifth of the length, middle half of the width), its Poisson ratio,
  and the table's homogeneous uniaxial state at the central zone's strain (hylcmat_uniaxial): T_table and
  the lateral strain. CSV columns: direction, face, step, strain, T, central_strain, lateral_strain,
  poisson, T_table, lateral_table, T_rel_diff, newton_its.
*/
PetscErrorCode HylcClothRunTensile_Private(HylcCloth c)
{
  MPI_Comm      comm = CLOTH_COMM_PRIVATE(c);
  PetscInt      ndir, dirs[2];
  HylcClothText csv = {0};
  char          path[PETSC_MAX_PATH_LEN + 64];
  PetscReal     L = c->length, W = c->width;

  PetscFunctionBegin;
  PetscCall(DirectionList(c, &ndir, dirs));
  PetscCall(HylcClothTextAppend_Private(&csv, "direction,face,step,strain,T_N_per_m,central_strain,lateral_strain,poisson,T_table,lateral_table,T_rel_diff,newton_its\n"));
  for (PetscInt id = 0; id < ndir; id++) {
    PetscInt   d = dirs[id], n, *v, ns = c->strainSteps;
    PetscReal  angle = c->angle > -360 ? c->angle : (d ? 90.0 : 0.0), disp[3] = {c->strainMax * L, 0, 0}, *z, *eps, *T, *lat, maxrel = 0, maxdlat = 0;
    PetscBool  faceDown = c->face == HYLC_CLOTH_FACE_DOWN ? PETSC_TRUE : PETSC_FALSE;
    const char dn[2][2] = {"x", "y"}, *fn = faceDown ? "down" : "up";
    char       name[64];

    PetscCall(HylcClothStrip_Private(c, 0, L, W, c->h, angle, faceDown));
    PetscCall(HylcClothVerticesInBox_Private(c, -1, 1e-9 * L, -1, 2 * W, &n, &v));
    PetscCall(HylcClothAddClamp_Private(c, n, v, NULL, PETSC_FALSE));
    PetscCall(PetscFree(v));
    PetscCall(HylcClothVerticesInBox_Private(c, L * (1 - 1e-9), 2 * L, -1, 2 * W, &n, &v));
    PetscCall(HylcClothAddClamp_Private(c, n, v, disp, PETSC_FALSE));
    PetscCall(PetscFree(v));
    PetscCall(HylcClothPrepare_Private(c));
    PetscCall(PetscPrintf(comm, "tensile %s (material angle %g deg, face %s): %" PetscInt_FMT " vertices, %" PetscInt_FMT " triangles, %g x %g m\n", dn[d], (double)angle, fn, c->nv, c->nt, (double)L, (double)W));
    PetscCall(PetscMalloc4(6 * c->nt, &z, ns + 1, &eps, ns + 1, &T, ns + 1, &lat));
    eps[0] = T[0] = lat[0] = 0;
    if (c->gravity > 0) { /* the strip's own weight first */
      PetscBool ok;
      c->gscale = 0;
      PetscCall(HylcClothLoadPath_Private(c, 0, 1, c->loadSteps > 0 ? c->loadSteps : 4, &ok));
      PetscCheck(ok, comm, PETSC_ERR_NOT_CONVERGED, "tensile %s: no equilibrium under gravity", dn[d]);
    }
    for (PetscInt k = 1; k <= ns; k++) {
      PetscReal F[3], zc[6], Tt = 0, lt = 0, rel;
      PetscBool ok;
      PetscInt  its0 = c->newtonIts, dm = ((PetscInt)PetscFloorReal(angle / 90 + 0.5) % 2 + 2) % 2;
      int       rc;
      PetscCall(HylcClothLoadPath_Private(c, (PetscReal)k / ns, 1, 1, &ok));
      if (!ok) { /* a result, not an error: the curve ends here */
        PetscCall(PetscPrintf(comm, "  no equilibrium found at strain %g: the curve ends at %g\n", (double)(c->strainMax * k / ns), (double)eps[k - 1]));
        ns = k - 1;
        break;
      }
      PetscCall(HylcClothReaction_Private(c, c->x, 1, F));
      PetscCall(HylcClothStrains_Private(c, c->x, z));
      PetscCall(HylcClothZoneMean_Private(c, z, 0.4 * L, 0.6 * L, 0.25 * W, 0.75 * W, zc));
      eps[k] = c->strainMax * k / ns;
      T[k]   = F[0] / W;
      lat[k] = zc[dm ? 0 : 2];
      { /* the table's uniaxial state (hylcmat_uniaxial) at the zone's stretch, from the zone's lateral
           strains: the local minimum the strip is in (tables can have several) */
        hylcmat_uniaxial_state st;
        double                 guess[2] = {zc[1], zc[dm ? 0 : 2]};
        char                   err[256];
        rc = hylcmat_uniaxial(c->hm, (int)dm, zc[dm ? 2 : 0], guess, &st, err, sizeof(err));
        PetscCheck(rc == 0, comm, PETSC_ERR_LIB, "uniaxial state of the table at strain %g: %s", (double)zc[dm ? 2 : 0], err);
        Tt = st.T;
        lt = st.lateral[1];
      }
      rel = PetscAbsReal(T[k] - Tt) / PetscMax(PetscAbsReal(Tt), 1e-300);
      if (eps[k] >= 0.01 - 1e-12) {
        maxrel  = PetscMax(maxrel, rel);
        maxdlat = PetscMax(maxdlat, PetscAbsReal(lat[k] - lt));
      }
      PetscCall(HylcClothTextAppend_Private(&csv, "%s,%s,%" PetscInt_FMT ",%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.6g,%" PetscInt_FMT "\n", dn[d], fn, k, (double)eps[k], (double)T[k], (double)zc[dm ? 2 : 0], (double)lat[k],
                                            (double)(-lat[k] / zc[dm ? 2 : 0]), (double)Tt, (double)lt, (double)rel, c->newtonIts - its0));
      if (c->monitor) PetscCall(PetscPrintf(comm, "  strain %.4g: T %.6g N/m (table %.6g, %.3g %%), lateral %.6g (table %.6g)\n", (double)eps[k], (double)T[k], (double)Tt, (double)(100 * rel), (double)lat[k], (double)lt));
      PetscCall(PetscSNPrintf(name, sizeof(name), "tensile_%s_%04d.vtk", dn[d], (int)k));
      PetscCall(HylcClothOutputName_Private(c, name, path, sizeof(path)));
      PetscCall(HylcClothWriteVTK_Private(c, path));
    }
    {
      PetscReal nu[64];
      PetscInt  m = PetscMin(ns + 1, 64);
      char      r[32];
      for (PetscInt k = 0; k < m; k++) nu[k] = k ? -lat[k] / eps[k] : 0;
      PetscCheck(ns >= 1, comm, PETSC_ERR_NOT_CONVERGED, "tensile %s: no equilibrium at the first strain step %g", dn[d], (double)(c->strainMax / c->strainSteps));
      PetscCall(PetscSNPrintf(r, sizeof(r), "T5_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, Interp(ns + 1, eps, T, 0.05)));
      PetscCall(PetscSNPrintf(r, sizeof(r), "T10_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, Interp(ns + 1, eps, T, 0.10)));
      PetscCall(PetscSNPrintf(r, sizeof(r), "k5_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, Slope(ns + 1, eps, T, 0.05)));
      PetscCall(PetscSNPrintf(r, sizeof(r), "k10_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, Slope(ns + 1, eps, T, 0.10)));
      PetscCall(PetscSNPrintf(r, sizeof(r), "nu5_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, Interp(m, eps, nu, 0.05)));
      PetscCall(PetscSNPrintf(r, sizeof(r), "table_rel_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, maxrel));
      PetscCall(PetscSNPrintf(r, sizeof(r), "table_dlat_%s", dn[d]));
      PetscCall(HylcClothResult_Private(c, r, maxdlat));
      {
        char b[4][48];
        PetscCall(PetscPrintf(comm, "  T(5%%) %s, T(10%%) %s, dT/de(5%%) %s, Poisson(5%%) %s; central zone vs the table: T within %.3g %%, lateral strain within %.3g\n", Fig(b[0], Interp(ns + 1, eps, T, 0.05), "N/m"),
                              Fig(b[1], Interp(ns + 1, eps, T, 0.10), "N/m"), Fig(b[2], Slope(ns + 1, eps, T, 0.05), "N/m"), Fig(b[3], Interp(m, eps, nu, 0.05), ""), (double)(100 * maxrel), (double)maxdlat));
      }
    }
    PetscCall(PetscFree4(z, eps, T, lat));
  }
  PetscCall(PetscPrintf(comm, "Newton iterations: %" PetscInt_FMT " (%" PetscInt_FMT " exact, %" PetscInt_FMT " projected Hessians), line-search failures %" PetscInt_FMT "\n", c->newtonIts, c->hessExact, c->hessProj, c->lsFails));
  PetscCall(HylcClothOutputName_Private(c, "tensile.csv", path, sizeof(path)));
  PetscCall(HylcClothTextWrite_Private(c, &csv, path));
  PetscCall(HylcClothPlot_Private(c, "tensile", path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  The table's homogeneous uniaxial curves (no mesh): for each direction and strain, Psi minimized over
  sa and the lateral strain (hylcmat_uniaxial). The CSV is the uniaxial-curve format of docs/fabric.md:
  direction, strain, T_N_per_m, lateral_strain, sa, psi.
*/
PetscErrorCode HylcClothRunUniaxial_Private(HylcCloth c)
{
  MPI_Comm      comm = CLOTH_COMM_PRIVATE(c);
  PetscInt      ndir, dirs[2], ns = c->strainSteps;
  HylcClothText csv = {0};
  char          path[PETSC_MAX_PATH_LEN + 64];

  PetscFunctionBegin;
  PetscCall(DirectionList(c, &ndir, dirs));
  PetscCall(HylcClothTextAppend_Private(&csv, "# hylc uniaxial curve: source table %s\ndirection,strain,T_N_per_m,lateral_strain,sa,psi\n", c->materialFile[0] ? c->materialFile : "(in memory)"));
  for (PetscInt id = 0; id < ndir; id++) {
    PetscInt   d = dirs[id];
    PetscReal *eps, *T, *lat;
    char       r[32];
    PetscCall(PetscMalloc3(ns + 1, &eps, ns + 1, &T, ns + 1, &lat));
    hylcmat_uniaxial_state st = {0};
    for (PetscInt k = 0; k <= ns; k++) { /* along the loading path: each state from the previous one */
      double Tt, lt, sa, psi;
      char   err[256];
      int    rc = hylcmat_uniaxial(c->hm, (int)d, c->strainMax * k / ns, k ? st.lateral : NULL, &st, err, sizeof(err));
      PetscCheck(rc == 0, comm, PETSC_ERR_LIB, "uniaxial state of the table at strain %g: %s", (double)(c->strainMax * k / ns), err);
      Tt     = st.T;
      lt     = st.lateral[1];
      sa     = st.lateral[0];
      psi    = st.psi;
      eps[k] = c->strainMax * k / ns;
      T[k]   = Tt;
      lat[k] = k ? -lt / eps[k] : 0;
      PetscCall(HylcClothTextAppend_Private(&csv, "%s,%.10g,%.10g,%.10g,%.10g,%.10g\n", d ? "y" : "x", (double)eps[k], Tt, lt, sa, psi));
    }
    PetscCall(PetscSNPrintf(r, sizeof(r), "T5_%s", d ? "y" : "x"));
    PetscCall(HylcClothResult_Private(c, r, Interp(ns + 1, eps, T, 0.05)));
    PetscCall(PetscSNPrintf(r, sizeof(r), "T10_%s", d ? "y" : "x"));
    PetscCall(HylcClothResult_Private(c, r, Interp(ns + 1, eps, T, 0.10)));
    PetscCall(PetscSNPrintf(r, sizeof(r), "nu5_%s", d ? "y" : "x"));
    PetscCall(HylcClothResult_Private(c, r, Interp(ns + 1, eps, lat, 0.05)));
    {
      char b[3][48];
      PetscCall(PetscPrintf(comm, "uniaxial %s (table): T(5%%) %s, T(10%%) %s, Poisson(5%%) %s\n", d ? "y" : "x", Fig(b[0], Interp(ns + 1, eps, T, 0.05), "N/m"), Fig(b[1], Interp(ns + 1, eps, T, 0.10), "N/m"),
                            Fig(b[2], Interp(ns + 1, eps, lat, 0.05), "")));
    }
    PetscCall(PetscFree3(eps, T, lat));
  }
  PetscCall(HylcClothOutputName_Private(c, "uniaxial.csv", path, sizeof(path)));
  PetscCall(HylcClothTextWrite_Private(c, &csv, path));
  PetscCall(HylcClothPlot_Private(c, "uniaxial", path));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Bias extension (docs/fabric.md): a strip of -cloth_length (0.15 m) by -cloth_width (0.05 m) with the
  material x axis at -cloth_angle (45 degrees) to its length, gripped over the full width at both ends;
  the right grip moves to each nominal strain (extension / length). Per step: the grip's force F (N) and
  F / width (N/m); the central zone's (the middle fifth of the length, the middle half of the width)
  shear angle gamma = asin(|sa|) (degrees: how far the angle between the deformed material axes is from
  90, either way) and its
  strains along the axes; for reference the shear angle of the pin-jointed (inextensible yarn) kinematics
  of the central region, gamma = 90 - 2 acos((D + d) / (sqrt(2) D)) with D = length - width. CSV columns:
  step, strain, extension_m, force_N, F_per_width_N_per_m, shear_deg, shear_kinematic_deg, sx, sy,
  newton_its.
*/
PetscErrorCode HylcClothRunBias_Private(HylcCloth c)
{
  MPI_Comm      comm = CLOTH_COMM_PRIVATE(c);
  HylcClothText csv  = {0};
  char          path[PETSC_MAX_PATH_LEN + 64], name[64];
  PetscReal     L = c->length, W = c->width, angle = c->angle > -360 ? c->angle : 45.0, disp[3] = {c->strainMax * L, 0, 0}, *z, *eps, *F, *gam, D = L - W;
  PetscInt      n, *v, ns = c->strainSteps;
  PetscBool     faceDown = c->face == HYLC_CLOTH_FACE_DOWN ? PETSC_TRUE : PETSC_FALSE;

  PetscFunctionBegin;
  PetscCheck(L > W, comm, PETSC_ERR_USER_INPUT, "bias: -cloth_length %g m must exceed -cloth_width %g m (the central zone of pure shear)", (double)L, (double)W);
  PetscCall(HylcClothStrip_Private(c, 0, L, W, c->h, angle, faceDown));
  PetscCall(HylcClothVerticesInBox_Private(c, -1, 1e-9 * L, -1, 2 * W, &n, &v));
  PetscCall(HylcClothAddClamp_Private(c, n, v, NULL, PETSC_FALSE));
  PetscCall(PetscFree(v));
  PetscCall(HylcClothVerticesInBox_Private(c, L * (1 - 1e-9), 2 * L, -1, 2 * W, &n, &v));
  PetscCall(HylcClothAddClamp_Private(c, n, v, disp, PETSC_FALSE));
  PetscCall(PetscFree(v));
  PetscCall(HylcClothPrepare_Private(c));
  PetscCall(PetscPrintf(comm, "bias (material angle %g deg, face %s): %" PetscInt_FMT " vertices, %" PetscInt_FMT " triangles, %g x %g m\n", (double)angle, faceDown ? "down" : "up", c->nv, c->nt, (double)L, (double)W));
  PetscCall(HylcClothTextAppend_Private(&csv, "step,strain,extension_m,force_N,F_per_width_N_per_m,shear_deg,shear_kinematic_deg,sx,sy,newton_its\n"));
  PetscCall(PetscMalloc4(6 * c->nt, &z, ns + 1, &eps, ns + 1, &F, ns + 1, &gam));
  eps[0] = F[0] = gam[0] = 0;
  if (c->gravity > 0) {
    PetscBool ok;
    c->gscale = 0;
    PetscCall(HylcClothLoadPath_Private(c, 0, 1, c->loadSteps > 0 ? c->loadSteps : 4, &ok));
    PetscCheck(ok, comm, PETSC_ERR_NOT_CONVERGED, "bias: no equilibrium under gravity");
  }
  for (PetscInt k = 1; k <= ns; k++) {
    PetscReal Fr[3], zc[6], e = c->strainMax * k / ns, r = (D + e * L) / (PetscSqrtReal(2.0) * D), gk;
    PetscBool ok;
    PetscInt  its0 = c->newtonIts;
    PetscCall(HylcClothLoadPath_Private(c, (PetscReal)k / ns, 1, 1, &ok));
    if (!ok) {
      PetscCall(PetscPrintf(comm, "  no equilibrium found at strain %g: the curve ends at %g\n", (double)e, (double)eps[k - 1]));
      ns = k - 1;
      break;
    }
    PetscCall(HylcClothReaction_Private(c, c->x, 1, Fr));
    PetscCall(HylcClothStrains_Private(c, c->x, z));
    PetscCall(HylcClothZoneMean_Private(c, z, 0.4 * L, 0.6 * L, 0.25 * W, 0.75 * W, zc));
    eps[k] = e;
    F[k]   = Fr[0];
    gam[k] = PetscAsinReal(PetscMin(PetscAbsReal(zc[1]), 1.0)) * 180 / PETSC_PI;
    gk     = r < 1 ? 90 - 2 * PetscAcosReal(r) * 180 / PETSC_PI : (PetscReal)NAN; /* beyond: no pin-jointed state */
    PetscCall(HylcClothTextAppend_Private(&csv, "%" PetscInt_FMT ",%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%" PetscInt_FMT "\n", k, (double)e, (double)(e * L), (double)F[k], (double)(F[k] / W), (double)gam[k], (double)gk, (double)zc[0],
                                          (double)zc[2], c->newtonIts - its0));
    if (c->monitor) PetscCall(PetscPrintf(comm, "  strain %.4g: F %.6g N, shear angle %.4g deg (kinematic %.4g)\n", (double)e, (double)F[k], (double)gam[k], (double)gk));
    PetscCall(PetscSNPrintf(name, sizeof(name), "bias_%04d.vtk", (int)k));
    PetscCall(HylcClothOutputName_Private(c, name, path, sizeof(path)));
    PetscCall(HylcClothWriteVTK_Private(c, path));
  }
  PetscCheck(ns >= 1, comm, PETSC_ERR_NOT_CONVERGED, "bias: no equilibrium at the first strain step %g", (double)(c->strainMax / c->strainSteps));
  PetscCall(HylcClothResult_Private(c, "bias_F5", Interp(ns + 1, eps, F, 0.05)));
  PetscCall(HylcClothResult_Private(c, "bias_F_end", F[ns]));
  PetscCall(HylcClothResult_Private(c, "bias_shear_end", gam[ns]));
  PetscCall(PetscPrintf(comm, "  F(5%%) %.6g N (%.6g N/m), at strain %.4g: F %.6g N, central shear angle %.4g deg\n", (double)Interp(ns + 1, eps, F, 0.05), (double)(Interp(ns + 1, eps, F, 0.05) / W), (double)eps[ns], (double)F[ns], (double)gam[ns]));
  PetscCall(PetscPrintf(comm, "Newton iterations: %" PetscInt_FMT " (%" PetscInt_FMT " exact, %" PetscInt_FMT " projected Hessians), line-search failures %" PetscInt_FMT "\n", c->newtonIts, c->hessExact, c->hessProj, c->lsFails));
  PetscCall(PetscFree4(z, eps, F, gam));
  PetscCall(HylcClothOutputName_Private(c, "bias.csv", path, sizeof(path)));
  PetscCall(HylcClothTextWrite_Private(c, &csv, path));
  PetscCall(HylcClothPlot_Private(c, "bias", path));
  PetscFunctionReturn(PETSC_SUCCESS);
}
/* the shadow of the cloth seen from above: the largest radius of the projected edges (sampled at a
   quarter of a bin's arc) in each of nb angular bins (rmax, nb entries), its area sum(r^2 / 2) dtheta, and the nodes: the local maxima of
   rmax smoothed over 5 bins that stand out of their neighbourhood (+-nb/16 bins) by more than 2 % of the
   radius */
static PetscErrorCode DrapeShadow(HylcCloth c, PetscInt nb, PetscReal *rmax, PetscReal *area, PetscInt *nodes)
{
  PetscReal *sm;

  PetscFunctionBegin;
  PetscCall(HylcClothGather_Private(c, c->x));
  for (PetscInt b = 0; b < nb; b++) rmax[b] = 0;
  for (PetscInt t = 0; t < c->nt; t++) /* points along every edge: the outline of the shadow is made of edges */
    for (int e = 0; e < 3; e++) {
      const PetscReal *p = c->xgather + 3 * c->tri[3 * t + e], *q = c->xgather + 3 * c->tri[3 * t + (e + 1) % 3];
      PetscReal        len = PetscSqrtReal((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1])), rr = PetscMax(PetscSqrtReal(p[0] * p[0] + p[1] * p[1]), 1e-3);
      PetscInt         m = 1 + (PetscInt)PetscCeilReal(4 * len / (rr * 2 * PETSC_PI / nb));
      for (PetscInt k = 0; k <= m; k++) {
        PetscReal s = (PetscReal)k / m, x = p[0] + s * (q[0] - p[0]), y = p[1] + s * (q[1] - p[1]), r = PetscSqrtReal(x * x + y * y), th = PetscAtan2Real(y, x);
        PetscInt  b = ((PetscInt)PetscFloorReal((th + PETSC_PI) / (2 * PETSC_PI) * nb) % nb + nb) % nb;
        rmax[b]     = PetscMax(rmax[b], r);
      }
    }
  for (PetscInt b = 0; b < nb; b++) /* an empty bin (a coarse mesh): its neighbours' */
    if (rmax[b] == 0) rmax[b] = PetscMax(rmax[(b + nb - 1) % nb], rmax[(b + 1) % nb]);
  *area = 0;
  for (PetscInt b = 0; b < nb; b++) *area += 0.5 * rmax[b] * rmax[b] * 2 * PETSC_PI / nb;
  PetscCall(PetscMalloc1(nb, &sm));
  for (PetscInt b = 0; b < nb; b++) {
    sm[b] = 0;
    for (PetscInt k = -2; k <= 2; k++) sm[b] += rmax[(b + k + nb) % nb] / 5;
  }
  *nodes = 0;
  for (PetscInt b = 0; b < nb; b++) {
    PetscBool top = PETSC_TRUE;
    PetscReal lo  = sm[b];
    for (PetscInt k = -nb / 16; k <= nb / 16; k++) {
      PetscReal v = sm[(b + k + nb) % nb];
      if (v > sm[b] || (v == sm[b] && k < 0)) top = PETSC_FALSE;
      lo = PetscMin(lo, v);
    }
    if (top && sm[b] - lo > 0.02 * sm[b]) (*nodes)++;
  }
  PetscCall(PetscFree(sm));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*
  Cusick drape, static (docs/fabric.md): a disc specimen of -cloth_drape_diameter (0.3 m) centred on a
  support disc of -cloth_drape_disc (0.18 m); the part over the support is clamped flat (the
  drapemeter's two discs hold it), the pedestal below it is a rigid support with frictionless barrier
  contact (rounded rim, -cloth_rim_radius); gravity is applied in -cloth_load_steps steps (default 8).
  The drape coefficient DC = (A_shadow - A_disc) / (A_specimen - A_disc) (the nominal areas pi R^2 of the
  specimen and the disc) from the shadow seen from above
  (the largest radius in each of 360 one-degree sectors), and the number of nodes (folds) of its
  outline. Symmetry is broken only by the lattice (hexagonal) and rounding: the nodes a perfectly
  symmetric specimen picks are those of the mesh. CSV: sector_deg, r_m (the outline), then the summary
  in comment lines; results DC and nodes.
*/
PetscErrorCode HylcClothRunDrape_Private(HylcCloth c)
{
  MPI_Comm      comm = CLOTH_COMM_PRIVATE(c);
  HylcClothText csv  = {0};
  char          path[PETSC_MAX_PATH_LEN + 64];
  PetscReal     R = c->drapeD / 2, Rd = c->discD / 2, h = c->h, rmax[360], area = 0, DC, A0 = PETSC_PI * R * R, Ad = PETSC_PI * Rd * Rd;
  PetscInt      n, *v, nodes = 0, nb = 360;
  PetscBool     ok;

  PetscFunctionBegin;
  PetscCheck(R > Rd && Rd > 0, comm, PETSC_ERR_USER_INPUT, "drape: -cloth_drape_diameter %g m must exceed -cloth_drape_disc %g m > 0", (double)c->drapeD, (double)c->discD);
  PetscCall(HylcClothSolverReset_Private(c));
  PetscCall(HylcClothClampsReset_Private(c));
  PetscCall(HylcClothMeshDisc_Private(c, R, Rd, h));
  PetscCall(HylcClothMeshMaterial_Private(c, (c->angle > -360 ? c->angle : 0.0) * PETSC_PI / 180, c->face == HYLC_CLOTH_FACE_DOWN ? PETSC_TRUE : PETSC_FALSE));
  c->load   = 0;
  c->gscale = 0;
  /* the clamped centre: every vertex within the support's radius */
  PetscCall(PetscMalloc1(c->nv, &v));
  n = 0;
  for (PetscInt i = 0; i < c->nv; i++)
    if (PetscSqrtReal(c->X[3 * i] * c->X[3 * i] + c->X[3 * i + 1] * c->X[3 * i + 1]) <= Rd * (1 + 1e-9)) v[n++] = i;
  PetscCall(HylcClothAddClamp_Private(c, n, v, NULL, PETSC_FALSE));
  PetscCall(PetscFree(v));
  /* the pedestal below, its top a barrier distance under the cloth */
  c->nsupport        = 1;
  c->support[0].kind = 1;
  c->support[0].cx = c->support[0].cy = 0;
  c->support[0].R                     = Rd;
  c->support[0].rho                   = PetscMin(c->rimRadius, 0.5 * Rd);
  c->support[0].z0                    = -0.5 * c->barrierDist;
  PetscCall(HylcClothPrepare_Private(c));
  PetscCall(PetscPrintf(comm, "drape (face %s, dynamics %s): specimen %g m on a %g m disc, %" PetscInt_FMT " vertices, %" PetscInt_FMT " triangles (h %g m)\n", c->face == HYLC_CLOTH_FACE_DOWN ? "down" : "up", HylcClothDynamicsTypes[c->dynamics],
                        (double)c->drapeD, (double)c->discD, c->nv, c->nt, (double)h));
  PetscCall(HylcClothEquilibrium_Private(c, c->loadSteps > 0 ? c->loadSteps : 8, &ok));
  PetscCheck(ok, comm, PETSC_ERR_NOT_CONVERGED, "drape: no equilibrium under gravity (%s; try -cloth_dynamic on, a longer -cloth_tmax or more -cloth_load_steps)",
             c->dynamics == HYLC_CLOTH_DYNAMICS_OFF ? "static load path only" : "the dynamics did not come to rest");
  PetscCall(DrapeShadow(c, nb, rmax, &area, &nodes));
  DC = (area - Ad) / (A0 - Ad);
  PetscCall(HylcClothResult_Private(c, "DC", DC));
  PetscCall(HylcClothResult_Private(c, "nodes", (PetscReal)nodes));
  PetscCall(PetscPrintf(comm, "  drape coefficient %.4f (shadow %.6g m^2, specimen %.6g m^2, disc %.6g m^2), %" PetscInt_FMT " nodes; Newton iterations %" PetscInt_FMT " (%" PetscInt_FMT " exact, %" PetscInt_FMT " projected Hessians)\n", (double)DC,
                        (double)area, (double)A0, (double)Ad, nodes, c->newtonIts, c->hessExact, c->hessProj));
  PetscCall(HylcClothTextAppend_Private(&csv, "# drape coefficient %.8g, nodes %" PetscInt_FMT ", shadow %.8g m^2, specimen %.8g m^2, disc %.8g m^2\nsector_deg,r_m\n", (double)DC, nodes, (double)area, (double)A0, (double)Ad));
  for (PetscInt b = 0; b < nb; b++) PetscCall(HylcClothTextAppend_Private(&csv, "%.1f,%.10g\n", (double)(-180.0 + (b + 0.5) * 360.0 / nb), (double)rmax[b]));
  PetscCall(HylcClothOutputName_Private(c, "drape.vtk", path, sizeof(path)));
  PetscCall(HylcClothWriteVTK_Private(c, path));
  PetscCall(HylcClothOutputName_Private(c, "drape.csv", path, sizeof(path)));
  PetscCall(HylcClothTextWrite_Private(c, &csv, path));
  PetscCall(HylcClothPlot_Private(c, "drape", path));
  PetscFunctionReturn(PETSC_SUCCESS);
}
/*
  A generic static scene (docs/fabric.md): the rectangle [0, L] x [0, W] (-cloth_length, -cloth_width,
  mesh -cloth_h, material x at -cloth_angle to its length, -cloth_face) or an .obj mesh
  (-cloth_mesh_file), clamped along a centred length -cloth_scene_clamp of its end x = 0 and/or pinned
  at the vertices nearest the corners -cloth_scene_corners (0 (0,0), 1 (L,0), 2 (L,W), 3 (0,W)), under
  gravity in -cloth_load_steps (8) steps. The equilibrium's coordinates are written (CSV: vertex, X, Y,
  Z rest, x, y, z) with the VTK; results: the lowest z and the largest displacement.
*/
PetscErrorCode HylcClothRunScene_Private(HylcCloth c)
{
  MPI_Comm      comm = CLOTH_COMM_PRIVATE(c);
  HylcClothText csv  = {0};
  char          path[PETSC_MAX_PATH_LEN + 64];
  PetscReal     L = c->length, W = c->width, zmin = PETSC_MAX_REAL, dmax = 0, lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL, -PETSC_MAX_REAL};
  PetscInt      n, *v;
  PetscBool     ok;

  PetscFunctionBegin;
  PetscCheck(c->sceneClamp > 0 || c->ncorners > 0, comm, PETSC_ERR_USER_INPUT, "scene: nothing holds the cloth: give -cloth_scene_clamp (m) or -cloth_scene_corners");
  PetscCall(HylcClothSolverReset_Private(c));
  PetscCall(HylcClothClampsReset_Private(c));
  if (c->meshFile[0])
    PetscCall(HylcClothMeshReadOBJ_Private(c, c->meshFile, c->meshScale));
  else
    PetscCall(HylcClothMeshStrip_Private(c, 0, L, W, c->h));
  PetscCall(HylcClothMeshMaterial_Private(c, (c->angle > -360 ? c->angle : 0.0) * PETSC_PI / 180, c->face == HYLC_CLOTH_FACE_DOWN ? PETSC_TRUE : PETSC_FALSE));
  for (PetscInt i = 0; i < c->nv; i++)
    for (int k = 0; k < 3; k++) {
      lo[k] = PetscMin(lo[k], c->X[3 * i + k]);
      hi[k] = PetscMax(hi[k], c->X[3 * i + k]);
    }
  c->nsupport = 0;
  c->load     = 0;
  c->gscale   = 0;
  if (c->sceneClamp > 0) {
    PetscReal yc = 0.5 * (lo[1] + hi[1]), tol = 1e-9 * (hi[0] - lo[0]);
    PetscCheck(c->sceneClamp <= (hi[1] - lo[1]) * (1 + 1e-9), comm, PETSC_ERR_USER_INPUT, "-cloth_scene_clamp %g m is outside the mesh: its end x = %g is %g m wide", (double)c->sceneClamp, (double)lo[0], (double)(hi[1] - lo[1]));
    PetscCall(HylcClothVerticesInBox_Private(c, lo[0] - 1, lo[0] + tol, yc - 0.5 * c->sceneClamp - tol, yc + 0.5 * c->sceneClamp + tol, &n, &v));
    PetscCheck(n > 0, comm, PETSC_ERR_USER_INPUT, "-cloth_scene_clamp %g m holds no vertex of the end x = %g", (double)c->sceneClamp, (double)lo[0]);
    PetscCall(HylcClothAddClamp_Private(c, n, v, NULL, PETSC_FALSE));
    PetscCall(PetscFree(v));
  }
  if (c->ncorners > 0) {
    PetscInt pins[4];
    for (PetscInt k = 0; k < c->ncorners; k++) {
      PetscReal cx = (c->corners[k] == 1 || c->corners[k] == 2) ? hi[0] : lo[0], cy = c->corners[k] >= 2 ? hi[1] : lo[1], best = PETSC_MAX_REAL;
      for (PetscInt i = 0; i < c->nv; i++) {
        PetscReal d = PetscSqr(c->X[3 * i] - cx) + PetscSqr(c->X[3 * i + 1] - cy);
        if (d < best) {
          best    = d;
          pins[k] = i;
        }
      }
    }
    PetscCall(HylcClothAddClamp_Private(c, c->ncorners, pins, NULL, PETSC_FALSE));
  }
  PetscCall(HylcClothPrepare_Private(c));
  PetscCall(PetscPrintf(comm, "scene: %s, %" PetscInt_FMT " vertices, %" PetscInt_FMT " triangles; clamp %g m, %" PetscInt_FMT " pinned corners, gravity %g m/s^2\n", c->meshFile[0] ? c->meshFile : "rectangle", c->nv, c->nt, (double)c->sceneClamp,
                        c->ncorners, (double)c->gravity));
  PetscCall(HylcClothEquilibrium_Private(c, c->loadSteps > 0 ? c->loadSteps : 8, &ok));
  PetscCheck(ok, comm, PETSC_ERR_NOT_CONVERGED, "scene: no equilibrium under gravity (%s; try -cloth_dynamic on, a longer -cloth_tmax or more -cloth_load_steps)",
             c->dynamics == HYLC_CLOTH_DYNAMICS_OFF ? "static load path only" : "the dynamics did not come to rest");
  PetscCall(HylcClothGather_Private(c, c->x));
  PetscCall(HylcClothTextAppend_Private(&csv, "vertex,X,Y,Z,x,y,z\n"));
  for (PetscInt i = 0; i < c->nv; i++) {
    const PetscReal *X = c->X + 3 * i, *x = c->xgather + 3 * i;
    zmin = PetscMin(zmin, x[2]);
    dmax = PetscMax(dmax, PetscSqrtReal(PetscSqr(x[0] - X[0]) + PetscSqr(x[1] - X[1]) + PetscSqr(x[2] - X[2])));
    PetscCall(HylcClothTextAppend_Private(&csv, "%" PetscInt_FMT ",%.10g,%.10g,%.10g,%.12g,%.12g,%.12g\n", i, (double)X[0], (double)X[1], (double)X[2], (double)x[0], (double)x[1], (double)x[2]));
  }
  PetscCall(HylcClothResult_Private(c, "zmin", zmin));
  PetscCall(HylcClothResult_Private(c, "max_displacement", dmax));
  PetscCall(
      PetscPrintf(comm, "  lowest z %.6g m, largest displacement %.6g m; Newton iterations %" PetscInt_FMT " (%" PetscInt_FMT " exact, %" PetscInt_FMT " projected Hessians)\n", (double)zmin, (double)dmax, c->newtonIts, c->hessExact, c->hessProj));
  PetscCall(HylcClothOutputName_Private(c, "scene.vtk", path, sizeof(path)));
  PetscCall(HylcClothWriteVTK_Private(c, path));
  PetscCall(HylcClothOutputName_Private(c, "scene.csv", path, sizeof(path)));
  PetscCall(HylcClothTextWrite_Private(c, &csv, path));
  PetscFunctionReturn(PETSC_SUCCESS);
}
/*
  The free curl of a strip (docs/fabric.md): a strip of -cloth_length by -cloth_width (0.03 x 0.02 m: less
  than a turn at the paper's stock1 curl), no gravity, held only against rigid motion (the vertex nearest
  the centre and its neighbour along x fixed, the neighbour along y fixed in z), relaxes from flat to the
  table's preferred curvature. Reports the central zone's (the middle half in both directions) II00,
  II11 (1/m) beside the table's free curl (HylcClothTableCurl). The cloth does not collide with itself:
  a strip longer than a turn passes through itself. CSV: II00_zone, II11_zone, II00_table, II11_table.
*/
PetscErrorCode HylcClothRunCurl_Private(HylcCloth c)
{
  MPI_Comm      comm = CLOTH_COMM_PRIVATE(c);
  HylcClothText csv  = {0};
  char          path[PETSC_MAX_PATH_LEN + 64];
  PetscReal     L = c->length, W = c->width, *z, zc[6], best[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL};
  PetscInt      v3[3] = {-1, -1, -1};
  PetscBool     ok;
  double        k0 = NAN, k1 = NAN;

  PetscFunctionBegin;
  PetscCall(HylcClothStrip_Private(c, 0, L, W, c->h, c->angle > -360 ? c->angle : 0.0, c->face == HYLC_CLOTH_FACE_DOWN ? PETSC_TRUE : PETSC_FALSE));
  for (PetscInt i = 0; i < c->nv; i++) { /* the centre */
    PetscReal d = PetscSqr(c->X[3 * i] - L / 2) + PetscSqr(c->X[3 * i + 1] - W / 2);
    if (d < best[0]) best[0] = d, v3[0] = i;
  }
  for (PetscInt i = 0; i < c->nv; i++) { /* its nearest neighbours along x and along y */
    PetscReal dx = c->X[3 * i] - c->X[3 * v3[0]], dy = c->X[3 * i + 1] - c->X[3 * v3[0] + 1], d = dx * dx + dy * dy;
    if (i == v3[0]) continue;
    if (PetscAbsReal(dy) < 1e-9 * W && dx > 0 && d < best[1]) best[1] = d, v3[1] = i;
    if (PetscAbsReal(dy) > 0.5 * PetscAbsReal(dx) && dy > 0 && d < best[2]) best[2] = d, v3[2] = i;
  }
  PetscCheck(v3[1] >= 0 && v3[2] >= 0, comm, PETSC_ERR_USER_INPUT, "curl: the strip %g x %g m with h %g m has no interior vertex to hold", (double)L, (double)W, (double)c->h);
  PetscCall(HylcClothAddClamp_Private(c, 2, v3, NULL, PETSC_FALSE));
  PetscCall(HylcClothAddClamp_Private(c, 1, v3 + 2, NULL, PETSC_TRUE));
  PetscCall(HylcClothPrepare_Private(c));
  c->gscale = 0;
  PetscCall(PetscPrintf(comm, "curl (free strip, face %s): %g x %g m, %" PetscInt_FMT " vertices, %" PetscInt_FMT " triangles\n", c->face == HYLC_CLOTH_FACE_DOWN ? "down" : "up", (double)L, (double)W, c->nv, c->nt));
  { /* from flat to a curled strip in one solve: rotations of order one need more than the load step's
       Newton iterations */
    PetscInt maxit = c->maxit;
    c->maxit       = PetscMax(c->maxit, 300);
    PetscCall(HylcClothSolverReset_Private(c));
    PetscCall(HylcClothSolveStatic_Private(c, &ok));
    c->maxit = maxit;
    PetscCall(HylcClothSolverReset_Private(c));
  }
  PetscCheck(ok, comm, PETSC_ERR_NOT_CONVERGED, "curl: no equilibrium of the free strip");
  PetscCall(PetscMalloc1(6 * c->nt, &z));
  PetscCall(HylcClothStrains_Private(c, c->x, z));
  PetscCall(HylcClothZoneMean_Private(c, z, 0.25 * L, 0.75 * L, 0.25 * W, 0.75 * W, zc));
  PetscCall(PetscFree(z));
  (void)HylcClothTableCurl(c->hm, &k0, &k1, NULL);
  PetscCall(HylcClothResult_Private(c, "curl_II00", zc[3]));
  PetscCall(HylcClothResult_Private(c, "curl_II11", zc[5]));
  PetscCall(PetscPrintf(comm, "  central zone: II00 %.5g 1/m, II11 %.5g 1/m; the table's free curl: II00 %.5g 1/m, II11 %.5g 1/m; Newton iterations %" PetscInt_FMT "\n", (double)zc[3], (double)zc[5], k0, k1, c->newtonIts));
  PetscCall(HylcClothTextAppend_Private(&csv, "II00_zone,II11_zone,II00_table,II11_table\n%.10g,%.10g,%.10g,%.10g\n", (double)zc[3], (double)zc[5], k0, k1));
  PetscCall(HylcClothOutputName_Private(c, "curl.vtk", path, sizeof(path)));
  PetscCall(HylcClothWriteVTK_Private(c, path));
  PetscCall(HylcClothOutputName_Private(c, "curl.csv", path, sizeof(path)));
  PetscCall(HylcClothTextWrite_Private(c, &csv, path));
  PetscFunctionReturn(PETSC_SUCCESS);
}
