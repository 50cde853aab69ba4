/* A correspondence body divided between processes (halo.h). */
#include "solid/correspondence/halo.h"

#include "core/mem.h"
#include "core/status.h"

#include <stdlib.h>
#include <string.h>

/* A bond that crosses: the whole index of its reverse bond, its own
 * local index and its point's. */
typedef struct {
    int64_t reverse, bond, point;
} Crossing;

static int by_reverse(const void *a, const void *b) {
    const int64_t x = ((const Crossing *)a)->reverse, y = ((const Crossing *)b)->reverse;
    return (x > y) - (x < y);
}

/* The rows of the run [lo, lo + own) with their neighbours renumbered by
 * local[] (ghosts' rows empty), the reverse bonds among them (-1 where
 * one crosses), the pairs anew, and each pair's whole index: the whole
 * body's pair of its canonical bond (pair_of: whole, before). */
static int take_rows(CpdBody *b, CpdHalo *h, int64_t lo, int64_t own, int64_t ghosts,
                     const int64_t *local) {
    const int64_t b0 = b->first[lo], count = b->first[lo + own] - b0;
    int64_t *first = NULL, *pair_of = NULL;
    int32_t *nbr = NULL;
    uint8_t *canonical = NULL;
    int status = nspd_alloc(&first, (size_t)(own + ghosts + 1), sizeof *first);
    if (status == NSPD_OK) status = nspd_alloc(&nbr, (size_t)count + 1, sizeof *nbr);
    if (status == NSPD_OK) status = nspd_alloc(&pair_of, (size_t)count + 1, sizeof *pair_of);
    if (status == NSPD_OK) status = nspd_alloc(&canonical, (size_t)count + 1, 1);
    if (status != NSPD_OK) goto done;
    for (int64_t i = 0; i <= own; i++) first[i] = b->first[lo + i] - b0;
    for (int64_t g = 1; g <= ghosts; g++) first[own + g] = count;
    /* the classic force has no pairs (its state is per point) */
    const bool paired = b->pairs.of != NULL;
    for (int64_t k = 0; k < count; k++) {
        nbr[k] = (int32_t)local[b->nbr[b0 + k]];
        pair_of[k] = paired ? b->pairs.of[b0 + k] : -1;
        canonical[k] = paired && b->pairs.bond[pair_of[k]] == b0 + k;
    }
    h->pairs_total = b->pairs.count;
    nspd_free(&b->first);
    nspd_free(&b->nbr);
    nspd_free(&b->reverse);
    bac_pairs_free(&b->pairs);
    b->first = first, b->nbr = nbr;
    first = NULL, nbr = NULL;
    b->n = own, b->ghosts = ghosts, b->bond_count = count;
    status = nspd_alloc(&b->reverse, (size_t)count + 1, sizeof(int64_t));
    if (status != NSPD_OK) goto done;
    (void)bac_reverse_bonds(own, b->first, b->nbr, b->reverse); /* -1: crosses */
    if (paired) status = bac_pairs_create(own, b->first, b->reverse, &b->pairs);
    const size_t np = (size_t)b->pairs.count + 1;
    if (status == NSPD_OK && paired) status = nspd_alloc(&h->pair_whole, np, sizeof(int64_t));
    if (status == NSPD_OK && paired) status = nspd_alloc(&h->pair_here, np, 1);
    for (int64_t p = 0; p < b->pairs.count && status == NSPD_OK; p++) {
        const int64_t k = b->pairs.bond[p];
        h->pair_whole[p] = pair_of[k];
        h->pair_here[p] = canonical[k];
    }
done:
    nspd_free(&first);
    nspd_free(&nbr);
    nspd_free(&pair_of);
    nspd_free(&canonical);
    return status;
}

/* The bonds of the run that cross, sorted by the whole index of their
 * reverse bond (so by its owner): the bonds' halo's "ghosts". */
static int crossings(const CpdBody *b, int64_t lo, int64_t own, const int64_t *local,
                     Crossing **out, int64_t *count) {
    const int64_t b0 = b->first[lo], b1 = b->first[lo + own];
    int64_t m = 0;
    for (int64_t k = b0; k < b1; k++) m += local[b->nbr[k]] >= own ? 1 : 0;
    TRY(nspd_alloc(out, (size_t)m + 1, sizeof **out));
    m = 0;
    for (int64_t i = lo; i < lo + own; i++)
        for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
            if (local[b->nbr[k]] >= own) (*out)[m++] = (Crossing){b->reverse[k], k - b0, i - lo};
    qsort(*out, (size_t)m, sizeof **out, by_reverse);
    *count = m;
    return NSPD_OK;
}

int cpd_body_divide(CpdBody *b, const NspdComm *comm) {
    if (!comm_distributed(comm)) return NSPD_OK;
    const int p = comm->size, r = comm->rank;
    const int64_t total = b->n;
    if (total < p)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "solid: %lld points over %d processes leave none on one; expected at "
                         "most %lld processes",
                         (long long)total, p, (long long)total);
    const int64_t lo = point_halo_run_start(total, p, r),
                  hi = point_halo_run_start(total, p, r + 1);
    const int64_t own = hi - lo;
    CpdHalo *h = NULL;
    TRY(nspd_alloc(&h, 1, sizeof *h));
    b->halo = h;
    /* the local index of each point of the whole body: the run, then the
     * ghosts in the whole body's order (-1: not kept) */
    int64_t *local = NULL, *from = NULL, *ghost = NULL, *asked = NULL, ghosts = 0, crossing = 0;
    Crossing *cross = NULL;
    int status = point_halo_number(total, lo, hi, b->first, b->nbr, &local, &ghost, &from, &ghosts);
    if (status == NSPD_OK) status = crossings(b, lo, own, local, &cross, &crossing);
    const int64_t count = b->first[hi] - b->first[lo];
    if (status == NSPD_OK) status = take_rows(b, h, lo, own, ghosts, local);
    for (int d = 0; d < 3 && status == NSPD_OK; d++) {
        status = point_halo_take(&b->x[d], sizeof(double), from, own + ghosts);
        if (status == NSPD_OK)
            status = point_halo_take(&b->lattice[d], sizeof(int32_t), from, own + ghosts);
    }
    if (status == NSPD_OK)
        status = point_halo_plan(&h->points, comm, own, ghosts, ghost, 9 * sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&asked, (size_t)crossing + 1, sizeof *asked);
    if (status == NSPD_OK)
        status = nspd_alloc(&h->cross_bond, (size_t)crossing + 1, sizeof(int64_t));
    if (status == NSPD_OK)
        status = nspd_alloc(&h->cross_point, (size_t)crossing + 1, sizeof(int64_t));
    if (status == NSPD_OK) {
        for (int64_t q = 0; q < crossing; q++)
            asked[q] = cross[q].reverse, h->cross_bond[q] = cross[q].bond,
            h->cross_point[q] = cross[q].point;
        status = point_halo_plan(&h->bonds, comm, count, crossing, asked,
                                 (size_t)b->dim * sizeof(double));
    }
    /* the classic force's gather reads T_ji of a crossing bond where the
     * bonds' exchange puts it, after the run's bonds (cpd_halo_bonds) */
    for (int64_t q = 0; status == NSPD_OK && b->cfg.force == CPD_FORCE_CLASSIC && q < crossing; q++)
        b->reverse[h->cross_bond[q]] = count + q;
    nspd_free(&local);
    nspd_free(&from);
    nspd_free(&ghost);
    nspd_free(&asked);
    nspd_free(&cross);
    return status;
}

void cpd_halo_free(CpdHalo **hp) {
    CpdHalo *h = *hp;
    if (!h) return;
    point_halo_free(&h->points);
    point_halo_free(&h->bonds);
    nspd_free(&h->cross_bond);
    nspd_free(&h->cross_point);
    nspd_free(&h->pair_whole);
    nspd_free(&h->pair_here);
    nspd_free(hp);
}

void cpd_halo_exchange(CpdBody *b, void *const *arrays, int count, size_t bytes) {
    if (b->halo) point_halo_exchange(&b->halo->points, arrays, count, bytes);
}

void cpd_halo_bonds(CpdBody *b, double *per_bond) {
    if (!b->halo) return;
    void *arrays[1] = {per_bond};
    point_halo_exchange(&b->halo->bonds, arrays, 1, (size_t)b->dim * sizeof(double));
}

void cpd_halo_reverse_weights(CpdBody *b) {
    CpdHalo *h = b->halo;
    if (!h) return;
    cpd_halo_bonds(b, b->phi);
    /* bac_coefficients' phi_ji V_j, the reverse bond's weights asked of
     * j's owner (after the run's own bonds' weights in phi) */
    const int dim = b->dim;
    for (int64_t q = 0; q < h->bonds.ghosts; q++) {
        const int64_t k = h->cross_bond[q];
        const double V = b->volume[b->nbr[k]];
        for (int a = 0; a < dim; a++)
            b->phi_rev[(int64_t)dim * k + a] = b->phi[(int64_t)dim * (b->bond_count + q) + a] * V;
    }
}

int64_t cpd_halo_sum(const CpdBody *b, int64_t mine) {
    return b->halo ? comm_sum_i64(&b->halo->points.comm, mine) : mine;
}

double cpd_halo_max(const CpdBody *b, double mine) {
    return b->halo ? comm_max(&b->halo->points.comm, mine) : mine;
}

double *cpd_halo_whole(const CpdBody *b, const double *mine, int width) {
    const int64_t total = cpd_whole_points(b);
    double *all = NULL;
    if (nspd_alloc(&all, (size_t)(total * width) + 1, sizeof *all) != NSPD_OK) return NULL;
    if (!b->halo) {
        memcpy(all, mine, (size_t)(total * width) * sizeof *all);
        return all;
    }
    /* a failed gather is MPI's abort */
    (void)comm_allgatherv(&b->halo->points.comm, mine, (int)(b->n * width), all);
    return all;
}

int cpd_halo_intact_rows(const CpdBody *b, int64_t **first, int64_t **nbr) {
    const int64_t n = b->n, total = cpd_whole_points(b);
    int64_t intact = 0;
    for (int64_t k = 0; k < b->bond_count; k++) intact += b->damage[k] < 1.0 ? 1 : 0;
    int64_t *length = NULL, *mine = NULL;
    const int64_t all = cpd_halo_sum(b, intact);
    int status = nspd_alloc(first, (size_t)total + 1, sizeof **first);
    if (status == NSPD_OK) status = nspd_alloc(nbr, (size_t)all + 1, sizeof **nbr);
    if (status == NSPD_OK) status = nspd_alloc(&length, (size_t)n + 1, sizeof *length);
    if (status == NSPD_OK) status = nspd_alloc(&mine, (size_t)intact + 1, sizeof *mine);
    if (status == NSPD_OK) {
        int64_t m = 0;
        for (int64_t i = 0; i < n; i++) {
            for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
                if (b->damage[k] < 1.0)
                    mine[m++] =
                        b->halo ? point_halo_global(&b->halo->points, b->nbr[k]) : b->nbr[k];
            length[i] = m;
        }
        for (int64_t i = n - 1; i > 0; i--) length[i] -= length[i - 1];
    }
    if (status == NSPD_OK && b->halo) {
        const NspdComm *comm = &b->halo->points.comm;
        status = comm_allgatherv_bytes(comm, length, (int)((size_t)n * sizeof *length), *first + 1);
        if (status == NSPD_OK)
            status = comm_allgatherv_bytes(comm, mine, (int)((size_t)intact * sizeof *mine), *nbr);
    } else if (status == NSPD_OK) {
        memcpy(*first + 1, length, (size_t)n * sizeof *length);
        memcpy(*nbr, mine, (size_t)intact * sizeof *mine);
    }
    if (status == NSPD_OK) {
        (*first)[0] = 0;
        for (int64_t i = 0; i < total; i++) (*first)[i + 1] += (*first)[i];
    }
    nspd_free(&length);
    nspd_free(&mine);
    if (status != NSPD_OK) {
        nspd_free(first);
        nspd_free(nbr);
    }
    return status;
}

int64_t cpd_whole_points(const CpdBody *b) {
    return b->halo ? b->halo->points.total : b->n;
}

int64_t cpd_whole_bonds(const CpdBody *b) {
    return b->halo ? b->halo->bonds.total : b->bond_count;
}

int cpd_halo_io_points(CpdBody *b, Checkpoint *ck, const char *name, void *mine, size_t size) {
    if (!b->halo) return checkpoint_io(ck, name, mine, (size_t)b->n * size);
    const PointHalo *h = &b->halo->points;
    return halo_checkpoint_io(&h->comm, h->first, b->n, h->total, h->ghost, b->ghosts, ck, name,
                              mine, size);
}

int cpd_halo_io_bonds(CpdBody *b, Checkpoint *ck, const char *name, void *mine, size_t size) {
    if (!b->halo) return checkpoint_io(ck, name, mine, (size_t)b->bond_count * size);
    const PointHalo *h = &b->halo->bonds;
    return halo_checkpoint_io(&h->comm, h->first, b->bond_count, h->total, NULL, 0, ck, name, mine,
                              size);
}

/* The pairs whose canonical bond lies in the run are, in local order, a
 * run of the whole body's pairs (both in the order of their canonical
 * bonds), and the runs lie in rank order: written as a gather of them;
 * read back through pair_whole. */
int cpd_halo_io_pairs(CpdBody *b, Checkpoint *ck, const char *name, void *state, size_t size,
                      int components) {
    const int64_t np = b->pairs.count;
    unsigned char *st = state;
    if (!b->halo) return checkpoint_io(ck, name, state, (size_t)components * (size_t)np * size);
    const CpdHalo *h = b->halo;
    const NspdComm *comm = &h->points.comm;
    const int64_t total = h->pairs_total;
    int64_t here = 0;
    for (int64_t p = 0; p < np; p++) here += h->pair_here[p];
    unsigned char *all = NULL, *mine = NULL;
    int status = nspd_alloc(&all, (size_t)(components * total) + 1, size);
    if (status == NSPD_OK) status = nspd_alloc(&mine, (size_t)here + 1, size);
    for (int c = 0; c < components && status == NSPD_OK && !checkpoint_reading(ck); c++) {
        int64_t m = 0;
        for (int64_t p = 0; p < np; p++)
            if (h->pair_here[p])
                memcpy(mine + (size_t)m++ * size, st + (size_t)(c * np + p) * size, size);
        status = comm_allgatherv_bytes(comm, mine, (int)((size_t)here * size),
                                       all + (size_t)(c * total) * size);
    }
    if (status == NSPD_OK)
        status = checkpoint_io(ck, name, all, (size_t)(components * total) * size);
    for (int c = 0; c < components && status == NSPD_OK && checkpoint_reading(ck); c++)
        for (int64_t p = 0; p < np; p++)
            memcpy(st + (size_t)(c * np + p) * size,
                   all + (size_t)(c * total + h->pair_whole[p]) * size, size);
    nspd_free(&all);
    nspd_free(&mine);
    return status;
}
