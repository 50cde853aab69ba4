/* Stretched Cartesian grid: segment layout and ghost geometry. */
#include "flow/gks/grid.h"

#include "core/search.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

/* Sum of a geometric progression with first term h and ratio r, n terms. */
static double progression_sum(double h, double r, int n) {
    if (fabs(r - 1.0) < 1e-12) return h * n;
    return h * (pow(r, n) - 1.0) / (r - 1.0);
}

/* Ratio r with progression_sum(h, r, n) = L (monotone in r: bisection in log r). */
static double solve_ratio(double h, int n, double L) {
    if (n <= 1) return 1.0;
    double lo = -20.0 / n, hi = 20.0 / n; /* log r */
    for (int it = 0; it < 200; it++) {
        const double mid = 0.5 * (lo + hi);
        if (progression_sum(h, exp(mid), n) < L)
            lo = mid;
        else
            hi = mid;
    }
    return exp(0.5 * (lo + hi));
}

static bool segment_uniform(const GridSegment *s) {
    return !(s->h_end > 0.0) || s->h_end == s->h_start;
}

double grid_segment_cells(const GridSegment *s) {
    if (s->cells > 0) return s->cells;
    const double L = s->length, a = s->h_start, b = s->h_end;
    if (segment_uniform(s)) return fmax(1.0, round(L / a));
    return fmax(1.0, round(1.0 + log(b / a) / log((L - a) / (L - b))));
}

static int segment_cells(const GridSegment *s, int *n, double *h0, double *ratio) {
    const double L = s->length;
    if (!(L > 0.0)) return NSPD_FAIL(NSPD_ERR_INPUT, "grid segment length must be > 0 (got %g)", L);
    const bool uniform = segment_uniform(s);
    const double a = s->h_start, b = s->h_end;
    if (uniform && !(s->cells > 0) && !(a > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "uniform grid segment needs a spacing > 0 or a cell count");
    if (!uniform && (!(a > 0.0) || a >= L || b >= L))
        return NSPD_FAIL(
            NSPD_ERR_INPUT,
            "stretched grid segment: spacings (%g, %g) must be > 0 and < its length %g", a, b, L);
    const double cells = grid_segment_cells(s);
    if (!(cells <= GRID_MAX_AXIS_CELLS)) /* NaN too */
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "a grid segment of %g m with spacing %g has %.3g cells; expected at most "
                         "%d",
                         L, a, cells, GRID_MAX_AXIS_CELLS);
    *n = (int)cells;
    if (uniform) {
        *h0 = L / *n;
        *ratio = 1.0;
        return NSPD_OK;
    }
    if (*n == 1) {
        *h0 = L;
        *ratio = 1.0;
        return NSPD_OK;
    }
    *h0 = a;
    *ratio = solve_ratio(a, *n, L);
    return NSPD_OK;
}

double grid_segments_min_spacing(int count, const GridSegment *segments) {
    double h_min = INFINITY;
    for (int k = 0; k < count; k++) {
        int n;
        double h0, ratio;
        if (segment_cells(&segments[k], &n, &h0, &ratio) != NSPD_OK) return 0.0;
        /* a progression's smallest spacing is at one of its ends */
        h_min = fmin(h_min, fmin(h0, h0 * pow(ratio, n - 1)));
    }
    return count > 0 ? h_min : 0.0;
}

int grid_segments_spacing(int count, const GridSegment *segments, double *h, int max) {
    if (count < 1) return NSPD_FAIL(NSPD_ERR_INPUT, "a grid axis needs at least one segment");
    int total = 0;
    for (int s = 0; s < count; s++) {
        int n = 0;
        double h0 = 0.0, r = 1.0;
        TRY(segment_cells(&segments[s], &n, &h0, &r));
        if (n > GRID_MAX_AXIS_CELLS - total)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "a grid axis of more than %d cells; expected at most %d",
                             GRID_MAX_AXIS_CELLS, GRID_MAX_AXIS_CELLS);
        /* Spacings from the progression, the last one adjusted by the
         * rounding residue so the segment ends exactly at its length. */
        double sum = 0.0, hk = h0;
        for (int k = 0; k < n; k++) {
            double v = k == n - 1 ? segments[s].length - sum : hk;
            if (h && total + k < max) h[total + k] = v;
            sum += hk;
            hk *= r;
        }
        total += n;
    }
    return total;
}

/* The six arrays of an axis of n cells (face has one more entry). */
static int axis_alloc(GridAxis *a, int n) {
    const int nt = n + 2 * GRID_NG;
    TRY(nspd_alloc(&a->block_, (size_t)(6 * (nt + 1)), sizeof(double)));
    double *p = a->block_;
    a->face = p + GRID_NG;
    p += nt + 1;
    a->center = p + GRID_NG;
    p += nt + 1;
    a->width = p + GRID_NG;
    p += nt + 1;
    a->inv_width = p + GRID_NG;
    p += nt + 1;
    a->inv_dl = p + GRID_NG;
    p += nt + 1;
    a->inv_dr = p + GRID_NG;
    a->n = n;
    return NSPD_OK;
}

int grid_axis_create(GridAxis *a, double lo, int count, const GridSegment *segments,
                     bool periodic) {
    memset(a, 0, sizeof *a);
    const int n = grid_segments_spacing(count, segments, NULL, 0);
    TRY(n);
    TRY(axis_alloc(a, n));
    a->periodic = periodic;
    grid_segments_spacing(count, segments, a->width, n);
    for (int k = 0; k < GRID_NG; k++) {
        a->width[-1 - k] = periodic ? a->width[n - 1 - k] : a->width[k];
        a->width[n + k] = periodic ? a->width[k] : a->width[n - 1 - k];
    }
    a->face[0] = lo;
    for (int i = 0; i < n; i++) a->face[i + 1] = a->face[i] + a->width[i];
    for (int k = 1; k <= GRID_NG; k++) {
        a->face[-k] = a->face[-k + 1] - a->width[-k];
        a->face[n + k] = a->face[n + k - 1] + a->width[n + k - 1];
    }
    for (int i = -GRID_NG; i < n + GRID_NG; i++) {
        a->center[i] = 0.5 * (a->face[i] + a->face[i + 1]);
        a->inv_width[i] = 1.0 / a->width[i];
    }
    for (int i = -GRID_NG; i < n + GRID_NG; i++) {
        /* centre distances from widths: exact for the ghost mirror images */
        if (i > -GRID_NG) a->inv_dl[i] = 2.0 / (a->width[i] + a->width[i - 1]);
        if (i < n + GRID_NG - 1) a->inv_dr[i] = 2.0 / (a->width[i] + a->width[i + 1]);
    }
    a->lo = lo;
    a->hi = a->face[n];
    return NSPD_OK;
}

/* Cells first .. first + n - 1 of axis a, with its ghost layers. */
static int axis_slice(GridAxis *out, const GridAxis *a, int first, int n) {
    memset(out, 0, sizeof *out);
    TRY(axis_alloc(out, n));
    out->periodic = a->periodic;
    for (int i = -GRID_NG; i <= n + GRID_NG; i++) out->face[i] = a->face[first + i];
    for (int i = -GRID_NG; i < n + GRID_NG; i++) {
        out->center[i] = a->center[first + i];
        out->width[i] = a->width[first + i];
        out->inv_width[i] = a->inv_width[first + i];
        /* the whole axis' ends have no outer neighbour */
        if (first + i > -GRID_NG) out->inv_dl[i] = a->inv_dl[first + i];
        if (first + i < a->n + GRID_NG - 1) out->inv_dr[i] = a->inv_dr[first + i];
    }
    out->lo = out->face[0];
    out->hi = out->face[n];
    return NSPD_OK;
}

void grid_axis_destroy(GridAxis *a) {
    nspd_free(&a->block_);
    memset(a, 0, sizeof *a);
}

int grid_create(Grid *g, double x0, int nsx, const GridSegment *sx, bool periodic_x, double y0,
                int nsy, const GridSegment *sy, bool periodic_y) {
    memset(g, 0, sizeof *g);
    TRY(grid_axis_create(&g->ax[0], x0, nsx, sx, periodic_x));
    int st = grid_axis_create(&g->ax[1], y0, nsy, sy, periodic_y);
    if (st < 0) {
        grid_axis_destroy(&g->ax[0]);
        return st;
    }
    g->nx = g->ax[0].n;
    g->ny = g->ax[1].n;
    g->stride = (g->nx + 2 * GRID_NG + 7) / 8 * 8;
    g->size = (int64_t)g->stride * (g->ny + 2 * GRID_NG);
    return NSPD_OK;
}

int grid_slice(Grid *out, const Grid *g, const int first[2], const int count[2]) {
    memset(out, 0, sizeof *out);
    const int n[2] = {g->nx, g->ny};
    for (int a = 0; a < 2; a++)
        if (first[a] < 0 || count[a] < GRID_NG || first[a] + count[a] > n[a])
            return NSPD_FAIL(NSPD_ERR_INTERNAL,
                             "grid: cells %d..%d of the %s axis are not a block of %d", first[a],
                             first[a] + count[a] - 1, a == 0 ? "x" : "y", n[a]);
    TRY(axis_slice(&out->ax[0], &g->ax[0], first[0], count[0]));
    const int st = axis_slice(&out->ax[1], &g->ax[1], first[1], count[1]);
    if (st < 0) {
        grid_axis_destroy(&out->ax[0]);
        return st;
    }
    out->nx = count[0];
    out->ny = count[1];
    out->stride = (out->nx + 2 * GRID_NG + 7) / 8 * 8;
    out->size = (int64_t)out->stride * (out->ny + 2 * GRID_NG);
    return NSPD_OK;
}

int grid_create_uniform(Grid *g, double x0, double x1, int nx, double y0, double y1, int ny,
                        bool periodic_x, bool periodic_y) {
    const GridSegment sx = {.length = x1 - x0, .cells = nx};
    const GridSegment sy = {.length = y1 - y0, .cells = ny};
    if (nx < 1 || ny < 1) return NSPD_FAIL(NSPD_ERR_INPUT, "grid needs at least 1 x 1 cells");
    return grid_create(g, x0, 1, &sx, periodic_x, y0, 1, &sy, periodic_y);
}

void grid_destroy(Grid *g) {
    grid_axis_destroy(&g->ax[0]);
    grid_axis_destroy(&g->ax[1]);
    memset(g, 0, sizeof *g);
}

int grid_axis_cell_of(const GridAxis *a, double x) {
    return search_bracket(a->face, 0, a->n, x);
}

int grid_axis_bracket(const GridAxis *a, double x) {
    return search_bracket(a->center, -1, a->n, x);
}
