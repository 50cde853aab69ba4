/* Logging for drivers and operators (never kernels).
 *
 * Messages go to stderr at or above the console level, and to the run's log
 * file (log.txt) at every level once nspd_log_open() has been called. */
#ifndef NSPD_CORE_LOG_H
#define NSPD_CORE_LOG_H

#include <stdbool.h>

typedef enum { LOG_DEBUG = 0, LOG_INFO = 1, LOG_WARN = 2, LOG_ERROR = 3, LOG_QUIET = 4 } LogLevel;

void nspd_log_set_console_level(LogLevel level);
/* append: continue an existing log (a resumed run). NSPD_ERR_IO if the file
 * cannot be created. */
int nspd_log_open(const char *path, bool append);
void nspd_log_close(void);
void nspd_log(LogLevel level, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* To the log file only (no-op when none is open). */
void nspd_log_file(LogLevel level, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#endif
