/* Error records: one per thread, the latest failure wins. The traceback is
 * kept as (function, line) pairs and formatted only when asked for. */
#include "core/status.h"

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static _Thread_local int error_status; /* of the recorded failure; NSPD_OK: none */
static _Thread_local char error_message[2048];
static _Thread_local char error_origin[256];

typedef struct {
    const char *func; /* __func__ of the TRY: static storage */
    int line;
} TraceFrame;
static _Thread_local TraceFrame trace[NSPD_TRACE_FRAMES];
static _Thread_local int trace_depth; /* frames appended, may exceed NSPD_TRACE_FRAMES */
static _Thread_local char trace_text[NSPD_TRACE_FRAMES * 64 + 32];

int nspd_error(int status, const char *src_file, int src_line, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    /* va_start above; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
     * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
    vsnprintf(error_message, sizeof error_message, fmt, args);
    va_end(args);
    snprintf(error_origin, sizeof error_origin, "%s:%d", src_file, src_line);
    error_status = status;
    trace_depth = 0;
    return status;
}

/* A status NSPD_FAIL can record: one of NspdStatus's failures. */
static int is_failure(int status) {
    return status <= NSPD_ERR_INPUT && status >= NSPD_ERR_INTERRUPTED;
}

int nspd_error_trace(const char *func, int line, int status) {
    if (status != error_status || !is_failure(status) || !error_message[0]) {
        /* returned without NSPD_FAIL (a bare code, or a count that
         * overflowed into a negative number): a bug, said where found */
        nspd_error(NSPD_ERR_INTERNAL, func, line,
                   "internal error: a failure without a message (status %d) reached %s:%d; "
                   "please report it with the input that gave it",
                   status, func, line);
        status = NSPD_ERR_INTERNAL;
    }
    if (trace_depth < NSPD_TRACE_FRAMES) trace[trace_depth] = (TraceFrame){func, line};
    if (trace_depth < INT_MAX) trace_depth++;
    return status;
}

int nspd_error_at(int status, const char *where) {
    if (status != NSPD_ERR_INPUT || !where || !where[0]) return status;
    char what[sizeof error_message];
    memcpy(what, error_message, sizeof what);
    snprintf(error_message, sizeof error_message, "%s: ", where);
    const size_t len = strlen(error_message), room = sizeof error_message - 1 - len;
    const size_t n = strnlen(what, room); /* the message, cut to what fits */
    memcpy(error_message + len, what, n);
    error_message[len + n] = '\0';
    return status;
}

int nspd_error_status(void) {
    return error_status;
}

int nspd_error_trace_depth(void) {
    return trace_depth;
}

const char *nspd_error_traceback(void) {
    const int kept = trace_depth < NSPD_TRACE_FRAMES ? trace_depth : NSPD_TRACE_FRAMES;
    size_t len = 0;
    trace_text[0] = '\0';
    for (int k = 0; k < kept && len < sizeof trace_text; k++) {
        const int n = snprintf(trace_text + len, sizeof trace_text - len, "%s%s:%d",
                               k ? " <- " : "", trace[k].func, trace[k].line);
        if (n < 0) break;
        len += (size_t)n;
    }
    if (trace_depth > kept && len < sizeof trace_text)
        snprintf(trace_text + len, sizeof trace_text - len, " <- (%d more)", trace_depth - kept);
    return trace_text;
}

const char *nspd_error_message(void) {
    return error_message;
}

const char *nspd_error_origin(void) {
    return error_origin;
}

void nspd_error_clear(void) {
    error_status = NSPD_OK;
    error_message[0] = '\0';
    error_origin[0] = '\0';
    trace_depth = 0;
}

const char *nspd_status_name(int status) {
    switch (status) {
    case NSPD_OK:
        return "ok";
    case NSPD_ERR_INPUT:
        return "bad input";
    case NSPD_ERR_IO:
        return "i/o error";
    case NSPD_ERR_NOMEM:
        return "out of memory";
    case NSPD_ERR_NUMERIC:
        return "numerical failure";
    case NSPD_ERR_INTERNAL:
        return "internal error";
    case NSPD_ERR_INTERRUPTED:
        return "interrupted";
    default:
        return "unknown status";
    }
}
