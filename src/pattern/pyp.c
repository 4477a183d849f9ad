/* Reader and writer of the .pyp periodic yarn pattern format (docs/patterns.md). */
#include <hylc/private/patternimpl.h>
#include <hylc/geom.h>
#include <ctype.h>
#include <errno.h>
#include <stdlib.h>

typedef enum { BLK_PATTERN, BLK_Q, BLK_E, BLK_RL, BLK_RK, BLK_RT, BLK_REFD1, BLK_REFT, NBLK } PypBlock;

static const char *const BlockName[NBLK] = {"pattern", "Q", "E", "RL", "RK", "RT", "RefD1", "RefT"};
static const int         BlockCols[NBLK] = {4, 4, 4, 1, 2, 1, 3, 1};
static const char *const BlockHelp[NBLK] = {"px py radius num_vertedges", "dofs: x y z t", "edges: v0 v1 dx dy", "rest lengths", "rest kappas", "rest twists", "reference directors", "reference twists"};

typedef struct {
  PetscInt   header; /* line of the header, 0 if absent */
  PetscInt   nrows, cap;
  PetscReal *val;  /* nrows * cols */
  PetscInt  *line; /* line number of each row */
} PypBlockData;

static PetscErrorCode PypBlockAppend(PypBlockData *b, int cols, const PetscReal v[], PetscInt line)
{
  PetscFunctionBegin;
  if (b->nrows == b->cap) {
    PetscInt   cap = b->cap ? 2 * b->cap : 64;
    PetscReal *val;
    PetscInt  *ln;
    PetscCall(PetscMalloc2(cap * cols, &val, cap, &ln));
    PetscCall(PetscArraycpy(val, b->val, b->nrows * cols));
    PetscCall(PetscArraycpy(ln, b->line, b->nrows));
    PetscCall(PetscFree2(b->val, b->line));
    b->val  = val;
    b->line = ln;
    b->cap  = cap;
  }
  PetscCall(PetscArraycpy(b->val + b->nrows * cols, v, cols));
  b->line[b->nrows++] = line;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Formats a number with C's printf (PETSc's printf appends '.' to integral %g values). */
static const char *Num(char buf[32], PetscReal v)
{
  snprintf(buf, 32, "%.17g", (double)v);
  return buf;
}

/* Checks that a value stored as a real is an integer in [lo, hi). */
static PetscBool IsIntIn(PetscReal v, PetscReal lo, PetscReal hi) { return (PetscBool)(v == PetscFloorReal(v) && v >= lo && v < hi); }

/* Parses the text of a .pyp file into p; the scratch blocks blk[] and *erow_ are owned (and freed, also
   on error) by the caller. fname is used in messages only. */
static PetscErrorCode PypParse(HylcPattern p, const char fname[], char *text, PypBlockData blk[NBLK], PetscInt **erow_)
{
  MPI_Comm  comm = PetscObjectComm((PetscObject)p);
  PetscInt  cur = -1, lineno = 0, nv;
  char     *s = text;
  PetscReal px, py, r;
  char      b0[32], b1[32];

  PetscFunctionBegin;
  while (s && *s) {
    char *eol = strchr(s, '\n'), *c;
    if (eol) *eol = 0;
    lineno++;
    if ((c = strchr(s, '#'))) { /* a comment; the *pattern header's may record the tile's state */
      const char *rec = strstr(c + 1, "hylc state: ");
      *c              = 0;
      if (rec && !strncmp(s + strspn(s, " \t"), "*pattern", 8)) {
        rec += 12;
        for (int k = 1; k <= HYLC_PATTERN_STATE_EQUILIBRIUM; k++) {
          const size_t n = strlen(HylcPatternStates[k]);
          if (!strncmp(rec, HylcPatternStates[k], n) && !isalnum((unsigned char)rec[n])) p->state = (HylcPatternState)k;
        }
      }
    }
    while (isspace((unsigned char)*s)) s++;
    if (*s == '*') { /* block header */
      char   name[32];
      size_t k = 0;
      s++;
      while (*s && !isspace((unsigned char)*s) && k < sizeof(name) - 1) name[k++] = *s++;
      name[k] = 0;
      cur     = -1;
      for (int b = 0; b < NBLK; b++) {
        PetscBool eq;
        PetscCall(PetscStrcmp(name, BlockName[b], &eq));
        if (eq) cur = b;
      }
      PetscCheck(cur >= 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": unknown block '*%s' (known: *pattern *Q *E *RL *RK *RT *RefD1 *RefT)", fname, lineno, name);
      PetscCheck(!blk[cur].header, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block '*%s' repeated (first at line %" PetscInt_FMT ")", fname, lineno, name, blk[cur].header);
      blk[cur].header = lineno;
      while (isspace((unsigned char)*s)) s++;
      PetscCheck(!*s, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": unexpected text '%s' after block header '*%s' (comments start with #)", fname, lineno, s, name);
    } else if (*s) { /* data row */
      PetscReal v[4];
      int       ncol = 0;
      PetscCheck(cur >= 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": data before the first block header ('*pattern')", fname, lineno);
      while (*s) {
        char  *end;
        char   tok[64];
        size_t k = 0;
        while (s[k] && !isspace((unsigned char)s[k]) && k < sizeof(tok) - 1) {
          tok[k] = s[k];
          k++;
        }
        tok[k] = 0;
        PetscCheck(ncol < BlockCols[cur], comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block *%s (%s) expects %d values per row, found more", fname, lineno, BlockName[cur], BlockHelp[cur], BlockCols[cur]);
        errno    = 0;
        double x = strtod(tok, &end);
        PetscCheck(end != tok && *end == 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block *%s: '%s' is not a number", fname, lineno, BlockName[cur], tok);
        PetscCheck(isfinite(x) && errno != ERANGE, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block *%s: value '%s' is not finite", fname, lineno, BlockName[cur], tok);
        v[ncol++] = x;
        s += k;
        while (isspace((unsigned char)*s)) s++;
      }
      PetscCheck(ncol == BlockCols[cur], comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block *%s (%s) expects %d values per row, found %d", fname, lineno, BlockName[cur], BlockHelp[cur], BlockCols[cur], ncol);
      PetscCall(PypBlockAppend(&blk[cur], BlockCols[cur], v, lineno));
    }
    s = eol ? eol + 1 : NULL;
  }

  for (int b = 0; b < NBLK; b++) PetscCheck(blk[b].header, comm, PETSC_ERR_USER_INPUT, "%s: missing block '*%s' (%s)", fname, BlockName[b], BlockHelp[b]);
  PetscCheck(blk[BLK_PATTERN].nrows == 1, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block *pattern needs exactly one row 'px py radius N', found %" PetscInt_FMT, fname, blk[BLK_PATTERN].header, blk[BLK_PATTERN].nrows);
  {
    const PetscReal *h  = blk[BLK_PATTERN].val;
    const PetscInt   ln = blk[BLK_PATTERN].line[0];
    px                  = h[0];
    py                  = h[1];
    r                   = h[2];
    PetscCheck(px > 0 && py > 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": periods must be positive, got px = %g, py = %g", fname, ln, (double)px, (double)py);
    PetscCheck(r > 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": yarn radius must be positive, got %g", fname, ln, (double)r);
    /* some lattice translate of every yarn is another yarn within max(px, py) of it: a radius that large
       means yarns overlapping their own periodic images by more than a radius */
    PetscCheck(r < PetscMax(px, py), comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": yarn radius %s is not smaller than the periods (px = %g, py = %g): every yarn would overlap its periodic images; not a physical tile", fname, ln,
               (snprintf(b0, sizeof(b0), "%.9g", (double)r), b0), (double)px, (double)py);
    PetscCheck(IsIntIn(h[3], 1, PETSC_MAX_INT), comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": num_vertedges must be a positive integer, got %s", fname, ln, Num(b0, h[3]));
    nv = (PetscInt)h[3];
  }
  for (int b = 1; b < NBLK; b++)
    PetscCheck(blk[b].nrows == nv, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": block *%s has %" PetscInt_FMT " rows, expected %" PetscInt_FMT " (num_vertedges of *pattern at line %" PetscInt_FMT ")", fname, blk[b].header, BlockName[b],
               blk[b].nrows, nv, blk[BLK_PATTERN].header);

  PetscCall(HylcPatternAllocate_Private(p, nv));
  p->px     = px;
  p->py     = py;
  p->radius = r;
  for (PetscInt v = 0; v < nv; v++) {
    for (int d = 0; d < 3; d++) p->X[3 * v + d] = blk[BLK_Q].val[4 * v + d];
    p->theta[v]             = blk[BLK_Q].val[4 * v + 3];
    p->restKappa[2 * v]     = blk[BLK_RK].val[2 * v];
    p->restKappa[2 * v + 1] = blk[BLK_RK].val[2 * v + 1];
    p->restTwist[v]         = blk[BLK_RT].val[v];
    p->refTwist[v]          = blk[BLK_REFT].val[v];
    p->next[v]              = -1;
    p->prev[v]              = -1;
  }
  /* edges: each row v0 v1 dx dy; RL and RefD1 are indexed by the source vertex v0 */
  PetscInt *erow;
  PetscCall(PetscMalloc1(nv, erow_));
  erow = *erow_;
  for (PetscInt k = 0; k < nv; k++) {
    const PetscReal *e  = blk[BLK_E].val + 4 * k;
    const PetscInt   ln = blk[BLK_E].line[k];
    PetscCheck(IsIntIn(e[0], 0, nv) && IsIntIn(e[1], 0, nv), comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": edge vertex index (%s, %s) out of range: vertices are integers in [0, %" PetscInt_FMT ")", fname, ln, Num(b0, e[0]), Num(b1, e[1]), nv);
    PetscCheck(e[2] == PetscFloorReal(e[2]) && e[3] == PetscFloorReal(e[3]) && PetscAbsReal(e[2]) < 1e6 && PetscAbsReal(e[3]) < 1e6, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": periodic offsets dx dy must be integers, got (%s, %s)", fname, ln,
               Num(b0, e[2]), Num(b1, e[3]));
    const PetscInt v0 = (PetscInt)e[0], v1 = (PetscInt)e[1];
    PetscCheck(p->next[v0] < 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": vertex %" PetscInt_FMT " has a second outgoing edge (the first is at line %" PetscInt_FMT "); every vertex needs exactly one outgoing and one incoming edge", fname,
               ln, v0, blk[BLK_E].line[erow[v0]]);
    PetscCheck(p->prev[v1] < 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": vertex %" PetscInt_FMT " has a second incoming edge (the first is at line %" PetscInt_FMT "); every vertex needs exactly one outgoing and one incoming edge", fname,
               ln, v1, blk[BLK_E].line[erow[p->prev[v1]]]);
    p->next[v0]          = v1;
    p->prev[v1]          = v0;
    p->shift[2 * v0]     = (PetscInt)e[2];
    p->shift[2 * v0 + 1] = (PetscInt)e[3];
    erow[v0]             = k;
  }
  /* with nv rows and no vertex repeated as source or target, every vertex has exactly one of each */
  if (p->consistentPeriods) {
    /* each edge crossing the boundary in x only (y only) fixes px (py) by |edge| = rest length */
    PetscReal sum[2] = {0, 0};
    PetscInt  cnt[2] = {0, 0};
    for (PetscInt v = 0; v < nv; v++) {
      const PetscInt w = p->next[v], sx = p->shift[2 * v], sy = p->shift[2 * v + 1];
      if ((sx != 0) == (sy != 0)) continue;
      const int       k  = sx ? 0 : 1;
      const PetscInt  sk = sx ? sx : sy;
      const PetscReal dk = p->X[3 * w + k] - p->X[3 * v + k], RL = blk[BLK_RL].val[v];
      const PetscReal o0 = p->X[3 * w + 1 - k] - p->X[3 * v + 1 - k], o2 = p->X[3 * w + 2] - p->X[3 * v + 2];
      const PetscReal perp2 = RL * RL - o0 * o0 - o2 * o2;
      if (perp2 <= 0) continue;
      /* dk + sk P = sign(sk) sqrt(perp2) */
      sum[k] += (PetscSign(sk) * PetscSqrtReal(perp2) - dk) / sk;
      cnt[k]++;
    }
    PetscCheck(cnt[0] && cnt[1], comm, PETSC_ERR_USER_INPUT, "%s: -pattern_consistent_periods needs edges crossing the tile boundary in x only and in y only", fname);
    PetscCall(PetscPrintf(comm, "%s: consistent periods %.9g %.9g (stored %.9g %.9g)\n", fname, (double)(sum[0] / cnt[0]), (double)(sum[1] / cnt[1]), (double)px, (double)py));
    p->px = px = sum[0] / cnt[0];
    p->py = py = sum[1] / cnt[1];
  }
  PetscInt  nwarnRL = 0, nwarnD1 = 0;
  PetscReal worstRL = 0, worstD1 = 0;
  for (PetscInt v = 0; v < nv; v++) {
    const PetscInt ln = blk[BLK_E].line[erow[v]], w = p->next[v];
    PetscReal      e[3], t[3], d1[3];
    e[0]              = p->X[3 * w + 0] + p->shift[2 * v] * px - p->X[3 * v + 0];
    e[1]              = p->X[3 * w + 1] + p->shift[2 * v + 1] * py - p->X[3 * v + 1];
    e[2]              = p->X[3 * w + 2] - p->X[3 * v + 2];
    const PetscReal l = HylcNorm3(e);
    PetscCheck(l > 1e-9 * r, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": edge %" PetscInt_FMT " -> %" PetscInt_FMT " has zero length (%g)", fname, ln, v, w, (double)l);
    const PetscReal RL = blk[BLK_RL].val[v];
    PetscCheck(RL > 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": rest length of the edge leaving vertex %" PetscInt_FMT " must be positive, got %g", fname, blk[BLK_RL].line[v], v, (double)RL);
    p->restLength[v] = RL;
    if (PetscAbsReal(RL / l - 1) > 0.02) {
      nwarnRL++;
      worstRL = PetscMax(worstRL, PetscAbsReal(RL / l - 1));
    }
    for (int d = 0; d < 3; d++) {
      t[d]  = e[d] / l;
      d1[d] = blk[BLK_REFD1].val[3 * v + d];
    }
    const PetscReal n1 = HylcNorm3(d1);
    PetscCheck(n1 > 0, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": reference director of the edge leaving vertex %" PetscInt_FMT " is zero", fname, blk[BLK_REFD1].line[v], v);
    const PetscReal cosang = PetscAbsReal(HylcDot3(d1, t)) / n1;
    /* re-orthonormalize only what needs it, so that write + read reproduces the numbers exactly */
    const PetscReal perp = (cosang > 1e-10 || PetscAbsReal(n1 - 1) > 1e-10) ? HylcOrthonormalizeDirector(t, d1) : 1.0;
    PetscCheck(perp >= 0.1, comm, PETSC_ERR_USER_INPUT, "%s:%" PetscInt_FMT ": reference director of the edge leaving vertex %" PetscInt_FMT " is not perpendicular to its edge (|d1.t|/|d1| = %.4g; its perpendicular part is only %.3g of |d1|)", fname,
               blk[BLK_REFD1].line[v], v, (double)cosang, (double)perp);
    if (cosang > 1e-3) {
      nwarnD1++;
      worstD1 = PetscMax(worstD1, cosang);
    }
    for (int d = 0; d < 3; d++) p->refD1[3 * v + d] = d1[d];
  }
  if (nwarnRL) PetscCall(PetscPrintf(comm, "Warning: %s: %" PetscInt_FMT " edges have rest lengths more than 2%% off their current lengths (worst %.3g%%)\n", fname, nwarnRL, (double)(100 * worstRL)));
  if (nwarnD1) PetscCall(PetscPrintf(comm, "Warning: %s: %" PetscInt_FMT " reference directors were not perpendicular to their edges (worst |d1.t| = %.3g) and were re-orthogonalized\n", fname, nwarnD1, (double)worstD1));
  PetscCall(HylcPatternBuildLoops_Private(p));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Parses the text of a .pyp file (fname is used in messages only); frees its scratch on every path. */
static PetscErrorCode HylcPatternParse_Private(HylcPattern p, const char fname[], char *text)
{
  PypBlockData   blk[NBLK];
  PetscInt      *erow = NULL;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(PetscMemzero(blk, sizeof(blk)));
  p->state = HYLC_PATTERN_STATE_UNRECORDED; /* unless the file records it */
  ierr     = PypParse(p, fname, text, blk, &erow);
  PetscCall(PetscFree(erow));
  for (int b = 0; b < NBLK; b++) PetscCall(PetscFree2(blk[b].val, blk[b].line));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternLoadFromString - Parses .pyp text (name is used in messages). Collective; every rank
  must pass the same text.
@*/
PetscErrorCode HylcPatternLoadFromString(HylcPattern p, const char name[], const char text[])
{
  char *copy;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscErrorCode ierr;

  PetscCall(PetscStrallocpy(text, &copy));
  ierr = HylcPatternParse_Private(p, name, copy);
  PetscCall(PetscFree(copy));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Error handler that keeps the message of the first error in ctx (HYLC_PATTERN_MSG_LEN chars): checks
   and writes made on rank 0 only are then reported on every rank by HylcPatternRaiseFromRank0_Private(). */
PetscErrorCode HylcPatternKeepMessage_Private(MPI_Comm comm, int line, const char *fun, const char *file, PetscErrorCode n, PetscErrorType t, const char *mess, void *ctx)
{
  (void)comm, (void)line, (void)fun, (void)file;
  if (t == PETSC_ERROR_INITIAL && mess) PetscStrncpy((char *)ctx, mess, HYLC_PATTERN_MSG_LEN);
  return n;
}

/* Broadcasts rank 0's error code (0: none) and message and raises it on comm. Collective. */
PetscErrorCode HylcPatternRaiseFromRank0_Private(MPI_Comm comm, PetscErrorCode code, char msg[])
{
  int c = (int)code;

  PetscFunctionBegin;
  PetscCallMPI(MPI_Bcast(&c, 1, MPI_INT, 0, comm));
  if (!c) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCallMPI(MPI_Bcast(msg, HYLC_PATTERN_MSG_LEN, MPI_CHAR, 0, comm));
  SETERRQ(comm, (PetscErrorCode)c, "%s", msg);
}

/* Rank 0 reads the whole file (an existing regular file, not a directory, below 1 GiB) into *text
   (allocated, NUL-terminated) and *len; errors are raised on comm on every rank with rank 0's message. */
static PetscErrorCode PypReadOnRank0(MPI_Comm comm, const char fname[], char **text, long *len)
{
  PetscMPIInt    rank;
  char           msg[HYLC_PATTERN_MSG_LEN] = "";
  PetscErrorCode code                      = 0; /* rank 0's error */
  FILE          *fp                        = NULL;

  PetscFunctionBegin;
  *text = NULL;
  *len  = 0;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    PetscCall(PetscPushErrorHandler(HylcPatternKeepMessage_Private, msg));
    code = HylcFileCheckInput(PETSC_COMM_SELF, fname, "-pattern_file");
    PetscCall(PetscPopErrorHandler());
    if (!code) {
      fp = fopen(fname, "rb");
      if (fp && fseek(fp, 0, SEEK_END) == 0) *len = ftell(fp);
      if (fp) rewind(fp);
      if (!fp || *len < 0) {
        code = PETSC_ERR_FILE_OPEN;
        PetscCall(PetscSNPrintf(msg, sizeof(msg), "Cannot open pattern file '%s': %s", fname, strerror(errno)));
      } else if (*len >= (1L << 30)) {
        code = PETSC_ERR_USER_INPUT;
        PetscCall(PetscSNPrintf(msg, sizeof(msg), "Pattern file '%s' is too large (%ld bytes; at most 1 GiB)", fname, *len));
      }
    }
    if (code && fp) fclose(fp);
  }
  PetscCall(HylcPatternRaiseFromRank0_Private(comm, code, msg));
  PetscCallMPI(MPI_Bcast(len, 1, MPI_LONG, 0, comm));
  if (PetscMalloc1(*len + 1, text)) {
    if (fp) fclose(fp);
    SETERRQ(comm, PETSC_ERR_MEM, "Cannot allocate %ld bytes for pattern file '%s'", *len, fname);
  }
  if (rank == 0) {
    size_t got = fread(*text, 1, (size_t)*len, fp);
    if ((long)got != *len) {
      code = PETSC_ERR_FILE_READ;
      PetscCall(PetscSNPrintf(msg, sizeof(msg), "Cannot read pattern file '%s'%s%s", fname, ferror(fp) ? ": " : " (it changed while being read)", ferror(fp) ? strerror(errno) : ""));
    }
    fclose(fp);
  }
  if (code) PetscCall(PetscFree(*text));
  PetscCall(HylcPatternRaiseFromRank0_Private(comm, code, msg));
  PetscCallMPI(MPI_Bcast(*text, (PetscMPIInt)*len, MPI_CHAR, 0, comm));
  (*text)[*len] = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternLoad - Reads a .pyp file and validates it; errors name the file, line and problem.
  Collective: rank 0 reads the file and broadcasts its text.
@*/
PetscErrorCode HylcPatternLoad(HylcPattern p, const char fname[])
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)p);
  long           len  = 0;
  char          *text = NULL;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCall(PetscLogEventBegin(HYLC_PatternLoad, p, 0, 0, 0));
  PetscCall(PypReadOnRank0(comm, fname, &text, &len));
  if (strlen(text) != (size_t)len) {
    const size_t at = strlen(text);
    PetscCall(PetscFree(text));
    SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: contains a NUL byte at offset %zu: not a text .pyp file", fname, at);
  }
  ierr = HylcPatternParse_Private(p, fname, text);
  PetscCall(PetscFree(text));
  PetscCall(ierr);
  if (fname != p->filename) PetscCall(PetscStrncpy(p->filename, fname, sizeof(p->filename)));
  PetscCall(PetscObjectChangeTypeName((PetscObject)p, HYLCPATTERNFILE));
  p->setupcalled = PETSC_TRUE;
  PetscCall(PetscLogEventEnd(HYLC_PatternLoad, p, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcPatternWrite - Writes the pattern as .pyp with %.17g, so that reading it back gives the same
  numbers bit for bit. Edge row k is the edge into vertex k (as in the paper's files). Collective;
  rank 0 writes.
@*/
PetscErrorCode HylcPatternWrite(HylcPattern p, const char fname[])
{
  MPI_Comm       comm = PetscObjectComm((PetscObject)p);
  PetscMPIInt    rank;
  PetscErrorCode code                      = 0;
  char           msg[HYLC_PATTERN_MSG_LEN] = "";

  PetscFunctionBegin;
  PetscValidHeaderSpecific(p, HYLC_PATTERN_CLASSID, 1);
  PetscCheck(p->hasdata, comm, PETSC_ERR_ARG_WRONGSTATE, "Pattern has no data to write");
  PetscCall(PetscLogEventBegin(HYLC_PatternWrite, p, 0, 0, 0));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    FILE          *fp = NULL;
    const PetscInt n  = p->nv;
    char           tmp[PETSC_MAX_PATH_LEN + 16];
    /* a unique temporary beside fname, renamed onto it once complete: a full disk leaves no partial file */
    PetscCall(PetscPushErrorHandler(HylcPatternKeepMessage_Private, msg));
    code = HylcFileOpenTemp(fname, tmp, sizeof(tmp), &fp);
    if (!code) {
      /* the tile's state in the header's comment, which every reader skips; a pattern read without the
         record was taken as its own reference state, and is written as one */
      fprintf(fp, "*pattern # px py radius num_vertedges; hylc state: %s\n%.17g %.17g %.17g %d\n\n",
              p->state == HYLC_PATTERN_STATE_GENERATED     ? "generated (not a reference state: hylc-sample computes one)"
              : p->state == HYLC_PATTERN_STATE_EQUILIBRIUM ? "equilibrium (a solved tile under a strain, not a reference state)"
                                                           : "reference",
              (double)p->px, (double)p->py, (double)p->radius, (int)n);
      fprintf(fp, "*Q # dofs: x y z t\n");
      for (PetscInt v = 0; v < n; v++) fprintf(fp, "%.17g %.17g %.17g %.17g\n", (double)p->X[3 * v], (double)p->X[3 * v + 1], (double)p->X[3 * v + 2], (double)p->theta[v]);
      fprintf(fp, "\n*E # edges: v0 v1 dx dy\n");
      for (PetscInt v = 0; v < n; v++) {
        const PetscInt u = p->prev[v];
        fprintf(fp, "%d %d %d %d\n", (int)u, (int)v, (int)p->shift[2 * u], (int)p->shift[2 * u + 1]);
      }
      fprintf(fp, "\n*RL # rest lengths\n");
      for (PetscInt v = 0; v < n; v++) fprintf(fp, "%.17g\n", (double)p->restLength[v]);
      fprintf(fp, "\n*RK # rest kappas\n");
      for (PetscInt v = 0; v < n; v++) fprintf(fp, "%.17g %.17g\n", (double)p->restKappa[2 * v], (double)p->restKappa[2 * v + 1]);
      fprintf(fp, "\n*RT # rest twists\n");
      for (PetscInt v = 0; v < n; v++) fprintf(fp, "%.17g\n", (double)p->restTwist[v]);
      fprintf(fp, "\n*RefD1 # reference directors\n");
      for (PetscInt v = 0; v < n; v++) fprintf(fp, "%.17g %.17g %.17g\n", (double)p->refD1[3 * v], (double)p->refD1[3 * v + 1], (double)p->refD1[3 * v + 2]);
      fprintf(fp, "\n*RefT # reference twists\n");
      for (PetscInt v = 0; v < n; v++) fprintf(fp, "%.17g\n", (double)p->refTwist[v]);
      code = HylcFileCommitTemp(&fp, tmp, fname);
    }
    PetscCall(PetscPopErrorHandler());
  }
  PetscCall(HylcPatternRaiseFromRank0_Private(comm, code, msg));
  PetscCall(PetscLogEventEnd(HYLC_PatternWrite, p, 0, 0, 0));
  PetscFunctionReturn(PETSC_SUCCESS);
}
