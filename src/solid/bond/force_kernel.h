/* The bond-based PD force density of one point (kernel; force.c has the
 * method, Eqs. 28-29, and the loops over points).
 *
 *     force_i = scale sum_j |k_ij| (1 - |xi_ij| / |y_ij|) y_ij,
 *     y_ij = xi_ij + u_j - u_i,   xi_ij = x_j - x_i,
 * k_ij = bond_coef (body.h: > 0 breakable, < 0 unbreakable, 0 broken).
 * A breakable bond whose stretch exceeds s_c (|y|^2 > limit2 |xi|^2) is
 * broken (coef set to 0) after its force is taken: Eq. 17's state is
 * history, used from the next step on.
 *
 * A point reads its own row of bonds and the coordinates of its neighbours
 * and writes only its own force and its own row of coef (each point holds
 * its own copy of a bond), so one CUDA thread per point needs no atomics.
 *
 * A point sums its bonds one after another in row order, which is offset
 * order (body.c sorts the rows: dz, then dy, then dx): the order of the
 * lattice view's SIMD lanes (stencil.h, what the CPU runs), so this kernel
 * and the view's give the same bits, on any machine and at any thread
 * count; so does a CUDA thread compiled without contraction (nvcc
 * --fmad=false: nvcc fuses a * b + c by default). The store that breaks a bond is conditional: an
 * unconditional one costs 25 % on the 2D plate (measured). */
#ifndef NSPD_SOLID_BOND_FORCE_KERNEL_H
#define NSPD_SOLID_BOND_FORCE_KERNEL_H

#include "core/kernel.h"

#include <math.h>
#include <stdint.h>

/* Force density of point i of a 2D body into fx[i], fy[i] (N/m^3); breaks
 * the bonds of row i that the step stretched past s_c. */
NSPD_KERNEL void bond_force_point_2d(int64_t i, const double *NSPD_RESTRICT x,
                                     const double *NSPD_RESTRICT y, const double *NSPD_RESTRICT ux,
                                     const double *NSPD_RESTRICT uy,
                                     const int64_t *NSPD_RESTRICT first,
                                     const int32_t *NSPD_RESTRICT nbr, float *NSPD_RESTRICT coef,
                                     double scale, double limit2, double *NSPD_RESTRICT fx,
                                     double *NSPD_RESTRICT fy) {
    const double xi = x[i], yi = y[i], uxi = ux[i], uyi = uy[i];
    double sx = 0.0, sy = 0.0;
    const int64_t b0 = first[i], b1 = first[i + 1];
    for (int64_t b = b0; b < b1; b++) { /* in order: no reduction in lanes */
        const int32_t j = nbr[b];
        float k = coef[b];
        const double ex = x[j] - xi, ey = y[j] - yi;
        const double rx = ex + (ux[j] - uxi), ry = ey + (uy[j] - uyi);
        const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
        const double f = (double)fabsf(k) * (1.0 - sqrt(e2 / r2));
        if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
        sx += f * rx;
        sy += f * ry;
    }
    fx[i] = scale * sx;
    fy[i] = scale * sy;
}

/* The same for point i of a 3D body. */
NSPD_KERNEL void bond_force_point_3d(int64_t i, const double *NSPD_RESTRICT x,
                                     const double *NSPD_RESTRICT y, const double *NSPD_RESTRICT z,
                                     const double *NSPD_RESTRICT ux, const double *NSPD_RESTRICT uy,
                                     const double *NSPD_RESTRICT uz,
                                     const int64_t *NSPD_RESTRICT first,
                                     const int32_t *NSPD_RESTRICT nbr, float *NSPD_RESTRICT coef,
                                     double scale, double limit2, double *NSPD_RESTRICT fx,
                                     double *NSPD_RESTRICT fy, double *NSPD_RESTRICT fz) {
    const double xi = x[i], yi = y[i], zi = z[i], uxi = ux[i], uyi = uy[i], uzi = uz[i];
    double sx = 0.0, sy = 0.0, sz = 0.0;
    const int64_t b0 = first[i], b1 = first[i + 1];
    for (int64_t b = b0; b < b1; b++) { /* in order: no reduction in lanes */
        const int32_t j = nbr[b];
        float k = coef[b];
        const double ex = x[j] - xi, ey = y[j] - yi, ez = z[j] - zi;
        const double rx = ex + (ux[j] - uxi), ry = ey + (uy[j] - uyi), rz = ez + (uz[j] - uzi);
        const double e2 = ex * ex + ey * ey + ez * ez, r2 = rx * rx + ry * ry + rz * rz;
        const double f = (double)fabsf(k) * (1.0 - sqrt(e2 / r2));
        if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
        sx += f * rx;
        sy += f * ry;
        sz += f * rz;
    }
    fx[i] = scale * sx;
    fy[i] = scale * sy;
    fz[i] = scale * sz;
}

#endif
