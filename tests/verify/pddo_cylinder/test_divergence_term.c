/* Where the PPE's (rho/dt) div u acts (flow.divergence_term; flow/pddo/step.h
 * PddoDivergenceTerm), through the whole pipeline from
 * cases/cylinder_confined_re10.yaml, coarse (dx 0.2 m, patch to 1 m,
 * antisymmetric ghosts), each run to its steady state (max |du/dt| below
 * 1e-4 m/s^2), at dt 2e-3 and 1e-3 s.
 *
 * On the bodies' wall ring the velocity is prescribed, so Eq. 8 never
 * feeds its divergence back; with the paper's term on that row the front
 * stagnation pressure grows as dt falls (measured 334.4, 432.3 and 585.6
 * Pa at dt 2e-3, 1e-3 and 5e-4 s: +29 % and +35 % per halving, no limit),
 * and with the term on the updated nodes' rows only it settles (136.6,
 * 134.9 and 132.3 Pa: -1.2 % and -2.0 %). The same split at the paper's
 * Re 100 (dx 0.05 m, symmetric phase at t = 0.2 s, docs/VALIDATION.md):
 * front 11.7 kPa at dt 5e-5 s and 13.2 kPa at 2.5e-5 s with the paper's
 * term, 9.04 kPa with `updated`, icoFoam 9.28 kPa.
 *
 * Asserted: with `paper` a halving of dt raises the front pressure by
 * more than 15 % (measured 29 %: the defect this option exists for, so
 * the test fails if it quietly disappears); with `updated` it moves it by
 * less than 3 % (measured 1.2 %). That 1.2 % is all the step's tau in
 * (rho/tau) div u (flow.divergence_time, step.h): with tau held at 2e-3 s
 * the run at dt 1e-3 s reaches the steady state of the run at 2e-3 s,
 * asserted to 1e-6 relative (measured 3.3e-9: both stop at max |du/dt| <
 * 1e-4 m/s^2, not at the exact state). About 9 s. */
#include "sim_fixtures.h"
#include "test_support.h"

#include "core/report.h"
#include "flow/flow.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The front pressure (the wall node at theta = pi) at the steady state. */
static double front_pressure(const char *divergence, const char *dt, const char *tau) {
    char div_set[64], dt_set[64], tau_set[64];
    snprintf(div_set, sizeof div_set, "flow.divergence_term=%s", divergence);
    snprintf(dt_set, sizeof dt_set, "time.dt=%s", dt);
    snprintf(tau_set, sizeof tau_set, "flow.divergence_time=%s", tau);
    const char *sets[] = {
        tau_set,
        "flow.spacing=0.2",
        "flow.walls=antisymmetric",
        div_set,
        dt_set,
        "time.end=3.0",
        "flow.steady_tolerance=1e-4",
        "flow.bodies=[{shape: circle, center: [5.0, 3.0], radius: 0.5, patch_radius: 1.0}]",
        "output.probes=[{type: point, name: front, on: flow, at: [4.5, 3.0]}]",
        "output.average_from=0",
    };
    Sim sim;
    fixture_sim("cylinder_confined_re10.yaml", sets, sizeof sets / sizeof *sets, &sim);
    int64_t steps = 0;
    while (!flow_finished(sim.flow) && sim.time < 3.0) {
        assert_ok(sim_advance(&sim, 50));
        steps += 50;
    }
    assert_true(flow_finished(sim.flow)); /* steady well before 3 s (about 2.2 s) */
    double state[5];
    flow_probe_state(sim.flow, sim.probes[0].point, state);
    printf("divergence_term %-7s dt %s s, tau %s s: steady after %lld steps, front pressure "
           "%.6f Pa\n",
           divergence, dt, tau, (long long)steps, state[3]);
    sim_destroy(&sim);
    return state[3];
}

static void test_wall_pressure_against_dt(void **state) {
    (void)state;
    const double paper[2] = {front_pressure("paper", "2e-3", "0"),
                             front_pressure("paper", "1e-3", "0")};
    const double updated[2] = {front_pressure("updated", "2e-3", "0"),
                               front_pressure("updated", "1e-3", "0")};
    const double held = front_pressure("updated", "1e-3", "2e-3");
    const double rise_paper = paper[1] / paper[0] - 1.0,
                 rise_updated = updated[1] / updated[0] - 1.0;
    printf("halving dt: front pressure %+.1f %% (paper), %+.1f %% (updated)\n", 100 * rise_paper,
           100 * rise_updated);
    printf("dt 1e-3 s with tau held at 2e-3 s against dt 2e-3 s: %+.1e relative\n",
           held / updated[0] - 1.0);
    assert_true(rise_paper > 0.15);
    assert_true(fabs(rise_updated) < 0.03);
    assert_true(fabs(held / updated[0] - 1.0) < 1e-6);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_wall_pressure_against_dt)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
