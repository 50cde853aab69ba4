/* Reproducing-kernel (RK) gradient weights of quadratic consistency, the
 * nonlocal gradient of correspondence peridynamics (paper 003 Sec. 2: "RK
 * functions with quadratic consistency, rectangular support"; the
 * construction of ../shared/notes/correspondence_and_penalty.md 1c.2, 1c.4).
 *
 * For point i with family H_i (bond xi = X_j - X_i, neighbour volume V_j),
 *     Q(xi)  = [xi_1, xi_2, xi_1^2, xi_1 xi_2, xi_2^2] / delta        (2D; 3D: 9 monomials)
 *     M_i    = sum_j w_ij Q(xi) Q(xi)^T V_j                            (the moment matrix)
 *     phi_ij = w_ij (M_i^-1 Q(xi))_{1..dim} / delta                    (the gradient weights)
 *     grad f(X_i) ~ sum_j (f_j - f_i) phi_ij V_j
 * with the tensor-product cubic B-spline kernel
 *     w(xi) = prod_a b(|xi_a| / delta),  b(r) = 1 - 6 r^2 + 6 r^3 (r <= 1/2), 2 (1 - r)^3 (r <= 1),
 * whose support is the square (cube) |xi|_inf <= delta. Because M_i M_i^-1 = I
 * the gradient is exact for every linear and quadratic field at every point
 * whose M_i is invertible, at the boundary too
 * (tests/unit/solid/correspondence/test_rk_gradient.c). A bond's damage d
 * scales its kernel, w <- (1 - d) w.
 *
 * Kernels: plain arrays in, weights out, no allocation; each point's rows
 * are computed from its own family alone (any thread count, the same bits). */
#ifndef NSPD_SOLID_CORRESPONDENCE_RK_GRADIENT_H
#define NSPD_SOLID_CORRESPONDENCE_RK_GRADIENT_H

#include <stdint.h>

/* The influence functions: the tensor product of cubic B-splines (support
 * the square |xi|_inf <= delta; the paper's "rectangular support", PdShell's
 * kernel) or the radial cubic B-spline b(|xi| / delta) (support the disc). */
typedef enum { RK_KERNEL_CUBIC_TENSOR, RK_KERNEL_CUBIC_RADIAL, RK_KERNEL_COUNT } RkKernel;
extern const char *const RK_KERNEL_NAMES[RK_KERNEL_COUNT + 1];

/* The tensor kernel w(xi) for a bond xi (dim components) and support
 * half-width delta. */
double rk_kernel(int dim, const double xi[3], double delta);
/* The kernel of the given kind. */
double rk_kernel_of(RkKernel kind, int dim, const double xi[3], double delta);

/* Smallest accepted ratio of the smallest to the largest pivot of M_i's
 * Cholesky factorisation (M_i scaled to a unit diagonal): below it the
 * family is too degenerate (too few or collinear neighbours) for a
 * quadratic fit, and the point gets no weights. */
#define RK_MIN_PIVOT 1e-10
/* The same for the cubic fit of order 3, which is an upgrade of accuracy,
 * not a need: a family that fits a cubic only poorly keeps the quadratic
 * fit. On a lattice the whole and the one-sided families of the second row
 * from a face pass it by far (their pivot ratios exceed 1e-2); on clouds
 * jittered by 20 % of h the threshold 1e-10 let fits through whose
 * round-off reached 1.0e-12 of the gradient, 1e-3 keeps it at 2.5e-13
 * (tests/unit/solid/correspondence/test_rk_gradient.c). */
#define RK_MIN_PIVOT_CUBIC 1e-3

/* Weights of every bond: phi[dim * k + a] for bond k (of the family CSR
 * first[i] .. first[i+1], neighbours nbr[k]), component a. bond_scale (NULL:
 * 1) multiplies each bond's kernel (1 - damage). ok[i] = 1 where M_i was
 * invertible, else 0 and the point's weights are 0. Returns the number of
 * points without weights. dim is 2 or 3. */
int64_t rk_gradient_weights(int dim, int64_t n, const double *const x[3], const double *volume,
                            const int64_t *first, const int32_t *nbr, double delta,
                            const double *bond_scale, double *phi, uint8_t *ok);

/* The same of order 1 (linear consistency: Q = xi / delta only, exact for
 * linear fields), 2, or 3 (Q adds the cubic monomials: exact for cubic
 * fields; a point whose family cannot fit a cubic, such as one on a face
 * at delta = 2.5 h, gets the order-2 weights instead), with
 * the kernel of the given kind, for every point (redo NULL) or only those
 * with redo[i] != 0 (after damage grew in their families; the others' weights and ok untouched).
 * Returns the number of those points without weights; n for a dim or order out of range. */
int64_t rk_gradient_weights_of(int order, RkKernel kernel, int dim, int64_t n,
                               const double *const x[3], const double *volume, const int64_t *first,
                               const int32_t *nbr, double delta, const double *bond_scale,
                               const uint8_t *redo, double *phi, uint8_t *ok);

/* The nonlocal gradient of a field f (one value per point) at point i:
 * g[a] = sum_j (f_j - f_i) phi_ij,a V_j. */
void rk_gradient_at(int dim, int64_t i, const double *f, const double *volume, const int64_t *first,
                    const int32_t *nbr, const double *phi, double g[3]);

/* The deformation gradient at every point, F = I + sum_j (u_j - u_i) (x) phi_ij V_j
 * (row-major dim x dim per point: F[9 i + 3 r + c], rows of u, columns of
 * X), from displacements u[0..dim), and with u2 (not NULL) F2 of u2 in the
 * same pass over the families. */
void rk_deformation_gradient(int dim, int64_t n, const double *const u[3],
                             const double *const u2[3], const double *volume, const int64_t *first,
                             const int32_t *nbr, const double *phi, double *F, double *F2);

#endif
