/* Small dense symmetric positive definite systems (up to 9 unknowns): the
 * moment matrices of the meshfree operators, one per point (the RK gradient
 * of solid/correspondence/rk_gradient.c, the PDDO shape matrix of flow/pddo/operators.c).
 *
 * The matrix is first scaled to a unit diagonal (scale[r] = 1/sqrt(M_rr)),
 * so the pivot test below is independent of units and of how unevenly the
 * monomials are sized, then factorised M = L L^T (Cholesky) in place in its
 * lower triangle. Pure arithmetic: no allocation, thread-safe. */
#ifndef NSPD_CORE_SPD_SMALL_H
#define NSPD_CORE_SPD_SMALL_H

#include <stdbool.h>

enum { SPD_SMALL_MAX = 19 }; /* 3D cubic fit: 3 linear, 6 quadratic and 10 cubic monomials */

/* Factorises the m x m matrix in M's lower triangle (the upper one is not
 * read) after scaling it to a unit diagonal; scale[] receives the scaling.
 * False when a diagonal entry is not positive or a squared pivot of the
 * scaled matrix falls to min_pivot or below (the family cannot carry the
 * fit); M is then left partly overwritten. */
bool spd_small_factor(double M[SPD_SMALL_MAX][SPD_SMALL_MAX], int m, double scale[SPD_SMALL_MAX],
                      double min_pivot);

/* Solves M z = q with the factor and scaling from spd_small_factor. */
void spd_small_solve(const double L[SPD_SMALL_MAX][SPD_SMALL_MAX], int m,
                     const double scale[SPD_SMALL_MAX], const double q[SPD_SMALL_MAX],
                     double z[SPD_SMALL_MAX]);

#endif
