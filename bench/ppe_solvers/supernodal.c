/* UMFPACK's factor of the PDDO pressure matrix (issue 26), solved by
 * runs: consecutive pivots of one frontal matrix share their pattern, so
 * a run of them is kept as a small triangle and one dense block over the
 * unknowns outside the run. The solve then gathers or scatters those
 * unknowns once per run and streams the block in SIMD lanes, instead of
 * reading an index and a value per entry. L groups by its columns (rows of
 * L^T: runs_build, the block summed over its columns into one sum per
 * row), U by its rows (columns of U^T: col_runs_build, the block's products
 * scattered once per run); each the other way round finds almost no runs.
 * This asks whether UMFPACK's own solve time is the factor's bytes or its
 * loops. Usage: supernodal DUMP_DIR SOLVE REPEATS (run.sh builds the
 * dump); the answers differ from UMFPACK's in the last bits (another
 * order of the same sums). */
#include "dump.h"

#include <string.h>
#include <umfpack.h>

/* A lower triangular factor by runs: run s holds rows start[s] ..
 * start[s+1]-1 and the columns col[cp[s] .. cp[s+1]) outside it; its
 * dense block and its strictly lower triangle at bx + bp[s] (the layout is
 * each builder's). diag: NULL for a unit diagonal. */
typedef struct {
    int n, count, widest;
    int *start, *col;
    int64_t *cp, *bp;
    double *bx;
    const double *diag;
} Runs;

/* Row k's off-diagonal columns are cols[rp[k] .. rp[k+1]) (ascending, all
 * < k), their values vals[...]. Row k+1 joins row k's run when its columns
 * are row k's and k itself. */
static Runs runs_build(int n, const int64_t *rp, const int *cols, const double *vals,
                       const double *diag, int max_rows) {
    Runs r = {.n = n, .diag = diag};
    r.start = malloc(((size_t)n + 1) * sizeof(int));
    int64_t entries = 0;
    for (int k = 0; k < n;) {
        int k1 = k + 1;
        while (k1 < n && k1 - k < max_rows) {
            const int64_t a = rp[k1 - 1], la = rp[k1] - a, b = rp[k1], lb = rp[k1 + 1] - b;
            if (lb != la + 1 || cols[b + la] != k1 - 1 ||
                memcmp(cols + a, cols + b, (size_t)la * sizeof(int)) != 0)
                break;
            k1++;
        }
        r.start[r.count++] = k;
        const int64_t c = rp[k + 1] - rp[k], rows = k1 - k;
        entries += rows * c + rows * (rows - 1) / 2;
        k = k1;
    }
    r.start[r.count] = n;
    r.cp = malloc(((size_t)r.count + 1) * sizeof(int64_t));
    r.bp = malloc(((size_t)r.count + 1) * sizeof(int64_t));
    r.bx = malloc((size_t)entries * sizeof(double));
    r.cp[0] = r.bp[0] = 0;
    for (int s = 0; s < r.count; s++) {
        const int k0 = r.start[s], rows = r.start[s + 1] - k0;
        const int64_t c = rp[k0 + 1] - rp[k0];
        r.cp[s + 1] = r.cp[s] + c;
        r.bp[s + 1] = r.bp[s] + rows * c + (int64_t)rows * (rows - 1) / 2;
        if (c > r.widest) r.widest = (int)c;
    }
    r.col = malloc((size_t)r.cp[r.count] * sizeof(int));
    for (int s = 0; s < r.count; s++) {
        const int k0 = r.start[s], rows = r.start[s + 1] - k0;
        const int64_t c = r.cp[s + 1] - r.cp[s];
        memcpy(r.col + r.cp[s], cols + rp[k0], (size_t)c * sizeof(int));
        double *B = r.bx + r.bp[s], *T = B + rows * c;
        for (int q = 0; q < rows; q++) {
            const int64_t a = rp[k0 + q];
            /* the block column by column (m-major), so that the solve runs
             * its lanes over the run's rows; the triangle by columns:
             * column t's entries below t, rows t+1 .. rows-1, packed */
            for (int64_t m = 0; m < c; m++) B[m * rows + q] = vals[a + m];
            for (int t = 0; t < q; t++)
                T[(int64_t)t * (2 * rows - t - 1) / 2 + (q - t - 1)] = vals[a + c + t];
        }
    }
    return r;
}

/* The share of the stored entries held by runs of at least `rows` rows. */
static double share_in_runs(const Runs *r, int rows) {
    int64_t in = 0;
    for (int s = 0; s < r->count; s++)
        if (r->start[s + 1] - r->start[s] >= rows) in += r->bp[s + 1] - r->bp[s];
    return (double)in / (double)(r->bp[r->count] > 0 ? r->bp[r->count] : 1);
}

/* y <- L^-1 y by runs; g: widest doubles of scratch, acc: the longest
 * run's rows. The block's products are summed over its columns into one
 * sum per row (the lanes over the rows, no reduction chain), then the
 * triangle column by column. */
static void runs_solve(const Runs *r, double *y, double *g, double *acc) {
    for (int s = 0; s < r->count; s++) {
        const int k0 = r->start[s], rows = r->start[s + 1] - k0;
        const int64_t c = r->cp[s + 1] - r->cp[s];
        const int *col = r->col + r->cp[s];
        for (int64_t m = 0; m < c; m++) g[m] = y[col[m]];
        const double *B = r->bx + r->bp[s], *T = B + rows * c;
        for (int q = 0; q < rows; q++) acc[q] = 0.0;
        for (int64_t m = 0; m < c; m++) {
            const double gm = g[m], *bm = B + m * rows;
#pragma omp simd
            for (int q = 0; q < rows; q++) acc[q] += bm[q] * gm;
        }
        for (int q = 0; q < rows; q++) {
            const double a = y[k0 + q] - acc[q];
            const double z = r->diag ? a / r->diag[k0 + q] : a;
            y[k0 + q] = z;
            const double *tri = T + (int64_t)q * (2 * rows - q - 1) / 2;
            for (int t = q + 1; t < rows; t++) acc[t] += tri[t - q - 1] * z;
        }
    }
}

/* The same for a lower triangular factor given by columns: column k's
 * off-diagonal rows rows[cp[k] .. cp[k+1]) (ascending, all > k). A run of
 * columns k0 .. k1-1 has nested patterns (column k+1's rows are column
 * k's without k+1), so it is its triangle and a dense block over the rows
 * C below the run; the solve takes the run's unknowns from the triangle,
 * then subtracts block^T times them from y[C] (one scatter per run). Kept
 * in Runs: start, col = C, bx + bp[s] = the block (run column q's values
 * over C, q-major), then the triangle (column q's entries below q, packed). */
static Runs col_runs_build(int n, const int64_t *cp, const int *rows_of, const double *vals,
                           const double *diag, int max_cols) {
    Runs r = {.n = n, .diag = diag};
    r.start = malloc(((size_t)n + 1) * sizeof(int));
    int64_t entries = 0;
    for (int k = 0; k < n;) {
        int k1 = k + 1;
        while (k1 < n && k1 - k < max_cols) {
            const int64_t a = cp[k1 - 1], la = cp[k1] - a, b = cp[k1], lb = cp[k1 + 1] - b;
            if (la != lb + 1 || rows_of[a] != k1 ||
                memcmp(rows_of + a + 1, rows_of + b, (size_t)lb * sizeof(int)) != 0)
                break;
            k1++;
        }
        r.start[r.count++] = k;
        const int64_t ns = k1 - k, c = cp[k1] - cp[k1 - 1]; /* the last column's rows: C */
        entries += ns * c + ns * (ns - 1) / 2;
        k = k1;
    }
    r.start[r.count] = n;
    r.cp = malloc(((size_t)r.count + 1) * sizeof(int64_t));
    r.bp = malloc(((size_t)r.count + 1) * sizeof(int64_t));
    r.bx = malloc((size_t)entries * sizeof(double));
    r.cp[0] = r.bp[0] = 0;
    for (int s = 0; s < r.count; s++) {
        const int k0 = r.start[s], k1 = r.start[s + 1];
        const int64_t ns = k1 - k0, c = cp[k1] - cp[k1 - 1];
        r.cp[s + 1] = r.cp[s] + c;
        r.bp[s + 1] = r.bp[s] + ns * c + ns * (ns - 1) / 2;
        if (c > r.widest) r.widest = (int)c;
    }
    r.col = malloc((size_t)r.cp[r.count] * sizeof(int));
    for (int s = 0; s < r.count; s++) {
        const int k0 = r.start[s], k1 = r.start[s + 1];
        const int64_t ns = k1 - k0, c = cp[k1] - cp[k1 - 1];
        memcpy(r.col + r.cp[s], rows_of + cp[k1 - 1], (size_t)c * sizeof(int));
        double *B = r.bx + r.bp[s], *T = B + ns * c;
        for (int64_t q = 0; q < ns; q++) {
            const int64_t a = cp[k0 + q], inside = ns - 1 - q; /* rows k0+q+1 .. k1-1 first */
            for (int64_t t = 0; t < inside; t++) T[q * (2 * ns - q - 1) / 2 + t] = vals[a + t];
            for (int64_t m = 0; m < c; m++) B[q * c + m] = vals[a + inside + m];
        }
    }
    return r;
}

/* y <- L^-1 y by column runs; g: widest doubles of scratch */
static void col_runs_solve(const Runs *r, double *y, double *g) {
    for (int s = 0; s < r->count; s++) {
        const int k0 = r->start[s];
        const int64_t ns = r->start[s + 1] - k0, c = r->cp[s + 1] - r->cp[s];
        const double *B = r->bx + r->bp[s], *T = B + ns * c;
        for (int64_t q = 0; q < ns; q++) {
            const double z = r->diag ? y[k0 + q] / r->diag[k0 + q] : y[k0 + q];
            y[k0 + q] = z;
            const double *tri = T + q * (2 * ns - q - 1) / 2;
            for (int64_t t = 0; t < ns - 1 - q; t++) y[k0 + q + 1 + t] -= tri[t] * z;
        }
        for (int64_t m = 0; m < c; m++) g[m] = 0.0;
        for (int64_t q = 0; q < ns; q++) {
            const double z = y[k0 + q], *row = B + q * c;
#pragma omp simd
            for (int64_t m = 0; m < c; m++) g[m] += row[m] * z;
        }
        const int *col = r->col + r->cp[s];
        for (int64_t m = 0; m < c; m++) y[col[m]] -= g[m];
    }
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: supernodal DUMP_DIR SOLVE REPEATS\n");
        return 2;
    }
    const Dump d = dump_matrix(argv[1]);
    const int solve = atoi(argv[2]), repeats = atoi(argv[3]), n = d.n;
    double *b = dump_vector(argv[1], "b", solve, n), *ref = dump_vector(argv[1], "p", solve, n);
    if (!b || !ref || repeats < 1 || repeats > 64) {
        fprintf(stderr, "%s: no solve %d, or repeats not in 1..64\n", argv[1], solve);
        return 2;
    }
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO], ms[64];
    umfpack_di_defaults(control);
    control[UMFPACK_ORDERING] = UMFPACK_ORDERING_CHOLMOD;
    control[UMFPACK_IRSTEP] = 0;
    void *symbolic = NULL, *numeric = NULL;
    umfpack_di_symbolic(n, n, d.ap, d.ai, d.ax, &symbolic, control, info);
    umfpack_di_numeric(d.ap, d.ai, d.ax, symbolic, &numeric, control, info);
    double *x = malloc((size_t)n * sizeof(double));
    for (int q = 0; q < repeats; q++) {
        const double t = now_s();
        umfpack_di_solve(UMFPACK_At, d.ap, d.ai, d.ax, x, b, numeric, control, info);
        ms[q] = 1e3 * (now_s() - t);
    }
    printf("UMFPACK's solve:        %6.1f ms (median of %d), error %.1e\n", median(ms, repeats),
           repeats, relative_error(x, ref, n));

    /* As direct.c: A = Q U^T L^T P R^-1, so x = R P^T L^-T U^-T Q^T b.
     * U^T runs forward by U's rows (col_runs_build); L^T (rows = L's
     * columns, entries after the diagonal, unit diagonal) runs backward,
     * solved forward in reversed numbering (runs_build). */
    int lnz, unz, rows, cols, udiag, recip;
    umfpack_di_get_lunz(&lnz, &unz, &rows, &cols, &udiag, numeric);
    int *Lp = malloc(((size_t)n + 1) * sizeof(int)), *Lj = malloc((size_t)lnz * sizeof(int));
    int *Up = malloc(((size_t)n + 1) * sizeof(int)), *Ui = malloc((size_t)unz * sizeof(int));
    int *P = malloc((size_t)n * sizeof(int)), *Q = malloc((size_t)n * sizeof(int));
    double *Lx = malloc((size_t)lnz * sizeof(double)), *Ux = malloc((size_t)unz * sizeof(double));
    double *D = malloc((size_t)n * sizeof(double)), *Rs = malloc((size_t)n * sizeof(double));
    umfpack_di_get_numeric(Lp, Lj, Lx, Up, Ui, Ux, P, Q, D, &recip, Rs, numeric);
    /* L^T's rows in reversed numbering k' = n - 1 - k: row k' holds L's
     * column k below the diagonal, that is L's rows j > k at j' < k' */
    int64_t *cnt = calloc((size_t)n + 1, sizeof(int64_t));
    for (int i = 0; i < n; i++)
        for (int m = Lp[i]; m < Lp[i + 1]; m++)
            if (Lj[m] != i) cnt[n - 1 - Lj[m] + 1]++;
    for (int k = 0; k < n; k++) cnt[k + 1] += cnt[k];
    int64_t *at = malloc((size_t)n * sizeof(int64_t));
    memcpy(at, cnt, (size_t)n * sizeof(int64_t));
    int *bc = malloc((size_t)lnz * sizeof(int));
    double *bv = malloc((size_t)lnz * sizeof(double));
    /* rows of L in descending order, so each reversed row's columns come ascending */
    for (int i = n - 1; i >= 0; i--)
        for (int m = Lp[i]; m < Lp[i + 1]; m++)
            if (Lj[m] != i) {
                const int k = n - 1 - Lj[m];
                bc[at[k]] = n - 1 - i, bv[at[k]++] = Lx[m];
            }
    /* U's rows (U^T's columns): entries right of the diagonal, ascending */
    int64_t *up = calloc((size_t)n + 1, sizeof(int64_t));
    for (int k = 0; k < n; k++)
        for (int m = Up[k]; m < Up[k + 1]; m++)
            if (Ui[m] != k) up[Ui[m] + 1]++;
    for (int k = 0; k < n; k++) up[k + 1] += up[k];
    int64_t *uat = malloc((size_t)n * sizeof(int64_t));
    memcpy(uat, up, (size_t)n * sizeof(int64_t));
    int *ur = malloc((size_t)unz * sizeof(int));
    double *uv = malloc((size_t)unz * sizeof(double));
    for (int k = 0; k < n; k++)
        for (int m = Up[k]; m < Up[k + 1]; m++)
            if (Ui[m] != k) ur[uat[Ui[m]]] = k, uv[uat[Ui[m]]++] = Ux[m];
    for (int max_rows = 16; max_rows <= 1024; max_rows *= 4) {
        const Runs fw = col_runs_build(n, up, ur, uv, D, max_rows);
        const Runs bw = runs_build(n, cnt, bc, bv, NULL, max_rows);
        double *acc = malloc((size_t)max_rows * sizeof(double));
        const int widest = fw.widest > bw.widest ? fw.widest : bw.widest;
        double *g = malloc((size_t)(widest > 0 ? widest : 1) * sizeof(double));
        double *y = malloc((size_t)n * sizeof(double)), *yr = malloc((size_t)n * sizeof(double));
        double fwd[64];
        for (int q = 0; q < repeats; q++) {
            const double t = now_s();
            for (int k = 0; k < n; k++) y[k] = b[Q[k]];
            col_runs_solve(&fw, y, g);
            fwd[q] = 1e3 * (now_s() - t);
            for (int k = 0; k < n; k++) yr[k] = y[n - 1 - k];
            runs_solve(&bw, yr, g, acc);
            for (int k = 0; k < n; k++) {
                const double w = yr[n - 1 - k];
                x[P[k]] = recip ? w * Rs[P[k]] : w / Rs[P[k]];
            }
            ms[q] = 1e3 * (now_s() - t);
        }
        free(acc);
        printf("runs of at most %4d: %6.1f ms (forward %.1f), error %.1e; %d + %d runs, "
               "%.0f %% + %.0f %% of the entries in runs of 8 or more\n",
               max_rows, median(ms, repeats), median(fwd, repeats), relative_error(x, ref, n),
               fw.count, bw.count, 100 * share_in_runs(&fw, 8), 100 * share_in_runs(&bw, 8));
        free(g), free(y), free(yr);
    }
    return 0;
}
