/* A parallel region of one thread, run without a team (libgomp only).
 *
 * Why: GCC compiles every `#pragma omp parallel` (and `parallel for` with a
 * static schedule) to a call of libgomp's GOMP_parallel(fn, data,
 * num_threads, flags), fn the region's body. A region whose `if` clause is
 * false, or any region when one thread is asked for (`--threads 1`), still
 * gets a team of one from libgomp: its set-up and, at the end, a barrier
 * whose last arrival issues a futex wake-up system call, with nobody to
 * wake. That costs 1.1-1.4 us a region on this project's machines
 * (virtual, where a system call is dear), and a PDDO step has 21 regions:
 * the Re 100 cavity's flow at 30 x 30 on one thread took 0.205 s with
 * them and takes 0.171 s without (docs/PERFORMANCE.md, 2026-12-05). The `if (n >=
 * PARALLEL_MIN_ITEMS)` clauses (parallel.h) were meant to make small loops cheap, and without this
 * they did not.
 *
 * So nspd defines GOMP_parallel itself: where the team would have one
 * thread and no team is active around it, it calls fn(data) on the calling
 * thread, and otherwise passes the call to libgomp's own (found with
 * dlsym(RTLD_NEXT)). Outside a team libgomp answers a thread number of 0
 * and a count of 1, and runs orphaned worksharing (`omp for`, `single`,
 * `barrier`, reductions) as on a team of one, so the body computes what it
 * computed on its team of one, bit for bit (unit.core.parallel). Inside an
 * active team it never skips: there the thread number must stay its
 * own team's. Under another OpenMP runtime (clang's libomp calls
 * __kmpc_fork_call) this function is simply never called. */
#define _GNU_SOURCE 1 /* RTLD_NEXT */
#include "core/parallel.h"

#include <dlfcn.h>
#include <omp.h>

typedef void (*RegionBody)(void *);
typedef void (*GompParallel)(RegionBody fn, void *data, unsigned num_threads, unsigned flags);

/* libgomp's ABI (GCC >= 4.9): num_threads is 0 where the region names no
 * count and its `if` holds, 1 where the `if` fails, else the clause's. */
void GOMP_parallel(RegionBody fn, void *data, unsigned num_threads, unsigned flags);

void GOMP_parallel(RegionBody fn, void *data, unsigned num_threads, unsigned flags) {
    const int one = num_threads == 1 || (num_threads == 0 && omp_get_max_threads() == 1);
    if (one && !omp_in_parallel()) {
        fn(data);
        return;
    }
    /* every thread that looks it up finds the same function, so the race
     * between two first callers is harmless; relaxed atomics say so */
    static GompParallel libgomp_parallel;
    GompParallel real = __atomic_load_n(&libgomp_parallel, __ATOMIC_RELAXED);
    if (!real) {
        *(void **)&real = dlsym(RTLD_NEXT, "GOMP_parallel");
        __atomic_store_n(&libgomp_parallel, real, __ATOMIC_RELAXED);
    }
    if (!real) { /* no libgomp behind this one (a static link): no results
                  * depend on the thread count, so one thread is right */
        fn(data);
        return;
    }
    real(fn, data, num_threads, flags);
}

int parallel_region_skips_team(void) {
    int skipped = 0;
#pragma omp parallel num_threads(1)
    skipped = omp_get_level() == 0;
    return skipped;
}
