/* Opening a file a case names (a polygon's vertices, a field to start
 * from): regular files only. A device (/dev/zero: endless bytes), a FIFO
 * (blocks until a writer comes) or a directory would hang or confuse the
 * reader; they are refused at once. */
#ifndef NSPD_IO_IN_FILE_H
#define NSPD_IO_IN_FILE_H

#include <stdio.h>

/* fopen(path, "r" or "rb") of a regular file; NULL with *err an errno
 * (ENOENT, EACCES, ...) or IN_FILE_NOT_REGULAR. */
enum { IN_FILE_NOT_REGULAR = -1 };
FILE *in_file_open(const char *path, int *err);
/* The reason of an in_file_open failure, as text. */
const char *in_file_error(int err);

#endif
