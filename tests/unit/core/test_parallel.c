/* core/parallel: a parallel region of one thread runs on the calling
 * thread without a team (GCC's libgomp), computes there what a team of one
 * computes (a static loop, a reduction, orphaned `for`, `single` and
 * `barrier`), and a team of two is still a team of two, whose nested
 * regions keep their own thread numbers. */
#include "test_support.h"

#include "core/parallel.h"

#include <omp.h>
#include <stdint.h>
#include <string.h>

enum { N = 1000 };

/* A region's body as nspd's loops write it: a static loop with a
 * reduction, then orphaned worksharing in the same region. */
static double region_sum(int team, double *x, int *single_runs, int *threads) {
    double sum = 0.0;
    *single_runs = 0;
#pragma omp parallel if (team) reduction(+ : sum)
    {
#pragma omp for schedule(static)
        for (int64_t i = 0; i < N; i++) x[i] = 1.0 / (double)(i + 1);
#pragma omp single
        {
            (*single_runs)++;
            *threads = omp_get_num_threads();
        }
#pragma omp barrier
#pragma omp for schedule(static)
        for (int64_t i = 0; i < N; i++) sum += x[i] * x[N - 1 - i];
    }
    return sum;
}

static void test_one_thread_without_team(void **state) {
    (void)state;
#if defined(__GNUC__) && !defined(__clang__)
    /* GCC's code calls GOMP_parallel, which nspd's core now answers */
    assert_int_equal(parallel_region_skips_team(), 1);
#endif
    int level = -1, number = -1, count = -1;
#pragma omp parallel if (0)
    {
        level = omp_get_level();
        number = omp_get_thread_num();
        count = omp_get_num_threads();
    }
    assert_int_equal(number, 0);
    assert_int_equal(count, 1);
    assert_int_equal(level, parallel_region_skips_team() ? 0 : 1);
}

static void test_same_result(void **state) {
    (void)state;
    double x[N], y[N];
    int single_runs = 0, threads = 0;
    /* what the body computes on one thread, in order, as the reference */
    double ref = 0.0;
    for (int64_t i = 0; i < N; i++) y[i] = 1.0 / (double)(i + 1);
    for (int64_t i = 0; i < N; i++) ref += y[i] * y[N - 1 - i];

    const double alone = region_sum(0, x, &single_runs, &threads);
    assert_memory_equal(&alone, &ref, sizeof ref);
    assert_memory_equal(x, y, sizeof x);
    assert_int_equal(single_runs, 1);
    assert_int_equal(threads, 1);

    /* --threads 1: a region with no `if` is skipped too */
    const int max = omp_get_max_threads();
    omp_set_num_threads(1);
    memset(x, 0, sizeof x);
    const double one = region_sum(1, x, &single_runs, &threads);
    omp_set_num_threads(max);
    assert_memory_equal(&one, &ref, sizeof ref);
    assert_memory_equal(x, y, sizeof x);
    assert_int_equal(single_runs, 1);
    assert_int_equal(threads, 1);
}

static void test_team_of_two(void **state) {
    (void)state;
    const int max = omp_get_max_threads();
    omp_set_num_threads(2);
    int threads = 0, inner[2] = {-1, -1}, outer[2] = {-1, -1};
#pragma omp parallel
    {
        const int t = omp_get_thread_num();
        outer[t] = t;
#pragma omp single
        threads = omp_get_num_threads();
        /* a nested region of one inside an active team: its thread number
         * is 0 on both threads, not the outer team's (so it is not skipped) */
#pragma omp parallel num_threads(1)
        inner[t] = omp_get_thread_num();
    }
    omp_set_num_threads(max);
    assert_int_equal(threads, 2);
    assert_int_equal(outer[0], 0);
    assert_int_equal(outer[1], 1);
    assert_int_equal(inner[0], 0);
    assert_int_equal(inner[1], 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_one_thread_without_team),
        cmocka_unit_test(test_same_result),
        cmocka_unit_test(test_team_of_two),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
