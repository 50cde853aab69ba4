/* Isentropic vortex across the periodic box: order of accuracy.
 *
 * The vortex starts at (8, 8) and moves with (1, 1) to (12, 12) = (2, 2) by
 * t = 4, crossing both periodic boundaries. L1 density error on 32^2, 64^2,
 * 128^2 cells; orders log2(e_h / e_{h/2}). Inviscid, CFL 0.5. */
#include "test_support.h"

#include "core/timer.h"
#include "vortex.h"

#include <stdio.h>

static void orders(FlowLimiter lim, double o[2], double e[3]) {
    for (int k = 0; k < 3; k++) {
        e[k] = vortex_l1_error(32 << k, 4.0, lim, 0, NULL);
        assert_true(e[k] > 0.0);
    }
    o[0] = log2(e[0] / e[1]);
    o[1] = log2(e[1] / e[2]);
}

/* Measured: van Leer L1 5.442e-3, 1.465e-3, 4.158e-4 (orders 1.89, 1.82);
 * unlimited 2.670e-3, 7.326e-4, 1.977e-4 (orders 1.87, 1.89). The van Leer
 * limiter clips the density minimum in the core, which costs a little order;
 * the requirement is order >= 1.8 on each refinement for both. */
static void test_vortex_order(void **state) {
    (void)state;
    const FlowLimiter lims[2] = {LIMITER_VAN_LEER, LIMITER_NONE};
    for (int l = 0; l < 2; l++) {
        const double t0 = nspd_wall_time();
        double o[2], e[3];
        orders(lims[l], o, e);
        printf("vortex %s: L1 %.4e %.4e %.4e, orders %.3f %.3f (%.2f s)\n",
               FLOW_LIMITER_NAMES[lims[l]], e[0], e[1], e[2], o[0], o[1], nspd_wall_time() - t0);
        assert_true(o[0] >= 1.8);
        assert_true(o[1] >= 1.8);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_vortex_order)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
