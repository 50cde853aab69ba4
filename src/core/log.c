#include "core/log.h"

#include "core/status.h"

#include <stdarg.h>
#include <stdio.h>

static LogLevel console_level = LOG_INFO;
static FILE *log_file;

void nspd_log_set_console_level(LogLevel level) {
    console_level = level;
}

int nspd_log_open(const char *path, bool append) {
    nspd_log_close();
    log_file = fopen(path, append ? "a" : "w");
    if (!log_file) return NSPD_FAIL(NSPD_ERR_IO, "cannot create log file '%s'", path);
    return NSPD_OK;
}

void nspd_log_close(void) {
    if (log_file) fclose(log_file);
    log_file = NULL;
}

static const char *const prefix[] = {"debug: ", "", "warning: ", "error: "};

void nspd_log_file(LogLevel level, const char *fmt, ...) {
    if (!log_file) return;
    va_list args;
    va_start(args, fmt);
    fputs(prefix[level], log_file);
    /* va_start above; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
     * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
    vfprintf(log_file, fmt, args);
    fputc('\n', log_file);
    va_end(args);
    fflush(log_file);
}

void nspd_log(LogLevel level, const char *fmt, ...) {
    va_list args;
    if (level >= console_level) {
        va_start(args, fmt);
        fputs(prefix[level], stderr);
        /* va_start above; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
         * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
        vfprintf(stderr, fmt, args);
        fputc('\n', stderr);
        va_end(args);
    }
    if (log_file) {
        va_start(args, fmt);
        fputs(prefix[level], log_file);
        /* va_start above; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
         * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
        vfprintf(log_file, fmt, args);
        fputc('\n', log_file);
        va_end(args);
        fflush(log_file);
    }
}
