/* Free-stream preservation with immersed bodies on a stretched grid.
 *
 * A uniform stream (Ma 0.8 at 30 degrees) on a 338 x 381 stretched grid
 * (spacing 0.004 to 0.03, ratios up to 1.021, all four faces far field) around a box and a circle
 * whose walls move with the stream (every marker's velocity is the stream's)
 * and are adiabatic: the uniform state solves the problem, so every ghost
 * value must be the free stream (the stencil weights sum to one) and the
 * flow must stay uniform to round-off. Second, a box with walls at rest in
 * a gas at rest, isothermal at the gas temperature. The grid is large
 * enough for the flow step to run threaded: the state after 20 steps at 1
 * and at 2 threads must agree bit for bit. Third, with sealed ghost faces
 * (ibm.h) the gas mass in a periodic box round bodies at rest is conserved
 * to round-off. */
#include "test_support.h"

#include "core/status.h"
#include "couple/ghost/ibm.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>

static void config(GksConfig *c, FlowPrim q) {
    gks_config_default(c);
    c->gas_constant = 1.0;
    c->viscosity = VISCOSITY_SUTHERLAND;
    c->mu_ref = 1e-3;
    c->T_ref = 1.0 / 1.4;
    c->sutherland_S = 0.26;
    c->x0 = 0.0;
    c->y0 = 0.0;
    c->segment_count[0] = 3;
    c->segments[0][0] = (GridSegment){.length = 1.0, .h_start = 0.02, .h_end = 0.005};
    c->segments[0][1] = (GridSegment){.length = 0.8, .h_start = 0.005};
    c->segments[0][2] = (GridSegment){.length = 1.2, .h_start = 0.005, .h_end = 0.03};
    c->segment_count[1] = 2;
    c->segments[1][0] = (GridSegment){.length = 1.0, .h_start = 0.004};
    c->segments[1][1] = (GridSegment){.length = 1.5, .h_start = 0.004, .h_end = 0.025};
    const FlowBc far = {.kind = BC_SUBSONIC_INFLOW, .state = q};
    for (int f = 0; f < 4; f++) gks_config_set_bc(c, f, &far);
    c->initial = q;
}

/* Largest relative deviation of the fluid and ghost cells from q. */
static double deviation(GksSolver *s, FlowPrim q) {
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    double w0[4];
    flow_prim_to_cons(&q, 1.4, w0);
    const double scale[4] = {w0[0], w0[0] * 1.0, w0[0] * 1.0, w0[3]};
    double worst = 0.0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (f.kind[k] == FLOW_CELL_SOLID) continue;
            for (int v = 0; v < 4; v++) worst = fmax(worst, fabs(f.w[v][k] - w0[v]) / scale[v]);
        }
    return worst;
}

static void make_bodies(IbmPolyline b[2], double u, double v, int thermal, double T) {
    const IbmBodyConfig box = {.kind = IBM_BODY_RECTANGLE,
                               .min = {1.2, 0.3},
                               .max = {1.55, 0.55},
                               .markers_per_side = 80,
                               .thermal = thermal,
                               .wall_temperature = T};
    const IbmBodyConfig cyl = {.kind = IBM_BODY_CIRCLE,
                               .center = {1.3, 0.8},
                               .radius = 0.12,
                               .markers = 256,
                               .thermal = thermal,
                               .wall_temperature = T};
    assert_ok(ibm_body_markers(&box, &b[0]));
    assert_ok(ibm_body_markers(&cyl, &b[1]));
    for (int q = 0; q < 2; q++)
        for (int k = 0; k < b[q].n; k++) b[q].vx[k] = u, b[q].vy[k] = v;
}

/* make_bodies, attached to s with `faces`; the polylines go to b. */
static Ibm *attach_bodies(GksSolver *s, IbmGhostFaces faces, IbmPolyline b[2], double u, double v,
                          int thermal, double T) {
    make_bodies(b, u, v, thermal, T);
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, gks_solver_grid(s), b, 2));
    ibm_set_ghost_faces(ibm, faces);
    assert_ok(ibm_attach(ibm, s));
    return ibm;
}

static void moving_walls(IbmGhostFaces faces) {
    const double U = 0.8, a = M_PI / 6;
    const FlowPrim q = {1.0, U * cos(a), U * sin(a), 1.0 / 1.4};
    GksConfig c;
    config(&c, q);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    IbmPolyline b[2];
    Ibm *ibm = attach_bodies(s, faces, b, q.u, q.v, IBM_WALL_ADIABATIC, 0.0);
    const Grid *g = gks_solver_grid(s);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    assert_true((int64_t)g->nx * g->ny >= 65536); /* the step runs threaded */
    const double d0 = deviation(s, q);
    for (int k = 0; k < 50; k++) assert_ok(gks_solver_step(s, gks_solver_stable_dt(s)));
    const double d1 = deviation(s, q);
    printf("free stream, walls moving with it, %s ghost faces: %d x %d cells, %d ghosts, %lld "
           "solid; relative deviation after attach %.2e, after 50 steps %.2e\n",
           IBM_GHOST_FACE_NAMES[faces], g->nx, g->ny, st.ghosts, (long long)st.solid_cells, d0, d1);
    /* Measured: 3.3e-16 after attach and after 50 steps (one ulp), with
     * either kind of ghost face (sealed: the wall's displacement flux is the
     * stream's); bound 1e-14 / 1e-13 (round-off growth over the steps). */
    assert_true(d0 < 1e-14);
    assert_true(d1 < 1e-13);
    ibm_destroy(&ibm);
    for (int k = 0; k < 2; k++) ibm_polyline_free(&b[k]);
    gks_solver_destroy(&s);
}

static void test_moving_walls(void **state) {
    (void)state;
    moving_walls(IBM_FACES_REFLECTED);
    moving_walls(IBM_FACES_SEALED);
}

/* Gas mass in a periodic box round bodies at rest after 100 steps of a
 * Ma 0.6 stream started impulsively, relative to the initial mass. */
static double mass_drift(IbmGhostFaces faces) {
    const FlowPrim q = {1.0, 0.6 * cos(0.3), 0.6 * sin(0.3), 1.0 / 1.4};
    GksConfig c;
    config(&c, q);
    c.segment_count[0] = c.segment_count[1] = 0;
    gks_config_uniform_grid(&c, 0.0, 2.0, 160, 0.0, 1.5, 120);
    const FlowBc periodic = {.kind = BC_PERIODIC};
    for (int f = 0; f < 4; f++) gks_config_set_bc(&c, f, &periodic);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    IbmPolyline b[2];
    Ibm *ibm = attach_bodies(s, faces, b, 0.0, 0.0, IBM_WALL_ADIABATIC, 0.0);
    double t0[4], t1[4];
    gks_solver_totals(s, t0);
    for (int k = 0; k < 100; k++) assert_ok(gks_solver_step(s, gks_solver_stable_dt(s)));
    gks_solver_totals(s, t1);
    ibm_destroy(&ibm);
    for (int k = 0; k < 2; k++) ibm_polyline_free(&b[k]);
    gks_solver_destroy(&s);
    return t1[0] / t0[0] - 1.0;
}

static void test_sealed_conserves_mass(void **state) {
    (void)state;
    const double reflected = mass_drift(IBM_FACES_REFLECTED), sealed = mass_drift(IBM_FACES_SEALED);
    printf("gas mass in a periodic box round bodies at rest, 100 steps: relative change %.2e "
           "with reflected ghost faces, %.2e with sealed ones\n",
           reflected, sealed);
    /* Measured: sealed 6.7e-16 (round-off of the sums); bound 1e-13.
     * Reflected -2.7e-5: the check sees a leak of that size. */
    assert_true(fabs(sealed) < 1e-13);
    assert_true(fabs(reflected) > 1e-6);
}

static void test_rest_isothermal(void **state) {
    (void)state;
    const FlowPrim q = {1.0, 0.0, 0.0, 1.0 / 1.4};
    GksConfig c;
    config(&c, q);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    IbmPolyline b[2]; /* T = p / (rho R) */
    Ibm *ibm = attach_bodies(s, IBM_FACES_REFLECTED, b, 0.0, 0.0, IBM_WALL_ISOTHERMAL, 1.0 / 1.4);
    for (int k = 0; k < 20; k++) assert_ok(gks_solver_step(s, gks_solver_stable_dt(s)));
    const double d = deviation(s, q);
    printf("gas at rest, isothermal walls at rest: relative deviation after 20 steps %.2e\n", d);
    assert_true(d < 1e-13);
    ibm_destroy(&ibm);
    for (int k = 0; k < 2; k++) ibm_polyline_free(&b[k]);
    gks_solver_destroy(&s);
}

/* Runs 20 steps from a perturbed stream at `threads` threads; returns rho. */
static void run_threads(int threads, IbmGhostFaces faces, double *out, int64_t n) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    const FlowPrim q = {1.0, 0.5, 0.0, 1.0 / 1.4};
    GksConfig c;
    config(&c, q);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    IbmPolyline b[2];
    Ibm *ibm = attach_bodies(s, faces, b, 0.0, 0.0, IBM_WALL_ADIABATIC, 0.0);
    ibm_soft_start(ibm, s, 0.1);
    for (int k = 0; k < 20; k++) assert_ok(gks_solver_step(s, gks_solver_stable_dt(s)));
    GksFields f = gks_solver_fields(s);
    memcpy(out, f.w[0], (size_t)n * sizeof(double));
    ibm_destroy(&ibm);
    for (int k = 0; k < 2; k++) ibm_polyline_free(&b[k]);
    gks_solver_destroy(&s);
    omp_set_num_threads(saved);
}

static void test_threads_bitwise(void **state) {
    (void)state;
    GksConfig c;
    config(&c, (FlowPrim){1, 0, 0, 1});
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    const int64_t n = gks_solver_grid(s)->size;
    gks_solver_destroy(&s);
    double *a = test_malloc((size_t)n * sizeof(double));
    double *b = test_malloc((size_t)n * sizeof(double));
    for (int faces = 0; faces < IBM_FACES_COUNT; faces++) {
        run_threads(1, (IbmGhostFaces)faces, a, n);
        run_threads(2, (IbmGhostFaces)faces, b, n);
        assert_memory_equal(a, b, (size_t)n * sizeof(double));
    }
    test_free(a);
    test_free(b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_moving_walls),
        cmocka_unit_test(test_sealed_conserves_mass),
        cmocka_unit_test(test_rest_isothermal),
        cmocka_unit_test(test_threads_bitwise),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
