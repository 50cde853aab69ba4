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
void pd_force_kernel_3d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict z, const double *restrict ux,
                        const double *restrict uy, const double *restrict uz,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy, double *restrict fz);

/* The same force on chunks [lo, hi) of a body's lattice view (stencil.h:
 * the arrays of BondStencil, x and u per cell, `held` the points of this
 * process; dim 2 or 3): eight points a chunk in SIMD lanes, each summing
 * its bonds in offset order, the bits of pd_force_kernel_2d / _3d on rows
 * in that order. A bond it breaks is broken in the view (state) and in
 * the body's rows (bond_coef). Writes force[.][i] of the chunks' held points
 * only. What pd_force_compute runs. */
void pd_force_kernel_stencil(int dim, int64_t lo, int64_t hi, const int64_t *restrict chunk_cell,
                             int offsets, const int64_t *restrict shift, const double *const x[3],
                             const double *const u[3], uint16_t *restrict state,
                             const int32_t *restrict block, const float *restrict magnitude,
                             const int32_t *restrict cell_point, int64_t held,
                             const int64_t *restrict first, const int32_t *restrict nbr,
                             float *restrict bond_coef, double scale, double limit2,
                             double *const force[3]);

/* Operator: the force of the whole body into body->force (OpenMP over
 * points, static schedule; bitwise the same at any thread count), the
 * contact force added where the body has contact (solid/pd/contact.h).
 * NSPD_ERR_NOMEM if contact's candidate lists cannot be rebuilt. */
int pd_force_compute(BondBody *body);

#endif
