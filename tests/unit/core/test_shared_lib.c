/* core/shared_lib: a library opened on first use. Its functions found and
 * callable; opened once; a missing library or function refused with a
 * message naming it and what needed it, on every later call too. */
#include "test_support.h"

#include "core/shared_lib.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

static const char *const libm_names[] = {"cos", "hypot"};

static void test_functions_found(void **state) {
    (void)state;
    void *slots[2] = {NULL, NULL};
    SharedLib lib = {.soname = "libm.so.6",
                     .purpose = "the test",
                     .names = libm_names,
                     .count = 2,
                     .slots = slots};
    assert_int_equal(shared_lib_load(&lib), NSPD_OK);
    double (*cos_of)(double) = (double (*)(double))slots[0];
    double (*hypot_of)(double, double) = (double (*)(double, double))slots[1];
    assert_true(cos_of(0.5) == cos(0.5));
    assert_true(hypot_of(3.0, 4.0) == 5.0);
    /* opened once: a second call keeps the slots */
    slots[0] = NULL;
    assert_int_equal(shared_lib_load(&lib), NSPD_OK);
    assert_null(slots[0]);
}

static void test_missing_library(void **state) {
    (void)state;
    void *slots[2] = {NULL, NULL};
    SharedLib lib = {.soname = "libnspd-no-such.so.7",
                     .purpose = "pictures",
                     .names = libm_names,
                     .count = 2,
                     .slots = slots};
    for (int call = 0; call < 2; call++) {
        nspd_error_clear();
        assert_int_equal(shared_lib_load(&lib), NSPD_ERR_IO);
        const char *msg = nspd_error_message();
        assert_non_null(strstr(msg, "libnspd-no-such.so.7, needed for pictures, could not"));
        assert_non_null(strstr(msg, "scripts/deps.sh"));
    }
}

static void test_missing_function(void **state) {
    (void)state;
    static const char *const names[] = {"cos", "nspd_no_such_function"};
    void *slots[2] = {NULL, NULL};
    SharedLib lib = {
        .soname = "libm.so.6", .purpose = "the test", .names = names, .count = 2, .slots = slots};
    for (int call = 0; call < 2; call++) {
        nspd_error_clear();
        assert_int_equal(shared_lib_load(&lib), NSPD_ERR_IO);
        assert_non_null(strstr(nspd_error_message(),
                               "libm.so.6, needed for the test, lacks nspd_no_such_function"));
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_functions_found),
        cmocka_unit_test(test_missing_library),
        cmocka_unit_test(test_missing_function),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
