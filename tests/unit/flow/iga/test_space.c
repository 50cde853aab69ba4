/* flow/iga/space: the B-spline identities of ../shared/notes/iga_flow.md T1
 * (partition of unity, integrals, Gauss exactness, interpolation at the
 * ends), for degrees 1-3, open and periodic. */
#include "test_support.h"

#include "core/status.h"
#include "flow/iga/space.h"

#include <math.h>

static void test_partition_of_unity(void **state) {
    (void)state;
    for (int p = 1; p <= 3; p++)
        for (int per = 0; per <= 1; per++) {
            IgaAxis a;
            assert_ok(iga_axis_create(&a, p, 7, -0.3, 1.1, per));
            assert_int_equal(a.count, per ? 7 : 7 + p);
            for (int k = 0; k <= 70; k++) {
                const double x = -0.3 + 1.4 * k / 70.0;
                const int e = iga_axis_element(&a, x);
                double v[IGA_MAX_LOCAL], d[IGA_MAX_LOCAL], sum = 0, dsum = 0;
                iga_axis_eval(&a, e, x, v, d);
                for (int l = 0; l <= p; l++) {
                    assert_true(v[l] >= -1e-15);
                    sum += v[l], dsum += d[l];
                }
                assert_close(sum, 1.0, 1e-14);
                assert_close(dsum, 0.0, 1e-12 / a.h);
            }
            /* the tabulated Gauss values: the same identities, and the
             * Gauss rule integrates x^(2p+1) exactly over the interval */
            double moment = 0.0;
            for (int e = 0; e < a.elements; e++)
                for (int q = 0; q < a.gauss; q++) {
                    double sum = 0;
                    for (int l = 0; l <= p; l++) sum += a.value[(e * a.gauss + q) * (p + 1) + l];
                    assert_close(sum, 1.0, 1e-14);
                    moment += a.weight[q] * pow(a.point[e * a.gauss + q], 2 * p + 1);
                }
            const int m = 2 * p + 2;
            assert_close(moment, (pow(1.1, m) - pow(-0.3, m)) / m, 1e-13);
            iga_axis_destroy(&a);
        }
}

/* int N_A = h/3, 2h/3, h, ..., h, 2h/3, h/3 for open quadratics (notes
 * 2.1), checked against the Gauss sums; the end functions interpolate. */
static void test_integrals_and_ends(void **state) {
    (void)state;
    for (int p = 1; p <= 3; p++) {
        IgaAxis a;
        assert_ok(iga_axis_create(&a, p, 6, 0.0, 3.0, false));
        double sums[16] = {0};
        for (int e = 0; e < a.elements; e++)
            for (int q = 0; q < a.gauss; q++)
                for (int l = 0; l <= p; l++)
                    sums[iga_axis_index(&a, e, l)] +=
                        a.weight[q] * a.value[(e * a.gauss + q) * (p + 1) + l];
        for (int k = 0; k < a.count; k++) assert_close(sums[k], iga_axis_integral(&a, k), 1e-14);
        if (p == 2) {
            assert_close(iga_axis_integral(&a, 0), a.h / 3, 1e-15);
            assert_close(iga_axis_integral(&a, 1), 2 * a.h / 3, 1e-15);
            assert_close(iga_axis_integral(&a, 2), a.h, 1e-15);
            assert_close(iga_axis_greville(&a, 1), 0.5 * a.h, 1e-15);
        }
        double v[IGA_MAX_LOCAL];
        iga_axis_eval(&a, 0, 0.0, v, NULL);
        assert_close(v[0], 1.0, 1e-15);
        iga_axis_eval(&a, a.elements - 1, 3.0, v, NULL);
        assert_close(v[p], 1.0, 1e-15);
        iga_axis_destroy(&a);
    }
    IgaAxis a;
    assert_int_equal(iga_axis_create(&a, 4, 6, 0.0, 1.0, false), NSPD_ERR_INPUT);
    assert_int_equal(iga_axis_create(&a, 2, 2, 0.0, 1.0, true), NSPD_ERR_INPUT);
    nspd_error_clear();
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_partition_of_unity),
        cmocka_unit_test(test_integrals_and_ends),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
