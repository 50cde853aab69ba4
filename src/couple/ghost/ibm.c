/* Ghost-cell immersed boundary: tagging, ghost lists, the per-step fill and
 * the incremental update (paper 000 Sec. 3.3; the equations are in ibm.h,
 * the stencils in stencil.c, the geometry in geometry.c).
 *
 * Tagging. A cell whose centre is inside a body or on its wall is "inside".
 * An inside cell is a GHOST if a fluid cell lies within Manhattan distance 2
 * (the flow step reads a fluid cell's face neighbours and their MUSCL
 * slopes, which read the neighbours' neighbours: with two layers the wall
 * faces get second-order slopes and no SOLID value is ever read), SOLID
 * otherwise. Box ghost layers are not tagged here: bc_fill copies the kinds
 * of their image cells every step.
 *
 * Ghost values (Eqs. 33-39), per ghost g with nodes m, weights wd, wn:
 *   u_P = sum_m wd_m u_m (u_m = wall velocity at a replaced node's wall point),
 *   p_P = sum_m wn_m p_m (fluid nodes only: the Neumann data are zero),
 *   T_P = the Dirichlet sum with T_wall (isothermal) or the Neumann sum (adiabatic),
 *   u_GC = u_BI + r (u_BI - u_P)   (r = 1: Eq. 39),
 *   p_GC = p_P (dp/dn = 0; the paper's p_GC = p_BI to the same order),
 *   T_GC = T_w + r (T_w - T_P) (isothermal, floored at T_w / 4 like the box
 *          walls of bc.c) or T_P (adiabatic), rho_GC = p_GC / (R T_GC).
 * p_P and adiabatic T_P are clipped to the range of the fluid node values: a
 * bilinear fit with wall rows can overshoot next to a shock, and a negative
 * ghost pressure would stop the run; for smooth data the clip is inactive.
 * The wall value at a boundary point is linear along its segment between
 * the two markers (Eq. 32 written with the segment parameter, which also
 * covers axis-parallel segments where Eq. 32 divides by zero). A replaced
 * node of another body uses the ghost's own wall temperature.
 *
 * Cost of the fill: per ghost 4 gathers of 4 conserved variables and ~80
 * flops; ghosts ~ 4 x wall length / h, so it is a small fraction of a flux
 * step over the whole grid (measured in tests/verify/ibm_cylinder).
 *
 * Update. The walls move from old to new marker positions. A cell's
 * inside flag can change only where some segment sweeps over it, and a
 * segment moving linearly from (a, b) to (a', b') stays within the bounding
 * box of the four points: only cell centres in those boxes are re-tested.
 * Kinds are recomputed within Manhattan distance 2 of changed cells. A ghost
 * stencil is rebuilt if it is new or its recorded dependency box touches a
 * bucket swept by a moved segment; others are kept. The ghost list stays
 * sorted by cell, so the result equals a build from scratch bit for bit
 * (tested in tests/unit/couple/ghost/test_update.c). */
#include "couple/ghost/ibm_internal.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "core/timer.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ markers */

static int reserve_markers(Ibm *ibm, int nm) {
    if (nm <= ibm->nm_cap) return NSPD_OK;
    const size_t o = (size_t)ibm->nm_cap, c = (size_t)nm;
    TRY(nspd_realloc(&ibm->mx, o, c, sizeof(double)));
    TRY(nspd_realloc(&ibm->my, o, c, sizeof(double)));
    TRY(nspd_realloc(&ibm->mvx, o, c, sizeof(double)));
    TRY(nspd_realloc(&ibm->mvy, o, c, sizeof(double)));
    TRY(nspd_realloc(&ibm->seg_end, o, c, sizeof(int)));
    TRY(nspd_realloc(&ibm->seg_body, o, c, sizeof(int)));
    ibm->nm_cap = nm;
    return NSPD_OK;
}

static int set_markers(Ibm *ibm, const IbmPolyline *bodies, int count) {
    int nm = 0;
    for (int b = 0; b < count; b++) nm += bodies[b].n;
    TRY(reserve_markers(ibm, nm));
    int k = 0;
    for (int b = 0; b < count; b++) {
        const IbmPolyline *p = &bodies[b];
        ibm->first[b] = k;
        ibm->count[b] = p->n;
        ibm->thermal[b] = p->thermal;
        ibm->wall_t[b] = p->wall_temperature;
        ibm->le[b] = p->leading_edge >= 0 && p->leading_edge < p->n ? k + p->leading_edge : -1;
        ibm->te[b] = p->trailing_edge >= 0 && p->trailing_edge < p->n ? k + p->trailing_edge : -1;
        for (int q = 0; q < p->n; q++, k++) {
            ibm->mx[k] = p->x[q];
            ibm->my[k] = p->y[q];
            ibm->mvx[k] = p->vx ? p->vx[q] : 0.0;
            ibm->mvy[k] = p->vy ? p->vy[q] : 0.0;
            ibm->seg_end[k] = q + 1 < p->n ? k + 1 : ibm->first[b];
            ibm->seg_body[k] = b;
        }
    }
    ibm->nm = nm;
    return NSPD_OK;
}

static int check_bodies(const IbmPolyline *bodies, int count) {
    if (count < 1 || count > 255)
        return NSPD_FAIL(NSPD_ERR_INPUT, "immersed boundary: 1 to 255 bodies (got %d)", count);
    for (int b = 0; b < count; b++) TRY(ibm_polyline_check(&bodies[b], b));
    return NSPD_OK;
}

/* ---------------------------------------------------------------- tags */

static int compute_kind(const Ibm *ibm, int i, int j) {
    const Grid *g = ibm->grid;
    if (!ibm->inside[grid_index(g, i, j)]) return FLOW_CELL_FLUID;
    for (int b = -IBM_REACH; b <= IBM_REACH; b++) {
        const int r = IBM_REACH - abs(b);
        for (int a = -r; a <= r; a++) {
            const int q = i + a, p = j + b;
            if (q < 0 || p < 0 || q >= g->nx || p >= g->ny) continue;
            if (!ibm->inside[grid_index(g, q, p)]) return FLOW_CELL_GHOST;
        }
    }
    return FLOW_CELL_SOLID;
}

/* First index i in [0, n] with c[i] >= x (c[n] counts as +infinity): the
 * centres increase strictly, so it is the bracket's lower centre when that
 * one sits exactly at x and the next one otherwise. */
static int lower_bound(const GridAxis *a, double x) {
    const int i = grid_axis_bracket(a, x);
    return i >= 0 && a->center[i] == x ? i : i + 1;
}
/* Last index i in [-1, n-1] with c[i] <= x. */
static int upper_last(const GridAxis *a, double x) {
    return grid_axis_bracket(a, x);
}

static void walls_box(const Ibm *ibm, double box[4]) {
    box[0] = box[2] = (double)INFINITY;
    box[1] = box[3] = -(double)INFINITY;
    for (int k = 0; k < ibm->nm; k++) {
        box[0] = fmin(box[0], ibm->mx[k]), box[1] = fmax(box[1], ibm->mx[k]);
        box[2] = fmin(box[2], ibm->my[k]), box[3] = fmax(box[3], ibm->my[k]);
    }
}

/* Inside flags and kinds of every interior cell. */
static void tag_all(Ibm *ibm) {
    const Grid *g = ibm->grid;
    memset(ibm->inside, 0, (size_t)ibm->cells);
    double box[4];
    walls_box(ibm, box);
    const int i0 = lower_bound(&g->ax[0], box[0]), i1 = upper_last(&g->ax[0], box[1]);
    const int j0 = lower_bound(&g->ax[1], box[2]), j1 = upper_last(&g->ax[1], box[3]);
    const int rows = j1 - j0 + 1;
    const int64_t n = rows > 0 && i1 >= i0 ? (int64_t)rows * (i1 - i0 + 1) : 0;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++)
            ibm->inside[grid_index(g, i, j)] =
                (uint8_t)ibm_point_inside(ibm, g->ax[0].center[i], g->ax[1].center[j]);
    int64_t solid = 0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            ibm->kind[k] = ibm->inside[k] ? (uint8_t)compute_kind(ibm, i, j) : FLOW_CELL_FLUID;
            solid += ibm->kind[k] == FLOW_CELL_SOLID;
        }
    ibm->last.solid_cells = solid;
}

/* ---------------------------------------------------------- work lists */

static int reserve_list(int64_t **list, int *cap, int64_t n) {
    if (n <= *cap) return NSPD_OK;
    int64_t c = *cap > 0 ? *cap : 256;
    while (c < n) c *= 2;
    if (c > 2000000000) return NSPD_FAIL(NSPD_ERR_NOMEM, "immersed boundary: list too long");
    TRY(nspd_realloc(list, (size_t)*cap, (size_t)c, sizeof(int64_t)));
    *cap = (int)c;
    return NSPD_OK;
}

static void cell_ij(const Grid *g, int64_t k, int *i, int *j) {
    *j = (int)(k / g->stride) - GRID_NG;
    *i = (int)(k % g->stride) - GRID_NG;
}

/* ------------------------------------------------------------ builds */

/* A stencil build costs ~2 us (nearest-point searches, sight tests, two 4x4
 * solves), a few hundred times a cell update: build loops take a thread
 * team from 256 items (PARALLEL_MIN_ITEMS / 16) on. Each item writes only
 * its own entry, so the result does not depend on the threads. */

static void build_probes_for(Ibm *ibm, int s) {
    const Grid *g = ibm->grid;
    const int e = ibm->seg_end[s];
    const double ax = ibm->mx[s], ay = ibm->my[s], bx = ibm->mx[e], by = ibm->my[e];
    const double l = hypot(bx - ax, by - ay), nx = (by - ay) / l, ny = -(bx - ax) / l;
    const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
    const int i = grid_axis_cell_of(&g->ax[0], mx), j = grid_axis_cell_of(&g->ax[1], my);
    const double h = fmax(g->ax[0].width[i], g->ax[1].width[j]);
    for (int q = 0; q < 2; q++) {
        const double d = (q + 1) * IBM_PROBE_STEP * h, px = mx + d * nx, py = my + d * ny;
        /* another process's probe: its place only (the loads read its
         * distance, the plan its cell) */
        ibm_place_point(ibm, px, py, d, &ibm->probes, 2 * s + q);
        if (ibm_share_evaluates(ibm, ibm->probes.cell[2 * s + q]))
            ibm_build_point(ibm, px, py, d, NULL, &ibm->probes, 2 * s + q);
    }
}

static int build_probes(Ibm *ibm) {
    TRY(ibm_stencils_reserve(&ibm->probes, 2 * ibm->nm));
    ibm->probes.n = 2 * ibm->nm;
    const int n = ibm->nm;
#pragma omp parallel for schedule(dynamic, 64) if (n >= PARALLEL_MIN_ITEMS / 16)
    for (int s = 0; s < n; s++) build_probes_for(ibm, s);
    return NSPD_OK;
}

/* Ghost statistics (O(ghosts)); the solid count is kept by the callers.
 * On several processes, after an update, of the stencils this process
 * built (its block and halo): the levels, cases and weights; the count
 * of ghosts is the whole grid's. */
static void count_stats(Ibm *ibm) {
    IbmUpdateStats *st = &ibm->last;
    const IbmStencilSet *G = &ibm->ghosts;
    st->ghosts = G->n;
    memset(st->by_level, 0, sizeof st->by_level);
    memset(st->by_case, 0, sizeof st->by_case);
    st->max_weight_sum = 0.0;
    for (int e = 0; e < G->n; e++) {
        if (G->level[e] >= IBM_LEVEL_COUNT) continue; /* another process's */
        st->by_level[G->level[e]]++;
        if (G->level[e] == IBM_LEVEL_IMAGE && G->nrep[e] < 3) st->by_case[G->nrep[e]]++;
        double sd = 0.0, sn = 0.0;
        for (int m = 0; m < 4; m++) {
            sd += fabs(G->wd[4 * e + m]);
            if (G->rseg[4 * e + m] == IBM_NODE_FLUID) sn += fabs(G->wn[4 * e + m]);
        }
        st->max_weight_sum = fmax(st->max_weight_sum, fmax(sd, sn));
    }
}

static int build_all_ghosts(Ibm *ibm) {
    const Grid *g = ibm->grid;
    int n = 0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) n += ibm->kind[grid_index(g, i, j)] == FLOW_CELL_GHOST;
    TRY(ibm_stencils_reserve(&ibm->ghosts, n));
    IbmStencilSet *G = &ibm->ghosts;
    G->n = 0;
    for (int64_t k = 0; k < ibm->cells; k++) ibm->slot[k] = -1;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (ibm->kind[k] != FLOW_CELL_GHOST) continue;
            ibm->slot[k] = G->n;
            G->cell[G->n++] = k;
        }
#pragma omp parallel for schedule(dynamic, 64) if (n >= PARALLEL_MIN_ITEMS / 16)
    for (int e = 0; e < n; e++) {
        int i, j;
        cell_ij(g, G->cell[e], &i, &j);
        ibm_build_ghost(ibm, i, j, G, e);
    }
    return NSPD_OK;
}

/* --------------------------------------------------------- create/destroy */

int ibm_create(Ibm **out, const Grid *grid, const IbmPolyline *bodies, int count) {
    *out = NULL;
    TRY(check_bodies(bodies, count));
    const double t0 = nspd_wall_time();
    Ibm *ibm = NULL;
    TRY(nspd_alloc(&ibm, 1, sizeof *ibm));
    ibm->grid = grid;
    ibm->nx = grid->nx;
    ibm->ny = grid->ny;
    ibm->cells = grid->size;
    ibm->body_count = count;
    int st = NSPD_OK;
#define CHECK(expr)                                                                                \
    do {                                                                                           \
        if ((st = (expr)) < 0) goto fail;                                                          \
    } while (0)
    CHECK(nspd_alloc(&ibm->first, (size_t)count, sizeof(int)));
    CHECK(nspd_alloc(&ibm->count, (size_t)count, sizeof(int)));
    CHECK(nspd_alloc(&ibm->old_count, (size_t)count, sizeof(int)));
    CHECK(nspd_alloc(&ibm->thermal, (size_t)count, sizeof(int)));
    CHECK(nspd_alloc(&ibm->wall_t, (size_t)count, sizeof(double)));
    CHECK(nspd_alloc(&ibm->le, (size_t)count, sizeof(int)));
    CHECK(nspd_alloc(&ibm->te, (size_t)count, sizeof(int)));
    CHECK(nspd_alloc(&ibm->inside, (size_t)grid->size, 1));
    CHECK(nspd_alloc(&ibm->kind, (size_t)grid->size, 1));
    CHECK(nspd_alloc(&ibm->mark, (size_t)grid->size, 1));
    CHECK(nspd_alloc(&ibm->slot, (size_t)grid->size, sizeof(int32_t)));
    CHECK(set_markers(ibm, bodies, count));
    CHECK(ibm_buckets_build(ibm));
    tag_all(ibm);
    CHECK(build_all_ghosts(ibm));
    CHECK(build_probes(ibm));
#undef CHECK
    count_stats(ibm);
    ibm->last.seconds = nspd_wall_time() - t0;
    *out = ibm;
    return NSPD_OK;
fail:
    ibm_destroy(&ibm);
    return st;
}

void ibm_destroy(Ibm **pp) {
    Ibm *ibm = *pp;
    if (!ibm) return;
    nspd_free(&ibm->first);
    nspd_free(&ibm->count);
    nspd_free(&ibm->old_count);
    nspd_free(&ibm->thermal);
    nspd_free(&ibm->wall_t);
    nspd_free(&ibm->le);
    nspd_free(&ibm->te);
    nspd_free(&ibm->mx);
    nspd_free(&ibm->my);
    nspd_free(&ibm->mvx);
    nspd_free(&ibm->mvy);
    nspd_free(&ibm->seg_end);
    nspd_free(&ibm->seg_body);
    nspd_free(&ibm->old_mx);
    nspd_free(&ibm->old_my);
    ibm_buckets_free(&ibm->bk);
    nspd_free(&ibm->inside);
    nspd_free(&ibm->kind);
    nspd_free(&ibm->mark);
    nspd_free(&ibm->slot);
    ibm_stencils_free(&ibm->ghosts);
    ibm_stencils_free(&ibm->spare);
    ibm_stencils_free(&ibm->probes);
    nspd_free(&ibm->list_a);
    nspd_free(&ibm->list_b);
    nspd_free(&ibm->swept);
    nspd_free(&ibm->moved_bucket);
    ibm_share_free(&ibm->share);
    nspd_free(pp);
}

/* ---------------------------------------------------------------- fill */

static inline void set_cons(double *const w[4], int64_t k, double rho, double u, double v, double p,
                            double gm1) {
    w[0][k] = rho;
    w[1][k] = rho * u;
    w[2][k] = rho * v;
    w[3][k] = p / gm1 + 0.5 * rho * (u * u + v * v);
}

/* Ghost entry e from the fluid state w (indexed like the Ibm's cells),
 * into out (the solver's arrays: its cells ibm_share_local's). */
static inline void fill_one(Ibm *ibm, const GksSolver *s, int e, const IbmFieldView *w,
                            double *const out[4], double gm1, double R) {
    IbmStencilSet *G = &ibm->ghosts;
    const int b = G->body[e];
    const int iso = ibm->thermal[b] == IBM_WALL_ISOTHERMAL;
    const double Tw = ibm->wall_t[b], r = G->ratio[e];
    const IbmPrim q = ibm_stencil_eval(ibm, G, e, w, gm1, R, iso, Tw);
    double uw, vw;
    ibm_wall_velocity(ibm, G->seg[e], G->t[e], &uw, &vw);
    G->wu[e] = uw;
    G->wv[e] = vw;
    const double u = uw + r * (uw - q.u), v = vw + r * (vw - q.v); /* Eq. 39 */
    const double T = iso ? fmax(Tw + r * (Tw - q.T), 0.25 * Tw) : q.T;
    set_cons(out, ibm_share_local(ibm, s, G->cell[e]), q.p / (R * T), u, v, q.p, gm1);
}

void ibm_fill_ghosts(void *ctx, GksSolver *s) {
    Ibm *ibm = ctx;
    GksFields f = gks_solver_fields(s);
    const GksParams *gas = gks_solver_gas(s);
    const double gm1 = gas->gamma - 1.0, R = gas->R;
    double *const w[4] = {f.w[0], f.w[1], f.w[2], f.w[3]};
    if (ibm->share) { /* several processes: this block's ghosts, from the shadow */
        int n;
        const int *mine = ibm_share_ghosts(ibm, &n);
        const IbmFieldView shadow = ibm_share_refresh(ibm, s);
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int i = 0; i < n; i++) fill_one(ibm, s, mine[i], &shadow, w, gm1, R);
    } else {
        const int n = ibm->ghosts.n;
        const IbmFieldView view = ibm_solver_view(s);
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int e = 0; e < n; e++) fill_one(ibm, s, e, &view, w, gm1, R);
    }
    /* the solver reads the slot of its own cells */
    if (ibm->faces == IBM_FACES_SEALED)
        gks_solver_set_ghost_walls(s, ibm_share_slots(ibm), ibm->ghosts.wu, ibm->ghosts.wv);
    else
        gks_solver_set_ghost_walls(s, NULL, NULL, NULL);
}

const char *const IBM_GHOST_FACE_NAMES[IBM_FACES_COUNT + 1] = {"reflected", "sealed", NULL};

void ibm_set_ghost_faces(Ibm *ibm, IbmGhostFaces faces) {
    ibm->faces = faces;
}

int ibm_attach(Ibm *ibm, GksSolver *s) {
    const Grid *g = gks_solver_whole_grid(s);
    if (g->nx != ibm->nx || g->ny != ibm->ny || g->size != ibm->cells)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "immersed boundary: built for a %d x %d grid, attached to %d x %d",
                         ibm->nx, ibm->ny, g->nx, g->ny);
    if (comm_distributed(gks_solver_comm(s)) && !ibm->share) TRY(ibm_share_create(ibm, s));
    /* the kinds of this process's block (the whole grid on one) */
    GksFields f = gks_solver_fields(s);
    int first[2], count[2];
    gks_solver_block(s, gks_solver_comm(s)->rank, first, count);
    for (int j = first[1]; j < first[1] + count[1]; j++)
        for (int i = first[0]; i < first[0] + count[0]; i++) {
            const int64_t k = grid_index(g, i, j);
            f.kind[ibm_share_local(ibm, s, k)] = ibm->kind[k];
        }
    gks_solver_set_ghost_hook(s, ibm_fill_ghosts, ibm);
    gks_solver_fill_boundaries(s);
    ibm_fill_ghosts(ibm, s);
    return NSPD_OK;
}

static void soft_start(Ibm *ibm, GksSolver *s, double length, bool keep_total) {
    if (!(length > 0.0)) return;
    const Grid *g = ibm->grid;
    GksFields f = gks_solver_fields(s);
    const double gamma = gks_solver_gas(s)->gamma, gm1 = gamma - 1.0;
    const double cp = gamma * gks_solver_gas(s)->R / gm1;
    double box[4];
    walls_box(ibm, box);
    /* this process's block (the whole grid on one); the cells are the
     * Ibm's, the solver's ibm_share_local's */
    int first[2], count[2];
    gks_solver_block(s, gks_solver_comm(s)->rank, first, count);
    const int il = lower_bound(&g->ax[0], box[0] - length);
    const int ih = upper_last(&g->ax[0], box[1] + length);
    const int jl = lower_bound(&g->ax[1], box[2] - length);
    const int jh = upper_last(&g->ax[1], box[3] + length);
    const int i0 = il > first[0] ? il : first[0];
    const int i1 = ih < first[0] + count[0] - 1 ? ih : first[0] + count[0] - 1;
    const int j0 = jl > first[1] ? jl : first[1];
    const int j1 = jh < first[1] + count[1] - 1 ? jh : first[1] + count[1] - 1;
    double *const *w = f.w;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const int64_t cell = grid_index(g, i, j), k = ibm_share_local(ibm, s, cell);
            if (ibm->kind[cell] != FLOW_CELL_FLUID) continue;
            const IbmWallPoint wp = ibm_nearest(ibm, g->ax[0].center[i], g->ax[1].center[j]);
            if (wp.d >= length) continue;
            const double z = wp.d / length, fz = z * z * (3.0 - 2.0 * z);
            double uw, vw;
            ibm_wall_velocity(ibm, wp.seg, wp.t, &uw, &vw);
            const double rho = f.w[0][k], u = f.w[1][k] / rho, v = f.w[2][k] / rho;
            const double p = gm1 * (f.w[3][k] - 0.5 * (f.w[1][k] * u + f.w[2][k] * v));
            const double un = uw + (u - uw) * fz, vn = vw + (v - vw) * fz;
            if (!keep_total) {
                set_cons(w, k, rho, un, vn, p, gm1);
                continue;
            }
            const double T = p / (rho * gks_solver_gas(s)->R);
            const double T0 = T + 0.5 * (u * u + v * v) / cp;
            const double Tn = T0 - 0.5 * (un * un + vn * vn) / cp;
            const double pn = p * pow(Tn / T, gamma / gm1);
            set_cons(w, k, pn / (gks_solver_gas(s)->R * Tn), un, vn, pn, gm1);
        }
    ibm_fill_ghosts(ibm, s);
}

void ibm_soft_start(Ibm *ibm, GksSolver *s, double length) {
    soft_start(ibm, s, length, false);
}

void ibm_soft_start_isentropic(Ibm *ibm, GksSolver *s, double length) {
    soft_start(ibm, s, length, true);
}

/* -------------------------------------------------------------- update */

/* Marks the buckets a box touches (clamped to the bucket grid). */
static void mark_box(Ibm *ibm, const double b[4]) {
    const IbmBuckets *bk = &ibm->bk;
    int i0 = (int)fmax(-1.0, fmin(1e9, floor((b[0] - bk->x0) * bk->inv_size)));
    int i1 = (int)fmax(-1.0, fmin(1e9, floor((b[1] - bk->x0) * bk->inv_size)));
    int j0 = (int)fmax(-1.0, fmin(1e9, floor((b[2] - bk->y0) * bk->inv_size)));
    int j1 = (int)fmax(-1.0, fmin(1e9, floor((b[3] - bk->y0) * bk->inv_size)));
    i0 = i0 < 0 ? 0 : i0 >= bk->nbx ? bk->nbx - 1 : i0;
    i1 = i1 < 0 ? 0 : i1 >= bk->nbx ? bk->nbx - 1 : i1;
    j0 = j0 < 0 ? 0 : j0 >= bk->nby ? bk->nby - 1 : j0;
    j1 = j1 < 0 ? 0 : j1 >= bk->nby ? bk->nby - 1 : j1;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) ibm->moved_bucket[(int64_t)j * bk->nbx + i] = 1;
}

static int box_touches_moved(const Ibm *ibm, const double *b) {
    const double m[4] = {b[0], b[1], b[2], b[3]};
    const IbmBuckets *bk = &ibm->bk;
    int i0 = (int)fmax(-1.0, fmin(1e9, floor((m[0] - bk->x0) * bk->inv_size)));
    int i1 = (int)fmax(-1.0, fmin(1e9, floor((m[1] - bk->x0) * bk->inv_size)));
    int j0 = (int)fmax(-1.0, fmin(1e9, floor((m[2] - bk->y0) * bk->inv_size)));
    int j1 = (int)fmax(-1.0, fmin(1e9, floor((m[3] - bk->y0) * bk->inv_size)));
    i0 = i0 < 0 ? 0 : i0 >= bk->nbx ? bk->nbx - 1 : i0;
    i1 = i1 < 0 ? 0 : i1 >= bk->nbx ? bk->nbx - 1 : i1;
    j0 = j0 < 0 ? 0 : j0 >= bk->nby ? bk->nby - 1 : j0;
    j1 = j1 < 0 ? 0 : j1 >= bk->nby ? bk->nby - 1 : j1;
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++)
            if (ibm->moved_bucket[(int64_t)j * bk->nbx + i]) return 1;
    return 0;
}

/* Re-tests the inside flag of the interior cells whose centres lie in box b;
 * appends the cells whose flag changed to list_a. */
static int retag_box(Ibm *ibm, const double b[4], int *nchanged) {
    const Grid *g = ibm->grid;
    const int i0 = lower_bound(&g->ax[0], b[0]), i1 = upper_last(&g->ax[0], b[1]);
    const int j0 = lower_bound(&g->ax[1], b[2]), j1 = upper_last(&g->ax[1], b[3]);
    for (int j = j0; j <= j1; j++)
        for (int i = i0; i <= i1; i++) {
            const int64_t k = grid_index(g, i, j);
            ibm->last.retagged++;
            const uint8_t in =
                (uint8_t)ibm_point_inside(ibm, g->ax[0].center[i], g->ax[1].center[j]);
            if (in == ibm->inside[k]) continue;
            ibm->inside[k] = in;
            TRY(reserve_list(&ibm->list_a, &ibm->list_cap_a, *nchanged + 1));
            ibm->list_a[(*nchanged)++] = k;
        }
    return NSPD_OK;
}

/* Global segment number before the update -> after it (same body, same
 * local index). */
static int32_t renumber(const Ibm *ibm, int32_t old) {
    int first = 0;
    for (int b = 0; b < ibm->body_count; b++) {
        if (old < first + ibm->old_count[b]) return ibm->first[b] + (old - first);
        first += ibm->old_count[b];
    }
    return old;
}

static int cmp_i64(const void *a, const void *b) {
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* Several processes: the cells the n fresh stencils read, fetched into
 * the shadow (every rank builds every fresh stencil: they are few), which
 * first makes room for what this process's own (those of its rows and
 * halo) read. */
static int fetch_fresh_nodes(Ibm *ibm, const GksSolver *s, int n, const IbmStencilSet *tmp) {
    const int64_t stride = ibm->grid->stride;
    int lo[2] = {INT_MAX, INT_MAX}, hi[2] = {0, 0};
    for (int q = 0; q < n; q++) {
        if (ibm_share_local(ibm, s, ibm->list_a[q]) < 0) continue; /* another process's */
        for (int m = 0; m < 4; m++) {
            if (tmp->rseg[4 * q + m] != IBM_NODE_FLUID) continue;
            const int64_t k = tmp->node[4 * q + m];
            const int at[2] = {(int)(k % stride), (int)(k / stride)};
            for (int a = 0; a < 2; a++) {
                lo[a] = at[a] < lo[a] ? at[a] : lo[a];
                hi[a] = at[a] + 1 > hi[a] ? at[a] + 1 : hi[a];
            }
        }
    }
    if (lo[0] < hi[0]) TRY(ibm_share_cover(ibm, lo, hi));
    int64_t *cells = NULL;
    TRY(nspd_alloc(&cells, 4 * (size_t)n + 1, sizeof *cells));
    int m = 0;
    for (int q = 0; q < 4 * n; q++)
        if (tmp->rseg[q] == IBM_NODE_FLUID) cells[m++] = tmp->node[q];
    qsort(cells, (size_t)m, sizeof *cells, cmp_i64);
    int u = 0;
    for (int q = 0; q < m; q++)
        if (u == 0 || cells[q] != cells[u - 1]) cells[u++] = cells[q];
    const int status = ibm_share_fetch(ibm, u, cells);
    nspd_free(&cells);
    return status;
}

/* Fills the fresh cells listed in list_a[0..n) (flagged in mark, bit 2);
 * on several processes, those of this process's rows and halo. */
static int fill_fresh(Ibm *ibm, GksSolver *s, int n, IbmStencilSet *tmp) {
    const Grid *g = ibm->grid;
    GksFields f = gks_solver_fields(s);
    const GksParams *gas = gks_solver_gas(s);
    const double gm1 = gas->gamma - 1.0, R = gas->R;
    double *const local[4] = {f.w[0], f.w[1], f.w[2], f.w[3]};
    const IbmFieldView solver_view = ibm_solver_view(s);
    /* first all stencils (they read only non-fresh fluid cells), then all values */
    for (int q = 0; q < n; q++) {
        int i, j;
        cell_ij(g, ibm->list_a[q], &i, &j);
        ibm_build_point(ibm, g->ax[0].center[i], g->ax[1].center[j], 0.0, ibm->mark, tmp, q);
    }
    if (ibm->share) TRY(fetch_fresh_nodes(ibm, s, n, tmp));
    const IbmFieldView view = ibm->share ? ibm_share_shadow(ibm) : solver_view;
    for (int q = 0; q < n; q++) {
        const int64_t cell = ibm->list_a[q], k = ibm_share_local(ibm, s, cell);
        if (k < 0) continue;                               /* another process's */
        if (tmp->rseg[4 * q] == IBM_NODE_UNUSED) continue; /* nothing usable: keep the old value */
        /* the wall that uncovered the cell decides the thermal rows */
        int i, j;
        cell_ij(g, ibm->list_a[q], &i, &j);
        const int b = ibm->seg_body[ibm_nearest(ibm, g->ax[0].center[i], g->ax[1].center[j]).seg];
        const int iso = ibm->thermal[b] == IBM_WALL_ISOTHERMAL;
        const IbmPrim p = ibm_stencil_eval(ibm, tmp, q, &view, gm1, R, iso, ibm->wall_t[b]);
        const double T = iso ? fmax(p.T, 0.25 * ibm->wall_t[b]) : p.T;
        set_cons(local, k, p.p / (R * T), p.u, p.v, p.p, gm1);
    }
    return NSPD_OK;
}

/* The steps of ibm_update, in order. Each is a pass over the work of the
 * previous one; the work lists carry what passes between them:
 *   swept      4 doubles per box swept by moved walls (steps 2-4),
 *   list_a     cells whose inside flag changed (4-5), then the fresh cells (5-8),
 *   list_b     cells within reach of a changed one, queued for a new kind (5-6),
 *   mark       bit 1: queued; bit 2: fresh (cleared at the end of step 8). */

/* 1. Keeps the old walls and loads the new ones. May reallocate the marker
 * and old-wall arrays and the buckets. */
static int load_walls(Ibm *ibm, const IbmPolyline *bodies, int count) {
    if (ibm->nm > ibm->old_cap) {
        TRY(nspd_realloc(&ibm->old_mx, (size_t)ibm->old_cap, (size_t)ibm->nm, sizeof(double)));
        TRY(nspd_realloc(&ibm->old_my, (size_t)ibm->old_cap, (size_t)ibm->nm, sizeof(double)));
        ibm->old_cap = ibm->nm;
    }
    memcpy(ibm->old_mx, ibm->mx, (size_t)ibm->nm * sizeof(double));
    memcpy(ibm->old_my, ibm->my, (size_t)ibm->nm * sizeof(double));
    ibm->old_nm = ibm->nm;
    for (int b = 0; b < count; b++) ibm->old_count[b] = ibm->count[b];
    TRY(set_markers(ibm, bodies, count));
    TRY(ibm_buckets_build(ibm));
    return NSPD_OK;
}

/* The box of the four ends of a segment's old (a-b) and new (c-d) position. */
static void sweep_segment(double q[4], double ax, double ay, double bx, double by, double cx,
                          double cy, double dx, double dy) {
    q[0] = fmin(fmin(ax, bx), fmin(cx, dx));
    q[1] = fmax(fmax(ax, bx), fmax(cx, dx));
    q[2] = fmin(fmin(ay, by), fmin(cy, dy));
    q[3] = fmax(fmax(ay, by), fmax(cy, dy));
}

/* The box of all old and new markers of body b (old ones from old_first). */
static void sweep_body(const Ibm *ibm, int b, int old_first, double q[4]) {
    const int on = ibm->old_count[b], n = ibm->count[b], f = ibm->first[b];
    q[0] = q[2] = (double)INFINITY;
    q[1] = q[3] = -(double)INFINITY;
    for (int k = 0; k < on; k++) {
        q[0] = fmin(q[0], ibm->old_mx[old_first + k]);
        q[1] = fmax(q[1], ibm->old_mx[old_first + k]);
        q[2] = fmin(q[2], ibm->old_my[old_first + k]);
        q[3] = fmax(q[3], ibm->old_my[old_first + k]);
    }
    for (int k = 0; k < n; k++) {
        q[0] = fmin(q[0], ibm->mx[f + k]), q[1] = fmax(q[1], ibm->mx[f + k]);
        q[2] = fmin(q[2], ibm->my[f + k]), q[3] = fmax(q[3], ibm->my[f + k]);
    }
}

/* 2. The swept box of every moved segment, or of the whole body where its
 * marker count changed, into `swept`. May reallocate it. */
static int sweep_boxes(Ibm *ibm, int *nbox) {
    const int64_t max_boxes = ibm->nm + ibm->body_count;
    if (4 * max_boxes > ibm->swept_cap) {
        if (4 * max_boxes > 2000000000)
            return NSPD_FAIL(NSPD_ERR_NOMEM, "immersed boundary: list too long");
        TRY(nspd_realloc(&ibm->swept, (size_t)ibm->swept_cap, (size_t)(4 * max_boxes),
                         sizeof(double)));
        ibm->swept_cap = (int)(4 * max_boxes);
    }
    double *boxes = ibm->swept;
    int nb = 0, old_first = 0;
    for (int b = 0; b < ibm->body_count; b++) {
        const int on = ibm->old_count[b], n = ibm->count[b], f = ibm->first[b];
        if (on != n) {
            sweep_body(ibm, b, old_first, boxes + 4 * nb++);
            old_first += on;
            continue;
        }
        for (int k = 0; k < n; k++) {
            const int k1 = (k + 1) % n;
            const double ax = ibm->old_mx[old_first + k], ay = ibm->old_my[old_first + k];
            const double bx = ibm->old_mx[old_first + k1], by = ibm->old_my[old_first + k1];
            const double cx = ibm->mx[f + k], cy = ibm->my[f + k];
            const double dx = ibm->mx[f + k1], dy = ibm->my[f + k1];
            if (ax == cx && ay == cy && bx == dx && by == dy) continue;
            sweep_segment(boxes + 4 * nb++, ax, ay, bx, by, cx, cy, dx, dy);
        }
        old_first += on;
    }
    *nbox = nb;
    return NSPD_OK;
}

/* 3. The buckets touched by the swept boxes. May reallocate moved_bucket. */
static int mark_moved_buckets(Ibm *ibm, int nbox) {
    const int64_t nb = (int64_t)ibm->bk.nbx * ibm->bk.nby;
    if (nb > ibm->moved_cap) {
        nspd_free(&ibm->moved_bucket);
        TRY(nspd_alloc(&ibm->moved_bucket, (size_t)nb, 1));
        ibm->moved_cap = (int)nb;
    }
    memset(ibm->moved_bucket, 0, (size_t)nb);
    for (int q = 0; q < nbox; q++) mark_box(ibm, ibm->swept + 4 * q);
    return NSPD_OK;
}

/* 4. The inside flags in the swept boxes; the changed cells go to list_a. */
static int retag_swept(Ibm *ibm, int nbox, int *nchanged) {
    *nchanged = 0;
    for (int q = 0; q < nbox; q++) TRY(retag_box(ibm, ibm->swept + 4 * q, nchanged));
    ibm->last.changed = *nchanged;
    return NSPD_OK;
}

/* 5a. Queues in list_b every interior cell within reach of a changed cell,
 * once (mark bit 1). */
static int queue_reach(Ibm *ibm, int nchanged, int64_t *nq) {
    const Grid *g = ibm->grid;
    TRY(reserve_list(&ibm->list_b, &ibm->list_cap_b, (int64_t)nchanged * 13 + 1));
    int64_t *queue = ibm->list_b, n = 0;
    for (int c = 0; c < nchanged; c++) {
        int i, j;
        cell_ij(g, ibm->list_a[c], &i, &j);
        for (int b = -IBM_REACH; b <= IBM_REACH; b++) {
            const int r = IBM_REACH - abs(b);
            for (int a = -r; a <= r; a++) {
                const int q = i + a, p = j + b;
                if (q < 0 || p < 0 || q >= g->nx || p >= g->ny) continue;
                const int64_t k = grid_index(g, q, p);
                if (ibm->mark[k] & 1) continue;
                ibm->mark[k] |= 1;
                queue[n++] = k;
            }
        }
    }
    *nq = n;
    return NSPD_OK;
}

/* 5b. New kinds of the queued cells (written into `s` too, if given); fresh
 * cells (not fluid -> fluid) get mark bit 2 and go to list_a. *nadd counts
 * the new ghosts. */
static void update_kinds(Ibm *ibm, GksSolver *s, int64_t nq, int *nfresh, int *nadd) {
    const Grid *g = ibm->grid;
    IbmUpdateStats *st = &ibm->last;
    *nfresh = *nadd = 0;
    for (int64_t q = 0; q < nq; q++) {
        const int64_t k = ibm->list_b[q];
        int i, j;
        cell_ij(g, k, &i, &j);
        const uint8_t old = ibm->kind[k], now = (uint8_t)compute_kind(ibm, i, j);
        ibm->mark[k] &= (uint8_t)~1u;
        if (old == now) continue;
        ibm->kind[k] = now;
        st->solid_cells += (now == FLOW_CELL_SOLID) - (old == FLOW_CELL_SOLID);
        if (now == FLOW_CELL_GHOST) (*nadd)++;
        if (old != FLOW_CELL_FLUID && now == FLOW_CELL_FLUID) {
            ibm->mark[k] |= 2;
            ibm->list_a[(*nfresh)++] = k; /* nfresh <= nchanged: list_a holds it */
        }
        if (!s) continue;
        /* the solver's cells: ibm_share_local's (-1: another process's) */
        const int64_t local = ibm_share_local(ibm, s, k);
        if (local >= 0) gks_solver_fields(s).kind[local] = now;
    }
    st->fresh = *nfresh;
}

/* Copies ghost f of the old set O into entry e of N, renumbering its
 * segments: a body with another marker count shifts the global segment
 * numbers of the bodies after it (kept stencils only read bodies whose
 * markers did not change). */
static void keep_ghost(const Ibm *ibm, IbmStencilSet *N, int e, const IbmStencilSet *O, int f) {
    ibm_stencils_copy_entry(N, e, O, f);
    N->seg[e] = renumber(ibm, N->seg[e]);
    for (int m = 0; m < 4; m++)
        if (N->rseg[4 * e + m] >= 0) N->rseg[4 * e + m] = renumber(ibm, N->rseg[4 * e + m]);
}

/* 6. The new ghost list, sorted by cell, in the spare set, then swapped in:
 * survivors keep their stencils unless their dependency box touches moved
 * geometry; the others and the new ghosts (among the nq queued cells) are
 * built. May reallocate the spare set. */
static int rebuild_ghost_list(Ibm *ibm, int64_t nq, int nadd) {
    const Grid *g = ibm->grid;
    IbmStencilSet *O = &ibm->ghosts, *N = &ibm->spare;
    int nnew = 0;
    for (int e = 0; e < O->n; e++) nnew += ibm->kind[O->cell[e]] == FLOW_CELL_GHOST;
    TRY(ibm_stencils_reserve(N, nnew + nadd));
    N->n = 0;
    for (int e = 0; e < O->n; e++)
        if (ibm->kind[O->cell[e]] == FLOW_CELL_GHOST) N->cell[N->n++] = O->cell[e];
    for (int64_t q = 0; q < nq; q++) {
        const int64_t k = ibm->list_b[q];
        if (ibm->kind[k] == FLOW_CELL_GHOST && ibm->slot[k] < 0) N->cell[N->n++] = k;
    }
    qsort(N->cell, (size_t)N->n, sizeof(int64_t), cmp_i64);
    int rebuilt = 0, elsewhere = 0;
    for (int e = 0; e < N->n; e++) {
        const int f = ibm->slot[N->cell[e]];
        if (!ibm_share_fills(ibm, N->cell[e])) { /* another process's: never read here */
            N->level[e] = IBM_LEVEL_ELSEWHERE;
            elsewhere++;
        } else if (f >= 0 && !box_touches_moved(ibm, O->dep + 4 * f)) {
            keep_ghost(ibm, N, e, O, f);
        } else {
            N->level[e] = 255; /* to build */
            rebuilt++;
        }
    }
    const int nn = N->n;
#pragma omp parallel for schedule(dynamic, 64) if (rebuilt >= PARALLEL_MIN_ITEMS / 16)
    for (int e = 0; e < nn; e++) {
        if (N->level[e] != 255) continue;
        int i, j;
        cell_ij(g, N->cell[e], &i, &j);
        ibm_build_ghost(ibm, i, j, N, e);
    }
    ibm->last.rebuilt = rebuilt;
    ibm->last.kept = N->n - rebuilt - elsewhere;
    for (int e = 0; e < O->n; e++) ibm->slot[O->cell[e]] = -1;
    for (int e = 0; e < N->n; e++) ibm->slot[N->cell[e]] = e;
    const IbmStencilSet tmp = *O;
    *O = *N;
    *N = tmp;
    return NSPD_OK;
}

/* 8. The fresh cells (list_a[0..nfresh)), from their non-fresh fluid
 * neighbours, if there is a solver; then their mark bit is cleared. The
 * spare set serves as scratch space for their stencils (may reallocate). */
static int fill_fresh_cells(Ibm *ibm, GksSolver *s, int nfresh) {
    if (s && nfresh > 0) {
        TRY(ibm_stencils_reserve(&ibm->spare, nfresh));
        TRY(fill_fresh(ibm, s, nfresh, &ibm->spare));
    }
    for (int q = 0; q < nfresh; q++) ibm->mark[ibm->list_a[q]] &= (uint8_t)~2u;
    return NSPD_OK;
}

int ibm_update(Ibm *ibm, const IbmPolyline *bodies, int count, GksSolver *s) {
    if (count != ibm->body_count)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "immersed boundary: %d bodies given to an update of %d; expected the "
                         "same bodies (build a new one with ibm_create)",
                         count, ibm->body_count);
    TRY(check_bodies(bodies, count));
    if (s) {
        const Grid *sg = gks_solver_whole_grid(s);
        if (sg->nx != ibm->nx || sg->ny != ibm->ny)
            return NSPD_FAIL(NSPD_ERR_INPUT, "immersed boundary: update with another grid");
    }
    const double t0 = nspd_wall_time();
    IbmUpdateStats *st = &ibm->last;
    st->retagged = 0;
    st->changed = st->fresh = st->rebuilt = st->kept = 0;

    int nbox = 0, nchanged = 0, nfresh = 0, nadd = 0;
    int64_t nq = 0;
    TRY(load_walls(ibm, bodies, count));    /* 1 */
    TRY(sweep_boxes(ibm, &nbox));           /* 2 */
    TRY(mark_moved_buckets(ibm, nbox));     /* 3 */
    TRY(retag_swept(ibm, nbox, &nchanged)); /* 4 */
    TRY(queue_reach(ibm, nchanged, &nq));   /* 5 */
    update_kinds(ibm, s, nq, &nfresh, &nadd);
    TRY(rebuild_ghost_list(ibm, nq, nadd));     /* 6 */
    TRY(build_probes(ibm));                     /* 7: every segment moves with a deforming body */
    TRY(fill_fresh_cells(ibm, s, nfresh));      /* 8 */
    if (ibm->share) TRY(ibm_share_replan(ibm)); /* 9: who fills and fetches what */
    count_stats(ibm);
    st->seconds = nspd_wall_time() - t0;
    return NSPD_OK;
}

/* -------------------------------------------------------------- queries */

const uint8_t *ibm_kinds(const Ibm *ibm) {
    return ibm->kind;
}

void ibm_stats(const Ibm *ibm, IbmUpdateStats *out) {
    *out = ibm->last;
}

int ibm_body_count(const Ibm *ibm) {
    return ibm->body_count;
}

int ibm_segment_count(const Ibm *ibm) {
    return ibm->nm;
}

void ibm_body_markers_view(const Ibm *ibm, int b, int *count, const double **x, const double **y) {
    *count = ibm->count[b];
    *x = ibm->mx + ibm->first[b];
    *y = ibm->my + ibm->first[b];
}

int ibm_ghost_count(const Ibm *ibm) {
    return ibm->ghosts.n;
}

void ibm_ghost_info(const Ibm *ibm, int e, IbmGhostInfo *out) {
    const IbmStencilSet *G = &ibm->ghosts;
    memset(out, 0, sizeof *out);
    out->cell = G->cell[e];
    cell_ij(ibm->grid, G->cell[e], &out->i, &out->j);
    out->level = G->level[e];
    out->replaced = G->nrep[e];
    out->body = G->body[e];
    out->segment = G->seg[e];
    const IbmStencilGeo *geo = &G->geo[e];
    out->bi[0] = geo->bix, out->bi[1] = geo->biy;
    out->normal[0] = geo->nx, out->normal[1] = geo->ny;
    out->dist = geo->dist;
    out->point[0] = geo->px, out->point[1] = geo->py;
    out->ratio = G->ratio[e];
    for (int m = 0; m < 4; m++) {
        const int rs = G->rseg[4 * e + m];
        out->node[m] = rs == IBM_NODE_FLUID ? G->node[4 * e + m] : -1;
        out->node_segment[m] = rs >= 0 ? rs : -1;
        out->wd[m] = G->wd[4 * e + m];
        out->wn[m] = G->wn[4 * e + m];
    }
}

int ibm_find_ghost(const Ibm *ibm, int i, int j) {
    if (i < 0 || j < 0 || i >= ibm->nx || j >= ibm->ny) return -1;
    return ibm->slot[grid_index(ibm->grid, i, j)];
}
