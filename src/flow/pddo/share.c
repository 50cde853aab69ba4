/* flow/pddo/share.h: the PDDO flow's ranges of nodes on several processes. */
#include "flow/pddo/share.h"

#include "core/mem.h"
#include "core/status.h"

#include <string.h>

int pddo_share_init(PddoShare *share, PddoOps *ops, const NspdComm *comm) {
    pddo_share_free(share);
    share->comm = comm ? *comm : comm_self();
    const int size = share->comm.size, rank = share->comm.rank;
    const int64_t slices = pddo_ops_slices(ops);
    if (slices < size)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO flow: %lld slices of %d nodes for %d processes; expected at "
                         "least one slice a process",
                         (long long)slices, PDDO_LANES, size);
    TRY(nspd_alloc(&share->count, (size_t)size, sizeof(int)));
    TRY(nspd_alloc(&share->at, (size_t)size, sizeof(int)));
    for (int r = 0; r < size; r++) {
        int64_t lo, hi;
        pddo_ops_cut(ops, r, size, &lo, &hi);
        lo *= PDDO_LANES, hi = hi * PDDO_LANES < ops->n ? hi * PDDO_LANES : ops->n;
        share->at[r] = (int)lo, share->count[r] = (int)(hi - lo);
        if (r == rank) share->lo = lo, share->hi = hi;
    }
    pddo_ops_cut(ops, rank, size, &ops->own_lo, &ops->own_hi);
    return NSPD_OK;
}

int pddo_share(const PddoShare *share, double *whole, bool to_root) {
    if (!pddo_share_divided(share)) return NSPD_OK;
    return comm_share_ranges(&share->comm, whole, share->count, share->at, to_root);
}

void pddo_share_free(PddoShare *share) {
    nspd_free(&share->count);
    nspd_free(&share->at);
    memset(share, 0, sizeof *share);
}
