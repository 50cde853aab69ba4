/* The volumetric penalty coupling (model.h). */
#include "couple/penalty/model.h"

#include "core/checkpoint.h"
#include "core/comm.h"
#include "core/exact_sum.h"
#include "core/log.h"
#include "core/mem.h"
#include "core/status.h"
#include "couple/coupling.h"
#include "couple/penalty/relax.h"

#include <math.h>
#include <string.h>

const char *const PENALTY_THICKNESS_NAMES[] = {"depth_consistent", "plate_in_unit_depth", NULL};
const char *const PENALTY_ENERGY_NAMES[] = {"total", "momentum_only", NULL};
const char *const PENALTY_STRONG_CONSTRAINT_NAMES[] = {"every_step", "flow_step", NULL};
const char *const PENALTY_INTEGRATION_NAMES[] = {"implicit", "explicit", NULL};

/* Cells around a process's block within which a point's stencil may
 * reach its cells or its halo's (the faces a seal closes): the stencil's
 * one (the cells around the one that holds the point), the halo's two,
 * one to spare. */
enum { PENALTY_REACH = 4 };

typedef struct {
    PenaltyConfig cfg;
    double average_from;
    int64_t n;
    int width;
    double depth;  /* m of the solid per metre of gas depth's share: t or 1 */
    double dt_pen; /* s */
    double h;      /* m */
    /* per point of the whole body */
    double *m, *b, *v[2], *J[2];
    double *work_rate; /* J per metre: minus the impulse's work on the point */
    /* the candidates: the points whose stencils this process forms (within
     * PENALTY_REACH cells of its block; every point on one process), by
     * their order in the whole body: pick[k] its point, and per candidate
     * its position, mass, b, velocity, impulse and work rate */
    int64_t nc, *pick;
    double *x[2]; /* the points' positions at the relaxation */
    double *cm, *cb, *cv[2], *cJ[2], *cwr;
    /* per entry (nc * width) */
    int64_t *cell;
    double *w;
    int32_t *col;
    int64_t *entry; /* by cell: the entry p * width + j */
    int32_t *point; /* by cell: its point */
    double *weight; /* by cell: its weight */
    /* per touched cell (at most n * width) */
    int64_t cells;
    int64_t *cell_id;
    double *mass, *u[2], *dm[2], *de;
    int64_t *first;
    /* the flow's cell -> touched cell, -1 (grown to the largest cell seen) */
    int64_t *local;
    int64_t local_size;
    /* sealed faces (cfg.seal): per point its covering area and that times
     * its velocity; per touched cell the covered area and velocity */
    double *cover, *cover_v[2];
    double *seal_area, *seal_u[2];
    /* Eq. 20 (cfg.strong, cfg.subtract_fluid): per touched cell its lumped
     * volume, covered fraction, gas mass counted (1 - phi) m, the velocity
     * after the projection */
    double *volume, *phi, *mass_counted, *u_new[2];
    PenaltyWork work;
    /* divided between processes (issue 28): the touched cells' and the
     * candidates' owners, what this process forms, and the plan of the
     * cells its near points read from others (their touched numbers here,
     * and the flow's numbers of those asked) */
    NspdComm comm;
    int *cell_rank, *point_rank;
    int64_t *own_cell, *near_point, *own_point, *asked, *asked_id, *told;
    uint8_t *mark;
    int *ask_count, *told_count, *bytes; /* per rank; bytes: 4 per rank */
    int64_t asks, tells;                 /* their sums: the cells asked of others, told */
    double *send, *recv, *shared;        /* send, recv: cells; shared: 8 per point */
    PenaltyDivision div;
    int status;         /* of the division's collective calls within a relaxation */
    bool stencil_fresh; /* before_flow built the stencils at the points' current positions */
    double last_dt;     /* s, of the last relaxation */
    bool said;          /* C_pen logged (at the first step: the run's log is open then) */
    PenaltyStepInfo step;
    double force_x_max;      /* N per metre of depth, on the solid, over the run */
    double impulse_total[2]; /* N s per metre of depth, on the solid, over the run (the
                                paper's integrated penalty force, Fig. 4) */
} PenaltyCoupling;

static void penalty_destroy(void *impl) {
    PenaltyCoupling *p = impl;
    if (!p) return;
    double **arrays[] = {&p->x[0],       &p->x[1],        &p->m,
                         &p->b,          &p->v[0],        &p->v[1],
                         &p->J[0],       &p->J[1],        &p->w,
                         &p->mass,       &p->u[0],        &p->u[1],
                         &p->dm[0],      &p->dm[1],       &p->de,
                         &p->work_rate,  &p->work.sample, &p->work.x,
                         &p->work.r,     &p->work.z,      &p->work.p,
                         &p->work.ap,    &p->work.diag,   &p->cover,
                         &p->cover_v[0], &p->cover_v[1],  &p->seal_area,
                         &p->seal_u[0],  &p->seal_u[1],   &p->cm,
                         &p->cb,         &p->cv[0],       &p->cv[1],
                         &p->cJ[0],      &p->cJ[1],       &p->cwr,
                         &p->volume,     &p->phi,         &p->mass_counted,
                         &p->u_new[0],   &p->u_new[1]};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++) nspd_free(arrays[k]);
    nspd_free(&p->cell);
    nspd_free(&p->col);
    nspd_free(&p->entry);
    nspd_free(&p->point);
    nspd_free(&p->weight);
    nspd_free(&p->cell_id);
    nspd_free(&p->first);
    nspd_free(&p->local);
    nspd_free(&p->cell_rank);
    nspd_free(&p->point_rank);
    nspd_free(&p->own_cell);
    nspd_free(&p->near_point);
    nspd_free(&p->own_point);
    nspd_free(&p->asked);
    nspd_free(&p->asked_id);
    nspd_free(&p->told);
    nspd_free(&p->pick);
    nspd_free(&p->mark);
    nspd_free(&p->ask_count);
    nspd_free(&p->told_count);
    nspd_free(&p->bytes);
    nspd_free(&p->send);
    nspd_free(&p->recv);
    nspd_free(&p->shared);
    nspd_free(&p);
}

static int allocate(PenaltyCoupling *p) {
    const size_t n = (size_t)p->n, e = n * (size_t)p->width;
    double **per_point[] = {&p->x[0],  &p->x[1], &p->m,     &p->b,         &p->v[0],
                            &p->v[1],  &p->J[0], &p->J[1],  &p->work_rate, &p->work.sample,
                            &p->cm,    &p->cb,   &p->cv[0], &p->cv[1],     &p->cJ[0],
                            &p->cJ[1], &p->cwr};
    for (size_t k = 0; k < sizeof per_point / sizeof *per_point; k++)
        TRY(nspd_alloc(per_point[k], n ? n : 1, sizeof(double)));
    double **per_cell[] = {&p->mass,   &p->u[0],   &p->u[1],    &p->dm[0],
                           &p->dm[1],  &p->de,     &p->work.x,  &p->work.r,
                           &p->work.z, &p->work.p, &p->work.ap, &p->work.diag};
    for (size_t k = 0; k < sizeof per_cell / sizeof *per_cell; k++)
        TRY(nspd_alloc(per_cell[k], e ? e : 1, sizeof(double)));
    if (p->cfg.seal) {
        double **seal_point[] = {&p->cover, &p->cover_v[0], &p->cover_v[1]};
        double **seal_cell[] = {&p->seal_area, &p->seal_u[0], &p->seal_u[1]};
        for (size_t k = 0; k < 3; k++) {
            TRY(nspd_alloc(seal_point[k], n ? n : 1, sizeof(double)));
            TRY(nspd_alloc(seal_cell[k], e ? e : 1, sizeof(double)));
        }
    }
    if (p->cfg.strong && p->cfg.subtract_fluid) {
        double **eq20[] = {&p->volume, &p->phi, &p->mass_counted, &p->u_new[0], &p->u_new[1]};
        for (size_t k = 0; k < sizeof eq20 / sizeof *eq20; k++)
            TRY(nspd_alloc(eq20[k], e ? e : 1, sizeof(double)));
    }
    TRY(nspd_alloc(&p->w, e ? e : 1, sizeof(double)));
    TRY(nspd_alloc(&p->cell, e ? e : 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->col, e ? e : 1, sizeof(int32_t)));
    TRY(nspd_alloc(&p->entry, e ? e : 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->point, e ? e : 1, sizeof(int32_t)));
    TRY(nspd_alloc(&p->weight, e ? e : 1, sizeof(double)));
    TRY(nspd_alloc(&p->cell_id, e ? e : 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->first, e + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->pick, n + 1, sizeof(int64_t)));
    if (!comm_distributed(&p->comm)) return NSPD_OK;
    const size_t ranks = (size_t)p->comm.size;
    TRY(nspd_alloc(&p->cell_rank, e + 1, sizeof(int)));
    TRY(nspd_alloc(&p->point_rank, n + 1, sizeof(int)));
    TRY(nspd_alloc(&p->own_cell, e + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->asked, e + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->asked_id, e + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->near_point, n + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->own_point, n + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&p->mark, (n > e ? n : e) + 1, 1));
    TRY(nspd_alloc(&p->ask_count, ranks, sizeof(int)));
    TRY(nspd_alloc(&p->told_count, ranks, sizeof(int)));
    TRY(nspd_alloc(&p->bytes, 4 * ranks, sizeof(int)));
    TRY(nspd_alloc(&p->recv, e + 1, sizeof(double)));
    return nspd_alloc(&p->shared, 8 * n + 1, sizeof(double));
}

static int penalty_create(void **impl, CouplingConfig *cfg, Solid *solid, Flow *flow) {
    if (!solid)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the penalty coupling needs a solid; expected a "
                                         "'solid' section");
    if (!flow_has_transfer(flow))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the penalty coupling needs a flow with transfer weights; the '%s' "
                         "flow solver has none",
                         flow_name(flow));
    const PenaltyConfig *pc = cfg->model;
    if (pc->seal && !flow_can_seal(flow))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the penalty coupling's 'seal' needs a flow that can seal faces; the "
                         "'%s' flow solver cannot (expected seal: false or flow.method: gks)",
                         flow_name(flow));
    const PdPoints *pts = solid_points(solid);
    if (pts->dim != 2)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the penalty coupling needs a 2D solid, not %dD",
                         pts->dim);
    if (pc->strong && pc->strong_constraint == PENALTY_STRONG_EVERY_STEP &&
        !solid_can_be_constrained(solid))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the strong coupling at every step needs a solid whose velocities can "
                         "be prescribed; the '%s' solid's cannot (expected strong_constraint: "
                         "flow_step)",
                         solid_name(solid));
    PenaltyCoupling *p;
    TRY(nspd_alloc(&p, 1, sizeof *p));
    p->cfg = *(const PenaltyConfig *)cfg->model;
    nspd_free(&cfg->model); /* taken */
    p->average_from = cfg->average_from;
    p->comm = cfg->comm ? *cfg->comm : comm_self();
    p->n = pts->n;
    p->width = flow_transfer_width(p->cfg.transfer);
    p->depth = p->cfg.thickness == PENALTY_PLATE_IN_UNIT_DEPTH ? 1.0 : pts->thickness;
    p->h = p->cfg.h > 0 ? p->cfg.h : pts->spacing;
    p->dt_pen = p->cfg.dt > 0 ? p->cfg.dt : solid_stable_dt(solid);
    int status = allocate(p);
    if (status != NSPD_OK) {
        penalty_destroy(p);
        return status;
    }
    /* every point in the gas: a point off the grid would feel nothing */
    for (int64_t i = 0; i < p->n; i++) {
        p->x[0][i] = pts->x[0][i] + pts->u[0][i];
        p->x[1][i] = pts->x[1][i] + pts->u[1][i];
    }
    flow_transfer(flow, p->cfg.transfer, p->n, p->x[0], p->x[1], p->cell, p->w);
    for (int64_t i = 0; i < p->n; i++)
        if (p->cell[i * p->width] < 0) {
            status = NSPD_FAIL(NSPD_ERR_INPUT,
                               "the penalty coupling: solid point %lld at (%g, %g) m is outside "
                               "the flow's grid; expected the whole solid inside it",
                               (long long)i, p->x[0][i], p->x[1][i]);
            penalty_destroy(p);
            return status;
        }
    *impl = p;
    return NSPD_OK;
}

/* The touched cells of the entries in p->cell (candidate order, the whole
 * body's), their local numbers in p->col and the cell -> entries index (a
 * counting sort: each cell's entries in point order). */
static int index_cells(PenaltyCoupling *p) {
    const int64_t entries = p->nc * p->width;
    int64_t top = -1;
    for (int64_t e = 0; e < entries; e++)
        if (p->cell[e] > top) top = p->cell[e];
    if (top >= p->local_size) {
        const int64_t size = top + 1;
        TRY(nspd_realloc(&p->local, (size_t)p->local_size, (size_t)size, sizeof(int64_t)));
        for (int64_t c = p->local_size; c < size; c++) p->local[c] = -1;
        p->local_size = size;
    }
    p->cells = 0;
    for (int64_t e = 0; e < entries; e++) {
        const int64_t c = p->cell[e];
        if (c < 0) {
            p->col[e] = -1;
            continue;
        }
        if (p->local[c] < 0) {
            p->local[c] = p->cells;
            p->cell_id[p->cells++] = c;
        }
        p->col[e] = (int32_t)p->local[c];
    }
    for (int64_t k = 0; k < p->cells; k++) p->local[p->cell_id[k]] = -1;
    memset(p->first, 0, ((size_t)p->cells + 1) * sizeof(int64_t));
    for (int64_t e = 0; e < entries; e++)
        if (p->col[e] >= 0) p->first[p->col[e] + 1]++;
    for (int64_t k = 0; k < p->cells; k++) p->first[k + 1] += p->first[k];
    for (int64_t e = 0; e < entries; e++)
        if (p->col[e] >= 0) p->entry[p->first[p->col[e]]++] = e;
    for (int64_t k = p->cells; k > 0; k--) p->first[k] = p->first[k - 1];
    p->first[0] = 0;
    for (int64_t k = 0; k < p->first[p->cells]; k++) {
        p->point[k] = (int32_t)(p->entry[k] / p->width);
        p->weight[k] = p->w[p->entry[k]];
    }
    return NSPD_OK;
}

/* The candidates (the points whose stencils can reach this process's
 * cells, or those of its halo, which a seal reads: within PENALTY_REACH
 * cells of its block; every point on one process), at their current
 * positions, their transfer weights and the weights' index. */
static int stencil(PenaltyCoupling *p, const Flow *flow, const PdPoints *pts) {
    int64_t nc = 0;
    for (int64_t i = 0; i < p->n; i++) {
        const double x = pts->x[0][i] + pts->u[0][i], y = pts->x[1][i] + pts->u[1][i];
        if (!flow_point_near(flow, x, y, PENALTY_REACH)) continue;
        p->pick[nc] = i;
        p->x[0][nc] = x, p->x[1][nc] = y;
        nc++;
    }
    p->nc = nc;
    flow_transfer(flow, p->cfg.transfer, nc, p->x[0], p->x[1], p->cell, p->w);
    return index_cells(p);
}

/* sum over cell c's entries of w * f[point]: what the points give the
 * cell through the weights (a gather, the same bits on any thread count). */
static double gather(const PenaltyCoupling *p, int64_t c, const double *f) {
    double sum = 0.0;
    for (int64_t k = p->first[c]; k < p->first[c + 1]; k++) sum += p->weight[k] * f[p->point[k]];
    return sum;
}

/* ------------------------------------------- divided between processes */

/* The entry of point i whose weight is the largest (the first of equals):
 * for all three transfers the cell that holds the point (the nearest
 * centre); -1 for a point with no gas around it. */
static int32_t home_col(const PenaltyCoupling *p, int64_t i) {
    int32_t best = -1;
    double most = -1.0;
    for (int j = 0; j < p->width; j++) {
        const int64_t e = i * p->width + j;
        if (p->col[e] >= 0 && p->w[e] > most) best = p->col[e], most = p->w[e];
    }
    return best;
}

/* x at the cells this process's near points read and other processes
 * hold, from them (PenaltyDivision.exchange; one all-to-all with the
 * partners). */
static void halo_exchange(void *ctx, double *x) {
    PenaltyCoupling *p = ctx;
    const int ranks = p->comm.size;
    const int *send_bytes = p->bytes, *send_at = p->bytes + ranks;
    const int *recv_bytes = p->bytes + 2 * ranks, *recv_at = p->bytes + 3 * ranks;
    for (int64_t k = 0; k < p->tells; k++) p->send[k] = x[p->told[k]];
    const int status =
        comm_alltoallv_bytes(&p->comm, p->send, send_bytes, send_at, p->recv, recv_bytes, recv_at);
    if (p->status == NSPD_OK) p->status = status;
    for (int64_t k = 0; k < p->asks; k++) x[p->asked[k]] = p->recv[k];
}

static void sums_reduce(void *ctx, ExactSum *s, int count) {
    PenaltyCoupling *p = ctx;
    const int status = exact_sum_reduce(&p->comm, s, count);
    if (p->status == NSPD_OK) p->status = status;
}

/* Who forms what: each touched cell's row by the process that holds the
 * cell, each point's impulse by the process that holds the cell of its
 * largest weight (the one around it); the near points (the candidates that
 * touch this process's cells) are sampled here too, so the cells they read
 * that others hold are asked of those, by the flow's numbers (collective). */
static int divide(PenaltyCoupling *p, const Flow *flow) {
    const int me = p->comm.rank, ranks = p->comm.size;
    const int64_t nc = p->nc;
    int64_t own = 0, owned = 0, near = 0;
    for (int64_t c = 0; c < p->cells; c++) {
        p->cell_rank[c] = flow_cell_owner(flow, p->cell_id[c]);
        if (p->cell_rank[c] == me) p->own_cell[own++] = c;
    }
    for (int64_t k = 0; k < nc; k++) {
        const int32_t home = home_col(p, k);
        p->point_rank[k] = home >= 0 ? p->cell_rank[home] : -1; /* no gas: nobody's */
        if (p->point_rank[k] == me) p->own_point[owned++] = k;
    }
    for (int64_t k = 0; k < nc; k++) p->mark[k] = 0;
    for (int64_t q = 0; q < own; q++)
        for (int64_t k = p->first[p->own_cell[q]]; k < p->first[p->own_cell[q] + 1]; k++)
            p->mark[p->point[k]] = 1;
    for (int64_t k = 0; k < nc; k++)
        if (p->mark[k]) p->near_point[near++] = k;
    /* the cells they read that others hold: asked of their owners, grouped
     * by owner, each group in touched order */
    for (int64_t c = 0; c < p->cells; c++) p->mark[c] = 0;
    for (int64_t q = 0; q < near; q++)
        for (int j = 0; j < p->width; j++) {
            const int32_t c = p->col[p->near_point[q] * p->width + j];
            if (c >= 0 && p->cell_rank[c] != me) p->mark[c] = 1;
        }
    int *at = p->bytes; /* scratch until the byte counts below */
    for (int r = 0; r < ranks; r++) p->ask_count[r] = 0;
    for (int64_t c = 0; c < p->cells; c++)
        if (p->mark[c]) p->ask_count[p->cell_rank[c]]++;
    for (int r = 0, sum = 0; r < ranks; r++) at[r] = sum, sum += p->ask_count[r];
    for (int64_t c = 0; c < p->cells; c++)
        if (p->mark[c]) p->asked[at[p->cell_rank[c]]++] = c;
    int64_t asks = 0, tells = 0;
    for (int r = 0; r < ranks; r++) asks += p->ask_count[r];
    for (int64_t k = 0; k < asks; k++) p->asked_id[k] = p->cell_id[p->asked[k]];
    nspd_free(&p->told);
    TRY(comm_ask(&p->comm, p->asked_id, p->ask_count, &p->told, p->told_count));
    for (int r = 0; r < ranks; r++) tells += p->told_count[r];
    /* what others ask, by this process's touched numbers: a cell they read
     * is one of its own, so one of its candidates touches it */
    for (int64_t c = 0; c < p->cells; c++) p->local[p->cell_id[c]] = c;
    int64_t missing = 0;
    for (int64_t k = 0; k < tells; k++) {
        const int64_t id = p->told[k];
        p->told[k] = id >= 0 && id < p->local_size ? p->local[id] : -1;
        missing += p->told[k] < 0;
    }
    for (int64_t c = 0; c < p->cells; c++) p->local[p->cell_id[c]] = -1;
    if (missing > 0)
        return NSPD_FAIL(NSPD_ERR_INTERNAL,
                         "the penalty coupling: %lld cells asked of rank %d are not among its "
                         "touched cells",
                         (long long)missing, me);
    int *send_bytes = p->bytes, *send_at = p->bytes + ranks;
    int *recv_bytes = p->bytes + 2 * ranks, *recv_at = p->bytes + 3 * ranks;
    tells = asks = 0;
    for (int r = 0; r < ranks; r++) {
        send_bytes[r] = p->told_count[r] * (int)sizeof(double);
        send_at[r] = (int)(tells * (int64_t)sizeof(double));
        recv_bytes[r] = p->ask_count[r] * (int)sizeof(double);
        recv_at[r] = (int)(asks * (int64_t)sizeof(double));
        tells += p->told_count[r], asks += p->ask_count[r];
    }
    p->asks = asks, p->tells = tells;
    nspd_free(&p->send);
    TRY(nspd_alloc(&p->send, (size_t)tells + 1, sizeof(double)));
    p->div = (PenaltyDivision){.own_cells = own,
                               .own_cell = p->own_cell,
                               .near_points = near,
                               .near_point = p->near_point,
                               .own_points = owned,
                               .own_point = p->own_point,
                               .exchange = halo_exchange,
                               .reduce = sums_reduce,
                               .ctx = p};
    p->status = NSPD_OK;
    return NSPD_OK;
}

/* Every point's impulse and b on every process, from the process that
 * formed them (the solid's whole view takes them all; a point nobody owns
 * has no gas around it: b = 0, no impulse); the points with gas counted.
 * On one process the candidates are the points. */
static int share_impulses(PenaltyCoupling *p, int64_t *with_gas) {
    if (!comm_distributed(&p->comm)) {
        *with_gas = 0;
        for (int64_t i = 0; i < p->n; i++) {
            p->J[0][i] = p->cJ[0][i], p->J[1][i] = p->cJ[1][i], p->b[i] = p->cb[i];
            *with_gas += p->cell[i * p->width] >= 0;
        }
        return NSPD_OK;
    }
    double *mine = p->shared, *all = p->shared + 4 * p->n;
    const int64_t owned = p->div.own_points;
    for (int64_t q = 0; q < owned; q++) {
        const int64_t k = p->own_point[q];
        mine[4 * q] = (double)p->pick[k]; /* exact: below 2^53 */
        mine[4 * q + 1] = p->cJ[0][k];
        mine[4 * q + 2] = p->cJ[1][k];
        mine[4 * q + 3] = p->cb[k];
    }
    *with_gas = comm_sum_i64(&p->comm, owned);
    if (*with_gas > p->n)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "the penalty coupling: a point owned twice");
    TRY(comm_allgatherv(&p->comm, mine, (int)(4 * owned), all));
    for (int64_t i = 0; i < p->n; i++) p->J[0][i] = p->J[1][i] = p->b[i] = 0.0;
    for (int64_t q = 0; q < *with_gas; q++) {
        const int64_t i = (int64_t)all[4 * q];
        p->J[0][i] = all[4 * q + 1], p->J[1][i] = all[4 * q + 2], p->b[i] = all[4 * q + 3];
    }
    return NSPD_OK;
}

/* Before the flow's step, with `seal`: the area the intact solid covers
 * in each cell around it (a point's in-plane area times 1 - d through its
 * weights) and the solid's area-weighted velocity there, handed to the
 * flow, which seals the faces between the cells covered beyond
 * seal_fraction. From the solid's state alone, so a resumed run seals the
 * same faces. */
static int penalty_before_flow(void *impl, Solid *solid, Flow *flow) {
    PenaltyCoupling *p = impl;
    if (!p->cfg.seal) return NSPD_OK;
    TRY(solid_sync(solid)); /* a divided solid: the whole body's view */
    const PdPoints *pts = solid_points(solid);
    const double *damage = solid_damage(solid);
    TRY(stencil(p, flow, pts));
    p->stencil_fresh = true; /* the flow's step does not move the solid */
    for (int64_t k = 0; k < p->nc; k++) {
        const int64_t i = p->pick[k];
        const double a = pts->volume[i] / pts->thickness * (1.0 - damage[i]);
        p->cover[k] = a;
        p->cover_v[0][k] = a * pts->v[0][i];
        p->cover_v[1][k] = a * pts->v[1][i];
    }
    /* every cell of this process's block and halo has all its points among
     * the candidates; the flow seals only those */
    for (int64_t c = 0; c < p->cells; c++) {
        const double a = gather(p, c, p->cover);
        p->seal_area[c] = a;
        p->seal_u[0][c] = a > 0.0 ? gather(p, c, p->cover_v[0]) / a : 0.0;
        p->seal_u[1][c] = a > 0.0 ? gather(p, c, p->cover_v[1]) / a : 0.0;
    }
    return flow_seal(flow, p->cells, p->cell_id, p->seal_area, p->seal_u[0], p->seal_u[1],
                     p->cfg.seal_fraction);
}

/* C_pen at point i, kg/(m^3 s) (Eqs. 22-23: beta E dt / h^2, times 1 - d
 * where the penalty weakens with damage). */
static double penalty_at(const PenaltyCoupling *p, const Solid *solid, const double *damage,
                         int64_t i) {
    const double scale = p->cfg.beta * p->dt_pen / (p->h * p->h);
    return scale * solid_modulus(solid, i) * (damage ? 1.0 - damage[i] : 1.0);
}

/* Eq. 20's lumped reading: per touched cell c the fraction phi_c =
 * sum_P W_Pc A_P / V_c (capped at 1) of its lumped volume that the
 * coupled points cover (A_P a point's volume per metre of the gas's depth,
 * as its mass: its in-plane area when the solid is as deep as the gas,
 * that times t / 1 m for a plate in unit depth; a decoupled point,
 * b = 0, covers nothing: the gas is back where the solid has failed), and
 * the gas mass the momentum rows count, (1 - phi_c) m_c. The candidates'
 * work-rate array is the areas' scratch (written again after the solve). */
static int covered_fractions(PenaltyCoupling *p, const Flow *flow, const PdPoints *pts) {
    for (int64_t k = 0; k < p->nc; k++) {
        const int64_t i = p->pick[k];
        p->cwr[k] = p->cb[k] > 0.0 ? pts->volume[i] / p->depth : 0.0;
    }
    flow_lumped_volume(flow, p->cells, p->cell_id, p->volume);
    const bool divided = comm_distributed(&p->comm);
    const int64_t own = divided ? p->div.own_cells : p->cells;
    double most = 0.0;
    for (int64_t q = 0; q < own; q++) {
        const int64_t c = divided ? p->own_cell[q] : q;
        const double phi = fmin(1.0, gather(p, c, p->cwr) / p->volume[c]);
        p->phi[c] = phi;
        p->mass_counted[c] = (1.0 - phi) * p->mass[c];
        if (phi > most) most = phi;
    }
    p->step.covered_max = comm_max(&p->comm, most);
    return NSPD_OK;
}

/* The relaxation after the flow's step and before the solid's: the points'
 * velocities and the cells' momentum change by the impulses at once (a
 * split step: relaxation, then the solid's own dynamics from the relaxed
 * velocities; a force held over the solid's sub-steps instead lags them and
 * pumps its fastest modes), and the gas's total energy gets minus the
 * impulses' work on the points, J . (v + v') / 2, exactly what the solid's
 * kinetic energy gains. */
static int penalty_after_flow(void *impl, Solid *solid, Flow *flow, double dt) {
    PenaltyCoupling *p = impl;
    TRY(solid_sync(solid)); /* a divided solid: the whole body's view */
    PdPoints *pts = solid_points(solid);
    if (!p->said && pts->n > 0) {
        p->said = true;
        const double E = solid_modulus(solid, 0);
        nspd_log(LOG_INFO,
                 "penalty coupling: C_pen = beta E dt/h^2 = %g x %g Pa x %g s / (%g m)^2 = %g "
                 "kg/(m^3 s)%s%s%s%s, %s weights, %s",
                 p->cfg.beta, E, p->dt_pen, p->h, p->cfg.beta * E * p->dt_pen / (p->h * p->h),
                 p->cfg.strong ? " (strong: the limit beta -> infinity, " : "",
                 !p->cfg.strong                                          ? ""
                 : p->cfg.strong_constraint == PENALTY_STRONG_EVERY_STEP ? "at every step"
                                                                         : "once per flow step",
                 !p->cfg.strong          ? ""
                 : p->cfg.subtract_fluid ? ", Eq. 20's fluid over the solid subtracted)"
                                         : ")",
                 !p->cfg.strong && p->cfg.integration == PENALTY_EXPLICIT ? ", explicit" : "",
                 FLOW_TRANSFER_NAMES[p->cfg.transfer], PENALTY_THICKNESS_NAMES[p->cfg.thickness]);
    }
    const int64_t n = p->n;
    for (int64_t i = 0; i < n; i++) {
        p->v[0][i] = pts->v[0][i];
        p->v[1][i] = pts->v[1][i];
    }
    if (!p->stencil_fresh) TRY(stencil(p, flow, pts));
    p->stencil_fresh = false;
    const bool divided = comm_distributed(&p->comm);
    if (divided) TRY(divide(p, flow));
    /* the cells this process holds (the others' are NaN, never read here) */
    flow_lumped(flow, p->cells, p->cell_id, p->mass, p->dm[0], p->dm[1]);
    for (int64_t c = 0; c < p->cells; c++) {
        p->u[0][c] = p->dm[0][c] / p->mass[c];
        p->u[1][c] = p->dm[1][c] / p->mass[c];
    }
    const double *damage = p->cfg.damaged ? solid_damage(solid) : NULL;
    p->step.c_pen_max = 0.0;
    for (int64_t i = 0; i < n; i++) {
        const double V = pts->volume[i] / p->depth; /* m^2: per metre of gas depth */
        p->m[i] = solid_density(solid, i) * V;
        const double C = penalty_at(p, solid, damage, i);
        if (C > p->step.c_pen_max) p->step.c_pen_max = C;
    }
    for (int64_t k = 0; k < p->nc; k++) {
        const int64_t i = p->pick[k];
        const double a = dt * penalty_at(p, solid, damage, i) * (pts->volume[i] / p->depth);
        p->cm[k] = p->m[i];
        p->cv[0][k] = p->v[0][i], p->cv[1][k] = p->v[1][i];
        if (p->cell[k * p->width] < 0)
            p->cb[k] = 0.0; /* no gas around it */
        else if (p->cfg.strong)
            p->cb[k] = damage && damage[i] >= 1.0 ? 0.0 : p->m[i];
        else if (p->cfg.integration == PENALTY_EXPLICIT)
            p->cb[k] = a;
        else
            p->cb[k] = a > 0.0 ? a * p->m[i] / (p->m[i] + a) : 0.0;
    }
    const bool eq20 = p->cfg.strong && p->cfg.subtract_fluid;
    if (eq20) TRY(covered_fractions(p, flow, pts));
    const PenaltySystem sys = {.points = p->nc,
                               .width = p->width,
                               .col = p->col,
                               .w = p->w,
                               .m = p->cm,
                               .b = p->cb,
                               .v = {p->cv[0], p->cv[1]},
                               .cells = p->cells,
                               .mass = eq20 ? p->mass_counted : p->mass,
                               .u = {p->u[0], p->u[1]},
                               .u_out = {eq20 ? p->u_new[0] : NULL, eq20 ? p->u_new[1] : NULL},
                               .first = p->first,
                               .point = p->point,
                               .weight = p->weight,
                               .div = divided ? &p->div : NULL};
    PenaltyStats stats;
    if (p->cfg.integration == PENALTY_EXPLICIT && !p->cfg.strong)
        penalty_explicit(&sys, &p->work, p->cJ, &stats);
    else
        penalty_relax(&sys, &p->work, p->cJ, &stats);
    TRY(p->status);
    int64_t with_gas;
    TRY(share_impulses(p, &with_gas));
    p->step.outside = n - with_gas;
    p->step.iterations = stats.iterations;
    p->step.slip_max = comm_max(&p->comm, stats.slip_max);
    /* the solid: v' = v + J/m; the work of the impulse on each point */
    for (int d = 0; d < 2; d++) {
        ExactSum sum; /* exact, as the gas's side below */
        exact_sum_clear(&sum);
        for (int64_t i = 0; i < n; i++) {
            if (p->b[i] == 0.0) continue;
            pts->v[d][i] = p->v[d][i] + p->J[d][i] / p->m[i];
            exact_sum_add(&sum, p->J[d][i]);
        }
        p->step.impulse[d] = exact_sum_value(&sum);
    }
    solid_velocities_changed(solid); /* a divided solid's parts take them */
    for (int64_t i = 0; i < n; i++)
        p->work_rate[i] = -(p->J[0][i] * 0.5 * (p->v[0][i] + pts->v[0][i]) +
                            p->J[1][i] * 0.5 * (p->v[1][i] + pts->v[1][i]));
    for (int64_t k = 0; k < p->nc; k++) { /* the candidates', for the gathers below */
        const int64_t i = p->pick[k];
        p->cJ[0][k] = p->J[0][i], p->cJ[1][k] = p->J[1][i], p->cwr[k] = p->work_rate[i];
    }
    /* the gas: minus each impulse (and its work) through the weights, at
     * the cells this process holds; the totals exact, so the same on any
     * number of processes */
    const int64_t own = divided ? p->div.own_cells : p->cells;
    const bool energy = p->cfg.energy == PENALTY_ENERGY_TOTAL;
    ExactSum sums[3];
    for (int k = 0; k < 3; k++) exact_sum_clear(&sums[k]);
    for (int64_t q = 0; q < own; q++) {
        const int64_t c = divided ? p->own_cell[q] : q;
        /* Eq. 20: the whole cell moves at the projected velocity, the
         * covered part's gas (not in the rows) with it, its kinetic
         * energy's change added so its temperature stays */
        double covered_ke = 0.0;
        for (int d = 0; d < 2; d++) {
            if (eq20) {
                const double du = p->u_new[d][c] - p->u[d][c];
                p->dm[d][c] = p->mass[c] * du;
                covered_ke += 0.5 * p->phi[c] * p->mass[c] * du * (p->u_new[d][c] + p->u[d][c]);
            } else {
                p->dm[d][c] = -gather(p, c, p->cJ[d]);
            }
            exact_sum_add(&sums[d], p->dm[d][c]);
        }
        if (energy) {
            p->de[c] = gather(p, c, p->cwr) + covered_ke;
            exact_sum_add(&sums[2], p->de[c]);
        }
    }
    TRY(exact_sum_reduce(&p->comm, sums, 3));
    p->step.gas[0] = exact_sum_value(&sums[0]);
    p->step.gas[1] = exact_sum_value(&sums[1]);
    if (energy) p->step.energy_to_gas += exact_sum_value(&sums[2]);
    /* the flow adds only what this process holds */
    flow_add_lumped(flow, p->cells, p->cell_id, p->dm[0], p->dm[1], energy ? p->de : NULL);
    p->last_dt = dt;
    for (int d = 0; d < 2; d++) p->impulse_total[d] += p->step.impulse[d];
    const double fx = p->step.impulse[0] / dt;
    if (fabs(fx) > fabs(p->force_x_max)) p->force_x_max = fx;
    return NSPD_OK;
}

static bool penalty_constrains_solid(const void *impl) {
    const PenaltyCoupling *p = impl;
    return p->cfg.strong && p->cfg.strong_constraint == PENALTY_STRONG_EVERY_STEP;
}

static void penalty_loads(const void *impl, CouplingLoads *out) {
    const PenaltyCoupling *p = impl;
    const double dt = p->last_dt > 0 ? p->last_dt : 1.0;
    out->force_on_solid[0] = p->step.impulse[0] / dt;
    out->force_on_solid[1] = p->step.impulse[1] / dt;
}

/* The solid's centre-of-mass displacement along x, m. */
static double com_dx(const Solid *solid) {
    const PdPoints *pts = solid_points_const(solid);
    double mu = 0.0, mass = 0.0;
    for (int64_t i = 0; i < pts->n; i++) {
        const double m = solid_density(solid, i) * pts->volume[i];
        mu += m * pts->u[0][i];
        mass += m;
    }
    return mass > 0 ? mu / mass : 0.0;
}

static int penalty_history(void *impl, Solid *solid, Flow *flow, double time, Report *row) {
    (void)flow;
    (void)time;
    PenaltyCoupling *p = impl;
    CouplingLoads l;
    penalty_loads(p, &l);
    report_real(row, "penalty_force_x_N_per_m", l.force_on_solid[0]);
    report_real(row, "penalty_force_y_N_per_m", l.force_on_solid[1]);
    report_real(row, "penalty_impulse_x_N_s_per_m", p->impulse_total[0]);
    report_real(row, "penalty_impulse_y_N_s_per_m", p->impulse_total[1]);
    report_real(row, "slip_max_m_s", p->step.slip_max);
    report_int(row, "penalty_iterations", p->step.iterations);
    report_real(row, "penalty_energy_to_gas_J_per_m", p->step.energy_to_gas);
    report_int(row, "substeps", solid_last_substeps(solid));
    report_real(row, "com_dx_m", com_dx(solid));
    if (p->cfg.strong && p->cfg.subtract_fluid)
        report_real(row, "covered_max", p->step.covered_max);
    return NSPD_OK;
}

static int penalty_summary(void *impl, Solid *solid, Flow *flow, Report *out) {
    (void)flow;
    PenaltyCoupling *p = impl;
    report_real(out, "penalty_force_x_max_n", p->force_x_max);
    report_real(out, "penalty_impulse_x_N_s_per_m", p->impulse_total[0]);
    report_real(out, "penalty_impulse_y_N_s_per_m", p->impulse_total[1]);
    report_real(out, "com_dx_m", com_dx(solid));
    report_real(out, "c_pen_kg_m3_s", p->step.c_pen_max);
    report_real(out, "penalty_energy_to_gas_J_per_m", p->step.energy_to_gas);
    return NSPD_OK;
}

/* The coupling carries no state from step to step but its diagnostics:
 * the last step's (history) and the run's (summary). */
static int penalty_checkpoint(void *impl, Checkpoint *ck) {
    PenaltyCoupling *p = impl;
    TRY(checkpoint_io(ck, "penalty.step", &p->step, sizeof p->step));
    TRY(checkpoint_io_double(ck, "penalty.last_dt", &p->last_dt));
    TRY(checkpoint_io(ck, "penalty.impulse_total", p->impulse_total, sizeof p->impulse_total));
    return checkpoint_io_double(ck, "penalty.force_x_max", &p->force_x_max);
}

/* Beyond the solid and the flow: the map from the flow's cells to the
 * touched ones (8 bytes per stored cell); the per-point arrays (about 60
 * doubles a point with quadratic weights) are within the solid's own
 * estimate's margin. */
static CouplingEstimate penalty_estimate(const CouplingConfig *cfg, const FlowEstimate *flow) {
    (void)cfg;
    return (CouplingEstimate){.bytes = 8.0 * flow->stored_cells};
}

static void penalty_config_free(void *model) {
    (void)model; /* no owned parts */
}

const CouplingOps PENALTY_COUPLING_OPS = {
    .name = "penalty",
    /* the flow's ops gather and scatter the cells (flow/gks/model.c);
     * the relaxation runs alike on every rank over the whole body's view
     * of the solid, which a solid that divides keeps in parts (synced
     * before, its velocities handed back after) */
    .distributed = true,
    .divided_solid = true,
    .config_free = penalty_config_free,
    .estimate = penalty_estimate,
    .create = penalty_create,
    .destroy = penalty_destroy,
    .before_flow = penalty_before_flow,
    .after_flow = penalty_after_flow,
    .solid_dt_limit = NULL,
    .constrains_solid = penalty_constrains_solid,
    .loads = penalty_loads,
    .history = penalty_history,
    .summary = penalty_summary,
    .fields = NULL,
    .checkpoint = penalty_checkpoint,
};

const PenaltyStepInfo *penalty_coupling_step(Coupling *c) {
    const PenaltyCoupling *p = coupling_impl(c, COUPLING_PENALTY);
    return p ? &p->step : NULL;
}
