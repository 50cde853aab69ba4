/* core/comm.h: MPI where nspd is built with it, the one-process answers
 * otherwise. */
#include "core/comm.h"

#include "core/mem.h"
#include "core/status.h"

#include <string.h>

/* The one-process answers, shared by both builds. */
static int gather_alone(const double *mine, int count, double *all) {
    if (count > 0) memmove(all, mine, (size_t)count * sizeof(double));
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

NspdComm comm_init(int *argc, char ***argv) {
    int ready = 0;
    MPI_Initialized(&ready);
    if (!ready) {
        int provided = 0;
        MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
        initialised_here = true;
    }
    NspdComm c = {0, 1, (int)MPI_Comm_c2f(MPI_COMM_WORLD)};
    MPI_Comm_rank(MPI_COMM_WORLD, &c.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &c.size);
    return c;
}

void comm_finalize(void) {
    int done = 0;
    MPI_Finalized(&done);
    if (initialised_here && !done) MPI_Finalize();
    initialised_here = false;
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

int comm_allgatherv(const NspdComm *c, const double *mine, int count, double *all) {
    if (!comm_distributed(c)) return gather_alone(mine, count, all);
    int *counts = NULL, *offsets = NULL;
    int status = nspd_alloc(&counts, (size_t)c->size, sizeof(int));
    if (status == NSPD_OK) status = nspd_alloc(&offsets, (size_t)c->size, sizeof(int));
    if (status == NSPD_OK) {
        MPI_Allgather(&count, 1, MPI_INT, counts, 1, MPI_INT, mpi_of(c));
        for (int r = 0, at = 0; r < c->size; r++) offsets[r] = at, at += counts[r];
        MPI_Allgatherv(mine, count, MPI_DOUBLE, all, counts, offsets, MPI_DOUBLE, mpi_of(c));
    }
    nspd_free(&counts);
    nspd_free(&offsets);
    return status;
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

#else /* one process */

bool comm_enabled(void) {
    return false;
}

NspdComm comm_init(int *argc, char ***argv) {
    (void)argc, (void)argv;
    return comm_self();
}

void comm_finalize(void) {}

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

int comm_allgatherv(const NspdComm *c, const double *mine, int count, double *all) {
    (void)c;
    return gather_alone(mine, count, all);
}

int comm_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv, int from) {
    (void)c;
    return sendrecv_alone(send, bytes, to, recv, from);
}

#endif

NspdComm comm_self(void) {
    return (NspdComm){0, 1, 0};
}

bool comm_distributed(const NspdComm *c) {
    return c && c->size > 1;
}
