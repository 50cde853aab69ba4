/* Helpers shared by the test programs (cmocka is included for them). */
#ifndef NSPD_TEST_SUPPORT_H
#define NSPD_TEST_SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

/* Fails the test, printing both values, if |a - b| > tol. */
#define assert_close(a, b, tol) test_assert_close((a), (b), (tol), #a, #b, __FILE__, __LINE__)
void test_assert_close(double a, double b, double tol, const char *ta, const char *tb,
                       const char *file, int line);

/* Fails the test unless the NSPD status is NSPD_OK, printing the error message. */
#define assert_ok(expr) test_assert_ok((expr), #expr, __FILE__, __LINE__)
void test_assert_ok(int status, const char *expr, const char *file, int line);

/* A fresh empty directory under the build tree, named after `tag`; returns
 * its path (static storage, valid until the next call). */
const char *test_scratch_dir(const char *tag);

/* Path of a file in the source tree ("cases/plate_crack.yaml"). */
const char *test_source_path(const char *relative);

/* Reads a whole file; the caller frees. NULL if it cannot be read. */
char *test_read_file(const char *path);

#endif
