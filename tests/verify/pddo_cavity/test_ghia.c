/* cases/cavity_re200.yaml at Re 100 (lid 0.1 m/s), coarse (20 x 20
 * intervals, dt 1e-4 s: half the convective limit 2 nu/U^2), run through
 * the whole pipeline to its steady state (max |du/dt| < 1e-5 m/s^2 =
 * 1e-6 U^2/L, FlowOps.finished), its centreline tables against Ghia,
 * Ghia and Shin (1982), Tables I and II at Re 100 (the 15 stations off the
 * walls; tests/verify/pddo_cavity/ghia1982_*.csv holds all three Reynolds
 * numbers and names the source).
 *
 * Measured (max |u/U - Ghia| along x = L/2, max |v/U - Ghia| along
 * y = L/2, steps to steady state):
 *   paper wall ghosts          0.1221 (y = 0.9531)  0.0269 (x = 0.8047)  2277
 *   antisymmetric wall ghosts  0.0484 (y = 0.9531)  0.0360 (x = 0.8594)  2315
 * The paper's zero fictitious velocities halve the wall shear (notes/pddo.md
 * 1.6): the lid's boundary layer is too thick, hence 2.5 times the u error
 * of the second-order ghosts. Bounds: 2 % above each measured value (a
 * change to the scheme or the case file that moves them fails), and the
 * step counts within 2 %. At the paper's 100 intervals `make validate`
 * reports the same comparison (scripts/ghia_compare.sh). */
#include "sim_fixtures.h"
#include "test_support.h"

#include "flow/flow.h"

#include <math.h>
#include <stdlib.h>

/* Ghia et al. (1982), Re 100: stations and values, the walls left out. */
static const double GHIA_Y[15] = {0.9766, 0.9688, 0.9609, 0.9531, 0.8516, 0.7344, 0.6172, 0.5000,
                                  0.4531, 0.2813, 0.1719, 0.1016, 0.0703, 0.0625, 0.0547};
static const double GHIA_U[15] = {0.84123,  0.78871,  0.73722,  0.68717,  0.23151,
                                  0.00332,  -0.13641, -0.20581, -0.21090, -0.15662,
                                  -0.10150, -0.06434, -0.04775, -0.04192, -0.03717};
static const double GHIA_X[15] = {0.9688, 0.9609, 0.9531, 0.9453, 0.9063, 0.8594, 0.8047, 0.5000,
                                  0.2344, 0.2266, 0.1563, 0.0938, 0.0781, 0.0703, 0.0625};
static const double GHIA_V[15] = {-0.05906, -0.07391, -0.08864, -0.10313, -0.16914,
                                  -0.22445, -0.24533, 0.05454,  0.17527,  0.17507,
                                  0.16077,  0.12317,  0.10890,  0.10091,  0.09233};

static const double L = 1e-3, U = 0.1;

/* max |f/U - ghia| over the stations, f linear between the table's rows
 * (positions in column pos, ascending). */
static double deviation(const TableRef *t, int pos, int val, const double *s, const double *g) {
    double worst = 0.0;
    for (int k = 0; k < 15; k++) {
        const double at = s[k] * L;
        int64_t r = 0;
        while (r + 2 < t->rows && t->col[pos][r + 1] < at) r++;
        const double x0 = t->col[pos][r], x1 = t->col[pos][r + 1];
        const double w = (at - x0) / (x1 - x0);
        const double f = (1.0 - w) * t->col[val][r] + w * t->col[val][r + 1];
        worst = fmax(worst, fabs(f / U - g[k]));
    }
    return worst;
}

static void run(const char *walls, double u_bound, double v_bound, int64_t steps) {
    const char *const set[] = {"flow.spacing=5e-5",
                               walls,
                               "flow.boundaries.y_max.velocity=0.1",
                               "time.dt=1e-4",
                               "time.end=1.0",
                               "flow.steady_tolerance=1e-5",
                               "output.field_interval=1.0",
                               "output.history_interval=0.01"};
    Sim sim;
    fixture_sim("cavity_re200.yaml", set, sizeof set / sizeof set[0], &sim);
    SimRunOptions opt = {NULL, false, NULL};
    assert_ok(sim_run(&sim, &opt));
    assert_true(flow_finished(sim.flow)); /* steady before time.end */
    FieldSet fs;
    flow_fields(sim.flow, &fs);
    assert_int_equal(fs.table_count, 2);
    const double du = deviation(&fs.table[0], 1, 2, GHIA_Y, GHIA_U); /* vertical: y, u */
    const double dv = deviation(&fs.table[1], 0, 3, GHIA_X, GHIA_V); /* horizontal: x, v */
    print_message("%s: steady at step %lld (t = %g s); max |u/U - Ghia| %.4f, |v/U - Ghia| %.4f\n",
                  walls, (long long)sim.step, sim.time, du, dv);
    assert_true(du < u_bound);
    assert_true(dv < v_bound);
    assert_true(llabs(sim.step - steps) <= steps / 50);
    sim_destroy(&sim);
}

static void test_paper_ghosts(void **state) {
    (void)state;
    run("flow.walls=paper", 1.02 * 0.1221, 1.02 * 0.0269, 2277);
}

static void test_antisymmetric_ghosts(void **state) {
    (void)state;
    run("flow.walls=antisymmetric", 1.02 * 0.0484, 1.02 * 0.0360, 2315);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_paper_ghosts),
                                       cmocka_unit_test(test_antisymmetric_ghosts)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
