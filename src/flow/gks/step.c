/* The GKS step of the flow operator (paper 000 Eq. 20): box ghost layers,
 * stable time step, and per row limited slopes, face fluxes and the update.
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
#include "flow/gks/solver.h"

#include "core/kernel.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/gks/solver_internal.h"
#include "flow/gks/flux.h"
#include "flow/gks/update_kernel.h"
#include "flow/gks/recon.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>

/* The neighbours' rows into a slab's ghost rows (solver.h): the first
 * GRID_NG rows go down into the ghost rows above the slab below, the last
 * GRID_NG up; whole rows, x ghosts included, so corners come along. */
static int exchange_rows_begin(GksSolver *s, CommPending *pending) {
    const Grid *g = &s->grid;
    const int64_t low = grid_index(g, -GRID_NG, 0), high = grid_index(g, -GRID_NG, g->ny - GRID_NG);
    const int64_t under = grid_index(g, -GRID_NG, -GRID_NG), over = grid_index(g, -GRID_NG, g->ny);
    const int64_t count = (int64_t)GRID_NG * g->stride;
    for (int v = 0; v <= 4; v++) {
        const size_t size = v < 4 ? sizeof(double) : 1;
        char *base = v < 4 ? (char *)s->w[v] : (char *)s->kind;
        const int bytes = (int)(count * (int64_t)size);
        /* tags by field and direction: two ranks on a periodic axis are
         * each other's neighbour both ways */
        const int below = s->nbr[FLOW_FACE_YLO], above = s->nbr[FLOW_FACE_YHI];
        TRY(comm_begin_sendrecv(&s->comm, base + low * (int64_t)size, bytes, below,
                                base + over * (int64_t)size, above, 2 * v, pending));
        TRY(comm_begin_sendrecv(&s->comm, base + high * (int64_t)size, bytes, above,
                                base + under * (int64_t)size, below, 2 * v + 1, pending));
    }
    return NSPD_OK;
}

static int exchange_rows(GksSolver *s) {
    CommPending pending = {0};
    TRY(exchange_rows_begin(s, &pending));
    return comm_finish(&s->comm, &pending);
}

/* The x halo (2D process grids): the first GRID_NG columns of the
 * interior rows go to the left neighbour's ghost columns, the last to the
 * right's; the four fields and the kinds packed into one message each way. */
static void exchange_columns(GksSolver *s) {
    const Grid *g = &s->grid;
    const int ny = g->ny, per = 5 * GRID_NG * ny; /* values a message */
    double *send_lo = s->halo_x, *send_hi = send_lo + per, *recv_lo = send_hi + per,
           *recv_hi = recv_lo + per;
    /* side 0: columns 0 .. NG-1 out, -NG .. -1 in; side 1: nx-NG .. nx-1
     * out, nx .. nx+NG-1 in */
    for (int side = 0; side < 2; side++) {
        double *out = side ? send_hi : send_lo;
        const int i0 = side ? g->nx - GRID_NG : 0;
        for (int j = 0; j < ny; j++)
            for (int c = 0; c < GRID_NG; c++) {
                const int64_t k = grid_index(g, i0 + c, j);
                double *o = out + 5 * (j * GRID_NG + c);
                for (int v = 0; v < 4; v++) o[v] = s->w[v][k];
                o[4] = s->kind[k];
            }
    }
    const int left = s->nbr[FLOW_FACE_XLO], right = s->nbr[FLOW_FACE_XHI];
    const int bytes = per * (int)sizeof(double);
    CommPending pending = {0};
    /* tags after the rows' (0 .. 9); a failed exchange is MPI's abort */
    (void)comm_begin_sendrecv(&s->comm, send_lo, bytes, left, recv_hi, right, 10, &pending);
    (void)comm_begin_sendrecv(&s->comm, send_hi, bytes, right, recv_lo, left, 11, &pending);
    (void)comm_finish(&s->comm, &pending);
    for (int side = 0; side < 2; side++) {
        if (s->nbr[side ? FLOW_FACE_XHI : FLOW_FACE_XLO] < 0) continue;
        const double *in = side ? recv_hi : recv_lo;
        const int i0 = side ? g->nx : -GRID_NG;
        for (int j = 0; j < ny; j++)
            for (int c = 0; c < GRID_NG; c++) {
                const int64_t k = grid_index(g, i0 + c, j);
                const double *o = in + 5 * (j * GRID_NG + c);
                for (int v = 0; v < 4; v++) s->w[v][k] = o[v];
                s->kind[k] = (uint8_t)o[4];
            }
    }
}

/* The box faces' conditions this block fills; on a 2D process grid the x
 * faces first, then the x halo, then the y faces over every column (the
 * order of one process's fill: x faces for the interior rows, then y faces
 * over every column, so the corners see the x halo). */
static void fill_box(GksSolver *s) {
    if (s->dims[0] == 1) {
        bc_fill_faces(&s->grid, s->cfg.bc, &s->gas, s->w, s->kind, s->bc_faces);
        return;
    }
    const unsigned x_faces = 1u << FLOW_FACE_XLO | 1u << FLOW_FACE_XHI;
    bc_fill_faces(&s->grid, s->cfg.bc, &s->gas, s->w, s->kind, s->bc_faces & x_faces);
    const double t0 = nspd_wall_time();
    exchange_columns(s);
    s->comm_seconds += nspd_wall_time() - t0;
    bc_fill_faces(&s->grid, s->cfg.bc, &s->gas, s->w, s->kind, s->bc_faces & ~x_faces);
}

void gks_solver_fill_boundaries(GksSolver *s) {
    fill_box(s);
    /* a failed exchange is MPI's abort, not a recoverable status */
    if (comm_distributed(&s->comm)) {
        const double t0 = nspd_wall_time();
        (void)exchange_rows(s);
        s->comm_seconds += nspd_wall_time() - t0;
    }
}

/* The signal-speed rate of one state (1/s): the inviscid rates
 * (|u| + c)/dx + (|v| + c)/dy and the viscous nu (1/dx^2 + 1/dy^2). */
static inline __attribute__((always_inline)) double
signal_rate(const GksParams *gas, ViscosityLaw law, double visc_factor, double gamma, double iR,
            double ir, double u, double v, double p, double idx, double idy) {
    const double c = sqrt(gamma * p * ir);
    const double nu = visc_factor * gks_viscosity(gas, p * ir * iR, law) * ir;
    return (fabs(u) + c) * idx + (fabs(v) + c) * idy + nu * (idx * idx + idy * idy);
}

/* Signal-speed rate of each cell of row j into rate[0..nx) (whatever the
 * cell's kind: the caller takes the fluid cells' maximum); the law is a
 * constant in each instantiation so the loop vectorises. */
static inline __attribute__((always_inline)) void
dt_rates(const GksSolver *s, int j, ViscosityLaw law, double visc_factor, double *rate) {
    const Grid *g = &s->grid;
    const GksParams gas = s->gas;
    const double gamma = gas.gamma, gm1 = gamma - 1.0, iR = 1.0 / gas.R;
    const double idy = g->ax[1].inv_width[j];
    const int64_t base = grid_index(g, 0, j);
    const double *restrict r = s->w[0] + base, *restrict mx = s->w[1] + base,
                           *restrict my = s->w[2] + base, *restrict e = s->w[3] + base;
    const double *restrict idx = g->ax[0].inv_width;
    double *restrict out = rate;
    NSPD_IVDEP /* vectorised: tests/unit/core/vectorised.sh */
        for (int i = 0; i < g->nx; i++) {
        const double ir = 1.0 / r[i], u = mx[i] * ir, v = my[i] * ir;
        const double p = gm1 * (e[i] - 0.5 * (mx[i] * u + my[i] * v));
        out[i] = signal_rate(&gas, law, visc_factor, gamma, iR, ir, u, v, p, idx[i], idy);
    }
}

double gks_visc_factor(const GksParams *gas) {
    return gas->law == VISCOSITY_NONE ? 0.0 : 2.0 * fmax(4.0 / 3.0, gas->gamma / gas->prandtl);
}

double gks_signal_rate(const GksParams *gas, ViscosityLaw law, double visc_factor,
                       const FlowPrim *state, double idx, double idy) {
    return signal_rate(gas, law, visc_factor, gas->gamma, 1.0 / gas->R, 1.0 / state->rho, state->u,
                       state->v, state->p, idx, idy);
}

/* Threads for a team: OpenMP's current maximum, at most the work spaces
 * allocated at creation. */
static int team_size(const GksSolver *s) {
    const int nt = omp_get_max_threads();
    return nt > s->nthreads ? s->nthreads : nt;
}

double gks_solver_stable_dt(const GksSolver *s) {
    const Grid *g = &s->grid;
    const ViscosityLaw law = s->gas.law;
    const double visc_factor = gks_visc_factor(&s->gas);
    double rmax = 0.0;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
#pragma omp parallel num_threads(team_size(s)) if (big) reduction(max : rmax)
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
            /* only fluid cells limit the step: their maximum, in a pass of its
             * own, since the kinds (bytes) in the loop above kept GCC from
             * vectorising it (as in flux.c's row loop) */
            const uint8_t *restrict kd = s->kind + grid_index(g, 0, j);
            for (int i = 0; i < g->nx; i++)
                if (kd[i] == FLOW_CELL_FLUID && rate[i] > m) m = rate[i];
        }
        rmax = m > rmax ? m : rmax;
    }
    if (comm_distributed(&s->comm)) { /* a max is exact: the same bits on any ranks */
        const double t0 = nspd_wall_time();
        rmax = comm_max(&s->comm, rmax);
        ((GksSolver *)s)->comm_seconds += nspd_wall_time() - t0;
    }
    return rmax > 0.0 ? s->cfg.cfl / rmax : (double)INFINITY;
}

/* Pointers to cell (i, j) of the four fields, in the given component order. */
static void row_ptrs(const Grid *g, double *const w[4], const int perm[4], int i, int j,
                     const double *out[4]) {
    const int64_t k = grid_index(g, i, j);
    for (int v = 0; v < 4; v++) out[v] = w[perm[v]] + k;
}

/* Slopes along x and y of the cells i0 .. i0 + n - 1 of row j into sx[v],
 * sy[v] (cell i at offset GRID_NG + i); the fallbacks among them. */
static int64_t slopes_of(const GksSolver *s, int j, int i0, int n, double *const sx[4],
                         double *const sy[4]) {
    const Grid *g = &s->grid;
    static const int id[4] = {0, 1, 2, 3};
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

/* Slopes of the cells -1 .. nx of row j; the fallbacks counted in the
 * block's own cells and in the whole grid's ghost columns (a block's edge
 * columns inside the whole grid are its neighbours' to count: recomputed
 * alone, the same values, for their count). */
static int64_t row_slopes(const GksSolver *s, int j, double *const sx[4], double *const sy[4]) {
    const int nx = s->grid.nx;
    int64_t nb = slopes_of(s, j, -1, nx + 2, sx, sy);
    if (s->coord[0] > 0) nb -= slopes_of(s, j, -1, 1, sx, sy);
    if (s->coord[0] < s->dims[0] - 1) nb -= slopes_of(s, j, nx, 1, sx, sy);
    return nb;
}

/* The solver's arrays as the ghost-face kernel reads them. */
static GksGhostFaces ghost_faces(const GksSolver *s) {
    return (GksGhostFaces){.kind = s->kind,
                           .wall_slot = s->wall_slot,
                           .wall_u = s->wall_u,
                           .wall_v = s->wall_v,
                           .seal_slot = s->seal_slot,
                           .seal_u = s->seal_u,
                           .seal_v = s->seal_v,
                           .w = {s->w[0], s->w[1], s->w[2], s->w[3]},
                           .gamma = s->gas.gamma};
}

/* y-face fluxes between rows j and j+1 (cells 0 .. nx-1) into g[v]. */
static void row_yflux(const GksSolver *s, int j, double *const sxl[4], double *const syl[4],
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
    if (s->seals > 0) {
        const GksGhostFaces gf = ghost_faces(s);
        const int64_t bl = grid_index(g, 0, j), br = grid_index(g, 0, j + 1);
        for (int i = 0; i < g->nx; i++) gks_seal_face(&gf, bl + i, br + i, 1, dt, gout, i);
    }
}

/* x-face fluxes of row j: face i (i = 0 .. nx) between cells i-1 and i. */
static void row_xflux(const GksSolver *s, int j, double *const sx[4], double *const sy[4],
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
    if (s->seals > 0) {
        const GksGhostFaces gf = ghost_faces(s);
        const int64_t b = grid_index(g, 0, j);
        for (int i = 0; i <= g->nx; i++) gks_seal_face(&gf, b + i - 1, b + i, 0, dt, fout, i);
    }
}

/* Wn of row j (gks_update_cell per cell); returns non-zero if a fluid cell
 * is not physical. */
static int row_update(GksSolver *s, int j, double *const fx[4], double *const gb[4],
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
    NSPD_IVDEP
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

static void step_block(GksSolver *s, FlowWork *wk, int j0, int j1, double dt) {
    const int ny = s->grid.ny;
    int cur = 0;
    int64_t nb = 0;
    /* slopes of rows j0-1 and j0; fallbacks counted for owned rows only,
     * and the whole grid's ghost rows by the block at its end */
    const bool first_slab = s->coord[1] == 0, last_slab = s->coord[1] == s->dims[1] - 1;
    int64_t c = row_slopes(s, j0 - 1, wk->sx[1], wk->sy[1]);
    if (j0 == 0 && first_slab) nb += c;
    nb += row_slopes(s, j0, wk->sx[0], wk->sy[0]);
    row_yflux(s, j0 - 1, wk->sx[1], wk->sy[1], wk->sx[0], wk->sy[0], dt, wk->gy[0]);
    int gbot = 0;
    for (int j = j0; j < j1; j++) {
        const int nxt = 1 - cur;
        c = row_slopes(s, j + 1, wk->sx[nxt], wk->sy[nxt]);
        if (j + 1 < j1 || (j + 1 == ny && last_slab)) nb += c;
        row_xflux(s, j, wk->sx[cur], wk->sy[cur], dt, wk->fx);
        row_yflux(s, j, wk->sx[cur], wk->sy[cur], wk->sx[nxt], wk->sy[nxt], dt, wk->gy[1 - gbot]);
        wk->bad |= row_update(s, j, wk->fx, wk->gy[gbot], wk->gy[1 - gbot]);
        gbot = 1 - gbot;
        cur = nxt;
    }
    wk->fallbacks = nb;
}

/* The first non-physical fluid cell of the block in row-major order, as
 * its index in the whole grid (j nx + i), or INT64_MAX. */
static int64_t first_bad_cell(const GksSolver *s) {
    const Grid *g = &s->grid;
    const double gm1 = s->gas.gamma - 1.0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (s->kind[k] != FLOW_CELL_FLUID) continue;
            const double r = s->w[0][k], mx = s->w[1][k], my = s->w[2][k], e = s->w[3][k];
            const double p = gm1 * (e - 0.5 * (mx * mx + my * my) / r);
            if (!(r > 0.0) || !(p > 0.0) || !(2.0 * r * e - mx * mx - my * my > 0.0))
                return (int64_t)(s->first[1] + j) * gks_solver_whole_grid(s)->nx + s->first[0] + i;
        }
    return INT64_MAX;
}

/* The message names the first bad cell of the whole grid; the process
 * that holds it writes it with the cell's numbers and sends it to the
 * others, so every process fails with the same words as one process. */
static int report_bad_cell(const GksSolver *s, int64_t first) {
    const Grid *g = &s->grid;
    if (first == INT64_MAX)
        return NSPD_FAIL(NSPD_ERR_NUMERIC, "flow: non-physical state at step %lld",
                         (long long)s->steps);
    const int64_t nx = gks_solver_whole_grid(s)->nx;
    const int col = (int)(first % nx), row = (int)(first / nx);
    const int i = col - s->first[0], j = row - s->first[1];
    const int owner = gks_solver_cell_owner(s, col, row);
    char text[512] = "";
    if (owner == s->comm.rank) {
        const int64_t k = grid_index(g, i, j);
        const double gm1 = s->gas.gamma - 1.0, r = s->w[0][k], mx = s->w[1][k], my = s->w[2][k];
        const double p = gm1 * (s->w[3][k] - 0.5 * (mx * mx + my * my) / r);
        snprintf(text, sizeof text,
                 "flow: non-physical state at step %lld, t = %.6g s, in cell (%d, %d) at "
                 "(%.6g, %.6g) m: rho = %.6g kg/m^3, p = %.6g Pa",
                 (long long)s->steps, s->time, col, row, g->ax[0].center[i], g->ax[1].center[j], r,
                 p);
    }
    (void)comm_bcast(&s->comm, text, (int)sizeof text, owner);
    return NSPD_FAIL(NSPD_ERR_NUMERIC, "%s", text);
}

/* dt times the volume sources into the new state of the fluid cells: each
 * cell on its own, so any thread count gives the same bits. */
static void add_sources(GksSolver *s, double dt) {
    const Grid *g = &s->grid;
    const int64_t n = (int64_t)g->nx * g->ny;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_CELLS)
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t c = grid_index(g, i, j);
            if (s->kind[c] != FLOW_CELL_FLUID) continue;
            for (int k = 0; k < 3; k++) s->wn[k + 1][c] += dt * s->source[k][c];
        }
}

/* Rows [j0, j1) of the step on the thread team, their failures and
 * fallbacks added to *bad and *nb. Each face's flux is its own, so any
 * division of the rows gives the same bits: the threads' shares follow
 * their measured times (balance; NULL: equal shares), which also evens
 * out rows that cost more (a body's ghost cells, fallbacks). */
static void step_rows(GksSolver *s, int j0, int j1, double dt, Balance *balance, int *bad,
                      int64_t *nb) {
    const int rows = j1 - j0;
    if (rows <= 0) return;
    int nt = team_size(s);
    nt = nt > rows ? rows : nt;
    if ((int64_t)s->grid.nx * rows < PARALLEL_MIN_CELLS) nt = 1;
#pragma omp parallel num_threads(nt)
    {
        FlowWork *wk = &s->work[omp_get_thread_num()];
        wk->bad = 0;
        wk->fallbacks = 0;
        int64_t lo, hi;
        const double started = balance_begin(balance, rows, &lo, &hi);
        /* no empty block: each block counts its first rows' fallbacks */
        if (hi > lo) step_block(s, wk, j0 + (int)lo, j0 + (int)hi, dt);
        balance_end(balance, started);
    }
    balance_update(balance);
    for (int t = 0; t < nt; t++) {
        *bad |= s->work[t].bad;
        *nb += s->work[t].fallbacks;
    }
}

/* Whether the halo exchange overlaps the rows that do not read it: on
 * several processes, with rows beyond the two edges' GRID_NG each, and not
 * where a ghost hook on a periodic y axis would read rank 0's wrapped
 * ghost rows before they arrive. */
static bool overlapped(const GksSolver *s) {
    return comm_distributed(&s->comm) && s->grid.ny > 2 * GRID_NG &&
           !(s->hook && s->grid.ax[1].periodic);
}

int gks_solver_step(GksSolver *s, double dt) {
    if (!(dt > 0.0) || !isfinite(dt))
        return NSPD_FAIL(NSPD_ERR_NUMERIC, "flow: time step %g at step %lld is not positive", dt,
                         (long long)s->steps);
    const int ny = s->grid.ny;
    int bad = 0;
    int64_t nb = 0;
    if (overlapped(s)) {
        /* the box faces and the ghost cells first (the hook fetches what it
         * reads from the processes that hold it, and fills the halo's
         * ghosts as they will arrive), then the halo rows begun, the rows
         * that do not read them stepped, the halo awaited, the edge rows
         * stepped */
        fill_box(s);
        if (s->hook) s->hook(s->hook_ctx, s);
        CommPending pending = {0};
        double t0 = nspd_wall_time();
        (void)exchange_rows_begin(s, &pending); /* a failed exchange is MPI's abort */
        s->comm_seconds += nspd_wall_time() - t0;
        step_rows(s, GRID_NG, ny - GRID_NG, dt, &s->row_balance, &bad, &nb);
        t0 = nspd_wall_time();
        (void)comm_finish(&s->comm, &pending);
        s->comm_seconds += nspd_wall_time() - t0;
        step_rows(s, 0, GRID_NG, dt, NULL, &bad, &nb);
        step_rows(s, ny - GRID_NG, ny, dt, NULL, &bad, &nb);
    } else {
        gks_solver_fill_boundaries(s);
        if (s->hook) s->hook(s->hook_ctx, s);
        step_rows(s, 0, ny, dt, &s->row_balance, &bad, &nb);
    }
    if (s->has_sources) add_sources(s, dt);
    if (comm_distributed(&s->comm)) { /* integers: exact on any ranks */
        const double t0 = nspd_wall_time();
        nb = comm_sum_i64(&s->comm, nb);
        bad = (int)comm_max_i64(&s->comm, bad);
        s->comm_seconds += nspd_wall_time() - t0;
    }
    for (int v = 0; v < 4; v++) {
        double *tmp = s->w[v];
        s->w[v] = s->wn[v];
        s->wn[v] = tmp;
    }
    /* The step wrote the interior only: after the swap the box ghost layers
     * would hold the state of two steps back until the next step refills
     * them, and whatever reads the flow between steps (a coupling's surface
     * loads near a box face, probes, a checkpoint) would see that. Refilled
     * here, W is whole after every step; the fill at the start of the next
     * step gives the same values, so the flow's own bits do not change. */
    gks_solver_fill_boundaries(s);
    s->steps++;
    s->time += dt;
    s->fallbacks_last = nb;
    s->fallbacks_total += nb;
    if (bad) return report_bad_cell(s, comm_min_i64(&s->comm, first_bad_cell(s)));
    return NSPD_OK;
}

int gks_solver_advance(GksSolver *s, double t_end, int64_t max_steps) {
    int64_t n = 0;
    while (s->time < t_end && (max_steps <= 0 || n < max_steps)) {
        double dt = gks_solver_stable_dt(s);
        /* land on t_end without a sliver of a last step */
        if (s->time + dt >= t_end)
            dt = t_end - s->time;
        else if (s->time + 1.5 * dt > t_end)
            dt = 0.5 * (t_end - s->time);
        TRY(gks_solver_step(s, dt));
        n++;
        if (t_end - s->time < 1e-14 * fabs(t_end)) s->time = t_end;
    }
    return NSPD_OK;
}
