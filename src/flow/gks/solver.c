/* The flow operator: configuration defaults, create/destroy and accessors.
 * The struct and its invariants are in solver_internal.h; the initial
 * condition in initial.c, the step in step.c, diagnostics in
 * diagnostics.c, the benchmark in bench.c. */
#include "flow/gks/solver.h"

#include "core/blocks.h"
#include "core/mem.h"
#include "core/status.h"
#include "flow/gks/solver_internal.h"
#include "flow/gks/flux.h"

#include <omp.h>
#include <string.h>

const char *const FLOW_LIMITER_NAMES[LIMITER_COUNT + 1] = {"van_leer", "van_albada", "none",
                                                           "first_order", NULL};

void gks_config_default(GksConfig *c) {
    memset(c, 0, sizeof *c);
    c->gamma = 1.4;
    c->gas_constant = 287.0;
    c->viscosity = VISCOSITY_NONE;
    c->T_ref = 273.15;
    c->prandtl = 0.72;
    c->limiter = LIMITER_VAN_LEER;
    c->cfl = 0.5;
    c->tau_jump_c = 1.0;
    c->tau_eps = 0.0;
    for (int f = 0; f < 4; f++) {
        c->bc[f].count = 1;
        c->bc[f].seg[0].kind = BC_EXTRAPOLATION;
    }
    c->initial = (FlowPrim){1.0, 0.0, 0.0, 1.0};
    c->init_quadrature = 1;
}

void gks_config_uniform_grid(GksConfig *c, double x0, double x1, int nx, double y0, double y1,
                             int ny) {
    c->x0 = x0;
    c->y0 = y0;
    c->segment_count[0] = c->segment_count[1] = 1;
    c->segments[0][0] = (GridSegment){.length = x1 - x0, .cells = nx};
    c->segments[1][0] = (GridSegment){.length = y1 - y0, .cells = ny};
}

void gks_config_set_bc(GksConfig *c, int face, const FlowBc *bc) {
    c->bc[face].count = 1;
    c->bc[face].seg[0] = *bc;
    c->bc[face].seg[0].start = 0.0;
}

/* ------------------------------------------------------------ accessors */

GksFields gks_solver_fields(GksSolver *s) {
    GksFields f;
    for (int v = 0; v < 4; v++) f.w[v] = s->w[v];
    f.kind = s->kind;
    return f;
}
const Grid *gks_solver_grid(const GksSolver *s) {
    return &s->grid;
}
const GksParams *gks_solver_gas(const GksSolver *s) {
    return &s->gas;
}
const Grid *gks_solver_whole_grid(const GksSolver *s) {
    return comm_distributed(&s->comm) ? &s->whole : &s->grid;
}
int gks_solver_process_columns(const GksSolver *s) {
    return s->dims[0];
}
const NspdComm *gks_solver_comm(const GksSolver *s) {
    return &s->comm;
}

double gks_solver_comm_seconds(const GksSolver *s) {
    return s->comm_seconds;
}

void gks_solver_add_comm_seconds(GksSolver *s, double seconds) {
    s->comm_seconds += seconds;
}

const GksConfig *gks_solver_config(const GksSolver *s) {
    return &s->cfg;
}
void gks_solver_set_ghost_hook(GksSolver *s, FlowGhostHook hook, void *ctx) {
    s->hook = hook;
    s->hook_ctx = ctx;
}
int gks_solver_source_cells(GksSolver *s, double *out[3]) {
    for (int k = 0; k < 3; k++) {
        if (!s->source[k]) TRY(nspd_alloc(&s->source[k], (size_t)s->grid.size, sizeof(double)));
        memset(s->source[k], 0, (size_t)s->grid.size * sizeof(double));
        out[k] = s->source[k];
    }
    s->has_sources = true;
    return NSPD_OK;
}

void gks_solver_clear_sources(GksSolver *s) {
    s->has_sources = false;
}

void gks_solver_set_ghost_walls(GksSolver *s, const int32_t *slot, const double *u,
                                const double *v) {
    s->wall_slot = slot;
    s->wall_u = u;
    s->wall_v = v;
}
int gks_solver_set_seals(GksSolver *s, int64_t n, const int64_t *cells, const double *area,
                         const double *u, const double *v, double fraction) {
    if (!s->seal_slot) {
        if (n == 0) return NSPD_OK;
        TRY(nspd_alloc(&s->seal_slot, (size_t)s->grid.size, sizeof(int32_t)));
        for (int64_t k = 0; k < s->grid.size; k++) s->seal_slot[k] = -1;
    }
    for (int64_t k = 0; k < s->seals; k++) s->seal_slot[s->seal_cell[k]] = -1;
    s->seals = 0;
    if (n > s->seal_capacity) {
        const size_t old = (size_t)s->seal_capacity, size = (size_t)n;
        TRY(nspd_realloc(&s->seal_cell, old, size, sizeof(int64_t)));
        TRY(nspd_realloc(&s->seal_u, old, size, sizeof(double)));
        TRY(nspd_realloc(&s->seal_v, old, size, sizeof(double)));
        s->seal_capacity = n;
    }
    const Grid *g = &s->grid;
    int64_t kept = 0;
    for (int64_t k = 0; k < n; k++) {
        const int64_t c = cells[k];
        const int64_t i = c % g->stride - GRID_NG, j = c / g->stride - GRID_NG;
        if (s->kind[c] != FLOW_CELL_FLUID ||
            area[k] < fraction * g->ax[0].width[i] * g->ax[1].width[j])
            continue;
        s->seal_cell[kept] = c;
        s->seal_u[kept] = u[k];
        s->seal_v[kept] = v[k];
        s->seal_slot[c] = (int32_t)kept++;
    }
    s->seals = kept;
    return NSPD_OK;
}

double gks_solver_time(const GksSolver *s) {
    return s->time;
}
int64_t gks_solver_step_count(const GksSolver *s) {
    return s->steps;
}
int64_t gks_solver_fallbacks_last(const GksSolver *s) {
    return s->fallbacks_last;
}
int64_t gks_solver_fallbacks_total(const GksSolver *s) {
    return s->fallbacks_total;
}

/* The state a step changes: the conservative fields (ghost layers too),
 * the cell kinds (an immersed boundary changes them), the sources a
 * coupling holds over the steps, the clock and the counters. */
/* A per-cell array of `elem`-byte values is checkpointed as the whole
 * grid's padded array (io_cells): one process's as it is; on several, each
 * block's own cells gathered and placed (io_blocks), and on reading each
 * block's cut from the whole. So a checkpoint is the same for any number
 * of processes and process grid, and is read back by any other. */

/* The padded cells rank r holds as the whole grid's, per axis [lo, hi)
 * in the whole grid's padded indices: its interior, and the box's ghost
 * layers where it ends the whole grid. */
static void owned_padded(const GksSolver *s, int r, int lo[2], int hi[2]) {
    int first[2], count[2];
    gks_solver_block(s, r, first, count);
    const int c[2] = {r % s->dims[0], r / s->dims[0]};
    for (int a = 0; a < 2; a++) {
        lo[a] = c[a] == 0 ? 0 : first[a] + GRID_NG;
        hi[a] = first[a] + count[a] + (c[a] == s->dims[a] - 1 ? 2 : 1) * GRID_NG;
    }
}

/* io_cells on several processes: each rank's owned padded cells packed,
 * gathered, and placed in the whole padded array (its padding zeros); on
 * reading each rank cuts its padded block (its halo too) out of the
 * whole. */
static int io_blocks(GksSolver *s, Checkpoint *ck, const char *name, void *cells, size_t elem) {
    const Grid *g = &s->grid, *w = &s->whole;
    unsigned char *whole = NULL, *mine = NULL, *all = NULL, *local = cells;
    int lo[2], hi[2];
    owned_padded(s, s->comm.rank, lo, hi);
    const size_t run = (size_t)(hi[0] - lo[0]) * elem;
    int status = nspd_alloc(&whole, (size_t)w->size, elem);
    if (status == NSPD_OK && !checkpoint_reading(ck)) {
        status = nspd_alloc(&mine, (size_t)(hi[1] - lo[1]) * run + 1, 1);
        if (status == NSPD_OK) status = nspd_alloc(&all, (size_t)w->size, elem);
        for (int R = lo[1]; R < hi[1] && status == NSPD_OK; R++)
            memcpy(mine + (size_t)(R - lo[1]) * run,
                   local + ((size_t)(R - s->first[1]) * (size_t)g->stride +
                            (size_t)(lo[0] - s->first[0])) *
                               elem,
                   run);
        if (status == NSPD_OK)
            status =
                comm_allgatherv_bytes(&s->comm, mine, (int)((size_t)(hi[1] - lo[1]) * run), all);
        const unsigned char *at = all;
        for (int r = 0; r < s->comm.size && status == NSPD_OK; r++) {
            int l[2], h[2];
            owned_padded(s, r, l, h);
            const size_t n = (size_t)(h[0] - l[0]) * elem;
            for (int R = l[1]; R < h[1]; R++, at += n)
                memcpy(whole + ((size_t)R * (size_t)w->stride + (size_t)l[0]) * elem, at, n);
        }
    }
    if (status == NSPD_OK) status = checkpoint_io(ck, name, whole, (size_t)w->size * elem);
    if (status == NSPD_OK && checkpoint_reading(ck))
        for (int r = 0; r < g->ny + 2 * GRID_NG; r++)
            memcpy(local + (size_t)r * (size_t)g->stride * elem,
                   whole +
                       ((size_t)(s->first[1] + r) * (size_t)w->stride + (size_t)s->first[0]) * elem,
                   (size_t)(g->nx + 2 * GRID_NG) * elem);
    nspd_free(&whole);
    nspd_free(&mine);
    nspd_free(&all);
    return status;
}

static int io_cells(GksSolver *s, Checkpoint *ck, const char *name, void *cells, size_t elem) {
    if (!comm_distributed(&s->comm))
        return checkpoint_io(ck, name, cells, (size_t)s->grid.size * elem);
    return io_blocks(s, ck, name, cells, elem);
}

int gks_solver_checkpoint(GksSolver *s, Checkpoint *ck) {
    static const char *const W[4] = {"gks.rho", "gks.rho_u", "gks.rho_v", "gks.rho_e"};
    for (int v = 0; v < 4; v++) TRY(io_cells(s, ck, W[v], s->w[v], sizeof(double)));
    TRY(io_cells(s, ck, "gks.kind", s->kind, 1));
    int has = s->has_sources;
    TRY(checkpoint_io_int(ck, "gks.has_sources", &has));
    if (has) {
        double *src[3];
        if (checkpoint_reading(ck)) TRY(gks_solver_source_cells(s, src));
        static const char *const S[3] = {"gks.source_x", "gks.source_y", "gks.source_e"};
        for (int k = 0; k < 3; k++) TRY(io_cells(s, ck, S[k], s->source[k], sizeof(double)));
    }
    s->has_sources = has != 0;
    TRY(checkpoint_io_double(ck, "gks.time", &s->time));
    TRY(checkpoint_io_int64(ck, "gks.steps", &s->steps));
    TRY(checkpoint_io_int64(ck, "gks.fallbacks_last", &s->fallbacks_last));
    return checkpoint_io_int64(ck, "gks.fallbacks_total", &s->fallbacks_total);
}

/* ------------------------------------------------------ create/destroy */

static int alloc_counted(GksSolver *s, void *out, size_t count, size_t size) {
    TRY(nspd_alloc(out, count, size));
    s->bytes += count * size;
    return NSPD_OK;
}

/* The configuration's numbers, checked before anything is allocated. */
static int check_config(const GksConfig *cfg) {
    if (!(cfg->gamma > 1.0 && cfg->gamma < 3.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow: gamma must be in (1, 3) (got %g)", cfg->gamma);
    if (!(cfg->gas_constant > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow: gas constant must be > 0");
    if (!(cfg->cfl > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow: CFL number must be > 0 (got %g)", cfg->cfl);
    if (!(cfg->prandtl > 0.0)) return NSPD_FAIL(NSPD_ERR_INPUT, "flow: Prandtl number must be > 0");
    if ((int)cfg->limiter < 0 || cfg->limiter >= LIMITER_COUNT)
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow: unknown limiter");
    if (cfg->viscosity != VISCOSITY_NONE && !(cfg->mu_ref > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow: viscosity mu_ref must be > 0");
    if ((cfg->viscosity == VISCOSITY_POWER || cfg->viscosity == VISCOSITY_SUTHERLAND) &&
        !(cfg->T_ref > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow: viscosity T_ref must be > 0");
    for (int a = 0; a < 2; a++)
        if (cfg->segment_count[a] < 1 || cfg->segment_count[a] > FLOW_MAX_SEGMENTS)
            return NSPD_FAIL(NSPD_ERR_INPUT, "flow: the %s axis needs 1..%d grid segments",
                             a == 0 ? "x" : "y", FLOW_MAX_SEGMENTS);
    return NSPD_OK;
}

/* The kernel's gas parameters from the configuration. */
static void set_gas(GksParams *gas, const GksConfig *cfg) {
    gks_params_default(gas, cfg->gamma, cfg->gas_constant);
    gas->law = cfg->viscosity;
    gas->mu_ref = cfg->mu_ref;
    gas->T_ref = cfg->T_ref > 0.0 ? cfg->T_ref : 1.0;
    gas->omega = cfg->omega;
    gas->sutherland_S = cfg->sutherland_S;
    gas->prandtl = cfg->viscosity == VISCOSITY_NONE ? 1.0 : cfg->prandtl;
    gas->c_jump = cfg->tau_jump_c;
    gas->eps_dt = cfg->tau_eps;
}

/* State, kinds, half widths and row sums. */
static int alloc_state(GksSolver *s) {
    const Grid *g = &s->grid;
    for (int v = 0; v < 4; v++) {
        TRY(alloc_counted(s, &s->w[v], (size_t)g->size, sizeof(double)));
        TRY(alloc_counted(s, &s->wn[v], (size_t)g->size, sizeof(double)));
    }
    TRY(alloc_counted(s, &s->kind, (size_t)g->size, 1));
    for (int a = 0; a < 2; a++) {
        const int n = g->ax[a].n + 2 * GRID_NG;
        TRY(alloc_counted(s, &s->half_w[a], (size_t)n, sizeof(double)));
        for (int i = 0; i < n; i++) s->half_w[a][i] = 0.5 * g->ax[a].width[i - GRID_NG];
    }
    TRY(alloc_counted(s, &s->row_sums, (size_t)4 * (size_t)g->ny, sizeof(double)));
    return NSPD_OK;
}

/* The WALL_* flags of every cell along each box face, from the segment of
 * the face's boundary condition that covers it. */
static int build_walls(GksSolver *s, const GksConfig *cfg) {
    const Grid *g = &s->grid;
    for (int face = 0; face < 4; face++) {
        const GridAxis *along = &g->ax[face < 2 ? 1 : 0];
        TRY(alloc_counted(s, &s->wall[face], (size_t)along->n, 1));
        for (int t = 0; t < along->n; t++) {
            const FlowFaceBc *b = &cfg->bc[face];
            int k = 0;
            while (k + 1 < b->count && along->center[t] >= b->seg[k + 1].start) k++;
            const FlowBc *bc = &b->seg[k];
            uint8_t f = 0;
            if (bc->kind == BC_SLIP_WALL || bc->kind == BC_SYMMETRY) f = WALL_MASS | WALL_ENERGY;
            if (bc->kind == BC_NOSLIP_ADIABATIC)
                f = bc->wall_velocity == 0.0 ? WALL_MASS | WALL_ENERGY : WALL_MASS;
            if (bc->kind == BC_NOSLIP_ISOTHERMAL) f = WALL_MASS;
            s->wall[face][t] = f;
        }
    }
    return NSPD_OK;
}

/* The step's work space: one block of rows per thread (FlowWork). */
static int alloc_work(GksSolver *s) {
    s->nthreads = omp_get_max_threads();
    TRY(nspd_alloc(&s->work, (size_t)s->nthreads, sizeof(FlowWork)));
    const size_t row = (size_t)s->grid.stride;
    for (int t = 0; t < s->nthreads; t++) {
        FlowWork *wk = &s->work[t];
        /* 16 slope rows + 4 x-flux rows + 8 y-flux rows */
        TRY(alloc_counted(s, &wk->block, 28 * row, sizeof(double)));
        double *p = wk->block;
        for (int r = 0; r < 2; r++)
            for (int v = 0; v < 4; v++) {
                wk->sx[r][v] = p, p += row;
                wk->sy[r][v] = p, p += row;
                wk->gy[r][v] = p, p += row;
            }
        for (int v = 0; v < 4; v++) wk->fx[v] = p, p += row;
    }
    return NSPD_OK;
}

int gks_solver_validate(const GksConfig *cfg) {
    TRY(check_config(cfg));
    const bool per_x = cfg->bc[FLOW_FACE_XLO].seg[0].kind == BC_PERIODIC;
    const bool per_y = cfg->bc[FLOW_FACE_YLO].seg[0].kind == BC_PERIODIC;
    Grid g = {0};
    TRY(grid_create(&g, cfg->x0, cfg->segment_count[0], cfg->segments[0], per_x, cfg->y0,
                    cfg->segment_count[1], cfg->segments[1], per_y));
    const int status = bc_validate(&g, cfg->bc);
    grid_destroy(&g);
    return status;
}

double gks_solver_config_stable_dt(const GksConfig *cfg, const FlowRegion *regions, int count) {
    if (cfg->init_fn || check_config(cfg) != NSPD_OK) return 0.0;
    GksParams gas;
    set_gas(&gas, cfg);
    const double hx = grid_segments_min_spacing(cfg->segment_count[0], cfg->segments[0]);
    const double hy = grid_segments_min_spacing(cfg->segment_count[1], cfg->segments[1]);
    if (!(hx > 0.0 && hy > 0.0)) return 0.0;
    const double visc_factor = gks_visc_factor(&gas);
    double rate = gks_signal_rate(&gas, gas.law, visc_factor, &cfg->initial, 1.0 / hx, 1.0 / hy);
    for (int r = 0; r < count; r++)
        rate = fmax(rate, gks_signal_rate(&gas, gas.law, visc_factor, &regions[r].state, 1.0 / hx,
                                          1.0 / hy));
    return rate > 0.0 ? cfg->cfl / rate : 0.0;
}

void gks_solver_block(const GksSolver *s, int rank, int first[2], int count[2]) {
    const Grid *w = gks_solver_whole_grid(s);
    const int n[2] = {w->nx, w->ny}, c[2] = {rank % s->dims[0], rank / s->dims[0]};
    for (int a = 0; a < 2; a++) {
        first[a] = blocks_cut(n[a], s->dims[a], c[a]);
        count[a] = blocks_cut(n[a], s->dims[a], c[a] + 1) - first[a];
    }
}

/* The process grid of a group of p: the configuration's, or the one of
 * the fewest halo cells (core/blocks.h), each block at least GRID_NG
 * cells along each axis. */
static int process_grid(const GksConfig *cfg, const Grid *whole, int p, int dims[2]) {
    const int n[2] = {whole->nx, whole->ny};
    const bool periodic[2] = {whole->ax[0].periodic, whole->ax[1].periodic};
    static const char *const WHAT[2] = {"columns", "rows"};
    return blocks_process_grid(n, periodic, GRID_NG, p, cfg->processes, WHAT, dims);
}

/* This process's block of the whole grid `whole` (solver.h), into
 * s->grid; the whole grid itself on one process. */
static int take_block(GksSolver *s, Grid *whole, const GksConfig *cfg) {
    s->comm = cfg->comm ? *cfg->comm : comm_self();
    s->rows = whole->ny;
    s->dims[0] = s->dims[1] = 1;
    for (int face = 0; face < 4; face++) s->nbr[face] = -1;
    s->bc_faces = 15u;
    const bool alone = !comm_distributed(&s->comm);
    int status = process_grid(cfg, whole, alone ? 1 : s->comm.size, s->dims);
    if (status == NSPD_OK && alone) {
        s->grid = *whole;
        return NSPD_OK;
    }
    const int r = s->comm.rank;
    int count[2];
    if (status == NSPD_OK) {
        s->whole = *whole; /* kept: the probes and writers see the whole grid */
        gks_solver_block(s, r, s->first, count);
        status = grid_slice(&s->grid, whole, s->first, count);
    }
    if (status != NSPD_OK) {
        grid_destroy(whole);
        memset(&s->whole, 0, sizeof s->whole);
        return status;
    }
    s->coord[0] = r % s->dims[0];
    s->coord[1] = r / s->dims[0];
    /* per axis: the neighbours (wrapped on a periodic axis), or, on an
     * axis of one block, the box faces from their boundary conditions */
    s->bc_faces = 0u;
    const int step[2] = {1, s->dims[0]};
    for (int a = 0; a < 2; a++) {
        const int lo = 2 * a, hi = 2 * a + 1, c = s->coord[a], last = s->dims[a] - 1;
        if (s->dims[a] == 1) {
            s->bc_faces |= 1u << lo | 1u << hi;
            continue;
        }
        const bool wrap = s->grid.ax[a].periodic;
        s->nbr[lo] = c > 0 ? r - step[a] : (wrap ? r + last * step[a] : -1);
        s->nbr[hi] = c < last ? r + step[a] : (wrap ? r - last * step[a] : -1);
        if (s->nbr[lo] < 0) s->bc_faces |= 1u << lo;
        if (s->nbr[hi] < 0) s->bc_faces |= 1u << hi;
    }
    return NSPD_OK;
}

/* Everything after the grid; on failure the caller destroys the solver. */
static int build(GksSolver *s, const GksConfig *cfg) {
    TRY(bc_validate(&s->grid, cfg->bc));
    set_gas(&s->gas, cfg);
    TRY(alloc_state(s));
    TRY(build_walls(s, cfg));
    /* a block's inner faces are no walls */
    for (int face = 0; face < 4; face++)
        if (!(s->bc_faces >> face & 1u))
            memset(s->wall[face], 0, (size_t)(face < 2 ? s->grid.ny : s->grid.nx));
    if (comm_distributed(&s->comm))
        TRY(alloc_counted(s, &s->row_sums_all, (size_t)4 * (size_t)s->rows, sizeof(double)));
    if (s->dims[0] > 1) { /* 2D process grids: the x halo's buffers, rank 0's gather */
        TRY(alloc_counted(s, &s->halo_x, (size_t)20 * GRID_NG * (size_t)s->grid.ny,
                          sizeof(double)));
        if (s->comm.rank == 0)
            TRY(alloc_counted(s, &s->gather, (size_t)s->whole.nx * (size_t)s->whole.ny,
                              sizeof(double)));
    }
    TRY(alloc_work(s));
    gks_solver_apply_initial(s, cfg);
    return NSPD_OK;
}

int gks_solver_create(GksSolver **out, const GksConfig *cfg) {
    *out = NULL;
    TRY(check_config(cfg));
    GksSolver *s = NULL;
    TRY(nspd_alloc(&s, 1, sizeof *s));
    s->cfg = *cfg;
    s->cfg.regions = NULL; /* borrowed only during create */
    s->cfg.region_count = 0;
    s->cfg.comm = NULL; /* borrowed only during create; s->comm is the copy */
    const bool per_x = cfg->bc[FLOW_FACE_XLO].seg[0].kind == BC_PERIODIC;
    const bool per_y = cfg->bc[FLOW_FACE_YLO].seg[0].kind == BC_PERIODIC;
    Grid whole;
    int st = grid_create(&whole, cfg->x0, cfg->segment_count[0], cfg->segments[0], per_x, cfg->y0,
                         cfg->segment_count[1], cfg->segments[1], per_y);
    if (st >= 0) st = take_block(s, &whole, cfg);
    if (st < 0) {
        nspd_free(&s);
        return st;
    }
    if ((st = build(s, cfg)) < 0) {
        gks_solver_destroy(&s);
        return st;
    }
    *out = s;
    return NSPD_OK;
}

void gks_solver_destroy(GksSolver **sp) {
    GksSolver *s = *sp;
    if (!s) return;
    for (int v = 0; v < 4; v++) {
        nspd_free(&s->w[v]);
        nspd_free(&s->wn[v]);
    }
    nspd_free(&s->kind);
    nspd_free(&s->half_w[0]);
    nspd_free(&s->half_w[1]);
    nspd_free(&s->row_sums);
    nspd_free(&s->row_sums_all);
    nspd_free(&s->gather);
    nspd_free(&s->halo_x);
    for (int k = 0; k < 3; k++) nspd_free(&s->source[k]);
    nspd_free(&s->seal_slot);
    nspd_free(&s->seal_cell);
    nspd_free(&s->seal_u);
    nspd_free(&s->seal_v);
    for (int face = 0; face < 4; face++) nspd_free(&s->wall[face]);
    if (s->work)
        for (int t = 0; t < s->nthreads; t++) nspd_free(&s->work[t].block);
    nspd_free(&s->work);
    grid_destroy(&s->grid);
    if (comm_distributed(&s->comm)) grid_destroy(&s->whole);
    nspd_free(sp);
}
