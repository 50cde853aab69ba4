/* flow.initial.area_fractions: a disc's (or rectangle's) area in a cell,
 * exact (core/shape.c shape_area_in_rect against a fine midpoint sum and
 * the closed forms), and a charge's energy the same on every mesh (V15 of
 * ../shared/notes/correspondence_and_penalty.md Sec. 3): the excess total
 * energy of the gas equals (p - p0) / (gamma - 1) times the charge's area
 * to 1e-10, a full disc inside the box and a half disc on its wall. */
#include "test_support.h"

#include "core/shape.h"
#include "flow/flow.h"
#include "sim/sim.h"
#include "sim_fixtures.h"

#include <math.h>
#include <stdio.h>

static void test_disc_area(void **state) {
    (void)state;
    Shape d = {.kind = SHAPE_DISC, .center = {0.3, -0.2, 0.0}, .radius = 0.7};
    /* the whole disc, a half, a quarter */
    assert_close(shape_area_in_rect(&d, -5, 5, -5, 5), M_PI * 0.49, 1e-14);
    assert_close(shape_area_in_rect(&d, 0.3, 5, -5, 5), 0.5 * M_PI * 0.49, 1e-14);
    assert_close(shape_area_in_rect(&d, 0.3, 5, -0.2, 5), 0.25 * M_PI * 0.49, 1e-14);
    /* a cell cut by the circle: a midpoint sum of 4e6 points (error ~1e-7) */
    const double x0 = 0.6, x1 = 0.95, y0 = 0.1, y1 = 0.5;
    const int n = 2000;
    double hits = 0.0;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            const double x = x0 + (i + 0.5) * (x1 - x0) / n, y = y0 + (j + 0.5) * (y1 - y0) / n;
            hits += hypot(x - 0.3, y + 0.2) <= 0.7;
        }
    const double sampled = hits / ((double)n * n) * (x1 - x0) * (y1 - y0);
    printf("cut cell: exact %.9f, sampled %.9f\n", shape_area_in_rect(&d, x0, x1, y0, y1), sampled);
    assert_close(shape_area_in_rect(&d, x0, x1, y0, y1), sampled, 2e-5 * (x1 - x0) * (y1 - y0));
    /* cells that tile a box sum to the disc's area */
    double sum = 0.0;
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 9; i++)
            sum += shape_area_in_rect(&d, -0.5 + 0.2 * i, -0.3 + 0.2 * i, -1.0 + 0.2 * j,
                                      -0.8 + 0.2 * j);
    assert_close(sum, M_PI * 0.49, 1e-14);
    Shape r = {.kind = SHAPE_RECTANGLE, .lo = {0, 0, 0}, .hi = {1, 2, 0}};
    assert_close(shape_area_in_rect(&r, 0.5, 3, -1, 1), 0.5, 1e-15);
    Shape a = {.kind = SHAPE_ANNULUS};
    assert_true(shape_area_in_rect(&a, 0, 1, 0, 1) == -1.0);
}

/* The gas's excess energy per metre of depth with a charge of radius r at
 * (cx, 0.2) on an n x n grid of the 0.4 m box. */
static double charge_energy(int n, double cx, double r) {
    char text[2048];
    snprintf(text, sizeof text,
             "name: charge\n"
             "time: {end: 1.0e-6}\n"
             "flow:\n"
             "  gas: {gamma: 1.4, gas_constant: 287.0, prandtl: 0.72, viscosity: {law: none}}\n"
             "  grid:\n"
             "    x: {segments: [{length: 0.4, cells: %d}]}\n"
             "    y: {segments: [{length: 0.4, cells: %d}]}\n"
             "  boundaries:\n"
             "    x_min: {type: slip_wall}\n"
             "    x_max: {type: slip_wall}\n"
             "    y_min: {type: slip_wall}\n"
             "    y_max: {type: slip_wall}\n"
             "  initial:\n"
             "    state: {density: 1.2, velocity: [0.0, 0.0], pressure: 1.0e5}\n"
             "    regions:\n"
             "      - region: [{shape: disc, center: [%.17g, 0.2], radius: %.17g}]\n"
             "        state: {density: 16.0, velocity: [0.0, 0.0], pressure: 6.75e6}\n"
             "    area_fractions: true\n"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             n, n, cx, r);
    Sim sim;
    fixture_sim_text(text, &sim);
    double totals[4];
    flow_totals(sim.flow, totals);
    sim_destroy(&sim);
    return totals[3] - 1.0e5 / 0.4 * 0.16;
}

static void test_charge_energy(void **state) {
    (void)state;
    const double excess = (6.75e6 - 1.0e5) / 0.4;
    const int meshes[3] = {20, 40, 80};
    for (int k = 0; k < 3; k++) {
        /* the chamber's semicircle on the wall (971.7 J/m), and a disc
         * inside the box */
        const double half = charge_energy(meshes[k], 0.0, 6.1e-3);
        const double full = charge_energy(meshes[k], 0.2, 0.05);
        printf("%d cells: half disc %.10f J/m, disc %.10f J/m\n", meshes[k], half, full);
        assert_close(half, excess * 0.5 * M_PI * 6.1e-3 * 6.1e-3, 1e-10 * half);
        assert_close(full, excess * M_PI * 0.05 * 0.05, 1e-10 * full);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_disc_area),
        cmocka_unit_test(test_charge_energy),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
