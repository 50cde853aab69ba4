/* The penalty coupling's leak (V7 of ../shared/notes/
 * correspondence_and_penalty.md Sec. 3, the set-up of its leak2.py): a
 * fixed steel wall 0.1 m thick at [0.45, 0.55] m in a slip channel of air
 * at 1e5 Pa, a diaphragm at 0.3 m with 1e6 Pa behind it; at 2 ms the mean
 * pressure 1-15 cm behind the wall. A sharp wall would keep it at p0; the
 * locked gas inside the penalised wall still carries the scheme's
 * numerical pressure diffusion, whatever beta. Measured: 1.0030 p0 with
 * the wall 10 cells thick, 1.0001 with 20 (the notes' 1D HLL: 1.135 and
 * 1.011), the same at beta = 1 and 1000. */
#include "test_support.h"

#include "flow/flow.h"
#include "sim/sim.h"
#include "sim_fixtures.h"

#include <math.h>
#include <stdio.h>

static double leak(int cells_across, double beta) {
    const double h = 0.1 / cells_across;
    char text[4096];
    snprintf(text, sizeof text,
             "name: penalty_leak\n"
             "time: {end: 2.0e-3}\n"
             "solid:\n"
             "  model: plane_strain\n"
             "  spacing: %.17g\n"
             "  thickness: 1.0\n"
             "  material: {density: 7850, youngs_modulus: 200.0e9}\n"
             "  geometry: [{shape: rectangle, min: [0.45, 0.0], max: [0.55, 0.04]}]\n"
             "  boundaries:\n"
             "    - {name: held, region: [{shape: rectangle, min: [0.0, -1.0], max: [1.0, 1.0]}], "
             "fixed: true}\n"
             "  integrator: velocity_verlet\n"
             "flow:\n"
             "  gas: {gamma: 1.4, gas_constant: 287.0, prandtl: 0.72, viscosity: {law: none}}\n"
             "  grid:\n"
             "    x: {segments: [{length: 1.0, spacing: %.17g}]}\n"
             "    y: {segments: [{length: 0.04, cells: 4}]}\n"
             "  boundaries:\n"
             "    x_min: {type: extrapolation}\n"
             "    x_max: {type: extrapolation}\n"
             "    y_min: {type: slip_wall}\n"
             "    y_max: {type: slip_wall}\n"
             "  initial:\n"
             "    state: {density: 1.2014708, velocity: [0.0, 0.0], pressure: 1.0e5}\n"
             "    regions:\n"
             "      - region: [{shape: rectangle, min: [-1.0, -1.0], max: [0.3, 1.0]}]\n"
             "        state: {density: 12.014708, velocity: [0.0, 0.0], pressure: 1.0e6}\n"
             "coupling: {kind: penalty, beta: %.17g}\n"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             h / 3.0, h, beta);
    Sim sim;
    fixture_sim_text(text, &sim);
    assert_ok(sim_advance(&sim, 1000000));
    double sum = 0.0;
    int count = 0;
    for (double x = 0.5605; x < 0.7; x += 1e-3) {
        int64_t cell;
        assert_ok(flow_cell_at(sim.flow, "behind", x, 0.02, &cell));
        double s[5];
        flow_cell_state(sim.flow, cell, s);
        sum += s[3];
        count++;
    }
    sim_destroy(&sim);
    return sum / count / 1e5;
}

static void test_leak(void **state) {
    (void)state;
    const double l10 = leak(10, 1.0), l10s = leak(10, 1000.0), l20 = leak(20, 1.0);
    printf("behind the wall at 2 ms: %.5f p0 (10 cells, beta 1), %.5f (beta 1000), %.5f (20 "
           "cells)\n",
           l10, l10s, l20);
    /* bounds from the measured 1.0030 and 1.0001 with a margin: a remedy
     * (sealed faces) would bring both to 1 */
    assert_true(l10 > 1.0 && l10 < 1.006);
    assert_true(l20 < 1.0005);
    assert_true(l20 - 1.0 < 0.2 * (l10 - 1.0)); /* thicker walls leak much less */
    /* not a function of beta: measured 0.2 % of the leak apart */
    assert_close(l10s, l10, 0.01 * (l10 - 1.0));
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_leak)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
