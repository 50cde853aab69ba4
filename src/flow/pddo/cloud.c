/* Node clouds of the PDDO flow solver: lattice, fictitious layers, holes,
 * pressure images, families (paper 002 Sec. 4; notes/pddo.md 1.6).
 *
 * Invariants: nodes are numbered row by row over the index box
 * [-layers, nx + layers] x [-layers, ny + layers] with the removed hole
 * interiors skipped; slot[] inverts that numbering; every fictitious node
 * has image >= 0 pointing at a node that is not itself fictitious, so the
 * pressure rows p_g = sign p_image never chain or cycle. */
#include "flow/pddo/cloud.h"

#include "core/mem.h"
#include "core/neighbours.h"
#include "core/status.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

/* Whether index k lies beyond the low (-1) or high (+1) side of an axis of
 * n intervals, or not (0); on a periodic axis index n is already a copy. */
static int beyond(int k, int n, bool periodic) {
    if (k < 0) return -1;
    return k > n || (periodic && k == n) ? 1 : 0;
}

/* On a side of an axis (periodic axes have none). */
static bool on_side(int k, int n, bool periodic) {
    return !periodic && (k == 0 || k == n);
}

/* Why a node of the index box is there: 0 removed, else 1 + PddoNodeKind.
 * patch: the holes' polar patches, or NULL (staircases). */
static int classify(const PddoCloudSpec *s, const PddoPolarPatch *patch, int nx, int ny, double x,
                    double y, int i, int j) {
    const bool px = s->side[PDDO_LEFT] == PDDO_SIDE_PERIODIC;
    const bool py = s->side[PDDO_BOTTOM] == PDDO_SIDE_PERIODIC;
    if (beyond(i, nx, px) || beyond(j, ny, py)) return 1 + PDDO_NODE_GHOST;
    for (int h = 0; h < s->nholes; h++) {
        const PddoHole *o = &s->holes[h];
        const double r = hypot(x - o->x, y - o->y);
        if (patch) {
            if (r < patch[h].r_cut) return 0; /* the ring nodes replace it */
            continue;
        }
        /* a node exactly on the circle is fluid: it carries the wall's value */
        if (r < o->radius)
            return r >= o->radius - s->layers * s->dx * (1.0 + 1e-9) ? 1 + PDDO_NODE_BODY : 0;
    }
    if (on_side(i, nx, px) || on_side(j, ny, py)) return 1 + PDDO_NODE_SIDE;
    return 1 + PDDO_NODE_FLUID;
}

/* The image index of a fictitious index beyond the low (low = 1) or high
 * side of an axis with n intervals, and the sign it brings. */
static int image_index(int k, int n, PddoSideKind kind, int *sign) {
    const bool low = k < 0;
    if (kind == PDDO_SIDE_PERIODIC) return (k % n + n) % n;
    if (kind == PDDO_SIDE_OUTLET) *sign = -*sign;
    if (kind == PDDO_SIDE_INLET) return low ? 0 : n;
    return low ? -k : 2 * n - k;
}

static int check_spec(const PddoCloudSpec *s, int32_t *nx, int32_t *ny) {
    if (!(s->dx > 0.0) || s->layers < 1 || !(s->horizon_factor > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO cloud: dx %g, layers %d, horizon factor %g; expected dx > 0, "
                         "layers >= 1, factor > 0",
                         s->dx, s->layers, s->horizon_factor);
    int32_t *count[2] = {nx, ny};
    for (int a = 0; a < 2; a++) {
        const double len = s->hi[a] - s->lo[a], q = len / s->dx;
        const double whole = round(q);
        if (!(len > 0.0) || fabs(q - whole) > 1e-9 * fmax(1.0, q) || whole > 1e7)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "PDDO cloud: side %g m along axis %d is %.12g spacings of %g m; "
                             "expected a whole number (at most 1e7)",
                             len, a, q, s->dx);
        *count[a] = (int32_t)whole;
        const bool p0 = s->side[2 * a] == PDDO_SIDE_PERIODIC,
                   p1 = s->side[2 * a + 1] == PDDO_SIDE_PERIODIC;
        if (p0 != p1 || (p0 && whole < s->layers))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "PDDO cloud: axis %d is periodic on %s side with %.0f intervals; "
                             "expected both sides periodic and at least %d intervals",
                             a, p0 && p1 ? "each" : "one", whole, s->layers);
    }
    for (int h = 0; h < s->nholes; h++) {
        const PddoHole *o = &s->holes[h];
        /* 2 layers of room: no side's image falls into a body and no body's
         * mirror point out of the rectangle; a polar patch keeps that room
         * outside its r_cut (and so the side's fictitious layers away from
         * its rings) */
        const double room = 2.0 * s->layers * s->dx;
        double reach = o->radius;
        if (s->polar && o->radius > 0.0) {
            PddoPolarPatch p = {0};
            TRY(pddo_polar_layout(&p, o->x, o->y, o->radius, &s->polar[h], s->dx));
            reach = p.r_cut;
        }
        if (!(o->radius > 0.0) || o->x - reach < s->lo[0] + room ||
            o->x + reach > s->hi[0] - room || o->y - reach < s->lo[1] + room ||
            o->y + reach > s->hi[1] - room)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "PDDO cloud: hole %d (centre %g, %g m, radius %g m, reaching %g m) is "
                             "within %g m of a side; expected a circle at least 2 layers inside",
                             h, o->x, o->y, o->radius, reach, room);
    }
    return NSPD_OK;
}

/* The holes' polar patches into c->patch (s->polar set), numbered from
 * node `first` on; NSPD_ERR_INPUT for two that overlap. */
static int layout_patches(PddoCloud *c, const PddoCloudSpec *s, int64_t first) {
    TRY(nspd_alloc(&c->patch, (size_t)s->nholes, sizeof(PddoPolarPatch)));
    c->npatches = s->nholes;
    for (int h = 0; h < s->nholes; h++) {
        const PddoHole *o = &s->holes[h];
        PddoPolarPatch *p = &c->patch[h];
        TRY(pddo_polar_layout(p, o->x, o->y, o->radius, &s->polar[h], s->dx));
        p->first = first;
        first += pddo_polar_count(p);
        for (int g = 0; g < h; g++)
            if (hypot(o->x - c->patch[g].x, o->y - c->patch[g].y) <
                p->r_cut + c->patch[g].r_cut + c->delta)
                return NSPD_FAIL(NSPD_ERR_INPUT,
                                 "PDDO cloud: the polar patches of holes %d and %d overlap "
                                 "(reaches %g and %g m); expected them a horizon apart",
                                 g, h, c->patch[g].r_cut, p->r_cut);
    }
    return NSPD_OK;
}

/* Every node's horizon: the cloud's, or its ring's local one (polar.h). */
static void node_horizons(PddoCloud *c) {
    for (int64_t k = 0; k < c->n; k++) c->node_delta[k] = c->delta;
    for (int h = 0; h < c->npatches; h++) {
        const PddoPolarPatch *p = &c->patch[h];
        for (int q = 0; q < p->rings; q++) {
            const double d = pddo_polar_horizon(p, q, c->delta);
            for (int t = 0; t < p->ntheta; t++)
                c->node_delta[p->first + (int64_t)q * p->ntheta + t] = d;
        }
    }
}

/* The families of the nodes with a horizon below the cloud's cut to it,
 * in place (each family's members in order; the same margin); nothing to
 * do without a local-horizon patch (the paper's one horizon). */
static void local_families(PddoCloud *c) {
    bool any = false;
    for (int h = 0; h < c->npatches; h++) any = any || c->patch[h].local_horizon > 0.0;
    if (!any) return;
    int64_t at = 0;
    for (int64_t k = 0; k < c->n; k++) {
        const int64_t lo = c->first[k], hi = c->first[k + 1];
        const double d = c->node_delta[k] * (1.0 + 1e-9);
        const bool cut = c->node_delta[k] < c->delta;
        c->first[k] = at;
        for (int64_t q = lo; q < hi; q++) {
            const int32_t j = c->nbr[q];
            if (cut && hypot(c->x[j] - c->x[k], c->y[j] - c->y[k]) > d) continue;
            c->nbr[at++] = j;
        }
    }
    c->first[c->n] = at;
}

/* The ring nodes of every patch, after the lattice's (cloud.h). */
static void place_rings(PddoCloud *c) {
    for (int h = 0; h < c->npatches; h++) {
        const PddoPolarPatch *p = &c->patch[h];
        for (int q = 0; q < p->rings; q++)
            for (int t = 0; t < p->ntheta; t++) {
                const int64_t k = p->first + (int64_t)q * p->ntheta + t;
                pddo_polar_node(p, q, t, &c->x[k], &c->y[k], &c->area[k]);
                c->i[k] = c->j[k] = INT32_MIN;
                c->sides[k] = 0;
                c->image[k] = -1;
                c->image_sign[k] = 0;
                if (q < p->rings_inside) {
                    /* s_m at R - m dr mirrors f_m at R + m dr (Eq. 48) */
                    c->kind[k] = PDDO_NODE_BODY;
                    c->image[k] =
                        (int32_t)(p->first + (int64_t)(2 * p->rings_inside - q) * p->ntheta + t);
                    c->image_sign[k] = 1;
                } else {
                    c->kind[k] = q == p->rings_inside ? PDDO_NODE_WALL : PDDO_NODE_FLUID;
                }
            }
    }
}

/* The fluid or side node nearest to the mirror point of a body node across
 * its circle: a 5 x 5 window around the rounded mirror point holds one,
 * since the mirror lies at most `layers` spacings outside the circle. */
static int32_t body_image(const PddoCloud *c, const PddoCloudSpec *s, int64_t k) {
    const double x = c->x[k], y = c->y[k];
    const PddoHole *o = NULL;
    double r = 0.0;
    for (int h = 0; h < s->nholes && !o; h++) {
        r = hypot(x - s->holes[h].x, y - s->holes[h].y);
        if (r < s->holes[h].radius) o = &s->holes[h];
    }
    if (!o) return -1;
    /* the mirror point at 2R - r on the same ray (r > 0: a node at the centre
     * is removed, the hole being wider than `layers` spacings or not) */
    const double f = r > 0.0 ? (2.0 * o->radius - r) / r : 1.0;
    const double mx = o->x + (x - o->x) * f, my = o->y + (y - o->y) * f;
    const int64_t origin = pddo_cloud_node(c, 0, 0); /* a side node: always there */
    const int i0 = (int)lround((mx - c->x[origin]) / c->dx);
    const int j0 = (int)lround((my - c->y[origin]) / c->dx);
    int32_t best = -1;
    double best_d = INFINITY;
    for (int dj = -2; dj <= 2; dj++)
        for (int di = -2; di <= 2; di++) {
            const int64_t q = pddo_cloud_node(c, i0 + di, j0 + dj);
            if (q < 0 || c->kind[q] == PDDO_NODE_BODY || c->kind[q] == PDDO_NODE_GHOST) continue;
            const double d = hypot(c->x[q] - mx, c->y[q] - my);
            if (d < best_d) best_d = d, best = (int32_t)q;
        }
    return best;
}

int pddo_cloud_check(const PddoCloudSpec *s) {
    int32_t nx, ny;
    return check_spec(s, &nx, &ny);
}

int pddo_cloud_build(PddoCloud *c, const PddoCloudSpec *s) {
    pddo_cloud_free(c);
    int32_t nx = 0, ny = 0;
    TRY(check_spec(s, &nx, &ny));
    const int L = s->layers;
    const int64_t wi = (int64_t)nx + 2 * L + 1, wj = (int64_t)ny + 2 * L + 1;
    if (wi * wj > INT32_MAX)
        return NSPD_FAIL(NSPD_ERR_INPUT, "PDDO cloud: %lld lattice sites exceed 2^31",
                         (long long)(wi * wj));
    c->nx = nx, c->ny = ny, c->layers = L, c->dx = s->dx;
    c->delta = s->horizon_factor * s->dx;
    memcpy(c->side, s->side, sizeof c->side);
    const double centre[2] = {0.5 * (s->lo[0] + s->hi[0]), 0.5 * (s->lo[1] + s->hi[1])};
    const double mid[2] = {0.5 * nx, 0.5 * ny};

    int status = nspd_alloc(&c->slot, (size_t)(wi * wj), sizeof(int32_t));
    if (status == NSPD_OK && s->polar && s->nholes > 0) status = layout_patches(c, s, 0);
    const PddoPolarPatch *patch = c->patch;
    int64_t n = 0;
    for (int64_t q = 0; q < wi * wj && status == NSPD_OK; q++) {
        const int i = (int)(q % wi) - L, j = (int)(q / wi) - L;
        const double x = centre[0] + (i - mid[0]) * s->dx, y = centre[1] + (j - mid[1]) * s->dx;
        c->slot[q] = classify(s, patch, nx, ny, x, y, i, j) ? (int32_t)n++ : -1;
    }
    const int64_t lattice = n;
    for (int h = 0; h < c->npatches; h++) {
        c->patch[h].first = n;
        n += pddo_polar_count(&c->patch[h]);
    }
    if (status == NSPD_OK && n > INT32_MAX)
        status = NSPD_FAIL(NSPD_ERR_INPUT, "PDDO cloud: %lld nodes exceed 2^31", (long long)n);
    c->n = n;
    if (status == NSPD_OK) status = nspd_alloc(&c->x, (size_t)n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&c->y, (size_t)n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&c->area, (size_t)n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&c->i, (size_t)n, sizeof(int32_t));
    if (status == NSPD_OK) status = nspd_alloc(&c->j, (size_t)n, sizeof(int32_t));
    if (status == NSPD_OK) status = nspd_alloc(&c->kind, (size_t)n, 1);
    if (status == NSPD_OK) status = nspd_alloc(&c->sides, (size_t)n, 1);
    if (status == NSPD_OK) status = nspd_alloc(&c->image, (size_t)n, sizeof(int32_t));
    if (status == NSPD_OK) status = nspd_alloc(&c->image_sign, (size_t)n, 1);
    if (status == NSPD_OK) status = nspd_alloc(&c->node_delta, (size_t)n, sizeof(double));
    if (status != NSPD_OK) {
        pddo_cloud_free(c);
        return status;
    }
    const bool px = s->side[PDDO_LEFT] == PDDO_SIDE_PERIODIC;
    const bool py = s->side[PDDO_BOTTOM] == PDDO_SIDE_PERIODIC;
    place_rings(c);
    node_horizons(c);
    for (int64_t q = 0; q < wi * wj; q++) {
        const int32_t k = c->slot[q];
        if (k < 0) continue;
        const int i = (int)(q % wi) - L, j = (int)(q / wi) - L;
        c->i[k] = i, c->j[k] = j;
        c->x[k] = centre[0] + (i - mid[0]) * s->dx;
        c->y[k] = centre[1] + (j - mid[1]) * s->dx;
        c->area[k] = s->dx * s->dx;
        c->kind[k] = (uint8_t)(classify(s, patch, nx, ny, c->x[k], c->y[k], i, j) - 1);
        const int bx = beyond(i, nx, px), by = beyond(j, ny, py);
        uint8_t bits = 0;
        if (bx < 0 || (on_side(i, nx, px) && i == 0)) bits |= 1u << PDDO_LEFT;
        if (bx > 0 || (on_side(i, nx, px) && i == nx)) bits |= 1u << PDDO_RIGHT;
        if (by < 0 || (on_side(j, ny, py) && j == 0)) bits |= 1u << PDDO_BOTTOM;
        if (by > 0 || (on_side(j, ny, py) && j == ny)) bits |= 1u << PDDO_TOP;
        c->sides[k] = bits;
        c->image[k] = -1;
    }
    /* pressure images, once every node has its kind (body images need them);
     * the rings have theirs */
    for (int64_t k = 0; k < lattice; k++) {
        int sign = 1, ii = c->i[k], jj = c->j[k];
        if (c->kind[k] == PDDO_NODE_GHOST) {
            if (beyond(ii, nx, px))
                ii = image_index(ii, nx, s->side[ii < 0 ? PDDO_LEFT : PDDO_RIGHT], &sign);
            if (beyond(jj, ny, py))
                jj = image_index(jj, ny, s->side[jj < 0 ? PDDO_BOTTOM : PDDO_TOP], &sign);
            c->image[k] = (int32_t)pddo_cloud_node(c, ii, jj);
        } else if (c->kind[k] == PDDO_NODE_BODY) {
            c->image[k] = body_image(c, s, k);
        } else {
            sign = 0;
        }
        c->image_sign[k] = (int8_t)sign;
        if (sign != 0 && (c->image[k] < 0 || c->kind[c->image[k]] >= PDDO_NODE_GHOST)) {
            pddo_cloud_free(c);
            return NSPD_FAIL(NSPD_ERR_INTERNAL,
                             "PDDO cloud: fictitious node (%d, %d) has no fluid image", ii, jj);
        }
    }
    const double *const xyz[3] = {c->x, c->y, NULL};
    /* the margin decides the lattice nodes at exactly delta: they are in */
    status = neighbours_find(n, 2, xyz, c->delta * (1.0 + 1e-9), &c->first, &c->nbr);
    if (status == NSPD_OK) local_families(c);
    if (status != NSPD_OK) pddo_cloud_free(c);
    return status;
}

void pddo_cloud_free(PddoCloud *c) {
    nspd_free(&c->x);
    nspd_free(&c->y);
    nspd_free(&c->area);
    nspd_free(&c->i);
    nspd_free(&c->j);
    nspd_free(&c->kind);
    nspd_free(&c->sides);
    nspd_free(&c->image);
    nspd_free(&c->image_sign);
    nspd_free(&c->node_delta);
    nspd_free(&c->first);
    nspd_free(&c->nbr);
    nspd_free(&c->slot);
    nspd_free(&c->patch);
    memset(c, 0, sizeof *c);
}

int64_t pddo_cloud_node(const PddoCloud *c, int i, int j) {
    const int L = c->layers;
    if (i < -L || i > c->nx + L || j < -L || j > c->ny + L) return -1;
    const int64_t wi = (int64_t)c->nx + 2 * L + 1;
    return c->slot[(int64_t)(i + L) + (int64_t)(j + L) * wi];
}
