/* HylcSampler: the set-up (pattern, plan, solver, outputs, journal, reference state) and the MPI sampling run. */
#include "samplerimpl.h"
#include <hylc/files.h>
#include <petsctime.h>
#include <unistd.h>
#include <string.h>
#include <sys/stat.h>

#define TAG_RECORDS 7301
#define TAG_DONE    7302

/* the pattern set up, the plan resolved for its radius, the solver given the pattern and set up (its
   options, and its tile's, were read by HylcSamplerSetFromOptions(): the tile keeps them) */
PetscErrorCode HylcSamplerSetUpSolver_Private(HylcSampler S)
{
  MPI_Comm    comm = PetscObjectComm((PetscObject)S);
  HylcPattern pat;
  HylcMicro   micro;
  PetscReal   r;

  PetscFunctionBegin;
  PetscCall(HylcSamplerGetPattern(S, &pat));
  PetscCall(HylcSamplerGetMicro(S, &micro));
  PetscCall(HylcPatternSetUp(pat));
  PetscCall(HylcPatternGetRadius(pat, &r));
  PetscCall(HylcPlanRangesApply(comm, &S->ranges, r, &S->plan));
  S->plan.n1    = (int)S->n1;
  S->plan.n2    = (int)S->n2;
  S->plan.terms = (int)S->terms;
  PetscCall(HylcMicroSetPattern(micro, pat, &S->model));
  PetscCall(HylcMicroSetUp(micro));
  S->nsamples = HylcPlanSize(&S->plan);
  PetscCheck(S->nsamples > 0, comm, PETSC_ERR_USER_INPUT, "The sampling plan is empty (-sampler_terms)");
  S->solverSetUp = PETSC_TRUE;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0, before any solve: every output path writable and none of them an input, the existing output
   and journal as the mode allows, then the journal locked and opened (resume: the identity checked) */
static PetscErrorCode CheckOutputsAndLock(HylcSampler S)
{
  char            jpath[PETSC_MAX_PATH_LEN + 16], raw[2][PETSC_MAX_PATH_LEN + 16], pfileopt[300];
  const char     *pfile = "", *prefix = ((PetscObject)S)->prefix;
  HylcPatternType type;
  PetscBool       isfile;
  struct stat     st;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(jpath, sizeof(jpath), "%s.journal", S->output));
  PetscCall(HylcPatternGetType(S->pat, &type));
  PetscCall(PetscStrcmp(type, HYLCPATTERNFILE, &isfile));
  if (isfile) PetscCall(HylcPatternGetFileName(S->pat, &pfile));
  PetscCall(PetscSNPrintf(pfileopt, sizeof(pfileopt), "-%spattern_file", prefix ? prefix : ""));
  if (S->rawdir[0]) {
    PetscCheck(stat(S->rawdir, &st) == 0 && S_ISDIR(st.st_mode), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot write into -sampler_export_raw %s: %s", S->rawdir, stat(S->rawdir, &st) ? "no such directory (create it first)" : "not a directory");
    PetscCall(PetscSNPrintf(raw[0], sizeof(raw[0]), "%s/data.txt", S->rawdir));
    PetscCall(PetscSNPrintf(raw[1], sizeof(raw[1]), "%s/info.txt", S->rawdir));
  }
  /* every file (include/hylc/files.h): the pattern file and the options files read; the samples file, its
     journal, the reference state and the raw export writable and within the path limits, none of them
     an input or another output */
  {
    HylcFiles      files;
    PetscErrorCode ierr;
    PetscCall(HylcFilesCreate(PETSC_COMM_SELF, &files));
    ierr = HylcFilesAddOptionsFiles(files);
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_INPUT, pfile, pfileopt);
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, S->output, "-sampler_output");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, jpath, "the journal of -sampler_output");
    if (!ierr) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, S->refout, "-reference_output");
    if (!ierr && S->rawdir[0]) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, raw[0], "-sampler_export_raw");
    if (!ierr && S->rawdir[0]) ierr = HylcFilesAdd(files, HYLC_FILE_OUTPUT, raw[1], "-sampler_export_raw");
    if (!ierr) ierr = HylcFilesCheck(files);
    PetscCall(HylcFilesDestroy(&files));
    PetscCall(ierr);
  }
  if (!S->resume && !S->overwrite) PetscCheck(access(S->output, F_OK) != 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Output %s exists: start over with -sampler_overwrite, or continue its run with -sampler_resume", S->output);
  if (S->resume)
    PetscCheck(access(S->output, F_OK) != 0 || access(jpath, F_OK) == 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "-sampler_resume: output %s exists but its journal %s does not, so there is no run to continue: start over with -sampler_overwrite",
               S->output, jpath);
  PetscCall(HylcSamplesIdentity(S->pat, &S->identity));
  PetscCall(HylcJournalOpen(jpath, S->resume ? HYLC_JOURNAL_RESUME : (S->overwrite ? HYLC_JOURNAL_OVERWRITE : HYLC_JOURNAL_NEW), S->nsamples, S->identity, &S->journal));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerSetUp - Loads or generates the pattern, resolves the plan for its yarn radius and sets up the
  solver. Then, before any solve: refuses unknown options, checks every output path (writable, not a
  directory, not an input), locks and opens the journal (a resume with other settings is refused here,
  naming them); the verdict of rank 0 is shared, so every rank raises the same error. Then computes the
  reference state when asked for (Algorithm C1). -sampler_view prints the job at the end.

  Collective

  Input Parameter:
. S - the sampler

  Level: beginner

.seealso: HylcSamplerSetFromOptions(), HylcSamplerRun()
@*/
PetscErrorCode HylcSamplerSetUp(HylcSampler S)
{
  MPI_Comm comm      = PetscObjectComm((PetscObject)S);
  int      code      = 0;
  char     msg[2048] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  if (S->setupcalled) PetscFunctionReturn(PETSC_SUCCESS);
  if (!S->solverSetUp) PetscCall(HylcSamplerSetUpSolver_Private(S));
  PetscCall(HylcCheckOptionsUsed(comm));
  PetscCheck(!(S->resume && S->overwrite), comm, PETSC_ERR_USER_INPUT, "-sampler_resume (continue the run) and -sampler_overwrite (start over) exclude each other");
  if (!S->rank) {
    PetscErrorCode ierr;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CheckOutputsAndLock(S);
    PetscCall(PetscPopErrorHandler());
    if (ierr) {
      char *text = NULL;
      code       = (int)ierr;
      PetscCall(PetscErrorMessage(ierr, NULL, &text));
      PetscCall(PetscStrncpy(msg, text && text[0] ? text : "checking the outputs failed", sizeof(msg)));
    }
  }
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, 0, comm));
  if (code) {
    PetscCallMPI(MPI_Bcast(msg, (PetscMPIInt)sizeof(msg), MPI_CHAR, 0, comm));
    SETERRQ(comm, (PetscErrorCode)code, "%s", msg);
  }
  {
    HylcPattern ref;
    PetscCall(HylcReferenceStateForMode(S->pat, S->refmode, &S->model, &S->refpar, S->rank ? NULL : PETSC_VIEWER_STDOUT_SELF, &ref));
    if (ref) {
      PetscCall(HylcPatternDestroy(&S->pat));
      S->pat = ref;
      PetscCall(HylcMicroSetPattern(S->micro, S->pat, &S->model));
    }
  }
  if (S->refout[0]) PetscCall(HylcPatternWrite(S->pat, S->refout));
  S->setupcalled = PETSC_TRUE;
  PetscCall(HylcSamplerViewFromOptions(S, NULL, "-sampler_view"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void FillRecord(long k, int term, const double z[6], const HylcMicroResult *r, HylcSampleRecord *rec)
{
  memset(rec, 0, sizeof(*rec));
  rec->index      = k;
  rec->term       = term;
  rec->status     = (int)r->status;
  rec->iterations = (int)r->iterations;
  rec->retries    = (int)r->retries;
  for (int i = 0; i < 6; i++) rec->z[i] = z[i];
  rec->psi = r->psi;
  for (int i = 0; i < 4; i++) rec->parts[i] = r->parts[i];
  rec->residual    = r->residual;
  rec->cresidual   = r->cresidual;
  rec->time        = r->time;
  rec->start       = HYLC_SAMPLE_START_COLD;
  rec->negcurv     = (int)r->negcurv;
  rec->escapes     = (int)r->escapes;
  rec->psiOther    = NAN;
  rec->statusOther = -1;
  rec->multistable = -1;
  for (int i = 0; i < 6; i++) rec->stress[i] = NAN;
}

/* the stress of the micro solver's last equilibrium into rec, if it converged and the run records it */
static PetscErrorCode RecordStress(HylcSampler S, HylcSampleRecord *rec)
{
  PetscFunctionBegin;
  if (S->stress && rec->status == HYLC_MICRO_CONVERGED) {
    PetscReal g[6];
    PetscCall(HylcMicroGetStrainGradient(S->micro, HYLC_STRAIN_ALL_BITS | HYLC_STRAIN_NO_POISSON, g));
    for (int i = 0; i < 6; i++) rec->stress[i] = g[i];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the order of outcomes: converged, then not converged, then non-finite */
static int OutcomeRank(const HylcMicroResult *r) { return r->status == HYLC_MICRO_CONVERGED ? 0 : r->status == HYLC_MICRO_NONFINITE ? 2 : 1; }

/* sample k; from the fluctuation u (local coordinates, HylcMicroGetFluctuation() of the kept state of the
   sample before it on its half-line) if not NULL. On return the kept result's state is in 'state' (if not
   NULL).
   - cold and continue: a continued solve that does not converge is retried cold, and the better of the two
     is kept (converged, then not converged, then non-finite; the cold one on a tie). A continued solve that
     converges is kept even below its predecessor's Psi: different equilibria of cold and continued starts
     are path dependence (buckled compressions), and the lower energy is the better estimate
     (docs/performance.md, "Continuation").
   - both: the cold solve always, then the continued one if u is given; the continued one is kept if it is
     better (both converged: a Psi strictly lower), and the other one's Psi and status are recorded, with the
     multistable flag where both converged and differ by more than bothRtol of the larger |Psi|.
   Iterations and time are the sums of the solves. */
static PetscErrorCode SolveSample(HylcSampler S, long k, const PetscReal *u, PetscReal *state, HylcSampleRecord *rec)
{
  HylcMicroResult r, rc;
  double          z[6];
  int             term;

  PetscFunctionBegin;
  PetscCheck(!HylcPlanSample(&S->plan, k, z, &term), PETSC_COMM_SELF, PETSC_ERR_PLIB, "Sample %ld outside the plan", k);
  if (S->start == HYLC_SAMPLER_START_BOTH) {
    PetscCall(HylcMicroSolve(S->micro, z, &rc));
    FillRecord(k, term, z, &rc, rec);
    PetscCall(RecordStress(S, rec));
    if (state) PetscCall(HylcMicroGetState(S->micro, state));
    if (u) {
      PetscBool contBetter;
      PetscCall(HylcMicroSetInitialFluctuation(S->micro, u));
      PetscCall(HylcMicroSolve(S->micro, z, &r));
      contBetter = (PetscBool)(OutcomeRank(&r) < OutcomeRank(&rc) || (r.status == HYLC_MICRO_CONVERGED && rc.status == HYLC_MICRO_CONVERGED && r.psi < rc.psi));
      if (contBetter) {
        FillRecord(k, term, z, &r, rec);
        PetscCall(RecordStress(S, rec));
        rec->start = HYLC_SAMPLE_START_CONTINUED;
        if (state) PetscCall(HylcMicroGetState(S->micro, state));
      }
      rec->psiOther    = contBetter ? rc.psi : r.psi;
      rec->statusOther = (int)(contBetter ? rc.status : r.status);
      if (r.status == HYLC_MICRO_CONVERGED && rc.status == HYLC_MICRO_CONVERGED) rec->multistable = PetscAbsReal(r.psi - rc.psi) > S->bothRtol * PetscMax(PetscAbsReal(r.psi), PetscAbsReal(rc.psi));
      rec->iterations = (int)(r.iterations + rc.iterations);
      rec->time       = r.time + rc.time;
    }
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  {
    PetscBool retried;
    PetscCall(HylcMicroSolveContinued(S->micro, z, u, &r, state, &retried));
    FillRecord(k, term, z, &r, rec);
    PetscCall(RecordStress(S, rec)); /* a converged result is the last solve's (HylcMicroSolveContinued()) */
    rec->start = !u ? HYLC_SAMPLE_START_COLD : (retried ? HYLC_SAMPLE_START_RETRIED : HYLC_SAMPLE_START_CONTINUED);
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

typedef struct {
  long           done, total, failed, converged0;
  PetscLogDouble t0, last;
} Progress;

static PetscErrorCode Report(HylcSampler S, Progress *pg, PetscBool force)
{
  PetscLogDouble now;

  PetscFunctionBegin;
  PetscCall(PetscTime(&now));
  if (!force && now - pg->last < S->progress) PetscFunctionReturn(PETSC_SUCCESS);
  pg->last               = now;
  const double rate      = (pg->done - pg->converged0) / PetscMax(now - pg->t0, 1e-9);
  const double remaining = rate > 0 ? (pg->total - pg->done) / rate : 0;
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] %ld/%ld samples (%.1f%%), %ld not converged, %.2f samples/s, ETA %.0f s\n", pg->done, pg->total, 100.0 * pg->done / PetscMax(pg->total, 1), pg->failed, rate, remaining));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* rank 0: receive whatever records have arrived, append them to the journal */
static PetscErrorCode Drain(HylcSampler S, HylcJournal J, Progress *pg, PetscInt *finished, PetscBool wait)
{
  HylcSampleRecord *buf = NULL;

  PetscFunctionBegin;
  for (;;) {
    PetscMPIInt flag, count;
    MPI_Status  st;
    if (wait) {
      PetscCallMPI(MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, PetscObjectComm((PetscObject)S), &st));
      flag = 1;
    } else
      PetscCallMPI(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, PetscObjectComm((PetscObject)S), &flag, &st));
    if (!flag) break;
    if (st.MPI_TAG == TAG_DONE) {
      int dummy;
      PetscCallMPI(MPI_Recv(&dummy, 1, MPI_INT, st.MPI_SOURCE, TAG_DONE, PetscObjectComm((PetscObject)S), MPI_STATUS_IGNORE));
      (*finished)++;
    } else {
      PetscCallMPI(MPI_Get_count(&st, MPI_BYTE, &count));
      const PetscInt n = count / (PetscMPIInt)sizeof(HylcSampleRecord);
      PetscCall(PetscFree(buf)); /* a batch or a whole unit of continuation */
      PetscCall(PetscMalloc1(n + 1, &buf));
      PetscCallMPI(MPI_Recv(buf, count, MPI_BYTE, st.MPI_SOURCE, TAG_RECORDS, PetscObjectComm((PetscObject)S), MPI_STATUS_IGNORE));
      PetscCall(HylcJournalAppend(J, buf, n));
      for (PetscInt i = 0; i < n; i++) pg->failed += buf[i].status != HYLC_MICRO_CONVERGED;
      pg->done += n;
    }
    if (wait) break;
  }
  PetscCall(PetscFree(buf));
  PetscCall(Report(S, pg, PETSC_FALSE));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the raw layout of the paper's fitting scripts: data.txt rows "sx sa sy II00 II01 II11 Psi" in the order of
   C4 (the 1D terms, then the 2D terms; the zero sample is not a row), info.txt with the tile area (m^2)
   and the area density (kg/m^2) */
static PetscErrorCode ExportRaw(HylcSampler S, const HylcSampleRecord *all, const unsigned char *done)
{
  char      path[PETSC_MAX_PATH_LEN + 16], tmp[PETSC_MAX_PATH_LEN + 32];
  FILE     *fp;
  PetscReal px, py, rhoA;
  long      rows = 0, skipped = 0;

  PetscFunctionBegin;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/data.txt", S->rawdir));
  PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
  for (long k = 0; k < S->nsamples; k++) {
    if (!done[k] || all[k].term == 0) continue;
    if (all[k].status != HYLC_MICRO_CONVERGED) skipped++;
    fprintf(fp, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", all[k].z[0], all[k].z[1], all[k].z[2], all[k].z[3], all[k].z[4], all[k].z[5], all[k].psi);
    rows++;
  }
  PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  PetscCall(HylcPatternGetPeriods(S->pat, &px, &py));
  PetscCall(HylcPatternGetAreaDensity(S->pat, S->density, &rhoA));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/info.txt", S->rawdir));
  PetscCall(HylcFileOpenTemp(path, tmp, sizeof(tmp), &fp));
  fprintf(fp, "area %.17g\ndensity %.17g\n", (double)(px * py), (double)rhoA);
  PetscCall(HylcFileCommitTemp(&fp, tmp, path));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] wrote %s/data.txt (%ld rows%s) and info.txt\n", S->rawdir, rows, skipped ? ", some not converged: see /samples/status" : ""));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplerRun - Solves every sample of the plan not yet in the journal, gathers the records on rank 0
  and writes the HDF5 output (and the raw layout of -sampler_export_raw).

  Collective

  Input Parameter:
. S - the sampler, set up

  Level: beginner

.seealso: HylcSamplerSetUp()
@*/
PetscErrorCode HylcSamplerRun(HylcSampler S)
{
  char              jpath[PETSC_MAX_PATH_LEN + 16];
  HylcJournal       J = S->journal;
  unsigned char    *done;
  HylcSampleRecord *recs;
  Progress          pg;
  PetscInt          finished = 0;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(S, HYLC_SAMPLER_CLASSID, 1);
  PetscCheck(S->setupcalled, PetscObjectComm((PetscObject)S), PETSC_ERR_ARG_WRONGSTATE, "Call HylcSamplerSetUp() first");
  PetscCall(PetscLogEventBegin(HYLC_SamplerRun, S, 0, 0, 0));
  PetscCall(PetscSNPrintf(jpath, sizeof(jpath), "%s.journal", S->output));
  PetscCheck(S->rank || J, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Call HylcSamplerSetUp() first");
  PetscCall(PetscFree(S->done));
  PetscCall(PetscFree(S->recs));
  PetscCall(PetscMalloc1(S->nsamples + 1, &S->done));
  PetscCall(PetscMalloc1(S->batch, &S->recs));
  done = S->done;
  recs = S->recs;
  PetscCall(PetscArrayzero(done, S->nsamples + 1));
  PetscCall(PetscMemzero(&pg, sizeof(pg)));
  pg.total = S->nsamples;
  if (!S->rank) {
    const unsigned char *jd;
    PetscInt             nd;
    PetscCall(HylcJournalGetDone(J, &nd, &jd));
    PetscCall(PetscArraycpy(done, jd, S->nsamples));
    pg.done = pg.converged0 = nd;
    if (S->start != HYLC_SAMPLER_START_COLD)
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] %ld samples in %ld half-lines (%s) on %d ranks; %ld already done (%s)\n", S->nsamples, HylcPlanUnits(&S->plan, NULL, NULL),
                            S->start == HYLC_SAMPLER_START_BOTH ? "continuation, and every sample also cold" : "continuation", (int)S->size, (long)nd, jpath));
    else
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] %ld samples in %ld batches on %d ranks; %ld already done (%s)\n", S->nsamples, (S->nsamples + S->batch - 1) / S->batch, (int)S->size, (long)nd, jpath));
  }
  PetscCallMPI(MPI_Bcast(done, (PetscMPIInt)S->nsamples, MPI_UNSIGNED_CHAR, 0, PetscObjectComm((PetscObject)S)));
  PetscCall(PetscTime(&pg.t0));
  pg.last = pg.t0;
  /* dynamic scheduling: the next batch (cold) or unit (continue: a half-line, HylcPlanUnits) comes from a
     shared counter on rank 0 (MPI one-sided atomic fetch-and-add, no involvement of rank 0); which rank
     solves a sample (cold) or a unit (continue) does not change its result */
  const PetscBool cont   = (PetscBool)(S->start != HYLC_SAMPLER_START_COLD); /* continue and both: units are half-lines */
  long           *ustart = NULL, *uorder = NULL, nb;
  PetscReal      *uprev = NULL, *ycur = NULL;
  PetscInt        ny = 0, cap = S->batch;
  if (cont) {
    const long nu = HylcPlanUnits(&S->plan, NULL, NULL);
    PetscCheck(nu > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "Invalid plan for the units of continuation");
    PetscCall(PetscMalloc2(nu + 1, &ustart, S->nsamples, &uorder));
    PetscCheck(HylcPlanUnits(&S->plan, ustart, uorder) == nu && ustart[nu] == S->nsamples, PETSC_COMM_SELF, PETSC_ERR_PLIB, "The units of continuation do not cover the plan");
    for (long u = 0; u < nu; u++) cap = PetscMax(cap, (PetscInt)(ustart[u + 1] - ustart[u]));
    nb = nu;
    if (cap > S->batch) {
      PetscCall(PetscFree(S->recs));
      PetscCall(PetscMalloc1(cap, &S->recs));
      recs = S->recs;
    }
  } else
    nb = (S->nsamples + S->batch - 1) / S->batch;
  long   *counter = NULL, one = 1, b;
  MPI_Win win;
  PetscCallMPI(MPI_Win_allocate(S->rank ? 0 : (MPI_Aint)sizeof(long), sizeof(long), MPI_INFO_NULL, PetscObjectComm((PetscObject)S), &counter, &win));
  if (!S->rank) *counter = 0;
  PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)S)));
  PetscCallMPI(MPI_Win_lock_all(0, win));
  for (;;) {
    PetscCallMPI(MPI_Fetch_and_op(&one, &b, MPI_LONG, 0, 0, MPI_SUM, win));
    PetscCallMPI(MPI_Win_flush(0, win));
    if (b >= nb) break;
    PetscInt n = 0;
    if (cont) {
      /* a unit is solved whole, from its first sample, if any of its samples is not in the journal (a unit
         cut by a kill is recomputed from its start, so a resumed run is bitwise an uninterrupted one), and
         its records are sent and journalled together */
      PetscBool todo = PETSC_FALSE, prevOk = PETSC_FALSE;
      for (long i = ustart[b]; i < ustart[b + 1]; i++)
        if (!done[uorder[i]]) todo = PETSC_TRUE;
      if (!todo) continue;
      for (long i = ustart[b]; i < ustart[b + 1]; i++) {
        PetscCall(SolveSample(S, uorder[i], prevOk ? uprev : NULL, ycur, &recs[n]));
        if (!ycur) { /* the tile's size is known after its first set-up (a cold solve: its state is the kept one) */
          HylcPeriodic P;
          PetscCall(HylcMicroGetPeriodic(S->micro, &P));
          PetscCall(HylcPeriodicGetSizes(P, &ny, NULL, NULL, NULL));
          PetscCall(PetscMalloc2(ny, &uprev, ny, &ycur));
          PetscCall(HylcMicroGetState(S->micro, ycur));
        }
        /* the kept state's fluctuation, taken while the tile is at this sample's strain */
        prevOk = (PetscBool)(recs[n].status == HYLC_MICRO_CONVERGED);
        if (prevOk) PetscCall(HylcMicroGetFluctuation(S->micro, ycur, uprev));
        n++;
        if (!S->rank) PetscCall(Drain(S, J, &pg, &finished, PETSC_FALSE));
      }
    } else {
      for (long k = b * S->batch; k < PetscMin((b + 1) * S->batch, S->nsamples); k++) {
        if (done[k]) continue;
        PetscCall(SolveSample(S, k, NULL, NULL, &recs[n++]));
        if (!S->rank) PetscCall(Drain(S, J, &pg, &finished, PETSC_FALSE));
      }
    }
    if (!n) continue;
    if (S->rank)
      PetscCallMPI(MPI_Send(recs, (PetscMPIInt)(n * sizeof(HylcSampleRecord)), MPI_BYTE, 0, TAG_RECORDS, PetscObjectComm((PetscObject)S)));
    else {
      PetscCall(HylcJournalAppend(J, recs, n));
      for (PetscInt i = 0; i < n; i++) pg.failed += recs[i].status != HYLC_MICRO_CONVERGED;
      pg.done += n;
      PetscCall(Report(S, &pg, PETSC_FALSE));
    }
  }
  PetscCallMPI(MPI_Win_unlock_all(win));
  if (S->rank) {
    int fin = 1;
    PetscCallMPI(MPI_Send(&fin, 1, MPI_INT, 0, TAG_DONE, PetscObjectComm((PetscObject)S)));
  } else {
    while (finished < S->size - 1) PetscCall(Drain(S, J, &pg, &finished, PETSC_TRUE));
    PetscCall(Report(S, &pg, PETSC_TRUE));
    /* the HDF5 file from the journal: every sample of the plan, failures included */
    const HylcSampleRecord *all;
    const unsigned char    *jd;
    PetscInt                nd;
    char                   *opts = NULL;
    PetscErrorCode          ierr;
    PetscCall(HylcJournalGetDone(J, &nd, &jd));
    PetscCall(HylcJournalGetRecords(J, &all));
    PetscCall(PetscOptionsGetAll(NULL, &opts));
    ierr = HylcSamplesWriteHDF5WithIdentity(S->output, S->nsamples, all, jd, S->pat, &S->model, opts, S->identity, &S->plan);
    PetscCall(PetscFree(opts));
    PetscCall(ierr);
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] wrote %s: %ld samples, %ld not converged\n", S->output, (long)nd, pg.failed));
    { /* the second-order test over every sample of the file (docs/method.md, "Saddle points") */
      long nesc = 0, nsad = 0, nunk = 0, nconv = 0;
      for (long k = 0; k < S->nsamples; k++) {
        if (!jd[k] || all[k].status != HYLC_MICRO_CONVERGED) continue;
        nconv++;
        nesc += all[k].escapes > 0;
        nsad += all[k].negcurv > 0;
        nunk += all[k].negcurv < 0;
      }
      PetscCall(PetscPrintf(PETSC_COMM_SELF, "[sampler] of %ld converged samples: %ld left a saddle point (/samples/escapes), %ld ended at one (/samples/negcurv > 0), %ld not tested\n", nconv, nesc, nsad, nunk));
    }
    if (S->start == HYLC_SAMPLER_START_BOTH) { /* the map of multistability (/samples/multistable) */
      long ncmp = 0, nmulti = 0, ncont = 0;
      for (long k = 0; k < S->nsamples; k++) {
        if (!jd[k] || all[k].multistable < 0) continue;
        ncmp++;
        nmulti += all[k].multistable;
        ncont += all[k].multistable && all[k].start == HYLC_SAMPLE_START_CONTINUED;
      }
      PetscCall(PetscPrintf(PETSC_COMM_SELF,
                            "[sampler] -sampler_start both: %ld samples converged from both starts, %ld of them (%.1f%%) with Psi differing by more than %g relative (/samples/multistable), the continued start lower in %ld, the cold one in %ld\n",
                            ncmp, nmulti, 100.0 * nmulti / PetscMax(ncmp, 1), (double)S->bothRtol, ncont, nmulti - ncont));
    }
    if (S->rawdir[0]) PetscCall(ExportRaw(S, all, jd));
    PetscCall(HylcJournalClose(&S->journal));
  }
  PetscCall(PetscFree2(ustart, uorder));
  PetscCall(PetscFree2(uprev, ycur));
  PetscCall(PetscFree(S->done));
  PetscCall(PetscFree(S->recs));
  PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)S)));
  PetscCallMPI(MPI_Win_free(&win));
  PetscCall(PetscLogEventEnd(HYLC_SamplerRun, S, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
