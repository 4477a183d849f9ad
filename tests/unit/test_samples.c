/* Sample storage: the journal (append, reopen, resume; torn tails and garbage dropped without losing
   earlier records; a different run refused; locking) and the HDF5 samples file (written from records,
   some not done, and read back exactly with the HDF5 API).
   Helper modes for tests/regression/samples_*.sh:
     -test_write_h5 <path>          write the test's HDF5 file to <path> and exit
     -test_journal_writer <path>    append records 0, 1, 2, ... one by one until killed
     -test_journal_check <path>     resume that journal, check it holds an exact prefix, complete it, check
   hylc-test: nprocs=1 */
#include <hylc/samples.h>
#include <hdf5.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "hylctest.h"

#define RECSIZE 220 /* bytes per journal record (docs/output-format.md) */

static void MakeRecord(long k, HylcSampleRecord *r)
{
  memset(r, 0, sizeof(*r));
  r->index      = k;
  r->term       = (int)(k % HYLC_PLAN_NTERM);
  r->status     = (int)(k % 6);
  r->iterations = (int)(k % 37);
  r->retries    = (int)(k % 3);
  for (int i = 0; i < 6; i++) r->z[i] = sin(0.37 * (double)k + i) * (i >= 3 ? 100 : 0.5);
  r->psi = 1e-3 * (double)k + 1.0 / 3.0;
  for (int i = 0; i < 4; i++) r->parts[i] = 1e-7 * (double)(k + i) / 7.0;
  r->residual  = 1e-9 * (double)(k + 1);
  r->cresidual = 1e-13 / (double)(k + 1);
  r->time      = 0.01 * (double)k + 1e-6;
  r->start     = (int)((k / 2) % 3); /* 0 cold, 1 continued, 2 retried cold */
  r->negcurv   = (int)(k % 5) - 1;   /* -1 not tested */
  r->escapes   = (int)((k / 3) % 4);
}

static int SameRecord(const HylcSampleRecord *a, const HylcSampleRecord *b)
{
  int same = a->index == b->index && a->term == b->term && a->status == b->status && a->iterations == b->iterations && a->retries == b->retries;
  for (int i = 0; i < 6; i++) same = same && a->z[i] == b->z[i];
  for (int i = 0; i < 4; i++) same = same && a->parts[i] == b->parts[i];
  return same && a->psi == b->psi && a->residual == b->residual && a->cresidual == b->cresidual && a->time == b->time && a->start == b->start && a->negcurv == b->negcurv && a->escapes == b->escapes;
}

static long FileSize(const char *path)
{
  struct stat st;
  return stat(path, &st) ? -1 : (long)st.st_size;
}

/* checks that journal j holds exactly the records MakeRecord(k) for the flagged k */
static PetscErrorCode CheckJournal(HylcJournal j, long n, const unsigned char want[], const char *what)
{
  PetscInt                ndone, nwant = 0;
  const unsigned char    *done;
  const HylcSampleRecord *recs;
  HylcSampleRecord        r;
  int                     bad = 0;

  PetscFunctionBegin;
  PetscCall(HylcJournalGetDone(j, &ndone, &done));
  PetscCall(HylcJournalGetRecords(j, &recs));
  for (long k = 0; k < n; k++) {
    nwant += want[k];
    MakeRecord(k, &r);
    if (!!done[k] != !!want[k] || (want[k] && !SameRecord(&recs[k], &r))) bad++;
  }
  HYLC_CHECK(ndone == nwant && bad == 0, "%s: %d samples differ, ndone %d (expected %d)", what, bad, (int)ndone, (int)nwant);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode AppendRange(HylcJournal j, long k0, long k1, unsigned char want[])
{
  HylcSampleRecord r[64];
  PetscInt         n = 0;

  PetscFunctionBegin;
  for (long k = k0; k < k1; k++) {
    MakeRecord(k, &r[n++]);
    want[k] = 1;
    if (n == 64) {
      PetscCall(HylcJournalAppend(j, r, n));
      n = 0;
    }
  }
  PetscCall(HylcJournalAppend(j, r, n));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the last error's message contains s */
static int ErrorMentions(PetscErrorCode ierr, const char *s)
{
  char *msg = NULL;
  PetscErrorMessage(ierr, NULL, &msg);
  return msg && strstr(msg, s) != NULL;
}

static PetscErrorCode TestJournal(void)
{
  const char      *path = "j1.journal";
  const long       n    = 300;
  unsigned char    want[300];
  HylcJournal      j = NULL;
  HylcSampleRecord r;
  PetscInt         ndone, ndropped;
  long             ns;

  PetscFunctionBegin;
  memset(want, 0, sizeof(want));
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_OVERWRITE, n, "pattern=plain -plan_n1 10", &j));
  PetscCall(CheckJournal(j, n, want, "new journal"));
  PetscCall(AppendRange(j, 0, 100, want));
  for (long k = 200; k < 210; k++) { /* out of order, one at a time */
    MakeRecord(k, &r);
    PetscCall(HylcJournalAppend(j, &r, 1));
    want[k] = 1;
  }
  PetscCall(CheckJournal(j, n, want, "after appending"));
  PetscCall(HylcJournalClose(&j));
  HYLC_CHECK(j == NULL, "Close sets the handle to NULL");
  PetscCall(HylcJournalClose(&j));
  HYLC_CHECK(FileSize(path) == 64 + 25 + 8 + 110 * RECSIZE, "journal size %ld", FileSize(path));

  /* resume: every record back, then more appended, then again */
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, "pattern=plain -plan_n1 10", &j));
  PetscCall(CheckJournal(j, n, want, "resumed journal"));
  PetscCall(HylcJournalGetInfo(j, &ns, &ndropped));
  HYLC_CHECK(ns == n && ndropped == 0, "info: %ld samples, %d dropped", ns, (int)ndropped);
  PetscCall(AppendRange(j, 100, 150, want));
  PetscCall(HylcJournalClose(&j));
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, "pattern=plain -plan_n1 10", &j));
  PetscCall(CheckJournal(j, n, want, "resumed twice"));
  /* a later record of the same sample replaces the earlier one; ndone counts samples */
  MakeRecord(5, &r);
  r.psi = 42;
  PetscCall(HylcJournalAppend(j, &r, 1));
  PetscCall(HylcJournalClose(&j));
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, "pattern=plain -plan_n1 10", &j));
  {
    const HylcSampleRecord *recs;
    PetscCall(HylcJournalGetRecords(j, &recs));
    PetscCall(HylcJournalGetDone(j, &ndone, NULL));
    HYLC_CHECK(recs[5].psi == 42 && ndone == 160, "duplicate record: psi %g, ndone %d", recs[5].psi, (int)ndone);
  }
  PetscCall(HylcJournalClose(&j));

  /* without resume the journal starts over; resume of a missing file starts a new one */
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_OVERWRITE, n, "pattern=plain -plan_n1 10", &j));
  memset(want, 0, sizeof(want));
  PetscCall(CheckJournal(j, n, want, "restarted journal"));
  PetscCall(HylcJournalClose(&j));
  unlink("j2.journal");
  PetscCall(HylcJournalOpen("j2.journal", HYLC_JOURNAL_RESUME, n, "x", &j));
  PetscCall(CheckJournal(j, n, want, "resume of a missing journal"));
  PetscCall(HylcJournalClose(&j));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestTornTail(void)
{
  const char   *path = "torn.journal", *fp = "fingerprint of the torn run";
  const long    n = 40;
  unsigned char want[40];
  HylcJournal   j;
  PetscInt      ndropped;
  long          full, H = 64 + (long)strlen(fp) + 8;
  FILE         *f;
  unsigned char garbage[300];

  PetscFunctionBegin;
  memset(want, 0, sizeof(want));
  for (int i = 0; i < 300; i++) garbage[i] = (unsigned char)(37 * i + 11);
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_OVERWRITE, n, fp, &j));
  PetscCall(AppendRange(j, 0, 10, want));
  PetscCall(HylcJournalClose(&j));
  full = FileSize(path);
  HYLC_CHECK(full == H + 10 * RECSIZE, "size %ld", full);

  /* a record cut in the middle (SIGKILL during the write) */
  HYLC_CHECK(truncate(path, full - 50) == 0, "truncate");
  want[9] = 0;
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, fp, &j));
  PetscCall(CheckJournal(j, n, want, "torn last record"));
  PetscCall(HylcJournalGetInfo(j, NULL, &ndropped));
  HYLC_CHECK(ndropped == 1, "torn record: %d dropped", (int)ndropped);
  HYLC_CHECK(FileSize(path) == H + 9 * RECSIZE, "torn record not truncated: size %ld", FileSize(path));
  /* appending after the truncation continues cleanly */
  PetscCall(AppendRange(j, 9, 12, want));
  PetscCall(HylcJournalClose(&j));

  /* garbage shorter and longer than a record */
  for (int pass = 0; pass < 2; pass++) {
    size_t len = pass ? 300 : 37;
    f          = fopen(path, "ab");
    HYLC_CHECK(f && fwrite(garbage, 1, len, f) == len, "append garbage");
    if (f) fclose(f);
    PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, fp, &j));
    PetscCall(CheckJournal(j, n, want, pass ? "300 bytes of garbage" : "37 bytes of garbage"));
    PetscCall(HylcJournalGetInfo(j, NULL, &ndropped));
    HYLC_CHECK(ndropped == (PetscInt)((len + RECSIZE - 1) / RECSIZE), "garbage: %d dropped, %d expected (whole or partial records)", (int)ndropped, (int)((len + RECSIZE - 1) / RECSIZE));
    HYLC_CHECK(FileSize(path) == H + 12 * RECSIZE, "garbage not truncated: size %ld", FileSize(path));
    PetscCall(HylcJournalClose(&j));
  }
  /* a full record of zeros (a file system's zero-filled block) */
  f = fopen(path, "ab");
  memset(garbage, 0, sizeof(garbage));
  HYLC_CHECK(f && fwrite(garbage, 1, RECSIZE, f) == RECSIZE, "append zeros");
  if (f) fclose(f);
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, fp, &j));
  PetscCall(CheckJournal(j, n, want, "zero record"));
  PetscCall(HylcJournalClose(&j));

  /* a damaged byte inside record 5: the journal is cut there (records 5.. are recomputed) */
  f = fopen(path, "r+b");
  if (f) {
    int c;
    fseek(f, H + 5 * RECSIZE + 60, SEEK_SET);
    c = fgetc(f);
    fseek(f, H + 5 * RECSIZE + 60, SEEK_SET);
    fputc(c ^ 0x10, f);
    fclose(f);
  }
  for (int k = 5; k < 12; k++) want[k] = 0;
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, n, fp, &j));
  PetscCall(CheckJournal(j, n, want, "damaged record 5"));
  PetscCall(HylcJournalClose(&j));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestRefused(void)
{
  const char      *path = "refuse.journal";
  HylcJournal      j, j2 = NULL;
  HylcSampleRecord r;
  PetscErrorCode   ierr;
  FILE            *f;

  PetscFunctionBegin;
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_OVERWRITE, 20, "run A", &j));
  /* locked while open */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcJournalOpen(path, HYLC_JOURNAL_RESUME, 20, "run A", &j2);
  HYLC_CHECK(ierr && j2 == NULL && ErrorMentions(ierr, path) && ErrorMentions(ierr, "in use"), "a journal in use is refused (%d)", (int)ierr);
  ierr = HylcJournalOpen(path, HYLC_JOURNAL_OVERWRITE, 20, "run A", &j2);
  HYLC_CHECK(ierr && j2 == NULL, "a journal in use is not replaced (%d)", (int)ierr);
  MakeRecord(3, &r);
  r.index = 20;
  ierr    = HylcJournalAppend(j, &r, 1);
  HYLC_CHECK(ierr == PETSC_ERR_ARG_OUTOFRANGE, "index out of range refused (%d)", (int)ierr);
  PetscCall(PetscPopErrorHandler());
  MakeRecord(3, &r);
  PetscCall(HylcJournalAppend(j, &r, 1));
  PetscCall(HylcJournalClose(&j));

  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcJournalOpen(path, HYLC_JOURNAL_RESUME, 20, "run B", &j);
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT && ErrorMentions(ierr, path) && ErrorMentions(ierr, "different run"), "other fingerprint refused (%d)", (int)ierr);
  ierr = HylcJournalOpen(path, HYLC_JOURNAL_RESUME, 21, "run A", &j);
  HYLC_CHECK(ierr == PETSC_ERR_USER_INPUT && ErrorMentions(ierr, path) && ErrorMentions(ierr, "21"), "other sample count refused (%d)", (int)ierr);
  f = fopen("notajournal.txt", "w");
  if (f) {
    fputs("sx sa sy II00 II01 II11 psi\n0 0 0 0 0 0 0\n", f);
    fclose(f);
  }
  ierr = HylcJournalOpen("notajournal.txt", HYLC_JOURNAL_RESUME, 20, "run A", &j);
  HYLC_CHECK(ierr == PETSC_ERR_FILE_UNEXPECTED && ErrorMentions(ierr, "notajournal.txt"), "a file that is not a journal is refused (%d)", (int)ierr);
  ierr = HylcJournalOpen("no/such/dir/x.journal", HYLC_JOURNAL_NEW, 20, "run A", &j);
  HYLC_CHECK(ierr == PETSC_ERR_FILE_OPEN && ErrorMentions(ierr, "no/such/dir/x.journal"), "unwritable journal refused (%d)", (int)ierr);
  PetscCall(PetscPopErrorHandler());
  /* the refused resumes left the journal intact */
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, 20, "run A", &j));
  {
    PetscInt ndone;
    PetscCall(HylcJournalGetDone(j, &ndone, NULL));
    HYLC_CHECK(ndone == 1, "journal intact after refusals: ndone %d", (int)ndone);
  }
  PetscCall(HylcJournalClose(&j));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- HDF5 ---- */

#define NH5 57

static PetscErrorCode MakeH5Inputs(HylcPattern *p, HylcYarnModel *m, HylcSampleRecord recs[], unsigned char done[])
{
  HylcPatternGenParams g;

  PetscFunctionBegin;
  PetscCall(HylcPatternGenParamsDefault(&g));
  PetscCall(HylcPatternCreate(PETSC_COMM_SELF, p));
  PetscCall(HylcPatternGenerate(*p, HYLCPATTERNPLAIN, &g));
  PetscCall(HylcYarnModelDefault(m));
  m->kc = 50;
  for (long k = 0; k < NH5; k++) {
    done[k] = (k % 5 != 2);
    if (done[k])
      MakeRecord(k, &recs[k]);
    else
      memset(&recs[k], 0x5a, sizeof(recs[k])); /* garbage where not done */
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

static const char OptionsText[] = "-pattern_type plain -yarn_kc 50 -sampler_output s.h5 -plan_terms sx,sa";

static double ReadAttrDouble(hid_t loc, const char *obj, const char *name)
{
  double v = NAN;
  hid_t  a = H5Aopen_by_name(loc, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_DOUBLE, &v);
    H5Aclose(a);
  }
  return v;
}

static long long ReadAttrLong(hid_t loc, const char *obj, const char *name)
{
  long long v = -999;
  hid_t     a = H5Aopen_by_name(loc, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  if (a >= 0) {
    H5Aread(a, H5T_NATIVE_LLONG, &v);
    H5Aclose(a);
  }
  return v;
}

/* a variable-length string attribute, copied to buf ("" if missing) */
static void ReadAttrString(hid_t loc, const char *obj, const char *name, char *buf, size_t len)
{
  hid_t a = H5Aopen_by_name(loc, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  buf[0]  = 0;
  if (a >= 0) {
    hid_t t = H5Aget_type(a), s = H5Aget_space(a);
    char *str = NULL;
    if (H5Tis_variable_str(t) > 0 && H5Aread(a, t, &str) >= 0 && str) {
      snprintf(buf, len, "%s", str);
      H5Dvlen_reclaim(t, s, H5P_DEFAULT, &str);
    }
    H5Sclose(s);
    H5Tclose(t);
    H5Aclose(a);
  }
}

static PetscErrorCode TestHDF5(void)
{
  HylcPattern       p;
  HylcYarnModel     m;
  HylcYarnConstants c;
  HylcPatternData   d;
  HylcSampleRecord  recs[NH5], *back  = NULL;
  unsigned char     done[NH5], *bdone = NULL;
  long              n;
  char             *opts = NULL, buf[256];
  int               bad = 0, nconv = 0, ndone = 0;
  PetscErrorCode    ierr;

  PetscFunctionBegin;
  PetscCall(MakeH5Inputs(&p, &m, recs, done));
  PetscCall(HylcSamplesWriteHDF5("s.h5", NH5, recs, done, p, &m, OptionsText));
  HYLC_CHECK(access("s.h5.tmp", F_OK) != 0, "temporary file left behind");
  PetscCall(HylcSamplesReadHDF5("s.h5", &n, &back, &bdone, &opts));
  HYLC_CHECK(n == NH5, "read %ld samples", n);
  for (long k = 0; k < NH5 && n == NH5; k++) {
    if (done[k]) {
      ndone++;
      nconv += recs[k].status == 0;
      bad += !bdone[k] || !SameRecord(&back[k], &recs[k]);
    } else {
      int nan = isnan(back[k].psi) && isnan(back[k].residual) && isnan(back[k].cresidual) && isnan(back[k].time);
      for (int i = 0; i < 6; i++) nan = nan && isnan(back[k].z[i]);
      for (int i = 0; i < 4; i++) nan = nan && isnan(back[k].parts[i]);
      bad += bdone[k] || back[k].status != -1 || back[k].term != -1 || back[k].iterations != -1 || back[k].retries != -1 || !nan;
    }
  }
  HYLC_CHECK(bad == 0, "%d samples differ after the HDF5 round trip", bad);
  HYLC_CHECK(opts && !strcmp(opts, OptionsText), "options text: %s", opts ? opts : "(null)");
  PetscCall(PetscFree(back));
  PetscCall(PetscFree(bdone));
  PetscCall(PetscFree(opts));

  /* the rest of the schema, through the HDF5 API */
  {
    hid_t   f = H5Fopen("s.h5", H5F_ACC_RDONLY, H5P_DEFAULT), dset;
    double *X;
    int    *next, *shift;

    HYLC_CHECK(f >= 0, "H5Fopen");
    PetscCall(HylcPatternGetData(p, &d));
    PetscCall(HylcYarnModelGetConstants(&m, d.radius, &c));
    HYLC_CHECK(ReadAttrLong(f, "/", "nsamples") == NH5 && ReadAttrLong(f, "/", "ndone") == ndone && ReadAttrLong(f, "/", "nconverged") == nconv, "root counts %lld %lld %lld", ReadAttrLong(f, "/", "nsamples"), ReadAttrLong(f, "/", "ndone"),
               ReadAttrLong(f, "/", "nconverged"));
    ReadAttrString(f, "/", "hylc_version", buf, sizeof(buf));
    HYLC_CHECK(!strcmp(buf, HYLC_VERSION_STRING), "hylc_version '%s'", buf);
    ReadAttrString(f, "/", "creation_date", buf, sizeof(buf));
    HYLC_CHECK(strlen(buf) == 20 && buf[10] == 'T', "creation_date '%s'", buf);
    ReadAttrString(f, "/", "hostname", buf, sizeof(buf));
    HYLC_CHECK(buf[0], "hostname missing");
    ReadAttrString(f, "samples/psi", "units", buf, sizeof(buf));
    HYLC_CHECK(!strcmp(buf, "J/m^2"), "psi units '%s'", buf);
    ReadAttrString(f, "samples/energy_parts", "units", buf, sizeof(buf));
    HYLC_CHECK(!strcmp(buf, "J"), "energy_parts units '%s'", buf);
    ReadAttrString(f, "samples/status", "description", buf, sizeof(buf));
    HYLC_CHECK(strstr(buf, "-1: not computed") != NULL, "status description '%s'", buf);
    HYLC_CHECK(ReadAttrDouble(f, "material", "B") == c.B && ReadAttrDouble(f, "material", "ks") == c.ks && ReadAttrDouble(f, "material", "beta") == c.beta && ReadAttrDouble(f, "material", "kc") == 50, "material constants");
    HYLC_CHECK(ReadAttrLong(f, "material", "contact_points") == m.contactPoints, "contact points");
    ReadAttrString(f, "material", "curvature", buf, sizeof(buf));
    HYLC_CHECK(!strcmp(buf, "averaged"), "curvature '%s'", buf);
    HYLC_CHECK(ReadAttrDouble(f, "reference", "px") == d.px && ReadAttrDouble(f, "reference", "radius") == d.radius, "reference periods");
    PetscCall(PetscMalloc3(3 * d.nv, &X, d.nv, &next, 2 * d.nv, &shift));
    dset = H5Dopen2(f, "reference/X", H5P_DEFAULT);
    HYLC_CHECK(dset >= 0 && H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, X) >= 0, "read /reference/X");
    H5Dclose(dset);
    dset = H5Dopen2(f, "reference/next", H5P_DEFAULT);
    HYLC_CHECK(dset >= 0 && H5Dread(dset, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, next) >= 0, "read /reference/next");
    H5Dclose(dset);
    dset = H5Dopen2(f, "reference/shift", H5P_DEFAULT);
    HYLC_CHECK(dset >= 0 && H5Dread(dset, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, shift) >= 0, "read /reference/shift");
    H5Dclose(dset);
    bad = 0;
    for (PetscInt v = 0; v < d.nv; v++) {
      for (int i = 0; i < 3; i++) bad += X[3 * v + i] != d.X[3 * v + i];
      for (int i = 0; i < 2; i++) bad += shift[2 * v + i] != d.shift[2 * v + i];
      bad += next[v] != d.next[v];
    }
    HYLC_CHECK(bad == 0, "%d reference values differ", bad);
    PetscCall(PetscFree3(X, next, shift));
    for (const char **ds = (const char *[]){"reference/theta", "reference/prev", "reference/rest_length", "reference/rest_kappa", "reference/rest_twist", "reference/ref_d1", "reference/ref_twist", "samples/iterations", "samples/retries",
                                            "samples/term", "samples/residual", "samples/constraint_residual", "samples/time", "samples/start", "samples/negcurv", "samples/escapes", "options", NULL};
         *ds; ds++)
      HYLC_CHECK(H5Lexists(f, *ds, H5P_DEFAULT) > 0, "dataset %s missing", *ds);
    H5Fclose(f);
  }

  /* an unwritable path: a clear error naming it, nothing left behind */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcSamplesWriteHDF5("no/such/dir/s.h5", NH5, recs, done, p, &m, OptionsText);
  HYLC_CHECK(ierr == PETSC_ERR_FILE_OPEN && ErrorMentions(ierr, "no/such/dir/s.h5"), "unwritable output (%d)", (int)ierr);
  ierr = HylcSamplesReadHDF5("missing.h5", &n, &back, &bdone, NULL);
  HYLC_CHECK(ierr == PETSC_ERR_FILE_OPEN && ErrorMentions(ierr, "missing.h5"), "missing input (%d)", (int)ierr);
  PetscCall(PetscPopErrorHandler());

  /* no samples done at all, no pattern or model, default options text */
  PetscCall(PetscMemzero(done, sizeof(done)));
  PetscCall(HylcSamplesWriteHDF5("empty.h5", NH5, recs, done, NULL, NULL, NULL));
  PetscCall(HylcSamplesReadHDF5("empty.h5", &n, &back, &bdone, &opts));
  bad = 0;
  for (long k = 0; k < n; k++) bad += bdone[k] || back[k].status != -1;
  HYLC_CHECK(n == NH5 && bad == 0 && opts, "empty file: %ld samples, %d bad", n, bad);
  PetscCall(PetscFree(back));
  PetscCall(PetscFree(bdone));
  PetscCall(PetscFree(opts));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- helper modes for the regression scripts ---- */

static PetscErrorCode WriteH5Only(const char path[])
{
  HylcPattern      p;
  HylcYarnModel    m;
  HylcSampleRecord recs[NH5];
  unsigned char    done[NH5];

  PetscFunctionBegin;
  PetscCall(MakeH5Inputs(&p, &m, recs, done));
  PetscCall(HylcSamplesWriteHDF5(path, NH5, recs, done, p, &m, OptionsText));
  PetscCall(HylcPatternDestroy(&p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

#define NKILL 200000L

static PetscErrorCode JournalWriter(const char path[])
{
  HylcJournal      j;
  HylcSampleRecord r[2];

  PetscFunctionBegin;
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_OVERWRITE, NKILL, "kill test", &j));
  printf("started\n");
  fflush(stdout);
  for (long k = 0; k < NKILL; k++) {
    MakeRecord(k, &r[0]);
    r[1] = r[0];
    PetscCall(HylcJournalAppend(j, r, 1 + (PetscInt)(k % 3 == 0))); /* some batches write a record twice */
  }
  PetscCall(HylcJournalClose(&j));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode JournalCheck(const char path[])
{
  HylcJournal             j;
  PetscInt                ndone, ndropped;
  const unsigned char    *done;
  const HylcSampleRecord *recs;
  HylcSampleRecord        r;
  long                    m   = 0;
  int                     bad = 0;

  PetscFunctionBegin;
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, NKILL, "kill test", &j));
  PetscCall(HylcJournalGetDone(j, &ndone, &done));
  PetscCall(HylcJournalGetInfo(j, NULL, &ndropped));
  PetscCall(HylcJournalGetRecords(j, &recs));
  while (m < NKILL && done[m]) m++;
  for (long k = 0; k < NKILL; k++) {
    MakeRecord(k, &r);
    if (k < m)
      bad += !SameRecord(&recs[k], &r);
    else
      bad += done[k] != 0;
  }
  HYLC_CHECK(m > 0 && ndone == m && bad == 0, "resumed journal: prefix %ld, ndone %d, %d bad", m, (int)ndone, bad);
  /* finish a few more and check the continuation */
  for (long k = m; k < m + 10 && k < NKILL; k++) {
    MakeRecord(k, &r);
    PetscCall(HylcJournalAppend(j, &r, 1));
  }
  PetscCall(HylcJournalClose(&j));
  PetscCall(HylcJournalOpen(path, HYLC_JOURNAL_RESUME, NKILL, "kill test", &j));
  PetscCall(HylcJournalGetDone(j, &ndone, NULL));
  HYLC_CHECK(ndone == PetscMin(m + 10, NKILL), "continued journal: ndone %d, expected %ld", (int)ndone, m + 10);
  PetscCall(HylcJournalClose(&j));
  printf("records %ld dropped %d\n", m, (int)ndropped);
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  char      path[PETSC_MAX_PATH_LEN];
  PetscBool set;

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-test_write_h5", path, sizeof(path), &set));
  if (set)
    PetscCall(WriteH5Only(path));
  else {
    PetscCall(PetscOptionsGetString(NULL, NULL, "-test_journal_writer", path, sizeof(path), &set));
    if (set)
      PetscCall(JournalWriter(path));
    else {
      PetscCall(PetscOptionsGetString(NULL, NULL, "-test_journal_check", path, sizeof(path), &set));
      if (set)
        PetscCall(JournalCheck(path));
      else {
        PetscCall(TestJournal());
        PetscCall(TestTornTail());
        PetscCall(TestRefused());
        PetscCall(TestHDF5());
      }
    }
  }
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
