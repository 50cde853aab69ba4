#include "core/balance.h"
#include "core/timer.h"

#include <math.h>
#include <omp.h>

/* No thread's share below about this fraction of an equal one (the
 * shares are normalised after the floor): every thread keeps some items,
 * so that its rate stays measured. */
static const double MIN_SHARE = 0.125;

static int balanced(const Balance *b, int threads) {
    return b && threads > 1 && threads <= BALANCE_MAX_THREADS && b->threads == threads;
}

void balance_range(const Balance *b, int t, int threads, int64_t n, int64_t *lo, int64_t *hi) {
    if (!balanced(b, threads)) {
        *lo = n * t / threads;
        *hi = n * (t + 1) / threads;
        return;
    }
    /* both ends from the same cuts: the ranges tile [0, n) */
    *lo = t == 0 ? 0 : (int64_t)llround(b->cut[t] * (double)n);
    *hi = t + 1 == threads ? n : (int64_t)llround(b->cut[t + 1] * (double)n);
}

void balance_record(Balance *b, int t, int threads, double seconds) {
    if (!b || threads > BALANCE_MAX_THREADS) return;
    b->seconds[t] = seconds;
    if (t == 0) b->ran = threads;
}

double balance_begin(const Balance *b, int64_t n, int64_t *lo, int64_t *hi) {
    balance_range(b, omp_get_thread_num(), omp_get_num_threads(), n, lo, hi);
    return nspd_wall_time();
}

void balance_end(Balance *b, double started) {
    balance_record(b, omp_get_thread_num(), omp_get_num_threads(), nspd_wall_time() - started);
}

void balance_update(Balance *b) {
    if (!b) return;
    const int n = b->ran;
    b->ran = 0;
    if (n <= 1 || n > BALANCE_MAX_THREADS) {
        b->threads = 0;
        return;
    }
    if (b->threads != n) { /* the run had equal shares */
        for (int t = 0; t <= n; t++) b->cut[t] = (double)t / n;
        b->threads = n;
    }
    double rate[BALANCE_MAX_THREADS], total = 0.0;
    for (int t = 0; t < n; t++) {
        if (!(b->seconds[t] > 0.0)) return; /* not measured: keep the cuts */
        rate[t] = (b->cut[t + 1] - b->cut[t]) / b->seconds[t];
        total += rate[t];
    }
    /* half-way from each share to the one that would have equalised the
     * times, each at least MIN_SHARE of an equal share */
    double share[BALANCE_MAX_THREADS], sum = 0.0;
    for (int t = 0; t < n; t++) {
        const double old = b->cut[t + 1] - b->cut[t];
        share[t] = fmax(0.5 * (old + rate[t] / total), MIN_SHARE / n);
        sum += share[t];
    }
    double c = 0.0;
    for (int t = 0; t < n; t++) {
        b->cut[t] = c;
        c += share[t] / sum;
    }
    b->cut[n] = 1.0;
}
