/* The lattice view of a bond-based body (stencil.h). */
#include "solid/bond/stencil.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

enum { LANES = 8, MAX_CELLS_A_POINT = 8 };

/* The lattice offset of bond i-j, axis by axis (0 past dim). */
static void bond_offset(const BondBody *b, int64_t i, int32_t j, int64_t d[3]) {
    for (int a = 0; a < 3; a++)
        d[a] = a < b->dim ? (int64_t)b->lattice[a][j] - b->lattice[a][i] : 0;
}

/* Offset order: dz, then dy, then dx. */
static int64_t offset_key(const BondBody *b, int64_t i, int32_t j) {
    int64_t d[3];
    bond_offset(b, i, j, d);
    const int64_t span = (int64_t)1 << 21; /* |d| < 2^20 a lattice axis */
    return (d[2] * span + d[1]) * span + d[0];
}

void bond_rows_in_offset_order(BondBody *body) {
    const int64_t n = body->n;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) { /* insertion sort: rows of tens of bonds */
        int32_t *row = body->bond_nbr + body->bond_first[i];
        const int64_t len = body->bond_first[i + 1] - body->bond_first[i];
        for (int64_t a = 1; a < len; a++) {
            const int32_t j = row[a];
            const int64_t key = offset_key(body, i, j);
            int64_t c = a;
            for (; c > 0 && offset_key(body, i, row[c - 1]) > key; c--) row[c] = row[c - 1];
            row[c] = j;
        }
    }
}

/* The slot of offset d in offset_of (stencil.h). */
static int64_t offset_slot(const BondStencil *s, const int64_t d[3]) {
    const int64_t side = 2 * s->reach + 1, dz = s->dim == 3 ? d[2] + s->reach : 0;
    return (dz * side + d[1] + s->reach) * side + d[0] + s->reach;
}

/* The reach and the offsets of the held points' bonds, in offset order. */
static int find_offsets(const BondBody *b, BondStencil *s) {
    int64_t reach = 0, d[3];
    for (int64_t i = 0; i < b->n; i++)
        for (int64_t k = b->bond_first[i]; k < b->bond_first[i + 1]; k++) {
            bond_offset(b, i, b->bond_nbr[k], d);
            for (int a = 0; a < 3; a++) reach = llabs(d[a]) > reach ? llabs(d[a]) : reach;
        }
    if (reach > 64) return NSPD_OK; /* a horizon of more than 64 spacings: no view */
    s->reach = (int)reach;
    const int64_t side = 2 * reach + 1, slots = side * side * (b->dim == 3 ? side : 1);
    TRY(nspd_alloc(&s->offset_of, (size_t)slots, sizeof(int32_t)));
    for (int64_t i = 0; i < b->n; i++)
        for (int64_t k = b->bond_first[i]; k < b->bond_first[i + 1]; k++) {
            bond_offset(b, i, b->bond_nbr[k], d);
            s->offset_of[offset_slot(s, d)] = 1;
        }
    int m = 0;
    for (int64_t q = 0; q < slots; q++) /* q runs in offset order */
        s->offset_of[q] = s->offset_of[q] ? m++ : -1;
    s->offsets = m;
    return NSPD_OK;
}

/* The cells, their positions and maps, and the active chunks. */
static int fill(const BondBody *b, BondStencil *s) {
    const int64_t all = b->n + b->ghosts, cells = s->cells;
    const int dim = s->dim == 3 ? 3 : 2;
    const size_t nc = (size_t)cells;
    for (int a = 0; a < dim; a++) {
        TRY(nspd_alloc(&s->x[a], nc, sizeof(double)));
        TRY(nspd_alloc(&s->u[a], nc, sizeof(double)));
    }
    TRY(nspd_alloc(&s->shift, (size_t)s->offsets, sizeof(int64_t)));
    TRY(nspd_alloc(&s->cell_point, nc, sizeof(int32_t)));
    TRY(nspd_alloc(&s->point_cell, (size_t)all, sizeof(int32_t)));
    const int64_t side = 2 * s->reach + 1, slots = side * side * (dim == 3 ? side : 1);
    for (int64_t q = 0; q < slots; q++)
        if (s->offset_of[q] >= 0) {
            const int64_t dx = q % side - s->reach, dy = q / side % side - s->reach,
                          dz = dim == 3 ? q / (side * side) - s->reach : 0;
            s->shift[s->offset_of[q]] = dz * s->stride[2] + dy * s->stride[1] + dx * s->stride[0];
        }
    /* every cell at its lattice position (from point 0's), then the points */
    const double dx = b->spacing;
    for (int64_t c = 0; c < cells; c++) {
        for (int a = 0; a < dim; a++) {
            const int64_t idx = c / s->stride[a] % s->extent[a];
            s->x[a][c] = b->x[a][0] + (double)(idx + s->origin[a] - b->lattice[a][0]) * dx;
        }
        s->cell_point[c] = -1;
    }
    for (int64_t i = 0; i < all; i++) {
        int64_t c = 0;
        for (int a = 0; a < dim; a++) c += (b->lattice[a][i] - s->origin[a]) * s->stride[a];
        s->point_cell[i] = (int32_t)c;
        s->cell_point[c] = (int32_t)i;
        for (int a = 0; a < dim; a++) s->x[a][c] = b->x[a][i];
    }
    /* the active chunks: those holding a point of this process */
    uint8_t *active = NULL;
    TRY(nspd_alloc(&active, nc / LANES, 1));
    for (int64_t i = 0; i < b->n; i++) active[s->point_cell[i] / LANES] = 1;
    for (int64_t k = 0; k < cells / LANES; k++) s->chunks += active[k];
    int status = nspd_alloc(&s->chunk_cell, (size_t)s->chunks, sizeof(int64_t));
    if (status == NSPD_OK)
        status = nspd_alloc(&s->state, (size_t)s->chunks * (size_t)s->offsets, sizeof(uint16_t));
    if (status == NSPD_OK) status = nspd_alloc(&s->block, (size_t)s->chunks, sizeof(int32_t));
    for (int64_t k = 0, q = 0; status == NSPD_OK && k < cells / LANES; k++)
        if (active[k]) s->chunk_cell[q++] = k * LANES;
    nspd_free(&active);
    return status;
}

/* The held point in lane l of active chunk q, or -1 (no point, or a
 * ghost: no bonds of its own). */
static int32_t held_point(const BondStencil *s, const BondBody *b, int64_t q, int l) {
    const int32_t i = s->cell_point[s->chunk_cell[q] + l];
    return i < b->n ? i : -1;
}

/* The offset index of bond e of point i. */
static int bond_offset_index(const BondStencil *s, const BondBody *b, int32_t i, int64_t e) {
    int64_t d[3];
    bond_offset(b, i, b->bond_nbr[e], d);
    return s->offset_of[offset_slot(s, d)];
}

/* The magnitude most bonds of each offset have (a majority vote over the
 * intact ones; any value is correct, the most common saves the most). */
static int shared_magnitudes(const BondStencil *s, const BondBody *b, float *shared) {
    int64_t *votes = NULL;
    TRY(nspd_alloc(&votes, (size_t)s->offsets, sizeof *votes));
    for (int64_t q = 0; q < s->chunks; q++)
        for (int l = 0; l < LANES; l++) {
            const int32_t i = held_point(s, b, q, l);
            if (i < 0) continue;
            for (int64_t e = b->bond_first[i]; e < b->bond_first[i + 1]; e++) {
                const float k = fabsf(b->bond_coef[e]);
                const int o = bond_offset_index(s, b, i, e);
                if (k == 0.0f) continue; /* broken (body.h) */
                if (votes[o] == 0) shared[o] = k;
                votes[o] += k == shared[o] ? 1 : -1;
            }
        }
    nspd_free(&votes);
    return NSPD_OK;
}

/* Whether a bond of chunk q has a magnitude other than the shared one. */
static bool needs_own_block(const BondStencil *s, const BondBody *b, const float *shared,
                            int64_t q) {
    for (int l = 0; l < LANES; l++) {
        const int32_t i = held_point(s, b, q, l);
        if (i < 0) continue;
        for (int64_t e = b->bond_first[i]; e < b->bond_first[i + 1]; e++) {
            const float k = fabsf(b->bond_coef[e]);
            if (k != 0.0f && k != shared[bond_offset_index(s, b, i, e)]) return true;
        }
    }
    return false;
}

int bond_stencil_take(BondStencil *s, const BondBody *b) {
    const int m = s->offsets;
    float *shared = NULL, *magnitude = NULL;
    TRY(nspd_alloc(&shared, (size_t)m, sizeof *shared));
    int status = shared_magnitudes(s, b, shared);
    int64_t own = 0; /* the chunks with a bond of another magnitude: a block of their own */
    for (int64_t q = 0; status == NSPD_OK && q < s->chunks; q++)
        own += needs_own_block(s, b, shared, q);
    if (status == NSPD_OK)
        status = nspd_alloc(&magnitude, (size_t)(1 + own) * (size_t)m * LANES, sizeof(float));
    if (status != NSPD_OK) {
        nspd_free(&shared);
        return status;
    }
    int32_t blocks = 1;
    for (int64_t q = 0; q < s->chunks; q++)
        s->block[q] = needs_own_block(s, b, shared, q) ? blocks++ : 0;
    for (int o = 0; o < m; o++)
        for (int l = 0; l < LANES; l++) magnitude[o * LANES + l] = shared[o];
    nspd_free(&shared);
#pragma omp parallel for schedule(static) if (s->chunks >= PARALLEL_MIN_ITEMS / LANES)
    for (int64_t q = 0; q < s->chunks; q++) {
        uint16_t *state = s->state + q * m;
        float *mine = s->block[q] ? magnitude + (int64_t)s->block[q] * m * LANES : NULL;
        for (int o = 0; o < m; o++) state[o] = 0;
        for (int l = 0; l < LANES; l++) {
            const int32_t i = held_point(s, b, q, l);
            if (i < 0) continue;
            for (int64_t e = b->bond_first[i]; e < b->bond_first[i + 1]; e++) {
                const float k = b->bond_coef[e];
                const int o = bond_offset_index(s, b, i, e);
                if (k == 0.0f) continue; /* broken */
                state[o] |= (uint16_t)(1u << l | (k > 0.0f ? 1u << (LANES + l) : 0u));
                if (mine) mine[o * LANES + l] = fabsf(k);
            }
        }
    }
    nspd_free(&s->magnitude);
    s->magnitude = magnitude;
    s->u_current = false;
    return NSPD_OK;
}

int bond_stencil_create(const BondBody *b, BondStencil **out) {
    *out = NULL;
    const int64_t all = b->n + b->ghosts;
    if (b->n == 0) return NSPD_OK;
    int32_t lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int a = 0; a < b->dim; a++) lo[a] = hi[a] = b->lattice[a][0];
    for (int64_t i = 0; i < all; i++)
        for (int a = 0; a < b->dim; a++) {
            if (b->lattice[a][i] < lo[a]) lo[a] = b->lattice[a][i];
            if (b->lattice[a][i] > hi[a]) hi[a] = b->lattice[a][i];
        }
    BondStencil *s = NULL;
    TRY(nspd_alloc(&s, 1, sizeof *s));
    s->dim = b->dim;
    int status = find_offsets(b, s);
    if (status != NSPD_OK || !s->offset_of) {
        bond_stencil_free(&s);
        return status;
    }
    /* a chunk's lanes reach 7 cells past its last point along the major
     * axis, and every lane R cells further on each axis */
    const int64_t r = s->reach;
    for (int a = 1; a < b->dim; a++)
        if (hi[a] - lo[a] > hi[s->major] - lo[s->major]) s->major = a;
    double cells = 1;
    for (int a = 0; a < 3; a++) {
        const int64_t span = (int64_t)hi[a] - lo[a] + 1, pad = a < b->dim ? r : 0;
        s->extent[a] = span + 2 * pad;
        if (a == s->major) s->extent[a] = (s->extent[a] + 2 * (LANES - 1)) / LANES * LANES;
        s->origin[a] = (int32_t)(lo[a] - pad);
        cells *= (double)s->extent[a];
    }
    int64_t step = 1; /* the major axis, then the others in order */
    s->stride[s->major] = step, step *= s->extent[s->major];
    for (int a = 0; a < 3; a++)
        if (a != s->major) s->stride[a] = step, step *= s->extent[a];
    s->cells = step;
    if (cells > (double)(MAX_CELLS_A_POINT * all + 4096) || cells > (double)INT32_MAX) {
        bond_stencil_free(&s);
        return NSPD_OK;
    }
    status = fill(b, s);
    if (status != NSPD_OK) {
        bond_stencil_free(&s);
        return status;
    }
    status = bond_stencil_take(s, b); /* now, with the build, not in the first step */
    if (status != NSPD_OK) {
        bond_stencil_free(&s);
        return status;
    }
    *out = s;
    return NSPD_OK;
}

/* The displacements of points [from, to) into their cells. */
static void copy_u(BondStencil *s, const BondBody *b, int64_t from, int64_t to) {
    const int dim = s->dim == 3 ? 3 : 2;
#pragma omp parallel for schedule(static) if (to - from >= PARALLEL_MIN_ITEMS)
    for (int64_t i = from; i < to; i++)
        for (int a = 0; a < dim; a++) s->u[a][s->point_cell[i]] = b->u[a][i];
}

void bond_stencil_refresh(BondStencil *s, const BondBody *b) {
    copy_u(s, b, 0, b->n + b->ghosts);
}

void bond_stencil_refresh_ghosts(BondStencil *s, const BondBody *b) {
    copy_u(s, b, b->n, b->n + b->ghosts);
}

void bond_stencil_free(BondStencil **sp) {
    BondStencil *s = *sp;
    if (!s) return;
    for (int a = 0; a < 3; a++) {
        nspd_free(&s->x[a]);
        nspd_free(&s->u[a]);
    }
    nspd_free(&s->shift);
    nspd_free(&s->offset_of);
    nspd_free(&s->chunk_cell);
    nspd_free(&s->state);
    nspd_free(&s->block);
    nspd_free(&s->magnitude);
    nspd_free(&s->cell_point);
    nspd_free(&s->point_cell);
    nspd_free(sp);
}
