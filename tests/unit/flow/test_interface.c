/* flow/flow.h over the GKS solver: the interface's dispatch, sampling at
 * points (bilinear over the cell centres reproduces a linear field to
 * round-off, the same interpolation as flow.initial.from), totals, the
 * mesh, the checked accessor, and the refusal of an unknown method; over
 * the PDDO flow: a node mesh, the refusals of what it cannot do, its
 * fields and tables, totals by the trapezoidal rule, and `finished`; the
 * Mach and speed pictures' scales from the data (flow_mach_picture_top,
 * flow_speed_picture_top). */
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "flow/flow.h"
#include "flow/gks/model.h"
#include "flow/pddo/model.h"

#include <math.h>
#include <string.h>

/* rho = 1 + 0.5 x + 0.25 y with u, v, p uniform: every conservative
 * variable is linear, so the Gauss-averaged cells hold the centre values
 * exactly, the primitives come back exactly, and the bilinear
 * interpolation between centres is exact. (A linear u or p is not: the
 * cell holds the average of rho u, and (rho u)/rho of averages differs
 * from u at the centre by O(h^2), 2e-5 here.) */
static void linear(void *ctx, double x, double y, FlowPrim *out) {
    (void)ctx;
    *out = (FlowPrim){1.0 + 0.5 * x + 0.25 * y, 0.2, -0.05, 1.5};
}

/* A GKS flow configuration with R = 1 on an nx x ny grid over [0, lx] x [0, ly]. */
static GksConfig *gks(FlowConfig *c, int nx, int ny, double lx, double ly) {
    memset(c, 0, sizeof *c);
    c->method = FLOW_METHOD_GKS;
    GksCaseConfig *model;
    assert_ok(nspd_alloc(&model, 1, sizeof *model));
    c->model = model;
    GksConfig *s = &model->solver;
    gks_config_default(s);
    s->gas_constant = 1.0;
    gks_config_uniform_grid(s, 0.0, lx, nx, 0.0, ly, ny);
    return s;
}

static void make(Flow **f) {
    FlowConfig c;
    GksConfig *s = gks(&c, 16, 24, 1.0, 2.0);
    s->init_fn = linear;
    s->init_quadrature = 2;
    assert_ok(flow_create(f, &c));
}

static void test_sample_is_exact_for_linear_fields(void **state) {
    (void)state;
    Flow *f;
    make(&f);
    assert_int_equal(flow_method(f), FLOW_METHOD_GKS);
    assert_string_equal(flow_name(f), "gks");
    FlowMesh mesh = flow_mesh(f);
    assert_int_equal(mesh.kind, MESH_GRID);
    int64_t corner, centre_cell;
    assert_ok(flow_cell_at(f, "corner", 0.01, 0.01, &corner));
    assert_ok(flow_cell_at(f, "centre", 0.5, 1.0, &centre_cell));
    double xy[2];
    flow_cell_centre(f, corner, xy);
    assert_close(xy[0], 1.0 / 32, 1e-15);
    assert_close(xy[1], 1.0 / 24, 1e-15);
    assert_int_equal(flow_cell_at(f, "off", 1.5, 1.0, &corner), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "probe 'off': at[0] = 1.5 is outside"));
    int64_t *row, n;
    assert_ok(flow_grid_line(f, "row", centre_cell, 0, &row, &n));
    assert_int_equal(n, 16); /* the row of 16 cells through the point, left to right */
    for (int64_t k = 0; k < n; k++) {
        flow_cell_centre(f, row[k], xy);
        assert_close(xy[0], ((double)k + 0.5) / 16, 1e-15);
        assert_close(xy[1], 13.0 / 12 - 1.0 / 24, 1e-15); /* y = 1 lies on a face: the upper cell */
    }
    nspd_free(&row);
    assert_non_null(gks_flow_solver(f));
    enum { N = 40 };
    double x[N], y[N], rho[N], u[N], v[N], p[N];
    /* points between the outermost cell centres (x in [1/32, 31/32]) */
    for (int k = 0; k < N; k++) {
        x[k] = 1.0 / 32 + (30.0 / 32) * fmod(0.6180339887 * (k + 1), 1.0);
        y[k] = 1.0 / 24 + (46.0 / 24) * fmod(0.7548776662 * (k + 1), 1.0);
    }
    FlowSamples out = {rho, u, v, p};
    assert_ok(flow_sample(f, N, x, y, &out));
    double worst = 0.0;
    for (int k = 0; k < N; k++) {
        FlowPrim q;
        linear(NULL, x[k], y[k], &q);
        worst = fmax(worst,
                     fabs(rho[k] - q.rho) + fabs(u[k] - q.u) + fabs(v[k] - q.v) + fabs(p[k] - q.p));
    }
    print_message("sampled linear field: worst error %.2e\n", worst);
    assert_true(worst < 1e-13); /* measured 4.8e-16: round-off of the weights and conversions */
    /* totals: mass = integral of rho over [0,1] x [0,2] = 2 + 0.5 + 0.5 = 3 */
    double totals[4];
    flow_totals(f, totals);
    assert_close(totals[0], 3.0, 1e-13);
    flow_destroy(&f);
    assert_null(f);
}

/* Sources: a gas at rest in a periodic box, one point per cell at its
 * centre pushing with force F and power P (per m of depth). The uniform
 * state's fluxes cancel exactly, so after n steps every cell's momentum is
 * n dt F / A and its energy rises by n dt P / A; the totals by n dt F and
 * n dt P per point. A point outside the box is dropped and counted;
 * clearing the sources stops them. */
static void test_sources_push_the_gas(void **state) {
    (void)state;
    FlowConfig c;
    GksConfig *s = gks(&c, 8, 4, 1.0, 0.5);
    const FlowBc per = {.kind = BC_PERIODIC};
    for (int face = 0; face < 4; face++) gks_config_set_bc(s, face, &per);
    s->initial = (FlowPrim){1.0, 0.0, 0.0, 1.0};
    Flow *f;
    assert_ok(flow_create(&f, &c));
    enum { N = 8 * 4 + 1 };
    double x[N], y[N], fx[N], fy[N], power[N];
    for (int k = 0; k < N; k++) {
        x[k] = (k % 8 + 0.5) / 8.0;
        y[k] = (k / 8 % 4 + 0.5) / 8.0;
        fx[k] = 0.25;
        fy[k] = -0.125;
        power[k] = 0.5;
    }
    x[N - 1] = 2.0; /* off the mesh */
    FlowSources src = {N, x, y, fx, fy, power, 0};
    double before[4], after[4];
    flow_totals(f, before);
    assert_ok(flow_set_sources(f, &src));
    assert_int_equal(src.outside, 1);
    const double dt = 1e-3;
    for (int n = 0; n < 3; n++) assert_ok(flow_step(f, dt));
    flow_totals(f, after);
    /* 32 points in the box */
    assert_close(after[0], before[0], 1e-15);
    assert_close(after[1] - before[1], 3 * dt * 32 * 0.25, 1e-15);
    assert_close(after[2] - before[2], -3 * dt * 32 * 0.125, 1e-15);
    /* energy: exactly the power given. The work of the force on the moving
     * gas, F.u, is the caller's to include in the power if it means it; here
     * it does not, so the kinetic energy the gas gains comes out of its
     * internal energy. */
    assert_close(after[3] - before[3], 3 * dt * 32 * 0.5, 1e-14);
    flow_set_sources(f, NULL);
    double later[4];
    assert_ok(flow_step(f, dt));
    flow_totals(f, later);
    assert_close(later[1], after[1], 1e-15);
    flow_destroy(&f);
}

static void test_unknown_method_is_refused(void **state) {
    (void)state;
    FlowConfig c;
    memset(&c, 0, sizeof c);
    c.method = FLOW_METHOD_MAX - 1; /* an empty registry slot */
    Flow *f;
    assert_int_equal(flow_create(&f, &c), NSPD_ERR_INPUT);
    assert_null(f);
}

/* A unit cavity, 10 x 10 intervals, lid 1 m/s, Re 10. */
static void pddo_cavity(FlowConfig *c, double tolerance) {
    memset(c, 0, sizeof *c);
    c->method = FLOW_METHOD_PDDO;
    PddoFlowConfig *p;
    assert_ok(nspd_alloc(&p, 1, sizeof *p));
    c->model = p;
    p->cloud =
        (PddoCloudSpec){.lo = {0, 0}, .hi = {1, 1}, .dx = 0.1, .layers = 3, .horizon_factor = 3.0};
    p->step = (PddoStepParams){.rho = 1.0, .mu = 0.1};
    p->step.wall_u[PDDO_TOP] = 1.0;
    p->velocity_scale = p->reference_velocity = 1.0;
    p->reference_length = 1.0;
    p->step.dt = 0.5 * pddo_flow_dt_limit(p);
    p->steady_tolerance = tolerance;
    p->line_count = 1;
    p->lines[0] = (PddoLine){.name = "vertical", .at = {0.5, 0.5}, .along = 1};
}

static void test_pddo_behind_the_interface(void **state) {
    (void)state;
    FlowConfig c;
    pddo_cavity(&c, 0.0);
    const double dt = ((const PddoFlowConfig *)c.model)->step.dt;
    /* half of min(1.6 dx^2/nu, 2 nu/U^2) = min(0.16, 0.2) */
    assert_close(dt, 0.08, 1e-15);
    const FlowEstimate e = flow_estimate(&c);
    assert_close(e.cells, 17.0 * 17.0, 0); /* 11 nodes a side and 3 layers each way */
    Flow *f;
    assert_ok(flow_create(&f, &c));
    assert_string_equal(flow_name(f), "pddo");
    assert_int_equal(flow_mesh(f).kind, MESH_POINTS);
    int64_t cell;
    assert_int_equal(flow_cell_at(f, "p", 0.5, 0.5, &cell), NSPD_ERR_INPUT); /* no grid */
    assert_close(flow_stable_dt(f), dt, 0);
    double x = 0.5, y = 0.5, out[4];
    FlowSamples samples = {out, out + 1, out + 2, out + 3};
    assert_int_equal(flow_sample(f, 1, &x, &y, &samples), NSPD_ERR_INPUT);
    assert_int_equal(flow_set_sources(f, NULL), NSPD_ERR_INPUT);
    double totals[4];
    flow_totals(f, totals);
    assert_close(totals[0], 1.0, 1e-14); /* rho times the unit square's area */
    for (int k = 0; k < 20; k++) assert_ok(flow_step(f, dt));
    assert_false(flow_finished(f)); /* no tolerance: never */
    assert_close(flow_time(f), 20 * dt, 1e-14);
    FieldSet fs;
    flow_fields(f, &fs);
    assert_int_equal(fs.mesh, MESH_POINTS);
    assert_int_equal(fs.n, 121); /* the fluid and side nodes */
    assert_int_equal(fs.table_count, 1);
    assert_int_equal(fs.table[0].rows, 11);
    assert_close(fs.table[0].col[2][10], 1.0, 0); /* the lid's middle node */
    assert_true(fs.table[0].col[2][5] < 0.0);     /* the return flow below the vortex */
    flow_destroy(&f);

    pddo_cavity(&c, 1e30); /* any rate is below: finished after the first step */
    assert_ok(flow_create(&f, &c));
    assert_false(flow_finished(f));
    assert_ok(flow_step(f, dt));
    assert_true(flow_finished(f));
    flow_destroy(&f);
}

/* 1.25 times the largest Mach number, up to two significant digits; a
 * gas at rest leaves the scale open (0). The values are exact decimal
 * ones, so each is compared within a few ulps of its rounding unit. */
static void test_mach_picture_top(void **state) {
    (void)state;
    static const double cases[][2] = {
        {1.7, 2.2},   /* 2.125 up */
        {2.0, 2.5},   /* exactly 2.5: not one unit above */
        {0.3, 0.38},  /* 0.375 up */
        {8.0, 10.0},  /* 10 */
        {0.8, 1.0},   /* exactly 1 */
        {3.31, 4.2},  /* 4.1375 up */
        {0.01, 0.013} /* at the threshold: fixed */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const double got = flow_mach_picture_top(cases[k][0]);
        if (!(fabs(got - cases[k][1]) <= 1e-12 * cases[k][1]))
            fail_msg("Mach %g: top %.17g, expected %g", cases[k][0], got, cases[k][1]);
    }
    /* at rest, below the threshold, or no number: not fixed yet */
    assert_true(flow_mach_picture_top(0.0) == 0.0);
    assert_true(flow_mach_picture_top(0.5 * FLOW_MACH_AT_REST) == 0.0);
    assert_true(flow_mach_picture_top(NAN) == 0.0);
    assert_true(flow_mach_picture_top(INFINITY) == 0.0);
}

/* The speed pictures' top: the same rounding of the largest speed (m/s),
 * left open while the Mach number says the gas is at rest. */
static void test_speed_picture_top(void **state) {
    (void)state;
    static const double cases[][2] = {
        {340.0, 430.0}, /* 425 up */
        {800.0, 1000.0} /* exactly 1000 */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const double got = flow_speed_picture_top(cases[k][0], 1.0);
        if (!(fabs(got - cases[k][1]) <= 1e-12 * cases[k][1]))
            fail_msg("speed %g m/s: top %.17g, expected %g", cases[k][0], got, cases[k][1]);
    }
    /* moving air of Mach 0.01 (3.4 m/s at 290 K) fixes it; below, open */
    assert_true(fabs(flow_speed_picture_top(3.4, FLOW_MACH_AT_REST) - 4.3) <= 1e-12 * 4.3);
    assert_true(flow_speed_picture_top(3.0, 0.5 * FLOW_MACH_AT_REST) == 0.0);
    assert_true(flow_speed_picture_top(0.0, 1.0) == 0.0);
    assert_true(flow_speed_picture_top(NAN, 1.0) == 0.0);
    assert_true(flow_speed_picture_top(340.0, NAN) == 0.0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sample_is_exact_for_linear_fields),
        cmocka_unit_test(test_mach_picture_top),
        cmocka_unit_test(test_speed_picture_top),
        cmocka_unit_test(test_sources_push_the_gas),
        cmocka_unit_test(test_unknown_method_is_refused),
        cmocka_unit_test(test_pddo_behind_the_interface),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
