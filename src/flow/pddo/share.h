/* The PDDO flow on several processes (issue 58).
 *
 * Every rank keeps the whole cloud, its operators and whole state arrays;
 * each computes its own contiguous range of the operators' slices
 * (pddo_ops_cut: ranges of about equal cost, as the threads of one
 * process share theirs) and, after each update, sends its range to the
 * others (comm_share_ranges). Every node's value is computed by the same
 * code on the same data as on one process, so the explicit part of a
 * step, and whatever reads the whole state after it (forces, outputs,
 * probes, checkpoints), is the same bits at any rank count.
 *
 * This divides the work, not the memory: each rank holds O(nodes) state
 * and the whole operators, and each share moves a whole array. It is the
 * right trade on one node or a few (the paper's cylinder: 122,833 nodes,
 * 1 MB an array); a cloud beyond one node's memory needs owned nodes with
 * a horizon's ghost layer instead (docs/ARCHITECTURE.md). */
#ifndef NSPD_FLOW_PDDO_SHARE_H
#define NSPD_FLOW_PDDO_SHARE_H

#include "core/comm.h"
#include "flow/pddo/operators.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct {
    NspdComm comm;
    int64_t lo, hi;  /* this rank's nodes */
    int *count, *at; /* per rank, its nodes' count and first node (comm_share_ranges) */
} PddoShare;

/* Cuts the operators' slices among the group's ranks and gives this rank
 * its own (ops->own_lo, own_hi). share is zeroed or freed before.
 * NSPD_ERR_INPUT for more ranks than slices; NSPD_ERR_NOMEM. */
int pddo_share_init(PddoShare *share, PddoOps *ops, const NspdComm *comm);

/* Whether the flow is divided (a group of several). */
static inline bool pddo_share_divided(const PddoShare *share) {
    return share && comm_distributed(&share->comm);
}

/* This rank's nodes [*lo, *hi) of n: its range, or all of them on one
 * process (share NULL or not divided). */
static inline void pddo_share_nodes(const PddoShare *share, int64_t n, int64_t *lo, int64_t *hi) {
    const bool divided = pddo_share_divided(share);
    *lo = divided ? share->lo : 0, *hi = divided ? share->hi : n;
}

/* Each rank's range of whole[] (n doubles) to every rank (to_root: to
 * rank 0 only). Nothing on one process. */
int pddo_share(const PddoShare *share, double *whole, bool to_root);

void pddo_share_free(PddoShare *share);

#endif
