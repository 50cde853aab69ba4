/* ctest-labels: slow
 * Laminar flat plate, finer version (`make validate`, about 90 s on one
 * core): first cell 6e-4 L high (10 cells across the layer at x = 0.3, 15 at
 * x = 1), leading-edge spacing 0.005, run to t = 12. */
#include "test_support.h"

#include "blasius.h"

static void test_blasius_fine(void **state) {
    (void)state;
    const BlasiusSetup b = {
        .dy_wall = 6e-4, .dx_le = 0.005, .t_end = 12.0, .height = 1.2, .upstream = 1.0};
    double worst, mean, info[3];
    assert_ok(blasius_run(&b, 0.1, 0.9, &worst, &mean, info, 0));
    printf("blasius (fine): Cf/Cf_Blasius - 1 over Re_x 1e4..9e4: worst %+.4f, mean %+.4f "
           "(%.0f cells, %.0f steps, %.1f s)\n",
           worst, mean, info[2], info[1], info[0]);
    /* Measured: worst +0.0172, mean +0.0010; near x = 0.1 (Re_x = 1e4) the
     * physical leading-edge correction 2.33/Re_x alone is 3.5 % of Cf, so the
     * window starts there. Requirement: 3 %. */
    assert_true(fabs(worst) < 0.03);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_blasius_fine)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
