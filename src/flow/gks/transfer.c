/* The GKS flow's side of a volumetric coupling (flow.h FlowOps.transfer,
 * lumped, add_lumped): weights from points to cells on the stretched grid,
 * and the cells' mass and momentum per metre of depth. */
#include "flow/gks/transfer.h"

#include <math.h>

/* x on a periodic axis brought into [lo, hi). */
static double wrap(const GridAxis *a, double x) {
    const double L = a->hi - a->lo;
    double t = fmod(x - a->lo, L);
    if (t < 0) t += L;
    return a->lo + t;
}

/* One axis's weights of the point at x: up to 3 cells idx[] with weights
 * w[] (idx -1, w 0 where unused); false for a point off the axis. A
 * neighbour past a wall folds its weight onto the edge cell, so the weights
 * always sum to 1; a periodic axis wraps. */
static bool axis_weights(const GridAxis *a, FlowTransferKind kind, double x, int idx[3],
                         double w[3]) {
    for (int k = 0; k < 3; k++) idx[k] = -1, w[k] = 0.0;
    if (a->periodic && isfinite(x)) x = wrap(a, x);
    if (!(x >= a->lo && x <= a->hi)) return false;
    const int n = a->n;
    const double L = a->hi - a->lo;
    if (kind == FLOW_TRANSFER_NEAREST) {
        idx[0] = grid_axis_cell_of(a, x), w[0] = 1.0;
        return true;
    }
    if (kind == FLOW_TRANSFER_BILINEAR) {
        const int b = grid_axis_bracket(a, x); /* -1 .. n-1 */
        if ((b < 0 || b == n - 1) && !a->periodic) {
            idx[0] = b < 0 ? 0 : n - 1, w[0] = 1.0;
            return true;
        }
        const int i0 = b < 0 ? n - 1 : b, i1 = b == n - 1 ? 0 : b + 1;
        const double c0 = b < 0 ? a->center[n - 1] - L : a->center[i0];
        const double c1 = b == n - 1 ? a->center[0] + L : a->center[i1];
        const double t = (x - c0) / (c1 - c0);
        idx[0] = i0, w[0] = 1.0 - t;
        idx[1] = i1, w[1] = t;
        if (i1 == i0) idx[1] = -1, w[0] = 1.0, w[1] = 0.0; /* one cell on the axis */
        return true;
    }
    /* quadratic B-spline centred on the cell that holds x, in that cell's
     * own width (exact on uniform grids; a partition of unity always) */
    const int i = grid_axis_cell_of(a, x);
    const double s = (x - a->center[i]) * a->inv_width[i];
    const double wl = 0.5 * (0.5 - s) * (0.5 - s), wr = 0.5 * (0.5 + s) * (0.5 + s);
    idx[1] = i, w[1] = 1.0 - wl - wr;
    int left = i - 1, right = i + 1;
    if (a->periodic) {
        left = (left + n) % n, right = right % n;
    }
    if (left >= 0 && left != i)
        idx[0] = left, w[0] = wl;
    else
        w[1] += wl;
    if (right < n && right != i && right != left)
        idx[2] = right, w[2] = wr;
    else
        w[1] += wr;
    return true;
}

void gks_transfer(const Grid *g, const uint8_t *kind, FlowTransferKind mode, int64_t n,
                  const double *x, const double *y, int64_t *cell, double *w) {
    const int width = flow_transfer_width(mode), per = width == 1 ? 1 : width == 4 ? 2 : 3;
    for (int64_t p = 0; p < n; p++) {
        int64_t *pc = cell + p * width;
        double *pw = w + p * width;
        for (int k = 0; k < width; k++) pc[k] = -1, pw[k] = 0.0;
        int ix[3], iy[3];
        double wx[3], wy[3];
        if (!axis_weights(&g->ax[0], mode, x[p], ix, wx) ||
            !axis_weights(&g->ax[1], mode, y[p], iy, wy))
            continue;
        /* the entries in a fixed order; cells that hold no gas (a fixed
         * body's) are left out and the rest renormalised */
        double sum = 0.0;
        int m = 0;
        for (int b = 0; b < per; b++)
            for (int a = 0; a < per; a++) {
                if (ix[a] < 0 || iy[b] < 0) continue;
                const int64_t c = grid_index(g, ix[a], iy[b]);
                if (kind[c] != FLOW_CELL_FLUID) continue;
                pc[m] = c, pw[m] = wx[a] * wy[b];
                sum += pw[m++];
            }
        if (!(sum > 0.0)) {
            for (int k = 0; k < width; k++) pc[k] = -1, pw[k] = 0.0;
            continue;
        }
        if (sum != 1.0)
            for (int k = 0; k < m; k++) pw[k] /= sum;
    }
}

/* The area of cell c (an index of grid_index). */
static double cell_area(const Grid *g, int64_t c) {
    const int j = (int)(c / g->stride) - GRID_NG, i = (int)(c % g->stride) - GRID_NG;
    return g->ax[0].width[i] * g->ax[1].width[j];
}

void gks_lumped(const Grid *g, const GksFields *f, int64_t n, const int64_t *cells, double *mass,
                double *momentum_x, double *momentum_y) {
    for (int64_t k = 0; k < n; k++) {
        const int64_t c = cells[k];
        const double area = cell_area(g, c);
        mass[k] = f->w[0][c] * area;
        momentum_x[k] = f->w[1][c] * area;
        momentum_y[k] = f->w[2][c] * area;
    }
}

void gks_lumped_volume(const Grid *g, int64_t n, const int64_t *cells, double *volume) {
    for (int64_t k = 0; k < n; k++) volume[k] = cell_area(g, cells[k]);
}

void gks_add_lumped(const Grid *g, GksFields *f, int64_t n, const int64_t *cells, const double *dmx,
                    const double *dmy, const double *de) {
    for (int64_t k = 0; k < n; k++) {
        const int64_t c = cells[k];
        const double inv_area = 1.0 / cell_area(g, c);
        if (dmx) f->w[1][c] += dmx[k] * inv_area;
        if (dmy) f->w[2][c] += dmy[k] * inv_area;
        if (de) f->w[3][c] += de[k] * inv_area;
    }
}
