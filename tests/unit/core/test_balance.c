/* core/balance: the threads' ranges tile the items, equal shares until a
 * team has run, and the shares follow the measured rates: a thread twice
 * as fast ends with twice the items, half-way each run. */
#include "test_support.h"

#include "core/balance.h"

#include <stdint.h>

/* The ranges of a team of `threads` tile [0, n) in order. */
static void assert_tiles(const Balance *b, int threads, int64_t n) {
    int64_t next = 0;
    for (int t = 0; t < threads; t++) {
        int64_t lo, hi;
        balance_range(b, t, threads, n, &lo, &hi);
        assert_int_equal(lo, next);
        assert_true(hi >= lo);
        next = hi;
    }
    assert_int_equal(next, n);
}

/* One run of a team of `threads` whose thread t does an item in
 * cost[t] seconds; returns the share (fraction of n) thread 0 took. */
static double run(Balance *b, int threads, int64_t n, const double *cost) {
    int64_t lo0 = 0, hi0 = 0;
    for (int t = 0; t < threads; t++) {
        int64_t lo, hi;
        balance_range(b, t, threads, n, &lo, &hi);
        if (t == 0) lo0 = lo, hi0 = hi;
        balance_record(b, t, threads, (double)(hi - lo) * cost[t]);
    }
    balance_update(b);
    return (double)(hi0 - lo0) / (double)n;
}

static void test_equal_until_measured(void **state) {
    (void)state;
    Balance b = {0};
    int64_t lo, hi;
    balance_range(&b, 1, 3, 10, &lo, &hi); /* 10 t / 3 */
    assert_int_equal(lo, 3);
    assert_int_equal(hi, 6);
    balance_range(NULL, 1, 2, 7, &lo, &hi);
    assert_int_equal(lo, 3);
    assert_int_equal(hi, 7);
    for (int threads = 1; threads <= 5; threads++)
        for (int64_t n = 0; n < 12; n++) assert_tiles(&b, threads, n);
    /* a team of one is not balanced, and records nothing to move */
    balance_record(&b, 0, 1, 1.0);
    balance_update(&b);
    assert_int_equal(b.threads, 0);
}

static void test_follows_the_rates(void **state) {
    (void)state;
    Balance b = {0};
    const double cost[2] = {1.0, 2.0}; /* thread 1 half as fast */
    const int64_t n = 100000;
    /* the first run had equal shares; the update goes half-way to 2/3 */
    assert_close(run(&b, 2, n, cost), 0.5, 0.0);
    assert_close(b.cut[1], 0.5 * (0.5 + 2.0 / 3.0), 1e-12);
    double share = 0.0;
    for (int k = 0; k < 30; k++) {
        share = run(&b, 2, n, cost);
        assert_tiles(&b, 2, n);
        assert_tiles(&b, 2, 3); /* fewer items than a share's rounding */
    }
    assert_close(share, 2.0 / 3.0, 1e-4);

    /* the rates change: the shares follow */
    const double swapped[2] = {3.0, 1.0};
    for (int k = 0; k < 30; k++) share = run(&b, 2, n, swapped);
    assert_close(share, 0.25, 1e-4);

    /* an unmeasured thread (no time) leaves the cuts as they are */
    const double cut = b.cut[1];
    balance_record(&b, 0, 2, 1.0);
    balance_record(&b, 1, 2, 0.0);
    balance_update(&b);
    assert_close(b.cut[1], cut, 0.0);
}

static void test_every_thread_keeps_a_share(void **state) {
    (void)state;
    Balance b = {0};
    const double cost[4] = {1.0, 1.0, 1e6, 1.0}; /* thread 2 all but stopped */
    for (int k = 0; k < 40; k++) run(&b, 4, 1000000, cost);
    int64_t lo, hi;
    balance_range(&b, 2, 4, 1000000, &lo, &hi);
    /* about an eighth of an equal share (the others' renormalised in): it
     * stays measured */
    assert_true(hi - lo >= 1000000 / 40);
    assert_tiles(&b, 4, 1000000);
    /* another team size: equal shares again, then its own cuts */
    balance_range(&b, 1, 3, 9, &lo, &hi);
    assert_int_equal(lo, 3);
    assert_int_equal(hi, 6);
    const double three[3] = {1.0, 1.0, 2.0};
    run(&b, 3, 900, three);
    assert_int_equal(b.threads, 3);
    assert_tiles(&b, 3, 900);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_equal_until_measured),
        cmocka_unit_test(test_follows_the_rates),
        cmocka_unit_test(test_every_thread_keeps_a_share),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
