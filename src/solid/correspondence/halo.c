/* A correspondence body divided between processes (halo.h). */
#include "solid/correspondence/halo.h"

#include "core/mem.h"
#include "core/status.h"

#include <stdlib.h>
#include <string.h>

/* A bond that crosses: the whole index of its reverse bond (known once
 * the owners' bond numbers are), its own local index and its point's, the
 * local index of the ghost it reaches and its reverse bond's place in the
 * ghost's row. */
typedef struct {
    int64_t reverse, bond, point, ghost, place;
} Crossing;

static int by_reverse(const void *a, const void *b) {
    const int64_t x = ((const Crossing *)a)->reverse, y = ((const Crossing *)b)->reverse;
    return (x > y) - (x < y);
}

/* The bonds of the run [lo, lo + own) that cross (their reverse bonds
 * not yet numbered), in bond order; the rows of the run and of the points
 * it reaches are the whole body's numbering (body.c's find_families), so
 * each run bond's reverse lies in its neighbour's row. NSPD_ERR_INTERNAL
 * where one does not (families not symmetric). */
static int crossings(const CpdBody *b, int64_t lo, int64_t own, const int64_t *local,
                     Crossing **out, int64_t *count) {
    const int64_t b0 = b->first[lo], b1 = b->first[lo + own];
    int64_t m = 0;
    for (int64_t k = b0; k < b1; k++) {
        if (b->reverse[k] < 0)
            return NSPD_FAIL(NSPD_ERR_INTERNAL, "the correspondence families are not symmetric");
        m += local[b->nbr[k]] >= own ? 1 : 0;
    }
    TRY(nspd_alloc(out, (size_t)m + 1, sizeof **out));
    m = 0;
    for (int64_t i = lo; i < lo + own; i++)
        for (int64_t k = b->first[i]; k < b->first[i + 1]; k++) {
            const int64_t j = b->nbr[k];
            if (local[j] >= own)
                (*out)[m++] = (Crossing){-1, k - b0, i - lo, local[j], b->reverse[k] - b->first[j]};
        }
    *count = m;
    return NSPD_OK;
}

/* The rows of the run [lo, lo + own) with their neighbours renumbered by
 * local[] (ghosts' rows empty) and the reverse bonds among them (-1 where
 * one crosses); the rest of the families freed. */
static int take_rows(CpdBody *b, int64_t lo, int64_t own, int64_t ghosts, const int64_t *local) {
    const int64_t b0 = b->first[lo], count = b->first[lo + own] - b0;
    int64_t *first = NULL;
    int32_t *nbr = NULL;
    TRY(nspd_alloc(&first, (size_t)(own + ghosts + 1), sizeof *first));
    int status = nspd_alloc(&nbr, (size_t)count + 1, sizeof *nbr);
    if (status != NSPD_OK) {
        nspd_free(&first);
        return status;
    }
    for (int64_t i = 0; i <= own; i++) first[i] = b->first[lo + i] - b0;
    for (int64_t g = 1; g <= ghosts; g++) first[own + g] = count;
    for (int64_t k = 0; k < count; k++) nbr[k] = (int32_t)local[b->nbr[b0 + k]];
    nspd_free(&b->first);
    nspd_free(&b->nbr);
    nspd_free(&b->reverse);
    b->first = first, b->nbr = nbr;
    b->n = own, b->ghosts = ghosts, b->bond_count = count;
    TRY(nspd_alloc(&b->reverse, (size_t)count + 1, sizeof(int64_t)));
    (void)bac_reverse_bonds(own, b->first, b->nbr, b->reverse); /* -1: crosses */
    return NSPD_OK;
}

/* Each rank's value of one integer gathered into all[comm size]. */
static int gather_counts(const NspdComm *comm, int64_t mine, int64_t *all) {
    return comm_allgatherv_bytes(comm, &mine, (int)sizeof mine, all);
}

/* The whole body's index of each crossing bond's reverse: its ghost's
 * first bond in the whole numbering (the bonds' runs lie in rank order,
 * each its points' rows in order), asked of the ghost's owner, plus its
 * place in the ghost's row; then the crossings sorted by it (so by
 * owner), the bonds' halo's "ghosts". *start: the run's first bond. */
static int number_reverse(CpdBody *b, const NspdComm *comm, Crossing *cross, int64_t crossing,
                          int64_t *start) {
    const int64_t na = b->n + b->ghosts;
    int64_t *counts = NULL, *whole_first = NULL;
    int status = nspd_alloc(&counts, (size_t)comm->size, sizeof *counts);
    if (status == NSPD_OK) status = nspd_alloc(&whole_first, (size_t)na + 1, sizeof *whole_first);
    if (status == NSPD_OK) status = gather_counts(comm, b->bond_count, counts);
    if (status == NSPD_OK) {
        *start = 0;
        for (int q = 0; q < comm->rank; q++) *start += counts[q];
        for (int64_t i = 0; i < b->n; i++) whole_first[i] = *start + b->first[i];
        void *arrays[1] = {whole_first};
        point_halo_exchange(&b->halo->points, arrays, 1, sizeof *whole_first);
        for (int64_t q = 0; q < crossing; q++)
            cross[q].reverse = whole_first[cross[q].ghost] + cross[q].place;
        qsort(cross, (size_t)crossing, sizeof *cross, by_reverse);
    }
    nspd_free(&counts);
    nspd_free(&whole_first);
    return status;
}

/* The pairs of the run's rows (a crossing bond a pair of its own) and
 * each one's index among the whole body's pairs, which are numbered in
 * the order of their canonical bonds (the lower whole index of the two):
 * the pairs canonical here are a run of them, after the lower ranks'
 * (their counts gathered); a crossing pair canonical on the other rank
 * takes that rank's number for it, asked through the bonds' halo. */
static int number_pairs(CpdBody *b, const NspdComm *comm, int64_t start) {
    CpdHalo *h = b->halo;
    TRY(bac_pairs_create(b->n, b->first, b->reverse, &b->pairs));
    const int64_t np = b->pairs.count, nb = b->bond_count, crossing = h->bonds.ghosts;
    int64_t *counts = NULL, *whole = NULL, *reverse_of = NULL;
    int status = nspd_alloc(&h->pair_whole, (size_t)np + 1, sizeof(int64_t));
    if (status == NSPD_OK) status = nspd_alloc(&h->pair_here, (size_t)np + 1, 1);
    if (status == NSPD_OK) status = nspd_alloc(&counts, (size_t)comm->size, sizeof *counts);
    if (status == NSPD_OK) status = nspd_alloc(&whole, (size_t)(nb + crossing) + 1, sizeof *whole);
    if (status == NSPD_OK) status = nspd_alloc(&reverse_of, (size_t)nb + 1, sizeof *reverse_of);
    if (status != NSPD_OK) goto done;
    /* the whole index of each crossing bond's reverse, by bond (-1: none) */
    for (int64_t k = 0; k < nb; k++) reverse_of[k] = -1;
    for (int64_t q = 0; q < crossing; q++) reverse_of[h->cross_bond[q]] = h->bonds.ghost[q];
    int64_t here = 0;
    for (int64_t p = 0; p < np; p++) {
        const int64_t k = b->pairs.bond[p];
        h->pair_here[p] = reverse_of[k] < 0 || reverse_of[k] > start + k;
        here += h->pair_here[p];
    }
    status = gather_counts(comm, here, counts);
    if (status != NSPD_OK) goto done;
    int64_t next = 0;
    h->pairs_total = 0;
    for (int q = 0; q < comm->size; q++) {
        if (q < comm->rank) next += counts[q];
        h->pairs_total += counts[q];
    }
    for (int64_t p = 0; p < np; p++) h->pair_whole[p] = h->pair_here[p] ? next++ : -1;
    /* the other rank's numbers of the pairs canonical there */
    for (int64_t k = 0; k < nb; k++) whole[k] = h->pair_whole[b->pairs.of[k]];
    void *arrays[1] = {whole};
    point_halo_exchange(&h->bonds, arrays, 1, sizeof *whole);
    for (int64_t q = 0; q < crossing; q++) {
        const int64_t p = b->pairs.of[h->cross_bond[q]];
        if (!h->pair_here[p]) h->pair_whole[p] = whole[nb + q];
    }
done:
    nspd_free(&counts);
    nspd_free(&whole);
    nspd_free(&reverse_of);
    return status;
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
    int64_t start = 0;
    Crossing *cross = NULL;
    int status = point_halo_number(total, lo, hi, b->first, b->nbr, &local, &ghost, &from, &ghosts);
    if (status == NSPD_OK) status = crossings(b, lo, own, local, &cross, &crossing);
    if (status == NSPD_OK) status = take_rows(b, lo, own, ghosts, local);
    for (int d = 0; d < 3 && status == NSPD_OK; d++) {
        status = point_halo_take(&b->x[d], sizeof(double), from, own + ghosts);
        if (status == NSPD_OK)
            status = point_halo_take(&b->lattice[d], sizeof(int32_t), from, own + ghosts);
    }
    if (status == NSPD_OK)
        status = point_halo_plan(&h->points, comm, own, ghosts, ghost, 9 * sizeof(double));
    if (status == NSPD_OK) status = number_reverse(b, comm, cross, crossing, &start);
    if (status == NSPD_OK) status = nspd_alloc(&asked, (size_t)crossing + 1, sizeof *asked);
    if (status == NSPD_OK)
        status = nspd_alloc(&h->cross_bond, (size_t)crossing + 1, sizeof(int64_t));
    if (status == NSPD_OK)
        status = nspd_alloc(&h->cross_point, (size_t)crossing + 1, sizeof(int64_t));
    if (status == NSPD_OK) {
        for (int64_t q = 0; q < crossing; q++)
            asked[q] = cross[q].reverse, h->cross_bond[q] = cross[q].bond,
            h->cross_point[q] = cross[q].point;
        status = point_halo_plan(&h->bonds, comm, b->bond_count, crossing, asked,
                                 (size_t)b->dim * sizeof(double));
    }
    /* the bond-associated force's pairs; the classic force's gather reads
     * T_ji of a crossing bond where the bonds' exchange puts it, after the
     * run's bonds (cpd_halo_bonds) */
    if (status == NSPD_OK && b->cfg.force != CPD_FORCE_CLASSIC)
        status = number_pairs(b, comm, start);
    for (int64_t q = 0; status == NSPD_OK && b->cfg.force == CPD_FORCE_CLASSIC && q < crossing; q++)
        b->reverse[h->cross_bond[q]] = b->bond_count + q;
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
