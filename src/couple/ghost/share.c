/* The immersed boundary on several processes (issue 28).
 *
 * The choice: every process holds the whole Ibm (markers, tags, ghost and
 * probe stencils over the whole grid: a few bytes per cell and about 1 kB
 * per marker, small beside the flow), and each fills the ghost cells of
 * its own block of the process grid and of the two-cell halo around it
 * (the halo's ghosts are read by its own fluxes and must be as fresh as
 * the serial run's), and evaluates the surface probes whose point lies in
 * its block. A stencil reads fluid cells up to the image point, 2 d beyond
 * the wall plus a cell (d up to about 3 cells for the second ghost layer,
 * more for an extended point), which is further than the halo reaches;
 * instead of a halo as wide as the widest stencil on every step of every
 * rank, each process fetches exactly the cells its stencils read from the
 * processes that hold them, once per fill (a few per ghost cell near a
 * block's edge; none for a rank whose block holds no wall). Each process
 * lists what its own stencils read and tells each owner what it asks
 * (two all-to-all exchanges a plan). A cell's owner and its index on a rank are the solver's
 * (gks_solver_cell_owner, gks_solver_local_cell).
 *
 * The values are gathered into a shadow of the conserved fields: a window
 * of the whole grid (rows and columns) that holds this process's block
 * and the cells it fetches, filled only there; the stencil evaluation
 * reads it through the Ibm's cell numbers (IbmFieldView), as it reads the
 * solver's arrays on one process, so each ghost and probe value is the
 * serial one, bit for bit. The window is the box of the cells this
 * process's stencils read (32 bytes a cell of it; none for a block far
 * from every wall), and a fill copies only the block's cells inside it. Moving walls (ibm_update)
 * update the markers and the tags alike on every rank but build only the stencils this process
 * reads: the ghosts of its block and halo, the probes in its block (the others keep their place,
 * IBM_LEVEL_ELSEWHERE), and every fresh cell's (they are few); they widen the window for what this
 * process's fresh cells read (ibm_share_cover), write the kinds and fresh
 * cells of this block, and rebuild the plan (ibm_share_replan), which
 * fits the window to the new stencils. The stencils at ibm_create are
 * built whole (once, before the Ibm knows the processes). */
#include "couple/ghost/ibm_internal.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>

struct IbmShare {
    GksSolver *solver; /* the Ibm's (it outlives the Ibm) */
    NspdComm comm;
    int stride;    /* the whole grid's row length */
    int own_lo[2]; /* whole padded cells this process owns: per axis */
    int own_hi[2]; /* [lo, hi) (its block and the box's ghosts at its ends) */
    int32_t *slot; /* the Ibm's ghost slots of this process's cells */
    double *w[4];  /* the shadow of the conserved fields: the window's cells */
    int win_lo[2]; /* the window: whole padded cells [win_lo, win_hi) per axis */
    int win_hi[2];
    int *ghosts, nghosts; /* ghost entries this process fills */
    int *probes, nprobes; /* probe entries it evaluates */
    int *probe_rank;      /* per probe entry: the process that evaluates it */
    /* cells fetched from (recv) and sent to (send) each process, CSR by
     * rank, whole padded indices in ascending order */
    int *recv_first, *send_first;
    int64_t *recv_cells, *send_cells;
    double *send_buf, *recv_buf;
    int *send_bytes, *send_at, *recv_bytes, *recv_at;
    double *probe_mine; /* 4 values per probe entry */
};

/* The process that holds whole padded cell k current: the block of its
 * cell (the end blocks for the box's ghost layers: gks_solver_cell_owner). */
static int cell_rank(const GksSolver *s, const IbmShare *sh, int64_t k) {
    return gks_solver_cell_owner(s, (int)(k % sh->stride) - GRID_NG,
                                 (int)(k / sh->stride) - GRID_NG);
}

/* Whether ghost entry e is filled by rank r: its cell is in r's block or
 * the halo around it. */
static bool fills(const GksSolver *s, const IbmShare *sh, int64_t cell, int r) {
    int first[2], count[2];
    gks_solver_block(s, r, first, count);
    const int I = (int)(cell % sh->stride), J = (int)(cell / sh->stride); /* padded */
    return I >= first[0] && I < first[0] + count[0] + 2 * GRID_NG && J >= first[1] &&
           J < first[1] + count[1] + 2 * GRID_NG;
}

static int cmp_i64(const void *a, const void *b) {
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return x < y ? -1 : x > y;
}

bool ibm_share_fills(const Ibm *ibm, int64_t cell) {
    const IbmShare *sh = ibm->share;
    return !sh || fills(sh->solver, sh, cell, sh->comm.rank);
}

bool ibm_share_evaluates(const Ibm *ibm, int64_t cell) {
    const IbmShare *sh = ibm->share;
    return !sh || cell_rank(sh->solver, sh, cell) == sh->comm.rank;
}

/* The fluid cells that this process's stencils read and it does not
 * own, sorted and unique, into list (capacity: 4 per entry); their
 * count. */
static int64_t needed(const Ibm *ibm, const GksSolver *s, const IbmShare *sh, int64_t *list) {
    const int r = sh->comm.rank;
    int64_t n = 0;
    const IbmStencilSet *sets[2] = {&ibm->ghosts, &ibm->probes};
    for (int q = 0; q < 2; q++) {
        const IbmStencilSet *S = sets[q];
        for (int e = 0; e < S->n; e++) {
            const bool mine = q == 0 ? fills(s, sh, S->cell[e], r) : sh->probe_rank[e] == r;
            if (!mine) continue;
            for (int m = 0; m < 4; m++) {
                if (S->rseg[4 * e + m] != IBM_NODE_FLUID) continue;
                const int64_t k = S->node[4 * e + m];
                if (cell_rank(s, sh, k) != r) list[n++] = k;
            }
        }
    }
    qsort(list, (size_t)n, sizeof *list, cmp_i64);
    int64_t u = 0;
    for (int64_t i = 0; i < n; i++)
        if (u == 0 || list[i] != list[u - 1]) list[u++] = list[i];
    return u;
}

/* Which process evaluates each probe: the one whose rows hold its point
 * (rank 0 for a point off the grid). */
static void assign_probes(const Ibm *ibm, const GksSolver *s, IbmShare *sh) {
    const IbmStencilSet *P = &ibm->probes;
    sh->nprobes = 0;
    for (int e = 0; e < P->n; e++) {
        const int64_t k = P->cell[e];
        sh->probe_rank[e] = k >= 0 ? cell_rank(s, sh, k) : 0;
        if (sh->probe_rank[e] == sh->comm.rank) sh->probes[sh->nprobes++] = e;
    }
}

/* The shadow as a window [lo, hi) of the whole grid; `keep`: the values of
 * the old window's cells that the new one holds stay (the rest are
 * unset). */
static int set_window(IbmShare *sh, const int lo[2], const int hi[2], bool keep) {
    const int64_t row = hi[0] - lo[0], size = row * (int64_t)(hi[1] - lo[1]);
    double *w[4] = {NULL, NULL, NULL, NULL};
    int status = NSPD_OK;
    for (int v = 0; v < 4 && status == NSPD_OK; v++)
        status = nspd_alloc(&w[v], (size_t)size + 1, sizeof(double));
    if (status != NSPD_OK) { /* nspd_alloc said what */
        for (int v = 0; v < 4; v++) nspd_free(&w[v]);
        return status;
    }
    const int old_row = sh->win_hi[0] - sh->win_lo[0];
    for (int J = lo[1]; keep && J < hi[1]; J++) {
        if (J < sh->win_lo[1] || J >= sh->win_hi[1]) continue;
        const int I0 = lo[0] > sh->win_lo[0] ? lo[0] : sh->win_lo[0];
        const int I1 = hi[0] < sh->win_hi[0] ? hi[0] : sh->win_hi[0];
        if (I0 >= I1) continue;
        for (int v = 0; v < 4; v++)
            memcpy(w[v] + (int64_t)(J - lo[1]) * row + (I0 - lo[0]),
                   sh->w[v] + (int64_t)(J - sh->win_lo[1]) * old_row + (I0 - sh->win_lo[0]),
                   (size_t)(I1 - I0) * sizeof(double));
    }
    for (int v = 0; v < 4; v++) {
        nspd_free(&sh->w[v]);
        sh->w[v] = w[v];
    }
    for (int a = 0; a < 2; a++) sh->win_lo[a] = lo[a], sh->win_hi[a] = hi[a];
    return NSPD_OK;
}

static bool in_window(const IbmShare *sh, int64_t k) {
    const int I = (int)(k % sh->stride), J = (int)(k / sh->stride);
    return I >= sh->win_lo[0] && I < sh->win_hi[0] && J >= sh->win_lo[1] && J < sh->win_hi[1];
}

static int64_t window_index(const IbmShare *sh, int64_t k) {
    return (k / sh->stride - sh->win_lo[1]) * (sh->win_hi[0] - sh->win_lo[0]) +
           (k % sh->stride - sh->win_lo[0]);
}

/* The window of the plan: the box of the cells this process's stencils
 * read, its own and those it fetches (empty where its block holds no
 * wall: then a fill copies nothing). */
static int fit_window(const Ibm *ibm, IbmShare *sh) {
    int lo[2] = {INT_MAX, INT_MAX}, hi[2] = {INT_MIN, INT_MIN};
    const IbmStencilSet *sets[2] = {&ibm->ghosts, &ibm->probes};
    const int *entries[2] = {sh->ghosts, sh->probes}, counts[2] = {sh->nghosts, sh->nprobes};
    for (int q = 0; q < 2; q++)
        for (int i = 0; i < counts[q]; i++)
            for (int m = 0; m < 4; m++) {
                const int e = entries[q][i];
                if (sets[q]->rseg[4 * e + m] != IBM_NODE_FLUID) continue;
                const int64_t k = sets[q]->node[4 * e + m];
                const int at[2] = {(int)(k % sh->stride), (int)(k / sh->stride)};
                for (int a = 0; a < 2; a++) {
                    lo[a] = at[a] < lo[a] ? at[a] : lo[a];
                    hi[a] = at[a] + 1 > hi[a] ? at[a] + 1 : hi[a];
                }
            }
    if (lo[0] > hi[0]) lo[0] = lo[1] = hi[0] = hi[1] = 0; /* nothing read */
    if (sh->w[0] && lo[0] == sh->win_lo[0] && lo[1] == sh->win_lo[1] && hi[0] == sh->win_hi[0] &&
        hi[1] == sh->win_hi[1])
        return NSPD_OK;
    return set_window(sh, lo, hi, false); /* the next refresh fills it */
}

int ibm_share_cover(const Ibm *ibm, const int lo[2], const int hi[2]) {
    IbmShare *sh = ibm->share;
    int l[2], h[2];
    for (int a = 0; a < 2; a++) {
        l[a] = lo[a] < sh->win_lo[a] ? lo[a] : sh->win_lo[a];
        h[a] = hi[a] > sh->win_hi[a] ? hi[a] : sh->win_hi[a];
    }
    if (l[0] == sh->win_lo[0] && l[1] == sh->win_lo[1] && h[0] == sh->win_hi[0] &&
        h[1] == sh->win_hi[1])
        return NSPD_OK;
    return set_window(sh, l, h, true);
}

static int plan(Ibm *ibm, const GksSolver *s, IbmShare *sh) {
    const int p = sh->comm.size, me = sh->comm.rank;
    const IbmStencilSet *G = &ibm->ghosts, *P = &ibm->probes;
    TRY(nspd_alloc(&sh->ghosts, (size_t)G->n + 1, sizeof(int)));
    TRY(nspd_alloc(&sh->probes, (size_t)P->n + 1, sizeof(int)));
    TRY(nspd_alloc(&sh->probe_rank, (size_t)P->n + 1, sizeof(int)));
    for (int e = 0; e < G->n; e++)
        if (fills(s, sh, G->cell[e], me)) sh->ghosts[sh->nghosts++] = e;
    assign_probes(ibm, s, sh);
    /* what this process fetches, grouped by owner in rank order; each
     * owner is told what it sends (its stencils are not built here) */
    int64_t *recv = NULL, *list = NULL;
    int *asked = NULL, *told = NULL;
    TRY(nspd_alloc(&recv, 4 * ((size_t)G->n + (size_t)P->n) + 1, sizeof *recv));
    int status = nspd_alloc(&list, 4 * ((size_t)G->n + (size_t)P->n) + 1, sizeof *list);
    if (status == NSPD_OK) status = nspd_alloc(&sh->recv_first, (size_t)p + 1, sizeof(int));
    if (status == NSPD_OK) status = nspd_alloc(&sh->send_first, (size_t)p + 1, sizeof(int));
    if (status == NSPD_OK) status = nspd_alloc(&asked, (size_t)p, sizeof *asked);
    if (status == NSPD_OK) status = nspd_alloc(&told, (size_t)p, sizeof *told);
    int64_t nrecv = 0, nsend = 0;
    if (status == NSPD_OK) {
        const int64_t n = needed(ibm, s, sh, list);
        for (int q = 0; q < p; q++) {
            sh->recv_first[q] = (int)nrecv;
            for (int64_t i = 0; i < n; i++)
                if (cell_rank(s, sh, list[i]) == q) recv[nrecv++] = list[i];
            asked[q] = (int)(nrecv - sh->recv_first[q]);
        }
        sh->recv_first[p] = (int)nrecv;
        status = comm_ask(&sh->comm, recv, asked, &sh->send_cells, told);
    }
    for (int q = 0; q < p && status == NSPD_OK; q++) {
        sh->send_first[q] = (int)nsend;
        nsend += told[q];
    }
    if (status == NSPD_OK) sh->send_first[p] = (int)nsend;
    sh->recv_cells = recv;
    nspd_free(&list);
    nspd_free(&asked);
    nspd_free(&told);
    TRY(status);
    TRY(nspd_alloc(&sh->send_buf, 4 * (size_t)nsend + 1, sizeof(double)));
    TRY(nspd_alloc(&sh->recv_buf, 4 * (size_t)nrecv + 1, sizeof(double)));
    int **counts[] = {&sh->send_bytes, &sh->send_at, &sh->recv_bytes, &sh->recv_at};
    for (size_t q = 0; q < sizeof counts / sizeof counts[0]; q++)
        TRY(nspd_alloc(counts[q], (size_t)p, sizeof(int)));
    for (int r = 0; r < p; r++) {
        const int unit = 4 * (int)sizeof(double);
        sh->send_at[r] = sh->send_first[r] * unit;
        sh->send_bytes[r] = (sh->send_first[r + 1] - sh->send_first[r]) * unit;
        sh->recv_at[r] = sh->recv_first[r] * unit;
        sh->recv_bytes[r] = (sh->recv_first[r + 1] - sh->recv_first[r]) * unit;
    }
    TRY(nspd_alloc(&sh->probe_mine, 4 * (size_t)P->n + 1, sizeof(double)));
    /* the ghost slots of this process's cells, as the solver reads them */
    const Grid *g = gks_solver_grid(s);
    TRY(nspd_alloc(&sh->slot, (size_t)g->size, sizeof(int32_t)));
    int first[2], count[2];
    gks_solver_block(s, me, first, count);
    for (int64_t k = 0; k < g->size; k++) sh->slot[k] = -1; /* the rows' padding too */
    for (int J = 0; J < g->ny + 2 * GRID_NG; J++)           /* padded indices */
        for (int I = 0; I < g->nx + 2 * GRID_NG; I++)
            sh->slot[(int64_t)J * g->stride + I] =
                ibm->slot[(int64_t)(first[1] + J) * sh->stride + first[0] + I];
    return fit_window(ibm, sh);
}

/* Frees the plan (not the shadow). */
static void free_plan(IbmShare *sh) {
    int **ints[] = {&sh->ghosts,     &sh->probes,     &sh->probe_rank,
                    &sh->recv_first, &sh->send_first, &sh->send_bytes,
                    &sh->send_at,    &sh->recv_bytes, &sh->recv_at};
    for (size_t q = 0; q < sizeof ints / sizeof ints[0]; q++) nspd_free(ints[q]);
    nspd_free(&sh->recv_cells);
    nspd_free(&sh->send_cells);
    nspd_free(&sh->send_buf);
    nspd_free(&sh->recv_buf);
    nspd_free(&sh->probe_mine);
    nspd_free(&sh->slot);
    sh->nghosts = sh->nprobes = 0;
}

int ibm_share_replan(Ibm *ibm) {
    IbmShare *sh = ibm->share;
    free_plan(sh);
    return plan(ibm, sh->solver, sh);
}

int ibm_share_create(Ibm *ibm, GksSolver *s) {
    IbmShare *sh;
    TRY(nspd_alloc(&sh, 1, sizeof *sh));
    ibm->share = sh;
    sh->solver = s;
    sh->comm = *gks_solver_comm(s);
    const Grid *whole = gks_solver_whole_grid(s);
    sh->stride = whole->stride;
    /* owned: the block's cells, and the box's ghost layers where it ends
     * the whole grid (the padded indices of the whole grid) */
    int first[2], count[2];
    gks_solver_block(s, sh->comm.rank, first, count);
    const int n[2] = {whole->nx, whole->ny};
    for (int a = 0; a < 2; a++) {
        sh->own_lo[a] = first[a] == 0 ? 0 : first[a] + GRID_NG;
        sh->own_hi[a] = first[a] + count[a] + (first[a] + count[a] == n[a] ? 2 : 1) * GRID_NG;
    }
    return plan(ibm, s, sh);
}

void ibm_share_free(IbmShare **p) {
    IbmShare *sh = *p;
    if (!sh) return;
    for (int v = 0; v < 4; v++) nspd_free(&sh->w[v]);
    free_plan(sh);
    nspd_free(p);
}

IbmFieldView ibm_share_shadow(const Ibm *ibm) {
    const IbmShare *sh = ibm->share;
    return (IbmFieldView){{sh->w[0], sh->w[1], sh->w[2], sh->w[3]},
                          sh->stride,
                          {sh->win_lo[0], sh->win_lo[1]},
                          sh->win_hi[0] - sh->win_lo[0]};
}

IbmFieldView ibm_share_refresh(const Ibm *ibm, GksSolver *s) {
    IbmShare *sh = ibm->share;
    const GksFields f = gks_solver_fields(s);
    const int p = sh->comm.size;
    for (int r = 0; r < p; r++)
        for (int i = sh->send_first[r]; i < sh->send_first[r + 1]; i++) {
            const int64_t k = gks_solver_local_cell(s, sh->send_cells[i]);
            for (int v = 0; v < 4; v++) sh->send_buf[4 * i + v] = f.w[v][k];
        }
    /* MPI's default handler stops the job on a failed exchange */
    const double t0 = nspd_wall_time();
    (void)comm_alltoallv_bytes(&sh->comm, sh->send_buf, sh->send_bytes, sh->send_at, sh->recv_buf,
                               sh->recv_bytes, sh->recv_at);
    gks_solver_add_comm_seconds(s, nspd_wall_time() - t0);
    /* the owned cells in the window, row by row */
    int lo[2], hi[2];
    for (int a = 0; a < 2; a++) {
        lo[a] = sh->own_lo[a] > sh->win_lo[a] ? sh->own_lo[a] : sh->win_lo[a];
        hi[a] = sh->own_hi[a] < sh->win_hi[a] ? sh->own_hi[a] : sh->win_hi[a];
    }
    for (int J = lo[1]; J < hi[1] && lo[0] < hi[0]; J++) {
        const int64_t k = (int64_t)J * sh->stride + lo[0];
        const int64_t local = gks_solver_local_cell(s, k), at = window_index(sh, k);
        for (int v = 0; v < 4; v++)
            memcpy(sh->w[v] + at, f.w[v] + local, (size_t)(hi[0] - lo[0]) * sizeof(double));
    }
    for (int i = 0; i < sh->recv_first[p]; i++) {
        const int64_t at = window_index(sh, sh->recv_cells[i]);
        for (int v = 0; v < 4; v++) sh->w[v][at] = sh->recv_buf[4 * i + v];
    }
    return ibm_share_shadow(ibm);
}

const int *ibm_share_ghosts(const Ibm *ibm, int *count) {
    *count = ibm->share->nghosts;
    return ibm->share->ghosts;
}

int64_t ibm_share_local(const Ibm *ibm, const GksSolver *s, int64_t cell) {
    return ibm->share ? gks_solver_local_cell(s, cell) : cell;
}

const int32_t *ibm_share_slots(const Ibm *ibm) {
    return ibm->share ? ibm->share->slot : ibm->slot;
}

/* Each probe's (u, v, p, T) from the process that evaluated it, in entry
 * order, into q[4 e ..]. */
int ibm_share_probe_values(const Ibm *ibm, const double *mine, double *q) {
    IbmShare *sh = ibm->share;
    for (int i = 0; i < sh->nprobes; i++) /* packed first: mine may be q */
        memcpy(sh->probe_mine + 4 * i, mine + 4 * sh->probes[i], 4 * sizeof(double));
    return comm_share_items(&sh->comm, ibm->probes.n, sh->probe_rank, 4, sh->probe_mine, q);
}

const int *ibm_share_probes(const Ibm *ibm, int *count) {
    *count = ibm->share->nprobes;
    return ibm->share->probes;
}

int ibm_share_fetch(const Ibm *ibm, int n, const int64_t *cells) {
    IbmShare *sh = ibm->share;
    const GksSolver *s = sh->solver;
    const GksFields f = gks_solver_fields(sh->solver);
    double *mine = NULL, *all = NULL;
    int *owner = NULL;
    int status = nspd_alloc(&mine, 4 * (size_t)n + 1, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&all, 4 * (size_t)n + 1, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&owner, (size_t)n + 1, sizeof(int));
    if (status == NSPD_OK) {
        int count = 0;
        for (int i = 0; i < n; i++) {
            owner[i] = cell_rank(s, sh, cells[i]);
            if (owner[i] != sh->comm.rank) continue;
            const int64_t local = gks_solver_local_cell(s, cells[i]);
            for (int v = 0; v < 4; v++) mine[count++] = f.w[v][local];
        }
        status = comm_share_items(&sh->comm, n, owner, 4, mine, all);
    }
    /* what lies outside the window no stencil of this process reads */
    if (status == NSPD_OK)
        for (int i = 0; i < n; i++) {
            if (!in_window(sh, cells[i])) continue;
            const int64_t at = window_index(sh, cells[i]);
            for (int v = 0; v < 4; v++) sh->w[v][at] = all[4 * i + v];
        }
    nspd_free(&mine);
    nspd_free(&all);
    nspd_free(&owner);
    return status;
}
