/* Status codes, error messages and their traceback.
 *
 * Every function that can fail returns an int: NSPD_OK (0) or a negative
 * NspdStatus. The first failure records a message (thread-local) that the
 * caller can read with nspd_error_message(); TRY() propagates a failure
 * upward unchanged and, as PETSc's PetscCall does, appends the function and
 * line it passes through to a chain of callers (nspd_error_traceback), so a
 * log can say how the failure was reached, not only where it was raised.
 * Only main() turns a status into an exit code.
 *
 * The contract: no failure leaves a function without its text. NSPD_FAIL
 * is the one way to make a failure, and it takes a message (a non-empty
 * format: gcc's -Wformat-zero-length); TRY checks that the failure it
 * propagates is the one recorded (same status, a message) and otherwise
 * turns it into NSPD_ERR_INTERNAL with a message that says where it was
 * found, so the user always reads a reason, and the tests and fuzzers,
 * which treat an internal error as a bug, find the path
 * (tests/cli/test_status_contract.sh also refuses a bare
 * `return NSPD_ERR_...` in src/).
 *
 * Invariants of the thread-local record: NSPD_FAIL (nspd_error) sets the
 * status, the message and the origin and empties the chain; each TRY that
 * returns a failure appends one frame; the chain holds at most NSPD_TRACE_FRAMES
 * frames, the innermost ones, and counts those it had to drop. A frame
 * keeps __func__ by pointer (a string with static storage): nothing is
 * allocated, so a failed allocation can be traced too. */
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

enum { NSPD_TRACE_FRAMES = 16 }; /* frames kept by the traceback */

/* Records a printf-style message for `status` and returns `status`, so that
 * `return NSPD_FAIL(NSPD_ERR_IO, "...")` reads naturally. The C source
 * location is kept apart (nspd_error_origin) so user-facing messages stay
 * clean. A second call replaces the message and starts a new traceback. */
int nspd_error(int status, const char *src_file, int src_line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
#ifdef __clang_analyzer__
/* nspd_error is defined in another translation unit, so the static analyser
 * cannot know that it returns `status`; spelled out here, it follows the
 * failure paths as they run (a negative status, no result) instead of
 * inventing a success after a failed call. Compiled code is unchanged. */
#define NSPD_FAIL(status, ...) (nspd_error((status), __FILE__, __LINE__, __VA_ARGS__), (status))
#else
#define NSPD_FAIL(status, ...) nspd_error((status), __FILE__, __LINE__, __VA_ARGS__)
#endif

/* Appends the frame `func:line` to this thread's traceback and returns the
 * status to propagate (TRY calls it with the failure it received; `func`
 * must outlive the record, as __func__ does): `status` itself when it is
 * the failure NSPD_FAIL recorded, else NSPD_ERR_INTERNAL with the message
 * "a failure without a message (status S) reached func:line". */
int nspd_error_trace(const char *func, int line, int status);

/* Propagates a failure: returns the status of `expr` from the enclosing
 * function if it is negative, after adding this function and line to the
 * traceback; NSPD_ERR_INTERNAL, with a message, if that status is not the
 * failure NSPD_FAIL recorded (nspd_error_trace). */
#define TRY(expr)                                                                                  \
    do {                                                                                           \
        int try_status_ = (expr);                                                                  \
        if (try_status_ < 0) {                                                                     \
            try_status_ = nspd_error_trace(__func__, __LINE__, try_status_);                       \
            /* negative as written, so the compiler sees the early return is a failure */          \
            return try_status_ < 0 ? try_status_ : NSPD_ERR_INTERNAL;                              \
        }                                                                                          \
    } while (0)

/* Says an input failure at a place: when `status` is NSPD_ERR_INPUT and
 * `where` is not empty, the recorded message becomes "WHERE: message" (a
 * model's refusal found while it is built, which knows no place in the case
 * file, said at its section or key); returns `status` either way. */
int nspd_error_at(int status, const char *where);

const char *nspd_error_message(void); /* "" when no error was recorded */
int nspd_error_status(void);          /* the recorded failure's status; NSPD_OK when none */
const char *nspd_error_origin(void);  /* "file.c:123" of the NSPD_FAIL call */
/* The callers a failure passed through, innermost first:
 * "read_mesh:42 <- load:88 <- cmd_run:130", with " <- (N more)" when frames
 * were dropped; "" when none. Valid until the next nspd_error* call on this
 * thread. */
const char *nspd_error_traceback(void);
int nspd_error_trace_depth(void); /* frames recorded, dropped ones included */
void nspd_error_clear(void);      /* message, origin and traceback */
const char *nspd_status_name(int status);

#endif
