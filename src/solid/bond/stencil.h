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
 * ones, the only ones the force visits. Per active chunk and offset the
 * bonds' state, two bytes (a bit a lane): bonded (the bond is there and
 * intact) and breakable (body.h: the coefficient's sign). Their
 * coefficients' magnitudes are a block of offsets x 8 floats: away from
 * the body's surfaces the magnitude of a bond depends on its offset only
 * (the corrections: surface.h), so most chunks share block 0, one value
 * an offset repeated in the eight lanes, and only the chunks near a
 * surface (9 % of the paper's plate) have a block of their own. The
 * force so streams about half a byte a bond on the plate (a quarter of
 * state, and the own blocks), not the four of a float coefficient: that
 * stream, not the arithmetic, had set the kernel's
 * pace (a prototype of the loop on the plate: 1.3e9 bonds/s with a
 * float a bond streamed, 2.0e9 with the coefficients in cache).
 * Everything is taken from the bonds with the build and again by
 * bond_stencil_take (after a checkpoint read). A cell with no point, or
 * a point's missing or broken bond, is not bonded: no force. Cells with
 * no point hold their lattice position and no displacement, so that
 * every load is of a finite number.
 *
 * Memory: a cell's x and u (32 bytes in 2D, 48 in 3D), 4 bytes for its
 * point, 4 a point for the map back, 2 bytes an offset of an active
 * chunk and 4 an offset of a cell of a chunk with its own block (about
 * 0.6 a bond on the plate). A body
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
    double *u[3];        /* per cell: displacement (pd_step's drift writes it beside the
                            body's, or pd_force_compute copies it: u_current) */
    uint16_t *state;     /* per active chunk, per offset: bit l bonded, bit 8 + l breakable */
    int32_t *block;      /* per active chunk: its block of magnitudes (0: the shared one) */
    float *magnitude;    /* blocks x offsets x 8: |coefficient| of each lane's bond */
    int32_t *cell_point; /* per cell: the point there (held or ghost), or -1 */
    int32_t *point_cell; /* per point, held and ghosts: its cell */
    bool u_current;      /* u holds the body's: pd_step's drift wrote both and the ghosts
                            were copied; the next force takes it as it is, and clears this */
} BondStencil;

/* Sorts each row of the body's bonds into offset order (dz, then dy, then
 * dx, of the neighbour's lattice indices less the point's): the order the
 * view sums in. */
void bond_rows_in_offset_order(BondBody *body);

/* Builds the view of a body (held points and ghosts, their bonds
 * taken) into *out, or leaves *out NULL when the box would
 * hold more than 8 cells a point or 2^31 cells. NSPD_ERR_NOMEM. */
int bond_stencil_create(const BondBody *body, BondStencil **out);
void bond_stencil_free(BondStencil **s);

/* Takes the bonds' state and magnitudes from the body's rows again (after
 * whoever writes bond_coef other than the force: a checkpoint read), and
 * the displacements before the next force. NSPD_ERR_NOMEM (the view is
 * then left as it was). */
int bond_stencil_take(BondStencil *s, const BondBody *body);

/* Brings the view's displacements up to the body's: every point's, held
 * and ghosts (what the force does first, unless u_current, and the
 * elastic energy), or the ghosts' only (after a halo exchange). */
void bond_stencil_refresh(BondStencil *s, const BondBody *body);
void bond_stencil_refresh_ghosts(BondStencil *s, const BondBody *body);

#endif
