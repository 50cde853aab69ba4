/* Opening a file a case names (a polygon's vertices, a field to start
 * from): regular files only. A device (/dev/zero: endless bytes), a FIFO
 * (blocks until a writer comes) or a directory would hang or confuse the
 * reader; they are refused at once. */
#ifndef NSPD_IO_IN_FILE_H
#define NSPD_IO_IN_FILE_H

#include <stdint.h>
#include <stdio.h>

/* fopen(path, "r" or "rb") of a regular file; NULL with *err an errno
 * (ENOENT, EACCES, ...) or IN_FILE_NOT_REGULAR. */
enum { IN_FILE_NOT_REGULAR = -1 };
FILE *in_file_open(const char *path, int *err);
/* The reason of an in_file_open failure, as text. */
const char *in_file_error(int err);

/* Where a file a reader takes is wrong and why (io/stl_read.h,
 * io/inp_read.h). */
typedef struct {
    int os_error;   /* NSPD_ERR_IO: why the open failed (in_file_error) */
    int line;       /* NSPD_ERR_INPUT: the line (1-based); 0 for a binary file or the whole */
    int64_t offset; /* NSPD_ERR_INPUT with line 0: the byte offset */
    char text[256]; /* what is wrong there; expected what */
} InFileError;

/* Fills *err (line, offset, the formatted text) and returns
 * NSPD_FAIL(NSPD_ERR_INPUT) with that text, for the caller's wording. */
int in_file_refuse(InFileError *err, int line, int64_t offset, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
