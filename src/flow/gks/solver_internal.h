/* What the files of the flow operator share (solver.c: configuration,
 * create/destroy, accessors; initial.c; step.c; diagnostics.c;
 * bench.c): the solver's struct and the constants of its loops.
 *
 * Data: W (current) and Wn (next) conservative fields, one array per
 * variable, GRID_NG ghost layers, rows padded to 64 bytes; kind[] per cell.
 * The step reads W and writes Wn, then swaps the two: no cell is read after
 * it is overwritten, whatever the thread layout. All work arrays are
 * allocated at creation for omp_get_max_threads() threads. */
#ifndef NSPD_FLOW_GKS_SOLVER_INTERNAL_H
#define NSPD_FLOW_GKS_SOLVER_INTERNAL_H

#include "core/balance.h"
#include "flow/gks/solver.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Below this many cells (128^2) a step runs on one thread: a parallel region
 * costs microseconds, more than a small grid's step gains. Measured on the
 * panel case (59,540 cells): 2 threads run 1.7x faster than 1. On an
 * oversubscribed machine (`ctest -j2` with OMP_NUM_THREADS=2) a spinning
 * thread waiting for a descheduled partner costs a scheduler time slice per
 * region (5x-30x slow-downs were measured with the default wait policy), so
 * the tests run with OMP_WAIT_POLICY=passive. Results do not depend on the
 * thread count either way. */
enum { PARALLEL_MIN_CELLS = 16384 };

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

struct GksSolver {
    GksConfig cfg;
    Grid grid;
    Grid whole; /* the whole grid (its axes); several processes only, else unused */
    GksParams gas;
    double *w[4], *wn[4];
    uint8_t *kind;
    double *half_w[2]; /* half widths per axis, index -NG .. n+NG-1 (offset) */
    double *row_sums;  /* 4 * ny, for deterministic totals */
    uint8_t *wall[4];  /* per box face, per cell along it: WALL_* flags */
    int nthreads;
    FlowWork *work;
    /* the threads' shares of the rows all threads step (the edge rows of
     * an overlapped exchange go in equal shares), core/balance.h */
    Balance row_balance;
    FlowGhostHook hook;
    void *hook_ctx;
    double *source[3]; /* per cell: x, y momentum (N/m^3) and energy (W/m^3) sources;
                          allocated by the first gks_solver_source_cells */
    bool has_sources;
    const int32_t *wall_slot; /* gks_solver_set_ghost_walls */
    const double *wall_u, *wall_v;
    /* gks_solver_set_seals: per cell the seal's slot (-1: none; allocated
     * by the first call), per seal its cell and velocity */
    int32_t *seal_slot;
    int64_t *seal_cell;
    double *seal_u, *seal_v;
    int64_t seals, seal_capacity;
    double time;
    int64_t steps;
    int64_t fallbacks_last, fallbacks_total;
    size_t bytes; /* allocated by create (state + work), for the benchmark */
    /* processes (solver.h): the group; the process grid, dims[0] x
     * dims[1] blocks, this one at coord (rank = coord[1] dims[0] +
     * coord[0]); its first cell of the whole grid per axis and the whole
     * grid's rows; the neighbours across each of
     * its faces (FLOW_FACE_* order, -1: none); the box faces it fills from
     * boundary conditions (bit 1 << face) */
    NspdComm comm;
    int dims[2], coord[2], first[2];
    int rows;
    int nbr[4];
    unsigned bc_faces;
    double *row_sums_all; /* 4 * rows, the gathered row sums (several processes) */
    double *gather; /* rank 0, 2D process grids: nx * ny of the whole grid, blocks in rank order */
    double *halo_x; /* 2D process grids: the x halo's columns, packed (4 buffers) */
    double comm_seconds; /* wall time in exchanges and reductions so far */
};

/* The viscous factor of the stable step: 2 max(4/3, gamma/Pr), 0 inviscid. */
double gks_visc_factor(const GksParams *gas);

/* The signal-speed rate (1/s) of one primitive state on a cell of inverse
 * widths idx, idy: what gks_solver_stable_dt takes the maximum of. */
double gks_signal_rate(const GksParams *gas, ViscosityLaw law, double visc_factor,
                       const FlowPrim *state, double idx, double idy);

#endif
