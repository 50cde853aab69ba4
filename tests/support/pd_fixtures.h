/* PD bodies built in code for the tests. */
#ifndef NSPD_TEST_PD_FIXTURES_H
#define NSPD_TEST_PD_FIXTURES_H

#include "solid/pd/config.h"

/* A plane-stress steel-like block [0, nx dx] x [0, ny dx] (3D: x nz dx),
 * delta = 3.015 dx, no failure, linear volume and energy surface corrections,
 * velocity Verlet. The caller may change any field before bond_body_create. */
PdConfig fixture_block(int dim, int nx, int ny, int nz, double dx);

/* The smallest deformed distance |x_j + u_j - x_i - u_i| over all pairs
 * whose reference distance exceeds `reference` (points never bonded), m;
 * O(n^2), for the contact tests' runs without contact. */
double fixture_closest_unbonded(int64_t n, int dim, const double *const x[3],
                                const double *const u[3], double reference);

#endif
