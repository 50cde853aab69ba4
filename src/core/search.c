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
