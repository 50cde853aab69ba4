/* solid/pd/surface: tracing closed counter-clockwise loops of surface points
 * on the lattice, and moving tractions onto the points. */
#include "pd_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "solid/bond/body.h"
#include "solid/bond/model.h"
#include "solid/pd/surface.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void check_loops(const BondBody *b, const PdSurface *s) {
    for (int k = 0; k < s->loop_count; k++) {
        int64_t lo = s->loop_start[k], hi = s->loop_start[k + 1];
        double area = 0;
        for (int64_t m = lo; m < hi; m++) {
            int32_t a = s->point[m], c = s->point[m + 1 < hi ? m + 1 : lo];
            int di = b->lattice[0][c] - b->lattice[0][a], dj = b->lattice[1][c] - b->lattice[1][a];
            assert_true(abs(di) <= 1 && abs(dj) <= 1 && (di || dj)); /* lattice neighbours */
            area += b->x[0][a] * b->x[1][c] - b->x[0][c] * b->x[1][a];
        }
        assert_true(area > 0); /* counter-clockwise */
    }
}

static void test_rectangle_loop(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 10, 6, 0, 1e-3);
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    PdSurface s;
    assert_ok(pd_surface_trace(&pts, &s));
    assert_int_equal(s.loop_count, 1);
    assert_int_equal(s.length, 2 * (10 + 6) - 4); /* every edge point once */
    check_loops(&b, &s);
    /* exactly the points on the lattice's edges */
    for (int64_t m = 0; m < s.length; m++) {
        int32_t p = s.point[m], i = b.lattice[0][p], j = b.lattice[1][p];
        assert_true(i == 0 || j == 0 || i == 9 || j == 5);
    }
    pd_surface_free(&s);
    bond_body_destroy(&b);
}

static void test_disc_and_two_parts(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 1, 1, 0, 1e-3);
    shapeset_free(&cfg.geometry);
    assert_ok(nspd_alloc(&cfg.geometry.shapes, 2, sizeof(Shape)));
    cfg.geometry.count = 2;
    cfg.geometry.shapes[0] = (Shape){.kind = SHAPE_DISC, .center = {0, 0, 0}, .radius = 6e-3};
    cfg.geometry.shapes[1] =
        (Shape){.kind = SHAPE_RECTANGLE, .lo = {10e-3, -3e-3}, .hi = {14e-3, 3e-3}};
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    PdSurface s;
    assert_ok(pd_surface_trace(&pts, &s));
    assert_int_equal(s.loop_count, 2);
    check_loops(&b, &s);
    /* every loop point lacks one of its 4 lattice neighbours; every point
     * lacking one is in a loop */
    uint8_t *on_loop;
    assert_ok(nspd_alloc(&on_loop, (size_t)b.n, 1));
    for (int64_t m = 0; m < s.length; m++) on_loop[s.point[m]] = 1;
    for (int64_t p = 0; p < b.n; p++) {
        int missing = 4;
        for (int64_t q = 0; q < b.n; q++) {
            int di = b.lattice[0][q] - b.lattice[0][p], dj = b.lattice[1][q] - b.lattice[1][p];
            missing -= abs(di) + abs(dj) == 1;
        }
        if (missing > 0) assert_true(on_loop[p]);
    }
    nspd_free(&on_loop);
    pd_surface_free(&s);
    bond_body_destroy(&b);
}

static void test_thin_strip_goes_out_and_back(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 12, 1, 0, 1e-3);
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    PdSurface s;
    assert_ok(pd_surface_trace(&pts, &s));
    assert_int_equal(s.loop_count, 1);
    assert_int_equal(s.length, 2 * 12 - 2);
    pd_surface_free(&s);
    bond_body_destroy(&b);
}

/* A uniform pressure on a closed loop exerts no net force; the force the
 * points receive equals the force integrated over the segments. */
static void test_tractions_balance(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 9, 7, 0, 1e-3);
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    for (int64_t i = 0; i < b.n; i++) b.u[1][i] = 1e-4 * sin(b.x[0][i] * 300.0); /* bent */
    PdSurface s;
    assert_ok(pd_surface_trace(&pts, &s));
    double *tx, *ty, *x, *y;
    assert_ok(nspd_alloc(&tx, (size_t)s.length, sizeof(double)));
    assert_ok(nspd_alloc(&ty, (size_t)s.length, sizeof(double)));
    assert_ok(nspd_alloc(&x, (size_t)s.length, sizeof(double)));
    assert_ok(nspd_alloc(&y, (size_t)s.length, sizeof(double)));
    pd_surface_positions(&pts, &s, x, y, NULL, NULL);
    const double p = 1e5;
    for (int64_t m = 0; m < s.length; m++) { /* -p n, n = outward normal of a CCW loop */
        int64_t next = m + 1 < s.length ? m + 1 : 0;
        double dx = x[next] - x[m], dy = y[next] - y[m], len = hypot(dx, dy);
        tx[m] = -p * dy / len;
        ty[m] = p * dx / len;
    }
    double total[2];
    pd_surface_apply_tractions(&pts, &s, tx, ty, total);
    double scale = p * 32e-3; /* pressure x perimeter */
    assert_true(fabs(total[0]) < 1e-13 * scale && fabs(total[1]) < 1e-13 * scale);
    /* a traction along +x: the points get thickness x sum t |seg| */
    for (int64_t m = 0; m < s.length; m++) {
        tx[m] = 1e3;
        ty[m] = 0;
    }
    memset(b.external[0], 0, (size_t)b.n * sizeof(double));
    pd_surface_apply_tractions(&pts, &s, tx, ty, total);
    double received = 0;
    for (int64_t i = 0; i < b.n; i++) received += b.volume[i] * b.external[0][i];
    assert_close(received, b.cfg.thickness * total[0], 1e-12 * fabs(received));
    nspd_free(&tx);
    nspd_free(&ty);
    nspd_free(&x);
    nspd_free(&y);
    pd_surface_free(&s);
    bond_body_destroy(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rectangle_loop),
        cmocka_unit_test(test_disc_and_two_parts),
        cmocka_unit_test(test_thin_strip_goes_out_and_back),
        cmocka_unit_test(test_tractions_balance),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
