/* couple/ghost/ibm incremental update: moving walls and rebuilding incrementally
 * gives bitwise the tags and stencils of a build from scratch, at a cost
 * that scales with the moved interface; fresh cells get values from their
 * fluid neighbours. */
#include "test_support.h"

#include "core/status.h"
#include "couple/ghost/ibm.h"
#include "couple/ghost/wall_loads.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Stretched grid on [0, 2] x [0, 1]. */
static GksSolver *make_solver(void) {
    GksConfig c;
    gks_config_default(&c);
    c.gas_constant = 1.0;
    c.x0 = 0.0;
    c.y0 = 0.0;
    c.segment_count[0] = 2;
    c.segments[0][0] = (GridSegment){.length = 1.2, .h_start = 0.01};
    c.segments[0][1] = (GridSegment){.length = 0.8, .h_start = 0.01, .h_end = 0.03};
    c.segment_count[1] = 1;
    c.segments[1][0] = (GridSegment){.length = 1.0, .h_start = 0.008, .h_end = 0.015};
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    return s;
}

/* Asserts that two immersed boundaries hold the same tags and ghost stencils
 * bit for bit. */
static void assert_same(const Ibm *a, const Ibm *b, const Grid *g) {
    assert_memory_equal(ibm_kinds(a), ibm_kinds(b), (size_t)g->size);
    IbmUpdateStats sa, sb;
    ibm_stats(a, &sa);
    ibm_stats(b, &sb);
    assert_int_equal(sa.solid_cells, sb.solid_cells);
    assert_int_equal(sa.ghosts, sb.ghosts);
    assert_int_equal(ibm_ghost_count(a), ibm_ghost_count(b));
    for (int e = 0; e < ibm_ghost_count(a); e++) {
        IbmGhostInfo x, y;
        ibm_ghost_info(a, e, &x);
        ibm_ghost_info(b, e, &y);
        if (memcmp(&x, &y, sizeof x))
            printf("ghost %d (%d, %d): level %d/%d seg %d/%d nodeseg %d %d %d %d / %d %d %d %d "
                   "d %.17g/%.17g\n",
                   e, x.i, x.j, x.level, y.level, x.segment, y.segment, x.node_segment[0],
                   x.node_segment[1], x.node_segment[2], x.node_segment[3], y.node_segment[0],
                   y.node_segment[1], y.node_segment[2], y.node_segment[3], x.dist, y.dist);
        assert_memory_equal(&x, &y, sizeof x);
    }
}

static void shift(IbmPolyline *p, const IbmPolyline *ref, double dx, double dy, double rot) {
    /* rotation about the first marker, then a shift */
    const double c = cos(rot), s = sin(rot), x0 = ref->x[0], y0 = ref->y[0];
    for (int k = 0; k < p->n; k++) {
        const double x = ref->x[k] - x0, y = ref->y[k] - y0;
        p->x[k] = x0 + c * x - s * y + dx;
        p->y[k] = y0 + s * x + c * y + dy;
        p->vx[k] = 0.1;
        p->vy[k] = -0.05;
    }
}

static void test_update_equals_scratch(void **state) {
    (void)state;
    GksSolver *s = make_solver();
    const Grid *g = gks_solver_grid(s);
    const IbmBodyConfig cc = {
        .kind = IBM_BODY_CIRCLE, .center = {0.5, 0.5}, .radius = 0.2, .markers = 400};
    const IbmBodyConfig nc = {.kind = IBM_BODY_NACA,
                              .digits = "0012",
                              .chord = 0.5,
                              .leading_edge = {1.1, 0.5},
                              .angle_deg = 5,
                              .markers = 300};
    IbmPolyline ref[2], cur[2];
    assert_ok(ibm_body_markers(&cc, &ref[0]));
    assert_ok(ibm_body_markers(&nc, &ref[1]));
    assert_ok(ibm_body_markers(&cc, &cur[0]));
    assert_ok(ibm_body_markers(&nc, &cur[1]));
    Ibm *inc = NULL;
    assert_ok(ibm_create(&inc, g, cur, 2));
    IbmUpdateStats st;

    /* 1. nothing moves: nothing is rebuilt */
    assert_ok(ibm_update(inc, cur, 2, NULL));
    ibm_stats(inc, &st);
    assert_int_equal(st.rebuilt, 0);
    assert_int_equal(st.retagged, 0);

    /* 2. the circle moves by 0.3 cells and turns; the airfoil stays */
    shift(&cur[0], &ref[0], 0.003, -0.0021, 0.01);
    assert_ok(ibm_update(inc, cur, 2, NULL));
    ibm_stats(inc, &st);
    Ibm *scratch = NULL;
    assert_ok(ibm_create(&scratch, g, cur, 2));
    assert_same(inc, scratch, g);
    assert_true(st.changed > 0);
    assert_true(st.kept > 0); /* the airfoil's ghosts */
    assert_true(st.rebuilt > 0 && st.rebuilt < st.ghosts);
    /* re-tagging stays near the wall: the circle's band, not the grid */
    assert_true(st.retagged < (int64_t)g->nx * g->ny / 5);
    ibm_destroy(&scratch);

    /* 3. both move (the airfoil pitches by 0.5 degree) */
    shift(&cur[0], &ref[0], -0.004, 0.0017, 0.02);
    shift(&cur[1], &ref[1], 0.0011, 0.0, 0.5 * M_PI / 180);
    assert_ok(ibm_update(inc, cur, 2, NULL));
    assert_ok(ibm_create(&scratch, g, cur, 2));
    assert_same(inc, scratch, g);
    ibm_destroy(&scratch);

    /* 4. a marker count change (the circle re-sampled) re-tags its boxes */
    IbmPolyline fine;
    IbmBodyConfig cf = cc;
    cf.center[0] = 0.52;
    cf.markers = 512;
    assert_ok(ibm_body_markers(&cf, &fine));
    IbmPolyline pair[2] = {fine, cur[1]};
    assert_ok(ibm_update(inc, pair, 2, NULL));
    assert_ok(ibm_create(&scratch, g, pair, 2));
    assert_same(inc, scratch, g);
    assert_int_equal(ibm_segment_count(inc), 512 + 300);
    ibm_destroy(&scratch);

    /* a different number of bodies is refused */
    assert_int_equal(ibm_update(inc, pair, 1, NULL), NSPD_ERR_INPUT);
    ibm_destroy(&inc);
    ibm_polyline_free(&fine);
    for (int q = 0; q < 2; q++) {
        ibm_polyline_free(&ref[q]);
        ibm_polyline_free(&cur[q]);
    }
    gks_solver_destroy(&s);
}

/* A uniform flow moving with a translating body: the cells the body leaves
 * behind become fluid with exactly that state. */
static void test_fresh_cells(void **state) {
    (void)state;
    GksSolver *s = make_solver();
    const Grid *g = gks_solver_grid(s);
    const double U = 0.4, V = 0.1;
    GksFields f = gks_solver_fields(s);
    for (int j = -2; j < g->ny + 2; j++)
        for (int i = -2; i < g->nx + 2; i++) {
            const int64_t k = grid_index(g, i, j);
            f.w[0][k] = 1.1;
            f.w[1][k] = 1.1 * U;
            f.w[2][k] = 1.1 * V;
            f.w[3][k] = 2.0 + 0.5 * 1.1 * (U * U + V * V);
        }
    const IbmBodyConfig cc = {
        .kind = IBM_BODY_CIRCLE, .center = {0.6, 0.45}, .radius = 0.15, .markers = 256};
    IbmPolyline ref, cur;
    assert_ok(ibm_body_markers(&cc, &ref));
    assert_ok(ibm_body_markers(&cc, &cur));
    for (int k = 0; k < cur.n; k++) cur.vx[k] = U, cur.vy[k] = V;
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &cur, 1));
    assert_ok(ibm_attach(ibm, s));
    int total_fresh = 0;
    for (int step = 1; step <= 5; step++) {
        for (int k = 0; k < cur.n; k++) {
            cur.x[k] = ref.x[k] + step * 0.004; /* 0.4 cells per step */
            cur.y[k] = ref.y[k] + step * 0.001;
        }
        assert_ok(ibm_update(ibm, &cur, 1, s));
        IbmUpdateStats st;
        ibm_stats(ibm, &st);
        total_fresh += st.fresh;
        ibm_fill_ghosts(ibm, s);
        f = gks_solver_fields(s);
        for (int j = 0; j < g->ny; j++)
            for (int i = 0; i < g->nx; i++) {
                const int64_t k = grid_index(g, i, j);
                assert_int_equal(f.kind[k], ibm_kinds(ibm)[k]);
                if (f.kind[k] == FLOW_CELL_SOLID) continue;
                assert_close(f.w[0][k], 1.1, 1e-13);
                assert_close(f.w[1][k] / f.w[0][k], U, 1e-13);
                assert_close(f.w[2][k] / f.w[0][k], V, 1e-13);
                assert_close(f.w[3][k], 2.0 + 0.5 * 1.1 * (U * U + V * V), 1e-12);
            }
    }
    assert_true(total_fresh > 20);
    ibm_destroy(&ibm);
    ibm_polyline_free(&ref);
    ibm_polyline_free(&cur);
    gks_solver_destroy(&s);
}

/* Surface loads of a body in a fluid at rest at uniform pressure: no force;
 * the tractions carry -(p - p_ambient) n and lump onto the markers. */
static void test_surface_at_rest(void **state) {
    (void)state;
    GksSolver *s = make_solver();
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    for (int64_t k = 0; k < g->size; k++) {
        f.w[0][k] = 1.0;
        f.w[1][k] = f.w[2][k] = 0.0;
        f.w[3][k] = 3.0 / 0.4;
    }
    const IbmBodyConfig nc = {.kind = IBM_BODY_NACA,
                              .digits = "0012",
                              .chord = 0.8,
                              .leading_edge = {0.5, 0.5},
                              .markers = 200};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&nc, &p));
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &p, 1));
    assert_ok(ibm_attach(ibm, s));
    IbmSurface sf;
    memset(&sf, 0, sizeof sf);
    assert_ok(ibm_surface_reserve(ibm, &sf));
    const IbmReference ref = {
        .rho = 1.0, .u = 1.0, .v = 0.0, .p = 3.0, .length = 0.8, .p_ambient = 2.0};
    assert_ok(ibm_surface_compute(ibm, s, &ref, &sf));
    const IbmBodyForces *F = &sf.forces[0];
    assert_close(F->cd, 0.0, 1e-12);
    assert_close(F->cl, 0.0, 1e-12);
    for (int k = 0; k < sf.n; k++) {
        assert_close(sf.p[k], 3.0, 1e-12);
        assert_close(sf.cp[k], 0.0, 1e-12);
        assert_close(sf.tau[k], 0.0, 1e-14);
        assert_close(sf.fx[k], -1.0 * sf.nx[k], 1e-12);
        assert_close(sf.fy[k], -1.0 * sf.ny[k], 1e-12);
    }
    assert_close(F->chord, 0.8, 1e-15);
    assert_true(F->leading_edge[0] == 0.5 && F->trailing_edge[0] == 1.3);
    double fx[200], fy[200], sx = 0.0, sy = 0.0;
    ibm_surface_marker_forces(ibm, &sf, 0, fx, fy);
    for (int k = 0; k < 200; k++) sx += fx[k], sy += fy[k];
    assert_close(sx, 0.0, 1e-13); /* a closed wall under uniform pressure */
    assert_close(sy, 0.0, 1e-13);
    /* upper side: the segments from the trailing edge to the leading edge */
    for (int k = 0; k < 200; k++) assert_int_equal(sf.upper[k], k < 100);
    ibm_surface_free(&sf);
    ibm_destroy(&ibm);
    ibm_polyline_free(&p);
    gks_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_update_equals_scratch),
        cmocka_unit_test(test_fresh_cells),
        cmocka_unit_test(test_surface_at_rest),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
