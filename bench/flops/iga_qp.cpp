// The floating-point operations of the IGA flow's quadrature point
// (src/flow/iga/kernel.h) over the counting type of counted.hpp, for 1 to
// 10 Denman-Beavers iterations. bench/kernel_flops.sh builds and runs it.
#include "counted.hpp"

#include <cstdio>

#define double Counted
#define restrict
#define NSPD_CORE_KERNEL_H /* core/kernel.h's C qualifiers left out */
#define NSPD_KERNEL static inline
#include "flow/iga/kernel.h"
#undef double

int main() {
    // a state of the blast case (air behind the front), 6 mm elements, its step
    IgaQpParams g{};
    g.R = 287.0, g.cv = 287.0 / 0.4, g.mu = 1.81e-5, g.lambda = -2.0 * 1.81e-5 / 3.0;
    g.kappa = 1.81e-5 * 1.4 * g.cv / 0.72, g.c_dc = 2.5, g.dc_cap = true;
    g.tau_s = 4.0 / (1.9e-6 * 1.9e-6), g.G[0] = g.G[1] = 4.0 / (0.006 * 0.006);
    D Y[4] = {2e5, 150.0, -80.0, 400.0}, Yd[4] = {1e9, 1e6, -3e5, 2e6};
    D Yx[4] = {3e7, 1e4, 2e3, 5e4}, Yy[4] = {-1e7, 4e3, -5e3, 2e4};
    D gal[4], fx[4], fy[4], A0[16], nu;
    for (int it = 1; it <= 10; it++) {
        g.db_iterations = it;
        flops = 0;
        iga_point_residual(&g, Y, Yd, Yx, Yy, gal, fx, fy, A0, &nu);
        std::printf("Denman-Beavers iterations %2d: %ld flops a quadrature point\n", it, flops);
    }
    return 0;
}
