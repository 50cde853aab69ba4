/* io/run_files + core/report: a Report becomes history.csv rows (the header
 * from the first row's names, each kind in its format) and summary.json;
 * a report past its capacity is refused, not overrun. */
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/run_files.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void test_history_and_summary(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("run_files");
    Report *r;
    assert_ok(nspd_alloc(&r, 1, sizeof *r));
    HistoryFile h;
    assert_ok(history_open(&h, dir));
    for (int step = 0; step < 2; step++) {
        report_clear(r);
        report_int(r, "step", step);
        report_real(r, "time_s", 0.1 * step);
        report_precise(r, "mass_kg", 1.0 / 3.0);
        report_realf(r, 2.0, "%s_cd", "cylinder");
        assert_ok(history_write(&h, r));
    }
    history_close(&h);
    char path[4200];
    snprintf(path, sizeof path, "%s/history.csv", dir);
    char *text = test_read_file(path);
    assert_string_equal(text, "step,time_s,mass_kg,cylinder_cd\n"
                              "0,0,0.333333333333,2\n"
                              "1,0.1,0.333333333333,2\n");
    free(text);
    report_clear(r);
    report_text(r, "case", "a \"quoted\" name");
    report_bool(r, "completed", true);
    report_real(r, "cd", (double)NAN);
    assert_non_null(report_find(r, "completed"));
    assert_null(report_find(r, "cl"));
    assert_ok(summary_write(dir, r));
    snprintf(path, sizeof path, "%s/summary.json", dir);
    text = test_read_file(path);
    assert_string_equal(text, "{\n  \"case\": \"a \\\"quoted\\\" name\",\n  \"completed\": true,\n"
                              "  \"cd\": null\n}\n");
    free(text);
    nspd_free(&r);
}

static void test_overflow_is_refused(void **state) {
    (void)state;
    Report *r;
    assert_ok(nspd_alloc(&r, 1, sizeof *r));
    report_clear(r);
    for (int k = 0; k <= REPORT_MAX_ITEMS; k++) report_realf(r, (double)k, "column_%d", k);
    assert_int_equal(r->n, REPORT_MAX_ITEMS);
    assert_true(r->overflow);
    HistoryFile h;
    assert_ok(history_open(&h, test_scratch_dir("run_files_overflow")));
    assert_int_equal(history_write(&h, r), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "history columns"));
    history_close(&h);
    report_clear(r);
    assert_false(r->overflow);
    nspd_free(&r);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_history_and_summary),
        cmocka_unit_test(test_overflow_is_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
