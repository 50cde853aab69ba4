/* Flow operator plumbing: cell kinds and the ghost hook, sealed ghost faces,
 * the numeric check, accessors, the benchmark entry point. */
#include "test_support.h"

#include "core/status.h"
#include "flow/gks/solver.h"
#include "flow/gks/solver_internal.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void base_config(GksConfig *c, int n) {
    gks_config_default(c);
    c->gas_constant = 1.0;
    c->viscosity = VISCOSITY_CONSTANT;
    c->mu_ref = 1e-3;
    gks_config_uniform_grid(c, 0.0, 1.0, n, 0.0, 1.0, n);
    const FlowBc per = {.kind = BC_PERIODIC};
    for (int f = 0; f < 4; f++) gks_config_set_bc(c, f, &per);
    c->initial = (FlowPrim){1.0, 0.3, 0.1, 1.0};
}

/* A solid block (garbage inside) ringed by ghost cells that a hook fills
 * with the free stream: fluid cells stay finite, solid and ghost cells are
 * never updated, the hook runs once per step. */
typedef struct {
    int calls;
} HookCtx;

static void hook(void *ctx, GksSolver *s) {
    ((HookCtx *)ctx)->calls++;
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    const double w[4] = {1.0, 0.3, 0.1, 1.0 / 0.4 + 0.5 * 0.1};
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (f.kind[k] == FLOW_CELL_GHOST)
                for (int v = 0; v < 4; v++) f.w[v][k] = w[v];
        }
}

/* Cells 4..11 x 4..11 of a 16 x 16 solver: a ring of ghosts round a solid
 * block holding NaN. With `slot` (grid-sized), numbers the ring cells in it
 * (-1 elsewhere). Returns the ring's size. */
static int make_ring(GksSolver *s, int32_t *slot) {
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    if (slot)
        for (int64_t k = 0; k < g->size; k++) slot[k] = -1;
    int n = 0;
    for (int j = 4; j < 12; j++)
        for (int i = 4; i < 12; i++) {
            const int64_t k = grid_index(g, i, j);
            const int ring = i == 4 || i == 11 || j == 4 || j == 11;
            f.kind[k] = ring ? FLOW_CELL_GHOST : FLOW_CELL_SOLID;
            if (ring && slot) slot[k] = n;
            n += ring;
            if (!ring)
                for (int v = 0; v < 4; v++) f.w[v][k] = (double)NAN;
        }
    return n;
}

static void test_kinds_and_hook(void **state) {
    (void)state;
    GksConfig c;
    base_config(&c, 16);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    const Grid *g = gks_solver_grid(s);
    make_ring(s, NULL);
    HookCtx ctx = {0};
    gks_solver_set_ghost_hook(s, hook, &ctx);
    for (int n = 0; n < 5; n++) assert_ok(gks_solver_step(s, 1e-3));
    assert_int_equal(ctx.calls, 5);
    GksFields f = gks_solver_fields(s);
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (f.kind[k] == FLOW_CELL_SOLID)
                assert_true(isnan(f.w[0][k]));
            else
                assert_true(isfinite(f.w[0][k]) && isfinite(f.w[3][k]));
            /* a uniform stream around a ghost ring holding the same stream stays uniform */
            if (f.kind[k] == FLOW_CELL_FLUID) assert_close(f.w[0][k], 1.0, 1e-13);
        }
    gks_solver_destroy(&s);
    assert_null(s);
}

/* Sealed ghost faces (gks_solver_set_ghost_walls): the same ring with its
 * walls at rest. Fluid cell (3, 6) meets the ring only at its right face,
 * and the state is uniform, so one step changes it only by what that face
 * no longer carries: the face keeps the pressure and loses the convected
 * mass, momentum and enthalpy, so
 *     d rho = dt rho u / dx,  d (rho u) = dt rho u^2 / dx,  d (rho E) = dt rho u H / dx.
 * With the walls moving with the stream the face carries the stream's flux
 * and nothing changes. */
static void sealed_ring_step(double wall_u, double wall_v, double out[4]) {
    GksConfig c;
    base_config(&c, 16);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    const Grid *g = gks_solver_grid(s);
    int32_t *slot = test_malloc((size_t)g->size * sizeof(int32_t));
    double wu[28], wv[28];
    assert_int_equal(make_ring(s, slot), 28);
    for (int e = 0; e < 28; e++) wu[e] = wall_u, wv[e] = wall_v;
    HookCtx ctx = {0};
    gks_solver_set_ghost_hook(s, hook, &ctx);
    gks_solver_set_ghost_walls(s, slot, wu, wv);
    assert_ok(gks_solver_step(s, 1e-3));
    GksFields f = gks_solver_fields(s);
    for (int v = 0; v < 4; v++) out[v] = f.w[v][grid_index(g, 3, 6)];
    gks_solver_destroy(&s);
    test_free(slot);
}

static void test_sealed_ghost_faces(void **state) {
    (void)state;
    const double rho = 1.0, u = 0.3, v = 0.1, p = 1.0, E = p / 0.4 + 0.5 * (u * u + v * v);
    const double H = E + p / rho, dt = 1e-3, dx = 1.0 / 16;
    double w[4];
    sealed_ring_step(0.0, 0.0, w);
    assert_close(w[0], rho + dt * rho * u / dx, 1e-13);
    assert_close(w[1], rho * u + dt * rho * u * u / dx, 1e-13);
    assert_close(w[2], rho * v + dt * rho * u * v / dx, 1e-13);
    assert_close(w[3], rho * E + dt * rho * u * H / dx, 1e-13);
    sealed_ring_step(u, v, w);
    assert_close(w[0], rho, 1e-13);
    assert_close(w[1], rho * u, 1e-13);
    assert_close(w[3], rho * E, 1e-13);
}

static void test_numeric_check_names_the_cell(void **state) {
    (void)state;
    GksConfig c;
    base_config(&c, 8);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    f.w[3][grid_index(g, 5, 3)] = -1.0; /* negative energy: p < 0 */
    const int st = gks_solver_step(s, 1e-4);
    assert_int_equal(st, NSPD_ERR_NUMERIC);
    /* the bad cell spoils its stencil: the first bad one in row order is
     * within two cells of it */
    const char *msg = strstr(nspd_error_message(), "cell (");
    assert_non_null(msg);
    int i = -1, j = -1;
    assert_int_equal(sscanf(msg, "cell (%d, %d)", &i, &j), 2);
    assert_true(abs(i - 5) <= 2 && j >= 1 && j <= 3);
    assert_non_null(strstr(nspd_error_message(), "step 1"));
    nspd_error_clear();
    gks_solver_destroy(&s);
}

static void test_accessors_and_dt(void **state) {
    (void)state;
    GksConfig c;
    base_config(&c, 10);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    double out[100], tot[4];
    gks_solver_primitive(s, FLOW_PRESSURE, out);
    assert_close(out[37], 1.0, 1e-14);
    gks_solver_primitive(s, FLOW_MACH, out);
    assert_close(out[0], sqrt(0.1 / 1.4), 1e-14);
    gks_solver_primitive(s, FLOW_TEMPERATURE, out);
    assert_close(out[99], 1.0, 1e-14);
    gks_solver_totals(s, tot);
    assert_close(tot[0], 1.0, 1e-14);
    assert_close(tot[1], 0.3, 1e-14);
    /* dt: CFL / ((|u|+c)/dx + (|v|+c)/dy + 2 nu_eff (2/dx^2)) */
    const double cs = sqrt(1.4), h = 0.1, nu = fmax(4.0 / 3.0, 1.4 / 0.72) * 1e-3;
    const double rate = (0.3 + cs) / h + (0.1 + cs) / h + 2.0 * nu * 2.0 / (h * h);
    assert_close(gks_solver_stable_dt(s), 0.5 / rate, 1e-15);
    /* the same from the configuration alone (nspd check of a grid it does
     * not build), and its checks */
    assert_close(gks_solver_config_stable_dt(&c, NULL, 0), 0.5 / rate, 1e-15);
    assert_ok(gks_solver_validate(&c));
    assert_ok(gks_solver_advance(s, 0.05, 0));
    assert_close(gks_solver_time(s), 0.05, 1e-15);
    assert_true(gks_solver_step_count(s) > 0);
    assert_true(gks_solver_fallbacks_total(s) == 0);
    gks_solver_destroy(&s);
}

static void test_bad_config(void **state) {
    (void)state;
    GksConfig c;
    base_config(&c, 8);
    c.bc[FLOW_FACE_XHI].seg[0].kind = BC_EXTRAPOLATION;
    GksSolver *s = NULL;
    assert_int_equal(gks_solver_create(&s, &c), NSPD_ERR_INPUT);
    assert_null(s);
    assert_int_equal(gks_solver_validate(&c), NSPD_ERR_INPUT); /* the same checks */
    base_config(&c, 8);
    c.cfl = 0.0;
    assert_int_equal(gks_solver_create(&s, &c), NSPD_ERR_INPUT);
    assert_int_equal(gks_solver_validate(&c), NSPD_ERR_INPUT);
    assert_close(gks_solver_config_stable_dt(&c, NULL, 0), 0.0, 0.0);
    nspd_error_clear();
}

/* Initial regions: a rectangle and a disc (later regions win), Gauss-averaged. */
static void test_initial_regions(void **state) {
    (void)state;
    GksConfig c;
    base_config(&c, 20);
    Shape rect = {.kind = SHAPE_RECTANGLE, .lo = {0.0, 0.0}, .hi = {0.5, 1.0}};
    Shape disc = {.kind = SHAPE_DISC, .center = {0.25, 0.5}, .radius = 0.1};
    FlowRegion regions[2] = {{.shapes = {.count = 1, .shapes = &rect}, .state = {2.0, 0, 0, 3.0}},
                             {.shapes = {.count = 1, .shapes = &disc}, .state = {5.0, 0, 0, 3.0}}};
    c.regions = regions;
    c.region_count = 2;
    c.init_quadrature = 3;
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    double rho[400];
    gks_solver_primitive(s, FLOW_DENSITY, rho);
    assert_close(rho[0], 2.0, 1e-14);           /* cell (0, 0): rectangle */
    assert_close(rho[19], 1.0, 1e-14);          /* cell (19, 0): background */
    assert_close(rho[10 * 20 + 4], 5.0, 1e-14); /* (4, 10) centre (0.225, 0.525): disc */
    assert_close(rho[3 * 20 + 19], 1.0, 1e-14);
    /* the cell straddling the disc edge gets a quadrature average */
    assert_true(rho[10 * 20 + 6] > 2.0 && rho[10 * 20 + 6] < 5.0);
    /* the step from the configuration: the fastest state's (the
     * rectangle's: sound speed sqrt(2.1)), as the built one, since the
     * rectangle covers whole cells (whose state went through the conserved
     * variables: 3 ulp measured) */
    assert_close(gks_solver_config_stable_dt(&c, regions, 2), gks_solver_stable_dt(s),
                 1e-14 * gks_solver_stable_dt(s));
    gks_solver_destroy(&s);
}

/* The rows on two threads, their cuts skewed to start with and then moved
 * by the times measured (core/balance.h), give the bits of one thread: each
 * face's flux is its own, whichever thread's block holds it. */
static void test_rows_on_threads_any_cut(void **state) {
    (void)state;
    GksSolver *s[2];
    for (int k = 0; k < 2; k++) {
        GksConfig c;
        base_config(&c, 128); /* 16,384 cells: worth a team */
        assert_ok(gks_solver_create(&s[k], &c));
        const Grid *g = gks_solver_grid(s[k]);
        GksFields f = gks_solver_fields(s[k]);
        for (int j = 0; j < g->ny; j++) /* a density bump: the rows differ */
            for (int i = 0; i < g->nx; i++)
                f.w[0][grid_index(g, i, j)] +=
                    0.2 * exp(-0.01 * ((i - 40) * (i - 40) + (j - 70) * (j - 70)));
    }
    s[1]->row_balance = (Balance){.threads = 2, .cut = {0.0, 0.85, 1.0}};
    const int max = omp_get_max_threads();
    const double dt = 0.5 * gks_solver_stable_dt(s[0]);
    for (int step = 0; step < 12; step++) {
        omp_set_num_threads(1);
        assert_ok(gks_solver_step(s[0], dt));
        omp_set_num_threads(2);
        assert_ok(gks_solver_step(s[1], dt));
    }
    omp_set_num_threads(max);
    assert_int_equal(s[1]->row_balance.threads, 2); /* the rows did run on two threads */
    const Grid *g = gks_solver_grid(s[0]);
    for (int v = 0; v < 4; v++)
        assert_memory_equal(gks_solver_fields(s[0]).w[v], gks_solver_fields(s[1]).w[v],
                            (size_t)g->size * sizeof(double));
    for (int k = 0; k < 2; k++) gks_solver_destroy(&s[k]);
}

static void test_bench_runs(void **state) {
    (void)state;
    GksBenchResult r;
    assert_ok(gks_bench(1024, 1, 2, NULL, &r));
    assert_true(r.cells == 1024 && r.steps == 2 && r.threads == 1);
    assert_true(r.cell_updates_per_s > 0.0);
    assert_true(r.bytes_per_cell > 64.0 && r.bytes_per_cell < 200.0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kinds_and_hook),
        cmocka_unit_test(test_sealed_ghost_faces),
        cmocka_unit_test(test_numeric_check_names_the_cell),
        cmocka_unit_test(test_accessors_and_dt),
        cmocka_unit_test(test_bad_config),
        cmocka_unit_test(test_initial_regions),
        cmocka_unit_test(test_rows_on_threads_any_cut),
        cmocka_unit_test(test_bench_runs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
