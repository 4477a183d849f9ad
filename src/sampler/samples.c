/* Storage of microscale samples (include/hylc/samples.h; formats in docs/output-format.md):
   - the journal, an append-only binary file of fixed-size checksummed records that survives SIGKILL at
     any moment (plain C stdio + POSIX);
   - the HDF5 samples file (raw HDF5 C API), written atomically. */
#include <hylc/samples.h>
#include <hylc/sha256.h>
#include <petsc/private/petscimpl.h>
#include <hylc/private/h5util.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <time.h>
#include <unistd.h>

/* ------------------------------------------------------------------------------------------------ */
/* Journal                                                                                            */
/* ------------------------------------------------------------------------------------------------ */

#define JOURNAL_MAGIC     "HYLCJNL1"
#define JOURNAL_BOM       0x01020304u
#define JOURNAL_VERSION   2u  /* 1: a short fingerprint (hylc before the complete identity) */
#define JOURNAL_PAYLOAD   136 /* packed record without checksum */
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

static int NumStatuses(void)
{
  int n = 0;
  while (HylcMicroStatuses[n] && strcmp(HylcMicroStatuses[n], "HylcMicroStatus")) n++;
  return n;
}

/* the record layout: int64 index, int32 term, status, iterations, retries, 14 doubles, uint64 checksum */
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
  if (idx < 0 || idx >= nsamples || iv[0] < 0 || iv[0] >= HYLC_PLAN_NTERM || iv[1] < 0 || iv[1] >= NumStatuses()) return -1;
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
  PetscCheck(u[1] >= JOURNAL_VERSION, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s was written by an earlier hylc (journal format %u, without the complete run identity) and cannot be resumed safely: start over with -sampler_overwrite", j->path, (unsigned)u[1]);
  PetscCheck(got == JOURNAL_FIXEDHEAD, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s: corrupt header (too short): start over with -sampler_overwrite", j->path);
  memcpy(u, fixed + 8, 16);
  memcpy(&ns, fixed + 24, 8);
  PetscCheck(u[1] == JOURNAL_VERSION && u[2] == JOURNAL_RECSIZE, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "Journal %s has format version %u (record size %u); this hylc reads version %u (record size %u)", j->path, (unsigned)u[1], (unsigned)u[2], JOURNAL_VERSION, (unsigned)JOURNAL_RECSIZE);
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
    PetscCheck(recs[i].term >= 0 && recs[i].term < HYLC_PLAN_NTERM, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: sample %ld has invalid term %d", j->path, recs[i].index, recs[i].term);
    PetscCheck(recs[i].status >= 0 && recs[i].status < NumStatuses(), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Journal %s: sample %ld has invalid status %d", j->path, recs[i].index, recs[i].status);
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

PetscErrorCode HylcJournalGetDone(HylcJournal j, PetscInt *ndone, const unsigned char **done)
{
  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  if (ndone) *ndone = j->ndone;
  if (done) *done = j->done;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcJournalGetRecords(HylcJournal j, const HylcSampleRecord **recs)
{
  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  PetscValidPointer(recs, 2);
  *recs = j->recs;
  PetscFunctionReturn(PETSC_SUCCESS);
}

PetscErrorCode HylcJournalGetInfo(HylcJournal j, long *nsamples, PetscInt *ndropped)
{
  PetscFunctionBegin;
  PetscValidPointer(j, 1);
  if (nsamples) *nsamples = j->nsamples;
  if (ndropped) *ndropped = j->ndropped;
  PetscFunctionReturn(PETSC_SUCCESS);
}

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

/* ------------------------------------------------------------------------------------------------ */
/* HDF5                                                                                               */
/* ------------------------------------------------------------------------------------------------ */

/* The file the current HDF5 call works on, for error messages (rank-0, single-threaded code). */
static const char *HylcH5File = "?";

/* HylcCallHDF5(call): a negative return of a raw HDF5 call becomes a PETSc error naming the call, the
   file and HDF5's own description. HylcCallHDF5Id(id, call) also stores the returned hid_t. */
#define HylcCallHDF5(...)                                                                                            \
  do {                                                                                                               \
    if ((__VA_ARGS__) < 0) {                                                                                         \
      char hylc_h5msg_[256];                                                                                         \
      HylcH5ErrorText(hylc_h5msg_);                                                                                  \
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "HDF5 call %s failed on %s%s", #__VA_ARGS__, HylcH5File, hylc_h5msg_); \
    }                                                                                                                \
  } while (0)
#define HylcCallHDF5Id(id, ...) \
  do {                          \
    (id) = (__VA_ARGS__);       \
    HylcCallHDF5(id);           \
  } while (0)

static PetscErrorCode H5AttrString(hid_t loc, const char name[], const char value[])
{
  hid_t t, s, a;

  PetscFunctionBegin;
  HylcCallHDF5Id(t, H5Tcopy(H5T_C_S1));
  HylcCallHDF5(H5Tset_size(t, H5T_VARIABLE));
  HylcCallHDF5(H5Tset_cset(t, H5T_CSET_UTF8));
  HylcCallHDF5Id(s, H5Screate(H5S_SCALAR));
  HylcCallHDF5Id(a, H5Acreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(H5Awrite(a, t, &value));
  HylcCallHDF5(H5Aclose(a));
  HylcCallHDF5(H5Sclose(s));
  HylcCallHDF5(H5Tclose(t));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode H5AttrStrings(hid_t loc, const char name[], int n, const char *const values[])
{
  hid_t   t, s, a;
  hsize_t dim = (hsize_t)n;

  PetscFunctionBegin;
  HylcCallHDF5Id(t, H5Tcopy(H5T_C_S1));
  HylcCallHDF5(H5Tset_size(t, H5T_VARIABLE));
  HylcCallHDF5(H5Tset_cset(t, H5T_CSET_UTF8));
  HylcCallHDF5Id(s, H5Screate_simple(1, &dim, NULL));
  HylcCallHDF5Id(a, H5Acreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(H5Awrite(a, t, values));
  HylcCallHDF5(H5Aclose(a));
  HylcCallHDF5(H5Sclose(s));
  HylcCallHDF5(H5Tclose(t));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* scalar numeric attribute: memtype H5T_NATIVE_DOUBLE (stored as IEEE f64), H5T_NATIVE_LLONG (i64) or H5T_NATIVE_INT (i32) */
static PetscErrorCode H5AttrScalar(hid_t loc, const char name[], hid_t memtype, const void *value)
{
  hid_t s, a, ft = memtype == H5T_NATIVE_DOUBLE ? H5T_IEEE_F64LE : (memtype == H5T_NATIVE_LLONG ? H5T_STD_I64LE : H5T_STD_I32LE);

  PetscFunctionBegin;
  HylcCallHDF5Id(s, H5Screate(H5S_SCALAR));
  HylcCallHDF5Id(a, H5Acreate2(loc, name, ft, s, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(H5Awrite(a, memtype, value));
  HylcCallHDF5(H5Aclose(a));
  HylcCallHDF5(H5Sclose(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode H5AttrDouble(hid_t loc, const char name[], double v)
{
  PetscFunctionBegin;
  PetscCall(H5AttrScalar(loc, name, H5T_NATIVE_DOUBLE, &v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode H5AttrLong(hid_t loc, const char name[], long long v)
{
  PetscFunctionBegin;
  PetscCall(H5AttrScalar(loc, name, H5T_NATIVE_LLONG, &v));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a dataset of n rows and 'cols' columns (cols = 0: one-dimensional) of doubles (isint = 0) or int32,
   with the attributes units and description */
static PetscErrorCode H5Dataset(hid_t loc, const char name[], PetscBool isint, hsize_t n, hsize_t cols, const void *buf, const char units[], const char description[])
{
  hsize_t dims[2] = {n, cols};
  hid_t   s, d;

  PetscFunctionBegin;
  HylcCallHDF5Id(s, H5Screate_simple(cols ? 2 : 1, dims, NULL));
  HylcCallHDF5Id(d, H5Dcreate2(loc, name, isint ? H5T_STD_I32LE : H5T_IEEE_F64LE, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (n) HylcCallHDF5(H5Dwrite(d, isint ? H5T_NATIVE_INT : H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf));
  if (units) PetscCall(H5AttrString(d, "units", units));
  if (description) PetscCall(H5AttrString(d, "description", description));
  HylcCallHDF5(H5Dclose(d));
  HylcCallHDF5(H5Sclose(s));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode H5DatasetInt(hid_t loc, const char name[], PetscInt n, PetscInt cols, const PetscInt *v, const char units[], const char description[])
{
  int     *buf;
  PetscInt m = n * (cols ? cols : 1);

  PetscFunctionBegin;
  PetscCall(PetscMalloc1(m + 1, &buf));
  for (PetscInt i = 0; i < m; i++) buf[i] = (int)v[i];
  PetscCall(H5Dataset(loc, name, PETSC_TRUE, (hsize_t)n, (hsize_t)cols, buf, units, description));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteSamplesGroup(hid_t file, long N, const HylcSampleRecord recs[], const unsigned char done[])
{
  double *strain, *psi, *parts, *res, *cres, *t;
  int    *term, *status, *its, *retries;
  hid_t   g;
  int     nstat = NumStatuses();

  PetscFunctionBegin;
  PetscCall(PetscMalloc6(6 * N + 1, &strain, N + 1, &psi, 4 * N + 1, &parts, N + 1, &res, N + 1, &cres, N + 1, &t));
  PetscCall(PetscMalloc4(N + 1, &term, N + 1, &status, N + 1, &its, N + 1, &retries));
  for (long k = 0; k < N; k++) {
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
  PetscCall(H5AttrStrings(g, "status_names", nstat, (const char *const *)HylcMicroStatuses));
  {
    const char *names[HYLC_PLAN_NTERM];
    for (int t = 0; t < HYLC_PLAN_NTERM; t++) names[t] = HylcPlanTermName(t);
    PetscCall(H5AttrStrings(g, "term_names", HYLC_PLAN_NTERM, names));
  }
  PetscCall(H5AttrString(g, "description", "One row per sample of the plan, in plan order (row k = sample k). Samples not computed (interrupted run) have status -1, term/iterations/retries -1 and NaN values."));
  PetscCall(H5Dataset(g, "strain", PETSC_FALSE, (hsize_t)N, 6, strain, "1 for sx, sa, sy; 1/m for II00, II01, II11", "macroscopic strain z = (sx, sa, sy, II00, II01, II11): in-plane stretch/shear and the second fundamental form"));
  PetscCall(H5Dataset(g, "psi", PETSC_FALSE, (hsize_t)N, 0, psi, "J/m^2", "area energy density psi = E / A of the equilibrium (A: reference tile area)"));
  PetscCall(H5Dataset(g, "term", PETSC_TRUE, (hsize_t)N, 0, term, "1", "term of the sampling plan: 0 zero sample, 1..5 one-dimensional, 6..14 two-dimensional; index into /samples@term_names; -1 not computed"));
  PetscCall(H5Dataset(g, "status", PETSC_TRUE, (hsize_t)N, 0, status, "1", "HylcMicroStatus of the Newton solve, index into /samples@status_names (0 converged, 1 iteration_cap, 2 time_cap, 3 stalled, 4 nonfinite; 5 failed is reserved, no longer produced); -1: not computed (the run ended before this sample, all its values are NaN or -1)"));
  PetscCall(H5Dataset(g, "iterations", PETSC_TRUE, (hsize_t)N, 0, its, "1", "Newton iterations; -1 not computed"));
  PetscCall(H5Dataset(g, "retries", PETSC_TRUE, (hsize_t)N, 0, retries, "1", "regularization increases (alpha x 10 for an indefinite K); -1 not computed"));
  PetscCall(H5Dataset(g, "energy_parts", PETSC_FALSE, (hsize_t)N, 4, parts, "J", "energy of the tile by kind: columns stretch, bend, twist, contact"));
  PetscCall(H5Dataset(g, "residual", PETSC_FALSE, (hsize_t)N, 0, res, "1", "final projected-gradient norm relative to the initial one, |z| / |z0|"));
  PetscCall(H5Dataset(g, "constraint_residual", PETSC_FALSE, (hsize_t)N, 0, cres, "1 (units of the yarn radius)", "final periodicity-constraint residual |A y - dL| / r"));
  PetscCall(H5Dataset(g, "time", PETSC_FALSE, (hsize_t)N, 0, t, "s", "wall time of the sample's solve"));
  HylcCallHDF5(H5Gclose(g));
  PetscCall(PetscFree6(strain, psi, parts, res, cres, t));
  PetscCall(PetscFree4(term, status, its, retries));
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
  PetscCall(H5AttrString(g, "description", "the reference (rest) state of the periodic yarn tile the samples were computed on (layout: include/hylc/pattern.h, docs/patterns.md)"));
  PetscCall(H5AttrString(g, "type", type ? type : ""));
  PetscCall(H5AttrLong(g, "nv", (long long)d.nv));
  PetscCall(H5AttrDouble(g, "px", (double)d.px));
  PetscCall(H5AttrDouble(g, "py", (double)d.py));
  PetscCall(H5AttrDouble(g, "radius", (double)d.radius));
  PetscCall(H5AttrString(g, "units", "px, py, radius: m"));
  PetscCall(H5Dataset(g, "X", PETSC_FALSE, (hsize_t)d.nv, 3, d.X, "m", "reference position of each vertex"));
  PetscCall(H5Dataset(g, "theta", PETSC_FALSE, (hsize_t)d.nv, 0, d.theta, "rad", "twist of the edge leaving each vertex"));
  PetscCall(H5DatasetInt(g, "next", d.nv, 0, d.next, "1", "head vertex of the edge leaving each vertex (0-based)"));
  PetscCall(H5DatasetInt(g, "prev", d.nv, 0, d.prev, "1", "tail vertex of the edge entering each vertex (0-based)"));
  PetscCall(H5DatasetInt(g, "shift", d.nv, 2, d.shift, "periods", "lattice offset (dx, dy) of the head of the edge leaving each vertex: it runs from X[v] to X[next[v]] + (dx px, dy py, 0)"));
  PetscCall(H5Dataset(g, "rest_length", PETSC_FALSE, (hsize_t)d.nv, 0, d.restLength, "m", "rest length of the edge leaving each vertex"));
  PetscCall(H5Dataset(g, "rest_kappa", PETSC_FALSE, (hsize_t)d.nv, 2, d.restKappa, "1", "rest material curvature (kappa1, kappa2) at each vertex (integrated, dimensionless)"));
  PetscCall(H5Dataset(g, "rest_twist", PETSC_FALSE, (hsize_t)d.nv, 0, d.restTwist, "rad", "rest twist at each vertex"));
  PetscCall(H5Dataset(g, "ref_d1", PETSC_FALSE, (hsize_t)d.nv, 3, d.refD1, "1", "reference director d1 of the edge leaving each vertex (unit, perpendicular to the edge)"));
  PetscCall(H5Dataset(g, "ref_twist", PETSC_FALSE, (hsize_t)d.nv, 0, d.refTwist, "rad", "reference twist at each vertex"));
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
  PetscCall(H5AttrString(g, "description", "yarn material and contact model (include/hylc/yarn.h): resolved values used by the solver, and the option values they came from (*_option; <= 0 means the default rule)"));
  PetscCall(H5AttrString(g, "units", "E, Es, G: Pa; kc: N/m; radius: m; ks: N; B, beta: N m^2; exclude_arc: yarn radii"));
  PetscCall(H5AttrDouble(g, "E", (double)c.E));
  PetscCall(H5AttrDouble(g, "Es", (double)c.Es));
  PetscCall(H5AttrDouble(g, "G", (double)c.G));
  PetscCall(H5AttrDouble(g, "kc", (double)c.kc));
  PetscCall(H5AttrDouble(g, "radius", (double)c.r));
  PetscCall(H5AttrDouble(g, "ks", (double)c.ks));
  PetscCall(H5AttrDouble(g, "B", (double)c.B));
  PetscCall(H5AttrDouble(g, "beta", (double)c.beta));
  PetscCall(H5AttrDouble(g, "Es_option", (double)m->Es));
  PetscCall(H5AttrDouble(g, "G_option", (double)m->G));
  PetscCall(H5AttrDouble(g, "kc_option", (double)m->kc));
  PetscCall(H5AttrDouble(g, "radius_option", (double)m->radius));
  PetscCall(H5AttrLong(g, "contact_points", (long long)m->contactPoints));
  PetscCall(H5AttrString(g, "contact_type", (int)m->contactType >= 0 && (int)m->contactType < 2 ? ContactNames[m->contactType] : "unknown"));
  PetscCall(H5AttrDouble(g, "exclude_arc", (double)m->excludeArc));
  PetscCall(H5AttrString(g, "curvature", (int)m->curvature >= 0 && (int)m->curvature < 2 ? CurvatureNames[m->curvature] : "unknown"));
  HylcCallHDF5(H5Gclose(g));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a scalar UTF-8 string dataset with a description */
static PetscErrorCode H5ScalarString(hid_t loc, const char name[], const char text[], const char description[])
{
  hid_t t, s, d;

  PetscFunctionBegin;
  HylcCallHDF5Id(t, H5Tcopy(H5T_C_S1));
  HylcCallHDF5(H5Tset_size(t, H5T_VARIABLE));
  HylcCallHDF5(H5Tset_cset(t, H5T_CSET_UTF8));
  HylcCallHDF5Id(s, H5Screate(H5S_SCALAR));
  HylcCallHDF5Id(d, H5Dcreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  HylcCallHDF5(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, &text));
  PetscCall(H5AttrString(d, "description", description));
  HylcCallHDF5(H5Dclose(d));
  HylcCallHDF5(H5Sclose(s));
  HylcCallHDF5(H5Tclose(t));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode WriteOptions(hid_t file, const char text[])
{
  PetscFunctionBegin;
  PetscCall(H5ScalarString(file, "options", text, "the complete PETSc options of the run (PetscOptionsGetAll: command line, options files, environment), one string"));
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
  PetscCall(H5AttrString(file, "format", "hylc-samples"));
  PetscCall(H5AttrLong(file, "format_version", 1));
  PetscCall(H5AttrString(file, "hylc_version", HYLC_VERSION_STRING));
  PetscCall(H5AttrString(file, "petsc_version", petscv));
  PetscCall(H5AttrString(file, "hdf5_version", h5v));
  PetscCall(H5AttrString(file, "creation_date", date));
  PetscCall(H5AttrString(file, "hostname", host));
  PetscCall(H5AttrLong(file, "nsamples", (long long)N));
  PetscCall(H5AttrLong(file, "ndone", ndone));
  PetscCall(H5AttrLong(file, "nconverged", nconv));
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

/* a one-dimensional dataset of n strings */
static PetscErrorCode H5StringList(hid_t loc, const char name[], int n, const char *const values[], const char description[])
{
  hid_t   t, s, d;
  hsize_t dim = (hsize_t)n;

  PetscFunctionBegin;
  HylcCallHDF5Id(t, H5Tcopy(H5T_C_S1));
  HylcCallHDF5(H5Tset_size(t, H5T_VARIABLE));
  HylcCallHDF5(H5Tset_cset(t, H5T_CSET_UTF8));
  HylcCallHDF5Id(s, H5Screate_simple(1, &dim, NULL));
  HylcCallHDF5Id(d, H5Dcreate2(loc, name, t, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (n) HylcCallHDF5(H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, values));
  PetscCall(H5AttrString(d, "description", description));
  HylcCallHDF5(H5Dclose(d));
  HylcCallHDF5(H5Sclose(s));
  HylcCallHDF5(H5Tclose(t));
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
  PetscCall(H5AttrString(g, "description", "the identity of the run: everything that can change a sample's result (versions, the pattern bit for bit, every option but the neutral ones of docs/output-format.md); digest = SHA-256 of the identity text, as in the journal"));
  PetscCall(H5AttrString(g, "digest", hex));
  PetscCall(H5AttrString(g, "digest_algorithm", "sha256"));
  PetscCall(H5AttrString(g, "hylc_version", version[0]));
  PetscCall(H5AttrString(g, "hylc_build", version[1]));
  PetscCall(H5AttrString(g, "petsc_version", version[2]));
  PetscCall(H5StringList(g, "options", nopt, opts, "the options of the identity, \"-name value\", sorted by name (neutral options left out)"));
  PetscCall(H5StringList(g, "pattern", npat, pat, "the pattern of the identity, \"field value\" (scalars) or \"field sha256:<digest of the array's bytes>\" (arrays, native layout)"));
  PetscCall(H5ScalarString(g, "identity", identity, "the canonical identity text (its SHA-256 is /provenance@digest)"));
  HylcCallHDF5(H5Gclose(g));
  PetscCall(PetscFree2(opts, pat));
  PetscCall(PetscFree(copy));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* builds the whole file in memory (HDF5's core driver, no backing store) and returns its image */
static PetscErrorCode BuildImage(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[], const char identity[], void **image, size_t *size)
{
  hid_t          fapl, file;
  ssize_t        n;
  PetscErrorCode ierr;
  char           msg[256];

  PetscFunctionBegin;
  *image = NULL;
  *size  = 0;
  HylcCallHDF5Id(fapl, H5Pcreate(H5P_FILE_ACCESS));
  if (H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG) < 0 || H5Pset_fapl_core(fapl, 1 << 20, 0) < 0 || (file = H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl)) < 0) {
    HylcH5ErrorText(msg);
    H5Pclose(fapl);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot create the samples file %s in memory%s", path, msg);
  }
  H5Pclose(fapl);
  ierr = WriteFile(file, nsamples, recs, done, reference, model, optionsText);
  if (!ierr && identity) ierr = WriteProvenance(file, identity);
  if (!ierr) {
    if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0 || (n = H5Fget_file_image(file, NULL, 0)) <= 0) {
      HylcH5ErrorText(msg);
      H5Fclose(file);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "Cannot build the samples file %s%s", path, msg);
    }
    ierr = PetscMalloc((size_t)n, image);
    if (!ierr && H5Fget_file_image(file, *image, (size_t)n) != n) {
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
  Not collective (rank 0).
@*/
PetscErrorCode HylcSamplesWriteHDF5WithIdentity(const char path[], long nsamples, const HylcSampleRecord recs[], const unsigned char done[], HylcPattern reference, const HylcYarnModel *model, const char optionsText[], const char identity[])
{
  char           tmp[PETSC_MAX_PATH_LEN];
  H5E_auto2_t    efunc;
  void          *edata, *image = NULL;
  size_t         size = 0;
  FILE          *fp   = NULL;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidCharPointer(path, 1);
  PetscCheck(nsamples >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: negative number of samples %ld", path, nsamples);
  HylcH5File = path;
  /* HDF5 prints nothing itself: its innermost message goes into the PETSc error */
  H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  ierr = BuildImage(path, nsamples, recs, done, reference, model, optionsText, identity, &image, &size);
  H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  HylcH5File = "?";
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
  PetscCall(HylcSamplesWriteHDF5WithIdentity(path, nsamples, recs, done, reference, model, optionsText, NULL));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode H5ReadDataset(hid_t file, const char name[], hid_t memtype, hsize_t n, hsize_t cols, void *buf)
{
  hid_t   d, s;
  int     rank;
  hsize_t dims[2] = {0, 0};

  PetscFunctionBegin;
  HylcCallHDF5Id(d, H5Dopen2(file, name, H5P_DEFAULT));
  HylcCallHDF5Id(s, H5Dget_space(d));
  HylcCallHDF5Id(rank, H5Sget_simple_extent_ndims(s));
  HylcCallHDF5(H5Sget_simple_extent_dims(s, dims, NULL));
  PetscCheck(rank == (cols ? 2 : 1) && dims[0] == n && (!cols || dims[1] == cols), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: dataset %s has an unexpected shape", HylcH5File, name);
  if (n) HylcCallHDF5(H5Dread(d, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf));
  HylcCallHDF5(H5Sclose(s));
  HylcCallHDF5(H5Dclose(d));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode ReadFile(hid_t file, long *nsamples, HylcSampleRecord **recs_, unsigned char **done_, char **optionsText)
{
  hid_t             d, s, t;
  hsize_t           dims[2];
  long              N;
  double           *strain, *psi, *parts, *res, *cres, *tm;
  int              *term, *status, *its, *retries;
  HylcSampleRecord *recs;
  unsigned char    *done;

  PetscFunctionBegin;
  HylcCallHDF5Id(d, H5Dopen2(file, "samples/psi", H5P_DEFAULT));
  HylcCallHDF5Id(s, H5Dget_space(d));
  HylcCallHDF5(H5Sget_simple_extent_dims(s, dims, NULL));
  HylcCallHDF5(H5Sclose(s));
  HylcCallHDF5(H5Dclose(d));
  N = (long)dims[0];
  PetscCall(PetscMalloc6(6 * N + 1, &strain, N + 1, &psi, 4 * N + 1, &parts, N + 1, &res, N + 1, &cres, N + 1, &tm));
  PetscCall(PetscMalloc4(N + 1, &term, N + 1, &status, N + 1, &its, N + 1, &retries));
  PetscCall(H5ReadDataset(file, "samples/strain", H5T_NATIVE_DOUBLE, N, 6, strain));
  PetscCall(H5ReadDataset(file, "samples/psi", H5T_NATIVE_DOUBLE, N, 0, psi));
  PetscCall(H5ReadDataset(file, "samples/energy_parts", H5T_NATIVE_DOUBLE, N, 4, parts));
  PetscCall(H5ReadDataset(file, "samples/residual", H5T_NATIVE_DOUBLE, N, 0, res));
  PetscCall(H5ReadDataset(file, "samples/constraint_residual", H5T_NATIVE_DOUBLE, N, 0, cres));
  PetscCall(H5ReadDataset(file, "samples/time", H5T_NATIVE_DOUBLE, N, 0, tm));
  PetscCall(H5ReadDataset(file, "samples/term", H5T_NATIVE_INT, N, 0, term));
  PetscCall(H5ReadDataset(file, "samples/status", H5T_NATIVE_INT, N, 0, status));
  PetscCall(H5ReadDataset(file, "samples/iterations", H5T_NATIVE_INT, N, 0, its));
  PetscCall(H5ReadDataset(file, "samples/retries", H5T_NATIVE_INT, N, 0, retries));
  PetscCall(PetscCalloc1(N + 1, &recs));
  PetscCall(PetscCalloc1(N + 1, &done));
  for (long k = 0; k < N; k++) {
    HylcSampleRecord *r = &recs[k];
    r->index            = k;
    for (int i = 0; i < 6; i++) r->z[i] = strain[6 * k + i];
    for (int i = 0; i < 4; i++) r->parts[i] = parts[4 * k + i];
    r->psi        = psi[k];
    r->residual   = res[k];
    r->cresidual  = cres[k];
    r->time       = tm[k];
    r->term       = term[k];
    r->status     = status[k];
    r->iterations = its[k];
    r->retries    = retries[k];
    done[k]       = status[k] >= 0;
  }
  PetscCall(PetscFree6(strain, psi, parts, res, cres, tm));
  PetscCall(PetscFree4(term, status, its, retries));
  *nsamples = N;
  *recs_    = recs;
  *done_    = done;
  if (optionsText) {
    char *text = NULL;

    HylcCallHDF5Id(d, H5Dopen2(file, "options", H5P_DEFAULT));
    HylcCallHDF5Id(t, H5Tcopy(H5T_C_S1));
    HylcCallHDF5(H5Tset_size(t, H5T_VARIABLE));
    HylcCallHDF5(H5Tset_cset(t, H5T_CSET_UTF8));
    HylcCallHDF5Id(s, H5Dget_space(d));
    HylcCallHDF5(H5Dread(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, &text));
    PetscCall(PetscStrallocpy(text ? text : "", optionsText));
#if H5_VERSION_GE(1, 12, 0)
    HylcCallHDF5(H5Treclaim(t, s, H5P_DEFAULT, &text));
#else
    HylcCallHDF5(H5Dvlen_reclaim(t, s, H5P_DEFAULT, &text));
#endif
    HylcCallHDF5(H5Sclose(s));
    HylcCallHDF5(H5Tclose(t));
    HylcCallHDF5(H5Dclose(d));
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcSamplesReadHDF5 - Reads /samples (and /options) of a samples file. Not collective.
@*/
PetscErrorCode HylcSamplesReadHDF5(const char path[], long *nsamples, HylcSampleRecord **recs, unsigned char **done, char **optionsText)
{
  hid_t          fapl, file;
  H5E_auto2_t    efunc;
  void          *edata;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidCharPointer(path, 1);
  PetscValidPointer(nsamples, 2);
  PetscValidPointer(recs, 3);
  PetscValidPointer(done, 4);
  HylcH5File = path;
  H5Eget_auto2(H5E_DEFAULT, &efunc, &edata);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  fapl = H5Pcreate(H5P_FILE_ACCESS);
  if (fapl >= 0) H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG);
  file = H5Fopen(path, H5F_ACC_RDONLY, fapl >= 0 ? fapl : H5P_DEFAULT);
  if (file < 0) {
    char msg[256];
    HylcH5ErrorText(msg);
    if (fapl >= 0) H5Pclose(fapl);
    H5Eset_auto2(H5E_DEFAULT, efunc, edata);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open the samples file %s%s", path, msg);
  }
  ierr = ReadFile(file, nsamples, recs, done, optionsText);
  H5Fclose(file);
  if (fapl >= 0) H5Pclose(fapl);
  H5Eset_auto2(H5E_DEFAULT, efunc, edata);
  HylcH5File = "?";
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}
