// The floating-point operations of the GKS flow's face flux
// (src/flow/gks/flux_kernel.h: the BGK-NS flux with its exponentials and
// erfc, Sutherland air) and of one cell's MUSCL slopes along one axis
// (recon_kernel.h, van Leer) over the counting type of counted.hpp. A cell
// update of the 2D step is two faces' fluxes (each face is shared by two
// cells), two axes' slopes and the update itself. bench/kernel_flops.sh
// builds and runs it.
#include "counted.hpp"

#include <cstdint>
#include <cstdio>

#define double Counted
#define NSPD_CORE_KERNEL_H
#define NSPD_KERNEL static inline
#define NSPD_UNROLL(n)
#define NSPD_RESTRICT
#define NSPD_FMA(a, b, c) ((a) * (b) + (c)) /* a fused multiply-add: two flops, as counted for a peak */
#include "flow/gks/flux_kernel.h"
#include "flow/gks/recon_kernel.h"
#undef double

int main() {
    // air near 300 K, a Mach 0.3 flow and gentle slopes, as nspd bench gks
    const double gamma = 1.4;
    GksParams par{};
    par.gamma = gamma, par.K = (4.0 - 2.0 * gamma) / (gamma - 1.0), par.R = 287.0;
    par.law = VISCOSITY_SUTHERLAND, par.mu_ref = 1.716e-5, par.T_ref = 273.15;
    par.sutherland_S = 110.4, par.prandtl = 0.72, par.c_jump = 1.0, par.eps_dt = 0.0;
    const double rho = 1.2, u = 100.0, v = 20.0, p = 1e5;
    const double E = p / (gamma - 1.0) + 0.5 * rho * (u * u + v * v);
    Counted wl[4] = {rho, rho * u, rho * v, E}, wr[4] = {1.01 * rho, 1.01 * rho * u, rho * v, 1.01 * E};
    Counted nl[4] = {0.1, 10.0, 2.0, 1e4}, tl[4] = {0.05, 3.0, 1.0, 5e3};
    Counted nr[4] = {0.12, 11.0, 2.5, 1.1e4}, tr[4] = {0.04, 2.0, 1.5, 4e3};
    Counted n0[4] = {0.11, 10.5, 2.2, 1.05e4}, t0[4] = {0.045, 2.5, 1.2, 4.5e3};
    Counted f[4];
    flops = 0;
    gks_flux_kernel(wl, nl, tl, wr, nr, tr, n0, t0, Counted(1e-6), &par, par.law, f);
    const long face = flops;
    Counted w[3][4] = {{rho, rho * u, rho * v, E},
                       {1.01 * rho, 1.01 * rho * u, rho * v, 1.01 * E},
                       {1.03 * rho, 1.02 * rho * u, 1.01 * rho * v, 1.02 * E}};
    const uint8_t kind[3] = {0, 0, 0};
    Counted s[4];
    flops = 0;
    recon_slopes_cell(LIMITER_VAN_LEER, w, kind, Counted(1e3), Counted(1e3), Counted(5e-4), s);
    const long slopes = flops;
    // the update: W += (F_in - F_out) / h per axis, 4 variables: about 16
    std::printf("GKS: %ld flops a face flux, %ld a cell's slopes along one axis; a cell update "
                "(2 faces, 2 axes' slopes, the update) about %ld\n",
                face, slopes, 2 * face + 2 * slopes + 16);
    return 0;
}
