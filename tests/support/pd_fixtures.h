/* PD bodies built in code for the tests. */
#ifndef NSPD_TEST_PD_FIXTURES_H
#define NSPD_TEST_PD_FIXTURES_H

#include "solid/pd/config.h"

/* A plane-stress steel-like block [0, nx dx] x [0, ny dx] (3D: x nz dx),
 * delta = 3.015 dx, no failure, linear volume and energy surface corrections,
 * velocity Verlet. The caller may change any field before bond_body_create. */
PdConfig fixture_block(int dim, int nx, int ny, int nz, double dx);

#endif
