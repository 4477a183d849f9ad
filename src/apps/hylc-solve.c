static const char help[] = "hylc-solve: the equilibrium of a periodic yarn tile under one macroscopic strain.\n\n"
                           "  hylc-solve -options_file config/satin.yaml -strain 0.2,0,0,0,0,0\n"
                           "  hylc-solve -pattern_type stockinette -strain 0,0,0,100,0,0 -solve_vtk s.vtk\n\n"
                           "  hylc-solve -options_file config/satin.yaml -solve_uniaxial x -solve_uniaxial_strains 0.05,0.1,0.2 -solve_uniaxial_csv satin-x.csv\n"
                           "  hylc-solve -options_file config/satin.yaml -solve_path uniaxial -solve_path_angle 45 -solve_path_values 0.02,0.05 -solve_path_csv bias.csv\n\n"
                           "Prints psi (J/m^2), the energy parts, the status, the Newton iterations, the wall time and the stress dPsi/dz.\n"
                           "With -solve_uniaxial x|y: the homogeneous uniaxial tension state at each stretch (Psi minimized over the\n"
                           "two free strains, docs/fabric-uniaxial.md), one line per stretch: T = dPsi/ds (N/m), the lateral strains.\n"
                           "With -solve_path uniaxial|equibiaxial|shear|bending: the homogeneous state of that fabric test at each value\n"
                           "(Psi minimized over the path's free strains; its force d(min Psi)/ds; docs/fabric-fidelity.md).\n\n";

#include <hylc/options.h>
#include <hylc/micro.h>
#include <hylc/sys.h>
#include <hylc/files.h>

/* -solve_uniaxial: the uniaxial states at the stretches s[0..n), in order, each continued from the one before
   (its fluctuation, and its lateral strains extrapolated linearly) */
static PetscErrorCode SolveUniaxial(HylcMicro micro, HylcUniaxialDirection dir, PetscInt n, const PetscReal s[], const char csv[])
{
  HylcPeriodic P;
  PetscInt     ny, nfail = 0;
  PetscBool    haveU = PETSC_FALSE;
  PetscReal   *u, *unext, *T, *sa, *s2, lat[2] = {0, 0};
  PetscBool   *conv;

  PetscFunctionBegin;
  PetscCall(HylcMicroSetUp(micro));
  PetscCall(HylcMicroGetPeriodic(micro, &P));
  PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, NULL));
  PetscCall(PetscMalloc6(ny, &u, ny, &unext, n, &T, n, &sa, n, &s2, n, &conv));
  for (PetscInt i = 0; i < n; i++) {
    HylcMicroUniaxialResult r;
    if (i >= 2 && s[i - 1] != s[i - 2] && conv[i - 1] && conv[i - 2]) { /* linear predictor of the lateral strains */
      const PetscReal f = (s[i] - s[i - 1]) / (s[i - 1] - s[i - 2]);
      lat[0]            = sa[i - 1] + f * (sa[i - 1] - sa[i - 2]);
      lat[1]            = s2[i - 1] + f * (s2[i - 1] - s2[i - 2]);
      if (!(PetscAbsReal(lat[0]) < 0.9 && lat[1] > -0.9)) lat[0] = sa[i - 1], lat[1] = s2[i - 1];
    }
    PetscCall(HylcMicroSolveUniaxial(micro, dir, s[i], lat, haveU ? u : NULL, &r, unext));
    PetscCall(HylcMicroUniaxialResultView(&r, PETSC_VIEWER_STDOUT_SELF));
    conv[i] = r.converged;
    T[i]    = r.T;
    sa[i]   = r.lateral[0];
    s2[i]   = r.lateral[1];
    if (r.converged) { /* the next stretch continues from the last converged state */
      lat[0] = sa[i];
      lat[1] = s2[i];
      PetscCall(PetscArraycpy(u, unext, ny));
      haveU = PETSC_TRUE;
    } else
      nfail++;
  }
  for (PetscInt i = 0; i < n; i++)
    if (s[i] > 0) {
      char buf[160];
      snprintf(buf, sizeof(buf), "poisson ratio -%s/s%s at s = %g: %.6g\n", dir == HYLC_UNIAXIAL_X ? "sy" : "sx", dir == HYLC_UNIAXIAL_X ? "x" : "y", (double)s[i], (double)(-s2[i] / s[i]));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s", buf));
      break;
    }
  if (nfail) PetscCall(PetscPrintf(PETSC_COMM_SELF, "%" PetscInt_FMT " of %" PetscInt_FMT " uniaxial states did not converge\n", nfail, n));
  if (csv[0]) {
    PetscCall(HylcWriteUniaxialCSV(csv, n, s, T, sa, s2));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", csv));
  }
  PetscCall(PetscFree6(u, unext, T, sa, s2, conv));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* -solve_path: the states of a load path at the values s[0..n), in order, each continued from the one before (its
   fluctuation, and its free strains extrapolated linearly) */
static PetscErrorCode SolvePathMode(HylcMicro micro, const hylcmat_path *path, PetscInt n, const PetscReal s[], const char csv[])
{
  HylcPeriodic P;
  const int    nf = hylcmat_path_nfree(path);
  PetscInt     ny, nfail = 0;
  PetscBool    haveU = PETSC_FALSE, *conv;
  PetscReal   *u, *unext, *F, *Z, *psi, *pf, p0[3] = {0, 0, 0};

  PetscFunctionBegin;
  PetscCall(HylcMicroSetUp(micro));
  PetscCall(HylcMicroGetPeriodic(micro, &P));
  PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, NULL));
  PetscCall(PetscMalloc6(ny, &u, ny, &unext, n, &F, 6 * n, &Z, n, &psi, n, &conv));
  PetscCall(PetscMalloc1(3 * n, &pf));
  for (PetscInt i = 0; i < n; i++) {
    HylcMicroPathResult r;
    if (i >= 2 && s[i - 1] != s[i - 2] && conv[i - 1] && conv[i - 2]) { /* linear predictor of the free strains */
      const PetscReal f = (s[i] - s[i - 1]) / (s[i - 1] - s[i - 2]);
      for (int a = 0; a < nf; a++) p0[a] = pf[3 * (i - 1) + a] + f * (pf[3 * (i - 1) + a] - pf[3 * (i - 2) + a]);
    }
    PetscCall(HylcMicroSolvePath(micro, path, s[i], p0, haveU ? u : NULL, &r, unext));
    PetscCall(HylcMicroPathResultView(&r, PETSC_VIEWER_STDOUT_SELF));
    conv[i] = r.converged;
    F[i]    = r.force;
    psi[i]  = r.psi;
    for (int k = 0; k < 6; k++) Z[6 * i + k] = r.z[k];
    for (int a = 0; a < 3; a++) pf[3 * i + a] = r.p[a];
    if (r.converged) { /* the next value continues from the last converged state */
      for (int a = 0; a < 3; a++) p0[a] = r.p[a];
      PetscCall(PetscArraycpy(u, unext, ny));
      haveU = PETSC_TRUE;
    } else
      nfail++;
  }
  if (nfail) PetscCall(PetscPrintf(PETSC_COMM_SELF, "%" PetscInt_FMT " of %" PetscInt_FMT " %s states did not converge\n", nfail, n, hylcmat_path_name(path->kind)));
  if (csv[0]) {
    PetscCall(HylcWritePathCSV(csv, n, s, F, Z, psi, conv));
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", csv));
  }
  PetscCall(PetscFree6(u, unext, F, Z, psi, conv));
  PetscCall(PetscFree(pf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the work of hylc-solve on pat and micro (created and destroyed by Run, also on an error) */
static PetscErrorCode Solve(HylcPattern pat, HylcMicro micro)
{
  HylcYarnModel   model;
  HylcMicroResult res;
  PetscReal       z[6] = {0, 0, 0, 0, 0, 0};
  PetscInt        nz = 6, tiles[2] = {3, 3}, nt = 2;
  char            out[PETSC_MAX_PATH_LEN] = "", vtk[PETSC_MAX_PATH_LEN] = "", csv[PETSC_MAX_PATH_LEN] = "", udir[16] = "", pcsv[PETSC_MAX_PATH_LEN] = "";
  PetscBool       flg, uni, hasStrains, hasCsv, pathSet, hasPathValues;
  PetscReal       ustrain[64] = {0.05, 0.1, 0.2}, pvalues[64];
  PetscInt        nu = 64, npv = 64;
  PetscEnum       pkind = 0;
  hylcmat_path    path  = {HYLCMAT_PATH_UNIAXIAL, 0};

  PetscFunctionBeginUser;
  PetscCall(HylcPatternSetFromOptions(pat));
  PetscCall(HylcYarnModelDefault(&model));
  PetscCall(HylcYarnModelSetFromOptions(PETSC_COMM_SELF, NULL, &model));
  PetscOptionsBegin(PETSC_COMM_SELF, NULL, "hylc-solve options", "hylc-solve");
  PetscCall(HylcOptionsRealArray("-strain", "Macroscopic strain sx,sa,sy,II00,II01,II11 (II in 1/m): finite, |sa| < 1, 0 < 1+sx, 1+sy <= 1e3, the midsurface turning by at most 2 pi across a period (docs/method.md)", "HylcMicroSolve", z, &nz, &flg));
  PetscCheck(!flg || nz == 6, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-strain needs 6 comma-separated values sx,sa,sy,II00,II01,II11, got %" PetscInt_FMT, nz);
  PetscCall(HylcOptionsString("-solve_output", "Write the equilibrium tile as .pyp (positions and twists; rest data unchanged)", "hylc-solve", out, out, sizeof(out), NULL));
  PetscCall(HylcOptionsString("-solve_vtk", "Write the equilibrium, tiled, as legacy-VTK polylines", "hylc-solve", vtk, vtk, sizeof(vtk), NULL));
  nt = 2;
  PetscCall(HylcOptionsIntArray("-solve_vtk_tiles", "Tile copies nx,ny in the VTK file", "hylc-solve", tiles, &nt, NULL));
  PetscCall(HylcOptionsString("-solve_uniaxial", "Uniaxial tension mode: x or y, the material axis of the prescribed stretch; the other two in-plane strains free, bending zero (docs/fabric-uniaxial.md)", "HylcMicroSolveUniaxial", udir, udir,
                              sizeof(udir), &uni));
  PetscCall(HylcOptionsRealArray("-solve_uniaxial_strains", "Uniaxial mode: the stretches s in [0, 1) (strain, 0 at rest; default 0.05,0.1,0.2), solved in this order, each continued from the one before (at most 64)", "HylcMicroSolveUniaxial",
                                 ustrain, &nu, &hasStrains));
  PetscCall(HylcOptionsString("-solve_uniaxial_csv", "Uniaxial mode: write strain,T_N_per_m,lateral_strain_sa,lateral_strain_s2 (T in N/m) to this CSV file", "HylcWriteUniaxialCSV", csv, csv, sizeof(csv), &hasCsv));
  PetscCall(HylcOptionsEnum("-solve_path",
                            "Load path mode (docs/fabric-fidelity.md): uniaxial (stretch along -solve_path_angle, the other in-plane strains free), equibiaxial (sx = sy, sa free), shear (sa given, sx, sy free) or bending (II00, or II11 with "
                            "-solve_path_angle 90, in-plane strains free)",
                            "HylcMicroSolvePath", HylcPathNames, pkind, &pkind, &pathSet));
  PetscCall(
      HylcOptionsReal("-solve_path_angle", "Path mode: the uniaxial direction in degrees from the material x axis (0 strip along x, 90 along y, 45 bias), or the bending axis (0: II00, 90: II11)", "HylcMicroSolvePath", path.angle, &path.angle, NULL));
  PetscCall(HylcOptionsRealArray("-solve_path_values", "Path mode: the prescribed values (stretches in [0, 1), sa in (-0.95, 0.95), or curvatures in 1/m), solved in this order, each continued from the one before (at most 64)", "HylcMicroSolvePath",
                                 pvalues, &npv, &hasPathValues));
  PetscCall(HylcOptionsString("-solve_path_csv", "Path mode: write value,force,sx,sa,sy,II00,II11,psi,converged (force in N/m, N for bending) to this CSV file", "HylcWritePathCSV", pcsv, pcsv, sizeof(pcsv), NULL));
  PetscOptionsEnd();
  path.kind = (int)pkind;
  PetscCheck(pathSet || (!hasPathValues && !pcsv[0]), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_path_values and -solve_path_csv need -solve_path uniaxial|equibiaxial|shear|bending");
  PetscCheck(!pathSet || hasPathValues, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_path %s needs -solve_path_values", HylcPathNames[path.kind]);
  PetscCheck(!pathSet || (!uni && !flg && !out[0] && !vtk[0]), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_path cannot be combined with -solve_uniaxial, -strain, -solve_output or -solve_vtk");
  if (!hasStrains) nu = 3;
  PetscCheck(!hasStrains || nu > 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_uniaxial_strains: needs at least one stretch");
  PetscCheck(uni || (!hasStrains && !hasCsv), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_uniaxial_strains and -solve_uniaxial_csv need -solve_uniaxial x|y");
  if (uni) {
    PetscBool isx, isy;
    PetscCall(PetscStrcmp(udir, "x", &isx));
    PetscCall(PetscStrcmp(udir, "y", &isy));
    PetscCheck(isx || isy, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_uniaxial %s: unknown direction (x or y, the material axis of the stretch)", udir);
    PetscCheck(!flg, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-strain cannot be combined with -solve_uniaxial: the uniaxial mode chooses the strains itself (-solve_uniaxial_strains sets the stretches)");
    PetscCheck(!out[0] && !vtk[0], PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_output and -solve_vtk are not available with -solve_uniaxial (write the curve with -solve_uniaxial_csv)");
    for (PetscInt i = 0; i < nu; i++)
      PetscCheck(ustrain[i] >= 0 && ustrain[i] < 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_uniaxial_strains: stretch %g is outside [0, 1) (a uniaxial state is a tension test within the sampled stretches; a compressed strip buckles)",
                 (double)ustrain[i]);
  }
  PetscCall(HylcMicroSetFromOptions(micro)); /* only reads options; the pattern is given below */
  {
    PetscBool help_only;
    PetscCall(PetscOptionsHasHelp(NULL, &help_only));
    if (help_only) PetscFunctionReturn(PETSC_SUCCESS); /* -help: every option has been listed; do no work */
  }
  PetscCall(HylcCheckOptionsUsed(PETSC_COMM_SELF)); /* a misspelt option is an error, another stage's is not */
  /* every file before any work (include/hylc/files.h): the pattern file and the options files read, the
     outputs writable and within the path limits, never an input or each other */
  {
    const char     *in = "";
    HylcPatternType type;
    PetscBool       isfile;
    HylcFiles       files;
    PetscErrorCode  ierr;
    PetscCall(HylcPatternGetType(pat, &type));
    PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
    if (isfile) PetscCall(HylcPatternGetFileName(pat, &in));
    PetscCheck(!out[0] || (z[1] == 0 && z[3] == 0 && z[4] == 0 && z[5] == 0), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-solve_output %s: a deformed tile is a .pyp pattern only without shear and bending (sa = II = 0); use -solve_vtk instead", out);
    PetscCall(HylcFilesCreate(PETSC_COMM_SELF, &files));
    ierr = HylcFilesAddOptionsFiles(files);
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, in, "-pattern_file");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, out, "-solve_output");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, vtk, "-solve_vtk");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, csv, "-solve_uniaxial_csv");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, pcsv, "-solve_path_csv");
    if (!ierr) ierr = HylcFilesCheck(files);
    PetscCall(HylcFilesDestroy(&files));
    PetscCall(ierr);
  }
  PetscCall(HylcPatternSetUp(pat));
  if (pathSet) {
    PetscCall(HylcMicroSetPattern(micro, pat, &model));
    PetscCall(SolvePathMode(micro, &path, npv, pvalues, pcsv));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (uni) {
    PetscBool isx;
    PetscCall(PetscStrcmp(udir, "x", &isx));
    PetscCall(HylcMicroSetPattern(micro, pat, &model));
    PetscCall(SolveUniaxial(micro, isx ? HYLC_UNIAXIAL_X : HYLC_UNIAXIAL_Y, nu, ustrain, csv));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(HylcMicroSetPattern(micro, pat, &model));
  {
    HylcPeriodic P;
    PetscCall(HylcMicroGetPeriodic(micro, &P));
    PetscCall(HylcPeriodicCheckStrain(P, z, "-strain"));
  }
  PetscCall(HylcMicroSolve(micro, z, &res));
  PetscCall(HylcMicroResultView(&res, PETSC_VIEWER_STDOUT_SELF));
  if (res.status == HYLC_MICRO_CONVERGED) { /* the stress of the equilibrium (envelope theorem) */
    PetscReal g[6];
    char      buf[256];
    PetscCall(HylcMicroGetStrainGradient(micro, HYLC_STRAIN_ALL_BITS | HYLC_STRAIN_NO_POISSON, g));
    snprintf(buf, sizeof(buf), "stress: %.10e %.10e %.10e %.10e %.10e %.10e (dPsi/dz: N/m for sx, sa, sy; N for II00, II01, II11; nan: needs a Poisson midsurface)\n", (double)g[0], (double)g[1], (double)g[2], (double)g[3], (double)g[4],
             (double)g[5]);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s", buf));
  }
  if (out[0] || vtk[0]) {
    HylcPeriodic P;
    PetscCall(HylcMicroGetPeriodic(micro, &P));
    if (vtk[0]) {
      PetscCall(HylcPeriodicWriteVTK(P, vtk, tiles[0], tiles[1]));
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", vtk));
    }
    if (out[0]) {
      HylcPattern    eq;
      PetscErrorCode ierr;
      PetscCall(HylcPeriodicCreateStatePattern(P, &eq));
      ierr = HylcPatternWrite(eq, out);
      PetscCall(HylcPatternDestroy(&eq));
      PetscCall(ierr);
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "wrote %s\n", out));
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode Run(void)
{
  HylcPattern    pat   = NULL;
  HylcMicro      micro = NULL;
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, &pat));
  PetscCall(HylcMicroCreate(PETSC_COMM_SELF, &micro));
  ierr = Solve(pat, micro);
  PetscCall(HylcMicroDestroy(&micro)); /* also on an error: nothing leaks */
  PetscCall(HylcPatternDestroy(&pat));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(HylcInitialize(&argc, &argv, NULL, help));
  return HylcMainFinalize(Run());
}
