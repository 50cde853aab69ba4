/* Contiguous shares of a loop for the threads of a team, moved after
 * each run toward equal time per thread.
 *
 * A static schedule gives every thread the same number of items and so
 * runs at the pace of the slowest core. Cores are not alike: a laptop's
 * efficiency cores, a core whose SMT sibling is busy, a virtual CPU whose
 * host is shared. On this project's 2-core machine one core ran the bond
 * force's half 30 % slower than the other, and the faster thread spent
 * 12 % of the step waiting (perf, per thread). A Balance keeps each
 * thread's range contiguous (the locality of a static schedule; dynamic
 * and guided schedules were slower, docs/PERFORMANCE.md) and, after each
 * run, gives each thread a share in proportion to the rate it was
 * measured at, half-way from the old share (so one slow run moves the
 * cuts only half-way).
 *
 * Only for loops whose results do not depend on which thread takes an
 * item (every item's arithmetic its own, reductions exact or none): the
 * cuts move with the machine's noise, the bits must not.
 *
 *     #pragma omp parallel if (...)
 *     {
 *         int64_t lo, hi;
 *         const double started = balance_begin(b, n, &lo, &hi);
 *         ... items [lo, hi) ...
 *         balance_end(b, started);
 *     }
 *     balance_update(b);
 */
#ifndef NSPD_CORE_BALANCE_H
#define NSPD_CORE_BALANCE_H

#include <stdint.h>

/* Teams larger than this get equal shares (a static schedule). */
enum { BALANCE_MAX_THREADS = 64 };

typedef struct {
    int threads; /* the team the cuts are for; 0 before the first run */
    int ran;     /* the team of the last run (balance_record) */
    /* thread t takes the fraction [cut[t], cut[t + 1]) of the items */
    double cut[BALANCE_MAX_THREADS + 1];
    double seconds[BALANCE_MAX_THREADS]; /* each thread's time in the last run */
} Balance;

/* Thread t's items [lo, hi) of n, in a team of `threads`: equal shares
 * for a team the cuts are not for, or where b is NULL (as the two below
 * then do nothing). */
void balance_range(const Balance *b, int t, int threads, int64_t n, int64_t *lo, int64_t *hi);

/* Thread t's time on its range in this run (each thread its own slot). */
void balance_record(Balance *b, int t, int threads, double seconds);

/* In a parallel region: the calling thread's items [lo, hi) of n
 * (balance_range for its number in its team), and the time it starts at,
 * for balance_end to record (balance_record) when its items are done. */
double balance_begin(const Balance *b, int64_t n, int64_t *lo, int64_t *hi);
void balance_end(Balance *b, double started);

/* After the run (outside the region): the new cuts. */
void balance_update(Balance *b);

#endif
