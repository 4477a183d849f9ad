/* The one reader of user tables (src/sys/table.c) and the registry of a program's files (src/sys/files.c):
   - text: comments, blank lines, blank- or comma-separated fields, a line of 100 000 characters, a CRLF
     file and a CSV header in any order with extra columns are read with the right numbers and lines;
     an empty field, a wrong field count, 'nan', '1e999', a NUL byte and each strain outside the domain
     are refused naming the file, line and column;
   - HDF5: /strain read with its rows; a group, a string dataset, a wrong shape, a dataset declaring more
     rows than the file stores are refused naming the dataset, before anything is allocated;
   - the registry: an output equal to an input (by another spelling, a hard link), two outputs that do
     not exist yet with the same directory and name, a dangling link to another output, and an output
     over the path limits are refused; distinct files pass.
   hylc-test: nprocs=1 */
#include <hylc/table.h>
#include <hylc/files.h>
#include <hylc/private/h5util.h>
#include "hylctest.h"
#include <string.h>
#include <stdlib.h>
#include <unistd.h>
#include <sys/stat.h>

static const HylcTableSpec Strain7 = {HYLC_TABLE_NUMBERS, 7, HylcTableStrainNames, PETSC_TRUE};
static const HylcTableSpec Csv7    = {HYLC_TABLE_CSV, 7, HylcTableStrainNames, PETSC_TRUE};
static const HylcTableSpec Strain6 = {HYLC_TABLE_NUMBERS, 6, HylcTableStrainNames, PETSC_TRUE};

static int ErrorMentions(PetscErrorCode ierr, const char *s)
{
  char *msg = NULL;
  PetscErrorMessage(ierr, NULL, &msg);
  if (!(msg && strstr(msg, s))) fprintf(stderr, "  message: %s\n", msg ? msg : "(none)");
  return msg && strstr(msg, s) != NULL;
}

/* writes len bytes of text (0: strlen(text)) */
static void Write(const char path[], const char text[], size_t len)
{
  FILE *fp = fopen(path, "wb");
  if (!len) len = strlen(text);
  if (fp) {
    fwrite(text, 1, len, fp);
    fclose(fp);
  }
}

/* the text is refused with a message containing want */
static PetscErrorCode Refused(const char text[], size_t len, const HylcTableSpec *spec, const char want[])
{
  HylcTable      T;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  Write("t.txt", text, len);
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcTableReadText("t.txt", "-opt", spec, &T);
  PetscCall(PetscPopErrorHandler());
  HYLC_CHECK(ierr && ErrorMentions(ierr, want) && T.n == 0 && !T.v, "'%.40s' refused with '%s' (%d)", text, want, (int)ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestText(void)
{
  HylcTable T;
  char     *big;
  size_t    n = 100000;

  PetscFunctionBegin;
  /* blanks, commas, comments (also after the numbers), blank lines, CRLF */
  Write("a.txt", "# a comment\n\n0.1 0 -0.2 10 0 -5 1.5\r\n 0,0.5,0, 0 ,1,0, 2 # trailing\n\t-0.5\t0\t0\t0\t0\t0\t3e-1\n", 0);
  PetscCall(HylcTableReadText("a.txt", NULL, &Strain7, &T));
  HYLC_CHECK(T.n == 3 && T.ncol == 7, "3 rows of 7, got %d of %d", (int)T.n, (int)T.ncol);
  if (T.n == 3) {
    HYLC_CHECK(T.line[0] == 3 && T.line[1] == 4 && T.line[2] == 5, "lines %d %d %d", (int)T.line[0], (int)T.line[1], (int)T.line[2]);
    HYLC_CHECK(T.v[0] == 0.1 && T.v[2] == -0.2 && T.v[3] == 10 && T.v[6] == 1.5, "row 1");
    HYLC_CHECK(T.v[8] == 0.5 && T.v[11] == 1 && T.v[13] == 2, "row 2");
    HYLC_CHECK(T.v[14] == -0.5 && T.v[20] == 0.3, "row 3");
  }
  PetscCall(HylcTableDestroy(&T));
  /* a comment of 100 000 characters ending in numbers is one comment, not a row; a row after it */
  big = (char *)malloc(n + 64);
  memset(big, 'x', n);
  big[0] = '#';
  strcpy(big + n, "0.1 0 0 0 0 0\n0.2 0 0 0 0 0\n");
  Write("b.txt", big, strlen(big));
  PetscCall(HylcTableReadText("b.txt", NULL, &Strain6, &T));
  HYLC_CHECK(T.n == 1 && T.line[0] == 2 && T.v[0] == 0.2, "a long comment: %d rows", (int)T.n);
  PetscCall(HylcTableDestroy(&T));
  /* a row of 100 000 characters (blanks) is read */
  memset(big, ' ', n);
  strcpy(big + n, "0.3 0 0 0 0 0\n");
  Write("c.txt", big, strlen(big));
  PetscCall(HylcTableReadText("c.txt", NULL, &Strain6, &T));
  HYLC_CHECK(T.n == 1 && T.v[0] == 0.3, "a long row: %d rows", (int)T.n);
  PetscCall(HylcTableDestroy(&T));
  free(big);
  /* CSV: columns in any order, names ignoring case, an extra column, a UTF-8 byte-order mark */
  Write("d.csv", "\xEF\xBB\xBFpsi, SX,sa,sy,II00,note,II01,II11\n2,0.1,0,0,0,7,0,0\n3,0.2,0.1,0,0,8,0,0\n", 0);
  PetscCall(HylcTableReadText("d.csv", NULL, &Csv7, &T));
  HYLC_CHECK(T.n == 2 && T.v[0] == 0.1 && T.v[6] == 2 && T.v[7] == 0.2 && T.v[8] == 0.1 && T.v[13] == 3 && T.line[1] == 3, "CSV: %d rows", (int)T.n);
  PetscCall(HylcTableDestroy(&T));

  PetscCall(Refused("0,,0,0,0,0,1\n", 0, &Strain7, "t.txt:1: column 2 (sa): empty field"));
  PetscCall(Refused("0 0 0 0 0 0\n", 0, &Strain7, "t.txt:1: 6 fields, expected 7"));
  PetscCall(Refused("0 0 0 0 0 0 1 2\n", 0, &Strain7, "t.txt:1: 8 fields, expected 7"));
  PetscCall(Refused("0 0 0 0 0 0 1\nnan 0 0 0 0 0 5\n", 0, &Strain7, "t.txt:2: column 1 (sx): 'nan' is not a finite number"));
  PetscCall(Refused("0 0 0 0 0 0 1e999\n", 0, &Strain7, "t.txt:1: column 7 (psi): '1e999' is not a finite number"));
  PetscCall(Refused("0 0 0 0 0 0 1x\n", 0, &Strain7, "column 7 (psi): '1x' is not a number"));
  PetscCall(Refused("-1 0 0 0 0 0 1\n", 0, &Strain7, "t.txt:1: column 1 (sx) = -1: the stretch factor 1 + sx must be positive"));
  PetscCall(Refused("0 0 -2 0 0 0 1\n", 0, &Strain7, "column 3 (sy) = -2: the stretch factor 1 + sy must be positive"));
  PetscCall(Refused("0 1 0 0 0 0 1\n", 0, &Strain7, "column 2 (sa) = 1: |sa| must be below 1"));
  PetscCall(Refused("0 0 0 0 0 0 1\n0 0\0 0 0 0 1\n", 28, &Strain7, "t.txt:2: a NUL byte"));
  PetscCall(Refused("sx,sa,sy,II00,II11,psi\n", 0, &Csv7, "t.txt:1: the header has no column 'II01'"));
  PetscCall(Refused("sx,sa,sy,II00,II01,II11,psi,sx\n", 0, &Csv7, "the header names column 'sx' twice"));
  PetscCall(Refused("sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0\n", 0, &Csv7, "t.txt:2: 6 fields, the header (line 1) has 7"));
  PetscCall(Refused("sx,sa,sy,II00,II01,II11,psi\n0,0,0,0,0,0,\n", 0, &Csv7, "t.txt:2: field 7: empty field"));
  PetscCall(Refused("sx,sa,sy,II00,II01,II11,psi\n0,-1.5,0,0,0,0,1\n", 0, &Csv7, "t.txt:2: column 2 (sa) = -1.5"));
  PetscCall(Refused("# nothing\n", 0, &Csv7, "t.txt: empty CSV"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* an HDF5 file with /strain built by fn */
static PetscErrorCode H5Refused(const char path[], const char want[])
{
  static const char *const sets[] = {"strain", "samples/strain", NULL};
  HylcTable                T;
  PetscErrorCode           ierr;

  PetscFunctionBegin;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcTableReadHDF5(path, "-eval_input", sets, &Strain6, &T);
  PetscCall(PetscPopErrorHandler());
  HYLC_CHECK(ierr && ErrorMentions(ierr, want) && !T.v, "%s refused with '%s' (%d)", path, want, (int)ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestHDF5(void)
{
  static const char *const sets[]  = {"strain", "samples/strain", NULL};
  double                   z[3][6] = {{0.1, 0, 0, 0, 0, 0}, {0, 0.2, 0, 10, 0, 0}, {0, 0, -0.3, 0, 0, 5}};
  hsize_t                  d2[2]   = {3, 6};
  hid_t                    f, s, d, p, t;
  HylcTable                T;

  PetscFunctionBegin;
  f = H5Fcreate("s.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  HYLC_CHECK(HylcH5WriteDataset(f, "strain", 2, d2, H5T_NATIVE_DOUBLE, z, NULL, NULL) >= 0, "write");
  H5Fclose(f);
  PetscCall(HylcTableReadHDF5("s.h5", NULL, sets, &Strain6, &T));
  HYLC_CHECK(T.n == 3 && T.v[0] == 0.1 && T.v[7] == 0.2 && T.v[9] == 10 && T.v[14] == -0.3 && T.v[17] == 5 && T.line[2] == 2, "HDF5: %d rows", (int)T.n);
  PetscCall(HylcTableDestroy(&T));
  PetscCall(HylcTableReadStrainFile("s.h5", NULL, &T)); /* recognized by content */
  HYLC_CHECK(T.n == 3, "by content: %d rows", (int)T.n);
  PetscCall(HylcTableDestroy(&T));
  /* a group named strain */
  f = H5Fcreate("g.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Gclose(H5Gcreate2(f, "strain", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  H5Fclose(f);
  PetscCall(H5Refused("g.h5", "g.h5 (-eval_input): /strain is a group, not a dataset"));
  /* strings */
  f = H5Fcreate("str.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, 4);
  s = H5Screate_simple(2, d2, NULL);
  d = H5Dcreate2(f, "strain", t, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dclose(d);
  H5Sclose(s);
  H5Tclose(t);
  H5Fclose(f);
  PetscCall(H5Refused("str.h5", "dataset /strain holds strings, expected numbers"));
  /* (3, 5) */
  f     = H5Fcreate("shape.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  d2[1] = 5;
  HYLC_CHECK(HylcH5WriteDataset(f, "strain", 2, d2, H5T_NATIVE_DOUBLE, z, NULL, NULL) >= 0, "write");
  d2[1] = 6;
  H5Fclose(f);
  PetscCall(H5Refused("shape.h5", "dataset /strain has shape (3 x 5), expected (N x 6)"));
  /* chunked, declared 1e9 x 6, nothing stored */
  {
    hsize_t big[2] = {1000000000, 6}, chunk[2] = {100, 6};
    f = H5Fcreate("huge.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    s = H5Screate_simple(2, big, NULL);
    p = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(p, 2, chunk);
    d = H5Dcreate2(f, "strain", H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, p, H5P_DEFAULT);
    H5Dclose(d);
    H5Pclose(p);
    H5Sclose(s);
    H5Fclose(f);
  }
  PetscCall(H5Refused("huge.h5", "dataset /strain declares 6000000000 values (48000000000 bytes) but the file stores 0 bytes"));
  /* a NaN and a strain out of the domain, by row and column */
  z[1][2] = NAN;
  f       = H5Fcreate("nan.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  HYLC_CHECK(HylcH5WriteDataset(f, "strain", 2, d2, H5T_NATIVE_DOUBLE, z, NULL, NULL) >= 0, "write");
  H5Fclose(f);
  PetscCall(H5Refused("nan.h5", "nan.h5: dataset /strain row 1, column 3 (sy): nan is not finite"));
  z[1][2] = 0;
  z[2][1] = -1;
  f       = H5Fcreate("dom.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  HYLC_CHECK(HylcH5WriteDataset(f, "strain", 2, d2, H5T_NATIVE_DOUBLE, z, NULL, NULL) >= 0, "write");
  H5Fclose(f);
  PetscCall(H5Refused("dom.h5", "dataset /strain row 2, column 2 (sa) = -1: |sa| must be below 1"));
  f = H5Fcreate("none.h5", H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  H5Fclose(f);
  PetscCall(H5Refused("none.h5", "none.h5 (-eval_input): no dataset /strain or /samples/strain"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* the registry refuses (want in the message) or accepts (want NULL) these files */
static PetscErrorCode Files(const char *const spec[], const char want[])
{
  HylcFiles      files;
  PetscErrorCode ierr;

  PetscFunctionBegin;
  PetscCall(HylcFilesCreate(PETSC_COMM_SELF, &files));
  for (int i = 0; spec[i]; i += 3) PetscCall(HylcFilesAdd(files, spec[i][0] == 'o' ? HYLC_FILE_OUTPUT : spec[i][0] == 'i' ? HYLC_FILE_INPUT : HYLC_FILE_INPUT_OPTIONAL, spec[i + 1], spec[i + 2]));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = HylcFilesCheck(files);
  PetscCall(PetscPopErrorHandler());
  PetscCall(HylcFilesDestroy(&files));
  if (want)
    HYLC_CHECK(ierr && ErrorMentions(ierr, want), "%s %s refused with '%s' (%d)", spec[1], spec[4] ? spec[4] : "", want, (int)ierr);
  else
    HYLC_CHECK(!ierr, "%s %s accepted (%d)", spec[1], spec[4] ? spec[4] : "", (int)ierr);
  PetscFunctionReturn(PETSC_SUCCESS);
}

static PetscErrorCode TestFiles(void)
{
  char longname[300], longpath[5000];

  PetscFunctionBegin;
  Write("in.txt", "x\n", 0);
  mkdir("sub", 0755);
  unlink("hard.txt");
  HYLC_CHECK(link("in.txt", "hard.txt") == 0, "hard link");
  unlink("sub/dangling");
  HYLC_CHECK(symlink("../new.out", "sub/dangling") == 0, "symlink");
  PetscCall(Files((const char *const[]){"i", "in.txt", "-a", "o", "out.txt", "-b", "o", "out2.txt", "-c", NULL}, NULL));
  PetscCall(Files((const char *const[]){"i", "in.txt", "-a", "o", "./sub/../in.txt", "-b", NULL}, "Output ./sub/../in.txt (-b) is the input in.txt (-a)"));
  PetscCall(Files((const char *const[]){"i", "in.txt", "-a", "o", "hard.txt", "-b", NULL}, "Output hard.txt (-b) is the input in.txt (-a)"));
  PetscCall(Files((const char *const[]){"o", "new.out", "-a", "o", "sub/../new.out", "-b", NULL}, "-a and -b name the same file (new.out, sub/../new.out)"));
  PetscCall(Files((const char *const[]){"o", "new.out", "-a", "o", "sub/dangling", "-b", NULL}, "-a and -b name the same file"));
  PetscCall(Files((const char *const[]){"o", "x.out", "-a", "o", "x.out", "-b", NULL}, "-a and -b name the same file x.out"));
  PetscCall(Files((const char *const[]){"?", "missing.txt", "-a", "o", "missing.txt", "-b", NULL}, "Output missing.txt (-b) is the input missing.txt (-a)"));
  PetscCall(Files((const char *const[]){"?", "missing.txt", "-a", "o", "other.txt", "-b", NULL}, NULL));
  PetscCall(Files((const char *const[]){"i", "missing.txt", "-a", NULL}, "Cannot open missing.txt (-a)"));
  PetscCall(Files((const char *const[]){"o", "nodir/x", "-a", NULL}, "directory nodir does not exist"));
  PetscCall(Files((const char *const[]){"o", "sub", "-a", NULL}, "it is a directory"));
  memset(longname, 'n', 250);
  longname[250] = 0;
  PetscCall(Files((const char *const[]){"o", longname, "-a", NULL}, "has 250 characters, over the limit of 244"));
  PetscCall(Files((const char *const[]){"i", longname, "-a", NULL}, "Cannot open"));
  for (int i = 0; i < 4900; i += 2) longpath[i] = 'd', longpath[i + 1] = '/';
  strcpy(longpath + 4900, "x");
  PetscCall(Files((const char *const[]){"o", longpath, "-a", NULL}, "-a: the path has 4901 characters, over the limit of 4084"));
  PetscFunctionReturn(PETSC_SUCCESS);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(TestText());
  PetscCall(TestHDF5());
  PetscCall(TestFiles());
  PetscCall(PetscFinalize());
  return HYLC_TEST_RESULT();
}
