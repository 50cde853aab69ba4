#include "flow/iga/decomp.h"

#include "core/blocks.h"
#include "core/mem.h"
#include "core/status.h"

#include <omp.h>
#include <string.h>

void iga_decomp_cuts(const IgaDecomp *d, int axis, int n_items, int *cut) {
    const IgaWindowAxis *w = &d->ax[axis];
    for (int c = 0; c < w->parts; c++) cut[c] = blocks_cut(w->elements, w->parts, c);
    cut[w->parts] = n_items;
}

/* The block along an axis that owns global point g. */
static int point_block(const IgaWindowAxis *w, int g) {
    return blocks_owner(w->elements, w->parts, g < w->elements ? g : w->elements - 1);
}

/* One axis's window, its elements and their maps. */
static int axis_window(IgaWindowAxis *w, const IgaAxis *a, int axis, int parts, int part,
                       int halo) {
    w->count = a->count, w->elements = a->elements, w->degree = a->degree;
    w->periodic = a->periodic;
    w->parts = parts, w->part = part;
    w->whole = parts == 1;
    const int p = a->degree;
    const int g0 = blocks_cut(a->elements, parts, part);
    const int g1 = part == parts - 1 ? a->count : blocks_cut(a->elements, parts, part + 1);
    if (w->whole) {
        w->w0 = 0, w->n = a->count, w->own0 = 0, w->own = a->count;
    } else {
        int lo = g0 - halo, hi = g1 + halo;
        if (!a->periodic) lo = lo < 0 ? 0 : lo, hi = hi > a->count ? a->count : hi;
        if (hi - lo > a->count)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "iga flow: a block's %d control points and a halo of %d on each "
                             "side exceed the %d of the periodic %c axis; expected fewer blocks "
                             "along %c (--processes) or more elements",
                             g1 - g0, halo, a->count, "xy"[axis], "xy"[axis]);
        w->w0 = lo, w->n = hi - lo, w->own0 = g0 - lo, w->own = g1 - g0;
    }
    TRY(nspd_alloc(&w->global, (size_t)w->n, sizeof(int)));
    TRY(nspd_alloc(&w->local, (size_t)a->count, sizeof(int)));
    for (int g = 0; g < a->count; g++) w->local[g] = -1;
    for (int l = 0; l < w->n; l++) {
        const int g = ((w->w0 + l) % a->count + a->count) % a->count;
        w->global[l] = g;
        w->local[g] = l;
    }
    /* local elements: the whole axis's, or those whose p + 1 points all
     * lie in the window (local element le starts at local point le) */
    w->ne = w->whole ? a->elements : w->n - p;
    TRY(nspd_alloc(&w->element, (size_t)w->ne, sizeof(int)));
    TRY(nspd_alloc(&w->local_element, (size_t)a->elements, sizeof(int)));
    TRY(nspd_alloc(&w->sorted, (size_t)w->ne, sizeof(int)));
    for (int e = 0; e < a->elements; e++) w->local_element[e] = -1;
    for (int le = 0; le < w->ne; le++) {
        const int e = w->whole ? le : w->global[le];
        w->element[le] = e;
        w->local_element[e] = le;
    }
    for (int e = 0, k = 0; e < a->elements; e++)
        if (w->local_element[e] >= 0) w->sorted[k++] = w->local_element[e];
    /* the elements touching an own point: starts g0 - p .. g1 - 1 */
    if (w->whole) {
        w->e0 = 0, w->en = a->elements;
    } else {
        int lo = g0 - p - w->w0, hi = g1 - w->w0; /* local starts [lo, hi) */
        if (!a->periodic) {
            if (lo + w->w0 < 0) lo = -w->w0;
            if (hi + w->w0 > a->elements) hi = a->elements - w->w0;
        }
        w->e0 = lo, w->en = hi - lo;
    }
    return NSPD_OK;
}

void iga_decomp_destroy(IgaDecomp *d) {
    for (int a = 0; a < 2; a++) {
        IgaWindowAxis *w = &d->ax[a];
        nspd_free(&w->global);
        nspd_free(&w->local);
        nspd_free(&w->element);
        nspd_free(&w->local_element);
        nspd_free(&w->sorted);
    }
    nspd_free(&d->ask_local);
    nspd_free(&d->tell_local);
    nspd_free(&d->ask_count);
    nspd_free(&d->tell_count);
    nspd_free(&d->bytes);
    nspd_free(&d->send);
    nspd_free(&d->recv);
}

int64_t iga_decomp_local(const IgaDecomp *d, int64_t g) {
    const int cx = d->ax[0].count;
    const int i = d->ax[0].local[g % cx], j = d->ax[1].local[g / cx];
    return i < 0 || j < 0 ? -1 : i + (int64_t)d->ax[0].n * j;
}

int64_t iga_decomp_global(const IgaDecomp *d, int64_t k) {
    const int nx = d->ax[0].n;
    return d->ax[0].global[k % nx] + (int64_t)d->ax[0].count * d->ax[1].global[k / nx];
}

int iga_decomp_owner(const IgaDecomp *d, int64_t g) {
    if (!iga_decomp_divided(d)) return 0;
    const int cx = d->ax[0].count;
    return point_block(&d->ax[0], (int)(g % cx)) +
           d->dims[0] * point_block(&d->ax[1], (int)(g / cx));
}

int iga_decomp_element_owner(const IgaDecomp *d, int ex, int ey) {
    if (!iga_decomp_divided(d)) return 0;
    return blocks_owner(d->ax[0].elements, d->dims[0], ex) +
           d->dims[0] * blocks_owner(d->ax[1].elements, d->dims[1], ey);
}

/* The halo's plan: every window point another rank owns, asked of it. */
static int plan_halo(IgaDecomp *d) {
    const int ranks = d->comm.size, me = d->comm.rank;
    const int64_t n = (int64_t)d->ax[0].n * d->ax[1].n;
    TRY(nspd_alloc(&d->ask_count, (size_t)ranks, sizeof(int)));
    TRY(nspd_alloc(&d->tell_count, (size_t)ranks, sizeof(int)));
    TRY(nspd_alloc(&d->bytes, 4 * (size_t)ranks, sizeof(int)));
    int *at = d->bytes; /* scratch until the byte counts */
    int64_t asks = 0;
    for (int64_t k = 0; k < n; k++) {
        const int r = iga_decomp_owner(d, iga_decomp_global(d, k));
        if (r != me) d->ask_count[r]++, asks++;
    }
    int64_t *asked = NULL;
    TRY(nspd_alloc(&d->ask_local, (size_t)asks + 1, sizeof(int64_t)));
    TRY(nspd_alloc(&asked, (size_t)asks + 1, sizeof(int64_t)));
    for (int r = 0, sum = 0; r < ranks; r++) at[r] = sum, sum += d->ask_count[r];
    for (int64_t k = 0; k < n; k++) {
        const int64_t g = iga_decomp_global(d, k);
        const int r = iga_decomp_owner(d, g);
        if (r == me) continue;
        d->ask_local[at[r]] = k;
        asked[at[r]++] = g;
    }
    int status = comm_ask(&d->comm, asked, d->ask_count, &d->tell_local, d->tell_count);
    nspd_free(&asked);
    TRY(status);
    int64_t tells = 0;
    for (int r = 0; r < ranks; r++) tells += d->tell_count[r];
    for (int64_t k = 0; k < tells; k++) {
        const int64_t l = iga_decomp_local(d, d->tell_local[k]);
        if (l < 0 || !iga_decomp_owns(d, (int)(l % d->ax[0].n), (int)(l / d->ax[0].n)))
            return NSPD_FAIL(NSPD_ERR_INTERNAL,
                             "iga flow: control point %lld asked of rank %d, which does not own it",
                             (long long)d->tell_local[k], me);
        d->tell_local[k] = l;
    }
    d->asks = asks, d->tells = tells;
    TRY(nspd_alloc(&d->send, (size_t)(tells * d->max_width) + 1, sizeof(double)));
    TRY(nspd_alloc(&d->recv, (size_t)(asks * d->max_width) + 1, sizeof(double)));
    return NSPD_OK;
}

int iga_decomp_create(IgaDecomp *d, const NspdComm *comm, const int processes[2],
                      const IgaAxis ax[2], int halo, int max_width) {
    memset(d, 0, sizeof *d);
    d->comm = comm ? *comm : comm_self();
    d->max_width = max_width;
    const int p = comm_distributed(&d->comm) ? d->comm.size : 1;
    const int n[2] = {ax[0].elements, ax[1].elements};
    const bool periodic[2] = {ax[0].periodic, ax[1].periodic};
    static const char *const WHAT[2] = {"element columns", "element rows"};
    /* a block of one element holds a point; its halo may reach past its
     * neighbours' blocks (the plan asks whoever owns a point) */
    const int min_width = 1;
    const int none[2] = {0, 0};
    TRY(blocks_process_grid(n, periodic, min_width, p, p > 1 ? processes : none, WHAT, d->dims));
    const int r = p > 1 ? d->comm.rank : 0;
    const int part[2] = {r % d->dims[0], r / d->dims[0]};
    for (int a = 0; a < 2; a++) TRY(axis_window(&d->ax[a], &ax[a], a, d->dims[a], part[a], halo));
    if (comm_distributed(&d->comm)) TRY(plan_halo(d));
    return NSPD_OK;
}

int iga_decomp_exchange(IgaDecomp *d, double *const *arrays, int count, int width) {
    if (!iga_decomp_divided(d)) return NSPD_OK;
    const double started = omp_get_wtime();
    const int ranks = d->comm.size, per = count * width;
    if (per > d->max_width)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "iga flow: a halo of %d doubles a point; at most %d",
                         per, d->max_width);
    int *send_bytes = d->bytes, *send_at = d->bytes + ranks;
    int *recv_bytes = d->bytes + 2 * ranks, *recv_at = d->bytes + 3 * ranks;
    int64_t tells = 0, asks = 0;
    for (int r = 0; r < ranks; r++) {
        send_bytes[r] = d->tell_count[r] * per * (int)sizeof(double);
        send_at[r] = (int)(tells * per * (int64_t)sizeof(double));
        recv_bytes[r] = d->ask_count[r] * per * (int)sizeof(double);
        recv_at[r] = (int)(asks * per * (int64_t)sizeof(double));
        tells += d->tell_count[r], asks += d->ask_count[r];
    }
    for (int64_t k = 0; k < d->tells; k++)
        for (int c = 0; c < count; c++)
            memcpy(d->send + (k * count + c) * width, arrays[c] + d->tell_local[k] * width,
                   sizeof(double) * (size_t)width);
    const int status =
        comm_alltoallv_bytes(&d->comm, d->send, send_bytes, send_at, d->recv, recv_bytes, recv_at);
    for (int64_t k = 0; k < d->asks && status == NSPD_OK; k++)
        for (int c = 0; c < count; c++)
            memcpy(arrays[c] + d->ask_local[k] * width, d->recv + (k * count + c) * width,
                   sizeof(double) * (size_t)width);
    d->seconds += omp_get_wtime() - started;
    return status;
}

int iga_decomp_gather(IgaDecomp *d, const int n[2], int *const cut[2], const double *mine,
                      int width, double *whole, bool all_ranks) {
    const int ranks = iga_decomp_divided(d) ? d->comm.size : 1;
    const int me = ranks > 1 ? d->comm.rank : 0;
    const int c0 = me % d->dims[0], c1 = me / d->dims[0];
    const int count = (cut[0][c0 + 1] - cut[0][c0]) * (cut[1][c1 + 1] - cut[1][c1]) * width;
    if (ranks == 1) {
        memcpy(whole, mine, sizeof(double) * (size_t)count);
        return NSPD_OK;
    }
    double *all = NULL;
    const bool here = all_ranks || me == 0;
    if (here) TRY(nspd_alloc(&all, (size_t)n[0] * (size_t)n[1] * (size_t)width, sizeof(double)));
    const int status = all_ranks ? comm_allgatherv(&d->comm, mine, count, all)
                                 : comm_gatherv(&d->comm, mine, count, all);
    if (status == NSPD_OK && here) {
        const double *at = all;
        for (int r = 0; r < ranks; r++) {
            const int bx = r % d->dims[0], by = r / d->dims[0];
            const size_t w = (size_t)(cut[0][bx + 1] - cut[0][bx]), per = (size_t)width;
            for (int j = cut[1][by]; j < cut[1][by + 1]; j++, at += w * per)
                memcpy(whole + ((size_t)j * (size_t)n[0] + (size_t)cut[0][bx]) * per, at,
                       sizeof(double) * w * per);
        }
    }
    nspd_free(&all);
    return status;
}
