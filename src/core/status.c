/* Error records: one per thread, the latest failure wins. */
#include "core/status.h"

#include <stdarg.h>
#include <stdio.h>

static _Thread_local char error_message[2048];
static _Thread_local char error_origin[256];

int nspd_error(int status, const char *src_file, int src_line, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    vsnprintf(error_message, sizeof error_message, fmt, args);
    va_end(args);
    snprintf(error_origin, sizeof error_origin, "%s:%d", src_file, src_line);
    return status;
}

const char *nspd_error_message(void) {
    return error_message;
}

const char *nspd_error_origin(void) {
    return error_origin;
}

void nspd_error_clear(void) {
    error_message[0] = '\0';
    error_origin[0] = '\0';
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
