#include "iga_fixtures.h"

IgaConfig iga_fixture_strip(int nx) {
    return (IgaConfig){.lo = {0.0, 0.0},
                       .hi = {1.0, 2.0 / nx},
                       .elements = {nx, 2},
                       .degree = 2,
                       .side = {IGA_SIDE_SLIP, IGA_SIDE_SLIP, IGA_SIDE_SLIP, IGA_SIDE_SLIP},
                       .gamma = 1.4,
                       .R = 1.0,
                       .mu = 0.0,
                       .prandtl = 1.0,
                       .initial = {0.1, 0.0, 0.0, 0.8},
                       .init = IGA_INIT_NODAL,
                       .c_dc = 2.5,
                       .dc_cap = true,
                       .passes = 3,
                       .rho_inf = 0.5,
                       .db_iterations = 10,
                       .cfl = 0.3};
}
