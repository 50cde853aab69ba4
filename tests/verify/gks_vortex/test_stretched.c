/* The vortex of test_order on a strongly stretched grid.
 *
 * Each axis is 12 segments of 10/12 alternately stretched from h to h/2 and
 * back (h = 10/64, the uniform reference spacing; 7 cells per segment, about
 * 10 % change from one cell to the next, 84 cells in all). No cell is coarser
 * than the reference, so a correct treatment of the stretching (centre-to-
 * centre distances in the slopes, face distances in the reconstruction)
 * gives an error no larger than on the uniform 64^2 grid; a wrong one adds a
 * first-order error that dominates. Requirement: within 20 % of the uniform
 * error. */
#include "test_support.h"

#include "vortex.h"

#include <stdio.h>

static void test_vortex_stretched(void **state) {
    (void)state;
    const double h = 10.0 / 64.0, L = 10.0 / 12.0;
    GridSegment seg[12];
    for (int k = 0; k < 12; k++)
        seg[k] = (GridSegment){
            .length = L, .h_start = k % 2 ? 0.5 * h : h, .h_end = k % 2 ? h : 0.5 * h};
    const double eu = vortex_l1_error(64, 4.0, LIMITER_VAN_LEER, 0, NULL);
    const double es = vortex_l1_error(64, 4.0, LIMITER_VAN_LEER, 12, seg);
    printf("vortex L1: uniform 64^2 %.4e, stretched %.4e (ratio %.3f)\n", eu, es, es / eu);
    assert_true(eu > 0.0 && es > 0.0);
    assert_true(es < 1.2 * eu);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_vortex_stretched)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
