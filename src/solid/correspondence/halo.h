/* A correspondence body divided between processes (issue 28: a solid
 * alone on several ranks), bitwise the run of one process.
 *
 * Every rank places the whole body's points (the lattice) but finds the
 * families of its run of points in the Morton order and of the points
 * they reach only (body.c), so no rank holds the whole body's bonds; it
 * keeps the run and, as ghosts, the points its bonds reach (the point
 * halo of solid/pd/halo.h, as the bond-based body), and frees the rest.
 * The whole numbering that outputs and checkpoints need is formed from
 * the parts: a bond's whole index from its point's first bond in the
 * whole numbering (the runs' bond counts gathered, the ghosts' asked of
 * their owners), a pair's from the counts of the pairs canonical in each
 * run (a crossing pair's from the rank where its canonical bond lies).
 * The build goes on with the part alone (kernel, RK weights, the settling of
 * the pre-cracks, the stable step: all through the exchanges below, so
 * the same bits as one process).
 *
 * What a step takes from the owners (cpd_step):
 * - u of the ghosts after every drift (u_prev: the ghosts' u at the
 *   step's start);
 * - F of the ghosts after the force's first pass (and F at u_prev where
 *   it is formed), and S before the last (BacSystem.exchange);
 * - when damage grew: the ghosts' ok flags at each pass of the settling,
 *   their 1 / w0 and dirty flags, and, per bond that crosses (i -> j, j a
 *   ghost), the RK weight phi_ji of its reverse bond, which j's owner holds
 *   (the bonds' halo: the reverse bonds are its "ghosts").
 * A pair that crosses has no reverse bond on either rank, so each keeps
 * it as a pair of its own; both form the same F_b (negated operands: the
 * same bits) and advance the same J2 state. Whether damage grew, the
 * settling's loop and a numerical failure are decided by all ranks
 * together (integers: exact); the stable step's dot products and the
 * diagnostics' sums gather the terms in the whole body's order.
 *
 * The classic force is divided too: its state is per point, so a ghost's
 * T_ji (formed from the ghost's own F and P) is its owner's, asked of it
 * after the T pass through the bonds' halo (cpd_halo_bonds; a crossing
 * bond's reverse[] points past the run's bonds, where that puts it), and
 * the damage law reads the ghosts' plastic strain, principal stress and
 * inversion flag, exchanged before it. */
#ifndef NSPD_SOLID_CORRESPONDENCE_HALO_H
#define NSPD_SOLID_CORRESPONDENCE_HALO_H

#include "solid/correspondence/body.h"
#include "solid/pd/halo.h"

typedef struct CpdHalo {
    PointHalo points; /* the run of points, its ghosts and their exchange */
    /* the run of bonds (the rows of the run's points, the whole body's
     * [bonds.first, ...)); its "ghosts": the reverse bonds of the bonds
     * that cross, exchanged as the RK weights phi (dim a bond) */
    PointHalo bonds;
    int64_t *cross_bond;  /* per reverse bond asked, the local bond it is the reverse of */
    int64_t *cross_point; /* and that bond's point */
    /* the pairs: per local pair its index among the whole body's, and
     * whether its canonical bond lies in this run (the checkpoint's) */
    int64_t pairs_total;
    int64_t *pair_whole;
    uint8_t *pair_here;
} CpdHalo;

/* Keeps this rank's part of the whole body `b`, which holds only its
 * points (x, lattice) and families (first, nbr, reverse, pairs) so far
 * (see above; body.c's build). Nothing on one process. NSPD_ERR_INPUT:
 * fewer points than processes; NSPD_ERR_NOMEM. */
int cpd_body_divide(CpdBody *b, const NspdComm *comm);
void cpd_halo_free(CpdHalo **h);

/* The ghosts' entries of `count` per-point arrays of `bytes` a point
 * (collective; nothing on one process). */
void cpd_halo_exchange(CpdBody *b, void *const *arrays, int count, size_t bytes);

/* Of a per-bond array of dim doubles a bond (room for the run's bonds and
 * then one per bond that crosses): the reverse bonds of the crossing bonds,
 * from their owners, after the run's (collective; nothing on one process).
 * The classic force's T_ji; its reverse[] points there. */
void cpd_halo_bonds(CpdBody *b, double *per_bond);

/* phi_rev of the bonds that cross from their owners' RK weights
 * (collective; after the weights or the damage changed). */
void cpd_halo_reverse_weights(CpdBody *b);

/* Integer sum and max over the ranks (the value itself on one process). */
int64_t cpd_halo_sum(const CpdBody *b, int64_t mine);
double cpd_halo_max(const CpdBody *b, double mine);

/* The whole body's `width` values a point in its order: this rank's n
 * points' `mine` gathered in rank order into a new array (nspd_alloc'd;
 * the caller frees it), or on one process a copy. NULL: no memory. */
double *cpd_halo_whole(const CpdBody *b, const double *mine, int width);

/* The whole body's rows of intact bonds (damage < 1), neighbours by whole
 * index: *first (points + 1) and *nbr, new arrays the caller frees (the
 * ranks' rows gathered in rank order). NSPD_ERR_NOMEM. */
int cpd_halo_intact_rows(const CpdBody *b, int64_t **first, int64_t **nbr);

/* Whole-body counts: points, stored bonds. */
int64_t cpd_whole_points(const CpdBody *b);
int64_t cpd_whole_bonds(const CpdBody *b);

/* Checkpoint records in the one process's layout: a per-point array
 * (ghosts read back too), a per-bond one (the run's rows), and a per-pair
 * one of `components` arrays of the pairs, component c of pair p at
 * state + size (c pairs.count + p). */
int cpd_halo_io_points(CpdBody *b, Checkpoint *ck, const char *name, void *mine, size_t size);
int cpd_halo_io_bonds(CpdBody *b, Checkpoint *ck, const char *name, void *mine, size_t size);
int cpd_halo_io_pairs(CpdBody *b, Checkpoint *ck, const char *name, void *state, size_t size,
                      int components);

#endif
