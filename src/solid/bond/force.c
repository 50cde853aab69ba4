/* Bond-based PD force.
 *
 * Eq. 29 gives the pair force density of bond i-j as
 *     f_ij = c s_ij (y_ij / |y_ij|),   s_ij = (|y_ij| - |xi_ij|) / |xi_ij|,
 * and Eq. 28 sums f_ij beta_ij nu_ij V_j over the family. Folding the
 * constant factors into k_ij = c beta_ij nu_ij V_j / |xi_ij| gives
 *     force_i = sum_j k_ij (|y| - |xi|) y / |y| = sum_j k_ij (1 - |xi|/|y|) y,
 * and |xi|/|y| = sqrt(|xi|^2 / |y|^2) costs one division and one square root
 * per bond. The failure test s >= s_c is |y|^2 >= (1 + s_c)^2 |xi|^2, with no
 * root at all.
 *
 * Order of force and failure: lambda_s of Eq. 17 is a history variable. The
 * force at step n uses the bond state left by step n-1, and the bonds
 * stretched past s_c are broken afterwards, for step n+1 - the order of
 * Madenci and Oterkus' reference code. On the 20 m/s plate the other order
 * (break, then take the force) made one crack tip branch at x = -17 mm while
 * the reference (and this order) runs straight to +-22 mm.
 *
 * The point body, its SIMD reduction over the bonds and the conditional
 * store that breaks a bond are in force_kernel.h. */
#include "solid/bond/force.h"
#include "core/parallel.h"
#include "solid/bond/force_kernel.h"

void pd_force_kernel_2d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict ux, const double *restrict uy,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy) {
    for (int64_t i = lo; i < hi; i++)
        bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, scale, limit2, fx, fy);
}

void pd_force_kernel_3d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict z, const double *restrict ux,
                        const double *restrict uy, const double *restrict uz,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy, double *restrict fz) {
    for (int64_t i = lo; i < hi; i++)
        bond_force_point_3d(i, x, y, z, ux, uy, uz, first, nbr, coef, scale, limit2, fx, fy, fz);
}

/* Rows per OpenMP chunk: large enough to amortise scheduling, small enough
 * to balance two threads on a 10^4-point test body. */
enum { FORCE_BLOCK = 1024 };

void pd_force_compute(BondBody *body) {
    const int64_t n = body->n, blocks = (n + FORCE_BLOCK - 1) / FORCE_BLOCK;
    const double scale = body->coef_scale, limit2 = body->stretch_limit2;
    if (body->dim == 2) {
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int64_t blk = 0; blk < blocks; blk++) {
            int64_t lo = blk * FORCE_BLOCK, hi = lo + FORCE_BLOCK < n ? lo + FORCE_BLOCK : n;
            pd_force_kernel_2d(lo, hi, body->x[0], body->x[1], body->u[0], body->u[1],
                               body->bond_first, body->bond_nbr, body->bond_coef, scale, limit2,
                               body->force[0], body->force[1]);
        }
    } else {
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int64_t blk = 0; blk < blocks; blk++) {
            int64_t lo = blk * FORCE_BLOCK, hi = lo + FORCE_BLOCK < n ? lo + FORCE_BLOCK : n;
            pd_force_kernel_3d(lo, hi, body->x[0], body->x[1], body->x[2], body->u[0], body->u[1],
                               body->u[2], body->bond_first, body->bond_nbr, body->bond_coef, scale,
                               limit2, body->force[0], body->force[1], body->force[2]);
        }
    }
}
