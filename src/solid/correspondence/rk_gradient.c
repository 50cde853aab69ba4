#include "solid/correspondence/rk_gradient.h"

#include "core/kernel.h"
#include "core/parallel.h"
#include "core/spd_small.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

enum { RK_MAX_TERMS = SPD_SMALL_MAX }; /* 3D cubic: 3 + 6 + 10 monomials */

/* The cubic B-spline of the kernel, b(r) for r = |xi_a| / delta. */
static double bspline(double r) {
    if (r <= 0.5) return 1.0 - 6.0 * r * r + 6.0 * r * r * r;
    if (r <= 1.0) return 2.0 * (1.0 - r) * (1.0 - r) * (1.0 - r);
    return 0.0;
}

const char *const RK_KERNEL_NAMES[RK_KERNEL_COUNT + 1] = {"cubic_bspline", "cubic_bspline_radial",
                                                          NULL};

double rk_kernel(int dim, const double xi[3], double delta) {
    double w = 1.0;
    for (int a = 0; a < dim; a++) w *= bspline(fabs(xi[a]) / delta);
    return w;
}

double rk_kernel_of(RkKernel kind, int dim, const double xi[3], double delta) {
    if (kind == RK_KERNEL_CUBIC_TENSOR) return rk_kernel(dim, xi, delta);
    double r2 = 0.0;
    for (int a = 0; a < dim; a++) r2 += xi[a] * xi[a];
    return bspline(sqrt(r2) / delta);
}

/* Q(xi): the monomials of degree 1 to `order` (1 to 3), each over delta
 * (so that the moment matrix is of order one whatever the units); returns
 * their count. */
static int monomials(int order, int dim, const double xi[3], double delta, double q[RK_MAX_TERMS]) {
    const double s[3] = {xi[0] / delta, xi[1] / delta, dim == 3 ? xi[2] / delta : 0.0};
    int m = 0;
    for (int a = 0; a < dim; a++) q[m++] = s[a];
    if (order >= 2)
        for (int a = 0; a < dim; a++)
            for (int b = a; b < dim; b++) q[m++] = s[a] * s[b];
    if (order >= 3)
        for (int a = 0; a < dim; a++)
            for (int b = a; b < dim; b++)
                for (int c = b; c < dim; c++) q[m++] = s[a] * s[b] * s[c];
    return m;
}

static void bond_vector(int dim, const double *const x[3], int64_t i, int64_t j, double xi[3]) {
    xi[0] = xi[1] = xi[2] = 0.0;
    for (int a = 0; a < dim && a < 3; a++) xi[a] = x[a][j] - x[a][i];
}

/* Point i's weights; false (weights 0) when its M_i is singular. */
static bool point_weights(int order, RkKernel kernel, int dim, int64_t i, const double *const x[3],
                          const double *volume, const int64_t *first, const int32_t *nbr,
                          double delta, const double *bond_scale, double *phi) {
    double M[RK_MAX_TERMS][RK_MAX_TERMS] = {{0}}, q[RK_MAX_TERMS] = {0}, xi[3] = {0};
    int m = 0;
    for (int64_t k = first[i]; k < first[i + 1]; k++) {
        bond_vector(dim, x, i, nbr[k], xi);
        const double w = rk_kernel_of(kernel, dim, xi, delta) * (bond_scale ? bond_scale[k] : 1.0) *
                         volume[nbr[k]];
        m = monomials(order, dim, xi, delta, q);
        for (int r = 0; r < m; r++)
            for (int c = 0; c <= r; c++) M[r][c] += w * q[r] * q[c];
    }
    if (m == 0) m = dim; /* no neighbour: singular whatever the order */
    for (int r = 0; r < m; r++)
        for (int c = r + 1; c < m; c++) M[r][c] = M[c][r];
    double scale[RK_MAX_TERMS];
    const bool ok = spd_small_factor(M, m, scale, order == 3 ? RK_MIN_PIVOT_CUBIC : RK_MIN_PIVOT);
    /* Orders 1 and 2: the gradient's rows of M_i^-1 (M_i is symmetric: its
     * columns), two or three solves a point, and each bond's weights their
     * products with Q(xi), not a solve a bond (which was half the
     * semi-Lagrangian frame's time: perf, hollow_square_pressure; the
     * same errors in test_rk_gradient.c). Order 3 keeps a solve a bond: its
     * fits are nearer singular (RK_MIN_PIVOT_CUBIC), and the rows' products
     * cancel more (quadratic fields' gradients to 1.6e-12 against 1e-13). */
    const bool rows = order <= 2;
    double A[3][RK_MAX_TERMS] = {{0}};
    for (int a = 0; a < dim && ok && rows; a++) {
        double e[RK_MAX_TERMS] = {0};
        e[a] = 1.0;
        spd_small_solve((const double(*)[SPD_SMALL_MAX])M, m, scale, e, A[a]);
    }
    for (int64_t k = first[i]; k < first[i + 1]; k++) {
        double *out = phi + (int64_t)dim * k;
        if (!ok) {
            for (int a = 0; a < dim; a++) out[a] = 0.0;
            continue;
        }
        bond_vector(dim, x, i, nbr[k], xi);
        const double w = rk_kernel_of(kernel, dim, xi, delta) * (bond_scale ? bond_scale[k] : 1.0);
        monomials(order, dim, xi, delta, q);
        double z[RK_MAX_TERMS] = {0};
        if (rows)
            for (int a = 0; a < dim; a++)
                for (int r = 0; r < m; r++) z[a] += A[a][r] * q[r];
        else
            spd_small_solve((const double(*)[SPD_SMALL_MAX])M, m, scale, q, z);
        for (int a = 0; a < dim; a++) out[a] = w * z[a] / delta;
    }
    return ok;
}

int64_t rk_gradient_weights(int dim, int64_t n, const double *const x[3], const double *volume,
                            const int64_t *first, const int32_t *nbr, double delta,
                            const double *bond_scale, double *phi, uint8_t *ok) {
    return rk_gradient_weights_of(2, RK_KERNEL_CUBIC_TENSOR, dim, n, x, volume, first, nbr, delta,
                                  bond_scale, NULL, phi, ok);
}

int64_t rk_gradient_weights_of(int order, RkKernel kernel, int dim, int64_t n,
                               const double *const x[3], const double *volume, const int64_t *first,
                               const int32_t *nbr, double delta, const double *bond_scale,
                               const uint8_t *redo, double *phi, uint8_t *ok) {
    if ((dim != 2 && dim != 3) || (order < 1 || order > 3)) return n;
    int64_t missing = 0;
    /* dynamic: a redo list is sparse and uneven; each point's weights are
     * its own, so the bits do not depend on the schedule. A team by the
     * bonds (core/parallel.h): a point's weights walk its family twice and
     * solve its moment matrix (the coarse blast's 3,900 points ran on one
     * thread, the other waiting 18 % of the step) */
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : missing) if (first[n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        if (redo && !redo[i]) continue;
        /* order 3 falls back to 2 where the family cannot fit a cubic
         * (on a face with delta = 2.5 h: two distinct offsets inward) */
        const bool fit =
            point_weights(order, kernel, dim, i, x, volume, first, nbr, delta, bond_scale, phi) ||
            (order == 3 &&
             point_weights(2, kernel, dim, i, x, volume, first, nbr, delta, bond_scale, phi));
        ok[i] = fit ? 1 : 0;
        missing += ok[i] ? 0 : 1;
    }
    return missing;
}

void rk_gradient_at(int dim, int64_t i, const double *f, const double *volume, const int64_t *first,
                    const int32_t *nbr, const double *phi, double g[3]) {
    g[0] = g[1] = g[2] = 0.0;
    for (int64_t k = first[i]; k < first[i + 1]; k++) {
        const double df = (f[nbr[k]] - f[i]) * volume[nbr[k]];
        for (int a = 0; a < dim; a++) g[a] += df * phi[(int64_t)dim * k + a];
    }
}

/* Point i's F (and F2 of u2 when `two`): one pass over its family for
 * both fields and every component, each sum in rk_gradient_at's order (the
 * same bits). dim and two are constants at each call (inlined into the
 * loop: an OpenMP region is outlined before inlining). */
static inline __attribute__((always_inline)) void
point_gradients(const int dim, const int two, int64_t i, const double *const u[3],
                const double *const u2[3], const double *volume, const int64_t *first,
                const int32_t *nbr, const double *phi, double *F, double *F2) {
    double g[3][3] = {{0}}, h[3][3] = {{0}};
    for (int64_t k = first[i]; k < first[i + 1]; k++) {
        const int32_t j = nbr[k];
        const double V = volume[j];
        for (int r = 0; r < dim; r++) {
            const double df = (u[r][j] - u[r][i]) * V;
            for (int a = 0; a < dim; a++) g[r][a] += df * phi[(int64_t)dim * k + a];
            if (two) {
                const double df2 = (u2[r][j] - u2[r][i]) * V;
                for (int a = 0; a < dim; a++) h[r][a] += df2 * phi[(int64_t)dim * k + a];
            }
        }
    }
    double *Fi = F + 9 * i, *F2i = two ? F2 + 9 * i : NULL;
    for (int q = 0; q < 9; q++) Fi[q] = 0.0;
    if (two)
        for (int q = 0; q < 9; q++) F2i[q] = 0.0;
    for (int r = 0; r < dim; r++)
        for (int c = 0; c < dim; c++) {
            Fi[3 * r + c] = (r == c ? 1.0 : 0.0) + g[r][c];
            if (two) F2i[3 * r + c] = (r == c ? 1.0 : 0.0) + h[r][c];
        }
}

/* point_gradients in 2D with the bonds in SIMD lanes (the sums' order is
 * the lanes', fixed by the build: the same bits at any thread count, not
 * rk_gradient_at's). */
static inline __attribute__((always_inline)) void
point_gradients_2d(const int two, int64_t i, const double *const u[3], const double *const u2[3],
                   const double *volume, const int64_t *first, const int32_t *nbr,
                   const double *phi, double *F, double *F2) {
    const double *u0 = u[0], *u1 = u[1], *w0 = two ? u2[0] : u0, *w1 = two ? u2[1] : u1;
    const double ui0 = u0[i], ui1 = u1[i], wi0 = w0[i], wi1 = w1[i];
    double g00 = 0.0, g01 = 0.0, g10 = 0.0, g11 = 0.0, h00 = 0.0, h01 = 0.0, h10 = 0.0, h11 = 0.0;
#pragma omp simd reduction(+ : g00, g01, g10, g11, h00, h01, h10, h11)
    for (int64_t k = first[i]; k < first[i + 1]; k++) {
        /* vectorised x2: tests/unit/core/vectorised.sh (F alone, and with F at u2) */
        const int32_t j = nbr[k];
        const double V = volume[j], f0 = phi[2 * k], f1 = phi[2 * k + 1];
        const double d0 = (u0[j] - ui0) * V, d1 = (u1[j] - ui1) * V;
        g00 += d0 * f0, g01 += d0 * f1, g10 += d1 * f0, g11 += d1 * f1;
        if (two) {
            const double e0 = (w0[j] - wi0) * V, e1 = (w1[j] - wi1) * V;
            h00 += e0 * f0, h01 += e0 * f1, h10 += e1 * f0, h11 += e1 * f1;
        }
    }
    double *Fi = F + 9 * i;
    for (int q = 0; q < 9; q++) Fi[q] = 0.0;
    Fi[0] = 1.0 + g00, Fi[1] = g01, Fi[3] = g10, Fi[4] = 1.0 + g11;
    if (two) {
        double *F2i = F2 + 9 * i;
        for (int q = 0; q < 9; q++) F2i[q] = 0.0;
        F2i[0] = 1.0 + h00, F2i[1] = h01, F2i[3] = h10, F2i[4] = 1.0 + h11;
    }
}

void rk_deformation_gradient(int dim, int64_t n, const double *const u[3],
                             const double *const u2[3], const double *volume, const int64_t *first,
                             const int32_t *nbr, const double *phi, double *F, double *F2) {
#define NSPD_RK_F_LOOP(DIM, TWO)                                                                   \
    NSPD_PRAGMA(omp parallel for schedule(static) if (first[n] >= PARALLEL_MIN_ITEMS))             \
    for (int64_t i = 0; i < n; i++)                                                                \
    point_gradients(DIM, TWO, i, u, u2, volume, first, nbr, phi, F, F2)
#define NSPD_RK_F_LOOP_2D(TWO)                                                                     \
    NSPD_PRAGMA(omp parallel for schedule(static) if (first[n] >= PARALLEL_MIN_ITEMS))             \
    for (int64_t i = 0; i < n; i++)                                                                \
    point_gradients_2d(TWO, i, u, u2, volume, first, nbr, phi, F, F2)
    if (dim == 2 && u2)
        NSPD_RK_F_LOOP_2D(1);
    else if (dim == 2)
        NSPD_RK_F_LOOP_2D(0);
    else if (u2)
        NSPD_RK_F_LOOP(3, 1);
    else
        NSPD_RK_F_LOOP(3, 0);
#undef NSPD_RK_F_LOOP
#undef NSPD_RK_F_LOOP_2D
}
