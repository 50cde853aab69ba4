/* The bond-based PD internal force (paper 000 Eqs. 16-17, 28-29). */
#ifndef NSPD_SOLID_BOND_FORCE_H
#define NSPD_SOLID_BOND_FORCE_H

#include "solid/bond/body.h"

/* Force density on points [lo, hi) of a 2D / 3D body: bond_force_point_2d
 * / _3d (force_kernel.h, which states the formula) for each point.
 * Plain arrays in, no allocation, no I/O; writes force[.][lo..hi) and coef
 * of those rows only. */
void pd_force_kernel_2d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict ux, const double *restrict uy,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy);
/* The same force in 2D from the points' packed rows p[4 i ..] = (x, y,
 * ux, uy), the copy of x, y, ux, uy (32-byte aligned; BondBody.packed):
 * with AVX2, four bonds at a time loaded whole instead of gathered, the
 * bits of pd_force_kernel_2d as GCC 12 vectorises it with AVX-512 (its
 * reduction's order kept: force.c); without AVX2, pd_force_kernel_2d on
 * x, y, ux, uy. What pd_force_compute runs in 2D. */
void pd_force_kernel_2d_packed(int64_t lo, int64_t hi, const double *restrict x,
                               const double *restrict y, const double *restrict ux,
                               const double *restrict uy, const double *restrict p,
                               const int64_t *restrict first, const int32_t *restrict nbr,
                               float *restrict coef, double scale, double limit2,
                               double *restrict fx, double *restrict fy);
void pd_force_kernel_3d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict z, const double *restrict ux,
                        const double *restrict uy, const double *restrict uz,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy, double *restrict fz);

/* The same in 3D from packed rows of 8, p[8 i ..] = (x, y, z, 0, ux, uy,
 * uz, 0) (BondBody.packed), as pd_force_kernel_2d_packed: the bits of
 * pd_force_kernel_3d. */
void pd_force_kernel_3d_packed(int64_t lo, int64_t hi, const double *const x[3],
                               const double *const u[3], const double *restrict p,
                               const int64_t *restrict first, const int32_t *restrict nbr,
                               float *restrict coef, double scale, double limit2,
                               double *const force[3]);

/* Operator: the force of the whole body into body->force (OpenMP over
 * points, static schedule; bitwise the same at any thread count). */
void pd_force_compute(BondBody *body);

#endif
