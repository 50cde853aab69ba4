/* The isogeometric flow divided between processes (issue 58).
 *
 * The elements are divided into blocks over the Cartesian process grid
 * that the GKS flow's cells use (core/blocks.h). Control point k along
 * an axis belongs to the block of element k (the p last points of an
 * open axis to the last block), so each block owns a rectangle of
 * control points. A process stores a window of them: its own and `halo`
 * more on each side (clipped at an open axis's ends), the points the
 * elements touching its own points reach (halo p) and, for the convex
 * limiter, the points its pair fluxes reach (3 p: the low-order rate of
 * a neighbour's neighbour, then the pair factors of both sides). Every
 * kernel runs on the window's local indices unchanged; what lies on the
 * window's rim is wrong and never read for an owned point. After each
 * update of the owned points the halo is copied in from its owners
 * (iga_decomp_exchange: one message per partner).
 *
 * On one process, or along an axis of one block, the window is the whole
 * axis and a periodic axis wraps on local indices as it always has, so a
 * run on one process is the code path it was. Every per-point sum goes
 * over the point's elements in ascending global order, and totals are
 * exact sums (core/exact_sum.h): the same bits on any number of
 * processes. */
#ifndef NSPD_FLOW_IGA_DECOMP_H
#define NSPD_FLOW_IGA_DECOMP_H

#include "core/blocks.h"
#include "core/comm.h"
#include "flow/iga/space.h"

#include <stdbool.h>
#include <stdint.h>

/* Blocks along an axis at most (a checkpoint's cuts live on the stack). */
enum { IGA_MAX_BLOCKS = 1024 };

/* One axis of this process's window. */
typedef struct {
    int count;    /* the axis's control points */
    int elements; /* the axis's elements */
    int degree;
    bool periodic;
    int parts, part;    /* blocks along the axis, this process's */
    bool whole;         /* the window is the whole axis (one block) */
    int w0, n;          /* the window: global point w0 + l (mod count) at local l, n points */
    int own0, own;      /* this block's points: local [own0, own0 + own) */
    int *global;        /* [n]: the global point of local point l */
    int *local;         /* [count]: the local point of a global one, -1 */
    int ne;             /* local elements: those whose points all lie in the window */
    int *element;       /* [ne]: the global element of local element le */
    int *local_element; /* [elements]: the local element of a global one, -1 */
    int *sorted;        /* [ne]: the local elements in ascending global order */
    int e0, en;         /* the local elements that touch an own point: [e0, e0 + en) */
} IgaWindowAxis;

typedef struct {
    NspdComm comm;
    int dims[2];
    IgaWindowAxis ax[2];
    /* the halo's plan: per rank, the points asked of it (their local
     * indices here, grouped by rank) and those it asks of this process
     * (local indices here) */
    int64_t asks, tells;
    int64_t *ask_local, *tell_local;
    int *ask_count, *tell_count;
    int *bytes; /* 4 per rank: send bytes and offsets, receive bytes and offsets */
    double *send, *recv;
    int max_width;  /* doubles per point an exchange carries at most */
    double seconds; /* wall time in exchanges and reductions so far */
} IgaDecomp;

/* This process's share of the axes (comm NULL or of one: the whole), with
 * `halo` points around its own; `processes` as FlowConfig's ({0, 0}: the
 * fewest halo points). NSPD_ERR_INPUT for a grid the group cannot
 * divide (blocks narrower than the halo, or a periodic axis too short
 * for its window), NSPD_ERR_NOMEM. Collective. */
int iga_decomp_create(IgaDecomp *d, const NspdComm *comm, const int processes[2],
                      const IgaAxis ax[2], int halo, int max_width);
void iga_decomp_destroy(IgaDecomp *d);

static inline bool iga_decomp_divided(const IgaDecomp *d) {
    return comm_distributed(&d->comm);
}

/* This block's own elements along the axis: global [*lo, *hi). */
static inline void iga_window_own_elements(const IgaWindowAxis *w, int *lo, int *hi) {
    *lo = blocks_cut(w->elements, w->parts, w->part);
    *hi = blocks_cut(w->elements, w->parts, w->part + 1);
}

/* The local element's function a: its local point along the axis. */
static inline int iga_window_function(const IgaWindowAxis *w, int le, int a) {
    const int k = le + a;
    return w->whole && w->periodic ? k % w->count : k;
}

/* Whether local point (i, j) is this process's own. */
static inline bool iga_decomp_owns(const IgaDecomp *d, int i, int j) {
    return i >= d->ax[0].own0 && i < d->ax[0].own0 + d->ax[0].own && j >= d->ax[1].own0 &&
           j < d->ax[1].own0 + d->ax[1].own;
}

/* The local index of global control point g (= gi + count_x gj), -1 off
 * the window. */
int64_t iga_decomp_local(const IgaDecomp *d, int64_t g);

/* The global index of local point k. */
int64_t iga_decomp_global(const IgaDecomp *d, int64_t k);

/* The rank that owns global control point g. */
int iga_decomp_owner(const IgaDecomp *d, int64_t g);

/* The rank whose block holds global element (ex, ey). */
int iga_decomp_element_owner(const IgaDecomp *d, int ex, int ey);

/* The owned points' local index q-th in row-major order over the owned
 * rectangle (q < own_x own_y). */
static inline int64_t iga_decomp_owned(const IgaDecomp *d, int64_t q) {
    const int ox = d->ax[0].own;
    return d->ax[0].own0 + (int)(q % ox) + (int64_t)d->ax[0].n * (d->ax[1].own0 + (int)(q / ox));
}

static inline int64_t iga_decomp_owned_count(const IgaDecomp *d) {
    return (int64_t)d->ax[0].own * d->ax[1].own;
}

/* The halo points' values of `count` per-point arrays of `width` doubles
 * each (count width <= max_width) from their owners (collective; nothing
 * on one process). */
int iga_decomp_exchange(IgaDecomp *d, double *const *arrays, int count, int width);

/* Each rank's owned block of a per-item array (`width` doubles an item)
 * gathered into the whole array `whole` (row-major over n[0] x n[1]
 * items) of every rank (all_ranks) or of rank 0, the blocks cut along
 * each axis at cut[a][c] (dims[a] + 1 entries); mine: this rank's block
 * row-major. One gather. */
int iga_decomp_gather(IgaDecomp *d, const int n[2], int *const cut[2], const double *mine,
                      int width, double *whole, bool all_ranks);

/* The cuts of an axis's blocks for items that number n_items (elements:
 * `elements`; control points: count; corners: elements + 1): block c's
 * first item, the last entry n_items. */
void iga_decomp_cuts(const IgaDecomp *d, int axis, int n_items, int *cut);

#endif
