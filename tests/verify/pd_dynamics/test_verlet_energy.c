/* Velocity Verlet on a free vibration without failure: the total energy
 * error stays bounded over 10,000 steps and falls as dt^2.
 *
 * A free 16 x 16 plane-stress block vibrates from an initial velocity field
 * (a smooth shear-and-stretch pattern with zero net momentum). Velocity
 * Verlet is symplectic: the energy error oscillates without drift, with an
 * amplitude O(dt^2). Measured (dt = 0.5 x stable, 10,000 steps): largest
 * relative error 2.03e-3; the largest error over the last 2,000 steps is
 * 0.98 x the one over the first 2,000 (no drift); halving dt (20,000 steps,
 * the same simulated time) divides it by 4.01. */
#include "pd_fixtures.h"
#include "test_support.h"

#include "solid/bond/body.h"
#include "solid/bond/diagnostics.h"
#include "solid/bond/integrate.h"

#include <math.h>

/* Runs `steps` steps of `dt`; returns the largest |E/E0 - 1| overall and
 * over the first and last fifth of the run. */
static void run(double dt_factor, int64_t steps, double *worst, double *early, double *late) {
    PdConfig cfg = fixture_block(2, 16, 16, 0, 1e-3);
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    double L = 16e-3;
    for (int64_t i = 0; i < b.n; i++) {
        double x = b.x[0][i] / L - 0.5, y = b.x[1][i] / L - 0.5;
        b.v[0][i] = 2.0 * sin(M_PI * x) * cos(M_PI * y);
        b.v[1][i] = -1.0 * cos(M_PI * x) * sin(M_PI * y);
    }
    double dt = dt_factor * pd_stable_time_step(&b);
    double e0 = pd_kinetic_energy(&b) + pd_elastic_energy(&b);
    *worst = *early = *late = 0;
    for (int64_t s = 1; s <= steps; s++) {
        assert_ok(pd_step(&b, dt));
        double err = fabs((pd_kinetic_energy(&b) + pd_elastic_energy(&b)) / e0 - 1);
        *worst = fmax(*worst, err);
        if (s <= steps / 5) *early = fmax(*early, err);
        if (s > steps - steps / 5) *late = fmax(*late, err);
    }
    bond_body_destroy(&b);
}

static void test_energy_bounded_and_second_order(void **state) {
    (void)state;
    double w1, e1, l1, w2, e2, l2;
    run(0.5, 10000, &w1, &e1, &l1);
    run(0.25, 20000, &w2, &e2, &l2);
    print_message("dt: worst %.3e (first fifth %.3e, last %.3e); dt/2: worst %.3e; ratio %.3f\n",
                  w1, e1, l1, w2, w1 / w2);
    assert_true(w1 < 1e-2);     /* bounded: a fraction of a percent */
    assert_true(l1 < 1.5 * e1); /* no drift between the first and last 2,000 steps */
    assert_true(w1 / w2 > 3.6 && w1 / w2 < 4.4); /* second order: 4 within 10 % */
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_energy_bounded_and_second_order)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
