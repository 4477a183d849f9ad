/* -help of hylc programs: hylc's own options first, PETSc's after a header (issue 33). PETSc prints its
   banner and general options inside PetscInitialize() and each object's options as the program reads
   them, so the SNES and KSP options of the micro stage came between hylc's; with -help, HylcInitialize()
   keeps what PETSc prints to stdout (PetscVFPrintf) in a buffer, and HylcHelpFlush() prints it sorted: the
   program's description, the sections that hold hylc options (src/sys/programs.c), then a header and
   PETSc's sections in their order. */
#include <hylc/private/sysimpl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char  *HylcHelpText = NULL;
static size_t HylcHelpLen = 0, HylcHelpCap = 0;

/* PETSc prints help both through PetscHelpPrintf and with PetscFPrintf(stdout) (the "(one of)" lists of
   choices), both through PetscVFPrintf: what goes to stdout is kept, in order */
static PetscErrorCode (*HylcVFPrintfSaved)(FILE *, const char[], va_list) = NULL;

static PetscErrorCode HylcHelpVFPrintf(FILE *fd, const char format[], va_list ap)
{
  va_list aq;
  int     n;

  if (fd != stdout && fd != PETSC_STDOUT) return HylcVFPrintfSaved(fd, format, ap);
  va_copy(aq, ap);
  n = vsnprintf(NULL, 0, format, aq);
  va_end(aq);
  if (n < 0) return PETSC_SUCCESS;
  if (HylcHelpLen + (size_t)n + 1 > HylcHelpCap) {
    size_t cap = HylcHelpCap ? 2 * HylcHelpCap : 65536;
    char  *t;
    while (cap < HylcHelpLen + (size_t)n + 1) cap *= 2;
    t = (char *)realloc(HylcHelpText, cap);
    if (!t) { /* out of memory: what was kept, then the text as it comes */
      fwrite(HylcHelpText, 1, HylcHelpLen, fd);
      free(HylcHelpText);
      HylcHelpText = NULL;
      HylcHelpLen = HylcHelpCap = 0;
      PetscVFPrintf             = HylcVFPrintfSaved;
      return HylcVFPrintfSaved(fd, format, ap);
    }
    HylcHelpText = t;
    HylcHelpCap  = cap;
  }
  vsnprintf(HylcHelpText + HylcHelpLen, HylcHelpCap - HylcHelpLen, format, ap);
  HylcHelpLen += (size_t)n;
  return PETSC_SUCCESS;
}

/*@C
  HylcHelpCapture - Keeps what PETSc prints to stdout in a buffer when the arguments ask for -help (not for
  "-help intro", which PETSc prints and ends with). Called by HylcInitialize() before PetscInitialize();
  HylcHelpFlush() prints the buffer sorted. Not collective.

  Level: developer
@*/
void HylcHelpCapture(int argc, char **argv)
{
  for (int i = 1; i < argc; i++)
    if (!strcmp(argv[i], "-help") && !(i + 1 < argc && !strcmp(argv[i + 1], "intro"))) {
      HylcVFPrintfSaved = PetscVFPrintf;
      PetscVFPrintf     = HylcHelpVFPrintf;
      return;
    }
}

/* whether a section of PETSc's help (the text after a line of dashes) lists an option of a hylc stage */
static int HylcSectionIsHylc(const char *s, const char *end)
{
  while (s < end) {
    const char *eol = memchr(s, '\n', (size_t)(end - s)), *c = s;
    char        name[256];
    size_t      n = 0;
    if (!eol) eol = end;
    while (c < eol && *c == ' ') c++;
    if (c < eol && *c == '-') {
      c++;
      while (c < eol && n + 1 < sizeof(name) && *c != ' ' && *c != ':' && *c != '<') name[n++] = *c++;
      name[n] = 0;
      if (n && HylcOptionIsHylc_Private(name)) return 1;
    }
    s = eol + 1;
  }
  return 0;
}

/*@C
  HylcHelpFlush - Prints the help that HylcHelpCapture() kept, sorted: the program's description and the
  sections with hylc options, then "PETSc options" and PETSc's sections; then gives PETSc's printer
  back. Called by HylcMainFinalize(); prints on rank 0 of PETSC_COMM_WORLD. Not collective.

  Level: developer
@*/
void HylcHelpFlush(void)
{
  static const char sep[] = "----------------------------------------\n";
  const size_t      ls    = sizeof(sep) - 1;
  PetscMPIInt       rank  = 0;
  int               pass;

  if (PetscVFPrintf != HylcHelpVFPrintf) return;
  PetscVFPrintf = HylcVFPrintfSaved;
  if (!HylcHelpText) return;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank); /* with objects on PETSC_COMM_SELF, every rank kept the text */
  if (!rank) {
    /* the description: up to the first separator */
    const char *text = HylcHelpText, *end = HylcHelpText + HylcHelpLen, *first = strstr(text, sep);
    if (!first) first = end;
    fwrite(text, 1, (size_t)(first - text), stdout);
    for (pass = 0; pass < 2; pass++) {
      const char *s = first;
      if (pass == 1) fputs("========================================\nPETSc options (the solvers, logging, debugging; https://petsc.org):\n", stdout);
      while (s < end) {
        const char *body = s + ls, *next = body < end ? strstr(body, sep) : NULL;
        if (!next) next = end;
        if (HylcSectionIsHylc(body, next) == !pass) fwrite(s, 1, (size_t)(next - s), stdout);
        s = next;
      }
    }
    fflush(stdout);
  }
  free(HylcHelpText);
  HylcHelpText = NULL;
  HylcHelpLen = HylcHelpCap = 0;
}
