/* Laminar flat plate, coarse version for `make test` (about 30 s on one core):
 * first cell 1e-3 L high (7 cells across the layer at x = 0.3, 11 at x = 0.8),
 * run to t = 10 (3 flow-through times of the plate). */
#include "test_support.h"

#include "blasius.h"

static void test_blasius_coarse(void **state) {
    (void)state;
    const BlasiusSetup b = {
        .dy_wall = 1e-3, .dx_le = 0.008, .t_end = 10.0, .height = 1.2, .upstream = 1.0};
    double worst, mean, info[3];
    assert_ok(blasius_run(&b, 0.2, 0.8, &worst, &mean, info, 0));
    printf("blasius (coarse): Cf/Cf_Blasius - 1 over Re_x 2e4..8e4: worst %+.4f, mean %+.4f "
           "(%.0f cells, %.0f steps, %.1f s)\n",
           worst, mean, info[2], info[1], info[0]);
    /* Measured: worst +0.0149 (x = 0.8, where the layer is still settling at
     * t = 10), -0.009 at x = 0.2, mean -0.0003. The physical leading-edge
     * correction (Imai, 2.33/Re_x) and the Mach 0.3 adiabatic-wall density
     * change are each ~0.5-1 % here. Requirement: 3 %. */
    assert_true(fabs(worst) < 0.03);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_blasius_coarse)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
