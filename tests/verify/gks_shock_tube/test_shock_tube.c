/* Sod and Lax shock tubes against the exact Riemann solution: L1 density
 * error at 400 cells, along x, along y and at 45 degrees, and convergence
 * under refinement. Inviscid gas, tau = 0, numerical tau_n = C dt |dp|/(p_L+p_R)
 * with C = 1, van Leer limiter, CFL 0.5. */
#include "test_support.h"

#include "core/timer.h"
#include "shock_tube.h"

static void check_case(const TubeCase *c, double bound_x, double bound_diag) {
    const double t0 = nspd_wall_time();
    const double ex = tube_l1_error(c, TUBE_X, 400, LIMITER_VAN_LEER, NULL, 0, NULL);
    const double ey = tube_l1_error(c, TUBE_Y, 400, LIMITER_VAN_LEER, NULL, 0, NULL);
    const double ed = tube_l1_error(c, TUBE_DIAGONAL, 200, LIMITER_VAN_LEER, NULL, 0, NULL);
    printf("%s: L1(rho) x %.4e, y %.4e, 45 deg (200x200, diagonal) %.4e  (%.2f s)\n", c->name, ex,
           ey, ed, nspd_wall_time() - t0);
    assert_true(ex > 0.0 && ed > 0.0);
    /* x and y run the same kernel with swapped components: same bits */
    assert_true(ex == ey);
    assert_true(ex < bound_x);
    assert_true(ed < bound_diag);
}

/* Measured (400 cells): Sod 1.4998e-3, Lax 4.8418e-3; at 45 degrees on
 * 200 x 200, along the diagonal: Sod 1.2714e-3, Lax 3.6841e-3. The results are
 * deterministic; the bounds are the measured values + 10 %, to catch a
 * regression in the flux or the limiter, not to be met loosely. For scale: a
 * first-order (zero-slope) run gives Sod 6.77e-3 at 400 cells. */
static void test_sod(void **state) {
    (void)state;
    check_case(&SOD, 1.65e-3, 1.40e-3);
}

static void test_lax(void **state) {
    (void)state;
    check_case(&LAX, 5.33e-3, 4.05e-3);
}

/* Errors at 100, 200, 400, 800 cells must fall. Measured Sod: 4.652e-3,
 * 2.800e-3, 1.500e-3, 7.963e-4 (ratios 1.66, 1.87, 1.88: order ~0.9, the
 * contact limits it); Lax: 1.464e-2, 9.114e-3, 4.842e-3, 3.323e-3 (ratios
 * 1.61, 1.88, 1.46). Required ratio: 1.5 (Sod), 1.35 (Lax). */
static void test_convergence(void **state) {
    (void)state;
    const TubeCase *cases[2] = {&SOD, &LAX};
    const double min_ratio[2] = {1.5, 1.35};
    for (int c = 0; c < 2; c++) {
        double prev = 0.0;
        for (int n = 100; n <= 800; n *= 2) {
            const double e = tube_l1_error(cases[c], TUBE_X, n, LIMITER_VAN_LEER, NULL, 0, NULL);
            printf("%s n = %d: L1 %.4e%s", cases[c]->name, n, e, n == 800 ? "\n" : ";  ");
            assert_true(e > 0.0);
            if (prev > 0.0) assert_true(prev / e > min_ratio[c]);
            prev = e;
        }
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sod),
        cmocka_unit_test(test_lax),
        cmocka_unit_test(test_convergence),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
