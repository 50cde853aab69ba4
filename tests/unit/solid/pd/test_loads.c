/* Loads that vary (issue 61; case/case_loads.h, solid/pd/regions.c): a
 * prescribed velocity "20*t" integrates to the exact 10 t^2 under velocity
 * Verlet (the midpoint rule is exact for a linear rate), a held
 * displacement g(t, x) is g at every step's end with its rate for v, an
 * initial velocity of x is set point by point, and a load written as an
 * expression of a constant gives the same bits as the number - on the
 * bond-based and on the correspondence solid (force density, body force,
 * pressure). */
#include "test_support.h"

#include "sim/sim.h"
#include "sim_fixtures.h"
#include "solid/solid.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A 20 x 6 mm plane-stress steel strip of bond-based points at 1 mm, to
 * t = 2e-6 s at dt 1e-8 (200 steps, below the stable 2.6e-8); `extra`
 * goes into solid: (boundaries and loads). */
static void strip(Sim *sim, const char *integrator, const char *extra) {
    char text[4096];
    snprintf(text, sizeof text,
             "name: loads\n"
             "time: {end: 2.0e-6, dt: 1.0e-8}\n"
             "solid:\n"
             "  model: plane_stress\n"
             "  spacing: 1.0e-3\n"
             "  thickness: 1.0e-3\n"
             "  material: {density: 8000, youngs_modulus: 192.0e9}\n"
             "  geometry: [{shape: rectangle, min: [-0.01, -0.003], max: [0.01, 0.003]}]\n"
             "  integrator: %s\n"
             "%s"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             integrator, extra);
    fixture_sim_text(text, sim);
}

static void run_to_end(Sim *sim) {
    assert_ok(sim_advance(sim, 200));
}

static void test_velocity_of_time(void **state) {
    (void)state;
    Sim sim;
    strip(&sim, "velocity_verlet",
          "  boundaries:\n"
          "    - name: left\n"
          "      region: [{shape: rectangle, min: [-1, -1], max: [-0.008, 1]}]\n"
          "      velocity: {x: \"20*t\", y: 0}\n");
    run_to_end(&sim);
    const PdPoints *p = solid_points(sim.solid);
    const double T = sim.time; /* 200 steps of 1e-8 s, summed as the run sums them */
    assert_true(fabs(T - 2e-6) < 1e-18);
    int held = 0;
    double worst_u = 0.0, worst_v = 0.0;
    for (int64_t i = 0; i < p->n; i++) {
        if (p->x[0][i] > -0.008) continue;
        held++;
        worst_u = fmax(worst_u, fabs(p->u[0][i] - 10.0 * T * T) / (10.0 * T * T));
        worst_v = fmax(worst_v, fabs(p->v[0][i] - 20.0 * T) / (20.0 * T));
        assert_true(p->u[1][i] == 0.0 && p->v[1][i] == 0.0);
    }
    printf("velocity 20 t: %d points, u against 10 t^2 %.2e, v against 20 t %.2e (relative)\n",
           held, worst_u, worst_v);
    assert_true(held == 2 * 6); /* two columns of six points */
    /* measured 7.1e-15 / 0: the sum of 200 midpoint increments rounds
     * (about 200 ulp at most), v is 20 t at the run's own time exactly */
    assert_true(worst_u <= 1e-13 && worst_v <= 1e-15);
    sim_destroy(&sim);
}

static void test_displacement_of_time_and_place(void **state) {
    (void)state;
    Sim sim;
    strip(&sim, "velocity_verlet",
          "  boundaries:\n"
          "    - name: right\n"
          "      region: [{shape: rectangle, min: [0.008, -1], max: [1, 1]}]\n"
          "      displacement: {y: \"1e-6*sin(2*pi*t/4e-6)*x/0.01\"}\n");
    run_to_end(&sim);
    const PdPoints *p = solid_points(sim.solid);
    const double T = sim.time, w = 2.0 * M_PI / 4e-6;
    int held = 0;
    double worst_v = 0.0;
    for (int64_t i = 0; i < p->n; i++) {
        if (p->x[0][i] < 0.008) continue;
        held++;
        const double x = p->x[0][i];
        /* the same expression, the same bits */
        assert_true(p->u[1][i] == 1e-6 * sin(2 * M_PI * T / 4e-6) * x / 0.01);
        const double rate = 1e-6 * w * cos(w * T) * x / 0.01;
        worst_v = fmax(worst_v, fabs(p->v[1][i] - rate) / (1e-6 * w * x / 0.01));
    }
    printf("displacement g(t, x): %d points, v against dg/dt %.2e (of its amplitude)\n", held,
           worst_v);
    assert_true(held == 12);
    /* the central difference over h = dt/2 errs by (w h)^2 / 6 = 1.03e-5 of
     * the amplitude, as measured (1.03e-5) */
    assert_true(worst_v <= 3e-5);
    sim_destroy(&sim);
}

static void test_initial_velocity_of_place(void **state) {
    (void)state;
    Sim sim;
    strip(&sim, "velocity_verlet",
          "  initial_velocity:\n"
          "    - region: [{shape: rectangle, min: [-1, -1], max: [1, 1]}]\n"
          "      velocity: [\"-100*y\", \"100*x\"]\n");
    const PdPoints *p = solid_points(sim.solid);
    for (int64_t i = 0; i < p->n; i++) {
        assert_true(p->v[0][i] == -100 * p->x[1][i]);
        assert_true(p->v[1][i] == 100 * p->x[0][i]);
    }
    sim_destroy(&sim);
}

/* Runs the strip (or the correspondence square) with `a` and with `b` and
 * asserts that every displacement has the same bits. */
static void same_bits(void (*make)(Sim *, const char *), const char *a, const char *b) {
    Sim sa, sb;
    make(&sa, a);
    make(&sb, b);
    assert_ok(sim_advance(&sa, 50));
    assert_ok(sim_advance(&sb, 50));
    const PdPoints *pa = solid_points(sa.solid), *pb = solid_points(sb.solid);
    assert_true(pa->n == pb->n);
    double moved = 0.0;
    for (int d = 0; d < 2; d++) {
        assert_memory_equal(pa->u[d], pb->u[d], (size_t)pa->n * sizeof(double));
        for (int64_t i = 0; i < pa->n; i++) moved = fmax(moved, fabs(pa->u[d][i]));
    }
    assert_true(moved > 0.0); /* not vacuous: the load moved the body */
    sim_destroy(&sa);
    sim_destroy(&sb);
}

static void bond_strip(Sim *sim, const char *extra) {
    strip(sim, "euler_cromer", extra);
}

static void test_constant_expressions_same_bits(void **state) {
    (void)state;
    same_bits(bond_strip,
              "  body_force: [1.0e9, -2.0e8]\n"
              "  boundaries:\n"
              "    - region: [{shape: rectangle, min: [-1, -1], max: [-0.008, 1]}]\n"
              "      force_density: [3.0e9, 0]\n",
              "  body_force: [\"1.0e9\", \"-2.0e8\"]\n"
              "  boundaries:\n"
              "    - region: [{shape: rectangle, min: [-1, -1], max: [-0.008, 1]}]\n"
              "      force_density: [\"3.0e9\", \"0\"]\n");
}

/* A coarse hollow square of correspondence points (cases/
 * hollow_square_pressure.yaml's geometry at 4 mm) under the cavity
 * pressure `load`. */
static void cpd_square(Sim *sim, const char *load) {
    char text[4096];
    snprintf(text, sizeof text,
             "name: cpd_loads\n"
             "time: {end: 2.0e-4}\n"
             "solid:\n"
             "  formulation: correspondence\n"
             "  model: plane_strain\n"
             "  spacing: 4.0e-3\n"
             "  thickness: 3.5e-3\n"
             "  horizon_factor: 2.5\n"
             "  material: {density: 7870, youngs_modulus: 200.0e9, poisson_ratio: 0.29,\n"
             "             yield_stress: 0.4e9, hardening_modulus: 0.1e9}\n"
             "  geometry:\n"
             "    - {shape: rectangle, min: [-0.08, -0.08], max: [0.08, 0.08]}\n"
             "    - {shape: rectangle, min: [-0.05, -0.05], max: [0.05, 0.05], op: subtract}\n"
             "  pressure_loads:\n"
             "    - region: [{shape: rectangle, min: [-0.05, -0.05], max: [0.05, 0.05]}]\n"
             "%s"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             load);
    fixture_sim_text(text, sim);
}

static void test_pressure_expression(void **state) {
    (void)state;
    /* the trapezoid's ramp written out: the same operations, the same bits */
    same_bits(cpd_square, "      peak: 400.0e6\n      rise_time: 2.0e-4\n",
              "      pressure: \"t < 2.0e-4 ? 400.0e6*t/2.0e-4 : 400.0e6\"\n");
    /* a pressure that varies in space, evaluated per loaded point: 0 on
     * the left half of the cavity's faces moves them less */
    Sim sim;
    cpd_square(&sim, "      pressure: \"400.0e6*t/2.0e-4*(x > 0)\"\n");
    assert_ok(sim_advance(&sim, 50));
    const PdPoints *p = solid_points(sim.solid);
    double left = 0.0, right = 0.0;
    for (int64_t i = 0; i < p->n; i++) {
        if (fabs(p->x[1][i]) > 0.04) continue;
        if (p->x[0][i] < -0.05 && p->x[0][i] > -0.055) left = fmax(left, fabs(p->u[0][i]));
        if (p->x[0][i] > 0.05 && p->x[0][i] < 0.055) right = fmax(right, fabs(p->u[0][i]));
    }
    printf("pressure on x > 0 only: inner faces' |u_x| left %.3e, right %.3e m\n", left, right);
    assert_true(right > 10.0 * left);
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_velocity_of_time),
        cmocka_unit_test(test_displacement_of_time_and_place),
        cmocka_unit_test(test_initial_velocity_of_place),
        cmocka_unit_test(test_constant_expressions_same_bits),
        cmocka_unit_test(test_pressure_expression),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
