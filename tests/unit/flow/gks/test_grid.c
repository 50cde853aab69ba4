/* Stretched grid: segments fill their lengths exactly, ghost geometry. */
#include "test_support.h"

#include "core/status.h"
#include "core/search.h"
#include "flow/gks/grid.h"

#include <math.h>

static void test_uniform_and_stretched_segments(void **state) {
    (void)state;
    const GridSegment seg[3] = {
        {.length = 1.0, .h_start = 0.1},               /* uniform: 10 cells */
        {.length = 2.0, .h_start = 0.1, .h_end = 0.4}, /* stretched */
        {.length = 0.5, .h_start = 0.05, .cells = 7},  /* uniform, given count */
    };
    GridAxis a;
    assert_ok(grid_axis_create(&a, -1.0, 3, seg, false));
    assert_close(a.face[0], -1.0, 0.0);
    assert_close(a.face[10], 0.0, 1e-14);
    assert_close(a.hi, 2.5, 1e-13);
    for (int i = 0; i < 10; i++) assert_close(a.width[i], 0.1, 1e-15);
    /* stretched: first spacing exact, constant ratio, last near h_end */
    int n2 = 0;
    while (a.face[10 + n2] < 2.0 - 1e-12) n2++;
    assert_close(a.face[10 + n2], 2.0, 1e-13);
    assert_close(a.width[10], 0.1, 1e-14);
    const double r = a.width[11] / a.width[10];
    for (int i = 11; i < 10 + n2 - 1; i++) assert_close(a.width[i + 1] / a.width[i], r, 1e-12);
    const double last = a.width[10 + n2 - 1];
    assert_true(last > 0.4 / r && last < 0.4 * r);
    for (int i = a.n - 7; i < a.n; i++) assert_close(a.width[i], 0.5 / 7.0, 1e-15);
    /* the smallest spacing without the axis (nspd check of a grid it does
     * not build): the built axis' smallest width, to round-off */
    double w_min = INFINITY;
    for (int i = 0; i < a.n; i++) w_min = fmin(w_min, a.width[i]);
    assert_close(grid_segments_min_spacing(3, seg), w_min, 1e-14);
    const GridSegment shrinking = {.length = 2.0, .h_start = 0.4, .h_end = 0.1};
    GridAxis b;
    assert_ok(grid_axis_create(&b, 0.0, 1, &shrinking, false));
    assert_close(grid_segments_min_spacing(1, &shrinking), b.width[b.n - 1], 1e-14);
    assert_true(b.width[b.n - 1] < b.width[0]);
    grid_axis_destroy(&b);
    /* mirrored ghost widths and centre distances */
    assert_close(a.width[-1], a.width[0], 0.0);
    assert_close(a.width[-2], a.width[1], 0.0);
    assert_close(a.width[a.n], a.width[a.n - 1], 0.0);
    for (int i = -1; i < a.n + 1; i++) {
        assert_close(1.0 / a.inv_dl[i], a.center[i] - a.center[i - 1], 1e-14);
        assert_close(1.0 / a.inv_dr[i], a.center[i + 1] - a.center[i], 1e-14);
    }
    grid_axis_destroy(&a);
}

static void test_periodic_ghosts_and_index(void **state) {
    (void)state;
    const GridSegment seg[2] = {{.length = 1.0, .h_start = 0.05, .h_end = 0.2},
                                {.length = 1.0, .h_start = 0.2, .h_end = 0.05}};
    Grid g;
    assert_ok(grid_create(&g, 0.0, 2, seg, true, 0.0, 1, seg, false));
    const GridAxis *x = &g.ax[0];
    assert_close(x->width[-1], x->width[x->n - 1], 0.0);
    assert_close(x->width[x->n], x->width[0], 0.0);
    assert_true(g.stride % 8 == 0 && g.stride >= g.nx + 2 * GRID_NG);
    assert_true(grid_index(&g, -GRID_NG, -GRID_NG) == 0);
    assert_true(grid_index(&g, 1, 0) == grid_index(&g, 0, 0) + 1);
    assert_true(grid_index(&g, 0, 1) == grid_index(&g, 0, 0) + g.stride);
    assert_true(grid_index(&g, g.nx + GRID_NG - 1, g.ny + GRID_NG - 1) < g.size);
    grid_destroy(&g);
}

static void test_bad_segments(void **state) {
    (void)state;
    GridAxis a;
    const GridSegment zero = {.length = 0.0, .h_start = 0.1};
    assert_int_equal(grid_axis_create(&a, 0.0, 1, &zero, false), NSPD_ERR_INPUT);
    const GridSegment big = {.length = 1.0, .h_start = 2.0, .h_end = 0.1};
    assert_int_equal(grid_axis_create(&a, 0.0, 1, &big, false), NSPD_ERR_INPUT);
}

/* The axis searches against a linear scan, on a stretched axis, at faces,
 * centres, between them, outside the axis and for NaN. */
static int scan_last_le(const double *v, int lo, int hi, double x) {
    int found = lo;
    for (int i = lo + 1; i < hi; i++)
        if (v[i] <= x) found = i;
    return found;
}

static void test_axis_searches(void **state) {
    (void)state;
    const GridSegment seg[2] = {
        {.length = 1.0, .h_start = 0.3, .h_end = 0.05},
        {.length = 0.7, .h_start = 0.1, .cells = 7},
    };
    GridAxis a;
    assert_ok(grid_axis_create(&a, -0.4, 2, seg, false));
    const int n = a.n;
    for (int i = 0; i < n; i++) {
        assert_int_equal(grid_axis_cell_of(&a, a.face[i]), i);
        assert_int_equal(grid_axis_cell_of(&a, a.center[i]), i);
        assert_int_equal(grid_axis_cell_of(&a, nextafter(a.face[i + 1], -(double)INFINITY)), i);
        assert_int_equal(grid_axis_bracket(&a, a.center[i]), i);
        assert_int_equal(grid_axis_bracket(&a, nextafter(a.center[i], -(double)INFINITY)), i - 1);
        assert_int_equal(grid_axis_bracket(&a, a.face[i + 1]), i);
    }
    /* clamped outside; NaN gives the low end */
    assert_int_equal(grid_axis_cell_of(&a, a.lo - 1.0), 0);
    assert_int_equal(grid_axis_cell_of(&a, a.face[n]), n - 1);
    assert_int_equal(grid_axis_cell_of(&a, (double)INFINITY), n - 1);
    assert_int_equal(grid_axis_cell_of(&a, (double)NAN), 0);
    assert_int_equal(grid_axis_bracket(&a, -(double)INFINITY), -1);
    assert_int_equal(grid_axis_bracket(&a, a.hi + 1.0), n - 1);
    assert_int_equal(grid_axis_bracket(&a, (double)NAN), -1);
    /* the bare-array search against a linear scan, ghost range included */
    for (int k = 0; k <= 400; k++) {
        const double x =
            a.face[-GRID_NG] - 0.1 + k * (a.face[n + GRID_NG] - a.face[-GRID_NG] + 0.2) / 400;
        assert_int_equal(search_bracket(a.face, -GRID_NG, n + GRID_NG, x),
                         scan_last_le(a.face, -GRID_NG, n + GRID_NG, x));
        assert_int_equal(grid_axis_cell_of(&a, x), scan_last_le(a.face, 0, n, x));
        assert_int_equal(grid_axis_bracket(&a, x), scan_last_le(a.center, -1, n, x));
    }
    grid_axis_destroy(&a);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform_and_stretched_segments),
        cmocka_unit_test(test_periodic_ghosts_and_index),
        cmocka_unit_test(test_bad_segments),
        cmocka_unit_test(test_axis_searches),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
