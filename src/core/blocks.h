/* A 2D index space divided into blocks over a Cartesian process grid
 * (issues 28, 58): the grid of PX x PY blocks a group of P processes
 * takes, and the block of each rank. The GKS flow divides its cells this
 * way and the isogeometric flow its elements; one choice for both, so a
 * case divides alike whichever flow it names.
 *
 * Rank r is the block (r mod PX, r / PX); along an axis of n items in q
 * blocks, block c holds [n c / q, n (c + 1) / q). */
#ifndef NSPD_CORE_BLOCKS_H
#define NSPD_CORE_BLOCKS_H

#include <stdbool.h>

/* The first item of block c of q along an axis of n (c = q: n). */
static inline int blocks_cut(int n, int q, int c) {
    return (int)((long long)n * c / q);
}

/* The process grid of p blocks over n[0] x n[1] items whose largest block
 * exchanges the fewest halo items a fill (a face's items each), each block
 * at least min_width items along each axis; of equals the one with fewer
 * blocks along x. 1 x p where none fits. What MPI_Dims_create does,
 * weighed by the grid's shape. */
void blocks_fewest_halo(const int n[2], const bool periodic[2], int min_width, int p, int dims[2]);

/* The process grid of a group of p: `asked` (`nspd run --processes
 * PXxPY`; {0, 0}: none) or blocks_fewest_halo's; NSPD_ERR_INPUT where
 * PX PY is not p or a block would hold fewer than min_width of the n[a]
 * `what[a]` ("columns", "rows"; "element columns", ...). */
int blocks_process_grid(const int n[2], const bool periodic[2], int min_width, int p,
                        const int asked[2], const char *const what[2], int dims[2]);

/* The block along an axis of n items in q blocks that holds item i. */
int blocks_owner(int n, int q, int i);

#endif
