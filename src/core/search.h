/* Binary search in an increasing array: over axes, faces and centres
 * (grids, pictures, samples), and over offsets (the PDDO solve's runs, the
 * operators' slices by cost). */
#ifndef NSPD_CORE_SEARCH_H
#define NSPD_CORE_SEARCH_H

#include <stdint.h>

/* In an increasing array v, the last index i in [lo, hi - 1] with
 * v[i] <= x, where v[lo] counts as -infinity and v[hi] as +infinity
 * (neither is read); so v[i] <= x < v[i+1] inside the range, lo below it,
 * hi - 1 above it, and lo for a NaN x. Negative indices are fine where the
 * array is offset (GridAxis). O(log n), thread-safe, never failing. */
int search_bracket(const double *v, int lo, int hi, double x);

/* In a non-decreasing array v[0 .. n), the first index i with v[i] >= x;
 * n when there is none. O(log n), thread-safe, never failing. */
int64_t search_first_at_least(const int64_t *v, int64_t n, int64_t x);
/* The same in an array of 32-bit values (indices). */
int64_t search_first_at_least_i32(const int32_t *v, int64_t n, int64_t x);

#endif
