/* core/comm.h: MPI where nspd is built with it, the one-process answers
 * otherwise. */
#include "core/comm.h"

#include "core/mem.h"
#include "core/status.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static NspdComm world_group = {0, 1, 0};

/* comm_at_finalize's hooks; registered from the main thread only (a run's
 * setup), so no lock */
static void (*finalize_hooks[COMM_FINALIZE_HOOKS])(void);
static int finalize_hook_count = 0;

void comm_at_finalize(void (*fn)(void)) {
    for (int k = 0; k < finalize_hook_count; k++)
        if (finalize_hooks[k] == fn) return;
    if (finalize_hook_count < COMM_FINALIZE_HOOKS) finalize_hooks[finalize_hook_count++] = fn;
}

static void run_finalize_hooks(void) {
    while (finalize_hook_count > 0) finalize_hooks[--finalize_hook_count]();
}

NspdComm comm_world(void) {
    return world_group;
}

/* The one-process answers, shared by both builds. */
static int gather_alone(const void *mine, int bytes, void *all) {
    if (bytes > 0) memmove(all, mine, (size_t)bytes);
    return NSPD_OK;
}

static int sendrecv_alone(const void *send, int bytes, int to, void *recv, int from) {
    if (to == 0 && from == 0 && bytes > 0) memmove(recv, send, (size_t)bytes);
    return NSPD_OK;
}

#ifdef NSPD_HAVE_MPI
#include <mpi.h>

static bool initialised_here = false;

static MPI_Comm mpi_of(const NspdComm *c) {
    return MPI_Comm_f2c((MPI_Fint)c->handle);
}

bool comm_enabled(void) {
    return true;
}

/* Whether an MPI launcher started this process: Open MPI's mpirun,
 * MPICH's Hydra and PMIx-based launchers (srun) set these. */
static bool launched(void) {
    static const char *const VARS[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", NULL};
    for (int k = 0; VARS[k]; k++)
        if (getenv(VARS[k])) return true;
    return false;
}

NspdComm comm_init(int *argc, char ***argv) {
    int ready = 0;
    MPI_Initialized(&ready);
    if (!ready && !launched()) return world_group;
    if (!ready) {
        int provided = 0;
        MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
        initialised_here = true;
    }
    NspdComm c = {0, 1, (int)MPI_Comm_c2f(MPI_COMM_WORLD)};
    MPI_Comm_rank(MPI_COMM_WORLD, &c.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &c.size);
    world_group = c;
    return c;
}

void comm_finalize(void) {
    run_finalize_hooks();
    int done = 0;
    MPI_Finalized(&done);
    if (initialised_here && !done) MPI_Finalize();
    initialised_here = false;
    world_group = comm_self();
}

double comm_max(const NspdComm *c, double value) {
    if (!comm_distributed(c)) return value;
    double out = value;
    MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, mpi_of(c));
    return out;
}

static int64_t reduce_i64(const NspdComm *c, int64_t value, MPI_Op op) {
    if (!comm_distributed(c)) return value;
    int64_t out = value;
    MPI_Allreduce(&value, &out, 1, MPI_INT64_T, op, mpi_of(c));
    return out;
}

int64_t comm_min_i64(const NspdComm *c, int64_t value) {
    return reduce_i64(c, value, MPI_MIN);
}
int64_t comm_max_i64(const NspdComm *c, int64_t value) {
    return reduce_i64(c, value, MPI_MAX);
}
int64_t comm_sum_i64(const NspdComm *c, int64_t value) {
    return reduce_i64(c, value, MPI_SUM);
}

int comm_sum_i64_array(const NspdComm *c, int64_t *values, int n) {
    if (!comm_distributed(c) || n <= 0) return NSPD_OK;
    MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_INT64_T, MPI_SUM, mpi_of(c));
    return NSPD_OK;
}

int comm_allgatherv_bytes(const NspdComm *c, const void *mine, int bytes, void *all) {
    if (!comm_distributed(c)) return gather_alone(mine, bytes, all);
    int *counts = NULL, *offsets = NULL;
    int status = nspd_alloc(&counts, (size_t)c->size, sizeof(int));
    if (status == NSPD_OK) status = nspd_alloc(&offsets, (size_t)c->size, sizeof(int));
    if (status == NSPD_OK) {
        MPI_Allgather(&bytes, 1, MPI_INT, counts, 1, MPI_INT, mpi_of(c));
        int64_t at = 0;
        for (int r = 0; r < c->size; r++) offsets[r] = (int)at, at += counts[r];
        if (at > INT32_MAX)
            status = NSPD_FAIL(NSPD_ERR_INTERNAL, "a gather of %lld bytes exceeds MPI's int counts",
                               (long long)at);
    }
    if (status == NSPD_OK)
        MPI_Allgatherv(mine, bytes, MPI_BYTE, all, counts, offsets, MPI_BYTE, mpi_of(c));
    nspd_free(&counts);
    nspd_free(&offsets);
    return status;
}

int comm_share_ranges(const NspdComm *c, double *whole, const int *count, const int *at,
                      bool to_root) {
    if (!comm_distributed(c)) return NSPD_OK;
    if (!to_root)
        MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, whole, count, at, MPI_DOUBLE, mpi_of(c));
    else if (c->rank == 0)
        MPI_Gatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, whole, count, at, MPI_DOUBLE, 0, mpi_of(c));
    else
        MPI_Gatherv(whole + at[c->rank], count[c->rank], MPI_DOUBLE, NULL, NULL, NULL, MPI_DOUBLE,
                    0, mpi_of(c));
    return NSPD_OK;
}

int comm_gatherv(const NspdComm *c, const double *mine, int count, double *all) {
    if (!comm_distributed(c)) return gather_alone(mine, count * (int)sizeof(double), all);
    int *counts = NULL, *offsets = NULL;
    int status = nspd_alloc(&counts, (size_t)c->size, sizeof(int));
    if (status == NSPD_OK) status = nspd_alloc(&offsets, (size_t)c->size, sizeof(int));
    if (status == NSPD_OK) {
        MPI_Gather(&count, 1, MPI_INT, counts, 1, MPI_INT, 0, mpi_of(c));
        for (int r = 0, at = 0; r < c->size; r++) offsets[r] = at, at += counts[r];
        MPI_Gatherv(mine, count, MPI_DOUBLE, all, counts, offsets, MPI_DOUBLE, 0, mpi_of(c));
    }
    nspd_free(&counts);
    nspd_free(&offsets);
    return status;
}

int comm_bcast(const NspdComm *c, void *data, int bytes, int root) {
    if (!comm_distributed(c)) return NSPD_OK;
    MPI_Bcast(data, bytes, MPI_BYTE, root, mpi_of(c));
    return NSPD_OK;
}

int comm_alltoallv_bytes(const NspdComm *c, const void *send, const int *send_bytes,
                         const int *send_at, void *recv, const int *recv_bytes,
                         const int *recv_at) {
    if (!comm_distributed(c))
        return gather_alone((const char *)send + send_at[0], send_bytes[0],
                            (char *)recv + recv_at[0]);
    /* point to point with the ranks that have something to say: an
     * MPI_Alltoallv visits every rank, P latencies a call where most
     * counts are zero (a slab's neighbours are few) */
    MPI_Request *req = NULL;
    TRY(nspd_alloc(&req, 2 * (size_t)c->size, sizeof *req));
    const MPI_Comm m = mpi_of(c);
    int n = 0;
    for (int q = 0; q < c->size; q++)
        if (recv_bytes[q] > 0)
            MPI_Irecv((char *)recv + recv_at[q], recv_bytes[q], MPI_BYTE, q, 1, m, &req[n++]);
    for (int q = 0; q < c->size; q++)
        if (send_bytes[q] > 0)
            MPI_Isend((const char *)send + send_at[q], send_bytes[q], MPI_BYTE, q, 1, m, &req[n++]);
    MPI_Waitall(n, req, MPI_STATUSES_IGNORE);
    nspd_free(&req);
    return NSPD_OK;
}

static void max_i64_n(const NspdComm *c, int64_t *values, int n) {
    MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_INT64_T, MPI_MAX, mpi_of(c));
}

int comm_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv, int from) {
    if (!comm_distributed(c)) return sendrecv_alone(send, bytes, to, recv, from);
    const MPI_Comm m = mpi_of(c);
    const int rc = MPI_Sendrecv(send, to >= 0 ? bytes : 0, MPI_BYTE, to >= 0 ? to : MPI_PROC_NULL,
                                0, recv, from >= 0 ? bytes : 0, MPI_BYTE,
                                from >= 0 ? from : MPI_PROC_NULL, 0, m, MPI_STATUS_IGNORE);
    return rc == MPI_SUCCESS ? NSPD_OK
                             : NSPD_FAIL(NSPD_ERR_IO, "MPI_Sendrecv failed on rank %d", c->rank);
}

int comm_begin_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv,
                        int from, int tag, CommPending *pending) {
    if (!comm_distributed(c)) return sendrecv_alone(send, bytes, to, recv, from);
    if (pending->count + 2 > COMM_MAX_PENDING)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "more than %d exchanges pending", COMM_MAX_PENDING);
    /* the requests are waited by comm_finish through their integer
     * handles, which clang's MPI checker cannot follow (hence the NOLINTs) */
    const MPI_Comm m = mpi_of(c);
    if (from >= 0) {
        MPI_Request rr;
        MPI_Irecv(recv, bytes, MPI_BYTE, from, tag, m, &rr);
        pending->handle[pending->count++] =
            (int)MPI_Request_c2f(rr); // NOLINT(clang-analyzer-optin.mpi.MPI-Checker)
    }
    if (to >= 0) {
        MPI_Request rs;
        MPI_Isend(send, bytes, MPI_BYTE, to, tag, m, &rs);
        pending->handle[pending->count++] =
            (int)MPI_Request_c2f(rs); // NOLINT(clang-analyzer-optin.mpi.MPI-Checker)
    }
    return NSPD_OK; // NOLINT(clang-analyzer-optin.mpi.MPI-Checker)
}

int comm_finish(const NspdComm *c, CommPending *pending) {
    (void)c;
    for (int k = 0; k < pending->count; k++) {
        MPI_Request r = MPI_Request_f2c((MPI_Fint)pending->handle[k]);
        MPI_Wait(&r, MPI_STATUS_IGNORE); // NOLINT(clang-analyzer-optin.mpi.MPI-Checker)
    }
    pending->count = 0;
    return NSPD_OK;
}

#else /* one process */

bool comm_enabled(void) {
    return false;
}

NspdComm comm_init(int *argc, char ***argv) {
    (void)argc, (void)argv;
    return comm_self();
}

void comm_finalize(void) {
    run_finalize_hooks();
}

double comm_max(const NspdComm *c, double value) {
    return (void)c, value;
}
int64_t comm_min_i64(const NspdComm *c, int64_t value) {
    return (void)c, value;
}
int64_t comm_max_i64(const NspdComm *c, int64_t value) {
    return (void)c, value;
}
int64_t comm_sum_i64(const NspdComm *c, int64_t value) {
    return (void)c, value;
}
int comm_sum_i64_array(const NspdComm *c, int64_t *values, int n) {
    return (void)c, (void)values, (void)n, NSPD_OK;
}

int comm_allgatherv_bytes(const NspdComm *c, const void *mine, int bytes, void *all) {
    (void)c;
    return gather_alone(mine, bytes, all);
}

int comm_share_ranges(const NspdComm *c, double *whole, const int *count, const int *at,
                      bool to_root) {
    (void)c, (void)whole, (void)count, (void)at, (void)to_root;
    return NSPD_OK; /* one process holds every range */
}

int comm_gatherv(const NspdComm *c, const double *mine, int count, double *all) {
    (void)c;
    return gather_alone(mine, count * (int)sizeof(double), all);
}

int comm_bcast(const NspdComm *c, void *data, int bytes, int root) {
    (void)c, (void)data, (void)bytes, (void)root;
    return NSPD_OK;
}

int comm_alltoallv_bytes(const NspdComm *c, const void *send, const int *send_bytes,
                         const int *send_at, void *recv, const int *recv_bytes,
                         const int *recv_at) {
    (void)c, (void)recv_bytes;
    return gather_alone((const char *)send + send_at[0], send_bytes[0], (char *)recv + recv_at[0]);
}

static void max_i64_n(const NspdComm *c, int64_t *values, int n) {
    (void)c, (void)values, (void)n;
}

int comm_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv, int from) {
    (void)c;
    return sendrecv_alone(send, bytes, to, recv, from);
}

int comm_begin_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv,
                        int from, int tag, CommPending *pending) {
    (void)c, (void)tag, (void)pending;
    return sendrecv_alone(send, bytes, to, recv, from);
}

int comm_finish(const NspdComm *c, CommPending *pending) {
    (void)c;
    pending->count = 0;
    return NSPD_OK;
}

#endif

NspdComm comm_self(void) {
    return (NspdComm){0, 1, 0};
}

bool comm_distributed(const NspdComm *c) {
    return c && c->size > 1;
}

int comm_allgatherv(const NspdComm *c, const double *mine, int count, double *all) {
    if ((int64_t)count * (int64_t)sizeof(double) > INT32_MAX)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "a gather of %d doubles exceeds MPI's int counts",
                         count);
    return comm_allgatherv_bytes(c, mine, count * (int)sizeof(double), all);
}

int comm_agree(const NspdComm *c, int status, int64_t *flags, int n) {
    if (!comm_distributed(c)) return status;
    enum { MAX_FLAGS = 7 };
    int64_t v[MAX_FLAGS + 1] = {0};
    if (n > MAX_FLAGS) return NSPD_FAIL(NSPD_ERR_INTERNAL, "comm_agree takes %d flags", MAX_FLAGS);
    /* the largest of size - rank over the failed ranks is the lowest of them */
    v[0] = status != NSPD_OK ? c->size - c->rank : 0;
    for (int k = 0; k < n; k++) v[k + 1] = flags[k];
    max_i64_n(c, v, n + 1);
    for (int k = 0; k < n; k++) flags[k] = v[k + 1];
    if (v[0] == 0) return NSPD_OK;
    const int failed = c->size - (int)v[0];
    struct {
        int status;
        char message[1800];
    } said = {status, ""};
    if (c->rank == failed) snprintf(said.message, sizeof said.message, "%s", nspd_error_message());
    comm_bcast(c, &said, (int)sizeof said, failed);
    /* the same words on every rank, the failed one included */
    if (failed > 0)
        return nspd_error(said.status, __FILE__, __LINE__, "on rank %d: %s", failed, said.message);
    if (c->rank == failed) return status;
    return nspd_error(said.status, __FILE__, __LINE__, "%s", said.message);
}

int comm_share_items(const NspdComm *c, int64_t n, const int *owner, int width, const double *mine,
                     double *all) {
    const int p = comm_distributed(c) ? c->size : 1, me = comm_distributed(c) ? c->rank : 0;
    int64_t *at = NULL;
    double *gathered = NULL;
    int status = nspd_alloc(&at, (size_t)p + 1, sizeof *at);
    if (status == NSPD_OK) status = nspd_alloc(&gathered, (size_t)(n * width) + 1, sizeof(double));
    if (status == NSPD_OK) {
        for (int64_t k = 0; k < n; k++) at[owner[k] + 1] += width;
        status = comm_allgatherv(c, mine, (int)at[me + 1], gathered);
        for (int r = 0; r < p; r++) at[r + 1] += at[r]; /* each rank's first value */
    }
    if (status == NSPD_OK)
        for (int64_t k = 0; k < n; k++) {
            memcpy(all + k * width, gathered + at[owner[k]], (size_t)width * sizeof(double));
            at[owner[k]] += width;
        }
    nspd_free(&at);
    nspd_free(&gathered);
    return status;
}

int comm_ask(const NspdComm *c, const int64_t *asked, const int *count, int64_t **told,
             int *told_count) {
    const int p = comm_distributed(c) ? c->size : 1;
    const int unit = (int)sizeof(int64_t);
    int *bytes = NULL;
    *told = NULL;
    TRY(nspd_alloc(&bytes, 4 * (size_t)p, sizeof *bytes));
    int *at = bytes + p, *told_bytes = bytes + 2 * p, *told_at = bytes + 3 * p;
    for (int q = 0; q < p; q++) {
        bytes[q] = told_bytes[q] = (int)sizeof(int);
        at[q] = told_at[q] = q * (int)sizeof(int);
    }
    int status = comm_alltoallv_bytes(c, count, bytes, at, told_count, told_bytes, told_at);
    int64_t asks = 0, tells = 0;
    for (int q = 0; q < p && status == NSPD_OK; q++) {
        bytes[q] = count[q] * unit, at[q] = (int)(asks * unit);
        told_bytes[q] = told_count[q] * unit, told_at[q] = (int)(tells * unit);
        asks += count[q], tells += told_count[q];
    }
    if (status == NSPD_OK) status = nspd_alloc(told, (size_t)tells + 1, sizeof **told);
    if (status == NSPD_OK)
        status = comm_alltoallv_bytes(c, asked, bytes, at, *told, told_bytes, told_at);
    nspd_free(&bytes);
    if (status != NSPD_OK) nspd_free(told);
    return status;
}

int64_t comm_first_failure(const NspdComm *c, int64_t mine, char *text, int size) {
    if (!comm_distributed(c)) return mine;
    const int64_t first = comm_min_i64(c, mine);
    if (first == INT64_MAX) return first;
    const int64_t root = comm_min_i64(c, mine == first ? c->rank : INT64_MAX);
    (void)comm_bcast(c, text, size, (int)root); /* a failed broadcast is MPI's abort */
    return first;
}
