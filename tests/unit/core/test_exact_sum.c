/* core/exact_sum: sums exact before one rounding, so the same bits in any
 * order and any split (what the penalty coupling's dot products need on
 * several processes): cancellation, the tie cases of the rounding, the
 * subnormals, the ends of the range, infinities and NaNs, and random sums
 * in three orders and two splits. */
#include "test_support.h"

#include "core/exact_sum.h"
#include "core/status.h"

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

static double sum_of(const double *x, int n) {
    ExactSum s;
    exact_sum_clear(&s);
    for (int k = 0; k < n; k++) exact_sum_add(&s, x[k]);
    return exact_sum_value(&s);
}

static bool same_bits(double a, double b) {
    return memcmp(&a, &b, sizeof a) == 0;
}

static void test_exact_before_rounding(void **state) {
    (void)state;
    /* what a floating sum loses, kept */
    assert_true(sum_of((const double[]){1e100, 1.0, -1e100}, 3) == 1.0);
    assert_true(sum_of((const double[]){1.0, 1e-300, -1.0}, 3) == 1e-300);
    double tenth[10];
    for (int k = 0; k < 10; k++) tenth[k] = 0.1;
    /* the ten doubles 0.1 add to 1 + 5.55e-17, which rounds to 1 (a
     * floating sum in order gives 0.9999999999999999) */
    assert_true(sum_of(tenth, 10) == 1.0);
    /* cancellation to zero; negative sums */
    assert_true(same_bits(sum_of((const double[]){3.5, -3.5}, 2), 0.0));
    assert_true(sum_of((const double[]){-2.0, -0.25}, 2) == -2.25);
    ExactSum empty;
    exact_sum_clear(&empty);
    assert_true(same_bits(exact_sum_value(&empty), 0.0));
}

static void test_rounding(void **state) {
    (void)state;
    const double big = 9007199254740992.0; /* 2^53: the spacing of doubles is 2 there */
    /* a tie rounds to even; anything past it (the sticky bits) rounds up */
    assert_true(sum_of((const double[]){big, 1.0}, 2) == big);
    assert_true(sum_of((const double[]){big, 1.0, ldexp(1.0, -60)}, 3) == big + 2.0);
    assert_true(sum_of((const double[]){big, 3.0}, 2) == big + 4.0);
    assert_true(sum_of((const double[]){big, 1.0, -ldexp(1.0, -60)}, 3) == big);
    /* the same with the sign turned */
    assert_true(sum_of((const double[]){-big, -1.0, -ldexp(1.0, -60)}, 3) == -big - 2.0);
}

static void test_range_and_specials(void **state) {
    (void)state;
    const double tiny = ldexp(1.0, -1074); /* the smallest subnormal */
    assert_true(sum_of((const double[]){tiny, tiny}, 2) == ldexp(1.0, -1073));
    assert_true(sum_of((const double[]){DBL_MAX, -DBL_MAX, tiny}, 3) == tiny);
    assert_true(sum_of((const double[]){DBL_MAX, DBL_MAX}, 2) == (double)INFINITY);
    assert_true(sum_of((const double[]){-DBL_MAX, -DBL_MAX}, 2) == -(double)INFINITY);
    assert_true(sum_of((const double[]){DBL_MAX, -tiny}, 2) == DBL_MAX);
    assert_true(sum_of((const double[]){1.0, (double)INFINITY}, 2) == (double)INFINITY);
    assert_true(sum_of((const double[]){-(double)INFINITY, 1.0}, 2) == -(double)INFINITY);
    assert_true(isnan(sum_of((const double[]){(double)INFINITY, -(double)INFINITY}, 2)));
    assert_true(isnan(sum_of((const double[]){1.0, (double)NAN, 2.0}, 3)));
}

static double lcg(uint64_t *state) {
    *state = *state * 6364136223846793005u + 1442695040888963407u;
    return (double)(*state >> 11) / 9007199254740992.0;
}

/* 20,000 terms of either sign over 600 binary orders of magnitude: the
 * same bits forwards, backwards, shuffled and in two and three parts
 * merged in either order; against a sum in long double (64-bit
 * significand) of terms within 2^40 of each other, to its accuracy. */
static void test_any_order(void **state) {
    (void)state;
    enum { N = 20000 };
    static double x[N];
    uint64_t seed = 12345;
    for (int k = 0; k < N; k++) {
        const double m = lcg(&seed) - 0.5;
        x[k] = ldexp(m, (int)(lcg(&seed) * 600) - 300);
    }
    const double forward = sum_of(x, N);
    ExactSum s;
    exact_sum_clear(&s);
    for (int k = N - 1; k >= 0; k--) exact_sum_add(&s, x[k]);
    assert_true(same_bits(exact_sum_value(&s), forward));
    exact_sum_clear(&s);
    for (int k = 0; k < N; k++) exact_sum_add(&s, x[(int64_t)k * 7919 % N]); /* 7919 prime */
    assert_true(same_bits(exact_sum_value(&s), forward));
    ExactSum part[3];
    for (int q = 0; q < 3; q++) exact_sum_clear(&part[q]);
    for (int k = 0; k < N; k++) exact_sum_add(&part[k % 3], x[k]);
    ExactSum joined = part[2];
    exact_sum_merge(&joined, &part[0]);
    exact_sum_merge(&joined, &part[1]);
    assert_true(same_bits(exact_sum_value(&joined), forward));
    /* the reduction over a group of one leaves the sum as it was */
    assert_int_equal(exact_sum_reduce(NULL, &joined, 1), NSPD_OK);
    assert_true(same_bits(exact_sum_value(&joined), forward));

    long double ref = 0.0L;
    exact_sum_clear(&s);
    for (int k = 0; k < N; k++) {
        const double y = ldexp(lcg(&seed) - 0.5, (int)(lcg(&seed) * 40));
        exact_sum_add(&s, y);
        ref += y;
    }
    const double got = exact_sum_value(&s);
    /* long double's error: N terms of up to 2^39 at 2^-64 each */
    assert_true(fabsl((long double)got - ref) <=
                0.5L * (nextafter(fabs(got), (double)INFINITY) - fabs(got)) +
                    N * ldexpl(1.0L, 39 - 64));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_before_rounding),
        cmocka_unit_test(test_rounding),
        cmocka_unit_test(test_range_and_specials),
        cmocka_unit_test(test_any_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
