/* cases/block_3d.yaml: a 3D body with a pre-crack, failure and no boundary
 * conditions runs, breaks bonds, and conserves linear momentum to
 * round-off. Pair forces are exactly antisymmetric (both ends compute the
 * same bond from negated vectors), so only the different summation orders
 * of the points' force sums leave a trace: measured relative drift 3e-16
 * over 100 steps; the bound 1e-12 leaves room for longer runs. */
#include "sim_fixtures.h"
#include "test_support.h"

#include "solid/bond/diagnostics.h"

#include <math.h>

static void test_block_3d_conserves_momentum(void **state) {
    (void)state;
    Sim sim;
    fixture_sim("block_3d.yaml", NULL, 0, &sim);
    assert_int_equal(fixture_body(&sim)->dim, 3);
    double p0[3], p1[3];
    pd_momentum(fixture_body(&sim), p0);
    int64_t broken0 = pd_broken_bonds(fixture_body(&sim));
    SimRunOptions opt = {NULL, false, NULL};
    assert_ok(sim_run(&sim, &opt));
    pd_momentum(fixture_body(&sim), p1);
    double scale = fabs(p0[0]);
    assert_true(scale > 0); /* the ends move at -20 and +60 m/s */
    for (int d = 0; d < 3; d++) {
        print_message("p[%d]: %.17g -> %.17g (relative change %.2e)\n", d, p0[d], p1[d],
                      fabs(p1[d] - p0[d]) / scale);
        assert_true(fabs(p1[d] - p0[d]) < 1e-12 * scale);
    }
    assert_true(pd_broken_bonds(fixture_body(&sim)) > broken0); /* the crack grew */
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_block_3d_conserves_momentum)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
