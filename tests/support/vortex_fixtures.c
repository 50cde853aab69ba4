#include "vortex_fixtures.h"

FlowVortex vortex_fixture_at(double start, double t) {
    return (FlowVortex){.x0 = start + t,
                        .y0 = start + t,
                        .strength = 5.0,
                        .gamma = 1.4,
                        .rho_inf = 1.0,
                        .u_inf = 1.0,
                        .v_inf = 1.0,
                        .p_inf = 1.0,
                        .period_x = 10.0,
                        .period_y = 10.0};
}
