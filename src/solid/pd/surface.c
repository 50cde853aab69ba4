/* Surface loops of a 2D PD body by Moore-neighbour tracing.
 *
 * The lattice indices of the points give a binary image (occupied or not)
 * with a one-pixel empty border. Its 8-connected parts are labelled by a
 * flood fill; each part's outer boundary is traced from its lowest, leftmost
 * pixel: standing on boundary pixel p, having come from the empty pixel b,
 * visit p's eight neighbours clockwise starting at b; the first occupied one
 * is the next boundary pixel, and the empty one visited just before it is the
 * new b. Jacob's stopping rule ends the trace when the start pixel is entered
 * again from the same side as at the beginning, so thin spikes (a pixel with
 * one neighbour) are walked out and back instead of ending the loop early.
 * The loop is then oriented counter-clockwise by its signed area. */
#include "solid/pd/surface.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

/* The eight neighbours, clockwise starting east (image with y up). */
static const int DI[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int DJ[8] = {0, -1, -1, -1, 0, 1, 1, 1};

typedef struct {
    int32_t imin, jmin;
    int nx, ny;     /* image size including the border */
    int32_t *owner; /* pixel -> point index, -1 empty */
    int32_t *label; /* pixel -> connected part, -1 empty */
} LatticeImage;

static int64_t pix(const LatticeImage *im, int i, int j) {
    return (int64_t)j * im->nx + i;
}

static int image_build(const PdPoints *b, LatticeImage *im) {
    int32_t imax = INT32_MIN, jmax = INT32_MIN;
    im->imin = im->jmin = INT32_MAX;
    for (int64_t p = 0; p < b->n; p++) {
        int32_t i = b->lattice[0][p], j = b->lattice[1][p];
        im->imin = i < im->imin ? i : im->imin;
        im->jmin = j < im->jmin ? j : im->jmin;
        imax = i > imax ? i : imax;
        jmax = j > jmax ? j : jmax;
    }
    im->nx = imax - im->imin + 3;
    im->ny = jmax - im->jmin + 3;
    size_t size = (size_t)im->nx * (size_t)im->ny;
    TRY(nspd_alloc(&im->owner, size, sizeof(int32_t)));
    TRY(nspd_alloc(&im->label, size, sizeof(int32_t)));
    for (size_t k = 0; k < size; k++) im->owner[k] = im->label[k] = -1;
    for (int64_t p = 0; p < b->n; p++)
        im->owner[pix(im, b->lattice[0][p] - im->imin + 1, b->lattice[1][p] - im->jmin + 1)] =
            (int32_t)p;
    return NSPD_OK;
}

/* Labels the 8-connected parts; returns their number. `stack` has room for
 * every pixel. */
static int label_parts(LatticeImage *im, int64_t *stack) {
    int parts = 0;
    for (int64_t start = 0; start < (int64_t)im->nx * im->ny; start++) {
        if (im->owner[start] < 0 || im->label[start] >= 0) continue;
        int64_t top = 0;
        stack[top++] = start;
        im->label[start] = parts;
        while (top > 0) {
            int64_t k = stack[--top];
            int i = (int)(k % im->nx), j = (int)(k / im->nx);
            for (int d = 0; d < 8; d++) {
                int64_t q = pix(im, i + DI[d], j + DJ[d]);
                if (im->owner[q] >= 0 && im->label[q] < 0) {
                    im->label[q] = parts;
                    stack[top++] = q;
                }
            }
        }
        parts++;
    }
    return parts;
}

/* Direction index from pixel (i, j) to its neighbour (i2, j2). */
static int direction(int i, int j, int i2, int j2) {
    for (int d = 0; d < 8; d++)
        if (i + DI[d] == i2 && j + DJ[d] == j2) return d;
    return -1;
}

/* Traces the part `part` from its start pixel (lowest row, leftmost); writes
 * the pixels' points into out (capacity `cap`) and returns their number. */
static int64_t trace(const LatticeImage *im, int part, int64_t start, int32_t *out, int64_t cap) {
    int si = (int)(start % im->nx), sj = (int)(start / im->nx);
    int pi = si, pj = sj;
    int bi = si, bj = sj - 1; /* the pixel below the lowest row is empty */
    int64_t count = 0;
    int first_next = -1;
    for (;;) {
        if (count < cap) out[count] = im->owner[pix(im, pi, pj)];
        count++;
        int d0 = direction(pi, pj, bi, bj), next = -1;
        int prev_i = bi, prev_j = bj;
        for (int k = 1; k <= 8; k++) {
            int d = (d0 + k) % 8, qi = pi + DI[d], qj = pj + DJ[d];
            int64_t q = pix(im, qi, qj);
            if (im->owner[q] >= 0 && im->label[q] == part) {
                next = d;
                break;
            }
            prev_i = qi;
            prev_j = qj;
        }
        if (next < 0) return count; /* a single isolated pixel */
        if (pi == si && pj == sj) {
            if (first_next < 0)
                first_next = next;
            else if (next == first_next)
                return count - 1; /* Jacob: back where we began */
        }
        bi = prev_i;
        bj = prev_j;
        pi += DI[next];
        pj += DJ[next];
        if (count > 4 * cap + 8) return -1; /* cannot happen on a finite image */
    }
}

int pd_surface_trace(const PdPoints *body, PdSurface *s) {
    memset(s, 0, sizeof *s);
    if (body->dim != 2)
        return NSPD_FAIL(NSPD_ERR_INPUT, "a PD surface for the immersed boundary needs a 2D body");
    LatticeImage im = {0};
    int64_t *stack = NULL;
    int32_t *buf = NULL;
    int64_t *starts = NULL;
    int status = image_build(body, &im);
    size_t pixels = (size_t)im.nx * (size_t)im.ny;
    if (status == NSPD_OK) status = nspd_alloc(&stack, pixels, sizeof(int64_t));
    int parts = status == NSPD_OK ? label_parts(&im, stack) : 0;
    /* a loop visits each boundary pixel at most 4 times (thin parts) */
    int64_t cap = 4 * body->n + 8;
    if (status == NSPD_OK) status = nspd_alloc(&buf, (size_t)cap, sizeof(int32_t));
    if (status == NSPD_OK) status = nspd_alloc(&starts, (size_t)parts + 1, sizeof(int64_t));
    if (status == NSPD_OK) status = nspd_alloc(&s->loop_start, (size_t)parts + 1, sizeof(int64_t));
    /* start pixel of each part: the first in row-major order (lowest row, leftmost) */
    for (int p = 0; p < parts && status == NSPD_OK; p++) starts[p] = -1;
    for (int64_t k = 0; k < (int64_t)pixels && status == NSPD_OK; k++)
        if (im.label[k] >= 0 && starts[im.label[k]] < 0) starts[im.label[k]] = k;
    int64_t used = 0;
    for (int p = 0; p < parts && status == NSPD_OK; p++) {
        int64_t count = trace(&im, p, starts[p], buf + used, cap - used);
        if (count < 0 || used + count > cap) {
            status = NSPD_FAIL(NSPD_ERR_INTERNAL, "surface tracing did not close a loop");
            break;
        }
        if (count < 3) continue; /* fragments of one or two points carry no surface */
        /* counter-clockwise: positive signed area */
        double area = 0.0;
        for (int64_t m = 0; m < count; m++) {
            int32_t a = buf[used + m], c = buf[used + (m + 1) % count];
            area += body->x[0][a] * body->x[1][c] - body->x[0][c] * body->x[1][a];
        }
        if (area < 0)
            for (int64_t m = 0; m < count / 2; m++) {
                int32_t t = buf[used + m];
                buf[used + m] = buf[used + count - 1 - m];
                buf[used + count - 1 - m] = t;
            }
        s->loop_start[s->loop_count++] = used;
        used += count;
    }
    if (status == NSPD_OK) {
        s->loop_start[s->loop_count] = used;
        s->length = used;
        status = nspd_alloc(&s->point, (size_t)used, sizeof(int32_t));
        if (status == NSPD_OK && used) memcpy(s->point, buf, (size_t)used * sizeof(int32_t));
    }
    nspd_free(&im.owner);
    nspd_free(&im.label);
    nspd_free(&stack);
    nspd_free(&buf);
    nspd_free(&starts);
    if (status != NSPD_OK) pd_surface_free(s);
    return status;
}

void pd_surface_free(PdSurface *s) {
    nspd_free(&s->loop_start);
    nspd_free(&s->point);
    memset(s, 0, sizeof *s);
}

void pd_surface_positions(const PdPoints *b, const PdSurface *s, double *x, double *y, double *vx,
                          double *vy) {
    for (int64_t m = 0; m < s->length; m++) {
        int32_t i = s->point[m];
        x[m] = b->x[0][i] + b->u[0][i];
        y[m] = b->x[1][i] + b->u[1][i];
        if (vx) vx[m] = b->v[0][i];
        if (vy) vy[m] = b->v[1][i];
    }
}

void pd_surface_apply_tractions(PdPoints *b, const PdSurface *s, const double *tx, const double *ty,
                                double total[2]) {
    total[0] = total[1] = 0.0;
    const double depth = b->thickness;
    for (int k = 0; k < s->loop_count; k++) {
        int64_t lo = s->loop_start[k], hi = s->loop_start[k + 1];
        for (int64_t m = lo; m < hi; m++) {
            int32_t a = s->point[m], c = s->point[m + 1 < hi ? m + 1 : lo];
            double dx = b->x[0][c] + b->u[0][c] - b->x[0][a] - b->u[0][a];
            double dy = b->x[1][c] + b->u[1][c] - b->x[1][a] - b->u[1][a];
            double len = sqrt(dx * dx + dy * dy);
            double fx = tx[m] * len, fy = ty[m] * len; /* N per metre of depth */
            total[0] += fx;
            total[1] += fy;
            /* half to each end, as a force density: F/2 / (V / depth) */
            b->external[0][a] += 0.5 * fx * depth / b->volume[a];
            b->external[1][a] += 0.5 * fy * depth / b->volume[a];
            b->external[0][c] += 0.5 * fx * depth / b->volume[c];
            b->external[1][c] += 0.5 * fy * depth / b->volume[c];
        }
    }
}
