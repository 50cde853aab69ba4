/* The lattice view of a bond-based body (issue 27): the force read as a
 * stencil, eight points at a time.
 *
 * Every body is a set of lattice points (solid/pd/lattice.h), so a point's
 * bonds reach its neighbours at a few fixed lattice offsets (28 in 2D and
 * 122 in 3D for a horizon of 3.015 dx). The view copies the points into a
 * box of lattice cells, padded by the reach of the offsets, whose fastest
 * axis is the body's longest (the major axis; then the others in order):
 * eight cells side by side along it are eight points, and their
 * neighbours at one offset are eight cells side by side too, read by one
 * contiguous load (no gather, no transpose). A thin panel standing along y
 * so fills its lanes. Each point sums its bonds in offset order (dz, then
 * dy, then dx), and the rows of the body's bonds are kept in the same
 * order (body.c), so the plain kernels (bond_force_point_2d / _3d, a
 * sequential sum over the row) give the same bits: they stay the
 * reference, and the CUDA back end's kernels.
 *
 * Cells are grouped in chunks of eight along the major axis (aligned to
 * the box); the chunks holding a point of this process are the active
 * ones, the only ones the force visits. Per active chunk the bond
 * coefficients of its eight cells, offset by offset (coef[(chunk offsets
 * + o) 8 + lane]), a copy of the bonds' own (body.h: sign = failure
 * state), taken with the build and again whenever `stale`. A cell with no
 * point, or a point's missing bond, has 0 there (a broken bond: no force).
 * Cells with no point hold their lattice position and no displacement, so
 * that every load is of a finite number.
 *
 * Memory: a cell's x and u (32 bytes in 2D, 48 in 3D), 4 bytes for its
 * point, 8 a point for the map back, and 4
 * bytes an offset of an active chunk's cell (about 4 a bond). A body
 * whose box holds more than 8 cells a point (a thin ring, a shell, a
 * scattered set) gets no view: pd_force_compute then runs the plain
 * kernel, with the same bits. */
#ifndef NSPD_SOLID_BOND_STENCIL_H
#define NSPD_SOLID_BOND_STENCIL_H

#include "solid/bond/body.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct BondStencil {
    int dim;
    int reach;           /* R: every offset within [-R, R]^dim lattice spacings */
    int offsets;         /* m: the offsets any bond of the body takes */
    int64_t *shift;      /* m: cell index of the neighbour minus the cell's, in offset order */
    int32_t *offset_of;  /* (2R + 1)^dim: offset index of (dx, dy, dz) at
                            ((dz + R)(2R + 1) + dy + R)(2R + 1) + dx + R (dz = 0 in 2D); -1 */
    int major;           /* the axis along which a chunk's cells lie: the body's longest */
    int64_t extent[3];   /* cells along each axis (major: a multiple of 8; 1 past dim) */
    int64_t stride[3];   /* cell index step along each axis (1 along major) */
    int64_t cells;       /* extent[0] extent[1] extent[2] */
    int32_t origin[3];   /* lattice indices of cell 0 */
    int64_t chunks;      /* active chunks */
    int64_t *chunk_cell; /* first cell of each active chunk */
    double *x[3];        /* per cell: reference position (z: NULL in 2D) */
    double *u[3];        /* per cell: displacement (pd_force_compute refreshes) */
    float *coef;         /* per active chunk, offsets x 8: the bonds' coefficients */
    int32_t *cell_point; /* per cell: the point there (held or ghost), or -1 */
    int64_t *point_cell; /* per point, held and ghosts: its cell */
    bool stale;          /* coef to be taken from the bonds before the next force */
} BondStencil;

/* Sorts each row of the body's bonds into offset order (dz, then dy, then
 * dx, of the neighbour's lattice indices less the point's): the order the
 * view sums in. */
void bond_rows_in_offset_order(BondBody *body);

/* Builds the view of a body (held points and ghosts, their bonds'
 * coefficients taken) into *out, or leaves *out NULL when the box would
 * hold more than 8 cells a point or 2^31 cells. NSPD_ERR_NOMEM. */
int bond_stencil_create(const BondBody *body, BondStencil **out);
void bond_stencil_free(BondStencil **s);

/* Brings the view up to the body: the coefficients when stale, and the
 * displacements of every point, held and ghosts (what the force and the
 * elastic energy do first). */
void bond_stencil_refresh(BondStencil *s, const BondBody *body);

#endif
