/* Sharp-interface ghost-cell immersed boundary (paper 000 Sec. 3.3, Eqs. 31-39).
 *
 * Walls are closed polylines (couple/ghost/markers.h). The method, per ghost cell
 * GC (a cell inside a body that the flux stencil of a fluid cell reads):
 *   BI = the nearest wall point, d = |GC - BI|, n = outward normal,
 *   IP = GC + 2 d n                                                       (Eq. 31)
 *   phi(IP) from the bilinear fit phi = w1 + w2 x + w3 y + w4 x y through the
 *   four cell centres around IP; a node that is not fluid is replaced by its
 *   own wall point with a Dirichlet row [1 x y xy] = phi_wall (Eqs. 35, 37)
 *   or a Neumann row [0 n_x n_y x n_y + y n_x] = 0 (Eqs. 36, 38)      (Eq. 34)
 *   Dirichlet: phi_GC = 2 phi_BI - phi_IP                                (Eq. 39)
 *   Neumann (zero normal gradient): phi_GC = phi_IP.
 * Variables: velocity Dirichlet (no slip: the wall velocity, linear along a
 * segment between its markers, Eq. 32); temperature Dirichlet on isothermal
 * walls, Neumann on adiabatic ones; pressure Neumann; density from the gas
 * law rho = p / (R T). stencil.c documents the degenerate cases.
 *
 * Use from a time loop (fixed bodies):
 *     ibm_create(&ibm, gks_solver_grid(s), bodies, count);   // tags, stencils
 *     ibm_attach(ibm, s);           // writes the cell kinds, sets the ghost hook
 *     loop: gks_solver_step(s, dt) // the hook fills the ghost cells
 *           ibm_surface_compute(...) when loads or outputs are due (wall_loads.h)
 * Moving or deforming bodies: before each flow step, ibm_update(ibm, bodies,
 * count, s) with the polylines at their new positions (same count of bodies;
 * wall velocities per marker): it re-tags only the cells swept by moved
 * segments, rebuilds only the stencils that read moved geometry, fills the
 * cells uncovered by the bodies ("fresh" cells) from their fluid neighbours
 * and writes the new kinds into the solver.
 *
 * Ownership: the Ibm borrows the grid (the solver's) for its lifetime and
 * copies the markers. Thread safety: one Ibm per solver; ibm_fill_ghosts is
 * OpenMP-parallel over ghost cells for large sets and deterministic (each
 * ghost value is a fixed-order function of fluid cells only). The fill
 * allocates nothing. */
#ifndef NSPD_COUPLE_GHOST_IBM_H
#define NSPD_COUPLE_GHOST_IBM_H

#include "couple/ghost/markers.h"
#include "flow/gks/solver.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct Ibm Ibm;

/* How a stencil was built (stencil.c: degenerate cases). */
typedef enum {
    IBM_LEVEL_IMAGE = 0,    /* Eq. 31 image point, bilinear with wall rows (cases 1-3) */
    IBM_LEVEL_EXTENDED = 1, /* image point moved out along the normal; linear extrapolation */
    IBM_LEVEL_NEAREST = 2,  /* inverse-distance mean of nearby fluid cells (last resort) */
    IBM_LEVEL_COUNT
} IbmStencilLevel;

/* Counts of the current ghost set and of the last build or update. */
typedef struct {
    int ghosts;
    int by_level[IBM_LEVEL_COUNT];
    int by_case[3];        /* IMAGE level: 0, 1, 2 replaced nodes (the paper's cases 1, 2, 3) */
    double max_weight_sum; /* max over ghosts of sum |w| (Dirichlet and Neumann) */
    int64_t solid_cells;
    /* last ibm_update (zero after ibm_create) */
    int64_t retagged; /* cells whose inside/outside test was redone */
    int changed;      /* cells whose inside flag changed */
    int fresh;        /* cells that became fluid (filled from their neighbours) */
    int rebuilt;      /* ghost stencils built */
    int kept;         /* ghost stencils kept from the previous geometry */
    double seconds;   /* wall time of the build or update */
} IbmUpdateStats;

/* Builds tags, ghost list, ghost stencils and surface probes for `count`
 * closed counter-clockwise polylines on `grid` (borrowed; must outlive the
 * Ibm). Bodies should stay >= 3 cells inside the box; a stencil that would
 * reach beyond the first box ghost layer falls back (see stencil.c).
 * NSPD_ERR_INPUT for invalid polylines, NSPD_ERR_NOMEM. */
int ibm_create(Ibm **out, const Grid *grid, const IbmPolyline *bodies, int count);
void ibm_destroy(Ibm **ibm);

/* Writes the cell kinds into the solver (whose grid must be the Ibm's),
 * installs ibm_fill_ghosts as its ghost hook and fills the ghost cells once
 * (so that outputs before the first step show them). Fluid cells keep their
 * state. NSPD_ERR_INPUT if the grids differ. */
int ibm_attach(Ibm *ibm, GksSolver *s);

/* Moves the walls to `bodies` (same body count as at creation; a body's
 * marker count may change, which re-tags its whole old and new bounding
 * box). Cost ~ cells swept by moved segments + ghost cells. If `s` is not
 * NULL, writes the changed kinds into it and fills fresh cells (cells that
 * were not fluid and now are): their velocity (and temperature on
 * isothermal walls) by the Dirichlet stencil at the cell centre with the
 * fresh cells themselves replaced by wall points, pressure (and adiabatic
 * temperature) by the Neumann stencil, density by the gas law. The result is
 * bitwise the same as ibm_create with the new walls.
 * May reallocate: the Ibm's marker, bucket, stencil and work arrays grow
 * (by doubling where they are lists) when the new walls need more room, so
 * a time loop allocates only while the walls grow; never shrinks. Pointers
 * from ibm_body_markers_view are invalid afterwards. NSPD_ERR_NOMEM then
 * leaves the Ibm fit only for ibm_destroy. */
int ibm_update(Ibm *ibm, const IbmPolyline *bodies, int count, GksSolver *s);

/* Soft start: in every fluid cell within `length` (m) of a wall, replaces
 * the velocity u by u_w + (u - u_w) f(d / length), f(z) = z^2 (3 - 2 z) (d
 * the distance to the nearest wall point, u_w the wall velocity there).
 * ibm_soft_start keeps density and pressure; ibm_soft_start_isentropic keeps
 * total enthalpy and entropy (the state of a steady isentropic slow-down:
 * T = T_0 - |u|^2 / (2 c_p), p = p_old (T / T_old)^(gamma / (gamma - 1))).
 * An impulsively started body in a supersonic stream otherwise empties the
 * cells behind it within a few steps (measured: the Mach 2 cylinder at D/32
 * reached rho = 3e-4 rho_inf at the rear stagnation point at t = 0.03 D/c and
 * stopped); brought to the wall velocity smoothly, the start is benign.
 * Both variants start an acoustic transient; on the Ma 0.5 airfoil neither
 * settled faster (the slow part was the transient's return from a far field
 * 10 chords away). Call after ibm_attach and before the first step. */
void ibm_soft_start(Ibm *ibm, GksSolver *s, double length);
void ibm_soft_start_isentropic(Ibm *ibm, GksSolver *s, double length);

/* What the faces between fluid and ghost cells carry.
 *   REFLECTED  the GKS flux between the fluid cell and the ghost state of
 *              Eq. 39, as in the paper: second order at the wall, but not
 *              conservative, and a fluid cell whose centre sits on the wall
 *              can drain into the body where the image point sees faster
 *              or opposite flow (measured: the Ma 2 cylinder from rest at
 *              D/128 reached p < 0 at t = 2.95 in a cell 0.04 h from the
 *              wall, in reversed flow ahead of separation).
 *   SEALED     no mass but what the wall displaces (gks_solver_set_ghost_walls):
 *              conservative and robust; the mass sees the cell staircase,
 *              a first-order wall (measured: stagnation Cp on a nose of 6
 *              cells' radius erratic by +-4 to 10 %; on a cylinder of 8
 *              cells' radius within 0.1 %). */
typedef enum { IBM_FACES_REFLECTED = 0, IBM_FACES_SEALED, IBM_FACES_COUNT } IbmGhostFaces;
extern const char *const IBM_GHOST_FACE_NAMES[IBM_FACES_COUNT + 1]; /* "reflected", "sealed" */

/* Default REFLECTED; takes effect at the next fill. */
void ibm_set_ghost_faces(Ibm *ibm, IbmGhostFaces faces);

/* The FlowGhostHook (ctx = the Ibm): sets every ghost cell from the current
 * fluid state (Eqs. 33-39); with SEALED faces, hands the solver each
 * ghost's wall velocity. No allocation; deterministic. */
void ibm_fill_ghosts(void *ctx, GksSolver *s);

/* Cell kinds (FLOW_CELL_*), indexed with grid_index (interior cells). */
const uint8_t *ibm_kinds(const Ibm *ibm);
void ibm_stats(const Ibm *ibm, IbmUpdateStats *out);

int ibm_body_count(const Ibm *ibm);
int ibm_segment_count(const Ibm *ibm);
/* The current markers of body b (pointers into the Ibm, valid until the
 * next update). Its segment k (marker k to k+1) has the global number
 * first + k, first = the markers of the bodies before it: the order of the
 * per-segment arrays of wall_loads.h. */
void ibm_body_markers_view(const Ibm *ibm, int b, int *count, const double **x, const double **y);

/* One ghost cell's stencil, for tests and diagnostics. */
typedef struct {
    int64_t cell;
    int i, j;
    int level;    /* IbmStencilLevel */
    int replaced; /* nodes replaced by wall points */
    int body;     /* body of its wall point */
    int segment;  /* global segment of its wall point */
    double bi[2], normal[2], dist;
    double point[2];     /* image point (or the extended one) */
    double ratio;        /* phi_GC = phi_BI + ratio (phi_BI - phi_P) for Dirichlet variables */
    int64_t node[4];     /* fluid nodes (-1 where replaced or unused) */
    int node_segment[4]; /* replaced: the segment of its wall point, else -1 */
    double wd[4], wn[4]; /* weights */
} IbmGhostInfo;

int ibm_ghost_count(const Ibm *ibm);
void ibm_ghost_info(const Ibm *ibm, int g, IbmGhostInfo *out);
/* Index of the ghost at interior cell (i, j), or -1. */
int ibm_find_ghost(const Ibm *ibm, int i, int j);

/* ------------------------------------------------------------ kernels */

/* The bilinear weights of Eqs. 34-38 (kernel; exposed for unit tests).
 * Nodes are the four corners (0,0), (1,0), (0,1), (1,1) of the unit square
 * (coordinates scaled by the cell-centre spacings hx, hy); fluid[m] = 0
 * replaces node m by the wall point (bx[m], by[m]) (same scaled coordinates)
 * with outward normal (nx[m], ny[m]) (physical). Writes the weights of the
 * value at (px, py): Dirichlet wd (phi_P = sum_m wd[m] phi_m, phi_m the wall
 * value for replaced nodes) and Neumann wn (the weights of replaced nodes
 * multiply the prescribed normal derivative, zero here). Returns 0, or -1 if
 * either 4x4 system is singular (pivot below 1e-10 of the largest entry). */
int ibm_bilinear_weights(double px, double py, double hx, double hy, const int fluid[4],
                         const double bx[4], const double by[4], const double nx[4],
                         const double ny[4], double wd[4], double wn[4]);

#endif
