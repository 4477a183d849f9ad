/* The fill-reducing ordering "metisnd" (MATORDERINGMETISND): METIS 5 nested dissection (METIS_NodeND)
   of the symmetrized adjacency graph of a sequential matrix, registered with MatOrderingRegister() by
   HylcSysInitializePackage() because Debian's PETSc is built without METIS. Usable wherever PETSc takes an
   ordering: MatGetOrdering(), -pc_factor_mat_ordering_type metisnd, PCFactorSetMatOrderingType().

   Options (global, no prefix; read at each call, and checked and listed by -help in HylcMetisSetFromOptions()):
     -hylc_metis_seed <int>     METIS random seed (default: METIS's own, deterministic)
     -hylc_metis_nseps <int>    separators computed at each bisection, the smallest is kept (default 1)
     -hylc_metis_ufactor <int>  allowed imbalance of the bisections, in 1/1000 (default: METIS's, 200)
     -hylc_metis_compress <bool> compress vertices with identical adjacency (default true) */
#include <hylc/options.h>
#include <hylc/sys.h>
#include <petscmat.h>
#include <metis.h>

PetscLogEvent HYLC_MetisND;

static const char *MetisError(int st)
{
  switch (st) {
  case METIS_ERROR_INPUT:
    return "input error";
  case METIS_ERROR_MEMORY:
    return "out of memory";
  default:
    return "error";
  }
}

/* Reads the options into a METIS options array. */
static PetscErrorCode MetisOptions(idx_t opt[METIS_NOPTIONS])
{
  PetscInt  v;
  PetscBool set, b;

  PetscFunctionBegin;
  PetscCheck(METIS_SetDefaultOptions(opt) == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_SetDefaultOptions failed");
  opt[METIS_OPTION_NUMBERING] = 0;
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-hylc_metis_seed", &v, &set));
  if (set) opt[METIS_OPTION_SEED] = (idx_t)v;
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-hylc_metis_nseps", &v, &set));
  if (set) {
    PetscCheck(v >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -hylc_metis_nseps: %" PetscInt_FMT " is not >= 1", v);
    opt[METIS_OPTION_NSEPS] = (idx_t)v;
  }
  PetscCall(PetscOptionsGetInt(NULL, NULL, "-hylc_metis_ufactor", &v, &set));
  if (set) {
    PetscCheck(v >= 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "option -hylc_metis_ufactor: %" PetscInt_FMT " is not >= 1", v);
    opt[METIS_OPTION_UFACTOR] = (idx_t)v;
  }
  PetscCall(PetscOptionsGetBool(NULL, NULL, "-hylc_metis_compress", &b, &set));
  if (set) opt[METIS_OPTION_COMPRESS] = b ? 1 : 0;
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMetisSetFromOptions - Reads and checks the options of the "metisnd" ordering (-hylc_metis_seed,
  -hylc_metis_nseps, -hylc_metis_ufactor, -hylc_metis_compress; no prefix), so that -help lists them and a
  program that refuses unused options before its work (HylcCheckOptionsUsed()) accepts them: they are
  otherwise read only at the first ordering. Called by HylcMicroSetFromOptions(). Collective.

  Input Parameter:
. comm - the communicator of the options' help
@*/
PetscErrorCode HylcMetisSetFromOptions(MPI_Comm comm)
{
  PetscInt  seed = -1, nseps = 1, ufactor = 200;
  PetscBool b = PETSC_TRUE;
  idx_t     opt[METIS_NOPTIONS];

  PetscFunctionBegin;
  PetscOptionsBegin(comm, NULL, "METIS nested-dissection ordering (metisnd; the factorization of the Newton matrix)", "Mat");
  PetscCall(HylcOptionsInt("-hylc_metis_seed", "METIS random seed (-1: METIS's own, deterministic)", "HylcMetisNodeND", seed, &seed, NULL));
  PetscCall(HylcOptionsInt("-hylc_metis_nseps", "Separators computed at each bisection, the smallest kept (>= 1)", "HylcMetisNodeND", nseps, &nseps, NULL));
  PetscCall(HylcOptionsInt("-hylc_metis_ufactor", "Allowed imbalance of the bisections, in 1/1000 (>= 1; METIS's default)", "HylcMetisNodeND", ufactor, &ufactor, NULL));
  PetscCall(PetscOptionsBool("-hylc_metis_compress", "Compress vertices with identical adjacency", "HylcMetisNodeND", b, &b, NULL));
  PetscOptionsEnd();
  PetscCall(MetisOptions(opt)); /* the checks of the values, the same as at each ordering */
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* MatOrdering function of "metisnd": row and column permutations (the same IS values, new-to-old as
   all PETSc orderings) from METIS_NodeND on the graph of A + A^T without its diagonal. Sequential
   matrices only (the ordering of a factorization is always local).

   The graph is inode-compressed, as in PETSc's own orderings: for a SeqAIJ matrix with inodes (rows of
   identical structure, e.g. the 4 unknowns of a yarn vertex) MatGetRowIJ() gives one vertex per inode
   and MatGetOrdering() expands the permutation (MatInodeAdjustForInodes), so inodes stay contiguous.
   This is required, not only faster: PETSc 3.18's inode LU (MatLUFactorNumeric_SeqAIJ_Inode) gives wrong
   results or corrupts memory with a permutation that splits the inodes of the matrix (seen on the
   stockinette H_y: relative residual 2.5e3, or free(): invalid pointer). */
static PetscErrorCode MatGetOrdering_HylcMetisND(Mat mat, MatOrderingType type, IS *row, IS *col)
{
  PetscInt        n, nloc, nedge = 0;
  const PetscInt *ia, *ja;
  PetscBool       done;
  MatType         mtype;
  idx_t          *xadj, *adj, *perm, *iperm, nv, opt[METIS_NOPTIONS];
  PetscInt       *p;

  PetscFunctionBegin;
  (void)type;
  PetscCall(MetisOptions(opt)); /* before allocating: a bad option is an error */
  PetscCall(MatGetRowIJ(mat, 0, PETSC_TRUE, PETSC_TRUE, &n, &ia, &ja, &done));
  if (!done) {
    PetscCall(MatGetType(mat, &mtype));
    SETERRQ(PetscObjectComm((PetscObject)mat), PETSC_ERR_SUP, "ordering metisnd: cannot get the row structure of a %s matrix", mtype);
  }
  nloc = n; /* MatRestoreRowIJ() zeroes n */
#if defined(PETSC_USE_64BIT_INDICES) && IDXTYPEWIDTH == 32
  PetscCheck(ia[nloc] <= IDX_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "ordering metisnd: graph with %" PetscInt_FMT " entries too large for METIS's 32-bit idx_t", ia[nloc]);
#endif
  PetscCall(PetscMalloc2(nloc + 1, &xadj, ia[nloc], &adj));
  xadj[0] = 0;
  for (PetscInt i = 0; i < nloc; i++) {
    for (PetscInt k = ia[i]; k < ia[i + 1]; k++)
      if (ja[k] != i) adj[nedge++] = (idx_t)ja[k];
    xadj[i + 1] = (idx_t)nedge;
  }
  PetscCall(MatRestoreRowIJ(mat, 0, PETSC_TRUE, PETSC_TRUE, &n, &ia, &ja, &done));
  PetscCheck(done, PetscObjectComm((PetscObject)mat), PETSC_ERR_LIB, "ordering metisnd: MatRestoreRowIJ failed");

  PetscCall(PetscMalloc1(nloc, &p));
  if (nedge == 0) { /* empty, 1x1 or diagonal: no fill in any order; METIS is not needed */
    for (PetscInt i = 0; i < nloc; i++) p[i] = i;
  } else {
    int st;
    PetscCall(PetscMalloc2(nloc, &perm, nloc, &iperm));
    nv = (idx_t)nloc;
    PetscCall(PetscLogEventBegin(HYLC_MetisND, mat, 0, 0, 0));
    st = METIS_NodeND(&nv, xadj, adj, NULL, opt, perm, iperm);
    PetscCall(PetscLogEventEnd(HYLC_MetisND, mat, 0, 0, 0));
    if (st == METIS_OK)
      for (PetscInt i = 0; i < nloc; i++) p[i] = (PetscInt)perm[i]; /* new-to-old */
    PetscCall(PetscFree2(perm, iperm));
    if (st != METIS_OK) {
      PetscCall(PetscFree2(xadj, adj));
      PetscCall(PetscFree(p));
    }
    PetscCheck(st == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "ordering metisnd: METIS_NodeND failed (%s, code %d) on a graph of %" PetscInt_FMT " vertices and %" PetscInt_FMT " edges", MetisError(st), st, nloc, nedge / 2);
  }
  PetscCall(PetscFree2(xadj, adj));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, nloc, p, PETSC_COPY_VALUES, row));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, nloc, p, PETSC_OWN_POINTER, col));
  PetscFunctionReturn(PETSC_SUCCESS);
}

/*@C
  HylcMetisNodeND - METIS_NodeND ordering of a graph given in CSR form (xadj[n + 1], adj; symmetric, no
  self loops): perm[new] = old. The options of "metisnd" apply. A graph without edges gets the identity.
  Not collective.
@*/
PetscErrorCode HylcMetisNodeND(PetscInt n, const PetscInt xadj[], const PetscInt adj[], PetscInt perm[])
{
  idx_t *xa, *ad, *pm, *ip, nv = (idx_t)n, opt[METIS_NOPTIONS];
  int    st;

  PetscFunctionBegin;
  PetscCall(MetisOptions(opt));
  if (n == 0 || xadj[n] == 0) {
    for (PetscInt i = 0; i < n; i++) perm[i] = i;
    PetscFunctionReturn(PETSC_SUCCESS);
  }
  PetscCall(PetscMalloc4(n + 1, &xa, xadj[n], &ad, n, &pm, n, &ip));
  for (PetscInt i = 0; i <= n; i++) xa[i] = (idx_t)xadj[i];
  for (PetscInt k = 0; k < xadj[n]; k++) ad[k] = (idx_t)adj[k];
  PetscCall(PetscLogEventBegin(HYLC_MetisND, 0, 0, 0, 0));
  st = METIS_NodeND(&nv, xa, ad, NULL, opt, pm, ip);
  PetscCall(PetscLogEventEnd(HYLC_MetisND, 0, 0, 0, 0));
  if (st == METIS_OK)
    for (PetscInt i = 0; i < n; i++) perm[i] = (PetscInt)pm[i];
  PetscCall(PetscFree4(xa, ad, pm, ip));
  PetscCheck(st == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_NodeND failed (%s, code %d) on a graph of %" PetscInt_FMT " vertices and %" PetscInt_FMT " edges", MetisError(st), st, n, xadj[n] / 2);
  PetscFunctionReturn(PETSC_SUCCESS);
}

/* Registers "metisnd" with PETSc (called by HylcSysInitializePackage()). Not collective. */
PetscErrorCode HylcMetisRegister(void)
{
  PetscFunctionBegin;
  PetscCall(MatOrderingRegister(MATORDERINGMETISND, MatGetOrdering_HylcMetisND));
  PetscCall(PetscLogEventRegister("ORDER_MetisND", MAT_CLASSID, &HYLC_MetisND));
  PetscFunctionReturn(PETSC_SUCCESS);
}
