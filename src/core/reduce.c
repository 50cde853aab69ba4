#include "core/reduce.h"
#include "core/parallel.h"

double reduce_sum(const double *a, int64_t n) {
    double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int c = 0; c < REDUCE_CHUNKS; c++) {
        int64_t lo, hi;
        reduce_chunk(n, c, &lo, &hi);
        double s = 0.0;
        for (int64_t i = lo; i < hi; i++) s += a[i];
        partial[c] = s;
    }
    return reduce_combine(partial);
}
