/* The bond-based PD internal force (paper 000 Eqs. 16-17, 28-29). */
#ifndef NSPD_SOLID_PD_FORCE_H
#define NSPD_SOLID_PD_FORCE_H

#include "solid/pd_body.h"

/* Kernel: force density on points [lo, hi) of a 2D / 3D body,
 *     force_i = sum_j k_ij (|y_ij| - |xi_ij|) y_ij / |y_ij|,
 * y_ij = xi_ij + u_j - u_i. A breakable bond (coef > 0) whose stretch
 * exceeds s_c (|y|^2 > limit2 |xi|^2) is broken (coef set to 0) after its
 * force is taken: Eq. 17's state is history, used from the next step on.
 * Plain arrays in, no
 * allocation, no I/O; writes force[.][lo..hi) and coef of those rows only. */
void pd_force_kernel_2d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict ux, const double *restrict uy,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy);
void pd_force_kernel_3d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict z, const double *restrict ux,
                        const double *restrict uy, const double *restrict uz,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy, double *restrict fz);

/* Operator: the force of the whole body into body->force (OpenMP over
 * points, static schedule; bitwise the same at any thread count). */
void pd_force_compute(PdBody *body);

#endif
