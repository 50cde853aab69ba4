/* Sampling a stored flow field (field_sample.h). */
#include "flow/gks/field_sample.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/search.h"
#include "flow/gks/grid.h"

#include <string.h>

/* Index of the first face that does not increase, or -1. */
static int first_unordered(const double *f, int n) {
    for (int i = 0; i < n; i++)
        if (!(f[i + 1] > f[i])) return i;
    return -1;
}

int flow_field_source_create(FlowFieldSource *src, int nx, int ny, const double *xf,
                             const double *yf) {
    memset(src, 0, sizeof *src);
    if (nx < 1 || ny < 1) return NSPD_FAIL(NSPD_ERR_INPUT, "a field of %d x %d cells", nx, ny);
    const int bad_x = first_unordered(xf, nx), bad_y = first_unordered(yf, ny);
    if (bad_x >= 0 || bad_y >= 0)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the field's %c faces do not increase at %d",
                         bad_x >= 0 ? 'x' : 'y', bad_x >= 0 ? bad_x : bad_y);
    const size_t n = (size_t)nx * (size_t)ny;
    src->nx = nx;
    src->ny = ny;
    int status = nspd_alloc(&src->xc, (size_t)nx, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&src->yc, (size_t)ny, sizeof(double));
    double **fields[4] = {&src->rho, &src->u, &src->v, &src->p};
    for (int k = 0; k < 4 && status == NSPD_OK; k++)
        status = nspd_alloc(fields[k], n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&src->valid, n, 1);
    if (status != NSPD_OK) {
        flow_field_source_free(src);
        return status;
    }
    memset(src->valid, 1, n);
    for (int i = 0; i < nx; i++) src->xc[i] = 0.5 * (xf[i] + xf[i + 1]);
    for (int j = 0; j < ny; j++) src->yc[j] = 0.5 * (yf[j] + yf[j + 1]);
    return NSPD_OK;
}

void flow_field_source_free(FlowFieldSource *src) {
    nspd_free(&src->xc);
    nspd_free(&src->yc);
    nspd_free(&src->rho);
    nspd_free(&src->u);
    nspd_free(&src->v);
    nspd_free(&src->p);
    nspd_free(&src->valid);
    memset(src, 0, sizeof *src);
}

/* The lower of the two centres bracketing x (clamped to [0, n-2]) and the
 * weight t of the upper one, in [0, 1]. */
static void bracket(const double *c, int n, double x, int *lo, double *t) {
    if (n == 1) {
        *lo = 0;
        *t = 0.0;
        return;
    }
    if (x <= c[0]) {
        *lo = 0;
        *t = 0.0;
        return;
    }
    if (x >= c[n - 1]) {
        *lo = n - 2;
        *t = 1.0;
        return;
    }
    const int a = search_bracket(c, 0, n - 1, x); /* c[a] <= x < c[a+1] */
    *lo = a;
    *t = (x - c[a]) / (c[a + 1] - c[a]);
}

void flow_field_sample(void *source, double x, double y, FlowPrim *out) {
    const FlowFieldSource *s = source;
    int i, j;
    double tx, ty;
    bracket(s->xc, s->nx, x, &i, &tx);
    bracket(s->yc, s->ny, y, &j, &ty);
    const int i1 = s->nx > 1 ? i + 1 : i, j1 = s->ny > 1 ? j + 1 : j;
    const int64_t node[4] = {(int64_t)j * s->nx + i, (int64_t)j * s->nx + i1,
                             (int64_t)j1 * s->nx + i, (int64_t)j1 * s->nx + i1};
    const double w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    double sum = 0.0, q[4] = {0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < 4; k++) {
        if (!s->valid[node[k]]) continue;
        sum += w[k];
        q[0] += w[k] * s->rho[node[k]];
        q[1] += w[k] * s->u[node[k]];
        q[2] += w[k] * s->v[node[k]];
        q[3] += w[k] * s->p[node[k]];
    }
    if (sum > 0.0) {
        out->rho = q[0] / sum;
        out->u = q[1] / sum;
        out->v = q[2] / sum;
        out->p = q[3] / sum;
        return;
    }
    /* the gas nodes carry no weight (the point is a body cell's centre) or
     * there are none: the nearest gas node, else the nearest node */
    int best = -1;
    double best_d2 = 0.0;
    for (int pass = 0; pass < 2 && best < 0; pass++)
        for (int k = 0; k < 4; k++) {
            if (pass == 0 && !s->valid[node[k]]) continue;
            const double dx = s->xc[k & 1 ? i1 : i] - x, dy = s->yc[k & 2 ? j1 : j] - y;
            const double d2 = dx * dx + dy * dy;
            if (best < 0 || d2 < best_d2) best = k, best_d2 = d2;
        }
    out->rho = s->rho[node[best]];
    out->u = s->u[node[best]];
    out->v = s->v[node[best]];
    out->p = s->p[node[best]];
}
