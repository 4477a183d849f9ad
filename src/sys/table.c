/* The one reader of user tables of strains and energies (include/hylc/table.h): text (CSV with a header,
   or rows of numbers) and HDF5 datasets, every value checked where it is read and every problem one line
   naming the file, line (dataset, row) and column. */
#include <hylc/table.h>
#include <hylc/private/h5util.h>
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* " (-option)" or "" */
static void OptionText(const char option[], char buf[], size_t len)
{
  if (option && option[0])
    snprintf(buf, len, " (%s)", option);
  else if (len)
    buf[0] = 0;
}

const char *HylcStrainDomainError(const PetscReal z[6], int *comp)
{
  for (int k = 0; k < 6; k++)
    if (!isfinite((double)z[k])) {
      *comp = k;
      return "is not finite";
    }
  if (!(1 + z[0] > 0)) {
    *comp = 0;
    return "the stretch factor 1 + sx must be positive";
  }
  if (!(1 + z[2] > 0)) {
    *comp = 2;
    return "the stretch factor 1 + sy must be positive";
  }
  if (!(PetscAbsReal(z[1]) < 1)) {
    *comp = 1;
    return "|sa| must be below 1 (sa is the cosine of the angle between the deformed material axes)";
  }
  return NULL;
}

/*@C
  HylcTableDestroy - Frees the rows of a table and empties it (accepts an empty table).

  Not collective

  Input Parameter:
. t - the table

  Level: developer
@*/
PetscErrorCode HylcTableDestroy(HylcTable *t)
{
  PetscFunctionBegin;
  PetscCall(PetscFree(t->v));
  PetscCall(PetscFree(t->line));
  t->n = t->ncol = 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* room for one more row (capacity doubled; the counts stay within PetscInt) */
static PetscErrorCode TableGrow(HylcTable *t, PetscInt *cap, const char path[])
{
  PetscFunctionBegin;
  if (t->n < *cap) PetscFunctionReturn(PETSC_SUCCESS);
  PetscCheck(*cap <= PETSC_MAX_INT / 2 / t->ncol, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: more than %" PetscInt_FMT " rows", path, *cap);
  *cap = *cap ? 2 * *cap : 256;
  PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)(*cap) * (size_t)t->ncol, &t->v));
  PetscCall(PetscRealloc(sizeof(PetscInt) * (size_t)(*cap), &t->line));
  PetscFunctionReturn(PETSC_SUCCESS);
}

static int IsBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

static char *Trim(char *s)
{
  char *e;
  while (IsBlank(*s)) s++;
  e = s + strlen(s);
  while (e > s && IsBlank(e[-1])) *--e = 0;
  return s;
}

/* the fields of a line (in place): split at commas when it has one (each field trimmed, an empty one
   kept), else at runs of blanks; at most max kept, *n counts all */
static void SplitFields(char *s, char *f[], int max, int *n)
{
  *n = 0;
  if (strchr(s, ',')) {
    for (;;) {
      char *c = strchr(s, ',');
      if (c) *c = 0;
      if (*n < max) f[*n] = Trim(s);
      (*n)++;
      if (!c) break;
      s = c + 1;
    }
  } else {
    for (;;) {
      while (IsBlank(*s)) s++;
      if (!*s) break;
      if (*n < max) f[*n] = s;
      (*n)++;
      while (*s && !IsBlank(*s)) s++;
      if (*s) *s++ = 0;
    }
  }
}

/* a field as one finite number (strtod's syntax, the whole field), or a reason */
static const char *ParseNumber(const char *s, PetscReal *v)
{
  char  *end;
  double x;

  if (!*s) return "empty field";
  errno = 0;
  x     = strtod(s, &end);
  if (end == s || *end) return "is not a number";
  if (!isfinite(x)) return "is not a finite number";
  *v = (PetscReal)x; /* a subnormal value (ERANGE on underflow) is a finite number */
  return NULL;
}

typedef struct {
  const HylcTableSpec *spec;
  const char          *path;
  HylcTable           *t;
  PetscInt             cap;
  int                  header;                 /* CSV: the header has been read */
  long                 hline;                  /* its line */
  int                  nfields;                /* its number of fields */
  int                  col[HYLC_TABLE_MAXCOL]; /* CSV: the field of each column */
} TextReader;

/* a short form of a token for messages */
static void Shorten(const char *s, char buf[48])
{
  size_t n = strlen(s);
  if (n <= 40)
    snprintf(buf, 48, "%s", s);
  else
    snprintf(buf, 48, "%.36s...", s);
}

static PetscErrorCode ReadHeader(TextReader *r, char *s, long ln)
{
  const HylcTableSpec *spec = r->spec;
  char                *f[1024];
  int                  nf;

  PetscFunctionBegin;
  SplitFields(s, f, 1024, &nf);
  PetscCheck(nf <= 1024, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: the header has %d fields, at most 1024", r->path, ln, nf);
  for (int i = 0; i < spec->ncol; i++) r->col[i] = -1;
  for (int k = 0; k < nf; k++) {
    char  *name = f[k];
    size_t len  = strlen(name);
    if (len >= 2 && name[0] == '"' && name[len - 1] == '"') {
      name[len - 1] = 0;
      name          = Trim(name + 1);
    }
    for (int i = 0; i < spec->ncol; i++)
      if (!strcasecmp(name, spec->names[i])) {
        PetscCheck(r->col[i] < 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: the header names column '%s' twice (fields %d and %d)", r->path, ln, spec->names[i], r->col[i] + 1, k + 1);
        r->col[i] = k;
      }
  }
  for (int i = 0; i < spec->ncol; i++) {
    if (r->col[i] >= 0) continue;
    char need[256] = "";
    for (int j = 0; j < spec->ncol; j++) snprintf(need + strlen(need), sizeof(need) - strlen(need), "%s%s", j ? "," : "", spec->names[j]);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: the header has no column '%s' (needs %s)", r->path, ln, spec->names[i], need);
  }
  r->header  = 1;
  r->hline   = ln;
  r->nfields = nf;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* a field that is not one finite number: one line naming the file, line and column */
static PetscErrorCode FieldError(const TextReader *r, long ln, int field, const char name[], const char *text, const char *why)
{
  char tok[48];

  PetscFunctionBegin;
  Shorten(text, tok);
  if (!*text) SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: column %d (%s): empty field", r->path, ln, field + 1, name);
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: column %d (%s): '%s' %s", r->path, ln, field + 1, name, tok, why);
}

/* one line of text: a comment, blank, the header or a row */
static PetscErrorCode ReadLine(TextReader *r, char *s, size_t len, long ln)
{
  const HylcTableSpec *spec = r->spec;
  HylcTable           *t    = r->t;
  char                *f[1025], *hash;
  int                  nf, field[HYLC_TABLE_MAXCOL];
  PetscReal            v[HYLC_TABLE_MAXCOL];

  PetscFunctionBegin;
  PetscCheck(!memchr(s, 0, len), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: a NUL byte (not a text file)", r->path, ln);
  if (ln == 1 && len >= 3 && !memcmp(s, "\xEF\xBB\xBF", 3)) s += 3; /* a UTF-8 byte-order mark */
  if ((hash = strchr(s, '#'))) *hash = 0;
  s[strcspn(s, "\n")] = 0;
  s                   = Trim(s);
  if (!*s) PetscFunctionReturn(PETSC_SUCCESS);
  if (spec->layout == HYLC_TABLE_CSV && !r->header) {
    PetscCall(ReadHeader(r, s, ln));
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  if (spec->layout == HYLC_TABLE_CSV) {
    /* as many fields as the header, none empty (also of the columns not read) */
    SplitFields(s, f, 1025, &nf);
    PetscCheck(nf == r->nfields, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: %d fields, the header (line %ld) has %d", r->path, ln, nf, r->hline, r->nfields);
    for (int k = 0; k < nf; k++) PetscCheck(*f[k], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: field %d: empty field", r->path, ln, k + 1);
    for (int i = 0; i < spec->ncol; i++) field[i] = r->col[i];
  } else {
    SplitFields(s, f, HYLC_TABLE_MAXCOL + 1, &nf);
    for (int i = 0; i < spec->ncol; i++) field[i] = i;
  }
  for (int i = 0; i < spec->ncol && field[i] < nf; i++) {
    const char *why = ParseNumber(f[field[i]], &v[i]);
    if (why) PetscCall(FieldError(r, ln, field[i], spec->names[i], f[field[i]], why));
  }
  if (nf != spec->ncol && spec->layout == HYLC_TABLE_NUMBERS) {
    char need[256] = "";
    for (int j = 0; j < spec->ncol; j++) snprintf(need + strlen(need), sizeof(need) - strlen(need), "%s%s", j ? " " : "", spec->names[j]);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: %d fields, expected %d (%s)", r->path, ln, nf, spec->ncol, need);
  }
  if (spec->strain) {
    int         c;
    const char *why = HylcStrainDomainError(v, &c);
    if (why) {
      char num[32];
      snprintf(num, sizeof(num), "%.15g", (double)v[c]);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s:%ld: column %d (%s) = %s: %s", r->path, ln, field[c] + 1, spec->names[c], num, why);
    }
  }
  PetscCheck(ln <= PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s:%ld: too many lines", r->path, ln);
  PetscCall(TableGrow(t, &r->cap, r->path));
  for (int i = 0; i < spec->ncol; i++) t->v[t->n * spec->ncol + i] = v[i];
  t->line[t->n++] = (PetscInt)ln;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTableReadStream - Reads a text table from an open stream (include/hylc/table.h).

  Not collective

  Input Parameters:
+ fp   - the stream (read to its end, not closed)
. path - the file's name for the messages
- spec - what the table holds

  Output Parameter:
. t - the rows (free with HylcTableDestroy()); empty on an error

  Level: developer
@*/
PetscErrorCode HylcTableReadStream(FILE *fp, const char path[], const HylcTableSpec *spec, HylcTable *t)
{
  TextReader     r;
  char          *buf = NULL;
  size_t         cap = 0;
  ssize_t        len;
  long           ln   = 0;
  PetscErrorCode ierr = PETSC_SUCCESS;

  PetscFunctionBegin;
  PetscCheck(spec->ncol >= 1 && spec->ncol <= HYLC_TABLE_MAXCOL && (!spec->strain || spec->ncol >= 6), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Table of %d columns", spec->ncol);
  PetscCall(PetscMemzero(t, sizeof(*t)));
  PetscCall(PetscMemzero(&r, sizeof(r)));
  t->ncol = spec->ncol;
  r.spec  = spec;
  r.path  = path;
  r.t     = t;
  while (!ierr && (len = getline(&buf, &cap, fp)) >= 0) ierr = ReadLine(&r, buf, (size_t)len, ++ln);
  free(buf);
  if (!ierr && ferror(fp)) {
    ierr = PETSC_ERR_FILE_READ;
    (void)PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, ierr, PETSC_ERROR_INITIAL, "Cannot read %s: %s", path, strerror(errno));
  }
  if (!ierr && spec->layout == HYLC_TABLE_CSV && !r.header) {
    char need[256] = "";
    for (int j = 0; j < spec->ncol; j++) snprintf(need + strlen(need), sizeof(need) - strlen(need), "%s%s", j ? "," : "", spec->names[j]);
    ierr = PETSC_ERR_FILE_UNEXPECTED;
    (void)PetscError(PETSC_COMM_SELF, __LINE__, PETSC_FUNCTION_NAME, __FILE__, ierr, PETSC_ERROR_INITIAL, "%s: empty CSV (needs a header %s and rows)", path, need);
  }
  if (ierr) PetscCall(HylcTableDestroy(t));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTableReadText - Reads a text table (include/hylc/table.h) from the file path, which must be a
  readable regular file.

  Not collective

  Input Parameters:
+ path   - the file
. option - the option that named it (for the messages), or NULL
- spec   - what the table holds

  Output Parameter:
. t - the rows (free with HylcTableDestroy())

  Level: developer
@*/
PetscErrorCode HylcTableReadText(const char path[], const char option[], const HylcTableSpec *spec, HylcTable *t)
{
  FILE          *fp;
  PetscErrorCode ierr;
  char           w[PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  PetscCall(PetscMemzero(t, sizeof(*t)));
  PetscCall(HylcFileCheckInput(PETSC_COMM_SELF, path, option));
  OptionText(option, w, sizeof(w));
  fp = fopen(path, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open %s%s: %s", path, w, strerror(errno));
  ierr = HylcTableReadStream(fp, path, spec, t);
  fclose(fp);
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* ---- HDF5 ---- */

/* the kind of the object name (H5I_GROUP, H5I_DATASET, ...; H5I_BADID if it cannot be opened) */
static H5I_type_t ObjectType(hid_t loc, const char name[])
{
  hid_t      o = H5Oopen(loc, name, H5P_DEFAULT);
  H5I_type_t t = o >= 0 ? H5Iget_type(o) : H5I_BADID;
  if (o >= 0) H5Oclose(o);
  return t;
}

/* whether the object name (a path of links, relative to loc) exists: each link in turn, so that a missing
   or non-group intermediate is "no" and not an HDF5 error */
static int LinkExists(hid_t loc, const char name[])
{
  char   part[256];
  size_t at = 0, n = strlen(name);

  if (n >= sizeof(part)) return 0;
  while (at < n) {
    const char *slash = strchr(name + at, '/');
    size_t      end   = slash ? (size_t)(slash - name) : n;
    memcpy(part, name, end);
    part[end] = 0;
    if (H5Lexists(loc, part, H5P_DEFAULT) <= 0) return 0;
    if (slash && ObjectType(loc, part) != H5I_GROUP) return 0;
    at = end + 1;
  }
  return 1;
}

static const char *ClassName(H5T_class_t c)
{
  switch (c) {
  case H5T_INTEGER:
    return "integers";
  case H5T_FLOAT:
    return "floating-point numbers";
  case H5T_STRING:
    return "strings";
  case H5T_COMPOUND:
    return "compound records";
  case H5T_ENUM:
    return "enumerated values";
  case H5T_ARRAY:
    return "arrays";
  case H5T_VLEN:
    return "variable-length sequences";
  case H5T_REFERENCE:
    return "references";
  default:
    return "values of another type";
  }
}

/* checks one dataset (msg empty if good): *rows its rows; first: the dataset whose N rows it must have (NULL: any) */
static void CheckColumn(hid_t file, const char path[], const char w[], const char name[], int cols, H5T_class_t cls, const char first[], hsize_t N, hsize_t *rows, char msg[], size_t len)
{
  hid_t       d = -1, sp = -1, ty = -1, pl = -1;
  hsize_t     dims[H5S_MAX_RANK];
  int         rank = -1;
  H5I_type_t  kind;
  H5T_class_t c;

  msg[0] = 0;
  *rows  = 0;
  if (!LinkExists(file, name)) {
    snprintf(msg, len, "%s%s: no dataset /%s", path, w, name);
    return;
  }
  if ((kind = ObjectType(file, name)) != H5I_DATASET) {
    snprintf(msg, len, "%s%s: /%s is %s, not a dataset", path, w, name, kind == H5I_GROUP ? "a group" : kind == H5I_DATATYPE ? "a named type" : "an object that cannot be opened");
    return;
  }
  if ((d = H5Dopen2(file, name, H5P_DEFAULT)) < 0 || (sp = H5Dget_space(d)) < 0 || (ty = H5Dget_type(d)) < 0 || (pl = H5Dget_create_plist(d)) < 0) {
    snprintf(msg, len, "%s%s: cannot open dataset /%s", path, w, name);
    goto done;
  }
  rank = H5Sget_simple_extent_ndims(sp);
  if (rank < 0 || H5Sget_simple_extent_type(sp) != H5S_SIMPLE) rank = 0;
  if (rank > 0) H5Sget_simple_extent_dims(sp, dims, NULL);
  if (rank != (cols ? 2 : 1) || (first && dims[0] != N) || (cols && dims[1] != (hsize_t)cols)) {
    char shape[96] = "";
    for (int i = 0; i < rank && i < 4; i++) snprintf(shape + strlen(shape), sizeof(shape) - strlen(shape), "%s%llu", i ? " x " : "", (unsigned long long)dims[i]);
    if (rank > 4) snprintf(shape + strlen(shape), sizeof(shape) - strlen(shape), " x ...");
    if (cols)
      snprintf(msg, len, "%s%s: dataset /%s has shape (%s), expected (N x %d)%s%s", path, w, name, rank > 0 ? shape : "scalar", cols, first ? " with N the rows of /" : "", first ? first : "");
    else if (first)
      snprintf(msg, len, "%s%s: dataset /%s has shape (%s), expected (%llu): one row per row of /%s", path, w, name, rank > 0 ? shape : "scalar", (unsigned long long)N, first);
    else
      snprintf(msg, len, "%s%s: dataset /%s has shape (%s), expected a vector (N)", path, w, name, rank > 0 ? shape : "scalar");
    goto done;
  }
  c = H5Tget_class(ty);
  if (cls == H5T_NO_CLASS ? (c != H5T_FLOAT && c != H5T_INTEGER) : c != cls) {
    snprintf(msg, len, "%s%s: dataset /%s holds %s, expected %s", path, w, name, ClassName(c), cls == H5T_FLOAT ? "floating-point numbers" : cls == H5T_INTEGER ? "integers" : "numbers");
    goto done;
  }
  {
    /* the values it declares must be in the file: no external or virtual storage, and no more than an
       unfiltered dataset stores (or 1100 times what a filtered one stores: deflate's bound) */
    const size_t esize = H5Tget_size(ty);
    hsize_t      nval  = dims[0];
    const double bytes = (double)dims[0] * (cols ? cols : 1) * (double)esize;
    hsize_t      st    = H5Dget_storage_size(d);
    int          nfilt = H5Pget_nfilters(pl);
    if (cols) nval *= (hsize_t)cols;
    if (H5Pget_layout(pl) == H5D_VIRTUAL || H5Pget_external_count(pl) > 0) {
      snprintf(msg, len, "%s%s: dataset /%s is stored outside the file (external or virtual storage is not read)", path, w, name);
      goto done;
    }
    if (nval && (nfilt <= 0 ? bytes > (double)st : bytes > 1100.0 * (double)st + 4096)) {
      snprintf(msg, len, "%s%s: dataset /%s declares %llu values (%.0f bytes) but the file stores %llu bytes of it", path, w, name, (unsigned long long)nval, bytes, (unsigned long long)st);
      goto done;
    }
  }
  *rows = dims[0];
done:
  if (pl >= 0) H5Pclose(pl);
  if (ty >= 0) H5Tclose(ty);
  if (sp >= 0) H5Sclose(sp);
  if (d >= 0) H5Dclose(d);
}

/*@C
  HylcTableCheckHDF5Columns - Checks a group of datasets with one row per sample before any is read
  (include/hylc/table.h).

  Not collective

  Input Parameters:
+ file   - the open file
. path   - its name (messages)
. option - the option that named it (messages), or NULL
. group  - the group ("samples"), or NULL for the root
. n      - number of datasets
- cols   - the datasets; cols[0] gives N

  Output Parameter:
. N - the rows

  Level: developer
@*/
PetscErrorCode HylcTableCheckHDF5Columns(hid_t file, const char path[], const char option[], const char group[], int n, const HylcTableColumn cols[], hsize_t *N)
{
  HylcH5Quiet q;
  char        w[PETSC_MAX_PATH_LEN], msg[PETSC_MAX_PATH_LEN + 512] = "";
  hsize_t     rows = 0;

  PetscFunctionBegin;
  OptionText(option, w, sizeof(w));
  *N = 0;
  HylcH5QuietBegin(&q);
  if (group && group[0]) {
    H5I_type_t kind;
    if (!LinkExists(file, group))
      snprintf(msg, sizeof(msg), "%s%s: no group /%s", path, w, group);
    else if ((kind = ObjectType(file, group)) != H5I_GROUP)
      snprintf(msg, sizeof(msg), "%s%s: /%s is %s, not a group", path, w, group, kind == H5I_DATASET ? "a dataset" : "an object that cannot be opened");
  }
  for (int k = 0; k < n && !msg[0]; k++) {
    char name[256], first[256];
    snprintf(name, sizeof(name), "%s%s%s", group && group[0] ? group : "", group && group[0] ? "/" : "", cols[k].name);
    snprintf(first, sizeof(first), "%s%s%s", group && group[0] ? group : "", group && group[0] ? "/" : "", cols[0].name);
    if (cols[k].optional && !LinkExists(file, name)) continue;
    CheckColumn(file, path, w, name, cols[k].cols, cols[k].cls, k ? first : NULL, *N, &rows, msg, sizeof(msg));
    if (!k) *N = rows;
  }
  HylcH5QuietEnd(&q);
  PetscCheck(!msg[0], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s", msg);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTableReadHDF5Column - Reads a whole dataset checked by HylcTableCheckHDF5Columns().

  Not collective

  Input Parameters:
+ file    - the open file
. path    - its name (messages)
. name    - the dataset
- memtype - the memory type (H5T_NATIVE_DOUBLE, H5T_NATIVE_INT)

  Output Parameter:
. buf - the values

  Level: developer
@*/
PetscErrorCode HylcTableReadHDF5Column(hid_t file, const char path[], const char name[], hid_t memtype, void *buf)
{
  HylcH5Quiet q;
  hid_t       d;
  herr_t      e          = -1;
  char        h5msg[256] = "";

  PetscFunctionBegin;
  HylcH5QuietBegin(&q);
  d = H5Dopen2(file, name, H5P_DEFAULT);
  if (d >= 0) e = H5Dread(d, memtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
  if (e < 0) HylcH5ErrorText(h5msg);
  if (d >= 0) H5Dclose(d);
  HylcH5QuietEnd(&q);
  PetscCheck(e >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "Cannot read dataset /%s of %s%s", name, path, h5msg);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the body of HylcTableReadHDF5 on the open file: the first dataset of the list, checked, read, each row
   checked */
static PetscErrorCode ReadHDF5Table(hid_t file, const char path[], const char option[], const char *const datasets[], const HylcTableSpec *spec, HylcTable *t)
{
  const char     *name = NULL;
  char            w[PETSC_MAX_PATH_LEN], list[256] = "";
  hsize_t         N;
  HylcTableColumn col;
  HylcH5Quiet     q;

  PetscFunctionBegin;
  OptionText(option, w, sizeof(w));
  HylcH5QuietBegin(&q);
  for (int k = 0; datasets[k] && !name; k++)
    if (LinkExists(file, datasets[k])) name = datasets[k];
  HylcH5QuietEnd(&q);
  for (int k = 0; !name && datasets[k]; k++) snprintf(list + strlen(list), sizeof(list) - strlen(list), "%s/%s", k ? " or " : "", datasets[k]);
  PetscCheck(name, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s%s: no dataset %s", path, w, list);
  col.name     = name;
  col.cols     = spec->ncol;
  col.cls      = H5T_NO_CLASS;
  col.optional = PETSC_FALSE;
  PetscCall(HylcTableCheckHDF5Columns(file, path, option, NULL, 1, &col, &N));
  PetscCheck(N <= (hsize_t)(PETSC_MAX_INT / spec->ncol), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s%s: dataset /%s has %llu rows, more than this build reads", path, w, name, (unsigned long long)N);
  t->n    = (PetscInt)N;
  t->ncol = spec->ncol;
  PetscCall(PetscMalloc1((size_t)N * spec->ncol + 1, &t->v));
  PetscCall(PetscMalloc1((size_t)N + 1, &t->line));
  PetscCall(HylcTableReadHDF5Column(file, path, name, H5T_NATIVE_DOUBLE, t->v));
  for (PetscInt i = 0; i < t->n; i++) {
    const PetscReal *v = t->v + i * spec->ncol;
    t->line[i]         = i;
    char num[32]; /* C's %g: PETSc's appends '.' to integral values and nan */
    for (int c = 0; c < spec->ncol; c++) {
      snprintf(num, sizeof(num), "%g", (double)v[c]);
      PetscCheck(isfinite((double)v[c]), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: dataset /%s row %" PetscInt_FMT ", column %d (%s): %s is not finite", path, name, i, c + 1, spec->names[c], num);
    }
    if (spec->strain) {
      int         c;
      const char *why = HylcStrainDomainError(v, &c);
      if (why) snprintf(num, sizeof(num), "%.15g", (double)v[c]);
      PetscCheck(!why, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: dataset /%s row %" PetscInt_FMT ", column %d (%s) = %s: %s", path, name, i, c + 1, spec->names[c], num, why);
    }
  }
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTableReadHDF5 - Reads a table from a dataset of shape (N, ncol) of an HDF5 file: the first of the
  datasets listed that exists (include/hylc/table.h).

  Not collective

  Input Parameters:
+ path     - the file
. option   - the option that named it (messages), or NULL
. datasets - the names to try, NULL-terminated ("strain", "samples/strain")
- spec     - what the table holds (the layout is not used)

  Output Parameter:
. t - the rows (free with HylcTableDestroy()); line[i] = i

  Level: developer
@*/
PetscErrorCode HylcTableReadHDF5(const char path[], const char option[], const char *const datasets[], const HylcTableSpec *spec, HylcTable *t)
{
  HylcH5Quiet    q;
  hid_t          file;
  PetscErrorCode ierr;
  char           w[PETSC_MAX_PATH_LEN], h5msg[256] = "";

  PetscFunctionBegin;
  PetscCheck(spec->ncol >= 1 && spec->ncol <= HYLC_TABLE_MAXCOL && (!spec->strain || spec->ncol >= 6), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "Table of %d columns", spec->ncol);
  PetscCall(PetscMemzero(t, sizeof(*t)));
  PetscCall(HylcFileCheckInput(PETSC_COMM_SELF, path, option));
  OptionText(option, w, sizeof(w));
  HylcH5QuietBegin(&q);
  file = HylcH5FileOpen(path);
  if (file < 0) HylcH5ErrorText(h5msg);
  HylcH5QuietEnd(&q);
  PetscCheck(file >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open %s%s as HDF5%s", path, w, h5msg);
  ierr = ReadHDF5Table(file, path, option, datasets, spec, t);
  HylcH5QuietBegin(&q);
  H5Fclose(file);
  HylcH5QuietEnd(&q);
  if (ierr) PetscCall(HylcTableDestroy(t));
  PetscCall(ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcTableReadStrainFile - Reads strains (6 per row) from a file recognized by content: HDF5 (the
  dataset /strain or /samples/strain of shape (N, 6)) or text (6 numbers per line); every strain finite
  and in the domain (include/hylc/table.h). The reader of hylc-eval's -eval_input.

  Not collective

  Input Parameters:
+ path   - the file
- option - the option that named it (messages), or NULL

  Output Parameter:
. t - the rows (free with HylcTableDestroy())

  Level: developer
@*/
PetscErrorCode HylcTableReadStrainFile(const char path[], const char option[], HylcTable *t)
{
  static const char *const datasets[] = {"strain", "samples/strain", NULL};
  const HylcTableSpec      spec       = {HYLC_TABLE_NUMBERS, 6, HylcTableStrainNames, PETSC_TRUE};
  unsigned char            head[8]    = {0};
  size_t                   got        = 0;
  FILE                    *fp;
  char                     w[PETSC_MAX_PATH_LEN];

  PetscFunctionBegin;
  PetscCall(PetscMemzero(t, sizeof(*t)));
  PetscCall(HylcFileCheckInput(PETSC_COMM_SELF, path, option));
  OptionText(option, w, sizeof(w));
  fp = fopen(path, "rb");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "Cannot open %s%s: %s", path, w, strerror(errno));
  got = fread(head, 1, sizeof(head), fp);
  fclose(fp);
  if (got == sizeof(head) && !memcmp(head, "\211HDF\r\n\032\n", 8))
    PetscCall(HylcTableReadHDF5(path, option, datasets, &spec, t));
  else
    PetscCall(HylcTableReadText(path, option, &spec, t));
  PetscFunctionReturn(PETSC_SUCCESS);
}
