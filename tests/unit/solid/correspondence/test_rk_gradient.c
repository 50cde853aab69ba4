/* solid/correspondence/rk_gradient: the RK gradient of quadratic consistency is exact for
 * linear and quadratic fields at every point whose moment matrix is
 * invertible, boundary points included, on a randomly perturbed lattice in
 * 2D and 3D (notes 1c.10 test C1); a cubic field is not exact, and its
 * error falls as h^2 at fixed delta / h (second order); a homogeneous
 * deformation gives F exactly; a uniform kernel scale (damage on every
 * bond) changes no weight; a family on a line has no weights. Order 1
 * (linear consistency) is exact for linear fields only. */
#include "cloud_fixtures.h"
#include "test_support.h"

#include "solid/correspondence/rk_gradient.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

static double *weights(const Cloud *c, const double *scale, uint8_t **ok, int64_t *missing) {
    double *phi = calloc((size_t)(c->first[c->n] * c->dim), sizeof(double));
    *ok = calloc((size_t)c->n, 1);
    *missing = rk_gradient_weights(c->dim, c->n, (const double *const *)c->x, c->volume, c->first,
                                   c->nbr, c->delta, scale, phi, *ok);
    return phi;
}

typedef double (*Field)(const double p[3], double g[3]);

static double linear(const double p[3], double g[3]) {
    g[0] = 2.0, g[1] = -5.0, g[2] = 0.5;
    return 3.0 + 2.0 * p[0] - 5.0 * p[1] + 0.5 * p[2];
}

static double quadratic(const double p[3], double g[3]) {
    const double x = p[0], y = p[1], z = p[2];
    g[0] = 2e3 * x - 3e3 * y + 1.0 + 1e3 * z;
    g[1] = -3e3 * x + 4e3 * y;
    g[2] = 1e3 * x - 2e3 * z;
    return 1e3 * (x * x - 3.0 * x * y + 2.0 * y * y + x * z - z * z) + x;
}

static double cubic(const double p[3], double g[3]) {
    const double x = p[0], y = p[1];
    g[0] = 3e6 * x * x + 1e6 * y * y, g[1] = 2e6 * x * y, g[2] = 0.0;
    return 1e6 * (x * x * x + x * y * y);
}

/* every cubic monomial of 3D but z^3, and a quadratic part */
static double cubic_full(const double p[3], double g[3]) {
    const double x = p[0], y = p[1], z = p[2];
    g[0] = 1e6 * (3 * x * x - 4 * x * y + y * z + z * z) + 1e3 * (2 * x + y);
    g[1] = 1e6 * (-2 * x * x + 3 * y * y + x * z) + 1e3 * x;
    g[2] = 1e6 * (x * y + 2 * x * z);
    return 1e6 * (x * x * x - 2 * x * x * y + y * y * y + x * y * z + x * z * z) +
           1e3 * (x * x + x * y);
}

static double quartic(const double p[3], double g[3]) {
    const double x = p[0], y = p[1];
    g[0] = 4e9 * x * x * x, g[1] = 4e9 * y * y * y, g[2] = 0.0;
    return 1e9 * (x * x * x * x + y * y * y * y);
}

/* The largest error of the nonlocal gradient of f against its exact value,
 * relative to the largest exact component, over the points with weights
 * (interior only: those at least delta inside the cloud's box). */
static double gradient_error(const Cloud *c, const double *phi, const uint8_t *ok, Field f,
                             bool interior_only) {
    double *val = calloc(c->n > 0 ? (size_t)c->n : 1, sizeof(double));
    double err = 0.0, size = 0.0, g[3], exact[3], p[3] = {0, 0, 0};
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int64_t i = 0; i < c->n; i++) {
        for (int a = 0; a < c->dim; a++) {
            p[a] = c->x[a][i];
            lo[a] = fmin(lo[a], p[a]);
            hi[a] = fmax(hi[a], p[a]);
        }
        val[i] = f(p, exact);
    }
    for (int64_t i = 0; i < c->n; i++) {
        if (!ok[i]) continue;
        bool inside = true;
        for (int a = 0; a < c->dim; a++) {
            p[a] = c->x[a][i];
            inside &= p[a] - lo[a] > c->delta && hi[a] - p[a] > c->delta;
        }
        if (interior_only && !inside) continue;
        f(p, exact);
        rk_gradient_at(c->dim, i, val, c->volume, c->first, c->nbr, phi, g);
        for (int a = 0; a < c->dim; a++) {
            err = fmax(err, fabs(g[a] - exact[a]));
            size = fmax(size, fabs(exact[a]));
        }
    }
    free(val);
    return err / size;
}

static void exact_for(int dim, int side) {
    Cloud c;
    cloud_make(&c, dim, side, 1e-3, 0.2);
    uint8_t *ok;
    int64_t missing;
    double *phi = weights(&c, NULL, &ok, &missing);
    assert_int_equal(missing, 0); /* corners included: 9 or more neighbours in a quadrant */
    const double e1 = gradient_error(&c, phi, ok, linear, false);
    const double e2 = gradient_error(&c, phi, ok, quadratic, false);
    print_message("%dD: relative gradient error, linear %.1e, quadratic %.1e\n", dim, e1, e2);
    /* round-off: measured 2.1e-13 / 2.8e-13 (linear: f_j - f_i of ~1e-2
     * against the constant 3 loses digits) and 1e-14 / 3e-14 (quadratic) */
    assert_true(e1 < 1e-12);
    assert_true(e2 < 1e-12);
    /* the check can fail: a cubic field is not reproduced */
    assert_true(gradient_error(&c, phi, ok, cubic, false) > 1e-6);
    free(phi);
    free(ok);
    cloud_free(&c);
}

static void test_exact_for_quadratics_2d(void **state) {
    (void)state;
    exact_for(2, 16);
}

static void test_exact_for_quadratics_3d(void **state) {
    (void)state;
    exact_for(3, 8);
}

/* Second order: the cubic's interior error on clouds of h, h/2 and h/4
 * (delta = 2.5 h, the same perturbation amplitude) falls as h^2. The
 * perturbations are random, so the observed order scatters about 2: the
 * finer pair's order is required within [1.7, 2.6]. */
static void test_second_order(void **state) {
    (void)state;
    double e[3];
    for (int k = 0; k < 3; k++) {
        Cloud c;
        cloud_make(&c, 2, 16 << k, 4e-3 / (double)(1 << k), 0.2);
        uint8_t *ok;
        int64_t missing;
        double *phi = weights(&c, NULL, &ok, &missing);
        e[k] = gradient_error(&c, phi, ok, cubic, true);
        free(phi);
        free(ok);
        cloud_free(&c);
    }
    const double p01 = log2(e[0] / e[1]), p12 = log2(e[1] / e[2]);
    print_message("cubic field, interior gradient error: %.3e %.3e %.3e; order %.2f, %.2f\n", e[0],
                  e[1], e[2], p01, p12);
    assert_true(p12 > 1.7 && p12 < 2.6);
}

/* u = (F - I) X gives F at every point; a uniform kernel scale (the same
 * damage on every bond) changes no weight beyond round-off. */
static void test_homogeneous_deformation(void **state) {
    (void)state;
    Cloud c;
    cloud_make(&c, 2, 12, 1e-3, 0.2);
    uint8_t *ok;
    int64_t missing;
    double *phi = weights(&c, NULL, &ok, &missing);
    const double F[2][2] = {{1.1, 0.2}, {-0.05, 0.95}};
    double *u[3] = {calloc((size_t)c.n, sizeof(double)), calloc((size_t)c.n, sizeof(double)), NULL};
    for (int64_t i = 0; i < c.n; i++)
        for (int r = 0; r < 2; r++)
            u[r][i] = (F[r][0] - (r == 0)) * c.x[0][i] + (F[r][1] - (r == 1)) * c.x[1][i];
    double *Fi = calloc((size_t)(9 * c.n), sizeof(double));
    rk_deformation_gradient(2, c.n, (const double *const *)u, NULL, c.volume, c.first, c.nbr, phi,
                            Fi, NULL);
    for (int64_t i = 0; i < c.n; i++)
        for (int r = 0; r < 2; r++)
            for (int col = 0; col < 2; col++)
                assert_close(Fi[9 * i + 3 * r + col], F[r][col], 1e-13);

    double *half = calloc((size_t)c.first[c.n], sizeof(double));
    for (int64_t k = 0; k < c.first[c.n]; k++) half[k] = 0.5;
    uint8_t *ok2;
    double *phi2 = weights(&c, half, &ok2, &missing);
    for (int64_t k = 0; k < 2 * c.first[c.n]; k++)
        assert_close(phi2[k], phi[k], 1e-12 * fabs(phi[k]) + 1e-6);
    free(phi2);
    free(ok2);
    free(half);
    free(Fi);
    free(u[0]);
    free(u[1]);
    free(phi);
    free(ok);
    cloud_free(&c);
}

/* Neighbours on one line cannot fit a quadratic in 2D: no weights. */
static void test_degenerate_family(void **state) {
    (void)state;
    const double x0[4] = {0.0, 1e-3, 2e-3, -1e-3}, y0[4] = {0, 0, 0, 0};
    double xs[4], ys[4], vol[4] = {1e-6, 1e-6, 1e-6, 1e-6};
    memcpy(xs, x0, sizeof xs);
    memcpy(ys, y0, sizeof ys);
    const double *x[3] = {xs, ys, NULL};
    const int64_t first[5] = {0, 3, 3, 3, 3};
    const int32_t nbr[3] = {1, 2, 3};
    double phi[6] = {1, 1, 1, 1, 1, 1};
    uint8_t ok[4];
    assert_int_equal(rk_gradient_weights(2, 4, x, vol, first, nbr, 2.5e-3, NULL, phi, ok), 4);
    for (int k = 0; k < 6; k++) assert_true(phi[k] == 0.0);
    assert_int_equal(ok[0], 0);
}

/* Order 1 (linear consistency): exact for linear fields at every point
 * with weights (measured 1.0e-13 on a 20 % jittered cloud), not for
 * quadratics (measured 0.061 of the gradient, largest at the one-sided
 * families of the boundary); an order other than 1 to 3 is refused. */
static void test_order_one(void **state) {
    (void)state;
    Cloud c;
    cloud_make(&c, 2, 14, 1e-3, 0.2);
    double *phi = calloc((size_t)(2 * c.first[c.n]), sizeof(double));
    uint8_t *ok = calloc((size_t)c.n, 1);
    assert_int_equal(rk_gradient_weights_of(1, RK_KERNEL_CUBIC_TENSOR, 2, c.n,
                                            (const double *const *)c.x, c.volume, c.first, c.nbr,
                                            c.delta, NULL, NULL, phi, ok),
                     0);
    const double lin = gradient_error(&c, phi, ok, linear, false);
    const double quad = gradient_error(&c, phi, ok, quadratic, false);
    print_message("order 1: linear %.3g, quadratic %.3g\n", lin, quad);
    assert_true(lin < 1e-12);
    assert_true(quad > 1e-3);
    /* the radial kernel: quadratic consistency holds for any kernel
     * (measured 1.2e-14) */
    assert_int_equal(rk_gradient_weights_of(2, RK_KERNEL_CUBIC_RADIAL, 2, c.n,
                                            (const double *const *)c.x, c.volume, c.first, c.nbr,
                                            c.delta, NULL, NULL, phi, ok),
                     0);
    const double radial = gradient_error(&c, phi, ok, quadratic, false);
    print_message("radial kernel, order 2: quadratic %.3g\n", radial);
    assert_true(radial < 1e-12);
    assert_int_equal(rk_gradient_weights_of(4, RK_KERNEL_CUBIC_TENSOR, 2, c.n,
                                            (const double *const *)c.x, c.volume, c.first, c.nbr,
                                            c.delta, NULL, NULL, phi, ok),
                     c.n);
    free(phi);
    free(ok);
    cloud_free(&c);
}

/* Order 3 (cubic consistency) at every point whose family fits a cubic
 * well (RK_MIN_PIVOT_CUBIC), order 2 at the others (on a face, delta =
 * 2.5 h leaves two distinct offsets inward, too few for xi^3): cubic
 * fields exact wherever the family is whole (delta inside the cloud's
 * box; measured 1.9e-15 2D, 2.6e-15 3D), quadratic ones everywhere
 * (2.5e-13, 6.6e-13: the one-sided cubic fits lose a digit against
 * order 2's 3e-14; the 1e-12), a quartic not; every point keeps
 * weights (the fallback). 2D and 3D on 20 % jittered clouds. */
static void order_three(int dim, int side) {
    Cloud c;
    cloud_make(&c, dim, side, 1e-3, 0.2);
    double *phi = calloc((size_t)(dim * c.first[c.n]), sizeof(double));
    uint8_t *ok = calloc((size_t)c.n, 1);
    assert_int_equal(rk_gradient_weights_of(3, RK_KERNEL_CUBIC_TENSOR, dim, c.n,
                                            (const double *const *)c.x, c.volume, c.first, c.nbr,
                                            c.delta, NULL, NULL, phi, ok),
                     0);
    const double quad = gradient_error(&c, phi, ok, quadratic, false);
    const double cub = gradient_error(&c, phi, ok, cubic_full, true);
    const double cub_all = gradient_error(&c, phi, ok, cubic_full, false);
    const double quart = gradient_error(&c, phi, ok, quartic, true);
    print_message("order 3, %dD: quadratic %.2g (all points), cubic %.2g (interior), %.2g (all: "
                  "the order-2 faces), quartic %.2g\n",
                  dim, quad, cub, cub_all, quart);
    /* round-off, measured up to ~1e-13 as for order 2 */
    assert_true(quad < 1e-12);
    assert_true(cub < 1e-12);
    /* both checks can fail: the faces are order 2, a quartic is not reproduced */
    assert_true(cub_all > 1e-6);
    assert_true(quart > 1e-6);
    free(phi);
    free(ok);
    cloud_free(&c);
}

static void test_order_three(void **state) {
    (void)state;
    order_three(2, 16);
    order_three(3, 9);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_for_quadratics_2d),
        cmocka_unit_test(test_exact_for_quadratics_3d),
        cmocka_unit_test(test_second_order),
        cmocka_unit_test(test_homogeneous_deformation),
        cmocka_unit_test(test_degenerate_family),
        cmocka_unit_test(test_order_one),
        cmocka_unit_test(test_order_three),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
