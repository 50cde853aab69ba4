/* cases/panel_shock.yaml, coarse (PD 4 points across the panel, flow cells
 * 0.5 mm near it and 2 mm away, 2 mm high), to t = 0.6 ms: the shock bends
 * the panel downstream. The full case's tip is at +1.21 mm at 0.6 ms
 * (docs/VALIDATION.md); the coarse one measured +1.07 mm (coarser flow, and a
 * 4-point panel vibrates 8.8 % slower than beam theory). Bounds: downstream,
 * and within a factor 2 of the full case - the sign and the order. The
 * shock reaches the panel at 0.24 ms: before that the tip must not move. */
#include "sim_fixtures.h"
#include "test_support.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const COARSE[] = {
    "solid.spacing=2.5e-4",
    "solid.thickness=2.5e-4",
    "solid.geometry=[{shape: rectangle, min: [0.1, -7.5e-4], max: [0.101, 0.05]}]",
    "flow.grid.x.segments=[{length: 0.095, spacing_start: 2.0e-3, spacing_end: 5.0e-4}, {length: "
    "0.02, spacing: 5.0e-4}, {length: 0.185, spacing_start: 5.0e-4, spacing_end: 2.0e-3}]",
    "flow.grid.y.segments=[{length: 0.065, spacing: 2.0e-3}]",
    "time.end=6.0e-4",
    "output.history_interval=2.0e-5",
};

static void test_panel_bends_downstream(void **state) {
    (void)state;
    Sim sim;
    fixture_sim("panel_shock.yaml", COARSE, sizeof COARSE / sizeof COARSE[0], &sim);
    const ProbeState *tip = &sim.probes[0];
    const int64_t point = tip->point;
    double before = 0.0;
    while (sim.time < 6.0e-4 - 1e-12) {
        assert_ok(sim_advance(&sim, 1));
        if (sim.time < 2.0e-4) before = fmax(before, fabs(fixture_body(&sim)->u[0][point]));
    }
    double dx = fixture_body(&sim)->u[0][point];
    print_message("tip displacement at t = %.3g ms: %+.3f mm (before the shock arrives: %.1e mm)\n",
                  1e3 * sim.time, 1e3 * dx, 1e3 * before);
    assert_true(before < 1e-6);
    assert_true(dx > 0.5 * 1.21e-3 && dx < 2.0 * 1.21e-3);
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_panel_bends_downstream)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
