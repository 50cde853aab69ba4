/* Geometry queries on the walls: bucket grid, nearest wall point,
 * inside/outside, segment blocking, normals.
 *
 * Bucket grid. Square buckets of side b = sqrt(area of the walls' bounding
 * box / segments) (about one segment per bucket), over the bounding box grown
 * by two buckets, at most 2048 per axis. A segment is listed in every bucket
 * its bounding box touches, and in every bucket row its y-range meets.
 * Bucket indices come from floor((x - x0) / b), monotone in x, so a point of
 * a segment always falls in a bucket where the segment is listed.
 *
 * Nearest point: rings of buckets around the query's bucket; after ring k
 * every wall point closer than (k - 1) b has been seen (one ring of margin
 * for the rounding of the index), so the search stops when the best distance
 * is below that. Queries outside the bucket grid scan all segments. Ties
 * (equal distance) go to the lower segment index, so the result does not
 * depend on the order of the scan.
 *
 * Inside test: winding number (Sunday's crossing rule: an upward edge with
 * a.y <= y < b.y crossing to the right counts +1, a downward one -1), over
 * the segments of the query's bucket row; a point on a wall (exactly zero
 * cross product inside the segment's box) is inside. Multiple bodies: inside
 * any. The predicates are evaluated the same way for every query, so a point
 * gets the same answer whatever the order of the build (tested with points
 * on edges and vertices). */
#include "couple/ghost/ibm_internal.h"

#include "core/mem.h"
#include "core/status.h"
#include "flow/gks/solver.h"

#include <math.h>
#include <string.h>

void ibm_buckets_free(IbmBuckets *bk) {
    nspd_free(&bk->first);
    nspd_free(&bk->items);
    nspd_free(&bk->row_first);
    nspd_free(&bk->row_items);
    memset(bk, 0, sizeof *bk);
}

static inline int clampi(int v, int lo, int hi) {
    return v < lo ? lo : v > hi ? hi : v;
}

static inline int bucket_of(double v, double v0, double inv) {
    const double f = floor((v - v0) * inv);
    return f < -1e9 ? -1000000000 : f > 1e9 ? 1000000000 : (int)f;
}

/* The bucket rows j0..j1 and columns i0..i1 that segment s's bounding box
 * covers. */
static void segment_buckets(const Ibm *ibm, const IbmBuckets *bk, int s, int *i0, int *i1, int *j0,
                            int *j1) {
    const int e = ibm->seg_end[s];
    *i0 = bucket_of(fmin(ibm->mx[s], ibm->mx[e]), bk->x0, bk->inv_size);
    *i1 = bucket_of(fmax(ibm->mx[s], ibm->mx[e]), bk->x0, bk->inv_size);
    *j0 = bucket_of(fmin(ibm->my[s], ibm->my[e]), bk->y0, bk->inv_size);
    *j1 = bucket_of(fmax(ibm->my[s], ibm->my[e]), bk->y0, bk->inv_size);
}

int ibm_buckets_build(Ibm *ibm) {
    IbmBuckets *bk = &ibm->bk;
    const int ns = ibm->nm;
    double xlo = (double)INFINITY, xhi = -(double)INFINITY, ylo = (double)INFINITY,
           yhi = -(double)INFINITY;
    for (int s = 0; s < ns; s++) {
        xlo = fmin(xlo, ibm->mx[s]), xhi = fmax(xhi, ibm->mx[s]);
        ylo = fmin(ylo, ibm->my[s]), yhi = fmax(yhi, ibm->my[s]);
    }
    const double w = xhi - xlo, h = yhi - ylo;
    double b = sqrt(fmax(w * h, 1e-300) / (ns > 0 ? ns : 1));
    b = fmax(b, fmax(w, h) / 2048.0);
    b = fmax(b, 1e-12 * fmax(1.0, fmax(fabs(xhi), fabs(yhi))));
    const int nbx = (int)ceil(w / b) + 4, nby = (int)ceil(h / b) + 4;
    const int64_t nb = (int64_t)nbx * nby;
    bk->size = b;
    bk->inv_size = 1.0 / b;
    bk->x0 = xlo - 2.0 * b;
    bk->y0 = ylo - 2.0 * b;
    const bool grow = (int64_t)bk->nbx * bk->nby < nb || bk->nby < nby || !bk->first;
    bk->nbx = nbx;
    bk->nby = nby;
    if (grow) {
        nspd_free(&bk->first);
        nspd_free(&bk->row_first);
        TRY(nspd_alloc(&bk->first, (size_t)nb + 1, sizeof(int)));
        TRY(nspd_alloc(&bk->row_first, (size_t)nby + 1, sizeof(int)));
    }
    memset(bk->first, 0, ((size_t)nb + 1) * sizeof(int));
    memset(bk->row_first, 0, ((size_t)nby + 1) * sizeof(int));
    /* count */
    int64_t total = 0, rtotal = 0;
    for (int s = 0; s < ns; s++) {
        int i0, i1, j0, j1;
        segment_buckets(ibm, bk, s, &i0, &i1, &j0, &j1);
        for (int j = j0; j <= j1; j++) {
            bk->row_first[j + 1]++;
            rtotal++;
            for (int i = i0; i <= i1; i++) {
                bk->first[(int64_t)j * nbx + i + 1]++;
                total++;
            }
        }
    }
    if (total > bk->items_cap) {
        TRY(nspd_realloc(&bk->items, (size_t)bk->items_cap, (size_t)total, sizeof(int)));
        bk->items_cap = (int)total;
    }
    if (rtotal > bk->row_items_cap) {
        TRY(nspd_realloc(&bk->row_items, (size_t)bk->row_items_cap, (size_t)rtotal, sizeof(int)));
        bk->row_items_cap = (int)rtotal;
    }
    for (int64_t k = 0; k < nb; k++) bk->first[k + 1] += bk->first[k];
    for (int j = 0; j < nby; j++) bk->row_first[j + 1] += bk->row_first[j];
    /* fill in segment order, so every list is sorted */
    for (int s = 0; s < ns; s++) {
        int i0, i1, j0, j1;
        segment_buckets(ibm, bk, s, &i0, &i1, &j0, &j1);
        for (int j = j0; j <= j1; j++) {
            bk->row_items[bk->row_first[j]++] = s;
            for (int i = i0; i <= i1; i++) bk->items[bk->first[(int64_t)j * nbx + i]++] = s;
        }
    }
    /* the fill advanced each start to the next list's start: shift back */
    for (int64_t k = nb; k > 0; k--) bk->first[k] = bk->first[k - 1];
    bk->first[0] = 0;
    for (int j = nby; j > 0; j--) bk->row_first[j] = bk->row_first[j - 1];
    bk->row_first[0] = 0;
    return NSPD_OK;
}

/* Nearest point of segment s to (x, y) and its squared distance d2 (the
 * point's own distance d is left for the caller: 0). */
static inline IbmWallPoint seg_nearest(const Ibm *ibm, int s, double x, double y, double *d2) {
    const int e = ibm->seg_end[s];
    const double ax = ibm->mx[s], ay = ibm->my[s];
    const double ex = ibm->mx[e] - ax, ey = ibm->my[e] - ay;
    double tt = ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey);
    tt = tt < 0.0 ? 0.0 : tt > 1.0 ? 1.0 : tt;
    double px, py;
    if (tt == 0.0) {
        px = ax, py = ay;
    } else if (tt == 1.0) {
        px = ibm->mx[e], py = ibm->my[e];
    } else {
        px = ax + tt * ex, py = ay + tt * ey;
    }
    *d2 = (x - px) * (x - px) + (y - py) * (y - py);
    return (IbmWallPoint){.seg = s, .t = tt, .bx = px, .by = py, .d = 0.0};
}

/* Keeps segment s's nearest point in *best if it is closer than the best so
 * far (squared distance *bd2), or as close and on a lower segment. */
static inline void consider(const Ibm *ibm, int s, double x, double y, IbmWallPoint *best,
                            double *bd2) {
    double d2;
    const IbmWallPoint p = seg_nearest(ibm, s, x, y, &d2);
    if (d2 < *bd2 || (d2 == *bd2 && s < best->seg)) {
        *best = p;
        *bd2 = d2;
    }
}

IbmWallPoint ibm_nearest(const Ibm *ibm, double x, double y) {
    const IbmBuckets *bk = &ibm->bk;
    IbmWallPoint best = {.seg = -1, .t = 0.0, .bx = x, .by = y, .d = 0.0};
    double bd2 = (double)INFINITY;
    const int ci = bucket_of(x, bk->x0, bk->inv_size), cj = bucket_of(y, bk->y0, bk->inv_size);
    if (ci < 0 || cj < 0 || ci >= bk->nbx || cj >= bk->nby) {
        for (int s = 0; s < ibm->nm; s++) consider(ibm, s, x, y, &best, &bd2);
    } else {
        const int kmax = bk->nbx > bk->nby ? bk->nbx : bk->nby;
        for (int k = 0; k <= kmax; k++) {
            const int i0 = ci - k, i1 = ci + k, j0 = cj - k, j1 = cj + k;
            for (int j = j0 < 0 ? 0 : j0; j <= j1 && j < bk->nby; j++) {
                const bool edge_row = j == j0 || j == j1;
                for (int i = i0 < 0 ? 0 : i0; i <= i1 && i < bk->nbx; i++) {
                    if (!edge_row && i != i0 && i != i1) continue;
                    const int64_t q = (int64_t)j * bk->nbx + i;
                    for (int m = bk->first[q]; m < bk->first[q + 1]; m++)
                        consider(ibm, bk->items[m], x, y, &best, &bd2);
                }
            }
            if (best.seg >= 0 && k >= 1) {
                const double r = (k - 1) * bk->size;
                if (bd2 <= r * r) break;
            }
            if (i0 <= 0 && j0 <= 0 && i1 >= bk->nbx - 1 && j1 >= bk->nby - 1) break;
        }
    }
    best.d = sqrt(bd2);
    return best;
}

int ibm_point_inside(const Ibm *ibm, double x, double y) {
    const IbmBuckets *bk = &ibm->bk;
    const int r = bucket_of(y, bk->y0, bk->inv_size);
    if (r < 0 || r >= bk->nby) return 0;
    int wn = 0;
    for (int m = bk->row_first[r]; m < bk->row_first[r + 1]; m++) {
        const int s = bk->row_items[m], e = ibm->seg_end[s];
        const double ax = ibm->mx[s], ay = ibm->my[s], bx = ibm->mx[e], by = ibm->my[e];
        if (y < fmin(ay, by) || y > fmax(ay, by)) continue;
        const double cross = (bx - ax) * (y - ay) - (x - ax) * (by - ay);
        if (cross == 0.0 && x >= fmin(ax, bx) && x <= fmax(ax, bx)) return 1; /* on the wall */
        if (ay <= y) {
            if (by > y && cross > 0.0) wn++;
        } else if (by <= y && cross < 0.0) {
            wn--;
        }
    }
    return wn != 0;
}

static inline double orient(double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

static inline int on_box(double ax, double ay, double bx, double by, double cx, double cy) {
    return cx >= fmin(ax, bx) && cx <= fmax(ax, bx) && cy >= fmin(ay, by) && cy <= fmax(ay, by);
}

/* Segments p-q and a-b meet (closed segments). */
static int segments_meet(double px, double py, double qx, double qy, double ax, double ay,
                         double bx, double by) {
    const double o1 = orient(ax, ay, bx, by, px, py), o2 = orient(ax, ay, bx, by, qx, qy);
    const double o3 = orient(px, py, qx, qy, ax, ay), o4 = orient(px, py, qx, qy, bx, by);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return 1;
    if (o1 == 0 && on_box(ax, ay, bx, by, px, py)) return 1;
    if (o2 == 0 && on_box(ax, ay, bx, by, qx, qy)) return 1;
    if (o3 == 0 && on_box(px, py, qx, qy, ax, ay)) return 1;
    if (o4 == 0 && on_box(px, py, qx, qy, bx, by)) return 1;
    return 0;
}

int ibm_blocked(const Ibm *ibm, double px, double py, double qx, double qy) {
    const IbmBuckets *bk = &ibm->bk;
    int i0 = bucket_of(fmin(px, qx), bk->x0, bk->inv_size);
    int i1 = bucket_of(fmax(px, qx), bk->x0, bk->inv_size);
    int j0 = bucket_of(fmin(py, qy), bk->y0, bk->inv_size);
    int j1 = bucket_of(fmax(py, qy), bk->y0, bk->inv_size);
    if (i1 < 0 || j1 < 0 || i0 >= bk->nbx || j0 >= bk->nby) return 0;
    i0 = clampi(i0, 0, bk->nbx - 1), i1 = clampi(i1, 0, bk->nbx - 1);
    j0 = clampi(j0, 0, bk->nby - 1), j1 = clampi(j1, 0, bk->nby - 1);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const int64_t q = (int64_t)j * bk->nbx + i;
            for (int m = bk->first[q]; m < bk->first[q + 1]; m++) {
                const int s = bk->items[m], e = ibm->seg_end[s];
                if (segments_meet(px, py, qx, qy, ibm->mx[s], ibm->my[s], ibm->mx[e], ibm->my[e]))
                    return 1;
            }
        }
    return 0;
}

/* Outward normal of segment s (counter-clockwise walls). */
static inline void seg_normal(const Ibm *ibm, int s, double *nx, double *ny) {
    const int e = ibm->seg_end[s];
    const double ex = ibm->mx[e] - ibm->mx[s], ey = ibm->my[e] - ibm->my[s];
    const double l = hypot(ex, ey);
    *nx = ey / l;
    *ny = -ex / l;
}

void ibm_normal(const Ibm *ibm, const IbmWallPoint *w, double x, double y, int inside, double *nx,
                double *ny) {
    if (w->t > 0.0 && w->t < 1.0) {
        seg_normal(ibm, w->seg, nx, ny);
        return;
    }
    if (w->d > 0.0) {
        /* at a marker: the direction between the point and the marker */
        const double s = inside ? 1.0 / w->d : -1.0 / w->d;
        *nx = (w->bx - x) * s;
        *ny = (w->by - y) * s;
        return;
    }
    /* on a marker: mean of the two segment normals there */
    const int b = ibm->seg_body[w->seg];
    const int marker = w->t == 0.0 ? w->seg : ibm->seg_end[w->seg];
    const int prev = marker == ibm->first[b] ? ibm->first[b] + ibm->count[b] - 1 : marker - 1;
    double ax, ay, cx, cy;
    seg_normal(ibm, prev, &ax, &ay);
    seg_normal(ibm, marker, &cx, &cy);
    double mx = ax + cx, my = ay + cy, l = hypot(mx, my);
    if (!(l > 1e-12)) mx = cx, my = cy, l = 1.0;
    *nx = mx / l;
    *ny = my / l;
}

int ibm_node_kind(const Ibm *ibm, int i, int j) {
    const Grid *g = ibm->grid;
    /* box ghost layer: the kind of the image cell, as bc_fill copies it */
    if (i < 0) i = g->ax[0].periodic ? i + g->nx : -1 - i;
    if (i >= g->nx) i = g->ax[0].periodic ? i - g->nx : 2 * g->nx - 1 - i;
    if (j < 0) j = g->ax[1].periodic ? j + g->ny : -1 - j;
    if (j >= g->ny) j = g->ax[1].periodic ? j - g->ny : 2 * g->ny - 1 - j;
    if (i < 0 || j < 0 || i >= g->nx || j >= g->ny) return FLOW_CELL_SOLID;
    return ibm->kind[grid_index(g, i, j)];
}
