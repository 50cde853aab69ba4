#include "core/shape_mesh.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct ShapeMesh {
    int64_t count;
    double *tri; /* 9 per triangle */
    double lo[3], hi[3];
    int grid[2];    /* bins over (y, z) */
    double h[2];    /* a bin's size */
    int64_t *first; /* the triangles of bin b: index[first[b] .. first[b + 1]) */
    int64_t *index;
};

/* ---- closedness: every edge of the welded vertices used twice ---- */

typedef struct {
    const double *v; /* x, y, z */
    int64_t at;      /* triangle corner: 3 t + c */
} Corner;

static int by_position(const void *a, const void *b) {
    const double *p = ((const Corner *)a)->v, *q = ((const Corner *)b)->v;
    for (int d = 0; d < 3; d++)
        if (p[d] != q[d]) return p[d] < q[d] ? -1 : 1;
    return 0;
}

typedef struct {
    int64_t a, b;
} Edge;

static int by_ends(const void *x, const void *y) {
    const Edge *p = x, *q = y;
    if (p->a != q->a) return p->a < q->a ? -1 : 1;
    if (p->b != q->b) return p->b < q->b ? -1 : 1;
    return 0;
}

static int check_closed(const ShapeMesh *m, char *why, size_t why_size) {
    const int64_t corners = 3 * m->count;
    Corner *c = NULL;
    int64_t *vertex = NULL;
    Edge *e = NULL;
    int status = nspd_alloc(&c, (size_t)corners, sizeof *c);
    if (status == NSPD_OK) status = nspd_alloc(&vertex, (size_t)corners, sizeof *vertex);
    if (status == NSPD_OK) status = nspd_alloc(&e, (size_t)corners, sizeof *e);
    if (status != NSPD_OK) goto done;
    for (int64_t k = 0; k < corners; k++) c[k] = (Corner){m->tri + 3 * k, k};
    qsort(c, (size_t)corners, sizeof *c, by_position);
    int64_t id = -1;
    for (int64_t k = 0; k < corners; k++) {
        if (k == 0 || by_position(&c[k - 1], &c[k]) != 0) id++;
        vertex[c[k].at] = id;
    }
    for (int64_t t = 0; t < m->count; t++)
        for (int j = 0; j < 3; j++) {
            const int64_t p = vertex[3 * t + j], q = vertex[3 * t + (j + 1) % 3];
            e[3 * t + j] = p < q ? (Edge){p, q} : (Edge){q, p};
        }
    qsort(e, (size_t)corners, sizeof *e, by_ends);
    for (int64_t k = 0; k < corners;) {
        int64_t n = 1;
        while (k + n < corners && by_ends(&e[k], &e[k + n]) == 0) n++;
        if (n != 2 || e[k].a == e[k].b) {
            snprintf(why, why_size,
                     "the surface is not closed: an edge is shared by %lld triangle%s; expected "
                     "each edge shared by exactly two (a watertight surface)",
                     (long long)n, n == 1 ? "" : "s");
            status = NSPD_FAIL(NSPD_ERR_INPUT, "%s", why);
            break;
        }
        k += n;
    }
done:
    nspd_free(&c);
    nspd_free(&vertex);
    nspd_free(&e);
    return status;
}

/* ---- the bins ---- */

static void bin_of(const ShapeMesh *m, double y, double z, int *i, int *j) {
    *i = (int)((y - m->lo[1]) / m->h[0]);
    *j = (int)((z - m->lo[2]) / m->h[1]);
    *i = *i < 0 ? 0 : *i >= m->grid[0] ? m->grid[0] - 1 : *i;
    *j = *j < 0 ? 0 : *j >= m->grid[1] ? m->grid[1] - 1 : *j;
}

static int build_bins(ShapeMesh *m) {
    const int g = (int)fmin(512.0, fmax(1.0, ceil(sqrt((double)m->count))));
    for (int a = 0; a < 2; a++) {
        m->grid[a] = g;
        const double span = m->hi[1 + a] - m->lo[1 + a];
        m->h[a] = span > 0.0 ? span / g : 1.0;
    }
    const int64_t bins = (int64_t)m->grid[0] * m->grid[1];
    TRY(nspd_alloc(&m->first, (size_t)bins + 1, sizeof(int64_t)));
    /* two passes: count, then fill */
    for (int pass = 0; pass < 2; pass++) {
        int64_t *fill = NULL;
        if (pass == 1) {
            for (int64_t b = 0; b < bins; b++) m->first[b + 1] += m->first[b];
            TRY(nspd_alloc(&m->index, (size_t)m->first[bins] + 1, sizeof(int64_t)));
            TRY(nspd_alloc(&fill, (size_t)bins, sizeof(int64_t)));
            for (int64_t b = 0; b < bins; b++) fill[b] = m->first[b];
        }
        for (int64_t t = 0; t < m->count; t++) {
            const double *v = m->tri + 9 * t;
            const double ylo = fmin(fmin(v[1], v[4]), v[7]), yhi = fmax(fmax(v[1], v[4]), v[7]);
            const double zlo = fmin(fmin(v[2], v[5]), v[8]), zhi = fmax(fmax(v[2], v[5]), v[8]);
            int i0, j0, i1, j1;
            bin_of(m, ylo, zlo, &i0, &j0);
            bin_of(m, yhi, zhi, &i1, &j1);
            for (int j = j0; j <= j1; j++)
                for (int i = i0; i <= i1; i++) {
                    const int64_t b = (int64_t)j * m->grid[0] + i;
                    if (pass == 0)
                        m->first[b + 1]++;
                    else
                        m->index[fill[b]++] = t;
                }
        }
        nspd_free(&fill);
    }
    return NSPD_OK;
}

int shape_mesh_create(const double *triangles, int64_t count, ShapeMesh **out, char *why,
                      size_t why_size) {
    *out = NULL;
    if (count < 4) {
        snprintf(why, why_size, "%lld triangles; expected a closed surface (at least 4)",
                 (long long)count);
        return NSPD_FAIL(NSPD_ERR_INPUT, "%s", why);
    }
    ShapeMesh *m;
    TRY(nspd_alloc(&m, 1, sizeof *m));
    m->count = count;
    int status = nspd_alloc(&m->tri, (size_t)(9 * count), sizeof(double));
    if (status == NSPD_OK) {
        memcpy(m->tri, triangles, (size_t)(9 * count) * sizeof(double));
        for (int d = 0; d < 3; d++) m->lo[d] = m->hi[d] = m->tri[d];
        for (int64_t k = 0; k < 3 * count; k++)
            for (int d = 0; d < 3; d++) {
                m->lo[d] = fmin(m->lo[d], m->tri[3 * k + d]);
                m->hi[d] = fmax(m->hi[d], m->tri[3 * k + d]);
            }
        for (int d = 0; d < 3 && status == NSPD_OK; d++)
            if (!(m->hi[d] > m->lo[d]) || !isfinite(m->hi[d] - m->lo[d])) {
                snprintf(why, why_size,
                         "the surface is flat or not finite along %c; expected a solid", "xyz"[d]);
                status = NSPD_FAIL(NSPD_ERR_INPUT, "%s", why);
            }
    }
    if (status == NSPD_OK) status = check_closed(m, why, why_size);
    if (status == NSPD_OK) status = build_bins(m);
    if (status != NSPD_OK) {
        shape_mesh_free(&m);
        return status;
    }
    *out = m;
    return NSPD_OK;
}

void shape_mesh_free(ShapeMesh **m) {
    if (!*m) return;
    nspd_free(&(*m)->tri);
    nspd_free(&(*m)->first);
    nspd_free(&(*m)->index);
    nspd_free(m);
}

/* 2D cross product (b - a) x (p - a) in the (y, z) plane, computed from
 * the edge's ends in one order whichever way it is walked, so that the two
 * triangles of an edge get exactly opposite values (else a point on the
 * edge can come out on the inside of both by rounding, and be counted
 * twice) */
static double edge_function(const double a[2], const double b[2], const double p[2]) {
    if (a[0] > b[0] || (a[0] == b[0] && a[1] > b[1])) return -edge_function(b, a, p);
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

/* the edge a -> b of a counter-clockwise shadow owns its points: left
 * edges (going down) and top edges (horizontal, going left) */
static bool top_left(const double a[2], const double b[2]) {
    const double du = b[0] - a[0], dv = b[1] - a[1];
    return dv < 0.0 || (dv == 0.0 && du < 0.0);
}

bool shape_mesh_contains(const ShapeMesh *m, const double p[3]) {
    for (int d = 0; d < 3; d++)
        if (!(p[d] >= m->lo[d] && p[d] <= m->hi[d])) return false;
    int i, j;
    bin_of(m, p[1], p[2], &i, &j);
    const int64_t b = (int64_t)j * m->grid[0] + i;
    const double q[2] = {p[1], p[2]};
    bool inside = false;
    for (int64_t k = m->first[b]; k < m->first[b + 1]; k++) {
        const double *v = m->tri + 9 * m->index[k];
        double s[3][2] = {{v[1], v[2]}, {v[4], v[5]}, {v[7], v[8]}};
        double x[3] = {v[0], v[3], v[6]};
        double area = edge_function(s[0], s[1], s[2]);
        if (area == 0.0) continue; /* edge-on to the ray: its neighbours count */
        if (area < 0.0) {          /* counter-clockwise */
            double t[2] = {s[1][0], s[1][1]};
            s[1][0] = s[2][0], s[1][1] = s[2][1], s[2][0] = t[0], s[2][1] = t[1];
            const double tx = x[1];
            x[1] = x[2], x[2] = tx;
            area = -area;
        }
        double w[3];
        bool hit = true;
        for (int e = 0; e < 3 && hit; e++) {
            const double *a = s[(e + 1) % 3], *c = s[(e + 2) % 3];
            w[e] = edge_function(a, c, q); /* the weight of vertex e */
            hit = w[e] > 0.0 || (w[e] == 0.0 && top_left(a, c));
        }
        if (!hit) continue;
        const double xh = (w[0] * x[0] + w[1] * x[1] + w[2] * x[2]) / area;
        if (xh == p[0]) return true; /* on the surface */
        if (xh > p[0]) inside = !inside;
    }
    return inside;
}

void shape_mesh_bounds(const ShapeMesh *m, double lo[3], double hi[3]) {
    for (int d = 0; d < 3; d++) lo[d] = m->lo[d], hi[d] = m->hi[d];
}

int64_t shape_mesh_triangles(const ShapeMesh *m) {
    return m->count;
}

/* ---- the section by a plane z = const ---- */

/* Where the edge a-b crosses z (its ends in one order, whichever triangle
 * asks, so both triangles of the edge get the same bits). */
static void crossing(const double *a, const double *b, double z, double out[2]) {
    if (a[0] > b[0] || (a[0] == b[0] && (a[1] > b[1] || (a[1] == b[1] && a[2] > b[2])))) {
        const double *t = a;
        a = b, b = t;
    }
    const double w = (z - a[2]) / (b[2] - a[2]);
    out[0] = a[0] + w * (b[0] - a[0]);
    out[1] = a[1] + w * (b[1] - a[1]);
}

typedef struct {
    double p[2], q[2]; /* from p to q */
    int used;
} Segment;

static bool same_point(const double a[2], const double b[2]) {
    return a[0] == b[0] && a[1] == b[1];
}

static int by_start(const void *x, const void *y) {
    const double *a = ((const Segment *)x)->p, *b = ((const Segment *)y)->p;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    if (a[1] != b[1]) return a[1] < b[1] ? -1 : 1;
    return 0;
}

int shape_mesh_section(const ShapeMesh *m, double z, double **xy, int *count, char *why,
                       size_t why_size) {
    *xy = NULL;
    *count = 0;
    Segment *seg;
    TRY(nspd_alloc(&seg, (size_t)m->count, sizeof *seg));
    int64_t n = 0;
    for (int64_t t = 0; t < m->count; t++) {
        const double *v[3] = {m->tri + 9 * t, m->tri + 9 * t + 3, m->tri + 9 * t + 6};
        int above = 0;
        for (int k = 0; k < 3; k++) above += v[k][2] >= z;
        if (above == 0 || above == 3) continue;
        /* the lone vertex (the one on its own side) and the two edges from it */
        int lone = 0;
        for (int k = 0; k < 3; k++)
            if ((v[k][2] >= z) == (above == 1)) lone = k;
        const double *o = v[lone], *a = v[(lone + 1) % 3], *b = v[(lone + 2) % 3];
        Segment s = {{0, 0}, {0, 0}, 0};
        crossing(o, a, z, s.p);
        crossing(o, b, z, s.q);
        /* every segment the same way round: turned so that the triangle's
         * normal n = (a - o) x (b - o) (outward, the STL convention) points
         * to its right, so that chaining by start points follows the loop
         * (counter-clockwise); a triangle wound against its neighbours
         * breaks the chain and is reported */
        const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
        const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
        const double nx = ay * bz - az * by, ny = az * bx - ax * bz;
        const double dx = s.q[0] - s.p[0], dy = s.q[1] - s.p[1];
        if (nx * dy - ny * dx < 0.0) { /* n to the left of p -> q: turn it */
            const double t0 = s.p[0], t1 = s.p[1];
            s.p[0] = s.q[0], s.p[1] = s.q[1], s.q[0] = t0, s.q[1] = t1;
        }
        if (!same_point(s.p, s.q)) seg[n++] = s;
    }
    int status = NSPD_OK;
    if (n < 3) {
        snprintf(why, why_size,
                 "the plane z = %g cuts the surface in %lld segments; expected a "
                 "closed section (at least 3)",
                 z, (long long)n);
        status = NSPD_FAIL(NSPD_ERR_INPUT, "%s", why);
    }
    if (status == NSPD_OK) {
        qsort(seg, (size_t)n, sizeof *seg, by_start);
        status = nspd_alloc(xy, (size_t)(2 * n), sizeof(double));
    }
    int64_t k = 0, len = 0;
    while (status == NSPD_OK) {
        seg[k].used = 1;
        (*xy)[2 * len] = seg[k].p[0], (*xy)[2 * len + 1] = seg[k].p[1];
        len++;
        if (same_point(seg[k].q, seg[0].p)) break; /* the loop closed */
        /* the segment that starts where this one ends */
        int64_t lo = 0, hi = n;
        Segment key = {{seg[k].q[0], seg[k].q[1]}, {0, 0}, 0};
        while (lo < hi) {
            const int64_t mid = (lo + hi) / 2;
            if (by_start(&seg[mid], &key) < 0)
                lo = mid + 1;
            else
                hi = mid;
        }
        if (lo == n || !same_point(seg[lo].p, key.p) || seg[lo].used) {
            snprintf(why, why_size,
                     "the section at z = %g does not close (a segment ends where "
                     "none starts); expected a watertight, consistently wound surface",
                     z);
            status = NSPD_FAIL(NSPD_ERR_INPUT, "%s", why);
            break;
        }
        k = lo;
    }
    if (status == NSPD_OK && len != n) {
        snprintf(why, why_size,
                 "the plane z = %g cuts the surface in more than one loop (%lld "
                 "of %lld segments in the first); expected one body's section",
                 z, (long long)len, (long long)n);
        status = NSPD_FAIL(NSPD_ERR_INPUT, "%s", why);
    }
    nspd_free(&seg);
    if (status != NSPD_OK) {
        nspd_free(xy);
        return status;
    }
    *count = (int)len;
    return NSPD_OK;
}
