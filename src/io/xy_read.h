/* A polygon's vertices from a text file: one "x, y" (or "x y", "x; y")
 * per line; blank lines and '#' comments skipped; one header line allowed
 * before the first vertex. Used by the polygon bodies of a case file. */
#ifndef NSPD_IO_XY_READ_H
#define NSPD_IO_XY_READ_H

typedef struct {
    int os_error; /* NSPD_ERR_IO: why the open failed (io/in_file.h: in_file_error) */
    int line;     /* NSPD_ERR_INPUT: the line that is not a vertex (1-based) */
    char text[512];
} XyReadError;

/* Reads the vertices into *xy (x0, y0, x1, y1, ...; the caller frees with
 * nspd_free) and their count. NSPD_ERR_IO if the file cannot be opened,
 * NSPD_ERR_INPUT for a line that is not a vertex, both described in *err
 * (no message is recorded: the caller words it with the case file's
 * position); NSPD_ERR_NOMEM. */
int xy_read_file(const char *path, double **xy, int *count, XyReadError *err);

#endif
