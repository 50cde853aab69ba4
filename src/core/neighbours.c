/* Cell-list neighbour search.
 *
 * Points are binned into cubic cells of side >= horizon, so every neighbour
 * of a point lies in its own cell or an adjacent one (3^dim cells). Two
 * passes over the same loop: count, then fill; each row is then sorted by
 * neighbour index so the loops over a family walk memory forward. The comparison
 * uses horizon^2 (1 + 1e-12): lattice distances that equal the horizon up to
 * round-off are in, which matters only for horizon factors without the usual
 * 0.015 margin. */
#include "core/neighbours.h"
#include "core/parallel.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdlib.h>

typedef struct {
    int dim;
    int64_t ncell[3];
    double lo[3], size;
    int64_t *cell_start; /* ncells + 1 */
    int32_t *cell_points;
} CellList;

static int64_t cell_coord(const CellList *cl, double x, int d) {
    int64_t c = (int64_t)floor((x - cl->lo[d]) / cl->size);
    if (c < 0) c = 0;
    if (c >= cl->ncell[d]) c = cl->ncell[d] - 1;
    return c;
}

static int64_t cell_of(const CellList *cl, const double *const x[3], int64_t i) {
    int64_t c = 0;
    for (int d = cl->dim - 1; d >= 0; d--) c = c * cl->ncell[d] + cell_coord(cl, x[d][i], d);
    return c;
}

static int cells_build(CellList *cl, int64_t n, int dim, const double *const x[3], double size) {
    cl->dim = dim;
    cl->size = size;
    int64_t ncells = 1;
    for (int d = 0; d < dim; d++) {
        double lo = x[d][0], hi = x[d][0];
        for (int64_t i = 1; i < n; i++) {
            lo = fmin(lo, x[d][i]);
            hi = fmax(hi, x[d][i]);
        }
        cl->lo[d] = lo;
        cl->ncell[d] = (int64_t)((hi - lo) / size) + 1;
        ncells *= cl->ncell[d];
    }
    for (int d = dim; d < 3; d++) cl->ncell[d] = 1;
    if (ncells > 4 * n + 64) {
        /* a sparse body in a huge box: coarser cells keep memory bounded */
        double grow = pow((double)ncells / (double)(4 * n + 64), 1.0 / dim);
        return cells_build(cl, n, dim, x, size * ceil(grow));
    }
    TRY(nspd_alloc(&cl->cell_start, (size_t)ncells + 1, sizeof(int64_t)));
    int status = nspd_alloc(&cl->cell_points, (size_t)n, sizeof(int32_t));
    if (status != NSPD_OK) {
        nspd_free(&cl->cell_start);
        return status;
    }
    for (int64_t i = 0; i < n; i++) cl->cell_start[cell_of(cl, x, i) + 1]++;
    for (int64_t c = 0; c < ncells; c++) cl->cell_start[c + 1] += cl->cell_start[c];
    int64_t *fill;
    status = nspd_alloc(&fill, (size_t)ncells, sizeof(int64_t));
    if (status != NSPD_OK) {
        nspd_free(&cl->cell_start);
        nspd_free(&cl->cell_points);
        return status;
    }
    for (int64_t i = 0; i < n; i++) {
        int64_t c = cell_of(cl, x, i);
        cl->cell_points[cl->cell_start[c] + fill[c]++] = (int32_t)i;
    }
    nspd_free(&fill);
    return NSPD_OK;
}

static int compare_int32(const void *a, const void *b) {
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return (x > y) - (x < y);
}

/* Visits the neighbours of the position at[] (point `self`, skipped, or
 * -1 for a query point); writes them to out (if not NULL) and returns
 * their number. */
static int64_t visit_at(const CellList *cl, const double *const x[3], const double at[3],
                        int64_t self, double r2, int32_t *out) {
    const int dim = cl->dim < 3 ? cl->dim : 3; /* at[] holds 3 (the analyser cannot tell) */
    int64_t c[3] = {0, 0, 0}, found = 0;
    for (int d = 0; d < dim; d++) c[d] = cell_coord(cl, at[d], d);
    int64_t klo = cl->dim == 3 ? c[2] - 1 : 0, khi = cl->dim == 3 ? c[2] + 1 : 0;
    for (int64_t k = klo; k <= khi; k++) {
        if (k < 0 || k >= cl->ncell[2]) continue;
        for (int64_t j = c[1] - 1; j <= c[1] + 1; j++) {
            if (j < 0 || j >= cl->ncell[1]) continue;
            for (int64_t ii = c[0] - 1; ii <= c[0] + 1; ii++) {
                if (ii < 0 || ii >= cl->ncell[0]) continue;
                int64_t cell = (k * cl->ncell[1] + j) * cl->ncell[0] + ii;
                for (int64_t s = cl->cell_start[cell]; s < cl->cell_start[cell + 1]; s++) {
                    int32_t p = cl->cell_points[s];
                    if (p == self) continue;
                    double d2 = 0.0;
                    for (int d = 0; d < dim; d++) {
                        double e = x[d][p] - at[d];
                        d2 += e * e;
                    }
                    if (d2 <= r2) {
                        if (out) out[found] = p;
                        found++;
                    }
                }
            }
        }
    }
    return found;
}

/* Visits the neighbours of point i (visit_at). */
static int64_t visit(const CellList *cl, const double *const x[3], int64_t i, double r2,
                     int32_t *out) {
    double at[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < cl->dim; d++) at[d] = x[d][i];
    return visit_at(cl, x, at, i, r2, out);
}

int neighbours_find(int64_t n, int dim, const double *const x[3], double horizon, int64_t **first,
                    int32_t **nbr) {
    return neighbours_find_rows(n, dim, x, horizon, NULL, first, nbr);
}

int neighbours_find_rows(int64_t n, int dim, const double *const x[3], double horizon,
                         const uint8_t *rows, int64_t **first, int32_t **nbr) {
    CellList cl = {0};
    TRY(cells_build(&cl, n, dim, x, horizon));
    double r2 = horizon * horizon * (1.0 + 1e-12);
    int status = nspd_alloc(first, (size_t)n + 1, sizeof(int64_t));
    if (status == NSPD_OK) {
        int64_t *f = *first;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < n; i++)
            f[i + 1] = !rows || rows[i] ? visit(&cl, x, i, r2, NULL) : 0;
        for (int64_t i = 0; i < n; i++) f[i + 1] += f[i];
        /* at least one entry: a body without bonds still gets an array,
         * so that b + f[i] below is never an offset from NULL */
        status = nspd_alloc(nbr, (size_t)(f[n] > 0 ? f[n] : 1), sizeof(int32_t));
    }
    if (status == NSPD_OK) {
        int64_t *f = *first;
        int32_t *b = *nbr;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < n; i++) {
            if (rows && !rows[i]) continue;
            visit(&cl, x, i, r2, b + f[i]);
            qsort(b + f[i], (size_t)(f[i + 1] - f[i]), sizeof(int32_t), compare_int32);
        }
    } else {
        nspd_free(first);
    }
    nspd_free(&cl.cell_start);
    nspd_free(&cl.cell_points);
    return status;
}

int neighbours_query(int64_t n, int dim, const double *const x[3], int64_t m,
                     const double *const q[3], double horizon, int64_t **first, int32_t **nbr) {
    CellList cl = {0};
    TRY(cells_build(&cl, n, dim, x, horizon));
    const double r2 = horizon * horizon * (1.0 + 1e-12);
    int status = nspd_alloc(first, (size_t)m + 1, sizeof(int64_t));
    for (int pass = 0; pass < 2 && status == NSPD_OK; pass++) {
        int64_t *f = *first;
        for (int64_t i = 0; i < m; i++) {
            double at[3] = {0.0, 0.0, 0.0};
            for (int d = 0; d < dim; d++) at[d] = q[d][i];
            if (pass == 0) {
                f[i + 1] = f[i] + visit_at(&cl, x, at, -1, r2, NULL);
            } else {
                visit_at(&cl, x, at, -1, r2, *nbr + f[i]);
                qsort(*nbr + f[i], (size_t)(f[i + 1] - f[i]), sizeof(int32_t), compare_int32);
            }
        }
        if (pass == 0) status = nspd_alloc(nbr, (size_t)f[m], sizeof(int32_t));
    }
    if (status != NSPD_OK) nspd_free(first);
    nspd_free(&cl.cell_start);
    nspd_free(&cl.cell_points);
    return status;
}
