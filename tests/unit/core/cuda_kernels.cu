/* Every kernel called from device code (compile only: ctest
 * unit.core.cuda_kernels, tests/unit/core/cuda_kernels.sh). nvcc refuses a
 * call from a __global__ function to a function that is not
 * __host__ __device__, so a kernel, or a helper it calls, that lost
 * NSPD_KERNEL fails here. One thread per face, cell or point, as a CUDA back
 * end would launch them; the data layouts are only plausible, not the
 * solver's. A new kernel gets its caller here. */
#include "flow/gks/flux_kernel.h"
#include "flow/gks/update_kernel.h"
#include "flow/gks/recon_kernel.h"
#include "solid/bond/force_kernel.h"
#include "solid/correspondence/j2_kernel.h"
#include "solid/correspondence/svk_kernel.h"

static __device__ int64_t thread_index(void) {
    return (int64_t)blockIdx.x * blockDim.x + threadIdx.x;
}

/* gks_flux_kernel (and through it flow/gks/special_functions.h): face i reads 32 values. */
__global__ void gks_flux_faces(int64_t n, const double *in, GksParams par, double dt, double *f) {
    const int64_t i = thread_index();
    if (i >= n) return;
    const double *s = in + 32 * i;
    gks_flux_kernel(s, s + 4, s + 8, s + 12, s + 16, s + 20, s + 24, s + 28, dt, &par, par.law,
                    f + 4 * i);
}

/* recon_limit of n pairs of one-sided slopes. */
__global__ void recon_limit_pairs(int64_t n, FlowLimiter limiter, const double *a, const double *b,
                                  double idl, double idr, double *out) {
    const int64_t i = thread_index();
    if (i >= n) return;
    out[i] = recon_limit(limiter, a[i], b[i], idl, idr);
}

/* recon_slopes_cell along x of a row of cells 1 .. n. */
__global__ void recon_slopes_row(int64_t n, FlowLimiter limiter, const double *const *w,
                                 const uint8_t *kind, double idl, double idr, double hw, double *s,
                                 int *fallback) {
    const int64_t i = thread_index() + 1;
    if (i > n) return;
    double c[3][4];
    uint8_t k[3];
    for (int m = 0; m < 3; m++) {
        for (int v = 0; v < 4; v++) c[m][v] = w[v][i - 1 + m];
        k[m] = kind[i - 1 + m];
    }
    fallback[i] = recon_slopes_cell(limiter, c, k, idl, idr, hw, s + 4 * i);
}

/* gks_update_cell for a row of n cells (x faces i, i+1; y faces below and above). */
__global__ void gks_update_row(int64_t n, const uint8_t *kind, const double *w, const double *fx,
                               const double *gb, const double *gt, const double *idx, double idy,
                               double *wn, int *bad) {
    const int64_t i = thread_index();
    if (i >= n) return;
    double f[2][4], g[2][4];
    for (int v = 0; v < 4; v++) {
        f[0][v] = fx[4 * i + v];
        f[1][v] = fx[4 * (i + 1) + v];
        g[0][v] = gb[4 * i + v];
        g[1][v] = gt[4 * i + v];
    }
    bad[i] = gks_update_cell(kind[i], w + 4 * i, f, g, idx[i], idy, wn + 4 * i);
}

/* gks_ghost_face on the x faces 1 .. n of a row. */
__global__ void gks_ghost_faces_row(int64_t n, GksGhostFaces g, double dt, double *f0, double *f1,
                                    double *f2, double *f3) {
    const int64_t i = thread_index() + 1;
    if (i > n) return;
    double *const f[4] = {f0, f1, f2, f3};
    gks_ghost_face(&g, i - 1, i, 0, dt, f, i);
}

/* bond_force_point_2d / _3d, one thread per point. */
__global__ void bond_force_points(int64_t n, int dim, const double *x, const double *y,
                                  const double *z, const double *ux, const double *uy,
                                  const double *uz, const int64_t *first, const int32_t *nbr,
                                  float *coef, double scale, double limit2, double *fx, double *fy,
                                  double *fz) {
    const int64_t i = thread_index();
    if (i >= n) return;
    if (dim == 2)
        bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, scale, limit2, fx, fy);
    else
        bond_force_point_3d(i, x, y, z, ux, uy, uz, first, nbr, coef, scale, limit2, fx, fy, fz);
}

/* The J2 material point of n bonds, one thread per bond: F and Fdot at the
 * step's midpoint (4 per bond), sigma_hat (4) and eqps updated, then P and
 * the two damage laws from F at the end of the step. */
__global__ void j2_bonds(int64_t n, J2Material m, const double *F_mid, const double *Fdot,
                         const double *F_end, double dt, double *sigma, double *eqps, double *P,
                         double *damage) {
    const int64_t i = thread_index();
    if (i >= n) return;
    double de[3], R[4], cauchy[4];
    if (!j2_unrotated_increment_2d(F_mid + 4 * i, Fdot + 4 * i, dt, de)) {
        damage[i] = 1.0;
        return;
    }
    j2_update(&m, de, sigma + 4 * i, eqps + i);
    j2_piola_2d(F_end + 4 * i, sigma + 4 * i, P + 4 * i);
    j2_polar_rotation_2d(F_end + 4 * i, R);
    j2_rotate_stress_2d(R, sigma + 4 * i, cauchy);
    damage[i] =
        fmax(damage[i], fmax(j2_damage_ductile(eqps[i], 0.18, 0.2),
                             j2_damage_brittle(j2_max_principal(cauchy), 3e9, J2_BRITTLE_RAMP)));
}

/* j2_step_2d, the correspondence solid's material step per bond pair as
 * bac_force takes it (pairs' state by component, c n + i), plane strain
 * and plane stress. */
__global__ void j2_pair_steps(int64_t n, J2Material m, const double *F, const double *Fp,
                              double *sigma, double *eqps, double *strain_zz, double *P,
                              double *principal, uint8_t *inverted) {
    const int64_t i = thread_index();
    if (i >= n) return;
    double s[4], Pi[4];
    for (int q = 0; q < 4; q++) s[q] = sigma[q * n + i];
    inverted[i] = (uint8_t)j2_step_2d(&m, m.plane_stress, F + 4 * i, Fp + 4 * i, s, eqps + i,
                                      strain_zz + i, Pi, principal + i);
    for (int q = 0; q < 4; q++) sigma[q * n + i] = s[q], P[q * n + i] = Pi[q];
}

/* svk_stress of n deformation gradients (9 each), 2D and 3D. */
__global__ void svk_points(int64_t n, int dim, const double *F, double lambda, double mu,
                           double *P) {
    const int64_t i = thread_index();
    if (i >= n) return;
    svk_stress(dim, F + 9 * i, lambda, mu, P + 9 * i);
}
