/* The penalty coupling's leak (V7 of ../shared/notes/
 * correspondence_and_penalty.md Sec. 3, the set-up of its leak2.py): a
 * fixed steel wall 0.1 m thick at [0.45, 0.55] m in a slip channel of air
 * at 1e5 Pa, a diaphragm at 0.3 m with 1e6 Pa behind it; at 2 ms the mean
 * pressure 1-15 cm behind the wall. A sharp wall would keep it at p0; the
 * locked gas inside the penalised wall still carries the scheme's
 * numerical pressure diffusion, whatever beta. Measured: 1.0030 p0 with
 * the wall 10 cells thick, 1.0001 with 20 (the notes' 1D HLL: 1.135 and
 * 1.011), the same at beta = 1 and 1000; with sealed faces (notes Sec.
 * 1a.7 (ii), `coupling.seal`) 1 to 1e-4 even 3.75 cells thick. */
#include "test_support.h"

#include "flow/flow.h"
#include "sim/sim.h"
#include "sim_fixtures.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>

static double leak(double cells_across, double beta, bool seal) {
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
             "coupling: {kind: penalty, beta: %.17g, seal: %s}\n"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             h / 3.0, h, beta, seal ? "true" : "false");
    Sim sim;
    fixture_sim_text(text, &sim);
    assert_ok(sim_advance(&sim, 1000000));
    double sum = 0.0;
    int count = 0;
    for (double x = 0.5605; x < 0.7; x += 1e-3) {
        double s[5];
        fixture_flow_state_at(&sim, x, 0.02, s);
        sum += s[3];
        count++;
    }
    sim_destroy(&sim);
    return sum / count / 1e5;
}

static void test_leak(void **state) {
    (void)state;
    const double l10 = leak(10, 1.0, false), l10s = leak(10, 1000.0, false),
                 l20 = leak(20, 1.0, false);
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
    /* sealed faces (coupling.seal): the paper's square wall is 3.75 cells
     * thick on its coarse mesh, where the open leak is 4.2 %; measured
     * sealed: 1 - 1.3e-4 there and 1 - 1.6e-5 at 10 cells, 0.3 % and 0.5 %
     * of the open leak (what is left comes through the held wall's own
     * penalty exchange, not through the locked gas) */
    const double l4 = leak(3.75, 1.0, false), l4s = leak(3.75, 1.0, true),
                 l10seal = leak(10, 1.0, true);
    printf("sealed: %.8f p0 (3.75 cells; open %.5f), %.8f (10 cells)\n", l4s, l4, l10seal);
    assert_true(fabs(l4s - 1.0) < 0.01 * (l4 - 1.0));
    assert_true(fabs(l10seal - 1.0) < 0.01 * (l10 - 1.0));
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_leak)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
