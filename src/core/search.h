/* Binary search in an increasing array: the one search over axes, faces and
 * centres in the code base (grids, pictures, samples). */
#ifndef NSPD_CORE_SEARCH_H
#define NSPD_CORE_SEARCH_H

/* In an increasing array v, the last index i in [lo, hi - 1] with
 * v[i] <= x, where v[lo] counts as -infinity and v[hi] as +infinity
 * (neither is read); so v[i] <= x < v[i+1] inside the range, lo below it,
 * hi - 1 above it, and lo for a NaN x. Negative indices are fine where the
 * array is offset (GridAxis). O(log n), thread-safe, never failing. */
int search_bracket(const double *v, int lo, int hi, double x);

#endif
