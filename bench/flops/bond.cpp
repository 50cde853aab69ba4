// The floating-point operations of the bond-based PD force of one bond
// (src/solid/bond/force_kernel.h, 2D) over the counting type of
// counted.hpp: a point with a full family of 28 bonds (horizon 3 spacings),
// counted and divided by the bonds. bench/kernel_flops.sh builds and runs it.
#include "counted.hpp"

#include <cstdint>
#include <cstdio>

#define double Counted
#define NSPD_CORE_KERNEL_H
#define NSPD_KERNEL static inline
#define NSPD_RESTRICT
#include "solid/bond/force_kernel.h"
#undef double

int main() {
    enum { SIDE = 7, N = SIDE * SIDE };
    Counted x[N], y[N], ux[N], uy[N], fx[N], fy[N];
    for (int j = 0; j < SIDE; j++)
        for (int i = 0; i < SIDE; i++) {
            const int k = i + SIDE * j;
            x[k] = i * 1e-3, y[k] = j * 1e-3, ux[k] = 1e-7 * i * j, uy[k] = -2e-7 * i;
        }
    const int centre = 3 + SIDE * 3;
    int32_t nbr[N];
    float coef[N];
    int64_t first[N + 1] = {0};
    int n = 0;
    for (int k = 0; k < N; k++) { // the family of the centre point: |xi| <= 3 spacings
        const double dx = x[k].v - x[centre].v, dy = y[k].v - y[centre].v;
        if (k != centre && dx * dx + dy * dy <= 9.0001e-6) nbr[n] = k, coef[n] = 1.0f, n++;
    }
    first[centre + 1] = n;
    for (int k = centre + 2; k <= N; k++) first[k] = n;
    for (int k = 0; k <= centre; k++) first[k] = 0;
    flops = 0;
    bond_force_point_2d(centre, x, y, ux, uy, first, nbr, coef, 1.0, 1e6, fx, fy);
    std::printf("bond-based PD, 2D: %ld flops for %d bonds: %.1f a bond (and 2 a point)\n", flops,
                n, (double)(flops - 2) / n);
    return 0;
}
