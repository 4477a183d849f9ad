/* The HDF5 samples file (include/hylc/samples.h; schema in docs/output-format.md): built in memory
   through the private HDF5 helper layer (include/hylc/private/h5util.h) and written atomically; and its
   reader. The journal is src/samples/journal.c. */
#include <hylc/samples.h>
#include <hylc/private/samplesimpl.h>
#include <hylc/private/h5util.h>
#include <hylc/table.h>
#include <petsc/private/petscimpl.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* The file the current HDF5 call works on, for HylcCallHDF5's messages (rank-0, single-threaded code). */
static const char *HylcH5Where = "?";

/* an int32 copy of a PetscInt array for HylcH5WriteDataset */
static PetscErrorCode DatasetInt(hid_t loc, const char name[], PetscInt n, PetscInt cols, const PetscInt *v, const char units[], const char description[])
{
  int          *buf;
  PetscInt      m       = n * (cols ? cols : 1);
  const hsize_t dims[2] = {(hsize_t)n, (hsize_t)cols};

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(m + 1, &buf));
  for (PetscInt i = 0; i < m; i++) buf[i] = (int)v[i];
  HylcCallHDF5(HylcH5WriteDataset(loc, name, cols ? 2 : 1, dims, H5T_NATIVE_INT, buf, units, description));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteSamplesGroup(hid_t file, long N, const HylcSampleRecord recs[], const unsigned char done[])
{
  double *strain, *psi, *parts, *res, *cres, *t, *psio, *stress;
  int    *term, *status, *its, *retries, *start, *negcurv, *escapes, *stato, *multi;
  hid_t   g;
  int     nstat = HylcSamplesNumStatuses_();

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(6 * N + 1, &stress));
  PetscCall(PetscMalloc6(6 * N + 1, &strain, N + 1, &psi, 4 * N + 1, &parts, N + 1, &res, N + 1, &cres, N + 1, &t));
  PetscCall(PetscMalloc7(N + 1, &term, N + 1, &status, N + 1, &its, N + 1, &retries, N + 1, &start, N + 1, &negcurv, N + 1, &escapes));
  PetscCall(PetscMalloc3(N + 1, &psio, N + 1, &stato, N + 1, &multi));
  for (long k = 0; k < N; k++) {
    start[k]   = done && done[k] ? recs[k].start : -1;
    negcurv[k] = done && done[k] ? recs[k].negcurv : -1;
    escapes[k] = done && done[k] ? recs[k].escapes : -1;
    psio[k]    = done && done[k] ? recs[k].psiOther : NAN;
    stato[k]   = done && done[k] ? recs[k].statusOther : -1;
    multi[k]   = done && done[k] ? recs[k].multistable : -1;
    for (int i = 0; i < 6; i++) stress[6 * k + i] = done && done[k] ? recs[k].stress[i] : NAN;
    if (done && done[k]) {
      const HylcSampleRecord *r = &recs[k];
      for (int i = 0; i < 6; i++) strain[6 * k + i] = r->z[i];
      for (int i = 0; i < 4; i++) parts[4 * k + i] = r->parts[i];
      psi[k]     = r->psi;
      res[k]     = r->residual;
      cres[k]    = r->cresidual;
      t[k]       = r->time;
      term[k]    = r->term;
      status[k]  = r->status;
      its[k]     = r->iterations;
      retries[k] = r->retries;
    } else {
      for (int i = 0; i < 6; i++) strain[6 * k + i] = NAN;
      for (int i = 0; i < 4; i++) parts[4 * k + i] = NAN;
      psi[k] = res[k] = cres[k] = t[k] = NAN;
      term[k] = status[k] = its[k] = retries[k] = -1;
    }
  }
  HylcCallHDF5Id(g, H5Gcreate2(file, "samples", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrStrings(g, "status_names", nstat, (const char *const *)HylcMicroStatuses));
  {
    const char *names[HYLC_PLAN_NTERM3];
    for (int t = 0; t < HYLC_PLAN_NTERM3; t++) names[t] = HylcPlanTermName(t);
    HylcCallHDF5(HylcH5WriteAttrStrings(g, "term_names", HYLC_PLAN_NTERM3, names));
  }
  HylcCallHDF5(HylcH5WriteAttrString(g, "description", "One row per sample of the plan, in plan order (row k = sample k). Samples not computed (interrupted run) have status -1, term/iterations/retries -1 and NaN values."));
  HylcCallHDF5(HylcH5WriteDataset(g, "strain", 2, (hsize_t[]){(hsize_t)N, 6}, H5T_NATIVE_DOUBLE, strain, "1 for sx, sa, sy; 1/m for II00, II01, II11",
                                  "macroscopic strain z = (sx, sa, sy, II00, II01, II11): in-plane stretch/shear and the second fundamental form"));
  HylcCallHDF5(HylcH5WriteDataset(g, "psi", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_DOUBLE, psi, "J/m^2", "area energy density psi = E / A of the equilibrium (A: reference tile area)"));
  HylcCallHDF5(
      HylcH5WriteDataset(g, "stress", 2, (hsize_t[]){(hsize_t)N, 6}, H5T_NATIVE_DOUBLE, stress, "N/m for sx, sa, sy; N (J/m^2 per 1/m) for II00, II01, II11",
                         "the stress dpsi/dz of the equilibrium, columns as /samples/strain, by the envelope theorem (no re-solve; docs/output-format.md); NaN where the solve did not converge or the run did not record it (-sampler_stress false)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "term", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, term, "1",
                                  "term of the sampling plan: 0 zero sample, 1..5 one-dimensional, 6..14 two-dimensional, 15..21 three-dimensional; index into /samples@term_names; -1 not computed"));
  HylcCallHDF5(HylcH5WriteDataset(g, "status", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, status, "1",
                                  "HylcMicroStatus of the Newton solve, index into /samples@status_names (0 converged, 1 iteration_cap, 2 time_cap, 3 stalled, 4 nonfinite; 5 failed is reserved, no longer produced); -1: not computed (the run ended "
                                  "before this sample, all its values are NaN or -1)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "iterations", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, its, "1", "Newton iterations; -1 not computed"));
  HylcCallHDF5(HylcH5WriteDataset(g, "retries", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, retries, "1", "regularization increases (alpha x 10 for an indefinite K); -1 not computed"));
  HylcCallHDF5(HylcH5WriteDataset(g, "start", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, start, "1",
                                  "how the kept solve started (-sampler_start): 0 cold (u~ = 0), 1 continued from the equilibrium of the sample before it on its half-line, 2 continued, did not converge, retried cold (the better of the two kept; "
                                  "iterations and time are the sums of both); -1 not computed. With -sampler_start both, 0 or 1 says which start was kept (iterations and time are the sums of both)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "negcurv", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, negcurv, "1",
                                  "second-order test of the final state (-micro_saddle_test): the number of negative eigenvalues of the Hessian on the tangent space of the constraints, 0 a local minimum, > 0 a saddle point (its escapes did not "
                                  "reach a minimum); -1 not tested (test off, solve not converged, or no inertia from the factorization) or not computed"));
  HylcCallHDF5(HylcH5WriteDataset(g, "escapes", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, escapes, "1", "steps along negative curvature that left a saddle point during the kept solve (-micro_saddle_escapes); -1 not computed"));
  HylcCallHDF5(HylcH5WriteDataset(g, "psi_other", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_DOUBLE, psio, "J/m^2",
                                  "-sampler_start both: psi of the start that was not kept (the kept one, in /samples/psi and /samples/start, has the lower psi of the two converged ones); NaN where only one start was solved (other starts; the first "
                                  "sample of a half-line has no continued start)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "status_other", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, stato, "1", "-sampler_start both: HylcMicroStatus of the start that was not kept (as /samples/status); -1 not solved"));
  HylcCallHDF5(
      HylcH5WriteDataset(g, "multistable", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_INT, multi, "1",
                         "-sampler_start both: 1 where both starts converged and their psi differ by more than -sampler_both_rtol of the larger (two equilibria at one strain: the tile is multistable there), 0 where they agree; -1 not compared"));
  HylcCallHDF5(HylcH5WriteDataset(g, "energy_parts", 2, (hsize_t[]){(hsize_t)N, 4}, H5T_NATIVE_DOUBLE, parts, "J", "energy of the tile by kind: columns stretch, bend, twist, contact"));
  HylcCallHDF5(HylcH5WriteDataset(g, "residual", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_DOUBLE, res, "1", "final projected-gradient norm relative to the initial one, |z| / |z0|"));
  HylcCallHDF5(HylcH5WriteDataset(g, "constraint_residual", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_DOUBLE, cres, "1 (units of the yarn radius)", "final periodicity-constraint residual |A y - dL| / r"));
  HylcCallHDF5(HylcH5WriteDataset(g, "time", 1, (hsize_t[]){(hsize_t)N}, H5T_NATIVE_DOUBLE, t, "s", "wall time of the sample's solve"));
  HylcCallHDF5(H5Gclose(g));
  PetscCall(PetscFree6(strain, psi, parts, res, cres, t));
  PetscCall(PetscFree7(term, status, its, retries, start, negcurv, escapes));
  PetscCall(PetscFree3(psio, stato, multi));
  PetscCall(PetscFree(stress));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteReferenceGroup(hid_t file, HylcPattern p)
{
  HylcPatternData d;
  HylcPatternType type;
  hid_t           g;

  PetscFunctionBegin;
  PetscCall(HylcPatternGetData(p, &d));
  PetscCall(HylcPatternGetType(p, &type));
  HylcCallHDF5Id(g, H5Gcreate2(file, "reference", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(g, "description", "the reference (rest) state of the periodic yarn tile the samples were computed on (layout: include/hylc/pattern.h, docs/patterns.md)"));
  HylcCallHDF5(HylcH5WriteAttrString(g, "type", type ? type : ""));
  HylcCallHDF5(HylcH5WriteAttrLong(g, "nv", (long long)d.nv));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "px", (double)d.px));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "py", (double)d.py));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "radius", (double)d.radius));
  HylcCallHDF5(HylcH5WriteAttrString(g, "units", "px, py, radius: m"));
  HylcCallHDF5(HylcH5WriteDataset(g, "X", 2, (hsize_t[]){(hsize_t)d.nv, 3}, H5T_NATIVE_DOUBLE, d.X, "m", "reference position of each vertex"));
  HylcCallHDF5(HylcH5WriteDataset(g, "theta", 1, (hsize_t[]){(hsize_t)d.nv}, H5T_NATIVE_DOUBLE, d.theta, "rad", "twist of the edge leaving each vertex"));
  PetscCall(DatasetInt(g, "next", d.nv, 0, d.next, "1", "head vertex of the edge leaving each vertex (0-based)"));
  PetscCall(DatasetInt(g, "prev", d.nv, 0, d.prev, "1", "tail vertex of the edge entering each vertex (0-based)"));
  PetscCall(DatasetInt(g, "shift", d.nv, 2, d.shift, "periods", "lattice offset (dx, dy) of the head of the edge leaving each vertex: it runs from X[v] to X[next[v]] + (dx px, dy py, 0)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "rest_length", 1, (hsize_t[]){(hsize_t)d.nv}, H5T_NATIVE_DOUBLE, d.restLength, "m", "rest length of the edge leaving each vertex"));
  HylcCallHDF5(HylcH5WriteDataset(g, "rest_kappa", 2, (hsize_t[]){(hsize_t)d.nv, 2}, H5T_NATIVE_DOUBLE, d.restKappa, "1", "rest material curvature (kappa1, kappa2) at each vertex (integrated, dimensionless)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "rest_twist", 1, (hsize_t[]){(hsize_t)d.nv}, H5T_NATIVE_DOUBLE, d.restTwist, "rad", "rest twist at each vertex"));
  HylcCallHDF5(HylcH5WriteDataset(g, "ref_d1", 2, (hsize_t[]){(hsize_t)d.nv, 3}, H5T_NATIVE_DOUBLE, d.refD1, "1", "reference director d1 of the edge leaving each vertex (unit, perpendicular to the edge)"));
  HylcCallHDF5(HylcH5WriteDataset(g, "ref_twist", 1, (hsize_t[]){(hsize_t)d.nv}, H5T_NATIVE_DOUBLE, d.refTwist, "rad", "reference twist at each vertex"));
  HylcCallHDF5(H5Gclose(g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteMaterialGroup(hid_t file, const HylcYarnModel *m, PetscReal patternRadius)
{
  static const char *const ContactNames[]   = {"quadrature", "closest"};
  static const char *const CurvatureNames[] = {"averaged", "per_edge"};
  HylcYarnConstants        c;
  hid_t                    g;

  PetscFunctionBegin;
  PetscCall(HylcYarnModelGetConstants(m, patternRadius, &c));
  HylcCallHDF5Id(g, H5Gcreate2(file, "material", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(g, "description", "yarn material and contact model (include/hylc/yarn.h): resolved values used by the solver, and the option values they came from (*_option; <= 0 means the default rule)"));
  HylcCallHDF5(HylcH5WriteAttrString(g, "units", "E, Es, G: Pa; kc: N/m; radius: m; ks: N; B, beta: N m^2; exclude_arc: yarn radii"));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "E", (double)c.E));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "Es", (double)c.Es));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "G", (double)c.G));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "kc", (double)c.kc));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "radius", (double)c.r));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "ks", (double)c.ks));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "B", (double)c.B));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "beta", (double)c.beta));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "Es_option", (double)m->Es));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "G_option", (double)m->G));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "kc_option", (double)m->kc));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "radius_option", (double)m->radius));
  HylcCallHDF5(HylcH5WriteAttrLong(g, "contact_points", (long long)m->contactPoints));
  HylcCallHDF5(HylcH5WriteAttrString(g, "contact_type", (int)m->contactType >= 0 && (int)m->contactType < 2 ? ContactNames[m->contactType] : "unknown"));
  HylcCallHDF5(HylcH5WriteAttrDouble(g, "exclude_arc", (double)m->excludeArc));
  HylcCallHDF5(HylcH5WriteAttrString(g, "curvature", (int)m->curvature >= 0 && (int)m->curvature < 2 ? CurvatureNames[m->curvature] : "unknown"));
  HylcCallHDF5(H5Gclose(g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteOptions(hid_t file, const char text[])
{
  PetscFunctionBegin;
  HylcCallHDF5(HylcH5WriteStrings(file, "options", 0, 1, &text, "the complete PETSc options of the run (PetscOptionsGetAll: command line, options files, environment), one string"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteFile(hid_t file, long N, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[])
{
  char      date[64], host[256], petscv[128];
  time_t    now = time(NULL);
  struct tm tm;
  long long ndone = 0, nconv = 0;
  unsigned  maj, min, rel;
  char      h5v[64];
  char     *allopts = NULL;
  PetscReal radius  = 0;

  PetscFunctionBegin;
  for (long k = 0; k < N; k++) {
    if (done && done[k]) {
      ndone++;
      if (recs[k].status == HYLC_MICRO_CONVERGED) nconv++;
    }
  }
  gmtime_r(&now, &tm);
  strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", &tm);
  if (gethostname(host, sizeof(host))) snprintf(host, sizeof(host), "unknown");
  host[sizeof(host) - 1] = 0;
  PetscCall(PetscGetVersion(petscv, sizeof(petscv)));
  HylcCallHDF5(H5get_libversion(&maj, &min, &rel));
  snprintf(h5v, sizeof(h5v), "%u.%u.%u", maj, min, rel);
  HylcCallHDF5(HylcH5WriteAttrString(file, "format", "hylc-samples"));
  HylcCallHDF5(HylcH5WriteAttrLong(file, "format_version", 1));
  HylcCallHDF5(HylcH5WriteAttrString(file, "hylc_version", HYLC_VERSION_STRING));
  HylcCallHDF5(HylcH5WriteAttrString(file, "petsc_version", petscv));
  HylcCallHDF5(HylcH5WriteAttrString(file, "hdf5_version", h5v));
  HylcCallHDF5(HylcH5WriteAttrString(file, "creation_date", date));
  HylcCallHDF5(HylcH5WriteAttrString(file, "hostname", host));
  HylcCallHDF5(HylcH5WriteAttrLong(file, "nsamples", (long long)N));
  HylcCallHDF5(HylcH5WriteAttrLong(file, "ndone", ndone));
  HylcCallHDF5(HylcH5WriteAttrLong(file, "nconverged", nconv));
  PetscCall(WriteSamplesGroup(file, N, recs, done));
  if (reference) {
    PetscCall(WriteReferenceGroup(file, reference));
    PetscCall(HylcPatternGetRadius(reference, &radius));
  }
  if (model) PetscCall(WriteMaterialGroup(file, model, model->radius > 0 ? model->radius : radius));
  if (!optionsText) PetscCall(PetscOptionsGetAll(NULL, &allopts));
  PetscCall(WriteOptions(file, optionsText ? optionsText : allopts));
  PetscCall(PetscFree(allopts));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* /provenance: the run's identity text, its SHA-256, and its lines by kind */
static PetscErrorCode WriteProvenance(hid_t file, const char identity[])
{
  char         hex[65], *copy, *line, *save = NULL;
  const char  *version[3] = {"", "", ""};
  const char **opts, **pat;
  int          nopt = 0, npat = 0, nlines = 1;
  hid_t        g;

  PetscFunctionBegin;
  HylcSamplesIdentityDigest(identity, hex);
  for (const char *c = identity; *c; c++) nlines += *c == '\n';
  PetscCall(PetscStrallocpy(identity, &copy));
  PetscCall(PetscMalloc2(nlines, &opts, nlines, &pat));
  for (line = strtok_r(copy, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
    if (!strncmp(line, "option ", 7))
      opts[nopt++] = line + 7;
    else if (!strncmp(line, "pattern ", 8))
      pat[npat++] = line + 8;
    else if (!strncmp(line, "version hylc ", 13))
      version[0] = line + 13;
    else if (!strncmp(line, "version build ", 14))
      version[1] = line + 14;
    else if (!strncmp(line, "version petsc ", 14))
      version[2] = line + 14;
  }
  HylcCallHDF5Id(g, H5Gcreate2(file, "provenance", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(
      g, "description",
      "the identity of the run: everything that can change a sample's result (versions, the pattern bit for bit, every option but the neutral ones of docs/output-format.md); digest = SHA-256 of the identity text, as in the journal"));
  HylcCallHDF5(HylcH5WriteAttrString(g, "digest", hex));
  HylcCallHDF5(HylcH5WriteAttrString(g, "digest_algorithm", "sha256"));
  HylcCallHDF5(HylcH5WriteAttrString(g, "hylc_version", version[0]));
  HylcCallHDF5(HylcH5WriteAttrString(g, "hylc_build", version[1]));
  HylcCallHDF5(HylcH5WriteAttrString(g, "petsc_version", version[2]));
  HylcCallHDF5(HylcH5WriteStrings(g, "options", 1, (hsize_t)nopt, opts, "the options of the identity, \"-name value\", sorted by name (neutral options left out)"));
  HylcCallHDF5(HylcH5WriteStrings(g, "pattern", 1, (hsize_t)npat, pat, "the pattern of the identity, \"field value\" (scalars) or \"field sha256:<digest of the array's bytes>\" (arrays, native layout)"));
  HylcCallHDF5(HylcH5WriteStrings(g, "identity", 0, 1, &identity, "the canonical identity text (its SHA-256 is /provenance@digest)"));
  HylcCallHDF5(H5Gclose(g));
  PetscCall(PetscFree2(opts, pat));
  PetscCall(PetscFree(copy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* builds the whole file in memory (HDF5's core driver, no backing store) and returns its image */
/* /plan: the spacing and, for graded spacing, its parameters and the knots of every axis of every term sampled
   (knots_<term> for a 1D term, knots_<term>_0, _1 (and _2) for the axes of a 2D (3D) term): the fabric fit's knots */
static PetscErrorCode WritePlan(hid_t file, const HylcPlan *plan)
{
  hid_t g;

  PetscFunctionBegin;
  HylcCallHDF5Id(g, H5Gcreate2(file, "plan", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(HylcH5WriteAttrString(g, "spacing", HylcPlanSpacings[plan->spacing]));
  HylcCallHDF5(HylcH5WriteAttrString(g, "description",
                                     "The sampling plan's spacing (-sampler_spacing); for graded spacing its parameters and the knots of each axis of each term (knots_<term>, knots_<term>_0, _1 and _2 for the axes of a 2D or 3D term), which the "
                                     "samples subdivide (docs/output-format.md)"));
  if (plan->spacing == HYLC_PLAN_SPACING_GRADED) {
    HylcCallHDF5(HylcH5WriteDataset(g, "h0", 1, (hsize_t[]){HYLC_PLAN_NCOORD}, H5T_NATIVE_DOUBLE, plan->h0, "1 for sx, sa, sy; 1/m for II00, II11", "knot spacing at 0 per coordinate"));
    HylcCallHDF5(HylcH5WriteAttrDouble(g, "growth", plan->growth));
    HylcCallHDF5(HylcH5WriteAttrDouble(g, "hmax", plan->hmax));
    HylcCallHDF5(HylcH5WriteAttrLong(g, "sub", plan->sub));
    for (int t = 1; t < HYLC_PLAN_NTERM3; t++) {
      if (!(plan->terms & (1 << t))) continue;
      for (int a = 0; a < HylcPlanTermDim(t); a++) {
        double    K[HYLC_PLAN_MAXAXIS];
        char      name[64];
        const int n = HylcPlanAxisKnots(plan, t, a, K);
        PetscCheck(n > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "graded knots of term %s", HylcPlanTermName(t));
        if (t <= 5)
          snprintf(name, sizeof(name), "knots_%s", HylcPlanTermName(t));
        else
          snprintf(name, sizeof(name), "knots_%s_%d", HylcPlanTermName(t), a);
        HylcCallHDF5(HylcH5WriteDataset(g, name, 1, (hsize_t[]){(hsize_t)n}, H5T_NATIVE_DOUBLE, K, "1 for sx, sa, sy; 1/m for II00, II11", "the knots of this axis of the term (ascending, 0 included)"));
      }
    }
  }
  HylcCallHDF5(H5Gclose(g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesReadKnots - The knots of axis a of term t of a samples file written with graded spacing (its /plan
  group, docs/output-format.md); n = 0 when the file has none (paper spacing, older files, the term not
  sampled). Not collective.

  Input Parameters:
+ path - the samples file
. t    - the term (1..21, include/hylc/plan.h)
- a    - the axis (0; 1 and 2 for the second and third coordinate of a 2D or 3D term)

  Output Parameters:
+ n - the number of knots (0: none)
- K - the knots (ascending; room for HYLC_PLAN_MAXAXIS)

  Level: developer

.seealso: HylcSamplesWriteHDF5WithIdentity(), HylcPlanAxisKnots()
@*/
PetscErrorCode HylcSamplesReadKnots(const char path[], int t, int a, PetscInt *n, PetscReal K[])
{
  hid_t       file, ds, sp;
  char        name[80];
  HylcH5Quiet q;
  htri_t      has;
  hssize_t    m;

  PetscFunctionBegin;
  *n = 0;
  PetscCheck(HylcPlanTermDim(t) >= 1 && a >= 0 && a < HylcPlanTermDim(t), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "HylcSamplesReadKnots: term %d axis %d", t, a);
  if (t <= 5)
    snprintf(name, sizeof(name), "plan/knots_%s", HylcPlanTermName(t));
  else
    snprintf(name, sizeof(name), "plan/knots_%s_%d", HylcPlanTermName(t), a);
  HylcH5QuietBegin(&q);
  file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  has  = file < 0 ? -1 : H5Lexists(file, "plan", H5P_DEFAULT) > 0 ? H5Lexists(file, name, H5P_DEFAULT) : 0;
  HylcH5QuietEnd(&q);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open %s as HDF5", path);
  if (has <= 0) {
    H5Fclose(file);
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  ds = H5Dopen2(file, name, H5P_DEFAULT);
  sp = ds < 0 ? -1 : H5Dget_space(ds);
  m  = sp < 0 ? -1 : H5Sget_simple_extent_npoints(sp);
  if (sp >= 0) H5Sclose(sp);
  if (ds < 0 || m < 1 || m > HYLC_PLAN_MAXAXIS || H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, K) < 0) {
    if (ds >= 0) H5Dclose(ds);
    H5Fclose(file);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: /%s is not a list of at most %d knots", path, name, HYLC_PLAN_MAXAXIS);
  }
  H5Dclose(ds);
  H5Fclose(file);
  for (hssize_t i = 0; i < m; i++) PetscCheck(PetscIsNormalReal(K[i]) || K[i] == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: /%s[%d] = %g is not finite", path, name, (int)i, (double)K[i]);
  for (hssize_t i = 1; i < m; i++) PetscCheck(K[i] > K[i - 1], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: /%s is not ascending at %d", path, name, (int)i);
  *n = (PetscInt)m;
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode BuildImage(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[], const char identity[], const HylcPlan *plan,
                                 void **image, size_t *size)
{
  hid_t          file;
  ssize_t        n = 0;
  PetscErrorCode ierr;
  char           msg[256];

  PetscFunctionBegin;
  *image = NULL;
  *size  = 0;
  if ((file = HylcH5ImageCreate(path, 1 << 20)) < 0) {
    HylcH5ErrorText(msg);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot create the samples file %s in memory%s", path, msg);
  }
  ierr = WriteFile(file, nsamples, recs, done, reference, model, optionsText);
  if (!ierr && identity) ierr = WriteProvenance(file, identity);
  if (!ierr && plan) ierr = WritePlan(file, plan);
  if (!ierr) {
    n = HylcH5ImageSize(file);
    if (n > 0) {
      ierr = PetscMalloc((size_t)n, image);
      if (!ierr && H5Fget_file_image(file, *image, (size_t)n) != n) n = -1;
    }
    if (!ierr && n <= 0) {
      HylcH5ErrorText(msg);
      H5Fclose(file);
      PetscCall(PetscFree(*image));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot build the samples file %s%s", path, msg);
    }
    *size = (size_t)n;
  }
  H5Fclose(file); /* strong close: also every object an error left open */
  if (ierr) PetscCall(PetscFree(*image));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesWriteHDF5WithIdentity - Writes the samples file (docs/output-format.md) atomically: the
  HDF5 image is built in memory, written to a unique temporary beside path, fsynced and renamed; on any
  failure (a full disk, say) the temporary is removed, path is left as it was and the error names it.
  With an identity, /provenance; with a plan, /plan (its spacing and graded knots, HylcSamplesReadKnots()).
  Not collective (rank 0).
@*/
PetscErrorCode HylcSamplesWriteHDF5WithIdentity(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[], const char identity[],
                                                const HylcPlan *plan)
{
  char           tmp[PETSC_MAX_PATH_LEN];
  HylcH5Quiet    quiet;
  void          *image = NULL;
  size_t         size  = 0;
  FILE          *fp    = NULL;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidCharPointer(path, 1);
  PetscCheck(nsamples >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: negative number of samples %ld", path, nsamples);
  HylcH5Where = path;
  /* HDF5 prints nothing itself: its innermost message goes into the PETSc error */
  HylcH5QuietBegin(&quiet);
  ierr = BuildImage(path, nsamples, recs, done, reference, model, optionsText, identity, plan, &image, &size);
  HylcH5QuietEnd(&quiet);
  HylcH5Where = "?";
  PetscCall(ierr);
  ierr = HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp);
  if (!ierr) {
    if (fwrite(image, 1, size, fp) != size) { /* the error (ENOSPC, EFBIG) stays on the stream: CommitTemp reports it */
    }
    ierr = HylcFileCommitTemp(&fp, tmp, path);
  }
  PetscCall(PetscFree(image));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesWriteHDF5 - HylcSamplesWriteHDF5WithIdentity() without /provenance. Not collective.
@*/
PetscErrorCode HylcSamplesWriteHDF5(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[])
{
  PetscFunctionBegin;
  PetscCall(HylcSamplesWriteHDF5WithIdentity(path, nsamples, recs, done, reference, model, optionsText, NULL, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the datasets of /samples that HylcSamplesReadHDF5() reads (start, negcurv, escapes, psi_other,
   status_other, multistable and stress are newer than the format's first files: optional) */
static const HylcTableColumn SamplesColumns[] = {
    {"strain", 6, H5T_FLOAT, PETSC_FALSE},       {"psi", 0, H5T_FLOAT, PETSC_FALSE},      {"energy_parts", 4, H5T_FLOAT, PETSC_FALSE}, {"residual", 0, H5T_FLOAT, PETSC_FALSE},     {"constraint_residual", 0, H5T_FLOAT, PETSC_FALSE},
    {"time", 0, H5T_FLOAT, PETSC_FALSE},         {"term", 0, H5T_INTEGER, PETSC_FALSE},   {"status", 0, H5T_INTEGER, PETSC_FALSE},     {"iterations", 0, H5T_INTEGER, PETSC_FALSE}, {"retries", 0, H5T_INTEGER, PETSC_FALSE},
    {"start", 0, H5T_INTEGER, PETSC_TRUE},       {"negcurv", 0, H5T_INTEGER, PETSC_TRUE}, {"escapes", 0, H5T_INTEGER, PETSC_TRUE},     {"psi_other", 0, H5T_FLOAT, PETSC_TRUE},     {"status_other", 0, H5T_INTEGER, PETSC_TRUE},
    {"multistable", 0, H5T_INTEGER, PETSC_TRUE}, {"stress", 6, H5T_FLOAT, PETSC_TRUE}};
#define NSAMPLESCOLUMNS ((int)(sizeof(SamplesColumns) / sizeof(SamplesColumns[0])))

/* whether /samples/name exists (checked by HylcTableCheckHDF5Columns() when it does) */
static int HasColumn(hid_t file, const char name[])
{
  HylcH5Quiet q;
  char        full[64];
  htri_t      has;

  snprintf(full, sizeof(full), "samples/%s", name);
  HylcH5QuietBegin(&q);
  has = H5Lexists(file, full, H5P_DEFAULT);
  HylcH5QuietEnd(&q);
  return has > 0;
}

/* every column read into the arrays given (allocated for N + 1 rows by the caller) */
static PetscErrorCode ReadColumns(hid_t file, const char path[], double *strain, double *psi, double *parts, double *res, double *cres, double *tm, int *term, int *status, int *its, int *retries, int *start, int *negcurv, int *escapes, double *psio,
                                  int *stato, int *multi, double *stress)
{
  PetscFunctionBegin;
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/strain", H5T_NATIVE_DOUBLE, strain));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/psi", H5T_NATIVE_DOUBLE, psi));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/energy_parts", H5T_NATIVE_DOUBLE, parts));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/residual", H5T_NATIVE_DOUBLE, res));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/constraint_residual", H5T_NATIVE_DOUBLE, cres));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/time", H5T_NATIVE_DOUBLE, tm));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/term", H5T_NATIVE_INT, term));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/status", H5T_NATIVE_INT, status));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/iterations", H5T_NATIVE_INT, its));
  PetscCall(HylcTableReadHDF5Column(file, path, "samples/retries", H5T_NATIVE_INT, retries));
  /* files before /samples/start: every sample was cold (0); before /samples/negcurv and /samples/escapes:
     not tested (-1), no escape (0) */
  if (HasColumn(file, "start")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/start", H5T_NATIVE_INT, start));
  if (HasColumn(file, "negcurv")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/negcurv", H5T_NATIVE_INT, negcurv));
  if (HasColumn(file, "escapes")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/escapes", H5T_NATIVE_INT, escapes));
  /* files before -sampler_start both: not compared (NaN, -1, -1) */
  if (HasColumn(file, "psi_other")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/psi_other", H5T_NATIVE_DOUBLE, psio));
  if (HasColumn(file, "status_other")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/status_other", H5T_NATIVE_INT, stato));
  if (HasColumn(file, "multistable")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/multistable", H5T_NATIVE_INT, multi));
  /* files before the stress: NaN */
  if (HasColumn(file, "stress")) PetscCall(HylcTableReadHDF5Column(file, path, "samples/stress", H5T_NATIVE_DOUBLE, stress));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadFile(hid_t file, const char path[], long *nsamples, HylcSampleRecord **recs_, unsigned char **done_, char **optionsText)
{
  hsize_t           dims;
  long              N;
  double           *strain, *psi, *parts, *res, *cres, *tm;
  int              *term, *status, *its, *retries, *start, *negcurv, *escapes;
  HylcSampleRecord *recs = NULL;
  unsigned char    *done = NULL;
  PetscErrorCode    ierr;
  double           *psio, *stress;
  int              *stato, *multi;

  PetscFunctionBegin;
  /* every dataset checked (kind, class, shape, declared size) before anything is allocated */
  PetscCall(HylcTableCheckHDF5Columns(file, path, NULL, "samples", NSAMPLESCOLUMNS, SamplesColumns, &dims));
  PetscCheck(dims <= (hsize_t)(PETSC_MAX_INT / 6), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: /samples has %llu rows, more than this build reads", path, (unsigned long long)dims);
  N = (long)dims;
  PetscCall(PetscMalloc6(6 * N + 1, &strain, N + 1, &psi, 4 * N + 1, &parts, N + 1, &res, N + 1, &cres, N + 1, &tm));
  PetscCall(PetscMalloc4(N + 1, &term, N + 1, &status, N + 1, &its, N + 1, &retries));
  PetscCall(PetscCalloc3(N + 1, &start, N + 1, &negcurv, N + 1, &escapes));
  PetscCall(PetscMalloc4(N + 1, &psio, N + 1, &stato, N + 1, &multi, 6 * N + 1, &stress));
  for (long k = 0; k < N; k++) negcurv[k] = -1, psio[k] = NAN, stato[k] = -1, multi[k] = -1;
  for (long k = 0; k < 6 * N; k++) stress[k] = NAN;
  ierr = ReadColumns(file, path, strain, psi, parts, res, cres, tm, term, status, its, retries, start, negcurv, escapes, psio, stato, multi, stress);
  if (!ierr) ierr = PetscCalloc1(N + 1, &recs);
  if (!ierr) ierr = PetscCalloc1(N + 1, &done);
  for (long k = 0; !ierr && k < N; k++) {
    HylcSampleRecord *r = &recs[k];
    r->index            = k;
    for (int i = 0; i < 6; i++) r->z[i] = strain[6 * k + i];
    for (int i = 0; i < 4; i++) r->parts[i] = parts[4 * k + i];
    r->psi         = psi[k];
    r->residual    = res[k];
    r->cresidual   = cres[k];
    r->time        = tm[k];
    r->term        = term[k];
    r->status      = status[k];
    r->iterations  = its[k];
    r->retries     = retries[k];
    r->start       = start[k] >= 0 ? start[k] : 0;
    r->negcurv     = negcurv[k] >= 0 ? negcurv[k] : -1;
    r->escapes     = escapes[k] >= 0 ? escapes[k] : 0;
    r->psiOther    = psio[k];
    r->statusOther = stato[k] >= -1 && stato[k] < HylcSamplesNumStatuses_() ? stato[k] : -1;
    r->multistable = multi[k] >= -1 && multi[k] <= 1 ? multi[k] : -1;
    for (int i = 0; i < 6; i++) r->stress[i] = stress[6 * k + i];
    done[k] = status[k] >= 0;
  }
  PetscCall(PetscFree4(psio, stato, multi, stress));
  PetscCall(PetscFree6(strain, psi, parts, res, cres, tm));
  PetscCall(PetscFree4(term, status, its, retries));
  PetscCall(PetscFree3(start, negcurv, escapes));
  if (!ierr && optionsText) {
    char       *text = NULL;
    HylcH5Quiet q;
    herr_t      e;

    HylcH5QuietBegin(&q);
    e = HylcH5ReadString(file, "options", &text);
    HylcH5QuietEnd(&q);
    if (e < 0) {
      free(text);
      ierr = PETSC_ERR_FILE_READ;
      (void)PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, ierr, PETSC_ERROR_INITIAL, "Cannot read dataset /options of %s (the options text)", path);
    } else {
      ierr = PetscStrallocpy(text ? text : "", optionsText);
      free(text);
    }
  }
  if (ierr) {
    PetscCall(PetscFree(recs));
    PetscCall(PetscFree(done));
  }
  PetscCall(ierr);
  *nsamples = N;
  *recs_    = recs;
  *done_    = done;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesCheckHDF5 - Checks the datasets of /samples of a samples file (each there, a dataset of the
  class and shape of the format, one row per sample, storing what it declares) before anything is read:
  a problem is one PETSC_ERR_FILE_UNEXPECTED error "path (option): ..." naming the dataset, and HDF5
  prints nothing. HylcSamplesReadHDF5() makes the same checks. Not collective.

  Input Parameters:
+ path   - the file
- option - the option that named it (for the messages), or NULL

  Level: developer
@*/
PetscErrorCode HylcSamplesCheckHDF5(const char path[], const char option[])
{
  hid_t          file;
  HylcH5Quiet    quiet;
  PetscErrorCode ierr;
  hsize_t        N;
  char           msg[256];

  PetscFunctionBegin;
  HylcH5QuietBegin(&quiet);
  file = HylcH5FileOpen(path);
  if (file < 0) HylcH5ErrorText(msg);
  HylcH5QuietEnd(&quiet);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open the samples file %s%s%s%s as HDF5%s", path, option ? " (" : "", option ? option : "", option ? ")" : "", msg);
  ierr = HylcTableCheckHDF5Columns(file, path, option, "samples", NSAMPLESCOLUMNS, SamplesColumns, &N);
  HylcH5QuietBegin(&quiet);
  H5Fclose(file);
  HylcH5QuietEnd(&quiet);
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesReadHDF5 - Reads /samples (and /options) of a samples file. Not collective.
@*/
PetscErrorCode HylcSamplesReadHDF5(const char path[], long *nsamples, HylcSampleRecord **recs, unsigned char **done, char **optionsText)
{
  hid_t          file;
  HylcH5Quiet    quiet;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidCharPointer(path, 1);
  PetscValidPointer(nsamples, 2);
  PetscValidPointer(recs, 3);
  PetscValidPointer(done, 4);
  HylcH5Where = path;
  HylcH5QuietBegin(&quiet);
  file = HylcH5FileOpen(path);
  if (file < 0) {
    char msg[256];
    HylcH5ErrorText(msg);
    HylcH5QuietEnd(&quiet);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open the samples file %s%s", path, msg);
  }
  HylcH5QuietEnd(&quiet);
  ierr = ReadFile(file, path, nsamples, recs, done, optionsText);
  HylcH5QuietBegin(&quiet);
  H5Fclose(file);
  HylcH5QuietEnd(&quiet);
  HylcH5Where = "?";
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}
