/* Neighbour search: the family of every point within a horizon, as
 * compressed rows (each point lists all its neighbours, ascending). The one
 * neighbour search of the code base: the PD solid's bonds and the PDDO
 * flow's families (flow/pddo/cloud.c) and its probes' stencils
 * (flow/pddo/sample.c) all come from it. */
#ifndef NSPD_CORE_NEIGHBOURS_H
#define NSPD_CORE_NEIGHBOURS_H

#include <stdint.h>

/* Finds, for each of the n points, all other points j with |x_j - x_i| <=
 * horizon. Allocates *first (n + 1 offsets) and *nbr (first[n] indices).
 * Uses a cell list of cell size `horizon`: O(n) work, parallel, and the
 * result does not depend on the thread count. */
int neighbours_find(int64_t n, int dim, const double *const x[3], double horizon, int64_t **first,
                    int32_t **nbr);
/* The same for the points i with rows[i] != 0 only (rows NULL: all); the
 * others' rows are empty. A point's row is the one neighbours_find gives. */
int neighbours_find_rows(int64_t n, int dim, const double *const x[3], double horizon,
                         const uint8_t *rows, int64_t **first, int32_t **nbr);

/* The same for m query points q (not among the n points): for each, all
 * points j with |x_j - q| <= horizon, ascending, into *first (m + 1
 * offsets) and *nbr (first[m] indices). Serial (queries are few: probes). */
int neighbours_query(int64_t n, int dim, const double *const x[3], int64_t m,
                     const double *const q[3], double horizon, int64_t **first, int32_t **nbr);

#endif
