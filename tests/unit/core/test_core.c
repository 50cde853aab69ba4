/* core/: status propagation, aligned allocation and its accounting and
 * failure injection, deterministic reductions, shapes. */
#include "test_support.h"

#include "core/mem.h"
#include "core/progress.h"
#include "core/reduce.h"
#include "core/shape.h"
#include "core/status.h"

#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

static int inner(int fail) {
    if (fail) return NSPD_FAIL(NSPD_ERR_IO, "disk %s", "full");
    return NSPD_OK;
}

static int outer(int fail, int *reached) {
    TRY(inner(fail));
    *reached = 1;
    return NSPD_OK;
}

static void test_try_propagates(void **state) {
    (void)state;
    int reached = 0;
    assert_int_equal(outer(1, &reached), NSPD_ERR_IO);
    assert_int_equal(reached, 0);
    assert_string_equal(nspd_error_message(), "disk full");
    assert_non_null(strstr(nspd_error_origin(), "test_core.c"));
    assert_int_equal(outer(0, &reached), NSPD_OK);
    assert_int_equal(reached, 1);
}

/* The traceback of a nested failure: the line of each TRY, innermost first. */
static int line_middle, line_top;

static int middle(int fail) {
    line_middle = __LINE__ + 1;
    TRY(inner(fail));
    return NSPD_OK;
}

static int top(int fail) {
    line_top = __LINE__ + 1;
    TRY(middle(fail));
    return NSPD_OK;
}

static int recurse(int depth) {
    if (depth == 0) return NSPD_FAIL(NSPD_ERR_INTERNAL, "bottom");
    TRY(recurse(depth - 1));
    return NSPD_OK;
}

static void test_try_records_traceback(void **state) {
    (void)state;
    assert_int_equal(top(1), NSPD_ERR_IO);
    char expected[128];
    snprintf(expected, sizeof expected, "middle:%d <- top:%d", line_middle, line_top);
    assert_string_equal(nspd_error_traceback(), expected);
    assert_int_equal(nspd_error_trace_depth(), 2);
    assert_string_equal(nspd_error_message(), "disk full"); /* the user's message is untouched */
    assert_non_null(strstr(nspd_error_origin(), "test_core.c"));

    /* a new failure starts a new chain */
    assert_int_equal(inner(1), NSPD_ERR_IO);
    assert_string_equal(nspd_error_traceback(), "");
    assert_int_equal(middle(1), NSPD_ERR_IO);
    snprintf(expected, sizeof expected, "middle:%d", line_middle);
    assert_string_equal(nspd_error_traceback(), expected);

    /* success leaves the record alone; clear empties it */
    assert_int_equal(top(0), NSPD_OK);
    assert_string_equal(nspd_error_traceback(), expected);
    nspd_error_clear();
    assert_string_equal(nspd_error_traceback(), "");
    assert_int_equal(nspd_error_trace_depth(), 0);

    /* bounded: the innermost NSPD_TRACE_FRAMES frames are kept, the rest counted */
    assert_int_equal(recurse(NSPD_TRACE_FRAMES + 4), NSPD_ERR_INTERNAL);
    assert_int_equal(nspd_error_trace_depth(), NSPD_TRACE_FRAMES + 4);
    const char *text = nspd_error_traceback();
    assert_non_null(strstr(text, "recurse:"));
    assert_non_null(strstr(text, " <- (4 more)"));
    int frames = 1;
    for (const char *c = strstr(text, " <- "); c; c = strstr(c + 1, " <- ")) frames++;
    assert_int_equal(frames, NSPD_TRACE_FRAMES + 1); /* + the "(4 more)" entry */
    assert_string_equal(nspd_error_message(), "bottom");
}

/* What the status contract catches: a code returned without NSPD_FAIL, a
 * count that overflowed into a negative number, and a stale message of an
 * earlier, handled failure with another status. */
static int bare_code(void) {
    return -1; /* NSPD_ERR_INPUT's value, written as a bare number */
}

static int overflowed_count(void) {
    return -123456;
}

static int propagate(int (*f)(void), int *line) {
    *line = __LINE__ + 1;
    TRY(f());
    return NSPD_OK;
}

static void test_try_refuses_a_failure_without_its_message(void **state) {
    (void)state;
    int line;
    nspd_error_clear();
    assert_int_equal(propagate(bare_code, &line), NSPD_ERR_INTERNAL);
    char expected[128];
    snprintf(expected, sizeof expected, "without a message (status -1) reached propagate:%d", line);
    assert_non_null(strstr(nspd_error_message(), expected));
    assert_int_equal(nspd_error_status(), NSPD_ERR_INTERNAL);

    assert_int_equal(propagate(overflowed_count, &line), NSPD_ERR_INTERNAL);
    assert_non_null(strstr(nspd_error_message(), "(status -123456)"));

    /* an earlier failure's message does not vouch for a later bare code */
    assert_int_equal(inner(1), NSPD_ERR_IO);
    assert_int_equal(propagate(bare_code, &line), NSPD_ERR_INTERNAL);
    /* the recorded failure passes unchanged, however far */
    assert_int_equal(top(1), NSPD_ERR_IO);
    assert_string_equal(nspd_error_message(), "disk full");
    nspd_error_clear();
    assert_int_equal(nspd_error_status(), NSPD_OK);
}

/* A refusal found where no place is known, said at one; other failures
 * and an empty place leave the message alone. */
static void test_error_at_says_the_place(void **state) {
    (void)state;
    int status = NSPD_FAIL(NSPD_ERR_INPUT, "no lattice point; expected a smaller spacing");
    assert_int_equal(nspd_error_at(status, "case.yaml:3:1: solid"), NSPD_ERR_INPUT);
    assert_string_equal(nspd_error_message(),
                        "case.yaml:3:1: solid: no lattice point; expected a smaller spacing");
    assert_int_equal(nspd_error_at(status, ""), NSPD_ERR_INPUT);
    assert_string_equal(nspd_error_message(),
                        "case.yaml:3:1: solid: no lattice point; expected a smaller spacing");
    status = NSPD_FAIL(NSPD_ERR_IO, "disk full");
    assert_int_equal(nspd_error_at(status, "case.yaml:3:1: solid"), NSPD_ERR_IO);
    assert_string_equal(nspd_error_message(), "disk full");
    /* a message that fills the record is cut, never overrun */
    char long_text[4000];
    memset(long_text, 'a', sizeof long_text - 1);
    long_text[sizeof long_text - 1] = '\0';
    status = NSPD_FAIL(NSPD_ERR_INPUT, "%s", long_text);
    assert_int_equal(nspd_error_at(status, "here"), NSPD_ERR_INPUT);
    assert_int_equal(strncmp(nspd_error_message(), "here: aaa", 9), 0);
    nspd_error_clear();
}

static void test_alloc_aligned_zeroed_counted(void **state) {
    (void)state;
    size_t before = nspd_mem_live_bytes();
    double *a;
    assert_ok(nspd_alloc(&a, 1000, sizeof(double)));
    assert_int_equal((uintptr_t)a % 64, 0);
    for (int i = 0; i < 1000; i++) assert_true(a[i] == 0.0);
    assert_int_equal(nspd_mem_live_bytes() - before, 8000);
    assert_true(nspd_mem_peak_bytes() >= 8000);
    a[999] = 7;
    assert_ok(nspd_realloc(&a, 1000, 2000, sizeof(double)));
    assert_true(a[999] == 7 && a[1999] == 0);
    nspd_free(&a);
    assert_null(a);
    assert_int_equal(nspd_mem_live_bytes(), before);
    double *none;
    assert_ok(nspd_alloc(&none, 0, 8));
    assert_null(none);
    /* a block large enough to ask for huge pages, written all over, freed
     * and taken again: zeroed again (calloc's pages, not a stale block) */
    enum { BIG = 1 << 20 };
    for (int round = 0; round < 2; round++) {
        double *big;
        assert_ok(nspd_alloc(&big, BIG, sizeof(double)));
        assert_int_equal((uintptr_t)big % 64, 0);
        for (int i = 0; i < BIG; i += 4099) assert_true(big[i] == 0.0);
        assert_true(big[BIG - 1] == 0.0);
        for (int i = 0; i < BIG; i++) big[i] = 1.0 + i;
        nspd_free(&big);
    }
    /* odd sizes keep the alignment and the count */
    for (size_t n = 1; n < 200; n += 7) {
        char *c;
        assert_ok(nspd_alloc(&c, n, 1));
        assert_int_equal((uintptr_t)c % 64, 0);
        assert_int_equal(nspd_mem_live_bytes() - before, n);
        memset(c, 0xff, n);
        nspd_free(&c);
    }
}

static void test_alloc_failure_injection_and_overflow(void **state) {
    (void)state;
    double *a = NULL, *b = NULL;
    nspd_mem_fail_after(1);
    assert_ok(nspd_alloc(&a, 10, 8));
    assert_int_equal(nspd_alloc(&b, 10, 8), NSPD_ERR_NOMEM);
    assert_null(b);
    nspd_mem_fail_after(-1);
    nspd_free(&a);
    assert_int_equal(nspd_alloc(&b, SIZE_MAX / 4, 8), NSPD_ERR_NOMEM);
}

static void test_reduce_same_at_any_thread_count(void **state) {
    (void)state;
    enum { N = 100003 };
    double *a;
    assert_ok(nspd_alloc(&a, N, sizeof(double)));
    for (int i = 0; i < N; i++) a[i] = sin(i * 0.37) * pow(10.0, (i % 17) - 8);
    omp_set_num_threads(1);
    double s1 = reduce_sum(a, N);
    omp_set_num_threads(2);
    double s2 = reduce_sum(a, N);
    omp_set_num_threads(3);
    double s3 = reduce_sum(a, N);
    assert_memory_equal(&s1, &s2, sizeof s1);
    assert_memory_equal(&s1, &s3, sizeof s1);
    double serial = 0;
    for (int i = 0; i < N; i++) serial += a[i];
    assert_close(s1, serial, 1e-12 * fabs(serial) + 1e-15);
    int64_t lo, hi, covered = 0;
    for (int c = 0; c < REDUCE_CHUNKS; c++) {
        reduce_chunk(N, c, &lo, &hi);
        assert_int_equal(lo, covered);
        covered = hi;
    }
    assert_int_equal(covered, N);
    nspd_free(&a);
}

static void test_shapes_and_csg(void **state) {
    (void)state;
    Shape rect = {.kind = SHAPE_RECTANGLE, .lo = {0, 0, 0}, .hi = {2, 1, 0}};
    Shape hole = {.kind = SHAPE_DISC, .center = {1, 0.5, 0}, .radius = 0.25, .subtract = true};
    Shape shapes[2] = {rect, hole};
    ShapeSet set = {2, shapes};
    assert_true(shapeset_contains(&set, (double[3]){0.1, 0.1, 0}));
    assert_false(shapeset_contains(&set, (double[3]){1.0, 0.5, 0}));
    assert_true(shapeset_contains(&set, (double[3]){2.0, 1.0, 0})); /* closed boundary */
    assert_false(shapeset_contains(&set, (double[3]){2.01, 0.5, 0}));
    double lo[3], hi[3];
    assert_true(shapeset_bounds(&set, 2, lo, hi));
    assert_true(lo[0] == 0 && hi[0] == 2 && lo[1] == 0 && hi[1] == 1);

    Shape ring = {.kind = SHAPE_ANNULUS, .center = {0, 0, 0}, .inner_radius = 1, .radius = 2};
    assert_true(shape_contains(&ring, (double[3]){1.5, 0, 0}));
    assert_false(shape_contains(&ring, (double[3]){0.5, 0, 0}));

    double tri[6] = {0, 0, 4, 0, 0, 3};
    Shape poly = {.kind = SHAPE_POLYGON, .vertex_count = 3, .vertices = tri};
    assert_true(shape_contains(&poly, (double[3]){1, 1, 0}));
    assert_false(shape_contains(&poly, (double[3]){3, 2, 0}));
    assert_true(shape_contains(&poly, (double[3]){2, 1.5, 0})); /* on the hypotenuse */
    assert_close(polygon_signed_area(tri, 3), 6.0, 1e-15);

    Shape cyl = {.kind = SHAPE_CYLINDER, .center = {0, 0, 1}, .radius = 1, .length = 2};
    assert_true(shape_contains(&cyl, (double[3]){0.5, 0.5, 1.9}));
    assert_false(shape_contains(&cyl, (double[3]){0.5, 0.5, 2.1}));
    Shape ball = {.kind = SHAPE_SPHERE, .center = {0, 0, 0}, .radius = 1};
    assert_false(shape_contains(&ball, (double[3]){0.6, 0.6, 0.6}));
}

static void test_duration_format(void **state) {
    (void)state;
    char buf[32];
    progress_format_duration(12.34, buf, sizeof buf);
    assert_string_equal(buf, "12.3s");
    progress_format_duration(185, buf, sizeof buf);
    assert_string_equal(buf, "3m05s");
    progress_format_duration(3725, buf, sizeof buf);
    assert_string_equal(buf, "1h02m");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_try_propagates),
        cmocka_unit_test(test_try_records_traceback),
        cmocka_unit_test(test_try_refuses_a_failure_without_its_message),
        cmocka_unit_test(test_error_at_says_the_place),
        cmocka_unit_test(test_alloc_aligned_zeroed_counted),
        cmocka_unit_test(test_alloc_failure_injection_and_overflow),
        cmocka_unit_test(test_reduce_same_at_any_thread_count),
        cmocka_unit_test(test_shapes_and_csg),
        cmocka_unit_test(test_duration_format),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
