/* The point halo of a divided PD body (halo.h). */
#include "solid/pd/halo.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"

#include <string.h>

int64_t point_halo_run_start(int64_t total, int p, int r) {
    return total * r / p;
}

/* The rank whose run holds whole-body point g. */
static int owner(const PointHalo *h, int64_t g) {
    int lo = 0, hi = h->comm.size - 1;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (h->run_first[mid] <= g)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

int point_halo_plan(PointHalo *h, const NspdComm *comm, int64_t n, int64_t ghosts,
                    const int64_t *ghost, size_t max_bytes) {
    memset(h, 0, sizeof *h);
    h->comm = *comm;
    h->n = n, h->ghosts = ghosts, h->max_bytes = max_bytes;
    const int p = comm->size, me = comm->rank;
    const size_t ps = (size_t)p;
    TRY(nspd_alloc(&h->run_first, ps + 1, sizeof(int64_t)));
    TRY(comm_allgatherv_bytes(comm, &n, (int)sizeof n, h->run_first + 1));
    for (int q = 0; q < p; q++) h->run_first[q + 1] += h->run_first[q];
    h->first = h->run_first[me], h->total = h->run_first[p];
    const int64_t first = h->first;
    TRY(nspd_alloc(&h->ghost, (size_t)ghosts + 1, sizeof(int64_t)));
    memcpy(h->ghost, ghost, (size_t)ghosts * sizeof(int64_t));
    int **plan[8] = {&h->send_count, &h->send_from, &h->recv_count, &h->recv_from,
                     &h->send_bytes, &h->send_at,   &h->recv_bytes, &h->recv_at};
    for (int k = 0; k < 8; k++) TRY(nspd_alloc(plan[k], ps, sizeof(int)));
    /* the ghosts (sorted, so grouped by owner) asked of their owners */
    for (int64_t k = 0; k < ghosts; k++) h->recv_count[owner(h, ghost[k])]++;
    TRY(comm_ask(comm, h->ghost, h->recv_count, &h->send_point, h->send_count));
    int64_t at = 0, sends = 0;
    for (int q = 0; q < p; q++) {
        h->recv_from[q] = (int)at;
        at += h->recv_count[q];
        h->send_from[q] = (int)sends;
        sends += h->send_count[q];
    }
    h->sends = sends;
    for (int64_t k = 0; k < sends; k++) h->send_point[k] -= first;
    TRY(nspd_alloc(&h->send_buf, (size_t)sends * max_bytes + 1, 1));
    return nspd_alloc(&h->recv_buf, (size_t)ghosts * max_bytes + 1, 1);
}

void point_halo_free(PointHalo *h) {
    nspd_free(&h->ghost);
    nspd_free(&h->run_first);
    nspd_free(&h->send_point);
    int **plan[8] = {&h->send_count, &h->send_from, &h->recv_count, &h->recv_from,
                     &h->send_bytes, &h->send_at,   &h->recv_bytes, &h->recv_at};
    for (int k = 0; k < 8; k++) nspd_free(plan[k]);
    nspd_free(&h->send_buf);
    nspd_free(&h->recv_buf);
}

void point_halo_exchange(PointHalo *h, void *const *arrays, int count, size_t bytes) {
    const double t0 = nspd_wall_time();
    const size_t per = (size_t)count * bytes; /* at most max_bytes */
    for (int64_t k = 0; k < h->sends; k++)
        for (int c = 0; c < count; c++)
            memcpy(h->send_buf + (size_t)k * per + (size_t)c * bytes,
                   (const unsigned char *)arrays[c] + (size_t)h->send_point[k] * bytes, bytes);
    for (int q = 0; q < h->comm.size; q++) {
        h->send_bytes[q] = h->send_count[q] * (int)per, h->send_at[q] = h->send_from[q] * (int)per;
        h->recv_bytes[q] = h->recv_count[q] * (int)per, h->recv_at[q] = h->recv_from[q] * (int)per;
    }
    /* a failed exchange is MPI's abort, not a recoverable status */
    (void)comm_alltoallv_bytes(&h->comm, h->send_buf, h->send_bytes, h->send_at, h->recv_buf,
                               h->recv_bytes, h->recv_at);
    for (int64_t k = 0; k < h->ghosts; k++)
        for (int c = 0; c < count; c++)
            memcpy((unsigned char *)arrays[c] + (size_t)(h->n + k) * bytes,
                   h->recv_buf + (size_t)k * per + (size_t)c * bytes, bytes);
    h->seconds += nspd_wall_time() - t0;
}

int point_halo_take(void *array, size_t size, const int64_t *from, int64_t n) {
    unsigned char **old = array;
    if (!*old) return NSPD_OK;
    unsigned char *kept = NULL;
    TRY(nspd_alloc(&kept, (size_t)n, size));
    for (int64_t k = 0; k < n; k++)
        memcpy(kept + (size_t)k * size, *old + (size_t)from[k] * size, size);
    nspd_free(old);
    *old = kept;
    return NSPD_OK;
}

int halo_checkpoint_io(const NspdComm *comm, int64_t first, int64_t n, int64_t total,
                       const int64_t *ghost, int64_t ghosts, Checkpoint *ck, const char *name,
                       void *mine, size_t size) {
    unsigned char *all = NULL, *own = mine;
    TRY(nspd_alloc(&all, (size_t)total + 1, size));
    int status = NSPD_OK;
    if (!checkpoint_reading(ck))
        status = comm_allgatherv_bytes(comm, own, (int)((size_t)n * size), all);
    if (status == NSPD_OK) status = checkpoint_io(ck, name, all, (size_t)total * size);
    if (status == NSPD_OK && checkpoint_reading(ck)) {
        memcpy(own, all + (size_t)first * size, (size_t)n * size);
        for (int64_t g = 0; ghost && g < ghosts; g++)
            memcpy(own + (size_t)(n + g) * size, all + (size_t)ghost[g] * size, size);
    }
    nspd_free(&all);
    return status;
}

int point_halo_number(int64_t total, int64_t lo, int64_t hi, const int64_t *first,
                      const int32_t *nbr, int64_t **local, int64_t **ghost, int64_t **from,
                      int64_t *ghosts) {
    const int64_t own = hi - lo;
    int64_t m = 0;
    TRY(nspd_alloc(local, (size_t)total, sizeof **local));
    int64_t *l = *local;
    for (int64_t g = 0; g < total; g++) l[g] = g >= lo && g < hi ? g - lo : -1;
    for (int64_t k = first[lo]; k < first[hi]; k++)
        if (l[nbr[k]] == -1) l[nbr[k]] = -2, m++; /* a ghost, numbered below */
    TRY(nspd_alloc(ghost, (size_t)m + 1, sizeof **ghost));
    TRY(nspd_alloc(from, (size_t)(own + m) + 1, sizeof **from));
    for (int64_t i = 0; i < own; i++) (*from)[i] = lo + i;
    int64_t k = 0;
    for (int64_t g = 0; g < total; g++)
        if (l[g] == -2) {
            l[g] = own + k;
            (*ghost)[k] = g;
            (*from)[own + k++] = g;
        }
    *ghosts = m;
    return NSPD_OK;
}

int64_t point_halo_global(const PointHalo *h, int64_t i) {
    return i < h->n ? h->first + i : h->ghost[i - h->n];
}
