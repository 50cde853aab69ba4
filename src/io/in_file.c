#include "io/in_file.h"

#include <errno.h>
#include <fcntl.h>
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
