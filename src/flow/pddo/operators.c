/* PDDO weights (paper 002, Eqs. 10-14): one 5 x 5 solve per node.
 *
 * With z = A_k^-1 P(xi_j) for each family member, Eq. 12's
 * g^op(j) = w P^T A^-1 b e_op = b_op,op w z_op (A_k is symmetric and b
 * diagonal), so one factorisation and one solve per member give all five
 * operators at once. Everything is computed in the scaled coordinates
 * s = xi / delta and areas A_j / delta^2; a first derivative then divides
 * by delta, a second by delta^2. */
#include "flow/pddo/operators.h"

#include "core/hash.h"
#include "core/mem.h"
#include "core/parallel.h"
#include "core/search.h"
#include "core/spd_small.h"
#include "core/status.h"

#include <math.h>
#include <omp.h>
#include <stdbool.h>
#include <string.h>

enum { TERMS = 5 }; /* xi1, xi2, xi1^2, xi2^2, xi1 xi2 (the interpolation adds 1 before them) */

/* The squared-pivot floor of the unit-diagonal Cholesky (below it the
 * matrix is numerically singular whatever the condition estimate says). */
#define PDDO_MIN_PIVOT 1e-12

/* P(s) of Eq. 12, after a leading 1 when `constant` (the interpolation's
 * basis); the number of terms. */
static int basis(bool constant, double s1, double s2, double p[SPD_SMALL_MAX]) {
    const int o = constant ? 1 : 0;
    p[0] = 1.0;
    p[o] = s1, p[o + 1] = s2, p[o + 2] = s1 * s1, p[o + 3] = s2 * s2, p[o + 4] = s1 * s2;
    return o + TERMS;
}

/* Eq. 12j in scaled coordinates: exp(-(2 |xi| / delta)^2). */
static double weight(double s1, double s2) {
    return exp(-4.0 * (s1 * s1 + s2 * s2));
}

/* 1-norm condition number of the unit-diagonal matrix D M D (D = scale),
 * from M (full, unfactored) and its factor: ||D M D||_1 ||(D M D)^-1||_1,
 * the inverse column by column, (D M D)^-1 e_c = D^-1 M^-1 D^-1 e_c. */
static double condition(double M[SPD_SMALL_MAX][SPD_SMALL_MAX],
                        double Lf[SPD_SMALL_MAX][SPD_SMALL_MAX], const double scale[SPD_SMALL_MAX],
                        int terms) {
    double norm = 0.0, inv_norm = 0.0;
    for (int c = 0; c < terms; c++) {
        double col = 0.0, inv_col = 0.0, e[SPD_SMALL_MAX] = {0}, z[SPD_SMALL_MAX] = {0};
        for (int r = 0; r < terms; r++) col += fabs(M[r][c]) * scale[r] * scale[c];
        e[c] = 1.0 / scale[c];
        spd_small_solve((const double(*)[SPD_SMALL_MAX])Lf, terms, scale, e, z);
        for (int r = 0; r < terms; r++) inv_col += fabs(z[r] / scale[r]);
        norm = fmax(norm, col);
        inv_norm = fmax(inv_norm, inv_col);
    }
    return norm * inv_norm;
}

/* The centre of a family: a point (xc, yc), or a node with its lattice
 * indices (li = INT32_MIN: none), and the scaled offsets xi / delta of
 * the members from it. */
typedef struct {
    const double *x, *y;
    double xc, yc, inv_delta;
    const PddoLattice *lattice;
    int32_t li, lj;
    const PddoPolarPatch *patch; /* a turned node's patch (its ring q, angle t), or NULL */
    int32_t q, t;
} Centre;

static Centre centre_at(const double *x, const double *y, double xc, double yc, double delta) {
    return (Centre){.x = x, .y = y, .xc = xc, .yc = yc, .inv_delta = 1.0 / delta, .li = INT32_MIN};
}

/* The patch whose ring holds node k and all of its members nbr[0 ..
 * count), or NULL (then k's weights are not turned: operators.h). */
static const PddoPolarPatch *turned_patch(const PddoLattice *lattice, int64_t k, const int32_t *nbr,
                                          int64_t count) {
    if (!lattice) return NULL;
    for (int h = 0; h < lattice->patches; h++) {
        const PddoPolarPatch *p = &lattice->patch[h];
        const int64_t lo = p->first, hi = p->first + pddo_polar_count(p);
        if (k < lo || k >= hi) continue;
        for (int64_t m = 0; m < count; m++)
            if (nbr[m] < lo || nbr[m] >= hi) return NULL;
        return p;
    }
    return NULL;
}

static Centre centre_node(const double *x, const double *y, int64_t k, double delta,
                          const PddoLattice *lattice, const PddoPolarPatch *patch) {
    Centre c = centre_at(x, y, x[k], y[k], delta);
    if (lattice) c.lattice = lattice, c.li = lattice->i[k], c.lj = lattice->j[k];
    if (patch) {
        c.patch = patch;
        c.q = (int32_t)((k - patch->first) / patch->ntheta);
        c.t = (int32_t)((k - patch->first) % patch->ntheta);
    }
    return c;
}

/* xi / delta of member j: from the lattice indices where both are lattice
 * nodes (the same bits for the same offset anywhere), else from the
 * coordinates. */
static void offset(const Centre *c, int32_t j, double *s1, double *s2) {
    if (c->patch) {
        /* in the centre's frame, from the polar layout: the same bits for
         * the same ring and angle difference at every angle */
        const PddoPolarPatch *p = c->patch;
        const int32_t n = p->ntheta, qj = (int32_t)((j - p->first) / n);
        int32_t dt = (int32_t)((j - p->first) % n) - c->t;
        if (dt > n / 2) dt -= n;
        if (dt < -n / 2) dt += n;
        const double a = dt * p->dtheta, r = pddo_polar_radius(p, c->q);
        const double rj = pddo_polar_radius(p, qj);
        *s1 = (rj * cos(a) - r) * c->inv_delta, *s2 = rj * sin(a) * c->inv_delta;
        return;
    }
    if (c->li != INT32_MIN && c->lattice->i[j] != INT32_MIN) {
        *s1 = (double)(c->lattice->i[j] - c->li) * c->lattice->dx * c->inv_delta;
        *s2 = (double)(c->lattice->j[j] - c->lj) * c->lattice->dx * c->inv_delta;
        return;
    }
    *s1 = (c->x[j] - c->xc) * c->inv_delta, *s2 = (c->y[j] - c->yc) * c->inv_delta;
}

/* The shape matrix (Eq. 14b) of the members nbr[0 .. count) of a family
 * around centre c, in scaled coordinates, with or without the constant
 * term, factored into Lf and scale (core/spd_small.h); its condition
 * number (the rule of operators.h), or INFINITY when the factorisation
 * fails. */
static double shape_factor(const int32_t *nbr, int64_t count, const Centre *ctr, const double *area,
                           bool constant, double Lf[SPD_SMALL_MAX][SPD_SMALL_MAX],
                           double scale[SPD_SMALL_MAX]) {
    double M[SPD_SMALL_MAX][SPD_SMALL_MAX] = {{0}}, p[SPD_SMALL_MAX] = {0};
    const double inv_area = ctr->inv_delta * ctr->inv_delta;
    int terms = TERMS + (constant ? 1 : 0);
    for (int64_t m = 0; m < count; m++) {
        const int32_t j = nbr[m];
        double s1, s2;
        offset(ctr, j, &s1, &s2);
        const double wa = weight(s1, s2) * area[j] * inv_area;
        terms = basis(constant, s1, s2, p);
        for (int r = 0; r < terms; r++)
            for (int c = 0; c <= r; c++) M[r][c] += wa * p[r] * p[c];
    }
    for (int r = 0; r < terms; r++)
        for (int c = r + 1; c < terms; c++) M[r][c] = M[c][r];
    memcpy(Lf, M, sizeof M);
    if (!spd_small_factor(Lf, terms, scale, PDDO_MIN_PIVOT)) return INFINITY;
    return condition(M, Lf, scale, terms);
}

/* Node k's weights of every operator; its condition number in *cond, or
 * INFINITY when the factorisation fails (then no weight is written). */
static void node_weights(PddoOps *ops, int64_t k, const double *x, const double *y,
                         const double *area, double delta, const PddoLattice *lattice, bool weights,
                         double *cond) {
    double Lf[SPD_SMALL_MAX][SPD_SMALL_MAX] = {{0}};
    double p[SPD_SMALL_MAX] = {0}, scale[SPD_SMALL_MAX] = {0};
    const double inv_delta = 1.0 / delta, inv_area = inv_delta * inv_delta;
    const int64_t lo = ops->first[k], hi = ops->first[k + 1];
    const PddoPolarPatch *patch = turned_patch(lattice, k, ops->nbr + lo, hi - lo);
    const Centre ctr = centre_node(x, y, k, delta, lattice, patch);
    *cond = shape_factor(ops->nbr + lo, hi - lo, &ctr, area, false, Lf, scale);
    if (!isfinite(*cond) || !weights) return;
    if (patch) {
        ops->turned[k] = 1;
        pddo_polar_angle(patch, ctr.t, &ops->turn_c[k], &ops->turn_s[k]);
    }
    /* b = diag(1, 1, 2, 2, 1) (Eq. 14c), then back to metres */
    const double b[TERMS] = {inv_delta, inv_delta, 2.0 * inv_area, 2.0 * inv_area, inv_area};
    for (int64_t m = lo; m < hi; m++) {
        const int32_t j = ops->nbr[m];
        double s1, s2;
        offset(&ctr, j, &s1, &s2);
        const double wa = weight(s1, s2) * area[j] * inv_area;
        double z[SPD_SMALL_MAX] = {0};
        basis(false, s1, s2, p);
        spd_small_solve((const double(*)[SPD_SMALL_MAX])Lf, TERMS, scale, p, z);
        const int64_t at = pddo_ops_slot(ops, k, m);
        ops->w[PDDO_D_X][at] = b[0] * wa * z[0];
        ops->w[PDDO_D_Y][at] = b[1] * wa * z[1];
        ops->w[PDDO_LAP][at] = b[2] * wa * z[2] + b[3] * wa * z[3];
        ops->w[PDDO_D_XY][at] = b[4] * wa * z[4];
        if (patch) ops->dif[at] = b[2] * wa * z[2] - b[3] * wa * z[3];
    }
}

/* The slices' layout (operators.h): each slice as many rows as its
 * largest family, the members' nodes placed, padding with the slot's own
 * node (the last node for the lanes past it) and weight 0. */
static int slices_build(PddoOps *ops, bool patches) {
    const int64_t n = ops->n, slices = pddo_ops_slices(ops);
    TRY(nspd_alloc(&ops->slice_first, (size_t)slices + 1, sizeof(int64_t)));
    for (int64_t s = 0; s < slices; s++) {
        int64_t rows = 0;
        for (int64_t k = s * PDDO_LANES; k < (s + 1) * PDDO_LANES && k < n; k++)
            rows =
                ops->first[k + 1] - ops->first[k] > rows ? ops->first[k + 1] - ops->first[k] : rows;
        ops->slice_first[s + 1] = ops->slice_first[s] + rows * PDDO_LANES;
    }
    const size_t slots = (size_t)ops->slice_first[slices] + 1;
    TRY(nspd_alloc(&ops->slot_nbr, slots, sizeof(int32_t)));
    for (int op = 0; op < PDDO_OPS; op++) TRY(nspd_alloc(&ops->w[op], slots, sizeof(double)));
    /* every node unturned (angle 0) until node_weights turns it */
    TRY(nspd_alloc(&ops->turn_c, (size_t)(slices * PDDO_LANES), sizeof(double)));
    TRY(nspd_alloc(&ops->turn_s, (size_t)(slices * PDDO_LANES), sizeof(double)));
    TRY(nspd_alloc(&ops->turned, (size_t)(slices * PDDO_LANES), 1));
    for (int64_t k = 0; k < slices * PDDO_LANES; k++) ops->turn_c[k] = 1.0;
    if (patches) TRY(nspd_alloc(&ops->dif, slots, sizeof(double)));
    for (int64_t s = 0; s < slices; s++) {
        const int64_t rows = (ops->slice_first[s + 1] - ops->slice_first[s]) / PDDO_LANES;
        for (int l = 0; l < PDDO_LANES; l++) {
            const int64_t k = s * PDDO_LANES + l, node = k < n ? k : n - 1;
            const int64_t size = k < n ? ops->first[k + 1] - ops->first[k] : 0;
            for (int64_t r = 0; r < rows; r++)
                ops->slot_nbr[ops->slice_first[s] + r * PDDO_LANES + l] =
                    r < size ? ops->nbr[ops->first[k] + r] : (int32_t)node;
        }
    }
    return NSPD_OK;
}

/* g^20 - g^02 of slot at (turned nodes only; 0 else). */
static double slot_dif(const PddoOps *ops, int64_t at) {
    return ops->dif ? ops->dif[at] : 0.0;
}

/* Whether slice s (base: its first slot, rows of them) matches template
 * t: the same rows, offsets and weights, bit for bit, both turned or not. */
static bool template_matches(const PddoOps *ops, int32_t t, int64_t s, int64_t base, int64_t rows) {
    const int64_t tf = ops->tpl_first[t];
    if (ops->tpl_first[t + 1] - tf != rows) return false;
    if (ops->tpl_turned[t] != ops->turned[s * PDDO_LANES]) return false;
    for (int64_t r = 0; r < rows; r++) {
        const int64_t at = base + r * PDDO_LANES;
        if (ops->tpl_off[tf + r] != ops->slot_nbr[at] - s * PDDO_LANES) return false;
        for (int op = 0; op < PDDO_OPS; op++)
            if (memcmp(&ops->tpl_w[op][tf + r], &ops->w[op][at], sizeof(double)) != 0) return false;
        const double dif = slot_dif(ops, at);
        if (memcmp(&ops->tpl_dif[tf + r], &dif, sizeof(double)) != 0) return false;
    }
    return true;
}

/* Whether slice s can be a template's: every lane a node with the same
 * number of members, all turned or none, member r of lane l node s L + l
 * + off[r], and the weights of a row the same bits in every lane (turned:
 * in the lanes' own frames). */
static bool slice_uniform(const PddoOps *ops, int64_t s, int64_t base, int64_t rows) {
    enum { L = PDDO_LANES };
    if ((s + 1) * L > ops->n) return false;
    for (int l = 0; l < L; l++)
        if (ops->first[s * L + l + 1] - ops->first[s * L + l] != rows ||
            ops->turned[s * L + l] != ops->turned[s * L])
            return false;
    for (int64_t r = 0; r < rows; r++) {
        const int64_t at = base + r * L;
        for (int l = 1; l < L; l++) {
            if (ops->slot_nbr[at + l] != ops->slot_nbr[at] + l) return false;
            for (int op = 0; op < PDDO_OPS; op++)
                if (memcmp(&ops->w[op][at + l], &ops->w[op][at], sizeof(double)) != 0) return false;
            const double a = slot_dif(ops, at + l), b = slot_dif(ops, at);
            if (memcmp(&a, &b, sizeof(double)) != 0) return false;
        }
    }
    return true;
}

/* The hash of slice s's rows (offsets and weights), to find its template. */
static uint64_t slice_hash(const PddoOps *ops, int64_t s, int64_t base, int64_t rows) {
    Hash64 h;
    hash64_init(&h);
    for (int64_t r = 0; r < rows; r++) {
        const int32_t off = (int32_t)(ops->slot_nbr[base + r * PDDO_LANES] - s * PDDO_LANES);
        hash64_add(&h, &off, sizeof off);
        for (int op = 0; op < PDDO_OPS; op++)
            hash64_add(&h, &ops->w[op][base + r * PDDO_LANES], sizeof(double));
        const double dif = slot_dif(ops, base + r * PDDO_LANES);
        hash64_add(&h, &dif, sizeof dif);
    }
    return hash64_final(&h);
}

/* The template slice s matches, found by its hash in table (size a power
 * of two, -1 empty), or a new one made of its rows. */
static int32_t template_of(PddoOps *ops, int32_t *table, int64_t size, int64_t s, int64_t base,
                           int64_t rows) {
    enum { L = PDDO_LANES };
    int64_t at = (int64_t)(slice_hash(ops, s, base, rows) & (uint64_t)(size - 1));
    for (; table[at] >= 0; at = (at + 1) & (size - 1))
        if (template_matches(ops, table[at], s, base, rows)) return table[at];
    const int32_t t = ops->templates++;
    const int64_t tf = ops->tpl_first[t];
    ops->tpl_turned[t] = ops->turned[s * L];
    for (int64_t r = 0; r < rows; r++) {
        ops->tpl_off[tf + r] = (int32_t)(ops->slot_nbr[base + r * L] - s * L);
        for (int op = 0; op < PDDO_OPS; op++) ops->tpl_w[op][tf + r] = ops->w[op][base + r * L];
        ops->tpl_dif[tf + r] = slot_dif(ops, base + r * L);
    }
    ops->tpl_first[t + 1] = tf + rows;
    table[at] = t;
    return t;
}

/* The turned nodes of the slices that keep their own slots: their weights
 * turned once, as pddo_ops_turned turns a template's row. */
static void turn_own_slots(PddoOps *ops) {
    const int64_t slices = pddo_ops_slices(ops);
    for (int64_t s = 0; s < slices; s++) {
        if (ops->slice_tpl[s] >= 0) continue;
        for (int l = 0; l < PDDO_LANES && s * PDDO_LANES + l < ops->n; l++) {
            const int64_t k = s * PDDO_LANES + l;
            if (!ops->turned[k]) continue;
            const double c = ops->turn_c[k], sn = ops->turn_s[k];
            for (int64_t m = ops->first[k]; m < ops->first[k + 1]; m++) {
                const int64_t at = pddo_ops_slot(ops, k, m);
                const double g10 = ops->w[PDDO_D_X][at], g01 = ops->w[PDDO_D_Y][at];
                const double g11 = ops->w[PDDO_D_XY][at];
                ops->w[PDDO_D_X][at] = c * g10 - sn * g01;
                ops->w[PDDO_D_Y][at] = sn * g10 + c * g01;
                ops->w[PDDO_D_XY][at] = (c * sn) * ops->dif[at] + (c * c - sn * sn) * g11;
            }
        }
    }
}

/* The templates (operators.h): every uniform slice takes the template it
 * matches, or makes one (a template of one slice still keeps an eighth
 * of its slots); the slots of the slices that keep their own are then
 * packed. */
static int templates_build(PddoOps *ops) {
    enum { L = PDDO_LANES };
    const int64_t slices = pddo_ops_slices(ops);
    TRY(nspd_alloc(&ops->slice_tpl, (size_t)slices + 1, sizeof(int32_t)));
    int64_t uniform = 0, rows_room = 0;
    for (int64_t s = 0; s < slices; s++) {
        const int64_t base = ops->slice_first[s], rows = (ops->slice_first[s + 1] - base) / L;
        ops->slice_tpl[s] = rows > 0 && slice_uniform(ops, s, base, rows) ? 0 : -1;
        if (ops->slice_tpl[s] == 0) uniform++, rows_room += rows;
    }
    int64_t size = 2;
    while (size < 2 * uniform) size *= 2;
    int32_t *table = NULL;
    int status = nspd_alloc(&table, (size_t)size, sizeof *table);
    if (status == NSPD_OK)
        status = nspd_alloc(&ops->tpl_first, (size_t)uniform + 1, sizeof(int64_t));
    if (status == NSPD_OK)
        status = nspd_alloc(&ops->tpl_off, (size_t)rows_room + 1, sizeof(int32_t));
    if (status == NSPD_OK)
        status = nspd_alloc(&ops->tpl_dif, (size_t)rows_room + 1, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&ops->tpl_turned, (size_t)uniform + 1, 1);
    for (int op = 0; op < PDDO_OPS && status == NSPD_OK; op++)
        status = nspd_alloc(&ops->tpl_w[op], (size_t)rows_room + 1, sizeof(double));
    if (status != NSPD_OK) {
        nspd_free(&table);
        return status;
    }
    for (int64_t q = 0; q < size; q++) table[q] = -1;
    int64_t kept = 0;
    for (int64_t s = 0; s < slices; s++) {
        const int64_t base = ops->slice_first[s], rows = (ops->slice_first[s + 1] - base) / L;
        if (ops->slice_tpl[s] == 0) {
            ops->slice_tpl[s] = template_of(ops, table, size, s, base, rows);
            ops->templated++;
        } else {
            kept += rows * L;
        }
    }
    nspd_free(&table);
    turn_own_slots(ops);
    nspd_free(&ops->dif);
    /* pack the slots of the slices without a template, in order (each
     * moves down or stays, so in place), then give back the rest */
    const size_t slots = (size_t)ops->slice_first[slices] + 1;
    int64_t at = 0;
    for (int64_t s = 0; s < slices; s++) {
        const int64_t base = ops->slice_first[s], size_s = ops->slice_first[s + 1] - base;
        ops->slice_first[s] = at;
        if (ops->slice_tpl[s] >= 0) continue;
        memmove(ops->slot_nbr + at, ops->slot_nbr + base, (size_t)size_s * sizeof(int32_t));
        for (int op = 0; op < PDDO_OPS; op++)
            memmove(ops->w[op] + at, ops->w[op] + base, (size_t)size_s * sizeof(double));
        at += size_s;
    }
    ops->slice_first[slices] = at;
    TRY(nspd_realloc(&ops->slot_nbr, slots, (size_t)kept + 1, sizeof(int32_t)));
    for (int op = 0; op < PDDO_OPS; op++)
        TRY(nspd_realloc(&ops->w[op], slots, (size_t)kept + 1, sizeof(double)));
    const int64_t used = ops->tpl_first[ops->templates];
    TRY(nspd_realloc(&ops->tpl_off, (size_t)rows_room + 1, (size_t)used + 1, sizeof(int32_t)));
    TRY(nspd_realloc(&ops->tpl_dif, (size_t)rows_room + 1, (size_t)used + 1, sizeof(double)));
    for (int op = 0; op < PDDO_OPS; op++)
        TRY(nspd_realloc(&ops->tpl_w[op], (size_t)rows_room + 1, (size_t)used + 1, sizeof(double)));
    TRY(nspd_alloc(&ops->cost_before, (size_t)slices + 1, sizeof(int64_t)));
    ops->cost_before[0] = 0;
    for (int64_t s = 0; s < slices; s++) {
        const int32_t t = ops->slice_tpl[s];
        const int64_t cost =
            t >= 0 ? ops->tpl_first[t + 1] - ops->tpl_first[t]
                   : PDDO_OWN_ROW_COST * (ops->slice_first[s + 1] - ops->slice_first[s]) / L;
        ops->cost_before[s + 1] = ops->cost_before[s] + cost + 1;
    }
    ops->own_lo = 0, ops->own_hi = slices;
    return NSPD_OK;
}

/* Part t of nt of slices [from, to) by cost. */
static void cut_range(const PddoOps *ops, int64_t from, int64_t to, int t, int nt, int64_t *lo,
                      int64_t *hi) {
    const int64_t *c = ops->cost_before + from, count = to - from, total = c[count] - c[0];
    *lo = t == 0 ? from : from + search_first_at_least(c, count, c[0] + total * t / nt);
    *hi = t == nt - 1 ? to : from + search_first_at_least(c, count, c[0] + total * (t + 1) / nt);
}

void pddo_ops_share(const PddoOps *ops, int t, int nt, int64_t *lo, int64_t *hi) {
    cut_range(ops, ops->own_lo, ops->own_hi, t, nt, lo, hi);
}

void pddo_ops_cut(const PddoOps *ops, int t, int nt, int64_t *lo, int64_t *hi) {
    cut_range(ops, 0, pddo_ops_slices(ops), t, nt, lo, hi);
}

static int build(PddoOps *ops, int64_t n, const double *x, const double *y, const double *area,
                 const int64_t *first, const int32_t *nbr, double delta, const double *node_delta,
                 const PddoLattice *lattice, bool weights) {
    pddo_ops_free(ops);
    for (int64_t k = 0; k < (node_delta ? n : 1); k++) {
        const double d = node_delta ? node_delta[k] : delta;
        if (!(d > 0.0))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "PDDO operators: horizon %g m at node %lld; expected > 0", d,
                             (long long)k);
    }
    ops->n = n, ops->first = first, ops->nbr = nbr;
    if (weights) {
        const int status = slices_build(ops, lattice && lattice->patches > 0);
        if (status != NSPD_OK) {
            pddo_ops_free(ops);
            return status;
        }
    }
    double *cond;
    int status = nspd_alloc(&cond, (size_t)n, sizeof(double));
    if (status != NSPD_OK) {
        pddo_ops_free(ops);
        return status;
    }
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++)
        node_weights(ops, k, x, y, area, node_delta ? node_delta[k] : delta, lattice, weights,
                     &cond[k]);
    /* the first node that breaks the rule, in node order whatever the threads */
    for (int64_t k = 0; k < n; k++) {
        if (!(cond[k] <= PDDO_COND_MAX)) {
            status = NSPD_FAIL(NSPD_ERR_INPUT,
                               "PDDO operators: node %lld at (%g, %g) m with %lld neighbours "
                               "has a shape matrix of condition %g (limit %g); expected a "
                               "family that spans the quadratics",
                               (long long)k, x[k], y[k], (long long)(first[k + 1] - first[k]),
                               cond[k], PDDO_COND_MAX);
            break;
        }
        if (cond[k] > ops->cond_max) ops->cond_max = cond[k], ops->cond_node = k;
    }
    nspd_free(&cond);
    if (status == NSPD_OK && weights) status = templates_build(ops);
    if (status != NSPD_OK) pddo_ops_free(ops);
    return status;
}

int pddo_ops_build(PddoOps *ops, int64_t n, const double *x, const double *y, const double *area,
                   const int64_t *first, const int32_t *nbr, double delta, const double *node_delta,
                   const PddoLattice *lattice) {
    return build(ops, n, x, y, area, first, nbr, delta, node_delta, lattice, true);
}

int pddo_ops_check(PddoOps *ops, int64_t n, const double *x, const double *y, const double *area,
                   const int64_t *first, const int32_t *nbr, double delta,
                   const double *node_delta) {
    return build(ops, n, x, y, area, first, nbr, delta, node_delta, NULL, false);
}

/* The sums of `count` (operator, field) pairs at node k in one pass over
 * its family: the neighbour index is read once for all of them. Each sum
 * runs over the members in order, as one operator alone would: fusing
 * changes no bits. */
static inline __attribute__((always_inline)) void at_many(const PddoOps *ops, int count,
                                                          const PddoOp *op, const double *const *f,
                                                          int64_t k, double *sum) {
    const double *w[PDDO_FUSED_MAX];
    double fk[PDDO_FUSED_MAX];
    /* a template's row r, or the slot of member r (stride PDDO_LANES) */
    const int32_t t = ops->slice_tpl[k / PDDO_LANES];
    if (t >= 0 && ops->tpl_turned[t]) {
        const int64_t tf = ops->tpl_first[t];
        const double c = ops->turn_c[k], s = ops->turn_s[k];
        for (int o = 0; o < count; o++) fk[o] = f[o][k], sum[o] = 0.0;
        for (int64_t m = 0; m < ops->first[k + 1] - ops->first[k]; m++) {
            const int32_t j = ops->nbr[ops->first[k] + m];
            for (int o = 0; o < count; o++)
                sum[o] += pddo_ops_turned(ops, op[o], tf + m, c, s) * (f[o][j] - fk[o]);
        }
        return;
    }
    const int64_t at = t >= 0 ? ops->tpl_first[t] : pddo_ops_slot(ops, k, ops->first[k]);
    const int64_t stride = t >= 0 ? 1 : PDDO_LANES;
    for (int o = 0; o < count; o++)
        w[o] = t >= 0 ? ops->tpl_w[op[o]] : ops->w[op[o]], fk[o] = f[o][k], sum[o] = 0.0;
    for (int64_t m = 0; m < ops->first[k + 1] - ops->first[k]; m++) {
        const int32_t j = ops->nbr[ops->first[k] + m];
        for (int o = 0; o < count; o++) sum[o] += w[o][at + m * stride] * (f[o][j] - fk[o]);
    }
}

/* A slice's lanes as one value (GCC's and Clang's vector extension: the
 * compiler keeps it in registers, where arrays of lanes it spilled to
 * the stack between the rows). */
typedef double Lanes __attribute__((vector_size(PDDO_LANES * sizeof(double))));

static inline Lanes lanes_set(double v) {
    Lanes l;
    for (int q = 0; q < PDDO_LANES; q++) l[q] = v;
    return l;
}

static inline Lanes lanes_load(const double *p) {
    Lanes v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* at_many at the nodes of slice s in SIMD lanes, with the differences
 * f_j - f_k formed once per distinct field: `fields` of them in F, op[o]
 * applied to F[of[o]]. A lane adds its node's members in their order and
 * then the padding's exact zeros: at_many's bits. */
static inline __attribute__((always_inline)) void slice_sums(const PddoOps *ops, int fields,
                                                             const double *const *F, int count,
                                                             const PddoOp *op, const int *of,
                                                             int64_t s, double *sum) {
    enum { L = PDDO_LANES };
    Lanes fk[PDDO_FUSED_MAX], acc[PDDO_FUSED_MAX];
    const int64_t last = ops->n - 1;
    for (int q = 0; q < fields; q++)
        for (int l = 0; l < L; l++) {
            const int64_t k = s * L + l;
            fk[q][l] = F[q][k < last ? k : last];
        }
    for (int o = 0; o < count; o++) acc[o] = (Lanes){0};
    const int32_t t = ops->slice_tpl[s];
    if (t >= 0) {
        /* a template's slice: member r of every lane one offset away, its
         * weight the same in every lane (broadcast: the same products) */
        const int64_t tf = ops->tpl_first[t], rows = ops->tpl_first[t + 1] - tf;
        if (ops->tpl_turned[t]) {
            /* each lane turns the row's weights by its node's angle:
             * pddo_ops_turned's products, so at_many's bits */
            const Lanes c = lanes_load(ops->turn_c + s * L), sn = lanes_load(ops->turn_s + s * L);
            const Lanes cs = c * sn, cc = c * c - sn * sn;
            const double *const *w = (const double *const *)ops->tpl_w;
            for (int64_t r = 0; r < rows; r++) {
                const int64_t j0 = s * L + ops->tpl_off[tf + r];
                Lanes d[PDDO_FUSED_MAX];
                for (int q = 0; q < fields; q++) d[q] = lanes_load(F[q] + j0) - fk[q];
                const double g10 = w[PDDO_D_X][tf + r], g01 = w[PDDO_D_Y][tf + r];
                for (int o = 0; o < count; o++) {
                    Lanes wl;
                    switch (op[o]) {
                    case PDDO_D_X:
                        wl = c * g10 - sn * g01;
                        break;
                    case PDDO_D_Y:
                        wl = sn * g10 + c * g01;
                        break;
                    case PDDO_D_XY:
                        wl = cs * ops->tpl_dif[tf + r] + cc * w[PDDO_D_XY][tf + r];
                        break;
                    default:
                        wl = lanes_set(w[op[o]][tf + r]);
                        break;
                    }
                    acc[o] += wl * d[of[o]];
                }
            }
            for (int o = 0; o < count; o++) memcpy(sum + o * L, &acc[o], sizeof acc[o]);
            return;
        }
        for (int64_t r = 0; r < rows; r++) {
            const int64_t j0 = s * L + ops->tpl_off[tf + r];
            Lanes d[PDDO_FUSED_MAX];
            for (int q = 0; q < fields; q++) d[q] = lanes_load(F[q] + j0) - fk[q];
            for (int o = 0; o < count; o++) acc[o] += ops->tpl_w[op[o]][tf + r] * d[of[o]];
        }
        for (int o = 0; o < count; o++) memcpy(sum + o * L, &acc[o], sizeof acc[o]);
        return;
    }
    const int64_t base = ops->slice_first[s], rows = (ops->slice_first[s + 1] - base) / L;
    for (int64_t r = 0; r < rows; r++) {
        const int32_t *j = ops->slot_nbr + base + r * L;
        Lanes d[PDDO_FUSED_MAX];
        /* the nodes are numbered row by row, so on a lattice the slice's
         * member r is mostly one offset from each of its nodes: the
         * members are consecutive, one load instead of a gather */
        int consecutive = 1;
        for (int l = 1; l < L; l++) consecutive &= j[l] == j[0] + l;
        for (int q = 0; q < fields; q++) {
            Lanes g;
            if (consecutive)
                g = lanes_load(F[q] + j[0]);
            else
                for (int l = 0; l < L; l++) g[l] = F[q][j[l]];
            d[q] = g - fk[q];
        }
        for (int o = 0; o < count; o++)
            acc[o] += lanes_load(ops->w[op[o]] + base + r * L) * d[of[o]];
    }
    for (int o = 0; o < count; o++) memcpy(sum + o * L, &acc[o], sizeof acc[o]);
}

/* The distinct fields of f[0 .. count) into F, and each one's index. */
static int distinct_fields(int count, const double *const *f, const double **F, int *of) {
    int fields = 0;
    for (int o = 0; o < count; o++) {
        int q = 0;
        while (q < fields && F[q] != f[o]) q++;
        if (q == fields) F[fields++] = f[o];
        of[o] = q;
    }
    return fields;
}

/* slice_sums with the step's (fields, count) constants, so that the
 * compiler keeps the lanes in registers: (2, 6) the velocity's
 * derivatives, (4, 4) the divergences, (1, 2) grad p, (1, 1) one operator */
static void slice_counted(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                          int64_t s, double *sum) {
    const double *F[PDDO_FUSED_MAX];
    int of[PDDO_FUSED_MAX];
    const int fields = distinct_fields(count, f, F, of);
    /* the maps and the step's operators as constants too: an index known
     * only at run time keeps the differences in memory, and an operator
     * known only at run time leaves a turned row's choice in the loop */
    static const int step6[6] = {0, 0, 1, 1, 0, 1}, each[4] = {0, 1, 2, 3}, one[2] = {0, 0};
    static const PddoOp velocity[6] = {PDDO_D_X, PDDO_D_Y, PDDO_D_X, PDDO_D_Y, PDDO_LAP, PDDO_LAP};
    static const PddoOp gradients[4] = {PDDO_D_X, PDDO_D_Y, PDDO_D_X, PDDO_D_Y};
    if (fields == 2 && count == 6 && !memcmp(of, step6, sizeof step6) &&
        !memcmp(op, velocity, sizeof velocity))
        slice_sums(ops, 2, F, 6, velocity, step6, s, sum);
    else if (fields == 2 && count == 6 && !memcmp(of, step6, sizeof step6))
        slice_sums(ops, 2, F, 6, op, step6, s, sum);
    else if (fields == 4 && count == 4 && !memcmp(op, gradients, sizeof gradients))
        slice_sums(ops, 4, F, 4, gradients, each, s, sum);
    else if (fields == 4 && count == 4)
        slice_sums(ops, 4, F, 4, op, each, s, sum);
    else if (fields == 1 && count == 2 && !memcmp(op, gradients, 2 * sizeof *op))
        slice_sums(ops, 1, F, 2, gradients, one, s, sum);
    else if (fields == 1 && count == 2)
        slice_sums(ops, 1, F, 2, op, one, s, sum);
    else if (fields == 1 && count == 1)
        slice_sums(ops, 1, F, 1, op, one, s, sum);
    else
        slice_sums(ops, fields, F, count, op, of, s, sum);
}

void pddo_ops_slice_many(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                         int64_t s, double *sum) {
    slice_counted(ops, count, op, f, s, sum);
}

void pddo_ops_at_many(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                      int64_t k, double *sum) {
    at_many(ops, count, op, f, k, sum);
}

double pddo_ops_at(const PddoOps *ops, PddoOp op, const double *f, int64_t k) {
    double sum;
    at_many(ops, 1, &op, &f, k, &sum);
    return sum;
}

void pddo_ops_apply_many(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                         double *const *out) {
    const int64_t n = ops->n;
#pragma omp parallel if (n >= PARALLEL_MIN_ITEMS)
    {
        int64_t lo, hi;
        pddo_ops_share(ops, omp_get_thread_num(), omp_get_num_threads(), &lo, &hi);
        for (int64_t s = lo; s < hi; s++) {
            double sum[PDDO_FUSED_MAX * PDDO_LANES];
            slice_counted(ops, count, op, f, s, sum);
            for (int o = 0; o < count; o++)
                for (int l = 0; l < PDDO_LANES && s * PDDO_LANES + l < n; l++)
                    out[o][s * PDDO_LANES + l] = sum[o * PDDO_LANES + l];
        }
    }
}

void pddo_ops_apply(const PddoOps *ops, PddoOp op, const double *f, double *out) {
    pddo_ops_apply_many(ops, 1, &op, &f, &out);
}

void pddo_ops_free(PddoOps *ops) {
    for (int op = 0; op < PDDO_OPS; op++) nspd_free(&ops->w[op]), nspd_free(&ops->tpl_w[op]);
    nspd_free(&ops->slice_first);
    nspd_free(&ops->slice_tpl);
    nspd_free(&ops->cost_before);
    nspd_free(&ops->tpl_first);
    nspd_free(&ops->tpl_off);
    nspd_free(&ops->tpl_dif);
    nspd_free(&ops->tpl_turned);
    nspd_free(&ops->turn_c);
    nspd_free(&ops->turn_s);
    nspd_free(&ops->turned);
    nspd_free(&ops->dif);
    nspd_free(&ops->slot_nbr);
    memset(ops, 0, sizeof *ops);
}

double pddo_ops_interpolation(double xc, double yc, int64_t count, const int32_t *nbr,
                              const double *x, const double *y, const double *area, double delta,
                              double *w) {
    double Lf[SPD_SMALL_MAX][SPD_SMALL_MAX] = {{0}};
    double p[SPD_SMALL_MAX] = {0}, scale[SPD_SMALL_MAX] = {0};
    const double inv_delta = 1.0 / delta, inv_area = inv_delta * inv_delta;
    const Centre ctr = centre_at(x, y, xc, yc, delta);
    const double cond = shape_factor(nbr, count, &ctr, area, true, Lf, scale);
    if (!isfinite(cond)) return cond;
    /* f(c) = a_0 of the weighted least-squares quadratic: w_j = wa P_j^T M^-1 e_0 */
    for (int64_t m = 0; m < count; m++) {
        const int32_t j = nbr[m];
        const double s1 = (x[j] - xc) * inv_delta, s2 = (y[j] - yc) * inv_delta;
        const double wa = weight(s1, s2) * area[j] * inv_area;
        double z[SPD_SMALL_MAX] = {0};
        const int terms = basis(true, s1, s2, p);
        spd_small_solve((const double(*)[SPD_SMALL_MAX])Lf, terms, scale, p, z);
        w[m] = wa * z[0];
    }
    return cond;
}
