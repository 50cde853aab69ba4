/* The penalty coupling's piston (V4 of ../shared/notes/
 * correspondence_and_penalty.md Sec. 3): a steel slab 0.1 m thick, its
 * velocity prescribed at 100 m/s, pushes through air at rest (1e5 Pa,
 * 290 K, R = 287) in a slip-walled channel. The exact 1D solution: a
 * shock ahead with 148,851 Pa behind it, a rarefaction behind with
 * 65,532 Pa at the slab (the notes' piston.py). The gas fills the slab
 * too; only the penalty makes it a piston. At 1 ms the pressures are
 * averaged over 0.05-0.2 m ahead of the slab's front and 0.05-0.2 m behind
 * its back, at 10, 20 and 40 cells across the slab (solid spacing a third
 * of a cell): within 5 % at 40 cells, and converging (at an order of about
 * 0.4, not 1: see the bound below). */
#include "test_support.h"

#include "flow/flow.h"
#include "sim/sim.h"
#include "sim_fixtures.h"

#include <math.h>
#include <stdio.h>

static const double P_FRONT = 148851.0, P_BACK = 65532.0; /* Pa, exact */

/* The mean pressure on the channel's centre line over [x0, x1]. */
static double mean_pressure(Sim *sim, double x0, double x1) {
    double sum = 0.0;
    int count = 0;
    for (double x = x0; x <= x1; x += 1e-3) {
        double s[5];
        fixture_flow_state_at(sim, x, 0.005, s);
        sum += s[3];
        count++;
    }
    return sum / count;
}

static void run(int cells_across, double *front, double *back) {
    const double h = 0.1 / cells_across;
    char text[4096];
    snprintf(text, sizeof text,
             "name: penalty_piston\n"
             "time: {end: 1.0e-3}\n"
             "solid:\n"
             "  model: plane_strain\n"
             "  spacing: %.17g\n"
             "  thickness: 1.0\n"
             "  material: {density: 7850, youngs_modulus: 200.0e9}\n"
             "  geometry: [{shape: rectangle, min: [0.5, 0.0], max: [0.6, 0.01]}]\n"
             "  boundaries:\n"
             "    - {name: pushed, region: [{shape: rectangle, min: [0.0, -1.0], max: [1.5, "
             "1.0]}], velocity: {x: 100.0, y: 0.0}}\n"
             "  initial_velocity:\n"
             "    - {region: [{shape: rectangle, min: [0.0, -1.0], max: [1.5, 1.0]}], "
             "velocity: [100.0, 0.0]}\n"
             "  integrator: velocity_verlet\n"
             "flow:\n"
             "  gas: {gamma: 1.4, gas_constant: 287.0, prandtl: 0.72, viscosity: {law: none}}\n"
             "  grid:\n"
             "    x: {segments: [{length: 1.5, spacing: %.17g}]}\n"
             "    y: {segments: [{length: 0.01, cells: 4}]}\n"
             "  boundaries:\n"
             "    x_min: {type: extrapolation}\n"
             "    x_max: {type: extrapolation}\n"
             "    y_min: {type: slip_wall}\n"
             "    y_max: {type: slip_wall}\n"
             "  initial:\n"
             "    state: {density: %.17g, velocity: [0.0, 0.0], pressure: 100000.0}\n"
             "coupling: {kind: penalty}\n"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             h / 3.0, h, 1e5 / (287.0 * 290.0));
    Sim sim;
    fixture_sim_text(text, &sim);
    assert_ok(sim_advance(&sim, 1000000));
    assert_close(sim.time, 1e-3, 1e-12);
    /* the slab is at [0.6, 0.7] m now */
    *front = mean_pressure(&sim, 0.75, 0.9);
    *back = mean_pressure(&sim, 0.4, 0.55);
    sim_destroy(&sim);
}

static void test_piston(void **state) {
    (void)state;
    const int across[3] = {10, 20, 40};
    double ef[3], eb[3];
    for (int k = 0; k < 3; k++) {
        double front, back;
        run(across[k], &front, &back);
        ef[k] = front / P_FRONT - 1.0;
        eb[k] = back / P_BACK - 1.0;
        printf("piston, %d cells across: front %.0f Pa (%+.2f %%), back %.0f Pa (%+.2f %%)\n",
               across[k], front, 100 * ef[k], back, 100 * eb[k]);
    }
    assert_true(fabs(ef[1]) <= 0.05 && fabs(eb[1]) <= 0.05);
    for (int k = 0; k < 2; k++) {
        const double of = log2(fabs(ef[k] / ef[k + 1])), ob = log2(fabs(eb[k] / eb[k + 1]));
        printf("orders %d -> %d: front %.2f, back %.2f\n", across[k], across[k + 1], of, ob);
        /* measured 0.37-0.40 from 20 to 80 cells: the pressure that leaks
         * through the locked gas (numerical diffusion ~ c h over the run,
         * a length ~ sqrt(h)) sets the error, not the first-order scheme */
        assert_true(of >= 0.3 && ob >= 0.3);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_piston)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
