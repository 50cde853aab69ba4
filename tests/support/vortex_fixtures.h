/* The isentropic vortex of the order tests (Yee et al.; cases/vortex.yaml):
 * strength 5 in a free stream rho = p = 1 moving at (1, 1), gamma 1.4, on
 * the periodic box [0, 10]^2. */
#ifndef NSPD_TEST_VORTEX_FIXTURES_H
#define NSPD_TEST_VORTEX_FIXTURES_H

#include "flow/vortex.h"

/* The vortex at time t, started at (start, start): centred at
 * (start + t, start + t), the nearest image on the box. */
FlowVortex vortex_fixture_at(double start, double t);

#endif
