/* flow/pddo/ppe_petsc.h: PETSc's KSP on the PDDO pressure matrix. */
#include "flow/pddo/ppe_petsc.h"

#include "core/status.h"
#include "flow/pddo/petsc_lib.h"

#include <string.h>

#if defined(NSPD_HAVE_PETSC) && defined(NSPD_HAVE_MPI)

bool ppe_petsc_built(void) {
    return true;
}

/* Most Krylov iterations a solve may take: BiCGStab with BoomerAMG took
 * 14 to 27 on the paper's cylinder (bench/ppe_solvers); far more means
 * it does not converge, and the run should say so rather than crawl. */
enum { PPE_PETSC_MAX_ITERATIONS = 500 };

static int petsc_fail(PetscErrorCode code, const char *what) {
    return NSPD_FAIL(NSPD_ERR_NUMERIC, "PDDO pressure solve: PETSc's %s failed (error %d)", what,
                     (int)code);
}

#define PETSC_TRY(call, what)                                                                      \
    do {                                                                                           \
        const PetscErrorCode petsc_code_ = (call);                                                 \
        if (petsc_code_) return petsc_fail(petsc_code_, what);                                     \
    } while (0)

static void petsc_stop(void) {
    PetscBool ready = PETSC_FALSE;
    if (PetscInitialized(&ready) == 0 && ready) (void)PetscFinalize();
}

/* PETSc over the running MPI (or starting it on one process without a
 * launcher), once; its errors returned to us, not printed and aborted. */
static int petsc_start(void) {
    TRY(petsc_lib_load());
    PetscBool ready = PETSC_FALSE;
    PETSC_TRY(PetscInitialized(&ready), "PetscInitialized");
    if (ready) return NSPD_OK;
    /* PETSc's own handlers would catch SIGTERM and abort; nspd's write a
     * checkpoint and stop cleanly (docs/CASES.md) */
    static char arg0[] = "nspd", arg1[] = "-no_signal_handler";
    char *args[] = {arg0, arg1, NULL};
    char **argv = args;
    int argc = 2;
    PETSC_TRY(PetscInitialize(&argc, &argv, NULL, NULL), "PetscInitialize");
    PETSC_TRY(PetscPushErrorHandler(PetscReturnErrorHandler, NULL), "PetscPushErrorHandler");
    comm_at_finalize(petsc_stop);
    return NSPD_OK;
}

/* name's value unless the user's options already set it */
static int default_option(const char *name, const char *value) {
    PetscBool set = PETSC_FALSE;
    PETSC_TRY(PetscOptionsHasName(NULL, NULL, name, &set), "PetscOptionsHasName");
    if (!set) PETSC_TRY(PetscOptionsSetValue(NULL, name, value), "PetscOptionsSetValue");
    return NSPD_OK;
}

static MPI_Comm mpi_comm(const NspdComm *comm) {
    return comm_distributed(comm) ? MPI_Comm_f2c(comm->handle) : MPI_COMM_SELF;
}

/* This rank's rows as PETSc's matrix (PetscInt is 32-bit in Debian's
 * build, checked below, so the arrays go in as they are). */
static int make_matrix(PpePetsc *s, MPI_Comm comm, bool transpose, int64_t n, const int32_t *ap,
                       const int32_t *ai, const double *ax) {
    _Static_assert(sizeof(PetscInt) == sizeof(int32_t), "PETSc with 32-bit indices");
    _Static_assert(sizeof(PetscScalar) == sizeof(double), "PETSc with real doubles");
    const int64_t rows = s->hi - s->lo;
    Mat a = NULL;
    /* copies the rows into its own storage */
    const PetscErrorCode code = MatCreateMPIAIJWithArrays(comm, (PetscInt)rows, (PetscInt)rows,
                                                          (PetscInt)n, (PetscInt)n, ap, ai, ax, &a);
    if (code) return petsc_fail(code, "MatCreateMPIAIJWithArrays");
    if (transpose) {
        Mat t = NULL;
        const PetscErrorCode tc = MatTranspose(a, MAT_INITIAL_MATRIX, &t);
        MatDestroy(&a);
        if (tc) return petsc_fail(tc, "MatTranspose");
        a = t;
    }
    s->mat = a;
    return NSPD_OK;
}

static int configure(PpePetsc *s, KSP ksp, double tolerance) {
    PC pc = NULL;
    PETSC_TRY(KSPGetPC(ksp, &pc), "KSPGetPC");
    PETSC_TRY(KSPSetOptionsPrefix(ksp, "pressure_"), "KSPSetOptionsPrefix");
    if (s->method == PPE_PETSC_MUMPS) {
        PETSC_TRY(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
        PETSC_TRY(PCSetType(pc, PCLU), "PCSetType");
        PETSC_TRY(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
        PETSC_TRY(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
        Mat f = NULL;
        PETSC_TRY(PCFactorGetMatrix(pc, &f), "PCFactorGetMatrix");
        /* the ordering on the host (ICNTL 28 = 1), by AMD (ICNTL 7 = 0):
         * the same factor, hence bits, run after run at a rank count */
        PETSC_TRY(MatMumpsSetIcntl(f, 28, 1), "MatMumpsSetIcntl(28)");
        PETSC_TRY(MatMumpsSetIcntl(f, 7, 0), "MatMumpsSetIcntl(7)");
    } else {
        PETSC_TRY(KSPSetType(ksp, KSPBCGS), "KSPSetType");
        PETSC_TRY(PCSetType(pc, PCHYPRE), "PCSetType");
        PETSC_TRY(PCHYPRESetType(pc, "boomeramg"), "PCHYPRESetType");
        /* the settings bench/ppe_solvers measured with hypre alone
         * (docs/PERFORMANCE.md), among them hypre's own limit of 4
         * interpolation weights a row, which PETSc lifts by default: without
         * it BiCGStab took 190-260 iterations a solve on the coarse Re 100
         * cylinder (3,369 nodes), with it 15-17; and the smoother over all
         * points at once, not C points then F points (PETSc's default):
         * with CF relaxation the first steps of the paper's cylinder took
         * 487 iterations and more, without it 19-27 */
        TRY(default_option("-pressure_pc_hypre_boomeramg_P_max", "4"));
        TRY(default_option("-pressure_pc_hypre_boomeramg_no_CF", NULL));
        TRY(default_option("-pressure_pc_hypre_boomeramg_coarsen_type", "HMIS"));
        TRY(default_option("-pressure_pc_hypre_boomeramg_interp_type", "ext+i"));
        TRY(default_option("-pressure_pc_hypre_boomeramg_relax_type_all", "l1scaled-Jacobi"));
        TRY(default_option("-pressure_pc_hypre_boomeramg_strong_threshold", "0.25"));
        /* the true residual against ||b||, whatever the preconditioner */
        PETSC_TRY(KSPSetPCSide(ksp, PC_RIGHT), "KSPSetPCSide");
        PETSC_TRY(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
        PETSC_TRY(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");
        PETSC_TRY(KSPSetTolerances(ksp, tolerance, 0.0, PETSC_DEFAULT, PPE_PETSC_MAX_ITERATIONS),
                  "KSPSetTolerances");
    }
    PETSC_TRY(KSPSetFromOptions(ksp), "KSPSetFromOptions");
    return NSPD_OK;
}

/* MUMPS's counts of the factors over every rank: INFOG(29) entries
 * (negative: millions), INFOG(22) MB. */
static int factor_counts(PpePetsc *s, KSP ksp) {
    PC pc = NULL;
    Mat f = NULL;
    PetscInt entries = 0, mb = 0;
    PETSC_TRY(KSPGetPC(ksp, &pc), "KSPGetPC");
    PETSC_TRY(PCFactorGetMatrix(pc, &f), "PCFactorGetMatrix");
    PETSC_TRY(MatMumpsGetInfog(f, 29, &entries), "MatMumpsGetInfog(29)");
    PETSC_TRY(MatMumpsGetInfog(f, 22, &mb), "MatMumpsGetInfog(22)");
    s->factor_nnz = entries < 0 ? -1e6 * (double)entries : (double)entries;
    s->factor_mb = (double)mb;
    return NSPD_OK;
}

static int create(PpePetsc *s, const NspdComm *comm, double tolerance, bool transpose, int64_t n,
                  const int32_t *ap, const int32_t *ai, const double *ax) {
    TRY(petsc_start());
    const MPI_Comm mc = mpi_comm(comm);
    TRY(make_matrix(s, mc, transpose, n, ap, ai, ax));
    const PetscInt rows = (PetscInt)(s->hi - s->lo);
    Vec b = NULL, x = NULL;
    PETSC_TRY(VecCreateMPIWithArray(mc, 1, rows, (PetscInt)n, NULL, &b), "VecCreateMPIWithArray");
    s->b = b;
    PETSC_TRY(VecCreateMPIWithArray(mc, 1, rows, (PetscInt)n, NULL, &x), "VecCreateMPIWithArray");
    s->x = x;
    KSP ksp = NULL;
    PETSC_TRY(KSPCreate(mc, &ksp), "KSPCreate");
    s->ksp = ksp;
    PETSC_TRY(KSPSetOperators(ksp, (Mat)s->mat, (Mat)s->mat), "KSPSetOperators");
    TRY(configure(s, ksp, tolerance));
    PETSC_TRY(KSPSetUp(ksp),
              s->method == PPE_PETSC_MUMPS ? "MUMPS factorisation" : "BoomerAMG setup");
    if (s->method == PPE_PETSC_MUMPS) TRY(factor_counts(s, ksp));
    return NSPD_OK;
}

int ppe_petsc_create(PpePetsc *s, const NspdComm *comm, PpePetscMethod method, double tolerance,
                     bool transpose, int64_t lo, int64_t hi, int64_t n, const int32_t *ap,
                     const int32_t *ai, const double *ax) {
    ppe_petsc_free(s);
    s->method = method, s->lo = lo, s->hi = hi;
    const int status = create(s, comm, tolerance, transpose, n, ap, ai, ax);
    if (status != NSPD_OK) ppe_petsc_free(s);
    return status;
}

/* KSPConvergedReason's names for the ways a solve fails */
static const char *diverged_why(KSPConvergedReason r) {
    switch (r) {
    case KSP_DIVERGED_ITS:
        return "the iteration limit";
    case KSP_DIVERGED_DTOL:
        return "the residual grew";
    case KSP_DIVERGED_BREAKDOWN:
        return "a breakdown";
    case KSP_DIVERGED_NANORINF:
        return "a NaN or infinity";
    case KSP_DIVERGED_PC_FAILED:
        return "the preconditioner failed";
    default:
        return "another reason";
    }
}

int ppe_petsc_solve(PpePetsc *s, const double *b, double *x) {
    Vec vb = (Vec)s->b, vx = (Vec)s->x;
    PETSC_TRY(VecPlaceArray(vb, b), "VecPlaceArray");
    PETSC_TRY(VecPlaceArray(vx, x), "VecPlaceArray");
    const PetscErrorCode code = KSPSolve((KSP)s->ksp, vb, vx);
    VecResetArray(vb);
    VecResetArray(vx);
    if (code) return petsc_fail(code, "KSPSolve");
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    PetscInt its = 0;
    PetscReal norm = 0.0;
    PETSC_TRY(KSPGetConvergedReason((KSP)s->ksp, &reason), "KSPGetConvergedReason");
    PETSC_TRY(KSPGetIterationNumber((KSP)s->ksp, &its), "KSPGetIterationNumber");
    PETSC_TRY(KSPGetResidualNorm((KSP)s->ksp, &norm), "KSPGetResidualNorm");
    s->iterations = s->method == PPE_PETSC_MUMPS ? 1 : (int)its;
    s->iterations_total += s->iterations;
    s->residual = norm;
    if (reason < 0)
        return NSPD_FAIL(
            NSPD_ERR_NUMERIC,
            "PDDO pressure solve: the Krylov solve with BoomerAMG stopped by %s (PETSc "
            "reason %d) after %d iterations, residual %.3g; expected convergence "
            "(try a smaller time step, or flow.pressure_solve: mumps)",
            diverged_why(reason), (int)reason, (int)its, norm);
    return NSPD_OK;
}

void ppe_petsc_free(PpePetsc *s) {
    if (s->ksp) {
        KSP ksp = (KSP)s->ksp;
        KSPDestroy(&ksp);
    }
    if (s->mat) {
        Mat a = (Mat)s->mat;
        MatDestroy(&a);
    }
    Vec v[2] = {(Vec)s->b, (Vec)s->x};
    for (int k = 0; k < 2; k++)
        if (v[k]) VecDestroy(&v[k]);
    memset(s, 0, sizeof *s);
}

#else /* without PETSc (or MPI) */

bool ppe_petsc_built(void) {
    return false;
}

int ppe_petsc_create(PpePetsc *s, const NspdComm *comm, PpePetscMethod method, double tolerance,
                     bool transpose, int64_t lo, int64_t hi, int64_t n, const int32_t *ap,
                     const int32_t *ai, const double *ax) {
    (void)s, (void)comm, (void)method, (void)tolerance, (void)transpose, (void)lo, (void)hi;
    (void)n, (void)ap, (void)ai, (void)ax;
    return NSPD_FAIL(NSPD_ERR_INPUT,
                     "PDDO pressure solve: this nspd was built without PETSc; expected "
                     "flow.pressure_solve: runs or umfpack, or a build with MPI and petsc-dev "
                     "(scripts/deps.sh installs it)");
}

int ppe_petsc_solve(PpePetsc *s, const double *b, double *x) {
    (void)s, (void)b, (void)x;
    return NSPD_FAIL(NSPD_ERR_INPUT, "PDDO pressure solve: this nspd was built without PETSc");
}

void ppe_petsc_free(PpePetsc *s) {
    memset(s, 0, sizeof *s);
}

#endif
