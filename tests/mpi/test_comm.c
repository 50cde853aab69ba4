/* The distributed engine's own operations (core/comm.h), on 1 to 4 ranks:
 *   - comm_agree: a failure on one rank only (the last) reaches every rank
 *     with its status and message ("on rank R: ..."), the flags are
 *     reduced to their maximum, and with no failure every rank gets
 *     NSPD_OK and no message;
 *   - comm_gatherv: the ranks' parts in rank order on rank 0 only;
 *   - comm_alltoallv_bytes: each rank sends rank q (q != itself) q + 1
 *     values naming sender and receiver, and receives the right ones;
 *   - comm_ask: each rank asks rank q (itself too) for q + 1 items naming
 *     asker and holder, and is told exactly what each rank asked of it,
 *     grouped by asker in rank order;
 *   - comm_bcast from the last rank.
 * Every check is collective (each rank calls it, its verdict reduced). */
#include "core/comm.h"
#include "core/mem.h"
#include "core/status.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static NspdComm world;
static int failures = 0;

static void check(bool ok, const char *what) {
    if (comm_max_i64(&world, ok ? 0 : 1)) {
        failures++;
        if (world.rank == 0) fprintf(stderr, "FAIL %s\n", what);
    }
}

static void agree(void) {
    const int last = world.size - 1;
    nspd_error_clear();
    int64_t flags[2] = {world.rank == last ? 7 : world.rank, 0};
    int status = comm_agree(&world, NSPD_OK, flags, 2);
    check(status == NSPD_OK && nspd_error_message()[0] == '\0', "no failure: NSPD_OK everywhere");
    check(flags[0] == 7 && flags[1] == 0, "flags reduced to their maximum");
    const int mine = world.rank == last ? NSPD_FAIL(NSPD_ERR_IO, "disk full at step 12") : NSPD_OK;
    status = comm_agree(&world, mine, NULL, 0);
    char expected[128];
    if (last > 0)
        snprintf(expected, sizeof expected, "on rank %d: disk full at step 12", last);
    else
        snprintf(expected, sizeof expected, "disk full at step 12");
    check(status == NSPD_ERR_IO, "the failed rank's status on every rank");
    check(strcmp(nspd_error_message(), expected) == 0, "the failed rank's message on every rank");
    nspd_error_clear();
}

static void gather(void) {
    const int count = world.rank + 1, total = world.size * (world.size + 1) / 2;
    double mine[8], all[64];
    for (int k = 0; k < count; k++) mine[k] = 100.0 * world.rank + k;
    for (int k = 0; k < total; k++) all[k] = -1.0;
    check(comm_gatherv(&world, mine, count, all) == NSPD_OK, "gatherv");
    bool ok = true;
    if (world.rank == 0)
        for (int r = 0, at = 0; r < world.size; r++)
            for (int k = 0; k <= r; k++) ok = ok && all[at++] == 100.0 * r + k;
    else
        ok = all[0] == -1.0; /* nothing arrives elsewhere */
    check(ok, "gatherv: the parts in rank order on rank 0 only");
}

static void exchange(void) {
    const int p = world.size, me = world.rank;
    double send[64] = {0}, recv[64] = {0};
    int sb[4] = {0}, sa[4] = {0}, rb[4] = {0}, ra[4] = {0};
    int at = 0, rat = 0;
    for (int q = 0; q < p; q++) {
        const int n = q == me ? 0 : q + 1; /* to q: q + 1 values */
        sa[q] = at * 8, sb[q] = n * 8;
        for (int k = 0; k < n; k++) send[at++] = 1000.0 * me + 10.0 * q + k;
        const int m = q == me ? 0 : me + 1; /* from q: my rank + 1 values */
        ra[q] = rat * 8, rb[q] = m * 8;
        rat += m;
    }
    for (int k = 0; k < rat; k++) recv[k] = -1.0;
    check(comm_alltoallv_bytes(&world, send, sb, sa, recv, rb, ra) == NSPD_OK, "alltoallv");
    bool ok = true;
    for (int q = 0, i = 0; q < p; q++)
        for (int k = 0; k < (q == me ? 0 : me + 1); k++)
            ok = ok && recv[i++] == 1000.0 * q + 10.0 * me + k;
    check(ok, "alltoallv: what each rank sent each other");
}

static void ask(void) {
    const int p = world.size, me = world.rank;
    int64_t asked[16];
    int count[4] = {0}, told_count[4] = {-1, -1, -1, -1};
    int n = 0;
    for (int q = 0; q < p; q++) {
        count[q] = q + 1;
        for (int k = 0; k < q + 1; k++) asked[n++] = 1000 * me + 10 * q + k;
    }
    int64_t *told = NULL;
    check(comm_ask(&world, asked, count, &told, told_count) == NSPD_OK, "ask");
    bool ok = told != NULL;
    for (int q = 0, i = 0; q < p && ok; q++) {
        ok = told_count[q] == me + 1; /* every rank asks me for my rank + 1 items */
        for (int k = 0; k < told_count[q] && ok; k++) ok = told[i++] == 1000 * q + 10 * me + k;
    }
    check(ok, "ask: what each rank asked of this one, by asker");
    nspd_free(&told);
}

static void broadcast(void) {
    double v = world.rank == world.size - 1 ? 42.5 : 0.0;
    check(comm_bcast(&world, &v, sizeof v, world.size - 1) == NSPD_OK && v == 42.5,
          "bcast from the last rank");
}

int main(int argc, char **argv) {
    world = comm_init(&argc, &argv);
    if (world.size > 4) {
        if (world.rank == 0) fprintf(stderr, "at most 4 ranks\n");
        comm_finalize();
        return 2;
    }
    agree();
    gather();
    exchange();
    ask();
    broadcast();
    if (world.rank == 0)
        printf("%s on %d ranks\n", failures ? "FAILED" : "comm operations right", world.size);
    comm_finalize();
    return failures ? 1 : 0;
}
