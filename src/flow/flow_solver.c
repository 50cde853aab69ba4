/* The flow operator: state, boundary filling, the GKS step (paper 000 Eq. 20).
 *
 * Data: W (current) and Wn (next) conservative fields, one array per
 * variable, GRID_NG ghost layers, rows padded to 64 bytes; kind[] per cell.
 * The step reads W and writes Wn, then swaps the two: no cell is read after
 * it is overwritten, whatever the thread layout.
 *
 * Row pipeline (one block of rows per thread, rows j0 .. j1-1):
 *   slopes(j0-1), slopes(j0); G_bottom = y-fluxes between j0-1 and j0
 *   for j = j0 .. j1-1:
 *       slopes(j+1)
 *       F = x-fluxes of row j (nx+1 faces), G_top = y-fluxes between j, j+1
 *       Wn(row j) = W - (F_{i+1/2} - F_{i-1/2})/dx_i - (G_top - G_bottom)/dy_j
 *       G_bottom <- G_top; slopes(j) <- slopes(j+1)
 * Slopes of a row are those along x and along y of the cells -1 .. nx (the
 * ghost columns feed the boundary faces and their tangential slopes). Each
 * face flux is computed once per block (twice on a block boundary, with
 * identical inputs and hence identical bits). All work arrays are allocated
 * at creation for omp_get_max_threads() threads. */
#include "flow/flow_solver.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/gks_flux.h"
#include "flow/gks_update_kernel.h"
#include "flow/recon.h"

#include <math.h>
#include <omp.h>
#include <string.h>

/* Below this many cells (128^2) a step runs on one thread: a parallel region
 * costs microseconds, more than a small grid's step gains. Measured on the
 * panel case (59,540 cells): 2 threads run 1.7x faster than 1. On an
 * oversubscribed machine (`ctest -j2` with OMP_NUM_THREADS=2) a spinning
 * thread waiting for a descheduled partner costs a scheduler time slice per
 * region (5x-30x slow-downs were measured with the default wait policy), so
 * the tests run with OMP_WAIT_POLICY=passive. Results do not depend on the
 * thread count either way. */
enum { PARALLEL_MIN_CELLS = 16384 };

const char *const FLOW_LIMITER_NAMES[LIMITER_COUNT + 1] = {"van_leer", "van_albada", "none",
                                                           "first_order", NULL};

/* Wall faces of the box. The ghost state of a no-slip wall is the image
 * with both velocity components reversed, which is not a mirror image: the
 * tangential-slope terms of the 2D flux then leave a mass flux of order
 * tau |V| dV/dt through the wall (measured 1e-6 of the mass in 20 steps of a
 * viscous box). The flux through a wall face is therefore corrected: its
 * mass flux is zero, and so is its energy flux where the wall is adiabatic and
 * does no work (slip walls, symmetry, resting adiabatic no-slip walls). */
enum { WALL_MASS = 1, WALL_ENERGY = 2 };

/* Per-thread work space (rows of length stride, cell i at offset GRID_NG). */
typedef struct {
    double *sx[2][4], *sy[2][4]; /* slopes along x and y, two rows */
    double *fx[4];               /* x-face fluxes of a row, face i at i */
    double *gy[2][4];            /* y-face fluxes below and above a row */
    double *block;
    int64_t fallbacks;
    int bad;
} FlowWork;

struct FlowSolver {
    FlowConfig cfg;
    Grid grid;
    GksParams gas;
    double *w[4], *wn[4];
    uint8_t *kind;
    double *half_w[2]; /* half widths per axis, index -NG .. n+NG-1 (offset) */
    double *row_sums;  /* 4 * ny, for deterministic totals */
    uint8_t *wall[4];  /* per box face, per cell along it: WALL_* flags */
    int nthreads;
    FlowWork *work;
    FlowGhostHook hook;
    void *hook_ctx;
    const int32_t *wall_slot; /* flow_solver_set_ghost_walls */
    const double *wall_u, *wall_v;
    double time;
    int64_t steps;
    int64_t fallbacks_last, fallbacks_total;
    size_t bytes; /* allocated by create (state + work), for the benchmark */
};

void flow_config_default(FlowConfig *c) {
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

void flow_config_uniform_grid(FlowConfig *c, double x0, double x1, int nx, double y0, double y1,
                              int ny) {
    c->x0 = x0;
    c->y0 = y0;
    c->segment_count[0] = c->segment_count[1] = 1;
    c->segments[0][0] = (GridSegment){.length = x1 - x0, .cells = nx};
    c->segments[1][0] = (GridSegment){.length = y1 - y0, .cells = ny};
}

void flow_config_set_bc(FlowConfig *c, int face, const FlowBc *bc) {
    c->bc[face].count = 1;
    c->bc[face].seg[0] = *bc;
    c->bc[face].seg[0].start = 0.0;
}

/* ------------------------------------------------------------ accessors */

FlowFields flow_solver_fields(FlowSolver *s) {
    FlowFields f;
    for (int v = 0; v < 4; v++) f.w[v] = s->w[v];
    f.kind = s->kind;
    return f;
}
const Grid *flow_solver_grid(const FlowSolver *s) {
    return &s->grid;
}
const GksParams *flow_solver_gas(const FlowSolver *s) {
    return &s->gas;
}
const FlowConfig *flow_solver_config(const FlowSolver *s) {
    return &s->cfg;
}
void flow_solver_set_ghost_hook(FlowSolver *s, FlowGhostHook hook, void *ctx) {
    s->hook = hook;
    s->hook_ctx = ctx;
}
void flow_solver_set_ghost_walls(FlowSolver *s, const int32_t *slot, const double *u,
                                 const double *v) {
    s->wall_slot = slot;
    s->wall_u = u;
    s->wall_v = v;
}
double flow_solver_time(const FlowSolver *s) {
    return s->time;
}
int64_t flow_solver_step_count(const FlowSolver *s) {
    return s->steps;
}
int64_t flow_solver_fallbacks_last(const FlowSolver *s) {
    return s->fallbacks_last;
}
int64_t flow_solver_fallbacks_total(const FlowSolver *s) {
    return s->fallbacks_total;
}

/* ------------------------------------------------------- initial state */

/* Gauss-Legendre points and weights on [-1/2, 1/2] for 1..4 points. */
static void gauss_rule(int n, double *x, double *w) {
    switch (n) {
    case 2: {
        const double a = 0.5 / sqrt(3.0);
        x[0] = -a, x[1] = a;
        w[0] = w[1] = 0.5;
        break;
    }
    case 3: {
        const double a = 0.5 * sqrt(0.6);
        x[0] = -a, x[1] = 0.0, x[2] = a;
        w[0] = w[2] = 5.0 / 18.0;
        w[1] = 8.0 / 18.0;
        break;
    }
    case 4: {
        const double a = 0.5 * sqrt(3.0 / 7.0 - 2.0 / 7.0 * sqrt(1.2));
        const double b = 0.5 * sqrt(3.0 / 7.0 + 2.0 / 7.0 * sqrt(1.2));
        const double wa = (18.0 + sqrt(30.0)) / 72.0, wb = (18.0 - sqrt(30.0)) / 72.0;
        x[0] = -b, x[1] = -a, x[2] = a, x[3] = b;
        w[0] = w[3] = wb;
        w[1] = w[2] = wa;
        break;
    }
    default:
        x[0] = 0.0, w[0] = 1.0;
    }
}

static void initial_prim(const FlowConfig *cfg, double x, double y, FlowPrim *q) {
    if (cfg->init_fn) {
        cfg->init_fn(cfg->init_ctx, x, y, q);
        return;
    }
    *q = cfg->initial;
    const double pt[3] = {x, y, 0.0};
    for (int r = 0; r < cfg->region_count; r++)
        if (shapeset_contains(&cfg->regions[r].shapes, pt)) *q = cfg->regions[r].state;
}

void flow_solver_apply_initial(FlowSolver *s, const FlowConfig *cfg) {
    const Grid *g = &s->grid;
    int nq = cfg->init_quadrature;
    nq = nq < 1 ? 1 : nq > 4 ? 4 : nq;
    double gx[4], gw[4];
    gauss_rule(nq, gx, gw);
    const double gamma = s->gas.gamma;
    for (int j = 0; j < g->ny; j++) {
        for (int i = 0; i < g->nx; i++) {
            double acc[4] = {0.0, 0.0, 0.0, 0.0};
            for (int b = 0; b < nq; b++) {
                for (int a = 0; a < nq; a++) {
                    const double x = g->ax[0].center[i] + gx[a] * g->ax[0].width[i];
                    const double y = g->ax[1].center[j] + gx[b] * g->ax[1].width[j];
                    FlowPrim q;
                    double c[4];
                    initial_prim(cfg, x, y, &q);
                    flow_prim_to_cons(&q, gamma, c);
                    for (int v = 0; v < 4; v++) acc[v] += gw[a] * gw[b] * c[v];
                }
            }
            const int64_t k = grid_index(g, i, j);
            for (int v = 0; v < 4; v++) s->w[v][k] = acc[v];
        }
    }
    flow_solver_fill_boundaries(s);
}

/* ------------------------------------------------------ create/destroy */

static int alloc_counted(FlowSolver *s, void *out, size_t count, size_t size) {
    TRY(nspd_alloc(out, count, size));
    s->bytes += count * size;
    return NSPD_OK;
}

int flow_solver_create(FlowSolver **out, const FlowConfig *cfg) {
    *out = NULL;
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

    FlowSolver *s = NULL;
    TRY(nspd_alloc(&s, 1, sizeof *s));
    s->cfg = *cfg;
    s->cfg.regions = NULL; /* borrowed only during create */
    s->cfg.region_count = 0;
    int st = NSPD_OK;
    const bool per_x = cfg->bc[FLOW_FACE_XLO].seg[0].kind == BC_PERIODIC;
    const bool per_y = cfg->bc[FLOW_FACE_YLO].seg[0].kind == BC_PERIODIC;
    st = grid_create(&s->grid, cfg->x0, cfg->segment_count[0], cfg->segments[0], per_x, cfg->y0,
                     cfg->segment_count[1], cfg->segments[1], per_y);
    if (st < 0) {
        nspd_free(&s);
        return st;
    }
    const Grid *g = &s->grid;
    if ((st = bc_validate(g, cfg->bc)) < 0) goto fail;

    gks_params_default(&s->gas, cfg->gamma, cfg->gas_constant);
    s->gas.law = cfg->viscosity;
    s->gas.mu_ref = cfg->mu_ref;
    s->gas.T_ref = cfg->T_ref > 0.0 ? cfg->T_ref : 1.0;
    s->gas.omega = cfg->omega;
    s->gas.sutherland_S = cfg->sutherland_S;
    s->gas.prandtl = cfg->viscosity == VISCOSITY_NONE ? 1.0 : cfg->prandtl;
    s->gas.c_jump = cfg->tau_jump_c;
    s->gas.eps_dt = cfg->tau_eps;

    for (int v = 0; v < 4; v++) {
        if ((st = alloc_counted(s, &s->w[v], (size_t)g->size, sizeof(double))) < 0) goto fail;
        if ((st = alloc_counted(s, &s->wn[v], (size_t)g->size, sizeof(double))) < 0) goto fail;
    }
    if ((st = alloc_counted(s, &s->kind, (size_t)g->size, 1)) < 0) goto fail;
    for (int a = 0; a < 2; a++) {
        const int n = g->ax[a].n + 2 * GRID_NG;
        if ((st = alloc_counted(s, &s->half_w[a], (size_t)n, sizeof(double))) < 0) goto fail;
        for (int i = 0; i < n; i++) s->half_w[a][i] = 0.5 * g->ax[a].width[i - GRID_NG];
    }
    if ((st = alloc_counted(s, &s->row_sums, (size_t)4 * g->ny, sizeof(double))) < 0) goto fail;
    for (int face = 0; face < 4; face++) {
        const GridAxis *along = &g->ax[face < 2 ? 1 : 0];
        if ((st = alloc_counted(s, &s->wall[face], (size_t)along->n, 1)) < 0) goto fail;
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

    s->nthreads = omp_get_max_threads();
    if ((st = nspd_alloc(&s->work, (size_t)s->nthreads, sizeof(FlowWork))) < 0) goto fail;
    const size_t row = (size_t)g->stride;
    for (int t = 0; t < s->nthreads; t++) {
        FlowWork *wk = &s->work[t];
        /* 16 slope rows + 4 x-flux rows + 8 y-flux rows */
        if ((st = alloc_counted(s, &wk->block, 28 * row, sizeof(double))) < 0) goto fail;
        double *p = wk->block;
        for (int r = 0; r < 2; r++)
            for (int v = 0; v < 4; v++) {
                wk->sx[r][v] = p, p += row;
                wk->sy[r][v] = p, p += row;
                wk->gy[r][v] = p, p += row;
            }
        for (int v = 0; v < 4; v++) wk->fx[v] = p, p += row;
    }
    flow_solver_apply_initial(s, cfg);
    *out = s;
    return NSPD_OK;
fail:
    flow_solver_destroy(&s);
    return st;
}

void flow_solver_destroy(FlowSolver **sp) {
    FlowSolver *s = *sp;
    if (!s) return;
    for (int v = 0; v < 4; v++) {
        nspd_free(&s->w[v]);
        nspd_free(&s->wn[v]);
    }
    nspd_free(&s->kind);
    nspd_free(&s->half_w[0]);
    nspd_free(&s->half_w[1]);
    nspd_free(&s->row_sums);
    for (int face = 0; face < 4; face++) nspd_free(&s->wall[face]);
    if (s->work)
        for (int t = 0; t < s->nthreads; t++) nspd_free(&s->work[t].block);
    nspd_free(&s->work);
    grid_destroy(&s->grid);
    nspd_free(sp);
}

/* ----------------------------------------------------------------- step */

void flow_solver_fill_boundaries(FlowSolver *s) {
    bc_fill(&s->grid, s->cfg.bc, &s->gas, s->w, s->kind);
}

/* Signal-speed rate of each cell of row j into rate[0..nx) (0 in non-fluid
 * cells); the law is a constant in each instantiation so the loop vectorises. */
static inline __attribute__((always_inline)) void dt_rates(const FlowSolver *s, int j, int law,
                                                           double visc_factor, double *rate) {
    const Grid *g = &s->grid;
    const GksParams gas = s->gas;
    const double gamma = gas.gamma, gm1 = gamma - 1.0, iR = 1.0 / gas.R;
    const double idy = g->ax[1].inv_width[j];
    const int64_t base = grid_index(g, 0, j);
    const double *restrict r = s->w[0] + base, *restrict mx = s->w[1] + base,
                           *restrict my = s->w[2] + base, *restrict e = s->w[3] + base;
    const uint8_t *restrict kd = s->kind + base;
    const double *restrict idx = g->ax[0].inv_width;
    double *restrict out = rate;
#pragma GCC ivdep
    for (int i = 0; i < g->nx; i++) {
        const double ir = 1.0 / r[i], u = mx[i] * ir, v = my[i] * ir;
        const double p = gm1 * (e[i] - 0.5 * (mx[i] * u + my[i] * v));
        const double c = sqrt(gamma * p * ir);
        const double nu = visc_factor * gks_viscosity(&gas, p * ir * iR, law) * ir;
        const double rt =
            (fabs(u) + c) * idx[i] + (fabs(v) + c) * idy + nu * (idx[i] * idx[i] + idy * idy);
        out[i] = kd[i] == FLOW_CELL_FLUID ? rt : 0.0;
    }
}

double flow_solver_stable_dt(const FlowSolver *s) {
    const Grid *g = &s->grid;
    const int law = s->gas.law;
    const double visc_factor =
        law == VISCOSITY_NONE ? 0.0 : 2.0 * fmax(4.0 / 3.0, s->gas.gamma / s->cfg.prandtl);
    double rmax = 0.0;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
    int nt = omp_get_max_threads();
    nt = nt > s->nthreads ? s->nthreads : nt;
#pragma omp parallel num_threads(nt) if (big) reduction(max : rmax)
    {
        /* the x-flux row of this thread's work space is free between steps */
        double *rate = s->work[omp_get_thread_num()].fx[0];
        double m = 0.0;
#pragma omp for schedule(static)
        for (int j = 0; j < g->ny; j++) {
            switch (law) {
            case VISCOSITY_CONSTANT:
                dt_rates(s, j, VISCOSITY_CONSTANT, visc_factor, rate);
                break;
            case VISCOSITY_POWER:
                dt_rates(s, j, VISCOSITY_POWER, visc_factor, rate);
                break;
            case VISCOSITY_SUTHERLAND:
                dt_rates(s, j, VISCOSITY_SUTHERLAND, visc_factor, rate);
                break;
            default:
                dt_rates(s, j, VISCOSITY_NONE, visc_factor, rate);
            }
            for (int i = 0; i < g->nx; i++) m = rate[i] > m ? rate[i] : m;
        }
        rmax = m > rmax ? m : rmax;
    }
    return rmax > 0.0 ? s->cfg.cfl / rmax : (double)INFINITY;
}

/* Pointers to cell (i, j) of the four fields, in the given component order. */
static void row_ptrs(const Grid *g, double *const w[4], const int perm[4], int i, int j,
                     const double *out[4]) {
    const int64_t k = grid_index(g, i, j);
    for (int v = 0; v < 4; v++) out[v] = w[perm[v]] + k;
}

/* Slopes along x and y of the cells -1 .. nx of row j into sx[v], sy[v]
 * (cell i at offset GRID_NG + i). */
static int64_t row_slopes(const FlowSolver *s, int j, double *const sx[4], double *const sy[4]) {
    const Grid *g = &s->grid;
    static const int id[4] = {0, 1, 2, 3};
    const int n = g->nx + 2, i0 = -1;
    const double *wc[4], *wm[4], *wp[4];
    row_ptrs(g, s->w, id, i0, j, wc);
    row_ptrs(g, s->w, id, i0, j - 1, wm);
    row_ptrs(g, s->w, id, i0, j + 1, wp);
    double *ox[4], *oy[4];
    for (int v = 0; v < 4; v++) {
        ox[v] = sx[v] + GRID_NG + i0;
        oy[v] = sy[v] + GRID_NG + i0;
    }
    const uint8_t *kc = s->kind + grid_index(g, i0, j);
    const uint8_t *km = s->kind + grid_index(g, i0, j - 1);
    const uint8_t *kp = s->kind + grid_index(g, i0, j + 1);
    const GridAxis *ax = &s->grid.ax[0], *ay = &s->grid.ax[1];
    int64_t nb = recon_slopes_x(n, s->cfg.limiter, wc, kc, ax->inv_dl + i0, ax->inv_dr + i0,
                                s->half_w[0] + GRID_NG + i0, ox);
    nb += recon_slopes_y(n, s->cfg.limiter, wm, wc, wp, km, kc, kp, ay->inv_dl[j], ay->inv_dr[j],
                         0.5 * ay->width[j], oy);
    return nb;
}

/* The solver's arrays as the ghost-face kernel reads them. */
static GksGhostFaces ghost_faces(const FlowSolver *s) {
    return (GksGhostFaces){.kind = s->kind,
                           .wall_slot = s->wall_slot,
                           .wall_u = s->wall_u,
                           .wall_v = s->wall_v,
                           .w = {s->w[0], s->w[1], s->w[2], s->w[3]},
                           .gamma = s->gas.gamma};
}

/* y-face fluxes between rows j and j+1 (cells 0 .. nx-1) into g[v]. */
static void row_yflux(const FlowSolver *s, int j, double *const sxl[4], double *const syl[4],
                      double *const sxr[4], double *const syr[4], double dt,
                      double *const gout[4]) {
    const Grid *g = &s->grid;
    static const int sw[4] = {0, 2, 1, 3}; /* normal frame: (rho, rho v, rho u, rho E) */
    GksRowSide L, R;
    row_ptrs(g, s->w, sw, 0, j, L.w);
    row_ptrs(g, s->w, sw, 0, j + 1, R.w);
    for (int v = 0; v < 4; v++) {
        L.sn[v] = syl[sw[v]] + GRID_NG;
        L.st[v] = sxl[sw[v]] + GRID_NG;
        R.sn[v] = syr[sw[v]] + GRID_NG;
        R.st[v] = sxr[sw[v]] + GRID_NG;
    }
    L.kind = s->kind + grid_index(g, 0, j);
    R.kind = s->kind + grid_index(g, 0, j + 1);
    double *f[4] = {gout[0], gout[2], gout[1], gout[3]};
    const GridAxis *ay = &g->ax[1];
    gks_flux_row_y(g->nx, &L, &R, 0.5 * ay->width[j], 0.5 * ay->width[j + 1], dt, &s->gas, f);
    const uint8_t *wall = j == -1          ? s->wall[FLOW_FACE_YLO]
                          : j == g->ny - 1 ? s->wall[FLOW_FACE_YHI]
                                           : NULL;
    if (wall)
        for (int i = 0; i < g->nx; i++) {
            if (wall[i] & WALL_MASS) gout[0][i] = 0.0;
            if (wall[i] & WALL_ENERGY) gout[3][i] = 0.0;
        }
    if (s->wall_slot) {
        const GksGhostFaces gf = ghost_faces(s);
        const int64_t bl = grid_index(g, 0, j), br = grid_index(g, 0, j + 1);
        for (int i = 0; i < g->nx; i++) gks_ghost_face(&gf, bl + i, br + i, 1, dt, gout, i);
    }
}

/* x-face fluxes of row j: face i (i = 0 .. nx) between cells i-1 and i. */
static void row_xflux(const FlowSolver *s, int j, double *const sx[4], double *const sy[4],
                      double dt, double *const fout[4]) {
    const Grid *g = &s->grid;
    static const int id[4] = {0, 1, 2, 3};
    GksRowSide L, R;
    row_ptrs(g, s->w, id, -1, j, L.w);
    row_ptrs(g, s->w, id, 0, j, R.w);
    for (int v = 0; v < 4; v++) {
        L.sn[v] = sx[v] + GRID_NG - 1;
        L.st[v] = sy[v] + GRID_NG - 1;
        R.sn[v] = sx[v] + GRID_NG;
        R.st[v] = sy[v] + GRID_NG;
    }
    L.kind = s->kind + grid_index(g, -1, j);
    R.kind = s->kind + grid_index(g, 0, j);
    const double *hw = s->half_w[0] + GRID_NG;
    gks_flux_row_x(g->nx + 1, &L, &R, hw - 1, hw, g->ax[0].inv_dl, dt, &s->gas, fout);
    const uint8_t wlo = s->wall[FLOW_FACE_XLO][j], whi = s->wall[FLOW_FACE_XHI][j];
    if (wlo & WALL_MASS) fout[0][0] = 0.0;
    if (wlo & WALL_ENERGY) fout[3][0] = 0.0;
    if (whi & WALL_MASS) fout[0][g->nx] = 0.0;
    if (whi & WALL_ENERGY) fout[3][g->nx] = 0.0;
    if (s->wall_slot) {
        const GksGhostFaces gf = ghost_faces(s);
        const int64_t b = grid_index(g, 0, j);
        for (int i = 0; i <= g->nx; i++) gks_ghost_face(&gf, b + i - 1, b + i, 0, dt, fout, i);
    }
}

/* Wn of row j (gks_update_cell per cell); returns non-zero if a fluid cell
 * is not physical. */
static int row_update(FlowSolver *s, int j, double *const fx[4], double *const gb[4],
                      double *const gt[4]) {
    const Grid *g = &s->grid;
    const int64_t base = grid_index(g, 0, j);
    const double idy = g->ax[1].inv_width[j];
    const double *restrict idx = g->ax[0].inv_width;
    const uint8_t *restrict kd = s->kind + base;
    double *restrict n0 = s->wn[0] + base, *restrict n1 = s->wn[1] + base,
                     *restrict n2 = s->wn[2] + base, *restrict n3 = s->wn[3] + base;
    const double *restrict o0 = s->w[0] + base, *restrict o1 = s->w[1] + base,
                           *restrict o2 = s->w[2] + base, *restrict o3 = s->w[3] + base;
    const double *restrict f0 = fx[0], *restrict f1 = fx[1], *restrict f2 = fx[2],
                           *restrict f3 = fx[3];
    const double *restrict b0 = gb[0], *restrict b1 = gb[1], *restrict b2 = gb[2],
                           *restrict b3 = gb[3];
    const double *restrict t0 = gt[0], *restrict t1 = gt[1], *restrict t2 = gt[2],
                           *restrict t3 = gt[3];
    int bad = 0;
#pragma GCC ivdep
    for (int i = 0; i < g->nx; i++) {
        const double w[4] = {o0[i], o1[i], o2[i], o3[i]};
        const double fx2[2][4] = {{f0[i], f1[i], f2[i], f3[i]},
                                  {f0[i + 1], f1[i + 1], f2[i + 1], f3[i + 1]}};
        const double gy2[2][4] = {{b0[i], b1[i], b2[i], b3[i]}, {t0[i], t1[i], t2[i], t3[i]}};
        double wn[4];
        bad |= gks_update_cell(kd[i], w, fx2, gy2, idx[i], idy, wn);
        n0[i] = wn[0];
        n1[i] = wn[1];
        n2[i] = wn[2];
        n3[i] = wn[3];
    }
    return bad;
}

static void step_block(FlowSolver *s, FlowWork *wk, int j0, int j1, double dt) {
    const int ny = s->grid.ny;
    int cur = 0;
    int64_t nb = 0;
    /* slopes of rows j0-1 and j0; fallbacks counted for owned rows only */
    int64_t c = row_slopes(s, j0 - 1, wk->sx[1], wk->sy[1]);
    if (j0 == 0) nb += c;
    nb += row_slopes(s, j0, wk->sx[0], wk->sy[0]);
    row_yflux(s, j0 - 1, wk->sx[1], wk->sy[1], wk->sx[0], wk->sy[0], dt, wk->gy[0]);
    int gbot = 0;
    for (int j = j0; j < j1; j++) {
        const int nxt = 1 - cur;
        c = row_slopes(s, j + 1, wk->sx[nxt], wk->sy[nxt]);
        if (j + 1 < j1 || j + 1 == ny) nb += c;
        row_xflux(s, j, wk->sx[cur], wk->sy[cur], dt, wk->fx);
        row_yflux(s, j, wk->sx[cur], wk->sy[cur], wk->sx[nxt], wk->sy[nxt], dt, wk->gy[1 - gbot]);
        wk->bad |= row_update(s, j, wk->fx, wk->gy[gbot], wk->gy[1 - gbot]);
        gbot = 1 - gbot;
        cur = nxt;
    }
    wk->fallbacks = nb;
}

static int report_bad_cell(const FlowSolver *s) {
    const Grid *g = &s->grid;
    const double gm1 = s->gas.gamma - 1.0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (s->kind[k] != FLOW_CELL_FLUID) continue;
            const double r = s->w[0][k], mx = s->w[1][k], my = s->w[2][k], e = s->w[3][k];
            const double p = gm1 * (e - 0.5 * (mx * mx + my * my) / r);
            if (!(r > 0.0) || !(p > 0.0) || !(2.0 * r * e - mx * mx - my * my > 0.0))
                return NSPD_FAIL(NSPD_ERR_NUMERIC,
                                 "flow: non-physical state at step %lld, t = %.6g s, in cell (%d, "
                                 "%d) at (%.6g, %.6g) m: rho = %.6g kg/m^3, p = %.6g Pa",
                                 (long long)s->steps, s->time, i, j, g->ax[0].center[i],
                                 g->ax[1].center[j], r, p);
        }
    return NSPD_FAIL(NSPD_ERR_NUMERIC, "flow: non-physical state at step %lld",
                     (long long)s->steps);
}

int flow_solver_step(FlowSolver *s, double dt) {
    if (!(dt > 0.0) || !isfinite(dt))
        return NSPD_FAIL(NSPD_ERR_NUMERIC, "flow: time step %g at step %lld is not positive", dt,
                         (long long)s->steps);
    flow_solver_fill_boundaries(s);
    if (s->hook) s->hook(s->hook_ctx, s);
    int nt = omp_get_max_threads();
    nt = nt > s->nthreads ? s->nthreads : nt;
    const int ny = s->grid.ny;
    nt = nt > ny ? ny : nt;
    if ((int64_t)s->grid.nx * ny < PARALLEL_MIN_CELLS) nt = 1;
#pragma omp parallel num_threads(nt)
    {
        const int t = omp_get_thread_num(), n = omp_get_num_threads();
        FlowWork *wk = &s->work[t];
        wk->bad = 0;
        wk->fallbacks = 0;
        step_block(s, wk, (int)((int64_t)ny * t / n), (int)((int64_t)ny * (t + 1) / n), dt);
    }
    int bad = 0;
    int64_t nb = 0;
    for (int t = 0; t < nt; t++) {
        bad |= s->work[t].bad;
        nb += s->work[t].fallbacks;
    }
    for (int v = 0; v < 4; v++) {
        double *tmp = s->w[v];
        s->w[v] = s->wn[v];
        s->wn[v] = tmp;
    }
    s->steps++;
    s->time += dt;
    s->fallbacks_last = nb;
    s->fallbacks_total += nb;
    if (bad) return report_bad_cell(s);
    return NSPD_OK;
}

int flow_solver_advance(FlowSolver *s, double t_end, int64_t max_steps) {
    int64_t n = 0;
    while (s->time < t_end && (max_steps <= 0 || n < max_steps)) {
        double dt = flow_solver_stable_dt(s);
        /* land on t_end without a sliver of a last step */
        if (s->time + dt >= t_end)
            dt = t_end - s->time;
        else if (s->time + 1.5 * dt > t_end)
            dt = 0.5 * (t_end - s->time);
        TRY(flow_solver_step(s, dt));
        n++;
        if (t_end - s->time < 1e-14 * fabs(t_end)) s->time = t_end;
    }
    return NSPD_OK;
}

/* ---------------------------------------------------------- diagnostics */

void flow_solver_primitive(const FlowSolver *s, FlowField field, double *out) {
    const Grid *g = &s->grid;
    const double gamma = s->gas.gamma, R = s->gas.R;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
#pragma omp parallel for schedule(static) if (big)
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            const double w[4] = {s->w[0][k], s->w[1][k], s->w[2][k], s->w[3][k]};
            FlowPrim q;
            flow_cons_to_prim(w, gamma, &q);
            double v;
            switch (field) {
            case FLOW_DENSITY:
                v = q.rho;
                break;
            case FLOW_VELOCITY_X:
                v = q.u;
                break;
            case FLOW_VELOCITY_Y:
                v = q.v;
                break;
            case FLOW_PRESSURE:
                v = q.p;
                break;
            case FLOW_TEMPERATURE:
                v = q.p / (R * q.rho);
                break;
            case FLOW_MACH:
                v = sqrt((q.u * q.u + q.v * q.v) * q.rho / (gamma * q.p));
                break;
            default:
                v = 0.0;
            }
            out[(int64_t)j * g->nx + i] = v;
        }
}

/* Deterministic at any thread count: each row is summed in index order by one
 * thread, then the row sums in row order. */
void flow_solver_totals(const FlowSolver *s, double totals[4]) {
    const Grid *g = &s->grid;
    double *rs = s->row_sums;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
#pragma omp parallel for schedule(static) if (big)
    for (int j = 0; j < g->ny; j++) {
        double acc[4] = {0.0, 0.0, 0.0, 0.0};
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (s->kind[k] != FLOW_CELL_FLUID) continue;
            const double vol = g->ax[0].width[i] * g->ax[1].width[j];
            for (int v = 0; v < 4; v++) acc[v] += s->w[v][k] * vol;
        }
        for (int v = 0; v < 4; v++) rs[4 * j + v] = acc[v];
    }
    for (int v = 0; v < 4; v++) totals[v] = 0.0;
    for (int j = 0; j < g->ny; j++)
        for (int v = 0; v < 4; v++) totals[v] += rs[4 * j + v];
}

void flow_isentropic_vortex(void *ctx, double x, double y, FlowPrim *out) {
    const FlowVortex *vx = ctx;
    double dx = x - vx->x0, dy = y - vx->y0;
    if (vx->period_x > 0.0) dx -= vx->period_x * round(dx / vx->period_x);
    if (vx->period_y > 0.0) dy -= vx->period_y * round(dy / vx->period_y);
    const double r2 = dx * dx + dy * dy, g = vx->gamma, eps = vx->strength;
    const double f = exp(0.5 * (1.0 - r2)) * eps / (2.0 * M_PI);
    /* The formula is in units of the free stream (R T_inf = p_inf/rho_inf = 1,
     * velocities per sqrt(R T_inf)); scale back. */
    const double T_inf = vx->p_inf / vx->rho_inf;
    const double Tr = 1.0 - (g - 1.0) * eps * eps / (8.0 * g * M_PI * M_PI) * exp(1.0 - r2);
    const double scale = sqrt(T_inf);
    out->u = vx->u_inf - f * dy * scale;
    out->v = vx->v_inf + f * dx * scale;
    out->rho = vx->rho_inf * pow(Tr, 1.0 / (g - 1.0));
    out->p = vx->p_inf * pow(Tr, g / (g - 1.0));
}

/* ------------------------------------------------------------ benchmark */

int flow_bench(int cells, int threads, int steps, FlowBenchResult *out) {
    memset(out, 0, sizeof *out);
    if (cells < 16 || threads < 1 || steps < 1)
        return NSPD_FAIL(NSPD_ERR_INPUT, "flow_bench: cells >= 16, threads >= 1, steps >= 1");
    const int n = (int)lround(sqrt((double)cells));
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    FlowConfig c;
    flow_config_default(&c);
    flow_config_uniform_grid(&c, 0.0, 1.0, n, 0.0, 1.0, n);
    FlowBc per = {.kind = BC_PERIODIC};
    for (int f = 0; f < 4; f++) flow_config_set_bc(&c, f, &per);
    c.viscosity = VISCOSITY_SUTHERLAND;
    c.mu_ref = 1.716e-5 * 1000.0; /* Re = rho U L / mu ~ 1e3 on the unit box */
    c.T_ref = 273.15;
    c.sutherland_S = 110.4;
    c.init_fn = NULL;
    c.initial = (FlowPrim){1.2, 0.0, 0.0, 1.0e5};
    FlowSolver *s = NULL;
    int st = flow_solver_create(&s, &c);
    if (st < 0) {
        omp_set_num_threads(saved);
        return st;
    }
    /* Taylor-Green vortices at Mach 0.3 */
    const Grid *g = flow_solver_grid(s);
    FlowFields f = flow_solver_fields(s);
    const double c0 = sqrt(1.4 * 1.0e5 / 1.2), U = 0.3 * c0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const double x = 2.0 * M_PI * g->ax[0].center[i], y = 2.0 * M_PI * g->ax[1].center[j];
            FlowPrim q = {1.2, U * sin(x) * cos(y), -U * cos(x) * sin(y),
                          1.0e5 + 0.25 * 1.2 * U * U * (cos(2 * x) + cos(2 * y))};
            double w[4];
            flow_prim_to_cons(&q, 1.4, w);
            const int64_t k = grid_index(g, i, j);
            for (int v = 0; v < 4; v++) f.w[v][k] = w[v];
        }
    st = flow_solver_step(s, flow_solver_stable_dt(s));
    const double t0 = nspd_wall_time();
    for (int k = 0; k < steps && st == NSPD_OK; k++)
        st = flow_solver_step(s, flow_solver_stable_dt(s));
    const double secs = nspd_wall_time() - t0;
    out->cells = (int64_t)n * n;
    out->steps = steps;
    out->threads = threads;
    out->seconds = secs;
    out->cell_updates_per_s = secs > 0.0 ? (double)out->cells * steps / secs : 0.0;
    out->bytes_per_cell = (double)s->bytes / (double)out->cells;
    flow_solver_destroy(&s);
    omp_set_num_threads(saved);
    return st;
}
