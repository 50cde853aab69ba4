/* Status codes and error messages.
 *
 * Every function that can fail returns an int: NSPD_OK (0) or a negative
 * NspdStatus. The first failure records a message (thread-local) that the
 * caller can read with nspd_error_message(); TRY() propagates a failure
 * upward unchanged. Only main() turns a status into an exit code. */
#ifndef NSPD_CORE_STATUS_H
#define NSPD_CORE_STATUS_H

typedef enum {
    NSPD_OK = 0,
    NSPD_ERR_INPUT = -1,       /* the user's input is wrong (case file, option): exit 2 */
    NSPD_ERR_IO = -2,          /* a file could not be read or written */
    NSPD_ERR_NOMEM = -3,       /* an allocation failed */
    NSPD_ERR_NUMERIC = -4,     /* the solution left the physical range (NaN, rho <= 0) */
    NSPD_ERR_INTERNAL = -5,    /* a broken invariant: a bug in nspd */
    NSPD_ERR_INTERRUPTED = -6, /* the user asked to stop (Ctrl-C) */
} NspdStatus;

/* Records a printf-style message for `status` and returns `status`, so that
 * `return NSPD_FAIL(NSPD_ERR_IO, "...")` reads naturally. The C source
 * location is kept apart (nspd_error_origin) so user-facing messages stay
 * clean. A second call replaces the message. */
int nspd_error(int status, const char *src_file, int src_line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
#define NSPD_FAIL(status, ...) nspd_error((status), __FILE__, __LINE__, __VA_ARGS__)

/* Propagates a failure: returns the status of `expr` from the enclosing
 * function if it is negative. */
#define TRY(expr)                                                                                  \
    do {                                                                                           \
        int try_status_ = (expr);                                                                  \
        if (try_status_ < 0) return try_status_;                                                   \
    } while (0)

const char *nspd_error_message(void); /* "" when no error was recorded */
const char *nspd_error_origin(void);  /* "file.c:123" of the NSPD_FAIL call */
void nspd_error_clear(void);
const char *nspd_status_name(int status);

#endif
