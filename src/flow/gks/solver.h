/* The compressible flow operator: grid + state + GKS step.
 *
 * A GksSolver owns a stretched Cartesian grid, the conservative state
 * (rho, rho u, rho v, rho E; one array per variable, with ghost layers), a
 * per-cell kind array and the work space of one time step. One call of
 * gks_solver_step advances the state by dt with the single-stage gas-kinetic
 * scheme (the flux is integrated in time, second order):
 *     W_i^{n+1} = W_i^n - (1/V_i) sum_faces (\int_0^dt F dt) |face|          (paper 000 Eq. 20)
 *
 * Step: box ghost layers (bc.h) -> optional fill_ghosts hook (immersed
 * boundary) -> per row, limited slopes, x-face and y-face fluxes
 * (flux.h), update of the fluid cells -> check for NaN / rho <= 0 / p <= 0.
 *
 * Cell kinds (uint8): FLUID cells are updated; SOLID and GHOST cells are not.
 * A face's flux is computed if at least one of its cells is fluid. Box ghost
 * layers take the kind of their image cell. A slope in a direction is zero in
 * a SOLID cell and in any cell with a SOLID neighbour in that direction, so
 * GHOST cell values (set by the hook) are used but nothing inside the solid
 * ever is.
 *
 * Determinism: every face flux is a pure function of the state, rows are
 * split among threads in fixed blocks, a face on a block boundary is computed
 * by both blocks identically, and sums are taken in a fixed order: results
 * are bitwise identical at any thread count.
 *
 * Thread safety: one solver per thread of the caller; the step itself is
 * OpenMP-parallel. No allocation happens after gks_solver_create. */
#ifndef NSPD_FLOW_GKS_SOLVER_H
#define NSPD_FLOW_GKS_SOLVER_H

#include "core/checkpoint.h"
#include "core/comm.h"
#include "core/shape.h"
#include "flow/gks/bc.h"
#include "flow/gks/cell_kind.h"
#include "flow/gks/flux_kernel.h"
#include "flow/gks/grid.h"
#include "flow/gks/recon_kernel.h"
#include "flow/vortex.h"

#include <stdint.h>

extern const char *const FLOW_LIMITER_NAMES[LIMITER_COUNT + 1]; /* "van_leer", ..., NULL */

enum { FLOW_MAX_SEGMENTS = 16 };

/* A region of the initial condition: cells (or quadrature points) inside
 * `shapes` take `state`. Later regions override earlier ones. */
typedef struct {
    ShapeSet shapes; /* borrowed */
    FlowPrim state;
} FlowRegion;

/* Initial condition as a function: the primitive state at (x, y). */
typedef void (*FlowInitFn)(void *ctx, double x, double y, FlowPrim *out);

typedef struct GksSolver GksSolver;
/* Called in every step after the box ghost layers are filled and before the
 * fluxes: sets the state of GHOST cells (immersed boundary). */
typedef void (*FlowGhostHook)(void *ctx, GksSolver *solver);

typedef struct {
    /* grid: segments per axis from (x0, y0) */
    double x0, y0;
    int segment_count[2];
    GridSegment segments[2][FLOW_MAX_SEGMENTS];
    /* gas */
    double gamma;        /* default 1.4 */
    double gas_constant; /* J/(kg K), default 287 */
    ViscosityLaw viscosity;
    double mu_ref, T_ref, omega, sutherland_S; /* see ViscosityLaw */
    double prandtl;                            /* default 0.72 */
    /* numerics */
    FlowLimiter limiter; /* default van Leer */
    double cfl;          /* default 0.5 */
    double tau_jump_c;   /* C in tau_n = tau + C dt |pL - pR|/(pL + pR); default 1 */
    double tau_eps;      /* eps: tau_n += eps dt everywhere; default 0 */
    /* boundaries: FLOW_FACE_XLO, XHI, YLO, YHI */
    FlowFaceBc bc[4];
    /* initial condition: uniform `initial`, then `regions` in order, or
     * init_fn if set; averaged over init_quadrature^2 Gauss points per cell
     * (1 = cell centre; up to 4). */
    FlowPrim initial;
    int region_count;
    const FlowRegion *regions; /* borrowed during gks_solver_create only */
    FlowInitFn init_fn;
    void *init_ctx;
    int init_quadrature;
    /* regions of one disc or rectangle each, not overlapping: cell averages
     * of the conserved variables by exact area fractions (a charge holds
     * the same energy on every mesh) instead of the quadrature */
    bool init_area_fractions;
    /* processes (borrowed during create; copied): NULL or a group of one,
     * the whole grid; more, each process holds a block (below) */
    const NspdComm *comm;
    /* the process grid on several processes: processes[0] blocks along x
     * times processes[1] along y, their product the group's size; {0, 0}:
     * the grid whose largest block exchanges the fewest halo cells (of
     * equals, fewer blocks along x: slabs of rows on a square grid's 2 or
     * 3 ranks, 2 x 2 on its 4) */
    int processes[2];
} GksConfig;

/* Several processes (issue 28). The group is a process grid of px x py
 * blocks (GksConfig.processes; by default the one of the fewest halo cells),
 * rank r at (r % px, r / px); along each axis a block holds the cells
 * n c / p .. n (c + 1) / p - 1, at least GRID_NG of them (grid_slice: the
 * same stretched-grid weights). Its box ghost layers come from the
 * boundary conditions on the whole grid's faces it holds (an axis of one
 * block fills both, a periodic one too) and, on the others, from its
 * neighbours: after the x faces' conditions, two columns of the four
 * fields and the kinds each way (interior rows); after the y faces'
 * conditions (over every column, the x halo's too), two whole rows each
 * way, corners included. So each rank's cells see the values the
 * one-process run gives. The stable step is the maximum rate over all
 * ranks, the fallback counts integer sums (a block's edge columns and
 * rows count only at the whole grid's ends), the totals each row summed
 * along x block after block (each continues its left neighbour's sum) and
 * the rows added in order: every number is the one-process run's, bit for
 * bit, at any process grid (tests/mpi). */

/* Defaults: air (gamma 1.4, R 287, Pr 0.72), inviscid, van Leer, CFL 0.5,
 * C = 1, eps = 0, extrapolation on all faces, no grid segments. */
void gks_config_default(GksConfig *c);
/* Convenience: a uniform nx x ny grid on [x0,x1] x [y0,y1]. */
void gks_config_uniform_grid(GksConfig *c, double x0, double x1, int nx, double y0, double y1,
                             int ny);
/* Sets every segment of a face to one condition. */
void gks_config_set_bc(GksConfig *c, int face, const FlowBc *bc);

/* Builds the solver and applies the initial condition. Allocates everything
 * the steps need (work space for omp_get_max_threads() threads).
 * NSPD_ERR_INPUT for an inconsistent configuration, NSPD_ERR_NOMEM. */
int gks_solver_create(GksSolver **out, const GksConfig *cfg);
void gks_solver_destroy(GksSolver **s);

/* Re-applies an initial condition from cfg (its IC fields only). */
void gks_solver_apply_initial(GksSolver *s, const GksConfig *cfg);

/* The current fields: pointers into the solver, valid until the next step
 * (the step swaps buffers). Index with grid_index(). */
typedef struct {
    double *w[4];  /* rho, rho u, rho v, rho E */
    uint8_t *kind; /* FLOW_CELL_* */
} GksFields;
GksFields gks_solver_fields(GksSolver *s);
const Grid *gks_solver_grid(const GksSolver *s);
const GksParams *gks_solver_gas(const GksSolver *s);
const GksConfig *gks_solver_config(const GksSolver *s);
/* The whole grid (its axes and sizes): on one process gks_solver_grid,
 * on several the grid this process's slab is cut from. */
const Grid *gks_solver_whole_grid(const GksSolver *s);
/* The processes the solver runs on (the one-process group alone). */
const NspdComm *gks_solver_comm(const GksSolver *s);
/* Wall time (s) this process spent in the exchanges of ghost rows and the
 * reductions of the stable step and the counts, since creation (0 on one
 * process). */
double gks_solver_comm_seconds(const GksSolver *s);
/* Counts a coupling's exchanges of the solver's cells in it too. */
void gks_solver_add_comm_seconds(GksSolver *s, double seconds);

void gks_solver_set_ghost_hook(GksSolver *s, FlowGhostHook hook, void *ctx);

/* Sealed ghost faces (immersed boundary; set by the ghost hook, valid until
 * its next call): slot[k] (indexed with grid_index) is the index of ghost
 * cell k into u[], v[], the velocity of its wall point, or -1. With them, a
 * face between a FLUID and a GHOST cell with a slot carries the mass only
 * that the wall's motion displaces,
 *     F_rho' = dt rho_f u_w.n,
 * and its momentum and energy fluxes lose what the removed mass carried,
 *     F_m' = F_m - (F_rho - F_rho') u_face,   F_E' = F_E - (F_rho - F_rho') H_face,
 * (rho_f the fluid cell's density; u_face, H_face the means of the two
 * cells'); pressure, viscous stress and heat conduction are kept. The gas
 * is then conserved to round-off round bodies at rest, and a fluid cell on
 * the wall cannot drain into the body. The price: for mass the wall is the
 * cell staircase, a first-order geometry (docs/VALIDATION.md). NULL slot:
 * the faces carry the GKS flux of the reflected ghost state (Eq. 39). */
void gks_solver_set_ghost_walls(GksSolver *s, const int32_t *slot, const double *u,
                                const double *v);

/* Sealed faces inside a solid (the penalty coupling's remedy for the
 * pressure that leaks through the gas it locks; update_kernel.h). A solid
 * moving at (u[k], v[k]) covers area[k] (m^2) of cell cells[k] (distinct,
 * indices of grid_index); the FLUID cells it covers to at least `fraction`
 * of their area are locked. For the next steps, a face between two locked
 * cells carries only the locked gas, advected with the mean of their
 * velocities, F = dt u_s.n W_face (gks_seal_face: no pressure, no
 * numerical diffusion). Replaces the last call's seals (n = 0: none).
 * Copies what it keeps; allocates on growth. */
int gks_solver_set_seals(GksSolver *s, int64_t n, const int64_t *cells, const double *area,
                         const double *u, const double *v, double fraction);

/* Volume sources for the next steps (a coupling's forces on the gas): the
 * per-cell arrays (index with grid_index) of x and y momentum (N/m^3) and
 * energy (W/m^3), zeroed, for the caller to fill; every later step adds
 * dt times them to the fluid cells' momentum and energy after the fluxes
 * (first order in time, as the coupling that sets them). The first call
 * allocates (3 doubles per cell); gks_solver_clear_sources stops them. */
int gks_solver_source_cells(GksSolver *s, double *out[3]);
void gks_solver_clear_sources(GksSolver *s);

/* Fills the box ghost layers now (the step does it itself; for output). */
void gks_solver_fill_boundaries(GksSolver *s);

/* Largest stable dt: CFL / max over fluid cells of
 *   (|u| + c)/dx + (|v| + c)/dy + 2 nu_eff (1/dx^2 + 1/dy^2),
 * nu_eff = max(4/3, gamma/Pr) mu / rho. */
double gks_solver_stable_dt(const GksSolver *s);

/* The checks of a configuration that need no cells (its numbers, the
 * grid's axes, the boundaries on them), as gks_solver_create makes them:
 * what `nspd check` runs on a grid too large to build (the axes are 1D). */
int gks_solver_validate(const GksConfig *cfg);

/* The stable step of the initial state from the configuration alone: the
 * signal rate of the uniform state and of each region's at the smallest
 * spacing of each axis (0 for an initial function or an invalid one). */
double gks_solver_config_stable_dt(const GksConfig *cfg, const FlowRegion *regions, int count);

/* One step of size dt (s). NSPD_ERR_NUMERIC if a fluid cell ends with NaN,
 * rho <= 0 or p <= 0; the message names the first such cell (row-major
 * order), its centre and the step. */
int gks_solver_step(GksSolver *s, double dt);

/* Steps with the stable dt until time t_end (the last step is shortened to
 * land on it) or max_steps steps (<= 0: no limit). */
int gks_solver_advance(GksSolver *s, double t_end, int64_t max_steps);

double gks_solver_time(const GksSolver *s);
/* Writes or reads the solver's state (core/checkpoint.h). */
int gks_solver_checkpoint(GksSolver *s, Checkpoint *ck);
int64_t gks_solver_step_count(const GksSolver *s);
/* First-order fallbacks (cell-directions whose limited slopes would have made
 * rho or p negative at a face) in the last step, and in all steps so far. */
int64_t gks_solver_fallbacks_last(const GksSolver *s);
int64_t gks_solver_fallbacks_total(const GksSolver *s);

typedef enum {
    FLOW_DENSITY = 0,
    FLOW_VELOCITY_X,
    FLOW_VELOCITY_Y,
    FLOW_PRESSURE,
    FLOW_TEMPERATURE,
    FLOW_MACH,
    FLOW_SPEED, /* |u|, m/s */
    FLOW_FIELD_COUNT
} FlowField;

/* Writes a primitive field of the interior cells into out[nx * ny], x
 * fastest, no ghosts (non-fluid cells included as stored). */
void gks_solver_primitive(const GksSolver *s, FlowField field, double *out);
/* The same over the whole grid on several processes (every rank calls):
 * out[nx * rows] on rank 0, the slabs in row order, for its writers (out
 * is not written elsewhere and may be NULL there); `slab` (nx * ny of
 * this rank) is scratch. On one process gks_solver_primitive. */
int gks_solver_primitive_whole(const GksSolver *s, FlowField field, double *slab, double *out);

/* The cell kinds (FLOW_CELL_*) of this process's interior cells as
 * numbers, into out[nx * ny] like gks_solver_primitive. */
void gks_solver_kinds(const GksSolver *s, double *out);
/* The cell kinds (FLOW_CELL_*) of the whole grid as numbers, gathered to
 * rank 0 like gks_solver_primitive_whole. */
int gks_solver_kinds_whole(const GksSolver *s, double *slab, double *out);
/* Rank `rank`'s block: its first cell of the whole grid and its cells per
 * axis (the whole grid on one process). */
void gks_solver_block(const GksSolver *s, int rank, int first[2], int count[2]);
/* Every rank's block of interior cells (x fastest, `elem` bytes a cell),
 * concatenated in rank order in blocks[] (what a gather of the blocks
 * gives), placed into out[]: a grid of rows `stride` cells long whose cell
 * (i, j) of the whole grid is at (j + pad) stride + i + pad (pad 0: the
 * interior alone; GRID_NG: the padded arrays). */
void gks_solver_place_blocks(const GksSolver *s, const void *blocks, size_t elem, void *out,
                             int64_t stride, int pad);
/* The blocks along x of the process grid (1: slabs of rows). */
int gks_solver_process_columns(const GksSolver *s);
/* The process that holds cell (i, j) of the whole grid, its box ghost
 * layers included (those of the blocks at the ends); 0 on one. */
int gks_solver_cell_owner(const GksSolver *s, int i, int j);
/* The index in this process's arrays of the whole grid's padded cell
 * `cell` (numbered as the whole grid's arrays), or -1 where it lies
 * outside this block and its ghost layers; `cell` itself on one process. */
int64_t gks_solver_local_cell(const GksSolver *s, int64_t cell);
/* The area-weighted mean pressure of the whole grid's fluid cells into
 * *mean on every rank (every rank calls; NaN without fluid); slab (this
 * slab's cells) and, on rank 0, all (the whole grid's) are scratch. */
int gks_solver_mean_pressure(const GksSolver *s, double *slab, double *all, double *mean);

/* Integrals over the fluid cells: mass (kg/m), x and y momentum, energy (J/m). */
void gks_solver_totals(const GksSolver *s, double totals[4]);

/* The isentropic vortex of flow/vortex.h (a FlowVortex) as an initial
 * condition. */
void flow_isentropic_vortex(void *vortex, double x, double y, FlowPrim *out);

/* Benchmark: viscous (Sutherland air, Pr 0.72) Taylor-Green-like flow at Mach
 * 0.3 on a periodic N x N grid, N = round(sqrt(cells)), run at `threads`
 * threads; times `steps` full steps (stable dt + step) after one warm-up step. */
typedef struct {
    int64_t cells; /* N * N */
    int steps;
    int threads;
    double seconds;            /* wall time of the timed steps */
    double cell_updates_per_s; /* cells * steps / seconds */
    double bytes_per_cell;     /* state + kinds + work arrays of the solver, per cell */
    double comm_seconds;       /* of the timed steps: the largest over the processes */
} GksBenchResult;
/* comm: NULL, or the processes that share the grid (slabs; every one calls) */
int gks_bench(int cells, int threads, int steps, const NspdComm *comm, GksBenchResult *out);

#endif
