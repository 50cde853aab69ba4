/* Exact Riemann solver: Toro's tabulated star states (Table 4.2) and the
 * Rankine-Hugoniot post-shock state of paper 000 Table 3. */
#include "test_support.h"

#include "core/status.h"
#include "flow/gks/bc.h"
#include "flow/riemann_exact.h"

#include <math.h>

static void test_toro_star_states(void **state) {
    (void)state;
    /* Toro, 3rd ed., Table 4.2: tests 1-5, p* and u* */
    const RiemannState l[5] = {{1.0, 0.0, 1.0},
                               {1.0, -2.0, 0.4},
                               {1.0, 0.0, 1000.0},
                               {1.0, 0.0, 0.01},
                               {5.99924, 19.5975, 460.894}};
    const RiemannState r[5] = {{0.125, 0.0, 0.1},
                               {1.0, 2.0, 0.4},
                               {1.0, 0.0, 0.01},
                               {1.0, 0.0, 100.0},
                               {5.99242, -6.19633, 46.0950}};
    const double ps[5] = {0.30313, 0.00189, 460.894, 46.0950, 1691.64};
    const double us[5] = {0.92745, 0.00000, 19.5975, -6.19633, 8.68975};
    for (int k = 0; k < 5; k++) {
        RiemannSolution s;
        assert_ok(riemann_exact_solve(&l[k], &r[k], 1.4, &s));
        assert_close(s.p_star, ps[k], 5e-5 * ps[k] + 1e-5);
        assert_close(s.u_star, us[k], 5e-5 * fabs(us[k]) + 1e-5);
    }
    /* sampling: far left and right are the data; Sod's plateau density */
    RiemannSolution s;
    assert_ok(riemann_exact_solve(&l[0], &r[0], 1.4, &s));
    RiemannState q;
    riemann_exact_sample(&s, -5.0, &q);
    assert_close(q.rho, 1.0, 0.0);
    riemann_exact_sample(&s, 5.0, &q);
    assert_close(q.rho, 0.125, 0.0);
    riemann_exact_sample(&s, 1.2, &q); /* between contact (0.927) and shock (1.752) */
    assert_close(q.rho, 0.26557, 1e-5);
    riemann_exact_sample(&s, 0.5, &q); /* between rarefaction tail and contact */
    assert_close(q.rho, 0.42632, 1e-5);
    const RiemannState vl = {1.0, -10.0, 0.4}, vr = {1.0, 10.0, 0.4};
    assert_int_equal(riemann_exact_solve(&vl, &vr, 1.4, &s), NSPD_ERR_INPUT);
}

static void test_shock_post_state_table3(void **state) {
    (void)state;
    /* Paper 000 Table 3: still air 1.20 kg/m^3, 101.0 kPa; inflow air 1.63,
     * 155.7 kPa, 109.6 m/s. The pressure ratio gives Ms; the rest follows. */
    const FlowPrim pre = {1.20, 0.0, 0.0, 101.0e3};
    const double ratio = 155.7 / 101.0;
    const double ms = sqrt((ratio * 2.4 + 0.4) / 2.8);
    FlowPrim post;
    flow_shock_post_state(&pre, ms, 1.4, 1, &post);
    assert_close(post.p, 155.7e3, 1e-6 * 155.7e3);
    assert_close(post.rho, 1.63, 0.005);
    assert_close(post.u, 109.6, 0.5);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_toro_star_states),
        cmocka_unit_test(test_shock_post_state_table3),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
