/* The distributed engine (MPI; issue 28), behind plain C.
 *
 * A model that runs on several processes takes an NspdComm: its rank, its
 * size and the handle of the MPI communicator of the group. Built without
 * MPI (-DNSPD_MPI=OFF), or given NULL or a group of one, every operation
 * below is the one-process answer and nothing is sent, so the same code
 * runs serially without mpirun.
 *
 * Reductions that must not depend on the number of processes never add
 * doubles across processes (MPI_SUM's order is the library's): a max, a
 * min and an integer sum are exact; a floating-point total is gathered
 * (comm_allgatherv) and summed in a fixed global order by the caller. */
#ifndef NSPD_CORE_COMM_H
#define NSPD_CORE_COMM_H

#include <stdbool.h>
#include <stdint.h>

typedef struct {
    int rank, size;
    int handle; /* MPI_Comm_c2f of the group's communicator (a portable integer) */
} NspdComm;

/* MPI_Init where nspd is built with MPI, started by an MPI launcher
 * (mpirun, mpiexec, srun: their environment says so) and not yet
 * initialised (the thread level funneled: OpenMP threads inside a rank
 * never call MPI); otherwise nothing, so a plain `nspd run` starts no MPI
 * runtime. Returns the world group (comm_self() without MPI). */
NspdComm comm_init(int *argc, char ***argv);
/* The group comm_init returned; comm_self() before it or without MPI. */
NspdComm comm_world(void);
/* Runs the hooks comm_at_finalize registered (last first), then
 * MPI_Finalize where comm_init initialised MPI. */
void comm_finalize(void);
/* fn runs at comm_finalize, before MPI_Finalize: what a library started on
 * top of MPI (PETSc: flow/pddo/ppe_petsc.h) must end first. At most
 * COMM_FINALIZE_HOOKS; registering the same fn twice keeps one. */
enum { COMM_FINALIZE_HOOKS = 4 };
void comm_at_finalize(void (*fn)(void));
/* Whether this build has MPI. */
bool comm_enabled(void);

/* The one-process group (rank 0 of 1). */
NspdComm comm_self(void);
/* Whether c spans more than one process (NULL: no). */
bool comm_distributed(const NspdComm *c);

/* Exact reductions over the group, the result on every rank. */
double comm_max(const NspdComm *c, double value);
int64_t comm_min_i64(const NspdComm *c, int64_t value);
int64_t comm_max_i64(const NspdComm *c, int64_t value);
int64_t comm_sum_i64(const NspdComm *c, int64_t value);
/* values[0..n) summed element by element over the group, in place on
 * every rank (integers: exact). */
int comm_sum_i64_array(const NspdComm *c, int64_t *values, int n);

/* Every rank's `count` doubles, concatenated in rank order into all[] on
 * every rank (counts may differ between ranks; all holds their sum). */
int comm_allgatherv(const NspdComm *c, const double *mine, int count, double *all);

/* whole[] laid out in ranges, rank r's at[r] .. at[r] + count[r] (arrays
 * of `size` entries, the same on every rank): each rank's range copied
 * from that rank into whole[] on every rank (to_root: on rank 0 only), in
 * place; one collective, no allocation. What a model whose every rank
 * keeps the whole array and updates its own range calls after each
 * update (the PDDO flow, flow/pddo/share.h). */
int comm_share_ranges(const NspdComm *c, double *whole, const int *count, const int *at,
                      bool to_root);

/* Every rank's `count` doubles, concatenated in rank order into all[] on
 * rank 0 only (all is not read elsewhere and may be NULL there): what a
 * writer on rank 0 gathers without the whole on every rank. */
int comm_gatherv(const NspdComm *c, const double *mine, int count, double *all);

/* Items 0..n-1, item k held by rank owner[k]: each rank passes the
 * `width` values of each item it holds, in item order (mine), and every
 * rank gets every item's values in item order in all[n * width]. One
 * gather; what a replicated model asks of a divided one (a cell's state,
 * a probe's value) answered alike everywhere. */
int comm_share_items(const NspdComm *c, int64_t n, const int *owner, int width, const double *mine,
                     double *all);

/* The same for bytes (each rank's count in bytes). */
int comm_allgatherv_bytes(const NspdComm *c, const void *mine, int bytes, void *all);

/* Lists asked of the ranks that hold what they name (a halo's plan):
 * this rank asks count[q] items of rank q, asked[] grouped by rank in rank
 * order; it is told what the ranks ask of it, *told (nspd_alloc'd, the
 * caller frees it) grouped by asking rank in rank order, told_count[q]
 * of rank q (arrays of `size` entries). One exchange of the counts and
 * one of the items. */
int comm_ask(const NspdComm *c, const int64_t *asked, const int *count, int64_t **told,
             int *told_count);

/* Each rank sends send_bytes[q] bytes from send + send_at[q] to rank q
 * and receives recv_bytes[q] bytes from rank q at recv + recv_at[q]
 * (arrays of `size` entries; the counts must match pairwise). Messages
 * go only where a count is not zero, so a call costs the latencies of
 * the partners, not of every rank. */
int comm_alltoallv_bytes(const NspdComm *c, const void *send, const int *send_bytes,
                         const int *send_at, void *recv, const int *recv_bytes, const int *recv_at);

/* Rank `root`'s `bytes` at data, copied into data on every rank. */
int comm_bcast(const NspdComm *c, void *data, int bytes, int root);

/* What one process decides, all do: every rank passes its own status (and
 * flags[n], reduced to their maximum in place); every rank gets back the
 * status of the lowest rank that failed, with that rank's message recorded
 * on every rank ("on rank R: ..." where R > 0), or NSPD_OK. One
 * reduction (a broadcast more on a failure); a failure on one rank then
 * stops all of them at the same point, and none waits for a partner that
 * left. */
int comm_agree(const NspdComm *c, int status, int64_t *flags, int n);

/* The first failure of a loop divided between the ranks: every rank
 * passes the whole run's index of its first failing item (INT64_MAX:
 * none) and, where it has one, its message in text[size]; every rank gets
 * the lowest index back and, where there is one, the message of the rank
 * that holds that item in text. So every rank fails with the words one
 * process would print. */
int64_t comm_first_failure(const NspdComm *c, int64_t mine, char *text, int size);

/* Sends `bytes` to rank `to` and receives `bytes` from rank `from` (-1:
 * nothing that way), as one exchange that cannot deadlock. */
int comm_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv, int from);

/* Exchanges begun and not yet finished: MPI's requests as portable
 * integers (MPI_Request_c2f). */
enum { COMM_MAX_PENDING = 32 };
typedef struct {
    int count;
    int handle[COMM_MAX_PENDING];
} CommPending;

/* comm_sendrecv begun (tag: which of a caller's exchanges this is, the
 * same on both sides): the buffers must not be touched until comm_finish.
 * At most COMM_MAX_PENDING / 2 at once. */
int comm_begin_sendrecv(const NspdComm *c, const void *send, int bytes, int to, void *recv,
                        int from, int tag, CommPending *pending);
/* Waits for every exchange begun into `pending`, and empties it. */
int comm_finish(const NspdComm *c, CommPending *pending);

#endif
