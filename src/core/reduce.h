/* Deterministic parallel reductions.
 *
 * A floating-point sum depends on its order. To give bitwise-identical
 * results at any thread count, every reduction in nspd splits [0, n) into
 * REDUCE_CHUNKS fixed chunks (independent of the thread count), sums each
 * chunk in index order, then adds the chunk sums in chunk order. Use it as
 *
 *     double partial[REDUCE_CHUNKS];
 *     #pragma omp parallel for schedule(static)
 *     for (int c = 0; c < REDUCE_CHUNKS; c++) {
 *         int64_t lo, hi; reduce_chunk(n, c, &lo, &hi);
 *         double s = 0; for (int64_t i = lo; i < hi; i++) s += term(i);
 *         partial[c] = s;
 *     }
 *     double total = reduce_combine(partial);
 */
#ifndef NSPD_CORE_REDUCE_H
#define NSPD_CORE_REDUCE_H

#include <stdint.h>

enum { REDUCE_CHUNKS = 256 };

static inline void reduce_chunk(int64_t n, int chunk, int64_t *lo, int64_t *hi) {
    *lo = n * chunk / REDUCE_CHUNKS;
    *hi = n * (chunk + 1) / REDUCE_CHUNKS;
}

static inline double reduce_combine(const double partial[REDUCE_CHUNKS]) {
    double total = 0.0;
    for (int c = 0; c < REDUCE_CHUNKS; c++) total += partial[c];
    return total;
}

/* Sum of a[0..n) in the deterministic order above (parallel). */
double reduce_sum(const double *a, int64_t n);

#endif
