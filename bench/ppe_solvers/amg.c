/* Algebraic multigrid on the PDDO pressure matrix (issue 26): hypre's
 * BoomerAMG as the preconditioner of BiCGStab (the matrix is not
 * symmetric), from three initial guesses: zero, the last step's pressure,
 * and its linear extrapolation from the last two steps. Prints the
 * iterations, the time and the error against the dumped UMFPACK solution.
 * Usage: amg DUMP_DIR TOL STRONG_THRESHOLD COARSENING INTERPOLATION RELAXATION
 * (hypre's numbers; the defaults are 0.25 10 6 6) */
#include "dump.h"

#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>
#include <string.h>

typedef struct {
    HYPRE_IJVector ij;
    HYPRE_ParVector par;
} Vector;

static Vector vector_make(int n) {
    Vector v;
    HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, &v.ij);
    HYPRE_IJVectorSetObjectType(v.ij, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(v.ij);
    HYPRE_IJVectorAssemble(v.ij);
    HYPRE_IJVectorGetObject(v.ij, (void **)&v.par);
    return v;
}

int main(int argc, char **argv) {
    MPI_Init(&argc, &argv);
    if (argc != 7) {
        fprintf(stderr, "usage: amg DUMP_DIR TOL THRESHOLD COARSENING INTERPOLATION RELAXATION\n");
        return 2;
    }
    const Dump d = dump_matrix(argv[1]);
    const int n = d.n;
    HYPRE_IJMatrix A;
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &A);
    HYPRE_IJMatrixSetObjectType(A, HYPRE_PARCSR);
    HYPRE_IJMatrixInitialize(A);
    HYPRE_BigInt *cols = malloc((size_t)d.nnz * sizeof(HYPRE_BigInt));
    HYPRE_BigInt *index = malloc((size_t)n * sizeof(HYPRE_BigInt));
    for (int m = 0; m < d.nnz; m++) cols[m] = d.ai[m];
    for (int i = 0; i < n; i++) {
        HYPRE_Int count = d.ap[i + 1] - d.ap[i];
        HYPRE_BigInt row = i;
        index[i] = i;
        HYPRE_IJMatrixSetValues(A, 1, &count, &row, cols + d.ap[i], d.ax + d.ap[i]);
    }
    HYPRE_IJMatrixAssemble(A);
    HYPRE_ParCSRMatrix pa;
    HYPRE_IJMatrixGetObject(A, (void **)&pa);
    Vector b = vector_make(n), x = vector_make(n);

    HYPRE_Solver amg, krylov;
    HYPRE_BoomerAMGCreate(&amg);
    HYPRE_BoomerAMGSetMaxIter(amg, 1);
    HYPRE_BoomerAMGSetTol(amg, 0.0);
    HYPRE_BoomerAMGSetStrongThreshold(amg, atof(argv[3]));
    HYPRE_BoomerAMGSetCoarsenType(amg, atoi(argv[4]));
    HYPRE_BoomerAMGSetInterpType(amg, atoi(argv[5]));
    HYPRE_BoomerAMGSetRelaxType(amg, atoi(argv[6]));
    HYPRE_ParCSRBiCGSTABCreate(MPI_COMM_WORLD, &krylov);
    HYPRE_BiCGSTABSetTol(krylov, atof(argv[2]));
    HYPRE_BiCGSTABSetMaxIter(krylov, 100);
    HYPRE_BiCGSTABSetPrecond(krylov, (HYPRE_PtrToSolverFcn)HYPRE_BoomerAMGSolve,
                             (HYPRE_PtrToSolverFcn)HYPRE_BoomerAMGSetup, amg);
    double t = now_s();
    HYPRE_ParCSRBiCGSTABSetup(krylov, pa, b.par, x.par);
    printf("%d unknowns; AMG setup %.2f s\n", n, now_s() - t);

    /* three consecutive solves: the third from the first two */
    const int first = 150;
    double *p1 = dump_vector(argv[1], "p", first, n), *p2 = dump_vector(argv[1], "p", first + 1, n);
    double *rhs = dump_vector(argv[1], "b", first + 2, n);
    double *ref = dump_vector(argv[1], "p", first + 2, n);
    if (!p1 || !p2 || !rhs || !ref) {
        fprintf(stderr, "%s: needs solves %d to %d\n", argv[1], first, first + 2);
        return 2;
    }
    double *x0 = malloc((size_t)n * sizeof(double)), *sol = malloc((size_t)n * sizeof(double));
    const char *guess[] = {"zero", "last pressure", "extrapolated"};
    for (int g = 0; g < 3; g++) {
        for (int i = 0; i < n; i++) x0[i] = g == 0 ? 0.0 : g == 1 ? p2[i] : 2.0 * p2[i] - p1[i];
        HYPRE_IJVectorSetValues(b.ij, n, index, rhs);
        HYPRE_IJVectorSetValues(x.ij, n, index, x0);
        HYPRE_Int iterations;
        t = now_s();
        HYPRE_ParCSRBiCGSTABSolve(krylov, pa, b.par, x.par);
        const double ms = 1e3 * (now_s() - t);
        HYPRE_BiCGSTABGetNumIterations(krylov, &iterations);
        HYPRE_IJVectorGetValues(x.ij, n, index, sol);
        printf("guess %-14s error %.1e -> %.1e in %3d iterations, %7.1f ms\n", guess[g],
               relative_error(x0, ref, n), relative_error(sol, ref, n), (int)iterations, ms);
    }
    MPI_Finalize();
    return 0;
}
