/* Direct solvers on the PDDO pressure matrix (issue 26): UMFPACK as
 * src/flow/pddo/ppe.c uses it, its own factor solved by plain compressed
 * row loops, SuperLU and sequential MUMPS with three orderings. Prints
 * each one's factorisation time, factor entries, median solve time and
 * error against the dumped solution. Usage: direct DUMP_DIR SOLVE REPEATS */
#include "dump.h"

#include <dmumps_c.h>
#include <slu_ddefs.h>
#include <string.h>
#include <umfpack.h>

static void report(const char *name, double factor_s, double entries, double *solve_ms, int repeats,
                   const double *x, const double *ref, int n) {
    printf("%-28s factor %6.2f s  entries %.4g  solve %6.1f ms (median of %d)  error %.1e\n", name,
           factor_s, entries, median(solve_ms, repeats), repeats, relative_error(x, ref, n));
}

/* ppe.c's UMFPACK, then its factor extracted and solved by plain loops */
static void umfpack(const Dump *d, const double *b, const double *ref, int repeats) {
    const int n = d->n;
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO], ms[64];
    umfpack_di_defaults(control);
    control[UMFPACK_ORDERING] = UMFPACK_ORDERING_CHOLMOD;
    control[UMFPACK_IRSTEP] = 0;
    void *symbolic = NULL, *numeric = NULL;
    double t = now_s();
    umfpack_di_symbolic(n, n, d->ap, d->ai, d->ax, &symbolic, control, info);
    umfpack_di_numeric(d->ap, d->ai, d->ax, symbolic, &numeric, control, info);
    const double factor_s = now_s() - t, entries = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
    double *x = malloc((size_t)n * sizeof(double));
    for (int r = 0; r < repeats; r++) {
        t = now_s();
        umfpack_di_solve(UMFPACK_At, d->ap, d->ai, d->ax, x, b, numeric, control, info);
        ms[r] = 1e3 * (now_s() - t);
    }
    report("UMFPACK (nspd today)", factor_s, entries, ms, repeats, x, ref, n);

    /* The compressed rows are the columns of M = A^T, and P R M Q = L U
     * (R the row scaling), so A = Q U^T L^T P R^-1: y = Q^T b, U^T z = y
     * forward, L^T w = z backward, x = R P^T w. */
    int lnz, unz, rows, cols, udiag;
    umfpack_di_get_lunz(&lnz, &unz, &rows, &cols, &udiag, numeric);
    int *Lp = malloc(((size_t)n + 1) * sizeof(int)), *Lj = malloc((size_t)lnz * sizeof(int));
    int *Up = malloc(((size_t)n + 1) * sizeof(int)), *Ui = malloc((size_t)unz * sizeof(int));
    int *P = malloc((size_t)n * sizeof(int)), *Q = malloc((size_t)n * sizeof(int)), recip;
    double *Lx = malloc((size_t)lnz * sizeof(double)), *Ux = malloc((size_t)unz * sizeof(double));
    double *D = malloc((size_t)n * sizeof(double)), *Rs = malloc((size_t)n * sizeof(double));
    umfpack_di_get_numeric(Lp, Lj, Lx, Up, Ui, Ux, P, Q, D, &recip, Rs, numeric);
    /* the columns of L as rows of L^T */
    int *Tp = calloc((size_t)n + 1, sizeof(int)), *Tj = malloc((size_t)lnz * sizeof(int));
    int *at = malloc((size_t)n * sizeof(int));
    double *Tx = malloc((size_t)lnz * sizeof(double)), *y = malloc((size_t)n * sizeof(double));
    for (int i = 0; i < n; i++)
        for (int m = Lp[i]; m < Lp[i + 1]; m++) Tp[Lj[m] + 1]++;
    for (int i = 0; i < n; i++) Tp[i + 1] += Tp[i];
    memcpy(at, Tp, (size_t)n * sizeof(int));
    for (int i = 0; i < n; i++)
        for (int m = Lp[i]; m < Lp[i + 1]; m++) Tj[at[Lj[m]]] = i, Tx[at[Lj[m]]++] = Lx[m];
    for (int r = 0; r < repeats; r++) {
        t = now_s();
        for (int k = 0; k < n; k++) y[k] = b[Q[k]];
        for (int k = 0; k < n; k++) {
            double s = y[k];
            for (int m = Up[k]; m < Up[k + 1]; m++)
                if (Ui[m] != k) s -= Ux[m] * y[Ui[m]];
            y[k] = s / D[k];
        }
        for (int k = n - 1; k >= 0; k--) {
            double s = y[k];
            for (int m = Tp[k]; m < Tp[k + 1]; m++)
                if (Tj[m] != k) s -= Tx[m] * y[Tj[m]];
            y[k] = s;
        }
        for (int k = 0; k < n; k++) x[P[k]] = recip ? y[k] * Rs[P[k]] : y[k] / Rs[P[k]];
        ms[r] = 1e3 * (now_s() - t);
    }
    report("UMFPACK's factor, CSR loops", 0.0, entries, ms, repeats, x, ref, n);
    umfpack_di_free_symbolic(&symbolic);
    umfpack_di_free_numeric(&numeric);
    free(Lp), free(Lj), free(Lx), free(Up), free(Ui), free(Ux), free(P), free(Q), free(D);
    free(Rs), free(Tp), free(Tj), free(Tx), free(at), free(y), free(x);
}

/* SuperLU: the compressed rows as the columns of A^T, solved transposed */
static void superlu(const Dump *d, const double *b, const double *ref, int repeats) {
    const int n = d->n;
    superlu_options_t o;
    set_default_options(&o);
    o.ColPerm = MMD_AT_PLUS_A, o.SymmetricMode = YES, o.DiagPivotThresh = 1e-3;
    SuperMatrix A, AC, L, U, B;
    int *ai = malloc((size_t)d->nnz * sizeof(int)), *ap = malloc(((size_t)n + 1) * sizeof(int));
    double *ax = malloc((size_t)d->nnz * sizeof(double)), *x = malloc((size_t)n * sizeof(double));
    memcpy(ai, d->ai, (size_t)d->nnz * sizeof(int));
    memcpy(ap, d->ap, ((size_t)n + 1) * sizeof(int));
    memcpy(ax, d->ax, (size_t)d->nnz * sizeof(double));
    dCreate_CompCol_Matrix(&A, n, n, d->nnz, ax, ai, ap, SLU_NC, SLU_D, SLU_GE);
    int *perm_c = malloc((size_t)n * sizeof(int)), *perm_r = malloc((size_t)n * sizeof(int));
    int *etree = malloc((size_t)n * sizeof(int)), info;
    SuperLUStat_t stat;
    StatInit(&stat);
    GlobalLU_t glu;
    double t = now_s(), ms[64];
    get_perm_c(o.ColPerm, &A, perm_c);
    sp_preorder(&o, &A, perm_c, etree, &AC);
    dgstrf(&o, &AC, sp_ienv(2), sp_ienv(1), etree, NULL, 0, perm_c, perm_r, &L, &U, &glu, &stat,
           &info);
    const double factor_s = now_s() - t;
    const double entries = ((SCformat *)L.Store)->nnz + ((NCformat *)U.Store)->nnz;
    dCreate_Dense_Matrix(&B, n, 1, x, n, SLU_DN, SLU_D, SLU_GE);
    for (int r = 0; r < repeats; r++) {
        memcpy(x, b, (size_t)n * sizeof(double));
        t = now_s();
        dgstrs(TRANS, &L, &U, perm_c, perm_r, &B, &stat, &info);
        ms[r] = 1e3 * (now_s() - t);
    }
    report("SuperLU (MMD on A + A^T)", factor_s, entries, ms, repeats, x, ref, n);
}

/* sequential MUMPS with ordering ICNTL(7) = ordering */
static void mumps(const Dump *d, const double *b, const double *ref, int repeats, int ordering,
                  const char *name) {
    const int n = d->n;
    int *irn = malloc((size_t)d->nnz * sizeof(int)), *jcn = malloc((size_t)d->nnz * sizeof(int));
    for (int i = 0; i < n; i++)
        for (int m = d->ap[i]; m < d->ap[i + 1]; m++) irn[m] = i + 1, jcn[m] = d->ai[m] + 1;
    DMUMPS_STRUC_C id;
    memset(&id, 0, sizeof id);
    id.par = 1, id.sym = 0, id.comm_fortran = -987654, id.job = -1;
    dmumps_c(&id);
    id.icntl[0] = id.icntl[1] = id.icntl[2] = -1, id.icntl[3] = 0, id.icntl[6] = ordering;
    id.n = n, id.nnz = d->nnz, id.irn = irn, id.jcn = jcn, id.a = d->ax;
    double t = now_s(), ms[64];
    id.job = 4;
    dmumps_c(&id);
    const double factor_s = now_s() - t, entries = (double)id.infog[28];
    double *x = malloc((size_t)n * sizeof(double));
    for (int r = 0; r < repeats; r++) {
        memcpy(x, b, (size_t)n * sizeof(double));
        id.rhs = x, id.job = 3;
        t = now_s();
        dmumps_c(&id);
        ms[r] = 1e3 * (now_s() - t);
    }
    report(name, factor_s, entries, ms, repeats, x, ref, n);
    id.job = -2;
    dmumps_c(&id);
    free(irn), free(jcn), free(x);
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: direct DUMP_DIR SOLVE REPEATS\n");
        return 2;
    }
    const Dump d = dump_matrix(argv[1]);
    const int solve = atoi(argv[2]), repeats = atoi(argv[3]);
    double *b = dump_vector(argv[1], "b", solve, d.n), *p = dump_vector(argv[1], "p", solve, d.n);
    if (!b || !p || repeats < 1 || repeats > 64) {
        fprintf(stderr, "%s: no solve %d, or repeats not in 1..64\n", argv[1], solve);
        return 2;
    }
    printf("%d unknowns, %d nonzeros; solve %d\n", d.n, d.nnz, solve);
    umfpack(&d, b, p, repeats);
    mumps(&d, b, p, repeats, 0, "MUMPS, AMD");
    mumps(&d, b, p, repeats, 4, "MUMPS, PORD");
    mumps(&d, b, p, repeats, 5, "MUMPS, METIS");
    superlu(&d, b, p, repeats);
    return 0;
}
