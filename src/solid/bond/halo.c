/* A bond-based body divided between processes (halo.h). */
#include "solid/bond/halo.h"

#include "core/mem.h"
#include "core/status.h"

#include <string.h>

/* The points and their per-point arrays: `from` lists the whole body's
 * index of each kept point, owned then ghosts. */
static int take_points(BondBody *b, const int64_t *from, int64_t n) {
    for (int d = 0; d < 3; d++) {
        TRY(point_halo_take(&b->x[d], sizeof(double), from, n));
        TRY(point_halo_take(&b->u[d], sizeof(double), from, n));
        TRY(point_halo_take(&b->v[d], sizeof(double), from, n));
        TRY(point_halo_take(&b->force[d], sizeof(double), from, n));
        TRY(point_halo_take(&b->external[d], sizeof(double), from, n));
        TRY(point_halo_take(&b->lattice[d], sizeof(int32_t), from, n));
    }
    TRY(point_halo_take(&b->volume, sizeof(double), from, n));
    TRY(point_halo_take(&b->region, sizeof(int16_t), from, n));
    return point_halo_take(&b->initial_bond_volume, sizeof(double), from, n);
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

int bond_body_divide(BondBody *b, const NspdComm *comm) {
    if (!comm_distributed(comm)) return NSPD_OK;
    const int p = comm->size, r = comm->rank;
    const int64_t total = b->n;
    if (total < p)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "solid: %lld points over %d processes leave none on one; expected at "
                         "most %lld processes",
                         (long long)total, p, (long long)total);
    const int64_t lo = point_halo_run_start(total, p, r),
                  hi = point_halo_run_start(total, p, r + 1), own = hi - lo;
    BondHalo *h = NULL;
    TRY(nspd_alloc(&h, 1, sizeof *h));
    b->halo = h;
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
    /* the local index of each point of the whole body: the run, then its
     * ghosts in the whole body's order */
    int64_t *local = NULL, *from = NULL, *ghost = NULL, ghosts = 0;
    int status = point_halo_number(total, lo, hi, b->bond_first, b->bond_nbr, &local, &ghost, &from,
                                   &ghosts);
    if (status == NSPD_OK) status = take_bonds(b, lo, hi, ghosts, local);
    if (status == NSPD_OK) status = take_points(b, from, own + ghosts);
    if (status == NSPD_OK)
        status =
            point_halo_plan(&h->points, comm, own, ghosts, ghost, (size_t)b->dim * sizeof(double));
    nspd_free(&local);
    nspd_free(&from);
    nspd_free(&ghost);
    if (status != NSPD_OK) return status;
    b->n = own;
    b->ghosts = ghosts;
    return NSPD_OK;
}

void bond_halo_free(BondHalo **hp) {
    if (*hp) point_halo_free(&(*hp)->points);
    nspd_free(hp);
}

void bond_halo_exchange(BondBody *b) {
    if (b->halo) point_halo_exchange(&b->halo->points, (void *const *)b->u, b->dim, sizeof(double));
}

int64_t bond_halo_global(const BondBody *b, int64_t i) {
    return b->halo ? point_halo_global(&b->halo->points, i) : i;
}
