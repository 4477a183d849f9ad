/* The journal of a sampling run (include/hylc/samples.h; format in docs/output-format.md): an
   append-only binary file of fixed-size checksummed records that survives SIGKILL at any moment, opened
   under an exclusive flock and tied to the run by its identity (format 2). Plain C stdio + POSIX. The
   HDF5 samples file is written by src/samples/h5samples.c. */
#include <hylc/samples.h>
#include <hylc/sha256.h>
#include <hylc/private/samplesimpl.h>
#include <petsc/private/petscimpl.h>
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

/* ------------------------------------------------------------------------------------------------ */
/* Journal                                                                                            */
/* ------------------------------------------------------------------------------------------------ */

#define JOURNAL_MAGIC     "HYLCJNL1"
#define JOURNAL_BOM       0x01020304u
#define JOURNAL_VERSION   6u  /* 1: a short fingerprint (hylc before the complete identity); 2: records without the start; 3: without negcurv and escapes; 4: without the other start's Psi, status and the multistable flag; 5: without the stress */
#define JOURNAL_PAYLOAD   212 /* packed record without checksum */
#define JOURNAL_RECSIZE   (JOURNAL_PAYLOAD + 8)
#define JOURNAL_FIXEDHEAD 64 /* header bytes before the identity text: 32 fixed + the SHA-256 of the identity */
#define JOURNAL_MAXID     (1 << 24)

struct _n_HylcJournal {
  char             *path;
  char             *identity;
  unsigned char     digest[32];
  FILE             *fp;
  long              nsamples;
  PetscInt          ndone, ndropped;
  unsigned char    *done;
  HylcSampleRecord *recs;
};

/* FNV-1a, 64 bit */
static uint64_t Fnv1a64(const unsigned char *p, size_t n)
{
  uint64_t h = 14695981039346656037ULL;
  for (size_t i = 0; i < n; i++) {
    h ^= p[i];
    h *= 1099511628211ULL;
  }
  return h;
}

/* the record layout: int64 index, int32 term, status, iterations, retries, 14 doubles, int32 start, negcurv,
   escapes, double psiOther, int32 statusOther, multistable, double stress[6], uint64 checksum */
static void PackRecord(const HylcSampleRecord *r, unsigned char b[JOURNAL_RECSIZE])
{
  int64_t  idx   = r->index;
  int32_t  iv[4] = {r->term, r->status, r->iterations, r->retries};
  double   dv[14];
  uint64_t h;

  for (int i = 0; i < 6; i++) dv[i] = r->z[i];
  dv[6] = r->psi;
  for (int i = 0; i < 4; i++) dv[7 + i] = r->parts[i];
  dv[11] = r->residual;
  dv[12] = r->cresidual;
  dv[13] = r->time;
  memcpy(b, &idx, 8);
  memcpy(b + 8, iv, 16);
  memcpy(b + 24, dv, 112);
  {
    int32_t tail[3] = {r->start, r->negcurv, r->escapes}, other[2] = {r->statusOther, r->multistable};
    memcpy(b + 136, tail, 12);
    memcpy(b + 148, &r->psiOther, 8);
    memcpy(b + 156, other, 8);
    memcpy(b + 164, r->stress, 48);
  }
  h = Fnv1a64(b, JOURNAL_PAYLOAD);
  memcpy(b + JOURNAL_PAYLOAD, &h, 8);
}

/* returns 0 and fills r if the checksum and the fields are valid */
static int UnpackRecord(const unsigned char b[JOURNAL_RECSIZE], long nsamples, HylcSampleRecord *r)
{
  int64_t  idx;
  int32_t  iv[4];
  double   dv[14];
  uint64_t h;

  memcpy(&h, b + JOURNAL_PAYLOAD, 8);
  if (h != Fnv1a64(b, JOURNAL_PAYLOAD)) return -1;
  memcpy(&idx, b, 8);
  memcpy(iv, b + 8, 16);
  memcpy(dv, b + 24, 112);
  if (idx < 0 || idx >= nsamples || iv[0] < 0 || iv[0] >= HYLC_PLAN_NTERM3 || iv[1] < 0 || iv[1] >= HylcSamplesNumStatuses_()) return -1;
  r->index      = (long)idx;
  r->term       = iv[0];
  r->status     = iv[1];
  r->iterations = iv[2];
  r->retries    = iv[3];
  for (int i = 0; i < 6; i++) r->z[i] = dv[i];
  r->psi = dv[6];
  for (int i = 0; i < 4; i++) r->parts[i] = dv[7 + i];
  r->residual  = dv[11];
  r->cresidual = dv[12];
  r->time      = dv[13];
  {
    int32_t tail[3];
    memcpy(tail, b + 136, 12);
    if (tail[0] < 0 || tail[0] > 2 || tail[1] < -1 || tail[2] < 0) return -1;
    r->start   = tail[0];
    r->negcurv = tail[1];
    r->escapes = tail[2];
  }
  {
    int32_t other[2];
    memcpy(&r->psiOther, b + 148, 8);
    memcpy(other, b + 156, 8);
    if (other[0] < -1 || other[0] >= HylcSamplesNumStatuses_() || other[1] < -1 || other[1] > 1) return -1;
    r->statusOther = other[0];
    r->multistable = other[1];
  }
  memcpy(r->stress, b + 164, 48);
  return 0;
}

/* the pid holding a flock on the file of fd, from /proc/locks (Linux), or 0 if unknown */
static int LockHolder(int fd)
{
  struct stat   st;
  char          line[256];
  FILE         *f;
  int           pid = 0;
  unsigned      maj, min;
  unsigned long ino;

  if (fstat(fd, &st) || !(f = fopen("/proc/locks", "r"))) return 0;
  while (!pid && fgets(line, sizeof(line), f)) {
    char type[16];
    int  p;
    if (sscanf(line, "%*d: %15s %*s %*s %d %x:%x:%lu", type, &p, &maj, &min, &ino) == 5 && !strcmp(type, "FLOCK") && maj == major(st.st_dev) && min == minor(st.st_dev) && ino == (unsigned long)st.st_ino) pid = p;
  }
  fclose(f);
  return pid;
}

/* Opens (creating it if missing) and locks the journal file before anything is read or written; the
   lock is on the file's inode, so the path is checked to still name it after locking (a racing
   process may have removed the file it created). *created: this call created the file. */
static PetscErrorCode JournalLockPath(const char path[], int *fdout, PetscBool *created)
{
  PetscFunctionBegin;
  *fdout = -1;
  for (int attempt = 0;; attempt++) {
    struct stat a, b;
    int         fd = open(path, O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);

    *created = fd >= 0 ? PETSC_TRUE : PETSC_FALSE;
    if (fd < 0 && errno == EEXIST) fd = open(path, O_RDWR | O_CLOEXEC);
    if (fd < 0 && errno == ENOENT && attempt < 100) continue; /* removed between the two opens */
    PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open journal %s: %s", path, strerror(errno));
    if (flock(fd, LOCK_EX | LOCK_NB)) {
      int err = errno, pid = 0;
      for (int k = 0; err == EWOULDBLOCK && !pid && k < 3; k++) { /* the holder may be between its lock and /proc/locks */
        if (k) usleep(10000);
        pid = LockHolder(fd);
      }
      close(fd);
      PetscCheck(err != EWOULDBLOCK || pid <= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Journal %s is in use by another job (pid %d): is the same run already going?", path, pid);
      PetscCheck(err != EWOULDBLOCK, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Journal %s is in use by another job: is the same run already going?", path);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot lock journal %s: %s", path, strerror(err));
    }
    if (!fstat(fd, &a) && !stat(path, &b) && a.st_dev == b.st_dev && a.st_ino == b.st_ino) {
      *fdout = fd;
      break;
    }
    close(fd); /* the path names another file now: lock that one */
    PetscCheck(attempt < 100, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot lock journal %s: it keeps being replaced", path);
  }
  if (*created) HylcSyncParentDirectory(path);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* writes the header of a new journal in place (the file is locked and emptied first), then fsync */
static PetscErrorCode JournalWriteHeader(HylcJournal j, int fd)
{
  size_t         L = strlen(j->identity), H = JOURNAL_FIXEDHEAD + L + 8;
  unsigned char *head;
  uint32_t       u[4] = {JOURNAL_BOM, JOURNAL_VERSION, JOURNAL_RECSIZE, (uint32_t)L};
  int64_t        ns   = j->nsamples;
  uint64_t       h;
  ssize_t        w;

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(H, &head));
  memcpy(head, JOURNAL_MAGIC, 8);
  memcpy(head + 8, u, 16);
  memcpy(head + 24, &ns, 8);
  memcpy(head + 32, j->digest, 32);
  memcpy(head + JOURNAL_FIXEDHEAD, j->identity, L);
  h = Fnv1a64(head, JOURNAL_FIXEDHEAD + L);
  memcpy(head + JOURNAL_FIXEDHEAD + L, &h, 8);
  if (ftruncate(fd, 0) || (w = pwrite(fd, head, H, 0)) != (ssize_t)H || fsync(fd)) {
    int err = errno;
    if (ftruncate(fd, 0)) { /* leave no partial header behind (an empty journal is a new one) */
    }
    PetscCall(PetscFree(head));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot write journal %s: %s", j->path, strerror(err ? err : ENOSPC));
  }
  PetscCall(PetscFree(head));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* reads and checks the header of an existing journal: *hsize header bytes; *same: its identity and
   sample count are this run's (else *why: the differences, PetscFree) */
static PetscErrorCode JournalReadHeader(HylcJournal j, long *hsize, PetscBool *same, char **why)
{
  unsigned char fixed[JOURNAL_FIXEDHEAD], *head;
  uint32_t      u[4];
  int64_t       ns;
  uint64_t      h, hs;
  size_t        L, got;

  PetscFunctionBegin;
  *same = PETSC_FALSE;
  *why  = NULL;
  got   = fread(fixed, 1, JOURNAL_FIXEDHEAD, j->fp);
  PetscCheck(got >= 16 && !memcmp(fixed, JOURNAL_MAGIC, 8), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s is not a hylc journal (bad magic): remove it or choose another -sampler_output", j->path);
  memcpy(u, fixed + 8, 8);
  PetscCheck(u[0] == JOURNAL_BOM, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s was written on a machine of another byte order", j->path);
  PetscCheck(u[1] >= 2, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s was written by an earlier hylc (journal format %u, without the complete run identity) and cannot be resumed safely: start over with -sampler_overwrite", j->path,
             (unsigned)u[1]);
  PetscCheck(u[1] != 2, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s was written by an earlier hylc (journal format 2, records without the start of each solve, /samples/start) and cannot be resumed: start over with -sampler_overwrite",
             j->path);
  PetscCheck(got == JOURNAL_FIXEDHEAD, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s: corrupt header (too short): start over with -sampler_overwrite", j->path);
  memcpy(u, fixed + 8, 16);
  memcpy(&ns, fixed + 24, 8);
  PetscCheck(u[1] == JOURNAL_VERSION && u[2] == JOURNAL_RECSIZE, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s has format version %u (record size %u); this hylc reads version %u (record size %u)", j->path, (unsigned)u[1], (unsigned)u[2],
             JOURNAL_VERSION, (unsigned)JOURNAL_RECSIZE);
  PetscCheck(u[3] < JOURNAL_MAXID, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s: corrupt header (identity length %u): start over with -sampler_overwrite", j->path, (unsigned)u[3]);
  L = u[3];
  PetscCall(PetscMalloc1(JOURNAL_FIXEDHEAD + L + 1, &head));
  memcpy(head, fixed, JOURNAL_FIXEDHEAD);
  if (fread(head + JOURNAL_FIXEDHEAD, 1, L, j->fp) != L || fread(&hs, 1, 8, j->fp) != 8 || (h = Fnv1a64(head, JOURNAL_FIXEDHEAD + L)) != hs) {
    PetscCall(PetscFree(head));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s: corrupt header (checksum mismatch): start over with -sampler_overwrite", j->path);
  }
  head[JOURNAL_FIXEDHEAD + L] = 0;
  *hsize                      = (long)(JOURNAL_FIXEDHEAD + L + 8);
  if (memcmp(head + 32, j->digest, 32)) {
    PetscCall(HylcSamplesIdentityDiff((char *)head + JOURNAL_FIXEDHEAD, j->identity, why));
    if (!(*why)[0]) { /* same lines, another order or spacing: not this hylc's canonical text */
      PetscCall(PetscFree(*why));
      PetscCall(PetscStrallocpy("the identity digests differ", why));
    }
  } else if (ns != j->nsamples) {
    char msg[128];
    PetscCall(PetscSNPrintf(msg, sizeof(msg), "it has %lld samples, this run %ld", (long long)ns, j->nsamples));
    PetscCall(PetscStrallocpy(msg, why));
  } else
    *same = PETSC_TRUE;
  PetscCall(PetscFree(head));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* reads the records after the header, keeps the intact prefix and truncates the rest */
static PetscErrorCode JournalReadRecords(HylcJournal j, long hsize)
{
  unsigned char    b[JOURNAL_RECSIZE];
  HylcSampleRecord r;
  struct stat      st;
  long             good = 0, total;

  PetscFunctionBegin;
  PetscCheck(!fstat(fileno(j->fp), &st), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot stat journal %s: %s", j->path, strerror(errno));
  total = (long)((st.st_size - hsize + JOURNAL_RECSIZE - 1) / JOURNAL_RECSIZE); /* complete or torn */
  while (fread(b, 1, JOURNAL_RECSIZE, j->fp) == JOURNAL_RECSIZE && !UnpackRecord(b, j->nsamples, &r)) {
    if (!j->done[r.index]) j->ndone++;
    j->done[r.index] = 1;
    j->recs[r.index] = r;
    good++;
  }
  PetscCheck(!ferror(j->fp), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot read journal %s: %s", j->path, strerror(errno));
  if ((off_t)(hsize + good * JOURNAL_RECSIZE) != st.st_size) {
    j->ndropped = (PetscInt)(total - good);
    PetscCheck(!fflush(j->fp) && !ftruncate(fileno(j->fp), (off_t)(hsize + good * JOURNAL_RECSIZE)) && !fsync(fileno(j->fp)), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot truncate the torn tail of journal %s: %s", j->path, strerror(errno));
  }
  PetscCheck(!fseeko(j->fp, (off_t)(hsize + good * JOURNAL_RECSIZE), SEEK_SET), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot seek in journal %s: %s", j->path, strerror(errno));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode JournalOpen_Private(HylcJournal j, HylcJournalMode mode, PetscBool *created)
{
  int         fd;
  struct stat st;
  long        hsize = 0;
  PetscBool   same, fresh;
  char       *why = NULL;

  PetscFunctionBegin;
  PetscCall(JournalLockPath(j->path, &fd, created));
  j->fp = fdopen(fd, "r+b");
  if (!j->fp) close(fd);
  PetscCheck(j->fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open journal %s: %s", j->path, strerror(errno));
  PetscCheck(!fstat(fd, &st), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot stat journal %s: %s", j->path, strerror(errno));
  fresh = (PetscBool)(st.st_size == 0 || mode == HYLC_JOURNAL_OVERWRITE); /* empty: a new file, or a creator that died before its header */
  if (!fresh) {
    PetscCall(JournalReadHeader(j, &hsize, &same, &why));
    if (mode == HYLC_JOURNAL_NEW) {
      const long nrec = (long)((st.st_size - hsize) / JOURNAL_RECSIZE);
      PetscCall(PetscFree(why));
      PetscCheck(st.st_size == hsize, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Journal %s holds %ld sample%s of an earlier run: continue it with -sampler_resume, or start over with -sampler_overwrite", j->path, nrec, nrec == 1 ? "" : "s");
      fresh = PETSC_TRUE; /* a header without records: nothing to lose */
    } else if (!same) {
      char msg[1024];
      PetscCall(PetscStrncpy(msg, why, sizeof(msg)));
      PetscCall(PetscFree(why));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "Journal %s belongs to a different run: %s. Resume with that run's settings, or start over with -sampler_overwrite", j->path, msg);
    }
  }
  if (fresh) {
    PetscCall(JournalWriteHeader(j, fd));
    hsize = (long)(JOURNAL_FIXEDHEAD + strlen(j->identity) + 8);
    PetscCheck(!fseeko(j->fp, hsize, SEEK_SET), PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot seek in journal %s: %s", j->path, strerror(errno));
  } else
    PetscCall(JournalReadRecords(j, hsize));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static void JournalFree(HylcJournal j)
{
  if (j->fp) fclose(j->fp); /* closing releases the lock */
  PetscFree(j->path);
  PetscFree(j->identity);
  PetscFree(j->done);
  PetscFree(j->recs);
  PetscFree(j);
}

/*@C
  HylcJournalOpen - Locks, then creates, resumes or overwrites the journal of a run; see
  include/hylc/samples.h. Not collective.
@*/
PetscErrorCode HylcJournalOpen(const char path[], HylcJournalMode mode, long nsamples, const char identity[], HylcJournal *journal)
{
  HylcJournal    j;
  PetscBool      created = PETSC_FALSE;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidCharPointer(path, 1);
  PetscValidPointer(journal, 5);
  *journal = NULL;
  PetscCheck(mode == HYLC_JOURNAL_NEW || mode == HYLC_JOURNAL_RESUME || mode == HYLC_JOURNAL_OVERWRITE, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: unknown mode %d", path, (int)mode);
  PetscCheck(nsamples >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: negative number of samples %ld", path, nsamples);
  PetscCheck(!identity || strlen(identity) < JOURNAL_MAXID, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: identity too long", path);
  PetscCall(PetscNew(&j));
  j->nsamples = nsamples;
  PetscCall(PetscStrallocpy(path, &j->path));
  PetscCall(PetscStrallocpy(identity ? identity : "", &j->identity));
  {
    HylcSha256 s;
    HylcSha256Init(&s);
    HylcSha256Update(&s, j->identity, strlen(j->identity));
    HylcSha256Final(&s, j->digest);
  }
  PetscCall(PetscCalloc1(nsamples + 1, &j->done));
  PetscCall(PetscCalloc1(nsamples + 1, &j->recs));
  ierr = JournalOpen_Private(j, mode, &created);
  if (ierr && created && j->fp) unlink(j->path); /* still locked: nobody else has it; leave no empty journal */
  if (ierr) JournalFree(j);                      /* closes the file and releases the lock */
  PetscCall(ierr);
  *journal = j;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcJournalAppend - Appends records to the journal, then flushes and fsyncs it: once it returns, the
  records survive SIGKILL and power loss. A later record of a sample replaces an earlier one. On a write
  error (a full disk) a partial record is cut off and the error names the journal.

  Not collective

  Input Parameters:
+ j    - the journal
. recs - the records (index in [0, nsamples), a valid term and status)
- n    - their number

  Level: developer

.seealso: HylcJournalOpen(), HylcJournalGetDone(), HylcJournalGetRecords()
@*/
PetscErrorCode HylcJournalAppend(HylcJournal j, const HylcSampleRecord recs[], PetscInt n)
{
  unsigned char *buf;
  off_t          end;

  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  if (n <= 0) PetscFunctionReturn(PETSC_SUCCESS);
  PetscValidPointer(recs, 2);
  PetscCheck(j->fp, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE, "Journal %s is closed", j->path);
  for (PetscInt i = 0; i < n; i++) {
    PetscCheck(recs[i].index >= 0 && recs[i].index < j->nsamples, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: sample index %ld out of range [0, %ld)", j->path, recs[i].index, j->nsamples);
    PetscCheck(recs[i].term >= 0 && recs[i].term < HYLC_PLAN_NTERM3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: sample %ld has invalid term %d", j->path, recs[i].index, recs[i].term);
    PetscCheck(recs[i].status >= 0 && recs[i].status < HylcSamplesNumStatuses_(), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: sample %ld has invalid status %d", j->path, recs[i].index, recs[i].status);
  }
  PetscCall(PetscMalloc1((size_t)n * JOURNAL_RECSIZE, &buf));
  for (PetscInt i = 0; i < n; i++) PackRecord(&recs[i], buf + (size_t)i * JOURNAL_RECSIZE);
  end = ftello(j->fp);
  if (fwrite(buf, JOURNAL_RECSIZE, (size_t)n, j->fp) != (size_t)n || fflush(j->fp) || fsync(fileno(j->fp))) {
    int err = errno;
    /* e.g. a full disk: cut a partial record so that later appends stay aligned (best effort) */
    if (end >= 0 && !ftruncate(fileno(j->fp), end)) (void)fseeko(j->fp, end, SEEK_SET);
    PetscCall(PetscFree(buf));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot append to journal %s: %s", j->path, strerror(err));
  }
  PetscCall(PetscFree(buf));
  for (PetscInt i = 0; i < n; i++) {
    if (!j->done[recs[i].index]) j->ndone++;
    j->done[recs[i].index] = 1;
    j->recs[recs[i].index] = recs[i];
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcJournalGetDone - The samples the journal holds a record of.

  Not collective

  Input Parameter:
. j - the journal

  Output Parameters:
+ ndone - the number of samples with a record (may be NULL)
- done  - per sample 1 if it has a record, else 0 (length nsamples, owned by the journal; may be NULL)

  Level: developer

.seealso: HylcJournalGetRecords(), HylcJournalGetInfo()
@*/
PetscErrorCode HylcJournalGetDone(HylcJournal j, PetscInt *ndone, const unsigned char **done)
{
  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  if (ndone) *ndone = j->ndone;
  if (done) *done = j->done;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcJournalGetRecords - The records of the journal, indexed by sample.

  Not collective

  Input Parameter:
. j - the journal

  Output Parameter:
. recs - the records (length nsamples, valid where HylcJournalGetDone() says done; owned by the journal)

  Level: developer

.seealso: HylcJournalGetDone(), HylcJournalAppend()
@*/
PetscErrorCode HylcJournalGetRecords(HylcJournal j, const HylcSampleRecord **recs)
{
  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  PetscValidPointer(recs, 2);
  *recs = j->recs;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcJournalGetInfo - The size of the run the journal belongs to and what its opening dropped.

  Not collective

  Input Parameter:
. j - the journal

  Output Parameters:
+ nsamples - the number of samples of the run (may be NULL)
- ndropped - the records dropped from a torn tail when the journal was opened (may be NULL)

  Level: developer

.seealso: HylcJournalOpen(), HylcJournalGetDone()
@*/
PetscErrorCode HylcJournalGetInfo(HylcJournal j, long *nsamples, PetscInt *ndropped)
{
  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  if (nsamples) *nsamples = j->nsamples;
  if (ndropped) *ndropped = j->ndropped;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcJournalClose - Closes the journal's file (the journal stays on disk), releases its lock and frees the
  object; accepts NULL and sets the handle to NULL.

  Not collective

  Input Parameter:
. journal - the journal

  Level: developer

.seealso: HylcJournalOpen()
@*/
PetscErrorCode HylcJournalClose(HylcJournal *journal)
{
  HylcJournal j;
  FILE       *fp;

  PetscFunctionBegin;
  if (!journal || !*journal) PetscFunctionReturn(PETSC_SUCCESS);
  j        = *journal;
  *journal = NULL;
  fp       = j->fp;
  j->fp    = NULL;
  if (fp && fclose(fp)) { /* every record was already flushed and synced: report, but free first */
    int  err = errno;
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(PetscStrncpy(path, j->path, sizeof(path)));
    JournalFree(j);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "Cannot close journal %s: %s", path, strerror(err));
  }
  JournalFree(j);
  PetscFunctionReturn(PETSC_SUCCESS);
}
