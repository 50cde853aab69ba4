/* The point halo of a PD body divided between processes (issue 28), the
 * one both solids use (solid/bond/halo.h, solid/correspondence/halo.h);
 * the correspondence solid's bonds use it too (items instead of points:
 * each rank a run of the whole body's bonds, its "ghosts" the reverse
 * bonds of the bonds that cross).
 *
 * Rank r of P holds the contiguous run [N r / P, N (r + 1) / P) of the
 * whole body's N points in their Morton order (compact patches, so few
 * bonds cross), first its own points, then its ghosts: the points its
 * bonds reach that other ranks hold, sorted by their whole-body index
 * (hence by owner). A ghost has no bonds; its values are its owner's,
 * copied in by point_halo_exchange, one message per partner rank. */
#ifndef NSPD_SOLID_PD_HALO_H
#define NSPD_SOLID_PD_HALO_H

#include "core/checkpoint.h"
#include "core/comm.h"

#include <stddef.h>
#include <stdint.h>

typedef struct PointHalo {
    NspdComm comm;
    int64_t first;      /* the whole body's index of point 0 */
    int64_t total;      /* points of the whole body */
    int64_t n;          /* points owned */
    int64_t ghosts;     /* ghosts, after the owned points */
    int64_t *ghost;     /* per ghost, its index in the whole body */
    int64_t *run_first; /* per rank, its run's first point; the whole count last */
    /* the plan: per rank q, the points sent to q (local indices, grouped
     * by q) and the ghosts received from q (a run of the ghosts), in
     * points; the byte counts are formed at each exchange */
    int64_t sends;
    int64_t *send_point;
    int *send_count, *send_from, *recv_count, *recv_from;
    int *send_bytes, *send_at, *recv_bytes, *recv_at;
    unsigned char *send_buf, *recv_buf;
    size_t max_bytes; /* per point, the most one exchange carries */
    double seconds;   /* wall time in the exchanges and the step's reductions so far */
} PointHalo;

/* The first point of rank r's run when `total` points are divided
 * evenly over p ranks (what the solids do). */
int64_t point_halo_run_start(int64_t total, int p, int r);

/* The halo of this rank's run of n points (the runs lie in rank order)
 * with `ghosts` ghosts (their whole-body indices, sorted, copied): a
 * gather of the runs' lengths and of the counts asked, and one exchange
 * of the indices (collective). An exchange carries at most max_bytes per
 * point. NSPD_ERR_NOMEM. */
int point_halo_plan(PointHalo *h, const NspdComm *comm, int64_t n, int64_t ghosts,
                    const int64_t *ghost, size_t max_bytes);
void point_halo_free(PointHalo *h);

/* The ghosts' entries of `count` per-point arrays, `bytes` per point
 * each (point i's at arrays[c] + bytes i), from their owners: one message
 * per partner (collective; count * bytes at most max_bytes). */
void point_halo_exchange(PointHalo *h, void *const *arrays, int count, size_t bytes);

/* Replaces *array (elements of `size` bytes; nothing when NULL) by its
 * elements at from[k], k < n: a whole body's per-point or per-bond array
 * cut to a rank's part. NSPD_ERR_NOMEM. */
int point_halo_take(void *array, size_t size, const int64_t *from, int64_t n);

/* One per-item array in a checkpoint as the whole body's, so that a
 * checkpoint is the same on any number of processes and any other reads
 * it: this rank's run of n items, the whole body's [first, first + n) of
 * `total`, gathered in rank order on writing; on reading each rank cuts
 * out its run and, where ghost is not NULL, its `ghosts` ghosts' values
 * (ghost[g]: the whole body's index of item n + g). `size` bytes an item. */
int halo_checkpoint_io(const NspdComm *comm, int64_t first, int64_t n, int64_t total,
                       const int64_t *ghost, int64_t ghosts, Checkpoint *ck, const char *name,
                       void *mine, size_t size);

/* The local numbering of a run [lo, hi) of `total` points whose rows
 * first[lo] .. first[hi] of nbr (whole-body indices) reach other points:
 * *local[g] the local index of whole point g (the run first, then its
 * ghosts in the whole body's order; -1 not kept), *ghost the ghosts'
 * whole indices, *from the whole index of each local point; new arrays
 * (nspd_alloc) the caller frees. NSPD_ERR_NOMEM. */
int point_halo_number(int64_t total, int64_t lo, int64_t hi, const int64_t *first,
                      const int32_t *nbr, int64_t **local, int64_t **ghost, int64_t **from,
                      int64_t *ghosts);

/* The whole body's index of local point i (owned or ghost). */
int64_t point_halo_global(const PointHalo *h, int64_t i);

#endif
