#include "core/search.h"

int search_bracket(const double *v, int lo, int hi, double x) {
    while (hi - lo > 1) { /* v[lo] <= x < v[hi] */
        const int mid = lo + (hi - lo) / 2;
        if (v[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* The first index of v[0 .. n) at or past x (v of any integer type). */
#define FIRST_AT_LEAST(v, n, x)                                                                    \
    do {                                                                                           \
        int64_t lo = 0, hi = (n);                                                                  \
        while (lo < hi) { /* v[lo - 1] < x <= v[hi] */                                             \
            const int64_t mid = lo + (hi - lo) / 2;                                                \
            if ((v)[mid] < (x))                                                                    \
                lo = mid + 1;                                                                      \
            else                                                                                   \
                hi = mid;                                                                          \
        }                                                                                          \
        return lo;                                                                                 \
    } while (0)

int64_t search_first_at_least(const int64_t *v, int64_t n, int64_t x) {
    FIRST_AT_LEAST(v, n, x);
}

int64_t search_first_at_least_i32(const int32_t *v, int64_t n, int64_t x) {
    FIRST_AT_LEAST(v, n, x);
}
