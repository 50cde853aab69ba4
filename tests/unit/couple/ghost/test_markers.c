/* couple/ghost/markers: marker generation (circle, NACA 4-digit with a closed
 * trailing edge, rectangle, polygon) and polyline checks. */
#include "test_support.h"

#include "core/status.h"
#include "couple/ghost/markers.h"

#include <math.h>
#include <string.h>

static void test_naca_thickness(void **state) {
    (void)state;
    /* closed trailing edge: the coefficients sum to zero with a4 = -0.1036 */
    assert_close(0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1036, 0.0, 1e-15);
    assert_true(naca4_half_thickness(1.0, 0.12) == 0.0);
    assert_true(naca4_half_thickness(0.0, 0.12) == 0.0);
    /* the formula, and the 12 % section's maximum half-thickness 0.06 at x ~ 0.3 */
    const double x = 0.3, t = 0.12;
    const double ref = 5 * t *
                       (0.2969 * sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                        0.1036 * x * x * x * x);
    assert_close(naca4_half_thickness(x, t), ref, 1e-15);
    assert_close(naca4_half_thickness(x, t), 0.0600071, 1e-7);
    double best = 0.0, xb = 0.0;
    for (int k = 1; k < 1000; k++) {
        const double y = naca4_half_thickness(k / 1000.0, t);
        if (y > best) best = y, xb = k / 1000.0;
    }
    assert_close(best, 0.0600, 2e-4);
    assert_close(xb, 0.30, 0.01);
    /* near the leading edge y_t ~ 5 t 0.2969 sqrt(x): nose radius 1.1019 t^2 */
    const double xs = 1e-8, r = 0.5 * pow(naca4_half_thickness(xs, t), 2) / xs;
    assert_close(r, 1.1019 * t * t, 2e-4);
}

static void test_naca_markers(void **state) {
    (void)state;
    IbmBodyConfig b = {.kind = IBM_BODY_NACA, .digits = "0012", .chord = 2.0, .markers = 512};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&b, &p));
    assert_int_equal(p.n, 512);
    assert_int_equal(p.trailing_edge, 0);
    assert_int_equal(p.leading_edge, 256);
    assert_true(p.x[0] == 2.0 && p.y[0] == 0.0);     /* closed trailing edge */
    assert_true(p.x[256] == 0.0 && p.y[256] == 0.0); /* leading edge at the origin */
    /* mirror pairs: marker k and n - k, bitwise */
    for (int k = 1; k < 256; k++) {
        assert_true(p.x[k] == p.x[512 - k]);
        assert_true(p.y[k] == -p.y[512 - k]);
        assert_true(p.y[k] > 0.0); /* upper surface first: counter-clockwise */
    }
    /* area of the closed-TE section: chord^2 * 10 t (0.2969 2/3 - 0.126/2 - 0.3516/3 +
     * 0.2843/4 - 0.1036/5) = 0.0817 c^2 */
    const double area =
        4.0 * 10 * 0.12 * (0.2969 * 2 / 3 - 0.1260 / 2 - 0.3516 / 3 + 0.2843 / 4 - 0.1036 / 5);
    assert_close(ibm_polyline_area(&p), area, 2e-4 * area);
    assert_true(ibm_polyline_area(&p) > 0.0);
    ibm_polyline_free(&p);

    /* angle of attack: turned clockwise about the leading edge (nose up) */
    b = (IbmBodyConfig){.kind = IBM_BODY_NACA,
                        .digits = "0012",
                        .chord = 1.0,
                        .leading_edge = {1.0, 2.0},
                        .angle_deg = 10.0,
                        .markers = 64};
    assert_ok(ibm_body_markers(&b, &p));
    assert_close(p.x[0], 1.0 + cos(10 * M_PI / 180), 1e-14);
    assert_close(p.y[0], 2.0 - sin(10 * M_PI / 180), 1e-14);
    assert_true(p.x[32] == 1.0 && p.y[32] == 2.0);
    ibm_polyline_free(&p);

    /* cambered: 2412 has its mean line 0.02 c high at x = 0.4 c */
    b = (IbmBodyConfig){.kind = IBM_BODY_NACA, .digits = "2412", .chord = 1.0, .markers = 2000};
    assert_ok(ibm_body_markers(&b, &p));
    double best = 1e9, mid = 0.0;
    for (int k = 1; k < 1000; k++) {
        const double xm = 0.5 * (p.x[k] + p.x[2000 - k]);
        if (fabs(xm - 0.4) < best) best = fabs(xm - 0.4), mid = 0.5 * (p.y[k] + p.y[2000 - k]);
    }
    assert_close(mid, 0.02, 2e-4);
    assert_true(ibm_polyline_area(&p) > 0.0);
    ibm_polyline_free(&p);
}

static void test_circle_rectangle_polygon(void **state) {
    (void)state;
    IbmBodyConfig b = {.kind = IBM_BODY_CIRCLE, .center = {2.0, 6.0}, .radius = 0.5, .markers = 96};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&b, &p));
    assert_int_equal(p.n, 96);
    assert_true(p.x[0] == 1.5 && p.y[0] == 6.0); /* most upstream first */
    for (int k = 0; k < 96; k++) {
        assert_close(hypot(p.x[k] - 2.0, p.y[k] - 6.0), 0.5, 1e-15);
        if (k > 0) {
            assert_true(p.x[k] == p.x[96 - k]); /* mirror pairs about y = 6 (one sine each) */
            assert_close(p.y[k] - 6.0, 6.0 - p.y[96 - k], 1e-15);
        }
    }
    assert_close(ibm_polyline_area(&p), 0.5 * 96 * 0.25 * sin(2 * M_PI / 96), 1e-14);
    ibm_polyline_free(&p);

    b = (IbmBodyConfig){
        .kind = IBM_BODY_RECTANGLE, .min = {0, 0}, .max = {2, 1}, .markers_per_side = 4};
    assert_ok(ibm_body_markers(&b, &p));
    assert_int_equal(p.n, 16);
    assert_close(ibm_polyline_area(&p), 2.0, 1e-15);
    assert_true(p.x[4] == 2.0 && p.y[4] == 0.0);
    ibm_polyline_free(&p);

    /* a clockwise triangle is reversed, long edges split */
    double v[6] = {0, 0, 0, 1, 1, 0};
    b = (IbmBodyConfig){
        .kind = IBM_BODY_POLYGON, .vertex_count = 3, .vertices = v, .max_spacing = 0.3};
    assert_ok(ibm_body_markers(&b, &p));
    assert_close(ibm_polyline_area(&p), 0.5, 1e-15);
    assert_int_equal(p.n, 4 + 4 + 5); /* ceil(1/0.3) = 4, 4, ceil(sqrt 2/0.3) = 5 */
    for (int k = 0; k < p.n; k++) {
        const int q = (k + 1) % p.n;
        assert_true(hypot(p.x[q] - p.x[k], p.y[q] - p.y[k]) <= 0.3 + 1e-15);
    }
    ibm_polyline_free(&p);
}

static void test_invalid(void **state) {
    (void)state;
    IbmPolyline p;
    IbmBodyConfig b = {.kind = IBM_BODY_CIRCLE, .radius = -1, .markers = 16};
    assert_int_equal(ibm_body_markers(&b, &p), NSPD_ERR_INPUT);
    b = (IbmBodyConfig){.kind = IBM_BODY_NACA, .digits = "12", .chord = 1, .markers = 16};
    assert_int_equal(ibm_body_markers(&b, &p), NSPD_ERR_INPUT);
    b = (IbmBodyConfig){.kind = IBM_BODY_NACA, .digits = "0012", .chord = 1, .markers = 15};
    assert_int_equal(ibm_body_markers(&b, &p), NSPD_ERR_INPUT);
    b = (IbmBodyConfig){
        .kind = IBM_BODY_CIRCLE, .radius = 1, .markers = 16, .thermal = IBM_WALL_ISOTHERMAL};
    assert_int_equal(ibm_body_markers(&b, &p), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "temperature"));
    /* clockwise or degenerate polylines are refused */
    double x[4] = {0, 0, 1, 1}, y[4] = {0, 1, 1, 0};
    IbmPolyline cw = {.n = 4, .x = x, .y = y};
    assert_int_equal(ibm_polyline_check(&cw, 3), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "counter-clockwise"));
    double x2[4] = {0, 1, 1, 1}, y2[4] = {0, 0, 1, 1};
    IbmPolyline dup = {.n = 4, .x = x2, .y = y2};
    assert_int_equal(ibm_polyline_check(&dup, 0), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "coincide"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_naca_thickness),
        cmocka_unit_test(test_naca_markers),
        cmocka_unit_test(test_circle_rectangle_polygon),
        cmocka_unit_test(test_invalid),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
