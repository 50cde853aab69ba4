/* The cost of a parallel region of one thread (docs/PERFORMANCE.md, "A
 * region of one thread without a team"): 200,000 empty regions whose `if`
 * fails, then 200,000 under omp_set_num_threads(1), each timed as a whole;
 * prints microseconds a region. Built twice, against libgomp alone and with
 * nspd's own GOMP_parallel (src/core/parallel.c) linked in:
 *   gcc -O2 -fopenmp omp_region.c -o /tmp/region_libgomp && /tmp/region_libgomp
 *   gcc -O2 -fopenmp -I../src omp_region.c ../src/core/parallel.c -ldl \
 *       -o /tmp/region_nspd && /tmp/region_nspd
 * Measured on the AMD EPYC (2026-12-05): libgomp alone 1.1-1.4 us a region
 * either way (1.14-1.22 in three runs); with nspd's 0.003-0.006 us, a call. */
#include <omp.h>
#include <stdio.h>

enum { REGIONS = 200000 };

static volatile double sink;

int main(int argc, char **argv) {
    (void)argv;
    const int team = argc > 5; /* false, unknown to the compiler */
    double t0 = omp_get_wtime();
    for (int i = 0; i < REGIONS; i++) {
#pragma omp parallel if (team)
        sink += 1.0;
    }
    const double if_false = (omp_get_wtime() - t0) / REGIONS;
    omp_set_num_threads(1);
    t0 = omp_get_wtime();
    for (int i = 0; i < REGIONS; i++) {
#pragma omp parallel
        sink += 1.0;
    }
    const double one_thread = (omp_get_wtime() - t0) / REGIONS;
    printf("a region whose if fails: %.3f us; a region under one thread: %.3f us\n", 1e6 * if_false,
           1e6 * one_thread);
    return 0;
}
