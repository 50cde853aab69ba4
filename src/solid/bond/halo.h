/* A bond-based body divided between processes (issue 28: a solid alone on
 * several ranks).
 *
 * Every rank places the whole body's points and finds the bonds of its
 * part (bond_body_create_divided), then keeps a contiguous run of its
 * points in the Morton order, rank r of P the points
 * [N r / P, N (r + 1) / P): Morton runs are compact patches of the body,
 * so few bonds cross. Its points come first (BondBody.n of them, in the
 * whole body's order), then the ghosts: every point a bond of its own
 * reaches that another rank holds, in the whole body's order
 * (BondBody.ghosts of them). Ghosts keep positions, volumes and a
 * displacement that the owner sends after every drift; they have no bonds
 * of their own (empty rows), so the force kernel, the integrator and the
 * diagnostics, which loop over the first n points, run unchanged.
 *
 * Bitwise the one-process run: a point's bonds keep their order (only the
 * neighbour indices are renumbered), the force sums them by their place in
 * the row (2D: one after another in offset order, the lattice view's
 * lanes being points, stencil.h; 3D: SIMD lanes by position in the row,
 * not by address, checked with -fopt-info-vec: no peeling), and each
 * point reads the same neighbour values. Both ends of a crossing bond break together, as they do on
 * one process, because both evaluate the same stretch.
 *
 * Every rank places the whole body's points (lattice, order, regions:
 * some 150 bytes a point) but finds the bonds only of its run and of its
 * ghosts (bond_body_create_divided), so the bonds' memory, the most of a
 * body, is the part's from the start; what a step holds afterwards is the
 * rank's part. */
#ifndef NSPD_SOLID_BOND_HALO_H
#define NSPD_SOLID_BOND_HALO_H

#include "core/comm.h"
#include "solid/bond/body.h"
#include "solid/pd/halo.h"

#include <stdint.h>

typedef struct BondHalo {
    PointHalo points;   /* the run, the ghosts and their exchange (solid/pd/halo.h) */
    int64_t bond_first; /* the whole body's index of bond 0 */
    int64_t bonds;      /* bonds of the whole body (each stored from both ends) */
} BondHalo;

/* Keeps this rank's part of the whole body `b` (see above) and its halo.
 * Nothing on one process. NSPD_ERR_NOMEM; NSPD_ERR_INPUT when there are
 * fewer points than processes. */
int bond_body_divide(BondBody *b, const NspdComm *comm);
void bond_halo_free(BondHalo **h);

/* The ghosts' displacements from their owners (collective). */
void bond_halo_exchange(BondBody *b);

/* The whole body's index of local point i (owned or ghost). */
int64_t bond_halo_global(const BondBody *b, int64_t i);

#endif
