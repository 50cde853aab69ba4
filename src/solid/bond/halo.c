/* A bond-based body divided between processes (halo.h). */
#include "solid/bond/halo.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"

#include <string.h>

/* Rank r of p holds the whole body's points [total r / p, total (r + 1) / p). */
static int64_t run_start(int64_t total, int p, int r) {
    return total * r / p;
}

static int owner_of(int64_t g, int64_t total, int p) {
    int r = (int)(g * p / total);
    while (r + 1 < p && run_start(total, p, r + 1) <= g) r++;
    while (r > 0 && run_start(total, p, r) > g) r--;
    return r;
}

/* Replaces *array (elements of `size` bytes) by its elements at `from[k]`,
 * k < n. */
static int take(void *array, size_t size, const int64_t *from, int64_t n) {
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

/* The points and their per-point arrays: `from` lists the whole body's
 * index of each kept point, owned then ghosts. */
static int take_points(BondBody *b, const int64_t *from, int64_t n) {
    for (int d = 0; d < 3; d++) {
        TRY(take(&b->x[d], sizeof(double), from, n));
        TRY(take(&b->u[d], sizeof(double), from, n));
        TRY(take(&b->v[d], sizeof(double), from, n));
        TRY(take(&b->force[d], sizeof(double), from, n));
        TRY(take(&b->external[d], sizeof(double), from, n));
        TRY(take(&b->lattice[d], sizeof(int32_t), from, n));
    }
    TRY(take(&b->volume, sizeof(double), from, n));
    TRY(take(&b->region, sizeof(int16_t), from, n));
    return take(&b->initial_bond_volume, sizeof(double), from, n);
}

/* The owned rows [lo, hi) of the bonds, their neighbours renumbered by
 * local[]; the ghosts' rows empty. */
static int take_bonds(BondBody *b, int64_t lo, int64_t hi, int64_t ghosts, const int64_t *local) {
    const int64_t own = hi - lo, b0 = b->bond_first[lo], count = b->bond_first[hi] - b0;
    int64_t *first = NULL;
    int32_t *nbr = NULL;
    float *coef = NULL;
    int status = nspd_alloc(&first, (size_t)(own + ghosts + 1), sizeof *first);
    if (status == NSPD_OK) status = nspd_alloc(&nbr, (size_t)count, sizeof *nbr);
    if (status == NSPD_OK) status = nspd_alloc(&coef, (size_t)count, sizeof *coef);
    if (status != NSPD_OK) {
        nspd_free(&first);
        nspd_free(&nbr);
        return status;
    }
    for (int64_t i = 0; i <= own; i++) first[i] = b->bond_first[lo + i] - b0;
    for (int64_t g = 1; g <= ghosts; g++) first[own + g] = count;
    for (int64_t k = 0; k < count; k++) nbr[k] = (int32_t)local[b->bond_nbr[b0 + k]];
    memcpy(coef, b->bond_coef + b0, (size_t)count * sizeof *coef);
    nspd_free(&b->bond_first);
    nspd_free(&b->bond_nbr);
    nspd_free(&b->bond_coef);
    b->bond_first = first;
    b->bond_nbr = nbr;
    b->bond_coef = coef;
    b->bond_count = count;
    return NSPD_OK;
}

/* The exchange plan: the ghosts are asked of their owners (one gather of
 * the counts, one point-to-point exchange of the indices). */
static int plan(BondHalo *h, int64_t lo, int64_t ghosts, int dim) {
    const int p = h->comm.size, me = h->comm.rank;
    const size_t ps = (size_t)p;
    TRY(nspd_alloc(&h->send_bytes, ps, sizeof(int)));
    TRY(nspd_alloc(&h->send_at, ps, sizeof(int)));
    TRY(nspd_alloc(&h->recv_bytes, ps, sizeof(int)));
    TRY(nspd_alloc(&h->recv_at, ps, sizeof(int)));
    int *wants = NULL, *asked = NULL, *ask_bytes = NULL, *ask_at = NULL, *get_bytes = NULL,
        *get_at = NULL;
    int status = nspd_alloc(&wants, ps * ps, sizeof(int)); /* wants[q p + r]: q asks r */
    if (status == NSPD_OK) status = nspd_alloc(&asked, ps, sizeof(int));
    if (status == NSPD_OK) status = nspd_alloc(&ask_bytes, 4 * ps, sizeof(int));
    if (status != NSPD_OK) goto done;
    ask_at = ask_bytes + ps, get_bytes = ask_bytes + 2 * ps, get_at = ask_bytes + 3 * ps;
    for (int64_t k = 0; k < ghosts; k++) asked[owner_of(h->ghost[k], h->total, p)]++;
    status = comm_allgatherv_bytes(&h->comm, asked, (int)(ps * sizeof(int)), wants);
    if (status != NSPD_OK) goto done;
    int64_t at = 0, sends = 0;
    for (int q = 0; q < p; q++) {
        ask_at[q] = (int)(at * (int64_t)sizeof(int64_t));
        ask_bytes[q] = asked[q] * (int)sizeof(int64_t);
        h->recv_at[q] = (int)(at * dim * (int64_t)sizeof(double));
        h->recv_bytes[q] = asked[q] * dim * (int)sizeof(double);
        at += asked[q];
        get_at[q] = (int)(sends * (int64_t)sizeof(int64_t));
        get_bytes[q] = wants[(size_t)q * ps + (size_t)me] * (int)sizeof(int64_t);
        h->send_at[q] = (int)(sends * dim * (int64_t)sizeof(double));
        h->send_bytes[q] = wants[(size_t)q * ps + (size_t)me] * dim * (int)sizeof(double);
        sends += wants[(size_t)q * ps + (size_t)me];
    }
    h->sends = sends;
    status = nspd_alloc(&h->send_point, (size_t)sends + 1, sizeof(int64_t));
    if (status == NSPD_OK)
        status = nspd_alloc(&h->send_buf, (size_t)(sends * dim) + 1, sizeof(double));
    if (status == NSPD_OK)
        status = nspd_alloc(&h->recv_buf, (size_t)(ghosts * dim) + 1, sizeof(double));
    if (status == NSPD_OK)
        status = comm_alltoallv_bytes(&h->comm, h->ghost, ask_bytes, ask_at, h->send_point,
                                      get_bytes, get_at);
    for (int64_t k = 0; k < sends && status == NSPD_OK; k++) h->send_point[k] -= lo;
done:
    nspd_free(&wants);
    nspd_free(&asked);
    nspd_free(&ask_bytes);
    return status;
}

int bond_body_divide(BondBody *b, const NspdComm *comm) {
    if (!comm_distributed(comm)) return NSPD_OK;
    const int p = comm->size, r = comm->rank;
    const int64_t total = b->n;
    if (total < p)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "solid: %lld points over %d processes leave none on one; expected at "
                         "most %lld processes",
                         (long long)total, p, (long long)total);
    const int64_t lo = run_start(total, p, r), hi = run_start(total, p, r + 1), own = hi - lo;
    BondHalo *h = NULL;
    TRY(nspd_alloc(&h, 1, sizeof *h));
    b->halo = h;
    h->comm = *comm;
    h->first = lo;
    h->total = total;
    /* the whole body's bonds: the runs' own rows, in rank order (a build
     * of this part alone holds no other rows) */
    int64_t *counts = NULL;
    TRY(nspd_alloc(&counts, (size_t)p, sizeof *counts));
    const int64_t own_bonds = b->bond_first[hi] - b->bond_first[lo];
    const int st = comm_allgatherv_bytes(comm, &own_bonds, (int)sizeof own_bonds, counts);
    for (int q = 0; q < p; q++) {
        if (q == r) h->bond_first = h->bonds;
        h->bonds += counts[q];
    }
    nspd_free(&counts);
    TRY(st);
    /* the local index of each point of the whole body (-1: not kept;
     * -2: a ghost, numbered below in the whole body's order) */
    int64_t *local = NULL, *from = NULL;
    TRY(nspd_alloc(&local, (size_t)total, sizeof *local));
    for (int64_t g = 0; g < total; g++) local[g] = g >= lo && g < hi ? g - lo : -1;
    int64_t ghosts = 0;
    for (int64_t k = b->bond_first[lo]; k < b->bond_first[hi]; k++)
        if (local[b->bond_nbr[k]] == -1) local[b->bond_nbr[k]] = -2, ghosts++;
    int status = nspd_alloc(&h->ghost, (size_t)ghosts + 1, sizeof(int64_t));
    if (status == NSPD_OK) status = nspd_alloc(&from, (size_t)(own + ghosts), sizeof *from);
    if (status == NSPD_OK) {
        for (int64_t i = 0; i < own; i++) from[i] = lo + i;
        int64_t k = 0;
        for (int64_t g = 0; g < total; g++)
            if (local[g] == -2) {
                local[g] = own + k;
                h->ghost[k] = g;
                from[own + k++] = g;
            }
        status = take_bonds(b, lo, hi, ghosts, local);
    }
    if (status == NSPD_OK) status = take_points(b, from, own + ghosts);
    nspd_free(&local);
    nspd_free(&from);
    if (status != NSPD_OK) return status;
    b->n = own;
    b->ghosts = ghosts;
    return plan(h, lo, ghosts, b->dim);
}

void bond_halo_free(BondHalo **hp) {
    BondHalo *h = *hp;
    if (!h) return;
    nspd_free(&h->ghost);
    nspd_free(&h->send_point);
    nspd_free(&h->send_bytes);
    nspd_free(&h->send_at);
    nspd_free(&h->recv_bytes);
    nspd_free(&h->recv_at);
    nspd_free(&h->send_buf);
    nspd_free(&h->recv_buf);
    nspd_free(hp);
}

void bond_halo_exchange(BondBody *b) {
    BondHalo *h = b->halo;
    if (!h) return;
    const int dim = b->dim;
    const double t0 = nspd_wall_time();
    for (int64_t k = 0; k < h->sends; k++)
        for (int d = 0; d < dim; d++) h->send_buf[k * dim + d] = b->u[d][h->send_point[k]];
    /* a failed exchange is MPI's abort, not a recoverable status */
    (void)comm_alltoallv_bytes(&h->comm, h->send_buf, h->send_bytes, h->send_at, h->recv_buf,
                               h->recv_bytes, h->recv_at);
    for (int64_t k = 0; k < b->ghosts; k++)
        for (int d = 0; d < dim; d++) b->u[d][b->n + k] = h->recv_buf[k * dim + d];
    h->seconds += nspd_wall_time() - t0;
}

int64_t bond_halo_global(const BondBody *b, int64_t i) {
    const BondHalo *h = b->halo;
    if (!h) return i;
    return i < b->n ? h->first + i : h->ghost[i - b->n];
}
