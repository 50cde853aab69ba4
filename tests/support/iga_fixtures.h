/* Test configurations of the isogeometric flow (flow/iga/solver.h). */
#ifndef NSPD_TEST_IGA_FIXTURES_H
#define NSPD_TEST_IGA_FIXTURES_H

#include "flow/iga/solver.h"

/* A strip of nx x 2 quadratic elements on the unit tube, slip walls all
 * round, Sod's right state (R = 1, gamma = 1.4, inviscid), nodal start,
 * the paper's code's scheme with the DC cap, Courant 0.3. */
IgaConfig iga_fixture_strip(int nx);

#endif
