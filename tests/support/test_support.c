#include "test_support.h"

#include "core/status.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void test_assert_close(double a, double b, double tol, const char *ta, const char *tb,
                       const char *file, int line) {
    if (fabs(a - b) <= tol) return;
    print_error("%s = %.17g and %s = %.17g differ by %.3g > %.3g\n", ta, a, tb, b, fabs(a - b),
                tol);
    _fail(file, line);
}

void test_assert_ok(int status, const char *expr, const char *file, int line) {
    if (status == NSPD_OK) return;
    print_error("%s failed (%s): %s\n", expr, nspd_status_name(status), nspd_error_message());
    _fail(file, line);
}

const char *test_scratch_dir(const char *tag) {
    static char path[1024];
    snprintf(path, sizeof path, "%s/test_scratch/%s", NSPD_BINARY_DIR, tag);
    char cmd[2200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", path, path);
    if (system(cmd) != 0) fail_msg("cannot create %s", path);
    return path;
}

const char *test_source_path(const char *relative) {
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", NSPD_SOURCE_DIR, relative);
    return path;
}

char *test_read_file(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    if (text && fread(text, 1, (size_t)size, f) != (size_t)size) {
        free(text);
        text = NULL;
    }
    if (text) text[size] = '\0';
    fclose(f);
    return text;
}
