/* Triangular factors stored by runs of pivots (lu_runs.h). */
#include "flow/pddo/lu_runs.h"

#include "core/mem.h"
#include "core/status.h"

#include <string.h>

/* Whether pivot k joins the run that pivot k - 1 is in: GATHER, row k is
 * row k-1 and then k-1; SCATTER, column k-1 is k and then column k. */
static int joins(LuRunsForm form, const int64_t *ptr, const int32_t *idx, int64_t k) {
    const int64_t a = ptr[k - 1], la = ptr[k] - a, b = ptr[k], lb = ptr[k + 1] - b;
    if (form == LU_RUNS_GATHER)
        return lb == la + 1 && idx[b + la] == k - 1 &&
               memcmp(idx + a, idx + b, (size_t)la * sizeof *idx) == 0;
    return la == lb + 1 && idx[a] == k &&
           memcmp(idx + a + 1, idx + b, (size_t)lb * sizeof *idx) == 0;
}

/* The unknowns outside run [k0, k1): GATHER, row k0's columns; SCATTER,
 * column k1-1's rows. */
static void outside(LuRunsForm form, const int64_t *ptr, int64_t k0, int64_t k1, int64_t *at,
                    int64_t *count) {
    const int64_t k = form == LU_RUNS_GATHER ? k0 : k1 - 1;
    *at = ptr[k];
    *count = ptr[k + 1] - ptr[k];
}

/* The packed position of entry (row q, column t), q > t, of an ns x ns
 * strictly lower triangle stored column by column. */
static inline int64_t tri_at(int64_t ns, int64_t q, int64_t t) {
    return t * (2 * ns - t - 1) / 2 + (q - t - 1);
}

int lu_runs_build(LuRuns *r, LuRunsForm form, int64_t n, const int64_t *ptr, const int32_t *idx,
                  const double *val, const double *diag, int64_t max_run) {
    memset(r, 0, sizeof *r);
    r->form = form, r->n = n, r->diag = diag;
    TRY(nspd_alloc(&r->start, (size_t)n + 1, sizeof *r->start));
    int64_t outside_total = 0, entries = 0;
    for (int64_t k = 0; k < n;) {
        int64_t k1 = k + 1;
        while (k1 < n && k1 - k < max_run && joins(form, ptr, idx, k1)) k1++;
        int64_t at, c;
        outside(form, ptr, k, k1, &at, &c);
        const int64_t ns = k1 - k;
        r->start[r->count++] = k;
        outside_total += c;
        entries += ns * c + ns * (ns - 1) / 2;
        if (c > r->widest) r->widest = c;
        if (ns > r->longest) r->longest = ns;
        k = k1;
    }
    r->start[r->count] = n;
    TRY(nspd_alloc(&r->cp, (size_t)r->count + 1, sizeof *r->cp));
    TRY(nspd_alloc(&r->bp, (size_t)r->count + 1, sizeof *r->bp));
    r->cp[0] = r->bp[0] = 0;
    TRY(nspd_alloc(&r->idx, (size_t)(outside_total > 0 ? outside_total : 1), sizeof *r->idx));
    TRY(nspd_alloc(&r->bx, (size_t)(entries > 0 ? entries : 1), sizeof *r->bx));
    for (int64_t s = 0; s < r->count; s++) {
        const int64_t k0 = r->start[s], k1 = r->start[s + 1], ns = k1 - k0;
        int64_t at, c;
        outside(form, ptr, k0, k1, &at, &c);
        r->cp[s + 1] = r->cp[s] + c;
        r->bp[s + 1] = r->bp[s] + ns * c + ns * (ns - 1) / 2;
        memcpy(r->idx + r->cp[s], idx + at, (size_t)c * sizeof *idx);
        double *B = r->bx + r->bp[s], *T = B + ns * c;
        for (int64_t q = 0; q < ns; q++) {
            const int64_t a = ptr[k0 + q];
            if (form == LU_RUNS_GATHER) {
                /* row q: the outside columns, then the run's columns 0 .. q-1;
                 * the block column by column (lanes over the run's rows) */
                for (int64_t m = 0; m < c; m++) B[m * ns + q] = val[a + m];
                for (int64_t t = 0; t < q; t++) T[tri_at(ns, q, t)] = val[a + c + t];
            } else {
                /* column q: the run's rows q+1 .. ns-1, then the outside rows;
                 * the block row by row of the run (lanes over the outside) */
                const int64_t inside = ns - 1 - q;
                for (int64_t t = 0; t < inside; t++) T[tri_at(ns, q + 1 + t, q)] = val[a + t];
                for (int64_t m = 0; m < c; m++) B[q * c + m] = val[a + inside + m];
            }
        }
    }
    return NSPD_OK;
}

void lu_runs_solve(const LuRuns *r, double *y, double *scratch) {
    double *g = scratch, *acc = scratch + r->widest;
    for (int64_t s = 0; s < r->count; s++) {
        const int64_t k0 = r->start[s], ns = r->start[s + 1] - k0, c = r->cp[s + 1] - r->cp[s];
        const int32_t *out = r->idx + r->cp[s];
        const double *B = r->bx + r->bp[s], *T = B + ns * c;
        if (r->form == LU_RUNS_GATHER) {
            for (int64_t m = 0; m < c; m++) g[m] = y[out[m]];
            for (int64_t q = 0; q < ns; q++) acc[q] = 0.0;
            for (int64_t m = 0; m < c; m++) {
                const double gm = g[m], *bm = B + m * ns;
#pragma omp simd
                for (int64_t q = 0; q < ns; q++) acc[q] += bm[q] * gm;
            }
            for (int64_t q = 0; q < ns; q++) {
                const double a = y[k0 + q] - acc[q];
                const double z = r->diag ? a / r->diag[k0 + q] : a;
                y[k0 + q] = z;
                const double *col = T + tri_at(ns, q + 1, q);
                for (int64_t t = q + 1; t < ns; t++) acc[t] += col[t - q - 1] * z;
            }
        } else {
            for (int64_t q = 0; q < ns; q++) {
                const double z = r->diag ? y[k0 + q] / r->diag[k0 + q] : y[k0 + q];
                y[k0 + q] = z;
                const double *col = T + tri_at(ns, q + 1, q);
                for (int64_t t = q + 1; t < ns; t++) y[k0 + t] -= col[t - q - 1] * z;
            }
            for (int64_t m = 0; m < c; m++) g[m] = 0.0;
            for (int64_t q = 0; q < ns; q++) {
                const double z = y[k0 + q], *row = B + q * c;
#pragma omp simd
                for (int64_t m = 0; m < c; m++) g[m] += row[m] * z;
            }
            for (int64_t m = 0; m < c; m++) y[out[m]] -= g[m];
        }
    }
}

int64_t lu_runs_entries(const LuRuns *r) {
    return r->count > 0 ? r->bp[r->count] : 0;
}

void lu_runs_free(LuRuns *r) {
    nspd_free(&r->start);
    nspd_free(&r->cp);
    nspd_free(&r->idx);
    nspd_free(&r->bp);
    nspd_free(&r->bx);
    memset(r, 0, sizeof *r);
}
