/* io/figure: tick values and the labels' units. */
#include "test_support.h"

#include "io/figure.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void expect_ticks(double lo, double hi, int max_ticks, int n, double first, double step) {
    double t[FIGURE_MAX_TICKS], s;
    assert_int_equal(figure_ticks(lo, hi, max_ticks, t, &s), n);
    assert_true(fabs(s - step) <= 1e-12 * step);
    for (int k = 0; k < n; k++) assert_true(fabs(t[k] - (first + k * step)) <= 1e-9 * step);
}

static void test_ticks(void **state) {
    (void)state;
    expect_ticks(0.0, 1.0, 8, 6, 0.0, 0.2);                  /* 0, 0.2, ..., 1: 0.1 gives 11 */
    expect_ticks(0.0, 1.37e5, 8, 7, 0.0, 2e4);               /* 0, 2e4, ..., 1.2e5: 1e4 gives 14 */
    expect_ticks(-1.0, 1.0, 8, 5, -1.0, 0.5);                /* 0.2 gives 11 */
    expect_ticks(0.0, 2.57, 8, 6, 0.0, 0.5);                 /* a Mach scale: 2.5 is the last */
    expect_ticks(-25.3, 25.3, 8, 5, -20.0, 10.0);            /* the plate in mm */
    expect_ticks(0.0, 1.0, 3, 3, 0.0, 0.5);                  /* fewer ticks asked: larger steps */
    expect_ticks(1.0e-3, 1.0e-3 + 6e-9, 8, 7, 1.0e-3, 1e-9); /* a narrow range off zero */
    double t[FIGURE_MAX_TICKS], s;
    assert_int_equal(figure_ticks(2.0, 2.0, 8, t, &s), 1); /* no range: the value alone */
    assert_true(t[0] == 2.0 && s == 0.0);
    assert_int_equal(figure_ticks(0.0, NAN, 8, t, &s), 1);
}

static void test_labels(void **state) {
    (void)state;
    char b[64];
    figure_format_tick(3 * 0.2, 0.2, b, sizeof b); /* 0.6000000000000001 */
    assert_string_equal(b, "0.6");
    figure_format_tick(-1e-17, 0.2, b, sizeof b); /* round-off of 0: not "-0.0" */
    assert_string_equal(b, "0.0");
    figure_format_tick(1.2e5, 2e4, b, sizeof b);
    assert_string_equal(b, "120000");
    figure_format_tick(0.05, 0.05, b, sizeof b);
    assert_string_equal(b, "0.05");
    figure_format_tick(1.5e6, 5e5, b, sizeof b);
    assert_string_equal(b, "1.5e+06");
    figure_format_time(16.7e-6, b, sizeof b);
    assert_string_equal(b, "16.7 \xc2\xb5s");
    figure_format_time(0.0, b, sizeof b);
    assert_string_equal(b, "0 s");
    figure_format_time(0.02, b, sizeof b);
    assert_string_equal(b, "20 ms");
    const char *unit;
    double per_m;
    figure_length_unit(0.0506, &unit, &per_m); /* the plate: 50.6 mm */
    assert_string_equal(unit, "mm");
    assert_true(per_m == 1e3);
    figure_length_unit(12.0, &unit, &per_m); /* the cylinder's flow domain */
    assert_string_equal(unit, "m");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ticks),
        cmocka_unit_test(test_labels),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
