#include "io/in_file.h"

#include "core/status.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

FILE *in_file_open(const char *path, int *err) {
    /* O_NONBLOCK: opening a FIFO must not wait for a writer */
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        *err = errno;
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        *err = IN_FILE_NOT_REGULAR;
        close(fd);
        return NULL;
    }
    const int flags = fcntl(fd, F_GETFL);
    if (flags >= 0) (void)fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    FILE *f = fdopen(fd, "r");
    if (!f) {
        *err = errno;
        close(fd);
    }
    return f;
}

const char *in_file_error(int err) {
    return err == IN_FILE_NOT_REGULAR
               ? "not a regular file (a directory, a device or a FIFO); expected a file"
               : strerror(err);
}

int in_file_refuse(InFileError *err, int line, int64_t offset, const char *fmt, ...) {
    err->line = line;
    err->offset = offset;
    va_list args;
    va_start(args, fmt);
    vsnprintf(err->text, sizeof err->text, fmt, args);
    va_end(args);
    return NSPD_FAIL(NSPD_ERR_INPUT, "%s", err->text);
}
