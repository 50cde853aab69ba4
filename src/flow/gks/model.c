#include "flow/gks/model.h"

#include "core/mem.h"
#include "core/status.h"
#include "flow/flow.h"
#include "flow/gks/transfer.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

void gks_case_config_free(GksCaseConfig *c) {
    for (int i = 0; i < c->region_count; i++) shapeset_free(&c->regions[i].shapes);
    nspd_free(&c->regions);
    c->region_count = 0;
    flow_field_source_free(&c->field);
    c->has_field = false;
}

enum { GKS_SCRATCH = 8 };      /* density, u, v, p, T, Mach, schlieren, speed */
enum { GKS_PIECE_FIELDS = 7 }; /* density, u, v, p, T, Mach, the kinds */

/* The model: the solver, its case and the output scratch (allocated once).
 * On several processes the model shows the whole grid: its cells are
 * numbered as the whole grid's padded arrays, and the output scratch holds
 * the whole grid's fields, gathered on rank 0 (the writer) and absent on
 * the others (NULL); `slab` is this process's part. */
typedef struct {
    GksCaseConfig cfg; /* owned; the vortex and field the initial condition reads live here */
    GksSolver *solver;
    double last_dt;        /* s, of the last step; 0 before the first */
    char process_grid[32]; /* "PXxPY" for the summary (it borrows the text) */
    double mach_scale;     /* the Mach pictures' top (flow_mach_picture_top); 0 until fixed */
    double speed_scale;    /* the speed pictures' top, m/s (flow_speed_picture_top); the same */
    double *cells[GKS_SCRATCH];
    double *kind;   /* cell kinds as a field */
    uint8_t *blank; /* 1: not a fluid cell */
    uint8_t *valid; /* 1: a fluid cell (sampling) */
    double *slab;   /* this process's interior cells (several processes) */
    /* several processes: this block's fields for its piece of the .pvtr
     * (density, u, v, p, T, Mach, the kinds) and every block's cells */
    double *piece[GKS_PIECE_FIELDS];
    int (*piece_cells)[4];
    /* several processes, a volumetric coupling: the whole grid's kinds
     * (padded, as grid_index) and their interior rows as gathered */
    uint8_t *whole_kind, *kind_rows;
    uint8_t *kind_last; /* this block's kinds at the last gather (whole_kinds) */
} GksFlow;

/* The vortex on a periodic box takes its nearest image: its periods are the
 * grid's lengths along the periodic axes. */
static void vortex_periods(GksCaseConfig *fc) {
    GksConfig *c = &fc->solver;
    FlowVortex *vx = &fc->vortex;
    if (c->bc[FLOW_FACE_XLO].seg[0].kind == BC_PERIODIC) {
        GridSegment *s = c->segments[0];
        vx->lo_x = c->x0;
        vx->period_x = 0;
        for (int k = 0; k < c->segment_count[0]; k++) vx->period_x += s[k].length;
    }
    if (c->bc[FLOW_FACE_YLO].seg[0].kind == BC_PERIODIC) {
        GridSegment *s = c->segments[1];
        vx->lo_y = c->y0;
        vx->period_y = 0;
        for (int k = 0; k < c->segment_count[1]; k++) vx->period_y += s[k].length;
    }
}

/* Seconds per cell of the validating build (`nspd check`): 0.17 s for the
 * 1.9e6 cells of cases/cylinder_ma2_re300.yaml, its rigid body included
 * (2 threads, this machine; median of 3), rounded up. */
#define GKS_CHECK_S_PER_CELL 1.0e-7

/* Cells from the grid's segments (no axis built); bytes: the solver's
 * padded state (two copies of four fields and the kinds: 65 per cell with
 * its ghost layers), its row work space (28 rows per thread), and the
 * model's output scratch (74 per interior cell: eight fields, the kinds as
 * a field, two masks). */
static FlowEstimate gks_estimate(const FlowConfig *mc) {
    const GksConfig *c = &((const GksCaseConfig *)mc->model)->solver;
    FlowEstimate e = {0};
    const int nx = grid_segments_spacing(c->segment_count[0], c->segments[0], NULL, 0);
    const int ny = grid_segments_spacing(c->segment_count[1], c->segments[1], NULL, 0);
    if (nx <= 0 || ny <= 0) return e; /* the solver's create says what is wrong */
    e.cells = (double)nx * (double)ny;
    e.items = "cells";
    const double stride = (double)((nx + 2 * GRID_NG + 7) / 8 * 8);
    const double padded = stride * (double)(ny + 2 * GRID_NG);
    e.stored_cells = padded;
    e.bytes = 65.0 * padded + 28.0 * 8.0 * stride * (double)omp_get_max_threads() + 74.0 * e.cells;
    e.check_s = GKS_CHECK_S_PER_CELL * e.cells;
    const GksCaseConfig *fc = mc->model;
    if (!fc->has_vortex && !fc->has_field)
        e.stable_dt = gks_solver_config_stable_dt(c, fc->regions, fc->region_count);
    return e;
}

static int gks_validate(const FlowConfig *mc) {
    return gks_solver_validate(&((const GksCaseConfig *)mc->model)->solver);
}

static void gks_destroy(void *impl) {
    GksFlow *g = impl;
    gks_solver_destroy(&g->solver);
    gks_case_config_free(&g->cfg);
    for (int k = 0; k < GKS_SCRATCH; k++) nspd_free(&g->cells[k]);
    nspd_free(&g->kind);
    nspd_free(&g->blank);
    nspd_free(&g->valid);
    nspd_free(&g->slab);
    for (int k = 0; k < GKS_PIECE_FIELDS; k++) nspd_free(&g->piece[k]);
    nspd_free(&g->piece_cells);
    nspd_free(&g->whole_kind);
    nspd_free(&g->kind_rows);
    nspd_free(&g->kind_last);
    nspd_free(&g);
}

/* The piece's scratch and every block's cells (several processes). */
static int alloc_piece(GksFlow *g) {
    const Grid *slab = gks_solver_grid(g->solver);
    const int size = gks_solver_comm(g->solver)->size;
    for (int k = 0; k < GKS_PIECE_FIELDS; k++)
        TRY(nspd_alloc(&g->piece[k], (size_t)slab->nx * (size_t)slab->ny, sizeof(double)));
    TRY(nspd_alloc(&g->piece_cells, (size_t)size, sizeof *g->piece_cells));
    for (int r = 0; r < size; r++) {
        int first[2], count[2];
        gks_solver_block(g->solver, r, first, count);
        g->piece_cells[r][0] = first[0];
        g->piece_cells[r][1] = first[0] + count[0];
        g->piece_cells[r][2] = first[1];
        g->piece_cells[r][3] = first[1] + count[1];
    }
    return NSPD_OK;
}

static int gks_create(void **impl, FlowConfig *mc) {
    GksFlow *g;
    TRY(nspd_alloc(&g, 1, sizeof *g));
    /* the initial condition needs the vortex at its final address */
    g->cfg = *(GksCaseConfig *)mc->model;
    nspd_free(&mc->model); /* taken */
    GksCaseConfig *fc = &g->cfg;
    GksConfig *c = &fc->solver;
    if (fc->has_vortex) {
        vortex_periods(fc);
        c->init_fn = flow_isentropic_vortex;
        c->init_ctx = &fc->vortex;
    }
    if (fc->has_field) {
        c->init_fn = flow_field_sample;
        c->init_ctx = &fc->field;
    }
    c->comm = mc->comm; /* borrowed during create */
    c->processes[0] = mc->processes[0];
    c->processes[1] = mc->processes[1];
    int status = gks_solver_create(&g->solver, c);
    if (status == NSPD_OK) {
        const int px = gks_solver_process_columns(g->solver);
        snprintf(g->process_grid, sizeof g->process_grid, "%dx%d", px,
                 gks_solver_comm(g->solver)->size / px);
        const Grid *grid = gks_solver_whole_grid(g->solver), *slab = gks_solver_grid(g->solver);
        const size_t n = (size_t)grid->nx * (size_t)grid->ny;
        status = nspd_alloc(&g->slab, (size_t)slab->nx * (size_t)slab->ny, sizeof(double));
        const bool writer = gks_solver_comm(g->solver)->rank == 0;
        const bool pieces = comm_distributed(gks_solver_comm(g->solver));
        /* in pieces the writer's whole grid holds what the pictures draw */
        for (int k = 0; k < GKS_SCRATCH && status == NSPD_OK && writer; k++)
            if (!pieces || k == 0 || k >= 5) status = nspd_alloc(&g->cells[k], n, sizeof(double));
        if (status == NSPD_OK && writer) status = nspd_alloc(&g->kind, n, sizeof(double));
        if (status == NSPD_OK && writer) status = nspd_alloc(&g->blank, n, 1);
        if (status == NSPD_OK && writer) status = nspd_alloc(&g->valid, n, 1);
        if (status == NSPD_OK && comm_distributed(gks_solver_comm(g->solver)))
            status = alloc_piece(g);
    }
    if (status != NSPD_OK) {
        gks_destroy(g);
        return status;
    }
    *impl = g;
    return NSPD_OK;
}

static double gks_stable_dt(const void *impl) {
    return gks_solver_stable_dt(((const GksFlow *)impl)->solver);
}

static int gks_step(void *impl, double dt) {
    GksFlow *g = impl;
    TRY(gks_solver_step(g->solver, dt));
    g->last_dt = dt;
    return NSPD_OK;
}

static double gks_time(const void *impl) {
    return gks_solver_time(((const GksFlow *)impl)->solver);
}

static void gks_config_free(void *model) {
    gks_case_config_free(model);
}

static FlowMesh gks_mesh(const void *impl) {
    (void)impl;
    return (FlowMesh){MESH_GRID};
}

/* The probes' view of the grid (FlowOps.cell_at, grid_line, cell_centre):
 * cells are numbered as the whole grid's padded arrays (grid_index). */
static int gks_cell_at(const void *impl, const char *name, double x, double y, int64_t *cell) {
    const Grid *g = gks_solver_whole_grid(((const GksFlow *)impl)->solver);
    const double at[2] = {x, y};
    for (int d = 0; d < 2; d++)
        if (at[d] < g->ax[d].lo || at[d] > g->ax[d].hi)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "probe '%s': at[%d] = %g is outside the flow grid [%g, %g]; expected "
                             "a point on the grid",
                             name, d, at[d], g->ax[d].lo, g->ax[d].hi);
    *cell = grid_index(g, grid_axis_cell_of(&g->ax[0], x), grid_axis_cell_of(&g->ax[1], y));
    return NSPD_OK;
}

/* The interior indices (i, j) of cell `cell`. */
static void cell_ij(const Grid *g, int64_t cell, int *i, int *j) {
    *j = (int)(cell / g->stride) - GRID_NG;
    *i = (int)(cell % g->stride) - GRID_NG;
}

static int gks_grid_line(const void *impl, int64_t through, int along, int64_t **cells,
                         int64_t *count) {
    const Grid *g = gks_solver_whole_grid(((const GksFlow *)impl)->solver);
    int i, j;
    cell_ij(g, through, &i, &j);
    const int n = g->ax[along].n;
    TRY(nspd_alloc(cells, (size_t)n, sizeof(int64_t)));
    *count = n;
    for (int k = 0; k < n; k++)
        (*cells)[k] = along == 0 ? grid_index(g, k, j) : grid_index(g, i, k);
    return NSPD_OK;
}

static void gks_cell_centre(const void *impl, int64_t cell, double xy[2]) {
    const Grid *g = gks_solver_whole_grid(((const GksFlow *)impl)->solver);
    int i, j;
    cell_ij(g, cell, &i, &j);
    xy[0] = g->ax[0].center[i];
    xy[1] = g->ax[1].center[j];
}

/* A cell of the whole grid: read on the process that holds it, then sent
 * to the others (every rank calls). */
static void gks_cell_state(const void *impl, int64_t cell, double out[5]) {
    /* the fields are read only here; the accessor is not const-qualified */
    GksSolver *solver = ((const GksFlow *)impl)->solver;
    const Grid *whole = gks_solver_whole_grid(solver);
    int i, j;
    cell_ij(whole, cell, &i, &j);
    const int owner = gks_solver_cell_owner(solver, i, j);
    const NspdComm *comm = gks_solver_comm(solver);
    if (comm->rank == owner) {
        int first[2], count[2];
        gks_solver_block(solver, owner, first, count);
        const int64_t k = grid_index(gks_solver_grid(solver), i - first[0], j - first[1]);
        GksFields f = gks_solver_fields(solver);
        const GksParams *gas = gks_solver_gas(solver);
        double w[4] = {f.w[0][k], f.w[1][k], f.w[2][k], f.w[3][k]};
        FlowPrim q;
        flow_cons_to_prim(w, gas->gamma, &q);
        out[0] = q.rho;
        out[1] = q.u;
        out[2] = q.v;
        out[3] = q.p;
        out[4] = q.p / (q.rho * gas->R);
    }
    (void)comm_bcast(comm, out, 5 * (int)sizeof(double), owner);
}

static FlowReference gks_reference(const void *impl) {
    const GksFlow *g = impl;
    const GksCaseConfig *f = &g->cfg;
    const FlowPrim *q = f->has_free_stream ? &f->free_stream : &f->solver.initial;
    const GksParams *gas = gks_solver_gas(g->solver);
    return (FlowReference){.rho = q->rho,
                           .u = q->u,
                           .v = q->v,
                           .p = q->p,
                           .length = f->reference_length,
                           .gamma = gas->gamma,
                           .gas_constant = gas->R};
}

/* The primitive fields of the whole grid's interior cells and their
 * kinds, into the output scratch (cells[0..5], blank, kind) of rank 0;
 * every rank calls. */
static void primitives(GksFlow *gf) {
    const Grid *g = gks_solver_whole_grid(gf->solver);
    static const FlowField order[6] = {FLOW_DENSITY,  FLOW_VELOCITY_X,  FLOW_VELOCITY_Y,
                                       FLOW_PRESSURE, FLOW_TEMPERATURE, FLOW_MACH};
    /* a failed gather is MPI's (its default handler stops the job) */
    for (int k = 0; k < 6; k++)
        (void)gks_solver_primitive_whole(gf->solver, order[k], gf->slab, gf->cells[k]);
    (void)gks_solver_kinds_whole(gf->solver, gf->slab, gf->kind);
    if (!gf->blank) return; /* not the writer */
    for (int64_t c = 0; c < (int64_t)g->nx * g->ny; c++)
        gf->blank[c] = gf->kind[c] != FLOW_CELL_FLUID;
}

/* Bilinear between the cell centres around each point, body cells left out:
 * the interpolation that starts a flow from a stored field
 * (field_sample.h), over the current state. */
static int gks_sample(void *impl, int64_t n, const double *x, const double *y, FlowSamples *out) {
    GksFlow *gf = impl;
    if (comm_distributed(gks_solver_comm(gf->solver)))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "sampling the GKS flow at points (a volumetric coupling) runs on one "
                         "process only so far");
    const Grid *g = gks_solver_whole_grid(gf->solver);
    primitives(gf);
    for (int64_t c = 0; c < (int64_t)g->nx * g->ny; c++) gf->valid[c] = !gf->blank[c];
    /* a view of the scratch: the source's arrays are read only here */
    FlowFieldSource view = {.nx = g->nx,
                            .ny = g->ny,
                            .xc = g->ax[0].center,
                            .yc = g->ax[1].center,
                            .rho = gf->cells[0],
                            .u = gf->cells[1],
                            .v = gf->cells[2],
                            .p = gf->cells[3],
                            .valid = gf->valid};
    for (int64_t k = 0; k < n; k++) {
        FlowPrim q;
        flow_field_sample(&view, x[k], y[k], &q);
        out->rho[k] = q.rho;
        out->u[k] = q.u;
        out->v[k] = q.v;
        out->p[k] = q.p;
    }
    return NSPD_OK;
}

/* Each point's force and power, over the area of the cell that holds it,
 * into the solver's source arrays. */
static int gks_set_sources(void *impl, FlowSources *src) {
    GksSolver *solver = ((GksFlow *)impl)->solver;
    if (!src) {
        gks_solver_clear_sources(solver);
        return NSPD_OK;
    }
    double *cell[3];
    TRY(gks_solver_source_cells(solver, cell));
    const Grid *g = gks_solver_grid(solver);
    const uint8_t *kind = gks_solver_fields(solver).kind;
    src->outside = 0;
    for (int64_t k = 0; k < src->n; k++) {
        const double x = src->x[k], y = src->y[k];
        if (!(x >= g->ax[0].lo && x <= g->ax[0].hi && y >= g->ax[1].lo && y <= g->ax[1].hi)) {
            src->outside++;
            continue;
        }
        const int i = grid_axis_cell_of(&g->ax[0], x), j = grid_axis_cell_of(&g->ax[1], y);
        const int64_t c = grid_index(g, i, j);
        if (kind[c] != FLOW_CELL_FLUID) {
            src->outside++;
            continue;
        }
        const double inv_area = g->ax[0].inv_width[i] * g->ax[1].inv_width[j];
        cell[0][c] += src->force_x[k] * inv_area;
        cell[1][c] += src->force_y[k] * inv_area;
        if (src->power) cell[2][c] += src->power[k] * inv_area;
    }
    return NSPD_OK;
}

/* A volumetric coupling's side (FlowOps.transfer, cell_owner, lumped,
 * add_lumped, seal). On several processes the coupling passes whole-grid
 * cells: the weights need the whole grid's kinds (gathered again when a
 * block's changed); the lumped values are read, and added, by the rank
 * that holds each cell (the coupling divides its cells by their owners,
 * couple/penalty/model.c); each rank seals the faces of its block and
 * halo, so every value is the one-process one. */

/* The whole grid's kinds on every rank (padded; ghost layers SOLID, never
 * read by the weights). Gathered again only when some block's kinds
 * changed since the last gather (one integer reduction a call otherwise,
 * not a byte a cell of the whole grid). */
static int whole_kinds(GksFlow *gf) {
    GksSolver *s = gf->solver;
    const Grid *w = gks_solver_whole_grid(s), *g = gks_solver_grid(s);
    const size_t local = (size_t)g->nx * (size_t)g->ny;
    bool fresh = false;
    if (!gf->whole_kind) {
        TRY(nspd_alloc(&gf->whole_kind, (size_t)w->size, 1));
        TRY(nspd_alloc(&gf->kind_rows, (size_t)w->nx * (size_t)w->ny + 1, 1));
        TRY(nspd_alloc(&gf->kind_last, local + 1, 1));
        memset(gf->whole_kind, FLOW_CELL_SOLID, (size_t)w->size);
        fresh = true;
    }
    uint8_t *mine = (uint8_t *)gf->slab; /* nx * ny bytes fit in the doubles */
    const uint8_t *kind = gks_solver_fields(s).kind;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) mine[(int64_t)j * g->nx + i] = kind[grid_index(g, i, j)];
    const NspdComm *comm = gks_solver_comm(s);
    const int64_t changed = fresh || memcmp(mine, gf->kind_last, local) != 0;
    if (comm_max_i64(comm, changed) == 0) return NSPD_OK;
    memcpy(gf->kind_last, mine, local);
    TRY(comm_allgatherv_bytes(comm, mine, g->nx * g->ny, gf->kind_rows));
    gks_solver_place_blocks(s, gf->kind_rows, 1, gf->whole_kind, w->stride, GRID_NG);
    return NSPD_OK;
}

static void gks_flow_transfer(const void *impl, FlowTransferKind kind, int64_t n, const double *x,
                              const double *y, int64_t *cell, double *w) {
    GksFlow *gf = (GksFlow *)impl; /* the kinds' scratch only */
    GksSolver *s = gf->solver;
    const uint8_t *kinds = gks_solver_fields(s).kind;
    if (comm_distributed(gks_solver_comm(s))) {
        if (whole_kinds(gf) != NSPD_OK) { /* no memory: no weights, the coupling refuses */
            for (int64_t k = 0; k < n * flow_transfer_width(kind); k++) cell[k] = -1, w[k] = 0.0;
            return;
        }
        kinds = gf->whole_kind;
    }
    gks_transfer(gks_solver_whole_grid(s), kinds, kind, n, x, y, cell, w);
}

/* The process that holds whole-grid cell c, and c's index here (where
 * this process holds it). */
static int cell_owner(const GksSolver *s, int64_t c, int64_t *local) {
    const Grid *w = gks_solver_whole_grid(s);
    *local = gks_solver_local_cell(s, c);
    return gks_solver_cell_owner(s, (int)(c % w->stride) - GRID_NG, (int)(c / w->stride) - GRID_NG);
}

static int gks_flow_cell_owner(const void *impl, int64_t cell) {
    int64_t local;
    return cell_owner(((const GksFlow *)impl)->solver, cell, &local);
}

static bool gks_flow_point_near(const void *impl, double x, double y, int margin) {
    const GksSolver *s = ((const GksFlow *)impl)->solver;
    const NspdComm *comm = gks_solver_comm(s);
    if (!comm_distributed(comm)) return true;
    const Grid *w = gks_solver_whole_grid(s);
    const double at[2] = {x, y};
    int first[2], count[2];
    gks_solver_block(s, comm->rank, first, count);
    for (int a = 0; a < 2; a++) {
        const GridAxis *ax = &w->ax[a];
        if (!(at[a] >= ax->face[0] && at[a] <= ax->face[ax->n])) return false; /* off the grid */
        const int i = grid_axis_cell_of(ax, at[a]);
        const int lo = first[a], hi = first[a] + count[a] - 1;
        /* cells between i and the block, the shorter way round a periodic axis */
        int d = i < lo ? lo - i : i > hi ? i - hi : 0;
        if (ax->periodic && i < lo && i + ax->n - hi < d) d = i + ax->n - hi;
        if (ax->periodic && i > hi && lo + ax->n - i < d) d = lo + ax->n - i;
        if (d > margin) return false;
    }
    return true;
}

static void gks_flow_lumped(const void *impl, int64_t n, const int64_t *cells, double *mass,
                            double *momentum_x, double *momentum_y) {
    const GksFlow *gf = impl;
    GksSolver *s = gf->solver;
    const GksFields f = gks_solver_fields(s);
    const NspdComm *comm = gks_solver_comm(s);
    if (!comm_distributed(comm)) {
        gks_lumped(gks_solver_grid(s), &f, n, cells, mass, momentum_x, momentum_y);
        return;
    }
    for (int64_t k = 0; k < n; k++) {
        int64_t local;
        if (cell_owner(s, cells[k], &local) != comm->rank) { /* another process's */
            mass[k] = momentum_x[k] = momentum_y[k] = (double)NAN;
            continue;
        }
        gks_lumped(gks_solver_grid(s), &f, 1, &local, &mass[k], &momentum_x[k], &momentum_y[k]);
    }
}

static void gks_flow_lumped_volume(const void *impl, int64_t n, const int64_t *cells,
                                   double *volume) {
    const GksFlow *gf = impl;
    GksSolver *s = gf->solver;
    const NspdComm *comm = gks_solver_comm(s);
    for (int64_t k = 0; k < n; k++) {
        int64_t local = cells[k];
        if (comm_distributed(comm) && cell_owner(s, cells[k], &local) != comm->rank) {
            volume[k] = (double)NAN; /* another process's */
            continue;
        }
        gks_lumped_volume(gks_solver_grid(s), 1, &local, &volume[k]);
    }
}

static void gks_flow_add_lumped(void *impl, int64_t n, const int64_t *cells, const double *dmx,
                                const double *dmy, const double *de) {
    GksSolver *s = ((GksFlow *)impl)->solver;
    GksFields f = gks_solver_fields(s);
    const NspdComm *comm = gks_solver_comm(s);
    if (!comm_distributed(comm)) {
        gks_add_lumped(gks_solver_grid(s), &f, n, cells, dmx, dmy, de);
        return;
    }
    for (int64_t k = 0; k < n; k++) {
        int64_t local;
        if (cell_owner(s, cells[k], &local) != comm->rank) continue;
        gks_add_lumped(gks_solver_grid(s), &f, 1, &local, dmx ? &dmx[k] : NULL,
                       dmy ? &dmy[k] : NULL, de ? &de[k] : NULL);
    }
}

static int gks_flow_seal(void *impl, int64_t n, const int64_t *cells, const double *area,
                         const double *u, const double *v, double fraction) {
    GksSolver *s = ((GksFlow *)impl)->solver;
    if (!comm_distributed(gks_solver_comm(s)))
        return gks_solver_set_seals(s, n, cells, area, u, v, fraction);
    /* this block's cells and its halo's: a face between the two is this
     * rank's to seal too */
    int64_t *mine = NULL;
    double *val = NULL;
    int status = nspd_alloc(&mine, (size_t)n + 1, sizeof *mine);
    if (status == NSPD_OK) status = nspd_alloc(&val, 3 * (size_t)n + 3, sizeof *val);
    int64_t m = 0;
    for (int64_t k = 0; k < n && status == NSPD_OK; k++) {
        const int64_t local = gks_solver_local_cell(s, cells[k]);
        if (local < 0) continue;
        mine[m] = local;
        val[m] = area[k], val[n + 1 + m] = u[k], val[2 * n + 2 + m] = v[k];
        m++;
    }
    if (status == NSPD_OK)
        status = gks_solver_set_seals(s, m, mine, val, val + n + 1, val + 2 * n + 2, fraction);
    nspd_free(&mine);
    nspd_free(&val);
    return status;
}

static void gks_totals(const void *impl, double totals[4]) {
    gks_solver_totals(((const GksFlow *)impl)->solver, totals);
}

static int gks_checkpoint(void *impl, Checkpoint *ck) {
    GksFlow *g = impl;
    TRY(gks_solver_checkpoint(g->solver, ck));
    TRY(checkpoint_io_double(ck, "gks.mach_scale", &g->mach_scale));
    TRY(checkpoint_io_double(ck, "gks.speed_scale", &g->speed_scale));
    return checkpoint_io_double(ck, "gks.last_dt", &g->last_dt);
}

static void gks_history(const void *impl, Report *row) {
    const GksFlow *g = impl;
    double totals[4];
    gks_solver_totals(g->solver, totals);
    report_real(row, "dt_s", g->last_dt);
    report_precise(row, "mass_kg_per_m", totals[0]);
    report_precise(row, "momentum_x_kg_per_s", totals[1]);
    report_precise(row, "momentum_y_kg_per_s", totals[2]);
    report_precise(row, "energy_J_per_m", totals[3]);
    report_int(row, "fallbacks", gks_solver_fallbacks_last(g->solver));
}

static void gks_summary(const void *impl, const RunStats *run, Report *out) {
    const GksFlow *g = impl;
    const Grid *grid = gks_solver_whole_grid(g->solver);
    double totals[4];
    gks_solver_totals(g->solver, totals);
    int64_t cells = (int64_t)grid->nx * grid->ny;
    report_int(out, "cells", cells);
    report_int(out, "cells_x", grid->nx);
    report_int(out, "cells_y", grid->ny);
    report_real(out, "cell_updates_per_s",
                run->wall_s > 0 ? (double)cells * (double)run->steps / run->wall_s : 0.0);
    report_int(out, "fallbacks", gks_solver_fallbacks_total(g->solver));
    report_real(out, "mass_kg_per_m", totals[0]);
    report_real(out, "momentum_x_kg_per_s", totals[1]);
    report_real(out, "momentum_y_kg_per_s", totals[2]);
    report_real(out, "energy_J_per_m", totals[3]);
    /* the area-weighted mean pressure of the fluid cells (a closed box's
     * late pressure is its energy balance's) */
    double mean = NAN;
    (void)gks_solver_mean_pressure(g->solver, g->slab, g->cells[6], &mean);
    report_real(out, "mean_pressure_pa", mean);
    /* several processes: this one's wall time in exchanges and reductions
     * (halo rows, the stable step, counts, a coupling's cells) */
    if (comm_distributed(gks_solver_comm(g->solver))) {
        report_real(out, "exchange_s", gks_solver_comm_seconds(g->solver));
        report_text(out, "process_grid", g->process_grid); /* the layout: PX x PY blocks */
    }
}

static void gks_info(const void *impl, size_t memory, char *buf, size_t size) {
    const GksFlow *gf = impl;
    const Grid *g = gks_solver_whole_grid(gf->solver);
    const GksConfig *c = gks_solver_config(gf->solver);
    int len = 0;
#define APPEND(...)                                                                                \
    len += snprintf(buf + len, size > (size_t)len ? size - (size_t)len : 0, __VA_ARGS__)
    for (int a = 0; a < 2; a++) {
        double hmin = INFINITY, hmax = 0;
        for (int i = 0; i < g->ax[a].n; i++) {
            hmin = fmin(hmin, g->ax[a].width[i]);
            hmax = fmax(hmax, g->ax[a].width[i]);
        }
        APPEND("grid %c               %d cells on [%.6g, %.6g] m, spacing %.4g to %.4g m\n",
               "xy"[a], g -> ax[a].n, g->ax[a].lo, g->ax[a].hi, hmin, hmax);
    }
    APPEND("cells                %lld\n", (long long)g->nx * g->ny);
    APPEND("gas                  gamma %.4g, R %.6g J/(kg K), Pr %.3g, viscosity %s\n", c->gamma,
           c->gas_constant, c->prandtl, c->viscosity == VISCOSITY_NONE ? "none (Euler)" : "on");
    const GksCaseConfig *fc = &gf->cfg;
    if (fc->has_free_stream) {
        const FlowPrim *q = &fc->free_stream;
        double speed = hypot(q->u, q->v), a = sqrt(c->gamma * q->p / q->rho);
        APPEND("free stream          rho %.6g, |u| %.6g, p %.6g, Mach %.4g", q->rho, speed, q->p,
               speed / a);
        if (c->viscosity != VISCOSITY_NONE && fc->reference_length > 0)
            APPEND(", Re %.6g over %.4g m", q->rho * speed * fc->reference_length / c->mu_ref,
                   fc->reference_length);
        APPEND("\n");
    }
    APPEND("CFL time step        %.6g s at the start (CFL %.3g)\n",
           gks_solver_stable_dt(gf->solver), c->cfl);
    APPEND("memory               %.1f MB in solver arrays (%.0f bytes per cell)\n",
           (double)memory / 1e6, (double)memory / ((double)g->nx * g->ny));
#undef APPEND
}

static void gks_brief(const void *impl, char *buf, size_t size) {
    const Grid *g = gks_solver_whole_grid(((const GksFlow *)impl)->solver);
    snprintf(buf, size, "%d x %d cells, ", g->nx, g->ny);
}

static int64_t gks_fallbacks_total(const void *impl) {
    return gks_solver_fallbacks_total(((const GksFlow *)impl)->solver);
}

/* Numerical schlieren (Quirk 1994): S = exp(-k |grad rho| / max |grad rho|),
 * k = 15, from central differences of the density on the stretched grid. */
static void schlieren(const Grid *g, const double *rho, const uint8_t *solid, double *out) {
    int nx = g->nx, ny = g->ny;
    double gmax = 0.0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int il = i > 0 ? i - 1 : i, ir = i < nx - 1 ? i + 1 : i;
            int jl = j > 0 ? j - 1 : j, jr = j < ny - 1 ? j + 1 : j;
            double gx = ir > il ? (rho[(int64_t)j * nx + ir] - rho[(int64_t)j * nx + il]) /
                                      (g->ax[0].center[ir] - g->ax[0].center[il])
                                : 0.0;
            double gy = jr > jl ? (rho[(int64_t)jr * nx + i] - rho[(int64_t)jl * nx + i]) /
                                      (g->ax[1].center[jr] - g->ax[1].center[jl])
                                : 0.0;
            double m = solid[(int64_t)j * nx + i] ? 0.0 : sqrt(gx * gx + gy * gy);
            out[(int64_t)j * nx + i] = m;
            if (m > gmax) gmax = m;
        }
    for (int64_t c = 0; c < (int64_t)nx * ny; c++)
        out[c] = gmax > 0.0 ? exp(-15.0 * out[c] / gmax) : 1.0;
}

/* The Mach and speed pictures' tops, while open: from the largest Mach
 * number and speed of this output, over the fluid cells and the reference
 * state (the free stream), what flow_mach_picture_top and
 * flow_speed_picture_top scale. */
static void fix_picture_tops(GksFlow *gf, int64_t ncell) {
    if (gf->mach_scale != 0.0 && gf->speed_scale != 0.0) return;
    double mach = 0.0, speed = 0.0;
    for (int64_t c = 0; c < ncell; c++)
        if (!gf->blank[c]) {
            mach = fmax(mach, gf->cells[5][c]);
            speed = fmax(speed, gf->cells[7][c]);
        }
    const FlowReference r = gks_reference(gf);
    speed = fmax(speed, hypot(r.u, r.v));
    if (r.rho > 0 && r.p > 0) mach = fmax(mach, hypot(r.u, r.v) / sqrt(r.gamma * r.p / r.rho));
    if (gf->mach_scale == 0.0) gf->mach_scale = flow_mach_picture_top(mach);
    if (gf->speed_scale == 0.0) gf->speed_scale = flow_speed_picture_top(speed, mach);
}

/* This block's piece of the .pvtr (several processes): its own cells'
 * fields, computed where they live; nothing is gathered for it. */
static void piece_fields(GksFlow *gf, FieldPiece *pc) {
    GksSolver *solver = gf->solver;
    const Grid *g = gks_solver_grid(solver);
    static const FlowField order[6] = {FLOW_DENSITY,  FLOW_VELOCITY_X,  FLOW_VELOCITY_Y,
                                       FLOW_PRESSURE, FLOW_TEMPERATURE, FLOW_MACH};
    for (int k = 0; k < 6; k++) gks_solver_primitive(solver, order[k], gf->piece[k]);
    gks_solver_kinds(solver, gf->piece[6]);
    const NspdComm *comm = gks_solver_comm(solver);
    pc->index = comm->rank;
    pc->count = comm->size;
    pc->cells = (const int(*)[4])gf->piece_cells;
    pc->nx = g->nx;
    pc->ny = g->ny;
    pc->face[0] = g->ax[0].face;
    pc->face[1] = g->ax[1].face;
    double *const *c = gf->piece;
    const FieldRef fields[] = {
        {"density", 1, {c[0], NULL, NULL}},  {"velocity", 3, {c[1], c[2], NULL}},
        {"pressure", 1, {c[3], NULL, NULL}}, {"temperature", 1, {c[4], NULL, NULL}},
        {"mach", 1, {c[5], NULL, NULL}},     {"cell_kind", 1, {c[6], NULL, NULL}},
    };
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++)
        pc->field[pc->field_count++] = fields[k];
}

/* What the pictures draw, of the whole grid on rank 0 (several
 * processes): the density (schlieren), the Mach number, the speed and the
 * kinds. */
static void picture_fields(GksFlow *gf) {
    const Grid *g = gks_solver_whole_grid(gf->solver);
    /* a failed gather is MPI's (its default handler stops the job) */
    (void)gks_solver_primitive_whole(gf->solver, FLOW_DENSITY, gf->slab, gf->cells[0]);
    (void)gks_solver_primitive_whole(gf->solver, FLOW_MACH, gf->slab, gf->cells[5]);
    (void)gks_solver_primitive_whole(gf->solver, FLOW_SPEED, gf->slab, gf->cells[7]);
    (void)gks_solver_kinds_whole(gf->solver, gf->slab, gf->kind);
    if (!gf->blank) return; /* not the writer */
    for (int64_t c = 0; c < (int64_t)g->nx * g->ny; c++)
        gf->blank[c] = gf->kind[c] != FLOW_CELL_FLUID;
}

/* One process: the whole grid's fields, pictures and .vtr. Several: each
 * block's piece, and the pictures on rank 0 from what they draw only. */
static void gks_fields(void *impl, FieldSet *out) {
    GksFlow *gf = impl;
    const Grid *g = gks_solver_whole_grid(gf->solver);
    const int64_t ncell = (int64_t)g->nx * g->ny;
    memset(out, 0, sizeof *out);
    out->series = "flow";
    out->mesh = MESH_GRID;
    const bool pieces = comm_distributed(gks_solver_comm(gf->solver));
    if (pieces) {
        piece_fields(gf, &out->piece);
        picture_fields(gf);
    } else {
        primitives(gf); /* cell kinds too, as 0/1 "blank" and as a field */
        /* the speed as FLOW_SPEED gives it (the pieces' gather), from u, v */
        for (int64_t c = 0; c < ncell; c++)
            gf->cells[7][c] =
                sqrt(gf->cells[1][c] * gf->cells[1][c] + gf->cells[2][c] * gf->cells[2][c]);
    }
    if (!gf->blank) return; /* not the writer: its piece only */
    fix_picture_tops(gf, ncell);
    schlieren(g, gf->cells[0], gf->blank, gf->cells[6]);
    out->nx = g->nx;
    out->ny = g->ny;
    out->face[0] = g->ax[0].face;
    out->face[1] = g->ax[1].face;
    out->blank = gf->blank;
    double *const *c = gf->cells;
    const FieldRef fields[] = {
        {"density", 1, {c[0], NULL, NULL}},  {"velocity", 3, {c[1], c[2], NULL}},
        {"pressure", 1, {c[3], NULL, NULL}}, {"temperature", 1, {c[4], NULL, NULL}},
        {"mach", 1, {c[5], NULL, NULL}},     {"cell_kind", 1, {gf->kind, NULL, NULL}},
    };
    for (size_t k = 0; k < sizeof fields / sizeof fields[0] && !pieces; k++)
        out->field[out->field_count++] = fields[k];
    /* 0 to 1 while the scale is open (a gas at rest) */
    const double mach_hi = gf->mach_scale > 0.0 ? gf->mach_scale : 1.0;
    out->picture[out->picture_count++] = (PictureRef){.file = "mach",
                                                      .label = "Mach number",
                                                      .units = "-",
                                                      .values = c[5],
                                                      .lo = 0.0,
                                                      .hi = mach_hi,
                                                      .map = COLORMAP_VIRIDIS,
                                                      .overlay_file = "mach_damage"};
    /* |u|, paper 003's air speed (Figs. 2, 7, 11), where a solid is coupled
     * (drawn with it on top); from the velocity, no VTK array of its own */
    out->picture[out->picture_count++] =
        (PictureRef){.file = "speed",
                     .label = "speed",
                     .units = "m/s",
                     .values = c[7],
                     .lo = 0.0,
                     .hi = gf->speed_scale > 0.0 ? gf->speed_scale : 1.0,
                     .map = COLORMAP_VIRIDIS,
                     .overlay_file = "speed_damage",
                     .coupled_only = true};
    out->picture[out->picture_count++] = (PictureRef){.file = "schlieren",
                                                      .label = "schlieren exp(-15 |∇ρ| / max |∇ρ|)",
                                                      .units = "-",
                                                      .values = c[6],
                                                      .lo = 0.0,
                                                      .hi = 1.0,
                                                      .map = COLORMAP_GRAY};
}

const FlowOps GKS_FLOW_OPS = {
    .name = "gks",
    .distributed = true,
    .config_free = gks_config_free,
    .estimate = gks_estimate,
    .validate = gks_validate,
    .create = gks_create,
    .destroy = gks_destroy,
    .stable_dt = gks_stable_dt,
    .step = gks_step,
    .time = gks_time,
    .mesh = gks_mesh,
    .cell_state = gks_cell_state,
    .cell_at = gks_cell_at,
    .grid_line = gks_grid_line,
    .cell_centre = gks_cell_centre,
    .reference = gks_reference,
    .sample = gks_sample,
    .set_sources = gks_set_sources,
    .transfer = gks_flow_transfer,
    .cell_owner = gks_flow_cell_owner,
    .point_near = gks_flow_point_near,
    .lumped = gks_flow_lumped,
    .lumped_volume = gks_flow_lumped_volume,
    .add_lumped = gks_flow_add_lumped,
    .seal = gks_flow_seal,
    .totals = gks_totals,
    .history = gks_history,
    .summary = gks_summary,
    .info = gks_info,
    .brief = gks_brief,
    .fallbacks_total = gks_fallbacks_total,
    .fields = gks_fields,
    .checkpoint = gks_checkpoint,
    .bench_name = "gks",
    .bench = gks_bench_report,
};

GksSolver *gks_flow_solver(Flow *f) {
    GksFlow *g = flow_impl(f, FLOW_METHOD_GKS);
    return g ? g->solver : NULL;
}
