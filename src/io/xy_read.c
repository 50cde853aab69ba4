#include "io/xy_read.h"

#include "io/in_file.h"

#include "core/mem.h"
#include "core/status.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Parses "x, y" or "x y" (with optional trailing text after a '#'). */
static int parse_pair(char *line, double *x, double *y) {
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    for (char *c = line; *c; c++)
        if (*c == ',' || *c == ';' || *c == '\t' || *c == '\r' || *c == '\n') *c = ' ';
    char *end;
    errno = 0;
    *x = strtod(line, &end);
    if (end == line) return -1;
    char *p = end;
    *y = strtod(p, &end);
    if (end == p || errno == ERANGE) return -1;
    while (*end == ' ') end++;
    if (*end != '\0' || !isfinite(*x) || !isfinite(*y)) return -1;
    return 0;
}

static int blank(const char *s) {
    for (; *s; s++)
        if (*s == '#')
            return 1;
        else if (*s != ' ' && *s != '\t' && *s != '\r' && *s != '\n')
            return 0;
    return 1;
}

int xy_read_file(const char *path, double **xy, int *count, XyReadError *err) {
    memset(err, 0, sizeof *err);
    *xy = NULL;
    *count = 0;
    int open_error = 0;
    FILE *fp = in_file_open(path, &open_error);
    if (!fp) {
        err->os_error = open_error;
        return NSPD_FAIL(NSPD_ERR_IO, "%s: cannot open it", path); /* err: for the caller's */
    }
    char line[512];
    int lineno = 0, n = 0, cap = 0, st = NSPD_OK, data_lines = 0;
    while (fgets(line, sizeof line, fp)) {
        lineno++;
        if (blank(line)) continue;
        char copy[512];
        snprintf(copy, sizeof copy, "%s", line);
        double x, y;
        if (parse_pair(line, &x, &y) < 0) {
            if (data_lines == 0) { /* a header line */
                data_lines = -1;
                continue;
            }
            copy[strcspn(copy, "\r\n")] = '\0';
            err->line = lineno;
            snprintf(err->text, sizeof err->text, "%s", copy);
            st = NSPD_FAIL(NSPD_ERR_INPUT, "%s:%d: '%s' is not two numbers", path, lineno, copy);
            break;
        }
        data_lines = data_lines < 0 ? 1 : data_lines + 1;
        if (n == cap) {
            const int nc = cap ? 2 * cap : 64;
            if ((st = nspd_realloc(xy, 2 * (size_t)cap, 2 * (size_t)nc, sizeof(double))) < 0) break;
            cap = nc;
        }
        (*xy)[2 * n] = x;
        (*xy)[2 * n + 1] = y;
        n++;
    }
    fclose(fp);
    *count = n;
    return st;
}
